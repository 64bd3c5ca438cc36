//! Generated exercises: every one passes the hard-case screen and uses exactly the effects
//! asked for (read off the specialised plan's key), over 1000 seeds and every level; the
//! same seed gives the same exercises.

use phonglab_core::exercise::{Effect, Level, Spec, generate, screen};
use phonglab_core::plan::Key;
use phonglab_core::{EvalOptions, Rules};

#[test]
fn a_thousand_seeds_pass_the_screen_with_exactly_the_effects_asked() {
    let mut redraws = 0;
    for seed in 0..1000u64 {
        let level = Level::from_number((seed % 4) as u8 + 1).unwrap();
        let rules = if seed % 3 == 0 { Rules::OPENGL } else { Rules::WORKSHEET };
        let spec = Spec::level(level, rules);
        let ex = generate(seed, 1, &spec).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        let scene = &ex[0].doc.scene;
        assert_eq!(screen(scene, &spec), None, "seed {seed}");
        let mut got = Effect::of_key(&Key::of(scene, EvalOptions::default()));
        got.sort();
        let mut want = level.effects();
        want.sort();
        assert_eq!(got, want, "seed {seed} level {level:?}");
        // Nice numbers: integer vertex, normal and light coordinates.
        let v = scene.vertex.position;
        assert!([v.x, v.y, v.z].iter().all(|x| x.fract() == 0.0), "seed {seed}: {v:?}");
        for l in &scene.lights {
            assert!(l.position.to_array().iter().all(|x| x.fract() == 0.0), "seed {seed}: {:?}", l.position);
        }
        assert!(ex[0].key.steps.iter().all(|s| s.value.as_ref().is_none_or(|v| v.iter().all(|x| x.is_finite()))));
        redraws += ex[0].redraws;
    }
    println!("{redraws} draws set aside over 1000 exercises");
}

#[test]
fn chosen_effects_are_exactly_those_used() {
    let cases: [&[Effect]; 4] = [
        &[Effect::Positional, Effect::Spot],
        &[Effect::LocalViewer],
        &[Effect::Positional, Effect::Attenuation, Effect::TwoSided],
        &[Effect::SeveralLights],
    ];
    for effects in cases {
        let spec = Spec { effects: effects.to_vec(), rules: Rules::OPENGL };
        for ex in generate(11, 20, &spec).unwrap() {
            let mut got = Effect::of_key(&Key::of(&ex.doc.scene, EvalOptions::default()));
            got.sort();
            let mut want = effects.to_vec();
            want.sort();
            assert_eq!(got, want);
        }
    }
}

#[test]
fn the_same_seed_gives_the_same_exercises() {
    let spec = Spec::level(Level::Spotlight, Rules::WORKSHEET);
    let a = generate(42, 5, &spec).unwrap();
    let b = generate(42, 5, &spec).unwrap();
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.doc, y.doc);
        assert_eq!(x.key, y.key);
    }
    let c = generate(43, 5, &spec).unwrap();
    assert_ne!(a[0].doc.scene, c[0].doc.scene, "another seed, other exercises");
}

#[test]
fn the_screen_refuses_what_hinges_on_rounding() {
    use glam::{DVec3, DVec4};
    let spec = Spec { effects: vec![Effect::Positional, Effect::Attenuation], rules: Rules::WORKSHEET };
    let base = phonglab_core::presets::worksheet(1);
    assert_eq!(screen(&base, &spec), None, "the worksheet's own scene passes");
    // n.L exactly 0: the normal at right angles to the light.
    let mut s = base.clone();
    let p = s.vertex.position.truncate();
    let to_light = s.lights[0].position.truncate() - p;
    s.vertex.normal = to_light.normalize().any_orthonormal_vector();
    assert!(screen(&s, &spec).unwrap().contains("n.L"), "{:?}", screen(&s, &spec));
    // Lit from behind only: nothing to compute but the ambient.
    let mut s = base.clone();
    s.vertex.normal = -s.vertex.normal;
    assert!(screen(&s, &spec).unwrap().contains("unlit"), "{:?}", screen(&s, &spec));
    // The light on the vertex.
    let mut s = base.clone();
    s.lights[0].position = s.vertex.position;
    assert!(screen(&s, &spec).is_some());
    // The vertex on the cone's edge.
    let mut s = base.clone();
    let spot = Spec { effects: vec![Effect::Positional, Effect::Attenuation, Effect::Spot], rules: Rules::WORKSHEET };
    s.lights[0].spot_direction = -DVec3::Z;
    let to_vertex = (p - s.lights[0].position.truncate()).normalize();
    s.lights[0].spot_cutoff = to_vertex.dot(-DVec3::Z).acos().to_degrees();
    assert!(screen(&s, &spot).unwrap().contains("cone"), "{:?}", screen(&s, &spot));
    // Effects other than those asked.
    let mut s = base.clone();
    s.lights[0].position = DVec4::new(0.0, 0.0, 1.0, 0.0);
    assert!(screen(&s, &spec).unwrap().contains("uses"));
    // A sharp highlight seen near its peak: a power of 128 magnifies f32's rounding of
    // cos(beta) past 1e-6.
    let mut s = base.clone();
    s.material.shininess = 128.0;
    s.material.specular = DVec4::ONE;
    let lit = phonglab_core::Engine::<f64>::new(&s).unwrap().light(&s.vertex);
    let h = lit.lights()[0].h;
    s.vertex.normal = (h + h.any_orthonormal_vector() * 0.02).normalize();
    let why = screen(&s, &spec);
    assert!(why.as_deref().is_some_and(|w| w.contains("differ")), "{why:?}");
}

#[test]
fn every_keys_own_answers_check_right_with_carried_forward_inputs() {
    use phonglab_core::quiz::{check, score};
    for seed in 0..200u64 {
        let level = Level::from_number((seed % 4) as u8 + 1).unwrap();
        let rules = if seed % 2 == 0 { Rules::OPENGL } else { Rules::WORKSHEET };
        let ex = &generate(seed, 1, &Spec::level(level, rules)).unwrap()[0];
        let answers: Vec<Option<Vec<f64>>> = ex.key.steps.iter().map(|s| s.value.clone()).collect();
        for k in 0..ex.key.steps.len() {
            if let Some(v) = check(&ex.doc.scene, &ex.key, &answers, k) {
                assert!(
                    v.right,
                    "seed {seed} step {} {}: key {:?}, recomputed {:?}",
                    k + 1,
                    ex.key.steps[k].name,
                    ex.key.steps[k].value,
                    v.expected
                );
            }
        }
        let sc = score(&ex.doc.scene, &ex.key, &answers, &[]);
        assert_eq!((sc.right, sc.answered), (sc.asked, sc.asked), "seed {seed}");
    }
}

/// The numbers of a sheet's line `- NAME = [a b c d]` (the first such vector on the line).
fn sheet_vector(sheet: &str, name: &str) -> Vec<f64> {
    let at = sheet.find(&format!("{name} = [")).unwrap_or_else(|| panic!("{name} in {sheet}"));
    let rest = &sheet[at + name.len() + 4..];
    let inner = &rest[..rest.find(']').unwrap()];
    inner.split_whitespace().map(|x| x.parse().unwrap()).collect()
}

#[test]
fn a_sheet_writes_colours_as_the_worksheet_does_so_the_products_match_the_key() {
    for seed in 0..40u64 {
        let level = Level::from_number((seed % 4) as u8 + 1).unwrap();
        let ex = &generate(seed, 1, &Spec::level(level, Rules::WORKSHEET)).unwrap()[0];
        let sheet = phonglab_core::exercise::sheet_markdown(ex);
        let (lamb, mamb) = (sheet_vector(&sheet, "Lamb"), sheet_vector(&sheet, "matAmb"));
        assert_eq!((lamb[3], mamb[3]), (0.0, 0.0), "seed {seed}: colours are [r g b 0]");
        // The worksheet's element-wise product of the sheet's vectors is the key's Iamb.
        let product: Vec<f64> = lamb.iter().zip(&mamb).map(|(a, b)| a * b).collect();
        let iamb = ex.key.steps.iter().find(|s| s.name.starts_with("Iamb")).unwrap().value.clone().unwrap();
        for (p, k) in product.iter().zip(&iamb) {
            assert!((p - k).abs() < 1e-7, "seed {seed}: {product:?} against the key's {iamb:?}");
        }
        // Steps that do not apply are not asked: no spot factor without a spotlight.
        let spot = ex.doc.scene.lights.iter().any(phonglab_core::Light::is_spot);
        assert_eq!(sheet.contains("`spot"), spot, "seed {seed}");
    }
}
