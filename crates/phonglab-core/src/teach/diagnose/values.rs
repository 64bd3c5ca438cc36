//! The one number a student's picture shows differently: for `spot-cutoff-differs` and its
//! kin, a mistake in a single number the program sets (a light's spot cutoff, spot exponent
//! or an attenuation coefficient, the material's shininess) that no row of the table need
//! foresee (a cutoff given as the cone's full angle, an exponent typed 2 for 20, a
//! quadratic coefficient 100 times too large).
//!
//! Each number the scene uses is tried over a grid of the values a program could give it
//! ([`grid`]), then refined between the best value's neighbours by golden-section search,
//! the picture drawn at each and measured against the student's by the mean levels its
//! pixels miss by, a pixel's shift allowed (`picture_match::Match::miss`). A value is kept when its picture is closer than the
//! scene's own by [`CLOSER`]; it is then drawn and scored as every mistake is.

use crate::model::error::SceneError;
use crate::model::scene::{Light, MAX_LIGHTS};
use crate::teach::picture_match::compare;

use super::drawing::Drawing;

/// The numbers of a light, in the order of [`Values::lights`].
pub const LIGHT_NAMES: [&str; 5] = [
    "GL_SPOT_CUTOFF",
    "GL_SPOT_EXPONENT",
    "GL_CONSTANT_ATTENUATION",
    "GL_LINEAR_ATTENUATION",
    "GL_QUADRATIC_ATTENUATION",
];

/// The share of the scene's own distance a value's picture must come under to be kept.
const CLOSER: f64 = 0.7;

/// The weight of the mean levels a picture misses by in place ([`in_place`]) beside those it
/// misses by past the tolerance: where several values' pictures all come within the
/// tolerance of the student's (a shininess of 64 to 75 for 70), the one nearest in place is
/// the value, not the first found (which may be too close to the scene's to show).
const TIE_BREAK: f64 = 0.01;

/// The mean over the pixels `covered` of the levels (the largest channel) by which
/// `picture` misses `image` in place.
fn in_place(picture: &[u8], covered: &[bool], image: &[u8]) -> f64 {
    let (mut sum, mut n) = (0u64, 0u64);
    for (p, _) in covered.iter().enumerate().filter(|(_, c)| **c) {
        let (a, b) = (&picture[p * 4..p * 4 + 3], &image[p * 4..p * 4 + 3]);
        sum += u64::from((0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0));
        n += 1;
    }
    if n == 0 { 0.0 } else { sum as f64 / n as f64 }
}

/// Golden-section steps between the best grid value's neighbours.
const REFINE: usize = 10;

/// The message arguments of each number (per light, then the shininess): the value the
/// picture shows and the scene's.
pub const ARGS: [(&str, &str); 6] = [
    ("cutoff", "cutoff-scene"),
    ("exponent", "exponent-scene"),
    ("constant", "constant-scene"),
    ("linear", "linear-scene"),
    ("quadratic", "quadratic-scene"),
    ("shininess", "shininess-scene"),
];

/// The numbers fitted from the picture, each with the scene's own (picture, scene); `None`
/// where the scene's own is as close.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Values {
    /// Per light: cutoff, exponent, constant, linear, quadratic ([`LIGHT_NAMES`]).
    pub lights: [[Option<(f64, f64)>; 5]; MAX_LIGHTS],
    /// The material's shininess (both sides).
    pub shininess: Option<(f64, f64)>,
    /// Per light and number: the picture shows the light negligible, and the value is the
    /// least of the grid's that makes it so ("≥ value"), not a value the picture tells.
    pub negligible: [[bool; 5]; MAX_LIGHTS],
}

/// An attenuation coefficient so large that nothing of its light reaches the object.
const NEGLIGIBLE: f64 = 1e6;

/// Is a picture at `distance` from the image as close as one at `best`: within a
/// hundredth of a level on the mean, or 1 %?
fn as_close(distance: f64, best: f64) -> bool {
    distance <= best + 0.01 + 0.01 * best
}

/// A fitted number as text: three significant digits at most, no trailing zeros.
pub fn shown(v: f64) -> String {
    let decimals = if v.abs() >= 100.0 {
        0
    } else if v.abs() >= 10.0 {
        1
    } else if v.abs() >= 1.0 {
        2
    } else {
        3
    };
    let digits = if v != 0.0 && v.abs() < 0.001 { format!("{v:.1e}") } else { format!("{v:.decimals$}") };
    if digits.contains('.') && !digits.contains('e') {
        digits.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        digits
    }
}

/// Light number `k` ([`LIGHT_NAMES`]).
pub fn light_value(l: &Light, k: usize) -> f64 {
    match k {
        0 => l.spot_cutoff,
        1 => l.spot_exponent,
        _ => l.attenuation[k - 2],
    }
}

/// Sets light number `k`.
pub fn set_light_value(l: &mut Light, k: usize, v: f64) {
    match k {
        0 => l.spot_cutoff = v,
        1 => l.spot_exponent = v,
        _ => l.attenuation[k - 2] = v,
    }
}

/// Does number `k` take part in light `l`'s lighting: the spot's for a spotlight, the
/// attenuation's for a positional light?
fn used(l: &Light, k: usize) -> bool {
    if k < 2 { l.is_spot() } else { !l.is_directional() }
}

/// The values a program could give number `k` of a light (5 for the shininess): OpenGL's
/// range, denser where students' numbers fall.
fn grid(k: usize) -> Vec<f64> {
    let powers = || {
        [
            0.0, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0, 40.0, 50.0, 64.0, 80.0, 100.0,
            128.0,
        ]
    };
    match k {
        0 => (1..=45).map(|i| f64::from(i) * 2.0).collect(),
        1 | 5 => powers().to_vec(),
        _ => std::iter::once(0.0).chain((0..=24).map(|i| 10f64.powf(-3.0 + f64::from(i) * 0.25))).collect(),
    }
}

/// The number the picture shows for one setting: `set` puts a value in a drawing; the
/// grid is searched, then refined. `None` unless a value's picture is closer than the
/// scene's own (`own`) by [`CLOSER`]; with `true` when the picture at `huge` (the light
/// made negligible) is as close, the value then the least of the grid's that is.
#[allow(clippy::too_many_arguments)]
fn fit_one(
    right: &Drawing,
    set: &dyn Fn(&mut Drawing, f64),
    grid: &[f64],
    own: f64,
    huge: Option<f64>,
    image: &[u8],
    size: usize,
) -> Result<Option<(f64, bool)>, SceneError> {
    let bg = right.background8();
    let measure = |v: f64| -> Result<f64, SceneError> {
        let mut d = right.clone();
        set(&mut d, v);
        let (_, picture, covered) = d.draw(size)?;
        Ok(compare(&picture, &covered, image, bg, size).miss + TIE_BREAK * in_place(&picture, &covered, image))
    };
    let own_distance = measure(own)?;
    // Nothing comes closer than a picture that misses by nothing.
    if own_distance == 0.0 {
        return Ok(None);
    }
    let mut tried: Vec<(f64, f64)> = Vec::with_capacity(grid.len());
    for &v in grid {
        tried.push((v, measure(v)?));
    }
    let Some(best) = (0..tried.len()).min_by(|&a, &b| tried[a].1.total_cmp(&tried[b].1)) else {
        return Ok(None);
    };
    let (mut low, mut high) = (tried[best.saturating_sub(1)].0, tried[(best + 1).min(tried.len() - 1)].0);
    let (mut value, mut at) = tried[best];
    let phi = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..REFINE {
        let (a, b) = (high - phi * (high - low), low + phi * (high - low));
        let (da, db) = (measure(a)?, measure(b)?);
        if da.min(db) < at {
            (value, at) = if da < db { (a, da) } else { (b, db) };
        }
        if da < db { high = b } else { low = a }
    }
    let differs = (value - own).abs() > 0.02 * own.abs().max(1e-3);
    if !(differs && at < CLOSER * own_distance) {
        return Ok(None);
    }
    // An attenuation whose picture is the light's absence tells only a least value: the
    // grid's least whose picture is as close.
    if let Some(huge) = huge.map(measure).transpose()?.filter(|&h| as_close(h, at)) {
        let least =
            tried.iter().filter(|&&(v, d)| v >= own && as_close(d, huge)).map(|&(v, _)| v).fold(value, f64::min);
        return Ok(Some((least, true)));
    }
    Ok(Some((value, false)))
}

/// The numbers `image` (RGBA8, `size` square) shows for `right`'s lights and material.
pub fn fit(right: &Drawing, image: &[u8], size: usize) -> Result<Values, SceneError> {
    let mut out = Values::default();
    for (i, l) in right.scene.lights.iter().enumerate().take(MAX_LIGHTS) {
        for k in 0..LIGHT_NAMES.len() {
            if !used(l, k) {
                continue;
            }
            let set = |d: &mut Drawing, v: f64| set_light_value(&mut d.scene.lights[i], k, v);
            let own = light_value(l, k);
            let huge = (k >= 2).then_some(NEGLIGIBLE);
            let fitted = fit_one(right, &set, &grid(k), own, huge, image, size)?;
            out.lights[i][k] = fitted.map(|(v, _)| (v, own));
            out.negligible[i][k] = fitted.is_some_and(|(_, n)| n);
        }
    }
    let shiny = right.scene.material.specular.truncate().max_element() > 0.0;
    if shiny {
        let set = |d: &mut Drawing, v: f64| {
            d.scene.material.shininess = v;
            if let Some(b) = d.scene.back_material.as_mut() {
                b.shininess = v;
            }
        };
        let own = right.scene.material.shininess;
        out.shininess = fit_one(right, &set, &grid(5), own, None, image, size)?.map(|(v, _)| (v, own));
    }
    Ok(out)
}

/// The pictures [`fit`] draws for `right`, at most.
pub fn drawings(right: &Drawing) -> usize {
    let per = |k: usize| grid(k).len() + 2 + 2 * REFINE;
    let lights: usize =
        right.scene.lights.iter().map(|l| (0..LIGHT_NAMES.len()).filter(|&k| used(l, k)).map(per).sum::<usize>()).sum();
    lights + per(5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fitted_number_shows_three_significant_digits() {
        assert_eq!(shown(24.0), "24");
        assert_eq!(shown(23.96), "24");
        assert_eq!(shown(0.5), "0.5");
        assert_eq!(shown(0.0312), "0.031");
        assert_eq!(shown(128.0), "128");
        assert_eq!(shown(0.0), "0");
        assert_eq!(shown(0.0004), "4.0e-4");
    }
}
