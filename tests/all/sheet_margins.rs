//! Every word of an exercise set's PDFs (the sheets students get, the teacher's keys) stays
//! inside the page's margins in every language: measured by poppler's `pdftotext -bbox`,
//! each word's box against A4's width less the 56 pt margin.

use crate::common::phonglab;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A4's width, 595 pt, less the right margin of 56 pt; a point over for the fonts' side bearings.
const RIGHT_EDGE: f64 = 595.0 - 56.0 + 1.0;

fn out_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("margins-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// The words of a PDF past the right margin, each with its right edge and page.
fn past_the_margin(pdf: &Path) -> (usize, Vec<String>) {
    let out = Command::new("pdftotext").arg("-bbox").arg(pdf).arg("-").output().expect("poppler's pdftotext");
    assert!(out.status.success(), "pdftotext {}", pdf.display());
    let html = String::from_utf8_lossy(&out.stdout);
    let (mut words, mut past, mut page) = (0, Vec::new(), 0);
    for line in html.lines() {
        if line.contains("<page ") {
            page += 1;
        }
        let Some(at) = line.find("xMax=\"") else { continue };
        words += 1;
        let x: f64 = line[at + 6..].split('"').next().unwrap().parse().unwrap();
        if x > RIGHT_EDGE {
            let word = line.rsplit_once("\">").map_or("", |(_, w)| w.trim_end_matches("</word>"));
            past.push(format!("page {page}: {word:?} ends at {x} pt"));
        }
    }
    (words, past)
}

#[test]
fn no_word_of_a_sheet_or_a_key_passes_the_right_margin_in_any_language() {
    // pt-BR's exam key wrote "vertexNormal ≈ [...] (arredondado para quatro algarismos
    // significativos)" on one line, its ")" past x = 595 pt.
    for lang in ["en", "pt-PT", "pt-BR"] {
        for (level, exam) in [("3", true), ("4", true), ("3", false), ("4", false)] {
            let dir = out_dir(&format!("{lang}-{level}-{exam}"));
            let mut args = vec!["exercise", "--level", level, "--count", "3", "--lang", lang];
            args.extend(["--seed", "7", "--out", dir.to_str().unwrap()]);
            if exam {
                args.push("--exam");
            }
            let out = phonglab(&args);
            assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
            for file in ["sheets.pdf", "keys.pdf"] {
                let (words, past) = past_the_margin(&dir.join(file));
                assert!(words > 300, "{lang} level {level}: {file} has {words} words");
                assert!(past.is_empty(), "{lang} level {level} exam {exam}, {file}:\n{}", past.join("\n"));
            }
        }
    }
}
