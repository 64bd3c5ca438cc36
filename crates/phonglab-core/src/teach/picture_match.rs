//! How well a picture explains an image of the same scene: over the object's pixels, each
//! pixel of one must find its colour in the other within a pixel's shift (the 3 x 3
//! neighbourhood: rasterisers differ by a pixel at the edges) and within [`TOLERANCE`]
//! levels of 8 bits (each channel; the rounding of two implementations and a little noise).

/// Levels (of 255, per channel) by which two colours may differ and still match.
pub const TOLERANCE: u8 = 3;

/// How a picture matches an image (both RGBA8, `size` pixels square).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Match {
    /// The share of the object's pixels that match (1 when all do).
    pub score: f64,
    /// The object's pixels: covered in the picture, or unlike the background in the image.
    pub pixels: usize,
    /// The pixel that differs most (x from the left, y from the top).
    pub worst: (usize, usize),
    /// How much it differs there: levels past the best neighbour, the largest channel.
    pub worst_levels: u8,
    /// How far it is, continuously: the mean over the object's pixels of the levels by which
    /// a pixel misses its best neighbour past [`TOLERANCE`] (noise within it costs nothing).
    /// A search for the value a picture shows descends on it where `score` is flat.
    pub miss: f64,
}

/// The largest channel difference of two RGBA8 pixels.
pub(crate) fn apart(a: &[u8], b: &[u8]) -> u8 {
    (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0)
}

/// The smallest difference between pixel `p` of `a` and the 3 x 3 around it in `b`.
///
/// The diagnosis asks this of most pixels that differ, for every mistake it tries (a
/// quarter of a `diagnose` run's time was here): a pixel inside the picture reads its
/// three rows of three as three slices, one bounds check a row; only the border's pixels
/// go neighbour by neighbour ([`nearest_at_border`], the same answer).
pub(crate) fn nearest(a: &[u8], b: &[u8], size: usize, p: usize) -> u8 {
    let (x, y) = (p % size, p / size);
    if x == 0 || y == 0 || x + 1 >= size || y + 1 >= size {
        return nearest_at_border(a, b, size, p);
    }
    let here = &a[p * 4..p * 4 + 3];
    let mut best = u8::MAX;
    for row in [p - size, p, p + size] {
        let three = &b[(row - 1) * 4..(row + 2) * 4];
        for q in three.chunks_exact(4) {
            best = best.min(apart(here, q));
        }
    }
    best
}

/// [`nearest`] for any pixel, the neighbours outside the picture left out.
fn nearest_at_border(a: &[u8], b: &[u8], size: usize, p: usize) -> u8 {
    let (x, y) = ((p % size) as i64, (p / size) as i64);
    let mut best = u8::MAX;
    for dy in -1..=1 {
        for dx in -1..=1 {
            let (qx, qy) = (x + dx, y + dy);
            if qx < 0 || qy < 0 || qx >= size as i64 || qy >= size as i64 {
                continue;
            }
            let q = (qy as usize * size + qx as usize) * 4;
            best = best.min(apart(&a[p * 4..p * 4 + 3], &b[q..q + 3]));
        }
    }
    best
}

/// Levels (of 255, per channel) by which a picture saved lossily (JPEG of quality 90 and
/// more, then PNG) may differ from the picture it was made from, past a pixel's shift.
/// Measured (docs/guide.md): the spotlight scene's right picture saved at quality 90
/// matches 99.1 % of the object's pixels within it, at 95 99.9 % (within [`TOLERANCE`],
/// 88.8 % and 92.6 %); at quality 75, 96.0 %.
pub const LOSSY: u8 = 12;

/// How `picture` (with `covered`, the pixels its object covers) matches `image`, whose
/// object is told from the background `bg` by more than [`TOLERANCE`] levels. Both are
/// RGBA8, `size` x `size`.
pub fn compare(picture: &[u8], covered: &[bool], image: &[u8], bg: [u8; 3], size: usize) -> Match {
    compare_within(picture, covered, image, bg, size, TOLERANCE)
}

/// [`compare`] with pixels matching within `tolerance` levels rather than [`TOLERANCE`]
/// (the object is still told from the background by [`TOLERANCE`], and `miss` counts the
/// levels past `tolerance`).
pub fn compare_within(
    picture: &[u8],
    covered: &[bool],
    image: &[u8],
    bg: [u8; 3],
    size: usize,
    tolerance: u8,
) -> Match {
    let (mut pixels, mut matching, mut worst, mut worst_levels) = (0usize, 0usize, (0, 0), 0u8);
    let mut missed = 0u64;
    for p in 0..size * size {
        let in_image = apart(&image[p * 4..p * 4 + 3], &bg) > TOLERANCE;
        if !covered[p] && !in_image {
            continue;
        }
        pixels += 1;
        // Each pixel is its own neighbour: where the two agree in place, both best
        // neighbours do too, and the 3 x 3 need not be searched (most of an object's pixels).
        if apart(&image[p * 4..p * 4 + 3], &picture[p * 4..p * 4 + 3]) <= tolerance {
            matching += 1;
            continue;
        }
        let levels = nearest(image, picture, size, p).max(nearest(picture, image, size, p));
        missed += u64::from(levels.saturating_sub(tolerance));
        if levels <= tolerance {
            matching += 1;
        } else if levels > worst_levels {
            (worst, worst_levels) = ((p % size, p / size), levels);
        }
    }
    let (score, miss) =
        if pixels == 0 { (1.0, 0.0) } else { (matching as f64 / pixels as f64, missed as f64 / pixels as f64) };
    Match { score, pixels, worst, worst_levels, miss }
}

/// The share of the object's pixels (covered by `picture`, or unlike `bg` in `image` by more
/// than [`TOLERANCE`]) where each channel of `image` lies within `tolerance` levels of the
/// range that channel spans in the 3 x 3 around the pixel in `picture`: a blend of the
/// pixel's neighbours, as resampling, a blur, antialiasing or a half-pixel shift makes
/// (each pixel a weighted mean of its neighbours), and the ringing of a lossy saving
/// within `tolerance`. Both RGBA8, `size` x `size`; 1 when the object has no pixels.
pub fn blended_share(picture: &[u8], covered: &[bool], image: &[u8], bg: [u8; 3], size: usize, tolerance: u8) -> f64 {
    object_share(covered, image, bg, size, |p| {
        let (x, y) = (p % size, p / size);
        let around: Vec<usize> = (y.saturating_sub(1)..=(y + 1).min(size - 1))
            .flat_map(|qy| (x.saturating_sub(1)..=(x + 1).min(size - 1)).map(move |qx| qy * size + qx))
            .collect();
        (0..3).all(|c| {
            let (low, high) =
                around.iter().fold((u8::MAX, 0u8), |(l, h), &q| (l.min(picture[q * 4 + c]), h.max(picture[q * 4 + c])));
            (low.saturating_sub(tolerance)..=high.saturating_add(tolerance)).contains(&image[p * 4 + c])
        })
    })
}

/// The share of the object's pixels (covered by the picture, or unlike `bg` in `image` by
/// more than [`TOLERANCE`]) for which `holds` is true; 1 when the object has no pixels. The
/// loop [`blended_share`] and [`blended_share_subsampled`] count with.
fn object_share(covered: &[bool], image: &[u8], bg: [u8; 3], size: usize, holds: impl Fn(usize) -> bool) -> f64 {
    let (mut pixels, mut counted) = (0usize, 0usize);
    for p in 0..size * size {
        if !covered[p] && apart(&image[p * 4..p * 4 + 3], &bg) <= TOLERANCE {
            continue;
        }
        pixels += 1;
        counted += usize::from(holds(p));
    }
    if pixels == 0 { 1.0 } else { counted as f64 / pixels as f64 }
}

/// A picture in JFIF's Y, Cb, Cr (what JPEG stores), one triple a pixel of RGBA8 `rgba`.
pub fn luma_chroma(rgba: &[u8]) -> Vec<[f64; 3]> {
    rgba.chunks_exact(4).map(|px| ycc(px[0], px[1], px[2])).collect()
}

/// JFIF's Y, Cb, Cr of an RGB pixel.
fn ycc(r: u8, g: u8, b: u8) -> [f64; 3] {
    let (r, g, b) = (f64::from(r), f64::from(g), f64::from(b));
    [
        0.299 * r + 0.587 * g + 0.114 * b,
        128.0 - 0.168736 * r - 0.331264 * g + 0.5 * b,
        128.0 + 0.5 * r - 0.418688 * g - 0.081312 * b,
    ]
}

/// How far pixel `p` of `image` (RGBA8, `size` square) lies outside what a JPEG with its
/// colour subsampled (4:2:0: what libjpeg, browsers, PIL and ImageMagick below quality 90
/// write by default) can make of `picture` (in [`luma_chroma`]): JPEG keeps the brightness
/// (Y) of every pixel but the colour (Cb, Cr) once for each 2 x 2 block, which the reader
/// spreads back over a block's neighbours. So Y is measured against the range Y spans in
/// the 3 x 3 around the pixel in `picture`, Cb and Cr against the range they span in the
/// 5 x 5 (the block and the reader's spreading); the most of the three, in levels.
pub fn outside_subsampled(picture: &[[f64; 3]], image: &[u8], size: usize, p: usize) -> f64 {
    let (x, y) = (p % size, p / size);
    let here = ycc(image[p * 4], image[p * 4 + 1], image[p * 4 + 2]);
    let mut most = 0.0f64;
    for (c, &v) in here.iter().enumerate() {
        let reach = if c == 0 { 1 } else { 2 };
        let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
        for qy in y.saturating_sub(reach)..=(y + reach).min(size - 1) {
            for qx in x.saturating_sub(reach)..=(x + reach).min(size - 1) {
                let w = picture[qy * size + qx][c];
                (low, high) = (low.min(w), high.max(w));
            }
        }
        most = most.max(low - v).max(v - high);
    }
    most
}

/// `rgba` (RGBA8, `size` square) as a JPEG with its colour subsampled (4:2:0) gives it
/// back, losses of quantisation aside: each pixel keeps its brightness (JFIF's Y), and the
/// colour (Cb, Cr) of each 2 x 2 block, from the top left, is the block's mean.
pub fn subsampled_420(rgba: &[u8], size: usize) -> Vec<u8> {
    let ycc = luma_chroma(rgba);
    let mut out = rgba.to_vec();
    for by in (0..size).step_by(2) {
        for bx in (0..size).step_by(2) {
            let block: Vec<usize> =
                (by..(by + 2).min(size)).flat_map(|y| (bx..(bx + 2).min(size)).map(move |x| y * size + x)).collect();
            let mean = |c: usize| block.iter().map(|&p| ycc[p][c]).sum::<f64>() / block.len() as f64;
            let (cb, cr) = (mean(1) - 128.0, mean(2) - 128.0);
            for &p in &block {
                let y = ycc[p][0];
                let rgb = [y + 1.402 * cr, y - 0.344136 * cb - 0.714136 * cr, y + 1.772 * cb];
                for (c, v) in rgb.into_iter().enumerate() {
                    out[p * 4 + c] = v.round().clamp(0.0, 255.0) as u8;
                }
            }
        }
    }
    out
}

/// [`blended_share`] for a picture saved as JPEG with its colour subsampled: the share of
/// the object's pixels within `tolerance` levels of what the subsampling can make of
/// `picture` ([`outside_subsampled`]). A sharp coloured edge (the spotlight's rim) then
/// agrees though each of its RGB channels may not; a colour or an intensity off everywhere
/// is as far from the right picture as before (the systematic test that follows still
/// applies).
pub fn blended_share_subsampled(
    picture: &[u8],
    covered: &[bool],
    image: &[u8],
    bg: [u8; 3],
    size: usize,
    tolerance: u8,
) -> f64 {
    let of_picture = luma_chroma(picture);
    object_share(covered, image, bg, size, |p| outside_subsampled(&of_picture, image, size, p) <= f64::from(tolerance))
}

/// The most a difference image amplifies: past it, the 8-bit rounding's one level would
/// look like a difference.
pub const MAX_DIFFERENCE_GAIN: u32 = 64;

/// A difference image ([`difference_image`]): its pixels (RGBA8), the gain each channel's
/// difference is drawn at, and the largest difference (levels, the largest channel) before
/// the gain.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// Its pixels (RGBA8, opaque).
    pub rgba: Vec<u8>,
    /// The gain each channel's difference is drawn at.
    pub gain: u32,
    /// The largest difference of a channel anywhere, before the gain.
    pub largest: u8,
}

impl Difference {
    /// The level the largest difference is drawn at: `largest × gain`, at most 255. Only
    /// a difference of at least [`Difference::full_from`] is drawn white (255): a picture
    /// 2 levels off at most is drawn at 128, grey.
    pub fn largest_drawn(&self) -> u8 {
        (u32::from(self.largest) * self.gain).min(255) as u8
    }

    /// The least difference drawn at full strength (255): 255 / gain, rounded up.
    pub fn full_from(&self) -> u32 {
        255u32.div_ceil(self.gain)
    }
}

/// The difference image of `picture` and `image` (RGBA8, opaque): black where they agree;
/// elsewhere each channel's difference amplified by `255 / largest`, from 1 to
/// [`MAX_DIFFERENCE_GAIN`]: a picture at most 6 levels off is shown × 42 (its largest
/// difference at 252, near white), one 1 to 3 levels off × 64 (at 64 to 192, grey).
pub fn difference_image(picture: &[u8], image: &[u8]) -> Difference {
    let pixels = || picture.chunks_exact(4).zip(image.chunks_exact(4));
    let largest = pixels().map(|(a, b)| apart(a, b)).max().unwrap_or(0);
    // Equal pictures: nothing to amplify.
    let gain = 255u32.checked_div(u32::from(largest)).map_or(1, |g| g.clamp(1, MAX_DIFFERENCE_GAIN));
    let rgba = pixels()
        .flat_map(|(a, b)| {
            let d = |c: usize| (u32::from(a[c].abs_diff(b[c])) * gain).min(255) as u8;
            [d(0), d(1), d(2), 255]
        })
        .collect();
    Difference { rgba, gain, largest }
}

/// A box around pixels a diagnosis names: its top-left and bottom-right corners, included
/// (x from the left, y from the top).
pub type Boxed = ((usize, usize), (usize, usize));

/// The ink of the boxes [`draw_boxes`] draws: magenta, in dashes (a difference is grey or
/// one channel's colour, never dashed).
pub const BOX_INK: [u8; 3] = [255, 0, 255];

/// How far outside a box its outline is drawn, in pixels: the pixels boxed stay seen.
pub const BOX_GAP: usize = 2;

/// Draws each box of `boxes` on `rgba` (RGBA8, `size` square) as a dashed outline in
/// [`BOX_INK`], `BOX_GAP` pixels outside it (within the picture): 3 pixels drawn, 2 left.
pub fn draw_boxes(rgba: &mut [u8], size: usize, boxes: &[Boxed]) {
    let Some(last) = size.checked_sub(1) else { return };
    let dashed = |k: usize| k % 5 < 3;
    for &((x0, y0), (x1, y1)) in boxes {
        let (left, top) = (x0.saturating_sub(BOX_GAP), y0.saturating_sub(BOX_GAP));
        let (right, bottom) = ((x1 + BOX_GAP).min(last), (y1 + BOX_GAP).min(last));
        let mut ink = |x: usize, y: usize| {
            let i = (y * size + x) * 4;
            if let Some(p) = rgba.get_mut(i..i + 3) {
                p.copy_from_slice(&BOX_INK);
            }
        };
        for x in (left..=right).filter(|&x| dashed(x - left)) {
            ink(x, top);
            ink(x, bottom);
        }
        for y in (top..=bottom).filter(|&y| dashed(y - top)) {
            ink(left, y);
            ink(right, y);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::uniform;

    #[test]
    fn the_nearest_neighbour_inside_is_the_one_found_neighbour_by_neighbour() {
        // Pictures of few levels, so that many pixels have an equal neighbour somewhere
        // and the minimum is often 0 or small: every pixel of a 7 x 7 and a 1 x 1, against
        // the border's way, which checks each neighbour's place.
        for size in [1usize, 2, 3, 7] {
            let pixels = |seed: u64| -> Vec<u8> {
                let mut next = uniform(seed);
                (0..size * size * 4).map(|_| (next() * 6.0) as u8 * 40).collect()
            };
            for seed in 0..20 {
                let (a, b) = (pixels(2 * seed), pixels(2 * seed + 1));
                for p in 0..size * size {
                    assert_eq!(nearest(&a, &b, size, p), nearest_at_border(&a, &b, size, p), "{size} {seed} {p}");
                }
            }
        }
    }

    #[test]
    fn a_small_difference_is_amplified_to_show_and_a_large_one_is_not() {
        // Six levels at most: × 42, the largest near white, the agreeing pixel black.
        let a = [100, 100, 100, 255, 50, 50, 50, 255];
        let b = [106, 103, 100, 255, 50, 50, 50, 255];
        let d = difference_image(&a, &b);
        assert_eq!((d.gain, d.largest, d.largest_drawn(), d.full_from()), (42, 6, 252, 7));
        assert_eq!(d.rgba, vec![252, 126, 0, 255, 0, 0, 0, 255]);
        // A difference of 200 levels: as it is.
        let d = difference_image(&a, &[255, 100, 100, 255, 50, 50, 250, 255]);
        assert_eq!((d.gain, &d.rgba[..4]), (1, &[155, 0, 0, 255][..]));
        // One level (the 8-bit rounding) is not made white: drawn at 64, grey, and only a
        // difference of 4 levels would be white; the same pictures stay black.
        let d = difference_image(&a, &[101, 100, 100, 255, 50, 50, 50, 255]);
        assert_eq!((d.gain, d.largest_drawn(), d.full_from()), (MAX_DIFFERENCE_GAIN, 64, 4));
        let same = difference_image(&a, &a);
        assert_eq!((same.rgba, same.gain, same.largest), (vec![0, 0, 0, 255, 0, 0, 0, 255], 1, 0));
    }

    #[test]
    fn a_box_is_a_dashed_outline_outside_the_pixels_it_names_and_stays_in_the_picture() {
        let size = 12;
        let mut rgba = vec![0u8; size * size * 4];
        draw_boxes(&mut rgba, size, &[((4, 4), (6, 6)), ((0, 10), (11, 11))]);
        let inked = |x: usize, y: usize| rgba[(y * size + x) * 4..(y * size + x) * 4 + 3] == BOX_INK;
        // The first box's outline runs 2 pixels outside it, from (2, 2) to (8, 8), dashed.
        assert!(inked(2, 2) && inked(3, 2) && inked(4, 2) && !inked(5, 2) && !inked(6, 2) && inked(7, 2));
        assert!(inked(2, 4) && inked(8, 2) && !inked(8, 5));
        // The pixels boxed are left as they were.
        assert!((3..=7).all(|x| (3..=7).all(|y| !inked(x, y))), "inside the outline");
        // A box at the picture's edge is drawn along the edge, never past it.
        assert!(inked(0, 8) && inked(11, 8) && inked(0, 11));
        assert_eq!(rgba.len(), size * size * 4);
    }

    #[test]
    fn the_mean_miss_forgives_a_pixel_s_shift_and_counts_the_rest() {
        // A bright pixel at the centre of grey, and the same moved a pixel: nothing missed.
        let grey = |bright: usize| -> Vec<u8> {
            (0..9).flat_map(|p| if p == bright { [200, 200, 200, 255] } else { [100, 100, 100, 255] }).collect()
        };
        let covered = [true; 9];
        assert_eq!(compare(&grey(4), &covered, &grey(8), [0, 0, 0], 3).miss, 0.0);
        // Six levels more on the left column (three pixels of nine): three past the
        // tolerance, a mean of 1; two levels more is noise within it.
        let flat = grey(usize::MAX);
        let mut brighter = flat.clone();
        for p in [0, 3, 6] {
            brighter[p * 4 + 1] += 6;
        }
        assert_eq!(compare(&flat, &covered, &brighter, [0, 0, 0], 3).miss, 1.0);
        for p in [0, 3, 6] {
            brighter[p * 4 + 1] -= 4;
        }
        assert_eq!(compare(&flat, &covered, &brighter, [0, 0, 0], 3).miss, 0.0);
    }

    fn square(size: usize, at: (usize, usize), colour: [u8; 3], bg: [u8; 3]) -> (Vec<u8>, Vec<bool>) {
        let mut rgba = Vec::new();
        let mut covered = Vec::new();
        for y in 0..size {
            for x in 0..size {
                let inside = (at.0..at.0 + 4).contains(&x) && (at.1..at.1 + 4).contains(&y);
                let c = if inside { colour } else { bg };
                rgba.extend_from_slice(&[c[0], c[1], c[2], 255]);
                covered.push(inside);
            }
        }
        (rgba, covered)
    }

    #[test]
    fn a_shift_of_one_pixel_and_two_levels_match_and_another_colour_does_not() {
        let bg = [10, 10, 20];
        let (picture, covered) = square(12, (4, 4), [200, 50, 40], bg);
        let (shifted, _) = square(12, (5, 4), [202, 48, 40], bg);
        assert_eq!(compare(&picture, &covered, &shifted, bg, 12).score, 1.0);
        let (other, _) = square(12, (4, 4), [200, 60, 40], bg);
        let m = compare(&picture, &covered, &other, bg, 12);
        assert_eq!(m.score, 0.0);
        assert_eq!((m.pixels, m.worst_levels), (16, 10));
        let (far, _) = square(12, (7, 4), [200, 50, 40], bg);
        // Moved three pixels: only the columns that overlap within one pixel match.
        let m = compare(&picture, &covered, &far, bg, 12);
        assert!(m.score < 0.7, "{m:?}");
    }
}
