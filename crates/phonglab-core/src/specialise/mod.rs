//! Only the stages a scene needs, run over arrays: the engine that runs the plan's stage
//! list (`equation::plan`), its ways in, and the plan in words.

pub mod batch;
pub mod copies;
pub mod effects;
pub mod lighter;
pub mod slipped;
