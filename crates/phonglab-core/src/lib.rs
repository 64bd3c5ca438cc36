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
//!
//! The modules, by group (ARCHITECTURE.md says how data flows between them):
//!
//! | group | modules |
//! |---|---|
//! | model: what is lit | [`scene`], [`rules`], [`materials`], [`camera`], [`transform`], [`view`], [`presets`], [`library`] |
//! | equation: the lighting equation and its worked calculation | [`lighting`], [`breakdown`], [`explain`], [`validate`], [`error`] |
//! | numerics: where floating point needs care | [`robust`], [`real`], [`exact_pow`], [`pow`] |
//! | specialise: only the stages a scene needs | [`plan`], [`specialised`] |
//! | raster: meshes and the CPU renderer | [`mesh`], [`render`], [`shaded`] |
//! | formats: text in and out | [`document`], [`glref`] |
//! | study: what accuracy costs | [`cost`] |

pub mod breakdown;
pub mod camera;
pub mod cost;
pub mod document;
pub mod error;
pub mod exact_pow;
pub mod exercise;
pub mod explain;
pub mod glref;
pub mod library;
pub mod lighting;
pub mod materials;
pub mod mesh;
pub mod plan;
pub mod pow;
pub mod presets;
pub mod quiz;
pub mod real;
pub mod render;
pub mod robust;
pub mod rules;
pub mod scene;
pub mod shaded;
pub mod shader;
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
pub use shaded::ShadedSetup;
pub use view::{FlatNormal, Framing, LightingSpace, ObjectKind, Shading, View, ViewCamera};
