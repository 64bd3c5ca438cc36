//! The generated GLSL, compiled and run by a real OpenGL (Mesa 22.3.6, llvmpipe), draws
//! what the CPU renderer draws: the benchmark scene, shipped scenes (spotlight, three
//! lights, the worksheet, the gold teapot, two-sided lighting on the open cylinder, the
//! Phong demo) and a sample of the public cases' scenes chosen to cover the key's bits,
//! Gouraud and Phong, at 128x128.
//!
//! Mesa's pictures are data (`tests/data/mesa_glsl/*.png`), made once by
//! `scripts/shader_mesa.py` from the inputs the ignored test below writes (the programs,
//! their uniforms' values and the meshes), so this test needs neither Python nor Mesa:
//!
//! ```text
//! PHONGLAB_MESA_INPUTS=/tmp/glsl-in cargo test --test all shader_mesa::write_inputs -- --ignored
//! $GLREF/.venv/bin/python scripts/shader_mesa.py /tmp/glsl-in tests/data/mesa_glsl
//! ```

use std::path::{Path, PathBuf};

use phonglab::io::image::Difference;
use phonglab_core::mesh::{Mesh, sphere};
use phonglab_core::render::{Job, Renderer};
use phonglab_core::shader::{ShaderShading, ShadingLanguage, generate_for, uniform_value};
use phonglab_core::{CameraSpec, Document, EvalOptions, PowFn, Scene, Shading, library, presets};

const SIZE: usize = 128;

/// One picture's inputs: everything a [`Job`] holds, owned.
struct Sample {
    name: String,
    scene: Scene,
    mesh: Mesh,
    clip_from_object: glam::DMat4,
    options: EvalOptions,
    background: [f32; 3],
}

impl Sample {
    fn of_document(name: &str, doc: &Document) -> Sample {
        let setup = doc.shaded_setup(PowFn::Exact);
        Sample {
            name: name.into(),
            scene: setup.scene.clone(),
            mesh: doc.view.mesh(),
            clip_from_object: setup.clip_from_object,
            options: setup.options,
            background: doc.view.background,
        }
    }

    fn job(&self, shading: Shading) -> Job<'_> {
        Job {
            scene: &self.scene,
            mesh: &self.mesh,
            clip_from_object: self.clip_from_object,
            mode: phonglab_core::ShadingMode::of(shading, Default::default()),
            background: self.background,
            cull_back: false,
            depth_test: true,
            options: self.options,
        }
    }
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The public cases drawn, chosen (among the ordinary ones) so that together they switch on
/// every bit of the key those use, each in a picture that is lit: a spotlight, the local
/// viewer, two-sided lighting with a back material, separate specular, directional,
/// positional and attenuated lights, eight lights, GL_NORMALIZE, GL_RESCALE_NORMAL and
/// emission.
const CASES: [&str; 6] = ["rand0065", "rand0111", "rand0082", "rand0180", "rand0179", "rand0000"];

fn samples() -> Vec<Sample> {
    let mut out = Vec::new();
    let scene = presets::bench_scene(10);
    let mesh = sphere::glu_sphere(1.0, 50, 50);
    let job = phonglab_core::shaded::bench_job(&scene, &mesh, Shading::Gouraud);
    out.push(Sample {
        name: "benchmark".into(),
        scene: job.scene.clone(),
        mesh: mesh.clone(),
        clip_from_object: job.clip_from_object,
        options: job.options,
        background: job.background,
    });
    let scenes = root().join("assets/scenes");
    for f in ["spotlight", "three-lights", "worksheet-mview5", "redbook-teapots/11-gold"] {
        let doc = Document::from_toml(&std::fs::read_to_string(scenes.join(format!("{f}.toml"))).unwrap()).unwrap();
        out.push(Sample::of_document(&f.replace('/', "-"), &doc));
    }
    let mut two = Document::from_toml(&std::fs::read_to_string(scenes.join("spotlight.toml")).unwrap()).unwrap();
    two.scene.light_model.two_sided = true;
    two.view.object = phonglab_core::ObjectKind::Cylinder;
    out.push(Sample::of_document("two-sided-cylinder", &two));
    let demo = library::documents().into_iter().find(|(n, _)| n.contains("demo")).unwrap().1;
    out.push(Sample::of_document("phong-demo", &demo));
    let text = std::fs::read_to_string(root().join("tests/data/cases_public.json")).unwrap();
    let cases = phonglab_core::glref::parse_cases(&text).unwrap();
    for id in CASES {
        let (_, case) = cases.iter().find(|(i, _)| i == id).unwrap_or_else(|| panic!("{id}"));
        let scene = case.as_ref().unwrap().scene.clone();
        let doc = Document::from_scene(id, CameraSpec::Matrix(scene.eye_from_world), scene);
        out.push(Sample::of_document(id, &doc));
    }
    out
}

fn shadings() -> [(Shading, ShaderShading, &'static str); 2] {
    [(Shading::Gouraud, ShaderShading::Gouraud, "gouraud"), (Shading::Phong, ShaderShading::Phong, "phong")]
}

/// Writes each picture's inputs as JSON for `scripts/shader_mesa.py`.
#[test]
#[ignore = "writes the inputs of scripts/shader_mesa.py; run with PHONGLAB_MESA_INPUTS=DIR"]
fn write_inputs() {
    let dir = PathBuf::from(std::env::var("PHONGLAB_MESA_INPUTS").expect("PHONGLAB_MESA_INPUTS=DIR"));
    std::fs::create_dir_all(&dir).unwrap();
    for s in samples() {
        for (_, shading, word) in shadings() {
            let shader = generate_for(&s.scene, s.options, ShadingLanguage::Glsl, shading).unwrap();
            let uniforms: Vec<serde_json::Value> = shader
                .uniforms
                .iter()
                .map(|(name, ty)| {
                    let v = uniform_value(&s.scene, &s.clip_from_object, name).unwrap();
                    serde_json::json!({ "name": format!("u_{name}"), "type": ty, "value": v })
                })
                .collect();
            let flat3 = |v: &[glam::Vec3]| v.iter().flat_map(glam::Vec3::to_array).collect::<Vec<f32>>();
            let json = serde_json::json!({
                "name": format!("{}_{word}", s.name),
                "size": SIZE,
                "background": s.background,
                "vertex": shader.vertex,
                "fragment": shader.fragment,
                "uniforms": uniforms,
                "positions": flat3(&s.mesh.positions),
                "normals": flat3(&s.mesh.normals),
                "indices": s.mesh.triangles.iter().flatten().collect::<Vec<_>>(),
            });
            std::fs::write(dir.join(format!("{}_{word}.json", s.name)), json.to_string()).unwrap();
        }
    }
}

#[test]
fn the_generated_glsl_under_mesa_draws_what_the_cpu_renderer_draws() {
    let data = root().join("tests/data/mesa_glsl");
    let mut checked = 0;
    for s in samples() {
        for (cpu_shading, _, word) in shadings() {
            let name = format!("{}_{word}", s.name);
            let (w, h, mesa) = phonglab::io::image::read_png(&data.join(format!("{name}.png")))
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!((w, h), (SIZE, SIZE), "{name}");
            let mut r = Renderer::new();
            let cpu = r.render(&s.job(cpu_shading), SIZE, SIZE).unwrap().0;
            let bg = s.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
            let d = Difference::of(&mesa, &cpu.rgba, bg);
            println!("{name}: {d}");
            assert!(d.both > 300, "{name}: only {} pixels drawn", d.both);
            assert_eq!(d.only_one(), 0, "{name}: coverage differs: {d}");
            assert!(d.mad.iter().all(|m| *m <= 1.0), "{name}: mean difference > 1/255: {d}");
            checked += 1;
        }
    }
    assert_eq!(checked, 2 * (7 + CASES.len()));
}
