//! The app's state: the last valid document, UI choices, and the message of the last refusal.
//!
//! Data flows one way: widgets edit a copy of the [`Document`]; [`AppState::apply`] keeps
//! it if it is valid (or refuses it with a message, keeping the last valid one); the core
//! evaluates it ([`Evaluated`]); panels draw the result.

use phonglab_core::{Document, SceneError, library};

use crate::app::editing::editor::Editor;

pub use crate::app::editing::evaluated::{Evaluated, LightVectors, Precision, SideColors, evaluate};

pub use crate::app::editing::message::Message;
pub use crate::app::panels::vector_plot::Orbit;

/// What the centre drew last frame: the tests and `phonglab screenshot` check it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Geometry {
    /// The shaded view's picture or pictures.
    pub pictures: Vec<egui::Rect>,
    /// The vector plot, when it is shown.
    pub plot: Option<crate::app::panels::vector_plot::PlotGeometry>,
    /// How the centre was arranged.
    pub arrangement: Option<crate::app::shell::centre_layout::Arrangement>,
    /// The arrows drawn on the shaded view's picture.
    pub arrows: Vec<crate::app::panels::shaded::ArrowOnObject>,
    /// The spotlights' cones drawn on it: each rim's bounds.
    pub cones: Vec<egui::Rect>,
    /// The band under the squares where the things to try were offered, if they were.
    pub suggestions: Option<egui::Rect>,
    /// The reflection lobe, when it is shown: its legend's and its two plots' rects.
    pub lobe: Option<crate::app::panels::lobe::LobeGeometry>,
}

/// The shell's own choices: the window's arrangement, what the centre drew, the keys'
/// help, the step the arrow keys moved to, and a quit asked for. Each panel keeps its own
/// (`controls`, `view_options`, `files`, `export` ... in [`AppState`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UiState {
    /// The help overlay is open.
    pub show_help: bool,
    /// The window's arrangement (kept across restarts).
    pub layout: crate::app::shell::layout::Layout,
    /// The highlighted step moved this frame: the calculation scrolls to it.
    pub scroll_to_step: bool,
    /// Ctrl+Q was pressed: the window is closing (saving the session).
    pub quit: bool,
    /// What the centre drew last frame.
    pub geometry: Geometry,
    /// Open and Save pressed while a field had the keyboard: done once the field has let
    /// it go and committed what was typed (`true`: a whole frame has passed since).
    pub deferred: Vec<(crate::app::panels::help::Action, bool)>,
}

/// The whole app state.
#[derive(Default)]
pub struct AppState {
    /// The last valid document.
    pub doc: Document,
    /// The shell's own choices.
    pub ui: UiState,
    /// How the document is evaluated and explained: precision, power, side.
    pub settings: crate::app::editing::evaluated::Settings,
    /// The controls' own: the light shown.
    pub controls: crate::app::panels::controls::ControlsState,
    /// The vector plot's orbit.
    pub orbit: Orbit,
    /// The shaded view's own: the demo's corrections shown, the renderer, the mesh path typed.
    pub view_options: crate::app::panels::shaded::ShadedOptions,
    /// The "Things to try" window's.
    pub things: crate::app::panels::things_to_try::TryState,
    /// phonglab's own file chooser, while it is open (where the system's dialog cannot).
    pub chooser: Option<crate::app::panels::chooser::Chooser>,
    /// The scene file's path and the system's dialogs.
    pub files: crate::app::panels::files::FileState,
    /// The Export menu's exercise settings.
    pub export: crate::app::panels::export::ExportState,
    /// The last refusal or notice.
    pub message: Option<Message>,
    /// The shaded view's renderer and texture, kept between frames.
    pub shaded: crate::app::panels::shaded::cache::ShadedCache,
    /// The cost-of-accuracy panel and its background work.
    pub cost: crate::app::panels::cost::CostState,
    /// The error heat map beside the shaded view, and its background work.
    pub heat_map: crate::app::panels::shaded::heat_map::HeatMapState,
    /// Compare: the pinned scene A and its views.
    pub compare: crate::app::panels::compare::CompareState,
    /// Quiz mode: the exercise and the student's answers.
    pub quiz: crate::app::panels::quiz::QuizState,
    /// The Shader window.
    pub shader: crate::app::panels::shader_panel::ShaderState,
    /// The director's view: the scene from outside.
    pub director: crate::app::panels::director::DirectorState,
    /// The Share window: the scene as a link and a QR code.
    pub share: crate::app::panels::share::ShareState,
    /// The wgpu adapter eframe runs on, when there is one (the shaded view can then be
    /// drawn by the scene's generated WGSL).
    pub gpu: Option<crate::app::panels::shaded::gpu::GpuInfo>,
    /// A student's work checked against the scene, shown in the calculation panel.
    pub student: Option<crate::app::panels::student_column::StudentCheck>,
    /// A dropped notebook with outputs (its name and bytes), while the window asks whether
    /// to open it or check it.
    pub student_ask: Option<(String, Vec<u8>)>,
    /// The last student's file checked through File → Check a student's work…: the next
    /// one is chosen from its folder.
    pub student_last: Option<std::path::PathBuf>,
    /// The status a student's check made and what it said, while it is the status shown:
    /// said again in the language shown when that changes.
    pub student_status: Option<(StudentStatus, Message)>,
    /// Undo and redo of the scene's changes.
    pub history: crate::app::editing::history::History,
    /// This frame's time (seconds, egui's clock): a drag's changes within a second are one
    /// undo step.
    pub now: f64,
}

/// Which check made the status shown: the work's (the calculation panel) or the picture's
/// (Compare).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StudentStatus {
    /// A notebook or printed text checked.
    Work,
    /// A picture diagnosed.
    Picture,
}

impl AppState {
    /// What asks for the keyboard before the scene ([`crate::app::panels::help::pressed`]):
    /// phonglab's file chooser or the question of what to do with a dropped notebook (a
    /// choice), else the quiz (numbers). (The share window is not asking: its link follows
    /// the scene the keys change.)
    pub fn asking(&self) -> crate::app::panels::help::Asking {
        use crate::app::panels::help::Asking;
        if self.chooser.is_some() || self.student_ask.is_some() {
            Asking::Choice
        } else if self.quiz.open {
            Asking::Numbers
        } else {
            Asking::Nothing
        }
    }

    /// Starts on the worksheet's scene (modelview 5).
    pub fn worksheet() -> Self {
        Self::default()
    }

    /// Evaluates the document with the chosen precision and power function.
    pub fn evaluate(&self) -> Result<Evaluated, SceneError> {
        evaluate(&self.doc, self.settings.precision, self.settings.pow, self.settings.side)
    }

    /// The document, its history and the message, borrowed for an edit.
    pub fn editor(&mut self) -> Editor<'_> {
        Editor { doc: &mut self.doc, history: &mut self.history, message: &mut self.message, now: self.now }
    }

    /// Keeps `candidate` if it is valid ([`Editor::apply`]). Returns whether it was kept.
    pub fn apply(&mut self, candidate: Document) -> bool {
        self.apply_or_why(candidate).is_ok()
    }

    /// [`Self::apply`], with the validator's reason when it refuses; the light shown stays
    /// one of the scene's.
    pub fn apply_or_why(&mut self, candidate: Document) -> Result<(), String> {
        let r = self.editor().apply_or_why(candidate);
        self.controls.selected_light = self.controls.selected_light.min(self.doc.scene.lights.len().saturating_sub(1));
        r
    }

    /// Back to the start: the worksheet with modelview 5 (UI choices kept, and the user's
    /// mesh offered still).
    pub fn reset_to_worksheet(&mut self) {
        let mut start = Document::default();
        keep_mesh(&self.doc, &mut start);
        let before = std::mem::replace(&mut self.doc, start);
        if before != self.doc {
            self.history.record(&before, &self.doc, Some(&crate::t!("history-reset")), self.now);
        }
        self.controls.selected_light = 0;
        self.message = Some(Message::Info(crate::t!("reset-done")));
    }

    /// Loads a ready-made document. The user's mesh stays offered (the top bar's "Your
    /// mesh") unless the document names a mesh of its own: it goes only when the user
    /// closes it ([`Self::close_mesh`]).
    pub fn load(&mut self, mut doc: Document, what: &str) {
        keep_mesh(&self.doc, &mut doc);
        let before = std::mem::replace(&mut self.doc, doc);
        if before != self.doc {
            self.history.record(&before, &self.doc, Some(&crate::t!("history-open", what = what)), self.now);
        }
        self.controls.selected_light = 0;
        self.message = Some(Message::Info(crate::t!("loaded", what = what)));
    }
}

/// `doc` offering the mesh `before` offered, when it names none of its own (the object
/// shown stays `doc`'s).
fn keep_mesh(before: &Document, doc: &mut Document) {
    if doc.view.obj.is_none() {
        doc.view.obj.clone_from(&before.view.obj);
    }
}

impl AppState {
    /// Sets an experiment up: its scene loaded under its title, the step the last one
    /// highlighted let go, and the controls opened (the drawer, presenting) where its words
    /// tell the class to move one.
    pub fn set_up_experiment(&mut self, doc: Document, title: &str, names_a_control: bool) {
        self.load(doc, title);
        self.ui.layout.step = None;
        if names_a_control {
            if self.ui.layout.presenting {
                self.ui.layout.drawer_open = true;
            } else {
                self.ui.layout.controls_open = true;
            }
        }
    }

    /// Closes the user's mesh: the top bar offers it no more, and a view that showed it
    /// shows the default object instead (an undoable change).
    pub fn close_mesh(&mut self) {
        let mut c = self.doc.clone();
        c.view.obj = None;
        if c.view.object == phonglab_core::ObjectKind::Obj {
            c.view.object = phonglab_core::View::default().object;
        }
        self.apply(c);
    }

    /// Undoes the last change of the scene, saying what was undone.
    pub fn undo(&mut self) {
        self.message = Some(Message::Info(match self.history.undo() {
            Some((doc, label)) => {
                self.set_doc(doc);
                crate::t!("undid", what = label)
            }
            None => crate::t!("nothing-to-undo"),
        }));
    }

    /// Redoes the last undone change, saying what was redone.
    pub fn redo(&mut self) {
        self.message = Some(Message::Info(match self.history.redo() {
            Some((doc, label)) => {
                self.set_doc(doc);
                crate::t!("redid", what = label)
            }
            None => crate::t!("nothing-to-redo"),
        }));
    }

    /// Shows `doc` (a document that was valid when it was shown before).
    fn set_doc(&mut self, doc: Document) {
        self.doc = doc;
        self.controls.selected_light = self.controls.selected_light.min(self.doc.scene.lights.len().saturating_sub(1));
    }
}

/// The ready-made scenes of the Presets menu.
/// The built-in documents: [`phonglab_core::library::documents`] (kept in the core, so the CLI needs no app).
pub fn preset_documents() -> Vec<(String, Document)> {
    library::documents()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusing_keeps_the_last_valid_document() {
        let mut s = AppState::worksheet();
        let before = s.doc.clone();
        let mut c = s.doc.clone();
        c.scene.material.shininess = 200.0;
        assert!(!s.apply(c));
        assert_eq!(s.doc, before);
        assert!(
            matches!(&s.message, Some(Message::Refused(m)) if m.contains("material.shininess") && m.contains("[0, 128]"))
        );
        let mut c = s.doc.clone();
        c.scene.material.shininess = 100.0;
        assert!(s.apply(c));
        assert_eq!(s.doc.scene.material.shininess, 100.0);
        assert_eq!(s.message, None, "a good edit clears the refusal");
        // The refused edit left no step; the kept one is undone.
        s.undo();
        assert_eq!(s.doc, before);
        assert_eq!(s.message, Some(Message::Info("Undid: Material shininess 25.6 ➡ 100.".into())));
        s.redo();
        assert_eq!(s.doc.scene.material.shininess, 100.0);
    }

    #[test]
    fn the_camera_decides_the_view_matrix() {
        let mut s = AppState::worksheet();
        let mut c = s.doc.clone();
        c.camera = phonglab_core::CameraSpec::Worksheet(1);
        assert!(s.apply(c));
        assert_eq!(s.doc.scene.eye_from_world, phonglab_core::transform::worksheet_modelview(1).unwrap());
    }

    #[test]
    fn the_worksheet_evaluates_to_its_answer() {
        let s = AppState::worksheet();
        let e = s.evaluate().unwrap();
        assert!((e.front.primary[0] - 0.05958709).abs() < 1e-7);
        assert_eq!(preset_documents().len(), 6);
    }
}
