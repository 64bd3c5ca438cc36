//! phonglab's own file chooser, for where the system's dialog cannot open (no desktop
//! portal: a lab PC with a bare window manager). It never leaves a click without an answer:
//! it says why it is there, lists a folder (its subfolders, then the files the purpose
//! takes), and hands back the file chosen; the shell opens or saves it.

use std::path::{Path, PathBuf};

use egui::Ui;

use crate::io::listing::{Entry, list};
use crate::t;

/// What the file is for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Purpose {
    /// A scene file (or mesh, notebook, script) to open.
    OpenScene,
    /// Where to save the scene file.
    SaveScene,
    /// A student's work to check (a notebook with outputs, or printed text).
    CheckWork,
    /// Where to save these bytes, offered as `name` (the Export menu's files).
    SaveBytes {
        /// The name offered.
        name: String,
        /// What to write.
        bytes: Vec<u8>,
    },
}

impl Purpose {
    /// The files the chooser lists.
    fn extensions(&self) -> Vec<String> {
        match self {
            Purpose::OpenScene => ["toml", "obj", "ipynb", "py"].map(String::from).to_vec(),
            Purpose::SaveScene => vec!["toml".into()],
            Purpose::CheckWork => vec!["ipynb".into(), "txt".into(), "png".into()],
            Purpose::SaveBytes { name, .. } => {
                Path::new(name).extension().map(|e| vec![e.to_string_lossy().into_owned()]).unwrap_or_default()
            }
        }
    }
}

/// The chooser's state while it is open.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Chooser {
    /// What the file is for.
    pub purpose: Purpose,
    /// Why phonglab's own chooser is open (the system's dialog could not).
    pub why: String,
    /// The folder shown, as typed.
    pub folder: String,
    /// The file's name in it.
    pub name: String,
}

/// What the chooser hands back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Chosen {
    /// Open this file.
    Open(PathBuf),
    /// Save the scene here.
    Save(PathBuf),
    /// Check this student's work.
    Check(PathBuf),
    /// Save these bytes here.
    SaveBytes(PathBuf, Vec<u8>),
}

impl Chooser {
    /// A chooser for `purpose`, starting where `start` (a typed path, or a name) points, saying
    /// `why`.
    pub fn new(purpose: Purpose, start: Option<&Path>, why: String) -> Chooser {
        let start = start.map(|p| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf()));
        let folder = start
            .as_deref()
            .and_then(Path::parent)
            .filter(|d| d.is_dir())
            .map(Path::to_path_buf)
            .or_else(|| std::env::current_dir().ok())
            .unwrap_or_default();
        let name = match &purpose {
            Purpose::SaveBytes { name, .. } => name.clone(),
            _ => {
                start.as_deref().and_then(Path::file_name).map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()
            }
        };
        Chooser { purpose, why, folder: folder.display().to_string(), name }
    }

    /// The file the fields name.
    fn path(&self) -> PathBuf {
        Path::new(self.folder.trim()).join(self.name.trim())
    }
}

/// The chooser's window, while `chooser` is open; closes it and returns the file chosen.
pub fn chooser_ui(ctx: &egui::Context, chooser: &mut Option<Chooser>) -> Option<Chosen> {
    let c = chooser.as_mut()?;
    // A modal: the window behind it takes no click, no focus and no Tab while it is open
    // (the teacher's review: Tab then Space, in the chooser, opened the Scene menu behind
    // it); its keys are held by `help::Asking::Choice`.
    let width = 520.0_f32.min(ctx.content_rect().width() - 48.0);
    let (done, cancel) = egui::Modal::new(egui::Id::unique("phonglab chooser"))
        .show(ctx, |ui| {
            ui.set_width(width);
            ui.vertical_centered(|ui| ui.heading(t!("chooser-title")));
            ui.label(&c.why);
            ui.separator();
            chooser_body_ui(ui, c)
        })
        .inner;
    if cancel || done.is_some() {
        *chooser = None;
    }
    done
}

/// The folder field, its listing, the name field and the buttons: (what was chosen,
/// cancelled).
fn chooser_body_ui(ui: &mut Ui, c: &mut Chooser) -> (Option<Chosen>, bool) {
    ui.horizontal(|ui| {
        let label = ui.label(t!("chooser-folder"));
        ui.add(egui::TextEdit::singleline(&mut c.folder).desired_width(360.0)).labelled_by(label.id);
        if ui.button(t!("chooser-up")).clicked()
            && let Some(up) = Path::new(c.folder.trim()).parent()
        {
            c.folder = up.display().to_string();
        }
    });
    let extensions = c.purpose.extensions();
    let wanted: Vec<&str> = extensions.iter().map(String::as_str).collect();
    let mut enter = None;
    // A file double-clicked is chosen, as in every file dialog (it only selected before).
    let mut double_clicked = false;
    egui::ScrollArea::vertical().max_height(260.0).auto_shrink([false, true]).show(ui, |ui| {
        match list(Path::new(c.folder.trim()), &wanted) {
            Ok(entries) if entries.is_empty() => {
                ui.weak(t!("chooser-empty"));
            }
            Ok(entries) => {
                for Entry { name, folder } in entries {
                    // A name is shown as the terminal shows it: a line break, a right-to-left
                    // override or an ESC in it written visibly (`\u{202E}`).
                    let visible = phonglab_core::escape::window::text(&name);
                    let shown = if folder { format!("{visible}/") } else { visible };
                    let selected = !folder && name == c.name;
                    let item = ui.selectable_label(selected, shown);
                    if item.clicked() || item.double_clicked() {
                        // Only the file the double click's first click selected (in an
                        // earlier frame, or in this one: a slow frame takes both clicks, on
                        // one layout): egui's double click is the pointer's, and a list that
                        // moved between the two clicks would choose whatever the second one
                        // landed on.
                        let both_now = ui.input(|i| {
                            let released = |e: &&egui::Event| {
                                matches!(
                                    e,
                                    egui::Event::PointerButton {
                                        pressed: false,
                                        button: egui::PointerButton::Primary,
                                        ..
                                    }
                                )
                            };
                            i.events.iter().filter(released).count() >= 2
                        });
                        double_clicked |= (selected || both_now) && item.double_clicked();
                        if folder {
                            enter = Some(name);
                        } else {
                            c.name = name;
                        }
                    }
                }
            }
            Err(e) => {
                ui.colored_label(crate::app::widgets::palette::ERROR, e);
            }
        }
    });
    if let Some(sub) = enter {
        c.folder = Path::new(c.folder.trim()).join(sub).display().to_string();
    }
    let mut entered = false;
    ui.horizontal(|ui| {
        let label = ui.label(t!("chooser-name"));
        let field = ui.add(egui::TextEdit::singleline(&mut c.name).desired_width(300.0)).labelled_by(label.id);
        // Enter in the name field does what the button does (where the button may); so
        // does Enter after a file is selected in the list, while no text field is being
        // typed in.
        let focused = ui.memory(egui::Memory::focused);
        let typing = focused.is_some_and(|id| egui::TextEdit::load_state(ui.ctx(), id).is_some());
        let enter = ui.input(|i| i.key_pressed(egui::Key::Enter));
        entered = (field.lost_focus() && enter) || (enter && !typing && !c.name.trim().is_empty());
    });
    // Only where the button opens a file: for a save, a double click selects the name.
    let opens = matches!(c.purpose, Purpose::OpenScene | Purpose::CheckWork);
    entered |= double_clicked && opens;
    let mut done = None;
    let mut cancel = false;
    ui.horizontal(|ui| {
        let (verb, ok) = match &c.purpose {
            Purpose::OpenScene => (t!("open"), Path::new(&c.path()).is_file()),
            Purpose::CheckWork => (t!("student-check"), Path::new(&c.path()).is_file()),
            _ => (t!("save"), !c.name.trim().is_empty()),
        };
        if ui.add_enabled(ok, egui::Button::new(verb)).clicked() || (ok && entered) {
            let path = c.path();
            done = Some(match &c.purpose {
                Purpose::OpenScene => Chosen::Open(path),
                Purpose::SaveScene => Chosen::Save(path),
                Purpose::CheckWork => Chosen::Check(path),
                Purpose::SaveBytes { bytes, .. } => Chosen::SaveBytes(path, bytes.clone()),
            });
        }
        if ui.button(t!("chooser-cancel")).clicked() {
            cancel = true;
        }
    });
    (done, cancel)
}
