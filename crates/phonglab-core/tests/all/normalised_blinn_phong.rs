//! Energy-conserving Blinn-Phong (`specular = "blinn-phong-normalised"`): the engine's
//! specular term against the formula written out here, independently of the engine, on
//! 1 000 random scenes in f32 and in f64; the specialised lighter against the general
//! engine, bit for bit; the plan's stage that carries it; and the worked calculation that
//! says it.

use glam::{DMat3, DMat4, DQuat, DVec3, DVec4};
use phonglab_core::explain::{Side, StepKind, explain};
use phonglab_core::lighter::Lighter;
use phonglab_core::plan::{Key, Program, SpecularTerm, Stage};
use phonglab_core::scene::LightId;
use phonglab_core::{
    Engine, EvalOptions, Light, LightPlacement, Material, NormalMode, Real, Rules, Scene, SpecularModel, Vec3Ops,
    Vertex,
};

const NORMALISED: Rules = Rules { specular: SpecularModel::BlinnPhongNormalised, ..Rules::OPENGL };

/// A fixed sequence of doubles in [0, 1) (xorshift64, the top 53 bits).
fn uniform(mut state: u64) -> impl FnMut() -> f64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A random scene under OpenGL's rules with energy-conserving Blinn-Phong: one light,
/// positional or directional, in front of the surface more often than not; a local or an
/// infinite viewer; a random material (shininess 0 to 128) and a rotated, moved modelview.
fn random_scene(next: &mut impl FnMut() -> f64) -> Scene {
    let mut r = |lo: f64, hi: f64| lo + (hi - lo) * next();
    let unit = |r: &mut dyn FnMut(f64, f64) -> f64| {
        DVec3::new(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0)).try_normalize().unwrap_or(DVec3::Z)
    };
    let normal = unit(&mut r);
    let vertex = DVec3::new(r(-5.0, 5.0), r(-5.0, 5.0), r(-5.0, 5.0));
    let towards = (normal + 0.8 * unit(&mut r)).try_normalize().unwrap_or(normal);
    let positional = r(0.0, 1.0) < 0.6;
    let position = if positional { (vertex + towards * r(2.0, 40.0)).extend(1.0) } else { towards.extend(0.0) };
    let colour = |r: &mut dyn FnMut(f64, f64) -> f64| DVec4::new(r(0.0, 1.0), r(0.0, 1.0), r(0.0, 1.0), 1.0);
    let light = Light {
        position,
        specular: colour(&mut r),
        diffuse: colour(&mut r),
        placement: LightPlacement::World,
        ..Light::gl_default(0)
    };
    let material = Material {
        specular: colour(&mut r),
        diffuse: colour(&mut r),
        shininess: if r(0.0, 1.0) < 0.05 { 0.0 } else { r(0.0, 128.0) },
        ..Material::default()
    };
    let turn = DQuat::from_axis_angle(unit(&mut r), r(-3.0, 3.0));
    let eye_from_world =
        DMat4::from_rotation_translation(turn, DVec3::new(r(-3.0, 3.0), r(-3.0, 3.0), r(-60.0, -20.0)));
    let mut scene = Scene {
        lights: vec![light],
        material,
        eye_from_world,
        normal_mode: NormalMode::Normalize,
        rules: NORMALISED,
        vertex: Vertex { position: vertex.extend(1.0), normal },
        ..Scene::default()
    };
    scene.light_model.local_viewer = r(0.0, 1.0) < 0.5;
    scene
}

/// The specular term of light 0 on the front side, written out from the definitions: N by
/// the inverse transpose, L to the light (or its direction), V to the viewer, H halfway,
/// OpenGL's f (no specular where n . L <= 0), and energy-conserving Blinn-Phong's
/// (n + 8) / (8 pi) on Blinn-Phong's s_cm s_cl max(n . H, 0)^n.
fn written_out(scene: &Scene) -> [f64; 3] {
    let m = scene.eye_from_world;
    let p = m.transform_point3(scene.vertex.position.truncate());
    let n = (DMat3::from_mat4(m).inverse().transpose() * scene.vertex.normal).normalize();
    let light = &scene.lights[0];
    let lp = m * light.position;
    let l = if lp.w == 0.0 { lp.truncate().normalize() } else { (lp.truncate() / lp.w - p).normalize() };
    let v = if scene.light_model.local_viewer { (-p).normalize() } else { DVec3::Z };
    let h = (l + v).normalize();
    if n.dot(l) <= 0.0 {
        return [0.0; 3];
    }
    let s = scene.material.shininess;
    let factor = (s + 8.0) / (8.0 * std::f64::consts::PI);
    let power = n.dot(h).max(0.0).powf(s);
    let product = scene.material.specular.truncate() * light.specular.truncate();
    (product * power * factor).to_array()
}

/// The engine's specular term of light 0 on the front side, in precision `S`.
fn engine_term<S: Real>(scene: &Scene) -> [f64; 3] {
    let lit = Engine::<S>::light_scene_vertex(scene).unwrap();
    lit.lights()[0].front.specular.to_dvec3().to_array()
}

fn assert_close(what: &str, got: [f64; 3], want: [f64; 3], rel: f64, abs: f64) {
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= rel * w.abs() + abs, "{what}: {got:?}, written out {want:?}");
    }
}

#[test]
fn the_engine_computes_the_formula_written_out_in_f32_and_f64() {
    let mut next = uniform(0x9e37_79b9_7f4a_7c15);
    let mut lit = 0;
    for k in 0..1000 {
        let scene = random_scene(&mut next);
        let want = written_out(&scene);
        lit += usize::from(want.iter().any(|x| *x > 1e-6));
        assert_close(&format!("case {k}, f64"), engine_term::<f64>(&scene), want, 1e-9, 1e-12);
        // f32: the cosine's rounding, raised to a power up to 128.
        assert_close(&format!("case {k}, f32"), engine_term::<f32>(&scene), want, 1e-3, 1e-6);
    }
    assert!(lit > 300, "only {lit} of 1 000 cases have a highlight to compare");
}

/// The normalisation is the only difference from Blinn-Phong: the term divided by
/// Blinn-Phong's is (n + 8) / (8 pi), to the last bits of f64.
#[test]
fn it_is_blinn_phong_times_its_factor() {
    let mut next = uniform(0x2545_f491_4f6c_dd1d);
    for k in 0..200 {
        let scene = random_scene(&mut next);
        let mut plain = scene.clone();
        plain.rules.specular = SpecularModel::BlinnPhong;
        let (a, b) = (engine_term::<f64>(&scene), engine_term::<f64>(&plain));
        let factor = (scene.material.shininess + 8.0) / (8.0 * std::f64::consts::PI);
        assert_close(&format!("case {k}"), a, b.map(|x| x * factor), 1e-15, 0.0);
    }
}

/// The specialised lighter gives the general engine's colours, bit for bit, over random
/// vertices of the random scenes.
#[test]
fn the_lighter_lights_as_the_engine_bit_for_bit() {
    let mut next = uniform(0xdead_beef_cafe_f00d);
    let (positions, normals) = phonglab_core::presets::sphere_points(200);
    for k in 0..50 {
        let mut scene = random_scene(&mut next);
        scene.light_model.two_sided = k % 2 == 1;
        let options = EvalOptions::default();
        let lighter = Lighter::new(&scene, options).unwrap();
        let mut front = vec![phonglab_core::lighter::Lit::default(); positions.len()];
        let mut back = front.clone();
        lighter.light_batch(&positions, &normals, &mut front, Some(&mut back));
        let engine = Engine::<f32>::with_options(&scene, options).unwrap();
        let bits = |c: [f32; 4]| c.map(f32::to_bits);
        for i in 0..positions.len() {
            let want = engine.light(&Vertex::from_f32(positions[i], normals[i]));
            assert_eq!(bits(front[i].primary), bits(want.front.primary), "case {k}, vertex {i}");
            if scene.light_model.two_sided {
                assert_eq!(bits(back[i].primary), bits(want.back.primary), "case {k}, vertex {i}, back");
            }
        }
    }
}

/// The plan says it: every light's Sum carries the normalised term, in the evaluator's
/// program and the worked one, and the stage list writes it.
#[test]
fn the_plan_carries_the_normalised_term() {
    let scene = random_scene(&mut uniform(7));
    let key = Key::of(&scene, EvalOptions::default());
    let normalised = Stage::Sum(LightId(0), Side::Front, SpecularTerm::Normalised);
    assert!(key.program().has(normalised) && Program::worked(&key).has(normalised));
    assert_eq!(normalised.to_string(), "Sum(0, 0, normalised)");
}

/// The worked calculation writes the factor in the specular step's formula, under the
/// worksheet's names, and its value is the engine's.
#[test]
fn explain_says_the_factor() {
    let scene = random_scene(&mut uniform(11));
    let lit = Engine::<f64>::light_scene_vertex(&scene).unwrap();
    let ex = explain(&scene, &lit, Side::Front);
    let step = ex.steps.iter().find(|s| s.kind == StepKind::Specular).unwrap();
    assert!(step.formula.contains("(ns + 8)/(8π)") && step.formula.contains("cosBeta"), "{}", step.formula);
    assert_eq!(step.value.as_ref().unwrap()[..3], lit.lights()[0].front.specular.to_array());
    assert!(ex.heading.contains("Normalised Blinn-Phong"), "{}", ex.heading);
}
