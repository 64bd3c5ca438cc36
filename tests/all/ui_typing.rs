//! Numbers typed as students type them, undo, and the keys: the window driven headless with
//! egui_kittest, typing, clicking and reading back as a student does.

use crate::common;

use common::click_field;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::shell::state::Message;
use phonglab::app::{AppState, app_ui};

fn harness() -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([1500.0, 1000.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h
}

/// Types `text` one key at a time into the field named `label`, then presses `leave`.
fn type_keys(h: &mut Harness<'static, AppState>, label: &str, text: &str, leave: egui::Key) {
    click_field(h, label);
    for c in text.chars() {
        h.get_by_role_and_label(Role::SpinButton, label).type_text(&c.to_string());
        h.run_steps(1);
    }
    h.key_press(leave);
    h.run_steps(2);
}

fn field_text(h: &Harness<'static, AppState>, label: &str) -> String {
    h.get_by_role_and_label(Role::SpinButton, label).value().unwrap_or_default()
}

#[test]
fn a_field_shows_six_digits_at_rest_and_the_exact_value_while_edited() {
    let mut h = harness();
    let mut d = h.state().doc.clone();
    d.scene.vertex.normal = glam::DVec3::new(0.0, 0.4472135954999579, 0.8944271909999159);
    assert!(h.state_mut().apply(d));
    h.run_steps(2);
    assert_eq!(field_text(&h, "Normal y"), "0.447214");
    let rest = h.get_by_role_and_label(Role::SpinButton, "Normal y").rect();
    assert!(rest.width() < 80.0, "the field stays narrow: {rest:?}");
    click_field(&mut h, "Normal y");
    h.run_steps(1);
    assert_eq!(field_text(&h, "Normal y"), "0.4472135954999579", "the exact value while it has focus");
    // Left without a change, the value is kept exactly (not rounded to what was shown).
    h.key_press(egui::Key::Tab);
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.vertex.normal.y, 0.4472135954999579);
}

#[test]
fn typing_commits_only_when_the_field_is_left() {
    let mut h = harness();
    click_field(&mut h, "Material shininess");
    let before = h.state().doc.scene.material.shininess;
    for (i, c) in "1e400".chars().enumerate() {
        h.get_by_role_and_label(Role::SpinButton, "Material shininess").type_text(&c.to_string());
        h.run_steps(1);
        assert_eq!(h.state().doc.scene.material.shininess, before, "after {} keys nothing is committed", i + 1);
    }
    assert_eq!(field_text(&h, "Material shininess"), "1e400", "no key was lost");
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
    // Refused: the text stays, in red, with the reason beside it; the scene is unchanged.
    assert_eq!(h.state().doc.scene.material.shininess, before);
    assert_eq!(field_text(&h, "Material shininess"), "1e400");
    h.get_by_label_contains("1e400 is beyond single precision's range (±3.4e38) (Esc: back to 25.6)");
    // Corrected: the red goes and the value is taken.
    type_keys(&mut h, "Material shininess", "64", egui::Key::Tab);
    assert_eq!(h.state().doc.scene.material.shininess, 64.0);
    assert!(h.query_by_label_contains("beyond single precision").is_none());
}

#[test]
fn every_refusal_is_said_and_nothing_is_truncated() {
    let mut h = harness();
    let before = h.state().doc.clone();
    for (typed, reason) in [
        ("abc", "\"abc\" is not a number"),
        ("NaN", "NaN is not a finite number"),
        ("1e-400", "1e-400 is too small for single precision: it would be 0"),
        ("-5", "material.shininess = -5 is out of range: allowed [0, 128]"),
        ("51,002.5", "2 numbers: type one"),
    ] {
        type_keys(&mut h, "Material shininess", typed, egui::Key::Enter);
        assert_eq!(h.state().doc, before, "{typed} changes nothing");
        assert_eq!(field_text(&h, "Material shininess"), typed, "{typed} stays in the field");
        assert!(h.get_all_by_label_contains(reason).count() >= 1, "{typed}: {reason}");
        h.get_by_label_contains("(Esc: back to 25.6)");
        // Esc puts the value back.
        click_field(&mut h, "Material shininess");
        h.key_press(egui::Key::Escape);
        h.run_steps(2);
        assert_eq!(field_text(&h, "Material shininess"), "25.6", "after {typed} and Esc");
    }
}

#[test]
fn a_decimal_comma_and_a_whole_vector_are_read() {
    let mut h = harness();
    type_keys(&mut h, "Material shininess", "12,5", egui::Key::Enter);
    assert_eq!(h.state().doc.scene.material.shininess, 12.5);
    type_keys(&mut h, "Linear attenuation", "1,5e-3", egui::Key::Tab);
    assert_eq!(h.state().doc.scene.lights[0].attenuation[1], 0.0015);
    // A whole colour typed into its first field, the Portuguese way and the code's way.
    type_keys(&mut h, "Material ambient r", "0,5; 0,3; 0,1", egui::Key::Enter);
    assert_eq!(h.state().doc.scene.material.ambient.truncate(), glam::DVec3::new(0.5, 0.3, 0.1));
    type_keys(&mut h, "Material ambient g", "0.25, 0.2, 0.15", egui::Key::Enter);
    assert_eq!(h.state().doc.scene.material.ambient.truncate(), glam::DVec3::new(0.25, 0.2, 0.15));
    // Two numbers for a row of three: refused, saying what to type.
    type_keys(&mut h, "Material ambient b", "0,5; 0,3", egui::Key::Enter);
    h.get_by_label_contains("2 numbers: type one, or all 3 of the row");
    assert_eq!(h.state().doc.scene.material.ambient.z, 0.15);
    // A whole number field refuses a fraction.
    h.get_by_label("View options").click();
    h.run_steps(3);
    type_keys(&mut h, "Teapot grid", "4,5", egui::Key::Enter);
    h.get_by_label_contains("4,5 is not a whole number");
}

#[test]
fn ctrl_z_undoes_and_the_buttons_say_what() {
    let mut h = harness();
    type_keys(&mut h, "Material shininess", "100", egui::Key::Enter);
    h.key_press(egui::Key::L); // the local viewer on
    h.run_steps(2);
    assert!(h.state().doc.scene.light_model.local_viewer);
    assert_eq!(h.state().history.undo_label().as_deref(), Some("Local viewer off ➡ on"));
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
    h.run_steps(2);
    assert!(!h.state().doc.scene.light_model.local_viewer);
    assert_eq!(h.state().history.undo_label().as_deref(), Some("Material shininess 25.6 ➡ 100"));
    // The Undo button (in the File menu) says what it undoes.
    common::open_menu(&mut h, &["File"]);
    h.get_by_label("⟲ Undo").hover();
    // Tooltips wait a moment before they show.
    h.run_steps(60);
    h.get_by_label("Undo: Material shininess 25.6 ➡ 100 (Ctrl+Z)");
    h.get_by_label("⟲ Undo").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.material.shininess, 25.6);
    assert_eq!(h.state().message, Some(Message::Info("Undid: Material shininess 25.6 ➡ 100.".into())));
    // Redo: Ctrl+Shift+Z and Ctrl+Y.
    h.key_press_modifiers(egui::Modifiers::CTRL | egui::Modifiers::SHIFT, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.material.shininess, 100.0);
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Y);
    h.run_steps(2);
    assert!(h.state().doc.scene.light_model.local_viewer);
}

/// Undo says what it undid in the window's language: a light removed is "luz 0 removida",
/// not the fields of light 0 that the list's closing up changed ("light 0 ambient and 9
/// more").
#[test]
fn undo_says_what_was_undone_in_the_users_language() {
    let mut h = harness();
    h.state_mut().ui.layout.language = Some("pt-PT".into());
    h.run_steps(2);
    h.get_by_label("Juntar luz").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.lights.len(), 2);
    let mut d = h.state().doc.clone();
    d.scene.lights[1].position.x = -50.0;
    assert!(h.state_mut().apply(d));
    h.run_steps(1);
    assert_eq!(h.state().history.undo_label().as_deref(), Some("luz 1: posição [1 1 1 0] ➡ [-50 1 1 0]"));
    // Light 0 removed: light 1 moves into its place, and every field of light 0 differs.
    h.get_by_label("Luz 0").click();
    h.run_steps(2);
    h.get_by_label("Remover luz").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.lights.len(), 1);
    assert_eq!(h.state().history.undo_label().as_deref(), Some("luz 0 removida"));
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().doc.scene.lights.len(), 2);
    assert_eq!(h.state().message, Some(Message::Info("Desfeito: luz 0 removida.".into())));
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Y);
    h.run_steps(2);
    assert_eq!(h.state().message, Some(Message::Info("Refeito: luz 0 removida.".into())));
    // In Brazilian Portuguese, the same step in its words.
    h.state_mut().ui.layout.language = Some("pt-BR".into());
    h.run_steps(2);
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
    h.run_steps(2);
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().message, Some(Message::Info("Desfeito: luz 1: posição [1 1 1 0] ➡ [-50 1 1 0].".into())));
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().message, Some(Message::Info("Desfeito: luz 1 adicionada.".into())));
}

#[test]
fn a_hundred_typed_changes_are_undone_one_by_one() {
    let mut h = harness();
    for i in 0..100 {
        let mut d = h.state().doc.clone();
        d.scene.material.shininess = f64::from(i);
        h.state_mut().now += 2.0;
        assert!(h.state_mut().apply(d));
    }
    for i in (0..100).rev() {
        assert_eq!(h.state().doc.scene.material.shininess, f64::from(i));
        h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Z);
        h.run_steps(1);
    }
    assert_eq!(h.state().doc.scene.material.shininess, 25.6);
}

#[test]
fn ctrl_s_saves_from_the_path_field_and_letters_there_are_text() {
    let mut h = harness();
    let dir = std::env::temp_dir().join(format!("phonglab-typing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("from-the-field.toml");
    let _ = std::fs::remove_file(&path);
    common::open_menu(&mut h, &["File"]);
    let field = h.get_by_role_and_label(Role::TextInput, "Scene file:");
    field.click();
    h.run_steps(1);
    let typed = path.display().to_string();
    let (start, last) = typed.split_at(typed.len() - 1);
    h.get_by_role_and_label(Role::TextInput, "Scene file:").set_text_value_accesskit(start);
    h.run_steps(1);
    // The last letter typed in the field is text, not a shortcut (L is the local viewer).
    assert_eq!(last, "l");
    h.get_by_role_and_label(Role::TextInput, "Scene file:").type_text(last);
    h.run_steps(1);
    assert!(!h.state().doc.scene.light_model.local_viewer);
    assert_eq!(h.state().files.path, typed);
    assert!(h.get_by_role_and_label(Role::TextInput, "Scene file:").is_focused());
    h.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::S);
    h.run_steps(2);
    assert!(path.exists(), "Ctrl+S saved with the field focused: {:?}", h.state().message);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn in_the_quiz_digits_and_letters_fire_no_shortcut() {
    let mut h = harness();
    common::menu_item(&mut h, &["View"], "Quiz");
    h.run_steps(3);
    let shading = h.state().doc.view.shading;
    let viewer = h.state().doc.scene.light_model.local_viewer;
    // Digits typed after a click that missed every field.
    for k in [egui::Key::Num2, egui::Key::Num3, egui::Key::L, egui::Key::M] {
        h.key_press(k);
        h.run_steps(1);
    }
    assert_eq!(h.state().doc.view.shading, shading);
    assert_eq!(h.state().doc.scene.light_model.local_viewer, viewer);
    // Ctrl shortcuts and F1 still work.
    h.key_press(egui::Key::F1);
    h.run_steps(1);
    assert!(h.state().ui.show_help);
}

/// Types `text` into the quiz's field for step `name` and presses Enter.
fn answer(h: &mut Harness<'static, AppState>, name: &str, text: &str) {
    let label = format!("{name} =");
    h.get_by_role_and_label(Role::TextInput, &label).scroll_to_me();
    h.run_steps(30);
    h.get_by_role_and_label(Role::TextInput, &label).click();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, &label).type_text(text);
    h.run_steps(1);
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
}

fn quiz_harness() -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([1440.0, 1400.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h
}

#[test]
fn the_quiz_hides_the_answers_unless_the_teacher_shows_them() {
    let mut h = quiz_harness();
    let labels = |h: &Harness<'static, AppState>| h.state().ui.geometry.plot.as_ref().unwrap().labels.len();
    let colour = "[0.059587089  0.035759287  0.015155245  1]";
    assert_eq!(h.get_all_by_label(colour).count(), 2);
    let with_angles = labels(&h);
    common::menu_item(&mut h, &["View"], "Quiz");
    h.run_steps(3);
    assert!(h.query_by_label(colour).is_none(), "the vertex colour (I) is hidden");
    h.get_by_label_contains("Hidden while the quiz is open");
    assert_eq!(labels(&h), with_angles - 2, "the plot's θ and β are hidden");
    assert!(h.query_by_label_contains("vlv = [0.79220526").is_none(), "the calculation's values are hidden");
    h.get_by_label("Show the answers (teacher)").click();
    h.run_steps(3);
    assert_eq!(h.get_all_by_label(colour).count(), 2);
    assert_eq!(labels(&h), with_angles);
    h.get_by_label("key: vlv = [0.79220526 0.55887606 -0.2450885 0]");
}

#[test]
fn the_quiz_marks_say_which_check_they_passed_and_no_field_moves() {
    let mut h = quiz_harness();
    common::menu_item(&mut h, &["View"], "Quiz");
    h.run_steps(3);
    // The tolerance, in readable type.
    h.get_by_label_contains("Right: within 0.01\u{a0}% of the value (or 1e-6 near 0)");
    // Steps that do not apply to one light with no spotlight, under the worksheet's rules.
    for name in ["spot =", "Ilight =", "glColor ="] {
        assert!(h.query_by_label(name).is_none(), "{name} is asked");
    }
    let field = |h: &Harness<'static, AppState>, name: &str| {
        h.get_by_role_and_label(Role::TextInput, &format!("{name} =")).rect()
    };
    let before: Vec<egui::Rect> = ["vlv", "cosTheta", "Idif", "cosBeta", "I"].iter().map(|n| field(&h, n)).collect();

    answer(&mut h, "vertexNormal", "[0 0,6 0,8 0]");
    h.get_by_label("✔ right");
    // A wrong L (twice the unit vector): the formula and what it takes, never the key's
    // value (the key stays hidden until the student asks for it).
    answer(&mut h, "vlv", "1.5844105 1.1177521 -0.490177 0");
    let wrong = h.get_by_label_contains("✖ wrong: vlv = normalize(lightPos − vertexPos), with");
    let wrong = wrong.accesskit_node().label().unwrap_or_default();
    assert!(!wrong.contains("0.79220526") && !wrong.contains('…'), "{wrong}");
    // cos(theta) from that L: right, given the student's vlv; the key's value is not said.
    // N · L = 0.6 · 1.1177521 + 0.8 · -0.490177 = 0.27851
    answer(&mut h, "cosTheta", "0,2785096");
    h.get_by_label("✔ right, given your vlv");
    // The worksheet's own Idif is right (a value equal to the key is never wrong).
    answer(&mut h, "Idif", "[0.09942795 0.05965677 0.0252664 0.]");
    assert_eq!(h.get_all_by_label("✔ right").count(), 2);
    // Rounded too far: close, with the digits it needs.
    answer(&mut h, "cosBeta", "0.764");
    h.get_by_label("≈ close: 0.05\u{a0}% from the key; give 4 significant digits");
    h.get_by_label_contains("Score: 3 of 14 (5 answered)");
    assert!(h.query_by_label_contains("key: ").is_none(), "no key shown");
    // No field moved while the marks appeared (relative to the list, which the student
    // scrolled to reach each field).
    let after: Vec<egui::Rect> = ["vlv", "cosTheta", "Idif", "cosBeta", "I"].iter().map(|n| field(&h, n)).collect();
    let offsets = |r: &[egui::Rect]| r.iter().map(|x| x.min - r[0].min).collect::<Vec<_>>();
    assert_eq!(offsets(&before), offsets(&after));
    // Every "Show the answer" button is one size, and wide enough for its words.
    let reveals: Vec<egui::Rect> = h.get_all_by_label("Show the answer").map(|n| n.rect()).collect();
    assert_eq!(reveals.len(), 14);
    assert!(reveals.iter().all(|r| r.size() == reveals[0].size() && r.width() >= 50.0), "{reveals:?}");
    // The four buttons at the top are one size too.
    let tops: Vec<egui::Vec2> = ["Quiz this scene", "New exercise", "Show all the answers", "Clear answers"]
        .iter()
        .map(|l| h.get_by_label(l).rect().size())
        .collect();
    assert!(tops.iter().all(|s| *s == tops[0]), "{tops:?}");
    // Not a number: said so, not counted.
    answer(&mut h, "d", "six hundred");
    h.get_by_label_contains("does not read as numbers");
    h.get_by_label_contains("(5 answered)");
    // Showing an answer shows the key's value and counts it: it no longer scores as right.
    let vlv = field(&h, "vlv");
    let row = |n: &egui_kittest::Node<'_>| (n.rect().center().y - vlv.center().y).abs() < 4.0;
    h.get_all_by_label("Show the answer").find(row).unwrap().click();
    h.run_steps(2);
    h.get_by_label("key: vlv = [0.79220526 0.55887606 -0.2450885 0]");
    h.get_by_label_contains("(5 answered, 1 answer shown)");
    h.get_by_label("Clear answers").click();
    h.run_steps(2);
    h.get_by_label_contains("(0 answered)");
}

#[test]
fn presenting_in_portuguese_no_reveal_button_is_clipped_and_no_row_grows() {
    let mut state = AppState::worksheet();
    state.ui.layout.presenting = true;
    state.ui.layout.language = Some("pt-BR".into());
    let mut h =
        Harness::builder().with_size([1920.0, 1080.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(2);
    common::menu_item(&mut h, &["Exibir"], "Teste");
    h.run_steps(4);
    let reveals: Vec<egui::Rect> = h.get_all_by_label("Mostrar a resposta").map(|n| n.rect()).collect();
    assert!(reveals.len() >= 4, "{reveals:?}");
    let fields: Vec<egui::Rect> =
        h.query_all_by_role(Role::TextInput).filter(|n| n.rect().min.x > 1000.0).map(|n| n.rect()).collect();
    for r in &reveals {
        assert!(r.max.x <= 1920.0 && r.size() == reveals[0].size(), "{r:?} against {:?}", reveals[0]);
    }
    // Every answer field one width, its Reveal beside it.
    assert!(fields.iter().all(|f| (f.width() - fields[0].width()).abs() < 0.5), "{fields:?}");
}

#[test]
fn a_slow_drag_still_moves_a_large_value() {
    let mut h = harness();
    let mut d = h.state().doc.clone();
    d.scene.vertex.position.x = 123456.0;
    assert!(h.state_mut().apply(d));
    h.run_steps(2);
    h.get_by_role_and_label(Role::SpinButton, "Vertex x").scroll_to_me();
    h.run_steps(30);
    let at = h.get_by_role_and_label(Role::SpinButton, "Vertex x").rect().center();
    // Ten moves of 0.3 points: each less than the last digit shown (1), together 3.
    h.drag_at(at);
    h.run_steps(1);
    for k in 1..=10 {
        h.hover_at(at + egui::vec2(0.3 * k as f32, 0.0));
        h.run_steps(1);
    }
    h.drop_at(at + egui::vec2(3.0, 0.0));
    h.run_steps(1);
    let x = h.state().doc.scene.vertex.position.x;
    assert!((x - 123459.0).abs() <= 1.0, "{x}");
}
