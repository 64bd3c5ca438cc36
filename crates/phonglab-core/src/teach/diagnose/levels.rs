//! The picture's levels changed as a whole: a gamma, a brightness or a colour profile
//! applied to the picture as saved (an image editor, a screenshot tool, a monitor's
//! profile). It explains the picture as well as any mistake does, which is all it tells: a
//! lighting mistake may hide under it (a wrong picture then darkened reads so too). Such a change moves every pixel by a function
//! of its level alone, so it is fitted from the right picture's levels to the student's:
//! a gamma (`255 (v / 255)^g`, the same for every channel) or an offset (`v + b`, clamped),
//! applied to the whole picture, its background included. A mistake is named rather than
//! this change only when its picture is clearly closer to the student's ([`clearly_closer`]):
//! an emission added lifts the dark pixels as much as the bright ones, and a gamma does
//! not; an attenuation changes the lit pixels and spares the background and the ambient.

use crate::teach::picture_match::{Match, TOLERANCE, compare};

// How much closer (in mean levels, the share of the change's) a mistake's picture must be
// to the student's to be named rather than the change of levels: as the footprint asks.
use super::footprint::CLEARLY;

/// The gammas tried: from 1/2 to 2, in steps of half a percent.
const GAMMAS: std::ops::RangeInclusive<i32> = -139..=139;

/// The offsets tried, in levels.
const OFFSETS: std::ops::RangeInclusive<i16> = -48..=48;

/// The share of the background that must keep the changed picture's background colour.
const BACKGROUND_KEPT: f64 = 0.99;

/// A change of the whole picture's levels that explains the student's picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Levels {
    /// The mean change over the object's pixels, in levels (negative: darker), where
    /// neither the right level nor the changed one is clamped.
    pub shift: f64,
    /// The gamma fitted (`None`: an offset).
    pub gamma: Option<f64>,
    /// The changed right picture against the student's.
    pub matched: Match,
    /// The mean levels (per pixel, the three channels summed) by which the changed right
    /// picture misses the student's over the object's inner pixels, in place.
    pub distance: f64,
}

/// A tone curve: a gamma or an offset.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Curve {
    Gamma(f64),
    Offset(i16),
}

impl Curve {
    /// Level `v` changed.
    fn level(self, v: u8) -> u8 {
        match self {
            Curve::Gamma(g) => (255.0 * (f64::from(v) / 255.0).powf(g)).round().clamp(0.0, 255.0) as u8,
            Curve::Offset(b) => (i16::from(v) + b).clamp(0, 255) as u8,
        }
    }
}

/// The object's inner pixels (the 3 x 3 around each covered): there a picture moved by a
/// pixel differs from the right one by a pixel's gradient at most, never by the background.
pub fn inner_pixels(covered: &[bool], size: usize) -> Vec<usize> {
    let inner = |p: usize| {
        let (x, y) = (p % size, p / size);
        x > 0
            && y > 0
            && x + 1 < size
            && y + 1 < size
            && (y - 1..=y + 1).all(|qy| (x - 1..=x + 1).all(|qx| covered[qy * size + qx]))
    };
    (0..size * size).filter(|&p| inner(p)).collect()
}

/// The mean over the pixels `at` of the levels (the three channels summed) by which
/// `picture` misses `image` in place.
pub fn distance(picture: &[u8], image: &[u8], at: &[usize]) -> f64 {
    if at.is_empty() {
        return 0.0;
    }
    let sum: u64 =
        at.iter().map(|&p| (0..3).map(|c| u64::from(picture[p * 4 + c].abs_diff(image[p * 4 + c]))).sum::<u64>()).sum();
    sum as f64 / at.len() as f64
}

/// The curve that best takes the right picture's levels at `flat` to `image`'s (least
/// squares over the pixels where neither is clamped), among those that keep the background
/// the student's picture shows (`background`, [`Background::keeps`]).
fn best_curve(picture: &[u8], image: &[u8], flat: &[usize], bg: [u8; 3], background: &Background) -> Option<Curve> {
    // How many pixels take each right level to each student's level, per channel.
    let mut pairs = vec![0u32; 256 * 256];
    for &p in flat {
        for c in 0..3 {
            let (r, i) = (picture[p * 4 + c], image[p * 4 + c]);
            if (1..=254).contains(&r) && (1..=254).contains(&i) {
                pairs[usize::from(r) * 256 + usize::from(i)] += 1;
            }
        }
    }
    let used: Vec<(u8, u8, f64)> = pairs
        .iter()
        .enumerate()
        .filter(|(_, n)| **n > 0)
        .map(|(k, &n)| ((k / 256) as u8, (k % 256) as u8, f64::from(n)))
        .collect();
    let cost = |curve: Curve| -> f64 {
        let table: Vec<f64> = (0..=255u8).map(|v| f64::from(curve.level(v))).collect();
        used.iter().map(|&(r, i, n)| n * (table[usize::from(r)] - f64::from(i)).powi(2)).sum()
    };
    let gammas = GAMMAS.map(|k| Curve::Gamma(2f64.powf(f64::from(k) / 139.0)));
    let offsets = OFFSETS.map(Curve::Offset);
    gammas
        .chain(offsets)
        .filter(|c| background.keeps(bg.map(|v| c.level(v))))
        .map(|c| (c, cost(c)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(c, _)| c)
}

/// The colours of the student's picture where no object is near (no covered pixel in the
/// 3 x 3), each with its count.
struct Background(Vec<([u8; 3], usize)>);

impl Background {
    /// The background of `image` around the object `covered` (`size` square).
    fn of(covered: &[bool], image: &[u8], size: usize) -> Background {
        let near = |p: usize| {
            let (x, y) = ((p % size) as i64, (p / size) as i64);
            (-1..=1).any(|dy| {
                (-1..=1).any(|dx| {
                    let (qx, qy) = (x + dx, y + dy);
                    qx >= 0
                        && qy >= 0
                        && qx < size as i64
                        && qy < size as i64
                        && covered[qy as usize * size + qx as usize]
                })
            })
        };
        let mut colours: std::collections::BTreeMap<[u8; 3], usize> = std::collections::BTreeMap::new();
        for p in (0..size * size).filter(|&p| !near(p)) {
            *colours.entry([image[p * 4], image[p * 4 + 1], image[p * 4 + 2]]).or_default() += 1;
        }
        Background(colours.into_iter().collect())
    }

    /// Does it show `bg` (within [`TOLERANCE`]) at [`BACKGROUND_KEPT`] of its pixels (true
    /// when there are none)?
    fn keeps(&self, bg: [u8; 3]) -> bool {
        let all: usize = self.0.iter().map(|(_, n)| n).sum();
        let kept: usize =
            self.0.iter().filter(|(c, _)| (0..3).all(|k| c[k].abs_diff(bg[k]) <= TOLERANCE)).map(|(_, n)| n).sum();
        all == 0 || kept as f64 >= BACKGROUND_KEPT * all as f64
    }
}

/// The change of levels that explains `image` (RGBA8, `size` square), given the right
/// picture `picture` with `covered` on the background `bg` and its inner pixels `flat`
/// ([`inner_pixels`]): `None` when the best curve leaves the right picture within
/// [`TOLERANCE`] of itself, or none keeps the background the student's picture shows.
pub fn fit(picture: &[u8], covered: &[bool], image: &[u8], bg: [u8; 3], flat: &[usize], size: usize) -> Option<Levels> {
    let curve = best_curve(picture, image, flat, bg, &Background::of(covered, image, size))?;
    let moves =
        flat.iter().any(|&p| (0..3).any(|c| curve.level(picture[p * 4 + c]).abs_diff(picture[p * 4 + c]) > TOLERANCE));
    if !moves {
        return None;
    }
    let changed_bg = bg.map(|v| curve.level(v));
    let changed: Vec<u8> = picture
        .chunks_exact(4)
        .flat_map(|px| [curve.level(px[0]), curve.level(px[1]), curve.level(px[2]), px[3]])
        .collect();
    // The change where neither level is clamped (a level taken to 0 says only that it
    // went down by as much as it was).
    let unclamped = |v: u8| (1..=254).contains(&v);
    let moved: Vec<i64> = (0..size * size)
        .filter(|&p| covered[p])
        .flat_map(|p| (0..3).map(move |c| p * 4 + c))
        .filter(|&k| unclamped(picture[k]) && unclamped(changed[k]))
        .map(|k| i64::from(changed[k]) - i64::from(picture[k]))
        .collect();
    let shift = moved.iter().sum::<i64>() as f64 / moved.len().max(1) as f64;
    Some(Levels {
        shift,
        gamma: match curve {
            Curve::Gamma(g) => Some(g),
            Curve::Offset(_) => None,
        },
        matched: compare(&changed, covered, image, changed_bg, size),
        distance: distance(&changed, image, flat),
    })
}

/// Is a mistake's picture, missing the student's by `distance` ([`distance`]) and matching
/// as `matched`, clearly closer to it than the change of levels `levels`: a larger share
/// by `margin` (the diagnosis's `MARGIN`), or at most [`CLEARLY`] of its distance?
pub fn clearly_closer(matched: Match, distance: f64, levels: &Levels, margin: f64) -> bool {
    matched.score >= levels.matched.score + margin || distance <= CLEARLY * levels.distance
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 16 x 16 picture: a ramp of levels on the middle 12 x 12 (covered), black around.
    fn ramp() -> (Vec<u8>, Vec<bool>) {
        let size = 16;
        let mut picture = vec![0u8; size * size * 4];
        let mut covered = vec![false; size * size];
        for p in 0..size * size {
            let (x, y) = (p % size, p / size);
            picture[p * 4 + 3] = 255;
            if (2..14).contains(&x) && (2..14).contains(&y) {
                covered[p] = true;
                let v = (20 + 16 * (x - 2) + (y - 2) / 6) as u8;
                picture[p * 4..p * 4 + 3].copy_from_slice(&[v, v / 2, v / 3]);
            }
        }
        (picture, covered)
    }

    #[test]
    fn a_gamma_over_the_whole_picture_is_fitted_and_an_emission_is_not() {
        let (picture, covered) = ramp();
        // Flat enough: the ramp moves 16 levels a column, so take every covered pixel.
        let flat: Vec<usize> = (0..256).filter(|&p| covered[p]).collect();
        let gamma: Vec<u8> = picture
            .chunks_exact(4)
            .flat_map(|px| {
                [Curve::Gamma(0.9).level(px[0]), Curve::Gamma(0.9).level(px[1]), Curve::Gamma(0.9).level(px[2]), 255]
            })
            .collect();
        let levels = fit(&picture, &covered, &gamma, [0; 3], &flat, 16).expect("a gamma");
        assert!(levels.gamma.is_some_and(|g| (g - 0.9).abs() < 0.01), "{levels:?}");
        assert!(levels.shift > 3.0 && levels.matched.score == 1.0, "{levels:?}");
        // An emission of 20 levels lifts the object, not the black background: an offset
        // would lift both, and no gamma lifts the dark levels as much as the bright ones.
        let lifted: Vec<u8> = (0..256)
            .flat_map(|p| {
                let px = &picture[p * 4..p * 4 + 4];
                let e = if covered[p] { 20 } else { 0 };
                [px[0] + e, px[1] + e, px[2] + e, 255]
            })
            .collect();
        let levels = fit(&picture, &covered, &lifted, [0; 3], &flat, 16);
        assert!(levels.is_none_or(|l| l.matched.score < 0.9), "{levels:?}");
        // Four levels darker, the black background kept black (clamped): an offset.
        let darker: Vec<u8> =
            picture.iter().enumerate().map(|(k, &v)| if k % 4 == 3 { v } else { v.saturating_sub(4) }).collect();
        let levels = fit(&picture, &covered, &darker, [0; 3], &flat, 16).expect("an offset");
        assert_eq!((levels.gamma, levels.shift.round()), (None, -4.0));
        // The right picture itself is no change.
        assert_eq!(fit(&picture, &covered, &picture, [0; 3], &flat, 16), None);
    }
}
