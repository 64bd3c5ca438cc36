//! The lighting equation (OpenGL 2.1, section 2.14.1) and its worked calculation.

pub mod breakdown;
pub mod explain;
pub mod lighting;
pub mod validate;
