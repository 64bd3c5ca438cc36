//! A check in words: the table `phonglab check` prints and the notebook's self-check
//! prints (`phonglab.check(globals())`), one line a finding, in the user's language and
//! decimal mark. The class report and the window use its pieces.

use super::{Cause, Check};
use crate::locale::num;
use crate::t;

/// Numbers for people, in the locale's mark: one alone, several in brackets.
pub fn numbers(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| num(*x, 8)).collect();
    if parts.len() == 1 { parts[0].clone() } else { format!("[{}]", parts.join("  ")) }
}

/// The typed inputs that differ, by the worksheet's names (the rule set in words).
pub fn input_names(c: &Check) -> String {
    let name = |n: &String| if n == "rules" { t!("check-input-rules") } else { n.clone() };
    c.inputs_differ.iter().map(name).collect::<Vec<_>>().join(", ")
}

/// The steps printed more than once with different numbers (each printing is checked).
/// One pass: a printing differs from some earlier one under its name where that name's
/// earlier printings already differ among themselves, or it differs from the first.
pub fn printed_again(c: &Check) -> Vec<String> {
    let mut seen: std::collections::HashMap<&str, (&[f64], bool)> = std::collections::HashMap::new();
    let mut names: Vec<String> = Vec::new();
    for s in &c.steps {
        let (first, differ) = seen.entry(s.name.as_str()).or_insert((s.student.as_slice(), false));
        let again = *differ || *first != s.student.as_slice();
        if again && !*differ {
            *differ = true;
            names.push(s.name.clone());
        }
    }
    names
}

/// A cause in words with its evidence: what the student printed at its step, and what the
/// key worked with the mistake gives there.
pub fn cause_line(c: &Check, cause: &Cause) -> String {
    let student = c.steps.iter().find(|s| s.name == cause.step).map_or_else(String::new, |s| numbers(&s.student));
    t!(
        "check-cause",
        words = cause.words(),
        id = cause.info.id,
        step = cause.step.clone(),
        student = student,
        value = numbers(&cause.value)
    )
}

/// The check in words, one line a finding: the rules, the typed inputs that differ, the
/// steps printed twice, each step, the first wrong one (or all right), why not checked,
/// and the causes with their formulas.
pub fn words(c: &Check) -> String {
    let mut out = format!("{}\n", t!("check-rules", rules = c.rules.to_string()));
    if !c.inputs_differ.is_empty() {
        out.push_str(&format!("{}\n", t!("check-inputs-differ", names = input_names(c))));
    }
    if c.other_scene() {
        out.push_str(&format!("{}\n", t!("check-other-scene", count = c.inputs_differ.len())));
    }
    let again = printed_again(c);
    if !again.is_empty() {
        out.push_str(&format!("{}\n", t!("check-printed-twice", names = again.join(", "))));
    }
    for s in &c.steps {
        let line = t!(
            "check-step",
            step = s.name.clone(),
            student = numbers(&s.student),
            key = numbers(&s.key),
            verdict = s.verdict.words()
        );
        out.push_str(&format!("  {line}\n"));
    }
    match c.first_wrong.and_then(|k| c.steps.get(k)) {
        Some(s) => out.push_str(&format!(
            "{}\n",
            t!("check-first-wrong", step = s.name.clone(), student = numbers(&s.student), key = numbers(&s.key))
        )),
        None if c.right() => out.push_str(&format!("{}\n", t!("check-all-right"))),
        None => {}
    }
    // Why it is not whole, and every step the worksheet asks for that it does not print
    // (incomplete, the first named), even beside a wrong step or another reason.
    let why = c.unchecked();
    if let Some(why) = &why {
        out.push_str(&format!("{}\n", why.words()));
    }
    if !c.after_error.is_empty() {
        out.push_str(&format!("{}\n", t!("check-after-error", names = c.after_error.join(", "))));
    }
    // Beside another reason, which gives the verdict, without a verdict's word of its own.
    if let Some(not_printed) = c.not_printed_reason().filter(|n| why.as_ref() != Some(n)) {
        let said = if why.is_some() { not_printed.steps_words() } else { Some(not_printed.words()) };
        out.push_str(&format!("{}\n", said.unwrap_or_default()));
    }
    for cause in &c.causes {
        // Labelled: the catalogue's formula with the mistake, never the student's own line.
        let formula = t!("check-cause-formula", formula = cause.formula());
        out.push_str(&format!("{}\n    {formula}\n", cause_line(c, cause)));
    }
    if c.first_wrong.is_some() && c.causes.is_empty() && !c.other_scene() {
        out.push_str(&format!("{}\n", t!("check-no-cause")));
    }
    out
}
