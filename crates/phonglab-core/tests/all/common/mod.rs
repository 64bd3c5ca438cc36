//! Shared helpers for the core's integration tests: the public Mesa cases.
#![allow(dead_code)]

use phonglab_core::glref::{Case, CaseColors, parse_cases};

/// The public glref cases with Mesa llvmpipe's results (copied from the glref harness, docs/lighting.md), parsed once.
pub fn public_cases() -> &'static [Case] {
    static CASES: std::sync::OnceLock<Vec<Case>> = std::sync::OnceLock::new();
    CASES.get_or_init(|| {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/cases_public.json"))
            .expect("tests/data/cases_public.json is in the repository");
        parse_cases(&text)
            .expect("the public case file parses")
            .into_iter()
            .map(|(id, c)| c.unwrap_or_else(|e| panic!("case {id}: {e}")))
            .collect()
    })
}

pub fn case(id: &str) -> Case {
    public_cases().iter().find(|c| c.id == id).cloned().unwrap_or_else(|| panic!("no case {id}"))
}

/// numpy.isclose: |a - b| <= atol + rtol |b|, with equal non-finite values matching.
pub fn close(a: f64, b: f64, rtol: f64, atol: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    if a.is_infinite() || b.is_infinite() {
        return a == b;
    }
    (a - b).abs() <= atol + rtol * b.abs()
}

/// The largest |a-b| / (atol + rtol |b|) over all 16 numbers (<= 1 means within tolerance).
pub fn worst_ratio(ours: &CaseColors, mesa: &CaseColors, rtol: f64, atol: f64) -> f64 {
    let pairs = [
        (ours.front, mesa.front),
        (ours.front_secondary, mesa.front_secondary),
        (ours.back, mesa.back),
        (ours.back_secondary, mesa.back_secondary),
    ];
    let mut worst = 0.0f64;
    for (a, b) in pairs {
        for k in 0..4 {
            let r = if close(a[k], b[k], rtol, atol) && !(a[k] - b[k]).is_finite() {
                0.0
            } else {
                (a[k] - b[k]).abs() / (atol + rtol * b[k].abs())
            };
            worst = worst.max(if r.is_nan() { f64::INFINITY } else { r });
        }
    }
    worst
}

/// A random light from a strategy for each of its parts, for the property tests (each
/// test chooses its own ranges: wild, tame, as the scene format allows).
pub fn light_from(
    colours: impl proptest::strategy::Strategy<Value = (glam::DVec4, glam::DVec4, glam::DVec4)>,
    position: impl proptest::strategy::Strategy<Value = glam::DVec4>,
    spot_direction: impl proptest::strategy::Strategy<Value = glam::DVec3>,
    spot_cutoff: impl proptest::strategy::Strategy<Value = f64>,
    spot_exponent: impl proptest::strategy::Strategy<Value = f64>,
    attenuation: impl proptest::strategy::Strategy<Value = [f64; 3]>,
    placement: impl proptest::strategy::Strategy<Value = phonglab_core::LightPlacement>,
) -> impl proptest::strategy::Strategy<Value = phonglab_core::Light> {
    use proptest::strategy::Strategy;
    (colours, position, spot_direction, spot_cutoff, spot_exponent, attenuation, placement).prop_map(
        |(
            (ambient, diffuse, specular),
            position,
            spot_direction,
            spot_cutoff,
            spot_exponent,
            attenuation,
            placement,
        )| {
            phonglab_core::Light {
                ambient,
                diffuse,
                specular,
                position,
                spot_direction,
                spot_cutoff,
                spot_exponent,
                attenuation,
                placement,
            }
        },
    )
}
