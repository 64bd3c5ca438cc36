//! The shaded view drawn on the GPU through its egui_wgpu paint callback, headless on
//! wgpu's software adapter (llvmpipe here; the choice "GPU (even a software one)" makes it
//! draw there). What the view says about who drew it is checked against what ran: the CPU
//! renderer's texture exists only when the CPU drew, and the window's pixels under the
//! view are the CPU renderer's picture of the same scene.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::panels::shaded::DrawnBy;
use phonglab::app::panels::shaded::gpu::{self as gpu_view, RendererChoice};
use phonglab::app::{AppState, app_ui};
use phonglab::io::image::Difference;
use phonglab_core::render::Renderer;
use phonglab_core::{PowFn, Shading};

const SIZE: [f32; 2] = [1280.0, 800.0];

/// The app with its GPU view installed on a software adapter, as `choice` says.
fn harness(choice: RendererChoice, shading: Shading) -> Harness<'static, AppState> {
    let rs = egui_kittest::wgpu::create_render_state(
        egui_kittest::wgpu::default_wgpu_setup(),
        eframe::egui_wgpu::RendererOptions::PREDICTABLE,
    );
    let mut state = AppState::worksheet();
    state.gpu = Some(gpu_view::install(&rs));
    state.view_options.renderer = choice;
    state.doc.view.shading = shading;
    // The sphere: the GPU and CPU rasters are compared pixel for pixel on it.
    state.doc.view.object = phonglab_core::ObjectKind::Sphere;
    let mut h = Harness::builder()
        .with_size(SIZE)
        .renderer(egui_kittest::wgpu::WgpuTestRenderer::from_render_state(rs))
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(2);
    h
}

/// The window's pixels under the shaded view against the CPU renderer's picture of the
/// same document.
fn compare_with_cpu(h: &mut Harness<'static, AppState>) -> Difference {
    // The first image in the window is the shaded view.
    let rect = h.get_all_by_role(egui::accesskit::Role::Image).next().expect("the shaded view").rect();
    let screen = h.render().expect("the wgpu test renderer draws");
    let px = rect.width().round() as usize;
    let state = h.state();
    let setup = state.doc.shaded_setup(PowFn::Exact);
    let mesh = state.doc.view.mesh();
    let mut renderer = Renderer::new();
    let cpu = renderer.render(&setup.job(&mesh), px, px).unwrap().0;
    let bg = state.doc.view.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    let (x0, y0) = (rect.min.x.round() as u32, rect.min.y.round() as u32);
    // A band along the edges is left out: a light outside the view is marked there.
    let band = 40;
    let mut under_view = Vec::new();
    let mut cpu_inner = Vec::new();
    for y in band..px - band {
        for x in band..px - band {
            under_view.extend_from_slice(&screen.get_pixel(x0 + x as u32, y0 + y as u32).0);
            cpu_inner.extend_from_slice(&cpu.rgba[(y * px + x) * 4..(y * px + x) * 4 + 4]);
        }
    }
    Difference::of(&under_view, &cpu_inner, bg)
}

fn assert_matches(d: &Difference, what: &str) {
    // The start camera frames the teapot whole (distance 2.8), so the sphere covers about
    // 17 000 of the compared pixels at this window size.
    assert!(d.both > 12_000, "{what}: {d}");
    assert!(d.only_one() as f64 <= 0.002 * d.both as f64, "{what}: coverage differs: {d}");
    assert!(d.mad.iter().all(|m| *m <= 1.0), "{what}: {d}");
}

#[test]
fn asked_for_the_gpu_the_view_runs_the_generated_wgsl_and_draws_the_cpu_renderers_picture() {
    for shading in [Shading::Gouraud, Shading::Phong] {
        let mut h = harness(RendererChoice::Gpu, shading);
        let drawn = h.state().shaded.main.drawn_by.clone();
        assert!(matches!(&drawn, DrawnBy::Gpu { adapter } if adapter.contains("llvmpipe")), "{drawn:?}");
        // The CPU renderer did not run: it has no picture.
        assert_eq!(h.state().shaded.main.image_px(), 0);
        h.get_by_label_contains("on the GPU (llvmpipe");
        let d = compare_with_cpu(&mut h);
        println!("{shading:?}: {d}");
        assert_matches(&d, &format!("{shading:?}"));
    }
}

#[test]
fn the_picture_follows_an_edit() {
    let mut h = harness(RendererChoice::Gpu, Shading::Phong);
    let before = h.render().unwrap();
    let mut doc = h.state().doc.clone();
    doc.scene.material.diffuse = glam::DVec4::new(0.1, 0.6, 0.9, 1.0);
    assert!(h.state_mut().apply(doc));
    h.run_steps(2);
    assert!(matches!(h.state().shaded.main.drawn_by, DrawnBy::Gpu { .. }));
    assert_matches(&compare_with_cpu(&mut h), "after the edit");
    assert_ne!(before.as_raw(), h.render().unwrap().as_raw(), "the edit changed the picture");
}

#[test]
fn on_a_software_adapter_the_cpu_renderer_draws_and_says_why() {
    let h = harness(RendererChoice::Auto, Shading::Phong);
    match &h.state().shaded.main.drawn_by {
        DrawnBy::Cpu { why } => assert!(why.contains("software"), "{why}"),
        other => panic!("{other:?}"),
    }
    assert!(h.state().shaded.main.image_px() > 0);
    h.get_by_label_contains("ms per frame on the CPU");
}

#[test]
fn flat_shading_and_the_pow_study_stay_on_the_cpu() {
    let h = harness(RendererChoice::Gpu, Shading::Flat);
    assert!(matches!(&h.state().shaded.main.drawn_by, DrawnBy::Cpu { why } if why.contains("Flat")));
    let mut h = harness(RendererChoice::Gpu, Shading::Phong);
    h.state_mut().settings.pow = PowFn::Schlick;
    h.run_steps(2);
    assert!(matches!(&h.state().shaded.main.drawn_by, DrawnBy::Cpu { why } if why.contains("power function")));
    // And back on the GPU when the exact power returns.
    h.state_mut().settings.pow = PowFn::Exact;
    h.run_steps(2);
    assert!(matches!(h.state().shaded.main.drawn_by, DrawnBy::Gpu { .. }));
}

#[test]
fn the_renderer_is_chosen_under_view_options() {
    let mut h = harness(RendererChoice::Gpu, Shading::Gouraud);
    h.get_by_label("View options").click();
    // The header opens over a few frames (egui animates it).
    h.run_steps(12);
    h.get_by_label_contains("Drawn on the GPU (llvmpipe");
    h.get_by_label("Renderer").click();
    h.run_steps(2);
    h.get_by_label("CPU (the reference)").click();
    h.run_steps(3);
    assert_eq!(h.state().view_options.renderer, RendererChoice::Cpu);
    h.get_by_label_contains("Drawn by the CPU renderer: the CPU renderer is chosen");
    assert!(h.state().shaded.main.image_px() > 0);
}

#[test]
fn the_shader_window_shows_the_program_the_gpu_runs() {
    for shading in [Shading::Gouraud, Shading::Phong] {
        let mut h = harness(RendererChoice::Gpu, shading);
        h.state_mut().shader.open = true;
        h.state_mut().shader.wgsl = true;
        h.run_steps(2);
        let state = h.state();
        let setup = state.doc.shaded_setup(PowFn::Exact);
        let runs = phonglab::paint::gpu::wgsl_for(&setup.scene, setup.options, shading).unwrap().vertex;
        assert_eq!(state.shader.shown, runs, "{shading:?}");
    }
}
