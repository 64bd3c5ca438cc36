//! The lighter compiled for the processor's vector units, and the choice among the copies
//! (as the renderer's `raster/render/copies.rs`): the chunked driver's portable code is
//! written once, `#[inline(always)]`, in `lighter`, and compiled here again inside
//! functions that enable AVX-512 or AVX2 and FMA, each for the proof that the processor
//! runs it. The copies do the same operations (FMA only replaces the library call behind
//! `mul_add` in the exact products), so they give the same bits (tested).

use crate::cpu::Isa;
#[cfg(target_arch = "x86_64")]
use crate::cpu::{Avx2, Avx512};
use crate::equation::lighting::FormulaSlip;
use crate::specialise::lighter::{Lighter, Output, Recorder, Source};

impl Lighter {
    /// The chunked driver. Runs a copy compiled for AVX-512 or AVX2 and FMA when the CPU
    /// has them (the same operations: FMA only replaces the library call behind `mul_add`
    /// in the exact products). A lighter made with a formula slip runs none of them: the
    /// general engine lights each vertex (`specialise::slipped`).
    pub(super) fn run(&self, src: Source<'_>, out: Output<'_>, probe: Recorder<'_>) {
        if self.engine().options().slip != FormulaSlip::None {
            return self.run_general(src, out);
        }
        match Isa::best() {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512(proof) => self.run_avx512(proof, src, out, probe),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2(proof) => self.run_avx2_fma(proof, src, out, probe),
            _ => self.run_portable(src, out, probe),
        }
    }

    #[cfg(target_arch = "x86_64")]
    fn run_avx512(&self, _: Avx512, src: Source<'_>, out: Output<'_>, probe: Recorder<'_>) {
        // SAFETY: the proof says the processor has AVX-512F/DQ/VL, AVX2 and FMA.
        unsafe { self.run_avx512_body(src, out, probe) }
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512dq,avx2,fma")]
    fn run_avx512_body(&self, src: Source<'_>, out: Output<'_>, probe: Recorder<'_>) {
        self.run_portable(src, out, probe);
    }

    #[cfg(target_arch = "x86_64")]
    fn run_avx2_fma(&self, _: Avx2, src: Source<'_>, out: Output<'_>, probe: Recorder<'_>) {
        // SAFETY: the proof says the processor has AVX2 and FMA.
        unsafe { self.run_avx2_fma_body(src, out, probe) }
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn run_avx2_fma_body(&self, src: Source<'_>, out: Output<'_>, probe: Recorder<'_>) {
        self.run_portable(src, out, probe);
    }
}
