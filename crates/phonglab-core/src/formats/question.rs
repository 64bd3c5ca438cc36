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

/// The most significant digits a number phonglab writes holds: a double's 15, past
/// which its digits are the arithmetic's noise (`0.00006400000000000001` is `0.000064`).
pub const SIGNIFICANT: usize = 15;

/// `x`'s shortest decimal: its sign, its significant digits (no trailing zeros; `[0]` for
/// 0) and the exponent of the first one (`0.0625`: `6`, `2`, `5` and -2). The fewest
/// digits, up to [`SIGNIFICANT`], that read back as `x`; where none do (the noise of a
/// double's arithmetic), `x` to [`SIGNIFICANT`] digits.
pub fn shortest_decimal(x: f64) -> (bool, Vec<u8>, i32) {
    if x == 0.0 || !x.is_finite() {
        return (false, vec![0], 0);
    }
    let sci = |p: usize| format!("{:.*e}", p - 1, x.abs());
    let p = (1..=SIGNIFICANT).find(|&p| sci(p).parse::<f64>() == Ok(x.abs())).unwrap_or(SIGNIFICANT);
    let text = sci(p);
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let mut digits: Vec<u8> = mantissa.bytes().filter(u8::is_ascii_digit).map(|b| b - b'0').collect();
    while digits.len() > 1 && digits.last() == Some(&0) {
        digits.pop();
    }
    (x < 0.0, digits, exponent.parse().unwrap_or(0))
}

/// Digits (the first at `exponent`) written with a point and no exponent: `-0.000064`.
pub fn positional(negative: bool, digits: &[u8], exponent: i32) -> String {
    let mut out = String::from(if negative { "-" } else { "" });
    let digit =
        |k: i32| if k >= 0 && (k as usize) < digits.len() { char::from(b'0' + digits[k as usize]) } else { '0' };
    // Places from the first digit's (or the units', if larger) down to the last digit's.
    let last = exponent - digits.len() as i32 + 1;
    for place in (last.min(0)..=exponent.max(0)).rev() {
        out.push(digit(exponent - place));
        if place == 0 && last < 0 {
            out.push('.');
        }
    }
    out
}

/// `x` as both formats read a number: with a point and no exponent (GIFT reads none), its
/// shortest decimal ([`shortest_decimal`]: no float noise), or, where that is longer than
/// 24 characters (3.7e-26), `x` to 15 decimals (`0`); `inf` and `NaN` are written `0`.
pub fn number(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let (negative, digits, exponent) = shortest_decimal(x);
    let s = positional(negative, &digits, exponent);
    if s.len() <= 24 || x.abs() >= 1.0 {
        return s;
    }
    // A value that small to 15 decimals: at most 17 characters once shortest.
    let fixed = format!("{x:.15}");
    let trimmed = fixed.trim_end_matches('0').trim_end_matches('.');
    if trimmed == "-0" || trimmed.is_empty() { "0".into() } else { number(trimmed.parse().unwrap_or(0.0)) }
}

/// `name` kept to the characters a file name in a question may hold.
pub fn file_name(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-') { c } else { '_' }).collect()
}
