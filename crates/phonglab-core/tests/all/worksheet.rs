//! The worksheet: with mview5 the engine's worked calculation prints the worksheet's own
//! values; with each of its five modelviews (as printed in its cell `In [4]`) every step
//! equals what the worksheet's own Python cells compute when `mview` is set to it (run by
//! `scripts/worksheet_cells.py`, kept in `tests/data/worksheet_cells.json`), to 1e-7.

use glam::DVec3;
use phonglab_core::explain::{Side, explain};
use phonglab_core::{Engine, Rules, presets};

/// The worksheet's printout with mview5 (docs/lighting.md).
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

/// One run of the worksheet's own cells (`scripts/worksheet_cells.py`, kept in
/// `tests/data/worksheet_cells.json`): what it printed and the values behind the prints.
struct Run {
    mview: usize,
    rows: Vec<Vec<f64>>,
    printed: serde_json::Map<String, serde_json::Value>,
    values: serde_json::Map<String, serde_json::Value>,
}

fn runs() -> Vec<Run> {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/worksheet_cells.json"))
        .expect("tests/data/worksheet_cells.json is in the repository");
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    doc["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| Run {
            mview: r["mview"].as_u64().unwrap() as usize,
            rows: serde_json::from_value(r["modelview_rows"].clone()).unwrap(),
            printed: r["printed"].as_object().unwrap().clone(),
            values: r["values"].as_object().unwrap().clone(),
        })
        .collect()
}

fn nums(v: &serde_json::Value) -> Vec<f64> {
    match v {
        serde_json::Value::Array(a) => a.iter().map(|x| x.as_f64().unwrap()).collect(),
        x => vec![x.as_f64().unwrap()],
    }
}

/// numpy's printout `[0.  0.6 0.8 0. ]` as numbers.
fn parse_printed(s: &str) -> Vec<f64> {
    s.trim_matches(|c| c == '[' || c == ']').split_whitespace().map(|x| x.parse().unwrap()).collect()
}

#[test]
fn the_modelviews_are_the_worksheets_as_printed() {
    let runs = runs();
    assert_eq!(runs.len(), 5);
    for r in &runs {
        let m = phonglab_core::transform::worksheet_modelview(r.mview).unwrap();
        let ours = phonglab_core::transform::mat4_rows(&m);
        for (i, row) in r.rows.iter().enumerate() {
            assert_eq!(row.as_slice(), ours[i].as_slice(), "mview{} row {i}", r.mview);
        }
    }
    // mview2's third row is printed with one digit less ("-0.85749"): kept as printed.
    let m2 = phonglab_core::transform::mat4_rows(&phonglab_core::transform::worksheet_modelview(2).unwrap());
    assert_eq!(m2[2][1], -0.85749);
}

#[test]
fn all_five_modelviews_give_what_the_worksheets_code_prints() {
    for r in runs() {
        let k = r.mview;
        let scene = presets::worksheet(k);
        let v = |name: &str| nums(&r.values[name]);
        let steps = [
            ("vertexNormal", "vertexNormal"),
            ("vlv", "vlv"),
            ("vov", "vov"),
            ("Iamb", "Iamb"),
            ("cosTheta", "cosTheta"),
            ("Idif", "Idif"),
            ("H", "H"),
            ("vertexPos", "vertexPos"),
            ("lightPos", "lightPos"),
            ("cosBeta", "cosBeta"),
            ("Ispec", "Ispec"),
            ("d", "d"),
            ("I", "I"),
        ];
        let ex64 = explain(&scene, &Engine::<f64>::light_scene_vertex(&scene).unwrap(), Side::Front);
        let ex32 = explain(&scene, &Engine::<f32>::light_scene_vertex(&scene).unwrap(), Side::Front);
        for (ours, theirs) in steps {
            let want = v(theirs);
            // d is ~2000: its 1e-7 is relative.
            let tol = if ours == "d" { 1e-7 * want[0] } else { 1e-7 };
            assert_close(&format!("mview{k} {ours}"), ex64.value(ours).unwrap(), &want, tol);
            let tol32 = if ours == "d" { 1e-6 * want[0] } else { 1e-6 };
            assert_close(&format!("mview{k} {ours} (f32)"), ex32.value(ours).unwrap(), &want, tol32);
        }
        let at = v("at")[0];
        assert_close(&format!("mview{k} at"), ex64.value("at").unwrap(), &[at], 1e-7 * at);
        // And every printed line, to its 8 digits.
        for (name, text) in &r.printed {
            let want = parse_printed(text.as_str().unwrap());
            assert_close(&format!("mview{k} printed {name}"), ex64.value(name).unwrap(), &want, 1e-8);
        }
    }
}

#[test]
fn mview2_normal_differs_from_opengls_and_the_calculation_says_so() {
    let scene = presets::worksheet(2);
    let ex = explain(&scene, &Engine::<f64>::light_scene_vertex(&scene).unwrap(), Side::Front);
    let n = ex.steps.iter().find(|s| s.name == "vertexNormal").unwrap();
    assert!(n.formula.contains("M itself"), "{}", n.formula);
    assert!(n.notes.iter().any(|x| x.contains("(M^-1)^T")), "{:?}", n.notes);
    // mview5 is a true rotation: no such note.
    let scene5 = presets::worksheet(5);
    let ex5 = explain(&scene5, &Engine::<f64>::light_scene_vertex(&scene5).unwrap(), Side::Front);
    assert!(ex5.steps.iter().find(|s| s.name == "vertexNormal").unwrap().notes.is_empty());
    // Under OpenGL's rules mview2's normal is the inverse transpose's, and differs.
    let mut gl = scene.clone();
    gl.rules = Rules::OPENGL;
    let a = Engine::<f64>::light_scene_vertex(&scene).unwrap().normal_in_eye;
    let b = Engine::<f64>::light_scene_vertex(&gl).unwrap().normal_in_eye;
    assert!((a - b).length() > 1e-6 && (a - b).length() < 1e-4, "{a} vs {b}");
}

#[test]
fn the_modelviews_give_different_eye_space_geometry() {
    // Guards against a helper that ignores its index.
    let ls: Vec<DVec3> = (1..=5)
        .map(|k| {
            let s = presets::worksheet(k);
            Engine::<f64>::light_scene_vertex(&s).unwrap().lights()[0].l
        })
        .collect();
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
    // Mesa llvmpipe with the default light-model ambient 0.2 (docs/lighting.md).
    assert_close("I", &lit.front.primary.map(|x| x as f64), &[0.102087, 0.061259, 0.025955, 1.0], 1e-6);
}

/// The specular step's note says which cosine gates it and what f is otherwise, in each
/// rule set and language: the worksheet's specular cosine (`cosBeta`, `cosAlpha` under
/// Phong's rule), OpenGL's `cosTheta` (n · L). (It said "only where cos > 0" under the
/// worksheet's rules, and "f = 1 if cosTheta > 0" with no "otherwise" under OpenGL's.)
#[test]
fn the_specular_note_says_the_condition_of_each_rule_set() {
    use phonglab_core::locale::{Lang, Locale, with_locale};
    use phonglab_core::rules::SpecularModel;
    let cases = [
        (Rules::WORKSHEET, "cosBeta > 0"),
        (Rules { specular: SpecularModel::Phong, ..Rules::WORKSHEET }, "cosAlpha > 0"),
        (Rules::OPENGL, "cosTheta > 0"),
    ];
    let otherwise = [(Lang::En, "if", "else 0"), (Lang::PtPt, "se", "senão 0"), (Lang::PtBr, "se", "senão 0")];
    for (rules, cond) in cases {
        let mut scene = presets::worksheet(5);
        scene.rules = rules;
        let lit = Engine::<f64>::light_scene_vertex(&scene).unwrap();
        for (lang, when, other) in otherwise {
            let ex = with_locale(Locale::of(lang), || explain(&scene, &lit, Side::Front));
            let step = ex.steps.iter().find(|s| s.name.starts_with("Ispec")).expect("a specular step");
            let said = format!("f = 1 {when} {cond}, {other}");
            assert!(step.formula.contains(&said), "{rules} {lang:?}: {:?} lacks {said:?}", step.formula);
        }
    }
}

/// A light that is not a spotlight is said so in Portuguese too: "abertura de 180°", not
/// the English "cutoff 180".
#[test]
fn the_spot_step_of_no_spotlight_is_in_the_readers_language() {
    use phonglab_core::locale::{Lang, Locale, with_locale};
    let scene = presets::worksheet(5);
    let lit = Engine::<f64>::light_scene_vertex(&scene).unwrap();
    for (lang, said) in [(Lang::En, "cutoff 180"), (Lang::PtPt, "abertura de 180°"), (Lang::PtBr, "abertura de 180°")]
    {
        let ex = with_locale(Locale::of(lang), || explain(&scene, &lit, Side::Front));
        let step = ex.steps.iter().find(|s| s.name.starts_with("spot")).expect("a spot step");
        assert!(step.formula.contains(said), "{lang:?}: {:?}", step.formula);
        if lang != Lang::En {
            assert!(!step.formula.contains("cutoff"), "{lang:?}: {:?}", step.formula);
        }
    }
}
