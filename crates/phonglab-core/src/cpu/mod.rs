//! What the processor can do, checked once, as proofs: a function compiled for AVX2 or
//! AVX-512 takes the proof that the processor runs it ([`Avx2`], [`Avx512`], [`Fma`]), and
//! only detection at run time makes one, so calling a copy where it cannot run is a type
//! error, not a broken promise in a comment. [`Isa`] is the choice among the copies.

/// Does this CPU have AVX-512F, DQ and VL (and AVX2, FMA)? (Checked once;
/// `PHONGLAB_NO_AVX512` set in the environment turns the AVX-512 kernels off, for
/// comparisons.)
#[cfg(target_arch = "x86_64")]
fn has_avx512() -> bool {
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
fn has_avx2_fma() -> bool {
    use std::sync::OnceLock;
    static HAS: OnceLock<bool> = OnceLock::new();
    *HAS.get_or_init(|| std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma"))
}

/// The portable copy: runs on any processor (no proof needed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Portable;

/// Proof that this processor runs AVX2 and FMA instructions: only [`Avx2::detect`] makes
/// one (or [`Avx512::avx2`], from a proof of more).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Avx2 {
    _proof: (),
}

impl Avx2 {
    /// The proof, where the processor has AVX2 and FMA.
    pub fn detect() -> Option<Avx2> {
        #[cfg(target_arch = "x86_64")]
        if has_avx2_fma() {
            return Some(Avx2 { _proof: () });
        }
        None
    }
}

/// Proof that this processor runs AVX-512 (F, DQ, VL) as well as AVX2 and FMA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Avx512 {
    _proof: (),
}

impl Avx512 {
    /// The proof, where the processor has AVX-512F, DQ and VL, AVX2 and FMA.
    pub fn detect() -> Option<Avx512> {
        #[cfg(target_arch = "x86_64")]
        if has_avx512() {
            return Some(Avx512 { _proof: () });
        }
        None
    }

    /// AVX-512 implies AVX2 and FMA (detection asked for them too).
    pub fn avx2(self) -> Avx2 {
        Avx2 { _proof: () }
    }
}

/// Proof that this processor runs FMA instructions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fma {
    _proof: (),
}

impl Fma {
    /// The proof, where the processor has FMA.
    pub fn detect() -> Option<Fma> {
        #[cfg(target_arch = "x86_64")]
        {
            use std::sync::OnceLock;
            static HAS: OnceLock<bool> = OnceLock::new();
            if *HAS.get_or_init(|| std::arch::is_x86_feature_detected!("fma")) {
                return Some(Fma { _proof: () });
            }
        }
        None
    }
}

/// Which compiled copy runs: each holds its proof.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Isa {
    /// For any processor.
    Portable,
    /// For processors with AVX2 and FMA.
    Avx2(Avx2),
    /// For processors with AVX-512 (F, DQ, VL) as well.
    Avx512(Avx512),
}

impl Isa {
    /// The fastest copy this processor runs.
    pub fn best() -> Isa {
        if let Some(p) = Avx512::detect() {
            return Isa::Avx512(p);
        }
        Avx2::detect().map_or(Isa::Portable, Isa::Avx2)
    }

    /// Every copy this processor runs, the portable one first (for tests that compare them).
    pub fn all_here() -> Vec<Isa> {
        let mut v = vec![Isa::Portable];
        v.extend(Avx2::detect().map(Isa::Avx2));
        v.extend(Avx512::detect().map(Isa::Avx512));
        v
    }

    /// The AVX2 proof this copy carries (AVX-512's implies it), if any.
    pub fn avx2(self) -> Option<Avx2> {
        match self {
            Isa::Portable => None,
            Isa::Avx2(p) => Some(p),
            Isa::Avx512(p) => Some(p.avx2()),
        }
    }
}
