//! The CPU renderer and the shaded view's setup.

pub mod render;
pub mod shaded;
