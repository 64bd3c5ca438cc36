//! Where floating point needs care: compensated sums, scaled lengths, zero-safe products, the powers.

pub mod copies;
pub mod elementary;
pub mod exact_pow;
pub mod fused;
pub mod pow;
pub mod real;
pub mod robust;
pub mod strict;
pub mod typed_number;
