//! What the command line says when it refuses: every refusal a whole sentence from the
//! catalogue in the language asked for (no message id said as it is, no clap English in
//! Portuguese), with clap's exit code 2 for a command line it cannot read; a key the
//! teacher edited is kept, not written over; a run past `ulimit -v` is refused at once.

use crate::common;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use common::phonglab;

fn out_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-errors-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// Every message id of both catalogues, in every language.
fn catalogue_ids() -> BTreeSet<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut ids = BTreeSet::new();
    for dir in ["i18n", "crates/phonglab-core/i18n"] {
        for lang in ["en", "pt-PT", "pt-BR"] {
            let text = std::fs::read_to_string(root.join(dir).join(format!("{lang}.ftl"))).unwrap();
            ids.extend(phonglab_core::locale::ids_of(&text));
        }
    }
    ids
}

/// The kebab-case words of `text` that are message ids (a word with a `-` inside, not an
/// option's `--name` nor a value the command line takes, such as `local-viewer`).
fn bare_ids(text: &str, ids: &BTreeSet<String>) -> Vec<String> {
    let values: Vec<&str> = phonglab_core::exercise::Effect::ALL.iter().map(|e| e.name()).collect();
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| !w.starts_with('-') && w.trim_matches('-').contains('-'))
        .filter(|w| ids.contains(*w) && !values.contains(w))
        .map(str::to_string)
        .collect()
}

/// A command line refused: its exit code and what it said.
fn refused(lang: &str, args: &[&str]) -> (i32, String) {
    let out = phonglab(&[&["--lang", lang][..], args].concat());
    assert!(!out.status.success(), "{args:?} was not refused");
    (out.status.code().unwrap_or(-1), String::from_utf8_lossy(&out.stderr).into_owned())
}

/// Refusals of every kind, in the three languages: no message id is said bare, and none
/// in Portuguese is clap's English.
#[test]
#[cfg(unix)]
fn no_refusal_says_a_message_id_or_claps_english() {
    let ids = catalogue_ids();
    let dir = out_dir("link");
    std::fs::create_dir_all(dir.join("real")).unwrap();
    std::os::unix::fs::symlink(dir.join("real"), dir.join("linked")).unwrap();
    let linked = dir.join("linked");
    let linked = linked.to_str().unwrap();
    let lines: Vec<Vec<&str>> = vec![
        vec!["exercise", "--count", "1", "--out", linked],
        vec!["exercise", "--variants", "0", "--format", "gift"],
        vec!["exercise", "--count", "5000"],
        vec!["exercise", "--seed"],
        vec!["exercise", "--seed", "many"],
        vec!["exercise", "--bogus"],
        vec!["exercise", "--format", "pdf"],
        vec!["exercise", "--level", "1", "--effects", "spot"],
        vec!["exercise", "--rules", "nope"],
        vec!["explain", "--worksheet", "9"],
    ];
    for lang in ["en", "pt-PT", "pt-BR"] {
        for line in &lines {
            let (_, said) = refused(lang, line);
            assert!(!said.trim().is_empty(), "{lang} {line:?}");
            let bare = bare_ids(&said, &ids);
            assert!(bare.is_empty(), "{lang} {line:?} says the message ids {bare:?}: {said}");
            if lang != "en" {
                for english in ["error:", "invalid value", "is not in", "For more information", "unexpected argument"] {
                    assert!(!said.contains(english), "{lang} {line:?} in English: {said}");
                }
            }
        }
    }
    let (_, said) = refused("en", &lines[0]);
    assert!(said.contains("the folder is unchanged"), "{said}");
}

/// clap's common errors in the catalogue's words, with clap's exit code 2.
#[test]
fn claps_common_errors_are_said_in_the_language_asked_for() {
    let cases: [(&[&str], &str, &str); 5] = [
        (
            &["exercise", "--variants", "0"],
            "--variants takes a whole number from 1 to 100, not \"0\"",
            "--variants aceita um número inteiro de 1 a 100, não \"0\"",
        ),
        (&["exercise", "--seed"], "--seed needs a value", "--seed precisa de um valor"),
        (
            &["exercise", "--seed", "x"],
            "--seed takes a whole number, not \"x\"",
            "--seed aceita um número inteiro, não \"x\"",
        ),
        (
            &["exercise", "--variant", "2"],
            "phonglab has no option \"--variant\". Did you mean --variants?",
            "O phonglab não tem a opção \"--variant\".",
        ),
        (
            &["exercise", "--format", "pdf"],
            "--format does not take \"pdf\": it takes sheets, moodle-xml, gift",
            "--format não aceita \"pdf\": aceita sheets, moodle-xml, gift",
        ),
    ];
    for (line, en, pt) in cases {
        let (code, said) = refused("en", line);
        assert_eq!(code, 2, "{line:?}: {said}");
        assert!(said.contains(en), "{line:?}: {said}");
        assert!(said.contains("phonglab exercise --help"), "{said}");
        for lang in ["pt-PT", "pt-BR"] {
            let (code, said) = refused(lang, line);
            assert_eq!(code, 2, "{lang} {line:?}: {said}");
            assert!(said.contains(pt), "{lang} {line:?}: {said}");
        }
    }
    let (_, said) = refused("pt-BR", &["exercise", "--variant", "2"]);
    assert!(said.contains("Você quis dizer --variants?"), "{said}");
    let (_, said) = refused("pt-PT", &["exercise", "--level", "1", "--effects", "spot"]);
    assert!(said.contains("não pode ser usada com"), "{said}");
}

/// A key the teacher edited after phonglab wrote it is not written over by the same
/// command run again: refused, the key as edited, every other file as it was.
#[test]
fn running_the_sheets_again_keeps_a_key_the_teacher_edited() {
    let dir = out_dir("edited-key");
    let args = ["exercise", "--exam", "--level", "2", "--count", "2", "--out", dir.to_str().unwrap()];
    let out = phonglab(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // The same command again replaces its own files, unchanged since.
    let out = phonglab(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let key = dir.join("exercise-02-key.md");
    let edited = format!("{}\nMarking: half a point per step.\n", std::fs::read_to_string(&key).unwrap());
    std::fs::write(&key, &edited).unwrap();
    let before: Vec<(PathBuf, Vec<u8>)> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .filter(|e| e.path().is_file())
        .map(|e| (e.path(), std::fs::read(e.path()).unwrap()))
        .collect();
    for lang in ["en", "pt-PT"] {
        let out = phonglab(&[&["--lang", lang][..], &args].concat());
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{said}");
        assert!(said.contains("exercise-02-key.md"), "{said}");
        let sentence =
            if lang == "en" { "was edited since it wrote it" } else { "foi editado depois de ele o escrever" };
        assert!(said.contains(sentence), "{said}");
        for (path, bytes) in &before {
            assert_eq!(&std::fs::read(path).unwrap(), bytes, "{} changed", path.display());
        }
    }
    assert_eq!(std::fs::read_to_string(&key).unwrap(), edited);
}

/// Under `ulimit -v` the default memory budget is what the limit leaves, so a bank that
/// would not fit is refused at once, in words, instead of aborting half-way.
#[test]
#[cfg(target_os = "linux")]
fn a_run_past_the_address_space_limit_is_refused_in_words() {
    let dir = out_dir("ulimit");
    let script = format!(
        "ulimit -v 2000000 && exec \"$0\" exercise --format gift --level 4 --count 100 --variants 100 --out {}",
        dir.display()
    );
    let out = std::process::Command::new("/bin/sh")
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_phonglab"))
        .env("LC_ALL", "C.UTF-8")
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "refused, not aborted: {said}");
    assert!(said.contains("memory budget") && said.contains("ulimit -v"), "{said}");
    assert!(!dir.join("questions.gift.txt").exists());
}

/// A refusal says the value once, calls an option given twice so, and a stray word an
/// unexpected argument (not an option), in every language.
#[test]
fn a_refusal_says_the_value_once_and_names_what_went_wrong() {
    let twice = [("en", "given twice"), ("pt-PT", "indicada duas vezes"), ("pt-BR", "informada duas vezes")];
    let unexpected =
        [("en", "did not expect \"extra\""), ("pt-PT", "não esperava \"extra\""), ("pt-BR", "não esperava \"extra\"")];
    for ((lang, twice), (_, stray)) in twice.into_iter().zip(unexpected) {
        for (args, value) in [(["--decimal", "virgula"], "\"virgula\""), (["--memory-budget", "1Q"], "\"1Q\"")] {
            let (code, said) = refused(lang, &[&["exercise"][..], &args[..]].concat());
            assert_eq!(code, 2);
            assert_eq!(said.matches(value).count(), 1, "{lang}: {said}");
        }
        let (_, said) = refused(lang, &["exercise", "--level", "3", "--level", "4"]);
        assert!(said.contains(twice) && !said.contains("--level cannot"), "{lang}: {said}");
        let (_, said) = refused(lang, &["exercise", "extra"]);
        assert!(said.contains(stray), "{lang}: {said}");
        assert!(!said.contains("has no option") && !said.contains("não tem a opção"), "{lang}: {said}");
    }
}
