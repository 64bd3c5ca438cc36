//! The exported openFrameworks apps (`phonglab export --to openframeworks`) compile as
//! C++17 against a stand-in for oF 0.12's header with oF's own signatures
//! (`tests/data/of_standin/ofMain.h`), for the shipped scenes and for scenes that need
//! every raw GL call the writer emits (the local viewer, two-sided lighting with a back
//! material, a separate specular colour, a light fixed to the eye, each normal mode, a
//! directional light and a spotlight), and for scenes whose app draws with the generated shader. Skipped, saying so, where no C++ compiler is here;
//! CI installs Debian's g++.

use std::path::Path;
use std::process::Command;

use phonglab_core::export::openframeworks::app;
use phonglab_core::{Document, LightPlacement, NormalMode, Rules};

fn compiler() -> Option<&'static str> {
    ["g++", "c++", "clang++"]
        .into_iter()
        .find(|c| Command::new(c).arg("--version").output().is_ok_and(|o| o.status.success()))
}

fn scene(path: &str) -> Document {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes").join(path);
    Document::from_toml_in(&std::fs::read_to_string(&p).unwrap(), p.parent()).unwrap()
}

fn documents() -> Vec<(String, Document)> {
    let mut docs: Vec<(String, Document)> = [
        "worksheet-mview5.toml",
        "spotlight.toml",
        "three-lights.toml",
        "phong-demo.toml",
        "redbook-teapots/11-gold.toml",
    ]
    .iter()
    .map(|f| (f.to_string(), scene(f)))
    .collect();
    // Everything oF cannot say, at once.
    let mut all = scene("spotlight.toml");
    all.scene.rules = Rules::OPENGL;
    all.scene.light_model.local_viewer = true;
    all.scene.light_model.two_sided = true;
    all.scene.light_model.separate_specular = true;
    all.scene.back_material = Some(phonglab_core::materials::by_name("gold").unwrap().clone());
    let mut eye = phonglab_core::Light::gl_default(1);
    eye.placement = LightPlacement::Eye;
    all.scene.lights.push(eye);
    let mut directional = phonglab_core::Light::gl_default(2);
    directional.position = glam::DVec4::new(0.0, 1.0, 0.0, 0.0);
    all.scene.lights.push(directional);
    for mode in [NormalMode::AsIs, NormalMode::Rescale] {
        let mut d = all.clone();
        d.scene.normal_mode = mode;
        d.view.object = phonglab_core::ObjectKind::Cylinder;
        docs.push((format!("everything-{mode:?}"), d));
    }
    docs
}

/// Scenes under energy-conserving Blinn-Phong, which fixed-function GL cannot compute: the
/// spotlight's (Gouraud) and the worksheet's (its rules, Phong shading).
fn normalised() -> Vec<(String, Document)> {
    let mut docs = Vec::new();
    for (file, shading) in
        [("spotlight.toml", phonglab_core::Shading::Gouraud), ("worksheet-mview5.toml", phonglab_core::Shading::Phong)]
    {
        let mut d = scene(file);
        d.scene.rules.specular = phonglab_core::SpecularModel::BlinnPhongNormalised;
        d.view.shading = shading;
        docs.push((format!("{file}, normalised Blinn-Phong"), d));
    }
    docs
}

/// The two stages in `setup`'s raw strings compile as GLSL for a compatibility context
/// (glslangValidator, which scripts/test installs).
fn compatibility_glsl_compiles(name: &str, setup: &str) {
    let dir = std::env::temp_dir().join(format!("phonglab-of-glsl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let sources: Vec<&str> = setup.split("R\"GLSL(\n").skip(1).map(|s| s.split(")GLSL\"").next().unwrap()).collect();
    assert_eq!(sources.len(), 2, "{name}");
    for (stage, src) in ["vert", "frag"].into_iter().zip(sources) {
        let p = dir.join(format!("stage.{stage}"));
        std::fs::write(&p, src).unwrap();
        let out = Command::new("glslangValidator")
            .arg(&p)
            .output()
            .expect("glslangValidator (glslang-tools) is installed by scripts/test");
        assert!(out.status.success(), "{name}.{stage}: {}\n{src}", String::from_utf8_lossy(&out.stdout));
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Where fixed-function GL cannot compute a term (energy-conserving Blinn-Phong's factor),
/// the app says so and draws with the general shaders: compiled and linked in setup(),
/// bound around the object in draw(), reading the lights and the material oF set from GL
/// and the rest of the state with glGet (never a scene value baked in), the factor in their
/// GLSL. The other apps draw with oF's lighting alone.
#[test]
fn what_gl_cannot_compute_is_drawn_by_the_generated_shader() {
    for (name, doc) in normalised() {
        let files = app(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
        let (header, cpp) = (&files[0].1, &files[1].1);
        assert!(header.contains("    ofShader shader;\n"), "{name}");
        assert!(cpp.contains("normalised Blinn-Phong: the specular term times (ns + 8)/(8π)"), "{name}");
        let (setup, draw) = cpp.split_at(cpp.find("void ofApp::draw()").unwrap());
        for line in
            ["shader.setupShaderFromSource(GL_VERTEX_SHADER, R\"GLSL(", "GL_FRAGMENT_SHADER", "shader.linkProgram();"]
        {
            assert!(setup.contains(line), "{name}: {line}");
        }
        // The general shaders: the whole of GL's lighting read from GL's state, only the
        // rule set fixed (here the normalised specular).
        assert!(setup.contains("#version 120") && setup.contains("#define SPECULAR_NORMALISED 1"), "{name}");
        assert!(setup.contains("gl_LightSource[i].position") && setup.contains("gl_FrontMaterial"), "{name}");
        assert!(setup.contains("#define u_eye_from_object gl_ModelViewMatrix"), "{name}");
        assert!(setup.contains("#define u_rescale gl_NormalScale"), "{name}");
        let begin = draw.find("shader.begin();").unwrap();
        let (object, end) = (draw.find("ofDrawSphere").unwrap(), draw.find("shader.end();").unwrap());
        assert!(begin < object && object < end, "{name}");
        // What GLSL has no variable for is read from GL, never written as the scene's value.
        assert!(draw.contains("glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER, &v);"), "{name}: {draw}");
        assert!(draw.contains("shader.setUniform1iv(\"u_light_on\", on, 8);"), "{name}: {draw}");
        assert!(!draw.contains("setUniform3f") && !draw.contains("setUniform1f"), "{name}: a scene value in {draw}");
        assert!(!draw.contains("u_eye_from_object"), "{name}: GL's own matrices are not set");
        compatibility_glsl_compiles(&name, setup);
    }
    for (name, doc) in documents() {
        let files = app(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
        assert!(!files[0].1.contains("ofShader") && !files[1].1.contains("shader."), "{name}");
    }
}

#[test]
fn the_exported_openframeworks_apps_compile_against_ofs_signatures() {
    let Some(cxx) = compiler() else {
        eprintln!("SKIPPED: the exported openFrameworks apps are not compiled: no C++ compiler here (Debian: g++)");
        return;
    };
    let standin = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/of_standin");
    for (name, doc) in documents().into_iter().chain(normalised()) {
        let dir = std::env::temp_dir().join(format!("phonglab-of-{}-{name}", std::process::id()).replace('/', "-"));
        std::fs::create_dir_all(&dir).unwrap();
        let files = app(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
        assert_eq!(files.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(), ["ofApp.h", "ofApp.cpp", "main.cpp"]);
        for (file, text) in &files {
            std::fs::write(dir.join(file), text).unwrap();
        }
        let source = &files[1].1;
        assert!(source.contains("ofEnableLighting()") && source.contains("material.begin()"), "{name}");
        // Each light and the material are set up once, in setup().
        let setup = &source[..source.find("void ofApp::draw()").unwrap()];
        assert_eq!(setup.matches("material.setDiffuseColor").count(), 1, "{name}");
        assert_eq!(
            setup.matches(".setDiffuseColor").count(),
            1 + files[0].1.matches("ofLight light").count(),
            "{name}"
        );
        for file in ["ofApp.cpp", "main.cpp"] {
            let out = Command::new(cxx)
                .args(["-std=c++17", "-fsyntax-only", "-Wall", "-Werror", "-I"])
                .arg(&standin)
                .arg("-I")
                .arg(&dir)
                .arg(dir.join(file))
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{name}/{file} does not compile:\n{}\n{}",
                String::from_utf8_lossy(&out.stderr),
                files[1].1
            );
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}

#[test]
fn what_of_cannot_say_is_the_raw_gl_call_with_a_comment() {
    let (_, doc) = documents().pop().unwrap();
    let files = app(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
    let cpp = &files[1].1;
    for call in [
        "glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE)",
        "glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE)",
        "glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR)",
        "glMaterialfv(GL_BACK, GL_DIFFUSE",
        "glEnable(GL_RESCALE_NORMAL)",
        "glLightfv(GL_LIGHT2, GL_POSITION, position)",
        "light1.setDirectional()",
        "light0.setSpotlight(",
        "ofSetGlobalAmbientColor(ofFloatColor(0.1f, 0.1f, 0.1f, 1.0f))",
    ] {
        let at = cpp.find(call).unwrap_or_else(|| panic!("no {call} in\n{cpp}"));
        // The line before a raw call (or its block) is a comment saying why.
        if call.starts_with("gl") && !call.starts_with("glLightfv") {
            let before = &cpp[..at];
            assert!(
                before.trim_end().lines().last().unwrap().trim_start().starts_with("//") || before.contains("// "),
                "{call}"
            );
        }
    }
    // The renderer it assumes is said.
    assert!(files[0].1.contains("GL 2.1") && files[2].1.contains("ofSetupOpenGL(512, 512, OF_WINDOW)"));
    // A light fixed to the eye is not placed by oF (oF would place it in the world).
    assert_eq!(files[0].1.matches("ofLight light").count(), 2);
}
