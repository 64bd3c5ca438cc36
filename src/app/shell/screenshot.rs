//! The whole window as a picture, drawn headless on the CPU (no display, no GPU) at a
//! given size and scale: `phonglab screenshot` (teachers use it for slides and handouts)
//! and the tests, which look at the pictures as a class would see them.

use std::path::PathBuf;

use anyhow::{Context as _, Result, bail};

use crate::app::shell::frame::app_ui;
use crate::app::shell::layout;
use crate::app::shell::state::AppState;
use crate::io::screenshot::Opened;

/// The picture asked for.
#[derive(Clone, Debug)]
pub struct Shot {
    /// The window's size in points.
    pub size: (u32, u32),
    /// Pixels per point.
    pub scale: f32,
    /// Presentation mode.
    pub present: bool,
    /// The light theme (else the dark one).
    pub light: bool,
    /// A scene file (else the worksheet's scene).
    pub scene: Option<PathBuf>,
    /// What is open first.
    pub open: Option<Opened>,
    /// The PNG to write.
    pub output: PathBuf,
}

/// The app's state for a screenshot: the scene, the mode, what is open.
pub fn state_for(doc: phonglab_core::Document, present: bool, light: bool, open: Option<Opened>) -> AppState {
    let mut state = AppState::worksheet();
    state.doc = doc;
    state.ui.layout.presenting = present;
    state.ui.layout.theme = if light { layout::Theme::Light } else { layout::Theme::Dark };
    match open {
        Some(Opened::Compare) => {
            state.compare.open = true;
            state.compare.pin(&state.doc, state.settings.precision, state.settings.pow);
            state.doc.view.shading = phonglab_core::Shading::Phong;
        }
        Some(Opened::Lobe) => state.ui.layout.beside = layout::Beside::Lobe,
        Some(Opened::Quiz) => state.quiz.start(state.doc.clone()),
        Some(Opened::Shader) => state.shader.open = true,
        Some(Opened::Cost) => state.cost.open = true,
        Some(Opened::DemoFixes) => {
            state.doc = phonglab_core::library::phong_demo_document();
            state.view_options.demo_fixes = [true; 3];
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
/// empty, so the gaps between the letters of a paragraph do not count). A tile inside one
/// of `pictures` (rects in pixels) is the picture's, even where the scene's background is
/// the panels' colour (the Phong demo's black on the dark theme's).
pub fn empty_share(
    rgba: &[u8],
    width: usize,
    height: usize,
    background: egui::Color32,
    tile: usize,
    pictures: &[egui::Rect],
) -> f64 {
    let bg = background.to_array();
    let (tx, ty) = (width / tile, height / tile);
    let mut empty = 0;
    for j in 0..ty {
        for i in 0..tx {
            let centre = egui::pos2(((i * tile) as f32) + tile as f32 * 0.5, ((j * tile) as f32) + tile as f32 * 0.5);
            if pictures.iter().any(|r| r.contains(centre)) {
                continue;
            }
            let all_bg = (0..tile).all(|y| {
                let row = ((j * tile + y) * width + i * tile) * 4;
                rgba[row..row + tile * 4].chunks_exact(4).all(|p| p[..3] == bg[..3])
            });
            empty += usize::from(all_bg);
        }
    }
    empty as f64 / (tx * ty).max(1) as f64
}

/// The window `shot` asks for: its scene file's scene, or a share link's scene with the
/// choices the link carries (its language, presenting, the term shown), as the window
/// started on that link takes them.
pub fn state_of(a: &Shot) -> Result<AppState> {
    let link = a.scene.as_deref().filter(|p| crate::io::input_file::share_fragment(p).is_some());
    let shared = match link {
        Some(p) => Some(crate::io::input_file::read_link(&p.to_string_lossy()).map_err(anyhow::Error::msg)?),
        None => None,
    };
    let doc = match (&shared, &a.scene) {
        (Some(s), _) => s.doc.clone(),
        (None, Some(p)) => crate::io::input_file::load_scene(p).map_err(anyhow::Error::msg)?,
        (None, None) => phonglab_core::Document::default(),
    };
    let mut state = state_for(doc, a.present, a.light, a.open);
    if let Some(s) = &shared {
        super::shared_link::take_choices(&mut state, s);
    }
    Ok(state)
}

/// Takes the picture `shot` asks for and writes it (`phonglab screenshot`).
pub fn run(a: &Shot) -> Result<()> {
    if !(0.5..=4.0).contains(&a.scale) {
        bail!(crate::t!("err-scale", scale = crate::locale::exact(f64::from(a.scale))));
    }
    let (pw, ph) = ((a.size.0 as f32 * a.scale).round() as u32, (a.size.1 as f32 * a.scale).round() as u32);
    let needed = crate::io::budget::window_picture_bytes(u64::from(a.size.0), u64::from(a.size.1), f64::from(a.scale));
    crate::io::budget::check(&crate::t!("budget-what-window", width = pw, height = ph), needed)
        .map_err(anyhow::Error::msg)?;
    use crate::io::same_file::{Input, refuse_onto};
    let scene: Vec<(&std::path::Path, Input)> = a.scene.iter().map(|p| (p.as_path(), Input::Scene)).collect();
    refuse_onto(&[&a.output], &scene).map_err(anyhow::Error::msg)?;
    crate::io::atomic_write::check_file_destination(&a.output)?;
    let state = state_of(a)?;
    let mesh: Vec<(&std::path::Path, Input)> =
        state.doc.view.obj.iter().map(|m| (std::path::Path::new(m), Input::Mesh)).collect();
    refuse_onto(&[&a.output], &mesh).map_err(anyhow::Error::msg)?;
    let (w, h) = (a.size.0 as f32, a.size.1 as f32);
    let (pw, ph, rgba, state) = take(state, w, h, a.scale);
    crate::io::image::write_png(&a.output, pw, ph, &rgba).context("the screenshot")?;
    let g = &state.ui.geometry;
    let bg = state.ui.layout.theme.visuals().panel_fill;
    let pictures: Vec<egui::Rect> = g
        .pictures
        .iter()
        .map(|r| egui::Rect::from_min_max((r.min.to_vec2() * a.scale).to_pos2(), (r.max.to_vec2() * a.scale).to_pos2()))
        .collect();
    let sides: Vec<String> = g.pictures.iter().map(|r| format!("{:.0}", r.width().min(r.height()))).collect();
    let none = crate::t!("screenshot-none");
    // The file name is the user's: its controls written visibly, never sent to the terminal.
    eprintln!(
        "{}",
        phonglab_core::escape::terminal::lines(&crate::t!(
            "screenshot-summary",
            path = crate::io::reasons::shown(&a.output),
            width = pw,
            height = ph,
            pictures = if sides.is_empty() { none.clone() } else { sides.join(" + ") },
            circle = g.plot.as_ref().map_or(none, |p| format!("{:.0}", 2.0 * p.unit)),
            empty =
                format!("{:.0}", 100.0 * empty_share(&rgba, pw, ph, bg, (16.0 * a.scale).round() as usize, &pictures))
        ))
    );
    Ok(())
}
