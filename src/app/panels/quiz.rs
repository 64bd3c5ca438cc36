//! Quiz mode: the worked calculation with every value hidden behind a field. The student
//! types each step's value; leaving the field checks it, and the mark says which check it
//! passed ([`phonglab_core::quiz::Mark`]): right; right given the student's own earlier
//! answers; close, with the digits it needs; or wrong, with the formula and the value it
//! gives. Each step's mark has its own reserved space, so no field moves when one appears.
//! While the quiz is open the vertex colour and the plot's angles (the answers) are hidden,
//! unless the teacher shows them. A score, "Reveal" per step and "Reveal all"; the quiz and
//! its answers are kept across restarts.

use egui::{RichText, Ui};
use phonglab_core::explain::{Explanation, Side, explain, fmt_value};
use phonglab_core::quiz::{Mark, TOLERANCE, Verdict, asked, check, parse_answer, score};
use phonglab_core::{Document, Engine};
use serde::{Deserialize, Serialize};

use crate::app::widgets::palette;
use crate::{locale, t};

/// The quiz: its scene and the student's work on it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuizState {
    /// The quiz is shown in place of the worked calculation.
    pub open: bool,
    /// The exercise's scene (`None`: not started).
    pub doc: Option<Document>,
    /// The text typed for each step.
    pub answers: Vec<String>,
    /// The step has been checked (Enter, or the field left).
    pub checked: Vec<bool>,
    /// The step's value is shown (the teacher revealed it).
    pub revealed: Vec<bool>,
    /// The level of "New exercise" (1 to 4).
    pub level: u8,
    /// The seed of the last generated exercise.
    pub seed: u64,
    /// The teacher shows the answers (the vertex colour, the plot's angles, every key).
    pub show_answers: bool,
    /// A picture question ("What is wrong with this picture?") in place of the steps.
    pub wrong: Option<super::quiz_picture::WrongQuestion>,
    /// How many picture questions have been asked (the next mistake shown).
    pub wrong_asked: usize,
}

/// What is kept across restarts.
#[derive(Serialize, Deserialize)]
struct Saved {
    doc: String,
    answers: Vec<String>,
    checked: Vec<bool>,
    revealed: Vec<bool>,
}

/// The key the quiz is kept under in eframe's storage.
pub const QUIZ_KEY: &str = "phonglab.quiz.ron";

impl QuizState {
    /// Starts a quiz on `doc`, with no answers.
    pub fn start(&mut self, doc: Document) {
        let (level, seed) = (self.level, self.seed);
        *self = QuizState { open: true, doc: Some(doc), level, seed, ..Default::default() };
    }

    /// Generates an exercise of `self.level` from `seed` (the worksheet's rules) and starts
    /// a quiz on it; returns its document, or why not.
    pub fn new_exercise(&mut self, seed: u64) -> Result<Document, String> {
        use phonglab_core::exercise::{Level, Spec, generate};
        let level = Level::from_number(self.level.clamp(1, 4)).ok_or("no such level")?;
        let ex = generate(seed, 1, &Spec::level(level, phonglab_core::Rules::WORKSHEET))?;
        let doc = ex.into_iter().next().ok_or("no exercise")?.doc;
        self.seed = seed;
        self.start(doc.clone());
        Ok(doc)
    }

    /// The quiz as stored (`None`: nothing started).
    pub fn to_ron(&self) -> Option<String> {
        let doc = self.doc.as_ref()?.to_toml().ok()?;
        ron::to_string(&Saved {
            doc,
            answers: self.answers.clone(),
            checked: self.checked.clone(),
            revealed: self.revealed.clone(),
        })
        .ok()
    }

    /// The stored quiz, closed (`None` when there is none or it does not read).
    pub fn from_ron(text: &str) -> Option<QuizState> {
        let s: Saved = ron::from_str(text).ok()?;
        let doc = Document::from_toml(&s.doc).ok()?;
        Some(QuizState {
            open: false,
            doc: Some(doc),
            answers: s.answers,
            checked: s.checked,
            revealed: s.revealed,
            level: 2,
            seed: 0,
            show_answers: false,
            wrong: None,
            wrong_asked: 0,
        })
    }

    /// The answer key (front side, f64).
    pub fn key(&self) -> Option<Explanation> {
        let doc = self.doc.as_ref()?;
        let lit = Engine::<f64>::new(&doc.scene).ok()?.light(&doc.scene.vertex);
        Some(explain(&doc.scene, &lit, Side::Front))
    }

    /// The answers that have been checked, as numbers (`None`: not checked or not numbers).
    pub fn parsed(&self) -> Vec<Option<Vec<f64>>> {
        self.answers.iter().zip(&self.checked).map(|(a, c)| if *c { parse_answer(a).ok() } else { None }).collect()
    }

    /// The verdict on step `k` (checked steps only).
    pub fn verdict(&self, key: &Explanation, k: usize) -> Option<Verdict> {
        let doc = self.doc.as_ref()?;
        check(&doc.scene, key, &self.parsed(), k)
    }

    /// Are the answers (the vertex colour, the plot's angles) hidden now?
    pub fn hides_answers(&self) -> bool {
        self.open && !self.show_answers
    }

    fn fit(&mut self, n: usize) {
        self.answers.resize(n, String::new());
        self.checked.resize(n, false);
        self.revealed.resize(n, false);
    }
}

/// The inputs a wrong answer's formula takes: the student's own earlier answers with their
/// values, the key's by name only (never a value the student has not found).
fn inputs_text(v: &Verdict) -> String {
    let list: Vec<String> = v
        .inputs
        .iter()
        .map(|(name, val, own)| {
            if *own {
                t!("quiz-input-yours", name = name, value = locale::decimal(&fmt_value(val, 8)))
            } else {
                t!("quiz-input-key", name = name)
            }
        })
        .collect();
    if list.is_empty() { t!("quiz-the-givens") } else { list.join(", ") }
}

/// The formula without OpenGL's names (which follow it in parentheses).
fn worksheet_formula(formula: &str) -> &str {
    formula.split("   (").next().unwrap_or(formula)
}

/// What a mark says, and whether it counts as right.
pub fn mark_text(v: &Verdict) -> (String, bool) {
    match &v.mark {
        Mark::Right => (t!("quiz-right"), true),
        Mark::RightGivenYours { yours, .. } => (t!("quiz-right-given", yours = yours.join(", ")), true),
        Mark::Close { percent, digits } => {
            let percent = locale::num(*percent, 1);
            let digits = *digits as i64;
            if close_to_key(v) {
                (t!("quiz-close-key", percent = percent, digits = digits), false)
            } else {
                (t!("quiz-close-yours", percent = percent, digits = digits), false)
            }
        }
        // The formula and what it takes, never the value it gives: the key stays hidden
        // until the student asks for it.
        Mark::Wrong => (t!("quiz-wrong", formula = worksheet_formula(&v.formula), inputs = inputs_text(v)), false),
    }
}

fn close_to_key(v: &Verdict) -> bool {
    phonglab_core::quiz::close(&v.expected, &v.key)
}

/// The quiz's buttons, all one size (the widest's), two to a row.
fn buttons_ui(ui: &mut Ui, labels: &[(String, String)]) -> Option<usize> {
    let font = egui::TextStyle::Button.resolve(ui.style());
    let pad = 2.0 * ui.spacing().button_padding.x;
    let widest = labels
        .iter()
        .map(|(l, _)| ui.ctx().fonts_mut(|f| f.layout_no_wrap(l.clone(), font.clone(), egui::Color32::WHITE).size().x))
        .fold(0.0, f32::max)
        + pad;
    let size = egui::vec2(widest, ui.spacing().interact_size.y);
    let mut clicked = None;
    ui.horizontal_wrapped(|ui| {
        for (k, (label, hover)) in labels.iter().enumerate() {
            if ui.add_sized(size, egui::Button::new(label)).on_hover_text(hover).clicked() {
                clicked = Some(k);
            }
        }
    });
    clicked
}

/// The quiz panel; `current` is the scene the app shows (a quiz can start on it). Returns a
/// generated exercise for the app to show.
pub fn quiz_ui(ui: &mut Ui, quiz: &mut QuizState, current: &Document) -> Option<Document> {
    let mut shown = None;
    ui.heading(t!("quiz"));
    // Level 2 (positional with attenuation) until one is chosen.
    quiz.level = if quiz.level == 0 { 2 } else { quiz.level.clamp(1, 4) };
    ui.horizontal_wrapped(|ui| {
        let mut level = u32::from(quiz.level);
        crate::app::widgets::fields::whole_number_ui(ui, &t!("quiz-level"), &mut level, 1..=4);
        quiz.level = level as u8;
        ui.small(t!("quiz-levels"));
    });
    let buttons = [
        (t!("quiz-this-scene"), t!("quiz-this-scene-hover")),
        (t!("quiz-new-exercise"), t!("quiz-new-exercise-hover")),
        (t!("quiz-reveal-all"), t!("quiz-reveal-all-hover")),
        (t!("quiz-clear"), t!("quiz-clear-hover")),
        (t!("wrong-title"), t!("wrong-quiz-hover")),
    ];
    match buttons_ui(ui, &buttons) {
        Some(0) => quiz.start(current.clone()),
        Some(1) => {
            let seed = quiz.seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407) >> 16;
            shown = quiz.new_exercise(seed).ok();
        }
        Some(2) => quiz.revealed.iter_mut().for_each(|r| *r = true),
        Some(3) => {
            let doc = quiz.doc.clone();
            quiz.start(doc.unwrap_or_default());
        }
        Some(4) => {
            // Each mistake in turn, from one the seed picks.
            let all = phonglab_core::misconception::Misconception::ALL;
            let kind = all[(quiz.seed as usize + quiz.wrong_asked) % all.len()];
            quiz.wrong_asked += 1;
            quiz.wrong = super::quiz_picture::WrongQuestion::new(kind).ok();
        }
        _ => {}
    }
    if let Some(q) = &mut quiz.wrong {
        if ui.button(t!("wrong-back")).clicked() {
            quiz.wrong = None;
        } else {
            egui::ScrollArea::vertical()
                .auto_shrink(false)
                .show(ui, |ui| super::quiz_picture::wrong_question_ui(ui, q));
        }
        return shown;
    }
    ui.checkbox(&mut quiz.show_answers, t!("quiz-show-answers")).on_hover_text(t!("quiz-show-answers-hover"));
    let Some(key) = quiz.key() else {
        ui.label(t!("quiz-nothing-open"));
        return shown;
    };
    let Some(doc) = quiz.doc.clone() else { return shown };
    ui.label(t!(
        "quiz-instructions",
        scene = phonglab_core::library::localised_name(&doc.name),
        percent = locale::num(100.0 * TOLERANCE.0, 2),
        absolute = locale::num(TOLERANCE.1, 2)
    ));
    let sc = score(&doc.scene, &key, &quiz.parsed(), &quiz.revealed);
    let text = t!("quiz-score", right = sc.right, all = sc.asked, answered = sc.answered, shown = sc.shown);
    ui.label(RichText::new(text).strong());
    ui.separator();
    // One field per step; after "Clear answers" just above, too.
    quiz.fit(key.steps.len());
    // Every row one width (the panel's, less the scroll bar), and Reveal as wide as its word
    // in this language and text size: no row grows, no button is clipped.
    let row_w = ui.available_width() - ui.spacing().scroll.bar_width - ui.spacing().scroll.bar_inner_margin;
    let font = egui::TextStyle::Button.resolve(ui.style());
    let word = ui.ctx().fonts_mut(|f| f.layout_no_wrap(t!("quiz-reveal"), font, egui::Color32::WHITE).size().x);
    let reveal_w = word + 2.0 * ui.spacing().button_padding.x + 4.0;
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        ui.set_max_width(row_w);
        for k in (0..key.steps.len()).filter(|k| asked(&doc.scene, &key, *k)) {
            step_ui(ui, quiz, &key, k, (row_w, reveal_w));
        }
    });
    shown
}

/// One step: its title, the name and the field, Reveal, and the space for its mark.
fn step_ui(ui: &mut Ui, quiz: &mut QuizState, key: &Explanation, k: usize, (row_w, reveal_w): (f32, f32)) {
    let st = &key.steps[k];
    let Some(value) = &st.value else { return };
    // The title and the name on one row, the field (wide enough for a 4-vector) and Reveal
    // on the next.
    let name = ui
        .horizontal_wrapped(|ui| {
            ui.label(RichText::new(&st.title).strong());
            let text = RichText::new(format!("{} =", st.name)).monospace();
            ui.add(egui::Label::new(text).wrap_mode(egui::TextWrapMode::Extend))
        })
        .inner;
    ui.horizontal(|ui| {
        let w = (row_w - reveal_w - ui.spacing().item_spacing.x).max(80.0);
        let field = ui
            .add(egui::TextEdit::singleline(&mut quiz.answers[k]).desired_width(w).hint_text(t!("quiz-your-value")))
            .labelled_by(name.id);
        if field.changed() {
            quiz.checked[k] = false;
        }
        if field.lost_focus() && !quiz.answers[k].trim().is_empty() {
            quiz.checked[k] = true;
        }
        let size = egui::vec2(reveal_w, ui.spacing().interact_size.y);
        if ui.add_sized(size, egui::Button::new(t!("quiz-reveal"))).on_hover_text(t!("quiz-reveal-hover")).clicked() {
            quiz.revealed[k] = true;
        }
    });
    // The mark and the key take this space whether they are shown or not (three rows of
    // text and the key's line), more where a mark needs more: a mark is never cut off.
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let mono = ui.text_style_height(&egui::TextStyle::Monospace);
    let ok = palette::ink(ui, egui::Color32::from_rgb(80, 200, 120));
    let bad = palette::ink(ui, palette::ERROR);
    let mark = quiz.checked[k].then(|| match parse_answer(&quiz.answers[k]) {
        Err(e) => (t!("quiz-not-numbers", error = e), bad),
        Ok(_) => match quiz.verdict(key, k) {
            Some(v) => {
                let (t, right) = mark_text(&v);
                (t, if right { ok } else { bad })
            }
            None => (String::new(), ok),
        },
    });
    let galley = mark.as_ref().map(|(text, colour)| {
        let font = egui::TextStyle::Body.resolve(ui.style());
        ui.ctx().fonts_mut(|f| f.layout(text.clone(), font, *colour, row_w))
    });
    let mark_h = galley.as_ref().map_or(0.0, |g| g.size().y).max((3.0 * body).ceil() + 1.0);
    let h = mark_h + mono + 2.0 * ui.spacing().item_spacing.y;
    let (rect, _) = ui.allocate_exact_size(egui::vec2(row_w, h), egui::Sense::hover());
    // A child that draws in the reserved rect without taking more space from the panel.
    let mut child = ui.new_child(egui::UiBuilder::new().max_rect(rect).id_salt(("mark", k)));
    child.set_clip_rect(rect.intersect(ui.clip_rect()));
    let ui = &mut child;
    {
        match galley {
            Some(g) => {
                ui.add(egui::Label::new(g));
            }
            None => ui.add_space(mark_h),
        }
        if quiz.revealed[k] || quiz.show_answers {
            ui.label(
                RichText::new(t!("quiz-key", name = &st.name, value = locale::decimal(&fmt_value(value, 8))))
                    .monospace()
                    .weak(),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quiz_is_kept_across_restarts() {
        let mut q = QuizState::default();
        assert_eq!(q.to_ron(), None);
        q.start(Document::default());
        q.fit(3);
        q.answers[1] = "[-512 -307.2 -729.6 1]".into();
        q.checked[1] = true;
        q.revealed[2] = true;
        let back = QuizState::from_ron(&q.to_ron().unwrap()).unwrap();
        assert_eq!(back.doc, q.doc);
        assert_eq!((back.answers, back.checked, back.revealed), (q.answers, q.checked, q.revealed));
        assert!(!back.open, "restored closed");
        assert!(QuizState::from_ron("(doc: 3").is_none());
    }
}
