//! The CPU renderer and the shaded view's setup.

pub mod reference;
pub mod render;
pub mod shaded;
