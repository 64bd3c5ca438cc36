//! `phonglab check FOLDER --report report.md --csv marks.csv`: a whole class's notebooks,
//! each student's first wrong step and causes, and the class's causes counted, with a bar
//! chart (`report.png` beside the report) for the next lesson, in the teacher's language.
//! Submissions are hostile input: at most [`MAX_SUBMISSIONS`] files each read through the
//! bounded reader, the whole run capped at [`MAX_SECONDS`], names escaped for Markdown,
//! CSV (no formula) and the terminal, and no output written over a submission, through a
//! link, over a file phonglab did not write, or named like a submission in the folder
//! ([`crate::io::work_output`]).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::t;
use anyhow::Result;
use phonglab_core::escape;
use phonglab_core::scene::Scene;
use phonglab_core::study::check::said::{input_names, printed_again};
use phonglab_core::study::check::{Check, Overall, check};

use crate::io::student_code::read_notebook;
use crate::io::work_output::{Kind, MARKS_BOM, marks_header, marks_separator};

/// Writes the class's output `path` of this `kind` by [`crate::io::work_output`]'s rule
/// (`dir`: the folder checked).
fn write(path: &Path, kind: Kind, dir: &Path, bytes: &[u8]) -> Result<()> {
    crate::io::work_output::write(path, kind, Some(dir), bytes).map_err(anyhow::Error::msg)
}

/// The most notebooks a folder may name for one run (each is listed in the report and the
/// marks): past it the folder is refused, said in words. Every one named is read, smallest
/// first, until [`MAX_SECONDS`] are spent: a classmate who drops a thousand junk files (or
/// FIFOs) in a shared folder costs the run a moment each, and cannot stop the class's marks
/// (a cap of 1000 refused the whole folder).
pub const MAX_SUBMISSIONS: usize = 20_000;
/// The most time a folder's check may take, in seconds: past it the rest is reported as
/// not read.
pub const MAX_SECONDS: u64 = 120;

/// Writes `text` to the standard output; a reader that has gone (`| head`) ends nothing.
pub fn out(text: &str) {
    use std::io::Write;
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

/// The check as JSON: `verdict` (`right`, `wrong`, `incomplete`), `unchecked` (why work
/// with no wrong step is still not right: `run-stopped`, `stale-outputs`,
/// `missing-steps`, `unreadable-step`, `nothing-compared`; else null), `missing` (the
/// steps asked for and not printed, in order), `after_error`, `rules`, `inputs_differ`,
/// `first_wrong`, `causes` (with their kebab-case ids), `steps`.
pub fn json(c: &Check) -> serde_json::Value {
    let first = c
        .first_wrong
        .and_then(|k| c.steps.get(k))
        .map(|s| serde_json::json!({"step": s.name, "student": s.student, "key": s.key}));
    let unchecked = c.unchecked().map(|u| serde_json::json!({"id": u.id(), "words": u.words()}));
    serde_json::json!({
        "verdict": c.overall().id(),
        "unchecked": unchecked,
        "missing": c.all_missing(),
        "after_error": c.after_error,
        "rules": c.rules.to_string(),
        "inputs_differ": c.inputs_differ,
        "first_wrong": first,
        "causes": c.causes.iter().map(|k| serde_json::json!({
            "id": k.info.id,
            "words": k.words(),
            "formula": k.formula(),
            "light": k.light,
            "step": k.step,
            "value": k.value,
        })).collect::<Vec<_>>(),
        "printed_twice": printed_again(c),
        "steps": c.steps.iter().map(|s| serde_json::json!({
            "step": s.name,
            "student": s.student,
            "key": s.key,
            "verdict": s.verdict.id(),
            "words": s.verdict.words(),
        })).collect::<Vec<_>>(),
    })
}

/// What the class's check is asked: the assignment's file (kept from being written over),
/// and the outputs.
pub struct ClassArgs {
    /// The assignment's scene file.
    pub scene: Option<PathBuf>,
    /// Write JSON.
    pub json: bool,
    /// The report (Markdown; its chart beside it).
    pub report: Option<PathBuf>,
    /// The marks (CSV).
    pub csv: Option<PathBuf>,
}

/// One student's result: the file's name, and the check or why it was not read.
pub struct Marked {
    /// The file's name (as it is: escaped where it is written).
    pub name: String,
    /// The check, or why the file was not read (its reason alone).
    pub check: Result<Check, String>,
}

/// The notebooks of `dir`, sorted, at most [`MAX_SUBMISSIONS`].
fn submissions(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if crate::io::student_code::student_code(&path) == Some(true) {
            out.push(path);
        }
        if out.len() > MAX_SUBMISSIONS {
            let folder = crate::io::reasons::shown(dir);
            anyhow::bail!(t!("check-too-many-notebooks", folder = folder, max = MAX_SUBMISSIONS as i64));
        }
    }
    out.sort();
    Ok(out)
}

/// Why `path` is not read, where it is not a regular file of the folder itself: a link
/// (which could lead out of it: `../secret.ipynb`, `/etc/passwd`), a folder, or anything
/// else (a FIFO, a device). (The read opens it with links refused as well.)
fn not_a_file(path: &Path) -> Option<String> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_file() => None,
        Ok(m) if m.file_type().is_symlink() => Some(t!("check-not-read-link")),
        Ok(m) if m.is_dir() => Some(t!("check-not-read-folder")),
        _ => Some(t!("check-not-read-not-a-file")),
    }
}

/// The order the submissions are checked in: smallest first (then by name), so that a few
/// huge files cannot use the whole [`MAX_SECONDS`] and leave every ordinary classmate not
/// read. (Indices into `paths`; a size that cannot be read counts as the largest.)
fn checking_order(paths: &[PathBuf]) -> Vec<usize> {
    let size = |p: &PathBuf| std::fs::symlink_metadata(p).map_or(u64::MAX, |m| m.len());
    let mut order: Vec<(u64, usize)> = paths.iter().enumerate().map(|(k, p)| (size(p), k)).collect();
    order.sort_unstable();
    order.into_iter().map(|(_, k)| k).collect()
}

/// Reads and checks one submission against `assignment` (its own scene without one).
fn mark_one(path: &Path, assignment: Option<&Scene>) -> Result<Check, String> {
    read_notebook(path).map(|w| check(assignment.unwrap_or(&w.own), &w.own, &w.printed)).map_err(|e| format!("{e:#}"))
}

/// Checks every notebook of `dir` against `assignment` (each its own scene without one),
/// smallest first (`checking_order`): once `budget` is spent the rest are not read (the
/// first is always read). The result is in the files' name order.
pub fn mark_all(dir: &Path, assignment: Option<&Scene>, budget: Duration) -> Result<Vec<Marked>> {
    let paths = submissions(dir)?;
    let start = Instant::now();
    let mut marked: Vec<(usize, Marked)> = Vec::new();
    // Regular files read so far (the first is always read).
    let mut read = 0usize;
    for k in checking_order(&paths) {
        let path = &paths[k];
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let check = if let Some(why) = not_a_file(path) {
            Err(why)
        } else if read > 0 && start.elapsed() > budget {
            Err(t!("check-not-read-time", seconds = budget.as_secs() as i64))
        } else {
            read += 1;
            mark_one(path, assignment)
        };
        marked.push((k, Marked { name, check }));
    }
    marked.sort_by_key(|(k, _)| *k);
    Ok(marked.into_iter().map(|(_, m)| m).collect())
}

/// Runs the class's check: the report and the marks where asked, a summary on the terminal.
pub fn run(dir: &Path, assignment: Option<&Scene>, a: &ClassArgs) -> Result<()> {
    let inputs = submissions(dir)?;
    let chart = a.report.as_ref().map(|r| r.with_extension("png"));
    let outputs: Vec<&Path> = [a.report.as_deref(), a.csv.as_deref(), chart.as_deref()].into_iter().flatten().collect();
    let code = crate::io::same_file::Input::Code;
    let mut guarded: Vec<(&Path, crate::io::same_file::Input)> = inputs.iter().map(|p| (p.as_path(), code)).collect();
    if let Some(s) = &a.scene {
        guarded.push((s.as_path(), crate::io::same_file::Input::Any));
    }
    // No link followed, no file phonglab did not write replaced, no phantom submission
    // made in the folder (`io::work_output`); a link said first, as a link.
    let kinds = [(a.report.as_deref(), Kind::Report), (chart.as_deref(), Kind::Chart), (a.csv.as_deref(), Kind::Marks)];
    let work_outputs: Vec<(&Path, Kind)> = kinds.into_iter().filter_map(|(p, k)| p.map(|p| (p, k))).collect();
    crate::io::work_output::refuse_links(&work_outputs).map_err(anyhow::Error::msg)?;
    crate::io::same_file::refuse_onto(&outputs, &guarded).map_err(anyhow::Error::msg)?;
    crate::io::work_output::refuse(&work_outputs, Some(dir)).map_err(anyhow::Error::msg)?;
    if assignment.is_none() {
        super::say(&t!("check-report-no-scene"));
    }
    let marked = mark_all(dir, assignment, Duration::from_secs(MAX_SECONDS))?;
    let counts = cause_counts(&marked);
    // A submission not read is not counted as checked (it is listed in the report).
    let read = marked.iter().filter(|m| m.check.is_ok()).count();
    let unread = marked.len() - read;
    let scene_shown = a.scene.as_deref().map(crate::io::reasons::shown);
    if a.report.is_some() || a.csv.is_some() {
        super::say(&t!("check-class-checked", count = read, unread = unread));
    }
    if let (Some(report), Some(chart)) = (&a.report, &chart) {
        let chart_name = chart.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let text = markdown(&marked, &counts, &chart_name, scene_shown.as_deref());
        write(report, Kind::Report, dir, text.as_bytes())?;
        let (w, h, rgba) = chart_png(&counts, read);
        write(chart, Kind::Chart, dir, &crate::io::image::encode_png_signed(w, h, &rgba, Kind::Chart.png_text())?)?;
        let (path, chart) = (crate::io::reasons::shown(report), crate::io::reasons::shown(chart));
        super::say(&t!("check-class-report-written", path = path, chart = chart));
    }
    if let Some(csv) = &a.csv {
        write(csv, Kind::Marks, dir, marks_csv(&marked).as_bytes())?;
        super::say(&t!("check-class-marks-written", path = crate::io::reasons::shown(csv)));
    }
    if a.json {
        let all: Vec<serde_json::Value> = marked
            .iter()
            .map(|m| match &m.check {
                Ok(c) => serde_json::json!({"file": m.name, "check": json(c)}),
                Err(e) => serde_json::json!({"file": m.name, "error": e}),
            })
            .collect();
        out(&format!("{}\n", escape::json::text(&serde_json::to_string_pretty(&all)?)));
    } else if a.report.is_none() && a.csv.is_none() {
        for m in &marked {
            out(&format!("{}\n", escape::terminal::text(&format!("{}: {}", m.name, summary(m)))));
        }
    }
    Ok(())
}

/// One student in a few words: right, or the first wrong step and the causes' ids.
fn summary(m: &Marked) -> String {
    match &m.check {
        Err(e) => t!("check-report-unreadable", reason = e.clone()),
        Ok(c) => match c.overall() {
            Overall::Right => t!("check-verdict-word-right"),
            // The reason may itself open with the verdict ("incomplete: the worksheet asks ..."):
            // said once.
            Overall::Incomplete => {
                let (word, why) = (verdict_word(c), causes(c));
                if why.starts_with(&format!("{word}:")) { why } else { format!("{word}: {why}") }
            }
            Overall::Wrong => format!("{}: {} ({})", verdict_word(c), first_wrong(c), causes(c)),
        },
    }
}

/// The verdict in the teacher's words: right, wrong or incomplete.
fn verdict_word(c: &Check) -> String {
    match c.overall() {
        Overall::Right => t!("check-verdict-word-right"),
        Overall::Wrong => t!("check-verdict-word-wrong"),
        Overall::Incomplete => t!("check-verdict-word-incomplete"),
    }
}

/// The first wrong step, as the single check says it; the typed inputs that differ where
/// no printed step is wrong.
fn first_wrong(c: &Check) -> String {
    match c.first_wrong.and_then(|k| c.steps.get(k)) {
        Some(s) => s.name.clone(),
        None => input_names(c),
    }
}

/// The causes in the teacher's words (why not checked, where nothing was compared).
fn causes(c: &Check) -> String {
    if c.causes.is_empty() && c.first_wrong.is_none() && c.inputs_differ.is_empty() {
        // Why it is incomplete, and the steps the worksheet asks for not printed.
        let why = c.unchecked();
        let not_printed = c.not_printed_reason().filter(|n| why.as_ref() != Some(n));
        return why
            .iter()
            .chain(&not_printed)
            .map(phonglab_core::study::check::Unchecked::words)
            .collect::<Vec<_>>()
            .join("; ");
    }
    // A typed input that differs is the first finding, as the single check says it.
    let mut said: Vec<String> = Vec::new();
    if !c.inputs_differ.is_empty() {
        said.push(t!("check-inputs-differ", names = input_names(c)));
    }
    if c.other_scene() {
        said.push(t!("check-other-scene", count = c.inputs_differ.len()));
    }
    if c.causes.is_empty() && !c.right() && said.is_empty() {
        return t!("check-report-unexplained");
    }
    said.extend(c.causes.iter().map(phonglab_core::study::check::Cause::words));
    said.join("; ")
}

/// How many students each cause explains (in the teacher's words), and how many no cause
/// explains.
pub fn cause_counts(marked: &[Marked]) -> Vec<(String, usize)> {
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    for c in marked.iter().filter_map(|m| m.check.as_ref().ok()).filter(|c| !c.right()) {
        if c.first_wrong.is_none() && c.inputs_differ.is_empty() && c.causes.is_empty() {
            *counts.entry(t!("check-report-unchecked")).or_default() += 1;
        } else if c.causes.is_empty() {
            *counts.entry(t!("check-report-unexplained")).or_default() += 1;
        }
        for k in &c.causes {
            *counts.entry((k.info.words)()).or_default() += 1;
        }
    }
    let mut v: Vec<(String, usize)> = counts.into_iter().collect();
    v.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    v
}

/// The report in Markdown: the assignment (`scene`, as shown, where one was given), a row
/// per student, then the causes counted and the chart.
pub fn markdown(marked: &[Marked], counts: &[(String, usize)], chart: &str, scene: Option<&str>) -> String {
    let md = escape::markdown::text;
    let mut out = format!("# {}\n\n", md(&t!("check-report-title")));
    match scene {
        Some(s) => out.push_str(&format!("{}\n\n", md(&t!("check-report-scene", scene = s.to_string())))),
        None => out.push_str(&format!("> {}\n\n", md(&t!("check-report-no-scene")))),
    }
    out.push_str(&format!(
        "| {} | {} | {} | {} |\n|---|---|---|---|\n",
        md(&t!("check-report-student")),
        md(&t!("check-report-verdict")),
        md(&t!("check-report-first-wrong")),
        md(&t!("check-report-causes"))
    ));
    for m in marked {
        let (verdict, first, why) = match &m.check {
            Err(_) => (t!("check-verdict-word-unread"), String::new(), String::new()),
            Ok(c) if c.right() => (t!("check-verdict-word-right"), String::new(), String::new()),
            Ok(c) => (verdict_word(c), first_wrong(c), causes(c)),
        };
        out.push_str(&format!("| {} | {} | {} | {} |\n", md(&m.name), md(&verdict), md(&first), md(&why)));
    }
    out.push_str(&printed_twice_section(marked));
    let unread: Vec<(&String, &String)> =
        marked.iter().filter_map(|m| m.check.as_ref().err().map(|e| (&m.name, e))).collect();
    if !unread.is_empty() {
        out.push_str(&format!("\n## {}\n\n", md(&t!("check-report-unread"))));
        for (name, why) in unread {
            out.push_str(&format!("- {}: {}\n", md(name), md(why)));
        }
    }
    out.push_str(&format!("\n## {}\n\n", md(&t!("check-report-counts"))));
    for (id, n) in counts {
        out.push_str(&format!("- {}: {n}\n", md(id)));
    }
    out.push_str(&format!("\n![{}]({})\n", md(&t!("check-report-counts")), chart.replace(['(', ')', ' '], "_")));
    out
}

/// The report's section of the steps each student printed more than once with different
/// values (every printing is checked: a later right value never hid an earlier wrong
/// one), escaped for Markdown; empty where no one did.
fn printed_twice_section(marked: &[Marked]) -> String {
    let md = escape::markdown::text;
    let twice: Vec<(&String, Vec<String>)> = marked
        .iter()
        .filter_map(|m| m.check.as_ref().ok().map(|c| (&m.name, printed_again(c))))
        .filter(|(_, steps)| !steps.is_empty())
        .collect();
    if twice.is_empty() {
        return String::new();
    }
    let mut out = format!("\n## {}\n\n", md(&t!("check-report-printed-twice")));
    for (name, steps) in twice {
        out.push_str(&format!("- {}: {}\n", md(name), md(&steps.join(", "))));
    }
    out
}

/// The marks as CSV, separated as the teacher's spreadsheet reads it ([`marks_separator`]),
/// after a byte order mark ([`MARKS_BOM`]), its header in the teacher's language: file, verdict in the teacher's words, first wrong step, the causes in the teacher's
/// words (for incomplete work, why: the steps not printed, the first named), their ids and
/// the verdict's id for machines (`right`, `wrong`, `incomplete`, `unread`); text fields
/// neutralised (never run as a formula).
pub fn marks_csv(marked: &[Marked]) -> String {
    let f = escape::csv::text_field;
    let sep = marks_separator();
    let mut out = format!("{MARKS_BOM}{}\n", marks_header(sep));
    for m in marked {
        let (id, first, why, ids) = match &m.check {
            Err(e) => ("unread", String::new(), e.clone(), String::new()),
            Ok(c) if c.right() => ("right", String::new(), String::new(), String::new()),
            Ok(c) => {
                let ids = c.causes.iter().map(|k| k.info.id).collect::<Vec<_>>().join(" ");
                (c.overall().id(), first_wrong(c), causes(c), ids)
            }
        };
        let word = match &m.check {
            Err(_) => t!("check-verdict-word-unread"),
            Ok(c) => verdict_word(c),
        };
        let row = [f(&m.name), f(&word), f(&first), f(&why), f(&ids), f(id)];
        out.push_str(&format!("{}\n", row.join(&sep.to_string())));
    }
    out
}

/// The causes counted as a bar chart, painted as the window paints
/// ([`super::class_chart`]).
pub fn chart_png(counts: &[(String, usize)], total: usize) -> (usize, usize, Vec<u8>) {
    let c = super::class_chart::chart(counts, total);
    (c.width, c.height, c.rgba)
}
