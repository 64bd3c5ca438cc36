//! Keyboard shortcuts: one table for the handler and the help overlay.

use egui::{Key, Modifiers, Ui};

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

/// (modifiers, key, shown as, action, description).
pub const SHORTCUTS: &[(Modifiers, Key, &str, Action, &str)] = &[
    (Modifiers::NONE, Key::F1, "F1", Action::Help, "show or hide this help"),
    (Modifiers::NONE, Key::Questionmark, "?", Action::Help, "show or hide this help"),
    (Modifiers::NONE, Key::L, "L", Action::LocalViewer, "toggle the local viewer"),
    (Modifiers::NONE, Key::M, "M", Action::NextMaterial, "next classic material"),
    (Modifiers::SHIFT, Key::M, "Shift+M", Action::PreviousMaterial, "previous classic material"),
    (Modifiers::NONE, Key::V, "V", Action::NextModelview, "next worksheet modelview (mview1..5)"),
    (Modifiers::NONE, Key::B, "B", Action::SpecularModel, "Blinn-Phong / Phong specular"),
    (Modifiers::NONE, Key::G, "G", Action::NextRuleSet, "next rule set (OpenGL, worksheet, Phong demo)"),
    (Modifiers::NONE, Key::N, "N", Action::NextNormals, "next normal mode (as is, normalize, rescale)"),
    (Modifiers::NONE, Key::W, "W", Action::TwoSided, "two-sided lighting on/off"),
    (Modifiers::NONE, Key::P, "P", Action::Precision, "f32 / f64 evaluation"),
    (Modifiers::CTRL, Key::R, "Ctrl+R", Action::Reset, "reset to the worksheet"),
    (Modifiers::CTRL, Key::O, "Ctrl+O", Action::Open, "open the scene file at the typed path"),
    (Modifiers::CTRL, Key::S, "Ctrl+S", Action::Save, "save the scene to the typed path"),
    (Modifiers::CTRL, Key::Q, "Ctrl+Q", Action::Quit, "quit (the session is saved)"),
    (Modifiers::CTRL, Key::Z, "Ctrl+Z", Action::Undo, "undo the last change of the scene"),
    (Modifiers::CTRL.plus(Modifiers::SHIFT), Key::Z, "Ctrl+Shift+Z", Action::Redo, "redo"),
    (Modifiers::CTRL, Key::Y, "Ctrl+Y", Action::Redo, "redo"),
    (
        Modifiers::NONE,
        Key::S,
        "S",
        Action::Object(phonglab_core::ObjectKind::Sphere),
        "shaded view: sphere (as the demo)",
    ),
    (Modifiers::NONE, Key::T, "T", Action::Object(phonglab_core::ObjectKind::Teapot), "shaded view: teapot"),
    (Modifiers::NONE, Key::C, "C", Action::Object(phonglab_core::ObjectKind::Cylinder), "shaded view: cylinder"),
    (
        Modifiers::NONE,
        Key::Num1,
        "1",
        Action::Shading(phonglab_core::Shading::Gouraud),
        "Gouraud shading (as the demo)",
    ),
    (Modifiers::NONE, Key::Num2, "2", Action::Shading(phonglab_core::Shading::Phong), "Phong shading"),
    (Modifiers::NONE, Key::Num3, "3", Action::Shading(phonglab_core::Shading::Flat), "Flat shading"),
    (Modifiers::NONE, Key::A, "A", Action::AutoRotate, "auto-rotate the shaded view"),
];

/// May `action` fire from its keys now? While a text field has the keyboard only what
/// works from everywhere does (Open, Save, Quit and Help's F1: Ctrl+Z is the field's own
/// undo); in the quiz, where the student types numbers, no key without Ctrl does, so digits
/// typed after a missed click change nothing.
fn allowed(modifiers: Modifiers, key: Key, action: Action, typing: bool, quiz: bool) -> bool {
    let plain = !modifiers.ctrl && !modifiers.command && key != Key::F1;
    if typing {
        matches!(action, Action::Open | Action::Save | Action::Quit) || key == Key::F1
    } else {
        !(quiz && plain)
    }
}

/// The actions whose keys were pressed this frame: see [`allowed`] for which fire while a
/// text field has the keyboard, or while the quiz (`quiz`) is open.
pub fn pressed(ctx: &egui::Context, quiz: bool) -> Vec<Action> {
    let typing = ctx.egui_wants_keyboard_input();
    ctx.input_mut(|i| {
        let mut out = Vec::new();
        // Most specific first, so Shift+M is not also taken as M.
        let mut ordered: Vec<_> = SHORTCUTS.iter().collect();
        ordered.sort_by_key(|(m, ..)| std::cmp::Reverse(m.shift as u8 + m.ctrl as u8 + m.command as u8));
        for (m, k, _, a, _) in ordered {
            if allowed(*m, *k, *a, typing, quiz) && i.consume_key(*m, *k) && !out.contains(a) {
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
            ui.label(*what);
            ui.end_row();
        }
    });
    ui.separator();
    ui.label("Drop a scene file (.toml) on the window to open it.");
    ui.label("Drag the vector plot or the shaded view to orbit it; scroll the shaded view to zoom; click its surface to explain that vertex.");
    ui.label("A number field takes a decimal point or comma, and reads what was typed when it is left (Enter, Tab, a click elsewhere); a refused value stays in red with its reason until it is corrected or Esc puts the value back.");
    ui.label("Ctrl+Z undoes any change of the scene. Keys without Ctrl do nothing while a text field has the keyboard, nor in the quiz.");
    ui.separator();
    ui.strong("The Phong demo preset: the demo's choices and OpenGL's");
    for line in DEMO_CHOICES {
        ui.label(*line);
    }
}

/// Where the Phong demo preset follows the demo's program rather than OpenGL (shown in the
/// help overlay; the scene file and the README say the same).
pub const DEMO_CHOICES: &[&str] = &[
    "The demo's: lighting in object space, light and eye at (-4, 0, -8), so the light turns with the object. OpenGL's: lighting in eye space after the modelview (switch: light fixed in the world).",
    "The demo's: every normal is normalize(position). OpenGL's: the surface's normals (switch: the surface's true normals).",
    "The demo's: R = 2 max(N.L, 0) N - L and pow(max(V.R, 0), 100), times the object's red, so the highlight is red. OpenGL's: Blinn-Phong's n.H and the light's specular colour times the material's (switch: highlight in the light's colour).",
    "The demo's: no projection (the picture is clip space), Phong without renormalising, Flat from dFdx/dFdy per fragment, colours interpolated unclamped. Under Pipeline, the shaded view offers OpenGL's choices.",
];
