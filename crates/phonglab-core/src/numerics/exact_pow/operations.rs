//! The exact power's operations, written once: the scalar steps every copy runs.

/// `a * b + c` rounded twice, the product first: the polynomials' step. Not the fused
/// multiply-add (one rounding): WebAssembly has no such instruction, and its exact
/// emulation (`numerics::fused`) made the page's per-pixel Phong 3.7 times the same
/// arithmetic built natively; rounded twice, the page's Phong takes half the time, every
/// target still gives the same bits (Rust never fuses a product and a sum on its own), and
/// the desktop's takes 13-16 % more (docs/performance.md, "In the browser"). The error it
/// adds, a few 2^-53, is far below the polynomials' own (2e-12 and 1e-13).
#[inline(always)]
fn fma(a: f64, b: f64, c: f64) -> f64 {
    a * b + c
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
    // 1 + f2/3 + f2^2/5 + ... + f2^6/13 by Estrin's scheme: pairs first, then pairs of
    // pairs, so the longest chain is 4 steps instead of Horner's 6 (the loop is bound by
    // latency, not by the number of operations).
    let f2 = f * f;
    let f4 = f2 * f2;
    let f8 = f4 * f4;
    let a = fma(f2, 1.0 / 3.0, 1.0);
    let b = fma(f2, 1.0 / 7.0, 1.0 / 5.0);
    let c = fma(f2, 1.0 / 11.0, 1.0 / 9.0);
    let series = fma(f8, fma(f4, 1.0 / 13.0, c), fma(f4, b, a));
    fma(f * (2.0 / std::f64::consts::LN_2), series, k)
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
    // The Taylor series to y^10/10! by Estrin's scheme (longest chain 4 steps, not 10):
    // every coefficient a constant 1/k!, folded when compiled.
    let y2 = y * y;
    let y4 = y2 * y2;
    let y8 = y4 * y4;
    let a0 = 1.0 + y;
    let a1 = fma(y, 1.0 / 6.0, 1.0 / 2.0);
    let a2 = fma(y, 1.0 / 120.0, 1.0 / 24.0);
    let a3 = fma(y, 1.0 / 5040.0, 1.0 / 720.0);
    let a4 = fma(y2, 1.0 / 3628800.0, fma(y, 1.0 / 362880.0, 1.0 / 40320.0));
    let p = fma(y8, a4, fma(y4, fma(y2, a3, a2), fma(y2, a1, a0)));
    let scale = f64::from_bits(((ni + 1023) as u64) << 52);
    let r = p * scale;
    let r = if t < -1022.0 { 0.0 } else { r };
    if t > 1023.0 { f64::INFINITY } else { r }
}

/// [`super::pow_f32`]'s operations (written once; `copies` compiles them for wider vectors).
#[inline(always)]
pub fn pow_f32_body(x: f32, e: f32) -> f32 {
    let r = match whole_exponent(e) {
        Some(k) => powi_f64(x as f64, k),
        None => pow_core(x as f64, e as f64),
    };
    pow_fix(x, e, r as f32)
}

/// `e` as a whole number from 1 to 128 (`None` for any other exponent): the exponents
/// [`super::pow_f32`] raises to by binary exponentiation.
#[inline(always)]
pub fn whole_exponent(e: f32) -> Option<u32> {
    ((1.0..=128.0).contains(&e) && e.fract() == 0.0).then_some(e as u32)
}

/// `x^k` by right-to-left binary exponentiation: for each bit of `k` from the lowest, the
/// result is multiplied by `b` where the bit is set, and `b = x^(2^j)` squared. Each of the
/// at most 2 log2(k) roundings adds 2^-53 relative, doubled by each later squaring: under
/// `k` x 2^-53 in all. [`pow_f32_chunk`] does these operations in this order.
#[inline(always)]
fn powi_f64(x: f64, k: u32) -> f64 {
    let (mut r, mut b, mut k) = (1.0, x, k);
    loop {
        if k & 1 == 1 {
            r *= b;
        }
        k >>= 1;
        if k == 0 {
            return r;
        }
        b *= b;
    }
}

/// `out[i] = pow_f32(max(x[i], 0), e)` for `i < n`, bit for bit, over a chunk: the way is
/// chosen once for the chunk, and a whole exponent's multiplications are done one bit at a
/// time over the whole array (each a loop that vectorises), in `powi_f64`'s order.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // index loops over parallel arrays vectorise
pub fn pow_f32_chunk<const N: usize>(x: &[f32; N], e: f32, out: &mut [f32; N], n: usize) {
    let n = n.min(N);
    match whole_exponent(e) {
        Some(k) => {
            let mut r = [1.0f64; N];
            let mut b = [0.0f64; N];
            for i in 0..n {
                b[i] = x[i].max(0.0) as f64;
            }
            let mut k = k;
            loop {
                if k & 1 == 1 {
                    for i in 0..n {
                        r[i] *= b[i];
                    }
                }
                k >>= 1;
                if k == 0 {
                    break;
                }
                for i in 0..n {
                    b[i] *= b[i];
                }
            }
            for i in 0..n {
                out[i] = pow_fix(x[i].max(0.0), e, r[i] as f32);
            }
        }
        None => {
            // By blocks of 8 (one vector of f64): a block where no x is above 0 is all
            // +0 for e > 0 (what pow_fix gives for 0, -0 and NaN, which max makes 0), and
            // skips the logarithm and the exponential. A lit surface's far side (or a
            // caller that zeroes the lanes whose power nobody reads) has many such blocks.
            let mut i = 0;
            while i + 8 <= n {
                let (xs, os) = (&x[i..i + 8], &mut out[i..i + 8]);
                if e > 0.0 && !xs.iter().fold(false, |any, &v| any | (v > 0.0)) {
                    os.fill(0.0);
                } else {
                    for (o, &v) in os.iter_mut().zip(xs) {
                        *o = pow_fractional(v, e);
                    }
                }
                i += 8;
            }
            for k in i..n {
                out[k] = pow_fractional(x[k], e);
            }
        }
    }
}

/// One lane of the array powers for an exponent that is not whole:
/// `pow_f32(max(x, 0), e)` by [`pow_core`] (what [`pow_f32_body`] does for such `e`).
#[inline(always)]
pub(super) fn pow_fractional(x: f32, e: f32) -> f32 {
    let x = x.max(0.0);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::uniform;

    #[test]
    fn whole_exponents_are_the_ones_from_1_to_128() {
        assert_eq!(whole_exponent(8.0), Some(8));
        assert_eq!(whole_exponent(128.0), Some(128));
        assert_eq!(whole_exponent(1.0), Some(1));
        for e in [0.0, 25.6, 0.5, 128.5, 129.0, -2.0, f32::NAN, f32::INFINITY] {
            assert_eq!(whole_exponent(e), None, "{e}");
        }
    }

    #[test]
    fn a_whole_exponent_is_raised_by_squarings_and_rounds_correctly() {
        // Against the f64 library pow (rounded once, for the f32 results; in f64 for the
        // error before rounding, over the f32 range): the squarings' error is some 5e-15
        // (bound k 2^-53), exp2(e log2 x)'s some 6e-11, ten thousand times larger.
        let mut next = uniform(0x9e37_79b9_7f4a_7c15);
        let (mut off, mut worst, mut worst_by_logs) = (0, 0.0f64, 0.0f64);
        for i in 0..100_000 {
            let x = if i % 2 == 0 { 1.0 - next().powi(3) } else { next() * 2.0 } as f32;
            let k = 1 + (next() * 128.0) as u32 % 128;
            let exact = crate::numerics::elementary::pow(x as f64, k as f64);
            if !(f32::MIN_POSITIVE as f64..f32::MAX as f64).contains(&exact) {
                continue;
            }
            off += usize::from(pow_f32_body(x, k as f32) != exact as f32);
            worst = worst.max((powi_f64(x as f64, k) / exact - 1.0).abs());
            worst_by_logs = worst_by_logs.max((pow_core(x as f64, k as f64) / exact - 1.0).abs());
        }
        assert_eq!(off, 0, "results not correctly rounded");
        assert!(worst < 1.5e-14, "squarings: {worst:e}");
        assert!(worst_by_logs > 1000.0 * worst, "the general way is less accurate: {worst_by_logs:e} vs {worst:e}");
        assert_eq!(powi_f64(3.0, 5), 243.0);
        assert_eq!(powi_f64(0.5, 128), 2f64.powi(-128));
        assert_eq!(pow_f32_body(0.5, 8.0), 1.0 / 256.0);
        assert_eq!(pow_f32_body(0.0, 8.0), 0.0);
        assert_eq!(pow_f32_body(f32::INFINITY, 8.0), f32::INFINITY);
        assert_eq!(pow_f32_body(1e-30, 8.0), 0.0, "underflows f32 as it should");
        assert_eq!(pow_f32_body(1e10, 8.0), f32::INFINITY, "overflows f32 as it should");
        assert!(pow_f32_body(-0.5, 2.0).is_nan(), "a negative base stays NaN, as for any exponent");
        assert!(pow_f32_body(f32::NAN, 8.0).is_nan());
    }

    #[test]
    fn the_chunk_power_is_pow_f32_bit_for_bit() {
        let mut next = uniform(0x2545_f491_4f6c_dd1d);
        let mut x = [0.0f32; 64];
        for (i, v) in x.iter_mut().enumerate() {
            *v = match i {
                0 => 0.0,
                1 => -0.0,
                2 => -0.3,
                3 => f32::NAN,
                4 => f32::INFINITY,
                5 => 1.0,
                6 => 1e-30,
                // Blocks of 8 with nothing above 0 (the skipped ones), one with a single
                // positive lane last, and one of NaN and -0.
                16..24 => -(next() as f32),
                24..31 => -1.0,
                31 => 0.25,
                32..40 => [f32::NAN, -0.0][i % 2],
                _ => (next() * 1.2) as f32,
            };
        }
        for e in [0.0, 1.0, 2.0, 8.0, 25.6, 32.0, 0.5, 127.0, 128.0, 3.3e-3] {
            let mut out = [7.0f32; 64];
            pow_f32_chunk(&x, e, &mut out, 60);
            for i in 0..60 {
                let want = pow_f32_body(x[i].max(0.0), e);
                assert_eq!(out[i].to_bits(), want.to_bits(), "x = {}, e = {e}", x[i]);
            }
            assert_eq!(out[60..], [7.0; 4], "only the first n are written");
        }
    }
}
