//! Whether a picture was saved as JPEG: JPEG codes 8 x 8 blocks apart, so its error (the
//! image less the right picture) jumps across the blocks' edges more than inside them.
//! A blur, a resize, noise or a wrong value change the picture as much on every column and
//! row; only a lossy saving in blocks puts a grid in the difference.

/// How much more, at the least, the difference must jump across the blocks' edges than
/// at the most jumping other place in a block for the picture to look saved as JPEG.
/// Measured (scripts/diagnose-table.sh, the three scenes at 512, over flat parts
/// (`FLAT`)): JPEG of quality 75 to 95, 4:4:4 and 4:2:0, 1.25 to 2.09; a blur,
/// antialiasing, resizes down and up (Lanczos, Mitchell), half a pixel's shift, noise of
/// ±3 and ±5 and a colour a few levels off, at most 1.02 (against `QUIET`).
pub const JPEG_GRID_AT: f64 = 1.12;

/// The blocks JPEG codes apart.
const BLOCK: usize = 8;

/// Levels (each channel) within which the right picture must stay over the four pixels
/// around a pair for the pair to be measured: on a flat part a blur or a resize changes
/// nothing and JPEG's blocks still step; across an edge or a highlight's rim a blur's error
/// is large wherever the edge happens to fall against the blocks.
const FLAT: u8 = 2;

/// The least mean jump inside the blocks a ratio is taken against (levels, the three
/// channels summed).
const QUIET: f64 = 0.25;

/// How much more the difference between `image` and `picture` (RGBA8, `size` square) jumps
/// from one pixel to the next across the edges of 8 x 8 blocks than at the most jumping
/// other place in a block, along rows and columns together, over pairs on flat parts of
/// the object (`covered`; `FLAT`); 1 when the difference never jumps across an edge.
pub fn jpeg_grid(picture: &[u8], covered: &[bool], image: &[u8], size: usize) -> f64 {
    let mut sum = [0u64; BLOCK];
    let mut count = [0u64; BLOCK];
    let error = |p: usize, c: usize| i32::from(image[p * 4 + c]) - i32::from(picture[p * 4 + c]);
    let jump = |p: usize, q: usize| (0..3).map(|c| (error(q, c) - error(p, c)).unsigned_abs()).sum::<u32>();
    let flat = |p: usize, q: usize| {
        covered[p] && covered[q] && (0..3).all(|c| picture[p * 4 + c].abs_diff(picture[q * 4 + c]) <= FLAT)
    };
    for y in 1..size.saturating_sub(2) {
        for x in 1..size.saturating_sub(2) {
            let p = y * size + x;
            // Along the row, then down the column: the pair (p, p + step) and one pixel
            // either side of it.
            for (step, at) in [(1, x), (size, y)] {
                if flat(p - step, p) && flat(p, p + step) && flat(p + step, p + 2 * step) {
                    sum[at % BLOCK] += u64::from(jump(p, p + step));
                    count[at % BLOCK] += 1;
                }
            }
        }
    }
    let mean = |k: usize| if count[k] == 0 { 0.0 } else { sum[k] as f64 / count[k] as f64 };
    let inside = (0..BLOCK - 1).map(mean).fold(0.0, f64::max);
    let edge = mean(BLOCK - 1);
    // A quarter of a level on the mean at the least inside (JPEG's, measured, are 1.07 and
    // more): a difference that is nearly none (a resize by 75 % of the Phong demo, 0.05 at
    // the edges against 0.04 inside) is no grid, and one that steps only at the blocks'
    // edges is not a division by nothing.
    if edge <= 0.0 { 1.0 } else { edge / inside.max(QUIET) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_that_steps_at_each_block_is_a_grid_and_noise_is_not() {
        let size = 64;
        let picture: Vec<u8> = (0..size * size).flat_map(|_| [100, 100, 100, 255]).collect();
        let covered = vec![true; size * size];
        // Each 8 x 8 block lifted by its own level: the error steps only at the blocks' edges.
        let blocks: Vec<u8> = (0..size * size)
            .flat_map(|p| {
                let v = 100 + ((p % size / 8 + p / size / 8) % 3) as u8 * 2;
                [v, v, v, 255]
            })
            .collect();
        assert!(jpeg_grid(&picture, &covered, &blocks, size) > 10.0);
        // Noise of ±2 everywhere: no grid.
        let mut s = 7u32;
        let noised: Vec<u8> = (0..size * size * 4)
            .map(|i| {
                s = s.wrapping_mul(1_103_515_245).wrapping_add(12345);
                if i % 4 == 3 { 255 } else { 98 + ((s >> 16) % 5) as u8 }
            })
            .collect();
        assert!(jpeg_grid(&picture, &covered, &noised, size) < JPEG_GRID_AT);
        assert_eq!(jpeg_grid(&picture, &covered, &picture, size), 1.0);
    }
}
