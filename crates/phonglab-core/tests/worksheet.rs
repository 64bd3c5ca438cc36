//! The worksheet: with mview5 the engine's worked calculation prints the worksheet's own
//! values; with each of the five modelviews every step equals an independent, literal
//! transcription of the worksheet's steps (to 1e-7, as the worksheet prints 8 digits).

use glam::{DMat3, DVec3, DVec4, Vec4Swizzles};
use phonglab_core::explain::{Side, explain};
use phonglab_core::{Engine, Rules, presets};

/// The worksheet's printout with mview5 (DESIGN.md).
const PRINTED: [(&str, [f64; 4]); 7] = [
    ("vertexNormal", [0.0, 0.6, 0.8, 0.0]),
    ("vlv", [0.79220526, 0.55887606, -0.2450885, 0.0]),
    ("vov", [0.0, 0.0, 1.0, 0.0]),
    ("Iamb", [0.2125, 0.1275, 0.054, 0.0]),
    ("Idif", [0.09942795, 0.05965677, 0.0252664, 0.0]),
    ("Ispec", [0.00040551, 0.00028017, 0.00017179, 0.0]),
    ("I", [0.05958709, 0.03575929, 0.01515525, 0.0]),
];

fn assert_close(name: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{name}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= tol, "{name}: got {got:?}, want {want:?}");
    }
}

#[test]
fn mview5_prints_the_worksheets_values() {
    let scene = presets::worksheet(5);
    let lit = Engine::<f64>::light_scene_vertex(&scene).unwrap();
    let ex = explain(&scene, &lit, Side::Front);
    for (name, want) in PRINTED {
        let got = ex.value(name).unwrap_or_else(|| panic!("no step {name}"));
        assert_close(name, got, &want, 1e-7);
    }
    // The f32 engine too (the worksheet's code used single precision).
    let lit32 = Engine::<f32>::light_scene_vertex(&scene).unwrap();
    let ex32 = explain(&scene, &lit32, Side::Front);
    for (name, want) in PRINTED {
        assert_close(name, ex32.value(name).unwrap(), &want, 1e-7);
    }
    let text = ex.to_text(8);
    assert!(text.contains("vlv = [0.79220526 0.55887606 -0.2450885 0]"), "{text}");
    assert!(text.contains("vertexNormal = [0 0.6 0.8 0]"), "{text}");
}

/// The worksheet's steps, transcribed literally (f64, no robustness tricks).
struct Hand {
    normal: DVec3,
    l: DVec3,
    v: DVec3,
    iamb: DVec3,
    idif: DVec3,
    h: DVec3,
    ispec: DVec3,
    at: f64,
    i: DVec3,
}

fn by_hand(k: usize) -> Hand {
    let m = phonglab_core::transform::worksheet_modelview(k).unwrap();
    let normal = DMat3::from_mat4(m).inverse().transpose() * DVec3::Z;
    let vertex = (m * DVec4::new(-512.0, -384.0, 0.0, 1.0)).xyz();
    let light = (m * DVec4::new(0.0, 0.0, 90.0, 1.0)).xyz();
    let l = (light - vertex).normalize();
    let v = DVec3::Z;
    let (ma, md, ms) = (
        DVec3::new(0.2125, 0.1275, 0.054),
        DVec3::new(0.714, 0.4284, 0.18144),
        DVec3::new(0.393548, 0.271906, 0.166721),
    );
    let iamb = ma;
    let cos_theta = normal.dot(l);
    let idif = if cos_theta > 0.0 { md * cos_theta } else { DVec3::ZERO };
    let h = (l + v).normalize();
    let cos_beta = normal.dot(h);
    let ispec = if cos_beta > 0.0 { ms * cos_beta.powf(0.2 * 128.0) } else { DVec3::ZERO };
    let d = (light - vertex).length();
    let at = 1.0 + 0.0001 * d + 0.00001 * d * d;
    Hand { normal, l, v, iamb, idif, h, ispec, at, i: (iamb + idif + ispec) / at }
}

#[test]
fn all_five_modelviews_match_the_worksheets_steps() {
    for k in 1..=5 {
        let scene = presets::worksheet(k);
        let hand = by_hand(k);
        for lit in [Engine::<f64>::light_scene_vertex(&scene).map(|l| explain(&scene, &l, Side::Front))] {
            let ex = lit.unwrap();
            let v4 = |v: DVec3| [v.x, v.y, v.z, 0.0];
            for (name, want) in [
                ("vertexNormal", v4(hand.normal)),
                ("vlv", v4(hand.l)),
                ("vov", v4(hand.v)),
                ("Iamb", v4(hand.iamb)),
                ("Idif", v4(hand.idif)),
                ("hv", v4(hand.h)),
                ("Ispec", v4(hand.ispec)),
                ("I", v4(hand.i)),
            ] {
                assert_close(&format!("mview{k} {name}"), ex.value(name).unwrap(), &want, 1e-7);
            }
            assert_close(&format!("mview{k} at"), ex.value("at").unwrap(), &[hand.at], 1e-7 * hand.at);
        }
        let ex32 = explain(&scene, &Engine::<f32>::light_scene_vertex(&scene).unwrap(), Side::Front);
        let i = ex32.value("I").unwrap();
        assert_close(&format!("mview{k} I (f32)"), &i[..3], &[hand.i.x, hand.i.y, hand.i.z], 1e-7);
    }
}

#[test]
fn the_modelviews_give_different_eye_space_geometry() {
    // Guards against a helper that ignores its index. (The colours themselves may agree:
    // with an infinite viewer a translation changes nothing relative, and a rotation about
    // z leaves this z-symmetric setup alone.)
    let ls: Vec<DVec3> = (1..=5).map(|k| by_hand(k).l).collect();
    for a in 0..5 {
        for b in a + 1..5 {
            assert!((ls[a] - ls[b]).length() > 1e-3, "mview{} and mview{} give the same L: {ls:?}", a + 1, b + 1);
        }
    }
}

#[test]
fn opengl_rules_add_the_scene_ambient_as_mesa_does() {
    let mut scene = presets::worksheet(5);
    scene.rules = Rules::OPENGL;
    let lit = Engine::<f32>::light_scene_vertex(&scene).unwrap();
    // Mesa llvmpipe with the default light-model ambient 0.2 (DESIGN.md).
    assert_close("I", &lit.front.primary.map(|x| x as f64), &[0.102087, 0.061259, 0.025955, 1.0], 1e-6);
}
