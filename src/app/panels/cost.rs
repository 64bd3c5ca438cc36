//! "Cost of accuracy": the core's study ([`phonglab_core::cost`]) run in the background on
//! the current scene and object, shown as a chart (time across, error up, every point
//! labelled) and a table. (The error heat map beside the shaded view is the view's own:
//! [`crate::app::panels::shaded::heat_map`].)
//!
//! Work runs on its own thread ([`Worker`]) with a progress bar; the UI never waits for
//! it, and closing the panel or starting again cancels what is running.

use std::sync::Arc;

use phonglab_core::ShadedSetup;
use phonglab_core::cost::{self, Setup, Study, Timing};

use crate::app::editing::worker::Worker;
pub use crate::app::panels::shaded::heat_map::APP_SIZE;
use crate::paint::cost_chart::{BACKGROUND, cost_chart_ui, cost_table_ui, takeaways};
use crate::t;

/// The panel's state.
#[derive(Default)]
pub struct CostState {
    /// The window is open.
    pub open: bool,
    /// The last finished study, and what it was of.
    pub study: Option<(Arc<Study>, String)>,
    /// The study under way.
    pub running: Option<Worker<Study>>,
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

    /// Is a study being computed?
    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// Collects finished work; returns whether something is still running.
    pub fn poll(&mut self) -> bool {
        if let Some(w) = &self.running
            && let Some(r) = w.poll()
        {
            match r {
                Ok(Some(s)) => self.study = Some((Arc::new(s), std::mem::take(&mut self.pending_about))),
                Ok(None) => {}
                Err(e) => self.error = Some(t!("cost-failed", error = e.clone())),
            }
            self.running = None;
        }
        self.running.is_some()
    }
}

/// The "Cost of accuracy" window: its study is of `doc`'s shaded view as it is drawn with
/// the power function `pow`.
pub fn cost_window_ui(
    ctx: &egui::Context,
    cost: &mut CostState,
    doc: &phonglab_core::Document,
    pow: phonglab_core::PowFn,
) {
    if !cost.open {
        if cost.running.is_some() {
            cost.running = None; // closing cancels
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
                let busy = cost.running.is_some();
                if ui.add_enabled(!busy, egui::Button::new(t!("cost-run"))).clicked() {
                    let about =
                        format!("{}, {}", doc.view.object.label(), phonglab_core::library::localised_name(&doc.name));
                    cost.start(doc.shaded_setup(pow), about);
                }
                if busy && ui.button(t!("cancel")).clicked() {
                    cost.running = None;
                }
            });
            if let Some(w) = &cost.running {
                let p = w.progress();
                ui.add(
                    egui::ProgressBar::new(p.done as f32 / p.total.max(1) as f32)
                        .text(format!("{}/{}: {}", p.done, p.total, p.what))
                        .show_percentage(),
                );
            }
            if let Some(e) = &cost.error {
                ui.colored_label(crate::app::widgets::palette::ERROR, e);
            }
            if let Some((study, about)) = &cost.study {
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
    cost.open = open;
}
