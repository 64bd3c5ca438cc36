//! `phonglab screenshot`'s arguments: the whole window, drawn headless on the CPU (no
//! display, no GPU) at a given size and scale, as a PNG. The window draws it
//! ([`crate::app`]'s `screenshot`); the binary hands these arguments over.

use std::path::PathBuf;

use clap::Args;

use crate::io::screenshot::Opened;

/// `phonglab screenshot`.
#[derive(Args, Debug, Clone)]
pub struct ScreenshotArgs {
    /// The window's size in points, WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x720", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Pixels per point (2 for a high-density screen).
    #[arg(long, default_value_t = 1.0)]
    pub scale: f32,
    /// Presentation mode (F5).
    #[arg(long)]
    pub present: bool,
    /// The light theme (default: dark).
    #[arg(long)]
    pub light: bool,
    /// A scene file (default: the worksheet's scene).
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// Open this first.
    #[arg(long, value_enum)]
    pub open: Option<Opened>,
    /// The PNG to write.
    #[arg(short, long)]
    pub output: PathBuf,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("{s:?}: write WIDTHxHEIGHT, e.g. 1280x720"))?;
    let n = |t: &str| t.trim().parse::<u32>().ok().filter(|v| (200..=8192).contains(v));
    match (n(w), n(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(format!("{s:?}: each side is a whole number of points from 200 to 8192")),
    }
}
