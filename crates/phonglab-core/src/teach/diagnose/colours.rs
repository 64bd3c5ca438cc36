//! The colours a student's picture shows, term by term: for `colours-differ`, a mistake in
//! any colour the program sets (a light's, the material's, the scene's ambient, the
//! emission, colour material), which no row of the table need foresee.
//!
//! Before the clamp, the lit colour is linear in each term's product of colours (Red Book,
//! the lighting equation): `c = g + Σ_i (a_i α_i + d_i δ_i + s_i σ_i)`, with `g = a_cs a_cm +
//! e_cm` and, for light `i`, `a_i = a_cli a_cm`, `d_i = d_cli d_cm`, `s_i = s_cli s_cm`; the
//! factors `α_i`, `δ_i`, `σ_i` (attenuation, spot, `n·L`, `(n·H)^s`) hold the geometry and do
//! not depend on any colour. Gouraud interpolates linearly, so each pixel is linear in the
//! products too. So each term's factor is drawn once (that term's colour alone set to
//! [`PROBE`], every other colour black), and the products the picture shows are the least
//! squares fit of the student's pixels by those drawings, per channel, pulled toward the
//! scene's own products by [`PULL`] (a term the scene cannot show keeps its value).

use glam::DVec4;

use crate::model::error::SceneError;
use crate::model::scene::{MAX_LIGHTS, Material, Side};

use super::drawing::Drawing;

/// The terms: the scene's (`g`), then each light's ambient, diffuse and specular.
pub const TERMS: usize = 1 + 3 * MAX_LIGHTS;

/// The colour a term is drawn with alone: half, so that a factor up to 2 (an attenuation
/// under 1) is not clamped.
pub(super) const PROBE: f64 = 0.5;

/// How strongly the fit is pulled toward the scene's products, relative to one pixel's
/// squared residual: enough to fix a term no pixel shows, too little to move one they do.
/// (A pull relative to each term's weight, a thousandth, cost the fit of a picture whose
/// emission and ambient are near each other: measured on a teapot under a local light.)
const PULL: f64 = 1e-6;

/// A product differs from the scene's by more than this (plus [`RELATIVE`] of it) in some
/// channel for the picture to show another colour: a fit from thousands of pixels of 8-bit
/// levels is within a few thousandths.
pub(super) const ABSOLUTE: f64 = 0.03;

/// The share of a product by which a fitted one may differ and be the same.
pub(super) const RELATIVE: f64 = 0.06;

/// Levels near which a channel may have been clamped (with noise).
pub(super) const CLAMPED: u8 = 250;

/// The products of colours per term, fitted from the picture and the scene's own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Colours {
    /// The lights in the scene (the terms used: `1 + 3 * lights`).
    pub lights: usize,
    /// The products the picture shows, linear RGB.
    pub fitted: [[f64; 3]; TERMS],
    /// The scene's products.
    pub scene: [[f64; 3]; TERMS],
    /// Whether the picture shows the fitted products where they draw another picture than
    /// the scene's (`shows_fitted`), and how near it is to each there: then a product that
    /// differs by less than a fit's noise on any picture (`ABSOLUTE`, `RELATIVE`) but past
    /// `FINE` differs.
    pub shown: Option<Nearer>,
}

/// Where the fitted products' drawing and the scene's differ (by 2 levels or more in a
/// channel, inside the object), how far the student's picture is from each: what
/// [`Colours::shown`] rests on, and what a "wrong" it decides says when both pictures explain
/// the same share of the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nearer {
    /// The pixels where the two drawings differ.
    pub pixels: usize,
    /// The picture's distance from the fitted products' drawing there: the root mean square
    /// of the levels, over the pixels and channels.
    pub to_fitted: f64,
    /// The same from the scene's drawing.
    pub to_scene: f64,
}

impl Colours {
    /// The products of colours of `d`'s scene, term by term: the scene's, then each
    /// light's ambient, diffuse and specular.
    pub fn products(d: &Drawing) -> [[f64; 3]; TERMS] {
        scene_products(d)
    }

    /// The terms whose fitted product is not the scene's.
    pub fn differing(&self) -> Vec<usize> {
        let past = |t: usize| {
            differs(self.fitted[t], self.scene[t])
                || (self.shown.is_some() && differs_finely(self.fitted[t], self.scene[t]))
        };
        (0..1 + 3 * self.lights).filter(|&t| past(t)).collect()
    }
}

/// Does a fitted colour differ from the scene's in some channel, by more than a fit's
/// noise ([`ABSOLUTE`] and [`RELATIVE`] of it)?
pub(super) fn differs(fitted: [f64; 3], scene: [f64; 3]) -> bool {
    (0..3).any(|c| (fitted[c] - scene[c]).abs() > ABSOLUTE + RELATIVE * scene[c].abs())
}

/// The least difference (absolute, and the share of the product) of a fitted product from
/// the scene's that a picture showing the fitted products ([`Colours::shown`]) tells: a
/// light's red typed 0.97 for 1 on the spotlight's gold teapot moves its diffuse product
/// by 0.023, the Phong demo's diffuse 0.388 for 0.4 by 0.012.
pub(super) const FINE: (f64, f64) = (0.004, 0.01);

/// Does a fitted colour differ from the scene's in some channel past [`FINE`]?
fn differs_finely(fitted: [f64; 3], scene: [f64; 3]) -> bool {
    (0..3).any(|c| (fitted[c] - scene[c]).abs() > FINE.0 + FINE.1 * scene[c].abs())
}

/// How much nearer (the mean squared levels) the student's picture must be to the fitted
/// products' drawing than to the scene's, where the two differ, for the picture to show
/// the fitted products: a third. Noise and a lossy saving add to both alike; a colour
/// typed a little off is the fitted one's and misses the scene's by its change.
const SHOWN_AT: f64 = 1.0 / 3.0;

/// The least pixels where the fitted products' drawing and the scene's differ for the
/// picture to tell which it shows.
const SHOWN_PIXELS: usize = 64;

/// Does `image` (RGBA8, `size` square, aligned to the object `covered`) show the products
/// `fitted` rather than `scene` ([`SHOWN_AT`]): over the object's inside, where their
/// drawings differ by 2 levels or more in a channel, the mean squared levels by which the
/// image misses the fitted drawing at most [`SHOWN_AT`] of those it misses the scene's by?
/// How near it is to each, when it does.
fn shows_fitted(
    right: &Drawing,
    (fitted, scene): (&[[f64; 3]; TERMS], &[[f64; 3]; TERMS]),
    covered: &[bool],
    image: &[u8],
    size: usize,
) -> Result<Option<Nearer>, SceneError> {
    let (_, with_fitted, _) = with_products(right, fitted).draw(size)?;
    let (_, with_scene, _) = with_products(right, scene).draw(size)?;
    let squared = |a: &[u8], b: &[u8], p: usize| -> f64 {
        (0..3).map(|c| (f64::from(a[p * 4 + c]) - f64::from(b[p * 4 + c])).powi(2)).sum()
    };
    let apart = |p: &usize| (0..3).any(|c| with_fitted[p * 4 + c].abs_diff(with_scene[p * 4 + c]) >= 2);
    let differ: Vec<usize> = interior(covered, size).into_iter().filter(apart).collect();
    let to_fitted: f64 = differ.iter().map(|&p| squared(image, &with_fitted, p)).sum();
    let to_scene: f64 = differ.iter().map(|&p| squared(image, &with_scene, p)).sum();
    let shown = differ.len() >= SHOWN_PIXELS && to_fitted <= SHOWN_AT * to_scene;
    let rms = |sum: f64| (sum / (3 * differ.len().max(1)) as f64).sqrt();
    Ok(shown.then(|| Nearer { pixels: differ.len(), to_fitted: rms(to_fitted), to_scene: rms(to_scene) }))
}

/// A fitted colour as words show it: two decimals in the reader's decimal mark, never
/// negative (a colour is not: a fit a little under 0 is 0).
pub(super) fn rgb_said(v: [f64; 3]) -> String {
    triple_said(v.map(|x| x.max(0.0) + 0.0))
}

/// Three numbers to two decimals for people: "(0.05, 0.06, 0.49)", or with the decimal
/// comma "(0,05; 0,06; 0,49)", as the probe writes them (a comma between components would
/// read as a decimal mark).
pub(super) fn triple_said([r, g, b]: [f64; 3]) -> String {
    let text = crate::locale::decimal(&format!("({r:.2}, {g:.2}, {b:.2})"));
    match crate::locale::current().decimal {
        crate::locale::DecimalMark::Point => text,
        crate::locale::DecimalMark::Comma => text.replace(", ", "; "),
    }
}

/// Each term's factor: `right` drawn `size` square with that term's products alone set to
/// [`PROBE`] ([`with_products`]), `adjust` then made to the drawing (RGBA8 each).
pub(super) fn factors(right: &Drawing, size: usize, adjust: impl Fn(&mut Drawing)) -> Result<Vec<Vec<u8>>, SceneError> {
    let terms = 1 + 3 * right.scene.lights.len();
    let mut out = Vec::with_capacity(terms);
    for t in 0..terms {
        let mut alone = [[0.0; 3]; TERMS];
        alone[t] = [PROBE; 3];
        let mut d = with_products(right, &alone);
        adjust(&mut d);
        out.push(d.draw(size)?.1);
    }
    Ok(out)
}

/// The differing terms in words, in the reader's language: each term, the product the
/// picture shows and the scene's ("GL_LIGHT1 diffuse: (0.00, 0.00, 0.00) in the picture,
/// (0.00, 0.80, 0.00) in the scene").
pub fn said(c: &Colours) -> String {
    use crate::locale::{Arg, tr, tr_args};
    let list: Vec<String> = c
        .differing()
        .into_iter()
        .map(|t| {
            let term = if t == 0 {
                tr("diagnose-term-scene")
            } else {
                let message = ["diagnose-term-ambient", "diagnose-term-diffuse", "diagnose-term-specular"][(t - 1) % 3];
                tr_args(message, &[("light", Arg::Text(((t - 1) / 3).to_string()))])
            };
            tr_args(
                "diagnose-term-differs",
                &[
                    ("term", Arg::Text(term)),
                    ("shown", Arg::Text(rgb_said(c.fitted[t]))),
                    ("scene", Arg::Text(rgb_said(c.scene[t]))),
                ],
            )
        })
        .collect();
    list.join("; ")
}

/// The scene's products, in the order of [`TERMS`].
fn scene_products(d: &Drawing) -> [[f64; 3]; TERMS] {
    let s = &d.scene;
    let m = s.lit_material(Side::Front);
    let mul = |a: DVec4, b: DVec4| (a.truncate() * b.truncate()).to_array();
    let mut out = [[0.0; 3]; TERMS];
    let mut g = glam::DVec3::ZERO;
    if s.rules.scene_ambient() {
        g += s.light_model.ambient.truncate() * m.ambient.truncate();
    }
    if s.rules.emission() {
        g += m.emission.truncate();
    }
    out[0] = g.to_array();
    for (i, l) in s.lights.iter().enumerate() {
        out[1 + 3 * i] = mul(l.ambient, m.ambient);
        out[2 + 3 * i] = mul(l.diffuse, m.diffuse);
        out[3 + 3 * i] = mul(l.specular, m.specular);
    }
    out
}

/// The pictures [`fit`] draws for `right`: one per term, the one change's and the joint
/// fit's, and the fitted products' and the scene's ([`shows_fitted`]), where it fits at all.
pub fn drawings(right: &Drawing) -> usize {
    if fittable(right) { 1 + 3 * right.scene.lights.len() + 4 } else { 0 }
}

/// Can this scene's colours be fitted: both sides lit with the same material (a term
/// cannot be split between two materials), and at least one light?
fn fittable(d: &Drawing) -> bool {
    let s = &d.scene;
    !s.lights.is_empty()
        && s.lights.len() <= MAX_LIGHTS
        && (!s.light_model.two_sided || s.lit_material(Side::Front) == s.lit_material(Side::Back))
}

/// The drawing with the terms' products `products` and nothing else: a white material (on
/// both sides, no colour material), each light's colours set to its products, the scene's
/// term given as the scene's ambient light (or the emission, under rules without it).
pub fn with_products(d: &Drawing, products: &[[f64; 3]; TERMS]) -> Drawing {
    let mut out = d.clone();
    let s = &mut out.scene;
    let colour = |c: [f64; 3]| DVec4::new(c[0].max(0.0), c[1].max(0.0), c[2].max(0.0), 1.0);
    let alpha = s.lit_material(Side::Front).diffuse.w;
    let shininess = s.lit_material(Side::Front).shininess;
    let white = DVec4::new(1.0, 1.0, 1.0, alpha);
    s.material = Material { ambient: white, diffuse: white, specular: white, emission: DVec4::W, shininess };
    s.back_material = None;
    s.color_material = None;
    s.light_model.ambient = DVec4::W;
    if s.rules.scene_ambient() {
        s.light_model.ambient = colour(products[0]);
    } else {
        s.material.emission = colour(products[0]);
    }
    for (i, l) in s.lights.iter_mut().enumerate() {
        l.ambient = colour(products[1 + 3 * i]);
        l.diffuse = colour(products[2 + 3 * i]);
        l.specular = colour(products[3 + 3 * i]);
    }
    out
}

/// The products `image` (RGBA8, `size` square) shows for `right`'s terms; `None` where
/// they cannot be fitted ([`fittable`]) or the object covers too few pixels.
pub fn fit(right: &Drawing, covered: &[bool], image: &[u8], size: usize) -> Result<Option<Colours>, SceneError> {
    if !fittable(right) {
        return Ok(None);
    }
    let lights = right.scene.lights.len();
    let terms = 1 + 3 * lights;
    let scene = scene_products(right);
    // Each term's factor, drawn alone.
    let factors = factors(right, size, |_| ())?;
    // Terms whose factors are the same picture (the scene's ambient and the ambient of each
    // light neither attenuated nor a spot: 1 everywhere) cannot be told apart: the first
    // of each such group is fitted for all, the others keep the scene's products.
    let first: Vec<usize> = (0..terms).map(|t| (0..=t).find(|&u| factors[u] == factors[t]).unwrap_or(t)).collect();
    let same: Vec<bool> = (0..terms).map(|t| first[t] != t).collect();
    let inside = interior(covered, size);
    // The student's picture may sit a pixel off the right one (another rasteriser): each
    // pixel is fitted with the student's pixel at the shift that matches best.
    let moved = aligned(covered, image, right.background8(), size);
    let original = image;
    let image = &moved[..];
    let mut fitted = scene;
    // The models of one change (a term alone, or a material colour in every light's term of
    // its kind), fitted beside the joint one: where the terms are nearly dependent (the
    // diffuse terms of four lights on a sphere are four linear functions of a 3-vector
    // wherever all light it) the joint fit may move several terms where one moved.
    let models = one_change_models(right, terms, &same);
    let mut one_change = vec![[[0.0; 3]; TERMS]; models.len()];
    let mut one_change_residual = vec![0.0; models.len()];
    for c in 0..3 {
        let level = |f: &[u8], p: usize| f[p * 4 + c];
        let usable: Vec<usize> =
            inside.iter().copied().filter(|&p| factors.iter().all(|f| level(f, p) < CLAMPED)).collect();
        // Pixels the student's picture clamped say only that the sum reached 1.
        let (clamped, open): (Vec<usize>, Vec<usize>) = usable.into_iter().partition(|&p| level(image, p) >= CLAMPED);
        if open.len() + clamped.len() < 4 * terms {
            continue;
        }
        let row = |p: usize| -> Vec<f64> {
            factors
                .iter()
                .zip(&same)
                .map(|(f, &s)| if s { 0.0 } else { f64::from(level(f, p)) / 255.0 / PROBE })
                .collect()
        };
        let target = |p: usize| if level(image, p) >= CLAMPED { 1.0 } else { f64::from(level(image, p)) / 255.0 };
        // A group's first term is fitted for the group's sum: its prior is the sum.
        let mut prior: Vec<f64> = (0..terms).map(|t| scene[t][c]).collect();
        for t in (0..terms).filter(|&t| same[t]) {
            prior[first[t]] += scene[t][c];
        }
        let mut x = censored_fit(&open, &clamped, &row, &target, &prior);
        // The group's others keep the scene's products; its first the rest of the sum.
        for t in (0..terms).filter(|&t| same[t]) {
            x[first[t]] -= scene[t][c];
            x[t] = scene[t][c];
        }
        for t in 0..terms {
            fitted[t][c] = x[t];
        }
        // Every term's own factor, for the one-change models and the residuals.
        let full = |p: usize| -> Vec<f64> { factors.iter().map(|f| f64::from(level(f, p)) / 255.0 / PROBE).collect() };
        let residual = |x: &[f64]| -> f64 {
            open.iter().map(|&p| (full(p).iter().zip(x).map(|(a, b)| a * b).sum::<f64>() - target(p)).powi(2)).sum()
        };
        for (i, model) in models.iter().enumerate() {
            let (base, direction) = model(c, &scene);
            // y - base·row = m (direction·row): one unknown, m.
            let (mut uu, mut ur) = (0.0, 0.0);
            for &p in &open {
                let r = full(p);
                let u: f64 = r.iter().zip(&direction).map(|(a, b)| a * b).sum();
                let rest: f64 = r.iter().zip(&base).map(|(a, b)| a * b).sum();
                uu += u * u;
                ur += u * (target(p) - rest);
            }
            let m = if uu > 1e-12 { ur / uu } else { 0.0 };
            let x: Vec<f64> = base.iter().zip(&direction).map(|(b, d)| b + m * d).collect();
            one_change_residual[i] += residual(&x);
            for t in 0..terms {
                one_change[i][t][c] = x[t];
            }
        }
    }
    // The one change that fits best, against the joint fit: each drawn and measured against
    // the student's picture (the clamp included, which the fits leave out); the one change
    // where it is as close.
    let best = (0..models.len()).min_by(|&a, &b| one_change_residual[a].total_cmp(&one_change_residual[b]));
    if let Some(b) = best {
        let bg = right.background8();
        let miss = |products: &[[f64; 3]; TERMS]| -> Result<f64, SceneError> {
            let (_, drawn, drawn_covered) = with_products(right, products).draw(size)?;
            Ok(crate::teach::picture_match::compare(&drawn, &drawn_covered, original, bg, size).miss)
        };
        if miss(&one_change[b])? <= miss(&fitted)? {
            fitted = one_change[b];
        }
    }
    let shown = shows_fitted(right, (&fitted, &scene), covered, image, size)?;
    Ok(Some(Colours { lights, fitted, scene, shown }))
}

/// A model of one change: given the channel and the scene's products, the products with
/// the changed ones set to 0 (`base`) and the direction they change along (the products
/// are `base + m direction` for the one unknown `m`).
type OneChange = Box<dyn Fn(usize, &[[f64; 3]; TERMS]) -> (Vec<f64>, Vec<f64>)>;

/// The one-change models of a drawing with `terms` terms: each term alone (a group of
/// terms that cannot be told apart once, by its first), and the material's ambient, diffuse
/// and specular colour, each in every light's term of its kind (and the scene's ambient
/// for the ambient).
fn one_change_models(right: &Drawing, terms: usize, same: &[bool]) -> Vec<OneChange> {
    let mut out: Vec<OneChange> = Vec::new();
    for t in (0..terms).filter(|&t| !same[t]) {
        out.push(Box::new(move |c, scene| {
            let mut base: Vec<f64> = (0..terms).map(|u| scene[u][c]).collect();
            base[t] = 0.0;
            let mut direction = vec![0.0; terms];
            direction[t] = 1.0;
            (base, direction)
        }));
    }
    let s = &right.scene;
    let lights: Vec<[DVec4; 3]> = s.lights.iter().map(|l| [l.ambient, l.diffuse, l.specular]).collect();
    let model_ambient = s.rules.scene_ambient().then_some(s.light_model.ambient);
    let emission = if s.rules.emission() { s.lit_material(Side::Front).emission } else { DVec4::ZERO };
    for kind in 0..3 {
        let lights = lights.clone();
        out.push(Box::new(move |c, scene| {
            let mut base: Vec<f64> = (0..terms).map(|u| scene[u][c]).collect();
            let mut direction = vec![0.0; terms];
            for (l, colours) in lights.iter().enumerate() {
                base[1 + 3 * l + kind] = 0.0;
                direction[1 + 3 * l + kind] = colours[kind][c];
            }
            if kind == 0 {
                base[0] = emission[c];
                direction[0] = model_ambient.map_or(0.0, |a| a[c]);
            }
            (base, direction)
        }));
    }
    out
}

/// The least squares fit over the `open` pixels and those `clamped` ones the fit leaves
/// under 1 (held at 1: a clamped pixel over 1 is right), refitted three times without the
/// pixels it explains worst (a clamped vertex's neighbours, a pixel's edge: a residual past
/// three levels and twice the median).
fn censored_fit(
    open: &[usize],
    clamped: &[usize],
    row: &dyn Fn(usize) -> Vec<f64>,
    target: &dyn Fn(usize) -> f64,
    prior: &[f64],
) -> Vec<f64> {
    let predicted = |p: usize, x: &[f64]| row(p).iter().zip(x).map(|(a, b)| a * b).sum::<f64>();
    let mut x = least_squares(open, row, target, prior);
    for _ in 0..3 {
        let mut active: Vec<usize> = open.to_vec();
        active.extend(clamped.iter().copied().filter(|&p| predicted(p, &x) < 1.0));
        let mut r: Vec<f64> = active.iter().map(|&p| (predicted(p, &x) - target(p)).abs()).collect();
        if r.is_empty() {
            break;
        }
        let middle = r.len() / 2;
        let median = *r.select_nth_unstable_by(middle, f64::total_cmp).1;
        let bound = (3.0_f64 / 255.0).max(2.0 * median);
        active.retain(|&p| (predicted(p, &x) - target(p)).abs() <= bound);
        if active.len() < 4 * prior.len() {
            break;
        }
        x = least_squares(&active, row, target, prior);
    }
    x
}

/// `image` moved by the shift [`best_shift`] finds (the pixels it would take from outside
/// kept as they are), RGBA8 opaque.
pub(super) fn aligned(covered: &[bool], image: &[u8], bg: [u8; 3], size: usize) -> Vec<u8> {
    let shift = best_shift(covered, image, bg, size);
    (0..size * size)
        .flat_map(|p| {
            let (x, y) = ((p % size) as i64 + shift.0, (p / size) as i64 + shift.1);
            let inside = x >= 0 && y >= 0 && (x as usize) < size && (y as usize) < size;
            let q = if inside { y as usize * size + x as usize } else { p };
            [image[q * 4], image[q * 4 + 1], image[q * 4 + 2], 255]
        })
        .collect()
}

/// The shift (each of x and y by -1, 0 or 1 pixel) that brings the object's outline in
/// `image` (its pixels apart from the background `bg`) nearest `covered`: the fewest
/// pixels covered in one and not the other. The outline, not the colours, which the
/// mistake changes.
fn best_shift(covered: &[bool], image: &[u8], bg: [u8; 3], size: usize) -> (i64, i64) {
    let shows = |q: usize| (0..3).any(|c| image[q * 4 + c].abs_diff(bg[c]) > crate::teach::picture_match::TOLERANCE);
    let mut best = ((0, 0), usize::MAX);
    for dy in -1i64..=1 {
        for dx in -1i64..=1 {
            let mut apart = 0usize;
            for y in 1..size.saturating_sub(1) {
                for x in 1..size - 1 {
                    let p = y * size + x;
                    let q = (y as i64 + dy) as usize * size + (x as i64 + dx) as usize;
                    apart += usize::from(covered[p] != shows(q));
                }
            }
            if apart < best.1 {
                best = ((dx, dy), apart);
            }
        }
    }
    best.0
}

/// The covered pixels whose eight neighbours are covered too (a pixel's shift at the
/// silhouette is not a colour).
pub(super) fn interior(covered: &[bool], size: usize) -> Vec<usize> {
    let mut out = Vec::new();
    for y in 1..size.saturating_sub(1) {
        for x in 1..size - 1 {
            let all = (y - 1..=y + 1).all(|qy| (x - 1..=x + 1).all(|qx| covered[qy * size + qx]));
            if all {
                out.push(y * size + x);
            }
        }
    }
    out
}

/// Solves `min Σ_p (row(p)·x - target(p))² + PULL n Σ_t (x_t - prior_t)²` over `pixels`
/// (`n` of them) by its normal equations.
pub(super) fn least_squares(
    pixels: &[usize],
    row: &dyn Fn(usize) -> Vec<f64>,
    target: &dyn Fn(usize) -> f64,
    prior: &[f64],
) -> Vec<f64> {
    least_squares_held(pixels, row, target, prior, &vec![1.0; prior.len()])
}

/// [`least_squares`] with each term pulled `hold[t]` times as hard toward its prior: where
/// two terms draw the same picture (a material's ambient under constant ambient light,
/// and its emission), the held one keeps its prior and the other takes the change.
pub(super) fn least_squares_held(
    pixels: &[usize],
    row: &dyn Fn(usize) -> Vec<f64>,
    target: &dyn Fn(usize) -> f64,
    prior: &[f64],
    hold: &[f64],
) -> Vec<f64> {
    let k = prior.len();
    let mut a = vec![vec![0.0; k]; k];
    let mut b = vec![0.0; k];
    for &p in pixels {
        let r = row(p);
        let y = target(p);
        for i in 0..k {
            b[i] += r[i] * y;
            for j in 0..k {
                a[i][j] += r[i] * r[j];
            }
        }
    }
    for i in 0..k {
        let pull = PULL * pixels.len() as f64 * hold[i];
        a[i][i] += pull;
        b[i] += pull * prior[i];
    }
    solve(a, b).unwrap_or_else(|| prior.to_vec())
}

/// Solves `a x = b` by Gaussian elimination with partial pivoting; `None` if singular.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let k = b.len();
    for col in 0..k {
        let pivot = (col..k).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() < 1e-12 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col].clone();
        for row in col + 1..k {
            let f = a[row][col] / pivot_row[col];
            for (x, p) in a[row][col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = vec![0.0; k];
    for row in (0..k).rev() {
        let rest: f64 = (row + 1..k).map(|j| a[row][j] * x[j]).sum();
        x[row] = (b[row] - rest) / a[row][row];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_keep_their_components_apart_with_the_decimal_comma() {
        use crate::locale::{Lang, Locale, with_locale};
        let v = [0.05, 0.06, 0.49];
        assert_eq!(with_locale(Locale::of(Lang::PtPt), || rgb_said(v)), "(0,05; 0,06; 0,49)");
        assert_eq!(with_locale(Locale::of(Lang::PtBr), || rgb_said(v)), "(0,05; 0,06; 0,49)");
        assert_eq!(with_locale(Locale::of(Lang::En), || rgb_said(v)), "(0.05, 0.06, 0.49)");
    }

    #[test]
    fn gaussian_elimination_solves_a_small_system() {
        let a = vec![vec![2.0, 1.0, 0.0], vec![1.0, 3.0, 1.0], vec![0.0, 1.0, 4.0]];
        let x = solve(a, vec![3.0, 5.0, 5.0]).unwrap();
        for (v, want) in x.iter().zip([1.0, 1.0, 1.0]) {
            assert!((v - want).abs() < 1e-12, "{x:?}");
        }
        assert!(solve(vec![vec![1.0, 2.0], vec![2.0, 4.0]], vec![1.0, 2.0]).is_none());
    }
}

#[cfg(test)]
mod drawn {
    use super::*;

    /// A shipped scene (`assets/scenes/NAME.toml`) drawn as `phonglab diagnose` draws it.
    fn shipped(name: &str) -> Drawing {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/scenes/");
        let text = std::fs::read_to_string(format!("{path}{name}.toml")).expect("a shipped scene");
        let doc = crate::formats::document::Document::from_toml(&text).expect("a scene");
        let mesh = doc.view.mesh();
        Drawing::of(&doc.shaded_setup(crate::numerics::pow::PowFn::Exact).job(&mesh))
    }

    #[test]
    fn the_scene_drawn_with_its_own_products_is_the_scene() {
        for name in ["three-lights", "of-set-color", "worksheet-mview5", "redbook-teapots/09-chrome"] {
            let right = shipped(name);
            let (_, want, _) = right.draw(64).expect("drawn");
            let (_, got, _) = with_products(&right, &scene_products(&right)).draw(64).expect("drawn");
            let worst = want.iter().zip(&got).map(|(a, b)| a.abs_diff(*b)).max().unwrap_or(0);
            assert!(worst <= 1, "{name}: {worst}");
        }
    }
}
