//! The scalar abstraction: one lighting engine, run in `f32` (as OpenGL does) or `f64`.
//!
//! [`Real`] is implemented for `f32` and `f64`. Each carries its glam vector and matrix
//! types ([`glam::Vec3`]/[`glam::Mat3`] and [`glam::DVec3`]/[`glam::DMat3`]) behind the
//! [`Vec3Ops`] trait, so the lighting code is written once and monomorphised twice.

use std::fmt::{Debug, Display};
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

use glam::{DMat3, DVec3};

/// The precision an engine computes in: f32 as OpenGL does, or f64 (what the app shows by
/// default, and the reference).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Precision {
    /// Single precision, as OpenGL computes.
    F32,
    /// Double precision.
    #[default]
    F64,
}

impl Precision {
    /// `f32` or `f64`.
    pub fn label(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

/// A floating-point scalar the engine can run in: `f32` or `f64`.
pub trait Real:
    Copy
    + Debug
    + Display
    + Default
    + PartialOrd
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
{
    /// The 3-vector of this precision.
    type V3: Vec3Ops<Self>;
    /// The 3x3 matrix of this precision.
    type M3: Copy + Debug + Send + Sync + Mul<Self::V3, Output = Self::V3>;

    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// +infinity.
    const INFINITY: Self;
    /// "f32" or "f64".
    const NAME: &'static str;

    /// Rounds an `f64` to this precision.
    fn from_f64(v: f64) -> Self;
    /// Widens to `f64` (exact).
    fn to_f64(self) -> f64;
    /// Square root.
    fn sqrt(self) -> Self;
    /// The engine's exact power: [`crate::numerics::exact_pow::pow_f32`] (computed in f64, rounded once)
    /// for f32, the C library's `pow` for f64.
    fn pow_exact(self, e: Self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// IEEE maxNum: `max(NaN, x) = x`.
    fn max(self, o: Self) -> Self;
    /// IEEE minNum.
    fn min(self, o: Self) -> Self;
    /// Neither infinite nor NaN.
    fn is_finite(self) -> bool;
    /// NaN.
    fn is_nan(self) -> bool;
    /// Converts a glam `DMat3` to this precision.
    fn m3_from_dmat3(m: DMat3) -> Self::M3;
    /// For a finite `m > 0`, the power of two `2^-floor(log2 m)`: multiplying by it is
    /// exact and brings `m` into [1, 2) (scaling a vector before squaring its components).
    fn inverse_pow2_scale(m: Self) -> Self;
    /// `1 / inverse_pow2_scale(m)`, exactly (a power of two, so dividing by the scale and
    /// multiplying by this give the same correctly rounded result), from the bits of `m`:
    /// no division.
    fn pow2_scale_inverse(m: Self) -> Self;
}

/// The vector operations the engine needs, on glam's `Vec3` or `DVec3`.
pub trait Vec3Ops<S>:
    Copy
    + Debug
    + Default
    + PartialEq
    + Send
    + Sync
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<S, Output = Self>
    + Mul<Self, Output = Self>
    + Div<S, Output = Self>
{
    /// (0, 0, 0).
    const ZERO: Self;
    /// Builds a vector.
    fn new(x: S, y: S, z: S) -> Self;
    /// x component.
    fn x(self) -> S;
    /// y component.
    fn y(self) -> S;
    /// z component.
    fn z(self) -> S;
    /// Dot product.
    fn dot(self, o: Self) -> S;
    /// Rounds a `DVec3` to this precision.
    fn from_dvec3(v: DVec3) -> Self;
    /// Widens to `DVec3` (exact).
    fn to_dvec3(self) -> DVec3;
    /// Largest absolute component (NaN-ignoring).
    fn max_abs(self) -> S;
}

macro_rules! impl_real {
    (@pow f32, $x:expr, $e:expr) => {
        crate::numerics::exact_pow::pow_f32($x, $e)
    };
    (@pow f64, $x:expr, $e:expr) => {
        crate::numerics::elementary::pow($x, $e)
    };
    // 2^(bias - e) for the biased exponent e of m: biased exponent 2 bias - e, or the
    // subnormal 2^-(bias) when that is 0 (m in the top binade). Branch-free.
    (@scale f32, $m:expr) => {{
        let e = ($m.to_bits() >> 23) & 0xff;
        let normal = (254u32.wrapping_sub(e)) << 23;
        f32::from_bits(if e >= 254 { 1 << 22 } else { normal })
    }};
    (@scale f64, $m:expr) => {{
        let e = ($m.to_bits() >> 52) & 0x7ff;
        let normal = (2046u64.wrapping_sub(e)) << 52;
        f64::from_bits(if e >= 2046 { 1 << 51 } else { normal })
    }};
    // 2^(e - bias): `m` with its mantissa cleared, or the subnormal 2^-(bias) for e = 0.
    (@unscale f32, $m:expr) => {{
        let b = $m.to_bits();
        f32::from_bits(if b & 0x7f80_0000 == 0 { 1 << 22 } else { b & 0x7f80_0000 })
    }};
    (@unscale f64, $m:expr) => {{
        let b = $m.to_bits();
        let e = b & 0x7ff0_0000_0000_0000;
        f64::from_bits(if e == 0 { 1 << 51 } else { e })
    }};
    ($t:ident, $v3:ty, $m3:ty, $name:literal) => {
        impl Real for $t {
            type V3 = $v3;
            type M3 = $m3;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const INFINITY: Self = <$t>::INFINITY;
            const NAME: &'static str = $name;
            #[inline(always)]
            fn from_f64(v: f64) -> Self {
                v as $t
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            #[inline(always)]
            fn pow_exact(self, e: Self) -> Self {
                impl_real!(@pow $t, self, e)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                <$t>::max(self, o)
            }
            #[inline(always)]
            fn min(self, o: Self) -> Self {
                <$t>::min(self, o)
            }
            #[inline(always)]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }
            #[inline(always)]
            fn is_nan(self) -> bool {
                <$t>::is_nan(self)
            }
            #[inline(always)]
            fn inverse_pow2_scale(m: Self) -> Self {
                impl_real!(@scale $t, m)
            }
            #[inline(always)]
            fn pow2_scale_inverse(m: Self) -> Self {
                impl_real!(@unscale $t, m)
            }
            #[inline(always)]
            fn m3_from_dmat3(m: DMat3) -> Self::M3 {
                <$m3>::from_cols(
                    <$v3 as Vec3Ops<$t>>::from_dvec3(m.x_axis),
                    <$v3 as Vec3Ops<$t>>::from_dvec3(m.y_axis),
                    <$v3 as Vec3Ops<$t>>::from_dvec3(m.z_axis),
                )
            }
        }

        impl Vec3Ops<$t> for $v3 {
            const ZERO: Self = <$v3>::ZERO;
            #[inline(always)]
            fn new(x: $t, y: $t, z: $t) -> Self {
                <$v3>::new(x, y, z)
            }
            #[inline(always)]
            fn x(self) -> $t {
                self.x
            }
            #[inline(always)]
            fn y(self) -> $t {
                self.y
            }
            #[inline(always)]
            fn z(self) -> $t {
                self.z
            }
            #[inline(always)]
            fn dot(self, o: Self) -> $t {
                <$v3>::dot(self, o)
            }
            #[inline(always)]
            fn from_dvec3(v: DVec3) -> Self {
                <$v3>::new(v.x as $t, v.y as $t, v.z as $t)
            }
            #[inline(always)]
            fn to_dvec3(self) -> DVec3 {
                DVec3::new(self.x as f64, self.y as f64, self.z as f64)
            }
            #[inline(always)]
            fn max_abs(self) -> $t {
                self.x.abs().max(self.y.abs()).max(self.z.abs())
            }
        }
    };
}

impl_real!(f32, glam::Vec3, glam::Mat3, "f32");
impl_real!(f64, glam::DVec3, glam::DMat3, "f64");
