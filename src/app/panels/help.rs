//! Keyboard shortcuts: one table for the handler and the help overlay.

use egui::{Key, Modifiers, Ui};

use crate::t;

/// What a shortcut does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Open or close this help.
    Help,
    /// Toggle the local viewer.
    LocalViewer,
    /// Next classic material.
    NextMaterial,
    /// Previous classic material.
    PreviousMaterial,
    /// Next worksheet modelview (mview1..5).
    NextModelview,
    /// Blinn-Phong <-> Phong.
    SpecularModel,
    /// Next rule set.
    NextRuleSet,
    /// Next normal mode.
    NextNormals,
    /// Two-sided lighting on/off.
    TwoSided,
    /// f32 <-> f64.
    Precision,
    /// Back to the worksheet.
    Reset,
    /// The shaded view's object.
    Object(phonglab_core::ObjectKind),
    /// The shaded view's shading.
    Shading(phonglab_core::Shading),
    /// Auto-rotation on/off.
    AutoRotate,
    /// Open the scene file at the typed path.
    Open,
    /// Save the scene to the typed path.
    Save,
    /// Close the window, saving the session.
    Quit,
    /// Undo the last change of the scene.
    Undo,
    /// Redo the last undone change.
    Redo,
}

/// (modifiers, key, shown as, action, the message id of its description).
pub const SHORTCUTS: &[(Modifiers, Key, &str, Action, &str)] = &[
    (Modifiers::NONE, Key::F1, "F1", Action::Help, "help-help"),
    (Modifiers::NONE, Key::Questionmark, "?", Action::Help, "help-help"),
    (Modifiers::NONE, Key::L, "L", Action::LocalViewer, "help-local-viewer"),
    (Modifiers::NONE, Key::M, "M", Action::NextMaterial, "help-next-material"),
    (Modifiers::SHIFT, Key::M, "Shift+M", Action::PreviousMaterial, "help-previous-material"),
    (Modifiers::NONE, Key::V, "V", Action::NextModelview, "help-next-modelview"),
    (Modifiers::NONE, Key::B, "B", Action::SpecularModel, "help-specular-model"),
    (Modifiers::NONE, Key::G, "G", Action::NextRuleSet, "help-next-rules"),
    (Modifiers::NONE, Key::N, "N", Action::NextNormals, "help-next-normals"),
    (Modifiers::NONE, Key::W, "W", Action::TwoSided, "help-two-sided"),
    (Modifiers::NONE, Key::P, "P", Action::Precision, "help-precision"),
    (Modifiers::CTRL, Key::R, "Ctrl+R", Action::Reset, "help-reset"),
    (Modifiers::CTRL, Key::O, "Ctrl+O", Action::Open, "help-open"),
    (Modifiers::CTRL, Key::S, "Ctrl+S", Action::Save, "help-save"),
    (Modifiers::CTRL, Key::Q, "Ctrl+Q", Action::Quit, "help-quit"),
    (Modifiers::CTRL, Key::Z, "Ctrl+Z", Action::Undo, "help-undo"),
    (Modifiers::CTRL.plus(Modifiers::SHIFT), Key::Z, "Ctrl+Shift+Z", Action::Redo, "help-redo"),
    (Modifiers::CTRL, Key::Y, "Ctrl+Y", Action::Redo, "help-redo"),
    (Modifiers::NONE, Key::S, "S", Action::Object(phonglab_core::ObjectKind::Sphere), "help-sphere"),
    (Modifiers::NONE, Key::T, "T", Action::Object(phonglab_core::ObjectKind::Teapot), "help-teapot"),
    (Modifiers::NONE, Key::C, "C", Action::Object(phonglab_core::ObjectKind::Cylinder), "help-cylinder"),
    (Modifiers::NONE, Key::Num1, "1", Action::Shading(phonglab_core::Shading::Gouraud), "help-gouraud"),
    (Modifiers::NONE, Key::Num2, "2", Action::Shading(phonglab_core::Shading::Phong), "help-phong"),
    (Modifiers::NONE, Key::Num3, "3", Action::Shading(phonglab_core::Shading::Flat), "help-flat"),
    (Modifiers::NONE, Key::A, "A", Action::AutoRotate, "help-auto-rotate"),
];

/// What asks for the keyboard before the scene does ([`pressed`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Asking {
    /// Nothing: every key works.
    Nothing,
    /// The quiz, where the student types numbers: no key without Ctrl works, so digits
    /// typed after a missed click change nothing.
    Numbers,
    /// A window that waits for a choice (phonglab's file chooser, the dropped notebook's
    /// question): only Quit and Help's F1 work. A name typed into the chooser whose field
    /// had lost the keyboard switched the rules, the normals and the two-sided lighting,
    /// one key each, and Ctrl+Z undid the scene behind it.
    Choice,
}

/// May `action` fire from its keys now? While a text field has the keyboard only what
/// works from everywhere does (Open, Save, Quit and Help's F1: Ctrl+Z is the field's own
/// undo); while something asks for the keyboard, what [`Asking`] says.
fn allowed(modifiers: Modifiers, key: Key, action: Action, typing: bool, asking: Asking) -> bool {
    let plain = !modifiers.ctrl && !modifiers.command && key != Key::F1;
    if asking == Asking::Choice {
        action == Action::Quit || key == Key::F1
    } else if typing {
        matches!(action, Action::Open | Action::Save | Action::Quit) || key == Key::F1
    } else {
        !(asking == Asking::Numbers && plain)
    }
}

/// The actions whose keys were pressed this frame: see `allowed` for which fire while a
/// text field has the keyboard, or while something asks for it (`asking`).
pub fn pressed(ctx: &egui::Context, asking: Asking) -> Vec<Action> {
    let typing = ctx.egui_wants_keyboard_input();
    ctx.input_mut(|i| {
        let mut out = Vec::new();
        // Most specific first, so Shift+M is not also taken as M.
        let mut ordered: Vec<_> = SHORTCUTS.iter().collect();
        ordered.sort_by_key(|(m, ..)| std::cmp::Reverse(m.shift as u8 + m.ctrl as u8 + m.command as u8));
        for (m, k, _, a, _) in ordered {
            if allowed(*m, *k, *a, typing, asking) && i.consume_key(*m, *k) && !out.contains(a) {
                out.push(*a);
            }
        }
        out
    })
}

/// The overlay's contents.
pub fn help_ui(ui: &mut Ui) {
    egui::Grid::new("shortcuts").striped(true).show(ui, |ui| {
        for (_, _, shown, _, what) in SHORTCUTS {
            ui.monospace(*shown);
            ui.label(crate::locale::tr(what));
            ui.end_row();
        }
        for (shown, what) in PRESENTATION_KEYS {
            ui.monospace(*shown);
            ui.label(crate::locale::tr(what));
            ui.end_row();
        }
    });
    ui.label(t!("help-things-to-try"));
    ui.separator();
    ui.label(t!("help-drop"));
    ui.label(t!("help-drag"));
    ui.label(t!("help-numbers"));
    ui.label(t!("help-undo-keys"));
    ui.separator();
    ui.strong(t!("help-demo-title"));
    for id in DEMO_CHOICES {
        ui.label(crate::locale::tr(id));
    }
}

/// The keys [`crate::app::shell::keys::presentation_keys`] and eframe's zoom read, shown
/// after [`SHORTCUTS`]: (the keys, the message id of what they do).
pub const PRESENTATION_KEYS: &[(&str, &str)] =
    &[("F5", "help-present"), ("← ↑  → ↓", "help-walk-steps"), ("Ctrl + / Ctrl − / Ctrl 0", "help-zoom")];

/// Where the Phong demo preset follows the demo's program rather than OpenGL (shown in the
/// help overlay; the scene file and the README say the same).
/// (Message ids.)
pub const DEMO_CHOICES: &[&str] = &["help-demo-space", "help-demo-normals", "help-demo-specular", "help-demo-pipeline"];
