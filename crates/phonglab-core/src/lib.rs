//! phonglab-core: OpenGL 2.1 fixed-function vertex lighting, evaluated step by step.
//!
//! The pure core of phonglab (no UI, no file system): a [`Scene`] describes the lighting
//! state; an [`Engine`] built from it lights vertices in `f32` or `f64` and returns a
//! [`VertexLighting`] breakdown with every intermediate value and the [`Limit`]s it chose
//! where a value was undefined.
//!
//! ```
//! use phonglab_core::{presets, Engine};
//! let scene = presets::worksheet(5);
//! let lit = Engine::<f64>::light_scene_vertex(&scene).unwrap();
//! assert!((lit.front.primary[0] - 0.05958709).abs() < 1e-7);
//! ```

pub mod breakdown;
pub mod camera;
pub mod cost;
pub mod document;
pub mod error;
pub mod explain;
pub mod glref;
pub mod lighting;
pub mod materials;
pub mod mesh;
pub mod plan;
pub mod pow;
pub mod presets;
pub mod real;
pub mod render;
pub mod robust;
pub mod rules;
pub mod scene;
pub mod specialised;
pub mod transform;
pub mod validate;
pub mod view;

pub use breakdown::{LightTerms, Limit, Limits, SideColor, SideTerms, SpotTerms, VertexLighting};
pub use camera::CameraSpec;
pub use document::{Document, DocumentError};
pub use error::SceneError;
pub use lighting::{Engine, EvalOptions, Renormalize};
pub use pow::PowFn;
pub use real::{Real, Vec3Ops};
pub use rules::{NormalTransform, RuleSet, Rules, SpecularGate, SpecularModel};
pub use scene::{Light, LightModel, LightPlacement, MAX_LIGHTS, Material, NormalMode, Rgba, Scene, Vertex};
pub use view::{FlatNormal, Framing, LightingSpace, ObjectKind, ShadedSetup, Shading, View, ViewCamera};
