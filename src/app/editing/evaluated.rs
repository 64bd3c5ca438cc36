//! What the panels draw, computed from a document: its colours, vectors and worked
//! calculation in the chosen precision. Kept apart from the app state so that panels
//! which only draw ([`crate::app::panels::compare`], [`crate::app::panels::result`]...) need nothing else.

use glam::DVec3;
use phonglab_core::breakdown::VertexLighting;
use phonglab_core::explain::{Side, explain};
use phonglab_core::{Document, Engine, EvalOptions, Limit, PowFn, Real, SceneError, Vec3Ops};

/// Engine precision shown in the app: the core's.
pub use phonglab_core::Precision;

/// How the document is evaluated and explained: the engine's precision, its power
/// function, and the side the worked calculation explains.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Settings {
    /// Engine precision (f64 by default).
    pub precision: Precision,
    /// The power function.
    pub pow: PowFn,
    /// Which side the calculation explains.
    pub side: Side,
}

/// The colours of one side, as f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SideColors {
    /// Primary, unclamped.
    pub primary: [f64; 4],
    /// Secondary, unclamped.
    pub secondary: [f64; 4],
    /// The colour sum clamped to [0, 1] (what a fixed-function fragment shows).
    pub shown: [f64; 4],
}

/// One light's vectors for the plot, in eye space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightVectors {
    /// GL_LIGHTi.
    pub index: usize,
    /// L (zero when undefined).
    pub l: DVec3,
    /// H (zero when undefined).
    pub h: DVec3,
    /// R (zero when undefined).
    pub r: DVec3,
    /// The spot axis when a spotlight.
    pub spot: Option<DVec3>,
}

/// Everything the panels draw, computed once per frame from the document.
#[derive(Clone, Debug)]
pub struct Evaluated {
    /// Front side colours.
    pub front: SideColors,
    /// Back side colours (two-sided lighting only).
    pub back: Option<SideColors>,
    /// The worked calculation of the chosen side.
    pub explanation: phonglab_core::explain::Explanation,
    /// N as used (front side).
    pub n: DVec3,
    /// V.
    pub v: DVec3,
    /// Per light.
    pub lights: Vec<LightVectors>,
    /// Limits taken, with the light they concern.
    pub limits: Vec<(Option<usize>, Limit)>,
}

fn d3<S: Real>(v: S::V3) -> DVec3 {
    v.to_dvec3()
}

fn side_colors<S: Real>(c: &phonglab_core::SideColor<S>) -> SideColors {
    let sum = c.sum();
    SideColors {
        primary: c.primary.map(S::to_f64),
        secondary: c.secondary.map(S::to_f64),
        shown: sum.map(|x| x.to_f64().clamp(0.0, 1.0)),
    }
}

fn evaluated<S: Real>(doc: &Document, lit: &VertexLighting<S>, side: Side) -> Evaluated {
    let two_sided = doc.scene.light_model.two_sided;
    Evaluated {
        front: side_colors(&lit.front),
        back: two_sided.then(|| side_colors(&lit.back)),
        explanation: explain(&doc.scene, lit, if two_sided { side } else { Side::Front }),
        n: d3::<S>(lit.normal_in_eye),
        v: d3::<S>(lit.v),
        lights: lit
            .lights()
            .iter()
            .map(|t| LightVectors {
                index: t.index,
                l: d3::<S>(t.l),
                h: d3::<S>(t.h),
                r: d3::<S>(t.r),
                spot: t.spot.active.then(|| d3::<S>(t.spot.dir_in_eye)),
            })
            .collect(),
        limits: lit.all_limits(),
    }
}

/// Evaluates `doc` in `precision` with `pow`, explaining `side`.
pub fn evaluate(doc: &Document, precision: Precision, pow: PowFn, side: Side) -> Result<Evaluated, SceneError> {
    let options = EvalOptions::with_pow(pow);
    Ok(match precision {
        Precision::F32 => {
            evaluated(doc, &Engine::<f32>::with_options(&doc.scene, options)?.light(&doc.scene.vertex), side)
        }
        Precision::F64 => {
            evaluated(doc, &Engine::<f64>::with_options(&doc.scene, options)?.light(&doc.scene.vertex), side)
        }
    })
}
