//! For the classroom: generated exercises, the quiz's checks, and the shader a scene compiles to.

pub mod diagnose;
pub mod director;
pub mod exercise;
pub mod misconception;
pub mod picture_match;
pub mod quiz;
pub mod shader;
