//! The plan in words: every effect of the equation, whether the specialised evaluator
//! computes it for this scene and why ("attenuation: skipped, the light is directional"),
//! read off the compiled program so it is true of what runs. The calculation panel lists
//! them; the compiler itself ([`crate::equation::plan`]) holds no prose.

use std::fmt;

use crate::equation::plan::*;
use crate::model::rules::SpecularVector;
use crate::model::scene::{LightId, NormalMode, Side};
use crate::specialise::lighter::CHUNK;

/// An effect of the equation, and whether the specialised evaluator computes it: read off
/// the compiled [`Program`], so it is true of what runs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Effect {
    /// Which effect.
    pub kind: EffectKind,
    /// The light it belongs to (`None`: the vertex).
    pub light: Option<usize>,
    /// What, e.g. "attenuation" (in the current language).
    pub name: String,
    /// Computed (true) or skipped (false).
    pub on: bool,
    /// Why, e.g. "the light is directional".
    pub why: String,
    /// The specular vector (decides whether H or R is meant).
    vector: SpecularVector,
}

impl fmt::Display for Effect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let who = self.light.map(|i| format!("light {i} ")).unwrap_or_default();
        write!(f, "{who}{}: {}, {}", self.name, if self.on { "computed" } else { "skipped" }, self.why)
    }
}

impl Effect {
    /// The step of the worked calculation this effect decides.
    pub fn step_kind(&self) -> Option<crate::equation::explain::StepKind> {
        self.kind.step_kind(self.vector)
    }
}

impl EffectKind {
    /// The step of the worked calculation this effect decides (for showing a skipped
    /// step greyed with its reason).
    pub fn step_kind(self, vector: SpecularVector) -> Option<crate::equation::explain::StepKind> {
        use crate::equation::explain::StepKind as K;
        Some(match self {
            EffectKind::Normalisation => K::Normal,
            EffectKind::Position => K::Position,
            EffectKind::ViewVector => K::V,
            EffectKind::LightVector => K::Distance,
            EffectKind::Attenuation => K::Attenuation,
            EffectKind::Spotlight => K::Spot,
            EffectKind::HalfwayOrReflection => match vector {
                SpecularVector::Halfway => K::H,
                SpecularVector::Reflection => K::R,
            },
            EffectKind::SpecularPower => K::Specular,
            EffectKind::SceneColor | EffectKind::BackSide => return None,
        })
    }
}

impl Key {
    /// Every effect with whether the program for object-space vertices runs it and why,
    /// lights in order.
    pub fn effects(&self) -> Vec<Effect> {
        self.effects_of(&self.program())
    }

    /// Every effect with whether `program` runs it and why.
    pub fn effects_of(&self, program: &Program) -> Vec<Effect> {
        let vector = self.rules.specular.vector();
        let e = |kind: EffectKind, light, on: bool, why: String| Effect {
            kind,
            light,
            name: kind.name(vector),
            on,
            why,
            vector,
        };
        let has = |s: Stage| program.has(s);
        let normalised = has(Stage::NormalizeNormal) || has(Stage::RescaleNormal) || has(Stage::NormalizeNormalFast);
        let mut out = vec![
            e(
                EffectKind::Normalisation,
                None,
                normalised,
                match (self.normals, normalised) {
                    (NormalMode::AsIs, false) => crate::t!("why-normalise-off"),
                    (NormalMode::Rescale, false) => {
                        crate::t!("why-rescale-one")
                    }
                    (NormalMode::Normalize, _) => crate::t!("why-normalize-on"),
                    (NormalMode::Rescale, true) => crate::t!("why-rescale-on"),
                    (NormalMode::AsIs, true) => crate::t!("why-renormalised"),
                },
            ),
            match (has(Stage::TransformPosition), has(Stage::TransformPositionProjective), self.needs_positions()) {
                _ if has(Stage::TranslatePosition) => {
                    e(EffectKind::Position, None, true, crate::t!("why-position-translation"))
                }
                (true, _, _) => e(EffectKind::Position, None, true, crate::t!("why-position-affine")),
                (_, true, _) => e(EffectKind::Position, None, true, crate::t!("why-position-projective")),
                (false, false, true) => e(EffectKind::Position, None, false, crate::t!("why-position-eye")),
                (false, false, false) => e(EffectKind::Position, None, false, crate::t!("why-position-unread")),
            },
            match program.stages.iter().find_map(|s| match s {
                Stage::ViewVector(viewer) => Some(*viewer),
                _ => None,
            }) {
                Some(Viewer::Local) => e(EffectKind::ViewVector, None, true, crate::t!("why-v-local", chunk = CHUNK)),
                Some(Viewer::EyePlane) => e(EffectKind::ViewVector, None, true, crate::t!("why-v-worksheet")),
                Some(Viewer::Infinite) | None => e(EffectKind::ViewVector, None, false, crate::t!("why-v-infinite")),
            },
            if has(Stage::SceneColor) {
                e(EffectKind::SceneColor, None, true, crate::t!("why-scene-added"))
            } else {
                e(EffectKind::SceneColor, None, false, crate::t!("why-scene-zero"))
            },
            if program.stages.iter().any(|s| s.side() == Some(Side::Back)) {
                e(EffectKind::BackSide, None, true, crate::t!("why-two-sided"))
            } else {
                e(EffectKind::BackSide, None, false, crate::t!("why-one-sided"))
            },
        ];
        for (i, l) in LightId::all(self.lights.len()).zip(&self.lights) {
            let li = Some(i.index());
            out.push(if has(Stage::LightVector(i)) {
                e(EffectKind::LightVector, li, true, crate::t!("why-l-positional", chunk = CHUNK))
            } else {
                e(EffectKind::LightVector, li, false, crate::t!("why-l-directional"))
            });
            out.push(match (has(Stage::Attenuate(i)), l.positional) {
                (true, _) => e(EffectKind::Attenuation, li, true, crate::t!("why-attenuation-on")),
                (false, false) => e(EffectKind::Attenuation, li, false, crate::t!("why-attenuation-directional")),
                (false, true) => e(EffectKind::Attenuation, li, false, crate::t!("why-attenuation-one")),
            });
            out.push(match (has(Stage::SpotCone(i)), l.spot) {
                (true, _) => e(EffectKind::Spotlight, li, true, crate::t!("why-spot-on")),
                (false, true) => e(EffectKind::Spotlight, li, false, crate::t!("why-spot-directional")),
                (false, false) => e(EffectKind::Spotlight, li, false, crate::t!("why-spot-none")),
            });
            out.push(if has(Stage::Halfway(i)) || has(Stage::Reflect(i)) {
                e(EffectKind::HalfwayOrReflection, li, true, crate::t!("why-per-vertex"))
            } else if has(Stage::HalfwayConstant(i)) {
                e(EffectKind::HalfwayOrReflection, li, false, crate::t!("why-h-constant"))
            } else {
                e(EffectKind::HalfwayOrReflection, li, false, crate::t!("why-specular-zero"))
            });
            out.push(if program.stages.iter().any(|s| matches!(s, Stage::Power(j, _) if *j == i)) {
                e(EffectKind::SpecularPower, li, true, crate::t!("why-power-on"))
            } else if !l.specular {
                e(EffectKind::SpecularPower, li, false, crate::t!("why-power-none"))
            } else {
                e(EffectKind::SpecularPower, li, false, crate::t!("why-power-zero"))
            });
        }
        out
    }
}
