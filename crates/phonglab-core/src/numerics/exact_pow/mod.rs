//! The engine's exact power in f32, `x^e` computed in f64 and rounded once, without
//! branches so loops over it vectorise. A numerics building block: [`crate::numerics::real::Real`]'s
//! `pow_exact` for f32 and [`crate::numerics::pow::PowFn::Exact`] both call it, and the specialised
//! evaluator's power stages call [`pow_f32_chunk`], the same operations over an array.
//!
//! Two ways, chosen by the exponent (a property of the scene, not of the vertex):
//!
//! | exponent | how | error before the rounding to f32 |
//! |---|---|---|
//! | whole, 1 to 128 (shininess 32, spot exponent 8) | binary exponentiation in f64: `e = 8` is three squarings | < `e` x 2^-53 relative (1.4e-14 at 128) |
//! | anything else (shininess 25.6) | `2^(e log2 x)`, both by polynomials in f64 | ~1e-10 relative |

//!
//! The steps are in [`operations`], written once; [`copies`] compiles them for AVX-512, and
//! [`pow_f32_chunk_packed`] chooses that copy where the processor runs it.

pub mod copies;
pub mod operations;

#[cfg(target_arch = "x86_64")]
use crate::cpu::Avx512;
pub use operations::{pow_f32_body, pow_f32_chunk, whole_exponent};

/// `x^e` in f32 for `x >= 0` (or NaN), computed in f64 and rounded once: the error before
/// rounding is below 1.4e-14 relative for a whole exponent up to 128 and ~1e-10 for any
/// other, so the result is the correctly rounded one except that close to a rounding tie.
/// `0^0 = 1`, `0^e = 0` and `inf^e = inf` for e > 0, NaN in gives NaN, a negative `x`
/// gives NaN. For a given `e` there are no branches (only selects), so loops over it
/// vectorise; the specialised kernels ([`pow_f32_chunk`]) and the general engine do the
/// same operations, so they agree bit for bit.
///
/// The polynomials' steps are a product then a sum, each rounded (`operations::fma`, not
/// the fused instruction, which WebAssembly lacks), so every processor and the page give the
/// same bits.
#[inline]
pub fn pow_f32(x: f32, e: f32) -> f32 {
    pow_f32_body(x, e)
}

/// [`pow_f32_chunk`] over a whole chunk of `N` (a multiple of 16, at most 128) for a
/// fractional exponent `e > 0`, with the lanes that need a power packed together first:
/// where `x <= 0` (or NaN) the result is +0 without any work, and the logarithm and
/// exponential run only over the others, 8 at a time. Bit for bit [`pow_f32_chunk`]'s
/// results (the same operations on the same values). With AVX-512 (`vcompressps` /
/// `vexpandps`); elsewhere it is [`pow_f32_chunk`], whose blocks of 8 with nothing above 0
/// are skipped. Scene (a)'s lit half of a sphere needs
/// about 40 % of the lanes, scattered (a fifth of its blocks of 8 have none).
#[inline(always)]
pub fn pow_f32_chunk_packed<const N: usize>(x: &[f32; N], e: f32, out: &mut [f32; N]) {
    #[cfg(target_arch = "x86_64")]
    if let Some(proof) = Avx512::detect()
        && e > 0.0
        && whole_exponent(e).is_none()
    {
        return copies::pow_packed_avx512(proof, x, e, out);
    }
    pow_f32_chunk(x, e, out, N);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::uniform;

    #[test]
    fn the_packed_power_is_the_chunk_power_bit_for_bit() {
        // Chunks of 16 to 128 (the evaluator's is lighter::CHUNK); densities from none
        // to all of the lanes above 0, with -0, NaN, +inf and tiny values among them. (On a
        // processor without AVX-512 both are the same loop.)
        fn check<const N: usize>(seed: u64) {
            let mut next = uniform(seed);
            for density in [0.0, 0.05, 0.4, 0.5, 0.9, 1.0] {
                for round in 0..20 {
                    let mut x = [0.0f32; N];
                    for (i, v) in x.iter_mut().enumerate() {
                        let r = next();
                        *v = if r < density { (next() * 1.2) as f32 } else { -(next() as f32) };
                        if round == 0 {
                            *v = [*v, -0.0, f32::NAN, f32::INFINITY, 1e-30, 1.0][i % 6];
                        }
                    }
                    for e in [25.6, 0.5, 3.3e-3, 127.5, 8.0, 0.0] {
                        let (mut packed, mut plain) = ([7.0f32; N], [7.0f32; N]);
                        pow_f32_chunk_packed(&x, e, &mut packed);
                        pow_f32_chunk(&x, e, &mut plain, N);
                        for i in 0..N {
                            assert_eq!(packed[i].to_bits(), plain[i].to_bits(), "N = {N}, x = {}, e = {e}", x[i]);
                        }
                    }
                }
            }
        }
        check::<16>(0x1357_9bdf_2468_ace0);
        check::<64>(0x2468_ace0_1357_9bdf);
        check::<128>(0x9bdf_1357_ace0_2468);
        check::<64>(0x0f1e_2d3c_4b5a_6978);
    }
}
