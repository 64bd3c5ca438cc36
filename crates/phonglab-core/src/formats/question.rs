//! A bank of quiz questions as Moodle's question bank holds them, written by
//! [`super::moodle_xml`] and [`super::gift`]: categories, each with its questions, each
//! either a statement with numbered parts that take a number (Moodle's embedded answers,
//! "Cloze", one `NUMERICAL` part each) or a multiple choice with pictures.
//!
//! The HTML here is phonglab's own: every text a person typed was escaped by
//! [`super::escape::html::text`] when it was put in, so a writer escapes only for its
//! format. Numbers are `f64`; the writers print them with a point, as both formats read
//! them (the statement says in words that Moodle takes a comma too).

/// Questions grouped into categories, in order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Bank {
    /// The categories, each written before its questions.
    pub categories: Vec<Category>,
}

/// A question category: Moodle's "random question from category" draws from one.
#[derive(Clone, Debug, PartialEq)]
pub struct Category {
    /// The category's names from the top down (each one level, a `/` in a name kept as
    /// part of it): `["phonglab", "level 2"]`.
    pub path: Vec<String>,
    /// Its questions.
    pub questions: Vec<Question>,
}

/// One question.
#[derive(Clone, Debug, PartialEq)]
pub struct Question {
    /// Its name in the bank (plain text).
    pub name: String,
    /// What it asks.
    pub body: Body,
    /// Shown after the attempt (HTML).
    pub general_feedback_html: String,
}

/// What a question asks.
#[derive(Clone, Debug, PartialEq)]
pub enum Body {
    /// A statement, then parts that each take a number, in rows.
    Numbers {
        /// The statement (HTML).
        statement_html: String,
        /// The parts, in order.
        parts: Vec<Part>,
    },
    /// A statement with pictures, and choices of which one is right.
    Choice {
        /// The statement (HTML), naming its pictures as `@@PLUGINFILE@@/NAME`.
        statement_html: String,
        /// The pictures the statement shows.
        files: Vec<File>,
        /// The choices, in order.
        choices: Vec<Choice>,
    },
}

/// A part that takes a number.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// The row it is on: what the row asks (HTML), shared by the parts of one row (a
    /// vector's components), in order.
    pub row_html: String,
    /// Its own label on the row, before its field (HTML; `x`, `r`, or empty).
    pub label_html: String,
    /// The right value.
    pub answer: f64,
    /// How far from it an answer is still right (absolute, as Moodle's tolerance is).
    pub tolerance: f64,
    /// Said for a right answer (plain text).
    pub right_feedback: String,
    /// Said for any other answer (plain text).
    pub wrong_feedback: String,
}

impl Part {
    /// Is `x` right: within the tolerance of the answer?
    pub fn accepts(&self, x: f64) -> bool {
        (x - self.answer).abs() <= self.tolerance
    }
}

/// A choice of a multiple-choice question.
#[derive(Clone, Debug, PartialEq)]
pub struct Choice {
    /// Its words (plain text).
    pub text: String,
    /// Is it the right one?
    pub right: bool,
    /// Said when it is chosen (plain text).
    pub feedback: String,
}

/// A file a question embeds.
#[derive(Clone, Debug, PartialEq)]
pub struct File {
    /// Its name, as the statement names it: `[A-Za-z0-9._-]` only.
    pub name: String,
    /// Its bytes.
    pub bytes: Vec<u8>,
}

/// `x` as both formats read a number: with a point and no exponent (GIFT reads none),
/// the shortest text that reads back as `x`, or, where that is longer than 24 characters
/// (3.7e-26), `x` to 15 decimals; `inf` and `NaN` are written `0`.
pub fn number(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let s = format!("{x}");
    if s.len() <= 24 {
        return s;
    }
    let fixed = format!("{x:.15}");
    let trimmed = fixed.trim_end_matches('0').trim_end_matches('.');
    if trimmed == "-0" || trimmed.is_empty() { "0".into() } else { trimmed.into() }
}

/// `name` kept to the characters a file name in a question may hold.
pub fn file_name(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-') { c } else { '_' }).collect()
}
