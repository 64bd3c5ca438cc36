//! The keyboard: each shortcut applied to the state (the table of shortcuts and the keys
//! pressed are [`crate::app::panels::help`]'s), and presentation's own keys (F5, and the
//! arrow keys walking through the calculation's steps).

use phonglab_core::{CameraSpec, NormalMode, RuleSet, Rules, materials};

use super::files;
use super::state::{AppState, Precision};
use crate::app::panels::help;

/// Applies one keyboard shortcut.
pub fn apply_action(state: &mut AppState, action: help::Action) {
    use help::Action as A;
    let mut c = state.doc.clone();
    match action {
        A::Help => {
            state.ui.show_help = !state.ui.show_help;
            return;
        }
        A::Reset => {
            state.reset_to_worksheet();
            return;
        }
        A::Quit => {
            state.ui.quit = true;
            return;
        }
        A::Open => return files::open_typed(state),
        A::Undo => return state.undo(),
        A::Redo => return state.redo(),
        A::Save => return files::save_typed(state),
        A::Precision => {
            state.settings.precision = match state.settings.precision {
                Precision::F32 => Precision::F64,
                Precision::F64 => Precision::F32,
            };
            return;
        }
        A::LocalViewer => c.scene.light_model.local_viewer = !c.scene.light_model.local_viewer,
        A::TwoSided => c.scene.light_model.two_sided = !c.scene.light_model.two_sided,
        A::NextMaterial | A::PreviousMaterial => {
            let table = materials::classic();
            let n = table.len();
            let now = table.iter().position(|m| m.material == c.scene.material);
            let next = match (now, action == A::NextMaterial) {
                (Some(i), true) => (i + 1) % n,
                (Some(i), false) => (i + n - 1) % n,
                (None, true) => 0,
                (None, false) => n - 1,
            };
            c.scene.material = table[next].material.clone();
        }
        A::NextModelview => {
            c.camera = match c.camera {
                CameraSpec::Worksheet(k) => CameraSpec::Worksheet(k % 5 + 1),
                _ => CameraSpec::Worksheet(1),
            }
        }
        A::SpecularModel => {
            c.scene.rules.specular = c.scene.rules.specular.next();
        }
        A::NextRuleSet => {
            let i = RuleSet::ALL.iter().position(|r| *r == c.scene.rules.set).unwrap_or(0);
            // A rule set comes with its specular model (the Phong demo's R.V), as when its
            // scene is loaded: the model shown, the plot and the set's summary then agree.
            c.scene.rules = Rules::of_set(RuleSet::ALL[(i + 1) % RuleSet::ALL.len()]);
        }
        A::Object(o) => c.view.object = o,
        A::Shading(sh) => c.view.shading = sh,
        A::AutoRotate => c.view.auto_rotate = !c.view.auto_rotate,
        A::NextNormals => {
            c.scene.normal_mode = match c.scene.normal_mode {
                NormalMode::AsIs => NormalMode::Normalize,
                NormalMode::Normalize => NormalMode::Rescale,
                NormalMode::Rescale => NormalMode::AsIs,
            }
        }
    }
    state.apply(c);
}

/// The keys of presentation: F5 toggles it; the arrow keys walk through the calculation's
/// steps (when no widget has the keyboard).
pub fn presentation_keys(ctx: &egui::Context, state: &mut AppState, steps: usize) {
    let layout = &mut state.ui.layout;
    if ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, egui::Key::F5)) {
        layout.presenting = !layout.presenting;
    }
    if ctx.egui_wants_keyboard_input() || ctx.memory(|m| m.focused().is_some()) {
        return;
    }
    let (down, up) = ctx.input_mut(|i| {
        let down = i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowDown)
            || i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowRight);
        let up = i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowUp)
            || i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowLeft);
        (down, up)
    });
    if down || up {
        layout.step_by(if down { 1 } else { -1 }, steps);
        state.ui.scroll_to_step = true;
    }
}
