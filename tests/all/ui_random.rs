//! A few hundred seeded random interactions with the whole window: sliders and number
//! fields set to values in range, out of range, huge, negative or NaN; buttons, checkboxes,
//! menus and radio buttons clicked; text typed; shortcuts pressed; drags on the plots and
//! the shaded view. After every step: no panic, the document valid, every displayed colour
//! finite, and a refused step leaves the scene as it was.

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::shell::state::{Message, Precision};
use phonglab::app::{AppState, app_ui};
use phonglab_core::Document;

/// xorshift64*: a small, seeded generator, so a failure replays exactly.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A value a user (or a cat on the keyboard) might enter.
fn wild_value(rng: &mut Rng) -> f64 {
    match rng.below(10) {
        0 => f64::NAN,
        1 => f64::INFINITY,
        2 => -1e300,
        3 => 1e-300,
        4 => -(rng.unit() * 500.0),
        5 => 0.0,
        _ => rng.unit() * 200.0 - 50.0,
    }
}

const TYPED: &[&str] = &["nan", "inf", "-1", "1e400", "abc", "0.5", "128", "-0", "", "1,5", "999999"];

const KEYS: &[egui::Key] = &[
    egui::Key::L,
    egui::Key::M,
    egui::Key::V,
    egui::Key::B,
    egui::Key::G,
    egui::Key::N,
    egui::Key::W,
    egui::Key::P,
    egui::Key::S,
    egui::Key::T,
    egui::Key::C,
    egui::Key::Num1,
    egui::Key::Num2,
    egui::Key::Num3,
    egui::Key::A,
    egui::Key::F1,
    egui::Key::Escape,
    egui::Key::Enter,
    egui::Key::Tab,
];

/// The document without the auto-rotation's spin (which moves every frame by itself).
fn without_spin(d: &Document) -> Document {
    let mut d = d.clone();
    d.view.spin_degrees = 0.0;
    d
}

fn colours(e: &phonglab::app::shell::state::Evaluated) -> Vec<[f64; 4]> {
    let mut v = vec![e.front.primary, e.front.secondary, e.front.shown];
    if let Some(b) = e.back {
        v.extend([b.primary, b.secondary, b.shown]);
    }
    v
}

/// Never NaN; the shown colour in [0, 1]; f64 finite; f32 infinite only where the f64
/// value is near or beyond f32's range (a term or a sum that overflows a float, as in
/// OpenGL: terms of 1e38 can overflow before they cancel).
fn check(h: &Harness<'static, AppState>, step: usize, what: &str) {
    let s = h.state();
    assert!(s.doc.validate().is_ok(), "step {step} ({what}): invalid document kept: {:?}", s.doc.validate());
    let e = s.evaluate().unwrap_or_else(|e| panic!("step {step} ({what}): {e}"));
    assert!(!e.explanation.steps.is_empty(), "step {step} ({what}): an explanation");
    let mut s64 = AppState { doc: s.doc.clone(), ..AppState::default() };
    s64.settings.precision = Precision::F64;
    s64.settings.pow = s.settings.pow;
    let e64 = s64.evaluate().unwrap();
    for (c, c64) in colours(&e).into_iter().zip(colours(&e64)) {
        for k in 0..4 {
            assert!(!c[k].is_nan(), "step {step} ({what}): NaN in {c:?}");
            assert!(c64[k].is_finite(), "step {step} ({what}): f64 {c64:?}\n{}", s.doc.to_toml().unwrap());
            assert!(
                c[k].is_finite() || c64[k].abs() > 1e30 && c[k].signum() == c64[k].signum(),
                "step {step} ({what}): {c:?} where f64 gives {c64:?}"
            );
        }
    }
    for c in &e.front.shown[..3] {
        assert!((0.0..=1.0).contains(c), "step {step} ({what}): shown colour {c} outside [0, 1]");
    }
}

/// The controls open again, out of presentation, Compare, the quiz and the shader.
fn bring_the_controls_back(h: &mut Harness<'_, AppState>) {
    let s = h.state_mut();
    s.ui.layout.presenting = false;
    s.ui.layout.controls_open = true;
    s.compare.open = false;
    s.quiz.open = false;
    s.shader.open = false;
    h.run_steps(1);
}

/// One random action a user could take, described; `None` where there was nothing to act on.
fn act(h: &mut Harness<'_, AppState>, rng: &mut Rng) -> Option<String> {
    match rng.below(6) {
        0 | 1 => set_a_value(h, rng),
        2 => click_something(h, rng),
        3 => type_into_a_field(h, rng),
        4 => {
            let k = KEYS[rng.below(KEYS.len())];
            h.key_press(k);
            Some(format!("press {k:?}"))
        }
        _ => Some(drag_somewhere(h, rng)),
    }
}

/// A slider or a number field set to a wild value.
fn set_a_value(h: &Harness<'_, AppState>, rng: &mut Rng) -> Option<String> {
    let nodes: Vec<_> = h.query_all_by_role(Role::Slider).chain(h.query_all_by_role(Role::SpinButton)).collect();
    if nodes.is_empty() {
        return None;
    }
    let n = &nodes[rng.below(nodes.len())];
    let v = wild_value(rng);
    let label = n.accesskit_node().label().unwrap_or_default();
    n.set_value_accesskit(v);
    Some(format!("set {label:?} to {v}"))
}

/// A button, check box, radio button or combo box clicked (by the pointer or by
/// AccessKit).
fn click_something(h: &Harness<'_, AppState>, rng: &mut Rng) -> Option<String> {
    let nodes: Vec<_> = h
        .query_all_by_role(Role::Button)
        .chain(h.query_all_by_role(Role::CheckBox))
        .chain(h.query_all_by_role(Role::RadioButton))
        .chain(h.query_all_by_role(Role::ComboBox))
        // Not the Export menu: it writes files (and here, with no file dialog,
        // only says it cannot), and changes no scene.
        .filter(|n| n.accesskit_node().label().is_none_or(|l| l != "Export"))
        .collect();
    if nodes.is_empty() {
        return None;
    }
    let n = &nodes[rng.below(nodes.len())];
    let label = n.accesskit_node().label().unwrap_or_default();
    if rng.below(2) == 0 {
        n.click();
    } else {
        n.click_accesskit();
    }
    Some(format!("click {label:?}"))
}

/// Text typed into a scene's field.
fn type_into_a_field(h: &Harness<'_, AppState>, rng: &mut Rng) -> Option<String> {
    let nodes: Vec<_> = h
        .query_all_by_role(Role::TextInput)
        .chain(h.query_all_by_role(Role::SpinButton))
        // Scene fields: not the file paths, nor the quiz's answer fields (which
        // hold any text and refuse nothing), nor the Export menu's exercise
        // settings, so typed bad values meet the validator.
        .filter(|n| {
            n.accesskit_node().label().is_none_or(|l| {
                !l.contains("Scene file")
                    && !l.contains("Mesh file")
                    && !l.ends_with(" =")
                    && !["Seed", "Exercises", "Level"].contains(&l.as_str())
            })
        })
        .collect();
    if nodes.is_empty() {
        return None;
    }
    let n = &nodes[rng.below(nodes.len())];
    let text = TYPED[rng.below(TYPED.len())];
    let label = n.accesskit_node().label().unwrap_or_default();
    n.click();
    n.type_text(text);
    Some(format!("type {text:?} into {label:?}"))
}

/// A drag from a random point by up to 100 points each way.
fn drag_somewhere(h: &mut Harness<'_, AppState>, rng: &mut Rng) -> String {
    let (x, y) = (rng.unit() as f32 * 1500.0, rng.unit() as f32 * 1000.0);
    let d = egui::vec2(rng.unit() as f32 * 200.0 - 100.0, rng.unit() as f32 * 200.0 - 100.0);
    h.drag_at(egui::pos2(x, y));
    h.run_steps(1);
    h.hover_at(egui::pos2(x, y) + d);
    h.run_steps(1);
    h.drop_at(egui::pos2(x, y) + d);
    format!("drag from ({x:.0}, {y:.0}) by {d:?}")
}

fn run(seed: u64, steps: usize) {
    let dir = std::env::temp_dir().join(format!("phonglab-ui-random-{seed}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut state = AppState::worksheet();
    // Save and Open use a file of their own.
    state.files.path = dir.join("random.toml").display().to_string();
    let mut h =
        Harness::builder().with_size([1500.0, 1000.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(2);
    let mut rng = Rng(seed);
    let (mut refusals, mut changes) = (0, 0);
    for step in 0..steps {
        // The walk can put the controls away (the Controls toggle, F5, Compare, Quiz): now and
        // then it brings them back, as a user would, so typed values keep reaching the
        // validator.
        if rng.below(4) == 0 {
            bring_the_controls_back(&mut h);
        }
        let before = without_spin(&h.state().doc);
        let message_before = h.state().message.clone();
        // A number field refuses what is not a number itself, beside the field.
        let fields_refusing = h.query_all_by_label_contains("(Esc: back to").count();
        let Some(what) = act(&mut h, &mut rng) else { continue };
        h.run_steps(2);
        check(&h, step, &what);
        changes += usize::from(without_spin(&h.state().doc) != before);
        if let Some(Message::Refused(m)) = &h.state().message
            && h.state().message != message_before
            && m.contains("Refused")
        {
            refusals += 1;
            // The refused value leaves the scene as it was (what the message says); the same
            // step's click may still have changed the view (a field's refusal arrives when
            // a click elsewhere takes its focus).
            assert_eq!(
                without_spin(&h.state().doc).scene,
                before.scene,
                "step {step} ({what}): refused ({m}) but changed"
            );
        } else if h.query_all_by_label_contains("(Esc: back to").count() > fields_refusing {
            refusals += 1;
        }
    }
    // The walk did meet bad values (and refused them), or it tested little.
    eprintln!("seed {seed:#x}: {steps} steps, {changes} changed the scene, {refusals} refused");
    assert!(refusals >= 5, "seed {seed}: {refusals} refusals in {steps} steps");
    // A typed value is taken when its field is left (by the next step's click or key), so
    // a walk changes the scene a little less often than one step in five.
    assert!(changes >= steps / 6, "seed {seed}: {changes} changes in {steps} steps");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn three_hundred_random_interactions_seed_1() {
    run(0x9E37_79B9_7F4A_7C15, 300);
}

#[test]
fn three_hundred_random_interactions_seed_2() {
    run(0xD1B5_4A32_D192_ED03, 300);
}
