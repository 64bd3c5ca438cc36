//! What a scene asks of the equation: the [`Key`] the specialised evaluator is built from,
//! and, in words, which effects it computes and which it skips and why.
//!
//! Mesa's fixed-function vertex program generator builds a state key and emits only the
//! instructions it needs; phonglab does the same with a plan of array stages
//! ([`crate::specialised`]). The key changes only when an effect switches on or off (a
//! light becomes positional, attenuation leaves (1, 0, 0), a cutoff leaves 180,
//! shininess reaches 0...), never when a value merely moves, so a slider move does not
//! re-plan.

use std::fmt;

use crate::lighting::EvalOptions;
use crate::pow::PowFn;
use crate::rules::{Rules, SpecularModel};
use crate::scene::{NormalMode, Scene};
use crate::transform::NormalMatrix;

/// One light's part of the key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightKey {
    /// w != 0: L, d and (with a local viewer or Phong) H vary per vertex.
    pub positional: bool,
    /// Attenuation other than (1, 0, 0), on a positional light.
    pub attenuated: bool,
    /// Cutoff other than 180.
    pub spot: bool,
    /// light specular x material specular is non-zero on some side.
    pub specular: bool,
}

/// Everything that decides which terms the equation has for a scene.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Key {
    /// Per enabled light.
    pub lights: Vec<LightKey>,
    /// A local viewer: V = normalize(-P).
    pub local_viewer: bool,
    /// V varies per vertex: a local viewer, or the worksheet's infinite viewer
    /// (0, 0, -sign(P.z)).
    pub per_vertex_view: bool,
    /// Back colours are computed too.
    pub two_sided: bool,
    /// Specular goes to the secondary colour.
    pub separate_specular: bool,
    /// Normal handling.
    pub normals: NormalMode,
    /// The modelview's 3x3 part preserves lengths (rescaling is then a no-op).
    pub preserves_lengths: bool,
    /// Rule set and specular model.
    pub rules: Rules,
    /// The power function.
    pub pow: PowFn,
    /// Shininess 0 per side (`max(cos, 0)^0 = 1`: no power to take).
    pub shininess_zero: [bool; 2],
    /// Emission and scene ambient are both absent (the sum starts at 0).
    pub scene_color_zero: bool,
}

impl Key {
    /// The key of `scene` under `options`.
    pub fn of(scene: &Scene, options: EvalOptions) -> Key {
        let back = scene.back();
        let spec_nonzero = |l: &crate::Light| {
            [&scene.material, back].iter().any(|m| (0..3).any(|i| m.specular[i] * l.specular[i] != 0.0))
        };
        let nm = NormalMatrix::new(&scene.eye_from_object());
        let rules = scene.rules;
        let scene_color_zero = [&scene.material, back].iter().all(|m| {
            let e = if rules.emission() { m.emission.truncate() } else { glam::DVec3::ZERO };
            let a = if rules.scene_ambient() {
                m.ambient.truncate() * scene.light_model.ambient.truncate()
            } else {
                glam::DVec3::ZERO
            };
            e == glam::DVec3::ZERO && a == glam::DVec3::ZERO
        });
        Key {
            lights: scene
                .lights
                .iter()
                .map(|l| LightKey {
                    // In eye space, as the engine decides (the placement can change w).
                    positional: !scene.light_is_directional(l),
                    attenuated: !scene.light_is_directional(l) && l.is_attenuated(),
                    spot: l.is_spot(),
                    specular: spec_nonzero(l),
                })
                .collect(),
            local_viewer: scene.light_model.local_viewer,
            per_vertex_view: scene.light_model.local_viewer || rules.viewer_from_eye_plane(),
            two_sided: scene.light_model.two_sided,
            separate_specular: scene.light_model.separate_specular,
            normals: scene.normal_mode,
            preserves_lengths: nm.orthonormal,
            rules,
            pow: options.pow,
            shininess_zero: [scene.material.shininess == 0.0, back.shininess == 0.0],
            scene_color_zero,
        }
    }

    /// Does light `i` need a per-vertex H (Blinn-Phong) or R (Phong)?
    pub fn per_vertex_halfway(&self, i: usize) -> bool {
        let l = &self.lights[i];
        match self.rules.specular {
            SpecularModel::BlinnPhong => l.positional || self.per_vertex_view,
            SpecularModel::Phong => true,
        }
    }
}

/// An effect of the equation, and whether the specialised evaluator computes it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Effect {
    /// The light it belongs to (`None`: the vertex).
    pub light: Option<usize>,
    /// What, e.g. "attenuation".
    pub name: &'static str,
    /// Computed (true) or skipped (false).
    pub on: bool,
    /// Why, e.g. "the light is directional".
    pub why: String,
}

impl fmt::Display for Effect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let who = self.light.map(|i| format!("light {i} ")).unwrap_or_default();
        write!(f, "{who}{}: {}, {}", self.name, if self.on { "computed" } else { "skipped" }, self.why)
    }
}

impl Effect {
    /// The step of the worked calculation this effect decides (for showing a skipped step
    /// greyed with its reason).
    pub fn step_kind(&self) -> Option<crate::explain::StepKind> {
        use crate::explain::StepKind as K;
        Some(match self.name {
            "normalisation" => K::Normal,
            "view vector V" => K::V,
            "light vector L and distance d" => K::Distance,
            "attenuation" => K::Attenuation,
            "spotlight" => K::Spot,
            "halfway vector H" => K::H,
            "reflection vector R" => K::R,
            "specular power" => K::Specular,
            _ => return None,
        })
    }
}

impl Key {
    /// Every effect with whether it is computed and why, lights in order.
    pub fn effects(&self) -> Vec<Effect> {
        let e = |light, name, on, why: &str| Effect { light, name, on, why: why.to_string() };
        let mut out = vec![
            match self.normals {
                NormalMode::AsIs => e(None, "normalisation", false, "GL_NORMALIZE and GL_RESCALE_NORMAL are off"),
                NormalMode::Normalize => e(None, "normalisation", true, "GL_NORMALIZE is on"),
                NormalMode::Rescale if self.preserves_lengths => e(
                    None,
                    "normalisation",
                    false,
                    "GL_RESCALE_NORMAL is on but the modelview preserves lengths (factor 1)",
                ),
                NormalMode::Rescale => e(None, "normalisation", true, "GL_RESCALE_NORMAL is on"),
            },
            if self.local_viewer {
                e(None, "view vector V", true, "local viewer: V = normalize(-P) per vertex")
            } else if self.per_vertex_view {
                e(
                    None,
                    "view vector V",
                    true,
                    "the worksheet's V = normalize(obs - P), obs = P (1, 1, 0, 1): (0, 0, -sign(P.z)) per vertex",
                )
            } else {
                e(None, "view vector V", false, "infinite viewer: V = (0, 0, 1) for every vertex")
            },
            if self.scene_color_zero {
                e(None, "emission and scene ambient", false, "both are zero (or the rule set leaves them out)")
            } else {
                e(None, "emission and scene ambient", true, "folded into one constant per side")
            },
            if self.two_sided {
                e(None, "back side", true, "two-sided lighting: -n and the back material")
            } else {
                e(None, "back side", false, "one-sided lighting: the back colour is the front's")
            },
        ];
        for (i, l) in self.lights.iter().enumerate() {
            let li = Some(i);
            out.push(if l.positional {
                e(li, "light vector L and distance d", true, "positional light: per vertex")
            } else {
                e(
                    li,
                    "light vector L and distance d",
                    false,
                    "the light is directional: L is one constant, there is no d",
                )
            });
            out.push(match (l.positional, l.attenuated) {
                (false, _) => e(li, "attenuation", false, "the light is directional"),
                (true, false) => e(li, "attenuation", false, "factors (1, 0, 0) give 1"),
                (true, true) => e(li, "attenuation", true, "1/(k0 + k1 d + k2 d^2) per vertex"),
            });
            out.push(if l.spot {
                e(li, "spotlight", true, "cone test and exponent per vertex")
            } else {
                e(li, "spotlight", false, "cutoff 180: not a spotlight")
            });
            let model = match self.rules.specular {
                SpecularModel::BlinnPhong => "halfway vector H",
                SpecularModel::Phong => "reflection vector R",
            };
            out.push(if !l.specular {
                e(li, model, false, "light specular x material specular is zero")
            } else if self.per_vertex_halfway(i) {
                e(li, model, true, "per vertex")
            } else {
                e(li, model, false, "directional light and infinite viewer: H = normalize(L + V) is one constant")
            });
            out.push(if !l.specular {
                e(li, "specular power", false, "no specular term")
            } else if self.shininess_zero.iter().all(|z| *z) {
                e(li, "specular power", false, "shininess 0: max(cos, 0)^0 = 1")
            } else {
                e(li, "specular power", true, "max(cos, 0)^shininess per vertex")
            });
        }
        out
    }
}
