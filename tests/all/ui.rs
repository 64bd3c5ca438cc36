//! The explorer UI, driven headless with egui_kittest: widgets found by their labels,
//! clicked, typed into and dragged; the state and the displayed text checked.

use crate::common;

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use glam::DVec3;
use phonglab::app::shell::state::{Message, Orbit};
use phonglab::app::{AppState, app_ui};
use phonglab_core::explain::{fmt_sig, fmt_value};
use phonglab_core::{CameraSpec, Engine, materials};

fn harness() -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([1500.0, 1000.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h
}

/// The app on the worksheet with its shaded view on the sphere (the start shows the teapot):
/// for the tests whose numbers are the r = 0.5 sphere's.
fn sphere_harness() -> Harness<'static, AppState> {
    let mut state = AppState::worksheet();
    state.doc.view.object = phonglab_core::ObjectKind::Sphere;
    let mut h =
        Harness::builder().with_size([1500.0, 1000.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(2);
    h
}

/// The unclamped rgba line of the result panel, as it is displayed.
fn displayed_rgba(c: [f64; 4]) -> String {
    let s: Vec<String> = c.iter().map(|x| fmt_sig(*x, 8)).collect();
    format!("[{}]", s.join("  "))
}

fn front_primary(state: &AppState) -> [f64; 4] {
    Engine::<f64>::light_scene_vertex(&state.doc.scene).unwrap().front.primary
}

#[test]
fn starts_on_the_worksheets_answer() {
    let h = harness();
    let want = displayed_rgba(front_primary(h.state()));
    assert!(want.starts_with("[0.059587089  0.035759287  0.015155245"), "{want}");
    // Shown twice: unclamped and clamped agree inside [0, 1].
    assert_eq!(h.get_all_by_label(&want).count(), 2);
    h.get_by_label("vlv = [0.79220526 0.55887606 -0.2450885 0]");
    h.get_by_label("I = [0.059587089 0.035759287 0.015155245 0]");
}

#[test]
fn moving_the_light_z_shows_exactly_what_the_core_computes() {
    let mut h = harness();
    let before = front_primary(h.state());
    h.get_by_role_and_label(Role::Slider, "Light z").set_value_accesskit(300.0);
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.lights[0].position.z, 300.0);
    let after = front_primary(h.state());
    assert_ne!(before, after, "moving the light changes the colour");
    assert!(h.get_all_by_label(&displayed_rgba(after)).count() >= 1);
    assert!(h.query_by_label(&displayed_rgba(before)).is_none(), "the old colour is gone within the frame");

    // Typing into the slider's number field works too.
    let field = h.get_by_role_and_label(Role::SpinButton, "Light z");
    field.click();
    h.run_steps(1);
    h.get_by_role_and_label(Role::SpinButton, "Light z").type_text("-40");
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.lights[0].position.z, -40.0);
    assert!(h.get_all_by_label(&displayed_rgba(front_primary(h.state()))).count() >= 1);
}

#[test]
fn toggling_the_local_viewer_changes_v() {
    let mut h = harness();
    h.get_by_label("vov = [0 0 1 0]");
    h.get_by_label("Local viewer").click();
    h.run_steps(2);
    assert!(h.state().doc.scene.light_model.local_viewer);
    assert!(h.query_by_label("vov = [0 0 1 0]").is_none());
    // V = normalize(-P) with P = mview5 (-512, -384, 0, 1) = (-512, -307.2, -729.6).
    let v = -DVec3::new(-512.0, -307.2, -729.6).normalize();
    h.get_by_label(&format!("vov = {}", fmt_value(&[v.x, v.y, v.z, 0.0], 8)));
}

#[test]
fn choosing_gold_sets_the_material() {
    let mut h = harness();
    h.get_by_label("Material preset").click();
    h.run_steps(2);
    // The list scrolls; click through accesskit as assistive technology does.
    h.get_by_label("gold").click_accesskit();
    h.run_steps(2);
    let gold = materials::by_name("gold").unwrap();
    assert_eq!(&h.state().doc.scene.material, gold);
    assert_eq!(h.get_by_role_and_label(Role::SpinButton, "Material shininess").value().as_deref(), Some("51.2"));
}

fn type_into(h: &mut Harness<'static, AppState>, label: &str, text: &str) {
    common::click_field(h, label);
    h.get_by_role_and_label(Role::SpinButton, label).type_text(text);
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
}

#[test]
fn an_out_of_range_shininess_is_refused_and_the_scene_keeps_its_value() {
    let mut h = harness();
    let before = h.state().doc.clone();
    type_into(&mut h, "Material shininess", "200");
    assert_eq!(h.state().doc, before, "the scene keeps its last valid value");
    let msg = match &h.state().message {
        Some(Message::Refused(m)) => m.clone(),
        other => panic!("expected a refusal, got {other:?}"),
    };
    assert!(msg.contains("material.shininess = 200") && msg.contains("[0, 128]"), "{msg}");
    h.get_by_label(&msg);
    // The refused text stays in the field, with the validator's reason beside it, until
    // it is corrected or Esc puts the value back.
    assert_eq!(h.get_by_role_and_label(Role::SpinButton, "Material shininess").value().as_deref(), Some("200"));
    h.get_by_label_contains("material.shininess = 200 is out of range: allowed [0, 128] (Esc: back to 25.6)");
    h.get_by_role_and_label(Role::SpinButton, "Material shininess").click();
    h.run_steps(1);
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
    assert_eq!(h.get_by_role_and_label(Role::SpinButton, "Material shininess").value().as_deref(), Some("25.6"));

    // NaN is refused the same way.
    type_into(&mut h, "Material shininess", "NaN");
    assert_eq!(h.state().doc, before);
    assert!(matches!(&h.state().message, Some(Message::Refused(m)) if m.contains("material.shininess")));

    // A valid value is taken and clears the message.
    type_into(&mut h, "Material shininess", "100");
    assert_eq!(h.state().doc.scene.material.shininess, 100.0);
    assert_eq!(h.state().message, None);
}

#[test]
fn a_nan_vertex_or_zero_attenuation_is_refused() {
    let mut h = harness();
    let before = h.state().doc.clone();
    type_into(&mut h, "Vertex x", "inf");
    assert_eq!(h.state().doc, before);
    // The field refuses it itself: the text stays, with the reason beside it.
    assert_eq!(h.get_by_role_and_label(Role::SpinButton, "Vertex x").value().as_deref(), Some("inf"));
    h.get_by_label_contains("inf is not a finite number (Esc: back to");
    h.get_by_role_and_label(Role::SpinButton, "Vertex x").click();
    h.run_steps(1);
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
    assert!(h.query_by_label_contains("inf is not a finite number").is_none(), "Esc puts the value back");
    for label in ["Constant attenuation", "Linear attenuation", "Quadratic attenuation"] {
        type_into(&mut h, label, "0");
    }
    let refused = match &h.state().message {
        Some(Message::Refused(m)) => m.clone(),
        other => panic!("{other:?}"),
    };
    assert!(refused.contains("lights[0].attenuation") && refused.contains("infinitely bright"), "{refused}");
    assert_ne!(h.state().doc.scene.lights[0].attenuation, [0.0; 3]);
}

#[test]
fn shortcuts_and_the_help_overlay() {
    let mut h = harness();
    h.key_press(egui::Key::L);
    h.run_steps(1);
    assert!(h.state().doc.scene.light_model.local_viewer);
    h.key_press(egui::Key::V);
    h.run_steps(1);
    assert_eq!(h.state().doc.camera, CameraSpec::Worksheet(1));
    h.key_press(egui::Key::M);
    h.run_steps(1);
    assert_eq!(materials::name_of(&h.state().doc.scene.material), Some("chrome"), "bronze is followed by chrome");
    h.key_press(egui::Key::F1);
    h.run_steps(2);
    h.get_by_label("Keyboard shortcuts");
    h.get_by_label("toggle the local viewer");
    // The keys of presentation too, each on its row beside what it does.
    for (keys, what) in [("F5", "present: large type"), ("← ↑  → ↓", "walk through the calculation's steps")] {
        let k = h.get_by_label(keys).rect();
        let w = h.get_by_label_contains(what).rect();
        assert!(k.max.x <= w.min.x && (k.center().y - w.center().y).abs() < 4.0, "{keys}: {k:?} {w:?}");
    }
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::R);
    h.run_steps(1);
    assert_eq!(h.state().doc, phonglab_core::Document::default());
}

#[test]
fn shortcuts_do_not_fire_while_typing() {
    let mut h = harness();
    h.get_by_role_and_label(Role::SpinButton, "Vertex z").click();
    h.run_steps(1);
    h.get_by_role_and_label(Role::SpinButton, "Vertex z").type_text("l");
    h.run_steps(1);
    assert!(!h.state().doc.scene.light_model.local_viewer);
}

#[test]
fn the_vector_plot_has_view_buttons_and_orbits_when_dragged() {
    let mut h = harness();
    h.get_by_label("XY").click();
    h.run_steps(1);
    assert_eq!(h.state().orbit, Orbit::XY);
    h.get_by_label("ZY").click();
    h.run_steps(1);
    assert_eq!(h.state().orbit, Orbit::ZY);
    let plot = h.get_by_label("vector plot").rect().center();
    h.drag_at(plot);
    h.run_steps(1);
    h.hover_at(plot + egui::vec2(40.0, 0.0));
    h.run_steps(1);
    h.drop_at(plot + egui::vec2(40.0, 0.0));
    h.run_steps(1);
    assert_ne!(h.state().orbit, Orbit::ZY, "dragging orbits the view");
}

#[test]
fn adding_and_removing_lights_up_to_eight() {
    let mut h = harness();
    for _ in 0..10 {
        h.get_by_label("Add light").click();
        h.run_steps(1);
    }
    assert_eq!(h.state().doc.scene.lights.len(), 8, "no ninth light: the button is disabled at 8");
    h.get_by_label("Light 7");
    h.get_by_label("Remove light").click();
    h.run_steps(1);
    assert_eq!(h.state().doc.scene.lights.len(), 7);
    assert!(h.state().evaluate().is_ok());
}

#[test]
fn copy_as_markdown_puts_the_table_on_the_clipboard() {
    let mut h = harness();
    h.get_by_label("Copy as Markdown").click();
    h.run_steps(1);
    let copied = common::copied_text(&h);
    assert!(
        copied.iter().any(|t| t.contains("| # | step | formula | value | notes |") && t.contains("vlv = [0.79220526")),
        "{copied:?}"
    );
}

#[test]
fn presets_load_the_phong_demo() {
    let mut h = harness();
    common::open_menu(&mut h, &["Scene"]);
    h.run_steps(2);
    h.get_by_label("Phong demo").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.rules, phonglab_core::Rules::PHONG_DEMO);
    h.get_by_label_contains("R = 2 max(vertexNormal · vlv, 0) vertexNormal − vlv");
    // The program as it draws: spinning, in clip space, the light turning with the object.
    let preset = phonglab_core::library::phong_demo_document();
    assert_eq!(h.state().doc.scene, preset.scene);
    let mut view = h.state().doc.view.clone();
    assert!(view.auto_rotate && view.spin_degrees > preset.view.spin_degrees, "it opens spinning");
    view.spin_degrees = preset.view.spin_degrees;
    assert_eq!(view, preset.view);
    // On a vertex where N, L and R are clearly apart (V is L: the demo's eye is its light).
    let lit = Engine::<f64>::light_scene_vertex(&h.state().doc.scene).unwrap();
    let (n, l, r) = (lit.normal_in_eye, lit.lights()[0].l, lit.lights()[0].r);
    for (a, b, what) in [(n, l, "N, L"), (n, r, "N, R"), (l, r, "L, R")] {
        let deg = a.dot(b).clamp(-1.0, 1.0).acos().to_degrees();
        assert!(deg > 30.0, "{what} are {deg} degrees apart");
    }
    common::menu_item(&mut h, &["Scene"], "Reset to worksheet");
    h.run_steps(1);
    assert_eq!(h.state().doc, phonglab_core::Document::default());
}

#[test]
fn the_shaded_view_follows_the_demos_keys() {
    let mut h = harness();
    h.key_press(egui::Key::T);
    h.run_steps(1);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Teapot);
    h.key_press(egui::Key::Num2);
    h.run_steps(1);
    assert_eq!(h.state().doc.view.shading, phonglab_core::Shading::Phong);
    h.key_press(egui::Key::C);
    h.key_press(egui::Key::Num3);
    h.run_steps(1);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Cylinder);
    assert_eq!(h.state().doc.view.shading, phonglab_core::Shading::Flat);
    h.get_by_label("Teapot").click();
    h.run_steps(1);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Teapot);
    h.get_by_label("Auto-rotate").click();
    h.run_steps(3);
    let spin = h.state().doc.view.spin_degrees;
    assert!(spin > 0.0 && spin <= 1.5 + 1e-9, "0.5 degrees a frame: {spin}");
}

#[test]
fn clicking_the_surface_explains_that_vertex() {
    let mut h = sphere_harness();
    let before = h.state().doc.scene.vertex;
    let image = h.get_by_label_contains("Sphere Gouraud").rect();
    // The image sits under its caption; click its centre (the sphere is in the middle).
    let img = h.query_all_by_role(Role::Image).next().map_or(image, |n| n.rect());
    h.get_all_by_role(Role::Image).next().unwrap().click();
    h.run_steps(2);
    let v = h.state().doc.scene.vertex;
    assert_ne!(v, before, "picked a vertex ({img:?})");
    assert!((v.position.truncate().length() - 0.5).abs() < 1e-5, "a vertex of the r = 0.5 sphere: {v:?}");
    assert!((v.normal.length() - 1.0).abs() < 1e-5);
    assert!(matches!(h.state().doc.camera, CameraSpec::Matrix(_)), "the shaded view's camera");
    assert!(matches!(&h.state().message, Some(Message::Info(m)) if m.contains("Vertex")));
    // The calculation now explains it: its normal in eye space faces the viewer.
    let lit = Engine::<f64>::light_scene_vertex(&h.state().doc.scene).unwrap();
    assert!(lit.normal_in_eye.z > 0.0, "the picked vertex faces the camera: {:?}", lit.normal_in_eye);
}

#[test]
fn the_calculation_says_what_the_specialised_plan_skips() {
    let mut h = harness();
    // The worksheet's light is positional and attenuated: attenuation is computed.
    assert!(h.query_by_label_contains("skipped by the specialised evaluator: the light is directional").is_none());
    h.get_by_label_contains("Specialised plan:");
    h.get_by_label("Directional (w = 0)").click();
    h.run_steps(2);
    h.get_by_label("skipped by the specialised evaluator: the light is directional");
    // Named in the plan summary and greyed in the spot-factor step: at least once.
    assert!(h.get_all_by_label_contains("cutoff 180: not a spotlight").count() >= 1);
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("phonglab-ui-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn set_file_path(h: &mut Harness<'static, AppState>, path: &std::path::Path) {
    if h.query_by_role_and_label(Role::TextInput, "Scene file:").is_none() {
        common::open_menu(h, &["File"]);
    }
    h.get_by_role_and_label(Role::TextInput, "Scene file:").set_text_value_accesskit(&path.display().to_string());
    h.run_steps(1);
}

#[test]
fn open_and_save_scene_files_by_path() {
    let mut h = harness();
    let spot = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    set_file_path(&mut h, &spot);
    common::menu_item(&mut h, &["File"], "Open");
    h.run_steps(2);
    assert_eq!(h.state().doc.name, "a spotlight");
    assert_eq!(h.state().doc.scene.lights[0].spot_cutoff, 12.0);
    assert!(matches!(&h.state().message, Some(Message::Info(m)) if m.contains("spotlight.toml")));

    // Change something, save it elsewhere, reset, open the saved file: the change is back.
    type_into(&mut h, "Material shininess", "77");
    assert_eq!(h.state().doc.scene.material.shininess, 77.0);
    let saved = temp_dir("save").join("mine.toml");
    set_file_path(&mut h, &saved);
    common::menu_item(&mut h, &["File"], "Save");
    h.run_steps(2);
    assert!(matches!(&h.state().message, Some(Message::Info(m)) if m.contains("Saved")), "{:?}", h.state().message);
    let doc = h.state().doc.clone();
    common::menu_item(&mut h, &["Scene"], "Reset to worksheet");
    h.run_steps(2);
    assert_ne!(h.state().doc, doc);
    set_file_path(&mut h, &saved);
    common::menu_item(&mut h, &["File"], "Open");
    h.run_steps(2);
    assert_eq!(h.state().doc, doc, "saved and opened: the same scene");
}

#[test]
fn a_bad_file_is_refused_with_its_line_and_the_scene_kept() {
    let mut h = harness();
    let before = h.state().doc.clone();
    let dir = temp_dir("bad");
    for (name, text, says) in [
        ("syntax.toml", "name = \"x\"\n[material\nshininess = 3\n", "line 2"),
        ("range.toml", "[material]\nshininess = 300\n", "material.shininess"),
        ("nan.toml", "[[lights]]\nposition = [0, nan, 1, 1]\n", "lights[0].position[1]"),
        ("binary.toml", "\u{0}\u{1}", "line 1"),
    ] {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        set_file_path(&mut h, &p);
        common::menu_item(&mut h, &["File"], "Open");
        h.run_steps(2);
        let msg = match &h.state().message {
            Some(Message::Refused(m)) => m.clone(),
            other => panic!("{name}: {other:?}"),
        };
        assert!(msg.contains(says) && msg.contains("unchanged"), "{name}: {msg}");
        assert_eq!(h.state().doc, before, "{name}: the scene is kept");
        assert!(h.get_all_by_label_contains(says).count() >= 1, "{name}: the message is shown");
    }
    set_file_path(&mut h, &dir.join("missing.toml"));
    common::menu_item(&mut h, &["File"], "Open");
    h.run_steps(2);
    assert!(matches!(&h.state().message, Some(Message::Refused(m)) if m.contains("cannot read")));
    // Saving into a folder that does not exist fails and says so; nothing is lost.
    set_file_path(&mut h, &dir.join("no/such/folder/x.toml"));
    common::menu_item(&mut h, &["File"], "Save");
    h.run_steps(2);
    assert!(matches!(&h.state().message, Some(Message::Refused(m)) if m.contains("Not saved")));
    assert_eq!(h.state().doc, before);
}

#[test]
fn dropping_a_scene_file_opens_it() {
    let mut h = harness();
    let demo = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/phong-demo.toml");
    h.input_mut().dropped_files.push(std::sync::Arc::new(common::Dropped(demo.clone())));
    h.run_steps(2);
    assert_eq!(h.state().doc.name, "the Phong demo");
    assert_eq!(h.state().files.path, demo.display().to_string(), "Save writes back to it");
    // A dropped file that is not a scene is refused; the Phong demo stays. (A picture is
    // taken for a student's, and this one is not of the export's size.)
    let png = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/screenshot.png");
    h.input_mut().dropped_files.push(std::sync::Arc::new(common::Dropped(png)));
    h.run_steps(2);
    assert!(
        matches!(&h.state().message, Some(Message::Refused(m)) if m.contains("Not checked") && m.contains("512x512")),
        "{:?}",
        h.state().message
    );
    assert_eq!(h.state().doc.name, "the Phong demo");
}

#[test]
fn ctrl_s_saves_and_ctrl_o_opens() {
    let mut h = harness();
    let p = temp_dir("keys").join("k.toml");
    set_file_path(&mut h, &p);
    // Leave the field (shortcuts are off while typing), as a user clicks elsewhere.
    h.key_press(egui::Key::Escape);
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::S);
    h.run_steps(2);
    assert!(p.exists(), "{:?}", h.state().message);
    assert_eq!(h.state().doc.to_toml().unwrap(), std::fs::read_to_string(&p).unwrap());
    let saved = h.state().doc.clone();
    h.key_press(egui::Key::L); // local viewer on
    h.run_steps(2);
    assert_ne!(h.state().doc, saved);
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::O);
    h.run_steps(2);
    assert_eq!(h.state().doc, saved);
}

#[test]
fn ctrl_q_closes_the_window_which_saves_the_session() {
    let mut h = harness();
    let closes = |h: &Harness<'static, AppState>| {
        h.output().viewport_output[&egui::ViewportId::ROOT]
            .commands
            .iter()
            .any(|c| matches!(c, egui::ViewportCommand::Close))
    };
    h.run_steps(1);
    assert!(!closes(&h));
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Q);
    h.run_steps(1);
    assert!(h.state().ui.quit && closes(&h), "Ctrl+Q asks eframe to close (its on_exit saves the session)");
    h.key_press(egui::Key::F1);
    h.run_steps(2);
    h.get_by_label("quit (the session is saved)");
}

/// Steps the UI until `done` holds (background work), failing after `secs` seconds.
fn wait_for(h: &mut Harness<'static, AppState>, secs: u64, done: impl Fn(&AppState) -> bool) {
    let start = std::time::Instant::now();
    while !done(h.state()) {
        assert!(start.elapsed().as_secs() < secs, "timed out");
        std::thread::sleep(std::time::Duration::from_millis(50));
        h.run_steps(1);
    }
    h.run_steps(2);
}

#[test]
fn the_cost_of_accuracy_study_runs_in_the_background() {
    let mut h = sphere_harness();
    common::menu_item(&mut h, &["View"], "Cost of accuracy");
    h.run_steps(2);
    h.get_by_label("Run the study").click();
    h.run_steps(2);
    // While it runs the UI keeps answering: a progress bar, a Cancel button, live edits.
    assert!(h.state().cost.running.is_some());
    h.get_by_label("Cancel");
    h.get_by_role_and_label(Role::Slider, "Light z").set_value_accesskit(120.0);
    h.run_steps(1);
    assert_eq!(h.state().doc.scene.lights[0].position.z, 120.0);
    wait_for(&mut h, 120, |s| s.cost.running.is_none());
    let (study, about) = h.state().cost.study.clone().expect("a study");
    assert!(about.contains("Sphere"), "{about}");
    assert_eq!(study.points.len(), phonglab_core::cost::variants(phonglab_core::ObjectKind::Sphere).len());
    // The table shows every variant, and the takeaways are stated.
    h.get_by_label("Gouraud 64");
    // In the table, and in the chart's legend.
    assert!(h.query_all_by_label("Phong 32, fast rsqrt").count() >= 1);
    h.get_by_label_contains("f32 against f64 on");
    // Phong beats Gouraud at every level, as the core's tests also say.
    for l in phonglab_core::cost::levels(phonglab_core::ObjectKind::Sphere) {
        let e = |s: &str| study.points.iter().find(|p| p.variant.label == format!("{s} {l}")).unwrap().error.mean;
        assert!(e("Phong") <= e("Gouraud"), "level {l}");
    }
}

#[test]
fn cancelling_or_closing_stops_the_study() {
    let mut h = harness();
    common::menu_item(&mut h, &["View"], "Cost of accuracy");
    h.run_steps(2);
    h.get_by_label("Run the study").click();
    h.run_steps(2);
    h.get_by_label("Cancel").click();
    h.run_steps(2);
    assert!(h.state().cost.running.is_none() && h.state().cost.study.is_none());
    h.get_by_label("Run the study").click();
    h.run_steps(2);
    assert!(h.state().cost.running.is_some());
    // Closed from the View menu (a switch).
    common::open_menu(&mut h, &["View"]);
    h.get_by_role_and_label(Role::CheckBox, "Cost of accuracy").click();
    h.run_steps(2);
    assert!(h.state().cost.running.is_none(), "closing cancels");
}

#[test]
fn the_heat_map_shows_beside_the_shaded_view() {
    let mut h = sphere_harness();
    h.get_by_label("Error heat map").click();
    h.run_steps(1);
    wait_for(&mut h, 60, |s| s.heat_map.heat.is_some());
    let heat = h.state().heat_map.heat.as_ref().unwrap();
    // Gouraud on the 50x50 sphere: close, but not exact, at the highlight and the rim.
    assert!(heat.error.mean > 0.0 && heat.error.mean < 2.0, "{:?}", heat.error);
    h.get_by_label_contains("Error against the f64 reference");
    // Switching to Phong asks for a new map, which is closer to the reference.
    let gouraud = heat.error;
    h.get_by_label("Phong").click();
    h.run_steps(2);
    wait_for(&mut h, 60, |s| {
        s.heat_map.heat.as_ref().is_some_and(|m| m.key.view.shading == phonglab_core::Shading::Phong)
    });
    let phong = h.state().heat_map.heat.as_ref().unwrap().error;
    assert!(phong.mean <= gouraud.mean && phong.share_over_one <= gouraud.share_over_one, "{phong:?} vs {gouraud:?}");
}

#[test]
fn the_demos_departures_are_switches_with_the_corrected_picture_beside() {
    let mut h = harness();
    common::open_menu(&mut h, &["Scene"]);
    h.run_steps(2);
    h.get_by_label("Phong demo").click();
    h.run_steps(2);
    // One picture: the demo's own.
    assert_eq!(h.query_all_by_role(Role::Image).count(), 1);
    for d in phonglab_core::library::DemoDeparture::ALL {
        h.get_by_label(&d.fix_label());
        assert!(h.query_by_label_contains(&d.why()).is_none(), "the reasons are folded");
    }
    h.get_by_label("light fixed in the world").click();
    h.run_steps(2);
    assert_eq!(h.state().view_options.demo_fixes, [true, false, false]);
    // The reasons open in one click, and the switches have not moved.
    h.get_by_label_contains("Why the demo differs").click();
    h.run_steps(2);
    h.get_by_label_contains(&phonglab_core::library::DemoDeparture::LightTurnsWithObject.why());
    // Two pictures: the demo's on the left, the corrected one on the right.
    let images: Vec<egui::Rect> = h.query_all_by_role(Role::Image).map(|n| n.rect()).collect();
    assert_eq!(images.len(), 2, "{images:?}");
    assert!(images[0].center().x < images[1].center().x);
    h.get_by_label("Corrected: light fixed in the world");
    let corrected =
        phonglab::app::panels::shaded::corrected_document(&h.state().doc, &h.state().view_options.demo_fixes).unwrap();
    assert_eq!(corrected.view.lighting_space, phonglab_core::LightingSpace::Eye);
    assert_eq!(h.state().doc.view.lighting_space, phonglab_core::LightingSpace::Object, "the demo's stays");
    h.get_by_label("highlight in the light's colour").click();
    h.run_steps(2);
    let corrected =
        phonglab::app::panels::shaded::corrected_document(&h.state().doc, &h.state().view_options.demo_fixes).unwrap();
    assert_eq!(corrected.scene.material.specular.truncate(), DVec3::splat(0.5));
    h.get_by_label("Corrected: light fixed in the world, highlight in the light's colour");
}

#[test]
fn the_presets_menu_lists_every_shipped_scene_grouped() {
    let mut h = harness();
    common::open_menu(&mut h, &["Scene"]);
    h.run_steps(2);
    for group in ["The worksheet", "The Phong demo", "More scenes"] {
        h.get_by_label(group);
    }
    for title in ["Worksheet, mview1", "Worksheet, mview5", "Phong demo", "Spotlight", "Three lights"] {
        // (A step of the calculation may share a name, e.g. "Spotlight": at least one.)
        assert!(h.get_all_by_label(title).count() >= 1, "{title} is listed");
    }
    h.get_by_label("Red Book teapots").click();
    h.run_steps(2);
    h.get_by_label("Gold").click();
    h.run_steps(2);
    let gold = materials::by_name("gold").unwrap();
    assert_eq!(h.state().doc.scene.material, gold.clone());
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Teapot);
}

#[test]
fn a_file_named_at_start_opens_or_the_worksheet_says_why() {
    let dir = temp_dir("start");
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("spot.toml");
    std::fs::copy(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes/spotlight.toml"), &good).unwrap();
    let mut s = AppState::worksheet();
    phonglab::app::shell::files::open_at_start(&mut s, &good);
    assert!(s.doc.scene.lights[0].is_spot(), "the spotlight scene is open");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "rules = \"opengl\"\n[material]\nshininess = 500\n").unwrap();
    let mut s = AppState::worksheet();
    s.doc = phonglab_core::library::phong_demo_document();
    phonglab::app::shell::files::open_at_start(&mut s, &bad);
    assert_eq!(s.doc, phonglab_core::Document::default(), "the default scene");
    assert!(
        matches!(&s.message, Some(Message::Refused(m)) if m.contains("bad.toml") && m.contains("shininess") && m.contains("Showing the worksheet")),
        "{:?}",
        s.message
    );
    let mut s = AppState::worksheet();
    phonglab::app::shell::files::open_at_start(&mut s, &dir.join("missing.toml"));
    assert!(matches!(&s.message, Some(Message::Refused(m)) if m.contains("cannot read")), "{:?}", s.message);
}

#[test]
fn an_obj_mesh_opens_from_the_path_field_and_a_bad_one_is_refused_with_its_line() {
    let dir = temp_dir("obj");
    let good = dir.join("pyramid.obj");
    std::fs::write(
        &good,
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 1 2 3 4\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n",
    )
    .unwrap();
    let bad = dir.join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 7\n").unwrap();
    let mut h = harness();
    let scene_before = h.state().doc.scene.clone();
    set_file_path(&mut h, &good);
    common::menu_item(&mut h, &["File"], "Open");
    h.run_steps(2);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Obj, "{:?}", h.state().message);
    assert_eq!(h.state().doc.scene, scene_before, "the scene stays; the view shows the mesh");
    assert!(
        matches!(&h.state().message, Some(Message::Info(m)) if m.contains("6 triangles") && m.contains("fanned") && m.contains("computed")),
        "{:?}",
        h.state().message
    );
    h.get_by_label("Your mesh");
    h.get_by_label_contains("Your mesh Gouraud");
    let view_before = h.state().doc.view.clone();
    set_file_path(&mut h, &bad);
    common::menu_item(&mut h, &["File"], "Open");
    h.run_steps(2);
    assert!(
        matches!(&h.state().message, Some(Message::Refused(m)) if m.contains("line 4") && m.contains("out of range")),
        "{:?}",
        h.state().message
    );
    assert_eq!(h.state().doc.view, view_before, "the current mesh stays");
    // Back to the sphere with one click, and to the mesh again.
    h.get_by_label("Sphere").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Sphere);
    h.get_by_label("Your mesh").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Obj);
}

/// Clicks `item` in the Scene menu (the controls have a "Spotlight" checkbox too).
fn scene_menu_item(h: &mut Harness<'static, AppState>, item: &str) {
    common::open_menu(h, &["Scene"]);
    h.get_all_by_label(item).find(|n| n.accesskit_node().role() == Role::Button).unwrap().click();
    h.run_steps(2);
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
}

/// The user's mesh stays offered ("Your mesh" in the top bar) through changes of scene, from
/// the Scene menu and a reset alike, until the user closes it there.
#[test]
fn the_users_mesh_stays_through_a_change_of_scene_until_it_is_closed() {
    let dir = temp_dir("obj-kept");
    let mesh = dir.join("tetra.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n").unwrap();
    let mut h = harness();
    phonglab::app::shell::files::open_obj(h.state_mut(), &mesh);
    h.run_steps(2);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Obj, "{:?}", h.state().message);
    let path = h.state().doc.view.obj.clone();
    assert!(path.is_some());
    scene_menu_item(&mut h, "Spotlight");
    assert_eq!(h.state().doc.name, "a spotlight", "{:?}", h.state().message);
    assert_eq!(h.state().doc.view.obj, path, "the mesh stays offered");
    h.get_by_label("Your mesh").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.view.object, phonglab_core::ObjectKind::Obj, "shown under the new scene's lights");
    assert_eq!(h.state().doc.scene.lights[0].spot_cutoff, 12.0);
    scene_menu_item(&mut h, "Reset to worksheet");
    assert_eq!(h.state().doc.view.obj, path, "a reset keeps it too");
    h.get_by_label("Your mesh");
    // Closed: the top bar offers it no more, and the next scene does not bring it back.
    h.get_by_label("Your mesh").click();
    h.run_steps(2);
    h.get_by_label("Close your mesh").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.view.obj, None);
    assert_ne!(h.state().doc.view.object, phonglab_core::ObjectKind::Obj);
    assert!(h.query_by_label("Your mesh").is_none());
    scene_menu_item(&mut h, "Spotlight");
    assert!(h.query_by_label("Your mesh").is_none());
}

#[test]
fn dropping_an_obj_file_shows_it() {
    let dir = temp_dir("drop-obj");
    let good = dir.join("tri.obj");
    std::fs::write(&good, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let mut h = harness();
    h.input_mut().dropped_files.push(std::sync::Arc::new(common::Dropped(good.clone())));
    h.run_steps(2);
    assert_eq!(h.state().doc.view.obj.as_deref(), Some(good.to_str().unwrap()));
}

#[test]
fn view_options_open_with_a_click_and_keep_the_picture_on_screen() {
    let mut h = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h.get_by_label("View options").click();
    // The header opens over a few frames (egui animates it).
    h.run_steps(12);
    h.get_by_label("Renderer");
    h.get_by_label_contains("Mesh file");
    let picture = h.state().ui.geometry.pictures[0];
    assert!(picture.max.y <= 800.0 && picture.width() > 150.0, "{picture:?}");
    assert!(!h.state().heat_map.on, "the click opened the options, and nothing else");
}

#[test]
fn a_new_spotlight_aims_at_the_object_so_the_demo_stays_lit() {
    let mut h = harness();
    common::open_menu(&mut h, &["Scene"]);
    h.run_steps(2);
    h.get_by_label("Phong demo").click();
    h.run_steps(2);
    let before = h.state().doc.clone();
    h.get_by_role_and_label(Role::CheckBox, "Spotlight").click();
    h.run_steps(2);
    let l = &h.state().doc.scene.lights[0];
    assert_eq!(l.spot_cutoff, 30.0);
    let aim = phonglab::app::panels::controls::aim_at_object(&before, &before.scene.lights[0]).unwrap();
    assert!((l.spot_direction - aim).length() < 1e-12, "{:?} vs {aim:?}", l.spot_direction);
    // The light at (-4, 0, -8) in the demo's object space aims back at the origin.
    let want = DVec3::new(4.0, 0.0, 8.0).normalize();
    assert!((l.spot_direction - want).length() < 1e-9, "{:?}", l.spot_direction);
    // The worked vertex, on the object, is inside the cone: lit.
    let c = front_primary(h.state());
    assert!(c[0] > 0.05, "{c:?}");
}

#[test]
fn the_demos_switches_stay_where_they_are_when_one_is_clicked() {
    let mut h = harness();
    common::open_menu(&mut h, &["Scene"]);
    h.run_steps(2);
    h.get_by_label("Phong demo").click();
    h.run_steps(3);
    let at = |h: &Harness<'static, AppState>| -> Vec<egui::Rect> {
        phonglab_core::library::DemoDeparture::ALL
            .iter()
            .map(|d| h.get_by_role_and_label(Role::CheckBox, &d.fix_label()).rect())
            .collect()
    };
    let before = at(&h);
    for d in phonglab_core::library::DemoDeparture::ALL {
        h.get_by_role_and_label(Role::CheckBox, &d.fix_label()).click();
        h.run_steps(3);
        assert_eq!(at(&h), before, "after switching {:?} on", d.fix_label());
    }
    assert_eq!(h.state().view_options.demo_fixes, [true; 3]);
    assert_eq!(h.state().ui.geometry.pictures.len(), 2, "the corrected picture beside the demo's");
}

#[test]
fn a_decimal_comma_is_read_and_a_number_a_float_cannot_hold_is_not_truncated() {
    let mut h = harness();
    type_into(&mut h, "Material shininess", "12,5");
    assert_eq!(h.state().doc.scene.material.shininess, 12.5);
    // 1e-400 was silently 0 before: now it is not taken.
    type_into(&mut h, "Material shininess", "1e-400");
    assert_eq!(h.state().doc.scene.material.shininess, 12.5);
    type_into(&mut h, "Light z", "-40,25");
    assert_eq!(h.state().doc.scene.lights[0].position.z, -40.25);
}

/// Ctrl+C in a number field copies what is selected there: the window's clipboard works in
/// fields as in the Copy buttons (eframe's `clipboard` feature is what hands it to the
/// system; here, egui's output).
#[test]
fn ctrl_c_in_a_field_copies_its_text() {
    let mut h = harness();
    common::click_field(&mut h, "Light z");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run_steps(1);
    h.input_mut().events.push(egui::Event::Copy);
    h.step();
    assert_eq!(common::copied_text(&h), ["90"], "the field's text, selected whole, copied");
    // And the desktop hands egui's copies to the system's clipboard, and its links to the
    // browser: eframe is built with both (without them, Copy silently copied nothing).
    let manifest = include_str!("../../Cargo.toml");
    let eframe = manifest.lines().find(|l| l.starts_with("eframe = ")).unwrap();
    assert!(eframe.contains("\"clipboard\"") && eframe.contains("\"links\""), "{eframe}");
}

/// Ctrl+S and Ctrl+O right after typing a path, still in the field: they use the text
/// typed, keys and all (not what the field held before).
#[test]
fn ctrl_s_and_ctrl_o_use_the_path_just_typed() {
    let mut h = harness();
    let p = temp_dir("typed").join("typed.toml");
    common::open_menu(&mut h, &["File"]);
    let field = h.get_by_role_and_label(Role::TextInput, "Scene file:");
    field.click();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "Scene file:").type_text(&p.display().to_string());
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::S);
    h.run_steps(3);
    assert!(p.exists(), "saved at the path typed: {:?}", h.state().message);
    let spot = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    h.get_by_role_and_label(Role::TextInput, "Scene file:").click();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "Scene file:").type_text(&spot.display().to_string());
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::O);
    h.run_steps(3);
    assert_eq!(h.state().doc.name, "a spotlight", "{:?}", h.state().message);
}

/// Ctrl+S right after typing a number, still in its field: the file holds the number
/// typed (the field is committed first), not the value before.
#[test]
fn ctrl_s_right_after_typing_a_number_saves_the_number_typed() {
    let mut h = harness();
    let p = temp_dir("typed-number").join("n.toml");
    set_file_path(&mut h, &p);
    h.key_press(egui::Key::Escape);
    h.run_steps(1);
    common::click_field(&mut h, "Light z");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run_steps(1);
    h.get_by_role_and_label(Role::SpinButton, "Light z").type_text("300");
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::S);
    h.run_steps(4);
    assert_eq!(h.state().doc.scene.lights[0].position.z, 300.0, "{:?}", h.state().message);
    let saved = phonglab_core::Document::from_toml(&std::fs::read_to_string(&p).unwrap()).unwrap();
    assert_eq!(saved.scene.lights[0].position.z, 300.0, "the file holds the number typed");
}

/// Where no system dialog opens, Open…, Save as… and the Export menu's Save… open
/// phonglab's own chooser, which says why, lists the folder, and opens or saves the file
/// chosen: a click never does nothing.
#[test]
fn the_in_app_chooser_opens_saves_and_exports_where_no_dialog_opens() {
    let mut state = AppState::worksheet();
    state.files.dialogs = phonglab::app::panels::files::Dialogs::InApp;
    let scenes = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    state.files.path = scenes.join("worksheet-mview5.toml").display().to_string();
    let mut h =
        Harness::builder().with_size([1280.0, 720.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(2);
    common::menu_item(&mut h, &["File"], "Open…");
    h.get_by_label("Choose a file");
    assert!(h.get_all_by_label("Choose the file here.").count() >= 1, "it says why it is there");
    // The folder's scene files are listed, its subfolders first.
    let first = h.get_by_label("redbook-teapots/").rect();
    let spot = h.get_by_label("spotlight.toml").rect();
    assert!(first.max.y <= spot.min.y, "folders first: {first:?} {spot:?}");
    h.get_by_label("spotlight.toml").click();
    h.run_steps(1);
    let opens: Vec<egui::Rect> = h.get_all_by_label("Open").map(|n| n.rect()).collect();
    h.get_all_by_label("Open").last().unwrap().click();
    h.run_steps(2);
    assert_eq!(opens.len(), 1, "the chooser's (the File menu, with the row's, is closed)");
    assert_eq!(h.state().doc.name, "a spotlight", "{:?}", h.state().message);
    assert!(h.state().chooser.is_none());
    // Save as…: a new name in a temporary folder.
    let dir = temp_dir("chooser");
    common::menu_item(&mut h, &["File"], "Save as…");
    h.get_by_role_and_label(Role::TextInput, "Folder:").set_text_value_accesskit(&dir.display().to_string());
    h.get_by_role_and_label(Role::TextInput, "File name:").set_text_value_accesskit("mine.toml");
    h.run_steps(1);
    h.get_all_by_label("Save").last().unwrap().click();
    h.run_steps(2);
    let saved = std::fs::read_to_string(dir.join("mine.toml")).unwrap();
    assert_eq!(saved, h.state().doc.to_toml().unwrap());
    // Export → the PNG: the chooser again, offering the PNG's name.
    common::open_menu(&mut h, &["File", "Export"]);
    h.get_by_label_contains("Shaded view as PNG").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::TextInput, "Folder:").set_text_value_accesskit(&dir.display().to_string());
    h.run_steps(1);
    h.get_all_by_label("Save").last().unwrap().click();
    h.run_steps(2);
    let png = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(Result::ok)
        .find(|e| e.path().extension().is_some_and(|x| x == "png"));
    assert!(png.is_some(), "{:?}", h.state().message);
}

/// Moving the light draws the shaded view again by lighting the last picture's triangles
/// again (nothing drawn moved): the picture is the one a new renderer draws whole, and its
/// caption says it was only lit again. Turning the object draws it whole, and the caption
/// drops the remark.
#[test]
fn moving_the_light_only_lights_the_picture_again_and_says_so() {
    let mut h = sphere_harness();
    assert!(!h.state().shaded.main.last_relit, "the first picture is drawn whole");
    assert!(h.query_by_label_contains("lit again, nothing drawn moved").is_none());
    h.state_mut().doc.scene.lights[0].position.x += 0.75;
    h.run_steps(2);
    let state = h.state();
    assert!(state.shaded.main.last_relit);
    let px = state.shaded.main.image_px();
    let setup = state.doc.shaded_setup(state.settings.pow);
    let mesh = state.doc.view.mesh();
    let mut fresh = phonglab_core::render::Renderer::new();
    let whole = fresh.render(&setup.job(&mesh), px, px).unwrap().0.rgba.clone();
    let differ = whole.iter().zip(state.shaded.main.rgba()).filter(|(a, b)| a != b).count();
    assert_eq!((differ, whole.len()), (0, state.shaded.main.rgba().len()), "bytes that differ");
    let named = h.get_by_label_contains("lit again, nothing drawn moved: ");
    assert!(named.accesskit_node().role() == Role::Image && named.rect().width() > 300.0, "{:?}", named.rect());
    h.state_mut().doc.view.spin_degrees += 10.0;
    h.run_steps(2);
    assert!(!h.state().shaded.main.last_relit, "the object turned: drawn whole");
    h.get_by_label_contains("ms per frame on the CPU");
    assert!(h.query_by_label_contains("lit again, nothing drawn moved").is_none());
}

/// Turning the orbit camera by a drag on the picture of a mesh of more than
/// `COARSE_ABOVE` triangles (the sphere at 400 x 400: 319 200) draws it from its coarse
/// copy while the mouse is down, and the caption says so with both counts (and names the
/// picture); the frame after
/// the mouse is let go draws the whole mesh, exactly as a new renderer draws it. The same
/// while the object spins by itself (auto-rotate).
#[test]
fn turning_the_camera_over_a_large_mesh_draws_a_coarse_copy_until_let_go() {
    use phonglab::app::panels::shaded::cache::{COARSE_ABOVE, COARSE_TARGET};
    let mut state = AppState::worksheet();
    state.doc.view.object = phonglab_core::ObjectKind::Sphere;
    (state.doc.view.sphere_slices, state.doc.view.sphere_stacks) = (400, 400);
    let mut h =
        Harness::builder().with_size([1500.0, 1000.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(2);
    let whole = h.state().doc.view.mesh().triangle_count();
    assert!(whole > COARSE_ABOVE, "{whole}");
    assert_eq!(h.state().shaded.main.last_coarse, None, "at rest: the whole mesh");
    let picture = h.get_all_by_role(Role::Image).next().expect("the shaded view").rect();
    let (from, to) = (picture.center(), picture.center() + egui::vec2(90.0, 30.0));
    let yaw = h.state().doc.view.camera.yaw;
    common::press_and_move(&mut h, from, to);
    assert_ne!(h.state().doc.view.camera.yaw, yaw, "the drag turned the camera");
    let drawn = h.state().shaded.main.last_coarse.expect("drawn from the coarse copy while turning");
    let (coarse, all) = (drawn.triangles, drawn.of);
    assert_eq!((all, drawn.spinning), (whole, false));
    assert!(coarse <= COARSE_TARGET + COARSE_TARGET / 10 && coarse * 4 >= COARSE_TARGET * 3, "{coarse}");
    let (coarse_said, whole_said) =
        (phonglab_core::locale::grouped(coarse as u64), phonglab_core::locale::grouped(whole as u64));
    let said = format!("a copy of {coarse_said} of the {whole_said} triangles while the camera turns: ");
    // The caption names the picture (which is labelled by it), and the picture is where it was.
    let named = h.get_by_label_contains(&said);
    assert_eq!(named.accesskit_node().role(), Role::Image);
    assert!((named.rect().min - picture.min).length() < 1.0 && named.rect().width() > 300.0, "{:?}", named.rect());
    common::button(&mut h, to, false);
    h.run_steps(3);
    let state = h.state();
    assert_eq!(state.shaded.main.last_coarse, None, "let go: the whole mesh again");
    let px = state.shaded.main.image_px();
    let mesh = state.doc.view.mesh();
    let fresh = phonglab_core::render::Renderer::new()
        .render(&state.doc.shaded_setup(state.settings.pow).job(&mesh), px, px)
        .unwrap()
        .0
        .rgba
        .clone();
    let differ = fresh.iter().zip(state.shaded.main.rgba()).filter(|(a, b)| a != b).count();
    assert_eq!((differ, fresh.len()), (0, state.shaded.main.rgba().len()), "bytes that differ");
    assert!(h.query_by_label_contains("while the camera turns").is_none());
    // Spinning by itself (auto-rotate): the copy, said so, until the spin is turned off.
    h.state_mut().doc.view.auto_rotate = true;
    h.run_steps(2);
    let drawn = h.state().shaded.main.last_coarse.expect("drawn from the coarse copy while spinning");
    assert_eq!((drawn.triangles, drawn.spinning), (coarse, true));
    h.get_by_label_contains(&format!("a copy of {coarse_said} of the {whole_said} triangles while the object spins: "));
    h.state_mut().doc.view.auto_rotate = false;
    h.run_steps(2);
    assert_eq!(h.state().shaded.main.last_coarse, None, "the spin stopped: the whole mesh");
}
