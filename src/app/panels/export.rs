//! The Export menu: what the app hands out as files. The scene as the student's own code
//! (the worksheet's notebook, a PyOpenGL program, an openFrameworks app, the GLSL: what
//! `phonglab export` writes), copied or saved; the shaded view as a PNG (the CPU
//! renderer at 512×512: what `phonglab render --scene` draws for this scene) and a set of
//! exercise sheets as one zip (what `phonglab exercise` writes: the sheets, keys and scene
//! files, `sheets.pdf` and `keys.pdf`, in the window's language). On the desktop they are
//! saved where the system's dialog says; in the browser they are downloads
//! ([`crate::io::save::save_bytes`]).

use egui::Ui;

use phonglab_core::export::Target;

use phonglab_core::{Document, PowFn};

use crate::app::editing::message::Message;
use crate::app::panels::chooser::{Chooser, Purpose};
use crate::app::panels::files::{Dialogs, FileState};
use crate::t;

/// The exercise set's settings, kept while the window runs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExportState {
    /// The random seed (the same seed gives the same sheets).
    pub seed: u32,
    /// How many exercises.
    pub count: u32,
    /// The level, 1 to 4.
    pub level: u32,
}

impl Default for ExportState {
    fn default() -> Self {
        ExportState { seed: 1, count: 5, level: 2 }
    }
}

/// The PNG's size in pixels.
pub const PNG_SIZE: usize = 512;

/// The shaded view of `doc` as a PNG file's bytes, drawn by the CPU renderer with the
/// power function `pow`.
pub fn shaded_png(doc: &Document, pow: PowFn) -> Result<Vec<u8>, String> {
    let mesh = doc.view.mesh();
    let setup = doc.shaded_setup(pow);
    let job = setup.job(&mesh);
    let mut renderer = phonglab_core::render::Renderer::new();
    let (img, _) = renderer.render(&job, PNG_SIZE, PNG_SIZE).map_err(|e| e.to_string())?;
    crate::io::image::encode_png(img.width, img.height, &img.rgba).map_err(|e| e.to_string())
}

/// An exercise set as a zip file's bytes: every file `phonglab exercise` writes.
pub fn exercises_zip(e: &ExportState) -> Result<Vec<u8>, String> {
    use phonglab_core::exercise::{Level, Spec};
    let level = Level::from_number(e.level.clamp(1, 4) as u8).ok_or_else(|| crate::t!("err-level"))?;
    let request = crate::io::exercise_set::Request {
        seed: u64::from(e.seed),
        count: e.count.clamp(1, 100) as usize,
        spec: Spec::level(level, phonglab_core::Rules::WORKSHEET),
        worksheet: false,
        exam: false,
    };
    let (_, set) = crate::io::exercise_set::exercise_set(&request).map_err(|e| format!("{e:#}"))?;
    Ok(crate::io::zip::zip_stored(&set.files))
}

/// Saves (or downloads) `bytes` as `name` (never over the scene file `files` names or
/// `doc`'s mesh), and says so: the window's message after it (none when cancelled).
fn hand_out(
    name: &str,
    bytes: Result<Vec<u8>, String>,
    mime: &str,
    doc: &Document,
    files: &mut FileState,
    chooser: &mut Option<Chooser>,
) -> Option<Message> {
    use crate::io::save::Saved;
    let inputs = export_inputs(doc, files);
    let inputs: Vec<&std::path::Path> = inputs.iter().map(std::path::PathBuf::as_path).collect();
    let system = files.dialogs == Dialogs::System;
    let bytes = match bytes {
        Ok(b) => b,
        Err(e) => return Some(Message::Refused(t!("not-exported", what = name, error = e))),
    };
    match crate::io::save::save_bytes(name, &bytes, mime, system, &inputs) {
        Ok(Saved::At(_)) if !crate::platform::files::TYPED_PATHS => Some(Message::Info(t!("downloaded", name = name))),
        Ok(Saved::At(at)) => Some(Message::Info(t!("exported", what = name, at = at))),
        Ok(Saved::Cancelled) => None,
        Ok(Saved::Choose(why)) => {
            if system {
                files.dialogs = Dialogs::InApp;
            }
            let start = files.typed();
            let purpose = Purpose::SaveBytes { name: name.to_string(), bytes };
            let mut c = Chooser::new(purpose, start.as_deref(), why.clone());
            c.name = name.to_string();
            *chooser = Some(c);
            Some(Message::Info(why))
        }
        Err(e) => Some(Message::Refused(t!("not-exported", what = name, error = e))),
    }
}

/// The files an export may not overwrite: the scene file typed and the view's mesh.
pub fn export_inputs(doc: &Document, files: &FileState) -> Vec<std::path::PathBuf> {
    let scene_file = std::path::PathBuf::from(files.path.trim());
    let mesh = doc.view.obj.as_deref().map(std::path::PathBuf::from);
    [Some(scene_file), mesh].into_iter().flatten().collect()
}

/// The file `target` is saved as: one file, or for openFrameworks a zip of its `src/`.
pub fn code_file(doc: &Document, target: Target) -> Result<(String, Vec<u8>, &'static str), String> {
    let written = phonglab_core::export::files(doc, target)?;
    if target == Target::OpenFrameworks {
        let files: Vec<(String, Vec<u8>)> =
            written.into_iter().map(|(name, text)| (format!("src/{name}"), text.into_bytes())).collect();
        return Ok(("phonglab-ofApp.zip".into(), crate::io::zip::zip_stored(&files), "application/zip"));
    }
    let mime = match target {
        Target::Notebook => "application/x-ipynb+json",
        Target::PyOpenGl => "text/x-python",
        _ => "text/plain",
    };
    let (name, text) = written.into_iter().next().ok_or_else(|| t!("export-nothing"))?;
    Ok((name, text.into_bytes(), mime))
}

/// The student's own code: for each target, Copy (to the clipboard) and Save.
fn code_ui(
    ui: &mut Ui,
    doc: &Document,
    files: &mut FileState,
    chooser: &mut Option<Chooser>,
    message: &mut Option<Message>,
) {
    ui.label(egui::RichText::new(t!("export-code")).strong());
    egui::Grid::new("export code").num_columns(3).show(ui, |ui| {
        for target in Target::ALL {
            ui.label(target.label());
            if ui.button(t!("export-copy")).on_hover_text(t!("export-copy-hover")).clicked() {
                *message = Some(match phonglab_core::export::copy_text(doc, target) {
                    Ok(text) => {
                        ui.ctx().copy_text(text);
                        Message::Info(t!("export-copied", what = target.label()))
                    }
                    Err(e) => Message::Refused(t!("not-exported", what = target.label(), error = e)),
                });
                ui.close();
            }
            if ui.button(t!("export-save")).on_hover_text(t!("export-save-hover")).clicked() {
                *message = match code_file(doc, target) {
                    Ok((name, bytes, mime)) => hand_out(&name, Ok(bytes), mime, doc, files, chooser),
                    Err(e) => Some(Message::Refused(t!("not-exported", what = target.label(), error = e))),
                };
                ui.close();
            }
            ui.end_row();
        }
    });
    ui.small(t!("export-import-hint"));
}

/// The Export menu's button and its contents: the code and the PNG of `doc` (drawn with
/// `pow`), the exercise set of `export`'s settings; each saved where `files` allows, said
/// in `message`.
pub fn export_menu_ui(
    ui: &mut Ui,
    export: &mut ExportState,
    doc: &Document,
    pow: PowFn,
    files: &mut FileState,
    chooser: &mut Option<Chooser>,
    message: &mut Option<Message>,
) {
    ui.menu_button(t!("export"), |ui| {
        code_ui(ui, doc, files, chooser, message);
        ui.separator();
        if ui.button(t!("export-png", size = PNG_SIZE.to_string())).on_hover_text(t!("export-png-hover")).clicked() {
            let name = format!("phonglab-{}-{}.png", doc.view.object.key(), doc.view.shading.label().to_lowercase());
            let png = shaded_png(doc, pow);
            *message = hand_out(&name, png, "image/png", doc, files, chooser);
            ui.close();
        }
        ui.separator();
        ui.label(egui::RichText::new(t!("export-exercises")).strong());
        let e = &mut *export;
        // A menu draws its widgets frameless: give the fields back their frame, so they read
        // as fields to type in.
        let framed = ui.visuals().widgets.noninteractive.bg_stroke;
        ui.visuals_mut().widgets.inactive.bg_stroke = framed;
        egui::Grid::new("export exercises").num_columns(2).show(ui, |ui| {
            crate::app::widgets::fields::whole_number_ui(ui, &t!("export-seed"), &mut e.seed, 1..=999_999);
            ui.end_row();
            crate::app::widgets::fields::whole_number_ui(ui, &t!("export-count"), &mut e.count, 1..=100);
            ui.end_row();
            crate::app::widgets::fields::whole_number_ui(ui, &t!("export-level"), &mut e.level, 1..=4);
            ui.end_row();
        });
        ui.small(t!("export-levels"));
        if ui.button(t!("export-exercises-save")).on_hover_text(t!("export-exercises-hover")).clicked() {
            let name = format!("phonglab-exercises-seed{}-level{}.zip", export.seed, export.level);
            let zip = exercises_zip(export);
            *message = hand_out(&name, zip, "application/zip", doc, files, chooser);
            ui.close();
        }
    });
}
