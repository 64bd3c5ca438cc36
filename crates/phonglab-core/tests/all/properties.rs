//! Property tests over random scenes:
//! - finite inputs, however extreme (magnitudes 1e-30..1e30, zero vectors, w = 0), never give NaN,
//!   and clamped colours lie in [0, 1];
//! - f32 agrees with f64 to 1e-4 where the inputs are well conditioned;
//! - moving the object, the lights and the eye by one rigid motion leaves the colour unchanged
//!   (local viewer).

use crate::common;

use glam::{DMat4, DQuat, DVec3, DVec4};
use phonglab_core::scene::{ColorMaterial, ColorMaterialMode, Face};
use phonglab_core::{
    Engine, Light, LightModel, LightPlacement, Material, NormalMode, Real, RuleSet, Rules, Scene, SpecularModel, Vertex,
};
use proptest::prelude::*;

/// A finite number of any size: 0, or +-10^[-30, 30].
fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        6 => (-30.0f64..30.0, any::<bool>()).prop_map(|(e, neg)| if neg { -(10f64.powf(e)) } else { 10f64.powf(e) }),
        3 => -10.0f64..10.0,
    ]
}

fn wild3() -> impl Strategy<Value = DVec3> {
    (wild(), wild(), wild()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn colour(lo: f64, hi: f64) -> impl Strategy<Value = DVec4> {
    (lo..hi, lo..hi, lo..hi, 0.0..1.0f64).prop_map(|(r, g, b, a)| DVec4::new(r, g, b, a))
}

fn rigid() -> impl Strategy<Value = DMat4> {
    (
        -1.0f64..1.0,
        -1.0f64..1.0,
        -1.0f64..1.0,
        0.0f64..std::f64::consts::TAU,
        -20.0f64..20.0,
        -20.0f64..20.0,
        -20.0f64..20.0,
    )
        .prop_map(|(ax, ay, az, angle, tx, ty, tz)| {
            let axis = DVec3::new(ax, ay, az).try_normalize().unwrap_or(DVec3::Y);
            DMat4::from_rotation_translation(DQuat::from_axis_angle(axis, angle), DVec3::new(tx, ty, tz))
        })
}

fn wild_matrix() -> impl Strategy<Value = DMat4> {
    (rigid(), -3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0, wild3()).prop_map(|(r, sx, sy, sz, t)| {
        DMat4::from_translation(t) * r * DMat4::from_scale(DVec3::new(10f64.powf(sx), 10f64.powf(sy), 10f64.powf(sz)))
    })
}

fn material(lo: f64, hi: f64) -> impl Strategy<Value = Material> {
    (colour(lo, hi), colour(lo, hi), colour(lo, hi), colour(lo, hi), 0.0..=128.0f64).prop_map(
        |(ambient, diffuse, specular, emission, shininess)| Material {
            ambient,
            diffuse,
            specular,
            emission,
            shininess,
        },
    )
}

fn placement() -> impl Strategy<Value = LightPlacement> {
    prop_oneof![Just(LightPlacement::Eye), Just(LightPlacement::World), Just(LightPlacement::Object)]
}

fn wild_light() -> impl Strategy<Value = Light> {
    common::light_from(
        (colour(-1.0, 2.0), colour(-1.0, 2.0), colour(-1.0, 2.0)),
        (wild3(), prop_oneof![Just(0.0), Just(1.0), wild()]).prop_map(|(p, w)| p.extend(w)),
        wild3(),
        prop_oneof![Just(180.0), 0.0..=90.0f64],
        0.0..=128.0f64,
        (
            prop_oneof![Just(0.0), 0.0..10.0f64],
            prop_oneof![Just(0.0), 0.0..1.0f64],
            prop_oneof![Just(0.0), 0.0..0.1f64],
        )
            .prop_map(|(a, b, c)| [a, b, c]),
        placement(),
    )
}

fn rules() -> impl Strategy<Value = Rules> {
    (prop::sample::select(RuleSet::ALL.to_vec()), prop::sample::select(SpecularModel::ALL.to_vec()))
        .prop_map(|(set, specular)| Rules { set, specular })
}

fn normal_mode() -> impl Strategy<Value = NormalMode> {
    prop::sample::select(vec![NormalMode::AsIs, NormalMode::Normalize, NormalMode::Rescale])
}

fn light_model() -> impl Strategy<Value = LightModel> {
    (colour(-1.0, 2.0), any::<bool>(), any::<bool>(), any::<bool>()).prop_map(
        |(ambient, local_viewer, two_sided, separate_specular)| LightModel {
            ambient,
            local_viewer,
            two_sided,
            separate_specular,
        },
    )
}

prop_compose! {
    fn wild_scene()(
        light_model in light_model(),
        lights in prop::collection::vec(wild_light(), 0..=8),
        material in material(-1.0, 2.0),
        back in prop::option::of(material(-1.0, 2.0)),
        color_material in prop::option::of((0..3usize, 0..5usize, colour(-1.0, 2.0))),
        eye_from_world in wild_matrix(),
        world_from_object in wild_matrix(),
        normal_mode in normal_mode(),
        rules in rules(),
        position in (wild3(), prop_oneof![Just(1.0), Just(0.0), wild()]),
        normal in wild3(),
    ) -> Scene {
        Scene {
            light_model, lights, material, back_material: back,
            color_material: color_material.map(|(face, mode, color)| ColorMaterial {
                face: [Face::Front, Face::Back, Face::FrontAndBack][face],
                mode: ColorMaterialMode::ALL[mode],
                color,
            }),
            eye_from_world, world_from_object, normal_mode, rules,
            vertex: Vertex { position: position.0.extend(position.1), normal },
        }
    }
}

fn check_finite<S: Real>(scene: &Scene) -> Result<(), TestCaseError> {
    let lit = Engine::<S>::light_scene_vertex(scene).map_err(|e| TestCaseError::fail(e.to_string()))?;
    for side in [lit.front, lit.back] {
        for c in [side.primary, side.secondary] {
            prop_assert!(c.iter().all(|x| !x.is_nan()), "{} NaN: {:?}\nlimits {:?}", S::NAME, c, lit.all_limits());
        }
        for c in [side.primary_clamped(), side.secondary_clamped()] {
            prop_assert!(c.iter().all(|x| (S::ZERO..=S::ONE).contains(x)), "{} clamped out of [0,1]: {:?}", S::NAME, c);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn finite_scenes_never_give_nan(scene in wild_scene()) {
        check_finite::<f32>(&scene)?;
        check_finite::<f64>(&scene)?;
    }
}

// ---- f32 against f64 on well-conditioned scenes ----

fn tame3(r: f64) -> impl Strategy<Value = DVec3> {
    (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn tame_light() -> impl Strategy<Value = Light> {
    common::light_from(
        (colour(0.0, 1.0), colour(0.0, 1.0), colour(0.0, 1.0)),
        (tame3(10.0), any::<bool>()).prop_map(|(p, positional)| p.extend(if positional { 1.0 } else { 0.0 })),
        tame3(1.0),
        prop_oneof![Just(180.0), 5.0..=90.0f64],
        0.0..=128.0f64,
        (0.2..2.0f64, 0.0..0.5f64, 0.0..0.1f64).prop_map(|(a, b, c)| [a, b, c]),
        placement(),
    )
}

prop_compose! {
    fn tame_scene()(
        light_model in light_model(),
        lights in prop::collection::vec(tame_light(), 1..=3),
        material in material(0.0, 1.0),
        eye_from_world in rigid(),
        world_from_object in rigid(),
        normal_mode in normal_mode(),
        rules in rules(),
        position in tame3(5.0),
        normal in tame3(1.0),
    ) -> Scene {
        Scene {
            light_model, lights, material, back_material: None, color_material: None,
            eye_from_world, world_from_object, normal_mode, rules,
            vertex: Vertex { position: position.extend(1.0), normal },
        }
    }
}

/// Well conditioned: no light within 0.05 of the vertex, the normal not tiny, no cosine
/// that switches a term (n.L for f, the worksheet's cos beta, the spot cosine against its
/// cutoff) within 1e-3 of its switch, |L + V| not near 0, and no exponent below 1 (x^0.5
/// has unbounded slope at 0), and a result f32 can represent.
fn well_conditioned(scene: &Scene) -> bool {
    let Ok(lit) = Engine::<f64>::light_scene_vertex(scene) else { return false };
    if scene.vertex.normal.length() < 0.1 || scene.material.shininess < 1.0 {
        return false;
    }
    // Unnormalised normals raised to powers up to 128 can leave f32's range (3.4e38),
    // in the result or in a term before att * spot scales it back (2.7^97 = 1.5e42 times a
    // spot factor of 6e-34): f32 then holds inf, as OpenGL would, not a disagreement.
    let huge = |v: glam::DVec3| v.abs().max_element() > 1e30;
    if lit.front.primary.iter().chain(&lit.back.primary).chain(&lit.front.secondary).any(|x| x.abs() > 1e30)
        || lit.lights().iter().any(|t| [t.front, t.back].iter().any(|s| huge(s.diffuse) || huge(s.specular)))
    {
        return false;
    }
    let gate_on_cos = scene.rules.set == RuleSet::Worksheet;
    let sides = if scene.light_model.two_sided { 2 } else { 1 };
    lit.lights().iter().zip(&scene.lights).all(|(t, l)| {
        let side_ok =
            |s: &phonglab_core::SideTerms<f64>| s.n_dot_l.abs() > 1e-3 && (!gate_on_cos || s.spec_cos.abs() > 1e-3);
        t.distance.is_none_or(|d| d > 0.05)
            && [t.front, t.back][..sides].iter().all(side_ok)
            && (!t.spot.active || ((t.spot.cos_angle - t.spot.cos_cutoff).abs() > 1e-3 && l.spot_exponent >= 1.0))
            && (scene.rules.specular == SpecularModel::Phong || t.h.length() > 0.5 && (t.l + lit.v).length() > 0.1)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn f32_agrees_with_f64_when_well_conditioned(scene in tame_scene()) {
        prop_assume!(well_conditioned(&scene));
        let a = Engine::<f32>::light_scene_vertex(&scene).unwrap();
        let b = Engine::<f64>::light_scene_vertex(&scene).unwrap();
        for (x, y) in [(a.front.primary, b.front.primary), (a.front.secondary, b.front.secondary), (a.back.primary, b.back.primary)] {
            for k in 0..4 {
                let (x, y) = (x[k] as f64, y[k]);
                prop_assert!((x - y).abs() <= 1e-4 * y.abs().max(1.0), "f32 {x} vs f64 {y}");
            }
        }
    }

    #[test]
    fn a_rigid_motion_of_everything_leaves_the_colour_unchanged(scene in tame_scene(), motion in rigid()) {
        let mut scene = scene;
        scene.light_model.local_viewer = true;
        // Move the whole world by `motion`: the object and world-fixed lights with it, and the
        // eye too, so the view matrix becomes V motion^-1. Eye- and object-fixed lights follow.
        let mut moved = scene.clone();
        moved.world_from_object = motion * scene.world_from_object;
        moved.eye_from_world = scene.eye_from_world * motion.inverse();
        for l in moved.lights.iter_mut().filter(|l| l.placement == LightPlacement::World) {
            l.position = motion * l.position;
            l.spot_direction = motion.transform_vector3(l.spot_direction);
        }
        let a = Engine::<f64>::light_scene_vertex(&scene).unwrap();
        let b = Engine::<f64>::light_scene_vertex(&moved).unwrap();
        let a32 = Engine::<f32>::light_scene_vertex(&scene).unwrap();
        let b32 = Engine::<f32>::light_scene_vertex(&moved).unwrap();
        let conditioned = well_conditioned(&scene);
        for k in 0..4 {
            let (x, y) = (a.front.primary[k], b.front.primary[k]);
            prop_assert!((x - y).abs() <= 1e-9 * y.abs().max(1.0) || !conditioned, "f64 {x} vs {y}");
            if conditioned {
                let (x, y) = (a32.front.primary[k] as f64, b32.front.primary[k] as f64);
                prop_assert!((x - y).abs() <= 1e-4 * y.abs().max(1.0), "f32 {x} vs {y}");
            }
        }
        // Whatever the conditioning, the eye-space geometry the engine sees is the same.
        prop_assert!((a.pos_in_eye - b.pos_in_eye).length() <= 1e-9 * a.pos_in_eye.length().max(1.0));
    }
}

/// Found by fuzzing (scene_file): a normal of length 5.5 left as is, with the Phong demo's
/// exponent 100, makes n.H = 5.1 and a specular term of 2.6e70. Exact pow keeps f64 finite;
/// llvmpipe's pow is f32 arithmetic (it emulates Mesa), so there it overflows to +infinity,
/// as in Mesa, and never to NaN.
#[test]
fn a_long_normal_with_a_high_exponent_overflows_only_in_f32_arithmetic() {
    let mut s = phonglab_core::presets::phong_demo();
    s.rules = Rules::OPENGL;
    s.light_model.local_viewer = false;
    s.normal_mode = NormalMode::AsIs;
    s.eye_from_world = DMat4::IDENTITY;
    // The fuzzer's scene: the demo as first written (a white highlight, the vertex facing
    // the light).
    s.material.specular = glam::DVec4::new(0.5, 0.5, 0.5, 1.0);
    s.vertex.position = glam::DVec4::new(-0.22360679774997896, 0.0, -0.4472135954999579, 1.0);
    s.vertex.normal = DVec3::new(-5.447_213_595_499_958, 0.0, -0.894_427_190_999_915_9);
    let exact = Engine::<f64>::new(&s).unwrap().light(&s.vertex).front.primary;
    assert!((exact[0] / 2.6417625e70 - 1.0).abs() < 1e-7, "{exact:?}");
    let llvm = Engine::<f64>::with_options(&s, phonglab_core::EvalOptions::with_pow(phonglab_core::PowFn::Llvmpipe))
        .unwrap()
        .light(&s.vertex)
        .front
        .primary;
    assert!(llvm[..3].iter().all(|c| *c == f64::INFINITY), "{llvm:?}");
}
