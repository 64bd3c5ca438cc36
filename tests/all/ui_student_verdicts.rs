//! Issue 57, the review of the picture checker's words: the window checks a spinning scene
//! at its own view (as `phonglab diagnose` does), every verdict starts with its word and
//! ends with what to do, a refusal has one period, coordinates say where (0, 0) is and stay
//! on one line, and a picture of another size is told to save the program's PNG.

use crate::common;
use crate::common::TempDir;

use std::path::{Path, PathBuf};

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::{AppState, app_ui};
use phonglab_core::document::Document;

fn harness(w: f32, h: f32) -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([w, h])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h
}

/// A shipped scene file's path and its document.
fn shipped(name: &str) -> (PathBuf, Document) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes").join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    let doc = Document::from_toml_in(&text, path.parent()).unwrap();
    (path, doc)
}

/// `doc` drawn at 512 pixels with the mistake `id`, written to `path`.
fn picture_with(doc: &Document, path: &Path, id: &str) {
    use phonglab_core::teach::diagnose::{Drawing, MISTAKES};
    let mesh = doc.view.mesh();
    let mut d = Drawing::of(&doc.shaded_setup(phonglab_core::PowFn::Exact).job(&mesh));
    d.inside = doc.view.mesh_inside();
    let m = MISTAKES.iter().find(|m| m.id == id).unwrap();
    (m.apply)(&mut d, phonglab_core::teach::diagnose::At::default());
    let (_, rgba, _) = d.draw(512).unwrap();
    phonglab::io::image::write_png(path, 512, 512, &rgba).unwrap();
}

/// A catalogue's message, by id, from `i18n/` (the app's) or the core's.
fn message(lang: &str, id: &str) -> String {
    ["i18n", "crates/phonglab-core/i18n"]
        .iter()
        .filter_map(|dir| {
            std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(dir).join(format!("{lang}.ftl"))).ok()
        })
        .flat_map(|text| text.lines().map(str::to_owned).collect::<Vec<_>>())
        .find_map(|l| l.strip_prefix(&format!("{id} = ")).map(str::to_owned))
        .unwrap_or_else(|| panic!("{lang}: no {id}"))
}

#[test]
fn a_spinning_scene_is_checked_at_its_own_view_as_the_command_line_checks_it() {
    let dir = TempDir::new("verdicts-spun");
    let (scene, doc) = shipped("phong-demo.toml");
    assert!(doc.view.auto_rotate, "the Phong demo's file spins");
    let path = dir.0.join("m05.png");
    picture_with(&doc, &path, "viewer-swapped");
    // The command line: the scene file's view.
    let o = common::phonglab(&[
        "diagnose",
        "--scene",
        scene.to_str().unwrap(),
        "--image",
        path.to_str().unwrap(),
        "--json",
    ]);
    let cli: serde_json::Value =
        serde_json::from_slice(&o.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stderr)));
    assert_eq!(cli["verdict"], "wrong", "{cli:#}");
    // The window, after the view has spun 20 degrees.
    let mut h = harness(1280.0, 720.0);
    h.state_mut().load(doc.clone(), "phong-demo");
    h.run_steps(40);
    let spin = h.state().doc.view.spin_degrees;
    assert!(spin > doc.view.spin_degrees + 10.0, "the view spins: {spin}");
    phonglab::app::shell::student::check_path(h.state_mut(), &path);
    h.run_steps(2);
    let p = h.state().compare.student.as_ref().unwrap_or_else(|| panic!("{:?}", h.state().message));
    let lines = p.lines();
    assert_eq!(p.verdict, cli["verdict"].as_str().unwrap(), "{lines:?}");
    let first = cli["causes"][0]["id"].as_str().unwrap();
    assert!(lines.iter().any(|l| l.contains(&format!("({first})"))), "{first}: {lines:?}");
    // And says so, shown.
    let said = "Checked against the scene's own view, as its program draws it";
    assert!(lines.iter().any(|l| l.starts_with(said)), "{lines:?}");
    assert!(h.query_by_label_contains(said).is_some());
    // Spun further, the verdict stays (the scene checked has not changed).
    let spun = h.state().view_options.spun.expect("spun").1;
    let mut more = h.state().doc.clone();
    more.view.spin_degrees += 0.5;
    h.state_mut().doc = more.clone();
    h.state_mut().view_options.spun = Some((doc.view.spin_degrees, more.view.spin_degrees));
    assert!(more.view.spin_degrees > spun);
    h.run_steps(2);
    assert!(h.query_by_label_contains(&format!("({first})")).is_some(), "hidden as stale while spinning");
}

#[test]
fn every_pictures_verdict_starts_with_its_word_and_ends_with_what_to_do() {
    let words = [("en", "Unexplained: "), ("pt-PT", "Não explicada: "), ("pt-BR", "Não explicada: ")];
    for (lang, word) in words {
        // The word is put before each finding in one place (the core's said.rs, whose tests
        // say each shape's line); the findings end with what to do.
        assert!(message(lang, "diagnose-unexplained-said").starts_with(word), "{lang}");
        for id in
            ["diagnose-offset-darker", "diagnose-offset-lighter", "diagnose-levels-darker", "diagnose-levels-lighter"]
        {
            let m = message(lang, id);
            assert!(!m.contains(word.trim_end()), "{lang} {id}: the word twice: {m}");
            assert!(m.contains("glLight*/glMaterial*") || m.contains("--png"), "{lang} {id}: no what to do: {m}");
        }
        for id in ["diagnose-region-differs", "diagnose-marks-differ"] {
            let m = message(lang, id);
            let last = m.rsplit(". ").next().unwrap();
            assert!(["Check ", "Verifique ", "Confira "].iter().any(|w| last.starts_with(w)), "{lang} {id}: {m}");
        }
        // The levels explain it as well as a mistake: no claim that none is there.
        let levels = message(lang, "diagnose-levels-darker");
        assert!(levels.contains("--png"), "{lang}: {levels}");
        let within = message(lang, "diagnose-verdict-right-within");
        assert!(within.contains("phonglab check") && within.contains("glLight*/glMaterial*"), "{lang}: {within}");
    }
    for (lang, claim) in [
        ("en", "not a mistake in the lighting"),
        ("pt-PT", "não é um erro na iluminação"),
        ("pt-BR", "não é um erro na iluminação"),
    ] {
        assert!(!message(lang, "diagnose-levels-darker").contains(claim), "{lang}");
        assert!(!message(lang, "diagnose-levels-lighter").contains(claim), "{lang}");
    }
}

#[test]
fn a_picture_of_another_size_is_told_to_save_the_programs_png_and_a_refusal_has_one_period() {
    let dir = TempDir::new("verdicts-size");
    let shot = dir.0.join("captura.png");
    phonglab::io::image::write_png(&shot, 511, 511, &vec![255; 511 * 511 * 4]).unwrap();
    let o = common::phonglab(&[
        "diagnose",
        "--scene",
        shipped("spotlight.toml").0.to_str().unwrap(),
        "--image",
        shot.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(err.contains("511x511") && err.contains("512x512"), "{err}");
    assert!(err.contains("--png option") && err.contains("a screenshot of a window is not the drawing"), "{err}");
    assert!(!err.contains("another size with --size"), "{err}");
    // A transparent picture, in the window: "Not checked: … ." with one period.
    let clear = dir.0.join("clara.png");
    phonglab::io::image::write_png(&clear, 512, 512, &vec![0; 512 * 512 * 4]).unwrap();
    let mut h = harness(1024.0, 600.0);
    phonglab::app::shell::student::check_path(h.state_mut(), &clear);
    h.run_steps(2);
    let said = format!("{:?}", h.state().message);
    assert!(said.contains("Not checked") && said.contains("transparent"), "{said}");
    assert!(!said.contains(".."), "{said}");
}

#[test]
fn coordinates_say_where_0_0_is_once_and_keep_each_pair_on_one_line() {
    use phonglab::app::panels::student_picture::one_line_pairs;
    assert_eq!(
        one_line_pairs("282 from (71, 207) to (135, 313), 4,0 níveis (3, 4, 5)."),
        "282 from (71,\u{a0}207) to (135,\u{a0}313), 4,0 níveis (3,\u{a0}4,\u{a0}5)."
    );
    assert_eq!(one_line_pairs("(viewer-swapped, 99 %)"), "(viewer-swapped, 99 %)");
    for lang in ["en", "pt-PT", "pt-BR"] {
        let m = message(lang, "diagnose-where");
        assert!(m.contains("(0, 0)") && m.contains("glReadPixels"), "{lang}: {m}");
    }
    // The command line says it once, before the pixel that differs most.
    let dir = TempDir::new("verdicts-where");
    let (scene, doc) = shipped("spotlight.toml");
    let path = dir.0.join("foco.png");
    picture_with(&doc, &path, "spot-cutoff-radians");
    let o = common::phonglab(&["diagnose", "--scene", scene.to_str().unwrap(), "--image", path.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    let where_ = message("en", "diagnose-where");
    assert_eq!(out.matches(where_.as_str()).count(), 1, "{out}");
    let worst = out.find("The pixel that differs most").expect("the worst pixel");
    assert!(out.find(where_.as_str()).unwrap() < worst, "{out}");
}

/// The difference image is said as drawn under the diagnosis (the gain, from how many
/// levels a channel is at full strength, the level its largest difference is drawn at),
/// and framed: mostly black, it vanished into the dark theme.
#[test]
fn the_difference_is_said_as_drawn_and_framed_on_the_dark_theme() {
    let dir = TempDir::new("verdicts-framed");
    let (_, doc) = shipped("phong-demo.toml");
    let path = dir.0.join("m05.png");
    picture_with(&doc, &path, "viewer-swapped");
    let mut h = harness(1280.0, 720.0);
    h.state_mut().load(doc.clone(), "phong-demo");
    h.run_steps(2);
    phonglab::app::shell::student::check_path(h.state_mut(), &path);
    h.run_steps(2);
    let p = h.state().compare.student.as_ref().unwrap_or_else(|| panic!("{:?}", h.state().message));
    let lines = p.lines();
    let said = lines.last().unwrap();
    let gain = format!("× {}: black where the two pictures agree", p.gain);
    assert!(said.starts_with("The difference (the third picture): each channel's |A − B| ") && said.contains(&gain));
    assert!(said.contains("is drawn at ") && !said.contains("near white"), "{said}");
    assert!(h.query_by_label_contains("The difference (the third picture)").is_some());
    // The frame shows against the dark panel and against the black of the difference.
    let dark = egui::Visuals::dark();
    let frame = phonglab::app::panels::student_picture::picture_frame(&dark).color;
    let apart = |a: egui::Color32, b: egui::Color32| {
        [a.r().abs_diff(b.r()), a.g().abs_diff(b.g()), a.b().abs_diff(b.b())].into_iter().max().unwrap()
    };
    assert!(apart(frame, egui::Color32::BLACK) >= 60, "{frame:?}");
    assert!(apart(frame, dark.panel_fill) >= 60, "{frame:?} on {:?}", dark.panel_fill);
}
