//! A student's work checked in the window (File → Check a student's work…, or a dropped
//! `.txt` of printed values, or a dropped notebook with outputs, after asking): read
//! through the same bounded reader as Open and `phonglab check`, checked by the core's
//! [`check`](phonglab_core::study::check::check) against the scene shown (the assignment),
//! and shown in the calculation panel ([`crate::app::panels::student_column`]). Nothing the student wrote is run; a file that
//! cannot be read is refused with a message and the scene and any earlier check stay.

use std::path::Path;

use phonglab_core::study::check::printed::{notebook_outputs, printed_text};

use super::state::{AppState, Message, StudentStatus as Status};
use crate::app::panels::student_column::StudentCheck;
use crate::io::student_code::{MAX_CODE_BYTES, import_text, student_code};
use crate::t;

/// Is `path` a picture (`.png`), diagnosed in Compare? A `.jpg` or `.jpeg` is one too: it
/// goes to Compare, whose reader says it is a JPEG and how to hand in a PNG (read as a
/// notebook's text, it was refused as "not a text file", behind the picture shown).
pub fn is_picture(path: &Path) -> bool {
    path.extension().is_some_and(|e| ["png", "jpg", "jpeg"].iter().any(|x| e.eq_ignore_ascii_case(x)))
}

/// Is `path` a script's printed text (`.txt`), checked rather than opened?
pub fn is_printed_text(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("txt"))
}

/// Does the notebook `bytes` hold printed outputs (then a drop asks: open it or check it)?
pub fn has_outputs(bytes: &[u8]) -> bool {
    std::str::from_utf8(bytes).ok().and_then(|t| notebook_outputs(t).ok()).is_some_and(|p| !p.values.is_empty())
}

/// Checks the file at `path` (a notebook with outputs, or printed text), read capped as
/// Open reads a notebook; says why not.
pub fn check_path(state: &mut AppState, path: &Path) {
    state.student_last = Some(path.to_path_buf());
    let (cap, kind) = if is_picture(path) {
        (crate::io::student_png::MAX_PICTURE_BYTES, t!("file-kind-pictures"))
    } else {
        (MAX_CODE_BYTES, t!("file-kind-code"))
    };
    match crate::io::input_file::read_capped(path, cap, &kind) {
        Ok(bytes) => check_bytes(state, &bytes, path),
        Err(why) if is_picture(path) => refuse_picture(state, path, why),
        Err(why) => refuse(state, why),
    }
}

/// Checks the work in `bytes`, from a file named `path`, against the scene shown.
pub fn check_bytes(state: &mut AppState, bytes: &[u8], path: &Path) {
    if is_picture(path) {
        return check_picture(state, bytes, path);
    }
    match checked(state, bytes, path) {
        Ok(c) => {
            // The steps show in the calculation, which Compare takes the place of: a
            // picture in Compare stays there, and Compare closes so the work checked shows.
            state.ui.layout.calculation_open = true;
            state.compare.open = false;
            state.student = Some(c);
            say(state, Status::Work);
        }
        Err(why) => refuse(state, why),
    }
}

/// The work read and checked, or why not (in the user's language, naming the file).
fn checked(state: &AppState, bytes: &[u8], path: &Path) -> Result<StudentCheck, String> {
    let shown = crate::io::reasons::shown(path);
    let text = std::str::from_utf8(bytes).map_err(|_| t!("not-text", path = shown.clone()))?;
    let (own, printed) = match student_code(path) {
        Some(true) => {
            let imported = import_text(text, true, path)?;
            let printed = notebook_outputs(text).map_err(|e| format!("{shown}: {e}"))?;
            (imported.doc.scene, printed)
        }
        _ if is_printed_text(path) => (state.doc.scene.clone(), printed_text(text)),
        _ => return Err(t!("student-not-work", path = shown)),
    };
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    Ok(StudentCheck::new(phonglab_core::escape::printable(&name), &state.doc.scene, (own, printed)))
}

/// The status `which` check says now, in the language shown; `None` once it is cleared.
fn status(state: &AppState, which: Status) -> Option<Message> {
    let (file, verdict) = match which {
        Status::Work => {
            let c = state.student.as_ref()?;
            let verdict = if c.check.right() { t!("check-all-right") } else { t!("student-checked-wrong") };
            // Checked against the notebook's own scene ([`StudentCheck::own_scene`]): not
            // "against this scene".
            if c.own_scene.is_some() {
                return Some(Message::Info(t!("student-checked-own", file = c.file.clone(), verdict = verdict)));
            }
            (c.file.clone(), verdict)
        }
        Status::Picture => {
            let p = state.compare.student.as_ref()?;
            if p.stale(&filed(state)) {
                return Some(Message::Info(p.stale_note()));
            }
            (p.file.clone(), p.lines().into_iter().next().unwrap_or_default())
        }
    };
    Some(Message::Info(t!("student-checked", file = file, verdict = verdict)))
}

/// Shows the status of `which` check, remembered so that it is said again in another
/// language.
fn say(state: &mut AppState, which: Status) {
    state.message = status(state, which);
    state.student_status = state.message.clone().map(|m| (which, m));
}

/// Says the check's status again, in the language shown now, while it is the status shown
/// (called each frame once the language is set: a switch of language or decimal mark
/// re-says it; another status replaces it for good).
pub fn restate(state: &mut AppState) {
    let Some((which, said)) = state.student_status.clone() else { return };
    if state.message.as_ref() != Some(&said) {
        state.student_status = None;
        return;
    }
    match status(state, which) {
        Some(now) if now != said => say(state, which),
        Some(_) => {}
        None => state.student_status = None,
    }
}

fn refuse(state: &mut AppState, why: String) {
    state.message = Some(Message::Refused(not_checked(&why)));
}

/// "Not checked: why." with one period, whether or not `why` ends its own sentence.
fn not_checked(why: &str) -> String {
    t!("student-not-checked", why = why.trim_end().trim_end_matches('.').to_owned())
}

/// Refuses a picture: says why in the status line. A picture checked earlier stays in
/// Compare as it was (its verdict is still its own); with none, Compare shows the refusal.
fn refuse_picture(state: &mut AppState, path: &Path, why: String) {
    let said = not_checked(&why);
    refuse(state, why);
    state.student_status = None;
    if state.compare.student.is_some() {
        return;
    }
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    state.compare.refused = Some((phonglab_core::escape::printable(&name), said));
    state.compare.open = true;
}

/// A notebook with outputs was dropped: asks whether to open it as the scene (as a drop
/// always did) or check it against the scene shown. Checks it here; returns the file
/// (name, bytes) when it is to be opened as the scene (the shell's files open it).
pub fn ask_ui(ctx: &egui::Context, state: &mut AppState) -> Option<(String, Vec<u8>)> {
    let (name, _) = state.student_ask.as_ref()?;
    let shown = phonglab_core::escape::printable(name);
    let (mut open, mut check_it, mut cancel) = (false, false, false);
    // A modal, as phonglab's chooser is: nothing behind it takes a click or the keyboard.
    egui::Modal::new(egui::Id::unique("phonglab student ask")).show(ctx, |ui| {
        ui.set_max_width(520.0_f32.min(ctx.content_rect().width() - 48.0));
        ui.vertical_centered(|ui| ui.heading(t!("student-ask-title")));
        ui.label(t!("student-ask", file = shown));
        ui.horizontal_wrapped(|ui| {
            check_it = ui.button(t!("student-ask-check")).clicked();
            open = ui.button(t!("student-ask-open")).clicked();
            cancel = ui.button(t!("chooser-cancel")).clicked();
        });
    });
    if !(open || check_it || cancel) {
        return None;
    }
    let (name, bytes) = state.student_ask.take()?;
    if check_it {
        check_bytes(state, &bytes, Path::new(&name));
    }
    open.then_some((name, bytes))
}

/// File → Check a student's work…: the system's dialog, or where it cannot open (or in
/// the tests) phonglab's own chooser; the work chosen is checked. (The browser: drop it.)
pub fn check_menu_ui(ui: &mut egui::Ui, state: &mut AppState) {
    use crate::app::panels::chooser::{Chooser, Purpose};
    use crate::app::panels::files::Dialogs;
    use crate::platform::files::{self as platform, Picked};
    if !platform::TYPED_PATHS {
        return;
    }
    if !ui.button(t!("student-menu")).on_hover_text(t!("student-menu-hover")).clicked() {
        return;
    }
    ui.close();
    // The folder of the last work checked, else the scene's.
    let start = state.student_last.clone().or_else(|| state.files.typed());
    let why = match state.files.dialogs {
        Dialogs::System => match platform::pick_work_to_check(
            start.as_deref(),
            &t!("student-choose-why"),
            &t!("student-choose-filter"),
        ) {
            Picked::Chosen(p) => return check_path(state, &p),
            Picked::Cancelled => return,
            Picked::NoDialog(why) => {
                state.files.dialogs = Dialogs::InApp;
                // Why phonglab's own chooser, then what to choose in it.
                format!("{why} {}", t!("student-choose-why"))
            }
        },
        _ => t!("student-choose-why"),
    };
    let mut chooser = Chooser::new(Purpose::CheckWork, start.as_deref(), why);
    // The scene file's folder, not its name: the student's file is another.
    chooser.name.clear();
    state.chooser = Some(chooser);
}

/// The scene shown as its file draws it: [`crate::app::panels::student_picture::filed`].
fn filed(state: &AppState) -> std::borrow::Cow<'_, phonglab_core::Document> {
    crate::app::panels::student_picture::filed(&state.doc, state.view_options.spun)
}

/// The export's window, the size a student's picture is drawn at.
pub const PICTURE_SIZE: usize = 512;

/// Diagnoses the picture `bytes` (a PNG of the export's size) against the scene shown, and
/// shows it in Compare as B beside the right picture and their difference.
fn check_picture(state: &mut AppState, bytes: &[u8], path: &Path) {
    let image = match crate::io::student_png::decode(bytes, path, PICTURE_SIZE) {
        Ok(image) => image,
        Err(why) => return refuse_picture(state, path, why),
    };
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    diagnose_picture(state, image, phonglab_core::escape::printable(&name), path);
}

/// Diagnoses the student's picture in Compare again, against the scene shown now (the
/// scene changed since it was checked).
pub fn recheck_picture(state: &mut AppState) {
    let Some(p) = state.compare.student.as_ref() else { return };
    let (image, file) = (p.image().to_vec(), p.file.clone());
    diagnose_picture(state, image, file.clone(), Path::new(&file));
}

/// Diagnoses `image` (RGBA8, the export's size) from the file shown as `file` (at `path`)
/// against the scene shown.
fn diagnose_picture(state: &mut AppState, image: Vec<u8>, file: String, path: &Path) {
    use phonglab_core::teach::diagnose::{Drawing, diagnose};
    // The scene's own view, as its program draws it (the window's spin taken back).
    let doc = filed(state).into_owned();
    let unspun = doc != state.doc;
    let mesh = doc.view.mesh();
    // As `phonglab diagnose` draws it: the exact power, whatever the window's setting (the
    // student's OpenGL computes the exact one).
    let mut right = Drawing::of(&doc.shaded_setup(phonglab_core::PowFn::Exact).job(&mesh));
    right.inside = doc.view.mesh_inside();
    match diagnose(&right, &image, PICTURE_SIZE) {
        Ok(d) => {
            let picture =
                crate::app::panels::student_picture::StudentPicture::new(file, PICTURE_SIZE, image, &d, &doc, unspun);
            state.compare.student = Some(picture);
            state.compare.refused = None;
            state.compare.open = true;
            say(state, Status::Picture);
        }
        Err(e) => refuse_picture(state, path, e.to_string()),
    }
}
