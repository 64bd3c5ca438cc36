//! The scene file's row: a path field with Open and Save and the system's dialogs on the
//! desktop, the browser's chooser and a download in the browser. It asks the window to
//! open or save ([`FileRequest`]); the shell does it.

use std::path::{Path, PathBuf};

use egui::Ui;
use phonglab_core::Document;

use crate::app::editing::message::Message;
use crate::app::panels::chooser::{Chooser, Purpose};
use crate::platform::files as platform;
use crate::t;

/// Which file dialogs Open…, Save as… and the Export menu's Save… use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Dialogs {
    /// None (headless tests, where a dialog would wait for a person): no Open… or Save as…,
    /// and the Export menu offers phonglab's own chooser.
    #[default]
    None,
    /// The system's dialog (the window's app); where it cannot open, phonglab's own chooser,
    /// saying why, and from then on the chooser.
    System,
    /// phonglab's own chooser.
    InApp,
}

/// The scene file's row: the path typed, and which dialogs may open.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileState {
    /// The scene file path typed for Open and Save.
    pub path: String,
    /// The dialogs Open… and Save as… use.
    pub dialogs: Dialogs,
}

/// The name Save suggests before any file is opened or typed: with the ending the Linux
/// package's MIME type claims (`*.phonglab.toml`, packaging/linux/phonglab.xml), so the
/// saved scene opens in phonglab with a double click.
pub const SUGGESTED_SCENE_NAME: &str = "scene.phonglab.toml";

impl Default for FileState {
    fn default() -> Self {
        FileState { path: SUGGESTED_SCENE_NAME.into(), dialogs: Dialogs::None }
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
    /// Open phonglab's own chooser (the system's dialog could not open).
    Choose(Chooser),
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
    if files.dialogs != Dialogs::None {
        let start = files.typed();
        if ui.button(t!("open-dialog")).on_hover_text(t!("open-dialog-hover")).clicked() {
            asked = pick(files, Purpose::OpenScene, start.as_deref(), platform::pick_scene_to_open);
        }
        if ui.button(t!("save-as")).on_hover_text(t!("save-as-hover")).clicked() {
            asked = pick(files, Purpose::SaveScene, start.as_deref(), platform::pick_scene_to_save);
        }
    }
    asked
}

/// Open… or Save as…: the system's dialog, or where it cannot open (now or before)
/// phonglab's own chooser, saying why. Never nothing: a dialog that fails opens the chooser.
fn pick(
    files: &mut FileState,
    purpose: Purpose,
    start: Option<&Path>,
    system: fn(Option<&Path>) -> platform::Picked,
) -> Option<FileRequest> {
    let why = match files.dialogs {
        Dialogs::System => match system(start) {
            platform::Picked::Chosen(p) if purpose == Purpose::OpenScene => return Some(FileRequest::Open(p)),
            platform::Picked::Chosen(p) => return Some(FileRequest::Save(p)),
            platform::Picked::Cancelled => return None,
            platform::Picked::NoDialog(why) => {
                files.dialogs = Dialogs::InApp;
                why
            }
        },
        _ => t!("dialog-in-app"),
    };
    Some(FileRequest::Choose(Chooser::new(purpose, start, why)))
}

/// The browser's Open… (the file chooser) and Save (a download of the scene file, named
/// after the file it came from, or [`SUGGESTED_SCENE_NAME`]).
fn browser_file_ui(ui: &mut Ui, files: &FileState, doc: &Document, message: &mut Option<Message>) {
    if ui.button(t!("open-dialog")).on_hover_text(t!("open-browser-hover")).clicked() {
        platform::choose_file(ui.ctx(), ".toml,.obj,.ipynb,.py", browser_check);
    }
    if ui.button(t!("save")).on_hover_text(t!("save-download-hover")).clicked() {
        let name = Path::new(files.path.trim())
            .file_name()
            .map_or(SUGGESTED_SCENE_NAME.to_string(), |n| n.to_string_lossy().into_owned());
        *message = Some(match doc.to_toml().map_err(|e| e.to_string()) {
            Ok(text) => match platform::download(&name, text.as_bytes(), "application/toml") {
                Ok(()) => Message::Info(t!("downloaded", name = name)),
                Err(e) => Message::Refused(t!("not-saved", error = e)),
            },
            Err(e) => Message::Refused(t!("not-saved", error = e)),
        });
    }
}

/// The browser's chooser's check of a chosen file, by its name and size, before it is read:
/// a drop's ([`crate::io::input_file::check_arriving`]) with the largest student code file
/// ([`crate::io::student_code::MAX_CODE_BYTES`]) as the cap.
fn browser_check(name: &str, size: u64) -> Result<(), String> {
    crate::io::input_file::check_arriving(name, size, crate::io::student_code::MAX_CODE_BYTES)
}
