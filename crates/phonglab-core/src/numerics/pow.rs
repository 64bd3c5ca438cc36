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

use crate::numerics::real::Real;

/// Which power function the specular and spot terms use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
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
    pub fn label(self) -> String {
        match self {
            PowFn::Exact => crate::t!("pow-exact"),
            PowFn::Llvmpipe => "llvmpipe exp2(e log2 x)".into(),
            PowFn::Schlick => "Schlick x/(e-ex+x)".into(),
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

pub use crate::numerics::exact_pow::pow_f32;

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
        let exact = crate::numerics::elementary::pow(x as f64, e as f64);
        let approx = llvmpipe_pow(x, e) as f64;
        let rel = (approx / exact - 1.0).abs();
        assert!(rel > 1e-6 && rel < 2e-5, "{rel}");
    }

    #[test]
    fn pow_f32_is_correctly_rounded() {
        // Against f64 pow rounded once, over the engine's domain: x in [0, 4], e in [0, 128].
        let mut worst = 0u32;
        let mut next = crate::test_support::uniform(0x2545_f491_4f6c_dd1d);
        for i in 0..200_000 {
            let x = if i % 3 == 0 { 1.0 - next().powi(4) } else { next() * 4.0 } as f32;
            let e = (next() * 128.0) as f32;
            let want = crate::numerics::elementary::pow(x as f64, e as f64) as f32;
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
