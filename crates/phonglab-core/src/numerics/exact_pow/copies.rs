//! The exact power's copies compiled for the processor's vector units (as the renderer's
//! `raster/render/copies.rs` and the lighter's `specialise/copies.rs`): [`super::operations`]
//! holds the scalar operations, written once; each copy takes the proof that the processor
//! runs it. The copy does the same operations (AVX-512 only packs the lanes that need a
//! power before the same scalar steps), so it gives the same bits on every processor
//! (tested in [`super`]).

#[cfg(target_arch = "x86_64")]
use super::operations::pow_fractional;
#[cfg(target_arch = "x86_64")]
use crate::cpu::Avx512;

/// [`super::pow_f32_chunk_packed`]'s AVX-512 way, for a fractional `e > 0`, for the proof
/// that the processor has AVX-512F/DQ/VL (and AVX2, FMA).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub fn pow_packed_avx512<const N: usize>(_: Avx512, x: &[f32; N], e: f32, out: &mut [f32; N]) {
    // SAFETY: the proof says the processor has AVX-512F/DQ/VL, AVX2 and FMA.
    unsafe { pow_packed_avx512_body(x, e, out) };
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
fn pow_packed_avx512_body<const N: usize>(x: &[f32; N], e: f32, out: &mut [f32; N]) {
    use std::arch::x86_64::*;
    const { assert!(N.is_multiple_of(16) && N <= 128, "whole blocks of 16, at most 8 of them") };
    // The lanes with x > 0, packed (16 spare lanes: each block of 16 is stored whole).
    let mut packed = [0.0f32; 128 + 16];
    let mut masks = [0u16; 8];
    let mut m = 0;
    for (b, mask) in masks.iter_mut().enumerate().take(N / 16) {
        // SAFETY: 16 lanes from 16 b < N are inside `x`; `m <= 16 b < 128`, so 16 lanes from
        // m are inside `packed`.
        unsafe {
            let v = _mm512_loadu_ps(x.as_ptr().add(16 * b));
            let k = _mm512_cmp_ps_mask::<_CMP_GT_OQ>(v, _mm512_setzero_ps());
            _mm512_storeu_ps(packed.as_mut_ptr().add(m), _mm512_maskz_compress_ps(k, v));
            *mask = k;
            m += k.count_ones() as usize;
        }
    }
    // Their powers, a block of 8 at a time (the last block's spare lanes hold zeros or
    // earlier values: computed and never read).
    let mut powers = [0.0f32; 128 + 16];
    for (pb, xb) in powers.chunks_exact_mut(8).zip(packed.chunks_exact(8)).take(m.div_ceil(8)) {
        for (o, &v) in pb.iter_mut().zip(xb) {
            *o = pow_fractional(v, e);
        }
    }
    // Back to their lanes; +0 in the others.
    let mut at = 0;
    for (b, &k) in masks.iter().enumerate().take(N / 16) {
        // SAFETY: as above, `at <= 16 b`; 16 lanes from 16 b < N are inside `out`.
        unsafe {
            let r = _mm512_loadu_ps(powers.as_ptr().add(at));
            _mm512_storeu_ps(out.as_mut_ptr().add(16 * b), _mm512_maskz_expand_ps(k, r));
        }
        at += k.count_ones() as usize;
    }
}
