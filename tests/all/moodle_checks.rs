//! What `phonglab exercise --format moodle-xml | gift` leaves alone and refuses (issue 60,
//! the hostile review): a question file replaces only its own earlier self, never the
//! sheets beside it or the other format's file; a bank past the memory budget, a category
//! Moodle cannot read back, and `--worksheet` are refused before anything is written; a
//! link at the file's name is called a link.

use crate::common;

use std::path::{Path, PathBuf};

use common::{phonglab, phonglab_in};

fn out_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("moodle-checks-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn run_ok(out: std::process::Output) -> String {
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{err}");
    err + &String::from_utf8_lossy(&out.stdout)
}

/// The refusal's message (it must fail).
fn refused(out: std::process::Output) -> String {
    assert!(!out.status.success(), "{}", String::from_utf8_lossy(&out.stdout));
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Every file in `dir` (not phonglab's own record) with its bytes, sorted by name.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut all: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().into_string().unwrap())
        .filter(|n| !n.starts_with(".phonglab"))
        .map(|n| (n.clone(), std::fs::read(dir.join(&n)).unwrap()))
        .collect();
    all.sort();
    all
}

fn names(dir: &Path) -> Vec<String> {
    files(dir).into_iter().map(|(n, _)| n).collect()
}

fn moodle(format: &str, dir: &Path, more: &[&str]) -> std::process::Output {
    let args = ["exercise", "--format", format, "--level", "1", "--count", "2", "--out", dir.to_str().unwrap()];
    phonglab(&[&args[..], more].concat())
}

#[test]
fn writing_questions_leaves_the_sheets_keys_and_the_other_format_in_place() {
    let dir = out_dir("beside");
    run_ok(phonglab(&["exercise", "--level", "1", "--count", "2", "--out", dir.to_str().unwrap()]));
    let sheets = files(&dir);
    assert!(sheets.iter().any(|(n, _)| n == "exercise-02-key.md") && sheets.len() >= 8, "{:?}", names(&dir));
    run_ok(moodle("moodle-xml", &dir, &[]));
    run_ok(moodle("gift", &dir, &[]));
    let after = files(&dir);
    for file in &sheets {
        assert!(after.contains(file), "{} removed or changed by writing questions", file.0);
    }
    assert!(after.iter().any(|(n, _)| n == "questions.xml"), "the Moodle XML kept beside the GIFT");
    assert!(after.iter().any(|(n, _)| n == "questions.gift.txt"));
    assert_eq!(after.len(), sheets.len() + 2, "{:?}", names(&dir));
    // Sheets leave the questions alone, and still replace their own earlier set whole:
    // exercise 2 of the earlier set goes (phonglab wrote it, unchanged), the questions stay.
    let xml = std::fs::read(dir.join("questions.xml")).unwrap();
    run_ok(phonglab(&["exercise", "--level", "1", "--count", "1", "--out", dir.to_str().unwrap()]));
    let now = names(&dir);
    assert!(!now.iter().any(|n| n.starts_with("exercise-02")), "{now:?}");
    assert!(now.contains(&"exercise-01-key.md".to_string()));
    assert_eq!(std::fs::read(dir.join("questions.xml")).unwrap(), xml);
    assert!(now.contains(&"questions.gift.txt".to_string()));
}

#[test]
fn a_question_file_replaces_only_its_own_earlier_self_as_phonglab_wrote_it() {
    let dir = out_dir("own-self");
    run_ok(moodle("moodle-xml", &dir, &[]));
    let first = std::fs::read(dir.join("questions.xml")).unwrap();
    run_ok(moodle("moodle-xml", &dir, &["--seed", "2"]));
    let second = std::fs::read(dir.join("questions.xml")).unwrap();
    assert_ne!(first, second, "phonglab's own file is replaced");
    // A teacher's edit makes it theirs: refused, kept byte for byte.
    let edited = [&second[..], b"<!-- my edit -->\n"].concat();
    std::fs::write(dir.join("questions.xml"), &edited).unwrap();
    let e = refused(moodle("moodle-xml", &dir, &[]));
    assert!(e.contains("was not written by phonglab, or has changed since"), "{e}");
    assert_eq!(std::fs::read(dir.join("questions.xml")).unwrap(), edited);
    // A file phonglab never wrote there, in Portuguese.
    let other = out_dir("own-self-foreign");
    std::fs::create_dir_all(&other).unwrap();
    std::fs::write(other.join("questions.gift.txt"), "// my questions\n").unwrap();
    let args = ["exercise", "--format", "gift", "--level", "1", "--count", "1", "--out", other.to_str().unwrap()];
    let e = refused(phonglab_in("pt_PT.UTF-8", &args));
    assert!(e.contains("não foi escrito pelo phonglab"), "{e}");
    assert_eq!(std::fs::read(other.join("questions.gift.txt")).unwrap(), b"// my questions\n");
}

#[test]
fn a_bank_past_the_memory_budget_is_refused_at_once_naming_its_size() {
    let dir = out_dir("budget");
    let args = ["exercise", "--format", "gift", "--level", "4", "--count", "1000", "--variants", "100"];
    let e = refused(phonglab(&[&args[..], &["--memory-budget", "1G", "--out", dir.to_str().unwrap()]].concat()));
    assert!(e.contains("a file for Moodle of 100 000 exercises (about "), "{e}");
    assert!(e.contains("more than the memory budget of 1 073 741 824 bytes"), "{e}");
    assert!(!dir.exists(), "nothing written");
    // The same bank, smaller, fits a budget its estimate fits.
    let args = ["exercise", "--format", "moodle-xml", "--level", "4", "--count", "2", "--variants", "3"];
    let e = refused(phonglab(&[&args[..], &["--memory-budget", "10K", "--out", dir.to_str().unwrap()]].concat()));
    assert!(e.contains("a file for Moodle of 6 exercises"), "{e}");
    run_ok(phonglab(&[&args[..], &["--memory-budget", "64M", "--out", dir.to_str().unwrap()]].concat()));
    assert!(dir.join("questions.xml").is_file());
}

/// The numbers of a refusal that are followed by " bytes (": the file's size on disk,
/// then the memory needed, then the budget.
fn sizes_said(e: &str) -> Vec<u64> {
    e.split(" bytes (")
        .filter_map(|before| {
            let digits: String = before.chars().rev().take_while(|c| c.is_ascii_digit() || *c == ' ').collect();
            digits.chars().rev().filter(char::is_ascii_digit).collect::<String>().parse().ok()
        })
        .collect()
}

/// Issue 60: the refusal suggests a budget that covers the run (it said "e.g.
/// --memory-budget 16G" to a run needing 68 GiB).
#[test]
fn the_refusal_suggests_a_budget_the_run_fits() {
    let dir = out_dir("suggest");
    let args = ["exercise", "--format", "gift", "--level", "4", "--count", "1000", "--variants", "100"];
    let e = refused(phonglab(&[&args[..], &["--memory-budget", "1G", "--out", dir.to_str().unwrap()]].concat()));
    let needed = sizes_said(&e)[1];
    let suggested =
        e.split("needs --memory-budget ").nth(1).and_then(|t| t.split(' ').next()).unwrap_or_else(|| panic!("{e}"));
    let gib: u64 = suggested.strip_suffix('G').and_then(|g| g.parse().ok()).unwrap_or_else(|| panic!("{e}"));
    assert!(gib << 30 >= needed && (gib - 1) << 30 < needed, "{suggested} for {needed} bytes: {e}");
}

/// Issue 60: the file's size the estimate says is never below the file written, and at
/// most 30 % above it (it was 50-60 % above: 3.4 GiB said for 2.3 GB written), at the
/// level whose exercises differ most (4) and at one whose hardly differ (2).
#[test]
fn the_estimated_file_size_is_at_most_30_percent_above_the_file() {
    let dir = out_dir("estimate");
    for (format, level, count, variants, file) in [
        ("moodle-xml", "4", "10", "10", "questions.xml"),
        ("gift", "2", "4", "12", "questions.gift.txt"),
        ("gift", "4", "3", "16", "questions.gift.txt"),
    ] {
        let args = ["exercise", "--format", format, "--level", level, "--count", count, "--variants", variants];
        let e = refused(phonglab(&[&args[..], &["--memory-budget", "1", "--out", dir.to_str().unwrap()]].concat()));
        let said = sizes_said(&e)[0];
        run_ok(phonglab(&[&args[..], &["--out", dir.to_str().unwrap()]].concat()));
        let real = std::fs::metadata(dir.join(file)).unwrap().len();
        let ratio = said as f64 / real as f64;
        assert!((1.0..=1.3).contains(&ratio), "{format} level {level}: said {said}, wrote {real}: {ratio}");
    }
}

#[test]
fn a_category_moodle_cannot_read_back_is_refused_before_anything_is_written() {
    let dir = out_dir("category");
    let slash = "cannot start or end with \"/\"";
    let cases: [(String, &str); 7] = [
        (String::new(), "--category needs a name"),
        ("   ".into(), "--category needs a name"),
        ("/".into(), slash),
        ("// comment".into(), slash),
        ("year 1/".into(), slash),
        ("é".repeat(256), "--category is 256 characters long; Moodle keeps a category's name in at most 255"),
        // A control character is refused, said visibly (issue 60: a line break was
        // written into the category's path).
        (format!("{}\u{1b}", "a".repeat(250)), "--category has a control character, \\u{1B}"),
    ];
    for (name, why) in cases {
        let e = refused(moodle("moodle-xml", &dir, &["--category", &name]));
        assert!(e.contains(why), "{name:?}: {e}");
        assert!(!dir.exists(), "{name:?}: nothing written");
    }
    let args = ["exercise", "--format", "gift", "--category", " ", "--out", dir.to_str().unwrap()];
    assert!(refused(phonglab_in("pt_PT.UTF-8", &args)).contains("--category precisa de um nome"));
    let args = ["exercise", "--format", "gift", "--category", "x/", "--out", dir.to_str().unwrap()];
    assert!(refused(phonglab_in("pt_BR.UTF-8", &args)).contains("não pode começar nem terminar com"));
    // 255 characters, and a slash inside a name, are written.
    run_ok(moodle("moodle-xml", &dir, &["--category", &"é".repeat(255)]));
    run_ok(moodle("gift", &dir, &["--category", "year 1/lighting"]));
}

#[test]
fn the_worksheet_is_refused_with_a_moodle_format() {
    let dir = out_dir("worksheet");
    for format in ["moodle-xml", "gift"] {
        let e = refused(moodle(format, &dir, &["--worksheet"]));
        assert!(e.contains("--worksheet writes exercise 0 into the sheets only"), "{e}");
    }
    assert!(!dir.exists());
}

#[cfg(unix)]
#[test]
fn a_question_file_that_is_a_link_to_a_file_is_called_a_link() {
    let dir = out_dir("link");
    std::fs::create_dir_all(&dir).unwrap();
    let target = dir.join("elsewhere.xml");
    std::fs::write(&target, "theirs").unwrap();
    std::os::unix::fs::symlink(&target, dir.join("questions.xml")).unwrap();
    let e = refused(moodle("moodle-xml", &dir, &[]));
    assert!(e.contains("(a link, a folder, a device or a pipe)"), "{e}");
    assert!(!e.contains("nothing"), "{e}");
    assert_eq!(std::fs::read(&target).unwrap(), b"theirs");
}
