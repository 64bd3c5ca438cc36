//! Every OpenGL field phonglab models appears in every place it must (the recipe of
//! docs/adding-a-gl-field.md): the engine, the scene file, a glref case, the worked
//! calculation, the notebook, the PyOpenGL program, the openFrameworks app, the generated
//! shader (text and uniform values), the CPU renderer's picture, and the window's
//! controls. For each field, a scene where it is at OpenGL's initial state and one where
//! it is not: each place's output must differ between the two (a field one place forgot
//! leaves that place's output unchanged, and this test names the field and the place),
//! and the scene file and the glref case must give the field back.
//!
//! A term of the equation that a rule chooses (`TERMS`: energy-conserving Blinn-Phong) is
//! held to the same places but the glref case, which is GL's state and always means
//! OpenGL's rules; the window must name it.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use glam::DVec4;
use phonglab::app::{AppState, app_ui};
use phonglab_core::explain::{Side, explain};
use phonglab_core::export::{key, notebook, openframeworks, pyopengl, shaded_key};
use phonglab_core::scene::{ColorMaterial, ColorMaterialMode, Face};
use phonglab_core::shader::{ShaderShading, ShadingLanguage, for_view, uniform_value};
use phonglab_core::{Document, Engine, PowFn, glref, presets};

/// A field: its name, a scene with it at OpenGL's initial state (`base`), the same scene
/// with it set (`set`), and the catalogue message labelling its control in the window.
struct Field {
    name: &'static str,
    base: fn(&mut Document),
    set: fn(&mut Document),
    label: &'static str,
}

/// The worksheet's scene under OpenGL's rules, with its shaded view in Phong shading (what
/// the PyOpenGL program draws), one spotlight aimed near the vertex, and a white specular
/// material.
fn scene() -> Document {
    let mut doc = Document::from_scene("fields", phonglab_core::CameraSpec::default(), presets::worksheet(5));
    doc.scene.rules = phonglab_core::Rules::OPENGL;
    doc.scene.material.specular = DVec4::new(0.6, 0.6, 0.6, 1.0);
    doc.scene.material.shininess = 20.0;
    doc.view.shading = phonglab_core::Shading::Phong;
    doc
}

/// A spotlight whose axis passes near (not through) the vertex, so its exponent matters.
fn spot(doc: &mut Document) {
    let s = &mut doc.scene;
    let to_vertex = s.vertex.position.truncate() / s.vertex.position.w - s.lights[0].position.truncate();
    s.lights[0].spot_direction = to_vertex + glam::DVec3::new(40.0, 0.0, 0.0);
    s.lights[0].spot_cutoff = 90.0;
}

const FIELDS: &[Field] = &[
    Field {
        name: "spot_exponent",
        base: spot,
        set: |d| {
            spot(d);
            d.scene.lights[0].spot_exponent = 7.25;
        },
        label: "spot-exponent",
    },
    Field {
        name: "color_material",
        base: |_| {},
        set: |d| {
            d.scene.color_material = Some(ColorMaterial {
                face: Face::FrontAndBack,
                mode: ColorMaterialMode::AmbientAndDiffuse,
                color: DVec4::new(1.0, 0.55, 0.0, 1.0),
            });
        },
        label: "color-material",
    },
    Field {
        name: "color_material (specular, front)",
        base: |_| {},
        set: |d| {
            d.scene.color_material = Some(ColorMaterial {
                face: Face::Front,
                mode: ColorMaterialMode::Specular,
                color: DVec4::new(0.2, 0.9, 0.3, 1.0),
            });
        },
        label: "color-material",
    },
    Field { name: "shininess", base: |_| {}, set: |d| d.scene.material.shininess = 64.0, label: "material-shininess" },
    Field {
        name: "attenuation (linear)",
        base: |_| {},
        set: |d| d.scene.lights[0].attenuation[1] = 0.01,
        label: "attenuation-linear",
    },
    Field {
        name: "separate_specular",
        base: |_| {},
        set: |d| d.scene.light_model.separate_specular = true,
        label: "separate-specular",
    },
];

/// The terms a rule chooses, each a "field" whose base is the scene under the rule without
/// it and whose label is the term's name in the catalogue.
const TERMS: &[Field] = &[Field {
    name: "specular = blinn-phong-normalised",
    base: |_| {},
    set: |d| d.scene.rules.specular = phonglab_core::SpecularModel::BlinnPhongNormalised,
    label: "specular-blinn-phong-normalised",
}];

/// What a place makes of a document, as text: two documents whose outputs differ give
/// different texts.
type Place = (&'static str, fn(&Document) -> String);

fn places() -> Vec<Place> {
    vec![
        ("the engine", |d| {
            let lit = Engine::<f64>::light_scene_vertex(&d.scene).unwrap();
            format!("{:?} {:?} {:?} {:?}", lit.front.primary, lit.front.secondary, lit.back.primary, lit.back.secondary)
        }),
        ("the scene file", |d| d.to_toml().unwrap()),
        ("the glref case", |d| glref::case_json("fields", &d.scene).to_string()),
        ("explain", |d| {
            let lit = Engine::<f64>::light_scene_vertex(&d.scene).unwrap();
            explain(&d.scene, &lit, Side::Front).to_text(8)
        }),
        ("the notebook", |d| notebook::notebook(d, &key(d))),
        ("the PyOpenGL program", |d| pyopengl::program(d, &shaded_key(d)).unwrap()),
        ("the openFrameworks app", |d| {
            openframeworks::app(d, &shaded_key(d)).unwrap().into_iter().map(|(n, t)| format!("{n}\n{t}")).collect()
        }),
        ("the shader", |d| {
            let shader = for_view(d, ShadingLanguage::Glsl, ShaderShading::Phong).unwrap();
            let setup = d.shaded_setup(PowFn::Exact);
            let values: Vec<String> = shader
                .uniforms
                .iter()
                .map(|(n, _)| format!("{n} = {:?}", uniform_value(&setup.scene, &setup.clip_from_object, n)))
                .collect();
            format!("{}\n{}", shader.text(ShadingLanguage::Glsl), values.join("\n"))
        }),
        ("the CPU renderer", |d| {
            let setup = d.shaded_setup(PowFn::Exact);
            let mesh = d.view.mesh();
            let mut r = phonglab_core::render::Renderer::new();
            let (img, _) = r.render(&setup.job(&mesh), 96, 96).unwrap();
            format!("{:?}", img.rgba)
        }),
    ]
}

fn with(field: &Field, which: fn(&Field) -> fn(&mut Document)) -> Document {
    let mut doc = scene();
    which(field)(&mut doc);
    doc.scene.validate().unwrap();
    doc
}

#[test]
fn every_field_changes_every_place() {
    let places = places();
    let mut missing = Vec::new();
    for field in FIELDS {
        let (base, set) = (with(field, |f| f.base), with(field, |f| f.set));
        assert_ne!(base.scene, set.scene, "{}: the field's value is its initial one", field.name);
        for (place, output) in &places {
            if output(&base) == output(&set) {
                missing.push(format!("{} does not reach {place}", field.name));
            }
        }
    }
    assert!(missing.is_empty(), "fields that miss a place:\n{}", missing.join("\n"));
}

#[test]
fn every_term_changes_every_place_but_the_glref_case() {
    let mut missing = Vec::new();
    for term in TERMS {
        let (base, set) = (with(term, |f| f.base), with(term, |f| f.set));
        assert_ne!(base.scene, set.scene, "{}: the term is already the scene's", term.name);
        for (place, output) in places().iter().filter(|(place, _)| *place != "the glref case") {
            if output(&base) == output(&set) {
                missing.push(format!("{} does not reach {place}", term.name));
            }
        }
        let again = Document::from_toml(&set.to_toml().unwrap()).unwrap();
        assert_eq!(again.scene, set.scene, "{}: the scene file loses it", term.name);
    }
    assert!(missing.is_empty(), "terms that miss a place:\n{}", missing.join("\n"));
}

/// The window names each term where its scene uses it (the worked calculation's heading,
/// the rules' menu).
#[test]
fn every_term_is_named_in_the_window() {
    for term in TERMS {
        let mut state = AppState::worksheet();
        state.doc = with(term, |f| f.set);
        let mut h =
            Harness::builder().with_size([1500.0, 2400.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
        h.run_steps(3);
        let label = phonglab::locale::tr(term.label);
        assert!(h.query_all_by_label_contains(&label).next().is_some(), "{}: {label:?} nowhere", term.name);
    }
}

#[test]
fn every_field_comes_back_from_the_scene_file_and_the_glref_case() {
    for field in FIELDS {
        let doc = with(field, |f| f.set);
        let again = Document::from_toml(&doc.to_toml().unwrap()).unwrap();
        assert_eq!(again.scene, doc.scene, "{}: the scene file loses it", field.name);
        let case = glref::parse_case(&glref::case_json("fields", &doc.scene), 0).unwrap();
        // A case has the modelview already applied to the object and its light placed in
        // eye space, so its own scene is compared through what it lights.
        let lit = |s: &phonglab_core::Scene| {
            let l = Engine::<f64>::light_scene_vertex(s).unwrap();
            (l.front.primary, l.front.secondary, l.back.primary)
        };
        let (a, b) = (lit(&case.scene), lit(&doc.scene));
        let close = |x: [f64; 4], y: [f64; 4]| x.iter().zip(y).all(|(p, q)| (p - q).abs() <= 1e-9 * q.abs().max(1.0));
        assert!(
            close(a.0, b.0) && close(a.1, b.1) && close(a.2, b.2),
            "{}: the glref case lights {a:?}, not {b:?}",
            field.name
        );
    }
}

/// The window shows each field's control, labelled from the catalogue, once the field is
/// set (the sections it lives in open).
#[test]
fn every_field_has_a_labelled_control_in_the_window() {
    for field in FIELDS {
        let mut state = AppState::worksheet();
        state.doc = with(field, |f| f.set);
        let mut h =
            Harness::builder().with_size([1500.0, 2400.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
        h.run_steps(3);
        let label = phonglab::locale::tr(field.label);
        assert!(
            h.query_all_by_label_contains(&label).next().is_some(),
            "{}: no control labelled {label:?}",
            field.name
        );
    }
}

/// Where `GL_COLOR_MATERIAL` tracks a material colour, the window greys that colour's
/// fields (they are not what lights the vertex) and leaves the others editable.
#[test]
fn the_colours_colour_material_tracks_are_greyed() {
    let mut state = AppState::worksheet();
    state.doc = with(&FIELDS[1], |f| f.set);
    let mut h =
        Harness::builder().with_size([1500.0, 2400.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(3);
    let enabled = |label: &str| -> Vec<bool> {
        let label = phonglab::locale::tr(label);
        h.query_all_by_label_contains(&label).map(|n| !n.accesskit_node().is_disabled()).collect()
    };
    for (label, want) in [("material-ambient", false), ("material-diffuse", false), ("material-specular", true)] {
        let got = enabled(label);
        assert!(!got.is_empty(), "no {label} fields");
        assert!(got.iter().all(|e| *e == want), "{label}: enabled {got:?}, want {want}");
    }
}
