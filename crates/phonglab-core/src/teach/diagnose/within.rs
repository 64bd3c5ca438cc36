//! How far a picture called right is from the right one inside the object, in place: what
//! a "right" verdict can and cannot vouch for. The share the right picture explains allows
//! a pixel's shift and [`TOLERANCE`] levels, as rasterisers and 8-bit rounding need; a
//! mistake that moves the picture by less passes it. Shininess 66 typed for 60 on the
//! three-lights scene changes 11 680 pixels inside the teapot by 4 to 7 levels, all
//! within a pixel's shift of the right picture's: 100 % explained. Mesa's right pictures
//! of the shipped scenes are the right one, inside the object, to [`ROUNDING`] level.
//!
//! [`TOLERANCE`]: crate::teach::picture_match::TOLERANCE

use crate::teach::picture_match::apart;

/// The levels by which a right picture drawn by another rasteriser may differ inside the
/// object, in place: the rounding to 8 bits. Measured (docs/guide.md): Mesa's pictures of
/// the spotlight, three-lights and Phong demo scenes differ from phonglab's by at most 1
/// level on every pixel inside the object.
pub const ROUNDING: u8 = 1;

/// A picture against the right one over the object's inside (pixels whose 8 neighbours are
/// covered too: the edge is the rasteriser's).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Within {
    /// The most levels (largest channel) the picture differs by anywhere inside, in place.
    pub most: u8,
    /// The pixels inside that differ by more than [`ROUNDING`].
    pub pixels: usize,
    /// The pixels inside.
    pub inside: usize,
}

impl Within {
    /// Is the picture the right one to the rounding everywhere inside the object? Then a
    /// "right" verdict is the right picture's; else only "right within what a picture can
    /// tell": a mistake that changes the picture by [`Within::most`] levels or less would
    /// look the same.
    pub fn exact(&self) -> bool {
        self.pixels == 0
    }
}

/// `image` against the right `picture` (both RGBA8, `size` square, the picture covering
/// `covered`) over the object's inside.
pub fn within(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> Within {
    let mut w = Within { most: 0, pixels: 0, inside: 0 };
    for y in 1..size.saturating_sub(1) {
        for x in 1..size - 1 {
            let inside = (y - 1..=y + 1).all(|ny| (x - 1..=x + 1).all(|nx| covered[ny * size + nx]));
            if !inside {
                continue;
            }
            let p = y * size + x;
            let here = apart(&picture[p * 4..p * 4 + 3], &image[p * 4..p * 4 + 3]);
            w.inside += 1;
            w.most = w.most.max(here);
            w.pixels += usize::from(here > ROUNDING);
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_picture_off_by_a_few_levels_inside_is_right_only_within_what_it_tells() {
        let size = 16;
        // A square object from (4, 4) to (11, 11): its inside is (5, 5) to (10, 10).
        let covered: Vec<bool> =
            (0..size * size).map(|p| (4..12).contains(&(p % size)) && (4..12).contains(&(p / size))).collect();
        let picture: Vec<u8> =
            covered.iter().flat_map(|&c| if c { [120, 90, 60, 255] } else { [0, 0, 0, 255] }).collect();
        let w = within(&picture, &covered, &picture, size);
        assert_eq!(w, Within { most: 0, pixels: 0, inside: 36 });
        assert!(w.exact());
        // Rounding by a level everywhere, and any change on the edge, is still exact.
        let mut image: Vec<u8> =
            picture.iter().enumerate().map(|(i, &v)| if i % 4 == 0 && v > 0 { v + 1 } else { v }).collect();
        image[(4 * size + 4) * 4] = 255;
        assert!(within(&picture, &covered, &image, size).exact());
        // Five pixels inside 4 levels darker, one 7: not exact, and how far is said.
        for (k, x) in (5..11).enumerate() {
            image[(7 * size + x) * 4 + 1] -= if k == 0 { 7 } else { 4 };
        }
        let w = within(&picture, &covered, &image, size);
        assert_eq!(w, Within { most: 7, pixels: 6, inside: 36 });
        assert!(!w.exact());
    }
}
