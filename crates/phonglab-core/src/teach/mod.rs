//! For the classroom: generated exercises, the quiz's checks, and the shader a scene compiles to.

pub mod diagnose;
pub mod director;
pub mod exam;
pub mod exercise;
pub mod misconception;
pub mod moodle;
pub mod picture_match;
pub mod quiz;
pub mod shader;
