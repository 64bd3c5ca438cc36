//! Helpers shared by the UI tests. (Each test file uses some of them.)
#![allow(dead_code)]

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::AppState;

/// Brings the number field named `label` into view and clicks it, as a student does.
pub fn click_field(h: &mut Harness<'static, AppState>, label: &str) {
    h.get_by_role_and_label(Role::SpinButton, label).scroll_to_me();
    // Scrolling is animated: wait for it to settle before clicking.
    h.run_steps(30);
    h.get_by_role_and_label(Role::SpinButton, label).click();
    h.run_steps(1);
}

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
