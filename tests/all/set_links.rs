//! Issue 59's attacks by links planted in an output folder (`scripts/wine/plant-links.sh`),
//! each refused before anything is written, moved or deleted, and the files outside the
//! folder left as they were. Run on Linux and, by `scripts/test-windows --cli`, under Wine,
//! where a Unix link shows as a plain file and a handle opened through it is the target's
//! (`platform::links`): there the links are planted on the Linux side and named in
//! `PHONGLAB_PLANTED_LINKS`, since a Windows program under Wine cannot make one.
use crate::common;
use std::path::{Path, PathBuf};

/// The planted links, a fresh folder for this test on Linux; under Wine the folder the
/// harness planted (each test uses its own subfolder of it). `None` on a Windows without it.
fn planted(name: &str) -> Option<PathBuf> {
    if let Some(d) = std::env::var_os("PHONGLAB_PLANTED_LINKS") {
        return Some(PathBuf::from(d));
    }
    if cfg!(windows) {
        eprintln!("no PHONGLAB_PLANTED_LINKS (scripts/test-windows plants them): nothing to test");
        return None;
    }
    let d = std::env::temp_dir().join(format!("phonglab-set-links {name} {}", std::process::id()));
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/wine/plant-links.sh");
    let ok = std::process::Command::new("bash")
        .args([script.as_ref(), d.as_os_str(), env!("CARGO_BIN_EXE_phonglab").as_ref()])
        .status()
        .is_ok_and(|s| s.success());
    assert!(ok, "the links are planted");
    Some(d)
}

/// Runs phonglab with `args`; its exit code and its error output.
fn refused(args: &[&str]) -> (Option<i32>, String) {
    let out = common::phonglab(args);
    (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
}

fn text(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{} is still there: {e}", p.display()))
}

/// The names in the folder `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// F1: an oF project whose `src/ofApp.h` is a link to a file outside it. Before: written
/// through (the link replaced by a regular file) and the file outside deleted, rc 0.
#[test]
fn an_of_project_file_planted_as_a_link_is_refused_and_its_target_kept() {
    let Some(d) = planted("f1") else { return };
    let p = d.join("f1").join("p");
    let (code, err) = refused(&["export", "--to", "openframeworks", "-o", p.to_str().unwrap()]);
    assert_ne!(code, Some(0), "refused: {err}");
    assert!(err.contains("not a regular file") && err.contains("ofApp.h"), "{err}");
    assert_eq!(text(&d.join("f1").join("vic").join("helper.h")), "helper\n");
    assert_eq!(names(&p.join("src")), ["ofApp.h"], "nothing else written");
}

/// F2: a set phonglab wrote, whose `exercise-01.md` was moved outside the folder and
/// linked back (its list names it with these very bytes). Before: the file outside
/// deleted, rc 0.
#[test]
fn an_exercise_planted_as_a_link_is_refused_and_its_target_kept() {
    let Some(d) = planted("f2") else { return };
    let ew = d.join("f2").join("ew");
    let before = names(&ew);
    assert!(before.contains(&"exercise-01.md".to_string()), "{before:?}");
    let (code, err) = refused(&["exercise", "--count", "2", "--seed", "2", "--out", ew.to_str().unwrap()]);
    assert_ne!(code, Some(0), "refused: {err}");
    assert!(err.contains("exercise-01.md") && err.contains("not a regular file"), "{err}");
    assert_eq!(text(&d.join("f2").join("vic").join("ex.md")), text(&d.join("f2").join("ex.md.copy")));
    assert_eq!(names(&ew), before, "nothing written, moved or removed");
}

/// F3: the output folder is a link to another folder. Before: the set written into it.
#[test]
fn an_output_folder_that_is_a_link_is_refused() {
    let Some(d) = planted("f3") else { return };
    let lw = d.join("f3").join("lw");
    let (code, err) = refused(&["exercise", "--count", "2", "--out", lw.to_str().unwrap()]);
    assert_eq!(code, Some(2), "refused: {err}");
    assert!(err.contains("a link to another folder"), "{err}");
    assert_eq!(names(&d.join("f3").join("v3")), ["notes.txt"], "nothing written into the folder it points to");
}

/// F4: an oF project whose `src` is a link to a folder outside it. Before: written there.
#[test]
fn an_of_project_folder_planted_as_a_link_is_refused() {
    let Some(d) = planted("f4") else { return };
    let ofw = d.join("f4").join("ofw");
    let (code, err) = refused(&["export", "--to", "openframeworks", "-o", ofw.to_str().unwrap()]);
    assert_ne!(code, Some(0), "refused: {err}");
    assert!(err.contains("a link to another folder"), "{err}");
    assert!(names(&d.join("f4").join("v1")).is_empty(), "nothing written into the folder it points to");
}

/// F5: the folder's list of what phonglab wrote is a link to a file outside it. Before:
/// the link replaced by a regular file.
#[test]
fn a_list_of_what_was_written_planted_as_a_link_is_refused() {
    let Some(d) = planted("f5") else { return };
    let ew = d.join("f5").join("ew");
    let (code, err) = refused(&["exercise", "--count", "2", "--out", ew.to_str().unwrap()]);
    assert_ne!(code, Some(0), "refused: {err}");
    assert!(err.contains(".phonglab-set.written") && err.contains("where phonglab keeps its list"), "{err}");
    assert_eq!(text(&d.join("f5").join("vic").join("list.txt")), "my list\n");
    assert_eq!(names(&ew), [".phonglab-set.written"], "nothing else written");
}
