//! `phonglab bench ui`: the CPU time of the whole window per frame, headless, with every
//! panel open (idle, a slider moved, the object turning), or presenting while a light is
//! dragged; median and p95 of the layout and of egui's tessellation.

use anyhow::Result;
use phonglab_core::Shading;

use crate::platform::clock::Instant;

use crate::app::shell::frame::app_ui;
use crate::app::shell::state::AppState;

/// What `phonglab bench ui` asks for.
#[derive(Clone, Copy, Debug)]
pub struct UiBench {
    /// Frames timed per case.
    pub frames: u32,
    /// Window width in points.
    pub width: f32,
    /// Window height in points.
    pub height: f32,
    /// Presentation mode at 1920x1080 (unless a size is given), the light dragged.
    pub present: bool,
}

/// Median and p95 of the layout times `ui`, the tessellation times `tess` and their sums
/// per frame: `[ui median, ui p95, tess median, tess p95, total median, total p95]`.
fn figures(ui: &mut [f64], tess: &mut [f64]) -> [f64; 6] {
    let mut total: Vec<f64> = ui.iter().zip(tess.iter()).map(|(a, b)| a + b).collect();
    let (um, up) = median_p95(ui);
    let (tm, tp) = median_p95(tess);
    let (sm, sp) = median_p95(&mut total);
    [um, up, tm, tp, sm, sp]
}

/// An edit as dragging the light-z slider makes it: frame f puts the light at `z0 + f mod 100`.
fn drag_light_z(z0: f64) -> impl FnMut(&mut AppState, u32) {
    move |s, f| {
        let mut d = s.doc.clone();
        d.scene.lights[0].position.z = z0 + (f % 100) as f64;
        s.apply(d);
    }
}

/// Median and 95th percentile of `v` (sorted in place).
fn median_p95(v: &mut [f64]) -> (f64, f64) {
    v.sort_by(f64::total_cmp);
    if v.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    (v[v.len() / 2], v[((v.len() as f64 * 0.95) as usize).min(v.len() - 1)])
}

/// One timed UI case: per frame, `change` edits the state, then the UI runs and is
/// tessellated. Returns (ui ms, tessellation ms) per frame.
pub fn time_ui_frames(
    ctx: &egui::Context,
    state: &mut AppState,
    size: [f32; 2],
    frames: u32,
    mut change: impl FnMut(&mut AppState, u32),
) -> (Vec<f64>, Vec<f64>) {
    let (mut ui_ms, mut tess_ms) = (Vec::new(), Vec::new());
    for f in 0..frames {
        change(state, f);
        let t0 = Instant::now();
        let mut out = ctx.run_ui(crate::paint::egui_cpu::raw_input(size[0], size[1], 1.0), |ui| app_ui(ui, state));
        let t1 = Instant::now();
        let prims = ctx.tessellate(std::mem::take(&mut out.shapes), out.pixels_per_point);
        let t2 = Instant::now();
        std::hint::black_box(prims);
        out.textures_delta.clear();
        ui_ms.push((t1 - t0).as_secs_f64() * 1e3);
        tess_ms.push((t2 - t1).as_secs_f64() * 1e3);
    }
    (ui_ms, tess_ms)
}

/// The app with every panel open: controls, calculation, vector plot, shaded view with its
/// heat map, the cost window with a finished study, and the help overlay.
pub fn all_panels_open(ctx: &egui::Context, size: [f32; 2]) -> Result<AppState> {
    let mut state = AppState::worksheet();
    state.ui.show_help = true;
    state.cost.open = true;
    state.heat_map.on = true;
    state.cost.start(state.doc.shaded_setup(state.settings.pow), "the worksheet".into());
    let start = Instant::now();
    while state.cost.study.is_none() || state.heat_map.heat.is_none() {
        if start.elapsed().as_secs() > 300 {
            anyhow::bail!(crate::t!("err-study-timeout"));
        }
        if let Some(e) = &state.cost.error {
            anyhow::bail!("{e}");
        }
        time_ui_frames(ctx, &mut state, size, 1, |_, _| {});
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    Ok(state)
}

/// An edit made before a timed frame (the frame's number given).
type StateChange = Box<dyn FnMut(&mut AppState, u32)>;

/// Presentation mode while the light is dragged: per shading, (ui, tessellation, total)
/// median and p95 in ms.
fn ui_presenting(a: &UiBench) -> Result<()> {
    let size = if a.width == 1440.0 && a.height == 900.0 { [1920.0, 1080.0] } else { [a.width, a.height] };
    let ctx = egui::Context::default();
    println!(
        "# {}",
        crate::t!(
            "bench-ui-present-header",
            width = size[0].to_string(),
            height = size[1].to_string(),
            frames = a.frames.to_string()
        )
    );
    println!("case ui_median ui_p95 tessellate_median tessellate_p95 total_median total_p95 image_px");
    for shading in [Shading::Gouraud, Shading::Phong] {
        let mut state = AppState::worksheet();
        state.ui.layout.presenting = true;
        state.ui.layout.drawer_open = true;
        let mut d = state.doc.clone();
        d.view.shading = shading;
        state.apply(d);
        // Settle the layout (panel sizes, fonts) before timing.
        time_ui_frames(&ctx, &mut state, size, 5, |_, _| {});
        let z0 = state.doc.scene.lights[0].position.z;
        let (mut u, mut t) = time_ui_frames(&ctx, &mut state, size, a.frames, drag_light_z(z0));
        let [um, up, tm, tp, sm, sp] = figures(&mut u, &mut t);
        let px = state.shaded.main.image_px();
        println!("drag_{} {um:.2} {up:.2} {tm:.2} {tp:.2} {sm:.2} {sp:.2} {px}", shading.label().to_lowercase());
    }
    Ok(())
}

/// Times the UI as `a` asks, printing the figures (`phonglab bench ui`).
pub fn run(a: &UiBench) -> Result<()> {
    if a.present {
        return ui_presenting(a);
    }
    let size = [a.width, a.height];
    let ctx = egui::Context::default();
    let mut state = all_panels_open(&ctx, size)?;
    println!(
        "# {}",
        crate::t!(
            "bench-ui-header",
            width = a.width.to_string(),
            height = a.height.to_string(),
            frames = a.frames.to_string()
        )
    );
    println!("case ui_median ui_p95 tessellate_median tessellate_p95 total_median");
    let z0 = state.doc.scene.lights[0].position.z;
    let cases: [(&str, StateChange); 3] = [
        ("idle", Box::new(|_, _| {})),
        ("slider_move", Box::new(drag_light_z(z0))),
        (
            "auto_rotate",
            Box::new(|s, _| {
                s.doc.view.auto_rotate = true;
            }),
        ),
    ];
    for (name, change) in cases {
        let (mut u, mut t) = time_ui_frames(&ctx, &mut state, size, a.frames, change);
        let [um, up, tm, tp, sm, _] = figures(&mut u, &mut t);
        println!("{name} {um:.2} {up:.2} {tm:.2} {tp:.2} {sm:.2}");
    }
    Ok(())
}
