//! The window on the desktop: eframe's native runner, the state restored from and kept in
//! phonglab's own session ([`super::session`], through [`super::session_loop`]), and the
//! termination signals that save it before the window closes ([`super::shutdown`]).

use egui::Ui;

use super::files;
use super::frame::app_ui;
use super::session::Session;
use super::session_loop::{DESKTOP_EVERY, SessionLoop, restore};
use super::shutdown::Shutdown;
use super::state::AppState;
use crate::app::panels::shaded::gpu::{self as gpu_view, RendererChoice};
use crate::t;

/// The eframe application: the state, and the session it is kept in.
pub struct PhongLabApp {
    state: AppState,
    session: SessionLoop,
    shutdown: Shutdown,
}

impl PhongLabApp {
    /// Restores the last session, then opens `file` when one is given.
    pub fn new(
        cc: &eframe::CreationContext<'_>,
        (session, notices): (Session, Vec<String>),
        file: Option<std::path::PathBuf>,
        renderer: RendererChoice,
    ) -> Self {
        let mut state = restore(&session, notices);
        // The shaded view can run the scene's generated WGSL on eframe's adapter.
        state.gpu = cc.wgpu_render_state.as_ref().map(gpu_view::install);
        state.view_options.renderer = renderer;
        state.files.dialogs = crate::app::panels::files::Dialogs::System;
        // A file named on the command line wins over the restored session.
        if let Some(path) = file {
            files::open_at_start(&mut state, &path);
        }
        let shutdown = Shutdown::install(&cc.egui_ctx);
        Self { state, session: SessionLoop::new(session, DESKTOP_EVERY), shutdown }
    }
}

impl eframe::App for PhongLabApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        app_ui(ui, &mut self.state);
        // Each change is handed to the signal handler at once, so SIGTERM keeps it.
        if let Some(text) = self.session.after_frame(&self.state)
            && let Some(path) = self.session.session().writer()
        {
            self.shutdown.keep(path, text);
        }
        if self.shutdown.requested() {
            self.session.write_now(&mut self.state);
            ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
        } else {
            self.session.write_when_due(&mut self.state, ui.ctx());
        }
    }

    fn on_exit(&mut self) {
        self.session.write_now(&mut self.state);
    }
}

/// Opens the window, on the scene file `file` when one is given, with the shaded view
/// drawn as `renderer` says. The session is phonglab's own (see [`super::session`]).
pub fn run(file: Option<std::path::PathBuf>, renderer: RendererChoice) -> eframe::Result {
    let opened = match crate::platform::storage::storage_dir() {
        Some(dir) => Session::open(&dir),
        None => (Session::in_memory(), vec![t!("no-session-folder")]),
    };
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("phonglab")
            .with_inner_size([1440.0, 900.0])
            .with_min_inner_size([900.0, 600.0]),
        ..Default::default()
    };
    eframe::run_native("phonglab", options, Box::new(|cc| Ok(Box::new(PhongLabApp::new(cc, opened, file, renderer)))))
}
