//! The materials a student's picture shows on each side: for `materials-differ`, a mistake
//! in the front or back material of two-sided lighting (the back's calls given to
//! `GL_FRONT`, a colour set for one side only), where the colour fit of
//! [`super::colours`] cannot go: two materials share each light's term.
//!
//! With the lights' colours fixed, a side's lit colour is linear in its material's four
//! colours (Red Book, the lighting equation): `c = e_cm + a_cm (a_cs + Σ_i a_cli α_i) +
//! d_cm Σ_i d_cli δ_i + s_cm Σ_i s_cli σ_i`, the factors `α_i`, `δ_i`, `σ_i` those
//! [`super::colours`] draws. Each side's four colours are fitted by least squares from the
//! pixels that side shows, per channel.

use glam::DVec4;

use crate::model::error::SceneError;
use crate::model::scene::{MAX_LIGHTS, Material, Side};

use super::colours::{CLAMPED, PROBE, aligned, differs, factors, interior, least_squares_held, rgb_said};
use super::drawing::Drawing;

/// A side's four colours, in the order ambient, diffuse, specular, emission; linear RGB.
pub type Four = [[f64; 3]; 4];

/// The GL names of a material's colours, in the order of [`Four`].
pub const NAMES: [&str; 4] = ["GL_AMBIENT", "GL_DIFFUSE", "GL_SPECULAR", "GL_EMISSION"];

/// Each side's material colours, fitted from the picture and the scene's own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sides {
    /// Front, back: as the picture shows them.
    pub fitted: [Four; 2],
    /// Front, back: the scene's (what it lights each side with).
    pub scene: [Four; 2],
    /// Front, back: the shininess the picture was fitted with (a side's calls given to the
    /// other side carry its shininess too), and the scene's.
    pub shininess: [(f64, f64); 2],
}

impl Sides {
    /// The (side, colour) pairs whose fitted colour is not the scene's.
    pub fn differing(&self) -> Vec<(usize, usize)> {
        let mut out = Vec::new();
        for side in 0..2 {
            for k in 0..4 {
                let shiny = k == 2 && self.shininess[side].0 != self.shininess[side].1;
                if shiny || differs(self.fitted[side][k], self.scene[side][k]) {
                    out.push((side, k));
                }
            }
        }
        out
    }
}

/// A material's four colours.
fn four(m: &Material) -> Four {
    [m.ambient, m.diffuse, m.specular, m.emission].map(|c| c.truncate().to_array())
}

/// Does this scene light its two sides with different materials (two-sided lighting)?
pub fn applies(d: &Drawing) -> bool {
    let s = &d.scene;
    !s.lights.is_empty()
        && s.lights.len() <= MAX_LIGHTS
        && s.light_model.two_sided
        && s.lit_material(Side::Front) != s.lit_material(Side::Back)
}

/// The drawing with each side's colours `sides` and shininess (no colour material: the
/// fit holds what it tracked), the alpha kept.
pub fn with_sides(d: &Drawing, sides: &[Four; 2], shininess: [f64; 2]) -> Drawing {
    let mut out = d.clone();
    let s = &mut out.scene;
    let colour = |c: [f64; 3], w: f64| DVec4::new(c[0].max(0.0), c[1].max(0.0), c[2].max(0.0), w);
    let lit = [s.lit_material(Side::Front), s.lit_material(Side::Back)];
    let made: Vec<Material> = lit
        .iter()
        .zip(sides)
        .zip(shininess)
        .map(|((m, f), shininess)| Material {
            ambient: colour(f[0], m.ambient.w),
            diffuse: colour(f[1], m.diffuse.w),
            specular: colour(f[2], m.specular.w),
            emission: colour(f[3], m.emission.w),
            shininess,
        })
        .collect();
    s.material = made[0].clone();
    s.back_material = Some(made[1].clone());
    s.color_material = None;
    out
}

/// The pictures [`fit`] draws for `right`: the side of each pixel, and one per term for
/// each of the nine pairs of shininess tried.
pub fn drawings(right: &Drawing) -> usize {
    if applies(right) { 1 + 9 * (1 + 3 * right.scene.lights.len()) } else { 0 }
}

/// Each side's colours `image` (RGBA8, `size` square) shows for `right`; `None` where the
/// scene does not light two sides differently. Each side's shininess is tried as its own,
/// the other side's and OpenGL's default 0 (a side's calls given to the other carry it),
/// the pair whose fit leaves the least residual kept.
pub fn fit(right: &Drawing, covered: &[bool], image: &[u8], size: usize) -> Result<Option<Sides>, SceneError> {
    if !applies(right) {
        return Ok(None);
    }
    let s = &right.scene;
    let (renderer, _, _) = right.draw(size)?;
    let back: Vec<bool> = (0..size * size).map(|i| renderer.surface_at(i).is_some_and(|x| x.back)).collect();
    let image = aligned(covered, image, right.background8(), size);
    let scene = [four(&s.lit_material(Side::Front)), four(&s.lit_material(Side::Back))];
    let own = [s.lit_material(Side::Front).shininess, s.lit_material(Side::Back).shininess];
    let choices = [own[0], own[1], 0.0];
    let mut best: Option<(f64, Sides)> = None;
    for front in choices {
        for back_shininess in choices {
            let shininess = [front, back_shininess];
            let (fitted, residual) = fit_with(right, &back, covered, &image, size, shininess, &scene)?;
            let sides = Sides { fitted, scene, shininess: [(front, own[0]), (back_shininess, own[1])] };
            // Near ties (a side that shows no highlight: 1 % of the residual) go to the
            // scene's own shininess, tried first.
            if best.as_ref().is_none_or(|(r, _)| residual < r * 0.99) {
                best = Some((residual, sides));
            }
        }
    }
    Ok(best.map(|(_, s)| s))
}

/// Each side's colours fitted with the sides' shininess `shininess`, and the residual.
fn fit_with(
    right: &Drawing,
    back: &[bool],
    covered: &[bool],
    image: &[u8],
    size: usize,
    shininess: [f64; 2],
    scene: &[Four; 2],
) -> Result<([Four; 2], f64), SceneError> {
    let s = &right.scene;
    // Each term's factor, drawn alone with white materials of the sides' shininess.
    let factors = factors(right, size, |d| {
        d.scene.material.shininess = shininess[0];
        d.scene.back_material = Some(Material { shininess: shininess[1], ..d.scene.material.clone() });
    })?;
    let mut fitted = *scene;
    let mut residual = 0.0;
    let inside = interior(covered, size);
    for (side, out) in fitted.iter_mut().enumerate() {
        for c in 0..3 {
            let level = |f: &[u8], p: usize| f[p * 4 + c];
            let pixels: Vec<usize> = inside
                .iter()
                .copied()
                .filter(|&p| back[p] == (side == 1) && level(image, p) < CLAMPED)
                .filter(|&p| factors.iter().all(|f| level(f, p) < CLAMPED))
                .collect();
            if pixels.len() < 16 {
                continue;
            }
            let factor = |t: usize, p: usize| f64::from(level(&factors[t], p)) / 255.0 / PROBE;
            let row = |p: usize| -> Vec<f64> {
                let sum = |k: usize, colour: fn(&crate::model::scene::Light) -> DVec4| -> f64 {
                    s.lights.iter().enumerate().map(|(i, l)| colour(l)[c] * factor(1 + 3 * i + k, p)).sum()
                };
                let scene_ambient = if s.rules.scene_ambient() { s.light_model.ambient[c] * factor(0, p) } else { 0.0 };
                let emission = if s.rules.emission() { factor(0, p) } else { 0.0 };
                vec![sum(0, |l| l.ambient) + scene_ambient, sum(1, |l| l.diffuse), sum(2, |l| l.specular), emission]
            };
            let target = |p: usize| f64::from(level(image, p)) / 255.0;
            let prior: Vec<f64> = (0..4).map(|k| scene[side][k][c]).collect();
            // The emission held: under near-constant ambient light a change of the ambient
            // draws as an emission; a student sets a side's ambient far more often.
            let x = least_squares_held(&pixels, &row, &target, &prior, &[1.0, 1.0, 1.0, 1e4]);
            residual += pixels
                .iter()
                .map(|&p| (row(p).iter().zip(&x).map(|(a, b)| a * b).sum::<f64>() - target(p)).powi(2))
                .sum::<f64>();
            for k in 0..4 {
                out[k][c] = x[k];
            }
        }
    }
    Ok((fitted, residual))
}

/// The differing colours in words, in the reader's language: each side and colour, what
/// the picture shows and the scene's ("GL_DIFFUSE of the front: (0.10, 0.10, 0.80) in the
/// picture, (0.80, 0.60, 0.20) in the scene").
pub fn said(sides: &Sides) -> String {
    use crate::locale::{Arg, tr, tr_args};
    let list: Vec<String> = sides
        .differing()
        .into_iter()
        .map(|(side, k)| {
            let which = tr(if side == 0 { "diagnose-side-front" } else { "diagnose-side-back" });
            let (fitted, scene) = (sides.fitted[side][k], sides.scene[side][k]);
            let colour = tr_args(
                "diagnose-material-colour-differs",
                &[
                    ("name", Arg::Text(NAMES[k].to_owned())),
                    ("which", Arg::Text(which.clone())),
                    ("shown", Arg::Text(rgb_said(fitted))),
                    ("scene", Arg::Text(rgb_said(scene))),
                ],
            );
            let (shown, own) = sides.shininess[side];
            if k != 2 || shown == own {
                return colour;
            }
            let number = |v: f64| Arg::Text(crate::locale::decimal(&super::values::shown(v)));
            let shiny = tr_args(
                "diagnose-material-shininess-differs",
                &[("which", Arg::Text(which)), ("shown", number(shown)), ("scene", number(own))],
            );
            if differs(fitted, scene) { format!("{colour}; {shiny}") } else { shiny }
        })
        .collect();
    list.join("; ")
}
