//! Where a mistake's picture differs from the right one in only a few pixels (the right
//! picture explains it, [`super::RIGHT_AT`]), whether the student's picture is the
//! mistake's there. A spot exponent of 10 typed for 8 moves some 2 300 pixels of the
//! spotlight's pool of light by 4 to 9 levels, one smooth ring of one sign: the right
//! picture still explains 99.4 % of the object's pixels, as it explains a noisy copy of
//! itself, and the share alone cannot tell the two apart. Over the mistake's footprint it
//! can: there a noisy copy stays near the right picture, the mistaken one is the mistake's.

use crate::teach::picture_match::{TOLERANCE, apart, nearest};

/// The least footprint, in pixels, on which a picture is judged: fewer is within what a
/// pixel's shift and the rounding leave. Measured (docs/guide.md): the spot exponent
/// typed 10 or 6 for 8 on the spotlight scene at 512 pixels has a footprint of some 420.
pub const FOOTPRINT_AT: usize = 64;

/// How much closer the student's picture must be to the mistake's than to the right one
/// over the footprint (the mean levels it misses each by): half. Measured (docs/guide.md):
/// right pictures with noise of ±3 or saved as JPEG of quality 90 come no closer than
/// the right one to any mistake's; a mistake's own picture misses it by 0.
pub const CLEARLY: f64 = 0.5;

/// Where a mistake's picture differs from the right one, and how far the student's
/// picture is from each there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Footprint {
    /// The pixels where the two pictures differ past [`TOLERANCE`], a pixel's shift allowed.
    pub pixels: usize,
    /// Their centre (x from the left, y from the top).
    pub centre: (usize, usize),
    /// The mean levels (largest channel, past the best neighbour, either way) by which the
    /// student's picture misses the right one over them.
    pub right: f64,
    /// The same for the mistake's picture.
    pub mistake: f64,
}

impl Footprint {
    /// Does the student's picture show the mistake: a footprint of at least
    /// [`FOOTPRINT_AT`] pixels, over which it is [`CLEARLY`] closer to the mistake's
    /// picture than to the right one?
    pub fn shows_mistake(&self) -> bool {
        self.pixels >= FOOTPRINT_AT && self.mistake <= CLEARLY * self.right
    }
}

/// The levels by which `a` and `b` (RGBA8, `size` square) differ at pixel `p`, a pixel's
/// shift allowed either way.
fn levels(a: &[u8], b: &[u8], size: usize, p: usize) -> u8 {
    if apart(&a[p * 4..p * 4 + 3], &b[p * 4..p * 4 + 3]) == 0 {
        return 0;
    }
    nearest(a, b, size, p).max(nearest(b, a, size, p))
}

/// The footprint of the mistake's picture `wrong` (covering `wrong_covered`) on the right
/// one `picture` (covering `covered`), and how far `image` is from each over it; `None`
/// when the two pictures differ nowhere. All RGBA8, `size` square.
pub fn footprint(
    (picture, covered): (&[u8], &[bool]),
    (wrong, wrong_covered): (&[u8], &[bool]),
    image: &[u8],
    size: usize,
) -> Option<Footprint> {
    let (mut pixels, mut sum, mut right, mut mistake) = (0usize, (0usize, 0usize), 0u64, 0u64);
    for p in 0..size * size {
        // Where the two agree in place, both best neighbours do too.
        if !(covered[p] || wrong_covered[p]) || apart(&picture[p * 4..p * 4 + 3], &wrong[p * 4..p * 4 + 3]) <= TOLERANCE
        {
            continue;
        }
        if levels(picture, wrong, size, p) <= TOLERANCE {
            continue;
        }
        pixels += 1;
        sum = (sum.0 + p % size, sum.1 + p / size);
        right += u64::from(levels(image, picture, size, p));
        mistake += u64::from(levels(image, wrong, size, p));
    }
    (pixels > 0).then(|| Footprint {
        pixels,
        centre: (sum.0 / pixels, sum.1 / pixels),
        right: right as f64 / pixels as f64,
        mistake: mistake as f64 / pixels as f64,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grey picture `size` square, with `lift` levels added over the square from
    /// (`at`, `at`) of `side` pixels.
    fn lifted(size: usize, at: usize, side: usize, lift: u8) -> Vec<u8> {
        (0..size * size)
            .flat_map(|p| {
                let inside = (at..at + side).contains(&(p % size)) && (at..at + side).contains(&(p / size));
                let v = if inside { 100 + lift } else { 100 };
                [v, v, v, 255]
            })
            .collect()
    }

    #[test]
    fn a_picture_near_the_mistakes_over_its_footprint_shows_it_and_noise_does_not() {
        let size = 32;
        let covered = vec![true; size * size];
        let (right, wrong) = (lifted(size, 8, 12, 0), lifted(size, 8, 12, 6));
        // The mistake's own picture: the square's 12 x 12 pixels (a lifted pixel finds no
        // neighbour as high in the right picture).
        let f = footprint((&right, &covered), (&wrong, &covered), &wrong, size).expect("a footprint");
        assert_eq!((f.pixels, f.centre, f.right, f.mistake), (144, (13, 13), 6.0, 0.0));
        assert!(f.shows_mistake());
        // The right picture with noise of ±2: nearer the right one.
        let noisy: Vec<u8> = right
            .iter()
            .enumerate()
            .map(|(i, &v)| if i % 4 == 3 { v } else { (i16::from(v) + (i % 5) as i16 - 2) as u8 })
            .collect();
        let f = footprint((&right, &covered), (&wrong, &covered), &noisy, size).expect("a footprint");
        assert!(!f.shows_mistake(), "{f:?}");
        // The mistake's picture over fewer than FOOTPRINT_AT pixels is not judged.
        let small = lifted(size, 8, 6, 6);
        let f = footprint((&right, &covered), (&small, &covered), &small, size).expect("a footprint");
        assert_eq!(f.pixels, 36);
        assert!(!f.shows_mistake());
        // Pictures that agree have none.
        assert_eq!(footprint((&right, &covered), (&right, &covered), &wrong, size), None);
    }
}
