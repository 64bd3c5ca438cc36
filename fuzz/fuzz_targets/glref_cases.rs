//! Any bytes as a glref case file (the `phonglab eval` input): it parses or is refused,
//! never panics; every case OpenGL accepts evaluates in f32 and f64, and the specialised
//! evaluator agrees with the general engine bit for bit. The numerics policy: when every
//! input is finite, no output is NaN (f64; in f32, when every input is also a float). The
//! cases read are those with unique string ids.
#![no_main]

use libfuzzer_sys::fuzz_target;
use phonglab_core::glref::{evaluate, parse_cases};
use phonglab_core::specialised::Lighter;
use phonglab_core::{Engine, EvalOptions, Scene};

fn numbers(s: &Scene) -> Vec<f64> {
    let mut v = Vec::new();
    let m = |m: &phonglab_core::Material, v: &mut Vec<f64>| {
        for c in [m.ambient, m.diffuse, m.specular, m.emission] {
            v.extend(c.to_array());
        }
        v.push(m.shininess);
    };
    v.extend(s.light_model.ambient.to_array());
    m(&s.material, &mut v);
    if let Some(b) = &s.back_material {
        m(b, &mut v);
    }
    v.extend(s.eye_from_world.to_cols_array());
    v.extend(s.world_from_object.to_cols_array());
    v.extend(s.vertex.position.to_array());
    v.extend(s.vertex.normal.to_array());
    for l in &s.lights {
        for c in [l.ambient, l.diffuse, l.specular, l.position] {
            v.extend(c.to_array());
        }
        v.extend(l.spot_direction.to_array());
        v.extend([l.spot_cutoff, l.spot_exponent]);
        v.extend(l.attenuation);
        v.extend(s.eye_from_light(l).to_cols_array());
    }
    v
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(cases) = parse_cases(text) else { return };
    let mut ids = std::collections::HashSet::new();
    for (id, case) in cases {
        let Ok(case) = case else { continue };
        assert_eq!(id, case.id, "an accepted case keeps its id as given");
        assert!(ids.insert(case.id.clone()), "two accepted cases share the id {id:?}");
        let s = &case.scene;
        let Ok(c64) = evaluate::<f64>(s, EvalOptions::default(), false) else { continue };
        let c32 = evaluate::<f32>(s, EvalOptions::default(), false).expect("f32 accepts what f64 accepts");
        let inputs = numbers(s);
        if inputs.iter().all(|x| x.is_finite()) {
            for c in [c64.front, c64.front_secondary, c64.back, c64.back_secondary] {
                assert!(!c.iter().any(|x| x.is_nan()), "f64 NaN from finite inputs: {c:?}");
            }
            if inputs.iter().all(|x| x.abs() <= f32::MAX as f64) {
                for c in [c32.front, c32.front_secondary, c32.back, c32.back_secondary] {
                    assert!(!c.iter().any(|x| x.is_nan()), "f32 NaN from float inputs: {c:?}");
                }
            }
        }
        let general = Engine::<f32>::new(s).unwrap().light(&s.vertex);
        let fast = Lighter::new(s, EvalOptions::default()).unwrap().light_vertex(&s.vertex);
        let same = |a: [f32; 4], b: [f32; 4]| {
            a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits() || x.is_nan() && y.is_nan())
        };
        assert!(same(fast[0].primary, general.front.primary), "{:?} vs {:?}", fast[0], general.front);
        assert!(same(fast[1].primary, general.back.primary), "{:?} vs {:?}", fast[1], general.back);
    }
});
