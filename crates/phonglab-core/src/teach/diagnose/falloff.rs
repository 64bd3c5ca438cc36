//! Whether a picture shows an attenuation fitted from it (`attenuation-*-differs`): an
//! attenuation scales each pixel of its light by a factor that falls with the distance to
//! the light, and over an object small beside that distance the factor is nearly the same
//! everywhere: a light's or a material's colour a few levels off draws nearly the picture
//! of some attenuation (the spotlight's diffuse 6 levels darker, a quadratic attenuation;
//! the Phong demo's diffuse 0.388 for 0.4, a linear one, on a scene with none). The
//! attenuation is named only where its picture is clearly nearer the student's than the
//! colours fitted from the picture ([`super::colours`]) are: where the picture's falloff
//! with distance shows it.

use crate::model::error::SceneError;

use super::colours::{self, Colours};
use super::drawing::Drawing;
use super::values::{self, Values};

/// How much nearer (the squared levels past the best neighbour) the student's picture
/// must be to the attenuation's drawing than to the fitted colours' drawing, where the
/// attenuation's differs from the right picture, for its falloff to show: by a twentieth,
/// past what noise adds to one more than the other. Measured at 256 pixels (the tests of
/// `diagnose_measured` and `diagnose::any_single_number_mistake...`): a colour a few levels
/// off is far nearer its fitted colours' drawing than any attenuation's (the Phong demo's
/// diffuse 0.388: the linear attenuation's 2.6 times as far; three lights' green 0.87: 17
/// times; the spotlight's diffuse 6 levels darker: 44 times); the spotlight's linear
/// attenuation 0.07 for 0.05 is 0.14 times as far from its own drawing as from the
/// colours'; a quadratic attenuation 10 times too large on the test sphere's spot, moved a
/// pixel with noise of ±2, 0.91 times.
pub const FALLOFF_AT: f64 = 0.95;

/// The attenuation numbers of light `l` in [`Values::lights`] (constant, linear, quadratic).
const ATTENUATIONS: std::ops::Range<usize> = 2..5;

/// `values` without the attenuations fitted from `image` (RGBA8, `size` square) whose
/// falloff the picture does not show ([`FALLOFF_AT`]) beside the colours `colours` fitted
/// from it; `right` is the scene's drawing and `picture` its right picture. An attenuation
/// that makes its light negligible is kept: no colour is fitted for an absent light.
pub fn shown(
    right: &Drawing,
    (picture, covered): (&[u8], &[bool]),
    colours: Option<&Colours>,
    mut values: Values,
    image: &[u8],
    size: usize,
) -> Result<Values, SceneError> {
    let Some(c) = colours else { return Ok(values) };
    let fitted = colours::with_products(right, &c.fitted).draw(size)?.1;
    let inside = colours::interior(covered, size);
    for l in 0..right.scene.lights.len().min(values.lights.len()) {
        for k in ATTENUATIONS {
            let Some((v, _)) = values.lights[l][k] else { continue };
            if values.negligible[l][k] {
                continue;
            }
            let mut d = right.clone();
            values::set_light_value(&mut d.scene.lights[l], k, v);
            let attenuated = d.draw(size)?.1;
            let moved: Vec<usize> = inside.iter().copied().filter(|&p| apart(&attenuated, picture, p) >= 2).collect();
            let to_attenuated: f64 = moved.iter().map(|&p| nearest(&attenuated, image, p, size)).sum();
            let to_colours: f64 = moved.iter().map(|&p| nearest(&fitted, image, p, size)).sum();
            if to_attenuated > FALLOFF_AT * to_colours {
                values.lights[l][k] = None;
            }
        }
    }
    Ok(values)
}

/// The pictures [`shown`] draws for `right`, at most: the fitted colours' and each
/// attenuation's of each light.
pub fn drawings(right: &Drawing) -> usize {
    1 + ATTENUATIONS.len() * right.scene.lights.len()
}

/// The largest channel difference of pixel `p` of two RGBA8 pictures.
fn apart(a: &[u8], b: &[u8], p: usize) -> u8 {
    (0..3).map(|c| a[p * 4 + c].abs_diff(b[p * 4 + c])).max().unwrap_or(0)
}

/// The squared levels (the three channels summed) by which pixel `p` of `a` misses the
/// nearest of the 3 x 3 around it in `b` (both RGBA8, `size` square; `p` off the border):
/// a picture a pixel off is measured where it sits.
fn nearest(a: &[u8], b: &[u8], p: usize, size: usize) -> f64 {
    let squared =
        |q: usize| -> f64 { (0..3).map(|c| (f64::from(a[p * 4 + c]) - f64::from(b[q * 4 + c])).powi(2)).sum() };
    let (x, y) = (p % size, p / size);
    (y - 1..=y + 1)
        .flat_map(|qy| (x - 1..=x + 1).map(move |qx| qy * size + qx))
        .map(squared)
        .fold(f64::INFINITY, f64::min)
}
