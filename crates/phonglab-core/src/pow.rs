//! The power function of the specular and spot terms: exact, as llvmpipe computes it, or Schlick's.
//!
//! `max(cos, 0)^e` with `e` up to 128 is the worst-conditioned step of the equation: a
//! relative error `r` in the cosine, or an absolute error `a` in `log2(cos)`, becomes
//! `e * r` (or `e * a * ln 2`) in the result. Which `pow` a renderer uses is therefore
//! visible at the fifth digit, and phonglab lets you choose:
//!
//! | [`PowFn`] | what | error |
//! |---|---|---|
//! | `Exact` | the C library's `pow` (`powf`/`pow`) | < 1 ulp |
//! | `Llvmpipe` | Mesa llvmpipe's `exp2(e * log2(x))` with gallivm's minimax polynomials | up to 1e-5 relative (e near 128) |
//! | `Schlick` | Schlick's rational `x / (e - e x + x)` (1994) | large away from x = 1; shape only |
//!
//! `Llvmpipe` reproduces Mesa 22.3 llvmpipe bit for bit on 540 probes
//! (`tests/data/mesa_pow_probes.json`): `log2(x) = exponent + y P4(y^2)` with
//! `y = (m - 1)/(m + 1)` for the mantissa `m` in [1, 2), `exp2(t) = 2^floor(t) P5(frac(t))`,
//! each polynomial evaluated as even and odd halves with fused multiply-adds, in f32.
//! It is why Mesa's lit colours differ from the exact ones by up to 1.2e-5.

use crate::real::Real;

/// Which power function the specular and spot terms use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PowFn {
    /// The correctly rounded library `pow` (the default).
    #[default]
    Exact,
    /// Mesa llvmpipe's `exp2(e log2 x)` approximation, in f32, bit-exact.
    Llvmpipe,
    /// Schlick's rational approximation `x / (e - e x + x)`.
    Schlick,
}

impl PowFn {
    /// Every choice, in menu order.
    pub const ALL: [PowFn; 3] = [PowFn::Exact, PowFn::Llvmpipe, PowFn::Schlick];

    /// A short name for menus and files.
    pub fn label(self) -> &'static str {
        match self {
            PowFn::Exact => "exact pow",
            PowFn::Llvmpipe => "llvmpipe exp2(e log2 x)",
            PowFn::Schlick => "Schlick x/(e-ex+x)",
        }
    }

    /// `x^e` for `x >= 0` (the engine passes `max(cos, 0)`), with `0^0 = 1` in every mode.
    #[inline]
    pub fn pow<S: Real>(self, x: S, e: S) -> S {
        match self {
            PowFn::Exact => x.pow_exact(e),
            PowFn::Llvmpipe => {
                if e == S::ZERO {
                    // Mesa's fixed-function key special-cases shininess 0: 0^0 = 1.
                    S::ONE
                } else {
                    S::from_f64(llvmpipe_pow(x.to_f64() as f32, e.to_f64() as f32) as f64)
                }
            }
            PowFn::Schlick => {
                if e == S::ZERO {
                    S::ONE
                } else {
                    let d = e - e * x + x;
                    if d == S::ZERO { S::ZERO } else { x / d }
                }
            }
        }
    }
}

/// 2^52 + 2^51: adding it to a double below 2^51 in magnitude rounds to an integer held
/// in the low mantissa bits (the classic magic-number conversion, vectorisable where a
/// packed double-to-int64 conversion is not).
const MAGIC: f64 = 6_755_399_441_055_744.0;

/// `log2(x)` for finite `x > 0`, absolute error < 2e-12: `x = m 2^k` with m in
/// [sqrt(1/2), sqrt(2)), `log2(m) = (2/ln 2) atanh(f)`, `f = (m - 1)/(m + 1)`, by its series
/// to f^13 (|f| < 0.172). No branches and no integer-to-float conversion, so loops over it
/// vectorise.
#[inline(always)]
fn log2_f64(x: f64) -> f64 {
    let bits = x.to_bits();
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    // The biased exponent as a double: 2^52 + e, minus 2^52.
    let e = f64::from_bits(0x4330_0000_0000_0000 | ((bits >> 52) & 0x7ff)) - 4_503_599_627_370_496.0;
    let big = m > std::f64::consts::SQRT_2;
    let m = if big { m * 0.5 } else { m };
    let k = e - 1023.0 + if big { 1.0 } else { 0.0 };
    let f = (m - 1.0) / (m + 1.0);
    let f2 = f * f;
    let series = 1.0
        + f2 * (1.0 / 3.0
            + f2 * (1.0 / 5.0 + f2 * (1.0 / 7.0 + f2 * (1.0 / 9.0 + f2 * (1.0 / 11.0 + f2 * (1.0 / 13.0))))));
    k + f * series * (2.0 / std::f64::consts::LN_2)
}

/// `2^t`, relative error < 1e-13: `t = n + r`, |r| <= 1/2, `e^(r ln 2)` by its Taylor series
/// to degree 10, scaled by 2^n through the exponent bits; 0 below 2^-1022, +inf above 2^1024.
#[inline(always)]
fn exp2_f64(t: f64) -> f64 {
    let tc = t.clamp(-1022.0, 1023.0);
    let shifted = tc + MAGIC;
    let n = shifted - MAGIC; // tc rounded to an integer
    let ni = shifted.to_bits().wrapping_sub(MAGIC.to_bits()) as i64; // the same integer
    let y = (tc - n) * std::f64::consts::LN_2;
    let p = 1.0
        + y * (1.0
            + y * (1.0 / 2.0
                + y * (1.0 / 6.0
                    + y * (1.0 / 24.0
                        + y * (1.0 / 120.0
                            + y * (1.0 / 720.0
                                + y * (1.0 / 5040.0 + y * (1.0 / 40320.0 + y * (1.0 / 362880.0 + y / 3628800.0)))))))));
    let scale = f64::from_bits(((ni + 1023) as u64) << 52);
    let r = p * scale;
    let r = if t < -1022.0 { 0.0 } else { r };
    if t > 1023.0 { f64::INFINITY } else { r }
}

/// `x^e` in f32 for `x >= 0` (or NaN), computed in f64 and rounded once: the error before
/// rounding is ~1e-10 relative, so the result is the correctly rounded one except within
/// 1e-10 of a rounding tie. `0^0 = 1`, `0^e = 0` and `inf^e = inf` for e > 0, NaN in gives
/// NaN, a negative `x` gives NaN. No branches (only selects), so loops over it vectorise;
/// the specialised kernels and the general engine both call it, so they agree bit for bit.
#[inline(always)]
pub fn pow_f32(x: f32, e: f32) -> f32 {
    pow_fix(x, e, pow_core(x as f64, e as f64) as f32)
}

/// The general case of [`pow_f32`], in f64: `2^(e log2 x)`.
#[inline(always)]
fn pow_core(xd: f64, ed: f64) -> f64 {
    exp2_f64(ed * log2_f64(xd))
}

/// [`pow_f32`]'s special cases, by selects over the general result `r`.
#[inline(always)]
fn pow_fix(x: f32, e: f32, r: f32) -> f32 {
    let r = if x == f32::INFINITY { if e > 0.0 { f32::INFINITY } else { 0.0 } } else { r };
    let r = if x == 0.0 { if e > 0.0 { 0.0 } else { f32::INFINITY } } else { r };
    let r = if x < 0.0 || x.is_nan() || e.is_nan() { f32::NAN } else { r };
    if e == 0.0 { 1.0 } else { r }
}

/// gallivm's `lp_build_log2_polynomial`, LOG_POLY_DEGREE 4, as the doubles gallivm
/// lists them (it rounds them to f32 when it builds the constant vector, as [`f32s`] does).
const LOG2_POLY: [f32; 5] = f32s([
    2.885_390_093_433_091_8,
    0.961_791_550_404_184_2,
    0.577_440_339_438_736_4,
    0.403_343_858_251_329_9,
    0.406_718_052_498_846_25,
]);

/// gallivm's `lp_build_exp2_polynomial`, EXP_POLY_DEGREE 5 (c0 = 1).
const EXP2_POLY: [f32; 6] = f32s([
    1.0,
    0.693_153_073_200_169,
    0.240_153_617_044_375_4,
    0.055_826_318_053_295_67,
    0.008_989_340_090_494_664,
    0.001_877_576_675_191_479,
]);

/// Rounds each coefficient to f32.
const fn f32s<const N: usize>(c: [f64; N]) -> [f32; N] {
    let mut out = [0.0f32; N];
    let mut i = 0;
    while i < N {
        out[i] = c[i] as f32;
        i += 1;
    }
    out
}

/// `lp_build_polynomial`: even and odd powers separately, fused multiply-adds.
#[inline]
fn gallivm_polynomial(x: f32, c: &[f32]) -> f32 {
    let x2 = x * x;
    let mut even: Option<f32> = None;
    let mut odd: Option<f32> = None;
    for i in (0..c.len()).rev() {
        let slot = if i % 2 == 0 { &mut even } else { &mut odd };
        *slot = Some(match *slot {
            Some(v) => v.mul_add(x2, c[i]),
            None => c[i],
        });
    }
    match (odd, even) {
        (Some(o), Some(e)) => o.mul_add(x, e),
        (None, Some(e)) => e,
        (Some(o), None) => o * x,
        (None, None) => 0.0,
    }
}

/// `lp_build_log2_approx`: exponent plus `y P(y^2)`, `y = (m - 1)/(m + 1)`, m in [1, 2).
#[inline]
fn llvmpipe_log2(x: f32) -> f32 {
    let bits = x.to_bits();
    let logexp = (((bits & 0x7f80_0000) >> 23) as i32 - 127) as f32;
    let mant = f32::from_bits((bits & 0x007f_ffff) | 1.0f32.to_bits());
    let y = (mant - 1.0) / (mant + 1.0);
    let z = y * y;
    y.mul_add(gallivm_polynomial(z, &LOG2_POLY), logexp)
}

/// `lp_build_exp2`: clamp to [-126.99999, 128], `2^floor(t)` from the exponent bits,
/// times `P(t - floor(t))`.
#[inline]
fn llvmpipe_exp2(t: f32) -> f32 {
    let t = t.clamp(-126.99999, 128.0);
    let ipart = t.floor();
    let fpart = t - ipart;
    let expipart = f32::from_bits((((ipart as i32) + 127) as u32) << 23);
    expipart * gallivm_polynomial(fpart, &EXP2_POLY)
}

/// llvmpipe's `pow(x, e) = exp2(log2(x) * e)`, 0 where x = 0 (gallivm's select).
pub fn llvmpipe_pow(x: f32, e: f32) -> f32 {
    if x == 0.0 {
        return 0.0;
    }
    llvmpipe_exp2(llvmpipe_log2(x) * e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_to_the_zero_is_one_in_every_mode() {
        for p in PowFn::ALL {
            assert_eq!(p.pow(0.0f32, 0.0), 1.0, "{p:?}");
            assert_eq!(p.pow(0.0f64, 0.0), 1.0, "{p:?}");
            assert_eq!(p.pow(1.0f32, 77.0), 1.0, "{p:?}");
        }
        assert_eq!(PowFn::Llvmpipe.pow(0.0f32, 0.001), 0.0);
    }

    #[test]
    fn llvmpipe_pow_is_close_but_not_exact() {
        let x = 0.999_998_4f32;
        let e = 124.0f32;
        let exact = (x as f64).powf(e as f64);
        let approx = llvmpipe_pow(x, e) as f64;
        let rel = (approx / exact - 1.0).abs();
        assert!(rel > 1e-6 && rel < 2e-5, "{rel}");
    }

    #[test]
    fn pow_f32_is_correctly_rounded() {
        // Against f64 pow rounded once, over the engine's domain: x in [0, 4], e in [0, 128].
        let mut worst = 0u32;
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for i in 0..200_000 {
            let x = if i % 3 == 0 { 1.0 - next().powi(4) } else { next() * 4.0 } as f32;
            let e = (next() * 128.0) as f32;
            let want = (x as f64).powf(e as f64) as f32;
            let got = pow_f32(x, e);
            let ulps = (want.to_bits() as i64 - got.to_bits() as i64).unsigned_abs() as u32;
            worst = worst.max(ulps);
        }
        assert!(worst <= 1, "{worst} ulps");
        assert_eq!(pow_f32(0.0, 0.0), 1.0);
        assert_eq!(pow_f32(0.0, 3.0), 0.0);
        assert_eq!(pow_f32(1.0, 128.0), 1.0);
        assert_eq!(pow_f32(f32::INFINITY, 2.0), f32::INFINITY);
        assert_eq!(pow_f32(1e-30, 128.0), 0.0);
        assert_eq!(pow_f32(3.0, 128.0), f32::INFINITY);
        assert!(pow_f32(f32::NAN, 2.0).is_nan());
        assert_eq!(pow_f32(0.5, 0.0), 1.0);
    }

    #[test]
    fn schlick_matches_at_the_ends() {
        assert_eq!(PowFn::Schlick.pow(1.0f64, 50.0), 1.0);
        assert_eq!(PowFn::Schlick.pow(0.0f64, 50.0), 0.0);
        let mid = PowFn::Schlick.pow(0.9f64, 10.0);
        assert!(mid > 0.3 && mid < 0.6, "{mid}");
    }
}
