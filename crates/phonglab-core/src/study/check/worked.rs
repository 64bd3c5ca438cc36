//! The worksheet's calculation, worked as the notebook's cells work it (NumPy's
//! four-component arrays, `vlv` and `vov` with a w of 0), by walking the stages of
//! [`Program::worked`] with one exhaustive `match`: the key, the key with one of the
//! catalogue's mistakes made, or the key continued from the student's own values ("right,
//! given your X").

use glam::{DMat3, DMat4, DVec4};

use super::mistakes::Mistake;
use super::printed::Printed;
use crate::equation::lighting::EvalOptions;
use crate::equation::plan::{Key, Program, SpecularTerm, Stage, Viewer};
use crate::model::rules::{NormalTransform, SpecularGate, SpecularVector};
use crate::model::scene::{LightId, Scene, Side};

/// The values a calculation printed, by the notebook's names, in the order computed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Worked {
    /// `(name, value)`: `vlv`, or `vlv[0]` for a light of several.
    pub values: Vec<(String, Vec<f64>)>,
}

impl Worked {
    /// The value computed under `name`.
    pub fn get(&self, name: &str) -> Option<&[f64]> {
        self.values.iter().find(|(n, _)| n == name).map(|(_, v)| v.as_slice())
    }
}

/// One light's values as the cells compute them.
#[derive(Clone, Copy, Debug, Default)]
struct LightState {
    pos: DVec4,
    vlv: DVec4,
    d: f64,
    at: f64,
    spot: f64,
    vector: DVec4,
    cos_theta: f64,
    cos_spec: f64,
    iamb: DVec4,
    idif: DVec4,
}

/// The walk's state: the vertex's values, each light's, the sum.
struct Walk<'a> {
    scene: &'a Scene,
    key: &'a Key,
    mistake: Option<Mistake>,
    student: Option<&'a Printed>,
    normal: DVec4,
    pos: DVec4,
    view: DVec4,
    lights: Vec<LightState>,
    sum: DVec4,
    out: Worked,
}

/// A colour as the notebook writes it: its alpha 0 (kept apart).
fn rgb(c: DVec4) -> DVec4 {
    c.truncate().extend(0.0)
}

/// NumPy's `x/np.linalg.norm(x)`.
fn unit(v: DVec4) -> DVec4 {
    v / v.length()
}

/// Works `scene`'s calculation with `mistake` made (`None`: the key). With `student`, each
/// value the student printed replaces the computed one from there on.
pub fn work(scene: &Scene, mistake: Option<Mistake>, student: Option<&Printed>) -> Worked {
    let key = Key::of(scene, EvalOptions::default());
    let mut walk = Walk {
        scene,
        key: &key,
        mistake,
        student,
        normal: scene.vertex.normal.extend(0.0),
        pos: scene.vertex.position,
        view: DVec4::ZERO,
        lights: vec![LightState { at: 1.0, spot: 1.0, ..LightState::default() }; scene.lights.len()],
        sum: DVec4::ZERO,
        out: Worked::default(),
    };
    for &stage in &Program::worked(&key).stages {
        walk.stage(stage);
    }
    walk.finish();
    walk.out
}

impl Walk<'_> {
    fn made(&self, m: Mistake) -> bool {
        self.mistake == Some(m)
    }

    /// A light's printed name: `vlv` for the one light, `vlv[0]` of several.
    fn name(&self, base: &str, i: usize) -> String {
        if self.lights.len() == 1 { base.to_string() } else { format!("{base}[{i}]") }
    }

    /// Records `value` under `name` and returns the value the walk goes on with: the
    /// student's own, where they printed one of the same size.
    fn emit(&mut self, name: String, value: &[f64]) -> Vec<f64> {
        let own = self.student.and_then(|p| p.get(&name)).filter(|v| v.numbers.len() == value.len());
        let next = own.map_or_else(|| value.to_vec(), |v| v.numbers.clone());
        if self.out.get(&name).is_none() {
            self.out.values.push((name, value.to_vec()));
        }
        next
    }

    fn emit4(&mut self, name: String, v: DVec4) -> DVec4 {
        let next = self.emit(name, &v.to_array());
        DVec4::from_slice(&next)
    }

    fn emit1(&mut self, name: String, x: f64) -> f64 {
        self.emit(name, &[x])[0]
    }

    /// One stage of the worked program.
    fn stage(&mut self, stage: Stage) {
        let m = self.scene.eye_from_object();
        match stage {
            Stage::TransformNormal => self.transform_normal(&m),
            Stage::RescaleNormal => {
                let f = DMat3::from_mat4(m).inverse().row(2).length();
                self.normal /= f;
            }
            Stage::NormalizeNormal | Stage::NormalizeNormalFast => {
                if !self.made(Mistake::NormalNotNormalised) {
                    self.normal = unit(self.normal);
                }
            }
            Stage::ZeroNormals => {}
            Stage::TransformPosition | Stage::TransformPositionProjective | Stage::TranslatePosition => {
                self.normal = self.emit4("vertexNormal".into(), self.normal);
                let p = m * self.scene.vertex.position;
                let p = if p.w != 0.0 && p.w != 1.0 && !self.made(Mistake::WDivideForgotten) { p / p.w } else { p };
                self.pos = self.emit4("vertexPos".into(), p);
            }
            Stage::ViewVector(viewer) => self.view_vector(viewer),
            Stage::LightVector(i) | Stage::LightConstant(i) => self.light_vector(i),
            Stage::Attenuate(i) => self.attenuate(i),
            Stage::SpotCone(i) => self.spot(i),
            Stage::SpotPower(_) => {}
            Stage::Halfway(i) | Stage::HalfwayConstant(i) => self.halfway(i),
            Stage::Reflect(i) => self.reflect(i),
            Stage::DiffuseCosine(i, Side::Front) => self.diffuse(i),
            Stage::SpecularCosine(i, Side::Front, vector) => self.specular_cosine(i, vector),
            Stage::Power(..) => {}
            Stage::Sum(i, Side::Front, term) => self.light_sum(i, term),
            // The back side of two-sided lighting is not checked (its names end in Back).
            Stage::DiffuseCosine(_, Side::Back)
            | Stage::SpecularCosine(_, Side::Back, _)
            | Stage::Sum(_, Side::Back, _) => {}
            Stage::SceneColor => self.scene_color(),
        }
    }

    /// `vertexNormal = M n`, or OpenGL's inverse transpose.
    fn transform_normal(&mut self, m: &DMat4) {
        let by_m = match self.scene.rules.normal_transform() {
            NormalTransform::Modelview => true,
            NormalTransform::InverseTranspose => self.made(Mistake::NormalByModelview),
        };
        self.normal = if by_m {
            *m * self.normal
        } else {
            (DMat3::from_mat4(*m).inverse().transpose() * self.normal.truncate()).extend(0.0)
        };
    }

    /// `vov`: the viewer the rules and the local-viewer flag choose (or the other one).
    fn view_vector(&mut self, viewer: Viewer) {
        let infinite = if self.scene.rules.viewer_from_eye_plane() { Viewer::EyePlane } else { Viewer::Infinite };
        let viewer = match (self.made(Mistake::ViewerSwapped), viewer) {
            (false, v) => v,
            (true, Viewer::Local) => infinite,
            (true, Viewer::EyePlane | Viewer::Infinite) => Viewer::Local,
        };
        let v = match viewer {
            Viewer::Local => unit(DVec4::W - self.pos),
            Viewer::EyePlane => unit(self.pos * DVec4::new(1.0, 1.0, 0.0, 1.0) - self.pos),
            Viewer::Infinite => DVec4::Z,
        };
        self.view = self.emit4("vov".into(), v);
    }

    /// `lightPos` in eye space, `vlv`, `d` and `at`.
    fn light_vector(&mut self, id: LightId) {
        let i = id.index();
        let light = &self.scene.lights[i];
        let to_eye = self.scene.eye_from_light(light);
        let pos = if self.made(Mistake::LightNotTransformed) {
            light.position
        } else if self.made(Mistake::LightTransformedTwice) {
            to_eye * (to_eye * light.position)
        } else {
            to_eye * light.position
        };
        let pos = self.emit4(self.name("lightPos", i), pos);
        let point =
            if pos.w != 0.0 && pos.w != 1.0 && !self.made(Mistake::WDivideForgotten) { pos / pos.w } else { pos };
        let directional = pos.w == 0.0 && !self.made(Mistake::DirectionalAsPoint);
        let mut vlv = if directional { pos } else { point - self.pos };
        if self.made(Mistake::VlvReversed) {
            vlv = -vlv;
        }
        if !self.made(Mistake::VlvNotNormalised) {
            vlv = unit(vlv);
        }
        let vlv = self.emit4(self.name("vlv", i), vlv);
        let d = if self.made(Mistake::AttenuationObjectDistance) {
            (light.position - self.scene.vertex.position).length()
        } else {
            (point - self.pos).length()
        };
        let state = &mut self.lights[i];
        state.pos = pos;
        state.vlv = vlv;
        state.d = d;
        state.at = if directional {
            1.0
        } else {
            light.attenuation[0] + light.attenuation[1] * d + light.attenuation[2] * d * d
        };
    }

    /// `d` (printed for a light with a position) and `at`.
    fn attenuate(&mut self, id: LightId) {
        let i = id.index();
        let s = self.lights[i];
        if s.pos.w != 0.0 || self.made(Mistake::DirectionalAsPoint) {
            self.lights[i].d = self.emit1(self.name("d", i), s.d);
        }
        self.lights[i].at = self.emit1(self.name("at", i), s.at);
    }

    /// The spotlight's factor: the cone, then the exponent.
    fn spot(&mut self, id: LightId) {
        let i = id.index();
        let light = &self.scene.lights[i];
        let mut spot = 1.0;
        if light.is_spot() {
            let dir = DMat3::from_mat4(self.scene.eye_from_light(light)) * light.spot_direction;
            let dir = dir / dir.length();
            let cos_spot = (-self.lights[i].vlv.truncate()).dot(dir);
            let cutoff =
                if self.made(Mistake::SpotCutoffRadians) { light.spot_cutoff } else { light.spot_cutoff.to_radians() };
            let inside = cos_spot >= cutoff.cos();
            spot = if inside || self.made(Mistake::SpotExponentOutsideCone) {
                cos_spot.max(0.0).powf(light.spot_exponent)
            } else {
                0.0
            };
        }
        self.lights[i].spot = self.emit1(self.name("spot", i), spot);
    }

    /// `H = normalize(vlv + vov)`.
    fn halfway(&mut self, id: LightId) {
        let i = id.index();
        let mut h = self.lights[i].vlv + self.view;
        if !self.made(Mistake::HalfwayNotNormalised) {
            h = unit(h);
        }
        self.lights[i].vector = self.emit4(self.name("H", i), h);
    }

    /// `R = 2 (N . L) N - L`.
    fn reflect(&mut self, id: LightId) {
        let i = id.index();
        let l = self.lights[i].vlv;
        let dot = self.normal.dot(l);
        let dot = if self.scene.rules.reflect_clamped() { dot.max(0.0) } else { dot };
        self.lights[i].vector = self.emit4(self.name("R", i), 2.0 * dot * self.normal - l);
    }

    /// `Iamb`, `cosTheta` and `Idif` (0 past 90 degrees).
    fn diffuse(&mut self, id: LightId) {
        let i = id.index();
        let (light, mat) = (&self.scene.lights[i], self.scene.lit_material(Side::Front));
        let iamb = rgb(light.ambient) * rgb(mat.ambient);
        let ldif = rgb(light.diffuse) * rgb(mat.diffuse);
        self.lights[i].iamb = self.emit4(self.name("Iamb", i), iamb);
        let cos = self.normal.dot(self.lights[i].vlv);
        let cos = self.emit1(self.name("cosTheta", i), cos);
        let idif = if cos < 0.0 && !self.made(Mistake::DiffuseNotClamped) { DVec4::ZERO } else { ldif * cos };
        self.lights[i].cos_theta = cos;
        self.lights[i].idif = self.emit4(self.name("Idif", i), idif);
    }

    /// `cosBeta = N . H`, or `cosAlpha = R . V`.
    fn specular_cosine(&mut self, id: LightId, vector: SpecularVector) {
        let i = id.index();
        let (name, cos) = match vector {
            SpecularVector::Halfway => ("cosBeta", self.normal.dot(self.lights[i].vector)),
            SpecularVector::Reflection => ("cosAlpha", self.lights[i].vector.dot(self.view)),
        };
        self.lights[i].cos_spec = self.emit1(self.name(name, i), cos);
    }

    /// `Ispec` as the rules gate it, then the light's share `Ilight`, added to the sum.
    fn light_sum(&mut self, id: LightId, term: SpecularTerm) {
        let i = id.index();
        let (light, mat) = (&self.scene.lights[i], self.scene.lit_material(Side::Front));
        let s = self.lights[i];
        let ns = if self.made(Mistake::ShininessFraction) { mat.shininess / 128.0 } else { mat.shininess };
        let scale = match term {
            SpecularTerm::Zero | SpecularTerm::Plain => 1.0,
            SpecularTerm::Normalised => (ns + 8.0) / (8.0 * std::f64::consts::PI),
        };
        let lspec = rgb(light.specular) * rgb(mat.specular);
        let gated = match self.scene.rules.specular_gate() {
            SpecularGate::None => false,
            SpecularGate::LitSide => s.cos_theta <= 0.0 && !self.made(Mistake::SpecularWithoutGate),
            SpecularGate::PositiveCosine => s.cos_spec < 0.0,
        };
        let ispec = if gated { DVec4::ZERO } else { lspec * s.cos_spec.max(0.0).powf(ns) * scale };
        let ispec = self.emit4(self.name("Ispec", i), ispec);
        // A separate specular colour leaves the specular out of the light's primary share.
        let lit = if self.key.separate_specular { s.iamb + s.idif } else { s.iamb + s.idif + ispec };
        let share = s.spot * lit;
        let share = if self.made(Mistake::AttenuationMultiplied) { share * s.at } else { share / s.at };
        let share = self.emit4(self.name("Ilight", i), share);
        self.sum += share;
    }

    /// OpenGL's scene ambient and emission.
    fn scene_color(&mut self) {
        let mat = self.scene.lit_material(Side::Front);
        let iscene = self.emit4("Iscene".into(), rgb(mat.ambient) * rgb(self.scene.light_model.ambient));
        let iemi = self.emit4("Iemi".into(), rgb(mat.emission));
        self.sum += iscene + iemi;
    }

    /// `I`, and the colour as drawn.
    fn finish(&mut self) {
        let i = self.emit4("I".into(), self.sum);
        let c = i.truncate().clamp(glam::DVec3::ZERO, glam::DVec3::ONE);
        let alpha = self.scene.lit_material(Side::Front).diffuse.w;
        if !self.key.separate_specular {
            self.emit4("glColor".into(), c.extend(alpha));
        }
    }
}
