//! What the processor can do, checked once: the renderer's and the lighter's copies for
//! AVX2 and AVX-512 run only where these say yes.

/// Does this CPU have AVX-512F, DQ and VL (and AVX2, FMA)? (Checked once;
/// `PHONGLAB_NO_AVX512` set in the environment turns the AVX-512 kernels off, for
/// comparisons.)
#[cfg(target_arch = "x86_64")]
pub fn has_avx512() -> bool {
    use std::sync::OnceLock;
    static HAS: OnceLock<bool> = OnceLock::new();
    *HAS.get_or_init(|| {
        std::env::var_os("PHONGLAB_NO_AVX512").is_none()
            && std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512dq")
            && std::arch::is_x86_feature_detected!("avx512vl")
            && has_avx2_fma()
    })
}

/// Does this CPU have AVX2 and FMA? (Checked once.)
#[cfg(target_arch = "x86_64")]
pub fn has_avx2_fma() -> bool {
    use std::sync::OnceLock;
    static HAS: OnceLock<bool> = OnceLock::new();
    *HAS.get_or_init(|| std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma"))
}
