//! Ready-made scenes: the worksheet (with each of its five modelviews) and the Phong demo.

use glam::{DMat4, DVec3, DVec4};

use crate::model::materials;
use crate::model::rules::Rules;
use crate::model::scene::{Light, LightModel, LightPlacement, Material, NormalMode, Scene, Vertex};
use crate::model::transform::{phong_demo_eye_from_object, worksheet_modelview};
use crate::numerics::elementary;

/// The worksheet's vertex, in the 1024x768 window's centre-relative coordinates.
pub const WORKSHEET_VERTEX: DVec4 = DVec4::new(-512.0, -384.0, 0.0, 1.0);
/// The worksheet's light position.
pub const WORKSHEET_LIGHT: DVec4 = DVec4::new(0.0, 0.0, 90.0, 1.0);

/// The worksheet's bronze (the classic table's).
pub fn bronze() -> Material {
    materials::by_name("bronze").cloned().unwrap_or_default()
}

/// The worksheet's scene with modelview `mview{index}` (1..=5; other values give 5):
/// vertex (-512, -384, 0, 1), normal (0, 0, 1), a white light at (0, 0, 90, 1) with
/// attenuation (1, 0.0001, 0.00001), bronze, infinite viewer, and the worksheet's rules
/// (no scene ambient, no emission, the normal transformed by `M` itself and normalised). The light-model ambient keeps OpenGL's 0.2, so
/// switching the rules to OpenGL shows what a real OpenGL prints (0.102087 for red).
pub fn worksheet(index: usize) -> Scene {
    let view = worksheet_modelview(index).or_else(|| worksheet_modelview(5)).unwrap_or(DMat4::IDENTITY);
    Scene {
        light_model: LightModel::default(),
        lights: vec![Light {
            ambient: DVec4::ONE,
            diffuse: DVec4::ONE,
            specular: DVec4::ONE,
            position: WORKSHEET_LIGHT,
            attenuation: [1.0, 0.0001, 0.00001],
            placement: LightPlacement::World,
            ..Light::gl_default(0)
        }],
        material: bronze(),
        back_material: None,
        color_material: None,
        eye_from_world: view,
        world_from_object: DMat4::IDENTITY,
        // The worksheet divides M n by its length (`vertexNormal/np.linalg.norm(...)`).
        normal_mode: NormalMode::Normalize,
        rules: Rules::WORKSHEET,
        vertex: Vertex { position: WORKSHEET_VERTEX, normal: DVec3::Z },
    }
}

/// The demo's eye and light position, in object coordinates.
pub const PHONG_DEMO_EYE: DVec3 = DVec3::new(-4.0, 0.0, -8.0);

/// The gluSphere(0.5, 50, 50) vertex the demo preset explains: slice 49, stack 40, up and
/// to the left of the point facing the light, where N, L and R are about 43 degrees apart
/// (V is L: the demo puts its eye at its light).
pub const PHONG_DEMO_VERTEX: (u32, u32) = (49, 40);

/// The Phong demo's lighting, as its shaders compute it: a red object (`objColor`
/// (1, 0, 0)) under a white light, ambient 0.2, diffuse 0.4, specular 0.5, all multiplied
/// by the object's colour (so the highlight is red), exponent 100, the reflection vector
/// `R = 2 max(N.L, 0) N - L`, no attenuation, no scene ambient, no emission.
///
/// The demo lights in object space with the light and the eye both at (-4, 0, -8).
/// OpenGL's local viewer sits at the eye-space origin, so this scene's modelview moves the
/// demo's eye there: eye space is object space translated by (4, 0, 8). Differences of
/// points, and so N, L, V, R, d and every term, are the demo's own. The vertex is
/// [`PHONG_DEMO_VERTEX`] with the demo's normal `normalize(position)`.
pub fn phong_demo() -> Scene {
    let sphere = crate::mesh::sphere::glu_sphere(0.5, 50, 50).with_position_normals();
    let (slice, stack) = PHONG_DEMO_VERTEX;
    let k = (2 + (stack - 1) * 51 + slice) as usize;
    let vertex = Vertex::from_f32(sphere.positions[k], sphere.normals[k]);
    Scene {
        light_model: LightModel { local_viewer: true, ..LightModel::default() },
        lights: vec![Light {
            ambient: DVec4::ONE,
            diffuse: DVec4::ONE,
            specular: DVec4::ONE,
            position: PHONG_DEMO_EYE.extend(1.0),
            placement: LightPlacement::World,
            ..Light::gl_default(0)
        }],
        material: Material {
            ambient: DVec4::new(0.2, 0.0, 0.0, 1.0),
            diffuse: DVec4::new(0.4, 0.0, 0.0, 1.0),
            specular: DVec4::new(0.5, 0.0, 0.0, 1.0),
            emission: DVec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 100.0,
        },
        back_material: None,
        color_material: None,
        eye_from_world: phong_demo_eye_from_object(),
        world_from_object: DMat4::IDENTITY,
        normal_mode: NormalMode::AsIs,
        rules: Rules::PHONG_DEMO,
        vertex,
    }
}

/// The three scenes of the lighting benchmark (issue 5): what specialisation saves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightingBench {
    /// (a) one directional light, no spot, infinite viewer.
    Directional,
    /// (b) one positional light with attenuation, local viewer.
    PositionalLocal,
    /// (c) eight positional spotlights.
    EightSpots,
}

impl LightingBench {
    /// All three, in order.
    pub const ALL: [LightingBench; 3] =
        [LightingBench::Directional, LightingBench::PositionalLocal, LightingBench::EightSpots];

    /// A short name for tables.
    pub fn name(self) -> &'static str {
        match self {
            LightingBench::Directional => "a_directional",
            LightingBench::PositionalLocal => "b_positional_local",
            LightingBench::EightSpots => "c_eight_spots",
        }
    }

    /// The scene: bronze under OpenGL's rules, camera at z = 4 looking at the origin.
    pub fn scene(self) -> Scene {
        let mut s = Scene {
            material: bronze(),
            eye_from_world: DMat4::from_translation(DVec3::new(0.0, 0.0, -4.0)),
            normal_mode: NormalMode::Normalize,
            ..Scene::default()
        };
        let white = |position: DVec4| Light {
            position,
            ambient: DVec4::new(0.2, 0.2, 0.2, 1.0),
            placement: LightPlacement::World,
            ..Light::gl_default(0)
        };
        match self {
            LightingBench::Directional => s.lights = vec![white(DVec4::new(2.0, 3.0, 1.0, 0.0))],
            LightingBench::PositionalLocal => {
                s.lights = vec![Light { attenuation: [1.0, 0.05, 0.01], ..white(DVec4::new(2.0, 3.0, 1.0, 1.0)) }];
                s.light_model.local_viewer = true;
            }
            LightingBench::EightSpots => {
                s.lights = (0..8)
                    .map(|i| {
                        let a = i as f64 / 8.0 * std::f64::consts::TAU;
                        let p = DVec3::new(3.0 * elementary::cos(a), 2.0, 3.0 * elementary::sin(a));
                        Light {
                            diffuse: DVec4::new(0.3, 0.3, 0.3, 1.0),
                            specular: DVec4::new(0.3, 0.3, 0.3, 1.0),
                            spot_direction: -p,
                            spot_cutoff: 35.0,
                            spot_exponent: 8.0,
                            attenuation: [1.0, 0.05, 0.0],
                            ..white(p.extend(1.0))
                        }
                    })
                    .collect();
            }
        }
        s
    }
}

/// `n` points of the unit sphere (a Fibonacci lattice) with their outward normals, as f32.
pub fn sphere_points(n: usize) -> (Vec<glam::Vec3>, Vec<glam::Vec3>) {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let t = golden * i as f64;
            let p = DVec3::new(r * elementary::cos(t), y, r * elementary::sin(t)).as_vec3();
            (p, p)
        })
        .unzip()
}

/// docs/lighting.md's rendering benchmark scene at frame `frame`: bronze under one light at
/// (2, 3, 1, 1) fixed to the eye (ambient 0.2, diffuse and specular 1, linear attenuation
/// 0.05), GL_NORMALIZE, the object rotated 3 `frame` degrees about (0.3, 1, 0.1) in front
/// of the eye at z = -4.
pub fn bench_scene(frame: u32) -> Scene {
    let axis = DVec3::new(0.3, 1.0, 0.1).normalize();
    Scene {
        lights: vec![Light {
            position: DVec4::new(2.0, 3.0, 1.0, 1.0),
            ambient: DVec4::new(0.2, 0.2, 0.2, 1.0),
            attenuation: [1.0, 0.05, 0.0],
            placement: LightPlacement::Eye,
            ..Light::gl_default(0)
        }],
        material: bronze(),
        eye_from_world: DMat4::from_translation(DVec3::new(0.0, 0.0, -4.0)),
        world_from_object: DMat4::from_axis_angle(axis, (3.0 * frame as f64).to_radians()),
        normal_mode: NormalMode::Normalize,
        ..Scene::default()
    }
}

/// The benchmark's projection: `gluPerspective(40, 1, 0.5, 20)`.
pub fn bench_projection() -> DMat4 {
    crate::model::transform::perspective(40.0, 1.0, 0.5, 20.0)
}

/// The benchmark's clear colour.
pub const BENCH_BACKGROUND: [f32; 3] = [0.1, 0.1, 0.15];
