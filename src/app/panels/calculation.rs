//! The worked calculation: every step with its formula and value, in the worksheet's order,
//! with the engine's notes beside the step they concern; copies as Markdown.

use egui::{RichText, Ui};
use phonglab_core::effects::Effect;
use phonglab_core::explain::{Explanation, Side, fmt_value};
use phonglab_core::plan::Stage;

use super::student_column::{StudentCheck, first_wrong_frame, student_summary_ui, student_value_ui};
use crate::app::widgets::palette;
use crate::t;

/// Significant digits shown.
const DIGITS: usize = 8;

/// The specialised evaluator's plan: what it computes and what it skips, and why, and
/// the stages it runs, in order (the same list the evaluator runs).
fn plan_ui(ui: &mut Ui, effects: &[Effect], stages: &[Stage]) {
    let skipped = effects.iter().filter(|e| !e.on).count();
    let title = t!("plan-heading", computed = effects.len() - skipped, skipped = skipped);
    // A header whose title wraps in a narrow panel (egui's collapsing header keeps one line,
    // and widened the panel past its edge); the title opens it too.
    let mut state = egui::collapsing_header::CollapsingState::load_with_default_open(
        ui.ctx(),
        ui.make_persistent_id("plan"),
        false,
    );
    let toggle = ui
        .horizontal(|ui| {
            state.show_toggle_button(ui, egui::collapsing_header::paint_default_icon);
            ui.add(egui::Label::new(title).wrap().sense(egui::Sense::click())).clicked()
        })
        .inner;
    if toggle {
        state.toggle(ui);
    }
    state.show_body_unindented(ui, |ui| {
        ui.indent("plan body", |ui| {
            for e in effects {
                let who = e.light.map(|i| t!("plan-light", index = i.to_string())).unwrap_or_default();
                let text = format!("{who}{}: {}", e.name, e.why);
                if e.on {
                    ui.label(RichText::new(t!("plan-computed", what = text)).small());
                } else {
                    ui.label(RichText::new(t!("plan-skipped", what = text)).small().weak());
                }
            }
            ui.label(RichText::new(t!("plan-program", stages = stages.len())).small());
            let list: Vec<String> = stages.iter().map(Stage::to_string).collect();
            ui.label(RichText::new(list.join(" > ")).small().monospace());
        });
    });
}

/// The teacher's walk through the steps: the step highlighted, and whether it just moved
/// (then the list scrolls to it).
#[derive(Clone, Copy, Debug, Default)]
pub struct Walk {
    /// The highlighted step, counted from 0.
    pub step: Option<usize>,
    /// Scroll it into view this frame.
    pub scroll: bool,
}

/// The steps; `side` is switchable when two-sided lighting is on. Steps the specialised
/// evaluator skips are greyed, with the reason. A student's work checked (`student`) shows
/// its summary above the steps and their value under each step's.
#[allow(clippy::too_many_arguments)]
pub fn calculation_ui(
    ui: &mut Ui,
    ex: &Explanation,
    side: &mut Side,
    two_sided: bool,
    effects: &[Effect],
    stages: &[Stage],
    walk: Walk,
    student: &mut Option<StudentCheck>,
) {
    // (Wrapped: a narrow panel puts the button under the title rather than widen.)
    ui.horizontal_wrapped(|ui| {
        ui.heading(t!("worked-calculation"));
        if ui.button(t!("copy-markdown")).on_hover_text(t!("copy-markdown-hover")).clicked() {
            ui.ctx().copy_text(ex.to_markdown(DIGITS));
        }
    });
    if two_sided {
        ui.horizontal(|ui| {
            ui.label(t!("side"));
            ui.radio_value(side, Side::Front, t!("side-front"));
            ui.radio_value(side, Side::Back, t!("side-back"));
        });
    }
    ui.small(&ex.heading);
    plan_ui(ui, effects, stages);
    ui.separator();
    let student = &mut *student;
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        // Clear of the scroll bar, which floats over the column's right edge: the values
        // wrap before it rather than end under it.
        let bar = {
            let s = &ui.spacing().scroll;
            s.bar_width + s.bar_inner_margin + s.bar_outer_margin
        };
        ui.set_max_width((ui.available_width() - bar).max(bar));
        student_summary_ui(ui, student);
        for (k, st) in ex.steps.iter().enumerate() {
            let skip = effects.iter().find(|e| !e.on && e.light == st.light && e.step_kind() == Some(st.kind));
            let here = walk.step == Some(k);
            let theirs = student.as_ref().and_then(|s| s.step(&st.name));
            let frame = if theirs.is_some_and(|(_, first)| first.is_some()) {
                first_wrong_frame(ui)
            } else if here {
                egui::Frame::new()
                    .fill(ui.visuals().selection.bg_fill.gamma_multiply(0.45))
                    .stroke(ui.visuals().selection.stroke)
                    .corner_radius(4.0)
                    .inner_margin(4.0)
            } else {
                egui::Frame::new().inner_margin(4.0)
            };
            let shown = frame.show(ui, |ui| step_ui(ui, k, st, skip, theirs));
            if here && walk.scroll {
                shown.response.scroll_to_me(Some(egui::Align::Center));
            }
            ui.add_space(2.0);
        }
    });
}

/// One step: its number, title and formula, then its value (in its symbol's colour) and
/// the notes.
fn step_ui(
    ui: &mut Ui,
    k: usize,
    st: &phonglab_core::explain::Step,
    skip: Option<&Effect>,
    theirs: Option<(&phonglab_core::study::check::StepCheck, Option<&phonglab_core::study::check::Check>)>,
) {
    ui.horizontal(|ui| {
        ui.label(RichText::new(format!("{:>2}.", k + 1)).monospace().weak());
        let title = RichText::new(&st.title);
        ui.label(if skip.is_some() { title.weak() } else { title.strong() });
    });
    // The formula on a line of its own, so that when it wraps it wraps under itself.
    ui.label(RichText::new(&st.formula).monospace().weak());
    let value = match &st.value {
        Some(v) => format!("{} = {}", st.name, crate::locale::decimal(&fmt_value(v, DIGITS))),
        None => format!("{} = {}", st.name, t!("not-applicable")),
    };
    let mut text = RichText::new(value).monospace();
    if let Some(c) = palette::step(st.kind).filter(|_| skip.is_none()) {
        text = text.color(palette::ink(ui, c));
    }
    if skip.is_some() {
        text = text.weak();
    }
    ui.indent(("value", k), |ui| {
        ui.add(egui::Label::new(text).wrap());
        if let Some((step, first)) = theirs {
            student_value_ui(ui, step, first);
        }
        if let Some(e) = skip {
            ui.label(RichText::new(t!("skipped-by-specialised", why = &e.why)).small().weak());
        }
        for n in &st.notes {
            ui.label(RichText::new(t!("note-line", note = n)).color(palette::ink(ui, palette::NOTE)));
        }
    });
}
