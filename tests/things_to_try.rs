//! "Things to try": each shipped experiment sets up what its words say (the light behind
//! the surface gives cosTheta < 0 and Idif = 0, the attenuation's d is 1 and at 1.11, …),
//! its answer is a step of the calculation, and the window sets up a scene in one click,
//! shows the question, and shows the answer from the calculation only when asked.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::model::evaluated::{Settings, evaluate};
use phonglab::app::panels::things_to_try::answer;
use phonglab::app::{AppState, app_ui};
use phonglab::io::experiments::{Experiment, shipped};
use phonglab_core::explain::Explanation;
use phonglab_core::{Document, RuleSet};

fn by_name(stem: &str) -> &'static Experiment {
    shipped().iter().find(|e| e.source.contains(stem)).unwrap_or_else(|| panic!("no {stem}"))
}

fn explain(doc: &Document) -> Explanation {
    let s = Settings::default();
    evaluate(doc, s.precision, s.pow, s.side).unwrap().explanation
}

/// The value of the step named `name` (the first light's).
fn step(ex: &Explanation, name: &str) -> Vec<f64> {
    ex.steps.iter().find(|s| s.name == name).and_then(|s| s.value.clone()).unwrap_or_else(|| panic!("no {name}"))
}

#[test]
fn every_answer_is_a_step_of_its_own_calculation() {
    for e in shipped() {
        let ex = explain(&e.doc);
        let (k, text) = answer(e, &ex).unwrap_or_else(|| panic!("{}: no step {}", e.source, e.answer));
        assert_eq!(ex.steps[k].name, e.answer);
        assert!(text.starts_with(&format!("{} = ", e.answer)), "{text}");
    }
}

#[test]
fn the_light_behind_the_surface_leaves_no_diffuse_term() {
    let ex = explain(&by_name("light-behind").doc);
    let cos = step(&ex, "cosTheta")[0];
    assert!(cos < 0.0 && cos > -0.2, "just past 90 degrees: {cos}");
    assert!(step(&ex, "Idif").iter().all(|x| *x == 0.0));
}

#[test]
fn the_attenuation_is_1_11_at_distance_1_and_grows_as_the_words_say() {
    let e = by_name("attenuation");
    let ex = explain(&e.doc);
    assert!((step(&ex, "d")[0] - 1.0).abs() < 1e-9);
    assert!((step(&ex, "at")[0] - 1.11).abs() < 1e-9);
    for (y, at) in [(10.0, 3.0), (100.0, 111.0)] {
        let mut d = e.doc.clone();
        d.scene.lights[0].position.y = y;
        assert!((step(&explain(&d), "at")[0] - at).abs() < 1e-9, "at {y}");
    }
}

#[test]
fn the_other_experiments_set_up_what_they_say() {
    // Gouraud on the coarse sphere.
    let g = &by_name("gouraud-coarse").doc;
    assert_eq!((g.view.shading, g.view.sphere_slices, g.view.sphere_stacks), (phonglab_core::Shading::Gouraud, 8, 6));
    // mview3 is not a rotation: step 1 says so.
    let m = explain(&by_name("normal-matrix").doc);
    assert!(m.steps[0].notes.iter().any(|n| n.contains("not a rotation")), "{:?}", m.steps[0].notes);
    // The viewer at infinity: V is (0, 0, 1).
    let lv = by_name("local-viewer");
    assert!(!lv.doc.scene.light_model.local_viewer);
    assert_eq!(step(&explain(&lv.doc), "vov")[..3], [0.0, 0.0, 1.0]);
    // A broad highlight at shininess 5, narrower at 100: the specular term falls.
    let sh = by_name("shininess");
    let mut sharp = sh.doc.clone();
    sharp.scene.material.shininess = 100.0;
    assert!(step(&explain(&sh.doc), "Ispec")[0] > 10.0 * step(&explain(&sharp), "Ispec")[0]);
    // Outside the 10-degree cone, inside a 25-degree one.
    let sp = by_name("spot-cutoff");
    assert_eq!(step(&explain(&sp.doc), "spot")[0], 0.0);
    let mut wide = sp.doc.clone();
    wide.scene.lights[0].spot_cutoff = 25.0;
    assert!(step(&explain(&wide), "spot")[0] > 0.5);
    // What OpenGL adds: the emission and the scene's ambient times the material's.
    let w = by_name("what-opengl-adds");
    assert_eq!(w.doc.scene.rules.set, RuleSet::Worksheet);
    let mut gl = w.doc.clone();
    gl.scene.rules.set = RuleSet::OpenGl;
    let (a, b) = (step(&explain(&w.doc), "I"), step(&explain(&gl), "I"));
    let s = &gl.scene;
    for c in 0..3 {
        let added = s.material.emission[c] + s.material.ambient[c] * s.light_model.ambient[c];
        assert!((b[c] - a[c] - added).abs() < 1e-9, "channel {c}: {a:?} -> {b:?}");
    }
    // The lights add up past 1 in some channel.
    let cl = explain(&by_name("clamping").doc);
    assert!(step(&cl, "I")[..3].iter().any(|x| *x > 1.0), "{:?}", step(&cl, "I"));
}

#[test]
fn the_window_sets_an_experiment_up_in_one_click_and_keeps_its_answer_until_asked() {
    let mut h = Harness::builder()
        .with_size([1024.0, 600.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h.get_by_label("Things to try").click();
    h.run_steps(3);
    let e = by_name("light-behind");
    let title = format!("1. {}", e.words(phonglab_core::locale::Lang::En).title);
    h.get_by_label(&title).click();
    h.run_steps(3);
    assert_eq!(h.state().doc, e.doc, "one click set the scene up");
    let question = &e.words(phonglab_core::locale::Lang::En).question;
    h.get_by_label(question);
    // The answer is not on screen until asked, then it is the calculation's own step.
    let ex = h.state().evaluate().unwrap().explanation;
    let (k, value) = answer(e, &ex).unwrap();
    let shown = format!("Step {}: {value}", k + 1);
    assert!(h.query_by_label(&shown).is_none());
    h.get_by_label("Show the calculation's answer").click();
    h.run_steps(3);
    let label = h.get_by_label(&shown).rect();
    assert_eq!(h.state().ui.layout.step, Some(k), "the step is highlighted in the calculation");
    // The window and what it says lie inside a 1024x600 window.
    let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1024.0, 600.0));
    let q = h.get_by_label(question).rect();
    assert!(window.contains_rect(label) && window.contains_rect(q), "{label:?} {q:?}");
    assert!(q.max.y <= label.min.y, "the question, then its answer");
    // Ctrl+Z brings back the scene the experiment replaced.
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().doc, Document::default());
}

/// Every experiment's words draw in the window, in each language (the test harness panics on
/// a character the fonts lack: a "▸" did), and each one sets its scene up.
#[test]
fn every_experiment_shows_in_every_language() {
    for lang in ["en", "pt-PT", "pt-BR"] {
        let mut state = AppState::worksheet();
        state.ui.layout.language = Some(lang.into());
        state.things.open = true;
        let mut h =
            Harness::builder().with_size([1280.0, 720.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
        h.run_steps(2);
        let code = phonglab_core::locale::Lang::parse(lang).unwrap();
        for (k, e) in shipped().iter().enumerate() {
            let title = format!("{}. {}", k + 1, e.words(code).title);
            h.get_by_label(&title).click();
            h.run_steps(3);
            assert_eq!(h.state().doc, e.doc, "{lang}: {title}");
            h.get_by_label(&e.words(code).question);
        }
    }
}

/// At the start (1280x720) the band under the picture and the plot offers the experiments:
/// below both squares, every button whole inside it; one click sets the experiment up and
/// opens the window on it.
#[test]
fn the_band_under_the_squares_offers_the_experiments() {
    let mut h = Harness::builder()
        .with_size([1280.0, 720.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(3);
    let g = h.state().ui.geometry.clone();
    let band = g.suggestions.expect("the band is offered");
    let squares = g.pictures[0].max.y.max(g.plot.as_ref().unwrap().rect.max.y);
    assert!(band.min.y >= squares, "{band:?} below {squares}");
    let lang = phonglab_core::locale::Lang::En;
    let shown: Vec<egui::Rect> =
        shipped().iter().filter_map(|e| h.query_by_label(&e.words(lang).title).map(|n| n.rect())).collect();
    assert!(shown.len() >= 6, "{} offered", shown.len());
    for r in &shown {
        assert!(band.contains_rect(*r), "{r:?} inside {band:?}");
    }
    let e = &shipped()[4];
    h.get_by_label(&e.words(lang).title).click();
    h.run_steps(3);
    assert_eq!(h.state().doc, e.doc);
    assert!(h.state().things.open && h.state().things.chosen == Some(4));
    h.get_by_label(&e.words(lang).question);
}
