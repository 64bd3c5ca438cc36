//! The scene file's row: a path field with Open and Save and the system's dialogs on the
//! desktop, the browser's chooser and a download in the browser. It asks the window to
//! open or save ([`FileRequest`]); the shell does it.

use std::path::{Path, PathBuf};

use egui::Ui;
use phonglab_core::{Document, t};

use crate::app::model::message::Message;
use crate::platform::files as platform;

/// The scene file's row: the path typed, and whether the system's dialogs may open (the
/// window's app; not headless tests, where a dialog would wait for a person).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileState {
    /// The scene file path typed for Open and Save.
    pub path: String,
    /// Open… and Save as… use the system's file dialog.
    pub dialogs: bool,
}

impl Default for FileState {
    fn default() -> Self {
        FileState { path: "scene.toml".into(), dialogs: false }
    }
}

impl FileState {
    /// The typed path, when one is typed.
    pub fn typed(&self) -> Option<PathBuf> {
        let p = self.path.trim();
        (!p.is_empty()).then(|| PathBuf::from(p))
    }
}

/// What the row asks the window to do.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FileRequest {
    /// Open the typed path.
    OpenTyped,
    /// Save to the typed path.
    SaveTyped,
    /// Open this file (chosen in the system's dialog).
    Open(PathBuf),
    /// Save to this file (chosen in the system's dialog).
    Save(PathBuf),
}

/// The scene file's controls: on the desktop the path field with Open and Save (Enter in
/// the field opens) and the system's dialogs; in the browser, where files have no paths,
/// Open… (the browser's chooser) and Save (a download).
///
/// `doc` and `message` are for the browser's Save, a download made here.
pub fn file_ui(
    ui: &mut Ui,
    files: &mut FileState,
    doc: &Document,
    message: &mut Option<Message>,
) -> Option<FileRequest> {
    if !platform::TYPED_PATHS {
        browser_file_ui(ui, files, doc, message);
        return None;
    }
    let mut asked = None;
    let label = ui.label(t!("scene-file"));
    let field = ui
        .add(egui::TextEdit::singleline(&mut files.path).desired_width(220.0).hint_text(t!("scene-file-hint")))
        .labelled_by(label.id);
    let enter = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
    if ui.button(t!("open")).on_hover_text(t!("open-hover")).clicked() || enter {
        asked = Some(FileRequest::OpenTyped);
    }
    if ui.button(t!("save")).on_hover_text(t!("save-hover")).clicked() {
        asked = Some(FileRequest::SaveTyped);
    }
    if files.dialogs {
        let start = files.typed();
        if ui.button(t!("open-dialog")).on_hover_text(t!("open-dialog-hover")).clicked()
            && let Some(p) = platform::pick_scene_to_open(start.as_deref())
        {
            asked = Some(FileRequest::Open(p));
        }
        if ui.button(t!("save-as")).on_hover_text(t!("save-as-hover")).clicked()
            && let Some(p) = platform::pick_scene_to_save(start.as_deref())
        {
            asked = Some(FileRequest::Save(p));
        }
    }
    asked
}

/// The browser's Open… (the file chooser) and Save (a download of the scene file, named
/// after the file it came from, or `scene.toml`).
fn browser_file_ui(ui: &mut Ui, files: &FileState, doc: &Document, message: &mut Option<Message>) {
    if ui.button(t!("open-dialog")).on_hover_text(t!("open-browser-hover")).clicked() {
        platform::choose_file(ui.ctx(), ".toml,.ipynb,.py");
    }
    if ui.button(t!("save")).on_hover_text(t!("save-download-hover")).clicked() {
        let name = Path::new(files.path.trim())
            .file_name()
            .map_or("scene.toml".to_string(), |n| n.to_string_lossy().into_owned());
        *message = Some(match doc.to_toml().map_err(|e| e.to_string()) {
            Ok(text) => match platform::download(&name, text.as_bytes(), "application/toml") {
                Ok(()) => Message::Info(t!("downloaded", name = name)),
                Err(e) => Message::Refused(t!("not-saved", error = e)),
            },
            Err(e) => Message::Refused(t!("not-saved", error = e)),
        });
    }
}
