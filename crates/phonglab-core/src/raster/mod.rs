//! Meshes and the CPU renderer, and the shaded view's setup.

pub mod mesh;
pub mod render;
pub mod shaded;
