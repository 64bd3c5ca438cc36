//! Checking a student's worked calculation step by step.
//!
//! A step's answer is right when every component is within 1e-4 of the expected value
//! relative to it, or within 1e-6 absolutely. What is expected is computed from the
//! student's own earlier answers wherever the step's formula takes them (the carried-forward
//! inputs), so one slip is counted once: with a wrong L, the cosine `N . L` is checked
//! against the student's N and L. Where an input was not given (or does not read as
//! numbers), the answer key's value stands in. Steps whose inputs are only the givens
//! (N, P, the light in eye space, the ambient term, the spot factor) are checked against
//! the key.

use glam::DVec3;

use crate::explain::{Explanation, Step, StepKind};
use crate::lighting::terms;
use crate::rules::SpecularModel;
use crate::scene::Scene;

/// Reads an answer: numbers separated by spaces, commas or semicolons, with optional
/// brackets, and a decimal point or comma, e.g. `[0.79 0.56 -0.25 0]`, `0.79, 0.56, -0.25`,
/// `0,79; 0,56; -0,25`, `646.297` or `0,7246526`
/// ([`crate::formats::typed_number::parse_numbers`]).
pub fn parse_answer(text: &str) -> Result<Vec<f64>, String> {
    crate::formats::typed_number::parse_numbers(text).map_err(|e| e.to_string())
}

/// Is `got` close to `want`: each component within 1e-4 relative or 1e-6 absolute? A
/// 3-number answer to a 4-component vector is compared on x, y, z.
pub fn close(got: &[f64], want: &[f64]) -> bool {
    let n = if got.len() + 1 == want.len() { got.len() } else { want.len() };
    got.len() >= n && got.len() <= want.len() && {
        got.iter().zip(want).take(n).all(|(g, w)| (g - w).abs() <= (1e-4 * w.abs()).max(1e-6))
    }
}

/// The verdict on one step.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// Within the tolerance.
    pub right: bool,
    /// What was expected (from the carried-forward inputs).
    pub expected: Vec<f64>,
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

/// What step `k` should be, given the student's earlier answers, with the inputs used.
/// `None` when the step has no value (e.g. d for a directional light).
pub fn expected(scene: &Scene, key: &Explanation, answers: &Answers, k: usize) -> Option<(Vec<f64>, Vec<Input>)> {
    let st: &Step = key.steps.get(k)?;
    let keyed = st.value.clone()?;
    let li = st.light;
    let light = li.and_then(|i| scene.lights.get(i));
    let mut used = Vec::new();
    let mut get = |kind: StepKind, l: Option<usize>| -> Option<Vec<f64>> {
        let (name, v, own) = input(key, answers, kind, l)?;
        used.push((name, v.clone(), own));
        Some(v)
    };
    let m = &scene.material;
    let value: Option<Vec<f64>> = match st.kind {
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
        StepKind::Diffuse => {
            let c = get(StepKind::CosTheta, li)?[0].max(0.0);
            let ld = light?.diffuse;
            Some((0..3).map(|i| ld[i] * m.diffuse[i] * c).chain([0.0]).collect())
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
        StepKind::CosBeta => match scene.rules.specular {
            SpecularModel::BlinnPhong => {
                let (n, h) = (get(StepKind::Normal, None)?, get(StepKind::H, li)?);
                Some(vec![v3(&n).dot(v3(&h))])
            }
            SpecularModel::Phong => {
                let (r, v) = (get(StepKind::R, li)?, get(StepKind::V, None)?);
                Some(vec![v3(&r).dot(v3(&v))])
            }
        },
        StepKind::Specular => {
            let c = get(StepKind::CosBeta, li)?[0];
            let n_dot_l = get(StepKind::CosTheta, li)?[0];
            let allowed = terms::specular_allowed(scene.rules.specular_gate(), n_dot_l, c);
            let f = if allowed { crate::PowFn::Exact.pow::<f64>(c.max(0.0), m.shininess) } else { 0.0 };
            let ls = light?.specular;
            Some((0..3).map(|i| ls[i] * m.specular[i] * f).chain([0.0]).collect())
        }
        StepKind::Attenuation => {
            let l = light?;
            match get(StepKind::Distance, li) {
                Some(d) => {
                    let [k0, k1, k2] = l.attenuation;
                    Some(vec![k0 + k1 * d[0] + k2 * d[0] * d[0]])
                }
                None => None,
            }
        }
        StepKind::Contribution => {
            let at = get(StepKind::Attenuation, li).map_or(1.0, |v| v[0]);
            let spot = get(StepKind::Spot, li).map_or(1.0, |v| v[0]);
            let amb = get(StepKind::Ambient, li)?;
            let dif = get(StepKind::Diffuse, li)?;
            let spe = get(StepKind::Specular, li).unwrap_or_else(|| vec![0.0; 4]);
            Some(
                (0..3)
                    .map(|i| spot * (amb[i] + dif[i] + spe[i]) / at)
                    .chain([keyed.get(3).copied().unwrap_or(0.0)])
                    .collect(),
            )
        }
        StepKind::Primary => {
            let mut sum = [0.0f64; 3];
            let mut add = |v: Option<Vec<f64>>| {
                if let Some(v) = v {
                    for (s, x) in sum.iter_mut().zip(&v) {
                        *s += x;
                    }
                }
            };
            add(get(StepKind::Emission, None));
            add(get(StepKind::SceneAmbient, None));
            for i in scene.lights.iter().enumerate().map(|(i, _)| i) {
                add(get(StepKind::Contribution, Some(i)));
            }
            Some(sum.into_iter().chain([keyed.get(3).copied().unwrap_or(0.0)]).collect())
        }
        StepKind::Clamped => {
            let i = get(StepKind::Primary, None)?;
            let w = keyed.get(3).copied().unwrap_or(1.0);
            Some(i.iter().take(3).map(|x| x.clamp(0.0, 1.0)).chain([w]).collect())
        }
        // From the givens alone: the key's value.
        _ => None,
    };
    let carried = value.is_some();
    Some((value.unwrap_or(keyed), if carried { used } else { Vec::new() }))
}

/// The verdict on step `k`, or `None` when it has no answer yet or no value to check.
pub fn check(scene: &Scene, key: &Explanation, answers: &Answers, k: usize) -> Option<Verdict> {
    let got = answers.get(k)?.as_ref()?;
    let (expected, inputs) = expected(scene, key, answers, k)?;
    Some(Verdict { right: close(got, &expected), expected, formula: key.steps[k].formula.clone(), inputs })
}

/// The score: (right, answered, steps with a value).
pub fn score(scene: &Scene, key: &Explanation, answers: &Answers) -> (usize, usize, usize) {
    let with_value = key.steps.iter().filter(|s| s.value.is_some()).count();
    let verdicts: Vec<Verdict> = (0..key.steps.len()).filter_map(|k| check(scene, key, answers, k)).collect();
    (verdicts.iter().filter(|v| v.right).count(), verdicts.len(), with_value)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explain::{Side, explain};
    use crate::lighting::Engine;

    fn worksheet() -> (Scene, Explanation) {
        let s = crate::presets::worksheet(5);
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
        let (right, answered, all) = score(&s, &e, &answers);
        assert_eq!((right, answered), (all, all));
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
        // The key's cos(theta) is now the wrong answer for this student.
        answers[idx("cosTheta")] = e.steps[idx("cosTheta")].value.clone();
        assert!(!check(&s, &e, &answers, idx("cosTheta")).unwrap().right);
        // Within 1e-4 relative is right; beyond it is not.
        let at = e.steps[idx("at")].value.clone().unwrap()[0];
        answers[idx("at")] = Some(vec![at * (1.0 + 5e-5)]);
        assert!(check(&s, &e, &answers, idx("at")).unwrap().right);
        answers[idx("at")] = Some(vec![at * (1.0 + 5e-4)]);
        let v = check(&s, &e, &answers, idx("at")).unwrap();
        assert!(!v.right && v.formula.contains("k0 + k1 d"), "{v:?}");
    }
}
