//! The elementary functions, one implementation on every platform: sines, cosines, powers,
//! exponentials and logarithms from the `libm` crate (Rust's port of musl and FreeBSD's
//! msun), so that whatever phonglab writes or compares bit for bit is the same bytes on
//! Linux, Windows, macOS and in a browser.
//!
//! Rust's `f64::sin`, `cos`, `powf`, `exp`, `ln` call the C library of the platform, and those
//! differ in the last bit: mingw's `cos` is the x87 `fcos` instruction (cos(π/2) =
//! 6.1230317e-17 where the true value is 6.1232340e-17), its `pow` goes through x87 too.
//! glam's rotations call the same functions; the core turns on glam's `libm` feature so
//! that they come from here as well. `f64::powi` is a compiler built-in whose algorithm
//! Rust does not promise: [`powi`] is written out.
//!
//! The fused multiply-add is special: inside the copies compiled for FMA it is one
//! instruction, exactly rounded by definition, and must stay one. Elsewhere LLVM calls the
//! C library's `fma`, which on glibc is exactly rounded but on mingw rounds twice (through
//! x87's 80 bits), and mingw's `fmaf` (`f32::mul_add`) is not fused at all. On Windows
//! with the GNU toolchain this module defines that `fma` and `fmaf` itself (the linker takes
//! them before mingw's), as the `libm` crate's, which are exactly rounded (and the
//! instruction where the processor has it). [`fma`] is the same, callable.

use glam::{DMat4, DVec4};

/// sin x.
#[inline]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// cos x.
#[inline]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// (sin x, cos x).
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

/// tan x.
#[inline]
pub fn tan(x: f64) -> f64 {
    libm::tan(x)
}

/// atan(y / x), in the quadrant of (x, y).
#[inline]
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// sin x, in single precision.
#[inline]
pub fn sin_f32(x: f32) -> f32 {
    libm::sinf(x)
}

/// x^y (C's `pow`: < 1 ulp).
#[inline]
pub fn pow(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// e^x.
#[inline]
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// The natural logarithm.
#[inline]
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

/// `x * y + z` rounded once.
#[inline]
pub fn fma(x: f64, y: f64, z: f64) -> f64 {
    libm::fma(x, y, z)
}

/// x^n by squarings, the order of compiler-builtins' and GCC's `__powidf2` (so today's
/// results stay the same), written out so that every platform multiplies in that order (and
/// LLVM cannot fold a constant one with the C library's `pow`): a negative `n` is the
/// reciprocal of x^|n|.
#[inline]
pub fn powi(x: f64, n: i32) -> f64 {
    let mut base = x;
    let mut k = n.unsigned_abs();
    let mut r = 1.0;
    loop {
        if k & 1 == 1 {
            r *= base;
        }
        k >>= 1;
        if k == 0 {
            break;
        }
        base *= base;
    }
    if n < 0 { 1.0 / r } else { r }
}

/// A turn by `angle` radians about x: glam's `DMat4::from_rotation_x`, with this module's
/// sine and cosine.
pub fn rotation_x(angle: f64) -> DMat4 {
    let (s, c) = sin_cos(angle);
    DMat4::from_cols(DVec4::X, DVec4::new(0.0, c, s, 0.0), DVec4::new(0.0, -s, c, 0.0), DVec4::W)
}

/// A turn by `angle` radians about y: glam's `DMat4::from_rotation_y`, with this module's
/// sine and cosine.
pub fn rotation_y(angle: f64) -> DMat4 {
    let (s, c) = sin_cos(angle);
    DMat4::from_cols(DVec4::new(c, 0.0, -s, 0.0), DVec4::Y, DVec4::new(s, 0.0, c, 0.0), DVec4::W)
}

/// A turn by `angle` radians about z: glam's `DMat4::from_rotation_z`, with this module's
/// sine and cosine.
pub fn rotation_z(angle: f64) -> DMat4 {
    let (s, c) = sin_cos(angle);
    DMat4::from_cols(DVec4::new(c, s, 0.0, 0.0), DVec4::new(-s, c, 0.0, 0.0), DVec4::Z, DVec4::W)
}

/// The C library's `fma`, which LLVM calls for `f64::mul_add` outside the FMA copies,
/// defined here where mingw's would round twice (see the module's documentation).
#[cfg(all(windows, target_env = "gnu"))]
#[unsafe(export_name = "fma")]
pub extern "C" fn fma_for_mingw(x: f64, y: f64, z: f64) -> f64 {
    libm::fma(x, y, z)
}

/// The C library's `fmaf`, which LLVM calls for `f32::mul_add` outside the FMA copies (the
/// llvmpipe `pow` model's polynomials), defined here where mingw's does not give the fused
/// result (under Wine, 258 of 540 of Mesa's `pow` probes off by an ulp or more, and the
/// specialised lighters apart from the general engine).
#[cfg(all(windows, target_env = "gnu"))]
#[unsafe(export_name = "fmaf")]
pub extern "C" fn fmaf_for_mingw(x: f32, y: f32, z: f32) -> f32 {
    libm::fmaf(x, y, z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cosine_of_a_right_angle_is_the_true_value_rounded() {
        // cos(π/2 rounded) = π/2 - fl(π/2) = 6.123233995736766e-17 (mingw's x87 gives
        // 6.1230317691118863e-17).
        assert_eq!(cos(std::f64::consts::FRAC_PI_2), 6.123233995736766e-17);
        assert_eq!(sin_cos(std::f64::consts::FRAC_PI_2), (1.0, 6.123233995736766e-17));
        assert_eq!(sin(std::f64::consts::PI), 1.2246467991473532e-16);
    }

    #[test]
    fn the_turns_are_glams_with_these_cosines() {
        // Away from the angles where two libraries could round differently, the same
        // matrices as glam's.
        for a in [0.3, -1.2, 2.5] {
            assert!(rotation_x(a).abs_diff_eq(DMat4::from_rotation_x(a), 1e-15));
            assert!(rotation_y(a).abs_diff_eq(DMat4::from_rotation_y(a), 1e-15));
            assert!(rotation_z(a).abs_diff_eq(DMat4::from_rotation_z(a), 1e-15));
        }
        // A quarter turn about x takes y to z, up to cos(π/2 rounded), the true value.
        let m = rotation_x(std::f64::consts::FRAC_PI_2);
        assert_eq!(m.y_axis, DVec4::new(0.0, 6.123233995736766e-17, 1.0, 0.0));
    }

    #[test]
    fn powi_multiplies_in_the_built_in_order() {
        // Linux's built-in (compiler-builtins); mingw's gives 0.5 * 10^-8 = 5.000000000000004e-9.
        #[cfg(not(windows))]
        for (x, n) in [(10.0f64, -3), (10.0, 7), (0.1, 5), (1.1, 33), (3.0, -17), (2.0, -1074), (7.5, 0)] {
            // (black_box: LLVM folds a constant powi with the C library's pow.)
            let built_in = std::hint::black_box(x).powi(std::hint::black_box(n));
            assert_eq!(powi(x, n).to_bits(), built_in.to_bits(), "{x}^{n}");
        }
        assert_eq!(powi(10.0, -3), 0.001);
        assert_eq!(0.5 * powi(10.0, -8), 5e-9);
        assert_eq!(powi(0.1, 5).to_bits(), 4532020583610935540);
        assert_eq!(powi(2.0, 10), 1024.0);
    }

    #[test]
    fn fma_rounds_once() {
        // (1 + 2^-30)^2 - 1 = 2^-29 + 2^-60: the product rounded first loses the 2^-60.
        let a = 1.0 + 2f64.powi(-30);
        assert_eq!(fma(a, a, -1.0), 2f64.powi(-29) + 2f64.powi(-60));
        assert_eq!(a * a - 1.0, 2f64.powi(-29));
        // The library call behind mul_add (mingw's replaced on Windows) rounds once too.
        assert_eq!(std::hint::black_box(a).mul_add(a, -1.0), fma(a, a, -1.0));
    }
}
