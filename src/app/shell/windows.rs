//! The windows over the layout: the cost study (its finished work collected first), the
//! shader, phonglab's own file chooser, the things to try, the keys' help.

use super::state::AppState;
use crate::app::panels::things_to_try::{self, TryAsked};
use crate::app::panels::{cost, director, help, shader_panel, share};
use crate::t;

/// The windows over the layout: the cost study (its finished work collected first), the
/// shader, the chooser, the things to try (`explanation`: the calculation as it stands, for
/// their answers; kept right of `centre`'s left edge, clear of the controls its words
/// name), the keys.
pub fn windows_ui(
    ctx: &egui::Context,
    state: &mut AppState,
    explanation: &phonglab_core::explain::Explanation,
    centre: egui::Rect,
) {
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
    let meshes = &mut state.shaded.main.mesh;
    if let Some(moved) = director::director_window_ui(ctx, &mut state.director, &state.doc, meshes) {
        state.apply(moved);
    }
    let lang = state.ui.layout.locale().lang;
    let shown = share::Shown { lang, channel: state.view_options.channel };
    share::share_window_ui(ctx, &mut state.share, &state.doc, &shown, &mut state.message);
    super::files::chooser_ui(ctx, state);
    match things_to_try::things_to_try_window_ui(ctx, &mut state.things, explanation, lang, centre) {
        Some(TryAsked::Load(doc, title, control)) => state.set_up_experiment(*doc, &title, control.is_some()),
        Some(TryAsked::Step(k)) => {
            // The answer is a step of the calculation: highlighted there, and in view.
            state.ui.layout.calculation_open = true;
            state.ui.layout.step = Some(k);
            state.ui.scroll_to_step = true;
        }
        None => {}
    }

    if state.ui.show_help {
        let mut open = true;
        egui::Window::new(t!("keyboard-shortcuts"))
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            // On a small screen (1024x600) the keys scroll inside the window.
            .max_height(ctx.content_rect().height() * 0.8)
            .vscroll(true)
            .show(ctx, help::help_ui);
        state.ui.show_help = open;
    }
}
