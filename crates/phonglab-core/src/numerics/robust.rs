//! Numerically robust building blocks: compensated sums, scaled lengths, zero-safe products.
//!
//! These implement docs/lighting.md's numerics policy where single precision (or even plain
//! double precision) breaks down while the answer is still well defined:
//!
//! | problem | remedy | function |
//! |---|---|---|
//! | `M * p` with `|p| ~ 1e18` and a cancelling translation | error-free products and sums (Ogita, Rump, Oishi 2005, *Accurate sum and dot product*, Dot2) | [`dot2`], [`transform_point`] |
//! | `|v|^2` underflows (`1e-25` in f32) or overflows (`1e20` in f32) | divide by the largest component before squaring | [`scaled_length`], [`normalize_or_zero`] |
//! | `0 * inf` where the infinity is an overflowed finite value or the d = 0 limit | a product is 0 when either factor is 0 | [`mul0`], [`scale0`] |

use glam::{DMat4, DVec3, DVec4};

use crate::numerics::real::{Real, Vec3Ops};

pub use crate::numerics::fused::two_sum;

/// Error-free product: `a * b = p + e` exactly (with a fused multiply-add; where there is
/// no such instruction, WebAssembly, by Dekker's product of Veltkamp's halves, exact as
/// well for |a|, |b| < 2^996 and no underflow, so the same bits).
#[inline(always)]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    #[cfg(not(target_arch = "wasm32"))]
    let e = a.mul_add(b, -p);
    #[cfg(target_arch = "wasm32")]
    let e = crate::numerics::fused::dekker_error(a, b, p);
    (p, e)
}

/// Dot product computed as if in twice the working precision, then rounded (Dot2).
///
/// The error is at most `eps*|result| + O(n^2 eps^2) * sum|x_i y_i|`: with `|x_i y_i| ~ 1e18`
/// terms cancelling to a result of order 1, the absolute error is ~1e-14, where a plain
/// f64 dot product would be off by ~100.
#[inline(always)]
pub fn dot2(x: &[f64], y: &[f64]) -> f64 {
    debug_assert_eq!(x.len(), y.len());
    if x.is_empty() {
        return 0.0;
    }
    let (mut p, mut s) = two_prod(x[0], y[0]);
    for i in 1..x.len() {
        let (h, r) = two_prod(x[i], y[i]);
        let (pp, q) = two_sum(p, h);
        p = pp;
        s += q + r;
    }
    p + s
}

/// `m * p` with each row evaluated by [`dot2`], so huge cancelling terms stay exact.
///
/// An affine `m` (last row (0, 0, 0, 1)) and a point with w = 1 give w = 1 exactly, so the
/// fourth row is not evaluated ([`transform_affine_rows`]): for finite input the same
/// result as evaluating it, and a point with an infinite coordinate keeps w = 1 instead of
/// `0 * inf = NaN`.
#[inline(always)]
pub fn transform_point(m: &DMat4, p: DVec4) -> DVec4 {
    let rows = m.transpose().to_cols_array_2d();
    if rows[3] == [0.0, 0.0, 0.0, 1.0] && p.w == 1.0 {
        let [x, y, z] = transform_affine_rows(&rows, [p.x, p.y, p.z]);
        return DVec4::new(x, y, z, 1.0);
    }
    DVec4::from_array(transform_point_rows(&rows, p.to_array()))
}

/// [`transform_point`] with the matrix given by its rows (`rows[i]` is row i), for loops
/// that transform many points by one matrix (the rows are taken out once). Written out
/// rather than with `array::map`, whose closure is not inlined into the callers' AVX2 + FMA
/// copies (Dot2's `mul_add` then becomes a library call, many times slower).
#[inline(always)]
pub fn transform_point_rows(rows: &[[f64; 4]; 4], p: [f64; 4]) -> [f64; 4] {
    [dot2(&rows[0], &p), dot2(&rows[1], &p), dot2(&rows[2], &p), dot2(&rows[3], &p)]
}

/// The first three rows of [`transform_point_rows`] for a point with w = 1: what an affine
/// matrix (last row (0, 0, 0, 1), so w = 1 exactly) leaves to compute.
#[inline(always)]
pub fn transform_affine_rows(rows: &[[f64; 4]; 4], p: [f64; 3]) -> [f64; 3] {
    let p = [p[0], p[1], p[2], 1.0];
    [dot2(&rows[0], &p), dot2(&rows[1], &p), dot2(&rows[2], &p)]
}

/// [`transform_affine_rows`] for a modelview that is a translation by `t` (its 3x3 part the
/// identity), in three additions: `P = (p + t) + 0`, or NaN in every row where a
/// coordinate of `p` is not finite and in a row whose sum overflows. The same bits (NaN
/// for NaN).
///
/// Why it is the same: in row `i`, [`dot2`]'s products are `p_i` and `t_i` exactly and
/// zeros, so its partial sum is `fl(p_i + t_i)` and its error sum is that addition's
/// rounding error `err` (the zeros add exactly); `fl(fl(p_i + t_i) + err)` is `fl(p_i + t_i)`
/// again, because `fl(p_i + t_i) + err` is the exact sum. Where the sum is 0 the error sum
/// is +0, so the row gives +0 even for `-0 + -0`: the `+ 0` does the same. A zero times an
/// infinite coordinate, an infinite coordinate's own error term (`inf - inf`) and an
/// overflowing sum's error term are NaN, and so is the row (every row multiplies every
/// coordinate, by 0 or 1).
#[inline(always)]
pub fn translate_point(t: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let finite = p[0].is_finite() & p[1].is_finite() & p[2].is_finite();
    let row = |i: usize| {
        let sum = p[i] + t[i];
        if finite & sum.is_finite() { sum + 0.0 } else { f64::NAN }
    };
    [row(0), row(1), row(2)]
}

/// The 3x3 part of `m` times `v`, each row by [`dot2`].
pub fn transform_vector3(m: &DMat4, v: DVec3) -> DVec3 {
    let va = v.to_array();
    let row = |i: usize| {
        let r = m.row(i);
        dot2(&[r.x, r.y, r.z], &va)
    };
    DVec3::new(row(0), row(1), row(2))
}

/// `(x, y, z) / |(x, y, z)|` and `|(x, y, z)|` on components, without branches (so loops of
/// it vectorise): the largest component is brought into [1, 2) by an exact power-of-two
/// scaling `s` before squaring, so neither underflow (`|v| = 1e-25`) nor overflow (`|v| =
/// 1e20` in f32, `1e200` in f64) of `|v|^2` loses the answer; then one reciprocal and three
/// multiplications (within 1 ulp, a third of the cost of three divisions). The flag says
/// whether the direction is defined (not for a zero or non-finite vector: the other
/// outputs are then meaningless). The length is `|v s| / s`, or the largest component
/// itself (0 or +inf) where the direction is undefined.
#[inline(always)]
pub fn normalize3<S: Real>(x: S, y: S, z: S) -> (S, S, S, S, bool) {
    let m = x.abs().max(y.abs()).max(z.abs());
    let ok = m != S::ZERO && m.is_finite();
    let s = S::inverse_pow2_scale(m);
    let (ux, uy, uz) = (x * s, y * s, z * s);
    let len_s = (ux * ux + uy * uy + uz * uz).sqrt();
    let inv = S::ONE / len_s;
    // len_s / s, as a product by the exact power of two 1 / s (one division fewer).
    let len = if ok { len_s * S::pow2_scale_inverse(m) } else { m };
    (ux * inv, uy * inv, uz * inv, len, ok)
}

/// The bounds of [`unscaled_is_exact`]: 2^-400 and 2^400.
const UNSCALED_MIN: f64 = 3.872_591_914_849_318e-121;
const UNSCALED_MAX: f64 = 2.582_249_878_086_908_6e120;

/// Is `x` 0, or of a magnitude from 2^-400 to 2^400? Where all three components of a
/// vector are, [`normalize3`]'s power-of-two scaling changes no rounding: every square,
/// sum, root, reciprocal and product it forms stays a normal f64 with or without it, and
/// scaling by 2^k commutes with rounding there. So [`normalize3_unscaled`] gives the same
/// bits, without the scaling's integer work.
#[inline(always)]
pub fn unscaled_is_exact(x: f64) -> bool {
    let a = x.abs();
    (a == 0.0) | ((UNSCALED_MIN..=UNSCALED_MAX).contains(&a))
}

/// [`normalize3`] in f64 without the power-of-two scaling, for vectors whose components
/// all pass [`unscaled_is_exact`]: bit for bit the same results there (for others the
/// squares may overflow or underflow; do not call it).
#[inline(always)]
pub fn normalize3_unscaled(x: f64, y: f64, z: f64) -> (f64, f64, f64, f64, bool) {
    let ok = (x != 0.0) | (y != 0.0) | (z != 0.0);
    let len = (x * x + y * y + z * z).sqrt();
    let inv = 1.0 / len;
    (x * inv, y * inv, z * inv, len, ok)
}

/// `|v|` by [`normalize3`]: 0 for the zero vector, `+inf` when a component is infinite.
#[inline(always)]
pub fn scaled_length<S: Real>(v: S::V3) -> S {
    normalize3::<S>(v.x(), v.y(), v.z()).3
}

/// `v / |v|` by [`normalize3`]; `None` for a zero or non-finite vector (the direction is
/// undefined).
#[inline(always)]
pub fn try_normalize<S: Real>(v: S::V3) -> Option<S::V3> {
    let (x, y, z, _, ok) = normalize3::<S>(v.x(), v.y(), v.z());
    ok.then(|| S::V3::new(x, y, z))
}

/// [`try_normalize`], with the zero vector for an undefined direction.
#[inline]
pub fn normalize_or_zero<S: Real>(v: S::V3) -> S::V3 {
    try_normalize::<S>(v).unwrap_or(S::V3::ZERO)
}

/// `a * b`, but 0 whenever either factor is 0 (so `0 * inf = 0`, never NaN).
///
/// Every infinity the engine can meet is either an overflowed finite value (whose product
/// with 0 is truly 0) or the attenuation limit at a zero denominator, which docs/lighting.md
/// defines as 0 where the term is 0.
#[inline(always)]
pub fn mul0<S: Real>(a: S, b: S) -> S {
    if (a == S::ZERO) | (b == S::ZERO) { S::ZERO } else { a * b }
}

/// Component-wise [`mul0`] of a vector by a scalar.
#[inline(always)]
pub fn scale0<S: Real>(v: S::V3, k: S) -> S::V3 {
    S::V3::new(mul0(v.x(), k), mul0(v.y(), k), mul0(v.z(), k))
}

/// Component-wise [`mul0`] of two vectors.
#[inline(always)]
pub fn mul0_v<S: Real>(a: S::V3, b: S::V3) -> S::V3 {
    S::V3::new(mul0(a.x(), b.x()), mul0(a.y(), b.y()), mul0(a.z(), b.z()))
}

/// `cos(deg)` with the exact values at multiples of 90 degrees (so a 90 degree spot
/// cutoff gives exactly 0, not 6e-17).
pub fn cos_deg(deg: f64) -> f64 {
    let r = deg.rem_euclid(360.0);
    if r == 0.0 {
        1.0
    } else if r == 90.0 || r == 270.0 {
        0.0
    } else if r == 180.0 {
        -1.0
    } else {
        crate::numerics::elementary::cos(deg.to_radians())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::xorshift;

    #[test]
    fn dot2_recovers_cancelled_terms() {
        // 1e18 + 3 - 1e18 in plain f64 loses the 3 (spacing at 1e18 is 128).
        let x = [1e18, 3.0, -1e18];
        let y = [1.0, 1.0, 1.0];
        assert_eq!(x.iter().sum::<f64>(), 0.0);
        assert_eq!(dot2(&x, &y), 3.0);
    }

    #[test]
    fn scaled_length_survives_underflow_and_overflow_in_f32() {
        let tiny = glam::Vec3::new(1e-25, 0.0, 1e-25);
        assert_eq!(tiny.length(), 0.0, "plain f32 underflows");
        let l = scaled_length::<f32>(tiny);
        assert!((l / 1.414_213_6e-25 - 1.0).abs() < 1e-6, "{l}");
        let huge = glam::Vec3::new(0.0, 0.0, 1e20);
        assert!(huge.length().is_infinite(), "plain f32 overflows");
        assert_eq!(scaled_length::<f32>(huge), 1e20);
        let n = normalize_or_zero::<f32>(tiny);
        assert_eq!(f32::inverse_pow2_scale(3.0), 0.5);
        assert_eq!(f32::inverse_pow2_scale(f32::MAX), 2f32.powi(-127));
        assert_eq!(f32::inverse_pow2_scale(1e-40) * 1e-40, 1e-40 * 2f32.powi(127));
        assert_eq!(f64::inverse_pow2_scale(f64::MAX), 2f64.powi(-1023));
        assert_eq!(f64::inverse_pow2_scale(0.75), 2.0);
        // The inverse scale is 1 / scale exactly, across the whole range.
        for m in [3.0f32, 1.0, 0.75, f32::MAX, 2f32.powi(127), f32::MIN_POSITIVE, 1e-40, 1e-45] {
            assert_eq!(f32::pow2_scale_inverse(m), 1.0 / f32::inverse_pow2_scale(m), "{m}");
        }
        for m in [3.0f64, 1.0, 0.75, f64::MAX, 2f64.powi(1023), f64::MIN_POSITIVE, 1e-310, 5e-324] {
            assert_eq!(f64::pow2_scale_inverse(m), 1.0 / f64::inverse_pow2_scale(m), "{m}");
        }
        assert!((n.x - std::f32::consts::FRAC_1_SQRT_2).abs() < 1e-7);
        assert_eq!(normalize_or_zero::<f32>(glam::Vec3::ZERO), glam::Vec3::ZERO);
    }

    #[test]
    fn the_length_is_the_scaled_length_divided_by_the_scale() {
        // normalize3 multiplies by the exact inverse of the scale instead of dividing by
        // it: the same correctly rounded result, over the whole exponent range.
        let mut next = xorshift(0x1234_5678_9abc_def1u64);
        for _ in 0..20_000 {
            let r = next();
            let v = [0, 1, 2]
                .map(|k| f64::from_bits((r >> (k * 3)) & 0x7fef_ffff_ffff_ffff ^ (next() & 0x800f_ffff_ffff_ffff)));
            let m = v[0].abs().max(v[1].abs()).max(v[2].abs());
            let s = f64::inverse_pow2_scale(m);
            let q = ((v[0] * s).powi(2) + (v[1] * s).powi(2) + (v[2] * s).powi(2)).sqrt();
            let len = normalize3::<f64>(v[0], v[1], v[2]).3;
            assert_eq!(len.to_bits(), (q / s).to_bits(), "{v:?}");
            let w = v.map(|x| x as f32);
            let m = w[0].abs().max(w[1].abs()).max(w[2].abs());
            if m == 0.0 || !m.is_finite() {
                continue;
            }
            let s = f32::inverse_pow2_scale(m);
            let q = ((w[0] * s) * (w[0] * s) + (w[1] * s) * (w[1] * s) + (w[2] * s) * (w[2] * s)).sqrt();
            let len = normalize3::<f32>(w[0], w[1], w[2]).3;
            assert_eq!(len.to_bits(), (q / s).to_bits(), "{w:?}");
        }
    }

    #[test]
    fn unscaled_normalisation_is_the_scaled_one_bit_for_bit_in_its_range() {
        let mut next = xorshift(0x0bad_5eed_1234_5678u64);
        let (mut tried, mut outside) = (0, 0);
        for k in 0..200_000 {
            // Exponents from 2^-420 to 2^420 (past both bounds), some components 0.
            let mut c = [0.0f64; 3];
            for v in &mut c {
                let r = next();
                let e = (r % 841) as i32 - 420;
                let m = 1.0 + (r >> 12) as f64 / (1u64 << 52) as f64;
                *v = if r.is_multiple_of(13) {
                    0.0
                } else if r.is_multiple_of(2) {
                    m * 2f64.powi(e)
                } else {
                    -m * 2f64.powi(e)
                };
            }
            if k % 3 == 0 {
                // Components of similar size, as in a scene.
                c[1] = c[0] * 0.75;
                c[2] = -c[0] * 1.25;
            }
            if !c.iter().all(|&v| unscaled_is_exact(v)) {
                outside += 1;
                continue;
            }
            tried += 1;
            let a = normalize3::<f64>(c[0], c[1], c[2]);
            let b = normalize3_unscaled(c[0], c[1], c[2]);
            assert_eq!(a.4, b.4, "{c:?}");
            if a.4 {
                let bits = |t: (f64, f64, f64, f64, bool)| [t.0, t.1, t.2, t.3].map(f64::to_bits);
                assert_eq!(bits(a), bits(b), "{c:?}");
            }
        }
        assert!(tried > 50_000 && outside > 1_000, "{tried} {outside}");
        assert!(unscaled_is_exact(0.0) && unscaled_is_exact(-2f64.powi(400)) && unscaled_is_exact(2f64.powi(-400)));
        assert!(!unscaled_is_exact(2f64.powi(401)) && !unscaled_is_exact(2f64.powi(-401)));
        assert!(!unscaled_is_exact(f64::NAN) && !unscaled_is_exact(f64::INFINITY));
    }

    #[test]
    fn a_translation_is_the_compensated_rows_bit_for_bit() {
        // Random coordinates and translations of every size, with the cases where the
        // shortcut must take care: exact cancellation to 0 (and -0 + -0), zeros of both
        // signs, infinities, NaN, and sums that overflow.
        let mut next = xorshift(0x7a45_1a7e_0000_0001u64);
        let value = |r: u64| -> f64 {
            let m = 1.0 + (r >> 12) as f64 / (1u64 << 52) as f64;
            let sign = if r.is_multiple_of(2) { 1.0 } else { -1.0 };
            match r % 23 {
                0 => 0.0,
                1 => -0.0,
                2 => f64::INFINITY * sign,
                3 => f64::NAN,
                4 => f64::MAX * sign,
                _ => sign * m * 2f64.powi((r % 61) as i32 - 30),
            }
        };
        let mut rows_by_kind = [0usize; 3];
        for k in 0..300_000 {
            let mut t = [0.0; 3];
            let mut p = [0.0; 3];
            for i in 0..3 {
                t[i] = value(next());
                // Keep the translation finite (a modelview is), and make some sums cancel.
                if !t[i].is_finite() {
                    t[i] = 1.5;
                }
                // Mostly f32 coordinates (as meshes give), some f64 ones (whose sums with a
                // translation near f64::MAX overflow).
                p[i] = match k % 5 {
                    0 => -t[i],
                    1 => value(next()),
                    _ => value(next()) as f32 as f64,
                };
            }
            let m = DMat4::from_translation(DVec3::from_array(t));
            let rows = m.transpose().to_cols_array_2d();
            let want = transform_affine_rows(&rows, p);
            let got = translate_point(t, p);
            // The same bits, or both NaN (whose payload and sign nothing reads: every
            // later step tests NaN with is_nan or lets it through a max).
            let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            assert!((0..3).all(|i| same(got[i], want[i])), "t = {t:?}, p = {p:?}: {got:?} vs {want:?}");
            for w in want {
                rows_by_kind[if w.is_nan() {
                    0
                } else if w == 0.0 {
                    1
                } else {
                    2
                }] += 1;
            }
        }
        assert!(rows_by_kind.iter().all(|&n| n > 10_000), "{rows_by_kind:?}");
        assert_eq!(translate_point([-0.0; 3], [-0.0; 3]).map(f64::to_bits), [0.0f64.to_bits(); 3]);
    }

    #[test]
    fn mul0_never_makes_nan() {
        assert_eq!(mul0(0.0f32, f32::INFINITY), 0.0);
        assert_eq!(mul0(f32::INFINITY, 0.0f32), 0.0);
        assert_eq!(mul0(-2.0f32, f32::INFINITY), f32::NEG_INFINITY);
    }

    #[test]
    fn cos_deg_is_exact_at_right_angles() {
        assert_eq!(cos_deg(90.0), 0.0);
        assert_eq!(cos_deg(0.0), 1.0);
        assert!((cos_deg(60.0) - 0.5).abs() < 1e-15);
    }
}
