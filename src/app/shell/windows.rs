//! The windows over the layout: the cost study (its finished work collected first), the
//! shader, phonglab's own file chooser, the keys' help.

use phonglab_core::t;

use super::state::AppState;
use crate::app::panels::{cost, help, shader_panel};

/// The windows over the layout: the cost study (its finished work collected first), the
/// shader, the keys.
pub fn windows_ui(ctx: &egui::Context, state: &mut AppState) {
    // Finished work is collected before the window is drawn, and a frame is asked for at
    // once when something finished (the result would otherwise wait for the next input).
    let was_running = state.cost.busy() || state.heat_map.busy();
    let running = state.cost.poll() | state.heat_map.poll();
    if was_running && !running {
        ctx.request_repaint();
    } else if running {
        ctx.request_repaint_after(std::time::Duration::from_millis(100));
    }
    cost::cost_window_ui(ctx, &mut state.cost, &state.doc, state.settings.pow);
    shader_panel::shader_window_ui(ctx, &mut state.shader, &state.doc);
    super::files::chooser_ui(ctx, state);

    if state.ui.show_help {
        let mut open = true;
        egui::Window::new(t!("keyboard-shortcuts"))
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .show(ctx, help::help_ui);
        state.ui.show_help = open;
    }
}
