//! The worked calculation: every step with its formula and value, in the worksheet's order,
//! with the engine's notes beside the step they concern; copies as Markdown.

use egui::{RichText, Ui};
use phonglab_core::explain::{Explanation, Side, fmt_value};

use super::palette;

/// Significant digits shown.
const DIGITS: usize = 8;

/// The steps; `side` is switchable when two-sided lighting is on.
pub fn calculation_ui(ui: &mut Ui, ex: &Explanation, side: &mut Side, two_sided: bool) {
    ui.horizontal(|ui| {
        ui.heading("Worked calculation");
        if ui.button("Copy as Markdown").on_hover_text("Copies every step as a Markdown table.").clicked() {
            ui.ctx().copy_text(ex.to_markdown(DIGITS));
        }
    });
    if two_sided {
        ui.horizontal(|ui| {
            ui.label("Side:");
            ui.radio_value(side, Side::Front, "front");
            ui.radio_value(side, Side::Back, "back");
        });
    }
    ui.small(&ex.heading);
    ui.separator();
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        for (k, st) in ex.steps.iter().enumerate() {
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(format!("{:>2}.", k + 1)).monospace().weak());
                ui.label(RichText::new(&st.title).strong());
                ui.label(RichText::new(&st.formula).monospace().weak());
            });
            let value = match &st.value {
                Some(v) => format!("{} = {}", st.name, fmt_value(v, DIGITS)),
                None => format!("{} = n/a", st.name),
            };
            let mut text = RichText::new(value).monospace();
            if let Some(c) = palette::step(st.kind) {
                text = text.color(c);
            }
            ui.indent(("value", k), |ui| {
                ui.label(text);
                for n in &st.notes {
                    ui.label(RichText::new(format!("note: {n}")).color(palette::NOTE));
                }
            });
            ui.add_space(2.0);
        }
    });
}
