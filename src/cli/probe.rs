//! `phonglab probe`: why one pixel of the shaded view is the colour it is.

use anyhow::{Result, bail};
use clap::Args;
use phonglab_core::render::Renderer;
use phonglab_core::{probe, probe_report};

use super::render::ShadedInput;
use crate::t;

/// `phonglab probe`.
#[derive(Args, Debug)]
pub struct ProbeArgs {
    /// What is drawn (the picture is `--size` pixels square).
    #[command(flatten)]
    pub input: ShadedInput,
    /// The pixel: x from the left, y from the top, from 0.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pub at: (usize, usize),
    /// Print JSON (for scripts and tests) instead of the report.
    #[arg(long)]
    pub json: bool,
}

/// "X,Y" as two whole numbers.
fn parse_pixel(s: &str) -> Result<(usize, usize), String> {
    let bad = || t!("err-probe-at", value = format!("{s:?}"));
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    Ok((x.trim().parse().map_err(|_| bad())?, y.trim().parse().map_err(|_| bad())?))
}

/// Runs `phonglab probe`.
pub fn run(a: &ProbeArgs) -> Result<()> {
    let loaded = a.input.load(&[])?;
    let job = loaded.job();
    let size = a.input.size as usize;
    let (x, y) = a.at;
    if x >= size || y >= size {
        bail!(t!("err-probe-outside", x = x as i64, y = y as i64, size = size as i64));
    }
    let mut r = Renderer::new();
    r.render(&job, size, size)?;
    match probe::probe(&r, &job, x, y)? {
        None if a.json => println!("{}", serde_json::json!({ "x": x, "y": y, "covered": false })),
        None => println!("{}", t!("probe-uncovered", x = x as i64, y = y as i64)),
        Some(p) if a.json => {
            let mut v = serde_json::to_value(&p)?;
            v["covered"] = true.into();
            v["size"] = size.into();
            println!("{}", phonglab_core::escape::json::text(&serde_json::to_string_pretty(&v)?));
        }
        Some(p) => print!("{}", probe_report::text(&probe_report::report(&p))),
    }
    Ok(())
}
