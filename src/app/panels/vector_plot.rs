//! The vector plot: N, L, V, H (R under Phong's model, S the spot axis when on) as arrows
//! from the vertex, in eye space, seen from an orbit the user drags; the angles θ (N, L) and
//! β (N, H) (α (R, V) under Phong's model) drawn as arcs and labelled outside them.
//!
//! Drawn for a projector: arrows at least 3 pixels wide, letters at their tips half as large
//! again as the body text, every label placed clear of the others and of every line
//! ([`crate::app::widgets::label_placement`]), the legend above the diagram rather than over it, the
//! tangent plane as one disc, and no axes or ticks (a small x/y/z triad says how the view is
//! turned). A vector that points at the viewer (or away) is drawn as ⊙ (or ⊗), the way a
//! physics text draws it, rather than as a dot.

use egui::{Color32, Pos2, Rect, Sense, Stroke, Ui, Vec2, vec2};
use glam::{DMat3, DVec3};
use phonglab_core::{SpecularModel, SpecularVector};

use crate::app::editing::evaluated::Evaluated;
use crate::app::widgets::arrows::{draw_arrow, draw_end_on, end_on_marker, paint_labels_fitted};
use crate::app::widgets::label_placement::{Segment, Wanted};
use crate::app::widgets::palette;

/// Orbit of the vector plot: yaw about y, then pitch about x, in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// Degrees about the eye-space y axis.
    pub yaw: f64,
    /// Degrees about the x axis.
    pub pitch: f64,
}

impl Orbit {
    /// Looking down -z: x across, y up.
    pub const XY: Orbit = Orbit { yaw: 0.0, pitch: 0.0 };
    /// Looking down from +y: x across, -z up the screen.
    pub const XZ: Orbit = Orbit { yaw: 0.0, pitch: 90.0 };
    /// Looking from -x: z across (to the right), y up.
    pub const ZY: Orbit = Orbit { yaw: -90.0, pitch: 0.0 };
    /// A three-quarter view.
    pub const PERSPECTIVE: Orbit = Orbit { yaw: 35.0, pitch: 20.0 };
}

impl Default for Orbit {
    /// The three-quarter view.
    fn default() -> Self {
        Orbit::PERSPECTIVE
    }
}

/// Eye space to the plot plane: yaw about y, then pitch about x.
pub fn view_rotation(o: Orbit) -> DMat3 {
    DMat3::from_rotation_x(o.pitch.to_radians()) * DMat3::from_rotation_y(-o.yaw.to_radians())
}

fn project(r: &DMat3, v: DVec3) -> [f64; 2] {
    let p = *r * v;
    [p.x, p.y]
}

/// What the plot drew, for the layout's tests and the screenshot's checks.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotGeometry {
    /// The diagram's square (without its buttons and legend).
    pub rect: Rect,
    /// Points per unit: a unit vector's length on screen.
    pub unit: f32,
    /// Every label's box.
    pub labels: Vec<Rect>,
    /// The arrows' stroke width (points).
    pub stroke: f32,
}

impl Default for PlotGeometry {
    fn default() -> Self {
        PlotGeometry { rect: Rect::NOTHING, unit: 0.0, labels: Vec::new(), stroke: 0.0 }
    }
}

/// One arrow of the diagram.
struct Arrow {
    tag: String,
    v: DVec3,
    color: Color32,
    dashed: bool,
}

/// The arrows: N, V, and each light's L and H (or R) and spot axis.
fn arrows(eval: &Evaluated, specular: SpecularModel, ink: &dyn Fn(Color32) -> Color32) -> Vec<Arrow> {
    let mut out = vec![
        Arrow { tag: "N".into(), v: eval.n, color: ink(palette::N), dashed: false },
        Arrow { tag: "V".into(), v: eval.v, color: ink(palette::V), dashed: false },
    ];
    let many = eval.lights.len() > 1;
    for lv in &eval.lights {
        let tag = if many { lv.index.to_string() } else { String::new() };
        out.push(Arrow { tag: format!("L{tag}"), v: lv.l, color: ink(palette::L), dashed: false });
        let (name, v) = match specular.vector() {
            SpecularVector::Halfway => ("H", lv.h),
            SpecularVector::Reflection => ("R", lv.r),
        };
        out.push(Arrow { tag: format!("{name}{tag}"), v, color: ink(palette::H), dashed: true });
        if let Some(s) = lv.spot {
            out.push(Arrow { tag: format!("S{tag}"), v: s, color: ink(palette::SPOT), dashed: true });
        }
    }
    out.retain(|a| a.v.length() > 0.0);
    out
}

/// The legend's entries: (symbol, the worksheet's name for it, colour, dashed). The
/// symbols are OpenGL's (N, L, V, H); the names the worksheet's code uses.
fn legend(eval: &Evaluated, specular: SpecularModel) -> Vec<(&'static str, String, Color32, bool)> {
    let mut v = vec![
        ("N", "vertexNormal".to_string(), palette::N, false),
        ("L", "vlv".to_string(), palette::L, false),
        ("V", "vov".to_string(), palette::V, false),
        match specular.vector() {
            // In words, the reader's (the sheets' "vetor médio").
            SpecularVector::Halfway => ("H", crate::t!("plot-legend-halfway"), palette::H, true),
            SpecularVector::Reflection => ("R", "R".to_string(), palette::H, true),
        },
    ];
    if eval.lights.iter().any(|l| l.spot.is_some()) {
        v.push(("S", "spot".to_string(), palette::SPOT, true)); // the scene file's name
    }
    v
}

/// The view buttons (XY, XZ, ZY, 3D), in the row the caller opened.
pub fn view_buttons_ui(ui: &mut Ui, orbit: &mut Orbit) {
    ui.label(crate::t!("plot-view"));
    for (name, o) in [("XY", Orbit::XY), ("XZ", Orbit::XZ), ("ZY", Orbit::ZY), ("3D", Orbit::PERSPECTIVE)] {
        if ui.selectable_label(*orbit == o, name).on_hover_text(crate::t!("plot-view-hover", plane = name)).clicked() {
            *orbit = o;
        }
    }
}

/// How a legend entry's sample line is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sample {
    /// A plain line.
    Solid,
    /// A thicker line (the scene's own model among several curves).
    Heavy,
    /// A dashed line (H, R, S; the lobe's L).
    Dashed,
}

/// One legend entry as one label (so that a wrapping row moves it whole): its sample line
/// in `color`, then `symbol` in `color` and `what` in the text's colour. Used by the vector
/// plot's legend and the lobe's.
pub fn legend_entry_ui(ui: &mut Ui, sample: Sample, symbol: &str, what: &str, color: Color32) {
    let body = egui::TextStyle::Body.resolve(ui.style());
    let mono = egui::FontId::monospace(body.size);
    let text = ui.visuals().text_color();
    let c = palette::ink(ui, color);
    let fmt = |font: egui::FontId, color: Color32| egui::TextFormat { font_id: font, color, ..Default::default() };
    let mut job = egui::text::LayoutJob::default();
    let line = match sample {
        Sample::Solid => "\u{2500}\u{2500}",
        Sample::Heavy => "\u{2501}\u{2501}",
        Sample::Dashed => "\u{254C}\u{254C}",
    };
    job.append(line, 0.0, fmt(mono, c));
    if !symbol.is_empty() {
        job.append(symbol, 4.0, fmt(body.clone(), c));
    }
    job.append(what, 4.0, fmt(body.clone(), text));
    ui.label(job);
    ui.add_space(body.size * 0.4);
}

/// The legend, above the diagram: each symbol's line (dashed where the diagram dashes it),
/// letter and meaning.
/// The legend's column when it stands beside the diagram (points).
pub const LEGEND_COLUMN: f32 = 170.0;

fn legend_ui(ui: &mut Ui, entries: &[(&str, String, Color32, bool)]) {
    ui.horizontal_wrapped(|ui| {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        for (sym, what, c, dashed) in entries {
            legend_entry_ui(ui, if *dashed { Sample::Dashed } else { Sample::Solid }, sym, what, *c);
        }
    });
}

/// The small triad in the diagram's corner: where eye space's x, y and z point.
fn triad(p: &egui::Painter, r: &DMat3, origin: Pos2, len: f32, color: Color32, font: egui::FontId) -> Vec<Segment> {
    let mut out = Vec::new();
    for (name, axis) in [("x", DVec3::X), ("y", DVec3::Y), ("z", DVec3::Z)] {
        let [x, y] = project(r, axis);
        let to = origin + vec2(x as f32, -y as f32) * len;
        if (to - origin).length() > 2.0 {
            p.line_segment([origin, to], Stroke::new(1.5, color));
            p.text(to + (to - origin).normalized() * 7.0, egui::Align2::CENTER_CENTER, name, font.clone(), color);
        } else {
            draw_end_on(p, origin, 5.0, 1.5, color, (*r * axis).z > 0.0);
            p.text(origin + vec2(9.0, -9.0), egui::Align2::CENTER_CENTER, name, font.clone(), color);
        }
        out.push(Segment { a: origin, b: to, half_width: 6.0 });
    }
    out
}

/// Points along the arc from `a` to `b` (unit vectors) at `radius`, projected; and the
/// arc's middle direction.
fn arc(r: &DMat3, a: DVec3, b: DVec3, radius: f64) -> Option<(Vec<[f64; 2]>, [f64; 2], f64)> {
    let (a, b) = (a.try_normalize()?, b.try_normalize()?);
    let angle = a.dot(b).clamp(-1.0, 1.0).acos();
    let axis = a.cross(b).try_normalize().unwrap_or_else(|| a.any_orthonormal_vector());
    let pts =
        (0..=24).map(|i| project(r, DMat3::from_axis_angle(axis, angle * i as f64 / 24.0) * a * radius)).collect();
    let mid = project(r, DMat3::from_axis_angle(axis, angle / 2.0) * a * radius);
    Some((pts, mid, angle))
}

/// The plot: its legend and the diagram, in the space given (the view buttons,
/// [`view_buttons_ui`], go in the row above it). θ and β are labelled when `show_angles`
/// (the quiz hides them). Returns what was drawn.
pub fn vector_plot_ui(
    ui: &mut Ui,
    orbit: &mut Orbit,
    eval: &Evaluated,
    specular: SpecularModel,
    show_angles: bool,
) -> PlotGeometry {
    let entries = legend(eval, specular);
    // A part wider than high by a legend's column has the legend beside the diagram (a
    // diagram below two pictures), otherwise above it.
    let (outer, side) = if ui.available_width() >= ui.available_height() + LEGEND_COLUMN {
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| {
                ui.set_width(LEGEND_COLUMN - ui.spacing().item_spacing.x);
                legend_ui(ui, &entries);
            });
            plot_area_ui(ui, orbit)
        })
        .inner
    } else {
        legend_ui(ui, &entries);
        plot_area_ui(ui, orbit)
    };
    let rect = Rect::from_center_size(outer.center(), Vec2::splat(side));
    let bg = ui.visuals().panel_fill;
    let ink = |c: Color32| palette::ink_on(c, bg);
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let ppp = ui.ctx().pixels_per_point();
    // Room beyond a unit vector's tip for its letter.
    let unit = side * 0.5 / 1.2;
    let canvas = Canvas {
        painter: ui.painter_at(outer),
        r: view_rotation(*orbit),
        centre: rect.center(),
        unit,
        width: (3.2 / ppp).max(unit * 0.022),
    };
    let mut marks = Marks::default();
    canvas.tangent_plane(eval.n, ink(palette::N));
    canvas.arrows(&arrows(eval, specular, &ink), egui::FontId::proportional(body * 1.6), &mut marks);
    canvas.painter.circle_filled(canvas.centre, canvas.width * 1.2, ink(palette::N));
    if show_angles && let Some(lv) = eval.lights.first() {
        let second = match specular.vector() {
            SpecularVector::Halfway => ("\u{3b2}", eval.n, lv.h),
            SpecularVector::Reflection => ("\u{3b1}", lv.r, eval.v),
        };
        let font = egui::FontId::proportional(body * 1.5);
        canvas.angle(0.3, ("\u{3b8}", eval.n, lv.l), ink(palette::L), font.clone(), &mut marks);
        canvas.angle(0.5, second, ink(palette::H), font, &mut marks);
    }

    // The triad, bottom left.
    let small = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Small));
    let grey = ink(Color32::from_gray(140));
    let origin = rect.left_bottom() + vec2(side * 0.08, -side * 0.08);
    marks.lines.extend(triad(&canvas.painter, &canvas.r, origin, side * 0.06, grey, small));

    // Every label, placed clear of every other and of every line; labels may use the whole
    // width given, beyond the square.
    let boxes = paint_labels_fitted(&canvas.painter, marks.wanted, marks.texts, &marks.lines, outer, None);
    PlotGeometry { rect, unit, labels: boxes, stroke: canvas.width }
}

/// The plot's area (the whole width given, as high as the square it holds) and the square's
/// side; dragged, it turns the view.
fn plot_area_ui(ui: &mut Ui, orbit: &mut Orbit) -> (Rect, f32) {
    let avail = ui.available_size();
    // As large as the part allows, and never wider than it.
    let side = avail.x.min(avail.y).max(40.0).min(avail.x.max(1.0));
    let (outer, resp) = ui.allocate_exact_size(vec2(avail.x.max(side), side), Sense::click_and_drag());
    resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Canvas, true, "vector plot"));
    crate::app::widgets::hint::above_pointer(
        &resp,
        crate::t!("plot-drag", yaw = format!("{:.0}", orbit.yaw), pitch = format!("{:.0}", orbit.pitch)),
    );
    if resp.dragged() {
        let d = resp.drag_delta();
        orbit.yaw = (orbit.yaw + d.x as f64 * 0.5).rem_euclid(360.0);
        orbit.pitch = (orbit.pitch + d.y as f64 * 0.5).clamp(-90.0, 90.0);
    }
    (outer, side)
}

/// Where the diagram is drawn: its painter, the view's rotation, the vertex on screen, the
/// length of a unit vector and the arrows' width (points).
struct Canvas {
    painter: egui::Painter,
    r: DMat3,
    centre: Pos2,
    unit: f32,
    width: f32,
}

/// What the labels must stay clear of (every line drawn), and the labels to place: each
/// one's anchor and its text, colour and font.
#[derive(Default)]
struct Marks {
    lines: Vec<Segment>,
    wanted: Vec<Wanted>,
    texts: Vec<(String, Color32, egui::FontId)>,
}

impl Canvas {
    /// A point of the plot plane on screen.
    fn at(&self, v: [f64; 2]) -> Pos2 {
        self.centre + vec2(v[0] as f32, -(v[1] as f32)) * self.unit
    }

    /// The tangent plane: the unit disc perpendicular to `n`.
    fn tangent_plane(&self, n: DVec3, color: Color32) {
        let Some(n) = n.try_normalize() else { return };
        let (a, b) = n.any_orthonormal_pair();
        let pts: Vec<Pos2> = (0..72)
            .map(|i| i as f64 / 72.0 * std::f64::consts::TAU)
            .map(|t| self.at(project(&self.r, a * t.cos() + b * t.sin())))
            .collect();
        self.painter.add(egui::Shape::convex_polygon(pts.clone(), color.gamma_multiply(0.10), Stroke::NONE));
        self.painter.add(egui::Shape::closed_line(pts, Stroke::new(1.0, color.gamma_multiply(0.5))));
    }

    /// The arrows from the vertex (⊙ or ⊗ for one seen end on), and each one's letter to
    /// place.
    fn arrows(&self, arrows: &[Arrow], font: egui::FontId, marks: &mut Marks) {
        let mut end_on = 0;
        for a in arrows {
            let v = a.v.normalize_or_zero();
            let [x, y] = project(&self.r, v);
            let z = (self.r * v).z;
            let tip = self.at([x, y]);
            if (x * x + y * y).sqrt() < 0.15 {
                // End on: ⊙ or ⊗ at the vertex, its letter beside it.
                let (line, label) = end_on_marker(&self.painter, self.centre, end_on, self.width, a.color, z > 0.0);
                end_on += 1;
                marks.lines.push(line);
                marks.wanted.push(label);
            } else {
                let line = draw_arrow(&self.painter, self.centre, tip, self.width, a.color, a.dashed, z < -1e-9);
                marks.lines.push(line);
                marks.wanted.push(Wanted {
                    anchor: tip,
                    direction: tip - self.centre,
                    size: Vec2::ZERO,
                    gap: self.width,
                });
            }
            marks.texts.push((a.tag.clone(), a.color, font.clone()));
        }
    }

    /// The angle `name` between `a` and `b` as an arc of `radius`, its label (the angle in
    /// degrees) outside it.
    fn angle(
        &self,
        radius: f64,
        (name, a, b): (&str, DVec3, DVec3),
        color: Color32,
        font: egui::FontId,
        marks: &mut Marks,
    ) {
        let Some((pts, mid, angle)) = arc(&self.r, a, b, radius) else { return };
        let pts: Vec<Pos2> = pts.iter().map(|p| self.at(*p)).collect();
        for w in pts.windows(2) {
            marks.lines.push(Segment { a: w[0], b: w[1], half_width: 1.0 });
        }
        self.painter.add(egui::Shape::line(pts, Stroke::new(1.5, color)));
        let m = self.at(mid);
        let out = if (m - self.centre).length() > 1.0 { m - self.centre } else { vec2(1.0, -1.0) };
        marks.wanted.push(Wanted { anchor: m, direction: out, size: Vec2::ZERO, gap: 4.0 });
        let text = crate::locale::decimal(&format!("{name} = {:.1}\u{b0}", angle.to_degrees()));
        marks.texts.push((text, color, font));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_named_views_show_their_planes() {
        let p = |o, v| project(&view_rotation(o), v);
        let close = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12;
        assert!(close(p(Orbit::XY, DVec3::new(1.0, 2.0, 3.0)), [1.0, 2.0]));
        // XZ: looking down from +y, z towards the viewer points down the screen.
        assert!(close(p(Orbit::XZ, DVec3::new(1.0, 2.0, 3.0)), [1.0, -3.0]));
        // ZY: z across, y up.
        assert!(close(p(Orbit::ZY, DVec3::new(1.0, 2.0, 3.0)), [3.0, 2.0]));
    }

    #[test]
    fn an_arc_spans_its_angle() {
        let r = view_rotation(Orbit::XY);
        let (pts, mid, angle) = arc(&r, DVec3::Y, DVec3::X, 0.5).unwrap();
        assert!((angle - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!((pts[0][1] - 0.5).abs() < 1e-12 && (pts[24][0] - 0.5).abs() < 1e-12);
        assert!((mid[0] - mid[1]).abs() < 1e-12 && mid[0] > 0.0);
    }
}
