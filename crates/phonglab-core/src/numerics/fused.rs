//! The fused multiply-add, `a * b + c` rounded once, where the processor has no such
//! instruction (WebAssembly): emulated exactly, without branches, so that loops over it
//! still vectorise and every target gives the same bits. Elsewhere it is `f64::mul_add`.
//!
//! The emulation is Boldo and Melquiond's (*Emulation of FMA and correctly rounded sums:
//! proved algorithms using rounding to odd*, IEEE Trans. Computers 57(4), 2008, algorithm
//! 5.4): `a b = uh + ul` and `c + uh = th + tl` exactly (error-free transforms), then
//! `RN(th + RO(tl + ul))`, where RO rounds to odd. Exact for finite operands whose
//! products and sums neither overflow nor underflow (the polynomials it serves run on
//! values near 1).

/// `a * b + c` rounded once.
#[inline(always)]
pub fn mul_add(a: f64, b: f64, c: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        emulated(a, b, c)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        a.mul_add(b, c)
    }
}

/// `a * b + c` rounded once, with no fused instruction (see the module's documentation).
#[inline(always)]
pub fn emulated(a: f64, b: f64, c: f64) -> f64 {
    let uh = a * b;
    let ul = dekker_error(a, b, uh);
    let (th, tl) = two_sum(c, uh);
    th + add_round_to_odd(tl, ul)
}

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

/// `x + y` rounded to odd: exact when it is representable, else the one of the two
/// neighbours whose last bit is 1. From the sum rounded to nearest and its error: the
/// neighbour towards zero is the rounded sum when the error has its sign, else the rounded
/// sum one unit in the last place towards zero; then its last bit is set.
#[inline(always)]
fn add_round_to_odd(x: f64, y: f64) -> f64 {
    let (s, e) = two_sum(x, y);
    let bits = s.to_bits();
    let towards_zero = if (bits ^ e.to_bits()) >> 63 == 0 { bits } else { bits.wrapping_sub(1) };
    if e == 0.0 { s } else { f64::from_bits(towards_zero | 1) }
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
    fn the_emulation_gives_the_fused_instructions_bits() {
        let v = values(3 * 400_000, 0x9e37_79b9_7f4a_7c15);
        let mut near_ties = 0;
        for t in v.chunks(3) {
            let (a, b, c) = (t[0], t[1], t[2]);
            let fused = a.mul_add(b, c);
            assert_eq!(emulated(a, b, c).to_bits(), fused.to_bits(), "{a:e} {b:e} {c:e}");
            near_ties += usize::from((a * b + c).to_bits() != fused.to_bits());
        }
        // Cancelling cases, where the unfused form is far off; and Dekker's product error,
        // which the error-free product takes where there is no fused instruction.
        for t in v.chunks(2) {
            let (a, b) = (t[0], t[1]);
            let p = a * b;
            let dekker = dekker_error(a, b, p);
            assert_eq!(dekker.to_bits(), a.mul_add(b, -p).to_bits(), "{a:e} {b:e}");
            let c = -(a * b);
            assert_eq!(emulated(a, b, c).to_bits(), a.mul_add(b, c).to_bits(), "{a:e} {b:e}");
            let c = -(a * b) * (1.0 + f64::EPSILON);
            assert_eq!(emulated(a, b, c).to_bits(), a.mul_add(b, c).to_bits(), "{a:e} {b:e}");
        }
        // The polynomials' own: near 1, constants of every kind.
        for t in values(2 * 100_000, 7).chunks(2) {
            let (y, k) = (t[0].fract() * 0.5, 1.0 / (1.0 + t[1].abs()));
            assert_eq!(emulated(y, k, 0.5).to_bits(), y.mul_add(k, 0.5).to_bits(), "{y:e} {k:e}");
        }
        assert!(near_ties > 1000, "the test is one where rounding twice differs: {near_ties}");
    }
}
