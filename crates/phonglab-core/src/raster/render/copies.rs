//! The renderer's copies compiled for the processor's vector units, and the choice among
//! them: each stage's scalar code (in `window`, `setup`, `raster`, `resolve`) is written
//! once, `#[inline(always)]`, and compiled here again inside functions that enable AVX2
//! and FMA (or AVX-512), as glam keeps its `sse2/` apart. Every copy does the same
//! operations, so every image is the same, bit for bit, on every processor (the tests
//! compare the copies); where the processor lacks the features, the portable copy runs.

use glam::Vec4;

use super::Job;
use super::resolve::{BandCounts, BandInput, Fragments};
use super::setup::{ChunkOut, Setup};
use super::vertices::Vertices;
use super::visibility::Band;
use super::window::WindowVert;
use crate::cpu::{Isa, Portable};

/// Each clip-space vertex of `clip` in window coordinates for a `width` x `height` image
/// ([`super::window::to_window`], the same bits as setup's own), into `out`: once per mesh
/// vertex, for the triangles that need no clipping, instead of once per triangle corner (a
/// vertex of a closed mesh has about six triangles). Vertices outside the view volume get
/// values no unclipped triangle reads. And each vertex's code against the view volume
/// into `codes` (`outcodes::codes`). The copy `isa` compiled with AVX2 rounds
/// inline instead of through the C library, and makes the codes eight vertices at a time.
pub fn window_vertices(isa: Isa, clip: &[Vec4], out: &mut [WindowVert], codes: &mut [u8], width: usize, height: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(proof) = isa.avx2() {
        return x86::window_vertices(proof, clip, out, codes, width, height);
    }
    let _ = isa;
    super::window::window_vertices(clip, out, width, height);
    super::outcodes::codes(clip, codes);
}

/// Clips, faces, culls and snaps the mesh triangles `faces` into `out` (their slots and the rest),
/// through the copy `isa`: the AVX2 one rounds to fixed point inline (the portable copy
/// calls the C library's `roundf`); the arithmetic is the same, so the bits are.
pub(super) fn setup_faces(
    isa: Isa,
    job: &Job<'_>,
    verts: &Vertices,
    faces: std::ops::Range<usize>,
    width: usize,
    height: usize,
    out: ChunkOut<'_>,
) {
    #[cfg(target_arch = "x86_64")]
    if let Some(proof) = isa.avx2() {
        return x86::setup_faces(proof, job, verts, faces, width, height, out);
    }
    let _ = isa;
    super::setup::setup_faces(job, verts, faces, width, height, out);
}

/// Clears a band and draws the triangles `bin` of `setup` into it (front faces first),
/// through the copy `isa`. Returns the number of back faces skipped as hidden whole.
pub fn draw_band(isa: Isa, setup: &Setup, bin: &[u32], band: Band<'_>) -> usize {
    #[cfg(target_arch = "x86_64")]
    if let Some(proof) = isa.avx2() {
        return x86::draw_band(proof, setup, bin, band);
    }
    let _ = isa;
    super::visibility::draw_band_any(Portable, setup, bin, band)
}

/// Shades one band (`band`) into `px`, its pixels, through the copy `isa`. Returns the
/// pixels covered and the lighting evaluations made (fragments lit). The copies do the
/// same operations, so they give the same bits (Rust never fuses a multiply and an add by
/// itself).
pub fn resolve_band(isa: Isa, band: &BandInput<'_>, px: &mut [[u8; 4]], frags: &mut Fragments) -> BandCounts {
    match isa {
        #[cfg(target_arch = "x86_64")]
        Isa::Avx512(proof) => x86::resolve_band_avx512(proof, band, px, frags),
        #[cfg(target_arch = "x86_64")]
        Isa::Avx2(proof) => x86::resolve_band_avx2(proof, band, px, frags),
        _ => super::resolve::resolve_band_any(Portable, band, px, frags),
    }
}

/// The copies for x86-64's AVX2 and AVX-512. Each entry takes the proof that the processor
/// runs it ([`Avx2`], [`Avx512`]), which only detection at run time makes: that is what
/// makes the `unsafe` calls of the `#[target_feature]` functions sound.
#[cfg(target_arch = "x86_64")]
mod x86 {
    use glam::Vec4;

    use crate::cpu::{Avx2, Avx512};
    use crate::raster::render::Job;
    use crate::raster::render::resolve::{
        BandCounts, BandInput, Fragments, LANES as ResolveLanes, ResolveLanes as Lanes,
    };
    use crate::raster::render::setup::{ChunkOut, Setup};
    use crate::raster::render::vertices::Vertices;
    use crate::raster::render::visibility::{Band, LANES, RowPlane, SpanFill};
    use crate::raster::render::window::WindowVert;

    pub(super) fn window_vertices(
        _: Avx2,
        clip: &[Vec4],
        out: &mut [WindowVert],
        codes: &mut [u8],
        width: usize,
        height: usize,
    ) {
        // SAFETY: the proof says the processor has AVX2 and FMA.
        unsafe { window_vertices_avx2(clip, out, codes, width, height) }
    }

    #[target_feature(enable = "avx2,fma")]
    fn window_vertices_avx2(clip: &[Vec4], out: &mut [WindowVert], codes: &mut [u8], width: usize, height: usize) {
        crate::raster::render::window::window_vertices(clip, out, width, height);
        crate::raster::render::outcodes::codes(clip, codes);
    }

    pub(super) fn setup_faces(
        _: Avx2,
        job: &Job<'_>,
        verts: &Vertices,
        faces: std::ops::Range<usize>,
        width: usize,
        height: usize,
        out: ChunkOut<'_>,
    ) {
        // SAFETY: the proof says the processor has AVX2 and FMA.
        unsafe { setup_faces_avx2(job, verts, faces, width, height, out) }
    }

    #[target_feature(enable = "avx2,fma")]
    fn setup_faces_avx2(
        job: &Job<'_>,
        verts: &Vertices,
        faces: std::ops::Range<usize>,
        width: usize,
        height: usize,
        out: ChunkOut<'_>,
    ) {
        crate::raster::render::setup::setup_faces(job, verts, faces, width, height, out);
    }

    pub(super) fn draw_band(proof: Avx2, setup: &Setup, bin: &[u32], band: Band<'_>) -> usize {
        // SAFETY: the proof says the processor has AVX2 and FMA.
        unsafe { draw_band_avx2(proof, setup, bin, band) }
    }

    #[target_feature(enable = "avx2,fma")]
    fn draw_band_avx2(proof: Avx2, setup: &Setup, bin: &[u32], band: Band<'_>) -> usize {
        crate::raster::render::visibility::draw_band_any(proof, setup, bin, band)
    }

    pub(super) fn resolve_band_avx2(
        proof: Avx2,
        band: &BandInput<'_>,
        px: &mut [[u8; 4]],
        frags: &mut Fragments,
    ) -> BandCounts {
        // SAFETY: the proof says the processor has AVX2 and FMA.
        unsafe { resolve_band_avx2_body(proof, band, px, frags) }
    }

    #[target_feature(enable = "avx2,fma")]
    fn resolve_band_avx2_body(
        proof: Avx2,
        band: &BandInput<'_>,
        px: &mut [[u8; 4]],
        frags: &mut Fragments,
    ) -> BandCounts {
        crate::raster::render::resolve::resolve_band_any(proof, band, px, frags)
    }

    /// [`resolve_band_avx2`] where the processor has AVX-512: the weights' f64 arithmetic,
    /// eight lanes, fits one register instead of two.
    pub(super) fn resolve_band_avx512(
        proof: Avx512,
        band: &BandInput<'_>,
        px: &mut [[u8; 4]],
        frags: &mut Fragments,
    ) -> BandCounts {
        // SAFETY: the proof says the processor has AVX-512 F, DQ and VL, AVX2 and FMA.
        unsafe { resolve_band_avx512_body(proof.avx2(), band, px, frags) }
    }

    #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
    fn resolve_band_avx512_body(
        proof: Avx2,
        band: &BandInput<'_>,
        px: &mut [[u8; 4]],
        frags: &mut Fragments,
    ) -> BandCounts {
        crate::raster::render::resolve::resolve_band_any(proof, band, px, frags)
    }

    impl SpanFill for Avx2 {
        #[inline(always)]
        fn fill_span(self, ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, n: usize) {
            // SAFETY: the proof (self) says the processor has AVX2.
            unsafe { fill_span_avx2(ti, plane, band, at, n) }
        }
    }

    impl Lanes for Avx2 {
        #[inline(always)]
        fn rgba8(self, ch: &[[f32; ResolveLanes]; 4]) -> [u32; ResolveLanes] {
            // SAFETY: the proof (self) says the processor has AVX2.
            unsafe { rgba8_avx2(ch) }
        }

        #[inline(always)]
        fn differ8(self, block: &[u32; 8], r: u32) -> u32 {
            differ8_sse2(block, r)
        }
    }

    /// `raster::fill_span` in AVX2 registers. The blocks are aligned to multiples of [`LANES`]
    /// pixels in the band, so that a block's loads meet earlier stores of the same block
    /// whole; lanes outside the span are masked off, and a block where no lane passes the
    /// depth test is not stored at all (a closed surface's back faces, drawn last, mostly
    /// stop there). The arithmetic is the portable loop's, operation for operation (multiply,
    /// then add; no fused multiply-add), so the bits are the same.
    #[target_feature(enable = "avx2")]
    #[inline]
    fn fill_span_avx2(ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, n: usize) {
        use std::arch::x86_64::*;
        let RowPlane { l1: l1_0, l2: l2_0, step1, step2, z0, dz1, dz2 } = plane;
        let iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        let (l1_0, step1, l2_0, step2) =
            (_mm256_set1_ps(l1_0), _mm256_set1_ps(step1), _mm256_set1_ps(l2_0), _mm256_set1_ps(step2));
        let (z0, dz1, dz2) = (_mm256_set1_ps(z0), _mm256_set1_ps(dz1), _mm256_set1_ps(dz2));
        let (minus_one, count, new_r) =
            (_mm256_set1_epi32(-1), _mm256_set1_epi32(n as i32), _mm256_set1_epi32(ti as i32));
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
                    crate::raster::render::visibility::fill_one(ti, plane, band, at, k);
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
                    // (vmaskmovps), which AMD's Zen runs slowly (docs/performance.md, "Why
                    // the code is written so").
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

    /// [`crate::raster::render::resolve::rgba8`] in AVX2 registers, with the same bytes: for a channel in [0, 1] the same
    /// multiply and add, then truncation; the clamps come from saturating packs (i32 to u16
    /// to u8) instead of a max, a min and a mask per channel. Only `min(1, c)` stays, so that
    /// a huge value cannot wrap: below 0 (or NaN, which the min passes on and the conversion
    /// turns into i32::MIN), the packs give 0 as `to_u8` does. A byte shuffle then
    /// interleaves the channels pixel by pixel.
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
    #[inline(always)]
    fn differ8_sse2(block: &[u32; 8], r: u32) -> u32 {
        use std::arch::x86_64::{
            __m128i, _mm_castsi128_ps, _mm_cmpeq_epi32, _mm_loadu_si128, _mm_movemask_ps, _mm_set1_epi32,
        };
        // SAFETY: SSE2 is part of x86_64; both loads read 16 bytes within `block`.
        let equal = unsafe {
            // `_mm_loadu_si128` reads unaligned: the cast to a 16-byte type aligns nothing.
            #[allow(clippy::cast_ptr_alignment)]
            let p = block.as_ptr().cast::<__m128i>();
            let rv = _mm_set1_epi32(r as i32);
            let lo = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_loadu_si128(p), rv)));
            let hi = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_loadu_si128(p.add(1)), rv)));
            (lo | hi << 4) as u32
        };
        !equal & 0xff
    }
}
