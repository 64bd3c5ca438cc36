//! The emission a student's picture shows beyond the right picture: for `emission-added`,
//! whose colour is not in the scene but fitted from the picture, then drawn and scored as
//! every other mistake is.

/// The levels taken as unclamped: a level within a little noise of 255 may be one clamped
/// there (a clamped 255 with noise of 2 reads 253). Light is never negative: 0 is a value.
const UNCLAMPED: std::ops::RangeInclusive<u8> = 0..=250;

/// The least lift, in levels, taken as an emission: a smaller one is within the picture
/// match's tolerance of the right picture (and the noise's median).
const LEAST: i16 = crate::teach::picture_match::TOLERANCE as i16 + 1;

/// Levels by which the right picture may vary around a pixel for the pixel to count as
/// flat: there a picture moved by a pixel differs from it by the emission alone.
const FLAT: u8 = 2;

/// Is channel `c` of `picture` (`size` pixels square) flat around pixel `p`: the 3 x 3
/// around it covered, within [`FLAT`] levels of each other?
fn flat(picture: &[u8], covered: &[bool], size: usize, p: usize, c: usize) -> bool {
    let (x, y) = (p % size, p / size);
    if x == 0 || y == 0 || x + 1 >= size || y + 1 >= size {
        return false;
    }
    let around = (y - 1..=y + 1).flat_map(|qy| (x - 1..=x + 1).map(move |qx| qy * size + qx));
    let (mut low, mut high) = (u8::MAX, 0);
    for q in around {
        if !covered[q] {
            return false;
        }
        (low, high) = (low.min(picture[q * 4 + c]), high.max(picture[q * 4 + c]));
    }
    high - low <= FLAT
}

/// Levels of the right picture below which a pixel is dark: there a tone curve (a gamma,
/// a colour profile) moves a level by a fraction of what it moves the middle levels by,
/// while an emission adds the same everywhere.
const DARK: u8 = 24;

/// The least share of the pixels measured that must be dark for the dark ones to decide
/// whether a lift is the same everywhere.
const DARK_SHARE: usize = 50;

/// The median of `differences` (0 when empty).
fn median(mut differences: Vec<i16>) -> i16 {
    if differences.is_empty() {
        return 0;
    }
    let middle = differences.len() / 2;
    *differences.select_nth_unstable(middle).1
}

/// The median, per channel, of the student's level less the right picture's (levels), over
/// the pixels the object covers where neither is clamped ([`UNCLAMPED`]) in that channel and
/// the right picture is flat around (so that a picture moved by a pixel does not bias it;
/// all such pixels where none is flat); with the same median over the dark ones ([`DARK`])
/// among them, `None` where fewer than one in [`DARK_SHARE`] is dark.
pub fn lifts(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> [(i16, Option<i16>); 3] {
    let mut out = [(0, None); 3];
    for (c, value) in out.iter_mut().enumerate() {
        let unclamped =
            |&p: &usize| covered[p] && UNCLAMPED.contains(&picture[p * 4 + c]) && UNCLAMPED.contains(&image[p * 4 + c]);
        let inside: Vec<usize> = (0..covered.len()).filter(unclamped).collect();
        let flats: Vec<usize> = inside.iter().copied().filter(|&p| flat(picture, covered, size, p, c)).collect();
        let pixels = if flats.is_empty() { inside } else { flats };
        let lift = |p: &usize| i16::from(image[p * 4 + c]) - i16::from(picture[p * 4 + c]);
        let dark: Vec<i16> = pixels.iter().filter(|&&p| picture[p * 4 + c] < DARK).map(lift).collect();
        let enough = dark.len() * DARK_SHARE >= pixels.len() && !dark.is_empty();
        *value = (median(pixels.iter().map(lift).collect()), enough.then(|| median(dark)));
    }
    out
}

/// The emission the picture shows, per channel, in linear units (0 to 1): the median lift
/// ([`lifts`]); 0 for a channel whose median is under [`LEAST`] levels, and for every
/// channel when the dark pixels of a channel are lifted by less than half its median: a
/// tone curve (a gamma, a colour profile), not a colour added alike everywhere.
/// `picture`, `covered` and `image` are `size` square.
pub fn emission(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> [f64; 3] {
    let lifts = lifts(picture, covered, image, size);
    let curved = lifts.iter().any(|&(all, dark)| all >= LEAST && dark.is_some_and(|d| 2 * d < all));
    if curved {
        return [0.0; 3];
    }
    lifts.map(|(all, _)| if all >= LEAST { f64::from(all) / 255.0 } else { 0.0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_median_lift_of_unclamped_pixels_is_the_emission() {
        // Four covered pixels, one uncovered: red lifted by 51 (one clamped at 255 is left
        // out, and one lifted by 5 is outvoted), green lowered, blue not lifted.
        // A level of 253 is clamped with noise: left out as 255 is.
        // (Five pixels in a row: none is flat around, so all covered ones count.)
        let picture = [100, 100, 0, 255, 100, 100, 0, 255, 240, 100, 0, 255, 100, 100, 0, 255, 0, 0, 0, 255];
        let image = [151, 90, 0, 255, 151, 90, 0, 255, 253, 90, 0, 255, 105, 90, 0, 255, 200, 200, 0, 255];
        let covered = [true, true, true, true, false];
        let e = emission(&picture, &covered, &image, 5);
        assert_eq!(e, [51.0 / 255.0, 0.0, 0.0]);
        // A lift of 3 levels is noise.
        let image: Vec<u8> = picture.iter().map(|&v| v.saturating_add(3)).collect();
        assert_eq!(emission(&picture, &covered, &image, 5), [0.0; 3]);
    }

    #[test]
    fn only_pixels_flat_around_count_where_there_are_some() {
        // 5 x 5, all covered: a steep ramp in red (20 levels a column) lifted by 30, except
        // the centre's 3 x 3, which is flat at 100 and lifted by 10. Only the centre is
        // flat around, so the lift is 10, not the ramp's 30.
        let size = 5;
        let mut picture = vec![0u8; size * size * 4];
        let mut image = vec![0u8; size * size * 4];
        for p in 0..size * size {
            let (x, y) = (p % size, p / size);
            let centre = (1..=3).contains(&x) && (1..=3).contains(&y);
            let level = if centre { 100 } else { 20 + 20 * x as u8 };
            picture[p * 4] = level;
            image[p * 4] = level + if centre { 10 } else { 30 };
        }
        let covered = vec![true; size * size];
        assert_eq!(emission(&picture, &covered, &image, size)[0], 10.0 / 255.0);
    }

    #[test]
    fn a_tone_curve_that_spares_the_dark_pixels_is_no_emission() {
        // 4 x 4 rows of pixels (no pixel is flat around at this size, so all count): half
        // dark at 10, half at 120. The dark ones lifted by 1 and the others by 5 is a
        // gamma's shape; both lifted by 5 is an emission.
        let size = 4;
        let level = |p: usize| if p < 8 { 10u8 } else { 120 };
        let picture: Vec<u8> = (0..16).flat_map(|p| [level(p), level(p), level(p), 255]).collect();
        let covered = vec![true; 16];
        let lifted = |dark: u8| -> Vec<u8> {
            (0..16)
                .flat_map(|p| {
                    let l = level(p) + if p < 8 { dark } else { 5 };
                    [l, l, l, 255]
                })
                .collect()
        };
        assert_eq!(emission(&picture, &covered, &lifted(1), size), [0.0; 3]);
        assert_eq!(emission(&picture, &covered, &lifted(5), size), [5.0 / 255.0; 3]);
    }
}
