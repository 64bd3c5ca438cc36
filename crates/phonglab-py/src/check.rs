//! `phonglab.check(globals())`: a notebook's work checked in the notebook itself, step by
//! step as `phonglab check` checks a saved one, and the table it prints (the words of
//! `phonglab check`, in the language asked).

use phonglab_core::export::read_python;
use phonglab_core::locale::num;
use phonglab_core::study::check::printed::read_printed_text;
use phonglab_core::study::check::{Check, check};
use phonglab_core::t;

/// Numbers as `phonglab check` prints them: one alone, several in brackets.
fn numbers(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| num(*x, 8)).collect();
    if parts.len() == 1 { parts[0].clone() } else { format!("[{}]", parts.join("  ")) }
}

/// The inputs that differ, the rule set named in words.
fn input_names(c: &Check) -> String {
    let name = |n: &String| if n == "rules" { t!("check-input-rules") } else { n.clone() };
    c.inputs_differ.iter().map(name).collect::<Vec<_>>().join(", ")
}

/// The steps given more than once with different numbers (each is checked).
fn printed_again(c: &Check) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for (k, s) in c.steps.iter().enumerate() {
        let again = c.steps[..k].iter().any(|old| old.name == s.name && old.student != s.student);
        if again && !names.contains(&s.name) {
            names.push(s.name.clone());
        }
    }
    names
}

/// The lines before the steps: the rules, the inputs that differ, the steps given twice.
fn heading(c: &Check) -> String {
    let mut out = format!("{}\n", t!("check-rules", rules = c.rules.to_string()));
    if !c.inputs_differ.is_empty() {
        out.push_str(&format!("{}\n", t!("check-inputs-differ", names = input_names(c))));
    }
    let again = printed_again(c);
    if !again.is_empty() {
        out.push_str(&format!("{}\n", t!("check-printed-twice", names = again.join(", "))));
    }
    out
}

/// The table `phonglab check` prints for `c`: each step, the first wrong one, its causes.
pub fn words(c: &Check) -> String {
    let mut out = heading(c);
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
    if let Some(why) = c.unchecked() {
        out.push_str(&format!("{}\n", why.words()));
    }
    for cause in &c.causes {
        let student = c.steps.iter().find(|s| s.name == cause.step).map_or_else(String::new, |s| numbers(&s.student));
        let line = t!(
            "check-cause",
            words = cause.words(),
            id = cause.info.id,
            step = cause.step.clone(),
            student = student,
            value = numbers(&cause.value)
        );
        out.push_str(&format!("{line}\n    {}\n", cause.formula()));
    }
    if c.first_wrong.is_some() && c.causes.is_empty() {
        out.push_str(&format!("{}\n", t!("check-no-cause")));
    }
    out
}

/// Checks the work whose code is `code` (the cells run, in order: the givens are read from
/// it, nothing is run) and whose values are `printed` (`name = value` lines): the table
/// and whether every step is right.
pub fn check_work(code: &str, printed: &str) -> Result<(String, bool), String> {
    let imported = read_python::read(code, false, "notebook").map_err(|e| e.to_string())?;
    if !imported.not_finite.is_empty() {
        return Err(t!("check-given-not-finite", givens = imported.not_finite.join("; ")));
    }
    let mut student = read_printed_text(printed).map_err(|e| e.to_string())?;
    student.code = code.to_string();
    let own = imported.doc.scene;
    let c = check(&own, &own, &student);
    Ok((words(&c), c.right()))
}
