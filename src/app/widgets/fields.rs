//! Labelled input widgets: every input has an accessible label (found by tests with
//! `get_by_label`), and every number is typed into the one number field
//! ([`crate::app::widgets::number_field::NumberField`]), whose values reach the validator unclamped, so
//! an out-of-range value is refused with a message rather than silently clamped.

use egui::{Response, Slider, SliderClamping, Ui};
use glam::{DVec3, DVec4};

use crate::app::widgets::number_field::{Accepts, NumberField, refusal_ui};

/// A number field's width in the controls: 6 significant digits and a sign.
const FIELD_WIDTH: f32 = 58.0;

/// `label`, then a slider over `range` (dragged values stay inside it) and a number field
/// beside it whose typed values are not clamped (the document validator decides), both
/// named `label`: the label before them, or above them where the panel is narrow.
pub fn slider_ui(ui: &mut Ui, label: &str, value: &mut f64, range: std::ops::RangeInclusive<f64>, log: bool) -> bool {
    ui.horizontal_wrapped(|ui| {
        // The label first, as every row has it (colours, vectors): before its controls
        // where they fit beside it, above them where they do not.
        ui.add(egui::Label::new(label).wrap_mode(egui::TextWrapMode::Extend));
        let controls = ui.spacing().slider_width + FIELD_WIDTH + 4.0 * ui.spacing().item_spacing.x;
        if ui.max_rect().max.x - ui.cursor().min.x < controls {
            ui.end_row();
        }
        let mut s = Slider::new(value, range).show_value(false).clamping(SliderClamping::Never);
        if log {
            s = s.logarithmic(true).smallest_positive(1e-6);
        }
        let slid = ui.add(s);
        if wanted_in_view(ui.ctx(), label) {
            slid.scroll_to_me(Some(egui::Align::Center));
        }
        ui.ctx().accesskit_node_builder(slid.id, |b| b.set_label(label.to_string()));
        landmark(ui.ctx(), label, slid.rect);
        let typed = NumberField::new(value, label).width(FIELD_WIDTH).show_in_row_ui(ui, 1);
        if let Some(why) = &typed.refused {
            ui.end_row();
            refusal_ui(ui, why);
        }
        slid.changed() || typed.response.changed()
    })
    .inner
}

/// Asks the slider labelled `label` to scroll into view the next time it is drawn (an
/// experiment names the control its words tell the class to move).
pub fn bring_into_view(ctx: &egui::Context, label: &str) {
    ctx.data_mut(|d| d.insert_temp(egui::Id::unique(WANTED_IN_VIEW), label.to_string()));
}

/// Whether the slider labelled `label` was asked into view; the request is then done.
fn wanted_in_view(ctx: &egui::Context, label: &str) -> bool {
    ctx.data_mut(|d| {
        let id = egui::Id::unique(WANTED_IN_VIEW);
        let wanted = d.get_temp::<String>(id).is_some_and(|l| l == label);
        if wanted {
            d.remove::<String>(id);
        }
        wanted
    })
}

const WANTED_IN_VIEW: &str = "phonglab: the control asked into view";

/// Notes where a named control or picture is this frame (in points), for those who drive
/// the window from outside: the browser test reads them through the page's probe
/// (`crate::web`), where there is no accessibility tree to search. Only while someone
/// asked for them ([`record_landmarks`]); otherwise this is one lookup.
pub fn landmark(ctx: &egui::Context, name: &str, rect: egui::Rect) {
    ctx.data_mut(|d| {
        if d.get_temp::<bool>(egui::Id::unique(RECORDING)) == Some(true) {
            d.get_temp_mut_or_default::<Landmarks>(egui::Id::unique(LANDMARKS)).0.insert(name.to_string(), rect);
        }
    });
}

/// Records this frame's landmarks from now on, forgetting the last frame's (a control
/// not drawn this frame is not where it was).
pub fn record_landmarks(ctx: &egui::Context) {
    ctx.data_mut(|d| {
        d.insert_temp(egui::Id::unique(RECORDING), true);
        d.insert_temp(egui::Id::unique(LANDMARKS), Landmarks::default());
    });
}

/// Where each named control was drawn this frame ([`landmark`]).
pub fn landmarks(ctx: &egui::Context) -> std::collections::BTreeMap<String, egui::Rect> {
    ctx.data(|d| d.get_temp::<Landmarks>(egui::Id::unique(LANDMARKS)).map(|l| l.0).unwrap_or_default())
}

const LANDMARKS: &str = "phonglab landmarks";
const RECORDING: &str = "phonglab landmarks: recording";

#[derive(Clone, Default)]
struct Landmarks(std::collections::BTreeMap<String, egui::Rect>);

/// A labelled number field (no clamping).
pub fn number_ui(ui: &mut Ui, label: &str, value: &mut f64, speed: f64) -> Response {
    ui.horizontal_wrapped(|ui| {
        ui.add(egui::Label::new(label).wrap_mode(egui::TextWrapMode::Extend));
        NumberField::new(value, label).speed(speed).show_ui(ui)
    })
    .inner
}

/// A labelled field for a whole number in `range` (a mesh's slices, a quiz's level).
pub fn whole_number_ui(ui: &mut Ui, label: &str, value: &mut u32, range: std::ops::RangeInclusive<u32>) -> bool {
    let mut x = f64::from(*value);
    ui.label(label);
    let accepts = Accepts::Whole { min: i64::from(*range.start()), max: i64::from(*range.end()) };
    let changed = NumberField::new(&mut x, label).speed(0.1).accepts(accepts).width(40.0).show_ui(ui).changed();
    if changed {
        *value = x as u32;
    }
    changed
}

/// A row of number fields, each named "{label} {component}" for assistive technology and
/// tests; a row of numbers typed into any of them sets them all.
pub fn components_ui(ui: &mut Ui, label: &str, comps: &mut [(&str, &mut f64)], speed: f64) -> bool {
    components_after_ui(ui, |_| {}, label, comps, speed)
}

/// [`components_ui`] after `before` (e.g. a swatch) on the same row.
fn components_after_ui(
    ui: &mut Ui,
    before: impl FnOnce(&mut Ui),
    label: &str,
    comps: &mut [(&str, &mut f64)],
    speed: f64,
) -> bool {
    let mut changed = false;
    let n = comps.len();
    // Wrapped, so a narrow panel puts the fields on a second line rather than widening.
    let row = ui
        .horizontal_wrapped(|ui| {
            let (mut row, mut refused) = (None, None);
            before(ui);
            ui.add(egui::Label::new(label).wrap_mode(egui::TextWrapMode::Extend));
            // The fields on the label's row when they all fit there, else on the next row.
            let each = FIELD_WIDTH + 14.0 + 2.0 * ui.spacing().item_spacing.x;
            let left = |ui: &Ui| ui.max_rect().max.x - ui.cursor().min.x;
            if left(ui) < n as f32 * each {
                ui.end_row();
            }
            for (name, c) in comps.iter_mut() {
                // A component's name and field go to the next row together.
                if left(ui) < each {
                    ui.end_row();
                }
                ui.small(*name);
                let shown = NumberField::new(c, format!("{label} {name}"))
                    .speed(speed)
                    .width(FIELD_WIDTH)
                    .show_in_row_ui(ui, n);
                changed |= shown.response.changed();
                row = row.or(shown.row);
                refused = refused.or(shown.refused);
            }
            if let Some(why) = &refused {
                ui.end_row();
                refusal_ui(ui, why);
            }
            row
        })
        .inner;
    if let Some(all) = row {
        for ((_, c), x) in comps.iter_mut().zip(all) {
            **c = x;
        }
    }
    changed
}

/// Three components: `"{label} x"`, `"{label} y"`, `"{label} z"`.
pub fn vec3_ui(ui: &mut Ui, label: &str, v: &mut DVec3, speed: f64) -> bool {
    components_ui(ui, label, &mut [("x", &mut v.x), ("y", &mut v.y), ("z", &mut v.z)], speed)
}

/// Four components (`x y z w`).
pub fn vec4_ui(ui: &mut Ui, label: &str, v: &mut DVec4, speed: f64) -> bool {
    components_ui(ui, label, &mut [("x", &mut v.x), ("y", &mut v.y), ("z", &mut v.z), ("w", &mut v.w)], speed)
}

/// An unclamped GL colour: r, g, b (and alpha when `alpha`), after a swatch of how it shows.
pub fn color_ui(ui: &mut Ui, label: &str, c: &mut DVec4, alpha: bool) -> bool {
    let shown = crate::app::widgets::palette::gl_to_color32([c.x, c.y, c.z]);
    // Wider than high, rounded, with an edge in the text's colour: a colour sample, not a
    // check box (a white square read as an unchecked one).
    let swatch = move |ui: &mut Ui| {
        let (rect, _) = ui.allocate_exact_size(egui::vec2(26.0, 14.0), egui::Sense::hover());
        let edge = ui.visuals().text_color().gamma_multiply(0.6);
        ui.painter().rect(rect, 7.0, shown, egui::Stroke::new(1.0, edge), egui::StrokeKind::Inside);
    };
    let DVec4 { x, y, z, w } = c;
    if alpha {
        components_after_ui(ui, swatch, label, &mut [("r", x), ("g", y), ("b", z), ("a", w)], 0.005)
    } else {
        components_after_ui(ui, swatch, label, &mut [("r", x), ("g", y), ("b", z)], 0.005)
    }
}

/// `label`, then a combo box showing `selected` with `contents` as its choices, named
/// `label`: the label before its control, as every row has it (egui's own puts it after).
pub fn combo_ui<R>(
    ui: &mut Ui,
    label: &str,
    selected: impl Into<egui::WidgetText>,
    contents: impl FnOnce(&mut Ui) -> R,
) -> egui::Response {
    // Wrapped: in a narrow panel the box goes under its label rather than past the edge.
    ui.horizontal_wrapped(|ui| {
        let l = ui.add(egui::Label::new(label).wrap_mode(egui::TextWrapMode::Extend));
        egui::ComboBox::from_id_salt(label).selected_text(selected).show_ui(ui, contents).response.labelled_by(l.id)
    })
    .inner
}
