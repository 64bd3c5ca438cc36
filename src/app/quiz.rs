//! Quiz mode: the worked calculation with every value hidden behind a field. The student
//! types each step's value; Enter checks it (✔, or ✖ with the formula expected and the
//! inputs it took, the student's own earlier values where the formula takes them). A
//! score, "Reveal" per step and "Reveal all" for the teacher; the quiz and its answers are
//! kept across restarts.

use egui::{RichText, Ui};
use phonglab_core::explain::{Explanation, Side, explain, fmt_value};
use phonglab_core::quiz::{Verdict, check, parse_answer, score};
use phonglab_core::{Document, Engine};
use serde::{Deserialize, Serialize};

use super::palette;

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

    fn fit(&mut self, n: usize) {
        self.answers.resize(n, String::new());
        self.checked.resize(n, false);
        self.revealed.resize(n, false);
    }
}

fn inputs_text(v: &Verdict) -> String {
    let list: Vec<String> = v
        .inputs
        .iter()
        .map(|(name, val, own)| format!("{name} = {}{}", fmt_value(val, 8), if *own { " (yours)" } else { " (key)" }))
        .collect();
    if list.is_empty() { "the givens".into() } else { list.join(", ") }
}

/// The quiz panel; `current` is the scene the app shows (a quiz can start on it). Returns a
/// generated exercise for the app to show.
pub fn quiz_ui(ui: &mut Ui, quiz: &mut QuizState, current: &Document) -> Option<Document> {
    let mut shown = None;
    ui.horizontal_wrapped(|ui| {
        ui.heading("Quiz");
        if ui.button("Quiz this scene").on_hover_text("Start over on the scene shown, every value hidden").clicked() {
            quiz.start(current.clone());
        }
        // Level 2 (positional with attenuation) until one is chosen.
        quiz.level = if quiz.level == 0 { 2 } else { quiz.level.clamp(1, 4) };
        let mut level = u32::from(quiz.level);
        super::widgets::whole_number_ui(ui, "Level", &mut level, 1..=4);
        quiz.level = level as u8;
        if ui
            .button("New exercise")
            .on_hover_text("A new scene of this level, screened as phonglab exercise screens")
            .clicked()
        {
            let seed = quiz.seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407) >> 16;
            shown = quiz.new_exercise(seed).ok();
        }
    });
    let Some(key) = quiz.key() else {
        ui.label("Open an exercise (phonglab exercise writes them) or any scene, then press \"Quiz this scene\", or press New exercise.");
        return shown;
    };
    let scene = &quiz.doc.as_ref().map(|d| d.name.clone()).unwrap_or_default();
    ui.small(format!(
        "{scene}: type each step's value and press Enter. 1e-4 relative or 1e-6 absolute counts as right."
    ));
    let (right, answered, all) = quiz.doc.as_ref().map_or((0, 0, 0), |d| score(&d.scene, &key, &quiz.parsed()));
    ui.horizontal_wrapped(|ui| {
        ui.label(RichText::new(format!("Score: {right} of {all} ({answered} answered)")).strong());
        if ui.button("Reveal all").clicked() {
            quiz.revealed.iter_mut().for_each(|r| *r = true);
        }
        if ui.button("Clear answers").clicked() {
            let doc = quiz.doc.clone();
            quiz.start(doc.unwrap_or_default());
        }
    });
    ui.separator();
    // One field per step; after "Clear answers" just above, too.
    quiz.fit(key.steps.len());
    let ok = palette::ink(ui, egui::Color32::from_rgb(80, 200, 120));
    let bad = palette::ink(ui, palette::ERROR);
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        for (k, st) in key.steps.iter().enumerate() {
            let Some(value) = &st.value else { continue };
            ui.label(RichText::new(format!("{:>2}. {}", k + 1, st.title)).strong());
            ui.horizontal(|ui| {
                let label = ui.monospace(format!("{} =", st.name));
                let field = ui
                    .add(egui::TextEdit::singleline(&mut quiz.answers[k]).desired_width(240.0).hint_text("your value"))
                    .labelled_by(label.id);
                if field.changed() {
                    quiz.checked[k] = false;
                }
                if field.lost_focus() && !quiz.answers[k].trim().is_empty() {
                    quiz.checked[k] = true;
                }
                if ui.small_button("Reveal").on_hover_text("Show the key's value for this step").clicked() {
                    quiz.revealed[k] = true;
                }
            });
            if quiz.checked[k] {
                match parse_answer(&quiz.answers[k]) {
                    Err(e) => {
                        ui.colored_label(bad, format!("does not read as numbers: {e}"));
                    }
                    Ok(_) => match quiz.verdict(&key, k) {
                        Some(v) if v.right => {
                            ui.colored_label(ok, "✔ right");
                        }
                        Some(v) => {
                            ui.colored_label(bad, format!("✖ expected {} from {}", v.formula, inputs_text(&v)));
                        }
                        None => {}
                    },
                }
            }
            if quiz.revealed[k] {
                ui.label(RichText::new(format!("key: {} = {}", st.name, fmt_value(value, 8))).monospace().weak());
            }
            ui.add_space(4.0);
        }
    });
    shown
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
