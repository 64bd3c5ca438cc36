//! The lighting equation (OpenGL 2.1, section 2.14.1), the stage list a scene compiles to,
//! and its worked calculation.

pub mod breakdown;
pub mod explain;
pub mod lighting;
pub mod plan;
pub mod validate;
