//! `phonglab check`: a student's work checked against the key. One notebook (with its
//! outputs) or a script's printed text: each printed step, the first wrong one and its
//! likely causes, in words or as JSON. A folder: the whole class, as a report (Markdown),
//! a bar chart of the causes beside it (PNG) and the marks (CSV). Nothing the student
//! wrote is run; every file is read through the bounded readers.

use std::path::{Path, PathBuf};

use crate::t;
use anyhow::Result;
use clap::Args;
use phonglab_core::study::check::check;
use phonglab_core::study::check::printed::{Printed, read_printed_text};
use phonglab_core::study::check::said::words;

/// `phonglab check`.
#[derive(Args, Debug)]
pub struct CheckArgs {
    /// The notebook (.ipynb, saved with its outputs), or a folder of them.
    pub work: Option<PathBuf>,
    /// The text a script printed, instead of a notebook (`-`: the standard input).
    #[arg(long)]
    pub printed: Option<PathBuf>,
    /// The assignment's scene (TOML); default: the notebook's own.
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// Write the check as JSON.
    #[arg(long)]
    pub json: bool,
    /// For a folder: the class report (Markdown), its chart beside it (.png).
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// For a folder: the marks (CSV).
    #[arg(long)]
    pub csv: Option<PathBuf>,
}

/// Reads a script's printed text (`-`: the standard input, as bounded as a file).
fn read_printed(path: &Path) -> Result<Printed> {
    let cap = crate::io::student_code::MAX_CODE_BYTES;
    let text = if path == Path::new("-") {
        use std::io::Read;
        let mut bytes = Vec::new();
        std::io::stdin().take(cap + 1).read_to_end(&mut bytes)?;
        crate::io::input_file::within_cap("-", bytes.len() as u64, cap, &t!("file-kind-code"))
            .map_err(anyhow::Error::msg)?;
        String::from_utf8_lossy(&bytes).into_owned()
    } else {
        crate::io::input_file::read_text_submission(path, cap, &t!("file-kind-code")).map_err(anyhow::Error::msg)?
    };
    read_printed_text(&text).map_err(|e| anyhow::anyhow!("{}: {e}", crate::io::reasons::shown(path)))
}

/// Refuses a check past the memory budget (`--memory-budget`, or the default): the
/// submissions it reads (a folder's notebooks, or the one file), their largest as JSON's
/// values ([`crate::io::budget::check_bytes`]). The standard input, whose size is not known
/// before it is read (it is read within its cap, [`crate::io::student_code::MAX_CODE_BYTES`]),
/// is counted as a submission of no bytes: the process's part and the rest.
fn within_budget(a: &CheckArgs, folder: Option<&Path>) -> Result<()> {
    let cap = crate::io::student_code::MAX_CODE_BYTES;
    let size = |p: &Path| std::fs::symlink_metadata(p).map_or(0, |m| if m.is_file() { m.len().min(cap) } else { 0 });
    let sizes: Vec<u64> = match (folder, &a.printed, &a.work) {
        (Some(dir), ..) => std::fs::read_dir(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| crate::io::student_code::student_code(p) == Some(true))
            .map(|p| size(&p))
            .collect(),
        (None, Some(p), _) if p.as_path() == Path::new("-") => vec![0],
        (None, Some(p), _) | (None, None, Some(p)) => vec![size(p)],
        (None, None, None) => Vec::new(),
    };
    let largest = sizes.iter().copied().max().unwrap_or(0);
    let what = t!(
        "budget-what-check",
        count = sizes.len() as i64,
        largest = phonglab_core::mesh::obj::describe_bytes(largest)
    );
    crate::io::budget::check(&what, crate::io::budget::check_bytes(sizes.len() as u64, largest))
        .map_err(anyhow::Error::msg)
}

/// Runs `phonglab check`: whether the work is right (the exit code, for scripts and
/// autograders: 0 right, 1 wrong or incomplete; [`super::judged`]); for a class folder,
/// true once the report is written.
pub fn run(a: &CheckArgs) -> Result<bool> {
    let assignment = match &a.scene {
        Some(p) => Some(super::scene_file(p)?.scene),
        None => None,
    };
    let folder = a.work.as_ref().filter(|w| w.is_dir());
    within_budget(a, folder.map(PathBuf::as_path))?;
    // A flag that does not apply is refused, never silently ignored.
    if folder.is_some() && a.printed.is_some() {
        anyhow::bail!(t!("check-printed-with-folder"));
    }
    if folder.is_none() && (a.report.is_some() || a.csv.is_some()) {
        anyhow::bail!(t!("check-report-needs-folder"));
    }
    if let Some(dir) = folder {
        let class = super::check_class::ClassArgs {
            scene: a.scene.clone(),
            json: a.json,
            report: a.report.clone(),
            csv: a.csv.clone(),
        };
        return super::check_class::run(dir, assignment.as_ref(), &class).map(|()| true);
    }
    let scene_line = match (&a.scene, &a.printed) {
        (Some(p), _) => t!("check-scene-file", path = crate::io::reasons::shown(p)),
        (None, Some(_)) => t!("check-scene-printed"),
        (None, None) => t!("check-scene-own"),
    };
    let work = match (&a.printed, &a.work) {
        (Some(p), _) => {
            let own = assignment.clone().unwrap_or_else(|| phonglab_core::presets::worksheet(5));
            crate::io::student_code::Work { own, printed: read_printed(p)? }
        }
        (None, Some(w)) => crate::io::student_code::read_notebook(w)?,
        (None, None) => anyhow::bail!(t!("check-nothing-printed")),
    };
    let key_scene = assignment.as_ref().unwrap_or(&work.own);
    let c = check(key_scene, &work.own, &work.printed);
    if a.json {
        let json = serde_json::to_string_pretty(&super::check_class::json(&c))?;
        super::check_class::out(&format!("{}\n", phonglab_core::escape::json::text(&json)));
    } else {
        let text = format!("{scene_line}\n{}", words(&c));
        super::check_class::out(&phonglab_core::escape::terminal::lines(&text));
    }
    Ok(c.right())
}

#[cfg(test)]
mod tests {
    use super::*;
    use phonglab_core::study::check::Check;

    /// The rule set is named in words where typed inputs differ, never as the id `rules`.
    #[test]
    fn the_rule_set_is_named_in_words_among_the_inputs_that_differ() {
        let c = Check {
            rules: phonglab_core::Rules::WORKSHEET,
            inputs_differ: vec!["lightPos".into(), "rules".into()],
            steps: Vec::new(),
            first_wrong: None,
            causes: Vec::new(),
            errors: Vec::new(),
            unreadable: Vec::new(),
            missing: Vec::new(),
            not_printed: Vec::new(),
            stale: None,
            after_error: Vec::new(),
        };
        let names = phonglab_core::study::check::said::input_names(&c);
        assert_eq!(names, format!("lightPos, {}", t!("check-input-rules")));
        assert!(!names.contains("rules") || t!("check-input-rules").contains("rules"));
        assert!(words(&c).contains(&names));
    }
}
