//! The exported notebooks, run: each notebook's code cells executed in order by Python
//! with NumPy (as Jupyter runs them, one namespace), and every value they print
//! (`name = value`, the worksheet's prints) checked against what `phonglab explain` gives
//! under that name, to 1e-7, on the shipped scenes and on 50 generated exercises
//! (levels 1 to 4, both rule sets). Skipped, saying so, where Python or NumPy is missing;
//! CI installs Debian's python3-numpy so that it runs there.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

use phonglab_core::Document;
use phonglab_core::exercise::{Level, Spec, generate};
use phonglab_core::explain::{Explanation, Side, explain};
use phonglab_core::export::notebook::notebook;
use phonglab_core::{Engine, Rules};

/// Runs each notebook's code cells and prints, per notebook, a JSON line of its output.
const RUNNER: &str = r#"
import io, json, sys, contextlib
import numpy as np
for path in sys.argv[1:]:
    nb = json.load(open(path, encoding="utf-8"))
    out = io.StringIO()
    ns = {}
    error = None
    with contextlib.redirect_stdout(out):
        # Full precision in what the cells print (the worksheet prints NumPy's 8 digits).
        np.set_printoptions(precision=17, floatmode="unique", linewidth=100000)
        try:
            for cell in nb["cells"]:
                if cell["cell_type"] == "code":
                    exec("".join(cell["source"]), ns)
        except Exception as e:
            error = f"{type(e).__name__}: {e}"
    print(json.dumps({"path": path, "stdout": out.getvalue(), "error": error}))
"#;

/// A Python with NumPy: the one on the PATH, or Debian's (a PATH may lead to another
/// Python first, such as pyenv's, without NumPy).
fn python_with_numpy() -> Option<&'static str> {
    ["python3", "/usr/bin/python3"]
        .into_iter()
        .find(|p| Command::new(p).args(["-c", "import numpy"]).output().is_ok_and(|o| o.status.success()))
}

/// The values a notebook printed: `name = [a b c d]` or `name = x`, by name.
fn printed_values(stdout: &str) -> BTreeMap<String, Vec<f64>> {
    let mut out = BTreeMap::new();
    for line in stdout.lines() {
        let Some((name, value)) = line.split_once(" = ") else { continue };
        let value = value.trim().trim_start_matches('[').trim_end_matches(']');
        let numbers: Option<Vec<f64>> =
            value.split_whitespace().map(|t| t.trim_end_matches('.').parse().ok()).collect();
        if let Some(v) = numbers.filter(|v| !v.is_empty()) {
            out.insert(name.trim().to_string(), v);
        }
    }
    out
}

/// Every printed value against explain's value of that name (the back side's names end
/// in `Back`). Returns the number of values compared.
fn check(what: &str, printed: &BTreeMap<String, Vec<f64>>, front: &Explanation, back: Option<&Explanation>) -> usize {
    let mut compared = 0;
    for (name, got) in printed {
        if name == "modelview" {
            continue;
        }
        let (ex, key) = match back {
            Some(b) if name.contains("Back") => (b, name.replacen("Back", "", 1)),
            _ => (front, name.clone()),
        };
        let Some(want) = ex.value(&key) else { continue };
        assert_eq!(got.len(), want.len(), "{what}: {name} printed {got:?}, explain has {want:?}");
        for (g, w) in got.iter().zip(want.iter()) {
            assert!(
                (g - w).abs() <= 1e-7 * w.abs().max(1e-3),
                "{what}: {name} = {got:?} in the notebook, {want:?} in explain"
            );
        }
        compared += 1;
    }
    compared
}

fn explanation(doc: &Document, side: Side) -> Explanation {
    let lit = Engine::<f64>::light_scene_vertex(&doc.scene).expect("the scene evaluates");
    explain(&doc.scene, &lit, side)
}

#[test]
fn the_exported_notebooks_print_what_explain_prints() {
    let Some(python) = python_with_numpy() else {
        eprintln!("SKIPPED: the exported notebooks are not run: no python3 with NumPy here (Debian: python3-numpy)");
        return;
    };
    // The shipped scenes and 50 exercises: 6 per level and rule set, 7 at level 4.
    let mut docs = shipped_scenes();
    docs.extend(normalised_scenes());
    docs.extend(exercises(100, |level| if level == 4 { 7 } else { 6 }));
    let exercises = docs.iter().filter(|(n, _)| n.starts_with("exercise")).count();
    assert!(exercises >= 50, "{exercises} exercises");

    let dir = std::env::temp_dir().join(format!("phonglab-notebooks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut paths = Vec::new();
    for (k, (_, doc)) in docs.iter().enumerate() {
        let p = dir.join(format!("{k}.ipynb"));
        std::fs::write(&p, notebook(doc, &phonglab_core::export::key(doc))).unwrap();
        paths.push(p.display().to_string());
    }
    let out = Command::new(python).arg("-c").arg(RUNNER).args(&paths).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let lines: Vec<serde_json::Value> =
        String::from_utf8(out.stdout).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), docs.len());
    let mut total = 0;
    for ((what, doc), run) in docs.iter().zip(&lines) {
        assert!(run["error"].is_null(), "{what}: the notebook failed: {}", run["error"]);
        let printed = printed_values(run["stdout"].as_str().unwrap());
        let front = explanation(doc, Side::Front);
        let back = doc.scene.light_model.two_sided.then(|| explanation(doc, Side::Back));
        let compared = check(what, &printed, &front, back.as_ref());
        // Every step explain prints with a value is printed by the notebook; but where the
        // worksheet's own form computes I of its one light directly (`(Iamb + Idif +
        // Ispec)/at`), explain's spot (1: not a spotlight) and its light's share (which is
        // I) have no cell of their own.
        let worksheet_form = !printed.contains_key("Ilight");
        for step in front.steps.iter().filter(|s| s.value.is_some()) {
            if worksheet_form && (step.name == "spot" || step.name == "Ilight") {
                assert!(doc.scene.lights.len() == 1 && !doc.scene.lights[0].is_spot(), "{what}: no Ilight printed");
                if step.name == "Ilight" {
                    assert_eq!(step.value.as_deref(), front.value("I"), "{what}: I is not the one light's share");
                }
                continue;
            }
            assert!(printed.contains_key(&step.name), "{what}: the notebook does not print {}", step.name);
        }
        if let Some(b) = &back {
            assert!(printed.contains_key("IBack") && b.value("I").is_some(), "{what}: no back side");
        }
        total += compared;
    }
    std::fs::remove_dir_all(&dir).ok();
    eprintln!("{} notebooks run ({exercises} exercises), {total} printed values checked against explain", docs.len());
}

/// Every scene file under assets/scenes/, with its path.
fn shipped_scenes() -> Vec<(String, Document)> {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut files: Vec<_> = std::fs::read_dir(&scenes).unwrap().map(|e| e.unwrap().path()).collect();
    files.extend(std::fs::read_dir(scenes.join("redbook-teapots")).unwrap().map(|e| e.unwrap().path()));
    files.sort();
    files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "toml"))
        .map(|f| {
            (f.display().to_string(), Document::from_toml_in(&std::fs::read_to_string(f).unwrap(), f.parent()).unwrap())
        })
        .collect()
}

/// Generated exercises of every level under both rule sets (seed `seed + level`), `count`
/// of them per level and rule set.
fn exercises(seed: u64, count: impl Fn(u8) -> usize) -> Vec<(String, Document)> {
    let mut docs = Vec::new();
    for level in 1..=4u8 {
        for rules in [Rules::WORKSHEET, Rules::OPENGL] {
            let spec = Spec::level(Level::from_number(level).unwrap(), rules);
            for (k, ex) in generate(seed + level as u64, count(level), &spec).unwrap().into_iter().enumerate() {
                docs.push((format!("exercise level {level} {rules:?} #{k}"), ex.doc));
            }
        }
    }
    docs
}

/// Shipped scenes under energy-conserving Blinn-Phong (`specular = "blinn-phong-normalised"`):
/// the worksheet's (its own rules), the spotlight and the three lights (OpenGL's, two-sided).
fn normalised_scenes() -> Vec<(String, Document)> {
    shipped_scenes()
        .into_iter()
        .filter(|(name, _)| ["worksheet-mview5", "spotlight", "three-lights"].iter().any(|s| name.contains(s)))
        .map(|(name, mut doc)| {
            doc.scene.rules.specular = phonglab_core::SpecularModel::BlinnPhongNormalised;
            doc.scene.light_model.two_sided = !name.contains("worksheet");
            (format!("{name}, normalised Blinn-Phong"), doc)
        })
        .collect()
}

/// The scenes the round trips are tried on: the shipped ones (and some under normalised
/// Blinn-Phong) and 32 generated exercises.
fn scenes_and_exercises() -> Vec<(String, Document)> {
    let mut docs = shipped_scenes();
    docs.extend(normalised_scenes());
    docs.extend(exercises(200, |_| 4));
    docs
}

/// Every step's value of two explanations, equal to 1e-12.
fn same_explanation(what: &str, a: &Explanation, b: &Explanation) {
    assert_eq!(a.steps.len(), b.steps.len(), "{what}: {} steps, then {}", a.steps.len(), b.steps.len());
    for (x, y) in a.steps.iter().zip(&b.steps) {
        assert_eq!(x.name, y.name, "{what}");
        match (&x.value, &y.value) {
            (Some(u), Some(v)) => {
                for (p, q) in u.iter().zip(v) {
                    assert!((p - q).abs() <= 1e-12 * p.abs().max(1.0), "{what}: {} = {u:?}, then {v:?}", x.name);
                }
            }
            (u, v) => assert_eq!(u, v, "{what}: {}", x.name),
        }
    }
}

#[test]
fn export_then_import_gives_back_the_same_scene() {
    use phonglab_core::export::read_python::read;
    for (what, doc) in scenes_and_exercises() {
        let imported = read(&notebook(&doc, &phonglab_core::export::key(&doc)), true, "back")
            .unwrap_or_else(|e| panic!("{what}: {e}"));
        assert!(imported.notices.is_empty(), "{what}: {:?}", imported.notices);
        let s = &imported.doc.scene;
        assert_eq!(s.lights.len(), doc.scene.lights.len(), "{what}");
        assert_eq!((s.rules, s.normal_mode), (doc.scene.rules, doc.scene.normal_mode), "{what}");
        assert_eq!(s.light_model.local_viewer, doc.scene.light_model.local_viewer, "{what}");
        assert_eq!(s.light_model.two_sided, doc.scene.light_model.two_sided, "{what}");
        assert_eq!(s.light_model.separate_specular, doc.scene.light_model.separate_specular, "{what}");
        for (l, m) in s.lights.iter().zip(&doc.scene.lights) {
            assert_eq!(
                (l.position, l.attenuation, l.spot_cutoff),
                (m.position, m.attenuation, m.spot_cutoff),
                "{what}"
            );
            assert_eq!(
                (l.ambient.truncate(), l.diffuse.truncate(), l.specular.truncate()),
                (m.ambient.truncate(), m.diffuse.truncate(), m.specular.truncate()),
                "{what}"
            );
        }
        assert_eq!(s.material.shininess, doc.scene.material.shininess, "{what}");
        for side in [Side::Front, Side::Back] {
            same_explanation(&what, &explanation(&doc, side), &explanation(&imported.doc, side));
        }
    }
}

/// The worksheet's own cells (tests/data/worksheet_cells.json, as printed in it).
fn worksheet_cells() -> Vec<String> {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/worksheet_cells.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    json["cells"].as_array().unwrap().iter().map(|c| c.as_str().unwrap().to_string()).collect()
}

#[test]
fn the_worksheets_own_notebook_and_a_students_edit_of_it_open_as_scenes() {
    use phonglab_core::export::notebook::{Cell, ipynb};
    use phonglab_core::export::read_python::read;
    let cells = worksheet_cells();
    let original = ipynb(&cells.iter().map(|c| Cell::Code(c.clone())).collect::<Vec<_>>());
    let imported = read(&original, true, "vertex_color_calculator").unwrap();
    assert!(imported.notices.is_empty(), "{:?}", imported.notices);
    assert_eq!(imported.doc.camera, phonglab_core::CameraSpec::Worksheet(5));
    let worksheet = Document::default();
    same_explanation("the worksheet", &explanation(&worksheet, Side::Front), &explanation(&imported.doc, Side::Front));
    assert_eq!(imported.doc.scene.material, worksheet.scene.material);
    assert!(!imported.doc.scene.light_model.local_viewer);

    // A student's edits, as a script (the cells one after the other): another modelview,
    // the custom material, the local viewer switched on, and a typing slip on one line.
    let script = cells
        .join("\n")
        .replace("mview = mview5", "mview = mview3")
        .replace("#custom\n#matAmb = np.array([0, 0, 0, 0]);", "#custom\nmatAmb = np.array([0, 0, 0, 0]);")
        .replace("#obs = np.array([0, 0, 0, 1])", "obs = np.array([0, 0, 0, 1])")
        .replace("obs = vertexPos*np.array([1, 1, 0, 1])", "#obs = vertexPos*np.array([1, 1, 0, 1])")
        .replace("atQuad = 0.00001;", "atQuad = 0.00001x;");
    let slip_line = script.lines().position(|l| l.starts_with("atQuad")).unwrap() + 1;
    let edited = read(&script, false, "edited").unwrap();
    assert_eq!(edited.doc.camera, phonglab_core::CameraSpec::Worksheet(3));
    assert_eq!(edited.doc.scene.material.ambient.truncate(), glam::DVec3::ZERO);
    assert_eq!(edited.doc.scene.material.shininess, 0.2 * 128.0);
    assert!(edited.doc.scene.light_model.local_viewer);
    // The slip is reported on its line, and the worksheet's value is kept; nothing else is lost.
    assert_eq!(edited.notices.len(), 1, "{:?}", edited.notices);
    assert!(
        edited.notices[0].contains(&format!("line {slip_line}")) && edited.notices[0].contains("atQuad"),
        "{:?}",
        edited.notices
    );
    assert_eq!(edited.doc.scene.lights[0].attenuation, [1.0, 0.0001, 0.00001]);
}

#[test]
fn what_is_not_a_worksheet_is_refused_with_a_reason() {
    use phonglab_core::export::read_python::read;
    assert!(read("{\"not\": 1}", true, "x").unwrap_err().to_string().contains("no cells"));
    assert!(read("not json", true, "x").unwrap_err().to_string().contains("not a Jupyter notebook"));
    assert!(read("print('hello')\nx = 3\n", false, "x").unwrap_err().to_string().contains("vertexPos"));
}

/// nbformat 4.5 (what the file declares) gives every cell an `id` of 1 to 64 characters
/// from `[A-Za-z0-9_-]`, unique in the notebook: without one Jupyter warns
/// (`MissingIDFieldWarning`), and nbformat's validator will refuse it.
#[test]
fn every_cell_has_the_unique_id_nbformat_4_5_asks_for() {
    let (_, doc) = shipped_scenes().into_iter().next().unwrap();
    let json: serde_json::Value = serde_json::from_str(&notebook(&doc, &phonglab_core::export::key(&doc))).unwrap();
    assert_eq!((json["nbformat"].as_u64(), json["nbformat_minor"].as_u64()), (Some(4), Some(5)));
    let cells = json["cells"].as_array().unwrap();
    assert!(cells.len() > 5);
    let mut seen = std::collections::BTreeSet::new();
    for cell in cells {
        let id = cell["id"].as_str().unwrap_or_else(|| panic!("a cell without an id: {cell}"));
        assert!((1..=64).contains(&id.len()), "{id}");
        assert!(id.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_'), "{id}");
        assert!(seen.insert(id.to_string()), "{id} twice");
    }
}

/// The notebook's words are true: the worksheet's "vov always comes out as [0 0 1 0]" is
/// kept only as its quote, with when it fails beside it, in every language; and the
/// comment above `glColor` says where its alpha comes from, which the code does (the
/// diffuse colour's as lit: the current colour's where GL_COLOR_MATERIAL tracks it).
#[test]
fn the_notebooks_words_are_true_of_its_code() {
    let scene = |name: &str| {
        let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes").join(name);
        Document::from_toml_in(&std::fs::read_to_string(&p).unwrap(), p.parent()).unwrap()
    };
    let markdown = |doc: &Document| -> String {
        let nb: serde_json::Value =
            serde_json::from_str(&notebook(doc, &phonglab_core::export::key(doc))).expect("the notebook is JSON");
        let cells = nb["cells"].as_array().unwrap().iter().filter(|c| c["cell_type"] == "markdown");
        cells.map(|c| c["source"].as_array().unwrap().iter().map(|l| l.as_str().unwrap()).collect::<String>()).collect()
    };
    let ws = scene("worksheet-mview5.toml");
    use phonglab_core::locale::{Lang, Locale, set_thread};
    for (lang, quote, behind) in [
        (
            Lang::En,
            "\"vov vai sempre resultar em [0 0 1 0]\" (vov always comes out as [0 0 1 0])",
            "(z > 0) this formula gives [0 0 -1 0]",
        ),
        (Lang::PtPt, "«vov vai sempre resultar em [0 0 1 0]»", "(z > 0) esta fórmula dá [0 0 -1 0]"),
        (Lang::PtBr, "\"vov vai sempre resultar em [0 0 1 0]\"", "(z > 0) essa fórmula dá [0 0 -1 0]"),
    ] {
        set_thread(Some(Locale::of(lang)));
        let text = markdown(&ws);
        set_thread(None);
        assert!(text.contains(quote) && text.contains(behind), "{lang:?}: {text}");
        // The claim is made only inside the quote.
        let claim = if lang == Lang::En { "always comes out as [0 0 1 0]" } else { "sempre resultar em [0 0 1 0]" };
        assert_eq!(text.matches(claim).count(), 1, "{lang:?}: {text}");
    }
    let Some(python) = python_with_numpy() else {
        eprintln!("SKIPPED: the notebooks are not run: no python3 with NumPy here (Debian: python3-numpy)");
        return;
    };
    // GL_COLOR_MATERIAL tracks the diffuse: the alpha is the current colour's, whichever
    // of the two is not 1 (the material's diffuse alone made the notebook fail on matAlpha).
    let mut colour_half = scene("of-set-color.toml");
    colour_half.scene.color_material.as_mut().unwrap().color.w = 0.5;
    let mut material_half = scene("of-set-color.toml");
    material_half.scene.material.diffuse.w = 0.5;
    let dir = std::env::temp_dir().join(format!("phonglab-notebook-alpha-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (what, doc, alpha) in [("colour alpha 0.5", &colour_half, 0.5), ("material alpha 0.5", &material_half, 1.0)] {
        let text = notebook(doc, &phonglab_core::export::key(doc));
        // The comment names the alpha the code writes, and says matDif[3] is not it (the
        // cells write colours [r g b 0]: a teacher's student took matDif[3] from it).
        assert!(text.contains("its alpha is the diffuse colour's as OpenGL lights it (1, or matAlpha;"));
        assert!(text.contains("not matDif[3]: the colours above are written [r g b 0]"));
        let p = dir.join("alpha.ipynb");
        std::fs::write(&p, text).unwrap();
        let out = Command::new(python).arg("-c").arg(RUNNER).arg(&p).output().unwrap();
        let run: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert!(run["error"].is_null(), "{what}: the notebook failed: {}", run["error"]);
        let printed = printed_values(run["stdout"].as_str().unwrap());
        assert_eq!(printed["glColor"][3], alpha, "{what}: {printed:?}");
        assert!(check(what, &printed, &explanation(doc, Side::Front), None) > 10, "{what}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
