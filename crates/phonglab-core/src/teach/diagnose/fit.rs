//! The emission a student's picture shows beyond the right picture: for `emission-added`,
//! whose colour is not in the scene but fitted from the picture, then drawn and scored as
//! every other mistake is.

/// The median, per channel, of the student's level less the right picture's, over the
/// pixels the object covers where neither is clamped (0 or 255) in that channel, in linear
/// units (0 to 1); 0 for a channel with no such pixel or a median not above 0.
pub fn emission(picture: &[u8], covered: &[bool], image: &[u8]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (c, value) in out.iter_mut().enumerate() {
        let mut differences: Vec<i16> = covered
            .iter()
            .enumerate()
            .filter(|&(_, &inside)| inside)
            .map(|(p, _)| (picture[p * 4 + c], image[p * 4 + c]))
            .filter(|&(a, b)| (1..=254).contains(&a) && (1..=254).contains(&b))
            .map(|(a, b)| i16::from(b) - i16::from(a))
            .collect();
        if differences.is_empty() {
            continue;
        }
        let middle = differences.len() / 2;
        let (_, median, _) = differences.select_nth_unstable(middle);
        *value = (f64::from(*median) / 255.0).max(0.0);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_median_lift_of_unclamped_pixels_is_the_emission() {
        // Four covered pixels, one uncovered: red lifted by 51 (one clamped at 255 is left
        // out, and one lifted by 5 is outvoted), green lowered, blue never unclamped.
        let picture = [100, 100, 0, 255, 100, 100, 0, 255, 250, 100, 0, 255, 100, 100, 0, 255, 0, 0, 0, 255];
        let image = [151, 90, 0, 255, 151, 90, 0, 255, 255, 90, 0, 255, 105, 90, 0, 255, 200, 200, 0, 255];
        let covered = [true, true, true, true, false];
        let e = emission(&picture, &covered, &image);
        assert_eq!(e, [51.0 / 255.0, 0.0, 0.0]);
    }
}
