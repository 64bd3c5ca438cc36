//! Pixels in blocks of [`LANES`]: colours to 8 bits as OpenGL converts them
//! (`round(255 clamp(c, 0, 1))`), a block packed and compared, a run filled with one colour.
//! The block operations are a trait ([`ResolveLanes`]) so that a SIMD copy can bring its
//! own instructions for the same operations.

use crate::cpu::Portable;

/// Pixels of a run shaded together: eight f32 lanes, one AVX2 register.
pub const LANES: usize = 8;

/// How blocks of [`LANES`] pixels are packed to bytes and compared: the portable loops
/// ([`Portable`]), or a copy's own instructions for the same operations (the AVX2 ones are
/// in `copies`, for the proof of AVX2). The resolve is written once, generic over it.
pub(in crate::raster::render) trait ResolveLanes: Copy {
    /// [`rgba8`]'s bytes.
    fn rgba8(self, ch: &[[f32; LANES]; 4]) -> [u32; LANES];
    /// One bit per entry of `block` that differs from `r`.
    fn differ8(self, block: &[u32; 8], r: u32) -> u32;
}

impl ResolveLanes for Portable {
    #[inline(always)]
    fn rgba8(self, ch: &[[f32; LANES]; 4]) -> [u32; LANES] {
        rgba8(ch)
    }

    #[inline(always)]
    fn differ8(self, block: &[u32; 8], r: u32) -> u32 {
        (0..8).fold(0u32, |m, j| m | (((block[j] != r) as u32) << j))
    }
}

#[inline(always)]
#[allow(clippy::manual_clamp)] // clamp keeps NaN; max/min turn it into 0, which the cast below needs
pub(super) fn to_u8(c: f32) -> u8 {
    // max/min (IEEE maxNum/minNum) also turn NaN into 0, so v is in [0.5, 255.5].
    let v = c.max(0.0).min(1.0) * 255.0 + 0.5;
    // SAFETY: v is finite and within i32's range (see above); i32, not u32, because
    // processors convert f32 lanes to i32 in one instruction.
    unsafe { v.to_int_unchecked::<i32>() as u8 }
}

/// Eight pixels' channels (`ch[c][j]`: channel c of pixel j) as [`to_u8`] bytes, each
/// pixel's four as one little-endian u32, built in the lanes by shifts (bytes assembled in
/// memory would be stored in two halves and reloaded whole, which stalls).
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lanes index several arrays; the loop vectorises
pub(in crate::raster::render) fn rgba8(ch: &[[f32; LANES]; 4]) -> [u32; LANES] {
    let mut rgba = [0u32; LANES];
    for j in 0..LANES {
        rgba[j] = to_u8(ch[0][j]) as u32
            | (to_u8(ch[1][j]) as u32) << 8
            | (to_u8(ch[2][j]) as u32) << 16
            | (to_u8(ch[3][j]) as u32) << 24;
    }
    rgba
}

/// Sets every pixel of `px` to `c`, eight at a time (32-byte stores; a plain `fill` of
/// 4-byte arrays stored them one by one).
#[inline(always)]
pub(super) fn fill_px(px: &mut [[u8; 4]], c: [u8; 4]) {
    let (blocks, rest) = px.as_chunks_mut::<8>();
    for b in blocks {
        *b = [c; 8];
    }
    rest.fill(c);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The AVX2 packing gives [`to_u8`]'s bytes for every kind of channel value: NaN,
    /// infinities, huge and tiny, negative, just around each rounding boundary, and random.
    #[test]
    fn avx2_bytes_are_the_portable_bytes() {
        if let Some(avx2) = crate::cpu::Avx2::detect() {
            let mut values = vec![
                f32::NAN,
                -f32::NAN,
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::MAX,
                f32::MIN,
                3e9,
                -3e9,
                1e-40,
                -1e-40,
                0.0,
                -0.0,
                1.0,
                -1.0,
                -0.5,
                1.5,
            ];
            // Each boundary between two bytes, and the floats next to it.
            for b in 0..=256 {
                let x = (b as f32 - 0.5) / 255.0;
                values.extend([x, x.next_up(), x.next_down(), x.next_up().next_up()]);
            }
            let mut next = crate::test_support::xorshift(0x9e3779b97f4a7c15);
            values.extend((0..4000).map(|_| f32::from_bits(next() as u32)));
            values.extend((0..4000).map(|_| (next() % 3_000_000) as f32 / 1e6 - 1.0));
            for block in values.chunks(4 * LANES) {
                let mut ch = [[0.0; LANES]; 4];
                for (i, &v) in block.iter().enumerate() {
                    ch[i % 4][i / 4] = v;
                }
                assert_eq!(avx2.rgba8(&ch), rgba8(&ch), "{ch:?}");
            }
        }
    }
}
