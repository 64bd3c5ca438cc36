//! "What is wrong with this picture?": each mistake's switch changes the picture the way
//! its key says (`misconception::check`), its pictures differ, its key names the cause and
//! gives the probe's numbers in the reader's language, and the exercise set's new level
//! prints both pictures in its PDF.

use crate::common;

use phonglab_core::misconception::{self, Misconception};

const SIZE: usize = 96;

#[test]
fn every_mistake_changes_the_picture_as_its_key_says() {
    for kind in Misconception::ALL {
        let case = misconception::case(kind);
        let drawn = case.draw(SIZE).unwrap();
        misconception::check(&case, &drawn).unwrap_or_else(|e| panic!("{kind:?}: {e}"));
        assert_ne!(drawn.correct, drawn.bugged, "{kind:?}");
        let key = misconception::key_lines(&case, &drawn);
        let text = key.join("\n");
        assert!(text.contains(&kind.cause()), "{kind:?}: {text}");
        let bytes = drawn.correct_probe.rgba8;
        assert!(text.contains(&format!("({}, {}, {})", bytes[0], bytes[1], bytes[2])), "{kind:?}: {text}");
        // The probe's bytes are the pictures' at the pixel.
        let (x, y) = drawn.pixel;
        let i = (y * SIZE + x) * 4;
        assert_eq!(&drawn.correct[i..i + 4], &drawn.correct_probe.rgba8[..]);
        assert_eq!(&drawn.bugged[i..i + 4], &drawn.bugged_probe.rgba8[..]);
        eprintln!("{kind:?}: {} pixels differ; {}", drawn.pixels_differing, key[3]);
    }
}

/// `exercise --level 5` writes the seven sheets and keys with both pictures in each PDF
/// (14 images in each), the pictures as PNG files, and keys that name the cause.
#[test]
fn level_five_prints_the_pictures() {
    let out = std::env::temp_dir().join(format!("phonglab-wrong-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = common::phonglab(&["exercise", "--level", "5", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for k in 1..=7 {
        for f in [format!("wrong-{k:02}.md"), format!("wrong-{k:02}-key.md"), format!("wrong-{k:02}.png")] {
            assert!(out.join(&f).is_file(), "{f}");
        }
        let key = std::fs::read_to_string(out.join(format!("wrong-{k:02}-key.md"))).unwrap();
        assert!(key.contains("Cause: ") && key.contains("drawn right: bytes ("), "{key}");
    }
    for pdf in ["sheets.pdf", "keys.pdf"] {
        let list = std::process::Command::new("pdfimages").arg("-list").arg(out.join(pdf)).output().unwrap();
        let images = String::from_utf8_lossy(&list.stdout).lines().skip(2).count();
        assert_eq!(images, 14, "{pdf}");
    }
    let text = std::process::Command::new("pdftotext").arg(out.join("sheets.pdf")).arg("-").output().unwrap();
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("What is wrong with this picture? (7)") && text.contains("Drawn with one mistake"));
    // One page a sheet, none of them blank, each with a box to tick by each of the seven
    // causes.
    let pages = text.split('\u{c}').filter(|p| !p.trim().is_empty()).collect::<Vec<_>>();
    assert_eq!(pages.len(), 7, "{text}");
    for (k, page) in pages.iter().enumerate() {
        assert!(page.contains(&format!("What is wrong with this picture? ({})", k + 1)), "page {}: {page}", k + 1);
        assert!(!page.contains("blank"), "page {}: {page}", k + 1);
        assert_eq!(tick_boxes(&out.join("sheets.pdf"), k + 1), 7, "page {}", k + 1);
        // Numbered in the document, as a viewer and a printer count (each said "page 1 of 1").
        assert!(page.contains(&format!("page {} of 7", k + 1)), "page {}: {page}", k + 1);
    }
    // The index says how to print what is there: one page an exercise, no blank backs, so
    // not "on both sides".
    let index = std::fs::read_to_string(out.join("index.md")).unwrap();
    assert!(index.contains("printed on one side") && !index.contains("both sides"), "{index}");
    // The same seed, the same files.
    let again = std::env::temp_dir().join(format!("phonglab-wrong-again-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&again);
    assert!(common::phonglab(&["exercise", "--level", "5", "--out", again.to_str().unwrap()]).status.success());
    assert_eq!(std::fs::read(out.join("keys.pdf")).unwrap(), std::fs::read(again.join("keys.pdf")).unwrap());
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_dir_all(&again);
}

/// Each mistake's scene makes the mistake visible: at the sizes the sheets (192) and the
/// quiz (160) draw, at least 5 % of the object's pixels differ by more than 24/255 between
/// the picture drawn right and the one with the mistake (Compare's measure of "visibly").
#[test]
fn every_mistake_is_visible_in_its_pictures() {
    use phonglab_core::difference::{VISIBLE, difference};
    let bg = misconception::BACKGROUND.map(|c| (c * 255.0).round() as u8);
    for px in [160, 192] {
        for kind in Misconception::ALL {
            let drawn = misconception::case(kind).draw(px).unwrap();
            let d = difference(&drawn.correct, &drawn.bugged, bg);
            eprintln!(
                "{kind:?} at {px}: {:.1} % of {} pixels differ by more than {VISIBLE}/255",
                d.visible_percent(),
                d.object
            );
            assert!(d.visible_percent() >= 5.0, "{kind:?} at {px}: {:.2} %", d.visible_percent());
        }
    }
}

/// The largest change of a colour term's luminance at the key's pixel, worked out here from
/// the two probes' own terms: (its label, its worksheet name, right, wrong).
fn largest_change(d: &misconception::Drawn) -> (String, &'static str, f64, f64) {
    use phonglab_core::vocabulary::Quantity as Q;
    let lum = |c: [f64; 3]| 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    let terms = |t: &phonglab_core::probe::Terms| {
        let mut v = vec![(Q::EmissionTerm, t.emission), (Q::SceneAmbientTerm, t.scene_ambient)];
        for l in &t.lights {
            v.extend([(Q::Ambient, l.ambient), (Q::Diffuse, l.diffuse), (Q::Specular, l.specular)]);
        }
        v
    };
    let (a, b) = (terms(&d.correct_probe.terms), terms(&d.bugged_probe.terms));
    let mut best = (Q::EmissionTerm, 0.0_f64, 0.0_f64);
    for ((q, x), (_, y)) in a.iter().zip(&b) {
        if (lum(*y) - lum(*x)).abs() > (best.2 - best.1).abs() {
            best = (*q, lum(*x), lum(*y));
        }
    }
    (best.0.label(), best.0.name(), best.1, best.2)
}

/// The key names the term that makes the difference: for every mistake, at the quiz's and
/// the sheets' sizes and in every set a seed orders, the term the key names is the one
/// whose luminance changes most between the two probes at the pixel it quotes, with its
/// two values. (Key 2 blamed the diffuse term doubling while its specular term went from
/// 0.0018 to 1.866.)
#[test]
fn every_key_names_the_term_whose_change_is_largest() {
    use phonglab_core::locale::num;
    let line = |d: &misconception::Drawn| {
        let (label, name, right, wrong) = largest_change(d);
        format!(
            "changes most at this pixel: {label} ({name}), its luminance from {} drawn right to {}",
            num(right, 4),
            num(wrong, 4)
        )
    };
    for px in [96, 160, 192] {
        for kind in Misconception::ALL {
            let case = misconception::case(kind);
            let drawn = case.draw(px).unwrap();
            let key = misconception::key_lines(&case, &drawn).join("\n");
            assert!(key.contains(&line(&drawn)), "{kind:?} at {px}: {key}");
        }
    }
    // The normal 2 long: the specular term, not the diffuse one.
    let case = misconception::case(Misconception::NormalNotNormalised);
    let drawn = case.draw(192).unwrap();
    assert_eq!(largest_change(&drawn).1, "Ispec");
    // The sheets' keys, in the order each seed gives.
    for seed in 0..4 {
        let set = phonglab::io::misconception_set::misconception_set(seed, 7).unwrap();
        for k in 1..=7 {
            let key = String::from_utf8(set.get(&format!("wrong-{k:02}-key.md")).unwrap().to_vec()).unwrap();
            let kind = Misconception::ALL.into_iter().find(|m| key.contains(&m.cause().replace('_', "\\_"))).unwrap();
            let drawn = misconception::case(kind).draw(192).unwrap();
            assert!(key.contains(&line(&drawn)), "seed {seed}, sheet {k}: {key}");
        }
    }
}

/// The boxes to tick on page `page` of `pdf`, counted on the page drawn at 72 dpi (one
/// pixel a point): dark runs 6 to 12 pixels tall down the left margin's column (x = 56),
/// below the pictures (a ruled line there is 1 pixel tall).
fn tick_boxes(pdf: &std::path::Path, page: usize) -> usize {
    let p = page.to_string();
    let o = std::process::Command::new("pdftoppm")
        .args(["-r", "72", "-gray", "-f", &p, "-l", &p])
        .arg(pdf)
        .output()
        .expect("pdftoppm runs");
    // A binary PGM: "P5\n<w> <h>\n255\n" and the bytes.
    let bytes = o.stdout;
    let mut fields = Vec::new();
    let mut at = 0;
    while fields.len() < 4 {
        while bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        fields.push(String::from_utf8_lossy(&bytes[start..at]).to_string());
    }
    let (w, h): (usize, usize) = (fields[1].parse().unwrap(), fields[2].parse().unwrap());
    let pixels = &bytes[at + 1..];
    let dark = |y: usize| pixels[y * w + 56] < 128;
    let (mut boxes, mut run) = (0, 0);
    for y in 300..h {
        if dark(y) {
            run += 1;
        } else {
            boxes += usize::from((6..=12).contains(&run));
            run = 0;
        }
    }
    boxes
}

/// `--lang pt-PT exercise --level 5`: the sheets and keys are in Portuguese through and
/// through, the mistaken formulas' words included ("lit per vertex", "everywhere",
/// "measured in object space" were left in English).
#[test]
fn level_five_in_portuguese_has_no_english_words() {
    let out = std::env::temp_dir().join(format!("phonglab-wrong-pt-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = common::phonglab(&["--lang", "pt-PT", "exercise", "--level", "5", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for pdf in ["sheets.pdf", "keys.pdf"] {
        let text = std::process::Command::new("pdftotext").arg(out.join(pdf)).arg("-").output().unwrap();
        let text = String::from_utf8_lossy(&text.stdout).to_string();
        for english in
            ["lit per", "interpolated", "everywhere", "measured in", "object space", "eye space", "only where"]
        {
            assert!(!text.contains(english), "{pdf}: {english:?} in\n{text}");
        }
        assert!(text.contains("espaço do objeto"), "{pdf}: {text}");
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// Issue 60: each choice of a level-5 sheet says its cause and its mistaken formula once,
/// as Moodle and the window's quiz write it: Gouraud's repeated itself ("…perde-se
/// (iluminação em cada vértice e cores interpoladas (Gouraud))"), and formulas in
/// parentheses after a cause ending in one doubled them ("(n · H) ((R . V)^s_rm").
#[test]
fn a_sheets_choices_say_each_cause_once_without_doubled_parentheses() {
    let out = std::env::temp_dir().join(format!("phonglab-wrong-choices-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    for lang in ["en", "pt-PT", "pt-BR"] {
        let o = common::phonglab(&[
            "--lang",
            lang,
            "exercise",
            "--level",
            "5",
            "--count",
            "1",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let sheet = std::fs::read_to_string(out.join("wrong-01.md")).unwrap();
        let choices: Vec<&str> = sheet.lines().filter(|l| l.starts_with("- [ ] ")).collect();
        assert_eq!(choices.len(), 7, "{sheet}");
        for c in choices {
            assert!(c.matches(": ").count() <= 1 && !c.contains("((") && !c.contains(" . "), "{lang}: {c}");
        }
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// The words of `text` of two letters or more, in lower case (a formula's symbols left
/// out: `f_i`, `R · V`).
fn words_of(text: &str) -> Vec<String> {
    text.split(|c: char| !c.is_alphabetic()).filter(|w| w.chars().count() >= 2).map(str::to_lowercase).collect()
}

/// Issue 60: "Attenuation computed with the distance in object space: d measured in object
/// space" said its cause twice. No choice's formula repeats two words in a row of its
/// cause, in the three languages.
#[test]
fn no_choice_says_its_cause_again_after_it() {
    use phonglab::locale::{Lang, Locale, with_locale};
    for lang in Lang::ALL {
        with_locale(Locale::of(lang), || {
            for kind in Misconception::ALL {
                let (cause, choice) = (kind.cause(), kind.choice());
                let after = choice.strip_prefix(&cause).unwrap_or_else(|| panic!("{choice:?} starts with {cause:?}"));
                let said = words_of(&cause);
                for pair in words_of(after).windows(2) {
                    assert!(!said.windows(2).any(|p| p == pair), "{}: {choice:?} says {pair:?} twice", lang.code());
                }
            }
        });
    }
}
