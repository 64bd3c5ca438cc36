//! The worksheet's calculation, worked as the notebook's cells work it (NumPy's
//! four-component arrays, `vlv` and `vov` with a w of 0), by walking the stages of
//! [`Program::worked`] with one exhaustive `match`: the key, the key with one of the
//! catalogue's mistakes made, or the key continued from the student's own values ("right,
//! given your X").

use glam::{DMat3, DMat4, DVec4};

use super::mistakes::{ColourSwap, Made, Mistake, Term};
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
    made: Option<Made>,
    student: Option<&'a Printed>,
    /// Do the cells divide by w (`vertexPos/vertexPos[3]`)? The export writes the divide
    /// where the scene's vertex or a light needs it: a mistake does not add or remove it.
    divide_w: bool,
    normal: DVec4,
    pos: DVec4,
    view: DVec4,
    lights: Vec<LightState>,
    sum: DVec4,
    /// The side being worked: the back side's values are printed with `Back` after their
    /// names, from the normal reversed and the back material.
    side: Side,
    /// The other side's lights and sum, swapped in while that side is worked.
    other_lights: Vec<LightState>,
    other_sum: DVec4,
    /// Has a stage of the back side been worked? Has the scene's colour (OpenGL's rules)?
    back_seen: bool,
    scene_colour_seen: bool,
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

/// Works `scene`'s calculation with `mistake` made for every light (`None`: the key).
/// With `student`, each value the student printed replaces the computed one from there on.
pub fn work(scene: &Scene, mistake: Option<Mistake>, student: Option<&Printed>) -> Worked {
    work_made(scene, mistake.map(Made::everywhere), student)
}

/// Works `scene`'s calculation with a mistake made as `made` says (for one light alone,
/// with which colours mixed up).
pub fn work_made(scene: &Scene, made: Option<Made>, student: Option<&Printed>) -> Worked {
    let key = Key::of(scene, EvalOptions::default());
    let mut walk = Walk {
        scene,
        key: &key,
        made,
        student,
        divide_w: key.projective
            || scene.vertex.position.w != 1.0
            || scene.lights.iter().any(|l| {
                let w = scene.light_pos_in_eye(l).w;
                w != 0.0 && w != 1.0
            }),
        normal: scene.vertex.normal.extend(0.0),
        pos: scene.vertex.position,
        view: DVec4::ZERO,
        lights: vec![LightState { at: 1.0, spot: 1.0, ..LightState::default() }; scene.lights.len()],
        sum: DVec4::ZERO,
        side: Side::Front,
        other_lights: vec![LightState { at: 1.0, spot: 1.0, ..LightState::default() }; scene.lights.len()],
        other_sum: DVec4::ZERO,
        back_seen: false,
        scene_colour_seen: false,
        out: Worked::default(),
    };
    for &stage in &Program::worked(&key).stages {
        walk.stage(stage);
    }
    walk.finish();
    walk.out
}

impl Walk<'_> {
    /// Is `m` the mistake made?
    fn made(&self, m: Mistake) -> bool {
        self.made.is_some_and(|x| x.mistake == m)
    }

    /// Is `m` the mistake made, and made for light `i`?
    fn made_at(&self, m: Mistake, i: usize) -> bool {
        self.made.is_some_and(|x| x.mistake == m && x.light.is_none_or(|l| l == i))
    }

    /// Which way the mistake made is written ([`Made::way`]).
    fn way(&self) -> u8 {
        self.made.map_or(0, |x| x.way)
    }

    /// `m * v`, or `v` by `m` as a row vector (`np.matmul(v, m)`, the transpose) where
    /// that is the mistake made (`all`: also for the normal and the spot direction, the
    /// mistake written its first way).
    fn times(&self, m: DMat4, v: DVec4, all: bool) -> DVec4 {
        if self.made(Mistake::RowVectors) && (!all || self.way() == 0) { m.transpose() * v } else { m * v }
    }

    /// The colours mixed up for light `i`, where that is the mistake made.
    fn swap_at(&self, i: usize) -> Option<ColourSwap> {
        self.made.filter(|x| x.light.is_none_or(|l| l == i)).and_then(|x| x.swap)
    }

    /// Light `i`'s and the material's colours of `term`, as multiplied (with a mix-up made).
    fn colours(&self, i: usize, term: Term) -> (DVec4, DVec4) {
        let (light, mat) = (&self.scene.lights[i], self.scene.lit_material(self.side));
        let of_light = |t: Term| {
            rgb(match t {
                Term::Ambient => light.ambient,
                Term::Diffuse => light.diffuse,
                Term::Specular => light.specular,
            })
        };
        let of_material = |t: Term| {
            rgb(match t {
                Term::Ambient => mat.ambient,
                Term::Diffuse => mat.diffuse,
                Term::Specular => mat.specular,
            })
        };
        let one = DVec4::new(1.0, 1.0, 1.0, 0.0);
        // An exchange: the other term takes this one's colour.
        let swap = self.swap_at(i).and_then(|s| match s {
            ColourSwap { exchanged: true, from: Some(f), .. } if f == term => {
                Some(ColourSwap { term, from: Some(s.term), ..s })
            }
            s if s.term == term => Some(s),
            _ => None,
        });
        match swap {
            Some(ColourSwap { light: true, from, .. }) => (from.map_or(one, of_light), of_material(term)),
            Some(ColourSwap { light: false, from, .. }) => (of_light(term), from.map_or(one, of_material)),
            None => (of_light(term), of_material(term)),
        }
    }

    /// A light's printed name: `vlv` for the one light, `vlv[0]` of several.
    fn name(&self, base: &str, i: usize) -> String {
        let base = self.named(base);
        if self.lights.len() == 1 { base } else { format!("{base}[{i}]") }
    }

    /// A value's printed name on the side worked: `I`, or `IBack`.
    fn named(&self, base: &str) -> String {
        match self.side {
            Side::Front => base.to_string(),
            Side::Back => format!("{base}Back"),
        }
    }

    /// Works `f` on the back side for light `id`: its geometry (`vlv`, `H`, `at`, `spot`)
    /// the front's, its normal reversed, its own material, sum and names.
    fn on_back(&mut self, id: LightId, f: impl FnOnce(&mut Self)) {
        let i = id.index();
        let front = self.lights[i];
        let back = &mut self.other_lights[i];
        (back.pos, back.vlv, back.d, back.at, back.spot, back.vector) =
            (front.pos, front.vlv, front.d, front.at, front.spot, front.vector);
        self.swap_sides();
        f(self);
        self.swap_sides();
        self.back_seen = true;
    }

    /// Swaps the side worked: lights, sum, normal.
    fn swap_sides(&mut self) {
        std::mem::swap(&mut self.lights, &mut self.other_lights);
        std::mem::swap(&mut self.sum, &mut self.other_sum);
        self.normal = -self.normal;
        self.side = match self.side {
            Side::Front => Side::Back,
            Side::Back => Side::Front,
        };
    }

    /// Records `value` under `name` and returns the value the walk goes on with: the
    /// student's own, where they printed one of the same size.
    fn emit(&mut self, name: String, value: &[f64]) -> Vec<f64> {
        // A student's x, y, z of a four-component value go on with the key's w.
        let own = self.student.and_then(|p| p.get(&name)).and_then(|v| match (v.numbers.len(), value.len()) {
            (g, w) if g == w => Some(v.numbers.clone()),
            (3, 4) => Some([&v.numbers[..], &value[3..]].concat()),
            _ => None,
        });
        let next = own.unwrap_or_else(|| value.to_vec());
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
            Stage::TransformNormal => {
                self.transform_normal(&m);
                // The cell run again: its normal (normalised the first time) once more.
                if self.made(Mistake::VectorsCellRunTwice) {
                    self.normal = unit(self.normal);
                    self.transform_normal(&m);
                }
            }
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
                let p = if self.made(Mistake::VertexNotTransformed) {
                    self.scene.vertex.position
                } else if self.made(Mistake::VectorsCellRunTwice) {
                    self.times(m, self.times(m, self.scene.vertex.position, false), false)
                } else {
                    self.times(m, self.scene.vertex.position, false)
                };
                let p = if self.divide_w && !self.made(Mistake::WDivideForgotten) { p / p.w } else { p };
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
            Stage::DiffuseCosine(i, Side::Back) => self.on_back(i, |w| w.diffuse(i)),
            Stage::SpecularCosine(i, Side::Back, vector) => self.on_back(i, |w| w.specular_cosine(i, vector)),
            Stage::Sum(i, Side::Back, term) => self.on_back(i, |w| w.light_sum(i, term)),
            Stage::SceneColor => self.scene_color(),
        }
    }

    /// `vertexNormal = M n`, or OpenGL's inverse transpose.
    fn transform_normal(&mut self, m: &DMat4) {
        if self.made(Mistake::NormalNotTransformed) {
            return;
        }
        if self.made(Mistake::NormalMatrixWithTranslation) {
            self.normal = m.inverse().transpose() * self.normal;
            return;
        }
        if self.made(Mistake::NormalAsPoint) && self.scene.rules.normal_transform() == NormalTransform::Modelview {
            self.normal = *m * self.normal.truncate().extend(1.0);
            return;
        }
        let row = self.made(Mistake::RowVectors) && self.way() == 0;
        if self.made(Mistake::NormalMatrixNotTransposed)
            || row && self.scene.rules.normal_transform() == NormalTransform::InverseTranspose
        {
            self.normal = (DMat3::from_mat4(*m).inverse() * self.normal.truncate()).extend(0.0);
            return;
        }
        if row {
            self.normal = m.transpose() * self.normal;
            return;
        }
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
        let v = if self.made(Mistake::ViewerReversed) { -v } else { v };
        let v = if self.made(Mistake::ViewerWithW) { unit(-self.pos) } else { v };
        self.view = self.emit4("vov".into(), v);
    }

    /// `lightPos` in eye space, `vlv`, `d` and `at`.
    fn light_vector(&mut self, id: LightId) {
        let i = id.index();
        let light = &self.scene.lights[i];
        let to_eye = self.scene.eye_from_light(light);
        let pos = if self.made_at(Mistake::LightNotTransformed, i) {
            light.position
        } else if self.made_at(Mistake::LightTransformedTwice, i) || self.made(Mistake::VectorsCellRunTwice) {
            to_eye * (to_eye * light.position)
        } else if self.made_at(Mistake::LightByMview, i) {
            self.times(self.scene.eye_from_object(), light.position, false)
        } else {
            self.times(to_eye, light.position, false)
        };
        let pos = self.emit4(self.name("lightPos", i), pos);
        let point = if self.divide_w && pos.w != 0.0 && !self.made_at(Mistake::WDivideForgotten, i) {
            pos / pos.w
        } else {
            pos
        };
        let directional = pos.w == 0.0 && !self.made_at(Mistake::DirectionalAsPoint, i);
        let mut vlv = if directional || self.made_at(Mistake::PointAsDirectional, i) { pos } else { point - self.pos };
        if self.made_at(Mistake::VlvReversed, i) {
            vlv = -vlv;
        }
        if !self.made_at(Mistake::VlvNotNormalised, i) {
            vlv = unit(vlv);
        }
        let vlv = self.emit4(self.name("vlv", i), vlv);
        let d = if self.made_at(Mistake::AttenuationObjectDistance, i) {
            (light.position - self.scene.vertex.position).length()
        } else if self.made_at(Mistake::DistanceFromNormalisedVlv, i) {
            vlv.length()
        } else if self.made_at(Mistake::DistanceWithoutWDivide, i) {
            (pos - self.pos).length()
        } else if self.made_at(Mistake::DistanceSquared, i) {
            (point - self.pos).length_squared()
        } else {
            (point - self.pos).length()
        };
        let [c, l, q] = light.attenuation;
        let c = if self.made_at(Mistake::AttenuationConstantLeftOut, i) { 0.0 } else { c };
        let dd = if self.made_at(Mistake::AttenuationQuadraticNotSquared, i) { d } else { d * d };
        let d_at_l = if self.made_at(Mistake::AttenuationTermsSwapped, i) { d * d } else { d };
        let dd = if self.made_at(Mistake::AttenuationTermsSwapped, i) { d } else { dd };
        let attenuated = !directional || self.made_at(Mistake::AttenuationOnDirectional, i);
        let inverted = self.made_at(Mistake::AttenuationInverted, i);
        let state = &mut self.lights[i];
        state.pos = pos;
        state.vlv = vlv;
        state.d = d;
        let at = if attenuated { c + l * d_at_l + q * dd } else { 1.0 };
        state.at = if inverted { 1.0 / at } else { at };
    }

    /// `d` (printed for a light with a position) and `at`.
    fn attenuate(&mut self, id: LightId) {
        let i = id.index();
        let s = self.lights[i];
        if s.pos.w != 0.0 || self.made_at(Mistake::DirectionalAsPoint, i) {
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
            let dir = if self.made_at(Mistake::SpotDirectionUntransformed, i) {
                light.spot_direction
            } else {
                self.times(self.scene.eye_from_light(light), light.spot_direction.extend(0.0), true).truncate()
            };
            let dir = dir / dir.length();
            let towards = if self.made_at(Mistake::SpotAngleReversed, i) { 1.0 } else { -1.0 };
            let cos_spot = (towards * self.lights[i].vlv.truncate()).dot(dir);
            let cutoff = if self.made_at(Mistake::SpotCutoffRadians, i) {
                light.spot_cutoff
            } else if self.made_at(Mistake::SpotCutoffHalved, i) {
                (light.spot_cutoff / 2.0).to_radians()
            } else {
                light.spot_cutoff.to_radians()
            };
            let limit = if self.made_at(Mistake::SpotCutoffNotCosine, i) { light.spot_cutoff } else { cutoff.cos() };
            let inside = (cos_spot >= limit) != self.made_at(Mistake::ConeTestInverted, i);
            let exponent = if self.made_at(Mistake::SpotExponentIgnored, i) { 1.0 } else { light.spot_exponent };
            let factor = self.made_at(Mistake::SpotExponentAsFactor, i);
            spot = if factor && inside {
                cos_spot * light.spot_exponent
            } else if inside || self.made_at(Mistake::SpotExponentOutsideCone, i) {
                cos_spot.max(0.0).powf(exponent)
            } else {
                0.0
            };
        }
        self.lights[i].spot = self.emit1(self.name("spot", i), spot);
    }

    /// `H = normalize(vlv + vov)`.
    fn halfway(&mut self, id: LightId) {
        let i = id.index();
        let mut h = if self.made_at(Mistake::HalfwayWithViewReversed, i) {
            self.lights[i].vlv - self.view
        } else {
            self.lights[i].vlv + self.view
        };
        if self.made_at(Mistake::ReflectionForHalfway, i) && self.way() > 0 {
            let l = self.lights[i].vlv;
            h = 2.0 * self.normal.dot(l) * self.normal - l;
        }
        if !self.made_at(Mistake::HalfwayNotNormalised, i) {
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
        let r = 2.0 * dot * self.normal - l;
        let r = if self.made_at(Mistake::ReflectionReversed, i) { -r } else { r };
        self.lights[i].vector = self.emit4(self.name("R", i), r);
    }

    /// `Iamb`, `cosTheta` and `Idif` (0 past 90 degrees).
    fn diffuse(&mut self, id: LightId) {
        let i = id.index();
        let (lamb, mamb) = self.colours(i, Term::Ambient);
        let (ldif, mdif) = self.colours(i, Term::Diffuse);
        let toward =
            if self.made_at(Mistake::CosThetaWithLightPosition, i) { self.lights[i].pos } else { self.lights[i].vlv };
        let cos = self.normal.dot(toward);
        let iamb = if self.made_at(Mistake::AmbientTimesCosine, i) { lamb * mamb * cos } else { lamb * mamb };
        self.lights[i].iamb = self.emit4(self.name("Iamb", i), iamb);
        let cos = self.emit1(self.name("cosTheta", i), cos);
        let dark = if self.made_at(Mistake::ThetaInDegrees, i) {
            cos.clamp(-1.0, 1.0).acos().to_degrees() > std::f64::consts::FRAC_PI_2
        } else {
            cos < 0.0 && !self.made_at(Mistake::DiffuseNotClamped, i)
        };
        let by = if self.made_at(Mistake::DiffuseAngleNotCosine, i) { cos.clamp(-1.0, 1.0).acos() } else { cos };
        let idif = if dark { DVec4::ZERO } else { ldif * mdif * by };
        self.lights[i].cos_theta = cos;
        self.lights[i].idif = self.emit4(self.name("Idif", i), idif);
    }

    /// `cosBeta = N . H`, or `cosAlpha = R . V`.
    fn specular_cosine(&mut self, id: LightId, vector: SpecularVector) {
        let i = id.index();
        let s = self.lights[i];
        let (name, cos) = match vector {
            SpecularVector::Halfway if self.made_at(Mistake::ReflectionForHalfway, i) && self.way() == 1 => {
                ("cosBeta", self.view.dot(s.vector))
            }
            SpecularVector::Halfway if self.made_at(Mistake::ReflectionForHalfway, i) && self.way() == 0 => {
                let r = 2.0 * self.normal.dot(s.vlv) * self.normal - s.vlv;
                ("cosBeta", r.dot(self.view))
            }
            SpecularVector::Halfway => ("cosBeta", self.normal.dot(s.vector)),
            SpecularVector::Reflection => ("cosAlpha", s.vector.dot(self.view)),
        };
        self.lights[i].cos_spec = self.emit1(self.name(name, i), cos);
    }

    /// `Ispec` as the rules gate it, then the light's share `Ilight`, added to the sum.
    fn light_sum(&mut self, id: LightId, term: SpecularTerm) {
        let i = id.index();
        let shininess = self.scene.lit_material(self.side).shininess;
        let s = self.lights[i];
        let ns = if self.made(Mistake::ShininessFraction) { shininess / 128.0 } else { shininess };
        let scale = match term {
            SpecularTerm::Zero | SpecularTerm::Plain => 1.0,
            SpecularTerm::Normalised => (ns + 8.0) / (8.0 * std::f64::consts::PI),
        };
        let (lspec, mspec) = self.colours(i, Term::Specular);
        let gated = match self.scene.rules.specular_gate() {
            SpecularGate::None => false,
            SpecularGate::LitSide => s.cos_theta <= 0.0 && !self.made_at(Mistake::SpecularWithoutGate, i),
            SpecularGate::PositiveCosine => s.cos_spec < 0.0 && !self.made_at(Mistake::SpecularTestInDegrees, i),
        };
        // NumPy's `max(cosBeta, 0)` keeps a NaN (a zero-length vov) where `f64::max` drops
        // it; the worksheet's angle test leaves the cosine unclamped.
        let unclamped = self.made_at(Mistake::SpecularCosineNotClamped, i)
            || s.cos_spec.is_nan()
            || self.scene.rules.specular_gate() == SpecularGate::PositiveCosine;
        let cos = if unclamped { s.cos_spec } else { s.cos_spec.max(0.0) };
        let cos = if self.made_at(Mistake::SpecularAngleNotCosine, i) { cos.clamp(-1.0, 1.0).acos() } else { cos };
        let cos = if self.made_at(Mistake::SpecularOfDiffuseCosine, i) { s.cos_theta.max(0.0) } else { cos };
        let lobe = if self.made_at(Mistake::ShininessAsProduct, i) { cos * ns } else { cos.powf(ns) };
        let lobe = if self.made_at(Mistake::SpecularTimesCosine, i) { lobe * s.cos_theta } else { lobe };
        let ispec = if gated { DVec4::ZERO } else { lspec * mspec * lobe * scale };
        let ispec = self.emit4(self.name("Ispec", i), ispec);
        let share = self.share(i, ispec);
        let share = self.emit4(self.name("Ilight", i), share);
        let last = i + 1 == self.lights.len();
        if !self.made_at(Mistake::LightLeftOut, i) && (last || !self.made(Mistake::OnlyLastLight)) {
            self.sum += share;
        }
    }

    /// The light's share: `spot*(Iamb + Idif + Ispec)/at`, as the mistake made writes it.
    fn share(&self, i: usize, ispec: DVec4) -> DVec4 {
        let s = self.lights[i];
        let iamb = if self.made_at(Mistake::LightAmbientLeftOut, i) { DVec4::ZERO } else { s.iamb };
        // A separate specular colour leaves the specular out of the light's primary share.
        let ispec =
            if self.key.separate_specular || self.made_at(Mistake::SpecularLeftOut, i) { DVec4::ZERO } else { ispec };
        let spot =
            if self.made_at(Mistake::SpotLeftOut, i) || self.made(Mistake::SpotOnWholeColour) { 1.0 } else { s.spot };
        let at = if self.made_at(Mistake::AttenuationLeftOut, i) || self.made(Mistake::AttenuationOnWholeColour) {
            1.0
        } else {
            s.at
        };
        if self.made_at(Mistake::AmbientOutsideShare, i) {
            iamb + spot * (s.idif + ispec) / at
        } else if self.made_at(Mistake::SpotNotOnAmbient, i) {
            (iamb + s.spot * (s.idif + ispec)) / at
        } else if self.made_at(Mistake::SpotOnDiffuseOnly, i) {
            (iamb + s.spot * s.idif + ispec) / at
        } else if self.made_at(Mistake::AttenuationMultiplied, i) {
            spot * (iamb + s.idif + ispec) * at
        } else if self.made_at(Mistake::AmbientNotAttenuated, i) {
            spot * (iamb + (s.idif + ispec) / at)
        } else {
            spot * (iamb + s.idif + ispec) / at
        }
    }

    /// OpenGL's scene ambient and emission.
    fn scene_color(&mut self) {
        self.scene_colour_seen = true;
        let mat = self.scene.lit_material(self.side);
        let scene_ambient = rgb(self.scene.light_model.ambient);
        let iscene = if self.made(Mistake::SceneAmbientWithoutMaterial) {
            scene_ambient
        } else if self.made(Mistake::SceneAmbientTimesLight) {
            let light = self.scene.lights.first().map_or(DVec4::ZERO, |l| rgb(l.ambient));
            rgb(mat.ambient) * scene_ambient * light
        } else if self.made(Mistake::SceneAmbientWrongMaterial) {
            rgb(if self.way() == 0 { mat.diffuse } else { mat.specular }) * scene_ambient
        } else {
            rgb(mat.ambient) * scene_ambient
        };
        let iscene = self.emit4(self.named("Iscene"), iscene);
        let iemi = self.emit4(self.named("Iemi"), rgb(mat.emission));
        if !self.made(Mistake::SceneAmbientLeftOut) {
            self.sum += iscene;
        }
        if !self.made(Mistake::EmissionLeftOut) {
            self.sum += iemi;
        }
        if self.made(Mistake::EmissionTwice) {
            self.sum += iemi;
        }
    }

    /// `I` and the colour as drawn, then the back side's (its scene colour, `IBack`,
    /// `glColorBack`) where it was worked.
    fn finish(&mut self) {
        self.finish_side();
        if self.back_seen {
            self.swap_sides();
            if self.scene_colour_seen {
                self.scene_color();
            }
            self.finish_side();
            self.swap_sides();
        }
    }

    /// `I`, and the colour as drawn, of the side worked.
    fn finish_side(&mut self) {
        if self.made(Mistake::SpotOnWholeColour) {
            self.sum *= self.lights.first().map_or(1.0, |l| l.spot);
        }
        if self.made(Mistake::AttenuationOnWholeColour) {
            self.sum /= self.lights.first().map_or(1.0, |l| l.at);
        }
        let i = self.emit4(self.named("I"), self.sum);
        let c = if self.made(Mistake::ColourNotClamped) {
            i.truncate()
        } else {
            // `np.clip`: a NaN stays NaN (`f64::clamp` keeps it; `DVec3::clamp` would make it 0).
            glam::DVec3::from_array(i.truncate().to_array().map(|x| x.clamp(0.0, 1.0)))
        };
        let alpha = if self.made(Mistake::AlphaFromSum) { i.w } else { self.scene.lit_material(self.side).diffuse.w };
        if !self.key.separate_specular {
            self.emit4(self.named("glColor"), c.extend(alpha));
        }
    }
}
