//! Labelled input widgets: every input has an accessible label (found by tests with
//! `get_by_label`), and numbers the user types reach the validator unclamped, so an
//! out-of-range value is refused with a message rather than silently clamped.

use egui::{DragValue, Response, Slider, SliderClamping, Ui};
use glam::{DVec3, DVec4};

/// A slider over `range` whose typed values are not clamped (the document validator
/// decides), with `label` as its accessible name.
pub fn slider(ui: &mut Ui, label: &str, value: &mut f64, range: std::ops::RangeInclusive<f64>, log: bool) -> Response {
    let mut s = Slider::new(value, range)
        .text(label)
        .clamping(SliderClamping::Never)
        .custom_formatter(|v, _| phonglab_core::explain::fmt_sig(v, 6));
    if log {
        s = s.logarithmic(true).smallest_positive(1e-6);
    }
    ui.add(s)
}

/// A labelled number field (no clamping).
pub fn number(ui: &mut Ui, label: &str, value: &mut f64, speed: f64) -> Response {
    ui.horizontal(|ui| {
        let l = ui.label(label);
        ui.add(DragValue::new(value).speed(speed).max_decimals(8)).labelled_by(l.id)
    })
    .inner
}

/// Number fields on one row, each named "{label} {component}" for assistive technology
/// and tests (the row label and the component label together).
fn components(ui: &mut Ui, label: &str, comps: &mut [(&str, &mut f64)], speed: f64, decimals: usize) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        let row = ui.label(label);
        for (name, c) in comps.iter_mut() {
            let cl = ui.small(*name);
            changed |= ui
                .add(DragValue::new(*c).speed(speed).max_decimals(decimals))
                .labelled_by(row.id)
                .labelled_by(cl.id)
                .changed();
        }
    });
    changed
}

/// Three components: `"{label} x"`, `"{label} y"`, `"{label} z"`.
pub fn vec3(ui: &mut Ui, label: &str, v: &mut DVec3, speed: f64) -> bool {
    components(ui, label, &mut [("x", &mut v.x), ("y", &mut v.y), ("z", &mut v.z)], speed, 8)
}

/// Four components (`x y z w`).
pub fn vec4(ui: &mut Ui, label: &str, v: &mut DVec4, speed: f64) -> bool {
    components(ui, label, &mut [("x", &mut v.x), ("y", &mut v.y), ("z", &mut v.z), ("w", &mut v.w)], speed, 8)
}

/// An unclamped GL colour: r, g, b (and alpha when `alpha`), after a swatch of how it shows.
pub fn color(ui: &mut Ui, label: &str, c: &mut DVec4, alpha: bool) -> bool {
    ui.horizontal(|ui| {
        let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
        ui.painter().rect_filled(rect, 2.0, crate::app::palette::gl_to_color32([c.x, c.y, c.z]));
        let DVec4 { x, y, z, w } = c;
        if alpha {
            components(ui, label, &mut [("r", x), ("g", y), ("b", z), ("a", w)], 0.005, 6)
        } else {
            components(ui, label, &mut [("r", x), ("g", y), ("b", z)], 0.005, 6)
        }
    })
    .inner
}
