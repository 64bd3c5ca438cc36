//! The reflection lobe: how much light the vertex sends towards each direction of view,
//! for the current material, the first light and its angle of incidence.
//!
//! The view direction turns in the plane of N and L, at the angle φ from N (positive on the
//! side away from L, where the mirror direction R lies at φ = θ). For each φ:
//!
//! | curve | formula |
//! |---|---|
//! | diffuse | kd · max(N·L, 0), the same towards every viewer |
//! | Blinn-Phong | ks · max(N·H, 0)^n, H = normalize(L + V) |
//! | Phong | ks · max(R·V, 0)^n, R = 2 (N·L) N − L |
//! | normalised Blinn-Phong (drawn when it is the scene's) | Blinn-Phong's · (n + 8)/(8π) |
//!
//! kd and ks are the luminances (Rec. 709 weights) of the material's colour times the
//! light's, so the curves are in the units of the vertex colour; where that product is grey
//! they are the material's own coefficients, and otherwise the caption says what was
//! weighed (the Phong demo's red: kd = 0.4 weighed on [0.4 0 0] is 0.08504). Both specular curves are 0
//! when N·L ≤ 0 (OpenGL's gate). A polar plot draws the lobes around N; a plot against φ
//! marks with a vertical line where the vertex's own V lies.

use egui::{Color32, Ui};
use egui_plot::{Line, Plot, PlotPoints, VLine};
use glam::DVec3;
use phonglab_core::lighting::terms;
use phonglab_core::{PowFn, Scene, SpecularGate, SpecularVector};

use crate::app::editing::evaluated::Evaluated;
use crate::app::widgets::palette;

/// Luminance of the product of two colours' rgb.
fn luminance(a: glam::DVec4, b: glam::DVec4) -> f64 {
    palette::linear_luminance((a * b).truncate().to_array())
}

/// The lobe of one light at one incidence, in the plane of N and L.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lobe {
    /// The angle of incidence θ, radians (between N and L).
    pub theta: f64,
    /// kd: diffuse luminance.
    pub kd: f64,
    /// ks: specular luminance.
    pub ks: f64,
    /// The shininess n.
    pub n: f64,
}

impl Lobe {
    /// Unit vectors in the plane: N = +y, L at −θ (to the left), V at φ.
    fn dir(angle: f64) -> DVec3 {
        DVec3::new(angle.sin(), angle.cos(), 0.0)
    }

    /// N, L and V in the lobe's plane, and n·L.
    fn vectors(&self, phi: f64) -> (DVec3, DVec3, DVec3, f64) {
        let (n, l, v) = (DVec3::Y, Self::dir(-self.theta), Self::dir(phi));
        (n, l, v, n.dot(l))
    }

    /// The diffuse term towards φ (the same for every φ): kd max(n·L, 0), the engine's own
    /// factor.
    pub fn diffuse(&self) -> f64 {
        let (_, _, _, n_dot_l) = self.vectors(0.0);
        self.kd * terms::shared_factors(n_dot_l, true, false, 0.0).0
    }

    /// A specular term of cosine `cos` as the engine forms it: OpenGL's gate (no specular
    /// from a light behind the surface), then ks max(cos, 0)^n.
    fn specular(&self, n_dot_l: f64, cos: f64) -> f64 {
        let allowed = terms::specular_allowed(SpecularGate::LitSide, n_dot_l, cos);
        let p = PowFn::Exact.pow::<f64>(cos.max(0.0), self.n);
        self.ks * terms::shared_factors(n_dot_l, true, allowed, p).1
    }

    /// The Blinn-Phong specular term towards φ: the engine's H = normalize(L + V).
    pub fn blinn(&self, phi: f64) -> f64 {
        let (n, l, v, n_dot_l) = self.vectors(phi);
        match terms::halfway::<f64>(l, v) {
            Some(h) => self.specular(n_dot_l, n.dot(h)),
            None => 0.0,
        }
    }

    /// Energy-conserving Blinn-Phong's term towards φ: Blinn-Phong's times the engine's own
    /// `(n + 8) / (8 pi)`.
    pub fn blinn_normalised(&self, phi: f64) -> f64 {
        self.blinn(phi) * terms::specular_normalisation(self.n)
    }

    /// The Phong specular term towards φ: the engine's R = 2 (n·L) n − L.
    pub fn phong(&self, phi: f64) -> f64 {
        let (n, l, v, n_dot_l) = self.vectors(phi);
        self.specular(n_dot_l, terms::reflect::<f64>(n, l, false).dot(v))
    }

    /// The lobe of the scene's first light at the evaluated vertex, with the signed angle
    /// φ of the vertex's V in the plane of N and L (`None` when there is no light or N, L
    /// are undefined).
    pub fn of(scene: &Scene, eval: &Evaluated) -> Option<(Lobe, f64)> {
        let lv = eval.lights.first()?;
        let light = scene.lights.get(lv.index)?;
        let n = eval.n.try_normalize()?;
        let l = lv.l.try_normalize()?;
        let theta = n.dot(l).clamp(-1.0, 1.0).acos();
        let m = &scene.material;
        let lobe = Lobe {
            theta,
            kd: luminance(m.diffuse, light.diffuse),
            ks: luminance(m.specular, light.specular),
            n: m.shininess,
        };
        // The tangent in the plane, pointing away from L (towards R).
        let t = (-(l - l.dot(n) * n)).try_normalize().unwrap_or_else(|| n.any_orthonormal_vector());
        let v = eval.v;
        let phi = v.dot(t).atan2(v.dot(n));
        Some((lobe, phi))
    }
}

const STEPS: usize = 180;

/// One curve: its name, colour, (φ, value) points, and whether it is the scene's model.
type Curve = (String, Color32, Vec<(f64, f64)>, bool);

fn sweep(f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    (0..=STEPS)
        .map(|i| {
            let phi = (i as f64 / STEPS as f64 - 0.5) * std::f64::consts::PI;
            (phi, f(phi))
        })
        .collect()
}

/// kd or ks as the caption says it: the material's own value where the product of the
/// material's and the light's colours is grey, otherwise the luminance and what it weighs.
fn coefficient(name: &str, product: glam::DVec3, value: f64) -> String {
    let grey = (product.x - product.y).abs() < 1e-12 && (product.y - product.z).abs() < 1e-12;
    if grey {
        format!("{name} = {}", fmt(value))
    } else {
        let colour = format!("[{} {} {}]", fmt(product.x), fmt(product.y), fmt(product.z));
        crate::t!("lobe-luminance", name = name, value = fmt(value), colour = colour)
    }
}

fn fmt(x: f64) -> String {
    crate::locale::num(x, 4)
}

/// The least side of each of the two plots (points): below it they scroll, rather than
/// shrink to nothing (after Ctrl + or in a small window). Under the column's width at
/// 1024x600 (about 175 points), so that there the plots fit it whole.
pub const MIN_PLOT: f32 = 140.0;

/// The legend, above the plots rather than over the curves (the scene's own model's curve
/// heavy, as in the plots; L dashed, as its ray is).
fn legend_ui(ui: &mut Ui, curves: &[Curve]) {
    use crate::app::panels::vector_plot::{Sample, legend_entry_ui};
    ui.horizontal_wrapped(|ui| {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        for (name, c, _, on) in curves {
            legend_entry_ui(ui, if *on { Sample::Heavy } else { Sample::Solid }, "", name, *c);
        }
        // The rays on a row of their own: at the end of the curves' row the last one was cut
        // by the column's edge (N, at 1024x600 with four curves).
        ui.end_row();
        for (name, c, sample) in
            [("N", palette::N, Sample::Solid), ("L", palette::L, Sample::Dashed), ("V", palette::V, Sample::Solid)]
        {
            legend_entry_ui(ui, sample, name, "", c);
        }
    });
}

/// How far the polar plot's rays (N, L, V) reach: just past the largest curve, so that the
/// plot's bounds are the lobe's.
fn polar_reach(curves: &[Curve]) -> f64 {
    1.1 * curves.iter().flat_map(|c| c.2.iter().map(|(_, r)| *r)).fold(1e-3, f64::max)
}

/// Where the lobe was drawn (for the tests): the visible part of its column, its legend
/// and its two plots (each the plot's frame, without its axes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LobeGeometry {
    /// The part of the column that is on screen.
    pub visible: egui::Rect,
    /// The legend above the plots.
    pub legend: egui::Rect,
    /// The polar plot.
    pub polar: egui::Rect,
    /// The plot against φ.
    pub against: egui::Rect,
}

/// The room kept free at the column's right edge (points): a plot's frame and the legend's
/// last letter stand clear of the panel's border.
const RIGHT_MARGIN: f32 = 6.0;

/// The diffuse curve's colour: a neutral grey, the same towards every viewer (in L's
/// vermillion it was hard to tell from Phong's orange in the light theme, both darkened).
const DIFFUSE: Color32 = Color32::from_gray(160);

/// The normalised Blinn-Phong curve's colour (Okabe-Ito sky blue): told apart from plain
/// Blinn-Phong's (H's reddish purple) by colour, not only by width.
const NORMALISED: Color32 = Color32::from_rgb(0x56, 0xB4, 0xE9);

/// The curves of `lobe`, each in its colour as drawn on `bg` (at a text's contrast, so the
/// legend's swatches read in the light theme too): the diffuse, Blinn-Phong, Phong, and
/// the normalised Blinn-Phong where it is the scene's (its factor, up to 4 at n = 100,
/// would rescale the others). The scene's own model's curve is marked to be drawn heavy.
fn curves_of(lobe: &Lobe, scene: &Scene, bg: Color32) -> Vec<Curve> {
    let ink = |c: Color32| palette::ink_with_contrast(c, bg, palette::TEXT_CONTRAST);
    let normalised = scene.rules.specular.normalised();
    let (blinn_chosen, phong_chosen) = match scene.rules.specular.vector() {
        SpecularVector::Halfway => (!normalised, false),
        SpecularVector::Reflection => (false, true),
    };
    let mut curves: Vec<Curve> = vec![
        (crate::t!("lobe-diffuse"), ink(DIFFUSE), sweep(|_| lobe.diffuse()), false),
        ("Blinn-Phong ks (N·H)^n".into(), ink(palette::H), sweep(|p| lobe.blinn(p)), blinn_chosen),
        ("Phong ks (R·V)^n".into(), ink(palette::SPOT), sweep(|p| lobe.phong(p)), phong_chosen),
    ];
    if normalised {
        curves.push((crate::t!("lobe-normalised"), ink(NORMALISED), sweep(|p| lobe.blinn_normalised(p)), true));
    }
    curves
}

/// The caption above the lobe: the light, θ, n, kd, ks and the vertex's own φ.
fn caption_ui(ui: &mut Ui, scene: &Scene, eval: &Evaluated, lobe: &Lobe, phi_v: f64) {
    let light = &scene.lights[eval.lights[0].index];
    let m = &scene.material;
    let kd = coefficient("kd", (m.diffuse * light.diffuse).truncate(), lobe.kd);
    let ks = coefficient("ks", (m.specular * light.specular).truncate(), lobe.ks);
    let deg = |a: f64| crate::locale::decimal(&format!("{:.1}", a.to_degrees()));
    ui.label(crate::t!(
        "lobe-caption",
        light = eval.lights[0].index.to_string(),
        theta = deg(lobe.theta),
        n = crate::locale::num(lobe.n, 6),
        kd = kd,
        ks = ks,
        phi = deg(phi_v)
    ));
}

/// The polar plot and the plot against φ, with the legend above them; all within the part
/// of the column on screen (the column reached under the next panel's border, and the
/// plots were cut at their right edge). Returns where they were drawn.
pub fn lobe_ui(ui: &mut Ui, scene: &Scene, eval: &Evaluated) -> Option<LobeGeometry> {
    let Some((lobe, phi_v)) = Lobe::of(scene, eval) else {
        ui.label(crate::t!("lobe-no-light"));
        return None;
    };
    let visible = ui.max_rect().intersect(ui.clip_rect());
    ui.set_max_width((visible.right() - RIGHT_MARGIN - ui.max_rect().left()).max(1.0));
    let bg = ui.visuals().panel_fill;
    let ink = |c: Color32| palette::ink_with_contrast(c, bg, palette::TEXT_CONTRAST);
    caption_ui(ui, scene, eval, &lobe, phi_v);
    let curves = curves_of(&lobe, scene, bg);
    let legend = ui.scope(|ui| legend_ui(ui, &curves)).response.rect;
    let polar = |ui: &mut Ui, (w, h): (f32, f32)| {
        Plot::new("lobe polar")
            .width(w)
            .height(h)
            .data_aspect(1.0)
            .allow_drag(false)
            .allow_zoom(false)
            .allow_scroll(false)
            .show(ui, |p| {
                for (name, c, pts, on) in &curves {
                    let xy: Vec<[f64; 2]> = pts.iter().map(|(phi, r)| [r * phi.sin(), r * phi.cos()]).collect();
                    p.line(Line::new(name.clone(), PlotPoints::from(xy)).color(*c).width(if *on { 3.0 } else { 1.5 }));
                }
                // N, L and V are directions: drawn just past the largest curve, so the plot
                // scales to the lobe (rays of length 1 left a lobe of 0.3 a few pixels wide).
                let reach = polar_reach(&curves);
                let ray = |a: f64| PlotPoints::from(vec![[0.0, 0.0], [a.sin() * reach, a.cos() * reach]]);
                p.line(Line::new("N", ray(0.0)).color(ink(palette::N)));
                p.line(
                    Line::new("L", ray(-lobe.theta)).color(ink(palette::L)).style(egui_plot::LineStyle::dashed_loose()),
                );
                p.line(Line::new("V", ray(phi_v)).color(ink(palette::V)));
            })
            .response
            .rect
    };
    let cartesian = |ui: &mut Ui, (w, h): (f32, f32)| {
        Plot::new("lobe against angle")
            .width(w)
            .height(h)
            .x_axis_label(crate::t!("lobe-axis"))
            .allow_drag(false)
            .allow_zoom(false)
            .allow_scroll(false)
            .include_y(0.0)
            .show(ui, |p| {
                for (name, c, pts, on) in &curves {
                    let xy: Vec<[f64; 2]> = pts.iter().map(|(phi, r)| [phi.to_degrees(), *r]).collect();
                    p.line(Line::new(name.clone(), PlotPoints::from(xy)).color(*c).width(if *on { 3.0 } else { 1.5 }));
                }
                p.vline(VLine::new(crate::t!("lobe-vertex-v"), phi_v.to_degrees()).color(ink(palette::V)).width(2.0));
            })
            .response
            .rect
    };
    let (polar, against) = egui::ScrollArea::both()
        .auto_shrink(false)
        .show(ui, |ui| {
            // Sized to the room inside the scroll area: a plot exactly as wide as the
            // column outside it was wider than the room within.
            let avail = ui.available_size();
            let wide = avail.x >= 1.6 * avail.y;
            let gap = ui.spacing().item_spacing;
            let (w, h) =
                if wide { ((avail.x - gap.x) / 2.0, avail.y - 4.0) } else { (avail.x, (avail.y - gap.y) / 2.0 - 2.0) };
            let size = (w.max(MIN_PLOT), h.max(MIN_PLOT));
            if wide {
                ui.horizontal_top(|ui| (polar(ui, size), cartesian(ui, size))).inner
            } else {
                (polar(ui, size), cartesian(ui, size))
            }
        })
        .inner;
    Some(LobeGeometry { visible, legend, polar, against })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_polar_plot_reaches_just_past_the_lobe() {
        let doc = phonglab_core::Document::default();
        let s = crate::app::editing::evaluated::Settings::default();
        let eval = crate::app::editing::evaluated::evaluate(&doc, s.precision, s.pow, s.side).unwrap();
        let (lobe, _) = Lobe::of(&doc.scene, &eval).unwrap();
        let top = (0..=180).map(|k| lobe.blinn((k as f64 - 90.0).to_radians())).fold(lobe.diffuse(), f64::max);
        let curves: Vec<Curve> = vec![
            ("d".into(), Color32::WHITE, sweep(|_| lobe.diffuse()), false),
            ("b".into(), Color32::WHITE, sweep(|p| lobe.blinn(p)), true),
        ];
        let reach = polar_reach(&curves);
        // The worksheet's lobe peaks near 0.29: the rays stop just past it, not at 1.
        assert!(top < 0.5 && (reach - 1.1 * top).abs() < 0.02 * top, "{top} {reach}");
    }

    #[test]
    fn the_lobes_peak_at_the_mirror_direction() {
        let lobe = Lobe { theta: 30f64.to_radians(), kd: 0.8, ks: 0.5, n: 50.0 };
        // R lies at φ = θ: Phong's lobe is ks there; Blinn-Phong's too (H = N).
        assert!((lobe.phong(lobe.theta) - 0.5).abs() < 1e-12);
        assert!((lobe.blinn(lobe.theta) - 0.5).abs() < 1e-12);
        // Off the peak both fall, and Blinn-Phong's lobe is the wider one (n·H is nearer 1).
        let off = lobe.theta + 0.2;
        assert!(lobe.phong(off) < lobe.blinn(off) && lobe.blinn(off) < 0.5);
        assert!((lobe.diffuse() - 0.8 * 30f64.to_radians().cos()).abs() < 1e-12);
        // Light below the surface: no specular at all.
        let below = Lobe { theta: 100f64.to_radians(), ..lobe };
        assert_eq!((below.phong(0.3), below.blinn(0.3), below.diffuse()), (0.0, 0.0, 0.0));
    }
}

#[cfg(test)]
mod colour_tests {
    use super::*;

    /// Each curve has a colour of its own, the two Blinn-Phong curves included (they were
    /// one colour, told apart only by width), each at a text's contrast on both themes'
    /// panels (the legend's swatches were faint in the light theme).
    #[test]
    fn the_curves_have_distinct_colours_readable_in_both_themes() {
        let lobe = Lobe { theta: 0.5, kd: 0.5, ks: 0.3, n: 25.0 };
        let mut scene = phonglab_core::presets::worksheet(5);
        scene.rules.specular = phonglab_core::rules::SpecularModel::BlinnPhongNormalised;
        for bg in [egui::Visuals::dark().panel_fill, egui::Visuals::light().panel_fill] {
            let curves = curves_of(&lobe, &scene, bg);
            assert_eq!(curves.len(), 4);
            for (i, a) in curves.iter().enumerate() {
                assert!(palette::contrast(a.1, bg) >= palette::TEXT_CONTRAST, "{} on {bg:?}: {:?}", a.0, a.1);
                for b in &curves[i + 1..] {
                    // The channels' differences summed: vermillion and orange, both darkened
                    // on the light panel, were 54 apart and hard to tell apart.
                    let apart =
                        a.1.to_array().iter().zip(b.1.to_array()).map(|(x, y)| x.abs_diff(y) as u32).sum::<u32>();
                    assert!(apart >= 70, "{} and {} on {bg:?}: {:?} {:?}", a.0, b.0, a.1, b.1);
                }
            }
        }
    }
}

#[cfg(test)]
mod caption_tests {
    use super::*;

    #[test]
    fn the_caption_gives_the_demos_own_kd_or_says_what_was_weighed() {
        assert_eq!(coefficient("kd", glam::DVec3::splat(0.4), 0.4), "kd = 0.4");
        let red = coefficient("kd", glam::DVec3::new(0.4, 0.0, 0.0), 0.2126 * 0.4);
        assert!(red.starts_with("kd = 0.08504") && red.contains("[0.4 0 0]"), "{red}");
    }
}
