//! Where a mistake's picture differs from the right one in only a few pixels (the right
//! picture explains it, [`super::RIGHT_AT`]), whether the student's picture is the
//! mistake's there. A spot exponent of 10 typed for 8 changes the spotlight's lit teapot by
//! up to 9 levels, all of one sign, but past a pixel's shift and 3 levels only in 422
//! pixels, on the handle's rim and the spout's: the right picture still explains 99.4 % of
//! the object's pixels, as it explains a noisy copy of itself, and the share alone cannot
//! tell the two apart. Over the mistake's footprint it can: there a noisy copy stays near
//! the right picture, the mistaken one is the mistake's.

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
#[derive(Clone, Debug, PartialEq)]
pub struct Footprint {
    /// The pixels where the two pictures differ past [`TOLERANCE`], a pixel's shift allowed.
    pub pixels: usize,
    /// The centre of the largest of [`Footprint::groups`] (x from the left, y from the
    /// top): never a mean of separate groups, which may fall where nothing differs.
    pub centre: (usize, usize),
    /// The most levels (largest channel) by which the two pictures differ anywhere on the
    /// object, no shift allowed: what the difference image shows at its brightest.
    pub most: u8,
    /// The footprint's connected groups (8 neighbours), the largest first.
    pub groups: Vec<Group>,
    /// The mean levels (largest channel, past the best neighbour, either way) by which the
    /// student's picture misses the right one over them.
    pub right: f64,
    /// The same for the mistake's picture.
    pub mistake: f64,
}

/// One connected group of a footprint's pixels: how many, and the box around them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Group {
    /// Its pixels.
    pub pixels: usize,
    /// The box's top-left corner (x from the left, y from the top).
    pub from: (usize, usize),
    /// The box's bottom-right corner, included.
    pub to: (usize, usize),
}

impl Group {
    /// The box's centre.
    pub fn centre(&self) -> (usize, usize) {
        (self.from.0.midpoint(self.to.0), self.from.1.midpoint(self.to.1))
    }
}

/// The side, as a share of the picture's, of the squares by which a footprint's pixels
/// are grouped: pixels in the same or neighbouring squares (8 neighbours) are one group.
/// Measured (docs/guide.md): the spot exponent 10 for 8 on the spotlight moves 422 pixels
/// in 25 pieces touching pixel to pixel, along the handle's rim and the spout's; squares
/// of an eighth join them into the handle's 282 and the spout's 140, the body between.
pub const GROUPED_BY: usize = 8;

/// The groups of the pixels `on` (`size` square), the largest first, then the topmost,
/// then the leftmost: pixels in the same or neighbouring squares of `side` pixels are one
/// group (`side` 1: pixels touching, 8 neighbours).
pub fn groups(on: &[bool], size: usize, side: usize) -> Vec<Group> {
    let side = side.max(1);
    let cells = size.div_ceil(side);
    let mut coarse = vec![false; cells * cells];
    for p in (0..on.len()).filter(|&p| on[p]) {
        coarse[(p / size / side) * cells + (p % size) / side] = true;
    }
    let label = labels(&coarse, cells);
    let mut found: Vec<Option<Group>> = vec![None; coarse.len()];
    for p in (0..on.len()).filter(|&p| on[p]) {
        let (x, y) = (p % size, p / size);
        let g =
            found[label[(y / side) * cells + x / side]].get_or_insert(Group { pixels: 0, from: (x, y), to: (x, y) });
        g.pixels += 1;
        g.from = (g.from.0.min(x), g.from.1.min(y));
        g.to = (g.to.0.max(x), g.to.1.max(y));
    }
    let mut found: Vec<Group> = found.into_iter().flatten().collect();
    found.sort_by(|a, b| b.pixels.cmp(&a.pixels).then(a.from.1.cmp(&b.from.1)).then(a.from.0.cmp(&b.from.0)));
    found
}

/// For each of the cells `on` (`cells` square), the first cell of its connected group
/// (8 neighbours); the cells off are their own.
fn labels(on: &[bool], cells: usize) -> Vec<usize> {
    let mut label: Vec<usize> = (0..on.len()).collect();
    let mut seen = vec![false; on.len()];
    for start in (0..on.len()).filter(|&p| on[p]) {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut stack = vec![start];
        while let Some(p) = stack.pop() {
            label[p] = start;
            let (x, y) = (p % cells, p / cells);
            for ny in y.saturating_sub(1)..=(y + 1).min(cells - 1) {
                for nx in x.saturating_sub(1)..=(x + 1).min(cells - 1) {
                    let q = ny * cells + nx;
                    if on[q] && !seen[q] {
                        seen[q] = true;
                        stack.push(q);
                    }
                }
            }
        }
    }
    label
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
    let (mut pixels, mut most, mut right, mut mistake) = (0usize, 0u8, 0u64, 0u64);
    let mut on = vec![false; size * size];
    for p in 0..size * size {
        if !(covered[p] || wrong_covered[p]) {
            continue;
        }
        let here = apart(&picture[p * 4..p * 4 + 3], &wrong[p * 4..p * 4 + 3]);
        most = most.max(here);
        // Where the two agree in place, both best neighbours do too.
        if here <= TOLERANCE || levels(picture, wrong, size, p) <= TOLERANCE {
            continue;
        }
        on[p] = true;
        pixels += 1;
        right += u64::from(levels(image, picture, size, p));
        mistake += u64::from(levels(image, wrong, size, p));
    }
    let groups = groups(&on, size, size / GROUPED_BY);
    let centre = groups.first()?.centre();
    Some(Footprint {
        pixels,
        centre,
        most,
        groups,
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
        assert_eq!((f.pixels, f.centre, f.most, f.right, f.mistake), (144, (13, 13), 6, 6.0, 0.0));
        assert_eq!(f.groups, vec![Group { pixels: 144, from: (8, 8), to: (19, 19) }]);
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
        // Two separate groups: each told, the larger first, its centre the footprint's
        // (the mean of the two, (13, 19), lies where nothing differs).
        let mut two = lifted(size, 2, 6, 6);
        let far = lifted(size, 22, 8, 6);
        for p in 0..size * size {
            if far[p * 4] != 100 {
                two[p * 4..p * 4 + 3].copy_from_slice(&far[p * 4..p * 4 + 3]);
            }
        }
        let f = footprint((&right, &covered), (&two, &covered), &two, size).expect("a footprint");
        assert_eq!(f.pixels, 36 + 64);
        assert_eq!(
            f.groups,
            vec![Group { pixels: 64, from: (22, 22), to: (29, 29) }, Group { pixels: 36, from: (2, 2), to: (7, 7) }]
        );
        assert_eq!(f.centre, (25, 25));
        // Pieces a few pixels apart: two touching groups, one by squares of 4.
        let mut on = vec![false; size * size];
        (on[0], on[1], on[4]) = (true, true, true);
        assert_eq!(groups(&on, size, 1).iter().map(|g| g.pixels).collect::<Vec<_>>(), [2, 1]);
        assert_eq!(groups(&on, size, 4), vec![Group { pixels: 3, from: (0, 0), to: (4, 0) }]);
        // Pictures that agree have none.
        assert_eq!(footprint((&right, &covered), (&right, &covered), &wrong, size), None);
    }
}
