//! The command line, run as a real process: `eval` and `explain`.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output};

use crate::common;
use common::{phonglab, phonglab_in};

#[test]
fn explain_speaks_the_systems_language_or_the_one_asked_for() {
    let run = |lang: &str, args: &[&str]| stdout(&phonglab_in(lang, args));
    let pt = run("pt_PT.UTF-8", &["explain", "--worksheet", "5"]);
    assert!(pt.starts_with("Cálculo passo a passo: a ficha, mview5\nface da frente, 1 luz, f64"), "{pt}");
    assert!(
        pt.contains(" 9. Componente difusa") && pt.contains("Idif = [0,09942795 0,05965677 0,025266397 0]"),
        "{pt}"
    );
    let br = run("pt_BR.UTF-8", &["explain", "--worksheet", "5"]);
    assert!(br.contains("Lista de exercícios") && br.contains("I = [0,059587089"), "{br}");
    // --lang and --decimal win over the system's.
    let en = run("pt_PT.UTF-8", &["--lang", "en", "explain", "--worksheet", "5"]);
    assert!(en.contains("Diffuse term") && en.contains("I = [0.059587089"), "{en}");
    let point = run("pt_PT.UTF-8", &["explain", "--worksheet", "5", "--decimal", "point"]);
    assert!(point.contains("Componente difusa") && point.contains("I = [0.059587089"), "{point}");
    // The help, where clap allows.
    let help = run("pt_PT.UTF-8", &["--help"]);
    assert!(help.contains("Imprimir o cálculo da cor de um vértice"), "{help}");
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("phonglab-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::File::create(&p).unwrap().write_all(text.as_bytes()).unwrap();
    p
}

fn result<'a>(out: &'a serde_json::Value, id: &str) -> &'a serde_json::Value {
    out["results"].as_array().unwrap().iter().find(|r| r["id"] == id).unwrap_or_else(|| panic!("no result {id}"))
}

fn num(v: &serde_json::Value) -> f64 {
    match v {
        serde_json::Value::String(s) if s == "Infinity" => f64::INFINITY,
        serde_json::Value::String(s) if s == "-Infinity" => f64::NEG_INFINITY,
        serde_json::Value::String(s) if s == "NaN" => f64::NAN,
        other => other.as_f64().unwrap(),
    }
}

#[test]
fn eval_prints_every_public_case_with_errors_in_place() {
    let o = phonglab(&["eval", "tests/data/cases_public.json"]);
    // Four public cases set parameters OpenGL refuses: printed, counted, and exit 1.
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("4 of 346 cases failed"), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(out["results"].as_array().unwrap().len(), 346);
    // The worksheet's known value (Mesa's, with the light-model ambient 0).
    let k = result(&out, "hard_known_bronze_lma0");
    assert!(k["error"].is_null());
    let front: Vec<f64> = k["front"].as_array().unwrap().iter().map(num).collect();
    for (got, want) in front.iter().zip([0.05958709, 0.03575929, 0.01515525, 1.0]) {
        assert!((got - want).abs() < 1e-7, "{front:?}");
    }
    // Refused parameters become an error of that case only.
    let bad = result(&out, "hard_shin200_invalid");
    assert!(bad["front"].is_null());
    assert!(bad["error"].as_str().unwrap().contains("material.shininess"), "{bad}");
    // Non-finite values are written as strings.
    assert_eq!(result(&out, "hard_att_all_zero")["front"][0], "Infinity");
    // No other case has an error or a NaN.
    for r in out["results"].as_array().unwrap() {
        let id = r["id"].as_str().unwrap();
        if !id.contains("invalid") {
            assert!(r["error"].is_null(), "{r}");
            for k in ["front", "front_secondary", "back", "back_secondary"] {
                assert!(r[k].as_array().unwrap().iter().all(|x| !num(x).is_nan()), "{id} {k}: {r}");
            }
        }
    }
}

#[test]
fn eval_clamps_on_request_and_takes_f64() {
    let f = temp_file(
        "bright.json",
        r#"{"cases": [{"id": "b", "lights": [{}], "material": {"emission": [2, -1, 0.5]}, "normal": [0, 0, 1]}]}"#,
    );
    let o = phonglab(&["eval", f.to_str().unwrap(), "--clamp", "--precision", "f64"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let front: Vec<f64> = result(&out, "b")["front"].as_array().unwrap().iter().map(num).collect();
    assert_eq!(front[0], 1.0);
    assert_eq!(front[1], 0.0);
    let o = phonglab(&["eval", f.to_str().unwrap()]);
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(num(&result(&out, "b")["front"][0]) > 2.0, "unclamped by default");
}

#[test]
fn eval_reports_schema_errors_per_case() {
    let f = temp_file(
        "mixed.json",
        r#"[{"id": "ok"}, {"id": "broken", "normal": [0, 1]}, {"id": "cut", "lights": [{"spot_cutoff": 91}]}]"#,
    );
    let o = phonglab(&["eval", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("2 of 3 cases failed"), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(result(&out, "ok")["error"].is_null());
    assert!(result(&out, "broken")["error"].as_str().unwrap().contains("normal"));
    assert!(result(&out, "cut")["error"].as_str().unwrap().contains("[0, 90], or 180"));
}

#[test]
fn eval_refuses_misspelt_keys_odd_ids_and_empty_cases() {
    let f = temp_file(
        "strict.json",
        r#"[{"id": "typo", "lights": [{"constant_atenuation": 2}]}, {}, {"id": 123, "vertex": [0,0,0]},
            {"id": "twice", "vertex": [0,0,0]}, {"id": "twice", "vertex": [1,0,0]}, {"id": "fine", "vertex": [0,0,0]}]"#,
    );
    let o = phonglab(&["eval", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("4 of 6 cases failed"), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let r = out["results"].as_array().unwrap();
    let ids: Vec<&str> = r.iter().map(|x| x["id"].as_str().unwrap()).collect();
    assert_eq!(ids, ["typo", "case1", "123", "twice", "twice", "fine"], "ids as given");
    let err = |i: usize| r[i]["error"].as_str().unwrap_or("").to_string();
    assert!(err(0).contains("did you mean \"constant_attenuation\""), "{}", err(0));
    assert!(err(1).contains("empty case"), "{}", err(1));
    assert!(err(2).contains("non-empty string"), "{}", err(2));
    assert!(r[3]["error"].is_null() && err(4).contains("earlier case"), "{}", err(4));
    assert!(r[5]["error"].is_null());
    let ok = temp_file("all-good.json", r#"[{"id": "a", "vertex": [0, 0, 0]}]"#);
    assert!(phonglab(&["eval", ok.to_str().unwrap()]).status.success(), "no failure, exit 0");
}

#[test]
fn scene_files_are_strict_and_their_errors_short() {
    for (text, want) in [
        ("[[lights]]\nattenuation = [1, 0.05, 0.01, nan]\n", "line 2, column 15: expected 3 numbers, found 4"),
        ("[[lights]]\nspot_direction = [0, -2.5, -1.5, 99]\n", "line 2, column 18: expected 3 numbers, found 4"),
        (
            "[vertex]\nposition = [0, 1, 0]\nnormal = [0, 1, 0, 5, 6]\n",
            "line 3, column 10: expected 3 numbers, found 5",
        ),
        (
            "[camera]\nkind = \"look-at\"\neye = [0, 1.2, 3, 4]\ncentre = [0, 0, 0]\nup = [0, 1, 0]\n",
            "line 3, column 7: expected 3 numbers, found 4",
        ),
        ("[material]\nshinyness = 3\n", "did you mean `shininess`?"),
        ("[view]\nbackground = [0, 0, 0, 1]\n", "expected 3 numbers, found 4"),
        ("", "the scene file is empty"),
        ("# only a comment\n", "the scene file is empty"),
    ] {
        let f = temp_file("strict.toml", text);
        let o = phonglab(&["explain", f.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{text}");
        assert!(stderr(&o).contains(want), "{text}: {}", stderr(&o));
    }
    // A line of 300 000 numbers (900 kB) gives a message of a few hundred characters, not megabytes.
    let huge = format!("[vertex]\nnormal = [0, 0, 1]\nposition = [{}]\n", vec!["1"; 300_000].join(", "));
    let f = temp_file("huge.toml", &huge);
    let o = phonglab(&["explain", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).len() < 600, "{} bytes: {}", stderr(&o).len(), stderr(&o));
    assert!(stderr(&o).contains("line 3"), "{}", stderr(&o));
    // Not a regular file: refused at once rather than read until the memory runs out.
    // (Windows: the device's name is refused before it is opened, issue 59 finding 7.)
    let o = phonglab(&["explain", ENDLESS_DEVICE]);
    assert_eq!(o.status.code(), Some(2));
    let said = if cfg!(windows) { "is a name Windows keeps for a device" } else { "not a regular file" };
    assert!(stderr(&o).contains(said), "{}", stderr(&o));
    // A name alone is a scene with OpenGL's defaults.
    let f = temp_file("named.toml", "name = \"defaults\"\n");
    assert!(phonglab(&["explain", f.to_str().unwrap()]).status.success());
}

#[test]
fn eval_refuses_a_file_that_is_not_cases_with_exit_code_2() {
    let f = temp_file("bad.json", "{\"cases\": [ {\"id\": 1,, } ]");
    let o = phonglab(&["eval", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("not valid JSON") && stderr(&o).contains("line 1"), "{}", stderr(&o));
    let o = phonglab(&["eval", "no/such/file.json"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot read no/such/file.json"), "{}", stderr(&o));
    let f = temp_file("shape.json", "{\"meta\": {}}");
    let o = phonglab(&["eval", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("expected a list of cases"), "{}", stderr(&o));
}

/// `name = [a b c d]` lines of the explain output.
fn explained(text: &str, name: &str) -> Vec<f64> {
    let prefix = format!("{name} = ");
    let line =
        text.lines().map(str::trim).find(|l| l.starts_with(&prefix)).unwrap_or_else(|| panic!("no {name} in\n{text}"));
    line[prefix.len()..].trim_matches(['[', ']']).split(' ').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn explain_worksheet_5_prints_the_worksheets_values() {
    let o = phonglab(&["explain", "--worksheet", "5"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for (name, want) in [
        ("vertexNormal", [0.0, 0.6, 0.8, 0.0]),
        ("vlv", [0.79220526, 0.55887606, -0.2450885, 0.0]),
        ("vov", [0.0, 0.0, 1.0, 0.0]),
        ("Iamb", [0.2125, 0.1275, 0.054, 0.0]),
        ("Idif", [0.09942795, 0.05965677, 0.0252664, 0.0]),
        ("Ispec", [0.00040551, 0.00028017, 0.00017179, 0.0]),
        ("I", [0.05958709, 0.03575929, 0.01515525, 0.0]),
    ] {
        let got = explained(&text, name);
        assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1e-7), "{name}: {got:?} vs {want:?}");
    }
    // In the worksheet's order.
    let order: Vec<usize> = ["vertexNormal =", "vlv =", "vov =", "Iamb =", "Idif =", "H =", "Ispec =", "at =", "I ="]
        .iter()
        .map(|k| text.find(&format!("    {k}")).unwrap_or_else(|| panic!("{k}")))
        .collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{order:?}");
}

#[test]
fn explain_other_modelviews_markdown_and_bad_arguments() {
    let one = stdout(&phonglab(&["explain", "--worksheet", "1"]));
    let five = stdout(&phonglab(&["explain"]));
    assert_ne!(explained(&one, "vlv"), explained(&five, "vlv"));
    assert!(five.contains("mview5"), "the default is the worksheet with mview5");
    let md = stdout(&phonglab(&["explain", "--markdown"]));
    assert!(md.contains("| # | step | formula | value | notes |"), "{md}");
    let demo = stdout(&phonglab(&["explain", "--preset", "phong-demo"]));
    assert!(demo.contains("R = 2 max(vertexNormal · vlv, 0) vertexNormal − vlv"), "{demo}");
    let o = phonglab(&["explain", "--worksheet", "9"]);
    assert_eq!(o.status.code(), Some(2));
    let o = phonglab(&["explain", "--preset", "nope"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("unknown preset"), "{}", stderr(&o));
}

#[test]
fn case_writes_a_scene_file_that_eval_lights_as_opengl() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes/worksheet-mview5.toml");
    let o = phonglab(&["case", scene]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("Worksheet rules"), "says a case means OpenGL's rules: {}", stderr(&o));
    let cases = temp_file("mview5-case.json", &stdout(&o));
    let o = phonglab(&["eval", cases.to_str().unwrap(), "--precision", "f32"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let front = &result(&out, "worksheet-mview5")["front"];
    // What Mesa prints for the worksheet with OpenGL's default scene ambient (docs/lighting.md).
    for (k, want) in [0.102087, 0.061259, 0.025955].into_iter().enumerate() {
        assert!((num(&front[k]) - want).abs() < 1e-6, "{front}");
    }
    let o = phonglab(&["case", "/no/such/scene.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("/no/such/scene.toml"), "{}", stderr(&o));
}

#[test]
fn cost_prints_a_table_and_writes_the_csv_the_chart_and_heat_maps() {
    let dir = std::env::temp_dir().join(format!("phonglab-cost-{}", std::process::id()));
    let o = phonglab(&["cost", "--object", "sphere", "--size", "48", "--quick", "--out", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("# Sphere: 48x48 px") && out.contains("Gouraud 32") && out.contains("Phong 32, fast rsqrt"),
        "{out}"
    );
    let csv = std::fs::read_to_string(dir.join("cost.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows.len(), 1 + phonglab_core::cost::variants(phonglab_core::ObjectKind::Sphere).len());
    assert!(rows[0].starts_with("object,variant,question"));
    assert!(rows[1].starts_with("sphere,Flat 8,Shading,Flat,8,112,"), "{}", rows[1]);
    // Every error figure parses and is non-negative; the f32 Phong on the reference mesh
    // is within 8-bit rounding.
    for r in &rows[1..] {
        let f: Vec<f64> = r.rsplit(',').take(3).map(|x| x.parse().unwrap()).collect();
        assert!(f.iter().all(|x| *x >= 0.0), "{r}");
    }
    let f32_row = rows.iter().find(|r| r.contains("(f32)")).unwrap();
    let max: f64 = f32_row.split(',').nth(8).unwrap().parse().unwrap();
    assert!(max <= 0.5 + 1e-3, "{f32_row}");
    let (w, h, _) = phonglab::io::image::read_png(&dir.join("cost.png")).unwrap();
    assert!(w >= 960 && h >= 400, "{w}x{h}");
    let (w, h, _) = phonglab::io::image::read_png(&dir.join("heat-sphere-phong-32.png")).unwrap();
    assert_eq!((w, h), (48, 48));
    let _ = std::fs::remove_dir_all(&dir);
    // Bad arguments are refused with a message.
    let o = phonglab(&["cost", "--size", "4"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn bench_ui_times_every_case_with_every_panel_open() {
    let o = phonglab(&["bench", "ui", "--frames", "3", "--width", "1200", "--height", "800"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let rows: Vec<Vec<&str>> = out.lines().filter(|l| !l.starts_with('#')).map(|l| l.split(' ').collect()).collect();
    assert_eq!(rows[0], ["case", "ui_median", "ui_p95", "tessellate_median", "tessellate_p95", "total_median"]);
    let cases: Vec<&str> = rows[1..].iter().map(|r| r[0]).collect();
    assert_eq!(cases, ["idle", "slider_move", "auto_rotate"]);
    for r in &rows[1..] {
        assert!(r[1..].iter().all(|x| x.parse::<f64>().is_ok_and(|v| v > 0.0)), "{r:?}");
    }
}

#[test]
fn the_performance_records_cost_tables_are_the_committed_csv() {
    let root = env!("CARGO_MANIFEST_DIR");
    let csv = std::fs::read_to_string(format!("{root}/docs/cost.csv")).unwrap();
    let tables = phonglab::cli::cost::markdown_tables(&csv).unwrap();
    let readme = std::fs::read_to_string(format!("{root}/docs/performance.md")).unwrap();
    let begin = readme.find("<!-- cost-tables:begin").expect("docs/performance.md marks its cost tables");
    let begin = begin + readme[begin..].find("-->\n").unwrap() + 4;
    let end = readme.find("<!-- cost-tables:end -->").unwrap();
    assert_eq!(readme[begin..end].trim(), tables.trim(), "regenerate docs/performance.md's tables from docs/cost.csv");
    // Every row has its columns in place: a triangle count, then the figures.
    for row in tables.lines().filter(|l| l.starts_with("| ") && !l.starts_with("| variant")) {
        let cells: Vec<&str> = row.trim_matches('|').split(" | ").map(str::trim).collect();
        assert_eq!(cells.len(), 6, "{row}");
        assert!(cells[1].parse::<u64>().is_ok(), "{row}");
        let share: f64 = cells[5].trim_end_matches(" %").parse().unwrap();
        assert!((0.0..=100.0).contains(&share), "{row}");
    }
}

#[test]
fn a_quoted_label_keeps_its_columns() {
    let csv = "object,variant,question,shading,level,triangles,ms_per_frame,mean_error_255,max_error_255,share_over_1_255\n\
               sphere,\"Phong 32, llvmpipe pow\",Approximation,Phong,32,1984,6.5,0.70,111.9,0.171\n";
    let t = phonglab::cli::cost::markdown_tables(csv).unwrap();
    assert!(t.contains("| Phong 32, llvmpipe pow | 1984 | 6.50 | 0.70 | 111.9 | 17.1 % |"), "{t}");
}

const PYRAMID: &str =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 1 2 3 4\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

#[test]
fn render_obj_shades_a_users_mesh_and_refuses_a_bad_one_with_its_line() {
    let obj = temp_file("pyramid.obj", PYRAMID);
    let png = obj.with_file_name("pyramid.png");
    let o = phonglab(&["render", "--obj", obj.to_str().unwrap(), "--output", png.to_str().unwrap(), "--size", "128"]);
    assert!(o.status.success(), "{}", stderr(&o));
    // The square base fans into 2 triangles: 6 in all; the notes say what was done.
    assert!(stderr(&o).contains("6 triangles"), "{}", stderr(&o));
    assert!(stderr(&o).contains("note: faces of more than 3 corners"), "{}", stderr(&o));
    assert!(stderr(&o).contains("note: centred and scaled"), "{}", stderr(&o));
    assert!(std::fs::metadata(&png).unwrap().len() > 100);

    // A scene file naming the mesh relative to itself.
    let scene = temp_file("mesh-scene.toml", "[view]\nobject = \"obj\"\nobj = \"pyramid.obj\"\nshading = \"phong\"\n");
    let o =
        phonglab(&["render", "--scene", scene.to_str().unwrap(), "--output", png.to_str().unwrap(), "--size", "64"]);
    assert!(o.status.success(), "{}", stderr(&o));

    for (name, text, want) in [
        ("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", "line 3: a vertex needs 3 finite numbers"),
        ("range.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n", "line 4: vertex index 9 is out of range"),
        ("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3: a face needs at least 3 corners"),
        ("vt.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/99 2/1 3/1\n", "line 5: texture index 99 is out of range"),
    ] {
        let bad = temp_file(name, text);
        let o = phonglab(&["render", "--obj", bad.to_str().unwrap(), "--output", png.to_str().unwrap()]);
        assert!(!o.status.success());
        assert!(stderr(&o).contains(want), "{name}: {}", stderr(&o));
    }

    // Far from the origin or tiny, a mesh is fitted in f64 and drawn.
    for (name, scale) in [("far.obj", "e20"), ("tiny.obj", "e-25")] {
        let text = PYRAMID
            .lines()
            .map(|l| match l.strip_prefix("v ") {
                Some(v) => {
                    format!("v {}", v.split_whitespace().map(|x| format!("{x}{scale}")).collect::<Vec<_>>().join(" "))
                }
                None => l.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n");
        let f = temp_file(name, &text);
        let o = phonglab(&["render", "--obj", f.to_str().unwrap(), "--output", png.to_str().unwrap(), "--size", "64"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let covered: f64 =
            stderr(&o).split("\u{a0}% covered").next().and_then(|s| s.rsplit(", ").next()).unwrap().parse().unwrap();
        assert!(covered > 5.0, "{name}: {}", stderr(&o));
    }
}

fn read_dir_sorted(dir: &std::path::Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read(&p).unwrap()))
        // phonglab's list of what the set wrote names identities: not the set's own bytes.
        .filter(|(n, _)| !n.starts_with(".phonglab-set"))
        .collect();
    v.sort();
    v
}

#[test]
fn exercise_sheets_are_reproducible_and_their_keys_are_what_explain_prints() {
    let base = std::env::temp_dir().join(format!("phonglab-ex-{}", std::process::id()));
    let (a, b) = (base.join("a"), base.join("b"));
    for out in [&a, &b] {
        let o = phonglab(&[
            "exercise",
            "--seed",
            "7",
            "--count",
            "4",
            "--effects",
            "attenuation,spot",
            "--rules",
            "worksheet",
            "--worksheet",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let (fa, fb) = (read_dir_sorted(&a), read_dir_sorted(&b));
    // Sheets, keys and scenes; exercise 0's sheet, key and five scenes; the index; the two PDFs.
    assert_eq!(fa.len(), 4 * 3 + 2 + 5 + 1 + 2, "{:?}", fa.iter().map(|f| &f.0).collect::<Vec<_>>());
    assert_eq!(fa, fb, "the same seed gives the same files, byte for byte");

    // Each key is explain's output on the exercise's own scene file.
    for k in 1..=4 {
        let toml = a.join(format!("exercise-{k:02}.toml"));
        let explained = stdout(&phonglab(&["explain", toml.to_str().unwrap()]));
        let key = std::fs::read_to_string(a.join(format!("exercise-{k:02}-key.md"))).unwrap();
        let block = key.split("```\n").nth(1).unwrap();
        assert_eq!(block, explained, "exercise {k}");
        let sheet = std::fs::read_to_string(a.join(format!("exercise-{k:02}.md"))).unwrap();
        assert!(sheet.contains("lightSpotDir") && sheet.contains("atQuad"), "the effects asked for: {sheet}");
    }
    // Exercise 0 is the worksheet, with the values it prints (mview5: I = [0.05958709 ...]).
    let key0 = std::fs::read_to_string(a.join("exercise-00-key.md")).unwrap();
    assert!(key0.contains("I = [0.059587089 0.035759287 0.015155245 0]"), "{key0}");
    assert_eq!(key0.matches("Worked calculation:").count(), 5);

    let o = phonglab(&["exercise", "--effects", "sparkles", "--out", base.join("c").to_str().unwrap()]);
    assert!(!o.status.success() && stderr(&o).contains("sparkles"), "{}", stderr(&o));
}

/// A device that reads without end (Unix's /dev/zero; Windows' NUL reads as empty, but is
/// a device all the same), which every reader refuses as not a regular file (Windows: by
/// its name, before it is opened).
const ENDLESS_DEVICE: &str = if cfg!(windows) { "NUL" } else { "/dev/zero" };

/// Poppler's `pdftotext` and `pdftoppm` read the PDFs back: scripts/test installs them, and
/// elsewhere than Windows their absence fails the tests. On Windows they are rarely there
/// (and never on Wine's side of this machine): the tests that need them say SKIPPED there
/// and end (the PDFs' bytes are compared with the Linux binary's by scripts/test-windows).
fn poppler_missing_on_windows() -> bool {
    let missing = cfg!(windows) && Command::new("pdftotext").arg("-v").output().is_err();
    if missing {
        eprintln!("SKIPPED: no pdftotext (poppler) on this Windows");
    }
    missing
}

#[test]
fn the_pdfs_are_typeset_sheets_to_hand_out_and_keys_for_the_teacher() {
    if poppler_missing_on_windows() {
        return;
    }
    let out = std::env::temp_dir().join(format!("phonglab-expdf-{}", std::process::id()));
    let o = phonglab(&[
        "exercise",
        "--seed",
        "5",
        "--count",
        "3",
        "--level",
        "4",
        "--worksheet",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text_of = |pdf: &str, pages: Option<(u32, u32)>| {
        let mut c = Command::new("pdftotext");
        if let Some((f, l)) = pages {
            c.args(["-f", &f.to_string(), "-l", &l.to_string()]);
        }
        stdout(&c.arg(out.join(pdf)).arg("-").output().expect("pdftotext (poppler-utils) is installed by scripts/test"))
    };
    for pdf in ["sheets.pdf", "keys.pdf"] {
        let ppm = Command::new("pdftoppm")
            .args(["-r", "30", "-png", "-f", "1", "-l", "1"])
            .arg(out.join(pdf))
            .arg(out.join("page"))
            .output()
            .expect("pdftoppm (poppler-utils) is installed by scripts/test");
        assert!(ppm.status.success(), "{}", stderr(&ppm));
        // Typeset, not Markdown: no syntax is printed.
        let text = text_of(pdf, None);
        for syntax in ["```", "## ", "# ", "`", "**", "________", "- ["] {
            assert!(!text.contains(syntax), "{pdf} prints {syntax:?}");
        }
    }
    // The sheets: each exercise starts a page, with the lines to write on, and no answers.
    let sheets = text_of("sheets.pdf", None);
    assert!(sheets.contains("Class:") && sheets.contains("Name:") && sheets.contains("Date:"), "{sheets}");
    let pages: Vec<String> =
        (1..=40).map(|p| text_of("sheets.pdf", Some((p, p)))).take_while(|t| !t.is_empty()).collect();
    for k in 1..=3 {
        let title = format!("exercise {k} (seed 5)");
        let page = pages.iter().position(|t| t.contains(&title)).unwrap();
        assert!(pages[page].trim_start().starts_with(&title), "exercise {k} opens page {}", page + 1);
        // Each page of it names it in the footer, numbered in the whole document; it has an
        // even number of pages (a blank back page where needed), so that printed on both
        // sides it is its own paper.
        let count = pages.iter().filter(|t| t.contains(&title)).count();
        assert!(count >= 2 && count.is_multiple_of(2), "exercise {k}: {count} pages");
        for n in 1..=count {
            let t = &pages[page + n - 1];
            assert!(
                t.contains(&title) && t.contains(&format!("page {} of {}", page + n, pages.len())),
                "exercise {k} page {n}:\n{t}"
            );
        }
    }
    assert!(pages.len().is_multiple_of(2), "{} pages", pages.len());
    assert!(pages.iter().any(|t| t.contains("This page is left blank on purpose.")), "level 4 pads an exercise");
    // The keys hold every answer, as explain prints it.
    let keys = text_of("keys.pdf", None);
    let mut values = 0;
    for k in 0..=3 {
        let key = std::fs::read_to_string(out.join(format!("exercise-{k:02}-key.md"))).unwrap();
        for line in key.lines().filter(|l| l.starts_with("    ") && l.contains(" = ")) {
            let value = line.trim();
            assert!(keys.contains(value), "exercise {k}: {value:?} is not in keys.pdf");
            assert!(
                !sheets.contains(value) || value.ends_with("= 1") || value.contains("= [0 0"),
                "{value:?} is on a sheet"
            );
            values += 1;
        }
    }
    assert!(values > 100, "{values} answers checked");

    // In Portuguese: the lines to write on, the steps' names and the decimal comma.
    let pt = out.join("pt");
    let o = phonglab(&[
        "exercise",
        "--lang",
        "pt-PT",
        "--seed",
        "5",
        "--count",
        "1",
        "--level",
        "4",
        "--out",
        pt.to_str().unwrap(),
    ]);

    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&Command::new("pdftotext").arg(pt.join("sheets.pdf")).arg("-").output().unwrap());
    for pt_text in ["Turma:", "Nome:", "Data:", "Vetor da luz", "Calcular", "exercício 1 (semente 5)"] {
        assert!(text.contains(pt_text), "{pt_text:?} in the Portuguese sheet:\n{text}");
    }
    let keys = stdout(&Command::new("pdftotext").arg(pt.join("keys.pdf")).arg("-").output().unwrap());
    assert!(keys.contains("Respostas:") && keys.contains("I = [0,"), "{keys}");
}

/// The handouts print what belongs there: no value below its vector's last printed digit
/// (a rotation's 6.123234e-17 beside a 1 is 0), no -0; one numbering (every step a sheet
/// asks has the number the key gives it); and an index in the reader's language.
#[test]
fn the_handouts_are_exact_numbered_as_their_keys_and_in_the_readers_words() {
    if poppler_missing_on_windows() {
        return;
    }
    let out = std::env::temp_dir().join(format!("phonglab-handouts-{}", std::process::id()));
    let args = ["exercise", "--seed", "5", "--count", "3", "--level", "4", "--worksheet", "--out"];
    let o = phonglab(&[&args[..], &[out.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let pdf = |name: &str| stdout(&Command::new("pdftotext").arg(out.join(name)).arg("-").output().unwrap());
    let (sheets, keys) = (pdf("sheets.pdf"), pdf("keys.pdf"));
    // Exact as printed: no value below its vector's last printed digit (a rotation's
    // 6.123234e-17 beside a 1 is 0), no -0; and one numbering: every step a sheet asks has
    // the number the key gives it.
    for text in [&sheets, &keys] {
        assert!(!text.split_whitespace().any(|t| t.trim_matches(|c| c == '[' || c == ']') == "-0"), "a -0 is printed");
    }
    let mut vectors = 0;
    for k in 0..=3 {
        let key = std::fs::read_to_string(out.join(format!("exercise-{k:02}-key.md"))).unwrap();
        let values = key.lines().filter(|l| l.starts_with("    ") && l.ends_with(']'));
        for v in values.filter_map(|l| l.split_once(" = [").map(|(_, v)| v.trim_end_matches(']'))) {
            let xs: Vec<f64> = v.split_whitespace().map(|x| x.parse().unwrap()).collect();
            let largest = xs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for x in xs.iter().filter(|x| **x != 0.0) {
                assert!(x.abs() >= largest * 1e-8, "exercise {k}: {x} beside {largest} is below the printed digits");
            }
            vectors += 1;
        }
    }
    assert!(vectors > 100, "{vectors} vectors checked");
    for k in 1..=3 {
        let sheet = std::fs::read_to_string(out.join(format!("exercise-{k:02}.md"))).unwrap();
        let key = std::fs::read_to_string(out.join(format!("exercise-{k:02}-key.md"))).unwrap();
        let mut asked = 0;
        for line in sheet.lines().filter(|l| l.ends_with("= ________")) {
            let (number, rest) = line.split_once(". ").unwrap();
            let title = rest.split(": `").next().unwrap();
            let numbered = format!("{number:>2}. {title}");
            assert!(key.contains(&numbered), "exercise {k}: the key does not number {title:?} {number}");
            asked += 1;
        }
        assert!(asked > 5, "exercise {k}: {asked} steps asked");
    }

    let pt = out.join("pt");
    let o = phonglab(&[
        "exercise",
        "--lang",
        "pt-PT",
        "--seed",
        "5",
        "--count",
        "1",
        "--level",
        "4",
        "--out",
        pt.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let index = std::fs::read_to_string(pt.join("index.md")).unwrap();
    for english in ["positional", "attenuation", "two-sided", "several-lights", "local-viewer", "worksheet"] {
        assert!(!index.contains(english), "{english:?} in the Portuguese index:\n{index}");
    }
    assert!(index.contains("várias luzes") && index.contains("atenuação"), "{index}");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn shader_prints_only_the_stages_the_scene_needs() {
    let spot = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    for lang in ["glsl", "wgsl"] {
        for shading in ["gouraud", "phong"] {
            let with = phonglab(&["shader", "--scene", spot.to_str().unwrap(), "--target", lang, "--shading", shading]);
            assert!(with.status.success(), "{}", stderr(&with));
            let with = stdout(&with);
            let without = stdout(&phonglab(&["shader", "--target", lang, "--shading", shading]));
            assert!(with.contains("spot_cos_cutoff"), "{lang} {shading}: the spotlight's cone test\n{with}");
            assert!(!without.contains("spot_"), "{lang} {shading}: the worksheet has no spotlight\n{without}");
            // Phong lights per fragment: the lighting is in the fragment stage.
            let fragment = with.split("fs_main").nth(1).or_else(|| with.split("fragment shader").nth(1)).unwrap();
            assert_eq!(fragment.contains("spot_cos_cutoff"), shading == "phong", "{lang} {shading}");
        }
    }
    let bad = phonglab(&["shader", "--target", "hlsl"]);
    assert!(!bad.status.success());
    assert!(stderr(&bad).contains("try glsl or wgsl"));
}

#[test]
fn bench_lighting_says_where_the_time_goes_stage_by_stage() {
    let o = phonglab(&["bench", "lighting", "--vertices", "3000", "--repeats", "1", "--stages"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("# memory floor: the same arrays read and written"), "{out}");
    let steps = |scene: &str| -> Vec<(String, f64)> {
        out.lines()
            .filter_map(|l| l.strip_prefix(&format!("{scene} ")))
            .filter(|rest| !rest.starts_with(|c: char| c.is_ascii_digit()))
            .map(|rest| {
                let (step, ns) = rest.rsplit_once(' ').unwrap();
                (step.to_string(), ns.parse::<f64>().unwrap())
            })
            .collect()
    };
    let a = steps("a_directional");
    let b = steps("b_positional_local");
    let c = steps("c_eight_spots");
    // Each scene lists its own program: the directional light's L is a constant, the
    // positional one's is a stage, and eight spotlights have eight cone tests.
    let names = |v: &[(String, f64)]| v.iter().map(|(s, _)| s.clone()).collect::<Vec<_>>();
    assert!(names(&a).contains(&"LightConstant(0)".to_string()) && !names(&a).contains(&"LightVector(0)".to_string()));
    assert!(names(&b).contains(&"LightVector(0)".to_string()) && names(&b).contains(&"Halfway(0)".to_string()));
    assert_eq!(names(&c).iter().filter(|s| s.starts_with("SpotCone(")).count(), 8);
    for v in [&a, &b, &c] {
        assert_eq!(v.first().unwrap().0, "load");
        assert_eq!(v.last().unwrap().0, "total");
        let parts: f64 = v[..v.len() - 1].iter().map(|(_, ns)| ns).sum();
        let total = v.last().unwrap().1;
        assert!(total > 0.0 && (parts - total).abs() <= 0.02 * total + 0.05, "{parts} vs {total}");
    }
}

#[test]
fn errors_tables_and_file_names_in_portuguese_data_in_english() {
    // A missing file, a device, an unwritable place, an unknown preset: said in Portuguese,
    // the system's reason too.
    let o = phonglab_in("pt_PT.UTF-8", &["eval", "/no/such/cases.json"]);
    assert_eq!(stderr(&o).trim(), "phonglab: não foi possível ler /no/such/cases.json: não existe");
    let o = phonglab_in("pt_BR.UTF-8", &["explain", ENDLESS_DEVICE]);
    let said = if cfg!(windows) {
        format!("phonglab: {ENDLESS_DEVICE} é um nome que o Windows reserva para um dispositivo")
    } else {
        format!("phonglab: {ENDLESS_DEVICE} não é um arquivo comum")
    };
    assert!(stderr(&o).trim().starts_with(&said), "{}", stderr(&o));
    let o = phonglab_in("pt_PT.UTF-8", &["render", "-o", "/no/such/folder/x.png"]);
    assert!(
        stderr(&o).contains(
            "não foi possível escrever /no/such/folder/x.png: criar: a pasta /no/such/folder não existe: crie-a primeiro"
        ) && stderr(&o).contains("; nada foi escrito"),
        "{}",
        stderr(&o)
    );
    let o = phonglab_in("pt_PT.UTF-8", &["render", "--preset", "foo", "-o", "/tmp/x.png"]);
    assert!(stderr(&o).contains("cena pronta desconhecida \"foo\""), "{}", stderr(&o));
    // The cost table in Portuguese, with decimal commas; its files keep English names and
    // the CSV English keys and decimal points.
    let dir = std::env::temp_dir().join(format!("phonglab-cost-pt-{}", std::process::id()));
    let out = dir.to_str().unwrap();
    let o = phonglab_in("pt_PT.UTF-8", &["cost", "--quick", "--object", "cylinder", "--size", "32", "--out", out]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = stdout(&o);
    assert!(table.starts_with("# Cilindro: 32x32 px, referência com 80000 triângulos"), "{table}");
    assert!(table.contains("variante") && table.contains("Phong 32, pow de Schlick"), "{table}");
    let row = table.lines().find(|l| l.starts_with("Gouraud 8 ")).unwrap();
    assert!(row.contains(',') && !row.contains('.'), "{row}");
    assert!(dir.join("heat-cylinder-phong-32.png").exists());
    let csv = std::fs::read_to_string(dir.join("cost.csv")).unwrap();
    let line = csv.lines().find(|l| l.contains("Schlick")).unwrap();
    assert!(line.starts_with("cylinder,\"Phong 32, Schlick pow\",Approximation,Phong,32,"), "{line}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn export_writes_each_kind_of_code_and_import_reads_a_notebook_back() {
    let dir = std::env::temp_dir().join(format!("phonglab-cli-export-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes/spotlight.toml");
    // To the standard output.
    let o = common::phonglab(&["export", "--scene", scene, "--to", "glsl"]);
    assert!(o.status.success() && String::from_utf8_lossy(&o.stdout).contains("#version 330 core"));
    // openFrameworks needs a folder: the files go into its src/.
    let o = common::phonglab(&["export", "--scene", scene, "--to", "openframeworks"]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("-o"), "{o:?}");
    let app = dir.join("spotApp");
    let o = common::phonglab(&["export", "--scene", scene, "--to", "openframeworks", "-o", app.to_str().unwrap()]);
    assert!(o.status.success(), "{o:?}");
    for f in ["ofApp.h", "ofApp.cpp", "main.cpp"] {
        assert!(app.join("src").join(f).is_file(), "{f}");
    }
    assert!(std::fs::read_to_string(app.join("src/ofApp.cpp")).unwrap().contains("light0.setSpotlight(12.0f, 8.0f)"));
    // The notebook, then back to a scene: the same worked calculation.
    let nb = dir.join("spot.ipynb");
    let o = common::phonglab(&["export", "--scene", scene, "--to", "notebook", "-o", nb.to_str().unwrap()]);
    assert!(o.status.success(), "{o:?}");
    let back = dir.join("back.toml");
    let o = common::phonglab(&["import", nb.to_str().unwrap(), "-o", back.to_str().unwrap()]);
    assert!(o.status.success(), "{o:?}");
    let explain = |p: &str| String::from_utf8(common::phonglab(&["explain", p]).stdout).unwrap();
    let (a, b) = (explain(scene), explain(back.to_str().unwrap()));
    // The heading names the scene; every step after it is the same.
    assert_eq!(a.lines().skip(1).collect::<Vec<_>>(), b.lines().skip(1).collect::<Vec<_>>());
    // Not a notebook: refused with the reason, nothing written.
    let bad = dir.join("bad.ipynb");
    std::fs::write(&bad, "{ not json").unwrap();
    let out = dir.join("never.toml");
    let o = common::phonglab(&["import", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("not a Jupyter notebook"), "{o:?}");
    assert!(!out.exists());
    // A Flat view has no PyOpenGL program (the generated shaders are Gouraud and Phong).
    let flat = dir.join("flat.toml");
    std::fs::write(&flat, std::fs::read_to_string(scene).unwrap().replace("shading = \"phong\"", "shading = \"flat\""))
        .unwrap();
    let o = common::phonglab(&["export", "--scene", flat.to_str().unwrap(), "--to", "pyopengl"]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("Gouraud or Phong"), "{o:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The rows `bench render` printed: (object, shading, triangles, coverage, the four stages'
/// ms), the stages each a number at least 0.
fn bench_rows(o: &Output) -> Vec<(String, String, usize, f64, [f64; 4])> {
    assert!(o.status.success(), "{}", stderr(o));
    stdout(o)
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("object"))
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            let stage = |k: usize| f[k].parse::<f64>().unwrap();
            let stages = [stage(5), stage(6), stage(7), stage(8)];
            assert!(stages.iter().all(|s| *s >= 0.0), "{l}");
            (f[0].into(), f[1].into(), f[3].parse().unwrap(), f[4].parse().unwrap(), stages)
        })
        .collect()
}

#[test]
fn bench_render_times_a_scan_like_mesh_an_obj_file_and_a_finer_sphere() {
    let scan = phonglab(&["bench", "render", "--scan", "3", "--frames", "1", "--size", "64", "--shading", "phong"]);
    let rows = bench_rows(&scan);
    assert_eq!(rows.len(), 1, "{}", stdout(&scan));
    assert_eq!((rows[0].0.as_str(), rows[0].1.as_str(), rows[0].2), ("scan", "phong", 20 * 64));
    // As large as the benchmark's sphere: about 40 % of the picture.
    assert!((0.25..0.6).contains(&rows[0].3), "coverage {}", rows[0].3);
    let sphere =
        phonglab(&["bench", "render", "--sphere", "20", "--object", "sphere", "--frames", "1", "--size", "64"]);
    let rows = bench_rows(&sphere);
    assert_eq!(rows.len(), 3, "Gouraud, Phong, Flat: {}", stdout(&sphere));
    assert!(rows.iter().all(|r| r.0 == "sphere" && r.2 == 2 * 20 * 19), "{rows:?}");
    let obj = temp_file("bench.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    let mesh = phonglab(&["bench", "render", "--mesh", obj.to_str().unwrap(), "--frames", "1", "--size", "64"]);
    let rows = bench_rows(&mesh);
    assert!(rows.len() == 3 && rows.iter().all(|r| r.0 == "mesh" && r.2 == 4 && r.3 > 0.05), "{rows:?}");
    let refused = phonglab(&["bench", "render", "--scan", "10"]);
    assert!(!refused.status.success() && stderr(&refused).contains("levels 0 to 9"), "{}", stderr(&refused));
}

/// `bench render --write-mesh` writes the mesh it would time, as placed in the benchmark's
/// view (what Mesa's harness draws), times nothing, and never writes over the mesh it read.
#[test]
fn bench_render_writes_the_timed_mesh_for_mesa() {
    let out = temp_file("scan2.obj", "");
    let _ = std::fs::remove_file(&out);
    let written = phonglab(&["bench", "render", "--scan", "2", "--write-mesh", out.to_str().unwrap()]);
    assert!(written.status.success(), "{}", stderr(&written));
    assert!(stdout(&written).contains("320 triangles"), "{}", stdout(&written));
    assert!(!stdout(&written).contains("ms_per_frame"), "times nothing: {}", stdout(&written));
    let text = std::fs::read_to_string(&out).unwrap();
    let count = |tag: &str| text.lines().filter(|l| l.starts_with(tag)).count();
    assert_eq!((count("v "), count("vn "), count("f ")), (162, 162, 320));
    // Made as large as the benchmark's sphere (radius 1; the scan's bumps stand out of it):
    // the mesh as timed, not as generated (about half that).
    let far = text
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| l.split_whitespace().map(|w| w.parse::<f64>().unwrap().powi(2)).sum::<f64>().sqrt())
        .fold(0.0, f64::max);
    assert!((1.0..1.25).contains(&far), "farthest vertex at {far}");
    // Read back as the mesh to time: the same triangles.
    let again = phonglab(&["bench", "render", "--mesh", out.to_str().unwrap(), "--frames", "1", "--size", "32"]);
    assert!(bench_rows(&again).iter().all(|r| r.2 == 320));
    let onto = phonglab(&["bench", "render", "--mesh", out.to_str().unwrap(), "--write-mesh", out.to_str().unwrap()]);
    assert!(!onto.status.success() && stderr(&onto).contains("the same file"), "{}", stderr(&onto));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), text, "the input is untouched");
}

/// `bench render --moving light` keeps the visibility of every timed frame (the light
/// circles the standing object) and `--moving object` of none; `--coarse N` times the copy
/// the app draws while the camera turns, and says how it was made.
#[test]
fn bench_render_times_frames_that_only_light_again_and_the_coarse_copy() {
    let kept = |moving: &str| {
        let o = phonglab(&[
            "bench", "render", "--sphere", "40", "--object", "sphere", "--frames", "4", "--size", "64", "--moving",
            moving,
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let lines: Vec<String> =
            stdout(&o).lines().filter(|l| l.starts_with("sphere ")).map(std::string::ToString::to_string).collect();
        assert_eq!(lines.len(), 3, "{}", stdout(&o));
        lines.iter().map(|l| l.split_whitespace().nth(10).unwrap().parse::<u32>().unwrap()).collect::<Vec<_>>()
    };
    assert_eq!(kept("light"), [4, 4, 4]);
    assert_eq!(kept("object"), [0, 0, 0]);
    let o = phonglab(&[
        "bench", "render", "--sphere", "200", "--object", "sphere", "--frames", "1", "--size", "64", "--coarse", "5000",
    ]);
    let out = stdout(&o);
    let made = out.lines().find(|l| l.contains("the coarse copy has")).unwrap_or_else(|| panic!("{out}"));
    assert!(made.contains("of 79600 triangles"), "{made}");
    let rows = bench_rows(&o);
    assert!(rows.iter().all(|r| (3750..=5500).contains(&r.2)), "{rows:?}");
    let refused = phonglab(&["bench", "render", "--moving", "camera"]);
    assert!(!refused.status.success());
}

/// A reader that goes away (`phonglab explain | head -1`) ends the command quietly, as Unix
/// tools end: no panic and no backtrace on the terminal (`println!` panicked with a broken
/// pipe before).
#[cfg(unix)]
#[test]
fn a_closed_pipe_ends_a_command_without_a_panic() {
    use std::process::Stdio;
    for args in [&["explain"][..], &["help"][..], &["export", "--to", "notebook"][..]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .args(args)
            .env("LC_ALL", "C.UTF-8")
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // The reader goes away before the command writes.
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked") && !err.contains("Broken pipe"), "{args:?}: {err}");
    }
}

/// A command stopped by Ctrl+C (SIGINT) or asked to end (SIGTERM: a logout, `kill`) says so
/// in the user's language, and that no file is left half-written, before it ends with the
/// code a shell expects (128 + the signal); it vanished without a word before. The command
/// waits on its standard input (`check --printed -`), and the signal is sent once its
/// handler is installed (its debug log line).
#[cfg(unix)]
#[test]
fn a_command_stopped_by_ctrl_c_says_so_in_the_users_language() {
    use std::io::{BufRead, BufReader, Read};
    use std::process::Stdio;
    for (lang, signal, said, code) in [
        ("C.UTF-8", libc::SIGINT, "phonglab: stopped by Ctrl+C. No file is left half-written", 130),
        ("pt_PT.UTF-8", libc::SIGINT, "phonglab: parado com Ctrl+C. Nenhum ficheiro ficou escrito a meio", 130),
        ("pt_BR.UTF-8", libc::SIGTERM, "phonglab: interrompido: o sistema pediu que ele terminasse.", 143),
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .args(["check", "--printed", "-"])
            .env_remove("LC_ALL")
            .env_remove("LC_MESSAGES")
            .env("LANG", lang)
            .env("RUST_LOG", "phonglab=debug")
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Its input closed after a minute, should no handler ever say it is installed: the
        // command then ends (nothing printed to check), and the test fails rather than hangs.
        let input = child.stdin.take();
        std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_secs(60));
            drop(input);
        });
        let mut err = BufReader::new(child.stderr.take().unwrap());
        let mut before = String::new();
        while !before.contains("a command stopped by Ctrl+C says so") {
            assert!(err.read_line(&mut before).unwrap() > 0, "ended before its handler: {before}");
        }
        // SAFETY: a signal to the child this test started and has not yet waited for.
        assert_eq!(unsafe { libc::kill(child.id() as i32, signal) }, 0);
        let mut after = String::new();
        err.read_to_string(&mut after).unwrap();
        let status = child.wait().unwrap();
        assert_eq!(status.code(), Some(code), "{lang}: {after}");
        assert!(after.contains(said), "{lang}: {after}");
    }
}
