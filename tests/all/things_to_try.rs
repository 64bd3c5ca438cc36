//! "Things to try": each shipped experiment sets up what its words say (the light behind
//! the surface gives cosTheta < 0 and Idif = 0, the attenuation's d is 1 and at 1.11, …),
//! its answer is a step of the calculation, and the window sets up a scene in one click,
//! shows the question, and shows the answer from the calculation only when asked.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::editing::evaluated::{Settings, evaluate};
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

/// The value of light `light`'s step `name` (printed `name[light]` with several lights).
fn light_step(ex: &Explanation, name: &str, light: usize) -> Vec<f64> {
    ex.steps
        .iter()
        .find(|s| s.light == Some(light) && (s.name == name || s.name == format!("{name}[{light}]")))
        .and_then(|s| s.value.clone())
        .unwrap_or_else(|| panic!("no {name} of light {light}"))
}

/// The calculation works the vertex as the picture lights it: the same modelview (the
/// picture's camera and spin), so what it finds is what the picture shows there.
fn assert_calculation_is_the_pictures(doc: &Document) {
    let (calc, picture) = (doc.scene.eye_from_object(), doc.shaded_scene().eye_from_object());
    let apart = (calc - picture).to_cols_array().iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(apart < 1e-12, "the calculation's modelview is {apart} from the picture's");
}

/// `doc` drawn `px` square in `shading`: its RGBA bytes.
fn picture(doc: &Document, shading: phonglab_core::Shading, px: usize) -> Vec<u8> {
    let mut d = doc.clone();
    d.view.shading = shading;
    let setup = d.shaded_setup(phonglab_core::PowFn::Exact);
    let mesh = d.view.mesh();
    let mut r = phonglab_core::render::Renderer::new();
    r.render(&setup.job(&mesh), px, px).unwrap().0.rgba.clone()
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

/// "Gouraud on a coarse sphere": the highlight is a dim star, and the worked vertex, one of
/// the mesh's, is the one nearest it, lit as the picture lights it: its Ispec is a fraction
/// of the highlight's. (The calculation worked the sphere's pole from another camera, where
/// it sat in the highlight: Ispec = 1, cosBeta = 1.)
#[test]
fn gouraud_on_a_coarse_sphere_works_the_vertex_nearest_a_dim_star() {
    use phonglab_core::Shading;
    use phonglab_core::scene::Vertex;
    let doc = &by_name("gouraud-coarse").doc;
    assert_eq!((doc.view.shading, doc.view.sphere_slices, doc.view.sphere_stacks), (Shading::Gouraud, 8, 6));
    assert_eq!(doc.scene.material.shininess, 100.0, "a sharp highlight (shininess 100)");
    assert_calculation_is_the_pictures(doc);
    // Exactly the picture's frame: the arrows stand on the sphere at the worked vertex.
    assert_eq!(doc.with_vertex_as_shaded(doc.scene.vertex), *doc);
    // The worked vertex is one of the mesh's.
    let mesh = doc.view.mesh();
    let v = doc.scene.vertex;
    let k = (0..mesh.positions.len())
        .find(|&i| mesh.positions[i].as_dvec3() == v.position.truncate() && mesh.normals[i].as_dvec3() == v.normal)
        .expect("the worked vertex is a vertex of the mesh");
    // Of all the mesh's vertices, it catches the most of the highlight, as the picture
    // lights them; and that is a fraction of it.
    let ispec = |d: &Document| step(&explain(d), "Ispec")[0];
    let worked = ispec(doc);
    for i in 0..mesh.positions.len() {
        let other = Vertex { position: mesh.positions[i].as_dvec3().extend(1.0), normal: mesh.normals[i].as_dvec3() };
        let there = ispec(&doc.with_vertex_as_shaded(other));
        assert!(there <= worked + 1e-12, "vertex {i} catches {there}, more than the worked vertex {k}'s {worked}");
    }
    assert!(worked > 0.05 && worked < 0.5, "Ispec {worked}: not a dim share of the highlight");
    // The picture: Gouraud's brightest white is a dim star beside Phong's full highlight.
    let white = |rgba: &[u8]| rgba.chunks(4).map(|p| p[0].min(p[1]).min(p[2])).max().unwrap_or(0);
    let (g, p) = (white(&picture(doc, Shading::Gouraud, 256)), white(&picture(doc, Shading::Phong, 256)));
    assert!(p >= 240 && f64::from(g) < 0.6 * f64::from(p), "Gouraud's peak {g}, Phong's {p}");
}

/// "When the lights add up to more than 1": the worked vertex sits in the red light's
/// highlight, in the calculation and in the picture (on the sphere, under its camera).
#[test]
fn the_clamping_vertex_sits_in_the_red_highlight_the_picture_shows() {
    let doc = &by_name("clamping").doc;
    assert_calculation_is_the_pictures(doc);
    let p = doc.scene.vertex.position.truncate();
    assert!((p.length() - 0.5).abs() < 1e-3, "on the sphere of radius 0.5: |P| = {}", p.length());
    let ex = explain(doc);
    let red = light_step(&ex, "cosBeta", 0)[0];
    assert!(red > 0.999, "cosBeta of the red light {red}");
    for l in 1..doc.scene.lights.len() {
        let s = light_step(&ex, "Ispec", l)[0];
        assert!(s < light_step(&ex, "Ispec", 0)[0], "light {l}'s specular {s} passes the red one's");
    }
}

#[test]
fn the_other_experiments_set_up_what_they_say() {
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
            click_title(&mut h, &title);
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

/// Clicks the experiment titled `title` in the window, scrolled into view first (the
/// window's list scrolls where the chosen one's words push the rest down).
fn click_title(h: &mut Harness<'static, AppState>, title: &str) {
    h.get_by_label(title).scroll_to_me();
    h.run_steps(30);
    h.get_by_label(title).click();
}

/// A harness at `w` x `h` with experiment `stem` set up from the Things to try window.
fn with_experiment(stem: &str, w: f32, ht: f32) -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([w, ht])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h.get_by_label("Things to try").click();
    h.run_steps(3);
    let k = shipped().iter().position(|e| e.source.contains(stem)).unwrap();
    let title = format!("{}. {}", k + 1, shipped()[k].words(phonglab_core::locale::Lang::En).title);
    click_title(&mut h, &title);
    h.run_steps(3);
    assert_eq!(h.state().doc, shipped()[k].doc);
    h
}

/// Presses `key` until `done` holds (at most `most` times); how many it took.
fn press_until(
    h: &mut Harness<'static, AppState>,
    key: egui::Key,
    most: usize,
    done: impl Fn(&AppState) -> bool,
) -> usize {
    for n in 1..=most {
        h.key_press(key);
        h.run_steps(2);
        if done(h.state()) {
            return n;
        }
    }
    panic!("{key:?} pressed {most} times did not get there");
}

/// G switches the rule set with the specular model it comes with: the Phong demo's R.V
/// (its summary says pow(max(R.V,0),e); G left Blinn-Phong n.H shown), then Blinn-Phong
/// again for OpenGL's.
#[test]
fn g_sets_the_specular_model_of_the_rule_set() {
    use phonglab_core::rules::SpecularModel;
    let mut h = with_experiment("what-opengl-adds", 1280.0, 720.0);
    press_until(&mut h, egui::Key::G, 3, |s| s.doc.scene.rules.set == RuleSet::PhongDemo);
    assert_eq!(h.state().doc.scene.rules.specular, SpecularModel::Phong);
    press_until(&mut h, egui::Key::G, 3, |s| s.doc.scene.rules.set == RuleSet::OpenGl);
    assert_eq!(h.state().doc.scene.rules.specular, SpecularModel::BlinnPhong);
}

/// The keys the experiments tell the class to press do what their words say, and what the
/// calculation then shows is what they ask about: G reaches OpenGL's rules (mview3's two
/// normals part by the note's angle; I grows by the emission and the scene ambient), L
/// turns the local viewer on (V and H change, L does not), 2 and 1 switch Phong and
/// Gouraud.
#[test]
fn the_keys_the_experiments_name_do_what_they_say() {
    let opengl = |s: &AppState| s.doc.scene.rules.set == RuleSet::OpenGl;
    // mview3: the worksheet's M n and OpenGL's (M^-1)^T n, as far apart as step 1 says.
    let mut h = with_experiment("normal-matrix", 1280.0, 720.0);
    let before = explain(&h.state().doc);
    let note = before.steps[0].notes.join(" ");
    press_until(&mut h, egui::Key::G, 3, opengl);
    let after = explain(&h.state().doc);
    let n = |ex: &Explanation| glam::DVec3::from_slice(&step(ex, "vertexNormal")[..3]);
    let degrees = n(&before).angle_between(n(&after)).to_degrees();
    assert!(
        degrees > 5.0 && note.contains(&format!("{}°", phonglab_core::locale::num(degrees, 3))),
        "{degrees} {note}"
    );
    // What OpenGL adds.
    let mut h = with_experiment("what-opengl-adds", 1280.0, 720.0);
    let before = step(&explain(&h.state().doc), "I");
    press_until(&mut h, egui::Key::G, 3, opengl);
    assert!(step(&explain(&h.state().doc), "I")[0] > before[0]);
    // The local viewer: V (and so H) change, L does not.
    let mut h = with_experiment("local-viewer", 1280.0, 720.0);
    let off = explain(&h.state().doc);
    press_until(&mut h, egui::Key::L, 1, |s| s.doc.scene.light_model.local_viewer);
    let on = explain(&h.state().doc);
    assert_ne!(step(&off, "vov"), step(&on, "vov"));
    assert_ne!(step(&off, "H"), step(&on, "H"));
    assert_eq!(step(&off, "vlv"), step(&on, "vlv"));
    // Gouraud on the coarse sphere: 2 is Phong, 1 Gouraud.
    let mut h = with_experiment("gouraud-coarse", 1280.0, 720.0);
    press_until(&mut h, egui::Key::Num2, 1, |s| s.doc.view.shading == phonglab_core::Shading::Phong);
    press_until(&mut h, egui::Key::Num1, 1, |s| s.doc.view.shading == phonglab_core::Shading::Gouraud);
}

/// The values the experiments tell the class to type or drag to are ones the window
/// takes: Light z through 0 to 90 (the slider reaches it), Light y 10 and 100, the spot
/// cutoff past the vertex's 11.6 degrees off the axis.
#[test]
fn the_values_the_experiments_name_are_taken() {
    let behind = &by_name("light-behind").doc;
    assert!(phonglab::app::panels::controls::position_range(behind) >= 90.0);
    let mut z90 = behind.clone();
    z90.scene.lights[0].position.z = 90.0;
    assert!(step(&explain(&z90), "Idif")[0] > 0.0, "Idif comes back");
    let mut state = AppState::worksheet();
    let at = by_name("attenuation").doc.clone();
    for y in [10.0, 100.0] {
        let mut d = at.clone();
        d.scene.lights[0].position.y = y;
        assert!(state.apply(d), "Light y = {y} is taken");
    }
    // The vertex is between 11 and 12 degrees off the spotlight's axis.
    let sp = &by_name("spot-cutoff").doc;
    for (cutoff, lit) in [(10.0, false), (11.0, false), (12.0, true)] {
        let mut d = sp.clone();
        d.scene.lights[0].spot_cutoff = cutoff;
        assert!(state.apply(d.clone()), "cutoff {cutoff} is taken");
        assert_eq!(step(&explain(&d), "spot")[0] > 0.0, lit, "cutoff {cutoff}");
    }
}

/// Where an experiment speaks of the picture, the picture says it: shininess 5 on the
/// teapot is a broad highlight that narrows at 100 (the specular channel's bright area
/// shrinks), and the spotlight's cone shows its rim on the picture.
#[test]
fn the_pictures_show_what_the_experiments_say() {
    use phonglab_core::channels::{Channel, channel_image};
    let bright_area = |doc: &Document| {
        let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
        let mesh = doc.view.mesh();
        let job = setup.job(&mesh);
        let mut r = phonglab_core::render::Renderer::new();
        r.keep_visibility(true);
        r.render(&job, 128, 128).unwrap();
        let c = channel_image(&r, &job, Channel::Specular, None).unwrap();
        c.values.iter().flatten().filter(|v| c.scalar(**v) >= 0.1).count()
    };
    let broad = by_name("shininess").doc.clone();
    assert_eq!(broad.view.object, phonglab_core::ObjectKind::Teapot, "on the teapot");
    let mut sharp = broad.clone();
    sharp.scene.material.shininess = 100.0;
    let (b, s) = (bright_area(&broad), bright_area(&sharp));
    assert!(b >= 3 * s && b > 100, "highlight of {b} pixels at 5, {s} at 100");
    let h = with_experiment("spot-cutoff", 1280.0, 720.0);
    let picture = h.state().ui.geometry.pictures[0];
    let cones = &h.state().ui.geometry.cones;
    assert!(!cones.is_empty() && cones.iter().all(|c| c.intersects(picture)), "{cones:?} on {picture:?}");
}

/// The Things to try window: its rect (the window node whose title it is).
fn things_window(h: &Harness<'static, AppState>) -> egui::Rect {
    h.root()
        .children_recursive()
        .find(|n| {
            n.accesskit_node().role() == egui::accesskit::Role::Window
                && n.accesskit_node().label().as_deref() == Some("Things to try")
        })
        .map(|n| n.rect())
        .expect("the window")
}

/// An experiment's window never covers the control its words tell the class to move: at
/// the projector sizes, at the desk and presenting (the drawer), the click opens the
/// controls on it, and it lies in sight, clear of the window (which opened over the
/// controls, on Light z). Every experiment names its control where its words name one.
#[test]
fn an_experiments_window_leaves_the_control_it_names_in_sight() {
    use egui::accesskit::Role;
    let named: Vec<&str> = shipped().iter().filter_map(|e| e.control.as_deref()).collect();
    assert_eq!(named, ["light-z", "light-y", "material-shininess", "spot-cutoff"]);
    for (w, ht) in [(1024.0, 600.0), (1280.0, 720.0), (1920.0, 1080.0)] {
        for presenting in [false, true] {
            let mut state = AppState::worksheet();
            state.ui.layout.presenting = presenting;
            state.ui.layout.controls_open = false;
            state.ui.layout.drawer_open = false;
            let mut h =
                Harness::builder().with_size([w, ht]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
            h.run_steps(2);
            h.state_mut().things.open = true;
            h.run_steps(2);
            let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(w, ht));
            for (k, e) in shipped().iter().enumerate() {
                let Some(control) = e.control_label() else { continue };
                let title = format!("{}. {}", k + 1, e.words(phonglab_core::locale::Lang::En).title);
                click_title(&mut h, &title);
                // The controls scroll to it (scrolling is animated).
                h.run_steps(30);
                let window = things_window(&h);
                let at = h
                    .query_all_by_label(&control)
                    .filter(|n| n.accesskit_node().role() == Role::Slider)
                    .map(|n| n.rect())
                    .find(|r| screen.contains_rect(*r))
                    .unwrap_or_else(|| panic!("{w}x{ht}, presenting {presenting}: {control} not in sight for {title}"));
                assert!(!at.intersects(window), "{w}x{ht}, presenting {presenting}: {control} {at:?} under {window:?}");
            }
        }
    }
}

/// Opening the next experiment lets go of the step the last one highlighted.
#[test]
fn the_next_experiment_clears_the_last_ones_highlighted_step() {
    let mut h = with_experiment("light-behind", 1280.0, 720.0);
    h.get_by_label("Show the calculation's answer").click();
    h.run_steps(3);
    assert!(h.state().ui.layout.step.is_some());
    let title = format!("2. {}", shipped()[1].words(phonglab_core::locale::Lang::En).title);
    click_title(&mut h, &title);
    h.run_steps(3);
    assert_eq!(h.state().ui.layout.step, None, "the last experiment's answer is no longer highlighted");
    // The band under the squares does the same.
    h.get_by_label("Show the calculation's answer").click();
    h.run_steps(3);
    assert!(h.state().ui.layout.step.is_some());
    let band = h.state().ui.geometry.suggestions.expect("the band");
    let third = shipped()[2].words(phonglab_core::locale::Lang::En).title.clone();
    h.query_all_by_label(&third).find(|n| band.contains_rect(n.rect())).expect("offered in the band").click();
    h.run_steps(3);
    assert_eq!(h.state().ui.layout.step, None);
}
