//! The vector plot: N, L, V, H (R for Phong, the spot axis when on) as arrows from the
//! vertex, in eye space, seen from an orbit the user drags; the angles theta (N, L) and
//! beta (N, H) (alpha (R, V) for Phong) drawn as arcs and labelled.

use egui::{Color32, Ui};
use egui_plot::{Arrows, Legend, Line, Plot, PlotPoints, Text};
use glam::{DMat3, DVec3};
use phonglab_core::SpecularModel;

use super::palette;
use super::state::{Evaluated, Orbit};

/// Eye space to the plot plane: yaw about y, then pitch about x.
pub fn view_rotation(o: Orbit) -> DMat3 {
    DMat3::from_rotation_x(o.pitch.to_radians()) * DMat3::from_rotation_y(-o.yaw.to_radians())
}

fn project(r: &DMat3, v: DVec3) -> [f64; 2] {
    let p = *r * v;
    [p.x, p.y]
}

/// Vectors pointing away from the viewer are drawn fainter.
fn depth_tint(r: &DMat3, v: DVec3, c: Color32) -> Color32 {
    if (*r * v).z < -1e-9 { c.gamma_multiply(0.45) } else { c }
}

/// The arrow from the vertex to `v` and its label just beyond its tip (`tag`, e.g. "L" or
/// "L1"), in its symbol's colour.
fn arrow<'a>(r: &DMat3, name: &str, tag: &str, v: DVec3, c: Color32) -> Option<(Arrows<'a>, Text)> {
    (v.length() > 0.0).then(|| {
        let c = depth_tint(r, v, c);
        let tip = project(r, v);
        let label = project(r, v * 1.16);
        let text = Text::new("", label.into(), egui::RichText::new(tag).strong().size(16.0)).color(c);
        (Arrows::new(name.to_string(), vec![[0.0, 0.0]], vec![tip]).color(c).tip_length(12.0), text)
    })
}

/// The tangent plane at the vertex (perpendicular to N), drawn as a disc of radius 1.2
/// seen from the orbit: θ and β are measured from N, up from this plane's normal.
fn tangent_plane<'a>(r: &DMat3, n: DVec3, c: Color32) -> Option<egui_plot::Polygon<'a>> {
    let n = n.try_normalize()?;
    let (a, b) = n.any_orthonormal_pair();
    let pts: Vec<[f64; 2]> = (0..64)
        .map(|i| i as f64 / 64.0 * std::f64::consts::TAU)
        .map(|t| project(r, (a * t.cos() + b * t.sin()) * 1.2))
        .collect();
    Some(
        egui_plot::Polygon::new("tangent plane", PlotPoints::from(pts))
            .fill_color(c.gamma_multiply(0.12))
            .stroke(egui::Stroke::new(1.0, c.gamma_multiply(0.6))),
    )
}

/// The arc from `a` to `b` (unit vectors) at radius `radius`, and its label.
fn angle_arc<'a>(
    r: &DMat3,
    name: &str,
    a: DVec3,
    b: DVec3,
    radius: f64,
    c: Color32,
) -> Option<(Line<'a>, String, [f64; 2])> {
    let (a, b) = (a.try_normalize()?, b.try_normalize()?);
    let angle = a.dot(b).clamp(-1.0, 1.0).acos();
    let axis = a.cross(b).try_normalize().unwrap_or_else(|| a.any_orthonormal_vector());
    let pts: Vec<[f64; 2]> = (0..=24)
        .map(|i| {
            let t = angle * i as f64 / 24.0;
            project(r, DMat3::from_axis_angle(axis, t) * a * radius)
        })
        .collect();
    let mid = DMat3::from_axis_angle(axis, angle / 2.0) * a * (radius + 0.12);
    let label = format!("{name} = {:.1}\u{b0}", angle.to_degrees());
    let p = project(r, mid);
    // Unnamed items stay out of the legend.
    Some((Line::new("", PlotPoints::from(pts)).color(c).width(1.5), label, p))
}

/// Where the second angle's label goes so that it stays clear of the first's: both are
/// boxes `size` (plot units) centred on their points; the second is pushed outwards along
/// its own direction until the boxes no longer overlap.
pub fn clear_of(first: [f64; 2], second: [f64; 2], size: [f64; 2]) -> [f64; 2] {
    let overlaps = |p: [f64; 2]| (p[0] - first[0]).abs() < size[0] && (p[1] - first[1]).abs() < size[1];
    let len = (second[0] * second[0] + second[1] * second[1]).sqrt();
    let dir = if len > 1e-9 { [second[0] / len, second[1] / len] } else { [0.0, 1.0] };
    let step = size[0].min(size[1]) * 0.25;
    let mut p = second;
    let mut k = 0;
    while overlaps(p) && k < 200 {
        p = [p[0] + dir[0] * step, p[1] + dir[1] * step];
        k += 1;
    }
    if overlaps(p) {
        // Straight below the first when pushing along the direction does not help.
        p = [first[0], first[1] - size[1]];
    }
    p
}

/// The plot and its view buttons.
pub fn vector_plot_ui(ui: &mut Ui, orbit: &mut Orbit, eval: &Evaluated, specular: SpecularModel) {
    ui.horizontal_wrapped(|ui| {
        ui.label("View:");
        for (name, o) in [("XY", Orbit::XY), ("XZ", Orbit::XZ), ("ZY", Orbit::ZY), ("3D", Orbit::PERSPECTIVE)] {
            if ui.selectable_label(*orbit == o, name).on_hover_text(format!("Look at the {name} plane")).clicked() {
                *orbit = o;
            }
        }
        ui.add(
            egui::Label::new(egui::RichText::new(format!("yaw {:.0}°, pitch {:.0}°", orbit.yaw, orbit.pitch)).small())
                .wrap_mode(egui::TextWrapMode::Extend),
        )
        .on_hover_text("Drag the plot to orbit");
    });
    let r = view_rotation(*orbit);
    let dark = ui.visuals().dark_mode;
    let ink = |c: Color32| if dark { c } else { palette::darker(c) };
    let first = eval.lights.first().copied();
    let side = (ui.available_height() - 8.0).max(120.0);
    // The legend (which can hide an arrow) only where it fits: the tips are labelled anyway.
    let entries = 3 + eval.lights.iter().map(|l| 2 + l.spot.is_some() as usize).sum::<usize>();
    let row = ui.text_style_height(&egui::TextStyle::Body) + 4.0;
    let show_legend = side >= 48.0 + entries as f32 * (row + 4.0);
    // An angle label's size in plot units: about 10 characters of 14-point text, on a plot
    // about 3.2 units across `side` points (the label is drawn at 14 points, scaled with the
    // presentation's zoom as text is).
    let units_per_point = 3.2 / side as f64;
    let label_box = [10.0 * 0.6 * 14.0 * units_per_point, 18.0 * units_per_point];
    let mut plot = Plot::new("vector plot")
        .width(ui.available_width())
        .height(side)
        .data_aspect(1.0)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .allow_double_click_reset(false)
        .include_x(-1.4)
        .include_x(1.4)
        .include_y(-1.4)
        .include_y(1.4)
        .sense(egui::Sense::click_and_drag());
    if show_legend {
        plot = plot.legend(Legend::default());
    }
    let response = plot.show(ui, |p| {
        let circle: Vec<[f64; 2]> =
            (0..=96).map(|i| i as f64 / 96.0 * std::f64::consts::TAU).map(|t| [t.cos(), t.sin()]).collect();
        p.line(Line::new("", PlotPoints::from(circle)).color(Color32::GRAY).width(1.0));
        let many = eval.lights.len() > 1;
        if let Some(plane) = tangent_plane(&r, eval.n, ink(palette::N)) {
            p.add(plane);
        }
        let put = |p: &mut egui_plot::PlotUi<'_>, a: Option<(Arrows<'static>, Text)>| {
            if let Some((a, t)) = a {
                p.add(a);
                p.text(t);
            }
        };
        put(p, arrow(&r, "N", "N", eval.n, ink(palette::N)));
        put(p, arrow(&r, "V", "V", eval.v, ink(palette::V)));
        for lv in &eval.lights {
            let sfx = if many { format!(" (light {})", lv.index) } else { String::new() };
            let tag = if many { lv.index.to_string() } else { String::new() };
            put(p, arrow(&r, &format!("L{sfx}"), &format!("L{tag}"), lv.l, ink(palette::L)));
            let (name, vec, c) = match specular {
                SpecularModel::BlinnPhong => ("H", lv.h, palette::H),
                SpecularModel::Phong => ("R", lv.r, palette::R),
            };
            put(p, arrow(&r, &format!("{name}{sfx}"), &format!("{name}{tag}"), vec, ink(c)));
            if let Some(s) = lv.spot {
                put(p, arrow(&r, &format!("S, spot axis{sfx}"), &format!("S{tag}"), s, ink(palette::SPOT)));
            }
        }
        if let Some(lv) = first {
            let theta = angle_arc(&r, "\u{3b8}", eval.n, lv.l, 0.35, ink(palette::L));
            let beta = match specular {
                SpecularModel::BlinnPhong => angle_arc(&r, "\u{3b2}", eval.n, lv.h, 0.6, ink(palette::H)),
                SpecularModel::Phong => angle_arc(&r, "\u{3b1}", lv.r, eval.v, 0.6, ink(palette::R)),
            };
            let label = |text: String, at: [f64; 2], c: Color32| {
                Text::new("", at.into(), egui::RichText::new(text).size(14.0)).color(c)
            };
            let theta_at = theta.as_ref().map(|t| t.2);
            if let Some((line, text, at)) = theta {
                p.line(line);
                p.text(label(text, at, ink(palette::L)));
            }
            if let Some((line, text, at)) = beta {
                p.line(line);
                let at = theta_at.map_or(at, |t| clear_of(t, at, label_box));
                let c = if specular == SpecularModel::BlinnPhong { palette::H } else { palette::R };
                p.text(label(text, at, ink(c)));
            }
        }
    });
    let resp = &response.response;
    if resp.dragged() {
        let d = resp.drag_delta();
        orbit.yaw = (orbit.yaw + d.x as f64 * 0.5).rem_euclid(360.0);
        orbit.pitch = (orbit.pitch + d.y as f64 * 0.5).clamp(-90.0, 90.0);
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
    fn angle_labels_are_kept_apart() {
        let d = |a: [f64; 2], b: [f64; 2]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
        // The worksheet's theta and beta labels nearly coincide in the XY view.
        let size = [0.4, 0.1];
        let apart = |a: [f64; 2], c: [f64; 2]| (a[0] - c[0]).abs() >= size[0] || (a[1] - c[1]).abs() >= size[1];
        for (a, b) in [([0.3, 0.2], [0.31, 0.21]), ([0.0, 0.0], [0.0, 0.0]), ([0.5, 0.1], [0.3, 0.15])] {
            let c = clear_of(a, b, size);
            assert!(apart(a, c), "{a:?} {b:?} -> {c:?}");
            assert!(d(b, c) < 1.0, "not pushed far: {b:?} -> {c:?}");
        }
        assert_eq!(clear_of([0.5, 0.1], [0.1, 0.5], size), [0.1, 0.5], "already clear: left alone");
    }
}
