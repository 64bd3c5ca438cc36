//! Compare: pin the scene as A, change anything, and see A and B (the current scene) side
//! by side: both shaded views, both colours, and every step of the worked calculation with
//! the ones whose values differ highlighted. Typical pairs: Gouraud against Phong, f32
//! against f64, bronze against gold.

use egui::{Color32, RichText, Ui};
use phonglab_core::explain::{Explanation, fmt_value};
use phonglab_core::{Document, PowFn};

use phonglab_core::difference::{Difference, GAIN, VISIBLE, difference};

use crate::app::editing::evaluated::{Evaluated, Precision, evaluate};
use crate::app::panels::shaded::cache::{ViewCache, Viewed, mesh_for};
use crate::app::panels::shaded::channel_view::{self, ChannelView};
use crate::{locale, t};

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

/// What differs between A and B, one entry per setting: (setting, A's value, B's value),
/// from their scene files key by key, and their numerics.
pub fn differences(a: &Pinned, b: &Pinned) -> Vec<(String, String, String)> {
    let table = |d: &Document| d.to_toml().ok().and_then(|t| t.parse::<toml::Table>().ok()).unwrap_or_default();
    let mut out = Vec::new();
    diff_tables("", &table(&a.doc), &table(&b.doc), &mut out);
    out.retain(|(k, _, _)| k != "name");
    // A material's preset name follows its values: it is said only when nothing else of
    // that material differs.
    let tables: Vec<String> =
        out.iter().filter_map(|(k, _, _)| k.rsplit_once('.').map(|(t, _)| t.to_string())).collect();
    out.retain(|(k, _, _)| {
        k.strip_suffix(".preset").is_none_or(|t| tables.iter().filter(|x| x.as_str() == t).count() == 1)
    });
    if a.precision != b.precision {
        out.push(("precision".into(), a.precision.label().into(), b.precision.label().into()));
    }
    if a.pow != b.pow {
        out.push(("pow".into(), a.pow.label(), b.pow.label()));
    }
    out
}

fn diff_tables(prefix: &str, a: &toml::Table, b: &toml::Table, out: &mut Vec<(String, String, String)>) {
    let mut keys: Vec<&String> = a.keys().chain(b.keys()).collect();
    keys.sort();
    keys.dedup();
    for k in keys {
        let path = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
        match (a.get(k), b.get(k)) {
            (Some(toml::Value::Table(x)), Some(toml::Value::Table(y))) => diff_tables(&path, x, y, out),
            (x, y) if x != y => {
                let show = |v: Option<&toml::Value>| v.map_or("none".to_string(), |v| v.to_string().replace('"', ""));
                out.push((path, show(x), show(y)));
            }
            _ => {}
        }
    }
}

/// The title that names what differs: "B: shininess 10; A: 100" for one setting, the
/// settings' names for several.
pub fn title(diffs: &[(String, String, String)]) -> String {
    let short = |k: &str| k.rsplit('.').next().unwrap_or(k).replace('_', " ");
    match diffs {
        [] => t!("compare-same"),
        [(k, a, b)] => t!("compare-one", setting = short(k), b = locale::decimal(b), a = locale::decimal(a)),
        many if many.len() <= 4 => {
            let names: Vec<String> = many.iter().map(|(k, _, _)| short(k)).collect();
            t!("compare-several", names = names.join(", "))
        }
        many => t!("compare-many", count = many.len()),
    }
}

fn describe(doc: &Document, precision: Precision, pow: PowFn) -> String {
    format!(
        "{}, {} {}, {}, {}",
        phonglab_core::library::localised_name(&doc.name),
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
    /// Show the difference picture `|A - B|` beside them.
    pub difference: bool,
    /// One term shown in place of both pictures, over one shared range.
    pub channel: Option<phonglab_core::channels::Channel>,
    /// A's channel picture.
    pub a_channel: ChannelView,
    /// B's channel picture.
    pub b_channel: ChannelView,
    /// A student's picture diagnosed, shown as B in place of the scenes while it is there.
    pub student: Option<super::student_picture::StudentPicture>,
    /// A student's picture refused: its name and why, shown in place of the scenes.
    pub refused: Option<(String, String)>,
    /// Asked to diagnose the student's picture again, against the scene shown now.
    pub recheck: bool,
    /// The last difference picture, and the pictures' generations it was made from.
    diff: Option<((u64, u64), Difference, egui::TextureHandle)>,
}

impl CompareState {
    /// Pins `doc` as A.
    pub fn pin(&mut self, doc: &Document, precision: Precision, pow: PowFn) {
        self.a = Some(Pinned { doc: doc.clone(), precision, pow });
    }
}

/// The steps of two calculations side by side: (step number, title, A's value, B's value,
/// they differ). Steps are matched by kind and light, so a step present in one only shows
/// "n/a" in the other.
pub fn step_pairs(a: &Explanation, b: &Explanation) -> Vec<(usize, String, String, String, bool)> {
    let value = |st: Option<&phonglab_core::explain::Step>| match st.and_then(|s| s.value.as_ref()) {
        Some(v) => fmt_value(v, 8),
        None => t!("not-applicable"),
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
    ui.painter().rect_filled(rect, 4.0, crate::app::widgets::palette::gl_to_color32([c[0], c[1], c[2]]));
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

/// One side: its name, colour and shaded view; returns where the picture went.
fn side_ui(ui: &mut Ui, s: &Side<'_>, view: &mut ViewCache, px: usize) -> Option<egui::Rect> {
    let which = s.which;
    let mut at = None;
    ui.vertical(|ui| {
        ui.label(RichText::new(format!("{which}: {}", s.what)).strong());
        swatch_ui(ui, s.eval);
        ui.label(RichText::new(locale::decimal(&fmt_value(&s.eval.front.shown, 8))).monospace());
        let mesh = mesh_for(&mut view.mesh, &s.doc.view).clone();
        match view.render(ui.ctx(), Viewed { doc: s.doc, mesh: &mesh }, s.pow, px, which, false) {
            Ok(()) => {
                if let Some(tex) = &view.texture {
                    let side = px as f32 / ui.ctx().pixels_per_point();
                    let label = ui.small(t!(
                        "compare-view",
                        which = which,
                        ms = locale::decimal(&format!("{:.1}", view.last_ms))
                    ));
                    let r = ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(label.id);
                    at = Some(r.rect);
                }
            }
            Err(e) => {
                ui.colored_label(
                    crate::app::widgets::palette::ERROR,
                    t!("compare-cannot-render", which = which, error = e.clone()),
                );
            }
        }
    });
    at
}

/// The difference picture `|A - B|` (amplified by [`GAIN`]) with its legend: how much of
/// the object differs visibly, and the largest difference. Made again only when either
/// picture was; returns where it went.
fn difference_ui(ui: &mut Ui, compare: &mut CompareState, background: [f32; 3], px: usize) -> Option<egui::Rect> {
    let (a, b) = (&compare.a_view, &compare.b_view);
    if a.rgba.len() != b.rgba.len() || a.rgba.is_empty() {
        return None;
    }
    let generations = (a.generation, b.generation);
    if compare.diff.as_ref().is_none_or(|(g, ..)| *g != generations) {
        let bg = background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
        let d = difference(&a.rgba, &b.rgba, bg);
        let size = [a.image_px(), a.image_px()];
        let image = egui::ColorImage::from_rgba_unmultiplied(size, &d.rgba);
        let tex = ui.ctx().load_texture("compare-difference", image, egui::TextureOptions::LINEAR);
        compare.diff = Some((generations, d, tex));
    }
    let (_, d, tex) = compare.diff.as_ref()?;
    let mut at = None;
    ui.vertical(|ui| {
        ui.label(RichText::new(t!("compare-difference-view", gain = GAIN.to_string())).strong());
        let legend = t!(
            "compare-difference-legend",
            gain = GAIN.to_string(),
            full = (256 / GAIN).to_string(),
            percent = locale::decimal(&format!("{:.1}", d.visible_percent())),
            visible = VISIBLE.to_string(),
            largest = d.largest.to_string()
        );
        let label = ui.label(legend);
        let side = px as f32 / ui.ctx().pixels_per_point();
        let r = ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(label.id);
        at = Some(r.rect);
    });
    at
}

/// One term in place of A's and B's pictures, both in false colour over the range that
/// holds both, each with its legend; returns a failure to say.
fn channels_ui(
    ui: &mut Ui,
    compare: &mut CompareState,
    channel: phonglab_core::channels::Channel,
    [(a, a_pow), (b, b_pow)]: [(&Document, PowFn); 2],
    side: f32,
) -> Option<String> {
    let mut range = (f64::INFINITY, f64::NEG_INFINITY);
    let sides = [
        (&mut compare.a_channel, &mut compare.a_view.mesh, a, a_pow),
        (&mut compare.b_channel, &mut compare.b_view.mesh, b, b_pow),
    ];
    for (view, meshes, doc, pow) in sides {
        // Each side's mesh, kept with its picture's.
        let mesh = mesh_for(meshes, &doc.view).clone();
        match view.prepare(doc, &mesh, pow, channel) {
            Ok((lo, hi)) => range = (range.0.min(lo), range.1.max(hi)),
            Err(e) => return Some(t!("compare-cannot-render", which = "A/B", error = e)),
        }
    }
    ui.columns(2, |cols| {
        for (col, (which, view)) in cols.iter_mut().zip([("A", &mut compare.a_channel), ("B", &mut compare.b_channel)])
        {
            col.vertical(|ui| {
                let name_id = view.name_id(channel);
                let label = ui.small(format!("{which}: {}", locale::tr(name_id)));
                if let Some(tex) = view.texture(ui.ctx(), range) {
                    ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(label.id);
                }
                channel_view::legend_ui(ui, channel, name_id, range, side);
            });
        }
    });
    None
}

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
    /// The window's spin ([`super::shaded::ShadedOptions::spun`]): a student's picture is
    /// checked against the scene without it ([`super::student_picture::filed`]).
    pub spun: Option<(f64, f64)>,
}

/// The compare view, in the centre; returns a notice for the app's message line, and where
/// the two pictures went.
pub fn compare_ui(
    ui: &mut Ui,
    compare: &mut CompareState,
    current: &Current<'_>,
    b: &Evaluated,
) -> (Option<String>, Vec<egui::Rect>) {
    if compare.student.is_some() {
        let rects = {
            let filed = super::student_picture::filed(current.doc, current.spun);
            super::student_picture::student_picture_ui(ui, &mut compare.student, &filed, &mut compare.recheck)
        };
        return (None, rects);
    }
    if compare.refused.is_some() {
        super::student_picture::refused_picture_ui(ui, &mut compare.refused);
        return (None, Vec::new());
    }
    let mut notice = None;
    let b_pinned = Pinned { doc: current.doc.clone(), precision: current.precision, pow: current.pow };
    let diffs = compare.a.as_ref().map(|a| differences(a, &b_pinned)).unwrap_or_default();
    ui.horizontal_wrapped(|ui| {
        ui.heading(if compare.a.is_some() { title(&diffs) } else { t!("compare") });
        let pin = if compare.a.is_some() { t!("compare-pin-again") } else { t!("compare-pin") };
        if ui.button(pin).clicked() {
            compare.pin(current.doc, current.precision, current.pow);
            notice = Some(t!("compare-pinned"));
        }
        if ui.button(t!("compare-close")).clicked() {
            compare.open = false;
        }
        if compare.a.is_some() {
            ui.checkbox(&mut compare.difference, t!("compare-difference"))
                .on_hover_text(t!("compare-difference-hover"));
        }
    });
    if let Some(a) = &compare.a {
        // Its own row: a narrow centre keeps it whole. Each term named as A's and B's rules
        // form it.
        let programs = [channel_view::program_of(&a.doc, a.pow), channel_view::program_of(current.doc, current.pow)];
        channel_view::channel_ui(ui, &mut compare.channel, &[&programs[0], &programs[1]]);
    }
    let Some(a) = compare.a.clone() else {
        ui.add_space(12.0);
        for line in [t!("compare-step-1"), t!("compare-step-2"), t!("compare-step-3")] {
            ui.label(RichText::new(line).heading());
        }
        return (notice, Vec::new());
    };
    let a_eval = match evaluate(&a.doc, a.precision, a.pow, current.side) {
        Ok(e) => e,
        Err(e) => {
            ui.colored_label(crate::app::widgets::palette::ERROR, t!("compare-a-fails", error = e.to_string()));
            return (notice, Vec::new());
        }
    };
    let avail = ui.available_size();
    // Two large squares; the steps below get what is left (at least a few lines).
    let row = ui.text_style_height(&egui::TextStyle::Body) * 4.0;
    let n = if compare.difference { 3.0 } else { 2.0 };
    let side = ((avail.x - 12.0 * n) / n).min(avail.y * 0.75 - row).max(64.0);
    let px = ((side * ui.ctx().pixels_per_point()) as usize).clamp(64, 2048);
    let (doc, pow) = (current.doc.clone(), current.pow);
    let sa = Side { which: "A", what: a.describe(), doc: &a.doc, eval: &a_eval, pow: a.pow };
    let sb = Side { which: "B", what: b_pinned.describe(), doc: &doc, eval: b, pow };
    if let Some(channel) = compare.channel {
        return (notice.or(channels_ui(ui, compare, channel, [(&a.doc, a.pow), (&doc, pow)], side)), Vec::new());
    }
    let pictures = ui.columns(n as usize, |cols| {
        let a = side_ui(&mut cols[0], &sa, &mut compare.a_view, px);
        let b = side_ui(&mut cols[1], &sb, &mut compare.b_view, px);
        let d = if compare.difference {
            difference_ui(&mut cols[2], compare, current.doc.view.background, px)
        } else {
            None
        };
        a.into_iter().chain(b).chain(d).collect::<Vec<_>>()
    });
    ui.separator();
    let mut pairs = step_pairs(&a_eval.explanation, &b.explanation);
    let differing = pairs.iter().filter(|p| p.4).count();
    // The steps that differ first, each group in the calculation's order.
    pairs.sort_by_key(|p| !p.4);
    ui.label(if differing == 0 {
        t!("compare-none-differ", all = pairs.len())
    } else {
        t!("compare-differing", differing = differing, all = pairs.len())
    });
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
    (notice, pictures)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_title_names_what_differs() {
        let a = Pinned { doc: Document::default(), precision: Precision::F64, pow: PowFn::Exact };
        let mut b = a.clone();
        assert_eq!(differences(&a, &b), vec![]);
        b.doc.scene.material.shininess = 10.0;
        let d = differences(&a, &b);
        assert_eq!(title(&d), "B: shininess 10.0; A: 25.6", "{d:?}");
        b.precision = Precision::F32;
        b.doc.view.shading = phonglab_core::Shading::Phong;
        let t = title(&differences(&a, &b));
        assert!(t.contains("shininess") && t.contains("shading") && t.contains("precision"), "{t}");
    }
}
