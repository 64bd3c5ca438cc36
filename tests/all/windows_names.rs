//! Issue 59's names that Windows cannot keep, refused as outputs on every system before
//! anything is written (a set or a picture written on Linux is opened on the lab's Windows
//! PCs): a name ending in a dot or a space (#40: `--csv rep.md.` beside `--report rep.md`
//! is one file on Windows; #53: `--out "set "` made `set`, then failed), and the names
//! Windows keeps for devices (#49, #50: `CON`, `nul.txt`, `con.png`). Run on Linux and, by
//! `scripts/test-windows --cli`, under Wine.
use crate::common;
use std::path::PathBuf;

/// A fresh folder of this test's own.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("phonglab-windows-names {name} {}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The names in the folder `dir`, sorted.
fn names(dir: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// #40: the marks at `rep.md.` beside the report at `rep.md`: refused before the report
/// is written (before, on Windows, the report was written, then the marks refused with an
/// untrue "phonglab did not write it"; on Linux, two files Windows cannot tell apart).
#[test]
fn marks_named_like_the_report_with_a_dot_at_the_end_are_refused_before_anything_is_written() {
    let d = scratch("check");
    let class = d.join("class");
    std::fs::create_dir_all(&class).unwrap();
    std::fs::write(class.join("ana.ipynb"), "{}").unwrap();
    let (report, marks) = (d.join("rep.md"), d.join("rep.md."));
    let out = common::phonglab(&[
        "check",
        class.to_str().unwrap(),
        "--report",
        report.to_str().unwrap(),
        "--csv",
        marks.to_str().unwrap(),
    ]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("rep.md.") && err.contains("Windows drops a dot or a space"), "{err}");
    assert!(!err.contains("did not write"), "{err}");
    assert_eq!(names(&d), ["class"], "nothing written");
}

/// #53: a set's folder named with a space at its end: refused, and no folder made (before,
/// on Windows, `set` was made and left empty).
#[test]
fn a_set_folder_with_a_space_at_its_end_is_refused_and_nothing_is_made() {
    let d = scratch("space");
    let out = common::phonglab(&["exercise", "--count", "1", "--out", d.join("set ").to_str().unwrap()]);
    let err = stderr(&out);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("set ") && err.contains("Windows drops"), "{err}");
    assert!(names(&d).is_empty(), "no folder made: {:?}", names(&d));
}

/// cmd's trap: `--out "C:\Exercícios de CG\"` keeps the quote (a backslash before it) and
/// joins the next arguments to the folder's name. Refused, nothing made, and the message
/// says how to write it in the user's language (before: Windows' "invalid name" alone).
#[test]
fn a_quote_kept_by_cmd_in_a_folders_name_is_refused_with_how_to_write_it() {
    let d = scratch("quote");
    let trapped = d.join("Exercícios de CG\" --count 3");
    let out = common::phonglab(&["exercise", "--count", "1", "--out", trapped.to_str().unwrap()]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("In cmd, a backslash just before a closing quote keeps the quote"), "{err}");
    assert!(err.contains(r#"("C:\Exercícios de CG", not "C:\Exercícios de CG\")"#), "{err}");
    let pt = common::phonglab_in("pt_PT.UTF-8", &["exercise", "--count", "1", "--out", trapped.to_str().unwrap()]);
    assert!(stderr(&pt).contains("No cmd, uma barra invertida mesmo antes das aspas finais"), "{}", stderr(&pt));
    assert!(names(&d).is_empty(), "no folder made: {:?}", names(&d));
}

/// #49, #50: device names as a picture, a set's folder and a folder above an output, in
/// English and in both Portuguese: refused, nothing made (before, Windows' raw errors).
#[test]
fn names_windows_keeps_for_devices_are_refused_in_every_language() {
    let d = scratch("devices");
    let picture = d.join("con.png");
    let out = common::phonglab(&["render", "--size", "16", "--output", picture.to_str().unwrap()]);
    let err = stderr(&out);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("con.png is a name Windows keeps for a device; choose another"), "{err}");
    let set = d.join("NUL");
    let out = common::phonglab_in("pt_PT.UTF-8", &["exercise", "--count", "1", "--out", set.to_str().unwrap()]);
    let err = stderr(&out);
    assert!(err.contains("NUL é um nome que o Windows reserva para um dispositivo; escolha outro"), "{err}");
    let below = d.join("aux").join("nota.txt");
    let out = common::phonglab_in("pt_BR.UTF-8", &["export", "--to", "pyopengl", "-o", below.to_str().unwrap()]);
    let err = stderr(&out);
    assert!(err.contains("aux é um nome que o Windows reserva para um dispositivo"), "{err}");
    assert!(names(&d).is_empty(), "nothing made: {:?}", names(&d));
}

/// Issue 59 (finding 6): an output named with an alternate data stream (`out.png:x`, which
/// on Windows writes a hidden stream of `out.png`) or a character Windows refuses in a name
/// (`? * < > | "`): refused on every system before anything is written, in words.
#[test]
fn names_with_a_stream_or_a_character_windows_refuses_are_refused_before_anything_is_written() {
    let d = scratch("chars");
    for (name, c) in [("out.png:x", ":"), ("a?.png", "?"), ("b*.png", "*"), ("c<d.png", "<"), ("e|f.png", "|")] {
        let out = common::phonglab(&["render", "--size", "16", "--output", d.join(name).to_str().unwrap()]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        let said = format!("{name} holds “{c}”, which Windows does not allow in a file name");
        assert!(err.contains(&said), "{name}: {err}");
    }
    let out =
        common::phonglab_in("pt_PT.UTF-8", &["exercise", "--count", "1", "--out", d.join("set:x").to_str().unwrap()]);
    let err = stderr(&out);
    assert!(err.contains("set:x contém “:”, que o Windows não permite num nome de ficheiro"), "{err}");
    assert!(names(&d).is_empty(), "nothing written: {:?}", names(&d));
}
