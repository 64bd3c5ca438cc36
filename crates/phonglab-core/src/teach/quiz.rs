//! Checking a student's worked calculation step by step.
//!
//! A step's answer is right when every component is within 1e-4 of the expected value
//! relative to it, or within 1e-6 absolutely ([`TOLERANCE`]). Each answer is checked twice,
//! and its [`Mark`] says which check it passed:
//! - against the key: an answer equal to the key is always right;
//! - against what the student's own earlier answers give, wherever the step's formula
//!   takes them (the carried-forward inputs), so one slip is counted once: with a wrong L,
//!   the cosine `N · L` from the student's N and L is "right, given your vlv".
//!
//! Where an input was not given (or does not read as numbers), the key's value stands in.
//! An answer within 1 % that is not right is "close", with the significant digits it needs.
//! Steps that do not apply to the scene ([`asked`]) are not asked.

use glam::DVec3;

use crate::equation::explain::{Explanation, Step, StepKind};
use crate::equation::lighting::{EvalOptions, terms};
use crate::equation::plan::{Key, Program, SpecularTerm, Stage};
use crate::model::rules::SpecularVector;
use crate::model::scene::{LightId, Scene};

/// Reads an answer: numbers separated by spaces, commas or semicolons, with optional
/// brackets, and a decimal point or comma, e.g. `[0.79 0.56 -0.25 0]`, `0.79, 0.56, -0.25`,
/// `0,79; 0,56; -0,25`, `646.297` or `0,7246526`
/// ([`crate::numerics::typed_number::parse_numbers`]).
pub fn parse_answer(text: &str) -> Result<Vec<f64>, String> {
    crate::numerics::typed_number::parse_numbers(text).map_err(|e| e.to_string())
}

/// How close is right: (relative, absolute).
pub const TOLERANCE: (f64, f64) = (1e-4, 1e-6);

/// How close is "close": within 1 % (or 1e-4 absolutely).
const CLOSE: (f64, f64) = (1e-2, 1e-4);

/// The components compared: a 3-number answer to a 4-component vector is compared on x,
/// y, z; otherwise the lengths must agree.
fn compared(got: &[f64], want: &[f64]) -> Option<usize> {
    let n = if got.len() + 1 == want.len() { got.len() } else { want.len() };
    (got.len() >= n && got.len() <= want.len()).then_some(n)
}

fn within(got: &[f64], want: &[f64], (rel, abs): (f64, f64)) -> bool {
    compared(got, want)
        .is_some_and(|n| got.iter().zip(want).take(n).all(|(g, w)| (g - w).abs() <= (rel * w.abs()).max(abs)))
}

/// Is `got` right for `want`: each component within [`TOLERANCE`]?
pub fn close(got: &[f64], want: &[f64]) -> bool {
    within(got, want, TOLERANCE)
}

/// The largest relative difference of `got` from `want`, over the components.
fn relative_gap(got: &[f64], want: &[f64]) -> f64 {
    got.iter().zip(want).map(|(g, w)| (g - w).abs() / w.abs().max(TOLERANCE.1)).fold(0.0, f64::max)
}

/// The fewest significant digits (up to 17) to which `want` rounds to a right answer.
pub fn digits_needed(want: &[f64]) -> usize {
    (1..=17)
        .find(|&d| {
            let rounded: Vec<f64> =
                want.iter().map(|w| crate::equation::explain::fmt_sig(*w, d).parse::<f64>().unwrap_or(*w)).collect();
            close(&rounded, want)
        })
        .unwrap_or(17)
}

/// What an answer was marked, and why.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// Within the tolerance of the key.
    Right,
    /// Not the key's value, but what the student's own earlier answers give: those
    /// answers (`yours`, by name) differ from the key's, which give `key`.
    RightGivenYours {
        /// The student's earlier answers it follows from (those that differ from the key).
        yours: Vec<String>,
        /// The key's value for this step.
        key: Vec<f64>,
    },
    /// Within 1 % of the value expected, but not within the tolerance.
    Close {
        /// How far off, in percent.
        percent: f64,
        /// The significant digits the expected value needs to be right.
        digits: usize,
    },
    /// Neither: the expected value, from the formula and its inputs.
    Wrong,
}

/// The verdict on one step.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// The mark.
    pub mark: Mark,
    /// Within the tolerance (of the key, or of what the student's answers give).
    pub right: bool,
    /// What was expected (from the carried-forward inputs).
    pub expected: Vec<f64>,
    /// The key's value.
    pub key: Vec<f64>,
    /// The step's formula.
    pub formula: String,
    /// The inputs used: (name, value, whether it is the student's own).
    pub inputs: Vec<Input>,
}

/// The student's answers, one per step of the key (`None`: not given or not numbers).
pub type Answers = [Option<Vec<f64>>];

/// An input a step took: its name, its value, and whether it is the student's own.
pub type Input = (String, Vec<f64>, bool);

fn v3(v: &[f64]) -> DVec3 {
    DVec3::new(v.first().copied().unwrap_or(0.0), v.get(1).copied().unwrap_or(0.0), v.get(2).copied().unwrap_or(0.0))
}

fn dir4(v: DVec3) -> Vec<f64> {
    vec![v.x, v.y, v.z, 0.0]
}

/// Finds the step of `kind` for `light` (or the vertex) and the value to use for it: the
/// student's when given, otherwise the key's.
fn input(
    key: &Explanation,
    answers: &Answers,
    kind: StepKind,
    light: Option<usize>,
) -> Option<(String, Vec<f64>, bool)> {
    let (k, st) = key
        .steps
        .iter()
        .enumerate()
        .find(|(_, s)| s.kind == kind && (s.light == light || light.is_none() && s.light.is_none()))?;
    match answers.get(k).cloned().flatten() {
        Some(v) => Some((st.name.clone(), v, true)),
        None => st.value.clone().map(|v| (st.name.clone(), v, false)),
    }
}

/// What the scene's worked program ([`Program::worked`]) says of the steps the quiz asks
/// and works out again: which lights are positional and spotlights, each light's specular
/// vector and term, and whether the scene's own colour is added.
#[derive(Default)]
struct Worked {
    lights: Vec<WorkedLight>,
    scene_color: bool,
}

/// One light's part of [`Worked`].
#[derive(Clone, Copy)]
struct WorkedLight {
    positional: bool,
    spot: bool,
    vector: SpecularVector,
    term: SpecularTerm,
}

impl Worked {
    fn of(scene: &Scene) -> Worked {
        let mut w = Worked::default();
        for &stage in &Program::worked(&Key::of(scene, EvalOptions::default())).stages {
            w.take(stage);
        }
        w
    }

    fn light_mut(&mut self, i: LightId) -> &mut WorkedLight {
        if self.lights.len() <= i.index() {
            self.lights.resize(i.index() + 1, WorkedLight::BLANK);
        }
        &mut self.lights[i.index()]
    }

    /// Light `index` (the explanation's numbering, the scene's own).
    fn light(&self, index: Option<usize>) -> WorkedLight {
        index.and_then(|i| self.lights.get(i)).copied().unwrap_or(WorkedLight::BLANK)
    }

    /// What one stage says of the quiz's steps.
    fn take(&mut self, stage: Stage) {
        match stage {
            // Steps whose formula has one form (or takes the key's value as given).
            Stage::TransformNormal
            | Stage::RescaleNormal
            | Stage::NormalizeNormal
            | Stage::NormalizeNormalFast
            | Stage::TransformPosition
            | Stage::TransformPositionProjective
            | Stage::TranslatePosition
            | Stage::ZeroNormals
            | Stage::ViewVector(_)
            | Stage::LightConstant(_)
            | Stage::Attenuate(_)
            | Stage::SpotPower(_)
            | Stage::DiffuseCosine(..)
            | Stage::Power(..) => {}
            Stage::LightVector(i) => self.light_mut(i).positional = true,
            Stage::SpotCone(i) => self.light_mut(i).spot = true,
            Stage::Halfway(i) | Stage::HalfwayConstant(i) => self.light_mut(i).vector = SpecularVector::Halfway,
            Stage::Reflect(i) => self.light_mut(i).vector = SpecularVector::Reflection,
            Stage::SpecularCosine(i, _, vector) => self.light_mut(i).vector = vector,
            Stage::Sum(i, _, term) => self.light_mut(i).term = term,
            Stage::SceneColor => self.scene_color = true,
        }
    }
}

impl WorkedLight {
    const BLANK: WorkedLight =
        WorkedLight { positional: false, spot: false, vector: SpecularVector::Halfway, term: SpecularTerm::Plain };
}

/// What step `k` should be, given the student's earlier answers, with the inputs used.
/// `None` when the step has no value (e.g. d for a directional light).
pub fn expected(scene: &Scene, key: &Explanation, answers: &Answers, k: usize) -> Option<(Vec<f64>, Vec<Input>)> {
    let st: &Step = key.steps.get(k)?;
    let keyed = st.value.clone()?;
    let mut inputs = Inputs { key, answers, used: Vec::new() };
    let worked = Worked::of(scene);
    let value = match st.kind {
        StepKind::L
        | StepKind::Distance
        | StepKind::V
        | StepKind::CosTheta
        | StepKind::H
        | StepKind::R
        | StepKind::CosBeta => vector_step(scene, &worked, st, &mut inputs),
        _ => term_step(scene, &worked, st, &keyed, &mut inputs),
    };
    let carried = value.is_some();
    Some((value.unwrap_or(keyed), if carried { inputs.used } else { Vec::new() }))
}

/// The inputs a step takes: the student's answer where given, else the key's, each one
/// recorded as it is read.
struct Inputs<'a> {
    key: &'a Explanation,
    answers: &'a Answers,
    used: Vec<Input>,
}

impl Inputs<'_> {
    /// The value of the step of `kind` for `light` (or the vertex).
    fn get(&mut self, kind: StepKind, light: Option<usize>) -> Option<Vec<f64>> {
        let (name, v, own) = input(self.key, self.answers, kind, light)?;
        self.used.push((name, v.clone(), own));
        Some(v)
    }
}

/// A vector or cosine step (L, d, V, cos θ, H, R, cos β) from the inputs it takes; `None`
/// where it comes from the givens alone (a directional light's L, an infinite viewer's V).
fn vector_step(scene: &Scene, worked: &Worked, st: &Step, inputs: &mut Inputs) -> Option<Vec<f64>> {
    let li = st.light;
    let light = li.and_then(|i| scene.lights.get(i));
    let mut get = |kind: StepKind, l: Option<usize>| inputs.get(kind, l);
    match st.kind {
        StepKind::L => match light {
            Some(l) if scene.light_pos_in_eye(l).w != 0.0 => {
                let (p, pl) = (get(StepKind::Position, None)?, get(StepKind::LightPosition, li)?);
                (v3(&pl) - v3(&p)).try_normalize().map(dir4)
            }
            _ => None,
        },
        StepKind::Distance => {
            let (p, pl) = (get(StepKind::Position, None)?, get(StepKind::LightPosition, li)?);
            Some(vec![(v3(&pl) - v3(&p)).length()])
        }
        StepKind::V if scene.light_model.local_viewer => {
            let p = get(StepKind::Position, None)?;
            (-v3(&p)).try_normalize().map(dir4)
        }
        StepKind::CosTheta => {
            let (n, l) = (get(StepKind::Normal, None)?, get(StepKind::L, li)?);
            Some(vec![v3(&n).dot(v3(&l))])
        }
        StepKind::H => {
            let (l, v) = (get(StepKind::L, li)?, get(StepKind::V, None)?);
            (v3(&l) + v3(&v)).try_normalize().map(dir4)
        }
        StepKind::R => {
            let (n, l) = (get(StepKind::Normal, None)?, get(StepKind::L, li)?);
            let (n, l) = (v3(&n), v3(&l));
            Some(dir4(2.0 * n.dot(l) * n - l))
        }
        StepKind::CosBeta => match worked.light(li).vector {
            SpecularVector::Halfway => {
                let (n, h) = (get(StepKind::Normal, None)?, get(StepKind::H, li)?);
                Some(vec![v3(&n).dot(v3(&h))])
            }
            SpecularVector::Reflection => {
                let (r, v) = (get(StepKind::R, li)?, get(StepKind::V, None)?);
                Some(vec![v3(&r).dot(v3(&v))])
            }
        },
        _ => None,
    }
}

/// A colour or factor step (the diffuse and specular terms, the attenuation, a light's
/// share, the sum, the clamped colour) from the inputs it takes; `None` for the givens.
/// `keyed` is the key's value (its alpha is kept).
fn term_step(scene: &Scene, worked: &Worked, st: &Step, keyed: &[f64], inputs: &mut Inputs) -> Option<Vec<f64>> {
    let li = st.light;
    let light = li.and_then(|i| scene.lights.get(i));
    let m = &scene.material;
    let alpha = |or: f64| keyed.get(3).copied().unwrap_or(or);
    let mut get = |kind: StepKind, l: Option<usize>| inputs.get(kind, l);
    match st.kind {
        StepKind::Diffuse => {
            let c = get(StepKind::CosTheta, li)?[0].max(0.0);
            let ld = light?.diffuse;
            Some((0..3).map(|i| ld[i] * m.diffuse[i] * c).chain([0.0]).collect())
        }
        StepKind::Specular => {
            let c = get(StepKind::CosBeta, li)?[0];
            let n_dot_l = get(StepKind::CosTheta, li)?[0];
            let allowed = terms::specular_allowed(scene.rules.specular_gate(), n_dot_l, c);
            let f = if allowed { crate::numerics::pow::PowFn::Exact.pow::<f64>(c.max(0.0), m.shininess) } else { 0.0 };
            let f = match worked.light(li).term {
                SpecularTerm::Zero | SpecularTerm::Plain => f,
                SpecularTerm::Normalised => f * terms::specular_normalisation(m.shininess),
            };
            let ls = light?.specular;
            Some((0..3).map(|i| ls[i] * m.specular[i] * f).chain([0.0]).collect())
        }
        StepKind::Attenuation => {
            let [k0, k1, k2] = light?.attenuation;
            let d = get(StepKind::Distance, li)?[0];
            Some(vec![k0 + k1 * d + k2 * d * d])
        }
        StepKind::Contribution => {
            let at = get(StepKind::Attenuation, li).map_or(1.0, |v| v[0]);
            let spot = get(StepKind::Spot, li).map_or(1.0, |v| v[0]);
            let amb = get(StepKind::Ambient, li)?;
            let dif = get(StepKind::Diffuse, li)?;
            let spe = get(StepKind::Specular, li).unwrap_or_else(|| vec![0.0; 4]);
            Some((0..3).map(|i| spot * (amb[i] + dif[i] + spe[i]) / at).chain([alpha(0.0)]).collect())
        }
        StepKind::Primary => {
            let mut sum = [0.0f64; 3];
            let parts = [get(StepKind::Emission, None), get(StepKind::SceneAmbient, None)].into_iter();
            let shares: Vec<_> = (0..scene.lights.len()).map(|i| get(StepKind::Contribution, Some(i))).collect();
            for v in parts.chain(shares).flatten() {
                for (s, x) in sum.iter_mut().zip(&v) {
                    *s += x;
                }
            }
            Some(sum.into_iter().chain([alpha(0.0)]).collect())
        }
        StepKind::Clamped => {
            let i = get(StepKind::Primary, None)?;
            Some(i.iter().take(3).map(|x| x.clamp(0.0, 1.0)).chain([alpha(1.0)]).collect())
        }
        // From the givens alone: the key's value.
        _ => None,
    }
}

/// The verdict on step `k`, or `None` when it has no answer yet or no value to check.
pub fn check(scene: &Scene, key: &Explanation, answers: &Answers, k: usize) -> Option<Verdict> {
    let got = answers.get(k)?.as_ref()?;
    let keyed = key.steps.get(k)?.value.clone()?;
    let (expected, inputs) = expected(scene, key, answers, k)?;
    let mark = if close(got, &keyed) {
        Mark::Right
    } else if close(got, &expected) {
        // Right from the student's own inputs, which differ from the key's.
        let differing = |(name, v, own): &Input| {
            let keyed_input = key.steps.iter().find(|s| &s.name == name).and_then(|s| s.value.clone());
            (*own && keyed_input.is_some_and(|kv| !close(v, &kv))).then(|| name.clone())
        };
        let yours: Vec<String> = inputs.iter().filter_map(differing).collect();
        if yours.is_empty() { Mark::Right } else { Mark::RightGivenYours { yours, key: keyed.clone() } }
    } else if compared(got, &keyed).is_some() && within(got, &keyed, CLOSE) {
        // Close to the key is close, whatever the earlier answers: one number gets one mark.
        let percent = 100.0 * relative_gap(got, &keyed);
        Mark::Close { percent, digits: digits_needed(&keyed) }
    } else if compared(got, &expected).is_some() && within(got, &expected, CLOSE) {
        let percent = 100.0 * relative_gap(got, &expected);
        Mark::Close { percent, digits: digits_needed(&expected) }
    } else {
        Mark::Wrong
    };
    let right = matches!(mark, Mark::Right | Mark::RightGivenYours { .. });
    Some(Verdict { mark, right, expected, key: keyed, formula: key.steps[k].formula.clone(), inputs })
}

/// Does step `k` apply to the scene (is it asked)? Not the spot factor of a light that is
/// not a spotlight, nor the attenuation of a directional light (both 1); not a light's
/// share when one light is all of I; not the clamped colour under the worksheet's rules
/// (the worksheet stops at I); not a step with no value (d of a directional light).
pub fn asked(scene: &Scene, key: &Explanation, k: usize) -> bool {
    let Some(st) = key.steps.get(k) else { return false };
    if st.value.is_none() {
        return false;
    }
    let worked = Worked::of(scene);
    let light = worked.light(st.light);
    match st.kind {
        StepKind::Spot => light.spot,
        StepKind::Attenuation => light.positional,
        StepKind::Contribution => worked.lights.len() > 1 || worked.scene_color,
        StepKind::Clamped => !scene.rules.stops_at_sum(),
        _ => true,
    }
}

/// A quiz's score.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Score {
    /// Steps answered right, their answers not shown.
    pub right: usize,
    /// Steps answered.
    pub answered: usize,
    /// Steps asked.
    pub asked: usize,
    /// Steps asked whose answer was shown (`shown[k]`): they never count as right.
    pub shown: usize,
}

/// The score, where `shown[k]` says the answer of step `k` was shown to the student.
pub fn score(scene: &Scene, key: &Explanation, answers: &Answers, shown: &[bool]) -> Score {
    let steps: Vec<usize> = (0..key.steps.len()).filter(|k| asked(scene, key, *k)).collect();
    let was_shown = |k: usize| shown.get(k).copied().unwrap_or(false);
    let verdicts: Vec<(usize, Verdict)> =
        steps.iter().filter_map(|&k| check(scene, key, answers, k).map(|v| (k, v))).collect();
    Score {
        right: verdicts.iter().filter(|(k, v)| v.right && !was_shown(*k)).count(),
        answered: verdicts.len(),
        asked: steps.len(),
        shown: steps.iter().filter(|&&k| was_shown(k)).count(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::equation::explain::{Side, explain};
    use crate::equation::lighting::Engine;

    fn worksheet() -> (Scene, Explanation) {
        let s = crate::model::presets::worksheet(5);
        let lit = Engine::<f64>::new(&s).unwrap().light(&s.vertex);
        let e = explain(&s, &lit, Side::Front);
        (s, e)
    }

    #[test]
    fn answers_read_in_the_usual_forms() {
        assert_eq!(parse_answer("[0.79 0.56 -0.25 0]").unwrap(), vec![0.79, 0.56, -0.25, 0.0]);
        assert_eq!(parse_answer("0.79, 0.56, -0.25").unwrap(), vec![0.79, 0.56, -0.25]);
        assert_eq!(parse_answer(" 646.297 ").unwrap(), vec![646.297]);
        assert!(parse_answer("").is_err());
        assert!(parse_answer("0.5 NaN").is_err());
        assert!(parse_answer("x").unwrap_err().contains("\"x\""));
        // The decimal comma a Portuguese-speaking student types.
        assert_eq!(parse_answer("0,7246526").unwrap(), vec![0.7246526]);
        assert_eq!(parse_answer("0,79; 0,56; -0,25").unwrap(), vec![0.79, 0.56, -0.25]);
    }

    #[test]
    fn the_keys_own_values_are_all_right() {
        let (s, e) = worksheet();
        let answers: Vec<Option<Vec<f64>>> = e.steps.iter().map(|st| st.value.clone()).collect();
        for k in 0..e.steps.len() {
            if let Some(v) = check(&s, &e, &answers, k) {
                assert!(v.right, "step {} {}: {:?} against {:?}", k + 1, e.steps[k].name, e.steps[k].value, v.expected);
            }
        }
        let sc = score(&s, &e, &answers, &[]);
        assert_eq!((sc.right, sc.answered, sc.shown), (sc.asked, sc.asked, 0));
        // A shown answer never counts as right, even answered right afterwards.
        let mut shown = vec![false; e.steps.len()];
        shown[3] = true;
        let sc = score(&s, &e, &answers, &shown);
        assert_eq!((sc.right, sc.answered, sc.shown), (sc.asked - 1, sc.asked, 1));
    }

    /// A number close to the key is marked close wherever it is typed, whatever the earlier
    /// answers it would follow from: one number, one mark.
    #[test]
    fn a_number_close_to_the_key_is_close_whatever_the_earlier_answers() {
        let (s, e) = worksheet();
        let idx = |n: &str| e.steps.iter().position(|st| st.name == n).unwrap();
        let mut answers: Vec<Option<Vec<f64>>> = vec![None; e.steps.len()];
        let cos = e.steps[idx("cosTheta")].value.clone().unwrap()[0];
        answers[idx("cosTheta")] = Some(vec![cos * 1.003]);
        assert!(matches!(check(&s, &e, &answers, idx("cosTheta")).unwrap().mark, Mark::Close { .. }));
        // Now with a wrong vlv before it: the same number is still close (to the key).
        let mut vlv = e.steps[idx("vlv")].value.clone().unwrap();
        vlv[0] += 0.3;
        answers[idx("vlv")] = Some(vlv);
        assert!(matches!(check(&s, &e, &answers, idx("cosTheta")).unwrap().mark, Mark::Close { .. }));
    }

    /// Every step worked out again from the key's own earlier values gives the key's value:
    /// each carried-forward formula is the engine's (a slip in one, such as R's factor 2 or
    /// the attenuation's d², would leave a student marked against a wrong number).
    #[test]
    fn each_step_recomputed_from_the_keys_inputs_is_the_key() {
        let mut spot = crate::model::presets::worksheet(3);
        spot.rules = crate::model::rules::Rules::OPENGL;
        spot.light_model.local_viewer = true;
        spot.lights[0].spot_cutoff = 80.0;
        spot.lights[0].spot_exponent = 4.0;
        // An emission bright enough that the sum passes 1 and the clamp shows.
        let mut bright = crate::model::presets::worksheet(5);
        bright.rules = crate::model::rules::Rules::OPENGL;
        bright.material.emission = glam::DVec4::new(1.5, 0.2, 0.2, 1.0);
        // Energy-conserving Blinn-Phong: the specular step takes its factor (n + 8)/(8 pi).
        let mut normalised = crate::model::presets::worksheet(5);
        normalised.rules.specular = crate::model::rules::SpecularModel::BlinnPhongNormalised;
        let scenes =
            [crate::model::presets::worksheet(5), crate::model::presets::phong_demo(), spot, bright, normalised];
        let mut carried = std::collections::BTreeSet::new();
        for (n, s) in scenes.iter().enumerate() {
            let lit = Engine::<f64>::new(s).unwrap().light(&s.vertex);
            let e = explain(s, &lit, Side::Front);
            let answers: Vec<Option<Vec<f64>>> = e.steps.iter().map(|st| st.value.clone()).collect();
            for (k, st) in e.steps.iter().enumerate() {
                let Some((want, inputs)) = expected(s, &e, &answers, k) else { continue };
                if inputs.is_empty() {
                    continue;
                }
                carried.insert(format!("{:?}", st.kind));
                let key = st.value.clone().unwrap();
                assert!(close(&want, &key), "scene {n}: step {} {}: {want:?} against {key:?}", k + 1, st.name);
            }
        }
        // The scenes carry every formula forward (R: the demo's Phong; V: the local viewer).
        for kind in ["L", "Distance", "V", "CosTheta", "H", "R", "CosBeta", "Diffuse", "Specular", "Attenuation"] {
            assert!(carried.contains(kind), "{kind} never carried: {carried:?}");
        }
        for kind in ["Contribution", "Primary", "Clamped"] {
            assert!(carried.contains(kind), "{kind} never carried: {carried:?}");
        }
    }

    #[test]
    fn a_slip_is_counted_once() {
        let (s, e) = worksheet();
        let idx = |name: &str| e.steps.iter().position(|st| st.name == name).unwrap();
        let mut answers: Vec<Option<Vec<f64>>> = e.steps.iter().map(|st| st.value.clone()).collect();
        // A wrong L (not normalised): L is marked wrong ...
        let l = e.steps[idx("vlv")].value.clone().unwrap();
        let wrong: Vec<f64> = l.iter().map(|x| x * 2.0).collect();
        answers[idx("vlv")] = Some(wrong.clone());
        assert!(!check(&s, &e, &answers, idx("vlv")).unwrap().right);
        // ... and cos(theta) computed from it is right, against the student's own L.
        let n = e.steps[idx("vertexNormal")].value.clone().unwrap();
        let cos_from_wrong = v3(&n).dot(v3(&wrong));
        answers[idx("cosTheta")] = Some(vec![cos_from_wrong]);
        let v = check(&s, &e, &answers, idx("cosTheta")).unwrap();
        assert!(v.right, "{v:?}");
        assert!(v.inputs.iter().any(|(name, val, own)| name == "vlv" && *own && *val == wrong));
        assert_eq!(
            v.mark,
            Mark::RightGivenYours { yours: vec!["vlv".into()], key: e.steps[idx("cosTheta")].value.clone().unwrap() }
        );
        // The key's cos(theta) is right too: a value equal to the key is never wrong.
        answers[idx("cosTheta")] = e.steps[idx("cosTheta")].value.clone();
        assert_eq!(check(&s, &e, &answers, idx("cosTheta")).unwrap().mark, Mark::Right);
        // And so is the worksheet's own Idif, typed next.
        answers[idx("Idif")] = Some(vec![0.09942795, 0.05965677, 0.0252664, 0.0]);
        assert_eq!(check(&s, &e, &answers, idx("Idif")).unwrap().mark, Mark::Right);
        // Within 1e-4 relative is right; beyond it is not.
        let at = e.steps[idx("at")].value.clone().unwrap()[0];
        answers[idx("at")] = Some(vec![at * (1.0 + 5e-5)]);
        assert!(check(&s, &e, &answers, idx("at")).unwrap().right);
        answers[idx("at")] = Some(vec![at * (1.0 + 5e-4)]);
        let v = check(&s, &e, &answers, idx("at")).unwrap();
        assert!(!v.right && v.formula.contains("atC + atLin · d + atQuad · d²"), "{v:?}");
        assert!(matches!(v.mark, Mark::Close { .. }), "{v:?}");
    }

    #[test]
    fn a_rounded_answer_is_close_and_says_the_digits_it_needs() {
        let (s, e) = worksheet();
        let idx = |name: &str| e.steps.iter().position(|st| st.name == name).unwrap();
        let cos_beta = e.steps[idx("cosBeta")].value.clone().unwrap()[0];
        assert!((cos_beta - 0.76439955).abs() < 1e-8, "{cos_beta}");
        let mut answers: Vec<Option<Vec<f64>>> = vec![None; e.steps.len()];
        answers[idx("cosBeta")] = Some(vec![0.764]);
        let v = check(&s, &e, &answers, idx("cosBeta")).unwrap();
        let Mark::Close { percent, digits } = v.mark else { panic!("{v:?}") };
        assert!((percent - 0.0523).abs() < 1e-4, "{percent}");
        assert_eq!(digits, 4, "0.7644 is within 1e-4 of 0.76439955; 0.764 is not");
        answers[idx("cosBeta")] = Some(vec![0.7644]);
        assert_eq!(check(&s, &e, &answers, idx("cosBeta")).unwrap().mark, Mark::Right);
        // Far off is wrong.
        answers[idx("cosBeta")] = Some(vec![0.5]);
        assert_eq!(check(&s, &e, &answers, idx("cosBeta")).unwrap().mark, Mark::Wrong);
        assert_eq!(digits_needed(&[646.29715]), 4);
        assert_eq!(digits_needed(&[0.0]), 1);
    }

    #[test]
    fn steps_that_do_not_apply_are_not_asked() {
        let (s, e) = worksheet();
        let asked_names: Vec<&str> =
            (0..e.steps.len()).filter(|k| asked(&s, &e, *k)).map(|k| e.steps[k].name.as_str()).collect();
        // One light, no spotlight, the worksheet's rules: spot, Ilight and glColor are not asked.
        for not in ["spot", "Ilight", "glColor"] {
            assert!(!asked_names.contains(&not), "{not} in {asked_names:?}");
        }
        for yes in [
            "vertexNormal",
            "vertexPos",
            "lightPos",
            "vlv",
            "d",
            "vov",
            "Iamb",
            "cosTheta",
            "Idif",
            "H",
            "cosBeta",
            "Ispec",
            "at",
            "I",
        ] {
            assert!(asked_names.contains(&yes), "{yes} not in {asked_names:?}");
        }
        // A spotlight's factor is asked.
        let mut spot = crate::model::presets::worksheet(5);
        spot.rules = crate::model::rules::Rules::OPENGL;
        spot.lights[0].spot_cutoff = 60.0;
        spot.lights[0].spot_direction = -glam::DVec3::Z;
        let lit = Engine::<f64>::new(&spot).unwrap().light(&spot.vertex);
        let es = explain(&spot, &lit, Side::Front);
        assert!((0..es.steps.len()).any(|k| es.steps[k].kind == StepKind::Spot && asked(&spot, &es, k)));
        assert!((0..es.steps.len()).any(|k| es.steps[k].kind == StepKind::Clamped && asked(&spot, &es, k)));
    }
}
