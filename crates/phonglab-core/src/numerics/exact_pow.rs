//! The engine's exact power in f32, `x^e` computed in f64 and rounded once, without
//! branches so loops over it vectorise. A numerics building block: [`crate::real::Real`]'s
//! `pow_exact` for f32 and [`crate::pow::PowFn::Exact`] both call it.

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
