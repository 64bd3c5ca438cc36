//! The scene files under `assets/scenes/`: each loads, evaluates, and lights its vertex as a
//! real OpenGL does (Mesa llvmpipe's results in `tests/data/scenes_mesa.json`, made with
//! `phonglab case` and the glref harness).

use std::path::{Path, PathBuf};

use phonglab::cli::case::cases_json;
use phonglab_core::glref::{self, CaseColors};
use phonglab_core::{Document, Engine, EvalOptions, LightPlacement, Rules, materials, presets};

use crate::common;

use common::scene_files;

fn load(p: &Path) -> Document {
    let text = std::fs::read_to_string(p).unwrap();
    Document::from_toml(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

fn asset(name: &str) -> Document {
    load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes").join(name))
}

#[test]
fn every_scene_file_loads_and_lights_its_vertex() {
    let files = scene_files();
    assert_eq!(files.len(), 5 + 1 + 24 + 4, "{files:?}");
    for p in &files {
        let doc = load(p);
        assert!(!doc.name.is_empty(), "{}", p.display());
        let lit32 = Engine::<f32>::new(&doc.scene).unwrap().light(&doc.scene.vertex);
        let lit64 = Engine::<f64>::new(&doc.scene).unwrap().light(&doc.scene.vertex);
        for k in 0..4 {
            let (a, b) = (lit32.front.primary[k] as f64, lit64.front.primary[k]);
            assert!(a.is_finite() && (a - b).abs() < 1e-5, "{}: {a} vs {b}", p.display());
        }
        assert!(lit64.front.primary[..3].iter().any(|&c| c > 0.01), "{} is lit", p.display());
        // And it survives a save and a load unchanged.
        assert_eq!(Document::from_toml(&doc.to_toml().unwrap()).unwrap(), doc, "{}", p.display());
    }
}

#[test]
fn the_worksheet_files_are_the_worksheet() {
    for k in 1..=5 {
        let doc = asset(&format!("worksheet-mview{k}.toml"));
        assert_eq!(doc.scene, presets::worksheet(k), "mview{k}");
    }
    let lit = Engine::<f64>::new(&asset("worksheet-mview5.toml").scene).unwrap().light(&presets::worksheet(5).vertex);
    for (got, want) in lit.front.primary.iter().zip([0.05958709, 0.03575929, 0.01515525]) {
        assert!((got - want).abs() < 1e-8, "I = {got}, the worksheet prints {want}");
    }
}

#[test]
fn the_phong_demo_file_is_the_preset() {
    let doc = asset("phong-demo.toml");
    let preset = phonglab_core::library::phong_demo_document();
    assert_eq!(doc.scene, preset.scene);
    assert_eq!(doc.view, preset.view);
    assert_eq!(doc.camera, preset.camera);
    // The demo's choices, as the program makes them.
    assert_eq!((doc.scene.rules, doc.scene.material.shininess), (Rules::PHONG_DEMO, 100.0));
    assert_eq!(doc.scene.material.specular.truncate(), glam::DVec3::new(0.5, 0.0, 0.0), "the highlight is red");
    assert!(doc.view.auto_rotate && doc.view.demo_normals && !doc.view.phong_renormalize);
    assert_eq!(doc.view.framing, phonglab_core::Framing::ClipSpace);
    assert_eq!(doc.view.lighting_space, phonglab_core::LightingSpace::Object);
}

#[test]
fn the_red_book_teapots_are_the_24_classic_materials() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/redbook-teapots");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    let table = materials::classic();
    assert_eq!(files.len(), table.len());
    for (p, m) in files.iter().zip(table) {
        let doc = load(p);
        assert_eq!(doc.scene.material, m.material, "{}", p.display());
        let l = &doc.scene.lights[0];
        assert_eq!((l.position.to_array(), &l.placement), ([0.0, 3.0, 3.0, 0.0], &LightPlacement::Eye));
        assert_eq!(doc.scene.light_model.ambient.x, 0.2);
        assert_eq!(doc.scene.normal_mode, phonglab_core::NormalMode::Normalize);
    }
}

fn close(ours: [f64; 4], mesa: [f64; 4]) -> bool {
    ours.iter().zip(mesa).all(|(a, b)| (a - b).abs() <= 1e-6 + 1e-5 * b.abs())
}

#[test]
fn every_scene_file_lights_as_mesa_does() {
    let stored =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/scenes_mesa.json")).unwrap();
    let stored = glref::parse_cases(&stored).unwrap();
    let files = scene_files();
    let fresh = cases_json(&files).unwrap();
    let fresh = fresh["cases"].as_array().unwrap();
    assert_eq!(stored.len(), files.len(), "regenerate tests/data/scenes_mesa.json (see its README)");
    for (p, json) in files.iter().zip(fresh) {
        let stem = p.file_stem().and_then(|s| s.to_str()).unwrap();
        let Some((_, case)) = stored.iter().find(|(id, _)| id == stem) else {
            panic!("{stem} has no stored case: regenerate tests/data/scenes_mesa.json")
        };
        let case = case.as_ref().unwrap();
        // The stored case is this file's (the files have not moved on since Mesa ran).
        let again = glref::parse_case(json, 0).unwrap();
        assert_eq!(again.scene, case.scene, "{}: regenerate tests/data/scenes_mesa.json", p.display());
        // A case means OpenGL's rules, whatever the file's.
        let mut scene = load(p).scene;
        scene.rules = Rules::OPENGL;
        let ours: CaseColors = glref::evaluate::<f32>(&scene, EvalOptions::default(), false).unwrap();
        let mesa = case.expected.unwrap();
        for (o, m, what) in [
            (ours.front, mesa.front, "front"),
            (ours.front_secondary, mesa.front_secondary, "front secondary"),
            (ours.back, mesa.back, "back"),
        ] {
            assert!(close(o, m), "{} {what}: phonglab {o:?}, Mesa {m:?}", p.display());
        }
    }
}

/// `GL_COLOR_MATERIAL` as Mesa lights it: every mode on every face, one- and two-sided,
/// with and without a back material (60 cases made from `of-set-color.toml` with
/// `phonglab case`, each run by Mesa in a fresh context: see tests/data/README.md), the
/// front and back colours, primary and secondary, within glref's tolerance.
#[test]
fn color_material_lights_as_mesa_does() {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/color_material_mesa.json"))
            .unwrap();
    let cases = glref::parse_cases(&text).unwrap();
    assert_eq!(cases.len(), 60);
    let mut tracked_differently = 0;
    for (id, case) in cases {
        let case = case.unwrap();
        let cm = case.scene.color_material.unwrap_or_else(|| panic!("{id}: no color_material read"));
        let ours: CaseColors = glref::evaluate::<f32>(&case.scene, EvalOptions::default(), false).unwrap();
        let mesa = case.expected.unwrap();
        for (o, m, what) in [
            (ours.front, mesa.front, "front"),
            (ours.front_secondary, mesa.front_secondary, "front secondary"),
            (ours.back, mesa.back, "back"),
            (ours.back_secondary, mesa.back_secondary, "back secondary"),
        ] {
            assert!(close(o, m), "{id} {what}: phonglab {o:?}, Mesa {m:?}");
        }
        // The colour material mattered: without it the colour is another one.
        let mut off = case.scene.clone();
        off.color_material = None;
        let plain: CaseColors = glref::evaluate::<f32>(&off, EvalOptions::default(), false).unwrap();
        let same = [
            (plain.front, mesa.front),
            (plain.front_secondary, mesa.front_secondary),
            (plain.back, mesa.back),
            (plain.back_secondary, mesa.back_secondary),
        ]
        .iter()
        .all(|(p, m)| close(*p, *m));
        if !same {
            tracked_differently += 1;
        }
        assert!(cm.color.w != 1.0, "{id}: the colour's alpha tells the diffuse's apart");
    }
    // It changes nothing where it tracks only the back material of a one-sided scene (both
    // sides light with the front's then: 5 modes, with and without a back material), nor
    // where it tracks only the back's specular and the back side faces away from the light
    // (no specular there: 2 cases); everywhere else it does.
    assert_eq!(tracked_differently, 48, "cases where the colour material changed a colour");
}

/// Save's first suggestion has the ending the .deb's MIME type claims, so a scene saved as
/// suggested opens with a double click (a plain `scene.toml` is any TOML file there).
#[test]
fn save_suggests_the_name_a_double_click_opens() {
    use phonglab::app::panels::files::{FileState, SUGGESTED_SCENE_NAME};
    assert_eq!(FileState::default().path, SUGGESTED_SCENE_NAME);
    let mime = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("packaging/linux/phonglab.xml"))
        .expect("the MIME type file");
    let ending = mime
        .split("<glob pattern=\"*")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .expect("a glob in the MIME type");
    assert_eq!(ending, ".phonglab.toml");
    assert!(
        SUGGESTED_SCENE_NAME.ends_with(ending) && SUGGESTED_SCENE_NAME.len() > ending.len(),
        "{SUGGESTED_SCENE_NAME}"
    );
}
