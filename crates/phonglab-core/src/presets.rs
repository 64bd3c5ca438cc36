//! Ready-made scenes: the worksheet (with each of its five modelviews) and the Phong demo.

use glam::{DMat4, DVec3, DVec4};

use crate::camera::CameraSpec;
use crate::document::Document;
use crate::materials;
use crate::rules::Rules;
use crate::scene::{Light, LightModel, LightPlacement, Material, NormalMode, Scene, Vertex};
use crate::transform::worksheet_modelview;
use crate::view::{FlatNormal, Framing, LightingSpace, ObjectKind, Shading, View};

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
        eye_from_world: phong_demo_eye_from_object(),
        world_from_object: DMat4::IDENTITY,
        normal_mode: NormalMode::AsIs,
        rules: Rules::PHONG_DEMO,
        vertex,
    }
}

/// The demo's "eye space": object space moved so that its eye (-4, 0, -8) is the origin.
pub fn phong_demo_eye_from_object() -> DMat4 {
    // -PHONG_DEMO_EYE, written out (negating 0 would give -0).
    DMat4::from_translation(DVec3::new(4.0, 0.0, 8.0))
}

/// The shaded view as the demo's program draws: clip space (no projection), the spin of
/// 0.5 degrees a frame (the first frame drawn has taken one step), lit in object space,
/// `normalize(position)` for normals, Phong without renormalising, Flat from the screen
/// derivatives, gluCylinder not centred, a black background, sphere and Gouraud first.
pub fn phong_demo_view() -> View {
    View {
        object: ObjectKind::Sphere,
        shading: Shading::Gouraud,
        sphere_slices: 50,
        sphere_stacks: 50,
        teapot_grid: 7,
        cylinder_slices: 20,
        cylinder_stacks: 5,
        cylinder_caps: false,
        demo_normals: true,
        auto_rotate: true,
        spin_degrees: 0.5,
        framing: Framing::ClipSpace,
        lighting_space: LightingSpace::Object,
        flat_normal: FlatNormal::ScreenDerivatives,
        phong_renormalize: false,
        cylinder_centered: false,
        background: [0.0, 0.0, 0.0],
        ..View::default()
    }
}

/// The Phong demo as a document: [`phong_demo`] lit, [`phong_demo_view`] drawn.
pub fn phong_demo_document() -> Document {
    let mut d = Document::from_scene("the Phong demo", CameraSpec::Matrix(phong_demo_eye_from_object()), phong_demo());
    d.view = phong_demo_view();
    d
}

/// Where the Phong demo departs from OpenGL's lighting: each a switch a teacher can flip.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DemoDeparture {
    /// The light turns with the object (lit in object space).
    LightTurnsWithObject,
    /// Normals are `normalize(position)`.
    PositionNormals,
    /// The highlight is multiplied by the object's colour.
    HighlightInObjectColour,
}

impl DemoDeparture {
    /// All three, in the order the document lists them.
    pub const ALL: [DemoDeparture; 3] =
        [DemoDeparture::LightTurnsWithObject, DemoDeparture::PositionNormals, DemoDeparture::HighlightInObjectColour];

    /// The correction's name, as the switch shows it.
    pub fn fix_label(self) -> &'static str {
        match self {
            DemoDeparture::LightTurnsWithObject => "light fixed in the world",
            DemoDeparture::PositionNormals => "the surface's true normals",
            DemoDeparture::HighlightInObjectColour => "highlight in the light's colour",
        }
    }

    /// One sentence on why.
    pub fn why(self) -> &'static str {
        match self {
            DemoDeparture::LightTurnsWithObject => {
                "The demo lights untransformed positions and normals, so its light turns with the object; the document's own fix transforms them by mvMatrix (for a rotation its inverse transpose is itself), and the light stays put while the object turns."
            }
            DemoDeparture::PositionNormals => {
                "normalize(position) is the normal of a sphere about the origin only; the teapot's and the cylinder's surfaces point elsewhere, and their true normals light them as they are."
            }
            DemoDeparture::HighlightInObjectColour => {
                "The demo multiplies the specular term by the object's red; OpenGL multiplies the light's specular colour by the material's specular colour (white here), so a highlight shows the light's colour."
            }
        }
    }

    /// Applies the correction to a document.
    pub fn correct(self, d: &mut Document) {
        match self {
            DemoDeparture::LightTurnsWithObject => d.view.lighting_space = LightingSpace::Eye,
            DemoDeparture::PositionNormals => d.view.demo_normals = false,
            DemoDeparture::HighlightInObjectColour => {
                let s = d.scene.material.specular;
                let k = s.x.max(s.y).max(s.z);
                d.scene.material.specular = DVec4::new(k, k, k, s.w);
            }
        }
    }

    /// Does the document still make this departure?
    pub fn present_in(self, d: &Document) -> bool {
        match self {
            DemoDeparture::LightTurnsWithObject => d.view.lighting_space == LightingSpace::Object,
            DemoDeparture::PositionNormals => d.view.demo_normals,
            DemoDeparture::HighlightInObjectColour => {
                let s = d.scene.material.specular;
                !(s.x == s.y && s.y == s.z)
            }
        }
    }
}

/// Every built-in document, in menu order: the worksheet with each modelview, the demo.
pub fn documents() -> Vec<(String, Document)> {
    let mut v: Vec<(String, Document)> = (1..=5u8)
        .map(|k| {
            let name = format!("Worksheet, mview{k}");
            (name.clone(), Document::from_scene(&name, CameraSpec::Worksheet(k), worksheet(k as usize)))
        })
        .collect();
    v.push(("Phong demo".into(), phong_demo_document()));
    v
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
                        let p = DVec3::new(3.0 * a.cos(), 2.0, 3.0 * a.sin());
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
            let p = DVec3::new(r * t.cos(), y, r * t.sin()).as_vec3();
            (p, p)
        })
        .unzip()
}

/// DESIGN.md's rendering benchmark scene at frame `frame`: bronze under one light at
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
    crate::transform::perspective(40.0, 1.0, 0.5, 20.0)
}

/// The benchmark's render job for `scene` (a [`bench_scene`] frame): its projection, Flat
/// per face, no culling, exact pow.
pub fn bench_job<'a>(scene: &'a Scene, mesh: &'a crate::mesh::Mesh, shading: Shading) -> crate::render::Job<'a> {
    crate::render::Job {
        scene,
        mesh,
        clip_from_object: bench_projection() * scene.eye_from_object(),
        shading,
        flat_normal: FlatNormal::Face,
        background: BENCH_BACKGROUND,
        cull_back: false,
        options: crate::EvalOptions::default(),
    }
}

/// The benchmark's clear colour.
pub const BENCH_BACKGROUND: [f32; 3] = [0.1, 0.1, 0.15];
