//! The numerics' code for one processor's instructions: the memory prefetch hint. (The
//! exact power's copies are in `exact_pow/copies.rs`.)

/// Asks the processor to bring the memory of `s` into its nearest cache, one cache line
/// at a time: a hint, which changes no result. The lighting of a large array, and the
/// raster's random reads of a large mesh's triangles, are otherwise bound by waiting for
/// memory (the figures: docs/performance.md, "Why the code is written so").
#[inline(always)]
pub fn prefetch<T>(s: &[T]) {
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
