//! A student's work checked, in the calculation panel: what they printed under each step's
//! value with its verdict (right; right given your X; rounding; wrong), the first wrong
//! step marked with a colour and a text marker, and above the steps the summary: the rules
//! assumed, the first wrong step and the causes with their formula and evidence, and Clear.
//! The check itself is the core's ([`phonglab_core::study::check::check`]).

use egui::{Color32, RichText, Ui};
use phonglab_core::scene::Scene;
use phonglab_core::study::check::printed::Printed;
use phonglab_core::study::check::said::{cause_line, numbers};
use phonglab_core::study::check::{Check, StepCheck, Verdict, check};

use crate::app::widgets::palette;
use crate::t;

/// A student's work checked against the scene shown (the assignment).
#[derive(Clone, Debug)]
pub struct StudentCheck {
    /// The file's name, as shown (printable).
    pub file: String,
    /// The core's check.
    pub check: Check,
    /// The scene the work typed, and what it printed: checked again when the scene shown
    /// (the assignment) changes.
    pub work: (Scene, Printed),
    /// The scene shown when it was checked (the assignment).
    pub against: Scene,
    /// How many typed inputs differed from the scene shown, when so many did
    /// ([`Check::other_scene`]) that the work was checked against its own scene instead.
    pub own_scene: Option<usize>,
}

impl StudentCheck {
    /// `work` (the scene it typed, what it printed) from `file` checked against `assignment`,
    /// or against the scene it typed when it looks typed for another scene
    /// ([`Check::other_scene`]: a notebook of the worksheet checked while the spotlight is
    /// shown): then its steps are judged on its own inputs, as `phonglab check` without
    /// `--scene` judges them, and the panel says so, instead of 60 inputs in red and a false
    /// "run every cell".
    pub fn new(file: String, assignment: &Scene, work: (Scene, Printed)) -> StudentCheck {
        let shown = check(assignment, &work.0, &work.1);
        let (check, own_scene) = if shown.other_scene() {
            (check(&work.0, &work.0, &work.1), Some(shown.inputs_differ.len()))
        } else {
            (shown, None)
        };
        StudentCheck { file, check, work, against: assignment.clone(), own_scene }
    }

    /// Checks the work again if the scene shown is no longer the one it was checked against.
    pub fn follow(&mut self, assignment: &Scene) {
        if &self.against != assignment {
            *self = StudentCheck::new(std::mem::take(&mut self.file), assignment, self.work.clone());
        }
    }

    /// The student's step printed under the worksheet's `name` (`vlv`, `vlv[1]`), and
    /// the check when it is the first wrong one (its causes are said beside it).
    /// `None` for every step when the work was checked against its own scene
    /// ([`StudentCheck::own_scene`]): the steps shown are the scene shown's, and its values
    /// ("yours = [-512 …]: right") beside another scene's would read as wrong or right of
    /// these; the summary names its first wrong step with both values.
    pub fn step(&self, name: &str) -> Option<(&StepCheck, Option<&Check>)> {
        if self.own_scene.is_some() {
            return None;
        }
        let k = self.check.steps.iter().position(|s| s.name == name)?;
        Some((&self.check.steps[k], (self.check.first_wrong == Some(k)).then_some(&self.check)))
    }
}

/// The first wrong step's fill: the panel's background with a fifth of red in it (opaque,
/// so the text's contrast on it is known).
pub fn wrong_fill(v: &egui::Visuals) -> Color32 {
    let (bg, red) = (v.panel_fill, palette::ERROR);
    let mix = |b: u8, r: u8| (b as f32 * 0.8 + r as f32 * 0.2).round() as u8;
    Color32::from_rgb(mix(bg.r(), red.r()), mix(bg.g(), red.g()), mix(bg.b(), red.b()))
}

/// The wrong steps' red: readable as text ([`palette::TEXT_CONTRAST`]) on the first wrong
/// step's fill, so on the panel's background too, in either theme.
pub fn wrong_ink_in(v: &egui::Visuals) -> Color32 {
    palette::ink_with_contrast(palette::ERROR, wrong_fill(v), palette::TEXT_CONTRAST)
}

/// [`wrong_ink_in`] `ui`'s theme.
pub fn wrong_ink(ui: &Ui) -> Color32 {
    wrong_ink_in(ui.visuals())
}

/// The first wrong step's frame: a tinted fill and a thick red stroke, seen at a projector
/// in either theme.
pub fn first_wrong_frame(ui: &Ui) -> egui::Frame {
    egui::Frame::new()
        .fill(wrong_fill(ui.visuals()))
        .stroke(egui::Stroke::new(2.0, wrong_ink(ui)))
        .corner_radius(4.0)
        .inner_margin(4.0)
}

/// The student's value under the key's, with its verdict; the first wrong step's with its
/// marker and its likely causes in words (`first_wrong`: the check, when it is the first
/// wrong step), so that the step and why are seen together.
pub fn student_value_ui(ui: &mut Ui, step: &StepCheck, first_wrong: Option<&Check>) {
    let line = t!("student-value", student = numbers(&step.student), verdict = step.verdict.words());
    let mut text = RichText::new(line).monospace();
    text = match &step.verdict {
        Verdict::Wrong => text.color(wrong_ink(ui)).strong(),
        Verdict::Rounding | Verdict::RightGiven(_) | Verdict::TooFewDigits(_) => {
            text.color(palette::ink(ui, palette::NOTE))
        }
        Verdict::Right => text.color(palette::ink(ui, palette::V)),
    };
    ui.add(egui::Label::new(text).wrap());
    if let Some(c) = first_wrong {
        ui.label(RichText::new(t!("student-first-wrong-marker")).color(wrong_ink(ui)).strong());
        for cause in &c.causes {
            let line = t!("student-cause-beside", words = cause.words(), id = cause.info.id);
            ui.add(egui::Label::new(line).wrap());
        }
    }
}

/// The summary above the steps: whose work, the rules, the first wrong step, the causes in
/// words with their formula and evidence, and Clear (which empties `student`).
pub fn student_summary_ui(ui: &mut Ui, student: &mut Option<StudentCheck>) {
    let Some(s) = student.as_ref() else { return };
    let mut clear = false;
    egui::Frame::group(ui.style()).show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(t!("student-heading", file = s.file.clone())).strong());
            clear = ui.button(t!("student-clear")).on_hover_text(t!("student-clear-hover")).clicked();
        });
        if let Some(count) = s.own_scene {
            let line = t!("student-own-scene", count = count);
            ui.add(egui::Label::new(RichText::new(line).color(wrong_ink(ui)).strong()).wrap());
        }
        findings_ui(ui, &s.check);
    });
    if clear {
        *student = None;
    }
}

/// The check's findings in words: rules, typed inputs, verdict, causes.
fn findings_ui(ui: &mut Ui, c: &Check) {
    // At the body's size: read at a projector like the rest.
    ui.add(egui::Label::new(t!("check-rules", rules = c.rules.to_string())).wrap());
    if !c.inputs_differ.is_empty() {
        // By the worksheet's names, the rule set in words: as the command line says them.
        let names = phonglab_core::study::check::said::input_names(c);
        let line = t!("check-inputs-differ", names = names);
        ui.label(RichText::new(line).color(wrong_ink(ui)));
    }
    if c.steps.is_empty() {
        ui.label(t!("check-nothing-printed"));
    }
    match c.first_wrong.and_then(|k| c.steps.get(k)) {
        Some(s) => {
            let line =
                t!("check-first-wrong", step = s.name.clone(), student = numbers(&s.student), key = numbers(&s.key));
            ui.add(egui::Label::new(RichText::new(line).color(wrong_ink(ui)).strong()).wrap());
        }
        None if c.right() => {
            ui.label(RichText::new(t!("check-all-right")).color(palette::ink(ui, palette::V)).strong());
        }
        None => {}
    }
    // Why the work is not whole (the run stopped, outputs out of order), and the steps the
    // worksheet asks for that it does not print: incomplete, never right.
    let why = c.unchecked().filter(|_| !c.steps.is_empty());
    let not_printed = c.not_printed_reason().filter(|n| why.as_ref() != Some(n));
    for u in why.iter().chain(&not_printed) {
        ui.add(egui::Label::new(RichText::new(u.words()).color(wrong_ink(ui))).wrap());
    }
    for cause in &c.causes {
        ui.add(egui::Label::new(cause_line(c, cause)).wrap());
        ui.add(egui::Label::new(RichText::new(cause.formula()).monospace().weak()).wrap());
    }
    if c.first_wrong.is_some() && c.causes.is_empty() {
        ui.label(t!("check-no-cause"));
    }
}
