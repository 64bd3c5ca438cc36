//! Scene files from the app: a path field with Open and Save, and files dropped on the
//! window. A file that cannot be read, parsed or validated is refused with a message that
//! names the line and column or the field, and the current scene stays as it was; a save
//! is written whole or not at all, so a failed save leaves the old file whole.

use std::path::{Path, PathBuf};

use egui::Ui;
use phonglab_core::Document;
use phonglab_core::t;

use crate::app::shell::state::{AppState, Message};
use crate::io::student_code::{MAX_CODE_BYTES, import_text, student_code};
use crate::platform::files as platform;

/// Writes `doc` to `path`, whole or not at all ([`crate::io::atomic_write::write`]).
pub fn write_document(doc: &Document, path: &Path) -> Result<(), String> {
    let text = doc.to_toml().map_err(|e| e.to_string())?;
    crate::io::atomic_write::write(path, text.as_bytes()).map_err(|e| e.to_string())
}

/// The app's first scene when it is started with a file (`phonglab FILE.toml`): that file,
/// or, when it cannot be used, the default scene (the worksheet), saying why.
pub fn open_at_start(state: &mut AppState, path: &Path) {
    if let Err(why) = open_or_why(state, path) {
        state.doc = Document::default();
        state.message = Some(Message::Refused(t!("not-opened-worksheet", why = why)));
    }
}

/// Opens a scene file into the app, or says why not and keeps the current scene.
pub fn open(state: &mut AppState, path: &Path) {
    if let Err(why) = open_or_why(state, path) {
        refuse(state, why);
    }
}

/// Opens a scene file (or an OBJ mesh) into the app, or returns why not (the scene stays).
fn open_or_why(state: &mut AppState, path: &Path) -> Result<(), String> {
    if is_obj(path) {
        return open_obj_or_why(state, path);
    }
    let (cap, kind) = match student_code(path) {
        Some(_) => (MAX_CODE_BYTES, t!("file-kind-code")),
        None => (crate::io::input_file::MAX_SCENE_BYTES, t!("file-kind-scenes")),
    };
    let bytes = crate::io::input_file::read_capped(path, cap, &kind)?;
    open_bytes_or_why(state, &bytes, path)
}

/// Does `path` name an OBJ mesh (rather than a scene file)?
pub fn is_obj(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}

/// Shows the OBJ mesh at `path` in the shaded view (the scene stays), or says why not with
/// the line at fault; says what was done to the file (fanned, normals computed, fitted).
pub fn open_obj(state: &mut AppState, path: &Path) {
    if let Err(why) = open_obj_or_why(state, path) {
        refuse(state, why);
    }
}

fn open_obj_or_why(state: &mut AppState, path: &Path) -> Result<(), String> {
    let full = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let mut c = state.doc.clone();
    c.view.object = phonglab_core::ObjectKind::Obj;
    c.view.obj = Some(full.display().to_string());
    let loaded = c.view.obj_mesh();
    state.apply_or_why(c)?;
    let what = match loaded {
        Ok(o) => t!(
            "mesh-summary",
            triangles = o.mesh.triangle_count(),
            vertices = o.mesh.positions.len(),
            notes = o.notes.join("; ")
        ),
        Err(e) => e.to_string(),
    };
    state.message = Some(Message::Info(t!("opened-mesh", path = path.display().to_string(), what = what)));
    Ok(())
}

/// Opens a scene from the bytes of the file at `path`, or says why not.
fn open_bytes(state: &mut AppState, bytes: &[u8], path: &Path) {
    if let Err(why) = open_bytes_or_why(state, bytes, path) {
        refuse(state, why);
    }
}

fn open_bytes_or_why(state: &mut AppState, bytes: &[u8], path: &Path) -> Result<(), String> {
    if is_obj(path) {
        return open_obj_or_why(state, path);
    }
    let Ok(text) = std::str::from_utf8(bytes) else {
        return Err(t!("not-text", path = path.display().to_string()));
    };
    if let Some(notebook) = student_code(path) {
        return import_or_why(state, text, notebook, path);
    }
    let doc = Document::from_toml_in(text, path.parent()).map_err(|e| format!("{}: {e}", path.display()))?;
    state.load(doc, &path.display().to_string());
    state.files.path = path.display().to_string();
    Ok(())
}

/// Opens a worksheet-style notebook or script as a scene (what `phonglab import` reads),
/// saying which lines could not be read; the scene stays when nothing could be.
fn import_or_why(state: &mut AppState, text: &str, notebook: bool, path: &Path) -> Result<(), String> {
    let imported = import_text(text, notebook, path)?;
    state.load(imported.doc, &path.display().to_string());
    // Save writes a scene file beside it, never over the student's notebook or script.
    state.files.path = path.with_extension("toml").display().to_string();
    let what = if imported.notices.is_empty() { String::new() } else { format!(" {}", imported.notices.join("; ")) };
    state.message = Some(Message::Info(t!("imported", path = path.display().to_string(), notices = what)));
    Ok(())
}

fn refuse(state: &mut AppState, why: String) {
    state.message = Some(Message::Refused(t!("not-opened", why = why)));
}

/// Saves the current scene, and says where (or why not).
pub fn save(state: &mut AppState, path: &Path) {
    // The scene's mesh is read from its file: saving the scene over it would lose it.
    let mesh: Vec<&Path> = state.doc.view.obj.iter().map(Path::new).collect();
    let written =
        crate::io::same_file::refuse_output_onto_input(&[path], &mesh).and_then(|()| write_document(&state.doc, path));
    state.message = Some(match written {
        Ok(()) => Message::Info(t!("saved", path = path.display().to_string())),
        Err(e) => Message::Refused(t!("not-saved", error = e)),
    });
}

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

fn path_of(state: &AppState) -> Option<PathBuf> {
    let p = state.files.path.trim();
    (!p.is_empty()).then(|| PathBuf::from(p))
}

/// The scene file's controls: on the desktop the path field with Open and Save (Enter in
/// the field opens) and the system's dialogs; in the browser, where files have no paths,
/// Open… (the browser's chooser) and Save (a download).
pub fn file_ui(ui: &mut Ui, state: &mut AppState) {
    if !platform::TYPED_PATHS {
        browser_file_ui(ui, state);
        return;
    }
    let label = ui.label(t!("scene-file"));
    let field = ui
        .add(egui::TextEdit::singleline(&mut state.files.path).desired_width(220.0).hint_text(t!("scene-file-hint")))
        .labelled_by(label.id);
    let enter = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
    if ui.button(t!("open")).on_hover_text(t!("open-hover")).clicked() || enter {
        open_typed(state);
    }
    if ui.button(t!("save")).on_hover_text(t!("save-hover")).clicked() {
        save_typed(state);
    }
    if state.files.dialogs {
        let start = path_of(state);
        if ui.button(t!("open-dialog")).on_hover_text(t!("open-dialog-hover")).clicked()
            && let Some(p) = platform::pick_scene_to_open(start.as_deref())
        {
            state.files.path = p.display().to_string();
            open(state, &p);
        }
        if ui.button(t!("save-as")).on_hover_text(t!("save-as-hover")).clicked()
            && let Some(p) = platform::pick_scene_to_save(start.as_deref())
        {
            state.files.path = p.display().to_string();
            save(state, &p);
        }
    }
}

/// The browser's Open… (the file chooser) and Save (a download of the scene file, named
/// after the file it came from, or `scene.toml`).
fn browser_file_ui(ui: &mut Ui, state: &mut AppState) {
    if ui.button(t!("open-dialog")).on_hover_text(t!("open-browser-hover")).clicked() {
        platform::choose_file(ui.ctx(), ".toml,.ipynb,.py");
    }
    if ui.button(t!("save")).on_hover_text(t!("save-download-hover")).clicked() {
        let name = Path::new(state.files.path.trim())
            .file_name()
            .map_or("scene.toml".to_string(), |n| n.to_string_lossy().into_owned());
        state.message = Some(match state.doc.to_toml().map_err(|e| e.to_string()) {
            Ok(text) => match platform::download(&name, text.as_bytes(), "application/toml") {
                Ok(()) => Message::Info(t!("downloaded", name = name)),
                Err(e) => Message::Refused(t!("not-saved", error = e)),
            },
            Err(e) => Message::Refused(t!("not-saved", error = e)),
        });
    }
}

/// Opens the file at the typed path.
pub fn open_typed(state: &mut AppState) {
    match path_of(state) {
        Some(p) => open(state, &p),
        None => state.message = Some(Message::Refused(t!("type-path-first"))),
    }
}

/// Saves to the typed path.
pub fn save_typed(state: &mut AppState) {
    match path_of(state) {
        Some(p) => save(state, &p),
        None => state.message = Some(Message::Refused(t!("type-path-first"))),
    }
}

/// Opens a scene file dropped on the window (the first one, when several are dropped), and
/// while files hover over the window, says that dropping one opens it.
pub fn dropped_files_ui(ctx: &egui::Context, state: &mut AppState) {
    let hovering = ctx.input(|i| !i.raw.hovered_files.is_empty());
    if hovering {
        let painter = ctx.layer_painter(egui::LayerId::new(egui::Order::Foreground, egui::Id::unique("drop target")));
        let rect = ctx.content_rect();
        painter.rect_filled(rect, 0.0, egui::Color32::from_black_alpha(160));
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            t!("drop-to-open"),
            egui::FontId::proportional(28.0),
            egui::Color32::WHITE,
        );
    }
    // Files that arrived since the last frame (the browser's chooser and drops).
    for arrived in platform::take_arrived() {
        match arrived {
            Ok((name, bytes)) => open_bytes(state, &bytes, Path::new(&name)),
            Err(why) => refuse(state, why),
        }
    }
    let dropped = ctx.input(|i| i.raw.dropped_files.clone());
    let Some(file) = dropped.first() else { return };
    // Read now on the desktop; in the browser the bytes arrive later (see file_ui).
    match crate::io::input_file::read_dropped(ctx, file, MAX_CODE_BYTES) {
        Some(Ok((name, bytes))) => open_bytes(state, &bytes, Path::new(&name)),
        Some(Err(why)) => refuse(state, why),
        None => {}
    }
    if dropped.len() > 1 {
        let extra = t!("dropped-several", count = dropped.len());
        if let Some(Message::Info(m) | Message::Refused(m)) = &mut state.message {
            m.push_str(&extra);
        }
    }
}
