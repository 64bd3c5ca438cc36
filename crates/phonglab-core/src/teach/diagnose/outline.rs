//! What the shape of a student's picture says before any colour is compared: nothing of the
//! object drawn (only the background), an outline that is not the scene's (another object,
//! camera or scene), a solid region of the object that differs from the right picture, or
//! thin marks (lines drawn over it) that do (defects no pixel's shift, 8-bit noise or lossy
//! saving makes).

use crate::teach::picture_match::TOLERANCE;

/// Levels (largest channel) by which a pixel must differ from the background to count in
/// an outline: well past the noise and the ringing of a lossy saving around the edges.
const OUTLINE_LEVELS: u8 = 12;

/// The share of the outlines' union that may differ (beyond a pixel's shift) for the
/// image to be of the scene. Measured (docs/guide.md): the right picture of the spotlight
/// scene shifted a pixel, noised or saved as JPEG of quality 75 and more differs by at most
/// 0.5 %, in grey 5.3 %; the 40 pictures of a blind set of Mesa's (right and mistaken) by 0;
/// a sphere for the spotlight's teapot by 30 %, a cylinder by 77 %.
pub const OUTLINE_AT: f64 = 0.15;

/// Levels (largest channel, outside the range of the 3 x 3 around it) by which a pixel must differ for a
/// region: more than a JPEG of quality 90 moves a pixel of a right picture (at most 11).
const REGION_LEVELS: u8 = 16;

/// The least solid region (pixels differing by 16 levels with their 8 neighbours)
/// taken as a defect: a square of 6 x 6 pixels painted on the object. Measured
/// (docs/guide.md): on right pictures shifted a pixel, noised, resized, saved as JPEG of
/// quality 90 or 95, and Mesa's (8 of a blind set), there is none; JPEG of quality 75 makes
/// one of 22 (and is not taken as right); a 10 x 10 square painted on the object has 64.
pub const REGION_AT: usize = 16;

/// The least set of joined pixels that differ by more than 16 levels past their best
/// neighbour (thin or not) taken as marks drawn over the object: a line of one pixel
/// across a sixth of the spotlight's teapot. Measured (docs/guide.md): on the 72 right
/// pictures of the blind sets (Mesa's) there are none; saved as JPEG of quality 90, with or
/// without a pixel's shift, at most 21 joined; with noise of ±3 none; white lines of a
/// pixel drawn across the teapot join 499.
pub const MARKS_AT: usize = 48;

/// A solid region of the object that differs from the right picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    /// Its pixels: those differing with all 8 neighbours.
    pub pixels: usize,
    /// Its centre (x from the left, y from the top).
    pub centre: (usize, usize),
    /// The corner of the box around it nearest the top left.
    pub from: (usize, usize),
    /// The corner of the box around it nearest the bottom right.
    pub to: (usize, usize),
}

/// Thin marks that differ from the right picture: joined pixels, each more than 16 levels
/// outside the range of the 3 x 3 around it in the right picture, that need not make a solid region (lines drawn over the object).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Marks {
    /// Its pixels.
    pub pixels: usize,
    /// The corner of the box around them nearest the top left (x from the left, y from the top).
    pub from: (usize, usize),
    /// The corner of the box around them nearest the bottom right.
    pub to: (usize, usize),
}

/// Joined pixels of a set: how many, their centre and the box around them.
struct Joined {
    region: Region,
}

/// Is pixel `p` of `rgba` more than `levels` from `bg` in a channel?
fn unlike(rgba: &[u8], p: usize, bg: [u8; 3], levels: u8) -> bool {
    (0..3).any(|c| rgba[p * 4 + c].abs_diff(bg[c]) > levels)
}

/// The outline of `rgba` (`size` square): the pixels unlike the background `bg`, within
/// `covered` when given.
pub fn mask(rgba: &[u8], covered: Option<&[bool]>, bg: [u8; 3], size: usize) -> Vec<bool> {
    (0..size * size).map(|p| covered.is_none_or(|c| c[p]) && unlike(rgba, p, bg, OUTLINE_LEVELS)).collect()
}

/// Is a pixel of `mask` set in the 3 x 3 around pixel `p`?
fn near(mask: &[bool], size: usize, p: usize) -> bool {
    let (x, y) = (p % size, p / size);
    (y.saturating_sub(1)..=(y + 1).min(size - 1))
        .any(|qy| (x.saturating_sub(1)..=(x + 1).min(size - 1)).any(|qx| mask[qy * size + qx]))
}

/// The share of the union of outlines `a` and `b` (`size` square) set in one with nothing of
/// the other within a pixel; 0 when both are empty.
pub fn apart(a: &[bool], b: &[bool], size: usize) -> f64 {
    let (mut union, mut alone) = (0usize, 0usize);
    for p in 0..size * size {
        if !a[p] && !b[p] {
            continue;
        }
        union += 1;
        if (a[p] && !near(b, size, p)) || (b[p] && !near(a, size, p)) {
            alone += 1;
        }
    }
    if union == 0 { 0.0 } else { alone as f64 / union as f64 }
}

/// How far pixel `p` of `a` lies outside the range each channel spans in the 3 x 3 around
/// it in `b` (the largest channel, levels): 0 where it is a blend of those neighbours, as
/// a picture resized, blurred, antialiased or moved half a pixel is of the picture it was
/// made from; a mark drawn over a flat part lies outside by its own levels.
fn outside(a: &[u8], b: &[u8], size: usize, p: usize) -> u8 {
    let (x, y) = (p % size, p / size);
    let mut most = 0;
    for c in 0..3 {
        let (mut low, mut high) = (u8::MAX, 0u8);
        for qy in y.saturating_sub(1)..=(y + 1).min(size - 1) {
            for qx in x.saturating_sub(1)..=(x + 1).min(size - 1) {
                let v = b[(qy * size + qx) * 4 + c];
                (low, high) = (low.min(v), high.max(v));
            }
        }
        let v = a[p * 4 + c];
        most = most.max(low.saturating_sub(v)).max(v.saturating_sub(high));
    }
    most
}

/// The largest solid region where `image` differs from `picture` (both RGBA8, `size`
/// square) over the object (`covered` in the picture, or unlike `bg` in the image): the
/// pixels that differ by more than [`REGION_LEVELS`] outside the range of the 3 x 3 around them (either way, [`outside`]),
/// kept where all 8 neighbours differ too (so that an edge a pixel out, or a thin line, is
/// no region), joined 8-connected. `None` when no pixel is solid.
///
/// `subsampled`: as for [`largest_marks`], a pixel differs only where it lies outside what a
/// JPEG's subsampled colour can make of `picture` too.
pub fn largest_region(
    picture: &[u8],
    covered: &[bool],
    image: &[u8],
    bg: [u8; 3],
    size: usize,
    subsampled: bool,
) -> Option<Region> {
    let mut differs = differing(picture, covered, image, bg, size);
    if subsampled {
        beyond_subsampling(&mut differs, picture, image, size);
    }
    let solid: Vec<bool> = (0..size * size)
        .map(|p| {
            let (x, y) = (p % size, p / size);
            x > 0
                && y > 0
                && x + 1 < size
                && y + 1 < size
                && (0..9).all(|i| differs[(y + i / 3 - 1) * size + x + i % 3 - 1])
        })
        .collect();
    regions(&solid, size).into_iter().map(|j| j.region).max_by_key(|r| r.pixels)
}

/// The pixels of the object (`covered` in `picture`, or unlike `bg` in `image`) where
/// `image` lies more than [`REGION_LEVELS`] outside the range of the 3 x 3 around the pixel
/// in `picture`, or `picture` outside that of `image` ([`outside`]).
fn differing(picture: &[u8], covered: &[bool], image: &[u8], bg: [u8; 3], size: usize) -> Vec<bool> {
    let object = |p: usize| covered[p] || unlike(image, p, bg, TOLERANCE);
    (0..size * size)
        .map(|p| object(p) && outside(image, picture, size, p).max(outside(picture, image, size, p)) > REGION_LEVELS)
        .collect()
}

/// The pixels of the object (`covered` in `picture`, or unlike `bg` in `image`) where
/// `image` lies more than [`REGION_LEVELS`] outside the range of the 3 x 3 around the pixel
/// in `picture` ([`outside`]): what is drawn over the picture. Not the other way round: a
/// picture resized down and up or blurred loses its thin extremes (a rim's highlight a
/// pixel or two wide falls below everything near it in the image), and adds nothing
/// outside its neighbours' range but the ringing of its filter.
fn added(picture: &[u8], covered: &[bool], image: &[u8], bg: [u8; 3], size: usize) -> Vec<bool> {
    let object = |p: usize| covered[p] || unlike(image, p, bg, TOLERANCE);
    (0..size * size).map(|p| object(p) && outside(image, picture, size, p) > REGION_LEVELS).collect()
}

/// The largest set of joined pixels (8-connected) where `image` lies outside `picture`'s
/// range as [`added`] counts them, solid or not: lines or marks drawn over the object.
/// `None` when no pixel does.
///
/// `subsampled`: the image may be a JPEG whose colour is subsampled (it was found right as
/// saved lossily): a pixel is then added only where it lies outside
/// what the subsampling can make of `picture` too
/// ([`crate::teach::picture_match::outside_subsampled`]): the colour of a sharp coloured
/// edge (the spotlight's rim) smeared over 2 x 2 blocks is not a mark, while lines drawn over
/// the object change the brightness as well.
pub fn largest_marks(
    picture: &[u8],
    covered: &[bool],
    image: &[u8],
    bg: [u8; 3],
    size: usize,
    subsampled: bool,
) -> Option<Marks> {
    let mut differs = added(picture, covered, image, bg, size);
    if subsampled {
        beyond_subsampling(&mut differs, picture, image, size);
    }
    let largest = regions(&differs, size).into_iter().max_by_key(|j| j.region.pixels)?;
    let r = largest.region;
    Some(Marks { pixels: r.pixels, from: r.from, to: r.to })
}

/// Keeps in `differs` only the pixels of `image` that lie more than [`REGION_LEVELS`] outside
/// what a JPEG with its colour subsampled can make of `picture`
/// ([`crate::teach::picture_match::outside_subsampled`]).
fn beyond_subsampling(differs: &mut [bool], picture: &[u8], image: &[u8], size: usize) {
    let of_picture = crate::teach::picture_match::luma_chroma(picture);
    for (p, d) in differs.iter_mut().enumerate() {
        *d = *d
            && crate::teach::picture_match::outside_subsampled(&of_picture, image, size, p) > f64::from(REGION_LEVELS);
    }
}

/// The 8-connected regions of `set` (`size` square).
fn regions(set: &[bool], size: usize) -> Vec<Joined> {
    let mut seen = vec![false; set.len()];
    let mut out = Vec::new();
    for start in 0..set.len() {
        if !set[start] || seen[start] {
            continue;
        }
        seen[start] = true;
        let (mut stack, mut pixels, mut sum) = (vec![start], 0usize, (0usize, 0usize));
        let (mut from, mut to) = ((size, size), (0, 0));
        while let Some(p) = stack.pop() {
            let (x, y) = (p % size, p / size);
            pixels += 1;
            sum = (sum.0 + x, sum.1 + y);
            (from, to) = ((from.0.min(x), from.1.min(y)), (to.0.max(x), to.1.max(y)));
            for qy in y.saturating_sub(1)..=(y + 1).min(size - 1) {
                for qx in x.saturating_sub(1)..=(x + 1).min(size - 1) {
                    let q = qy * size + qx;
                    if set[q] && !seen[q] {
                        seen[q] = true;
                        stack.push(q);
                    }
                }
            }
        }
        out.push(Joined { region: Region { pixels, centre: (sum.0 / pixels, sum.1 / pixels), from, to } });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(size: usize) -> Vec<u8> {
        (0..size * size).flat_map(|_| [100, 100, 100, 255]).collect()
    }

    #[test]
    fn a_painted_square_is_a_region_and_a_line_or_speckles_are_not() {
        let size = 40;
        let picture = grey(size);
        let covered = vec![true; size * size];
        let mut image = picture.clone();
        // A line two pixels wide and scattered pixels: no pixel differs with all neighbours.
        for x in 0..size {
            for y in [5, 6] {
                image[(y * size + x) * 4] = 255;
            }
        }
        for p in (0..size * size).step_by(7) {
            image[p * 4 + 1] = 0;
        }
        assert_eq!(largest_region(&picture, &covered, &image, [0, 0, 0], size, false), None);
        // A 10 x 10 square at (20, 20): 8 x 8 solid (its rim has neighbours outside).
        for y in 20..30 {
            for x in 20..30 {
                image[(y * size + x) * 4..(y * size + x) * 4 + 3].copy_from_slice(&[255, 0, 0]);
            }
        }
        let r = largest_region(&picture, &covered, &image, [0, 0, 0], size, false).expect("a region");
        assert_eq!(r, Region { pixels: 64, centre: (24, 24), from: (21, 21), to: (28, 28) });
    }

    #[test]
    fn a_line_of_one_pixel_is_marks_and_speckles_or_a_shift_are_not() {
        let size = 40;
        let (picture, covered) = (grey(size), vec![true; size * size]);
        let mut image = picture.clone();
        // Scattered pixels are no marks of more than one pixel each.
        for p in (0..size * size).step_by(7) {
            image[p * 4 + 1] = 0;
        }
        assert!(largest_marks(&picture, &covered, &image, [0, 0, 0], size, false).is_none_or(|m| m.pixels == 1));
        // Nor is the picture moved a pixel.
        let moved: Vec<u8> = (0..size * size).flat_map(|p| if p % size < 20 { [100; 4] } else { [180; 4] }).collect();
        let at = |dx: usize| -> Vec<u8> {
            (0..size * size)
                .flat_map(|p| moved[(p / size * size + (p % size).saturating_sub(dx)) * 4..][..4].to_vec())
                .collect()
        };
        assert_eq!(largest_marks(&at(0), &covered, &at(1), [0, 0, 0], size, false), None);
        let mut image = picture.clone();
        // A line of one pixel from (3, 10) to (32, 10), and a diagonal joined to it.
        for x in 3..33 {
            image[(10 * size + x) * 4..(10 * size + x) * 4 + 3].copy_from_slice(&[255, 255, 255]);
        }
        for i in 1..8 {
            image[((10 + i) * size + 20 + i) * 4 + 2] = 255;
        }
        let m = largest_marks(&picture, &covered, &image, [0, 0, 0], size, false).expect("marks");
        assert_eq!(m, Marks { pixels: 37, from: (3, 10), to: (32, 17) });
        // It is no solid region.
        assert_eq!(largest_region(&picture, &covered, &image, [0, 0, 0], size, false), None);
    }

    #[test]
    fn outlines_a_pixel_apart_agree_and_other_shapes_do_not() {
        let size = 20;
        let disc = |cx: f64, r: f64| -> Vec<bool> {
            (0..size * size).map(|p| ((p % size) as f64 - cx).hypot((p / size) as f64 - 10.0) < r).collect()
        };
        assert_eq!(apart(&disc(10.0, 6.0), &disc(11.0, 6.0), size), 0.0);
        assert!(apart(&disc(10.0, 6.0), &disc(10.0, 3.0), size) > 0.5);
        assert_eq!(apart(&vec![false; size * size], &vec![false; size * size], size), 0.0);
    }
}
