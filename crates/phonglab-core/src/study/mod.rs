//! What accuracy costs in time and in error.

pub mod cost;
