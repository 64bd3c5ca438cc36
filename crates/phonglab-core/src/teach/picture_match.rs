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
fn apart(a: &[u8], b: &[u8]) -> u8 {
    (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0)
}

/// The smallest difference between pixel `p` of `a` and the 3 x 3 around it in `b`.
fn nearest(a: &[u8], b: &[u8], size: usize, p: usize) -> u8 {
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

/// The difference image of `picture` and `image` (RGBA8, opaque): black where they agree,
/// each channel's difference four times brighter elsewhere.
pub fn difference_image(picture: &[u8], image: &[u8]) -> Vec<u8> {
    picture
        .chunks_exact(4)
        .zip(image.chunks_exact(4))
        .flat_map(|(a, b)| {
            let d = |c: usize| (a[c].abs_diff(b[c]) as u32 * 4).min(255) as u8;
            [d(0), d(1), d(2), 255]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

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
