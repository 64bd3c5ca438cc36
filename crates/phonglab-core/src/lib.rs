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
//! The modules, by group, each group a directory (`src/model/`, `src/equation/`, ...).
//! The groups form one order, from the bottom up: each uses only the groups below it,
//! and inside the crate modules name each other by group (`crate::equation::lighting`);
//! `tests/all/layers.rs` fails on a path against the order. For users every module is also
//! re-exported at the crate's root, so `phonglab_core::scene` and
//! `phonglab_core::model::scene` name the same module (ARCHITECTURE.md says how data flows
//! between them):
//!
//! | rank | group | modules |
//! |---|---|---|
//! | 9 | export: the student's own code, and back | `export::notebook`, `export::pyopengl`, `export::openframeworks`, `export::read_python` |
//! | 8 | teach: for the classroom; study: what accuracy costs, the benchmark timed | [`exercise`], [`quiz`], [`shader`]; [`cost`], [`bench`](mod@bench) |
//! | 7 | raster: the CPU renderer | [`render`], [`shaded`] |
//! | 6 | specialise: the plan's stages run over arrays | [`lighter`], [`batch`] (its ways in), [`effects`] (the plan in words) |
//! | 5 | formats: text in and out, ready-made documents | [`document`], [`library`], [`glref`], [`escape`] (user text for each language written) |
//! | 4 | equation: the lighting equation, the stage list a scene compiles to, its worked calculation | [`lighting`], [`breakdown`], [`plan`] (the stage list every writer walks), [`explain`], [`validate`] |
//! | 3 | model: what is lit | [`scene`], [`rules`], [`materials`], [`camera`], [`transform`], [`view`], [`presets`], [`error`], [`vocabulary`] (the worksheet's names, once) |
//! | 2 | mesh: the objects | [`mesh`] (`sphere`, `cylinder`, `teapot`, `obj`) |
//! | 1 | numerics: where floating point needs care | [`robust`], [`real`], [`exact_pow`], [`pow`], [`strict`], [`typed_number`] |
//! | 0 | locale: the user's language and decimal mark; cpu: what the processor can do, as proofs | [`locale`]; [`cpu`] |

pub mod cpu;
pub mod equation;
pub mod export;
pub mod formats;
pub mod locale;
pub mod mesh;
pub mod model;
pub mod numerics;
pub mod raster;
pub mod specialise;
pub mod study;
pub mod teach;

// Each module also at the crate's root, so paths name the module, not its group.
pub use equation::{breakdown, explain, lighting, plan, validate};
pub use formats::{document, escape, files, gift, glref, library, moodle_xml, question};
pub use model::{camera, error, materials, presets, rules, scene, transform, view, vocabulary};
pub use numerics::{exact_pow, pow, real, robust, strict, typed_number};
pub use raster::{channels, probe, probe_report, render, shaded};
pub use specialise::{batch, effects, lighter};
pub use study::{bench, cost, difference};
pub use teach::{director, exam, exercise, misconception, moodle, quiz, shader};

pub use breakdown::{LightTerms, Limit, Limits, SideColor, SideTerms, SpotTerms, VertexLighting};
pub use camera::CameraSpec;
pub use document::{Document, DocumentError};
pub use error::SceneError;
pub use lighting::{Engine, EvalOptions, Renormalize};
pub use pow::PowFn;
pub use real::{Precision, Real, Vec3Ops};
pub use rules::{NormalTransform, RuleSet, Rules, SpecularGate, SpecularModel, SpecularVector};
pub use scene::{
    ColorMaterial, ColorMaterialMode, Face, Light, LightModel, LightPlacement, MAX_LIGHTS, Material, NormalMode, Rgba,
    Scene, Vertex,
};
pub use shaded::ShadedSetup;
pub use view::{FlatNormal, Framing, LightingSpace, ObjectKind, Shading, ShadingMode, View, ViewCamera};

/// What the unit tests share.
#[cfg(test)]
pub(crate) mod test_support {
    /// A fixed sequence of 64-bit words (xorshift64): the same random cases on every run.
    pub(crate) fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        }
    }

    /// A fixed sequence of doubles in [0, 1): the top 53 bits of [`xorshift`]'s words.
    pub(crate) fn uniform(seed: u64) -> impl FnMut() -> f64 {
        let mut words = xorshift(seed);
        move || (words() >> 11) as f64 / (1u64 << 53) as f64
    }
}
