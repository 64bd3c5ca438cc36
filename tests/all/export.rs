//! The Export menu: the PNG is what `phonglab render` draws for the scene, byte for byte;
//! the exercise zip holds what `phonglab exercise` writes, byte for byte; the menu shows
//! its labelled fields inside the window.

use std::process::Command;

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::panels::export::{ExportState, exercises_zip, shaded_png};
use phonglab::app::{AppState, app_ui};

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("phonglab-export-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

use crate::common;

fn phonglab(args: &[&str]) {
    let o = common::phonglab(args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn the_png_is_what_render_draws_for_the_scene() {
    let dir = temp_dir("png");
    let mut state = AppState::worksheet();
    state.doc.view.shading = phonglab_core::Shading::Phong;
    let png = shaded_png(&state.doc, state.settings.pow).unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, state.doc.to_toml().unwrap()).unwrap();
    let out = dir.join("render.png");
    phonglab(&["render", "--scene", scene.to_str().unwrap(), "--size", "512", "-o", out.to_str().unwrap()]);
    assert_eq!(png, std::fs::read(&out).unwrap(), "the menu's PNG and render's");
    assert!(png.len() > 10_000, "{} bytes: a picture, not an empty image", png.len());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_exercise_zip_holds_what_exercise_writes() {
    let dir = temp_dir("zip");
    let zip = exercises_zip(&ExportState { seed: 3, count: 2, level: 2 }).unwrap();
    std::fs::write(dir.join("set.zip"), &zip).unwrap();
    let unzipped = Command::new("python3")
        .args(["-c", "import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])"])
        .arg(dir.join("set.zip"))
        .arg(dir.join("zip"))
        .output()
        .unwrap();
    assert!(unzipped.status.success(), "{}", String::from_utf8_lossy(&unzipped.stderr));
    let cli = dir.join("cli");
    phonglab(&["exercise", "--seed", "3", "--count", "2", "--level", "2", "--out", cli.to_str().unwrap()]);
    let mut names: Vec<String> =
        std::fs::read_dir(&cli).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    // The folder's list of what the set wrote is phonglab's own record, not a file of the set.
    names.retain(|n| !n.starts_with(".phonglab-set"));
    names.sort();
    assert!(names.contains(&"sheets.pdf".to_string()) && names.contains(&"keys.pdf".to_string()), "{names:?}");
    for name in &names {
        let a = std::fs::read(cli.join(name)).unwrap();
        let b = std::fs::read(dir.join("zip").join(name)).unwrap_or_else(|_| panic!("{name} is not in the zip"));
        assert!(a == b, "{name} differs between the zip and phonglab exercise");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_export_menu_shows_its_fields_inside_the_window() {
    let mut h = Harness::builder()
        .with_size([1440.0, 900.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(3);
    common::open_menu(&mut h, &["File", "Export"]);
    h.run_steps(1);
    let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1440.0, 900.0));
    for label in ["Seed", "Exercises", "Level"] {
        let field = h.get_by_role_and_label(Role::SpinButton, label);
        let r = field.rect();
        assert!(window.contains_rect(r) && r.width() > 20.0, "{label} at {r:?}");
    }
    let png = h.get_by_label("Shaded view as PNG (512×512)").rect();
    let save = h.get_by_label("Save the sheets (.zip)").rect();
    assert!(window.contains_rect(png) && window.contains_rect(save) && save.min.y > png.max.y, "{png:?} {save:?}");
}

/// A worksheet notebook made from the worksheet's own cells, with one edit.
fn students_notebook(dir: &std::path::Path) -> std::path::PathBuf {
    use phonglab_core::export::notebook::{Cell, ipynb};
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/worksheet_cells.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let cells: Vec<Cell> = json["cells"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| Cell::Code(c.as_str().unwrap().replace("mview = mview5", "mview = mview3")))
        .collect();
    let path = dir.join("aluno.ipynb");
    std::fs::write(&path, ipynb(&cells)).unwrap();
    path
}

#[test]
fn the_export_menu_copies_each_kind_of_code_and_a_dropped_notebook_opens_as_the_scene() {
    let mut h = Harness::builder()
        .with_size([1280.0, 720.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(3);
    let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1280.0, 720.0));
    let expected = [
        ("Jupyter notebook (the worksheet's)", "vertexNormal = np.matmul(mview, vertexNormal)"),
        ("Python program (PyOpenGL + GLUT)", "glLightfv(GL_LIGHT0, GL_POSITION, [0, 0, 90, 1])"),
        ("openFrameworks app (ofApp.h, ofApp.cpp, main.cpp)", "// ---- ofApp.cpp ----"),
        ("GLSL shaders", "#version 330 core"),
    ];
    for (row, (label, text)) in expected.iter().enumerate() {
        common::open_menu(&mut h, &["File", "Export"]);
        h.run_steps(1);
        let name = h.get_by_label(label).rect();
        let copies = h.query_all_by_label("Copy").map(|n| n.rect()).collect::<Vec<_>>();
        let saves = h.query_all_by_label("Save…").map(|n| n.rect()).collect::<Vec<_>>();
        assert_eq!((copies.len(), saves.len()), (4, 4), "a Copy and a Save for each");
        // On the label's row, to its right, inside the window.
        let (copy, save) = (copies[row], saves[row]);
        assert!(
            window.contains_rect(copy) && window.contains_rect(save) && window.contains_rect(name),
            "{name:?} {copy:?}"
        );
        assert!(copy.min.x > name.max.x && save.min.x > copy.max.x, "{label}: {name:?} {copy:?} {save:?}");
        assert!((copy.center().y - name.center().y).abs() < 4.0, "{label}: {name:?} {copy:?}");
        h.query_all_by_label("Copy").nth(row).unwrap().click();
        h.run_steps(1);
        let copied = common::copied_text(&h);
        assert!(
            copied.iter().any(|t| t.contains(text)),
            "{label}: {:?}",
            copied.iter().map(|t| &t[..t.len().min(200)]).collect::<Vec<_>>()
        );
        h.run_steps(2);
    }

    let dir = temp_dir("import");
    let notebook = students_notebook(&dir);
    h.input_mut().dropped_files.push(std::sync::Arc::new(common::Dropped(notebook.clone())));
    h.run_steps(2);
    let s = h.state();
    assert_eq!(s.doc.camera, phonglab_core::CameraSpec::Worksheet(3), "{:?}", s.message);
    assert!(
        matches!(&s.message, Some(phonglab::app::shell::state::Message::Info(m)) if m.contains("aluno.ipynb")),
        "{:?}",
        s.message
    );
    // Save goes beside the notebook, never over it.
    assert_eq!(s.files.path, dir.join("aluno.toml").display().to_string());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A shipped scene's name is English in its file; what phonglab writes from it says it in
/// the language set: a Portuguese notebook said "Cena: **the worksheet, mview1**".
#[test]
fn a_shipped_scene_s_name_is_written_in_the_language_set() {
    let dir = temp_dir("names");
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/worksheet-mview1.toml");
    let (nb, py) = (dir.join("nb.ipynb"), dir.join("p.py"));
    let s = |p: &std::path::Path| p.to_str().unwrap().to_owned();
    phonglab(&["--lang", "pt-PT", "export", "--scene", &s(&scene), "--to", "notebook", "-o", &s(&nb)]);
    phonglab(&["--lang", "pt-BR", "export", "--scene", &s(&scene), "--to", "pyopengl", "-o", &s(&py)]);
    let nb = std::fs::read_to_string(&nb).unwrap();
    assert!(nb.contains("Cena: **a ficha, mview1**") && !nb.contains("the worksheet"), "{nb}");
    let py = std::fs::read_to_string(&py).unwrap();
    assert!(py.contains("a lista, mview1") && !py.contains("the worksheet"), "{py}");
}
