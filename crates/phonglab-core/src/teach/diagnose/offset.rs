//! A region of a picture the right one otherwise explains that is evenly lighter or darker
//! than the right picture: a square painted over at 30 % less, dark initials, a light's
//! attenuation or shininess a little off saved as JPEG. Each pixel may stay within the
//! tolerance and a pixel's shift, so neither the share nor the marks test sees it; over a
//! square of [`BLOCK`] pixels the offset adds up where noise and a lossy saving average
//! out. The picture is first aligned (the best of the nine shifts by a pixel) and the
//! whole object's median offset taken away (a uniform lift is [`super::fit::lifts`]'s).

use crate::teach::picture_match::apart;

/// The side of the squares whose mean offsets are measured, in pixels.
pub const BLOCK: usize = 16;

/// How far the squares slide, in pixels: a quarter of [`BLOCK`], so that any square of
/// [`BLOCK`] pixels shares at least (1 - 1/8)² of its pixels with one measured.
const STEP: usize = BLOCK / 4;

/// The least pixels of a square inside the object for its offset to count: three
/// quarters. A picture moved half a pixel moves a square across the terminator near the
/// outline, half inside, by half its gradient (the spotlight's teapot at 512 pixels: a
/// square of 141 pixels inside, past [`OFFSET_AT`]).
const INSIDE_AT: usize = BLOCK * BLOCK * 3 / 4;

/// The least mean offset (levels, largest channel) of a square for the picture to be
/// changed there. Measured (docs/guide.md): honest pictures (Mesa's, noise of ±3 and ±5,
/// a pixel's shift, blur, resizing, JPEG of quality 90 and 95 of the blind set's right
/// pictures and their scenes' references) reach at most 2.66; a 16-pixel square 12 levels
/// darker reaches 3.8, dark initials 4.0, shininess 66 for 60 5.9.
pub const OFFSET_AT: f64 = 3.5;

/// The square where the picture is most evenly off the right one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Offset {
    /// The mean offset (levels, the channel furthest off, signed: below 0 darker).
    pub levels: f64,
    /// The square's pixels inside the object.
    pub pixels: usize,
    /// Its top-left corner (x from the left, y from the top).
    pub from: (usize, usize),
    /// Its bottom-right corner, included.
    pub to: (usize, usize),
    /// What the image's shift by a fraction of a pixel (fitted over the whole object,
    /// at most half a pixel each way) makes of the square's mean in that channel (levels,
    /// signed): on a steep gradient (the spot's pool's edge) an honest picture drawn at
    /// 1024 pixels, moved one and box-filtered to 512, is 4.7 levels darker over a square.
    pub shift: f64,
}

impl Offset {
    /// How far the square's mean is off beyond what the image's sub-pixel shift makes there.
    pub fn beyond_shift(&self) -> f64 {
        (self.levels - self.shift).abs()
    }
}

/// The object's inside: covered pixels whose 8 neighbours are covered too.
fn inside(covered: &[bool], size: usize) -> Vec<bool> {
    let mut on = vec![false; size * size];
    for y in 1..size.saturating_sub(1) {
        for x in 1..size - 1 {
            on[y * size + x] = (y - 1..=y + 1).all(|ny| (x - 1..=x + 1).all(|nx| covered[ny * size + nx]));
        }
    }
    on
}

/// The shift (dx, dy) of the image by at most a pixel that brings it nearest the picture
/// over `on` (the mean levels apart), none first.
fn aligned(picture: &[u8], image: &[u8], on: &[bool], size: usize) -> (isize, isize) {
    let shifts = [(0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (-1, -1), (1, -1), (-1, 1), (1, 1)];
    let cost = |&(dx, dy): &(isize, isize)| -> u64 {
        (0..size * size)
            .filter(|&p| on[p])
            .map(|p| {
                let q = shifted(p, (dx, dy), size);
                u64::from(apart(&picture[p * 4..p * 4 + 3], &image[q * 4..q * 4 + 3]))
            })
            .sum()
    };
    shifts.iter().min_by_key(|s| cost(s)).copied().unwrap_or((0, 0))
}

/// Pixel `p` moved by `(dx, dy)`, within the picture (`on` keeps a pixel off the border).
fn shifted(p: usize, (dx, dy): (isize, isize), size: usize) -> usize {
    let x = (p % size).saturating_add_signed(dx).min(size - 1);
    let y = (p / size).saturating_add_signed(dy).min(size - 1);
    y * size + x
}

/// The square of [`BLOCK`] (at least [`INSIDE_AT`] of its pixels inside the object) where `image` is most
/// evenly off `picture` (both RGBA8, `size` square, the picture covering `covered`), the
/// object's median offset taken away; `None` when no square holds enough of the object.
pub fn largest_offset(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> Option<Offset> {
    largest_offset_by(picture, covered, image, size, None)
}

/// [`largest_offset`] for a picture found right as saved lossily that may be a JPEG with its
/// colour subsampled (4:2:0): a JPEG keeps the colour once for each 2 x 2 block, which moves
/// a square's red or blue mean near a sharp coloured edge (the spotlight's rim: 3.9 levels
/// at quality 75). What that makes of each square is taken as losses, as a sub-pixel shift
/// is ([`Offset::shift`]): measured on the right picture subsampled so
/// ([`crate::teach::picture_match::subsampled_420`]). An attenuation or a colour off there
/// moves the square beyond it.
pub fn largest_offset_subsampled(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> Option<Offset> {
    let expected = crate::teach::picture_match::subsampled_420(picture, size);
    largest_offset_by(picture, covered, image, size, Some(&expected))
}

/// [`largest_offset`], with what a lossy saving makes of each square (`expected`, the right
/// picture as the saving would make it) taken as losses too.
fn largest_offset_by(
    picture: &[u8],
    covered: &[bool],
    image: &[u8],
    size: usize,
    expected: Option<&[u8]>,
) -> Option<Offset> {
    let on = inside(covered, size);
    let shift = aligned(picture, image, &on, size);
    let diff = |p: usize, c: usize| i32::from(image[shifted(p, shift, size) * 4 + c]) - i32::from(picture[p * 4 + c]);
    let median: Vec<i32> = (0..3).map(|c| median_of((0..size * size).filter(|&p| on[p]).map(|p| diff(p, c)))).collect();
    let sub = sub_pixel(picture, &on, |p, c| f64::from(diff(p, c) - median[c]), size);
    // The squares slide by a quarter of their side: a block painted across a fixed grid's
    // squares (a 16-pixel square from (248, 248) on a 16-pixel grid) would spread over four
    // of them and show a quarter of its offset in each.
    let starts: Vec<usize> = (0..size.saturating_sub(BLOCK / 2)).step_by(STEP).collect();
    let mut best: Option<Offset> = None;
    for (x0, y0) in starts.iter().flat_map(|&y| starts.iter().map(move |&x| (x, y))) {
        let (x1, y1) = ((x0 + BLOCK).min(size) - 1, (y0 + BLOCK).min(size) - 1);
        let pixels: Vec<usize> =
            (y0..=y1).flat_map(|y| (x0..=x1).map(move |x| y * size + x)).filter(|&p| on[p]).collect();
        if pixels.len() < INSIDE_AT {
            continue;
        }
        let mean =
            |c: usize| pixels.iter().map(|&p| f64::from(diff(p, c) - median[c])).sum::<f64>() / pixels.len() as f64;
        let saved = |c: usize| {
            expected.map_or(0.0, |e| {
                pixels.iter().map(|&p| f64::from(e[p * 4 + c]) - f64::from(picture[p * 4 + c])).sum::<f64>()
                    / pixels.len() as f64
            })
        };
        // With a saving's expectation, the square is off only beyond both what the shift
        // makes and what the shift and the saving make: a picture moved half a pixel before
        // it was saved meets the 2 x 2 blocks at another phase than the right picture's.
        let losses = |c: usize, m: f64| {
            let s = shifted_by(picture, &pixels, c, sub, size);
            let with = s + saved(c);
            if (m - with).abs() < (m - s).abs() { with } else { s }
        };
        let (levels, shift) = (0..3)
            .map(|c| (mean(c), losses(c, mean(c))))
            .max_by(|a, b| (a.0 - a.1).abs().total_cmp(&(b.0 - b.1).abs()))
            .unwrap_or((0.0, 0.0));
        let square = Offset { levels, pixels: pixels.len(), from: (x0, y0), to: (x1, y1), shift };
        if best.is_none_or(|b| square.beyond_shift() > b.beyond_shift()) {
            best = Some(square);
        }
    }
    best
}

/// The central differences across and down of `picture`'s channel `c` at `p` (inside the
/// object: it has its four neighbours).
fn gradient(picture: &[u8], p: usize, c: usize, size: usize) -> (f64, f64) {
    let at = |q: usize| f64::from(picture[q * 4 + c]);
    ((at(p + 1) - at(p - 1)) / 2.0, (at(p + size) - at(p - size)) / 2.0)
}

/// The image's shift by a fraction of a pixel, as the multiples (across, down) of the
/// picture's gradient that best make the difference `diff` (least squares over the
/// object's inside `on`, the three channels), each at most half a pixel: a shift the
/// whole image shares, which a mark or a value's change, not lined up with the
/// gradient everywhere, does not make.
fn sub_pixel(picture: &[u8], on: &[bool], diff: impl Fn(usize, usize) -> f64, size: usize) -> (f64, f64) {
    let (mut xx, mut xy, mut yy, mut xd, mut yd) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for p in (0..size * size).filter(|&p| on[p]) {
        for c in 0..3 {
            let ((gx, gy), d) = (gradient(picture, p, c, size), diff(p, c));
            (xx, xy, yy, xd, yd) = (xx + gx * gx, xy + gx * gy, yy + gy * gy, xd + gx * d, yd + gy * d);
        }
    }
    let half = |v: f64| if v.is_finite() { v.clamp(-0.5, 0.5) } else { 0.0 };
    let det = xx * yy - xy * xy;
    if det.abs() <= 1e-9 * (xx * yy).max(1.0) {
        // A gradient all one way (or none): each direction alone.
        return (half(xd / xx), half(yd / yy));
    }
    (half((xd * yy - yd * xy) / det), half((yd * xx - xd * xy) / det))
}

/// What the sub-pixel shift `(a, b)` ([`sub_pixel`]) makes of the mean of `picture`'s
/// channel `c` over `pixels` (levels, signed).
fn shifted_by(picture: &[u8], pixels: &[usize], c: usize, (a, b): (f64, f64), size: usize) -> f64 {
    let n = pixels.len().max(1) as f64;
    pixels
        .iter()
        .map(|&p| {
            let (gx, gy) = gradient(picture, p, c, size);
            a * gx + b * gy
        })
        .sum::<f64>()
        / n
}

/// The mean offset (levels, the channel furthest off, signed) of `image` from `picture`
/// (both RGBA8, `size` square, the picture covering `covered`) over the square of `at`,
/// in place and, the object's median offset taken away as [`largest_offset`] takes it.
pub fn offset_over(picture: &[u8], covered: &[bool], image: &[u8], at: Offset, size: usize) -> f64 {
    let on = inside(covered, size);
    let diff = |p: usize, c: usize| i32::from(image[p * 4 + c]) - i32::from(picture[p * 4 + c]);
    let median: Vec<i32> = (0..3).map(|c| median_of((0..size * size).filter(|&p| on[p]).map(|p| diff(p, c)))).collect();
    let pixels: Vec<usize> = (at.from.1..=at.to.1)
        .flat_map(|y| (at.from.0..=at.to.0).map(move |x| y * size + x))
        .filter(|&p| on[p])
        .collect();
    let mean =
        |c: usize| pixels.iter().map(|&p| f64::from(diff(p, c) - median[c])).sum::<f64>() / pixels.len().max(1) as f64;
    (0..3).map(mean).max_by(|a, b| a.abs().total_cmp(&b.abs())).unwrap_or(0.0)
}

/// The median of `values` (levels, −255 to 255); 0 when there are none.
fn median_of(values: impl Iterator<Item = i32>) -> i32 {
    let mut count = [0usize; 511];
    let mut n = 0;
    for v in values {
        count[(v + 255) as usize] += 1;
        n += 1;
    }
    let mut seen = 0;
    for (k, c) in count.iter().enumerate() {
        seen += c;
        if n > 0 && seen * 2 >= n {
            return k as i32 - 255;
        }
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A picture 64 square, all covered, a smooth gradient, with `lift` added over the
    /// square from (20, 20) of `side` pixels, and noise of up to ±`noise` levels.
    fn picture(lift: i32, side: usize, noise: i32) -> Vec<u8> {
        let size = 64;
        let mut seed = 11u32;
        (0..size * size)
            .flat_map(|p| {
                let (x, y) = (p % size, p / size);
                let inside = (20..20 + side).contains(&x) && (20..20 + side).contains(&y);
                let mut px = [0u8; 4];
                for (c, v) in px.iter_mut().take(3).enumerate() {
                    seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
                    let n = if noise > 0 { ((seed >> 16) % (2 * noise as u32 + 1)) as i32 - noise } else { 0 };
                    *v = (60 + 2 * x as i32 + c as i32 * 10 + if inside { lift } else { 0 } + n).clamp(0, 255) as u8;
                }
                px[3] = 255;
                px
            })
            .collect()
    }

    #[test]
    fn a_square_evenly_darker_is_found_and_noise_or_a_shift_is_not() {
        let size = 64;
        let covered = vec![true; size * size];
        let right = picture(0, 0, 0);
        // 12 levels darker over 16 x 16 pixels: found, about where it is.
        let o = largest_offset(&right, &covered, &picture(-12, 16, 0), size).expect("an offset");
        assert!(o.levels <= -OFFSET_AT, "{o:?}");
        assert!(o.from.0 <= 20 + 8 && o.to.0 >= 20 + 8, "{o:?}");
        // 8 levels darker over 16 x 16 pixels from (24, 24), across the squares of a fixed
        // 16-pixel grid (a quarter in each: 2 levels): found by the sliding squares.
        let mut straddling = right.clone();
        for p in (0..size * size).filter(|p| (24..40).contains(&(p % size)) && (24..40).contains(&(p / size))) {
            for c in 0..3 {
                straddling[p * 4 + c] -= 8;
            }
        }
        let o = largest_offset(&right, &covered, &straddling, size).expect("an offset");
        assert!(o.levels <= -6.0 && o.from == (24, 24), "{o:?}");
        // Noise of ±5 and the picture moved a pixel: nowhere near.
        let noisy = picture(0, 0, 5);
        let o = largest_offset(&right, &covered, &noisy, size).expect("an offset");
        assert!(o.levels.abs() < 1.5, "{o:?}");
        let moved: Vec<u8> = (0..size * size)
            .flat_map(|p| {
                let q = if p % size == 0 { p } else { p - 1 };
                right[q * 4..q * 4 + 4].to_vec()
            })
            .collect();
        let o = largest_offset(&right, &covered, &moved, size).expect("an offset");
        assert!(o.levels.abs() < 1.0, "{o:?}");
        // The whole picture lifted evenly is no region's offset.
        let lifted: Vec<u8> = right.iter().enumerate().map(|(i, &v)| if i % 4 == 3 { v } else { v + 4 }).collect();
        let o = largest_offset(&right, &covered, &lifted, size).expect("an offset");
        assert!(o.levels.abs() < 0.5, "{o:?}");
    }

    #[test]
    fn half_a_pixel_s_shift_on_a_steep_edge_is_not_an_offset() {
        // Flat at 40, a ramp of 12 levels a pixel over x 20..36, flat at 232: moved half a
        // pixel (each pixel the mean of itself and its left neighbour), the ramp's pixels
        // are 6 levels darker, a square's mean as far off as a painted mark's.
        let size = 64;
        let covered = vec![true; size * size];
        let level = |x: f64| (40.0 + 12.0 * (x - 20.0).clamp(0.0, 16.0)).round() as u8;
        let draw = |dx: f64| -> Vec<u8> {
            (0..size * size)
                .flat_map(|p| {
                    let v = level((p % size) as f64 - dx);
                    [v, v, v, 255]
                })
                .collect()
        };
        let (right, moved) = (draw(0.0), draw(0.5));
        let o = largest_offset(&right, &covered, &moved, size).expect("an offset");
        let on_ramp = Offset { from: (20, 0), to: (35, 15), ..o };
        let raw = offset_over(&right, &covered, &moved, on_ramp, size);
        assert!(raw.abs() >= OFFSET_AT, "as far off as a mark: {raw}");
        assert!(o.beyond_shift() < OFFSET_AT, "but no further than half a pixel's shift makes: {o:?}");
        // A mark 12 levels darker on the same edge is still beyond it.
        let mut marked = right.clone();
        for p in (0..size * size).filter(|p| (20..36).contains(&(p % size)) && (24..40).contains(&(p / size))) {
            for c in 0..3 {
                marked[p * 4 + c] -= 12;
            }
        }
        let o = largest_offset(&right, &covered, &marked, size).expect("an offset");
        assert!(o.beyond_shift() >= OFFSET_AT, "{o:?}");
    }
}
