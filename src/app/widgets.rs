//! Labelled input widgets: every input has an accessible label (found by tests with
//! `get_by_label`), and numbers the user types reach the validator unclamped, so an
//! out-of-range value is refused with a message rather than silently clamped.

use egui::{DragValue, Response, Slider, SliderClamping, Ui};
use glam::{DVec3, DVec4};

/// A number as the shortest decimal that reads back as the same `f64` (exponent form
/// outside [1e-4, 1e15)). egui puts a field's text in the editor when it gains focus and
/// parses it back when it loses focus, so a rounded display would round the value of a
/// field that was only clicked: every number field shows its value exactly.
pub fn exact_text(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e15).contains(&a) { format!("{v:e}") } else { format!("{v}") }
}

/// A typed number, with a decimal point or comma
/// ([`phonglab_core::formats::typed_number::parse_number`]). A number that is not finite or
/// too large goes on to the document's validator, which refuses it naming the field; one
/// that a float would hold as 0 (`1e-400`) keeps the field's value rather than become 0.
fn typed(text: &str) -> Option<f64> {
    use phonglab_core::formats::typed_number::{TypedNumberError as E, parse_number, with_decimal_point};
    match parse_number(text) {
        Ok(x) => Some(x),
        Err(E::NotFinite(t) | E::TooLarge(t)) => with_decimal_point(&t).parse().ok(),
        Err(E::TooSmall(_) | E::NotANumber(_) | E::Empty) => None,
    }
}

/// A number field (no clamping) that shows its value exactly and reads `12,5` as 12.5.
pub fn exact_drag(value: &mut f64, speed: f64) -> DragValue<'_> {
    DragValue::new(value).speed(speed).custom_formatter(|v, _| exact_text(v)).custom_parser(typed)
}

/// A slider over `range` whose typed values are not clamped (the document validator
/// decides), with `label` as its accessible name.
pub fn slider(ui: &mut Ui, label: &str, value: &mut f64, range: std::ops::RangeInclusive<f64>, log: bool) -> Response {
    let mut s = Slider::new(value, range)
        .text(label)
        .clamping(SliderClamping::Never)
        .custom_formatter(|v, _| exact_text(v))
        .custom_parser(typed);
    if log {
        s = s.logarithmic(true).smallest_positive(1e-6);
    }
    ui.add(s)
}

/// A labelled number field (no clamping).
pub fn number(ui: &mut Ui, label: &str, value: &mut f64, speed: f64) -> Response {
    ui.horizontal(|ui| {
        let l = ui.label(label);
        ui.add(exact_drag(value, speed)).labelled_by(l.id)
    })
    .inner
}

/// Number fields on one row, each named "{label} {component}" for assistive technology
/// and tests (the row label and the component label together).
fn components(ui: &mut Ui, label: &str, comps: &mut [(&str, &mut f64)], speed: f64) -> bool {
    components_after(ui, |_| {}, label, comps, speed)
}

/// [`components`] after `before` (e.g. a swatch) on the same row.
fn components_after(
    ui: &mut Ui,
    before: impl FnOnce(&mut Ui),
    label: &str,
    comps: &mut [(&str, &mut f64)],
    speed: f64,
) -> bool {
    let mut changed = false;
    // Wrapped, so a narrow panel puts the fields on a second line rather than widening.
    ui.horizontal_wrapped(|ui| {
        before(ui);
        let row = ui.label(label);
        for (name, c) in comps.iter_mut() {
            // A component's name and field go to the next row together.
            if ui.available_width() < 72.0 {
                ui.end_row();
            }
            let cl = ui.small(*name);
            changed |= ui.add(exact_drag(c, speed)).labelled_by(row.id).labelled_by(cl.id).changed();
        }
    });
    changed
}

/// Three components: `"{label} x"`, `"{label} y"`, `"{label} z"`.
pub fn vec3(ui: &mut Ui, label: &str, v: &mut DVec3, speed: f64) -> bool {
    components(ui, label, &mut [("x", &mut v.x), ("y", &mut v.y), ("z", &mut v.z)], speed)
}

/// Four components (`x y z w`).
pub fn vec4(ui: &mut Ui, label: &str, v: &mut DVec4, speed: f64) -> bool {
    components(ui, label, &mut [("x", &mut v.x), ("y", &mut v.y), ("z", &mut v.z), ("w", &mut v.w)], speed)
}

/// An unclamped GL colour: r, g, b (and alpha when `alpha`), after a swatch of how it shows.
pub fn color(ui: &mut Ui, label: &str, c: &mut DVec4, alpha: bool) -> bool {
    let shown = crate::app::palette::gl_to_color32([c.x, c.y, c.z]);
    let swatch = move |ui: &mut Ui| {
        let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
        ui.painter().rect_filled(rect, 2.0, shown);
    };
    let DVec4 { x, y, z, w } = c;
    if alpha {
        components_after(ui, swatch, label, &mut [("r", x), ("g", y), ("b", z), ("a", w)], 0.005)
    } else {
        components_after(ui, swatch, label, &mut [("r", x), ("g", y), ("b", z)], 0.005)
    }
}

#[cfg(test)]
mod tests {
    use super::exact_text;

    #[test]
    fn exact_text_reads_back_as_the_same_number() {
        for v in [0.0, -0.0, 0.2125, 121.76225070590814, 1e300, -1e-300, 5e-324, 1e15, 99999.5, 0.44721359549995804] {
            let t = exact_text(v);
            assert_eq!(t.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{v} -> {t}");
            assert!(t.len() <= 24, "{t}");
        }
        assert_eq!(exact_text(0.2125), "0.2125");
        assert_eq!(exact_text(1e300), "1e300");
        assert_eq!(exact_text(-665.1075), "-665.1075");
    }
}
