//! Helpers shared by the UI tests.

use egui_kittest::Harness;
use phonglab::app::AppState;

/// The texts the last frame put on the clipboard.
pub fn copied_text(h: &Harness<'_, AppState>) -> Vec<String> {
    h.output()
        .platform_output
        .commands
        .iter()
        .filter_map(|c| match c {
            egui::OutputCommand::CopyText(t) => Some(t.clone()),
            _ => None,
        })
        .collect()
}
