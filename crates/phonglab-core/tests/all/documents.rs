//! Scene files: saving any valid document and loading it gives back the same document,
//! and files that are not valid are refused with a message naming where and why.

use crate::common;

use glam::{DMat4, DVec3, DVec4};
use phonglab_core::scene::{ColorMaterial, ColorMaterialMode, Face};
use phonglab_core::view::{FlatNormal, Framing, LightingSpace, ObjectKind, Shading, View, ViewCamera};
use phonglab_core::{
    CameraSpec, Document, DocumentError, Light, LightModel, LightPlacement, Material, NormalMode, RuleSet, Rules,
    Scene, SpecularModel, Vertex,
};
use proptest::prelude::*;

/// Any number a float can hold, from the tiny to the huge, negative zero included.
fn num() -> BoxedStrategy<f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        1 => Just(-0.0),
        1 => (-37i32..38, 0.2..1.0f64, any::<bool>()).prop_map(|(e, m, neg)| if neg { -m } else { m } * 10f64.powi(e)),
        1 => any::<f32>().prop_filter("a normal float", |x| x.is_normal()).prop_map(f64::from),
    ]
    .prop_filter("a float", |x| phonglab_core::validate::is_float(*x))
    .boxed()
}

fn v3() -> BoxedStrategy<DVec3> {
    (num(), num(), num()).prop_map(|(x, y, z)| DVec3::new(x, y, z)).boxed()
}

fn v4() -> BoxedStrategy<DVec4> {
    (num(), num(), num(), num()).prop_map(|(x, y, z, w)| DVec4::new(x, y, z, w)).boxed()
}

fn m4() -> BoxedStrategy<DMat4> {
    prop::array::uniform16(num()).prop_map(|a| DMat4::from_cols_array(&a)).boxed()
}

fn material() -> BoxedStrategy<Material> {
    (v4(), v4(), v4(), v4(), prop_oneof![Just(0.0), Just(128.0), 0.0..=128.0f64])
        .prop_map(|(ambient, diffuse, specular, emission, shininess)| Material {
            ambient,
            diffuse,
            specular,
            emission,
            shininess,
        })
        .boxed()
}

fn light() -> BoxedStrategy<Light> {
    common::light_from(
        (v4(), v4(), v4()),
        (v3(), prop_oneof![Just(0.0), Just(1.0), num()]).prop_map(|(p, w)| p.extend(w)),
        v3(),
        prop_oneof![Just(180.0), 0.0..=90.0f64],
        0.0..=128.0f64,
        (0.001..10.0f64, 0.0..1.0f64, 0.0..1.0f64).prop_map(|(a, b, c)| [a, b, c]),
        prop_oneof![
            Just(LightPlacement::Eye),
            Just(LightPlacement::World),
            Just(LightPlacement::Object),
            m4().prop_map(LightPlacement::Matrix),
        ],
    )
    .boxed()
}

fn camera() -> BoxedStrategy<CameraSpec> {
    prop_oneof![
        (1u8..=5).prop_map(CameraSpec::Worksheet),
        (v3(), v3(), v3()).prop_map(|(eye, centre, up)| CameraSpec::LookAt { eye, centre, up }),
        (1.0..8192.0f64, 1.0..8192.0f64).prop_map(|(width, height)| CameraSpec::OpenFrameworks { width, height }),
        m4().prop_map(CameraSpec::Matrix),
    ]
    .prop_filter("a camera with a view matrix of floats", |c| {
        c.matrix().is_ok_and(|m| m.to_cols_array().iter().all(|x| phonglab_core::validate::is_float(*x)))
    })
    .boxed()
}

fn view() -> BoxedStrategy<View> {
    (
        (prop::sample::select(ObjectKind::ALL.to_vec()), prop::sample::select(Shading::ALL.to_vec())),
        (3u32..=400, 3u32..=400, 1u32..=64, 3u32..=400, 1u32..=400),
        (any::<bool>(), any::<bool>(), any::<bool>()),
        (num(), num(), -89.0..=89.0f64, 0.6..=20.0f64),
        (
            prop::sample::select(Framing::ALL.to_vec()),
            any::<bool>(),
            any::<bool>(),
            any::<bool>(),
            any::<bool>(),
            prop::array::uniform3(-1.0e3f32..1.0e3),
        ),
    )
        .prop_map(|((object, shading), t, (caps, demo, spin), (spin_degrees, yaw, pitch, distance), more)| View {
            object,
            shading,
            sphere_slices: t.0,
            sphere_stacks: t.1,
            teapot_grid: t.2,
            cylinder_slices: t.3,
            cylinder_stacks: t.4,
            cylinder_caps: caps,
            demo_normals: demo,
            auto_rotate: spin,
            spin_degrees,
            camera: ViewCamera { yaw, pitch, distance },
            framing: more.0,
            lighting_space: if more.1 { LightingSpace::Object } else { LightingSpace::Eye },
            flat_normal: if more.2 { FlatNormal::ScreenDerivatives } else { FlatNormal::Face },
            phong_renormalize: more.3,
            cylinder_centered: more.4,
            background: more.5,
            obj: None,
        })
        .boxed()
}

prop_compose! {
    fn document()(
        // Any printable name (a scene file refuses control characters and line separators).
        name in "[^\\p{C}\\p{Zl}\\p{Zp}]{0,40}",
        camera in camera(),
        lights in prop::collection::vec(light(), 0..=8),
        material in material(),
        back in prop::option::of(material()),
        color_material in prop::option::of((0..3usize, 0..5usize, v4())),
        world_from_object in prop_oneof![Just(DMat4::IDENTITY), m4()],
        normal_mode in prop::sample::select(vec![NormalMode::AsIs, NormalMode::Normalize, NormalMode::Rescale]),
        set in prop::sample::select(RuleSet::ALL.to_vec()),
        specular in prop::sample::select(SpecularModel::ALL.to_vec()),
        flags in (any::<bool>(), any::<bool>(), any::<bool>()),
        ambient in v4(),
        vertex in (v4(), v3()),
        view in view(),
    ) -> Document {
        let scene = Scene {
            light_model: LightModel { ambient, local_viewer: flags.0, two_sided: flags.1, separate_specular: flags.2 },
            lights, material, back_material: back,
            color_material: color_material.map(|(face, mode, color)| ColorMaterial {
                face: [Face::Front, Face::Back, Face::FrontAndBack][face],
                mode: ColorMaterialMode::ALL[mode],
                color,
            }),
            eye_from_world: DMat4::IDENTITY, world_from_object, normal_mode,
            rules: Rules { set, specular },
            vertex: Vertex { position: vertex.0, normal: vertex.1 },
        };
        let mut doc = Document::from_scene(&name, camera, scene);
        doc.view = view;
        doc
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn saving_and_loading_gives_back_the_same_document(doc in document()) {
        prop_assert!(doc.validate().is_ok(), "{:?}", doc.validate());
        let text = doc.to_toml().unwrap();
        let back = Document::from_toml(&text);
        prop_assert!(back.is_ok(), "{:?}\n{text}", back);
        let back = back.unwrap();
        // Bit for bit, so -0.0 stays -0.0.
        prop_assert_eq!(format!("{back:?}"), format!("{doc:?}"), "{}", text);
        prop_assert_eq!(back, doc);
    }

    /// Whatever the text, parsing returns (a document or a message), never panics, and a
    /// document it returns is valid.
    #[test]
    fn any_text_parses_or_is_refused(text in "\\PC{0,200}") {
        if let Ok(doc) = Document::from_toml(&text) {
            prop_assert!(doc.validate().is_ok());
        }
    }

    /// A saved document with one line cut out still loads or is refused with a message.
    #[test]
    fn a_damaged_file_is_refused_or_loads_valid(doc in document(), cut in any::<prop::sample::Index>()) {
        let text = doc.to_toml().unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let k = cut.index(lines.len());
        let damaged: String = lines.iter().enumerate().filter(|(i, _)| *i != k).map(|(_, l)| format!("{l}\n")).collect();
        match Document::from_toml(&damaged) {
            Ok(d) => prop_assert!(d.validate().is_ok()),
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
    }
}

#[test]
fn non_finite_values_are_refused_by_name() {
    for (text, field) in [
        ("[material]\nshininess = nan\n", "material.shininess"),
        ("[material]\ndiffuse = [1, inf, 0]\n", "material.diffuse[1]"),
        ("[[lights]]\nposition = [0, 0, -inf, 1]\n", "lights[0].position[2]"),
        ("[vertex]\nposition = [0, 0, 0, 1]\nnormal = [nan, 0, 1]\n", "vertex.normal[0]"),
        ("[view]\nspin_degrees = inf\n", "view.spin_degrees"),
        ("[material]\nemission = [1e300, 0, 0]\n", "material.emission[0]"),
        ("[[lights]]\nattenuation = [1e-300, 0, 0]\n", "lights[0].attenuation[0]"),
    ] {
        let e = Document::from_toml(text).unwrap_err();
        assert!(matches!(e, DocumentError::Invalid(_)), "{text}: {e:?}");
        assert!(e.to_string().contains(field), "{text}: {e}");
    }
}

#[test]
fn syntax_errors_name_the_line_and_column() {
    let e = Document::from_toml("name = \"x\"\n[material]\nshininess = = 3\n").unwrap_err();
    let msg = e.to_string();
    assert!(matches!(e, DocumentError::Syntax(_)));
    assert!(msg.contains("line 3") && msg.contains("column"), "{msg}");
    let e = Document::from_toml(
        "[[lights]]\n[[lights]]\n[[lights]]\n[[lights]]\n[[lights]]\n[[lights]]\n[[lights]]\n[[lights]]\n[[lights]]\n",
    )
    .unwrap_err();
    assert!(e.to_string().contains('9') && e.to_string().contains('8'), "{e}");
}

#[test]
fn a_camera_that_does_not_give_the_view_matrix_is_refused_in_a_sentence() {
    let mut doc = phonglab_core::Document::default();
    doc.scene.eye_from_world = DMat4::IDENTITY;
    let e = doc.validate().unwrap_err().to_string();
    assert!(e.contains("the scene's view matrix is not the one its camera gives (Worksheet modelview)"), "{e}");
    assert!(!e.contains("NaN"), "{e}");
}
