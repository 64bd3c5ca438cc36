//! Only the stages a scene needs: the key, the stage list compiled from it, and the engine that runs it.

pub mod batch;
pub mod copies;
pub mod effects;
pub mod lighter;
pub mod plan;
