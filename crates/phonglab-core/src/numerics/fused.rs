//! Error-free transforms without a fused multiply-add, for the processor that has none
//! (WebAssembly): the exact dot products' product error by Dekker's method, and Knuth's
//! TwoSum, both branch-free, so loops over them still vectorise and the page gives the
//! desktop's bits (`robust::two_prod` takes the fused instruction elsewhere).
//!
//! (Until 2026-11-29 this module also emulated the fused multiply-add itself, rounding to
//! odd, for the exact power's polynomials; they now round each product and sum, which the
//! page runs at the desktop's pace: docs/performance.md, "In the browser".)

/// Error-free sum: `a + b = s + e` exactly (Knuth's TwoSum).
#[inline(always)]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a * b - p` exactly, for `p = a * b` rounded (Dekker 1971, with Veltkamp's split: each
/// factor as two halves of 26 bits, whose products are exact).
#[inline(always)]
pub fn dekker_error(a: f64, b: f64, p: f64) -> f64 {
    /// 2^27 + 1.
    const SPLIT: f64 = 134_217_729.0;
    let split = |x: f64| {
        let t = SPLIT * x;
        let hi = t - (t - x);
        (hi, x - hi)
    };
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random doubles of random magnitude and sign (an xorshift generator).
    fn values(n: usize, mut seed: u64) -> Vec<f64> {
        (0..n)
            .map(|_| {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                let mantissa = (seed >> 12) as f64 / (1u64 << 52) as f64 + 1.0;
                let exponent = ((seed >> 3) % 120) as i32 - 60;
                let sign = if seed & 1 == 0 { 1.0 } else { -1.0 };
                sign * mantissa * 2f64.powi(exponent)
            })
            .collect()
    }

    #[test]
    fn dekkers_product_error_is_the_fused_instructions() {
        for t in values(2 * 400_000, 0x9e37_79b9_7f4a_7c15).chunks(2) {
            let (a, b) = (t[0], t[1]);
            let p = a * b;
            assert_eq!(dekker_error(a, b, p).to_bits(), a.mul_add(b, -p).to_bits(), "{a:e} {b:e}");
        }
    }

    /// `x` as an integer number of units of 2^`unit`, where it is one.
    fn in_units(x: f64, unit: i32) -> i128 {
        let scaled = x * 2f64.powi(-unit);
        assert_eq!(scaled.fract(), 0.0, "{x:e} is a whole number of 2^{unit}");
        scaled as i128
    }

    #[test]
    fn two_sum_is_exact() {
        // s + e = a + b, checked in integers: every value below is a whole number of units
        // of the smaller operand's last place, and no more than 2^120 of them.
        let mut inexact = 0;
        for t in values(2 * 200_000, 7).chunks(2) {
            let (a, b) = (t[0], t[1]);
            let unit = a.abs().min(b.abs()).log2().floor() as i32 - 52;
            if (a.abs().max(b.abs()).log2() as i32 - unit) > 110 {
                continue;
            }
            let (s, e) = two_sum(a, b);
            assert_eq!(s, a + b);
            let exact = in_units(a, unit) + in_units(b, unit);
            assert_eq!(in_units(s, unit) + in_units(e, unit), exact, "{a:e} {b:e}");
            inexact += usize::from(e != 0.0);
        }
        assert!(inexact > 100_000, "the pairs are ones whose sum rounds: {inexact}");
    }
}
