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

fn arrow<'a>(r: &DMat3, name: &str, v: DVec3, c: Color32) -> Option<Arrows<'a>> {
    (v.length() > 0.0).then(|| {
        Arrows::new(name.to_string(), vec![[0.0, 0.0]], vec![project(r, v)]).color(depth_tint(r, v, c)).tip_length(12.0)
    })
}

/// The arc from `a` to `b` (unit vectors) at radius `radius`, and its label.
fn angle_arc<'a>(r: &DMat3, name: &str, a: DVec3, b: DVec3, radius: f64, c: Color32) -> Option<(Line<'a>, Text)> {
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
    Some((Line::new("", PlotPoints::from(pts)).color(c).width(1.5), Text::new("", p.into(), label).color(c)))
}

/// The plot and its view buttons.
pub fn vector_plot_ui(ui: &mut Ui, orbit: &mut Orbit, eval: &Evaluated, specular: SpecularModel) {
    ui.horizontal(|ui| {
        ui.label("View:");
        for (name, o) in [("XY", Orbit::XY), ("XZ", Orbit::XZ), ("ZY", Orbit::ZY), ("3D", Orbit::PERSPECTIVE)] {
            if ui.selectable_label(*orbit == o, name).on_hover_text(format!("Look at the {name} plane")).clicked() {
                *orbit = o;
            }
        }
        ui.small(format!("yaw {:.0} deg, pitch {:.0} deg: drag the plot to orbit", orbit.yaw, orbit.pitch));
    });
    let r = view_rotation(*orbit);
    let first = eval.lights.first().copied();
    let side = ui.available_width().min(ui.available_height() - 4.0).max(120.0);
    let response = Plot::new("vector plot")
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
        .legend(Legend::default())
        .sense(egui::Sense::click_and_drag())
        .show(ui, |p| {
            let circle: Vec<[f64; 2]> =
                (0..=96).map(|i| i as f64 / 96.0 * std::f64::consts::TAU).map(|t| [t.cos(), t.sin()]).collect();
            p.line(Line::new("", PlotPoints::from(circle)).color(Color32::GRAY).width(1.0));
            let many = eval.lights.len() > 1;
            if let Some(a) = arrow(&r, "N", eval.n, palette::N) {
                p.add(a);
            }
            if let Some(a) = arrow(&r, "V", eval.v, palette::V) {
                p.add(a);
            }
            for lv in &eval.lights {
                let sfx = if many { format!(" (light {})", lv.index) } else { String::new() };
                if let Some(a) = arrow(&r, &format!("L{sfx}"), lv.l, palette::L) {
                    p.add(a);
                }
                let (name, vec, c) = match specular {
                    SpecularModel::BlinnPhong => ("H", lv.h, palette::H),
                    SpecularModel::Phong => ("R", lv.r, palette::R),
                };
                if let Some(a) = arrow(&r, &format!("{name}{sfx}"), vec, c) {
                    p.add(a);
                }
                if let Some(s) = lv.spot
                    && let Some(a) = arrow(&r, &format!("S, spot axis{sfx}"), s, palette::SPOT)
                {
                    p.add(a);
                }
            }
            if let Some(lv) = first {
                if let Some((line, text)) = angle_arc(&r, "\u{3b8}", eval.n, lv.l, 0.35, palette::L) {
                    p.line(line);
                    p.text(text);
                }
                let beta = match specular {
                    SpecularModel::BlinnPhong => angle_arc(&r, "\u{3b2}", eval.n, lv.h, 0.55, palette::H),
                    SpecularModel::Phong => angle_arc(&r, "\u{3b1}", lv.r, eval.v, 0.55, palette::R),
                };
                if let Some((line, text)) = beta {
                    p.line(line);
                    p.text(text);
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
}
