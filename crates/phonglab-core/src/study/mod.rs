//! What accuracy costs in time and in error; the benchmark scene timed.

pub mod bench;
pub mod check;
pub mod cost;
pub mod difference;
