//! The renderer's copies compiled for the processor's vector units, and the choice among
//! them: each stage's scalar code (in `window`, `setup`, `raster`, `resolve`) is written
//! once, `#[inline(always)]`, and compiled here again inside functions that enable AVX2
//! and FMA (or AVX-512), as glam keeps its `sse2/` apart. Every copy does the same
//! operations, so every image is the same, bit for bit, on every processor (the tests
//! compare the copies); where the processor lacks the features, the portable copy runs.

use glam::Vec4;

use super::Job;
#[cfg(target_arch = "x86_64")]
use super::resolve::LANES as ResolveLanes;
use super::resolve::{Attributes, BandInput, Fragments, Shaded};
use super::setup::{RasterTri, Setup};
use super::vertices::Vertices;
use super::visibility::Band;
#[cfg(target_arch = "x86_64")]
use super::visibility::{LANES, RowPlane};
use super::window::WindowVert;

/// Each clip-space vertex of `clip` in window coordinates for a `width` x `height` image
/// ([`super::window::to_window`], the same bits as setup's own), into `out`: once per mesh vertex, for the
/// triangles that need no clipping, instead of once per triangle corner (a vertex of a
/// closed mesh has about six triangles). Vertices outside the view volume get values no
/// unclipped triangle reads. Runs a copy compiled for AVX2 where the processor has it
/// (rounding inline instead of through the C library).
pub fn window_vertices(clip: &[Vec4], out: &mut [WindowVert], width: usize, height: usize) {
    #[cfg(target_arch = "x86_64")]
    if crate::numerics::cpu::has_avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA (checked just above).
        return unsafe { window_vertices_avx2(clip, out, width, height) };
    }
    super::window::window_vertices(clip, out, width, height);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn window_vertices_avx2(clip: &[Vec4], out: &mut [WindowVert], width: usize, height: usize) {
    super::window::window_vertices(clip, out, width, height);
}

/// Clips, faces, culls and snaps the mesh triangles `faces` into `out` (cleared first).
/// Runs a copy compiled for AVX2 where the processor has it, whose rounding to fixed point
/// is inline (the portable copy calls the C library's `roundf`); the arithmetic is the
/// same, so the bits are.
pub(super) fn setup_faces(
    job: &Job<'_>,
    verts: &Vertices,
    faces: std::ops::Range<usize>,
    width: usize,
    height: usize,
    out: &mut Vec<RasterTri>,
) {
    #[cfg(target_arch = "x86_64")]
    if crate::numerics::cpu::has_avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA (checked just above).
        return unsafe { setup_faces_avx2(job, verts, faces, width, height, out) };
    }
    super::setup::setup_faces(job, verts, faces, width, height, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn setup_faces_avx2(
    job: &Job<'_>,
    verts: &Vertices,
    faces: std::ops::Range<usize>,
    width: usize,
    height: usize,
    out: &mut Vec<RasterTri>,
) {
    super::setup::setup_faces(job, verts, faces, width, height, out);
}

/// Clears a band and draws the triangles `bin` of `setup` into it (front faces first).
/// Returns the number of back faces skipped as hidden whole.
pub fn draw_band(setup: &Setup, bin: &[u32], band: Band<'_>) -> usize {
    #[cfg(target_arch = "x86_64")]
    if crate::numerics::cpu::has_avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA (checked just above).
        return unsafe { draw_band_avx2(setup, bin, band) };
    }
    super::visibility::draw_band_any::<false>(setup, bin, band)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
pub(super) fn draw_band_avx2(setup: &Setup, bin: &[u32], band: Band<'_>) -> usize {
    super::visibility::draw_band_any::<true>(setup, bin, band)
}

/// The attributes of triangles `ts` (a chunk) into `out`, through the copy `copy` compiled
/// for this processor (the portable one if it cannot run it): the AVX2 copy does the same
/// operations, in registers of four f64 where the portable copy has SSE2's two, so the
/// same bits (tested).
pub(super) fn attributes_chunk(copy: Compiled, job: &Job<'_>, verts: &Vertices, ts: &[RasterTri], out: Attributes<'_>) {
    #[cfg(target_arch = "x86_64")]
    if copy != Compiled::Portable && crate::numerics::cpu::has_avx2_fma() {
        // SAFETY: the processor has AVX2 and FMA (checked just above).
        return unsafe { attributes_chunk_avx2(job, verts, ts, out) };
    }
    let _ = copy;
    super::resolve::attributes_chunk_any(job, verts, ts, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn attributes_chunk_avx2(job: &Job<'_>, verts: &Vertices, ts: &[RasterTri], out: Attributes<'_>) {
    super::resolve::attributes_chunk_any(job, verts, ts, out);
}

/// Shades one band (`band`) into `px`, its pixels. Returns the pixels covered and the lighting
/// evaluations made (fragments lit). Runs the fastest copy the processor has
/// (`Compiled::best`): the copies do the same operations, so they give the same bits
/// (Rust never fuses a multiply and an add by itself).
pub fn resolve_band(band: &BandInput<'_>, px: &mut [[u8; 4]], frags: &mut Fragments) -> Shaded {
    let copy = Compiled::best();
    resolve_band_copy(copy, band, px, frags)
        .unwrap_or_else(|| super::resolve::resolve_band_any::<false>(band, px, frags))
}

/// The compiled copies of the resolve (the AVX ones only exist on x86-64).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
pub(crate) enum Compiled {
    /// For any processor.
    Portable,
    /// For processors with AVX2 and FMA.
    Avx2,
    /// For processors with AVX-512 (F, DQ, VL) as well.
    Avx512,
}

impl Compiled {
    /// The fastest copy this processor runs.
    pub(super) fn best() -> Self {
        #[cfg(target_arch = "x86_64")]
        if crate::numerics::cpu::has_avx512() {
            return Compiled::Avx512;
        }
        #[cfg(target_arch = "x86_64")]
        if crate::numerics::cpu::has_avx2_fma() {
            return Compiled::Avx2;
        }
        Compiled::Portable
    }
}

/// [`resolve_band`] through one given copy; `None` if this processor cannot run it.
pub(crate) fn resolve_band_copy(
    copy: Compiled,
    band: &BandInput<'_>,
    px: &mut [[u8; 4]],
    frags: &mut Fragments,
) -> Option<Shaded> {
    match copy {
        Compiled::Portable => Some(super::resolve::resolve_band_any::<false>(band, px, frags)),
        #[cfg(target_arch = "x86_64")]
        // SAFETY: each copy runs only where the processor has its features.
        Compiled::Avx2 if crate::numerics::cpu::has_avx2_fma() => Some(unsafe { resolve_band_avx2(band, px, frags) }),
        #[cfg(target_arch = "x86_64")]
        Compiled::Avx512 if crate::numerics::cpu::has_avx512() => Some(unsafe { resolve_band_avx512(band, px, frags) }),
        _ => None,
    }
}

/// [`resolve_band_avx2`] where the processor has AVX-512: the weights' f64 arithmetic, eight
/// lanes, fits one register instead of two.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
fn resolve_band_avx512(band: &BandInput<'_>, px: &mut [[u8; 4]], frags: &mut Fragments) -> Shaded {
    super::resolve::resolve_band_any::<true>(band, px, frags)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn resolve_band_avx2(band: &BandInput<'_>, px: &mut [[u8; 4]], frags: &mut Fragments) -> Shaded {
    super::resolve::resolve_band_any::<true>(band, px, frags)
}

/// `raster::fill_span` in AVX2 registers. The blocks are aligned to multiples of [`super::visibility::LANES`]
/// pixels in the band, so that a block's loads meet earlier stores of the same block
/// whole; lanes outside the span are masked off, and a block where no lane passes the
/// depth test is not stored at all (a closed surface's back faces, drawn last, mostly
/// stop there). The arithmetic is the portable loop's, operation for operation (multiply,
/// then add; no fused multiply-add), so the bits are the same.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) fn fill_span_avx2(ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, n: usize) {
    use std::arch::x86_64::*;
    let RowPlane { l1: l1_0, l2: l2_0, step1, step2, z0, dz1, dz2 } = plane;
    let iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    let (l1_0, step1, l2_0, step2) =
        (_mm256_set1_ps(l1_0), _mm256_set1_ps(step1), _mm256_set1_ps(l2_0), _mm256_set1_ps(step2));
    let (z0, dz1, dz2) = (_mm256_set1_ps(z0), _mm256_set1_ps(dz1), _mm256_set1_ps(dz2));
    let (minus_one, count, new_r) = (_mm256_set1_epi32(-1), _mm256_set1_epi32(n as i32), _mm256_set1_epi32(ti as i32));
    let end = at + n;
    let mut i = at & !(LANES - 1);
    while i < end {
        let blocks = (
            band.depth.get_mut(i..).and_then(|s| s.first_chunk_mut::<LANES>()),
            band.raster.get_mut(i..).and_then(|s| s.first_chunk_mut::<LANES>()),
        );
        let (Some(d), Some(r)) = blocks else {
            // The band's last pixels, past its last whole block: one at a time.
            for k in i.max(at) - at..n {
                super::visibility::fill_one(ti, plane, band, at, k);
            }
            return;
        };
        // k: each lane's pixel counted from the span's first (negative before it).
        let k = _mm256_add_epi32(_mm256_set1_epi32(i as i32 - at as i32), iota);
        let kf = _mm256_cvtepi32_ps(k);
        let l1 = _mm256_add_ps(l1_0, _mm256_mul_ps(step1, kf));
        let l2 = _mm256_add_ps(l2_0, _mm256_mul_ps(step2, kf));
        let z = _mm256_add_ps(_mm256_add_ps(z0, _mm256_mul_ps(dz1, l1)), _mm256_mul_ps(dz2, l2));
        let in_span = _mm256_and_si256(_mm256_cmpgt_epi32(k, minus_one), _mm256_cmpgt_epi32(count, k));
        // SAFETY (the loads and stores): each array is LANES f32 or u32, 32 bytes; the
        // unaligned forms need no alignment.
        unsafe {
            let old_d = _mm256_loadu_ps(d.as_ptr());
            let pass = _mm256_and_ps(_mm256_castsi256_ps(in_span), _mm256_cmp_ps::<_CMP_LT_OQ>(z, old_d));
            if _mm256_movemask_ps(pass) != 0 {
                _mm256_storeu_ps(d.as_mut_ptr(), _mm256_blendv_ps(old_d, z, pass));
                // The old triangles are read by `load_opaque` so that the compiler keeps a
                // load, blend and store: left alone it makes them a masked store
                // (vmaskmovps), several times slower on AMD's Zen (measured: a fifth of
                // the raster's time).
                let old_r = load_opaque(r.as_ptr().cast());
                let r_new = _mm256_blendv_ps(old_r, _mm256_castsi256_ps(new_r), pass);
                _mm256_storeu_ps(r.as_mut_ptr().cast(), r_new);
            }
        }
        i += LANES;
    }
}

/// Eight f32 (or u32) from `p` by one `vmovups`, which the compiler cannot see through.
///
/// # Safety
/// `p` must be valid for reading 32 bytes, and the CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
unsafe fn load_opaque(p: *const f32) -> std::arch::x86_64::__m256 {
    let v;
    // SAFETY: the caller's promise; the instruction reads 32 bytes at p, unaligned.
    unsafe {
        std::arch::asm!("vmovups {v}, ymmword ptr [{p}]", v = out(ymm_reg) v, p = in(reg) p,
            options(pure, readonly, nostack, preserves_flags));
    }
    v
}

/// [`super::resolve::rgba8`] in AVX2 registers, with the same bytes: for a channel in [0, 1] the same
/// multiply and add, then truncation; the clamps come from saturating packs (i32 to u16
/// to u8) instead of a max, a min and a mask per channel. Only `min(1, c)` stays, so that
/// a huge value cannot wrap: below 0 (or NaN, which the min passes on and the conversion
/// turns into i32::MIN), the packs give 0 as `to_u8` does. A byte shuffle then
/// interleaves the channels pixel by pixel.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
pub(super) fn rgba8_avx2(ch: &[[f32; ResolveLanes]; 4]) -> [u32; ResolveLanes] {
    use std::arch::x86_64::*;
    let (one, scale, half) = (_mm256_set1_ps(1.0), _mm256_set1_ps(255.0), _mm256_set1_ps(0.5));
    // SAFETY (loads and stores): each array is LANES f32 or u32, 32 bytes; the unaligned
    // forms need no alignment.
    let q = |c: &[f32; ResolveLanes]| {
        let v = unsafe { _mm256_loadu_ps(c.as_ptr()) };
        // min(one, v): the second operand, v, where either is NaN.
        _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(_mm256_min_ps(one, v), scale), half))
    };
    // Per 128-bit half: r0..3 g0..3 b0..3 a0..3 (pixels 0-3), then the same for 4-7.
    let bytes =
        _mm256_packus_epi16(_mm256_packus_epi32(q(&ch[0]), q(&ch[1])), _mm256_packus_epi32(q(&ch[2]), q(&ch[3])));
    let by_pixel = _mm256_setr_epi8(
        0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15,
    );
    let mut out = [0u32; ResolveLanes];
    unsafe { _mm256_storeu_si256(out.as_mut_ptr().cast(), _mm256_shuffle_epi8(bytes, by_pixel)) };
    out
}

/// One bit per entry of `block` that differs from `r`: two SSE2 compares and masks (the
/// compiler turned a plain loop into eight scalar compares and shifts).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn differ8(block: &[u32; 8], r: u32) -> u32 {
    use std::arch::x86_64::{
        __m128i, _mm_castsi128_ps, _mm_cmpeq_epi32, _mm_loadu_si128, _mm_movemask_ps, _mm_set1_epi32,
    };
    // SAFETY: SSE2 is part of x86_64; both loads read 16 bytes within `block`.
    let equal = unsafe {
        let p = block.as_ptr() as *const __m128i;
        let rv = _mm_set1_epi32(r as i32);
        let lo = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_loadu_si128(p), rv)));
        let hi = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_loadu_si128(p.add(1)), rv)));
        (lo | hi << 4) as u32
    };
    !equal & 0xff
}

/// One bit per entry of `block` that differs from `r`.
#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
pub(super) fn differ8(block: &[u32; 8], r: u32) -> u32 {
    (0..8).fold(0u32, |m, j| m | (((block[j] != r) as u32) << j))
}
