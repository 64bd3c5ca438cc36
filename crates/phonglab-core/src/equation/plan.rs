//! What a scene asks of the equation: the [`Key`], and the [`Program`] of [`Stage`]s it
//! compiles to. Which effects it computes and which it skips, and why, in words: the
//! specialise group's `effects`.
//!
//! Mesa's fixed-function vertex program generator builds a state key and emits only the
//! instructions it needs; phonglab does the same with a plan of array stages, which the
//! specialise group's `lighter` runs over arrays and every writer (the worked calculation,
//! the shader, the exports, the quiz) walks. The key changes only when an effect switches on or off (a
//! light becomes positional, attenuation leaves (1, 0, 0), a cutoff leaves 180,
//! shininess reaches 0...), never when a value merely moves, so a slider move does not
//! re-plan.

use crate::equation::lighting::{EvalOptions, Renormalize};
use crate::model::rules::{Rules, SpecularVector};
use crate::model::scene::{ColorMaterialMode, Face, LightId, NormalMode, Scene, Side};
use crate::model::transform::NormalMatrix;
use crate::numerics::pow::PowFn;

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
    /// GL_RESCALE_NORMAL's factor is exactly 1 (a length-preserving modelview): rescaling
    /// would multiply by 1, so it is left out.
    pub rescale_is_one: bool,
    /// Rule set and specular model.
    pub rules: Rules,
    /// The power function.
    pub pow: PowFn,
    /// Shininess 0 per side (`max(cos, 0)^0 = 1`: no power to take).
    pub shininess_zero: [bool; 2],
    /// `GL_COLOR_MATERIAL`'s face and mode: which material colours are the current
    /// colour (a shader reads them from one uniform).
    pub color_material: Option<(Face, ColorMaterialMode)>,
    /// Emission and scene ambient are both absent (the sum starts at 0).
    pub scene_color_zero: bool,
    /// The modelview's last row is not (0, 0, 0, 1): w varies from vertex to vertex and
    /// P is divided by it. (With (0, 0, 0, 1), w = 1 exactly and there is nothing to divide.)
    pub projective: bool,
    /// The modelview is a translation: affine, and its 3x3 part is the identity. P is then
    /// `p + t`, three additions (the same bits as the compensated rows,
    /// [`crate::numerics::robust::translate_point`]).
    pub translation: bool,
}

impl Key {
    /// The key of `scene` under `options`.
    pub fn of(scene: &Scene, options: EvalOptions) -> Key {
        // The materials as lit: GL_COLOR_MATERIAL's current colour where it tracks.
        let (front, back) = (&scene.lit_material(Side::Front), &scene.lit_material(Side::Back));
        let spec_nonzero = |l: &crate::model::scene::Light| {
            [front, back].iter().any(|m| (0..3).any(|i| m.specular[i] * l.specular[i] != 0.0))
        };
        let eye_from_object = scene.eye_from_object();
        let affine = eye_from_object.row(3) == glam::DVec4::W;
        let nm = NormalMatrix::for_rules(&eye_from_object, scene.rules);
        let rules = scene.rules;
        let scene_color_zero = [front, back].iter().all(|m| {
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
            rescale_is_one: nm.rescale == 1.0,
            rules,
            pow: options.pow,
            shininess_zero: [front.shininess == 0.0, back.shininess == 0.0],
            color_material: scene.color_material.map(|cm| (cm.face, cm.mode)),
            scene_color_zero,
            projective: !affine,
            translation: affine && glam::DMat3::from_mat4(eye_from_object) == glam::DMat3::IDENTITY,
        }
    }

    /// Does light `i` raise a power on `side` (`Stage::Power(i, side)`): it has a specular
    /// term there and the side's shininess is not 0? The program compiles the stage exactly
    /// then, and `Sum` relies on it having run.
    pub fn has_power(&self, i: LightId, side: Side) -> bool {
        self.lights.get(i.index()).is_some_and(|l| l.specular) && !self.shininess_zero[side.index()]
    }

    /// Does light `i` need a per-vertex H (Blinn-Phong) or R (Phong)?
    pub fn per_vertex_halfway(&self, i: LightId) -> bool {
        let l = &self.lights[i.index()];
        match self.rules.specular.vector() {
            SpecularVector::Halfway => l.positional || self.per_vertex_view,
            SpecularVector::Reflection => true,
        }
    }
}

/// Where the stages' inputs come from: what the prologue of the program must do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SourceKind {
    /// Object-space vertices (w = 1): normals and positions to transform (Gouraud, the
    /// vertex panel).
    Object,
    /// Eye-space points with the normals the equation uses (Flat faces, the demo's
    /// derivative normals).
    Eye,
    /// Eye-space points with interpolated normals to renormalise as the options say
    /// (Phong fragments).
    EyeRaw(Renormalize),
}

/// Where the viewer is, as V is formed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Viewer {
    /// A local viewer (`GL_LIGHT_MODEL_LOCAL_VIEWER`): `V = normalize(-P)`.
    Local,
    /// The worksheet's infinite viewer, `V = normalize(obs - P)` with
    /// `obs = P (1, 1, 0, 1)`: `(0, 0, -sign(P.z))`.
    EyePlane,
    /// OpenGL's infinite viewer: `V = (0, 0, 1)`, one constant.
    Infinite,
}

/// What a light's specular term is on a side, as the plan compiled it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpecularTerm {
    /// None to add: the light's specular times the material's is zero (the evaluator's
    /// program leaves the term out; the worked program never does).
    Zero,
    /// `f max(cos, 0)^s_rm s_cm s_cl`.
    Plain,
    /// `f max(cos, 0)^s_rm s_cm s_cl (s_rm + 8) / (8 pi)`: energy-conserving Blinn-Phong's.
    Normalised,
}

/// One stage of the specialised program: a loop over a chunk of vertices. The list a key
/// compiles to ([`Program::compile`]) is exactly what the evaluator runs, in order, and
/// what the calculation panel reports as computed; every stage absent from it is skipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// `N = (M^-1)^T n` (or the worksheet's `M n`).
    TransformNormal,
    /// `N = f N`, GL_RESCALE_NORMAL with a factor other than exactly 1.
    RescaleNormal,
    /// `N = normalize(N)`: GL_NORMALIZE, or Phong's renormalisation of an interpolated normal.
    NormalizeNormal,
    /// `N = N rsqrt(N . N)` with the approximate reciprocal square root (the cost study).
    NormalizeNormalFast,
    /// `P = M p` (compensated, f64) with an affine modelview: three rows, w = 1 exactly,
    /// no division.
    TransformPosition,
    /// `P = M p / w` (compensated, f64) with a projective modelview: the fourth row too,
    /// and the division by w.
    TransformPositionProjective,
    /// `P = p + t` (f64) with a modelview that is a translation: three additions, the same
    /// bits as `TransformPosition`'s compensated rows.
    TranslatePosition,
    /// Which normals are zero (no direction: no diffuse, no specular).
    ZeroNormals,
    /// V: per vertex, `normalize(-P)` (a local viewer) or the worksheet's
    /// `(0, 0, -sign(P.z))`; or OpenGL's infinite viewer's (0, 0, 1), which only the worked
    /// program ([`Program::worked`]) writes out.
    ViewVector(Viewer),
    /// L and d of positional light `i` per vertex (f64, scaled before squaring).
    LightVector(LightId),
    /// L of directional light `i`: one constant (and its spot factor, one constant).
    LightConstant(LightId),
    /// `att = 1 / (k0 + k1 d + k2 d^2)` per vertex.
    Attenuate(LightId),
    /// The spot cosine `-L . s` and the cone test per vertex.
    SpotCone(LightId),
    /// The spot factor `(-L . s)^s_rl` inside the cone.
    SpotPower(LightId),
    /// `H = normalize(L + V)` per vertex.
    Halfway(LightId),
    /// `H = normalize(L + V)`: one constant (directional light, infinite viewer).
    HalfwayConstant(LightId),
    /// `R = 2 (N . L) N - L` per vertex (Phong's specular).
    Reflect(LightId),
    /// `n . L` on a side (the back side's with -n).
    DiffuseCosine(LightId, Side),
    /// The specular cosine on a side: `n . H`, or `R . V` (the same on both sides: R is
    /// formed with the front normal).
    SpecularCosine(LightId, Side, SpecularVector),
    /// `max(cos, 0)^s_rm` on a side.
    Power(LightId, Side),
    /// The light's ambient + diffuse + specular, scaled by att spot, added to the side's sums;
    /// the specular term as the plan found it.
    Sum(LightId, Side, SpecularTerm),
    /// `e_cm + a_cm a_cs` added to every side's primary colour.
    SceneColor,
}

impl Stage {
    /// The light the stage belongs to.
    pub fn light(self) -> Option<LightId> {
        match self {
            Stage::LightVector(i)
            | Stage::LightConstant(i)
            | Stage::Attenuate(i)
            | Stage::SpotCone(i)
            | Stage::SpotPower(i)
            | Stage::Halfway(i)
            | Stage::HalfwayConstant(i)
            | Stage::Reflect(i)
            | Stage::DiffuseCosine(i, _)
            | Stage::SpecularCosine(i, _, _)
            | Stage::Power(i, _)
            | Stage::Sum(i, _, _) => Some(i),
            _ => None,
        }
    }

    /// The side the stage lights, for the stages of one side.
    pub fn side(self) -> Option<Side> {
        match self {
            Stage::DiffuseCosine(_, side)
            | Stage::SpecularCosine(_, side, _)
            | Stage::Power(_, side)
            | Stage::Sum(_, side, _) => Some(side),
            _ => None,
        }
    }
}

/// The stage as the shader's comment and the calculation panel write it:
/// `DiffuseCosine(0, 1)` (light 0, the back side).
impl std::fmt::Display for Stage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = match self {
            Stage::TransformNormal => "TransformNormal",
            Stage::RescaleNormal => "RescaleNormal",
            Stage::NormalizeNormal => "NormalizeNormal",
            Stage::NormalizeNormalFast => "NormalizeNormalFast",
            Stage::TransformPosition => "TransformPosition",
            Stage::TransformPositionProjective => "TransformPositionProjective",
            Stage::TranslatePosition => "TranslatePosition",
            Stage::ZeroNormals => "ZeroNormals",
            Stage::ViewVector(_) => "ViewVector",
            Stage::LightVector(_) => "LightVector",
            Stage::LightConstant(_) => "LightConstant",
            Stage::Attenuate(_) => "Attenuate",
            Stage::SpotCone(_) => "SpotCone",
            Stage::SpotPower(_) => "SpotPower",
            Stage::Halfway(_) => "Halfway",
            Stage::HalfwayConstant(_) => "HalfwayConstant",
            Stage::Reflect(_) => "Reflect",
            Stage::DiffuseCosine(..) => "DiffuseCosine",
            Stage::SpecularCosine(..) => "SpecularCosine",
            Stage::Power(..) => "Power",
            Stage::Sum(..) => "Sum",
            Stage::SceneColor => "SceneColor",
        };
        match (self.light(), self.side()) {
            // The normalisation shows where there is one (the stage lists before it are unchanged).
            (Some(i), Some(side)) if matches!(self, Stage::Sum(_, _, SpecularTerm::Normalised)) => {
                write!(f, "{name}({i}, {}, normalised)", side.index())
            }
            (Some(i), Some(side)) => write!(f, "{name}({i}, {})", side.index()),
            (Some(i), None) => write!(f, "{name}({i})"),
            _ => f.write_str(name),
        }
    }
}

/// The stages a key compiles to, for one source of vertices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Program {
    /// In order.
    pub stages: Vec<Stage>,
}

/// What the compiler leaves out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Keep {
    /// Only what must run: every stage whose result the key knows (a product by 1, a sum
    /// with +0, a constant) is left out. The evaluator's and the shader's program.
    Needed,
    /// Every term of the rules' equation, as a person works it by hand (at = 1 is still
    /// computed): the worked calculation's, the notebook's and the quiz's program.
    Every,
}

impl Program {
    /// Compiles `key` for vertices from `source`: only the stages the key calls for.
    pub fn compile(key: &Key, source: SourceKind) -> Program {
        Self::compile_keeping(key, source, Keep::Needed)
    }

    /// The worked program of `key`: every term of the equation its rules have, none left out
    /// for a value the key knows (the attenuation of a light without one, the specular of
    /// a light whose specular product is zero, the scene colour of 0, V of an infinite
    /// viewer), for object-space vertices. What the worked calculation, the notebook and
    /// the quiz walk.
    pub fn worked(key: &Key) -> Program {
        Self::compile_keeping(key, SourceKind::Object, Keep::Every)
    }

    fn compile_keeping(key: &Key, source: SourceKind, keep: Keep) -> Program {
        let every = keep == Keep::Every;
        let mut st = Vec::new();
        match source {
            SourceKind::Object => {
                st.push(Stage::TransformNormal);
                match key.normals {
                    NormalMode::AsIs => {}
                    NormalMode::Rescale if key.rescale_is_one && !every => {}
                    NormalMode::Rescale => st.push(Stage::RescaleNormal),
                    NormalMode::Normalize => st.push(Stage::NormalizeNormal),
                }
                if key.needs_positions() || every {
                    st.push(if key.projective {
                        Stage::TransformPositionProjective
                    } else if key.translation {
                        Stage::TranslatePosition
                    } else {
                        Stage::TransformPosition
                    });
                }
            }
            SourceKind::Eye => {}
            SourceKind::EyeRaw(r) => match r {
                Renormalize::Exact => st.push(Stage::NormalizeNormal),
                Renormalize::FastRsqrt => st.push(Stage::NormalizeNormalFast),
                Renormalize::Skip => {}
            },
        }
        if !key.lights.is_empty() {
            st.push(Stage::ZeroNormals);
        }
        let viewer = match (key.local_viewer, key.per_vertex_view) {
            (true, _) => Viewer::Local,
            (false, true) => Viewer::EyePlane,
            (false, false) => Viewer::Infinite,
        };
        if every || (viewer != Viewer::Infinite && !key.lights.is_empty()) {
            st.push(Stage::ViewVector(viewer));
        }
        for (i, l) in LightId::all(key.lights.len()).zip(&key.lights) {
            Self::light_stages(key, i, l, keep, &mut st);
        }
        let scene_color = if every { key.rules.emission() || key.rules.scene_ambient() } else { !key.scene_color_zero };
        if scene_color {
            st.push(Stage::SceneColor);
        }
        Program { stages: st }
    }

    /// Light `i`'s stages: L, its attenuation and spot factor, H or R, then each side's
    /// cosines, power and sum.
    fn light_stages(key: &Key, i: LightId, l: &LightKey, keep: Keep, st: &mut Vec<Stage>) {
        let every = keep == Keep::Every;
        if l.positional {
            st.push(Stage::LightVector(i));
            if l.attenuated || every {
                st.push(Stage::Attenuate(i));
            }
        } else {
            st.push(Stage::LightConstant(i));
        }
        // A directional light's spot factor is a constant the evaluator folds into L's.
        if l.spot && (l.positional || every) {
            st.push(Stage::SpotCone(i));
            st.push(Stage::SpotPower(i));
        }
        let specular = l.specular || every;
        let vector = key.rules.specular.vector();
        if specular {
            st.push(match vector {
                SpecularVector::Halfway if key.per_vertex_halfway(i) => Stage::Halfway(i),
                SpecularVector::Halfway => Stage::HalfwayConstant(i),
                SpecularVector::Reflection => Stage::Reflect(i),
            });
        }
        let term = match (specular, key.rules.specular.normalised()) {
            (false, _) => SpecularTerm::Zero,
            (true, false) => SpecularTerm::Plain,
            (true, true) => SpecularTerm::Normalised,
        };
        let sides = if key.two_sided { &Side::ALL[..] } else { &Side::ALL[..1] };
        for &side in sides {
            st.push(Stage::DiffuseCosine(i, side));
            if specular {
                st.push(Stage::SpecularCosine(i, side, vector));
            }
            if key.has_power(i, side) || (every && specular) {
                st.push(Stage::Power(i, side));
            }
            st.push(Stage::Sum(i, side, term));
        }
    }

    /// Does the program run `stage`?
    pub fn has(&self, stage: Stage) -> bool {
        self.stages.contains(&stage)
    }

    /// The stages of light `i`, in order.
    pub fn of_light(&self, i: LightId) -> impl Iterator<Item = Stage> + '_ {
        self.stages.iter().copied().filter(move |s| s.light() == Some(i))
    }
}

/// The effects a panel reports, each decided by stages of the program.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EffectKind {
    /// GL_NORMALIZE or GL_RESCALE_NORMAL.
    Normalisation,
    /// P, the vertex in eye space (and whether it is divided by w).
    Position,
    /// V per vertex.
    ViewVector,
    /// `e_cm + a_cm a_cs`.
    SceneColor,
    /// The back side's colours.
    BackSide,
    /// L and d per vertex.
    LightVector,
    /// Attenuation.
    Attenuation,
    /// The spotlight's cone and exponent.
    Spotlight,
    /// H (Blinn-Phong) or R (Phong) per vertex.
    HalfwayOrReflection,
    /// The specular power.
    SpecularPower,
}

impl EffectKind {
    /// The effect's name, e.g. "attenuation".
    pub fn name(self, vector: SpecularVector) -> String {
        match self {
            EffectKind::Normalisation => crate::t!("effect-normalisation"),
            EffectKind::Position => crate::t!("effect-position"),
            EffectKind::ViewVector => crate::t!("effect-view-vector"),
            EffectKind::SceneColor => crate::t!("effect-scene-colour"),
            EffectKind::BackSide => crate::t!("effect-back-side"),
            EffectKind::LightVector => crate::t!("effect-light-vector"),
            EffectKind::Attenuation => crate::t!("effect-attenuation"),
            EffectKind::Spotlight => crate::t!("effect-spotlight"),
            EffectKind::HalfwayOrReflection => match vector {
                SpecularVector::Halfway => crate::t!("effect-halfway"),
                SpecularVector::Reflection => crate::t!("effect-reflection"),
            },
            EffectKind::SpecularPower => crate::t!("effect-specular-power"),
        }
    }
}

impl Key {
    /// Positions matter only to positional lights and a per-vertex V.
    pub fn needs_positions(&self) -> bool {
        self.per_vertex_view || self.lights.iter().any(|l| l.positional)
    }

    /// The program of object-space vertices (what Gouraud and the vertex panel run).
    pub fn program(&self) -> Program {
        Program::compile(self, SourceKind::Object)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stage is written as the shader's stage list has always written it: the light's
    /// number, then the side's (0 front, 1 back).
    #[test]
    fn a_stage_is_written_with_its_light_and_side_numbers() {
        let written: Vec<String> = [
            Stage::TransformNormal,
            Stage::LightVector(LightId(2)),
            Stage::DiffuseCosine(LightId(0), Side::Back),
            Stage::Sum(LightId(1), Side::Front, SpecularTerm::Plain),
        ]
        .iter()
        .map(Stage::to_string)
        .collect();
        assert_eq!(written, ["TransformNormal", "LightVector(2)", "DiffuseCosine(0, 1)", "Sum(1, 0)"]);
    }

    /// The worked program keeps every term the evaluator's program leaves out for a value
    /// the key knows, and only those: an attenuation of (1, 0, 0), V of OpenGL's infinite
    /// viewer, the power at shininess 0, a specular of zero, a scene colour of zero.
    #[test]
    fn the_worked_program_keeps_the_terms_whose_value_is_known() {
        let mut scene = crate::model::presets::worksheet(5);
        scene.rules = Rules::OPENGL;
        scene.material.shininess = 0.0;
        scene.material.emission = glam::DVec4::W;
        scene.light_model.ambient = glam::DVec4::W;
        scene.lights[0].specular = glam::DVec4::W;
        scene.lights[0].attenuation = [1.0, 0.0, 0.0];
        let key = Key::of(&scene, EvalOptions::default());
        let (needed, worked) = (key.program(), Program::worked(&key));
        let light = LightId(0);
        let known = [
            Stage::ViewVector(Viewer::Infinite),
            Stage::Attenuate(light),
            Stage::Halfway(light),
            Stage::SpecularCosine(light, Side::Front, SpecularVector::Halfway),
            Stage::Power(light, Side::Front),
            Stage::SceneColor,
        ];
        for stage in known {
            assert!(worked.has(stage) && !needed.has(stage), "{stage}: {worked:?} / {needed:?}");
        }
        assert!(needed.has(Stage::Sum(light, Side::Front, SpecularTerm::Zero)));
        assert!(worked.has(Stage::Sum(light, Side::Front, SpecularTerm::Plain)));
        // Everything else is the same list, in the same order.
        let rest: Vec<Stage> = worked.stages.iter().copied().filter(|s| !known.contains(s)).collect();
        let needed_rest: Vec<Stage> = needed
            .stages
            .iter()
            .map(|s| if let Stage::Sum(i, side, _) = *s { Stage::Sum(i, side, SpecularTerm::Plain) } else { *s })
            .collect();
        assert_eq!(rest, needed_rest);
    }

    /// A stage's forms come from the rules and the light model: Phong's R and its cosine,
    /// the local viewer's and the worksheet's V.
    #[test]
    fn the_stages_carry_the_forms_of_their_terms() {
        let demo = crate::model::presets::phong_demo();
        let program = Key::of(&demo, EvalOptions::default()).program();
        assert!(program.has(Stage::Reflect(LightId(0))));
        assert!(program.has(Stage::SpecularCosine(LightId(0), Side::Front, SpecularVector::Reflection)));
        let mut ws = crate::model::presets::worksheet(5);
        assert!(Key::of(&ws, EvalOptions::default()).program().has(Stage::ViewVector(Viewer::EyePlane)));
        ws.light_model.local_viewer = true;
        assert!(Key::of(&ws, EvalOptions::default()).program().has(Stage::ViewVector(Viewer::Local)));
    }
}
