//! The specialised evaluator gives the general engine's answer bit for bit (f32): on every
//! public case, and on random scenes lit in batches.

use crate::common;

use glam::{DMat4, DQuat, DVec3, DVec4, Vec3};
use phonglab_core::lighter::{Lighter, Lit};
use phonglab_core::{
    Engine, EvalOptions, Light, LightPlacement, Material, NormalMode, PowFn, RuleSet, Rules, Scene, SpecularModel,
    Vertex,
};
use proptest::prelude::*;

fn bits(c: [f32; 4]) -> [u32; 4] {
    c.map(f32::to_bits)
}

fn general(scene: &Scene, options: EvalOptions, v: &Vertex) -> [Lit; 2] {
    let lit = Engine::<f32>::with_options(scene, options).unwrap().light(v);
    [
        Lit { primary: lit.front.primary, secondary: lit.front.secondary },
        Lit { primary: lit.back.primary, secondary: lit.back.secondary },
    ]
}

fn same(a: &[Lit; 2], b: &[Lit; 2]) -> bool {
    a.iter().zip(b).all(|(x, y)| bits(x.primary) == bits(y.primary) && bits(x.secondary) == bits(y.secondary))
}

#[test]
fn every_public_case_bit_for_bit() {
    let mut checked = 0;
    for c in common::public_cases() {
        for pow in PowFn::ALL {
            let options = EvalOptions::with_pow(pow);
            let Ok(l) = Lighter::new(&c.scene, options) else { continue }; // the refused cases
            let s = l.light_vertex(&c.scene.vertex);
            let g = general(&c.scene, options, &c.scene.vertex);
            assert!(same(&s, &g), "{} {pow:?}:\n  specialised {s:?}\n  general     {g:?}", c.id);
            checked += 1;
        }
    }
    assert_eq!(checked, 3 * (346 - 4));
}

fn colour(lo: f64, hi: f64) -> impl Strategy<Value = DVec4> {
    (lo..hi, lo..hi, lo..hi, 0.0..1.0f64).prop_map(|(r, g, b, a)| DVec4::new(r, g, b, a))
}

fn v3(r: f64) -> impl Strategy<Value = DVec3> {
    (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn light() -> impl Strategy<Value = Light> {
    common::light_from(
        (colour(-0.5, 1.5), colour(-0.5, 1.5), prop_oneof![Just(DVec4::new(0.0, 0.0, 0.0, 1.0)), colour(0.0, 1.0)]),
        (v3(10.0), prop_oneof![Just(0.0), Just(1.0), 0.5..2.0f64]).prop_map(|(p, w)| p.extend(w)),
        v3(1.0),
        prop_oneof![Just(180.0), 0.0..=90.0f64],
        0.0..=128.0f64,
        prop_oneof![Just([1.0, 0.0, 0.0]), (0.0..2.0f64, 0.0..0.5f64, 0.0..0.1f64).prop_map(|(a, b, c)| [a, b, c])],
        prop_oneof![
            Just(LightPlacement::Eye),
            Just(LightPlacement::World),
            Just(LightPlacement::Object),
            // A placement matrix with any last row: w can go to 0 or away from it.
            (prop::array::uniform16(-2.0..2.0f64), prop::sample::select(vec![0.0, 1.0])).prop_map(|(m, k)| {
                let mut m = DMat4::from_cols_array(&m);
                if k == 0.0 {
                    m = m.transpose();
                    m.w_axis = DVec4::ZERO;
                    m = m.transpose(); // last row (0, 0, 0, 0)
                }
                LightPlacement::Matrix(m)
            }),
        ],
    )
}

fn material() -> impl Strategy<Value = Material> {
    (colour(0.0, 1.0), colour(0.0, 1.0), colour(0.0, 1.0), colour(0.0, 0.3), prop_oneof![Just(0.0), 0.0..=128.0f64])
        .prop_map(|(ambient, diffuse, specular, emission, shininess)| Material {
            ambient,
            diffuse,
            specular,
            emission,
            shininess,
        })
}

fn modelview() -> impl Strategy<Value = DMat4> {
    (v3(1.0), 0.0..6.3f64, v3(5.0), prop_oneof![Just(1.0), 0.2..3.0f64]).prop_map(|(axis, angle, t, s)| {
        let axis = axis.try_normalize().unwrap_or(DVec3::Y);
        DMat4::from_scale_rotation_translation(DVec3::splat(s), DQuat::from_axis_angle(axis, angle), t)
    })
}

prop_compose! {
    fn scene()(
        lights in prop::collection::vec(light(), 0..=4),
        material in material(),
        back in prop::option::of(material()),
        eye_from_world in modelview(),
        world_from_object in modelview(),
        normal_mode in prop::sample::select(vec![NormalMode::AsIs, NormalMode::Normalize, NormalMode::Rescale]),
        set in prop::sample::select(RuleSet::ALL.to_vec()),
        specular in prop::sample::select(SpecularModel::ALL.to_vec()),
        flags in (any::<bool>(), any::<bool>(), any::<bool>()),
        ambient in colour(0.0, 0.5),
    ) -> Scene {
        let mut s = Scene {
            lights, material, back_material: back, eye_from_world, world_from_object, normal_mode,
            rules: Rules { set, specular }, ..Scene::default()
        };
        s.light_model.ambient = ambient;
        (s.light_model.local_viewer, s.light_model.two_sided, s.light_model.separate_specular) = flags;
        s
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn random_scenes_in_batches_bit_for_bit(
        scene in scene(),
        pow in prop::sample::select(PowFn::ALL.to_vec()),
        verts in prop::collection::vec((v3(3.0), prop_oneof![Just(DVec3::ZERO), v3(1.0)]), 1..150),
    ) {
        let options = EvalOptions::with_pow(pow);
        let l = Lighter::new(&scene, options).unwrap();
        let positions: Vec<Vec3> = verts.iter().map(|(p, _)| p.as_vec3()).collect();
        let normals: Vec<Vec3> = verts.iter().map(|(_, n)| n.as_vec3()).collect();
        let mut front = vec![Lit::default(); verts.len()];
        let mut back = vec![Lit::default(); verts.len()];
        l.light_batch(&positions, &normals, &mut front, Some(&mut back));
        for i in 0..verts.len() {
            let v = Vertex { position: positions[i].as_dvec3().extend(1.0), normal: normals[i].as_dvec3() };
            let g = general(&scene, options, &v);
            let s = [front[i], if scene.light_model.two_sided { back[i] } else { front[i] }];
            prop_assert!(same(&s, &g), "vertex {i}:\n  specialised {s:?}\n  general     {g:?}");
        }
    }
}

/// The benchmark scenes take the fast paths (directional; positional; positional with
/// spots), and so do spots whose cones cut the sphere (the cross-product test under 45
/// degrees, the cosine test above): each of 4096 sphere points bit for bit.
#[test]
fn the_fast_paths_bit_for_bit() {
    use phonglab_core::presets::LightingBench;
    let (positions, normals) = phonglab_core::presets::sphere_points(4096);
    let mut scenes: Vec<(String, Scene, bool)> =
        LightingBench::ALL.iter().map(|b| (b.name().to_owned(), b.scene(), false)).collect();
    for (cutoff, closer) in [(8.0, 1.0), (50.0, 0.3)] {
        let mut s = LightingBench::EightSpots.scene();
        s.lights.truncate(2);
        for l in &mut s.lights {
            l.spot_cutoff = cutoff;
            l.position = (l.position.truncate() * closer).extend(1.0);
        }
        scenes.push((format!("spots cut off at {cutoff}"), s, true));
    }
    // Past robust::unscaled_is_exact's range, so L and V take normalize3's scaling: a light
    // 1e130 away, and a vertex shrunk to 1e-125 (P's x and y below 2^-400).
    let mut far = LightingBench::PositionalLocal.scene();
    far.lights[0].position = DVec4::new(1e130, -3e129, 2e130, 1.0);
    scenes.push(("a light 1e130 away".into(), far, false));
    let mut tiny = LightingBench::PositionalLocal.scene();
    tiny.world_from_object = DMat4::from_scale(DVec3::splat(1e-125));
    scenes.push(("vertices shrunk to 1e-125".into(), tiny, false));
    for (name, scene, partial) in scenes {
        for pow in PowFn::ALL {
            let options = EvalOptions::with_pow(pow);
            let l = Lighter::new(&scene, options).unwrap();
            let mut front = vec![Lit::default(); positions.len()];
            l.light_batch(&positions, &normals, &mut front, None);
            let mut dark = 0;
            for i in 0..positions.len() {
                let v = Vertex { position: positions[i].as_dvec3().extend(1.0), normal: normals[i].as_dvec3() };
                let g = general(&scene, options, &v);
                assert!(same(&[front[i], front[i]], &g), "{name} {pow:?} vertex {i}: {:?} vs {g:?}", front[i]);
                // Outside every cone only the scene's ambient is left: 0.2 x bronze's 0.2125.
                dark += usize::from(front[i].primary[0] <= 0.0425 + 1e-6);
            }
            if partial {
                assert!(dark > 100 && dark < positions.len() - 100, "{name}: {dark} vertices outside every cone");
            }
        }
    }
}

/// Found by fuzzing (glref_cases): a light placed under a matrix whose last row is zero is
/// positional in object space but directional in eye space. The plan must follow the
/// engine (eye space), or it folds no half vector and drops the specular term.
#[test]
fn a_placement_that_changes_w_is_planned_as_the_engine_lights_it() {
    let mut scene = phonglab_core::presets::LightingBench::Directional.scene();
    scene.material.shininess = 8.0;
    let mut to_infinity = DMat4::from_rotation_x(0.4).transpose();
    to_infinity.w_axis = DVec4::ZERO;
    let to_infinity = to_infinity.transpose(); // last row (0, 0, 0, 0)
    // And the other way: w' = z turns (2, 3, 1, 0) into a point at (2, 3, 1).
    let from_infinity = DMat4::from_cols(DVec4::X, DVec4::Y, DVec4::new(0.0, 0.0, 1.0, 1.0), DVec4::ZERO);
    for (placement, position) in
        [(to_infinity, DVec4::new(2.0, 3.0, 4.0, 1.0)), (from_infinity, DVec4::new(2.0, 3.0, 1.0, 0.0))]
    {
        scene.lights[0].placement = LightPlacement::Matrix(placement);
        scene.lights[0].position = position;
        let key = phonglab_core::plan::Key::of(&scene, EvalOptions::default());
        assert_eq!(key.lights[0].positional, !scene.light_is_directional(&scene.lights[0]));
        let (positions, normals) = phonglab_core::presets::sphere_points(512);
        let l = Lighter::new(&scene, EvalOptions::default()).unwrap();
        let mut front = vec![Lit::default(); positions.len()];
        l.light_batch(&positions, &normals, &mut front, None);
        let mut lit_specular = 0;
        for i in 0..positions.len() {
            let v = Vertex { position: positions[i].as_dvec3().extend(1.0), normal: normals[i].as_dvec3() };
            let g = general(&scene, EvalOptions::default(), &v);
            assert!(same(&[front[i], front[i]], &g), "vertex {i}: {:?} vs {g:?}", front[i]);
            lit_specular += usize::from(g[0].primary[2] > 0.3);
        }
        assert!(lit_specular > 0, "the highlight is there");
    }
}

/// A scene that switches on every key bit: a positional spotlight with attenuation, a
/// local viewer, two sides with a back material, emission, a scaled object and
/// GL_NORMALIZE.
fn everything_on() -> Scene {
    let mut s = Scene {
        material: Material {
            emission: DVec4::new(0.1, 0.0, 0.05, 1.0),
            specular: DVec4::new(0.5, 0.4, 0.3, 1.0),
            shininess: 20.0,
            ..Material::default()
        },
        back_material: Some(Material { shininess: 7.0, specular: DVec4::ONE, ..Material::default() }),
        color_material: None,
        eye_from_world: DMat4::from_translation(DVec3::new(0.0, 0.0, -4.0)),
        world_from_object: DMat4::from_scale(DVec3::splat(1.5)),
        normal_mode: NormalMode::Normalize,
        ..Scene::default()
    };
    s.light_model.local_viewer = true;
    s.light_model.two_sided = true;
    s.lights = vec![Light {
        position: DVec4::new(1.0, 2.0, 3.0, 1.0),
        spot_direction: DVec3::new(-1.0, -2.0, -3.0),
        spot_cutoff: 40.0,
        spot_exponent: 3.0,
        attenuation: [1.0, 0.1, 0.01],
        ..Light::gl_default(0)
    }];
    s
}

/// A key bit switched off: its name, the change to [`everything_on`], and the stages it
/// leaves out.
type Bit = (&'static str, fn(&mut Scene), fn(&phonglab_core::plan::Stage) -> bool);

/// Each key bit in turn ("nothing" first, as the control).
fn key_bits() -> [Bit; 13] {
    use phonglab_core::plan::Stage;
    use phonglab_core::scene::Side;
    [
        ("nothing", |_| {}, |_| false),
        (
            // The object unscaled: the modelview is the view's translation alone.
            "translation modelview",
            |s| s.world_from_object = DMat4::IDENTITY,
            |st| matches!(st, Stage::TransformPosition | Stage::TransformPositionProjective),
        ),
        (
            // The last row (0, 0, 0.05, 1): w = 1 + 0.075 z varies over the sphere.
            "projective modelview",
            |s| s.world_from_object.z_axis.w = 0.05,
            |st| matches!(st, Stage::TransformPosition),
        ),
        (
            "directional",
            |s| s.lights[0].position.w = 0.0,
            |st| matches!(st, Stage::LightVector(_) | Stage::Attenuate(_) | Stage::SpotCone(_) | Stage::SpotPower(_)),
        ),
        ("no attenuation", |s| s.lights[0].attenuation = [1.0, 0.0, 0.0], |st| matches!(st, Stage::Attenuate(_))),
        ("no spot", |s| s.lights[0].spot_cutoff = 180.0, |st| matches!(st, Stage::SpotCone(_) | Stage::SpotPower(_))),
        (
            "no specular",
            |s| {
                s.material.specular = DVec4::new(0.0, 0.0, 0.0, 1.0);
                s.back_material.as_mut().unwrap().specular = DVec4::new(0.0, 0.0, 0.0, 1.0);
            },
            |st| {
                matches!(
                    st,
                    Stage::Halfway(_)
                        | Stage::HalfwayConstant(_)
                        | Stage::Reflect(_)
                        | Stage::SpecularCosine(..)
                        | Stage::Power(..)
                )
            },
        ),
        (
            "shininess 0",
            |s| {
                s.material.shininess = 0.0;
                s.back_material.as_mut().unwrap().shininess = 0.0;
            },
            |st| matches!(st, Stage::Power(..)),
        ),
        (
            "one-sided",
            |s| s.light_model.two_sided = false,
            |st| {
                matches!(
                    st,
                    Stage::DiffuseCosine(_, Side::Back)
                        | Stage::SpecularCosine(_, Side::Back, _)
                        | Stage::Power(_, Side::Back)
                        | Stage::Sum(_, Side::Back, _)
                )
            },
        ),
        (
            "normals as they are",
            |s| s.normal_mode = NormalMode::AsIs,
            |st| matches!(st, Stage::NormalizeNormal | Stage::RescaleNormal),
        ),
        (
            "rescale with factor 1",
            |s| {
                s.normal_mode = NormalMode::Rescale;
                s.world_from_object = DMat4::IDENTITY;
            },
            |st| matches!(st, Stage::NormalizeNormal | Stage::RescaleNormal),
        ),
        (
            "no emission, no scene ambient",
            |s| {
                s.material.emission = DVec4::new(0.0, 0.0, 0.0, 1.0);
                s.back_material.as_mut().unwrap().emission = DVec4::new(0.0, 0.0, 0.0, 1.0);
                s.light_model.ambient = DVec4::new(0.0, 0.0, 0.0, 1.0);
            },
            |st| matches!(st, Stage::SceneColor),
        ),
        (
            "infinite viewer, directional",
            |s| {
                s.light_model.local_viewer = false;
                s.lights[0].position.w = 0.0;
            },
            |st| {
                matches!(
                    st,
                    Stage::ViewVector(_)
                        | Stage::Halfway(_)
                        | Stage::LightVector(_)
                        | Stage::TransformPosition
                        | Stage::TransformPositionProjective
                )
            },
        ),
    ]
}

/// The position effect the panel shows says which transform ran: the division by w only for
/// a projective modelview, `P = p + t` exactly where the modelview is a translation.
fn position_effect_is_what_ran(name: &str, l: &Lighter, trace: &[phonglab_core::plan::Stage], scene: &Scene) {
    use phonglab_core::plan::{EffectKind, Stage};
    let position = l.key().effects().into_iter().find(|e| e.kind == EffectKind::Position).unwrap();
    let projective = trace.contains(&Stage::TransformPositionProjective);
    assert_eq!(position.why.contains("division by w is skipped"), trace.contains(&Stage::TransformPosition));
    assert_eq!(position.why.contains("projective"), projective, "{name}: {position}");
    assert_eq!(projective, name == "projective modelview", "{name}: the division by w runs only there");
    let translation = trace.contains(&Stage::TranslatePosition);
    assert_eq!(position.why.contains("is a translation"), translation, "{name}: {position}");
    let m = scene.eye_from_object();
    let is_translation = m.row(3) == DVec4::W && glam::DMat3::from_mat4(m) == glam::DMat3::IDENTITY;
    assert_eq!(translation, is_translation, "{name}: P = p + t where the modelview is a translation");
    if name == "translation modelview" {
        assert!(translation, "the bit that makes the modelview a translation");
    }
}

/// What the panel says is skipped ran no stage of its kind.
fn skipped_effects_ran_nothing(name: &str, l: &Lighter, trace: &[phonglab_core::plan::Stage]) {
    use phonglab_core::plan::{EffectKind, Stage};
    use phonglab_core::scene::Side;
    for eff in l.key().effects().iter().filter(|e| !e.on) {
        let ran = trace.iter().any(|st| match eff.kind {
            EffectKind::Normalisation => matches!(st, Stage::NormalizeNormal | Stage::RescaleNormal),
            EffectKind::Position => {
                matches!(st, Stage::TransformPosition | Stage::TransformPositionProjective | Stage::TranslatePosition)
            }
            EffectKind::ViewVector => matches!(st, Stage::ViewVector(_)),
            EffectKind::SceneColor => matches!(st, Stage::SceneColor),
            EffectKind::BackSide => matches!(st, Stage::Sum(_, Side::Back, _)),
            EffectKind::LightVector => matches!(st, Stage::LightVector(_)),
            EffectKind::Attenuation => matches!(st, Stage::Attenuate(_)),
            EffectKind::Spotlight => matches!(st, Stage::SpotCone(_) | Stage::SpotPower(_)),
            EffectKind::HalfwayOrReflection => matches!(st, Stage::Halfway(_) | Stage::Reflect(_)),
            EffectKind::SpecularPower => matches!(st, Stage::Power(..)),
        });
        assert!(!ran, "{name}: the panel says {eff} but a stage of it ran");
    }
}

/// Every key bit switched off in turn from a scene that uses everything: the stages the
/// evaluator runs (traced) are exactly the compiled program, chunk after chunk; each stage
/// the key leaves out never runs; each effect the panel reports as skipped ran no stage of
/// its own; and the colours stay the general engine's, bit for bit.
#[test]
fn skipped_stages_never_run_for_any_key_bit() {
    use phonglab_core::plan::Stage;
    use phonglab_core::scene::{LightId, Side};
    let (positions, normals) = phonglab_core::presets::sphere_points(300);
    for (name, change, left_out) in key_bits() {
        let mut scene = everything_on();
        change(&mut scene);
        for model in SpecularModel::ALL {
            scene.rules.specular = model;
            let options = EvalOptions::default();
            let l = Lighter::new(&scene, options).unwrap();
            let program = l.program().stages.clone();
            let (lit, trace) = l.light_batch_traced(&positions, &normals);
            // 300 vertices in chunks of CHUNK (the last one partial): the program once a chunk.
            let chunks = positions.len().div_ceil(phonglab_core::lighter::CHUNK);
            assert_eq!(trace, program.repeat(chunks), "{name}: the evaluator runs exactly the program");
            if name != "nothing" {
                assert!(!trace.iter().any(left_out), "{name} {model:?}: a left-out stage ran: {program:?}");
            }
            assert!(program.iter().any(|s| matches!(s, Stage::Sum(LightId(0), Side::Front, _))));
            position_effect_is_what_ran(name, &l, &trace, &scene);
            skipped_effects_ran_nothing(name, &l, &trace);
            // And the colours are the general engine's.
            for (k, got) in lit.iter().enumerate().step_by(37) {
                let v = Vertex::from_f32(positions[k], normals[k]);
                let want = general(&scene, options, &v);
                assert!(same(got, &want), "{name} {model:?} vertex {k}: {got:?} vs {want:?}");
            }
        }
    }
}
