//! Whether a picture's difference from another is a change of the picture, not losses: a
//! lossy saving (JPEG, noise) scatters each 8 x 8 block's mean about zero, and a resize, a
//! blur or a sub-pixel shift moves a pixel by at most about half its step to its
//! neighbours; a colour or a value a few levels off lowers or lifts every pixel of a light's
//! footprint alike, a mean over many blocks that neither can make (issue 57: the red light's
//! diffuse 5 levels low, saved as JPEG of quality 75 to 95 or with noise of ±3 and ±5, was
//! "right as saved lossily").

/// The side of the squares the difference's mean is tested over (pixels).
pub const TILE: usize = 32;

/// The blocks whose means are the samples: JPEG's, so that its error, alike within a block,
/// is counted once per block.
const BLOCK: usize = 8;

/// The fewest measured pixels a block needs to be a sample, and a square its samples.
const BLOCK_PIXELS: usize = 32;
const TILE_BLOCKS: usize = 8;

/// Levels from 0 and 255 within which a channel is not measured: noise and JPEG's ringing
/// are clipped there, which lifts the mean of a channel near 0 (the Phong demo's blue, +1.5
/// levels with noise of ±5) as a change would.
const CLIPPED: u8 = 12;

/// The least standard error a square's mean is taken against (levels).
const ERROR_FLOOR: f64 = 0.1;

/// How many standard errors beyond what a half-pixel shift makes a square's mean must be
/// to be a change of the picture. Measured (scripts/diagnose-table.sh at 512 and the
/// issue's pictures in /tmp/h57/p): honest pictures (JPEG of quality 75 to 95, 4:4:4 and
/// 4:2:0, noise of ±3 and ±5, blur, resizes, antialiasing, 1024 box-filtered and shifted a
/// pixel, half-pixel shifts) at most 4.7; wrong values (a light's diffuse 5 levels low, a
/// linear attenuation 0.1 for 0.11, a shininess 10 % off) saved lossily 9.8 and up, except
/// a spot exponent 9 for 8 (5.7), the three-lights' attenuation 0.11 at quality 75 (5.8)
/// and the Phong demo's shininess 90 for 100 at quality 90 and 95 (4.0, 4.7): those the
/// picture cannot tell from its losses.
pub const SYSTEMATIC_AT: f64 = 8.0;

/// A square where the image is evenly lighter or darker than the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bias {
    /// The square's top left pixel.
    pub at: (usize, usize),
    /// The channel (0 red, 1 green, 2 blue).
    pub channel: usize,
    /// The mean difference, image less picture (levels).
    pub levels: f64,
    /// How many standard errors it lies beyond what a half-pixel shift makes there.
    pub errors: f64,
}

/// The square of `image` whose mean difference from `picture` (RGBA8, `size` square, the
/// object `covered`) in a channel lies furthest beyond what losses and a sub-pixel shift
/// make, when it lies [`SYSTEMATIC_AT`] standard errors beyond.
pub fn systematic(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> Option<Bias> {
    let inner = inner(covered, size);
    let mut best: Option<Bias> = None;
    for ty in (0..size).step_by(TILE) {
        for tx in (0..size).step_by(TILE) {
            for channel in 0..3 {
                let Some(b) = tile_bias(picture, &inner, image, size, (tx, ty), channel) else { continue };
                if best.is_none_or(|x| b.errors > x.errors) {
                    best = Some(b);
                }
            }
        }
    }
    best.filter(|b| b.errors >= SYSTEMATIC_AT)
}

/// The pixels whose 3 x 3 neighbourhood is all of the object.
fn inner(covered: &[bool], size: usize) -> Vec<bool> {
    let mut out = vec![false; size * size];
    for y in 1..size.saturating_sub(1) {
        for x in 1..size - 1 {
            out[y * size + x] = (y - 1..=y + 1).all(|qy| (x - 1..=x + 1).all(|qx| covered[qy * size + qx]));
        }
    }
    out
}

/// The square from `(tx, ty)`'s bias in `channel`: its blocks' mean difference, how far
/// beyond half the picture's mean step to a neighbour there, in standard errors of the
/// blocks' means; `None` when too little of it is measured.
fn tile_bias(
    picture: &[u8],
    inner: &[bool],
    image: &[u8],
    size: usize,
    (tx, ty): (usize, usize),
    channel: usize,
) -> Option<Bias> {
    let (x1, y1) = ((tx + TILE).min(size), (ty + TILE).min(size));
    let at = |x: usize, y: usize| picture[(y * size + x) * 4 + channel];
    let pixels: Vec<(usize, usize)> =
        (ty..y1).flat_map(|y| (tx..x1).map(move |x| (x, y))).filter(|&(x, y)| inner[y * size + x]).collect();
    if pixels.len() < TILE * TILE / 2 {
        return None;
    }
    let step = |(x, y): (usize, usize)| {
        let v = at(x, y);
        [(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)]
            .iter()
            .map(|&(qx, qy)| v.abs_diff(at(qx, qy)))
            .max()
            .unwrap_or(0)
    };
    let shift = 0.5 * pixels.iter().map(|&p| f64::from(step(p))).sum::<f64>() / pixels.len() as f64;
    let means = block_means(picture, inner, image, size, (tx, ty), (x1, y1), channel);
    if means.len() < TILE_BLOCKS {
        return None;
    }
    let n = means.len() as f64;
    let mean = means.iter().sum::<f64>() / n;
    let spread = (means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let error = (spread / n.sqrt()).max(ERROR_FLOOR);
    Some(Bias { at: (tx, ty), channel, levels: mean, errors: (mean.abs() - shift) / error })
}

/// The mean difference (image less picture) of each 8 x 8 block of the square from
/// `(tx, ty)` to `(x1, y1)` over its inner pixels whose `channel` is not near clipping.
fn block_means(
    picture: &[u8],
    inner: &[bool],
    image: &[u8],
    size: usize,
    (tx, ty): (usize, usize),
    (x1, y1): (usize, usize),
    channel: usize,
) -> Vec<f64> {
    let mut means = Vec::new();
    for by in (ty..y1).step_by(BLOCK) {
        for bx in (tx..x1).step_by(BLOCK) {
            let (mut sum, mut count) = (0i64, 0usize);
            for y in by..(by + BLOCK).min(y1) {
                for x in bx..(bx + BLOCK).min(x1) {
                    let p = (y * size + x) * 4 + channel;
                    if inner[y * size + x] && (CLIPPED..=255 - CLIPPED).contains(&picture[p]) {
                        sum += i64::from(image[p]) - i64::from(picture[p]);
                        count += 1;
                    }
                }
            }
            if count >= BLOCK_PIXELS {
                means.push(sum as f64 / count as f64);
            }
        }
    }
    means
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A smooth picture (a gentle ramp), RGBA8, all of it the object.
    fn ramp(size: usize) -> Vec<u8> {
        (0..size * size).flat_map(|p| [(60 + (p % size) / 4) as u8, 100, 140, 255]).collect()
    }

    #[test]
    fn noise_is_not_a_change_and_a_few_levels_over_a_square_are() {
        let size = 128;
        let picture = ramp(size);
        let covered = vec![true; size * size];
        let mut s = 7u32;
        let noised: Vec<u8> = picture
            .iter()
            .enumerate()
            .map(|(i, &v)| {
                s = s.wrapping_mul(1_103_515_245).wrapping_add(12345);
                if i % 4 == 3 { v } else { (i32::from(v) + ((s >> 16) % 11) as i32 - 5) as u8 }
            })
            .collect();
        assert_eq!(systematic(&picture, &covered, &noised, size), None);
        // The same noise, and the red of one square 2 levels low.
        let mut changed = noised.clone();
        for y in 32..64 {
            for x in 64..96 {
                changed[(y * size + x) * 4] -= 2;
            }
        }
        let b = systematic(&picture, &covered, &changed, size).expect("a change");
        assert_eq!((b.at, b.channel), ((64, 32), 0));
        assert!((b.levels + 2.0).abs() < 0.5, "{b:?}");
    }
}
