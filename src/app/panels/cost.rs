//! "Cost of accuracy": the core's study ([`phonglab_core::cost`]) run in the background on
//! the current scene and object, shown as a chart (time across, error up, every point
//! labelled) and a table; and an error heat map of the shaded view against the reference.
//!
//! Work runs on its own thread ([`Worker`]) with a progress bar; the UI never waits for
//! it, and closing the panel or starting again cancels what is running.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError};
use std::sync::{Arc, Mutex};

use egui::{ColorImage, TextureHandle, TextureOptions, Ui};

use crate::paint::cost_chart::{BACKGROUND, HEAT_FULL_SCALE, cost_chart_ui, cost_table_ui, takeaways};
use phonglab_core::ShadedSetup;
use phonglab_core::cost::{self, ErrorStats, Progress, Setup, Study, Timing};
use phonglab_core::{locale, t};

/// Image size of the app's study and heat map, in pixels (the CLI's default is larger).
/// Smaller in the browser, where the study runs on the page's one thread, before the next
/// frame ([`crate::platform::threads`]).
pub const APP_SIZE: usize = if crate::platform::threads::BACKGROUND { 256 } else { 128 };

/// A computation on its own thread, with progress and cancellation.
pub struct Worker<T> {
    progress: Arc<Mutex<Progress>>,
    cancel: Arc<AtomicBool>,
    result: Receiver<Result<Option<T>, String>>,
}

impl<T: Send + 'static> Worker<T> {
    /// Starts `job` on its own thread, rendering with `threads` threads of its own (0: one
    /// per core) so that it does not queue behind, or in front of, the UI's own renders.
    /// It reports progress through the callback, which returns `false` once the worker is
    /// cancelled (or dropped).
    pub fn spawn(
        threads: usize,
        job: impl FnOnce(&mut dyn FnMut(&Progress) -> bool) -> Result<Option<T>, String> + Send + 'static,
    ) -> Self {
        let progress = Arc::new(Mutex::new(Progress { done: 0, total: 1, what: "starting".into() }));
        let cancel = Arc::new(AtomicBool::new(false));
        let (tx, rx) = std::sync::mpsc::channel();
        let (p, c) = (progress.clone(), cancel.clone());
        crate::platform::threads::run_in_background(move || {
            let mut report = |now: &Progress| {
                if let Ok(mut g) = p.lock() {
                    *g = now.clone();
                }
                !c.load(Ordering::Relaxed)
            };
            let run = || {
                // A panic in the job must not take the app down: it becomes a message.
                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job(&mut report)))
                    .unwrap_or_else(|_| Err("the computation failed unexpectedly".into()))
            };
            let r = crate::platform::threads::with_pool(threads, run)
                .unwrap_or_else(|e| Err(format!("no thread pool: {e}")));
            let _ = tx.send(r);
        });
        Self { progress, cancel, result: rx }
    }

    /// Where it is.
    pub fn progress(&self) -> Progress {
        self.progress.lock().map(|g| g.clone()).unwrap_or(Progress { done: 0, total: 1, what: String::new() })
    }

    /// The result once finished (`Ok(None)`: cancelled).
    pub fn poll(&self) -> Option<Result<Option<T>, String>> {
        match self.result.try_recv() {
            Ok(r) => Some(r),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(Err("the computation stopped".into())),
        }
    }
}

impl<T> Drop for Worker<T> {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
}

/// A heat map of one view against the reference.
pub struct HeatMap {
    /// What it was computed for (the scene, the view, the options).
    pub key: String,
    /// Its error figures.
    pub error: ErrorStats,
    /// Milliseconds per frame of the view at this size.
    pub ms: f64,
    image: ColorImage,
    texture: Option<TextureHandle>,
}

/// The panel's state.
#[derive(Default)]
pub struct CostState {
    /// The window is open.
    pub open: bool,
    /// Show the shaded view's error heat map.
    pub heat_map: bool,
    /// The last finished study, and what it was of.
    pub study: Option<(Arc<Study>, String)>,
    /// The study under way.
    pub running: Option<Worker<Study>>,
    /// The last heat map.
    pub heat: Option<HeatMap>,
    heat_running: Option<(String, Worker<HeatMap>)>,
    /// Why the last computation failed.
    pub error: Option<String>,
    /// What the running study is of.
    pending_about: String,
}

impl CostState {
    /// Starts a study of the shaded view `shaded`.
    pub fn start(&mut self, shaded: ShadedSetup, about: String) {
        self.error = None;
        // The study times frames as the shaded view draws them: on every core.
        self.running = Some(Worker::spawn(0, move |progress| {
            let setup = Setup::new(&shaded, APP_SIZE, BACKGROUND);
            cost::run(&setup, Timing::QUICK, progress).map_err(|e| e.to_string())
        }));
        self.pending_about = about;
    }

    /// Is a study or a heat map being computed?
    pub fn busy(&self) -> bool {
        self.running.is_some() || self.heat_running.is_some()
    }

    /// Collects finished work; returns whether something is still running.
    pub fn poll(&mut self) -> bool {
        if let Some(w) = &self.running
            && let Some(r) = w.poll()
        {
            match r {
                Ok(Some(s)) => self.study = Some((Arc::new(s), std::mem::take(&mut self.pending_about))),
                Ok(None) => {}
                Err(e) => self.error = Some(t!("cost-failed", error = e.to_string())),
            }
            self.running = None;
        }
        if let Some((_, w)) = &self.heat_running
            && let Some(r) = w.poll()
        {
            match r {
                Ok(Some(h)) => self.heat = Some(h),
                Ok(None) => {}
                Err(e) => self.error = Some(t!("heat-map-failed", error = e.to_string())),
            }
            self.heat_running = None;
        }
        self.running.is_some() || self.heat_running.is_some()
    }

    /// Makes sure a heat map of the shaded view `shaded` is on its way (or there).
    pub fn want_heat_map(&mut self, shaded: &ShadedSetup) {
        let key = format!("{shaded:?}");
        if self.heat.as_ref().is_some_and(|h| h.key == key)
            || self.heat_running.as_ref().is_some_and(|(k, _)| *k == key)
        {
            return;
        }
        if self.heat_running.is_some() {
            // One at a time: the newest view is asked for when this one is done.
            return;
        }
        let (shaded, k) = (shaded.clone(), key.clone());
        // The heat map follows every edit: one thread, so the UI's own renders stay quick.
        let worker = Worker::spawn(1, move |progress| {
            let setup = Setup::new(&shaded, APP_SIZE, BACKGROUND);
            if !progress(&Progress { done: 0, total: 2, what: "reference".into() }) {
                return Ok(None);
            }
            let reference = cost::reference(&setup).map_err(|e| e.to_string())?;
            if !progress(&Progress { done: 1, total: 2, what: "the view".into() }) {
                return Ok(None);
            }
            let view = &shaded.view;
            let m = cost::measure_view(&setup, view, view.shading, shaded.options, &reference, Timing::ONCE)
                .map_err(|e| e.to_string())?;
            let rgba = cost::heat_map_rgba(&m.map, &reference, HEAT_FULL_SCALE);
            let image = ColorImage::from_rgba_unmultiplied([reference.size, reference.size], &rgba);
            Ok(Some(HeatMap { key: k, error: m.error, ms: m.ms, image, texture: None }))
        });
        self.heat_running = Some((key, worker));
    }
}

/// The "Cost of accuracy" window.
pub fn cost_window_ui(ctx: &egui::Context, state: &mut crate::app::shell::state::AppState) {
    if !state.cost.open {
        if state.cost.running.is_some() {
            state.cost.running = None; // closing cancels
        }
        return;
    }
    let mut open = true;
    let screen = ctx.content_rect();
    egui::Window::new(t!("cost-of-accuracy"))
        .open(&mut open)
        .default_pos(egui::pos2(screen.width() * 0.12, 60.0))
        .default_size(egui::vec2((screen.width() * 0.76).max(640.0), (screen.height() * 0.8).max(480.0)))
        .resizable(true)
        .vscroll(true)
        .show(ctx, |ui| {
            ui.label(t!("cost-intro"));
            ui.horizontal(|ui| {
                let busy = state.cost.running.is_some();
                if ui.add_enabled(!busy, egui::Button::new(t!("cost-run"))).clicked() {
                    let about = format!(
                        "{}, {}",
                        state.doc.view.object.label(),
                        phonglab_core::library::localised_name(&state.doc.name)
                    );
                    state.cost.start(state.doc.shaded_setup(state.settings.pow), about);
                }
                if busy && ui.button(t!("cancel")).clicked() {
                    state.cost.running = None;
                }
            });
            if let Some(w) = &state.cost.running {
                let p = w.progress();
                ui.add(
                    egui::ProgressBar::new(p.done as f32 / p.total.max(1) as f32)
                        .text(format!("{}/{}: {}", p.done, p.total, p.what))
                        .show_percentage(),
                );
            }
            if let Some(e) = &state.cost.error {
                ui.colored_label(crate::app::widgets::palette::ERROR, e);
            }
            if let Some((study, about)) = &state.cost.study {
                ui.separator();
                ui.strong(t!("cost-about", about = about, size = study.size.to_string()));
                // The chart takes the window's width, and height in proportion.
                let height = (ui.available_width() * 0.55).clamp(260.0, 900.0);
                cost_chart_ui(ui, study, height);
                for t in takeaways(study) {
                    ui.label(t);
                }
                egui::CollapsingHeader::new(t!("cost-table"))
                    .id_salt("cost table")
                    .default_open(true)
                    .show(ui, |ui| cost_table_ui(ui, study));
            }
        });
    state.cost.open = open;
}

/// The heat map beside the shaded view, `side` points square, with its caption.
pub fn heat_map_ui(ui: &mut Ui, state: &mut crate::app::shell::state::AppState, side: f32) {
    ui.vertical(|ui| {
        let Some(h) = &mut state.cost.heat else {
            ui.small(t!("heat-map-computing"));
            return;
        };
        let tex = h
            .texture
            .get_or_insert_with(|| ui.ctx().load_texture("error heat map", h.image.clone(), TextureOptions::NEAREST));
        let caption = ui.small(t!(
            "heat-map-caption",
            mean = locale::decimal(&format!("{:.2}", h.error.mean)),
            max = format!("{:.0}", h.error.max),
            share = locale::decimal(&format!("{:.1}", 100.0 * h.error.share_over_one)),
            white = HEAT_FULL_SCALE.to_string()
        ));
        ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(caption.id);
    });
}
