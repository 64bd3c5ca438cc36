//! Scene files opened and saved by the window (the scene file's row asks: [`crate::app::panels::files`]),
//! and files dropped on it. A file that cannot be read, parsed or validated is refused with a message that
//! names the line and column or the field, and the current scene stays as it was; a save
//! is written whole or not at all, so a failed save leaves the old file whole.

use std::path::{Path, PathBuf};

use phonglab_core::Document;

use super::state::{AppState, Message};
use crate::app::panels::files::FileRequest;
use crate::io::student_code::{MAX_CODE_BYTES, import_text, student_code};
use crate::platform::files as platform;
use crate::t;

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
    // A shared scene's link, where a file is taken: decoded as the browser build does.
    // (Its language, presenting and term too; a damaged one says why and changes nothing.)
    if crate::io::input_file::share_fragment(path).is_some() {
        let shared = crate::io::input_file::read_link(&path.to_string_lossy())?;
        super::shared_link::open_shared(state, shared);
        return Ok(());
    }
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
    path.to_str().is_some_and(crate::io::input_file::is_obj_name)
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
    show_obj(state, &full.display().to_string(), &path.display().to_string(), None)
}

/// Shows the mesh named `obj` (a path, or the name a mesh given as bytes is held under),
/// saying what was done to it, as `shown`, and `kept` (whether it is kept for a reload).
fn show_obj(state: &mut AppState, obj: &str, shown: &str, kept: Option<String>) -> Result<(), String> {
    let mut c = state.doc.clone();
    c.view.object = phonglab_core::ObjectKind::Obj;
    c.view.obj = Some(obj.to_string());
    let loaded = c.view.obj_mesh();
    state.apply_or_why(c)?;
    let mut what = match loaded {
        Ok(o) => t!(
            "mesh-summary",
            triangles = o.mesh.triangle_count(),
            vertices = o.mesh.positions.len(),
            notes = o.notes.join("; ")
        ),
        Err(e) => e.to_string(),
    };
    if let Some(kept) = kept {
        what.push(' ');
        what.push_str(&kept);
    }
    state.message = Some(Message::Info(t!("opened-mesh", path = shown.to_string(), what = what)));
    Ok(())
}

/// Shows the OBJ mesh given as `bytes` (the browser's chooser and drops: a name, no path):
/// read with the desktop's limits and messages, held under its name for the view, and kept
/// in the page's storage for this session where it fits.
fn open_obj_bytes_or_why(state: &mut AppState, name: &str, bytes: &[u8]) -> Result<(), String> {
    phonglab_core::mesh::obj::hold_obj_bytes(name, bytes)?;
    let kept = crate::platform::storage::keep_mesh(name, bytes).err();
    show_obj(state, name, name, kept)
}

/// Opens a scene (or a mesh, or a worksheet notebook) from the bytes of a file named `path`
/// (the browser's files: a name and bytes), or says why not.
pub fn open_bytes(state: &mut AppState, bytes: &[u8], path: &Path) {
    if let Err(why) = open_bytes_or_why(state, bytes, path) {
        refuse(state, why);
    }
}

fn open_bytes_or_why(state: &mut AppState, bytes: &[u8], path: &Path) -> Result<(), String> {
    if is_obj(path) {
        return open_obj_bytes_or_why(state, &path.display().to_string(), bytes);
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
    let mesh: Vec<(&Path, crate::io::same_file::Input)> =
        state.doc.view.obj.iter().map(|m| (Path::new(m), crate::io::same_file::Input::Mesh)).collect();
    let written = crate::io::same_file::refuse_onto(&[path], &mesh).and_then(|()| write_document(&state.doc, path));
    state.message = Some(match written {
        Ok(()) => Message::Info(t!("saved", path = path.display().to_string())),
        Err(e) => Message::Refused(t!("not-saved", error = e)),
    });
}

/// Opens the file at the typed path.
pub fn open_typed(state: &mut AppState) {
    match state.files.typed() {
        Some(p) => open(state, &p),
        None => state.message = Some(Message::Refused(t!("type-path-first"))),
    }
}

/// Saves to the typed path.
pub fn save_typed(state: &mut AppState) {
    match state.files.typed() {
        Some(p) => save(state, &p),
        None => state.message = Some(Message::Refused(t!("type-path-first"))),
    }
}

/// Carries out what the scene file's row asked for.
pub fn carry_out(state: &mut AppState, request: FileRequest) {
    match request {
        FileRequest::OpenTyped => open_typed(state),
        FileRequest::SaveTyped => save_typed(state),
        FileRequest::Open(p) => {
            state.files.path = p.display().to_string();
            open(state, &p);
        }
        FileRequest::Save(p) => {
            state.files.path = p.display().to_string();
            save(state, &p);
        }
        FileRequest::Choose(c) => {
            state.message = Some(Message::Info(c.why.clone()));
            state.chooser = Some(c);
        }
    }
}

/// phonglab's own file chooser, while open, and what was chosen in it carried out.
pub fn chooser_ui(ctx: &egui::Context, state: &mut AppState) {
    use crate::app::panels::chooser::{Chosen, chooser_ui};
    match chooser_ui(ctx, &mut state.chooser) {
        Some(Chosen::Open(p)) => carry_out(state, FileRequest::Open(p)),
        Some(Chosen::Save(p)) => carry_out(state, FileRequest::Save(p)),
        Some(Chosen::Check(p)) => super::student::check_path(state, &p),
        Some(Chosen::SaveBytes(p, bytes)) => {
            let inputs = crate::app::panels::export::export_inputs(&state.doc, &state.files);
            let inputs: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
            let name = p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            state.message = Some(match crate::io::save::save_at(&p, &bytes, &inputs) {
                Ok(at) => Message::Info(t!("exported", what = name, at = at)),
                Err(e) => Message::Refused(t!("not-exported", what = name, error = e)),
            });
        }
        None => {}
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
            Ok((name, bytes)) => open_or_check(state, name, bytes),
            Err(why) => refuse(state, why),
        }
    }
    let dropped = ctx.input(|i| i.raw.dropped_files.clone());
    let Some(file) = dropped.first() else { return };
    // A mesh is read from its path where it has one (a mesh may be far larger than a scene).
    if platform::TYPED_PATHS && is_obj(file.path()) {
        open_obj(state, file.path());
    } else {
        // Read now on the desktop; in the browser the bytes arrive later (see file_ui).
        match crate::io::input_file::read_dropped(ctx, file, MAX_CODE_BYTES) {
            Some(Ok((name, bytes))) => open_or_check(state, name, bytes),
            Some(Err(why)) => refuse(state, why),
            None => {}
        }
    }
    if dropped.len() > 1 {
        let extra = t!("dropped-several", count = dropped.len());
        if let Some(Message::Info(m) | Message::Refused(m)) = &mut state.message {
            m.push_str(&extra);
        }
    }
}

/// A dropped file: printed text (`.txt`) is checked against the scene; a notebook with
/// outputs asks whether to open it as the scene or check it; anything else opens as before.
fn open_or_check(state: &mut AppState, name: String, bytes: Vec<u8>) {
    let path = Path::new(&name);
    if super::student::is_printed_text(path) || super::student::is_picture(path) {
        super::student::check_bytes(state, &bytes, path);
    } else if student_code(path) == Some(true) && super::student::has_outputs(&bytes) {
        state.student_ask = Some((name, bytes));
    } else {
        open_bytes(state, &bytes, path);
    }
}
