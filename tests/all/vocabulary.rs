//! One vocabulary: the worked calculation, the quiz, the exercise sheets and the vector
//! plot use the worksheet's own names (read from its cells' text, kept in
//! `tests/data/worksheet_cells.json`) wherever it has one, with OpenGL's beside them.

use std::collections::BTreeSet;

use phonglab_core::explain::{Side, explain};
use phonglab_core::{Engine, presets};

/// The names the worksheet's cells assign (`vlv = ...`, `H = H/...`).
fn worksheet_names() -> BTreeSet<String> {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/worksheet_cells.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let cells = json["cells"].as_array().expect("the cells' text");
    let mut names = BTreeSet::new();
    for cell in cells {
        for line in cell.as_str().unwrap().lines() {
            let line = line.trim_start();
            if let Some((lhs, _)) = line.split_once('=')
                && !line.starts_with('#')
                && !lhs.contains(['(', '[', '!', '<', '>'])
                && !lhs.trim().is_empty()
            {
                names.insert(lhs.trim().to_string());
            }
        }
    }
    names
}

/// What the worksheet computes, step by step, and the givens its formulas use.
const COMPUTED: [&str; 14] = [
    "vertexNormal",
    "vertexPos",
    "lightPos",
    "vlv",
    "vov",
    "Iamb",
    "cosTheta",
    "Idif",
    "H",
    "cosBeta",
    "Ispec",
    "d",
    "at",
    "I",
];
const GIVENS: [&str; 11] =
    ["Lamb", "Ldif", "Lspec", "matAmb", "matDif", "matSpec", "ns", "atC", "atLin", "atQuad", "mview"];
/// Steps the worksheet does not have (several lights, spotlights, OpenGL's clamping, Phong's R).
const PHONGLAB_ONLY: [&str; 8] = ["spot", "Ilight", "glColor", "Iscene", "Iemi", "Isec", "R", "cosAlpha"];

#[test]
fn the_worksheets_names_are_read_from_its_cells() {
    let names = worksheet_names();
    for n in COMPUTED.iter().chain(&GIVENS) {
        assert!(names.contains(*n), "the worksheet's cells assign {n}: {names:?}");
    }
}

#[test]
fn the_calculation_and_the_quiz_name_each_step_as_the_worksheet_does() {
    let names = worksheet_names();
    for k in 1..=5 {
        let scene = presets::worksheet(k);
        let lit = Engine::<f64>::light_scene_vertex(&scene).unwrap();
        let e = explain(&scene, &lit, Side::Front);
        let steps: Vec<&str> = e.steps.iter().map(|s| s.name.as_str()).collect();
        for n in COMPUTED {
            assert!(steps.contains(&n), "mview{k}: the step {n} in {steps:?}");
        }
        // No name of our own where the worksheet has one (hv, vertexEye, lightEye were).
        for s in &steps {
            assert!(names.contains(*s) || PHONGLAB_ONLY.contains(s), "mview{k}: {s} is not the worksheet's name");
        }
        // The formulas use the worksheet's givens, and OpenGL's names beside them.
        let formulas: String = e.steps.iter().map(|s| s.formula.as_str()).collect::<Vec<_>>().join("\n");
        for g in GIVENS {
            assert!(formulas.contains(g), "mview{k}: {g} in the formulas:\n{formulas}");
        }
        let idif = &e.steps.iter().find(|s| s.name == "Idif").unwrap().formula;
        assert_eq!(idif, "Idif = Ldif · matDif · max(cosTheta, 0)   (OpenGL: d_cl · d_cm · max(n · L, 0))");
        let h = &e.steps.iter().find(|s| s.name == "H").unwrap().formula;
        assert!(h.starts_with("H = normalize(vlv + vov)") && h.contains("OpenGL"), "{h}");
    }
}

#[test]
fn a_sheet_lists_the_givens_and_the_steps_under_the_worksheets_names() {
    use phonglab_core::exercise::{Level, Spec, generate, sheet_markdown};
    let ex = &generate(7, 1, &Spec::level(Level::from_number(2).unwrap(), phonglab_core::Rules::WORKSHEET)).unwrap()[0];
    let sheet = sheet_markdown(ex);
    for g in [
        "vertexPos",
        "vertexNormal",
        "lightPos",
        "Lamb",
        "Ldif",
        "Lspec",
        "atC",
        "atLin",
        "atQuad",
        "matAmb",
        "matDif",
        "matSpec",
        "ns",
    ] {
        assert!(sheet.contains(&format!("{g} = ")), "{g} in the sheet:\n{sheet}");
    }
    for n in ["vlv", "vov", "Iamb", "cosTheta", "Idif", "H", "cosBeta", "Ispec", "d", "at", "I"] {
        assert!(sheet.contains(&format!("`{n}` = ________")), "{n} asked in the sheet:\n{sheet}");
    }
}
