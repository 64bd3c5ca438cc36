//! `phonglab screenshot`: the whole window, drawn headless on the CPU (no display, no
//! GPU) at a given size and scale, as a PNG. Teachers use it for slides and handouts; the
//! tests use it to look at the pictures as a class would see them.

use std::path::PathBuf;

use anyhow::{Context as _, Result, bail};
use clap::{Args, ValueEnum};

use crate::app::{AppState, app_ui, layout};

/// What to open before the picture is taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Open {
    /// Compare, with the scene pinned as A and B the same scene in Phong shading.
    Compare,
    /// The reflection lobe in the plot's place.
    Lobe,
    /// The quiz on the scene.
    Quiz,
    /// The Shader window.
    Shader,
    /// The Cost of accuracy window.
    Cost,
    /// The Phong demo's three corrections, side by side with the demo's own picture.
    DemoFixes,
}

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
    pub open: Option<Open>,
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

/// The app's state for a screenshot: the scene, the mode, what is open.
pub fn state_for(doc: phonglab_core::Document, present: bool, light: bool, open: Option<Open>) -> AppState {
    let mut state = AppState::worksheet();
    state.doc = doc;
    state.ui.layout.presenting = present;
    state.ui.layout.theme = if light { layout::Theme::Light } else { layout::Theme::Dark };
    match open {
        Some(Open::Compare) => {
            state.compare.open = true;
            state.compare.pin(&state.doc, state.ui.precision, state.ui.pow);
            state.doc.view.shading = phonglab_core::Shading::Phong;
        }
        Some(Open::Lobe) => state.ui.layout.beside = layout::Beside::Lobe,
        Some(Open::Quiz) => state.quiz.start(state.doc.clone()),
        Some(Open::Shader) => state.shader.open = true,
        Some(Open::Cost) => state.cost.open = true,
        Some(Open::DemoFixes) => {
            state.doc = phonglab_core::library::phong_demo_document();
            state.ui.demo_fixes = [true; 3];
        }
        None => {}
    }
    state
}

/// A picture of the whole window: `width` x `height` points at `scale` pixels a point, after
/// the frames it takes to settle. Returns the RGBA8 pixels and the state as last drawn.
pub fn take(state: AppState, width: f32, height: f32, scale: f32) -> (usize, usize, Vec<u8>, AppState) {
    let mut state = state;
    let canvas = crate::paint::egui_cpu::paint_ui(width, height, scale, |ui| app_ui(ui, &mut state));
    (canvas.width, canvas.height, canvas.rgba8(), state)
}

/// The share of the window that is empty: tiles of `tile` x `tile` pixels that show
/// nothing but the panels' background (a tile with any text, line or picture in it is not
/// empty, so the gaps between the letters of a paragraph do not count).
pub fn empty_share(rgba: &[u8], width: usize, height: usize, background: egui::Color32, tile: usize) -> f64 {
    let bg = background.to_array();
    let (tx, ty) = (width / tile, height / tile);
    let mut empty = 0;
    for j in 0..ty {
        for i in 0..tx {
            let all_bg = (0..tile).all(|y| {
                let row = ((j * tile + y) * width + i * tile) * 4;
                rgba[row..row + tile * 4].chunks_exact(4).all(|p| p[..3] == bg[..3])
            });
            empty += usize::from(all_bg);
        }
    }
    empty as f64 / (tx * ty).max(1) as f64
}

/// Runs `phonglab screenshot`.
pub fn run(a: &ScreenshotArgs) -> Result<()> {
    if !(0.5..=4.0).contains(&a.scale) {
        bail!(phonglab_core::t!("err-scale", scale = phonglab_core::locale::decimal(&a.scale.to_string())));
    }
    let (pw, ph) = ((a.size.0 as f32 * a.scale).round() as u32, (a.size.1 as f32 * a.scale).round() as u32);
    let needed = crate::io::budget::window_picture_bytes(u64::from(a.size.0), u64::from(a.size.1), f64::from(a.scale));
    crate::io::budget::check(&phonglab_core::t!("budget-what-window", width = pw, height = ph), needed)
        .map_err(anyhow::Error::msg)?;
    let scene: Vec<&std::path::Path> = a.scene.iter().map(PathBuf::as_path).collect();
    crate::io::same_file::refuse_output_onto_input(&[&a.output], &scene).map_err(anyhow::Error::msg)?;
    crate::io::atomic_write::check_file_destination(&a.output)?;
    let doc = match &a.scene {
        Some(p) => crate::cli::load_scene_file(p)?,
        None => phonglab_core::Document::default(),
    };
    let mesh: Vec<&std::path::Path> = doc.view.obj.iter().map(std::path::Path::new).collect();
    crate::io::same_file::refuse_output_onto_input(&[&a.output], &mesh).map_err(anyhow::Error::msg)?;
    let state = state_for(doc, a.present, a.light, a.open);
    let (w, h) = (a.size.0 as f32, a.size.1 as f32);
    let (pw, ph, rgba, state) = take(state, w, h, a.scale);
    crate::io::image::write_png(&a.output, pw, ph, &rgba).context("the screenshot")?;
    let g = &state.ui.geometry;
    let bg = state.ui.layout.theme.visuals().panel_fill;
    let sides: Vec<String> = g.pictures.iter().map(|r| format!("{:.0}", r.width().min(r.height()))).collect();
    eprintln!(
        "{}: {pw}x{ph} px; pictures {} points, the plot's unit circle {} points across, {:.0} % empty",
        a.output.display(),
        if sides.is_empty() { "none".to_string() } else { sides.join(" and ") },
        g.plot.as_ref().map_or("not shown".to_string(), |p| format!("{:.0}", 2.0 * p.unit)),
        100.0 * empty_share(&rgba, pw, ph, bg, (16.0 * a.scale).round() as usize)
    );
    Ok(())
}
