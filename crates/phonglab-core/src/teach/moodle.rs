//! Exercises as questions for Moodle's question bank ([`crate::formats::question`]): an
//! exercise's sheet as one statement with a numerical part for each value the sheet asks,
//! and "What is wrong with this picture?" as a multiple choice with its two pictures.
//!
//! A part is right within the quiz's rule ([`crate::teach::quiz::TOLERANCE`]: 1e-4 of the
//! value, or 1e-6 near 0), and its label asks for the significant digits that rule needs
//! ([`crate::teach::quiz::digits_needed`]); an exam's part ([`Rounding::Exam`]) asks for
//! four significant digits and takes half a unit of the fourth. Each part's feedback is
//! the step's formula and, for a wrong answer, the values it takes: never the key's value,
//! which Moodle shows only where the quiz's review options show the right answer.

use std::fmt::Write as _;

use crate::equation::explain::{Explanation, StepKind, printed_components};
use crate::formats::escape::html::text as esc;
use crate::formats::question::{Body, Choice, File, Part, Question};
use crate::model::vocabulary::Quantity as Q;
use crate::teach::exercise::{Exercise, rules_in_words};
use crate::teach::misconception::Misconception;
use crate::teach::quiz;

/// The digits a part asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rounding {
    /// As many as the quiz's rule needs for the value.
    Quiz,
    /// Four significant digits: an exam without a calculator.
    Exam,
}

/// The significant digits of an exam's answers.
pub const EXAM_DIGITS: usize = 4;

impl Rounding {
    /// The digits asked for `x` and the tolerance of the part: a quiz's the quiz's rule on
    /// the value as computed; an exam's taken from the exact answer ([`Rounding::answer`]),
    /// not from the engine's `0.8000000000000007`, and rounded to [`TOLERANCE_DIGITS`]
    /// significant digits, so that the product's last-bit noise (`0.8 * 1e-4` is
    /// `8.000000000000001e-5`) is not written into the file.
    pub fn of(self, x: f64) -> (usize, f64) {
        let (rel, abs) = quiz::TOLERANCE;
        let quiz_tolerance = |x: f64| (rel * x.abs()).max(abs);
        match self {
            Rounding::Quiz => (quiz::digits_needed(&[x]), quiz_tolerance(x)),
            Rounding::Exam => {
                // Exactly half a unit of the last digit the key shows (every digit of a
                // whole part): the honest roundings with Moodle's slack ([`MOODLE_SLACK`]),
                // never the quiz's 0.01 %, which above 5.05 in the leading digits takes a
                // neighbour (0.7839 for 0.78384). 0 takes half a unit of the eighth decimal,
                // below any other exam value.
                let x = self.answer(x);
                let shown = EXAM_DIGITS.max(whole_digits(x));
                let tolerance = if x == 0.0 {
                    0.5 * 10f64.powi(-(crate::teach::exam::MAX_DECIMALS as i32))
                } else {
                    half_unit(x, shown)
                };
                (EXAM_DIGITS, to_significant(tolerance, TOLERANCE_DIGITS))
            }
        }
    }

    /// The answer a part holds for `x`: an exam's value as the exact decimal it is (it ends
    /// in at most [`crate::teach::exam::MAX_DECIMALS`] decimals: `-0.6`, not the
    /// `-0.6000000000000001` the engine's arithmetic leaves), a quiz's as computed.
    pub fn answer(self, x: f64) -> f64 {
        match self {
            Rounding::Quiz => x,
            Rounding::Exam => {
                let scale = 10f64.powi(crate::teach::exam::MAX_DECIMALS as i32);
                let exact = (x * scale).round() / scale;
                if exact == 0.0 { 0.0 } else { exact }
            }
        }
    }
}

/// `x` to `digits` significant digits as a student rounds it by hand: half away from zero
/// on the decimal the key shows (its shortest, [`crate::formats::question::shortest_decimal`]),
/// so 1.5875 is 1.588 and -0.14625 is -0.1463, where rounding the double (a hair below
/// 1.5875) gives 1.587. Its trailing zeros kept (0.1360, -0.6000); a whole number keeps
/// every digit (12345); 0 is `0`; with a point.
pub fn round_by_hand(x: f64, digits: usize) -> String {
    use crate::formats::question::{positional, shortest_decimal};
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let (negative, mut d, mut exponent) = shortest_decimal(x);
    // The digits kept: as asked, or every digit of the whole part.
    let keep = digits.max(1).max((exponent + 1).max(0) as usize);
    if d.len() > keep {
        let up = d[keep] >= 5;
        d.truncate(keep);
        if up {
            let mut k = keep;
            loop {
                if k == 0 {
                    // 9.99996 to four digits: 10.00.
                    d.insert(0, 1);
                    d.truncate(keep.max((exponent + 2).max(0) as usize));
                    exponent += 1;
                    break;
                }
                k -= 1;
                if d[k] == 9 {
                    d[k] = 0;
                } else {
                    d[k] += 1;
                    break;
                }
            }
        }
    }
    d.resize(keep.max(d.len()), 0);
    positional(negative, &d, exponent)
}

/// The significant digits a tolerance is written with: far more than any rule asks for (the
/// quiz's 1e-4 of a value with eight, an exam's 1.01 half units), far fewer than a double's
/// 17, whose last ones are the arithmetic's noise.
pub const TOLERANCE_DIGITS: usize = 12;

/// `x` rounded to `digits` significant digits (to nearest), as a double: `8.000000000000001e-5`
/// to 12 is `8e-5`.
pub fn to_significant(x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    format!("{:.*e}", digits.max(1) - 1, x).parse().unwrap_or(x)
}

/// Moodle's own slack on a nominal tolerance (`qtype_numerical_answer::get_tolerance_interval`:
/// the tolerance grows by 1e-14, PHP's `precision`, of the larger of itself and the
/// answer). It makes an exam's tolerance of exactly half a unit take both neighbours of a
/// tie (0.14625: 0.1462 and 0.1463, half-up or as the double rounds), which a bare float
/// comparison may refuse by a hair, and still no other four-digit number: an exam value ends
/// in at most eight decimals, so any other is at least half a unit and 1e-8 away.
pub const MOODLE_SLACK: f64 = 1e-14;

/// The digits of `x`'s whole part (0 for |x| < 1): a key shows them all (12345).
fn whole_digits(x: f64) -> usize {
    if x.abs() < 1.0 { 0 } else { (x.abs().log10().floor() as i64 + 1).max(0) as usize }
}

/// Half a unit of `x`'s last digit when it is written to `digits` significant digits.
pub fn half_unit(x: f64, digits: usize) -> f64 {
    let exponent = x.abs().log10().floor() as i32;
    0.5 * 10f64.powi(exponent + 1 - digits as i32)
}

/// A vector or colour as the sheet writes it, in the reader's decimal mark: `[0,6 0,8 0 1]`.
fn vector(v: &[f64]) -> String {
    let parts: Vec<String> = printed_components(v, 8).iter().map(|x| crate::locale::num(*x, 8)).collect();
    format!("[{}]", parts.join(" "))
}

fn colour(c: glam::DVec4) -> String {
    vector(&[c.x, c.y, c.z, 0.0])
}

fn item(o: &mut String, name: &str, value: &str) {
    let _ = writeln!(o, "<li><code>{}</code> = {}</li>", esc(name), esc(value));
}

/// The givens of an exercise as HTML, in the sheet's order and words.
pub fn givens_html(ex: &Exercise) -> String {
    let s = &ex.doc.scene;
    let mut o = String::new();
    let _ = writeln!(o, "<h4>{}</h4>\n<ul>", esc(&crate::t!("sheet-vertex")));
    item(&mut o, Q::VertexPos.name(), &vector(&s.vertex.position.to_array()));
    item(&mut o, Q::VertexNormal.name(), &vector(&s.vertex.normal.extend(0.0).to_array()));
    let _ =
        writeln!(o, "</ul>\n<h4>{}</h4>\n<p>{}:</p>\n<pre>", esc(&crate::t!("sheet-modelview")), esc(&ex.modelview));
    let rows = crate::model::transform::mat4_rows(&s.eye_from_world);
    let printed = printed_components(rows.as_flattened(), 8);
    for r in printed.chunks(4) {
        let row: Vec<String> = r.iter().map(|x| format!("{:>12}", crate::locale::num(*x, 8))).collect();
        let _ = writeln!(o, "[{}]", esc(&row.join(" ")));
    }
    o.push_str("</pre>\n");
    for (i, l) in s.lights.iter().enumerate() {
        let _ = writeln!(o, "<h4>{}</h4>\n<ul>", esc(&crate::t!("light-tab", index = i.to_string())));
        let what = if l.position.w == 0.0 { crate::t!("sheet-direction") } else { crate::t!("sheet-position") };
        let note = crate::t!("sheet-light-world", what = what);
        item(&mut o, Q::LightPos.name(), &format!("{} ({note})", vector(&l.position.to_array())));
        item(&mut o, Q::LightAmbient.name(), &colour(l.ambient));
        item(&mut o, Q::LightDiffuse.name(), &colour(l.diffuse));
        item(&mut o, Q::LightSpecular.name(), &colour(l.specular));
        if l.position.w != 0.0 {
            for (q, v) in [Q::AttConstant, Q::AttLinear, Q::AttQuadratic].into_iter().zip(l.attenuation) {
                item(&mut o, q.name(), &crate::locale::num(v, 8));
            }
        }
        if l.is_spot() {
            let note = crate::t!("sheet-light-world", what = crate::t!("sheet-direction"));
            let direction = vector(&l.spot_direction.extend(0.0).to_array());
            item(&mut o, Q::SpotDirection.name(), &format!("{direction} ({note})"));
            let cutoff = crate::t!("sheet-degrees", value = crate::locale::num(l.spot_cutoff, 8));
            item(&mut o, Q::SpotCutoff.name(), &cutoff);
            item(&mut o, Q::SpotExponent.name(), &crate::locale::num(l.spot_exponent, 8));
        }
        o.push_str("</ul>\n");
    }
    let m = &s.material;
    let material = crate::model::materials::display_name(&ex.material);
    let _ = writeln!(o, "<h4>{}</h4>\n<ul>", esc(&crate::t!("sheet-material", name = material)));
    item(&mut o, Q::MatAmbient.name(), &colour(m.ambient));
    item(&mut o, Q::MatDiffuse.name(), &colour(m.diffuse));
    item(&mut o, Q::MatSpecular.name(), &colour(m.specular));
    item(&mut o, Q::Shininess.name(), &crate::locale::num(m.shininess, 8));
    let lm = &s.light_model;
    let yes_no = |b: bool| if b { crate::t!("yes") } else { crate::t!("no") };
    let _ = writeln!(o, "</ul>\n<h4>{}</h4>\n<ul>", esc(&crate::t!("sheet-light-model")));
    let _ = writeln!(o, "<li>{}: {}</li>", esc(&crate::t!("local-viewer")), esc(&yes_no(lm.local_viewer)));
    let _ = writeln!(o, "<li>{}: {}</li>", esc(&crate::t!("two-sided")), esc(&yes_no(lm.two_sided)));
    if s.rules.scene_ambient() {
        item(&mut o, &crate::t!("scene-ambient"), &colour(lm.ambient));
    }
    o.push_str("</ul>\n");
    o
}

/// The statement before the parts: what to do, under which rules, the decimal mark, the
/// givens.
fn statement_html(ex: &Exercise, rounding: Rounding) -> String {
    let s = &ex.doc.scene;
    let mut o = format!("<h3>{}</h3>\n", esc(&ex.doc.name));
    if rounding == Rounding::Exam {
        let _ = writeln!(
            o,
            "<p><strong>{}</strong> {}</p>",
            esc(&crate::t!("exam-no-calculator")),
            esc(&crate::t!("exam-by-hand"))
        );
    }
    let compute = crate::t!("sheet-compute", rules = rules_in_words(s.rules.set));
    let _ = writeln!(o, "<p>{} {}</p>", esc(&compute), esc(&crate::t!("sheet-colours")));
    if s.light_model.two_sided {
        let _ = writeln!(o, "<p>{}</p>", esc(&crate::t!("moodle-front-side")));
    }
    // Each value carried unrounded into the next step: a value carried with only the asked
    // digits can land outside the next field's tolerance.
    let digits = match rounding {
        Rounding::Quiz => format!("{} {}", quiz_tolerance_sentence(), crate::t!("moodle-carry")),
        Rounding::Exam => crate::t!("moodle-digits-exam", digits = EXAM_DIGITS.to_string()),
    };
    let _ = writeln!(o, "<p>{} {}</p>", esc(&digits), esc(&crate::t!("moodle-decimal-mark")));
    o.push_str(&givens_html(ex));
    let _ = writeln!(o, "<h4>{}</h4>", esc(&crate::t!("sheet-compute-heading")));
    o
}

/// What a quiz's field takes as right ([`quiz::TOLERANCE`]), its numbers in the reader's
/// decimal mark (`--decimal point` in Portuguese: `0.01 %`, not `0,01 %`).
fn quiz_tolerance_sentence() -> String {
    let (rel, abs) = quiz::TOLERANCE;
    let percent = crate::locale::decimal(&format!("{}", (rel * 1e6).round() / 1e4));
    let near_zero = crate::locale::decimal(&format!("{abs:.6}"));
    crate::t!("moodle-digits-quiz", percent = percent, near_zero = near_zero)
}

/// The names of a step's components: x, y, z for a vector or point, r, g, b (and a) for a
/// colour.
fn component_names(kind: StepKind) -> [&'static str; 4] {
    match kind {
        StepKind::Normal
        | StepKind::Position
        | StepKind::LightPosition
        | StepKind::L
        | StepKind::V
        | StepKind::H
        | StepKind::R => ["x", "y", "z", "w"],
        _ => ["r", "g", "b", "a"],
    }
}

/// How many of a value's components a part asks: all of a number or of the drawn colour
/// (its alpha is OpenGL's own), three of a 4-component vector or colour (the fourth, 0 or 1,
/// is the worksheet's convention and given).
fn asked_components(kind: StepKind, value: &[f64]) -> usize {
    if value.len() == 4 && kind != StepKind::Clamped { 3 } else { value.len() }
}

/// A step's formula without the values the key computed: the spotlight's formula ends with
/// its cosine `-L . s = 0.768` (after a `;`), which with an exponent of 1 is the step's
/// own value.
fn formula_without_values(kind: StepKind, formula: &str) -> String {
    match kind {
        StepKind::Spot => formula.split(';').next().unwrap_or(formula).trim_end().to_string(),
        _ => formula.to_string(),
    }
}

/// The values step `k` takes that the question shows: a given or an asked step by its
/// name; a step the question does not ask (`Ilight`) by what it takes in turn, `depth`
/// steps down at most.
fn asked_inputs(ex: &Exercise, key: &Explanation, k: usize, depth: usize) -> Vec<String> {
    let blank: Vec<Option<Vec<f64>>> = vec![None; key.steps.len()];
    let inputs = quiz::expected(&ex.doc.scene, key, &blank, k).map(|(_, i)| i).unwrap_or_default();
    let mut names = Vec::new();
    for (name, _, _) in inputs {
        let step = key.steps.iter().position(|s| s.name == name);
        match step {
            Some(j) if depth > 0 && j != k && !quiz::asked(&ex.doc.scene, key, j) => {
                names.extend(asked_inputs(ex, key, j, depth - 1));
            }
            _ => names.push(name),
        }
    }
    let mut seen = std::collections::HashSet::new();
    names.retain(|n| seen.insert(n.clone()));
    names
}

/// The feedback of step `k`'s parts: (right, wrong).
fn feedback(ex: &Exercise, key: &Explanation, k: usize) -> (String, String) {
    let st = &key.steps[k];
    let formula = dot(&formula_without_values(st.kind, &st.formula));
    let right = crate::t!("moodle-right", formula = formula.clone());
    let names = asked_inputs(ex, key, k, 4);
    let takes = if names.is_empty() { crate::t!("moodle-takes-givens") } else { names.join(", ") };
    let wrong = crate::t!("moodle-wrong", formula = formula, inputs = takes);
    (right, wrong)
}

/// The significant digits of the key's worked calculation (`phonglab explain`, the
/// sheets' keys).
pub const KEY_DIGITS: usize = 8;

/// A step's value as the key prints it ([`crate::equation::explain::printed_components`]):
/// a component below the largest one's last printed digit, or below a millionth of the
/// quiz's absolute tolerance (a value alone), is 0, and -0 is 0; so the engine's
/// `-0.000000000000001` next to a 2 is the key's 0, never written as an answer.
pub fn as_the_key_prints(value: &[f64]) -> Vec<f64> {
    let resolution = quiz::TOLERANCE.1 * 1e-6;
    crate::equation::explain::printed_components(value, KEY_DIGITS)
        .into_iter()
        .map(|x| if x.abs() < resolution { 0.0 } else { x })
        .collect()
}

/// The parts of an exercise: one per component of every step the sheet asks, numbered as
/// consecutive numbers.
pub fn parts(ex: &Exercise, rounding: Rounding) -> Vec<Part> {
    let key = &ex.key;
    let mut out = Vec::new();
    let asked = (0..key.steps.len()).filter(|&k| quiz::asked(&ex.doc.scene, key, k));
    // Rows numbered 1, 2, 3 … as the question asks them (the key's numbers skip the steps
    // it does not ask).
    for (row, k) in asked.enumerate() {
        let st = &key.steps[k];
        let Some(value) = &st.value else { continue };
        let (right, wrong) = feedback(ex, key, k);
        let value = &as_the_key_prints(value);
        let n = asked_components(st.kind, value);
        let asked: Vec<(usize, f64)> = value.iter().take(n).map(|&x| rounding.of(x)).collect();
        let digits = asked.iter().map(|(d, _)| *d).max().unwrap_or(1);
        let hint = crate::t!("moodle-part-digits", digits = digits as i64);
        let row_html =
            format!("{}. {}: <code>{}</code> <small>({})</small>", row + 1, esc(&st.title), esc(&st.name), esc(&hint));
        for (i, (&x, (_, tolerance))) in value.iter().zip(asked).enumerate() {
            let label_html = if n > 1 { esc(component_names(st.kind)[i]) } else { String::new() };
            out.push(Part {
                row_html: row_html.clone(),
                label_html,
                answer: rounding.answer(x),
                tolerance,
                right_feedback: right.clone(),
                wrong_feedback: wrong.clone(),
            });
        }
    }
    out
}

/// An exercise as a question, named as its scene is.
pub fn exercise_question(ex: &Exercise, rounding: Rounding) -> Question {
    Question {
        name: ex.doc.name.clone(),
        body: Body::Numbers { statement_html: statement_html(ex, rounding), parts: parts(ex, rounding) },
        general_feedback_html: format!("<p>{}</p>", esc(&crate::t!("moodle-general-feedback"))),
    }
}

/// The file names of a picture question's two pictures: the one drawn right, the one drawn
/// with the mistake. Neutral, the same in every question (Moodle keeps each question's
/// files apart).
pub const PICTURE_FILES: [&str; 2] = ["picture-1.png", "picture-2.png"];

/// "What is wrong with this picture?" for `kind` as a question named `name`: the picture
/// drawn right and the one drawn with the mistake (PNG bytes), and the seven causes to
/// choose from, each with its mistaken formula.
pub fn misconception_question(kind: Misconception, name: &str, right_png: Vec<u8>, wrong_png: Vec<u8>) -> Question {
    // Names that say nothing of the mistake: a student sees them by hovering a picture.
    let (right_file, wrong_file) = (PICTURE_FILES[0].to_string(), PICTURE_FILES[1].to_string());
    let figure = |file: &str, caption: String| {
        format!(
            "<figure style=\"display:inline-block;margin:0 1em 0 0\"><img src=\"@@PLUGINFILE@@/{file}\" alt=\"{c}\" width=\"192\" height=\"192\"><figcaption>{c}</figcaption></figure>",
            c = esc(&caption)
        )
    };
    let statement_html = format!(
        "<div>{}{}</div>\n<p>{}</p>",
        figure(&right_file, crate::t!("moodle-picture-right")),
        figure(&wrong_file, crate::t!("moodle-picture-wrong")),
        esc(&crate::t!("moodle-picture-question"))
    );
    let choices = Misconception::ALL
        .iter()
        .map(|&m| Choice {
            text: m.choice(),
            right: m == kind,
            feedback: if m == kind { m.why() } else { crate::t!("moodle-choice-not", why = m.why()) },
        })
        .collect();
    Question {
        name: name.to_string(),
        body: Body::Choice {
            statement_html,
            files: vec![File { name: right_file, bytes: right_png }, File { name: wrong_file, bytes: wrong_png }],
            choices,
        },
        general_feedback_html: format!("<p>{}</p>", esc(&picture_feedback(kind))),
    }
}

/// A picture question's general feedback: how each picture is drawn (not "Right: ...",
/// which would read as naming the right choice).
fn picture_feedback(kind: Misconception) -> String {
    let (right, wrong) = kind.formulas();
    crate::t!("moodle-picture-feedback", right = dot(&right), wrong = dot(&wrong))
}

/// A formula with the dot product written `·`, as the statements write it (`R . V` → `R · V`).
fn dot(formula: &str) -> String {
    formula.replace(" . ", " · ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_part_takes_the_quizs_tolerance_or_half_a_unit_of_the_fourth_digit() {
        assert_eq!(Rounding::Quiz.of(0.5), (1, 5e-5));
        assert_eq!(Rounding::Quiz.of(0.0), (1, 1e-6));
        let (digits, tolerance) = Rounding::Quiz.of(0.79220526);
        assert_eq!(digits, 4, "0.7922 is within 1e-4 of it");
        assert!((tolerance - 0.79220526e-4).abs() < 1e-15);
        let (digits, tolerance) = Rounding::Exam.of(38.2);
        assert_eq!(digits, 4);
        assert_eq!(tolerance, 0.005, "half a unit of 38.20's last digit: {tolerance}");
        // 0.12345 rounds to 0.1235 (or 0.1234): half a unit takes both, the quiz's rule neither.
        let (_, tolerance) = Rounding::Exam.of(0.12345);
        assert!((0.1235f64 - 0.12345).abs() <= tolerance + 1e-15 && tolerance < 6e-5);
        assert_eq!(Rounding::Exam.answer(0.8 * 0.5 - 1.0), -0.6, "the exact decimal, not -0.6000000000000001");
        assert_eq!(Rounding::Exam.answer(0.42024960000000006), 0.4202496);
    }

    /// Issue 60: `-0.000000000000001` (level 1's vertexPos x) was written as the right
    /// answer where the key says 0.
    #[test]
    fn float_noise_is_the_keys_zero_never_minus_zero() {
        assert_eq!(as_the_key_prints(&[-1e-15, 2.0, -3.5]), vec![0.0, 2.0, -3.5]);
        assert!(as_the_key_prints(&[-1e-15, 2.0])[0].is_sign_positive(), "never -0");
        assert!(as_the_key_prints(&[-0.0])[0].is_sign_positive(), "never -0");
        assert_eq!(as_the_key_prints(&[-1e-15]), vec![0.0], "a value alone");
        assert_eq!(as_the_key_prints(&[1e-5, 0.5]), vec![1e-5, 0.5], "a small value the key prints is kept");
    }

    #[test]
    fn a_tie_rounds_half_away_from_zero_on_the_decimal_the_key_shows() {
        // The double nearest 1.5875 is 1.58749999999999991...: binary rounding gives 1.587.
        assert_eq!(round_by_hand(1.5875, 4), "1.588");
        assert_eq!(round_by_hand(0.14625, 4), "0.1463");
        assert_eq!(round_by_hand(-0.14625, 4), "-0.1463");
        assert_eq!(round_by_hand(0.8 * 0.5 - 1.0, 4), "-0.6000", "-0.6000000000000001 is -0.6");
        assert_eq!(round_by_hand(0.1360384, 4), "0.1360");
        assert_eq!(round_by_hand(0.212992, 4), "0.2130");
        assert_eq!(round_by_hand(38.2, 4), "38.20");
        assert_eq!(round_by_hand(9.99996, 4), "10.00");
        assert_eq!(round_by_hand(99.996, 4), "100.0");
        assert_eq!(round_by_hand(0.099996, 4), "0.1000");
        assert_eq!(round_by_hand(12345.0, 4), "12345");
        assert_eq!(round_by_hand(0.0, 4), "0");
        assert_eq!(round_by_hand(0.00012344999, 4), "0.0001234");
    }

    #[test]
    fn numbers_are_written_with_a_point_and_no_exponent() {
        assert_eq!(crate::formats::question::number(0.64 * 1e-4), "0.000064", "not 0.00006400000000000001");
        assert_eq!(crate::formats::question::number(-0.8 * 0.5 - 0.2), "-0.6");
        assert_eq!(crate::formats::question::number(12345.0), "12345");
        assert_eq!(crate::formats::question::number(1200.0), "1200");
        use crate::formats::question::number;
        assert_eq!(number(-0.25), "-0.25");
        assert_eq!(number(3.7386036e-26), "0");
        assert_eq!(number(1.5e-9), "0.0000000015");
        assert_eq!(number(f64::NAN), "0");
    }
}
