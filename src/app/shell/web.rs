//! The app in a browser (`scripts/web` builds it): the same window as the desktop's, started
//! on the page's canvas by eframe's web runner, on WebGPU where the browser has it and on
//! WebGL2 otherwise (the shaded view then runs the scene's generated WGSL through wgpu's
//! WebGL2 backend, or falls back to the CPU renderer, on the page's one thread). What
//! differs from the desktop is in [`crate::platform`]: the session lives in `localStorage`,
//! files come from the browser's chooser and drops and leave as downloads, the language is
//! the browser's.
//!
//! The page's probe, `phonglab_probe()` (a JSON string), tells a test what the window shows:
//! the vertex colour, who drew the shaded view, and where the named controls are.

use std::cell::RefCell;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use super::frame::app_ui;
use super::session;
use super::session_loop::{BROWSER_EVERY, SessionLoop, restore};
use crate::app::panels::shaded::gpu::RendererChoice;
use crate::app::shell::state::AppState;
use crate::platform::clock::Instant;

thread_local! {
    static PROBE: RefCell<String> = const { RefCell::new(String::new()) };
    /// Whether a page has asked for the probe: from then on each frame writes it; until
    /// then the frames do no work for it.
    static PROBED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// The window's context, for the probe's first call to ask for a frame.
    static WINDOW: RefCell<Option<egui::Context>> = const { RefCell::new(None) };
}

/// What the window showed last frame, as JSON (see the module's documentation); empty
/// until a frame has been drawn since the first call.
#[wasm_bindgen]
pub fn phonglab_probe() -> String {
    if !PROBED.replace(true) {
        WINDOW.with(|w| w.borrow().as_ref().map(egui::Context::request_repaint));
    }
    PROBE.with(|p| p.borrow().clone())
}

/// The app on a page: its state and the text of the session it last kept.
struct WebApp {
    state: AppState,
    session: SessionLoop,
    frames: u64,
    /// The last frame's time in `app_ui` (layout, the scene's evaluation, the CPU render).
    ui_ms: f64,
    /// The address asked for the benchmark (read once, at the start).
    bench_asked: bool,
    /// The benchmark's figures, when the address asked for them.
    bench: Option<serde_json::Value>,
    /// `?picture=bench`: the page shows the benchmark scene's picture instead of the window.
    bench_picture: Option<BenchPicture>,
    /// Who drew the benchmark picture, or why it was not drawn.
    bench_drawn_by: Result<String, String>,
}

impl WebApp {
    fn new(cc: &eframe::CreationContext<'_>) -> Self {
        // The mesh this page's session opened, before the session that names it.
        let mesh_lost = crate::platform::storage::restore_meshes().err();
        let stored = crate::platform::storage::load_browser_session();
        let (session, notices) = session::Session::from_text(stored.as_deref());
        let mut state = restore(&session, notices);
        if let Some(why) = mesh_lost {
            state.message = Some(crate::app::editing::message::Message::Refused(why));
        }
        state.gpu = cc.wgpu_render_state.as_ref().map(crate::app::panels::shaded::gpu::install);
        state.view_options.renderer = renderer_asked();
        // `?open=director`: the director's view open from the start (for its test).
        state.director.open |= url_asks("open", "director");
        // `?open=share`: the Share window open from the start (for its test).
        if url_asks("open", "share") {
            state.share.open_with(state.ui.layout.presenting);
        }
        // A shared link: the scene in the address's fragment (never sent to the host).
        let hash = web_sys::window().and_then(|w| w.location().hash().ok()).unwrap_or_default();
        if hash.len() > 1 {
            super::shared_link::open_fragment(&mut state, &hash[1..]);
        }
        WINDOW.with(|w| *w.borrow_mut() = Some(cc.egui_ctx.clone()));
        WebApp {
            state,
            session: SessionLoop::new(session, BROWSER_EVERY),
            frames: 0,
            ui_ms: 0.0,
            bench_asked: url_asks("bench", "render"),
            bench: None,
            bench_picture: BenchPicture::asked(),
            bench_drawn_by: Ok(String::new()),
        }
    }

    /// `?bench=render`: the CPU renderer on the benchmark scene at 512x512 (what `phonglab
    /// bench render --size 512` times on the desktop), 20 frames per object and shading,
    /// on the page's one thread; the figures go into the probe.
    fn bench_once(&mut self) {
        if self.bench.is_some() || !self.bench_asked {
            return;
        }
        use phonglab_core::Shading;
        let figures = phonglab_core::bench::render_figures(20, 512, |_, s| s != Shading::Flat);
        self.bench = Some(match figures {
            Ok(f) => f
                .iter()
                .map(|f| serde_json::json!({"object": f.object, "shading": f.shading.label(), "ms_per_frame": f.ms_per_frame}))
                .collect(),
            Err(e) => serde_json::json!({ "error": e.to_string() }),
        });
    }

    fn probe(&self, ctx: &egui::Context) {
        let colour = self.state.evaluate().ok().map(|e| e.front.primary);
        let caption = match (&self.bench_picture, &self.bench_drawn_by) {
            (None, _) => crate::app::panels::shaded::drawn_caption(&self.state.shaded.main),
            (Some(_), Ok(by)) => by.clone(),
            (Some(_), Err(e)) => format!("not drawn: {e}"),
        };
        let landmarks: serde_json::Map<String, serde_json::Value> = crate::app::widgets::fields::landmarks(ctx)
            .into_iter()
            .map(|(k, r)| (k, serde_json::json!([r.min.x, r.min.y, r.width(), r.height()])))
            .collect();
        let probe = serde_json::json!({
            "frames": self.frames,
            "ui_ms": self.ui_ms,
            "bench": self.bench,
            "scene": self.state.doc.name,
            "colour": colour,
            "drawn_by": caption,
            "gpu": self.state.gpu.is_some(),
            "pixels_per_point": ctx.pixels_per_point(),
            "landmarks": landmarks,
            "language": self.state.ui.layout.locale().lang.code(),
            "object": format!("{:?}", self.state.doc.view.object).to_lowercase(),
            "mesh_triangles": self.state.doc.view.obj.as_ref().and_then(|_| self.state.doc.view.obj_mesh().ok()).map(|o| o.mesh.triangle_count()),
            "presenting": self.state.ui.layout.presenting,
            "message": self.state.message.as_ref().map(|m| format!("{m:?}")),
        });
        PROBE.with(|p| *p.borrow_mut() = probe.to_string());
    }
}

impl eframe::App for WebApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.bench_once();
        self.frames += 1;
        if let Some(picture) = &mut self.bench_picture {
            crate::app::widgets::fields::record_landmarks(ui.ctx());
            self.bench_drawn_by = picture.picture_ui(ui, self.state.gpu.is_some());
            self.probe(ui.ctx());
            return;
        }
        if PROBED.get() {
            crate::app::widgets::fields::record_landmarks(ui.ctx());
            let started = Instant::now();
            app_ui(ui, &mut self.state);
            self.ui_ms = started.elapsed().as_secs_f64() * 1e3;
            self.probe(ui.ctx());
        } else {
            app_ui(ui, &mut self.state);
        }
        self.session.after_frame(&self.state);
        self.session.write_when_due(&mut self.state, ui.ctx());
    }
}

/// Who draws the shaded view, as the page's address asks (`?renderer=gpu`, `cpu` or `auto`,
/// the desktop's `--renderer`): by default the GPU when the browser's adapter is a real
/// one, else the CPU renderer.
fn renderer_asked() -> RendererChoice {
    if url_asks("renderer", "gpu") {
        RendererChoice::Gpu
    } else if url_asks("renderer", "cpu") {
        RendererChoice::Cpu
    } else {
        RendererChoice::Auto
    }
}

/// Does the page's address say `key=value`?
fn url_asks(key: &str, value: &str) -> bool {
    let search = web_sys::window().and_then(|w| w.location().search().ok()).unwrap_or_default();
    web_sys::UrlSearchParams::new_with_str(&search).ok().and_then(|p| p.get(key)).as_deref() == Some(value)
}

/// Starts the app on the page's `<canvas id="phonglab">`.
pub fn start() {
    eframe::WebLogger::init(log::LevelFilter::Warn).ok();
    let lang = crate::platform::language::system();
    crate::locale::set_default(crate::locale::Locale::of(lang));
    wasm_bindgen_futures::spawn_local(async {
        let Some(document) = web_sys::window().and_then(|w| w.document()) else { return };
        let Some(canvas) =
            document.get_element_by_id("phonglab").and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok())
        else {
            log::error!("the page has no <canvas id=\"phonglab\">");
            return;
        };
        let started = eframe::WebRunner::new()
            .start(canvas, eframe::WebOptions::default(), Box::new(|cc| Ok(Box::new(WebApp::new(cc)))))
            .await;
        if let Some(loading) = document.get_element_by_id("loading") {
            match started {
                Ok(()) => loading.remove(),
                Err(e) => loading.set_text_content(Some(&format!("phonglab could not start: {e:?}"))),
            }
        }
    });
}

/// `?picture=bench&object=sphere|teapot&shading=gouraud|phong`: the page shows only the
/// benchmark scene's first frame (what `phonglab render --bench-frame 0` draws natively),
/// 256 pixels square, drawn by the renderer the address asks for, so that a test can put
/// the canvas's picture beside the desktop's image.
struct BenchPicture {
    /// The benchmark's frame 0 and the object (tessellated once, not every frame).
    scene: phonglab_core::Scene,
    mesh: std::sync::Arc<phonglab_core::mesh::Mesh>,
    shading: phonglab_core::Shading,
    gpu: bool,
    /// The CPU renderer's picture, drawn once.
    texture: Option<egui::TextureHandle>,
    /// Where the GPU reports a refused program.
    error: std::sync::Arc<std::sync::Mutex<Option<String>>>,
}

/// The benchmark picture's side in physical pixels.
const BENCH_PICTURE_PX: u32 = 256;

impl BenchPicture {
    /// The picture the address asks for, if it asks for one.
    fn asked() -> Option<Self> {
        use phonglab_core::Shading;
        if !url_asks("picture", "bench") {
            return None;
        }
        let [(_, sphere), (_, teapot)] = phonglab_core::bench::bench_meshes();
        let mesh = if url_asks("object", "teapot") { teapot } else { sphere };
        let shading = if url_asks("shading", "phong") { Shading::Phong } else { Shading::Gouraud };
        Some(BenchPicture {
            scene: phonglab_core::presets::bench_scene(0),
            mesh: std::sync::Arc::new(mesh),
            shading,
            gpu: url_asks("renderer", "gpu"),
            texture: None,
            error: Default::default(),
        })
    }

    /// Draws the picture at the window's top left; its rect is the landmark "bench-picture".
    fn picture_ui(&mut self, ui: &mut egui::Ui, gpu: bool) -> Result<String, String> {
        let ppp = ui.ctx().pixels_per_point();
        let side = BENCH_PICTURE_PX as f32 / ppp;
        let (rect, _) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
        crate::app::widgets::fields::landmark(ui.ctx(), "bench-picture", rect);
        let job = phonglab_core::shaded::bench_job(&self.scene, &self.mesh, self.shading);
        if self.gpu && gpu {
            if let Some(e) = self.error.lock().unwrap_or_else(std::sync::PoisonError::into_inner).clone() {
                return Err(e);
            }
            let shader = crate::paint::gpu::wgsl_for(job.scene, job.options, job.mode.shading())?;
            let uniforms = crate::paint::gpu::uniform_bytes(&shader.uniforms, job.scene, &job.clip_from_object)?;
            let picture = crate::app::panels::shaded::gpu::GpuImage {
                slot: u64::MAX,
                wgsl: shader.vertex.into(),
                uniforms,
                mesh: self.mesh.clone(),
                background: job.background,
                px: BENCH_PICTURE_PX,
                error: self.error.clone(),
            };
            crate::app::panels::shaded::gpu::paint(ui, rect, picture);
            return Ok("GPU".into());
        }
        if self.texture.is_none() {
            let size = BENCH_PICTURE_PX as usize;
            let mut renderer = phonglab_core::render::Renderer::new();
            let (img, _) = renderer.render(&job, size, size).map_err(|e| e.to_string())?;
            let image = egui::ColorImage::from_rgba_unmultiplied([img.width, img.height], &img.rgba);
            self.texture = Some(ui.ctx().load_texture("bench picture", image, egui::TextureOptions::NEAREST));
        }
        if let Some(t) = &self.texture {
            ui.painter().image(
                t.id(),
                rect,
                egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0)),
                egui::Color32::WHITE,
            );
        }
        Ok("CPU".into())
    }
}
