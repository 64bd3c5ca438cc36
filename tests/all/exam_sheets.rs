//! What a student sits: an exam's sheet (`exercise-KK.md`, `sheets.pdf`) says what its
//! Moodle statement says, with the same messages (the spotlight's direction in world
//! coordinates, the side to compute), never points at a key the student has not got,
//! numbers its steps 1, 2, 3 … as its key does, and leaves the scene file off.

use crate::common::phonglab;
use std::path::{Path, PathBuf};
use std::process::Command;

fn out_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("exam-sheets-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// An exam of one exercise in `lang` at `level`: (its Markdown sheet, its PDF sheet's words on
/// one line, its Markdown key, the Moodle statement of the same exercise).
fn exam(lang: &str, level: &str) -> (String, String, String, String) {
    // Each call its own folders: the tests run on parallel threads.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let (dir, xml) = (out_dir(&format!("{lang}-{level}-{n}")), out_dir(&format!("{lang}-{level}-{n}-xml")));
    for (out, format) in [(&dir, "sheets"), (&xml, "moodle-xml")] {
        let args = ["exercise", "--exam", "--level", level, "--count", "1", "--seed", "3", "--lang", lang];
        let out = phonglab(&[&args[..], &["--format", format, "--out", out.to_str().unwrap()]].concat());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let pdf = Command::new("pdftotext").arg(dir.join("sheets.pdf")).arg("-").output().expect("pdftotext");
    let pdf = String::from_utf8_lossy(&pdf.stdout).split_whitespace().collect::<Vec<_>>().join(" ");
    let read = |p: PathBuf| std::fs::read_to_string(p).unwrap();
    let statement = read(xml.join("questions.xml"));
    let statement = statement.split("<questiontext").nth(1).unwrap().split("</questiontext>").next().unwrap();
    (read(dir.join("exercise-01.md")), pdf, read(dir.join("exercise-01-key.md")), statement.to_string())
}

/// `text` with its Markdown code marks and HTML tags taken out, its spaces single.
fn words(text: &str) -> String {
    let mut out = String::new();
    let mut in_tag = false;
    for c in text.chars() {
        match c {
            '<' => in_tag = true,
            '>' if in_tag => in_tag = false,
            '`' => {}
            c if !in_tag => out.push(c),
            _ => {}
        }
    }
    out.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[test]
fn an_exam_sheet_says_the_spotlights_note_and_the_side_to_compute_as_moodle_does() {
    let spot = [
        ("en", "direction (w = 0), in world coordinates: transform it by the modelview"),
        ("pt-PT", "direção (w = 0), em coordenadas do mundo: transforme-a pela modelview"),
        ("pt-BR", "direção (w = 0), em coordenadas do mundo: transforme-a pela modelview"),
    ];
    for (lang, note) in spot {
        let (md, pdf, _, moodle) = exam(lang, "3");
        let line = md.lines().find(|l| l.contains("lightSpotDir")).expect("the spotlight's direction");
        assert!(line.contains(note), "{lang}: {line}");
        // As many times on the PDF as in the Markdown (pdftotext reads a note beside its
        // brackets out of order): the spotlight's, and a directional light's.
        assert_eq!(pdf.matches(note).count(), md.matches(note).count(), "{lang}: the PDF lacks {note:?}: {pdf}");
        let moodle = words(&moodle);
        let given = moodle.split("lightSpotDir").nth(1).unwrap();
        assert!(given[..200].contains(note), "{lang}: Moodle says {given}");
    }
    let front = [
        ("en", "compute the front side, the one the vertex normal faces"),
        ("pt-BR", "calcule a face da frente, aquela para onde aponta a normal do vértice"),
    ];
    for (lang, sentence) in front {
        let (md, pdf, _, moodle) = exam(lang, "4");
        assert!(md.contains(sentence), "{lang}: {md}");
        assert!(pdf.contains(sentence), "{lang}: {pdf}");
        assert!(words(&moodle).contains(sentence), "{lang}: {moodle}");
    }
}

#[test]
fn what_a_student_reads_never_points_at_the_key() {
    for (lang, key) in [("en", " key"), ("pt-PT", "chave"), ("pt-BR", "gabarito")] {
        let (md, pdf, _, moodle) = exam(lang, "2");
        for (what, text) in [("sheet", &md), ("PDF", &pdf), ("Moodle statement", &moodle)] {
            assert!(!text.to_lowercase().contains(key), "{lang} {what} names the key: {text}");
        }
    }
}

#[test]
fn an_exam_sheet_numbers_its_steps_from_1_as_its_key_and_names_no_scene_file() {
    let (md, pdf, key, _) = exam("pt-PT", "3");
    // Spotlight exams ask 15 of the calculation's steps; the key's own numbers skip some.
    let asked: Vec<&str> = md.lines().filter(|l| l.ends_with("= ________")).collect();
    assert!(asked.len() >= 10, "{md}");
    let in_key: Vec<&str> = key.lines().filter(|l| l.starts_with("- ") && l.contains("(exato)")).collect();
    assert_eq!(in_key.len(), asked.len(), "{key}");
    for (i, (line, key_line)) in asked.iter().zip(&in_key).enumerate() {
        let (number, title) = line.split_once(". ").unwrap();
        assert_eq!(number, (i + 1).to_string(), "{line}");
        let title = title.split(':').next().unwrap();
        assert!(key_line.starts_with(&format!("- {}. {title}:", i + 1)), "{key_line} is not step {} {title}", i + 1);
        assert!(pdf.contains(&format!("{}. {title}", i + 1)), "the PDF's step {} is not {title}", i + 1);
    }
    assert!(!md.contains(".toml") && !pdf.contains(".toml"), "a scene file on the student's sheet");
    assert!(!md.contains("Ficheiro de cena") && !pdf.contains("Ficheiro de cena"));
}
