//! Compare: pin the scene as A, change anything, and see A and B (the current scene) side
//! by side: both shaded views, both colours, and every step of the worked calculation with
//! the ones whose values differ highlighted. Typical pairs: Gouraud against Phong, f32
//! against f64, bronze against gold.

use egui::{Color32, RichText, Ui};
use phonglab_core::explain::{Explanation, fmt_value};
use phonglab_core::{Document, PowFn};

use super::evaluated::{Evaluated, Precision, evaluate};
use super::view_cache::ViewCache;

/// The pinned scene A: the document and the numerics it was evaluated with.
#[derive(Clone, Debug, PartialEq)]
pub struct Pinned {
    /// The document.
    pub doc: Document,
    /// Its precision.
    pub precision: Precision,
    /// Its power function.
    pub pow: PowFn,
}

impl Pinned {
    /// One line naming what A is.
    pub fn describe(&self) -> String {
        describe(&self.doc, self.precision, self.pow)
    }
}

fn describe(doc: &Document, precision: Precision, pow: PowFn) -> String {
    format!(
        "{}, {} {}, {}, {} pow",
        doc.name,
        doc.view.object.label(),
        doc.view.shading.label(),
        precision.label(),
        pow.label()
    )
}

/// The compare view's state.
#[derive(Default)]
pub struct CompareState {
    /// Compare is shown in the centre.
    pub open: bool,
    /// The pinned scene A.
    pub a: Option<Pinned>,
    /// A's shaded view.
    pub a_view: ViewCache,
    /// B's shaded view.
    pub b_view: ViewCache,
}

/// The steps of two calculations side by side: (step number, title, A's value, B's value,
/// they differ). Steps are matched by kind and light, so a step present in one only shows
/// "n/a" in the other.
pub fn step_pairs(a: &Explanation, b: &Explanation) -> Vec<(usize, String, String, String, bool)> {
    let value = |st: Option<&phonglab_core::explain::Step>| match st.and_then(|s| s.value.as_ref()) {
        Some(v) => fmt_value(v, 8),
        None => "n/a".into(),
    };
    b.steps
        .iter()
        .enumerate()
        .map(|(k, sb)| {
            let sa = a.steps.iter().find(|s| s.kind == sb.kind && s.light == sb.light && s.name == sb.name);
            let differ = sa.map(|s| &s.value) != Some(&sb.value);
            (k + 1, sb.title.clone(), value(sa), value(Some(sb)), differ)
        })
        .collect()
}

fn swatch_ui(ui: &mut Ui, eval: &Evaluated) {
    let c = eval.front.shown;
    let (rect, _) = ui.allocate_exact_size(egui::vec2(40.0, 24.0), egui::Sense::hover());
    ui.painter().rect_filled(rect, 4.0, super::palette::gl_to_color32([c[0], c[1], c[2]]));
}

/// One side of the comparison.
struct Side<'a> {
    /// "A" or "B".
    which: &'a str,
    /// What it is (scene, object, shading, numerics).
    what: String,
    doc: &'a Document,
    eval: &'a Evaluated,
    pow: PowFn,
}

/// One side: its name, colour and shaded view.
fn side_ui(ui: &mut Ui, s: &Side<'_>, view: &mut ViewCache, px: usize) {
    let which = s.which;
    ui.vertical(|ui| {
        ui.label(RichText::new(format!("{which}: {}", s.what)).strong());
        swatch_ui(ui, s.eval);
        ui.label(RichText::new(fmt_value(&s.eval.front.shown, 8)).monospace());
        match view.render(ui.ctx(), s.doc, s.pow, px, which) {
            Ok(()) => {
                if let Some(tex) = &view.texture {
                    let side = px as f32 / ui.ctx().pixels_per_point();
                    let label = ui.small(format!("{which}'s shaded view, {:.1} ms", view.last_ms));
                    ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(label.id);
                }
            }
            Err(e) => {
                ui.colored_label(super::palette::ERROR, format!("{which}'s view cannot render: {e}"));
            }
        }
    });
}

/// The compare view, in the centre.
/// The scene shown (B) and the numerics it is evaluated with.
pub struct Current<'a> {
    /// B's document.
    pub doc: &'a Document,
    /// B's precision.
    pub precision: Precision,
    /// B's power function.
    pub pow: PowFn,
    /// The side the calculation explains.
    pub side: phonglab_core::explain::Side,
}

/// The compare view, in the centre; returns a notice for the app's message line.
pub fn compare_ui(ui: &mut Ui, compare: &mut CompareState, current: &Current<'_>, b: &Evaluated) -> Option<String> {
    let mut notice = None;
    ui.horizontal_wrapped(|ui| {
        ui.heading("Compare");
        let pin = if compare.a.is_some() { "Pin the current scene as A again" } else { "Pin the current scene as A" };
        if ui.button(pin).clicked() {
            compare.a = Some(Pinned { doc: current.doc.clone(), precision: current.precision, pow: current.pow });
            notice = Some("Pinned as A: now change anything, and B follows.".to_string());
        }
        if ui.button("Close compare").clicked() {
            compare.open = false;
        }
    });
    let Some(a) = compare.a.clone() else {
        ui.label("Pin the current scene as A, then change anything (shading, precision, material): A and B show side by side.");
        return notice;
    };
    let a_eval = match evaluate(&a.doc, a.precision, a.pow, current.side) {
        Ok(e) => e,
        Err(e) => {
            ui.colored_label(super::palette::ERROR, format!("A cannot be evaluated: {e}"));
            return notice;
        }
    };
    let avail = ui.available_size();
    let side = ((avail.x - 24.0) / 2.0).min(avail.y * 0.5).max(64.0);
    let px = ((side * ui.ctx().pixels_per_point()) as usize).clamp(64, 1024);
    let b_what = describe(current.doc, current.precision, current.pow);
    let (doc, pow) = (current.doc.clone(), current.pow);
    let sa = Side { which: "A", what: a.describe(), doc: &a.doc, eval: &a_eval, pow: a.pow };
    let sb = Side { which: "B", what: b_what, doc: &doc, eval: b, pow };
    ui.columns(2, |cols| {
        side_ui(&mut cols[0], &sa, &mut compare.a_view, px);
        side_ui(&mut cols[1], &sb, &mut compare.b_view, px);
    });
    ui.separator();
    let pairs = step_pairs(&a_eval.explanation, &b.explanation);
    let differing = pairs.iter().filter(|p| p.4).count();
    ui.label(format!("{differing} of {} steps differ (highlighted).", pairs.len()));
    let hi = if ui.visuals().dark_mode { Color32::from_rgb(90, 60, 0) } else { Color32::from_rgb(255, 224, 150) };
    egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
        // One step after another: its title, then A's value and B's, highlighted where they
        // differ (values wrap rather than run under the next panel).
        for (k, title, va, vb, differ) in pairs {
            ui.label(RichText::new(format!("{k}. {title}")).strong());
            for (who, v) in [("A", va), ("B", vb)] {
                let mut t = RichText::new(format!("{who}  {v}")).monospace();
                if differ {
                    t = t.background_color(hi);
                }
                ui.label(t);
            }
            ui.add_space(2.0);
        }
    });
    notice
}
