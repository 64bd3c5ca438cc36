//! What is lit: the lighting state, its rules, materials, transforms, the view's settings and ready-made scenes.

pub mod camera;
pub mod error;
pub mod materials;
pub mod presets;
pub mod rules;
pub mod scene;
pub mod transform;
pub mod view;
pub mod vocabulary;
