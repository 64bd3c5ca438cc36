//! The shader a scene compiles to: generated for every public case's scene and every
//! shipped scene file, in GLSL 3.30 (validated by glslangValidator, Khronos' reference
//! compiler) and WGSL (validated by naga, wgpu's compiler), Gouraud and Phong; and each key
//! bit adds or removes exactly its lines.

use std::collections::HashSet;
use std::path::Path;
use std::process::Command;

use phonglab_core::explain::{Side, explain};
use phonglab_core::plan::Key;
use phonglab_core::shader::{Shader, ShaderShading, ShadingLanguage, generate};
use phonglab_core::{Document, Engine, EvalOptions, Scene};

fn shader(scene: &Scene, lang: ShadingLanguage, shading: ShaderShading) -> Shader {
    let lit = Engine::<f64>::new(scene).unwrap().light(&scene.vertex);
    let ex = explain(scene, &lit, Side::Front);
    generate(scene, EvalOptions::default(), &ex, lang, shading)
}

fn validate_wgsl(src: &str, what: &str) {
    let module =
        naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("{what}: {}\n{src}", e.emit_to_string(src)));
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::all())
        .validate(&module)
        .unwrap_or_else(|e| panic!("{what}: {e:?}\n{src}"));
}

fn validate_glsl(dir: &Path, name: &str, s: &Shader) {
    for (stage, src) in [("vert", &s.vertex), ("frag", &s.fragment)] {
        let p = dir.join(format!("{name}.{stage}"));
        std::fs::write(&p, src).unwrap();
        let out = Command::new("glslangValidator")
            .arg(&p)
            .output()
            .expect("glslangValidator (glslang-tools) is installed by scripts/test");
        assert!(out.status.success(), "{name}.{stage}: {}\n{src}", String::from_utf8_lossy(&out.stdout));
    }
}

fn scenes() -> Vec<(String, Scene)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("tests/data/cases_public.json")).unwrap();
    let mut out: Vec<(String, Scene)> = phonglab_core::glref::parse_cases(&text)
        .unwrap()
        .into_iter()
        .filter_map(|(id, c)| c.ok().map(|c| (id, c.scene)))
        .collect();
    let mut files: Vec<_> = walk(&root.join("assets/scenes"));
    files.sort();
    for f in files {
        let doc = Document::from_toml(&std::fs::read_to_string(&f).unwrap()).unwrap();
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        // Every shipped scene under energy-conserving Blinn-Phong too.
        let mut normalised = doc.scene.clone();
        normalised.rules.specular = phonglab_core::SpecularModel::BlinnPhongNormalised;
        out.push((format!("{name}, normalised Blinn-Phong"), normalised));
        out.push((name, doc.scene));
    }
    out
}

fn walk(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            v.extend(walk(&p));
        } else if p.extension().is_some_and(|x| x == "toml") {
            v.push(p);
        }
    }
    v
}

#[test]
fn every_public_cases_shader_compiles() {
    let dir = std::env::temp_dir().join(format!("phonglab-shaders-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut keys = HashSet::new();
    let all = scenes();
    for (k, (id, scene)) in all.iter().enumerate() {
        if scene.validate().is_err() {
            continue;
        }
        let key = Key::of(scene, EvalOptions::default());
        if !keys.insert(format!("{key:?}")) {
            continue; // the same key gives the same program
        }
        for shading in [ShaderShading::Gouraud, ShaderShading::Phong] {
            validate_wgsl(&shader(scene, ShadingLanguage::Wgsl, shading).vertex, &format!("{id} {shading:?} WGSL"));
            validate_glsl(&dir, &format!("s{k}-{shading:?}"), &shader(scene, ShadingLanguage::Glsl, shading));
        }
    }
    println!("{} scenes, {} distinct keys, each compiled as GLSL and WGSL, Gouraud and Phong", all.len(), keys.len());
    assert!(keys.len() >= 20, "{} keys", keys.len());
}

#[test]
fn each_key_bit_adds_or_removes_its_lines() {
    let base = phonglab_core::presets::worksheet(5);
    let text = |s: &Scene| {
        let g = shader(s, ShadingLanguage::Glsl, ShaderShading::Gouraud);
        format!("{}{}", g.vertex, g.fragment)
    };
    let plain = text(&base);
    assert!(!plain.contains("in_cone0"), "no spotlight, no cone test");
    // A spotlight brings the cone test and the spot power.
    let mut s = base.clone();
    s.lights[0].spot_cutoff = 45.0;
    s.lights[0].spot_direction = glam::DVec3::new(0.0, 0.0, -1.0);
    let spot = text(&s);
    assert!(spot.contains("bool in_cone0 = spot_cos0 >= u_light0_spot_cos_cutoff;") && spot.contains("spot0 *"));
    // Attenuation (1, 0, 0): no attenuation line.
    let mut s = base.clone();
    s.lights[0].attenuation = [1.0, 0.0, 0.0];
    assert!(plain.contains("att0") && !text(&s).contains("att0"));
    // A directional light under OpenGL's infinite viewer: one L and one H, no distance.
    let mut s = base.clone();
    s.rules = phonglab_core::Rules::OPENGL;
    s.lights[0].position = glam::DVec4::new(0.0, 1.0, 1.0, 0.0);
    let dir = text(&s);
    assert!(dir.contains("vec3 L0 = u_light0_direction;") && dir.contains("vec3 H0 = u_light0_halfway;"));
    assert!(!dir.contains("length(toL0)") && !dir.contains("vec3 V ="));
    // A local viewer: V = normalize(-P).
    let mut s = base.clone();
    s.light_model.local_viewer = true;
    assert!(text(&s).contains("vec3 V = normalize(-P);") && !plain.contains("normalize(-P)"));
    // Two-sided: a back colour, picked by gl_FrontFacing.
    let mut s = base.clone();
    s.light_model.two_sided = true;
    let two = text(&s);
    assert!(two.contains("color1") && two.contains("gl_FrontFacing") && !plain.contains("color1"));
    // Shininess 0: no power.
    let mut s = base.clone();
    s.material.shininess = 0.0;
    assert!(plain.contains("pow(max(spec_cos0_0") && !text(&s).contains("pow(max(spec_cos0_0"));
    // OpenGL's rules add the scene colour (emission + scene ambient); the worksheet's do not.
    let mut s = base.clone();
    s.rules = phonglab_core::Rules::OPENGL;
    assert!(text(&s).contains("u_scene_color") && !plain.contains("u_scene_color"));
    // Steps are numbered as in the worked calculation.
    assert!(plain.contains("float att0 = ") && plain.contains("// step 13"), "{plain}");
}
