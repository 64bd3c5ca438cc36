//! The exported PyOpenGL program assumes nothing of its scene that a student could edit:
//! for every shipped scene, in Gouraud and Phong shading, its shaders are the general
//! ones (`export::general_shader`: only the rule set's `#define`s are the scene's; no
//! light, material or light model value is baked in), they compile and link as GLSL
//! 1.20 (glslangValidator), the program reads every piece of state they need from GL, and
//! Python parses it (Debian's python3).

use std::path::{Path, PathBuf};
use std::process::Command;

use phonglab_core::export::general_shader::stages;
use phonglab_core::export::pyopengl::program;
use phonglab_core::{Document, Shading};

fn shipped() -> Vec<(String, Document)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut files: Vec<PathBuf> = Vec::new();
    for dir in [root.clone(), root.join("redbook-teapots")] {
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "toml") {
                files.push(p);
            }
        }
    }
    files.sort();
    let mut out = Vec::new();
    for p in files {
        let doc = Document::from_toml_in(&std::fs::read_to_string(&p).unwrap(), p.parent()).unwrap();
        for shading in [Shading::Gouraud, Shading::Phong] {
            let mut d = doc.clone();
            d.view.shading = shading;
            out.push((format!("{}-{shading:?}", p.file_stem().unwrap().to_string_lossy()), d));
        }
    }
    out
}

/// The text of the Python string `name = """..."""` in `program`.
fn string_of<'a>(program: &'a str, name: &str) -> &'a str {
    let start = program.find(&format!("{name} = \"\"\"\n")).unwrap() + name.len() + 7;
    &program[start..start + program[start..].find("\"\"\"").unwrap()]
}

#[test]
fn every_shipped_scene_exports_the_general_shaders_and_reads_their_state_from_gl() {
    let all = shipped();
    assert!(all.len() >= 60, "{} programs", all.len());
    for (name, doc) in &all {
        let text = program(doc, &phonglab_core::export::shaded_key(doc)).unwrap();
        let (vertex, fragment) = stages(doc.shaded_scene().rules, doc.view.shading == Shading::Phong);
        assert_eq!(string_of(&text, "vertex_shader"), vertex, "{name}: not the general vertex shader");
        assert_eq!(string_of(&text, "fragment_shader"), fragment, "{name}: not the general fragment shader");
        // Every uniform the shaders declare is given its value from GL's state.
        for uniform in vertex.lines().chain(fragment.lines()).filter_map(|l| l.strip_prefix("uniform ")) {
            let u = uniform.split([' ', '[', ';']).nth(1).unwrap();
            assert!(text.contains(&format!("location(\"{u}\")")), "{name}: {u} is never set");
        }
        for state in ["GL_LIGHT_MODEL_LOCAL_VIEWER", "GL_LIGHT_MODEL_TWO_SIDE", "GL_LIGHT_MODEL_COLOR_CONTROL"] {
            assert!(text.contains(&format!("glGetIntegerv({state})")), "{name}: {state} is not read back");
        }
        assert!(!text.contains("u_light0_") && !text.contains("specialised plan"), "{name}: a specialised shader");
    }
}

#[test]
fn the_general_shaders_compile_and_link_for_every_rule_set_and_shading() {
    let dir = std::env::temp_dir().join(format!("phonglab-general-glsl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for rules in [phonglab_core::Rules::OPENGL, phonglab_core::Rules::WORKSHEET, phonglab_core::Rules::PHONG_DEMO] {
        for per_fragment in [false, true] {
            let (v, f) = stages(rules, per_fragment);
            let (vp, fp) = (dir.join("general.vert"), dir.join("general.frag"));
            std::fs::write(&vp, v).unwrap();
            std::fs::write(&fp, f).unwrap();
            let out = Command::new("glslangValidator")
                .arg("-l")
                .arg(&vp)
                .arg(&fp)
                .output()
                .expect("glslangValidator (glslang-tools) is installed by scripts/test");
            assert!(out.status.success(), "{rules:?} {per_fragment}: {}", String::from_utf8_lossy(&out.stdout));
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn python_parses_every_exported_program() {
    let Some(python) = ["python3", "/usr/bin/python3"]
        .into_iter()
        .find(|p| Command::new(p).arg("-c").arg("import ast").output().is_ok_and(|o| o.status.success()))
    else {
        eprintln!("SKIPPED: the exported programs are not parsed: no python3 here");
        return;
    };
    let dir = std::env::temp_dir().join(format!("phonglab-general-py-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut paths = Vec::new();
    for (name, doc) in shipped() {
        let p = dir.join(format!("{name}.py"));
        std::fs::write(&p, program(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap()).unwrap();
        paths.push(p);
    }
    let out = Command::new(python)
        .arg("-c")
        .arg("import ast, sys\nfor p in sys.argv[1:]:\n    ast.parse(open(p, encoding='utf-8').read(), p)\nprint(len(sys.argv) - 1)")
        .args(&paths)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), paths.len().to_string());
    std::fs::remove_dir_all(&dir).ok();
}

/// The program's comments are true of it and readable: RULES is said to be read by the
/// normal matrix alone; under rules without SCENE_AMBIENT the scene ambient's call says
/// editing it changes nothing; GL_LIGHTING's says the shaders light whatever it is; the
/// docstring names no file it cannot know (it said "python3 phong_scene.py" whatever `-o`
/// was); and no comment line is longer than 90 characters (the edit note was one of 330).
#[test]
fn the_programs_comments_are_true_and_wrapped() {
    for (name, doc) in shipped() {
        let text = program(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
        let comments: Vec<&str> = text.lines().filter(|l| l.trim_start().starts_with('#')).collect();
        // The teapot's winding note is left as Mesa ran it: `tests/pyopengl_edits.rs`'s CRC
        // of the verified code reaches into draw_object.
        let long: Vec<&&str> =
            comments.iter().filter(|l| l.chars().count() > 90 && !l.contains("freeglut's teapot")).collect();
        assert!(long.is_empty(), "{name}: comment lines over 90 characters: {long:#?}");
        let all = comments.iter().map(|l| l.trim_start().trim_start_matches('#').trim()).collect::<Vec<_>>().join(" ");
        assert!(!all.contains("scene's ambient follow"), "{name}: RULES said to steer the scene's ambient");
        assert!(all.contains("Only the normal matrix in set_uniforms() reads RULES"), "{name}");
        assert!(!text.contains("phong_scene.py"), "{name}: the docstring names a file it may not be");
        // The scene ambient's line: said to change nothing where the shaders leave it out.
        let ambient_off = text.contains("#define SCENE_AMBIENT 0");
        let lines: Vec<&str> = text.lines().collect();
        let at = lines.iter().position(|l| l.contains("glLightModelfv(GL_LIGHT_MODEL_AMBIENT")).unwrap();
        let above = lines[..at].iter().rev().take_while(|l| l.trim_start().starts_with('#')).count();
        let note = lines[at - above..at].join(" ");
        assert_eq!(note.contains("changes nothing"), ambient_off, "{name}: {note:?}");
        let at = lines.iter().position(|l| l.trim() == "glEnable(GL_LIGHTING)").unwrap();
        assert!(lines[at - 1].trim_start().starts_with('#') && text.contains("these shaders would not"), "{name}");
    }
}
