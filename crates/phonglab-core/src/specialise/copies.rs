//! The lighter compiled for the processor's vector units, and the choice among the copies
//! (as the renderer's `raster/render/copies.rs`): the chunked driver's portable code is
//! written once, `#[inline(always)]`, in `specialised`, and compiled here again inside
//! functions that enable AVX-512 or AVX2 and FMA. The copies do the same operations (FMA
//! only replaces the library call behind `mul_add` in the exact products), so they give
//! the same bits (tested); the memory prefetch hint is here too.

#[cfg(target_arch = "x86_64")]
use crate::numerics::cpu::{has_avx2_fma, has_avx512};
use crate::specialise::lighter::{Lighter, Output, Probe, Source};

impl Lighter {
    /// The chunked driver. Runs a copy compiled for AVX-512 or AVX2 and FMA when the CPU
    /// has them (the same operations: FMA only replaces the library call behind `mul_add`
    /// in the exact products).
    pub(super) fn run(&self, src: Source<'_>, out: Output<'_>, probe: Probe<'_>) {
        #[cfg(target_arch = "x86_64")]
        if has_avx512() {
            // SAFETY: the CPU has AVX-512F/DQ, AVX2 and FMA (checked just above).
            unsafe { self.run_avx512(src, out, probe) };
            return;
        }
        #[cfg(target_arch = "x86_64")]
        if has_avx2_fma() {
            // SAFETY: the CPU has AVX2 and FMA (checked just above).
            unsafe { self.run_avx2_fma(src, out, probe) };
            return;
        }
        self.run_portable(src, out, probe);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512dq,avx2,fma")]
    fn run_avx512(&self, src: Source<'_>, out: Output<'_>, probe: Probe<'_>) {
        self.run_portable(src, out, probe);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn run_avx2_fma(&self, src: Source<'_>, out: Output<'_>, probe: Probe<'_>) {
        self.run_portable(src, out, probe);
    }
}

/// Asks the processor to bring the memory of `s` into its nearest cache, one cache line
/// at a time: a hint, which changes no result. The lighting of a large array is otherwise
/// bound by waiting for memory (1M vertices of scene (a) took 9.5 ns a vertex, 10 000 of
/// them, which stay in cache, 5.6).
#[inline(always)]
pub(super) fn prefetch<T>(s: &[T]) {
    #[cfg(target_arch = "x86_64")]
    {
        let (p, len) = (s.as_ptr().cast::<i8>(), std::mem::size_of_val(s));
        for off in (0..len).step_by(64) {
            // SAFETY: a prefetch never faults, and the address is inside `s`.
            unsafe { std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(p.add(off)) };
        }
    }
    // Elsewhere (the browser's wasm32) there is no hint to give.
    #[cfg(not(target_arch = "x86_64"))]
    let _ = s;
}
