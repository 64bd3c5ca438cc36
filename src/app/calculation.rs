//! The worked calculation: every step with its formula and value, in the worksheet's order,
//! with the engine's notes beside the step they concern; copies as Markdown.

use egui::{RichText, Ui};
use phonglab_core::explain::{Explanation, Side, fmt_value};
use phonglab_core::plan::{Effect, Stage};

use super::palette;

/// Significant digits shown.
const DIGITS: usize = 8;

/// The specialised evaluator's plan: what it computes and what it skips, and why, and
/// the stages it runs, in order (the same list the evaluator runs).
fn plan_ui(ui: &mut Ui, effects: &[Effect], stages: &[Stage]) {
    let skipped = effects.iter().filter(|e| !e.on).count();
    egui::CollapsingHeader::new(format!(
        "Specialised plan: {} effects computed, {skipped} skipped",
        effects.len() - skipped
    ))
    .id_salt("plan")
    .show(ui, |ui| {
        for e in effects {
            let who = e.light.map(|i| format!("light {i}: ")).unwrap_or_default();
            let text = format!("{who}{}: {}", e.name, e.why);
            if e.on {
                ui.label(RichText::new(format!("computed  {text}")).small());
            } else {
                ui.label(RichText::new(format!("skipped   {text}")).small().weak());
            }
        }
        ui.label(RichText::new(format!("The program, {} stages per chunk of vertices:", stages.len())).small());
        let list: Vec<String> = stages.iter().map(|s| format!("{s:?}")).collect();
        ui.label(RichText::new(list.join(" > ")).small().monospace());
    });
}

/// The steps; `side` is switchable when two-sided lighting is on. Steps the specialised
/// evaluator skips are greyed, with the reason.
pub fn calculation_ui(
    ui: &mut Ui,
    ex: &Explanation,
    side: &mut Side,
    two_sided: bool,
    effects: &[Effect],
    stages: &[Stage],
) {
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
    plan_ui(ui, effects, stages);
    ui.separator();
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        for (k, st) in ex.steps.iter().enumerate() {
            let skip = effects.iter().find(|e| !e.on && e.light == st.light && e.step_kind() == Some(st.kind));
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(format!("{:>2}.", k + 1)).monospace().weak());
                let title = RichText::new(&st.title);
                ui.label(if skip.is_some() { title.weak() } else { title.strong() });
                ui.label(RichText::new(&st.formula).monospace().weak());
            });
            let value = match &st.value {
                Some(v) => format!("{} = {}", st.name, fmt_value(v, DIGITS)),
                None => format!("{} = n/a", st.name),
            };
            let mut text = RichText::new(value).monospace();
            if let Some(c) = palette::step(st.kind).filter(|_| skip.is_none()) {
                text = text.color(c);
            }
            if skip.is_some() {
                text = text.weak();
            }
            ui.indent(("value", k), |ui| {
                ui.label(text);
                if let Some(e) = skip {
                    ui.label(RichText::new(format!("skipped by the specialised evaluator: {}", e.why)).small().weak());
                }
                for n in &st.notes {
                    ui.label(RichText::new(format!("note: {n}")).color(palette::NOTE));
                }
            });
            ui.add_space(2.0);
        }
    });
}
