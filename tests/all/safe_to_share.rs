//! Safe to share: what a hostile or careless input cannot do to a student's files, their
//! terminal or their machine, run as a real process (the command line) as a student runs
//! it. Each test is one attack of issue 43's list.

use std::path::{Path, PathBuf};
use std::process::Output;

use crate::common;
use common::phonglab;

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("phonglab-safe-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A worksheet-style script that `import` reads.
const SCRIPT: &str = "vertexPos = np.array([-512, -384, 0, 1])\nlightPos = np.array([0, 0, 90, 1])\n";

/// Runs `args`; it must refuse with exit 2, say that the output is the input, and leave
/// `input` byte for byte as it was.
fn refused_onto_input(args: &[&str], input: &Path) {
    let before = std::fs::read(input).unwrap();
    let out = phonglab(args);
    let e = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {e}");
    assert!(e.contains("which this command reads") && e.contains("the same file"), "{args:?}: {e}");
    assert_eq!(std::fs::read(input).unwrap(), before, "{args:?} changed its input");
}

#[test]
fn an_output_that_is_an_input_is_refused_by_every_command() {
    let dir = folder("onto-input");
    let nb = dir.join("nb.py");
    std::fs::write(&nb, SCRIPT).unwrap();
    refused_onto_input(&["import", s(&nb), "-o", s(&nb)], &nb);
    let scene = dir.join("s.toml");
    std::fs::copy("assets/scenes/spotlight.toml", &scene).unwrap();
    refused_onto_input(&["render", "--scene", s(&scene), "--size", "8", "-o", s(&scene)], &scene);
    refused_onto_input(&["export", "--scene", s(&scene), "--to", "notebook", "-o", s(&scene)], &scene);
    refused_onto_input(&["screenshot", "--scene", s(&scene), "--size", "320x200", "-o", s(&scene)], &scene);
    // Through a hard link, a symbolic link (not on Windows: see common::symlink)
    // and a detour.
    std::fs::hard_link(&scene, dir.join("hard.toml")).unwrap();
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    let mut through = vec!["hard.toml", "sub/../s.toml"];
    if cfg!(unix) {
        common::symlink(&scene, dir.join("soft.png")).unwrap();
        through.push("soft.png");
    }
    for out in through {
        let out = dir.join(out);
        refused_onto_input(&["render", "--scene", s(&scene), "--size", "8", "-o", s(&out)], &scene);
    }
    // The mesh a scene names is an input too.
    let mesh = dir.join("m.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    refused_onto_input(&["render", "--obj", s(&mesh), "--size", "8", "-o", s(&mesh)], &mesh);
    // An openFrameworks export into a folder whose src/ holds the scene.
    std::fs::create_dir_all(dir.join("app/src")).unwrap();
    let in_src = dir.join("app/src/ofApp.cpp");
    std::fs::copy("assets/scenes/spotlight.toml", &in_src).unwrap();
    refused_onto_input(
        &["export", "--scene", s(&in_src), "--to", "openframeworks", "-o", s(&dir.join("app"))],
        &in_src,
    );
    // A cost report into the folder of its scene, named like a report's file.
    let csv = dir.join("cost.csv");
    std::fs::copy("assets/scenes/spotlight.toml", &csv).unwrap();
    refused_onto_input(&["cost", "--scene", s(&csv), "--quick", "--size", "16", "--out", s(&dir)], &csv);
    // A different file is written as asked.
    let ok = phonglab(&["import", s(&nb), "-o", s(&dir.join("nb.toml"))]);
    assert!(ok.status.success(), "{}", stderr(&ok));
}

/// Issue 54, 1: the scene's mesh is an input of `share --qr` too, and one output of a
/// command is never another (the PFM of `render --raw` onto its PNG), said in those words.
#[test]
fn an_output_onto_the_mesh_or_onto_the_other_output_is_refused_in_those_words() {
    let dir = folder("onto-mesh");
    let mesh = dir.join("m.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let scene = dir.join("s.toml");
    std::fs::write(&scene, "name = \"m\"\n[material]\npreset = \"gold\"\n[view]\nobject = \"obj\"\nobj = \"m.obj\"\n")
        .unwrap();
    refused_onto_input(&["share", s(&scene), "--qr", s(&mesh)], &mesh);
    let e = stderr(&phonglab(&["share", s(&scene), "--qr", s(&mesh)]));
    assert!(e.contains("is the mesh"), "{e}");
    // The two outputs of one render: refused before either is written, whether the file
    // is there yet or not.
    let pic = dir.join("pic.png");
    for there in [false, true] {
        if there {
            std::fs::write(&pic, "the old picture").unwrap();
        }
        let o = phonglab(&["render", "--size", "8", "--channel", "diffuse", "--raw", s(&pic), "-o", s(&pic)]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{e}");
        assert!(e.contains("is the other output") && e.contains("the same file"), "{e}");
        let now = std::fs::read(&pic).ok();
        assert_eq!(now.as_deref(), there.then_some(b"the old picture".as_slice()), "nothing written");
    }
}

#[test]
fn a_name_reaches_the_terminal_without_its_escape_sequences() {
    let dir = folder("terminal");
    let scene = dir.join("s.toml");
    // A scene file refuses a control character in its name, saying which and where...
    std::fs::write(&scene, "name = \"a\\u001b[2J\\u001b[31mred\"\n[material]\npreset = \"gold\"\n").unwrap();
    let out = phonglab(&["explain", s(&scene)]);
    let e = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{e}");
    assert!(e.contains("name holds the control character U+001B (character 2)"), "{e}");
    assert!(!out.stderr.contains(&0x1b) && !out.stdout.contains(&0x1b), "no ESC reaches the terminal");
    // ...and a file named so, imported, gives a name that explain prints visibly.
    let nb = dir.join("evil\u{1b}[2J\"\"\"name.py");
    std::fs::write(&nb, SCRIPT).unwrap();
    let toml = dir.join("imported.toml");
    let out = phonglab(&["import", s(&nb), "-o", s(&toml)]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(!out.stderr.contains(&0x1b), "the notices name the file visibly: {}", stderr(&out));
    let out = phonglab(&["explain", s(&toml)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.starts_with("Worked calculation: evil\\u{1B}[2J\"\"\"name\n"), "{text}");
    // The scene file keeps the name, on one line, and reads back.
    let saved = std::fs::read_to_string(&toml).unwrap();
    assert!(saved.starts_with("name = \"evil\\\\u{1B}[2J\\\"\\\"\\\"name\"\n"), "{saved}");
}

/// The hostile scripts of the issue: 10 000 nested brackets, and 399 bytes of lists that
/// repeat the line above (3 GB when evaluated).
fn hostile_scripts(dir: &Path) -> Vec<(PathBuf, &'static str)> {
    let deep = dir.join("deep.py");
    std::fs::write(&deep, format!("lightPos = {}1{}\n", "[".repeat(10_000), "]".repeat(10_000))).unwrap();
    let mut growth = String::from("a0 = [1, 2, 3, 4]\n");
    for i in 1..=15 {
        growth.push_str(&format!("a{i} = [a{0}, a{0}, a{0}, a{0}]\n", i - 1));
    }
    growth.push_str("lightPos = np.array(a15)\n");
    let grows = dir.join("grows.py");
    std::fs::write(&grows, growth).unwrap();
    vec![(deep, "line 1: `lightPos = [[[["), (grows, "line 7: `a6 = [a5, a5, a5, a5]` holds more than 10 000")]
}

#[test]
fn a_hostile_script_is_refused_with_its_line_by_import_and_by_the_window() {
    let dir = folder("hostile");
    for (file, said) in hostile_scripts(&dir) {
        let out = phonglab(&["import", s(&file), "-o", s(&dir.join("x.toml"))]);
        let e = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{e}");
        assert!(e.contains(said) && e.contains("the file is not read"), "{e}");
        assert!(!dir.join("x.toml").exists());
        // Dropped on the window: a message, and the scene the student had stays.
        let mut state = phonglab::app::AppState::worksheet();
        state.doc.scene.material.shininess = 7.0;
        phonglab::app::shell::files::open(&mut state, &file);
        match &state.message {
            Some(phonglab::app::shell::state::Message::Refused(m)) => assert!(m.contains(said), "{m}"),
            other => panic!("{other:?}"),
        }
        assert_eq!(state.doc.scene.material.shininess, 7.0, "the last change is kept");
    }
}

#[test]
fn import_refuses_a_given_that_is_not_finite_and_writes_no_inf_or_nan() {
    let dir = folder("not-finite");
    let py = dir.join("nf.py");
    std::fs::write(&py, "vertexPos = np.array([1e999, 0, 0, 1])\nlightPos = np.array([0/0, 0, 90, 1])\n").unwrap();
    let toml = dir.join("nf.toml");
    let out = phonglab(&["import", s(&py), "-o", s(&toml)]);
    let e = stderr(&out);
    assert!(e.contains("line 1: vertexPos is Infinity, not a finite number"), "{e}");
    assert!(e.contains("line 2: lightPos is NaN, not a finite number"), "{e}");
    let text = std::fs::read_to_string(&toml).unwrap();
    assert!(!text.contains("inf") && !text.contains("nan"), "{text}");
}

#[test]
fn a_size_past_the_memory_budget_is_refused_with_its_estimate_before_any_work() {
    let dir = folder("budget");
    let out = dir.join("x.png");
    let t = std::time::Instant::now();
    // 32768 x 32768 pixels: 25.8 GB, past any machine's half; the budget is set small so
    // the test does not depend on this machine's memory.
    let o = phonglab(&["--memory-budget", "8G", "screenshot", "--size", "8192x8192", "--scale", "4", "-o", s(&out)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("the window at 32768 x 32768 pixels needs about 25 769 803 776 bytes"), "{e}");
    assert!(e.contains("memory budget of 8 589 934 592 bytes") && e.contains("--memory-budget SIZE raises it"), "{e}");
    assert!(t.elapsed().as_secs_f64() < 10.0, "refused before painting ({:?})", t.elapsed());
    let mesh = dir.join("m.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let o = phonglab(&["--memory-budget", "100M", "render", "--obj", s(&mesh), "--size", "4096", "-o", s(&out)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("a 4096 x 4096 picture of one triangle needs about 268 436 016 bytes"), "{e}");
    assert!(!out.exists(), "nothing written");
    // Within the budget, the same command draws.
    let o = phonglab(&["--memory-budget", "1G", "render", "--obj", s(&mesh), "--size", "64", "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = phonglab(&["--memory-budget", "lots", "render", "--size", "64", "-o", s(&out)]);
    assert!(stderr(&o).contains("write a size such as 512M, 8G or 1.5G"), "{}", stderr(&o));
}

/// Runs the binary with `args` under `ulimit -v KB` (in English).
#[cfg(target_os = "linux")]
fn under_ulimit(kb: u64, args: &str) -> Output {
    std::process::Command::new("/bin/sh")
        .arg("-c")
        .arg(format!("ulimit -v {kb} && exec \"$0\" {args}"))
        .arg(env!("CARGO_BIN_EXE_phonglab"))
        .env("LC_ALL", "C.UTF-8")
        .output()
        .unwrap()
}

/// Issue 60: under `ulimit -v`, a `--memory-budget` past what the limit leaves is refused
/// in words (the run went on and aborted on an allocation, SIGABRT and a backtrace), and
/// a set of sheets past the budget is refused before anything is written (the sheets were
/// not budgeted: 1000 of them aborted under 150 MB).
#[test]
#[cfg(target_os = "linux")]
fn a_budget_or_sheets_past_the_address_space_limit_are_refused_in_words() {
    let dir = folder("ulimit");
    let (bank, sheets) = (dir.join("b"), dir.join("u"));
    let o = under_ulimit(
        3_000_000,
        &format!("exercise --format gift --count 100 --variants 100 --level 4 --memory-budget 16G --out {}", s(&bank)),
    );
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "refused, not aborted: {e}");
    assert!(e.contains("--memory-budget 17 179 869 184 bytes") && e.contains("ulimit -v"), "{e}");
    assert!(!e.contains("backtrace") && !bank.exists(), "{e}");
    let o = under_ulimit(150_000, &format!("exercise --count 1000 --level 4 --out {}", s(&sheets)));
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "refused, not aborted: {e}");
    assert!(e.contains("1 000 exercise sheets with their keys and the two PDFs"), "{e}");
    assert!(e.contains("memory budget") && e.contains("ulimit -v") && !e.contains("backtrace"), "{e}");
    assert!(!sheets.exists(), "nothing written, not even the folder");
}

/// Issue 54, 4: a message quotes a line cut to about 80 characters, however long the line
/// (a 2 MiB `ns = AAAA…` once put 4 MiB on the standard error).
#[test]
fn a_message_quotes_a_line_cut_short_however_long_it_is() {
    let dir = folder("long-line");
    let py = dir.join("long.py");
    std::fs::write(&py, format!("{SCRIPT}ns = {}\n", "A".repeat(2 << 20))).unwrap();
    let o = phonglab(&["import", s(&py), "-o", s(&dir.join("long.toml"))]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(e.len() < 2000, "{} bytes on the standard error", e.len());
    assert!(e.contains("`ns = AAAA") && e.contains("A…`"), "{e}");
}

/// Issue 54, 5: `eval` and `cost` estimate before they allocate, and refuse past the
/// memory budget with the estimate (a 16 MiB case took 290 MB, a study at size 32 about
/// 700 MB, whatever the budget).
#[test]
fn eval_and_cost_refuse_past_the_memory_budget_before_any_work() {
    let dir = folder("budget-eval-cost");
    let cases = dir.join("big.json");
    let n = 2 << 20;
    std::fs::write(&cases, format!("{{\"cases\":[{{\"id\":\"a\",\"tags\":[{}0]}}]}}", "0,".repeat(n))).unwrap();
    let o = phonglab(&["--memory-budget", "64M", "eval", s(&cases)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("lighting one case of 4 194 335 bytes") && e.contains("needs about 150 995 936 bytes"), "{e}");
    assert!(o.stdout.is_empty(), "nothing printed");
    assert!(phonglab(&["--memory-budget", "1G", "eval", s(&cases)]).status.code() != Some(2), "within it, it runs");
    let out = dir.join("report");
    let t = std::time::Instant::now();
    let o = phonglab(&["--memory-budget", "100M", "cost", "--quick", "--size", "32", "--out", s(&out)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("the study of 3 objects at 32 x 32 pixels needs about"), "{e}");
    assert!(t.elapsed().as_secs_f64() < 5.0 && !out.exists(), "refused before any work");
}

/// Issue 54, 6 and 7: `--threads` past what the machine runs, and a `--light` the scene
/// does not have, are refused with a message (they spawned thousands of threads, and
/// drew an empty channel with exit 0).
#[test]
fn too_many_threads_and_a_missing_light_are_refused() {
    let dir = folder("threads-light");
    let o = phonglab(&["cost", "--quick", "--size", "16", "--threads", "100000", "--out", s(&dir)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("--threads 100000: this machine runs at most"), "{e}");
    let most = std::thread::available_parallelism().unwrap().get().to_string();
    let o = phonglab(&["bench", "render", "--frames", "1", "--size", "16", "--threads", "100000"]);
    assert!(stderr(&o).contains(&format!("at most {most} threads")), "{}", stderr(&o));
    let pic = dir.join("x.png");
    let o = phonglab(&["render", "--size", "8", "--channel", "specular", "--light", "99", "-o", s(&pic)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("--light 99: the scene has one light, number 0"), "{e}");
    assert!(!pic.exists());
    let o = phonglab(&["render", "--size", "8", "--channel", "specular", "--light", "0", "-o", s(&pic)]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Does `bytes` (a command's output) hold a control character: ESC, BEL, a C1 control,
/// a bidirectional control or a line separator (U+202E is E2 80 AE in UTF-8)?
fn holds_control(bytes: &[u8]) -> bool {
    String::from_utf8_lossy(bytes).chars().any(|c| c != '\n' && c != '\t' && phonglab_core::escape::is_control(c))
}

/// Issue 54, 9: every command's success and error lines, and clap's echo of a bad value,
/// write a file's name visibly: no OSC, CSI or right-to-left override reaches the
/// teacher's terminal.
#[test]
fn every_line_on_the_terminal_writes_user_text_visibly() {
    let dir = folder("terminal-names");
    let evil = "x\u{1b}]0;pwned\u{7}\u{1b}[31m\u{202e}";
    let scene = dir.join("s.toml");
    std::fs::copy("assets/scenes/spotlight.toml", &scene).unwrap();
    let nb = dir.join("nb.py");
    std::fs::write(&nb, SCRIPT).unwrap();
    let file = |ext: &str| dir.join(format!("{evil}.{ext}"));
    let runs: Vec<Vec<String>> = vec![
        vec!["render".into(), "--size".into(), "8".into(), "-o".into(), s(&file("png")).into()],
        vec!["export".into(), "--to".into(), "notebook".into(), "-o".into(), s(&file("ipynb")).into()],
        vec!["export".into(), "--to".into(), "openframeworks".into(), "-o".into(), s(&file("of")).into()],
        vec!["import".into(), s(&nb).into(), "-o".into(), s(&file("toml")).into()],
        vec!["exercise".into(), "--count".into(), "1".into(), "--out".into(), s(&file("sheets")).into()],
        vec![
            "exercise".into(),
            "--level".into(),
            "5".into(),
            "--count".into(),
            "1".into(),
            "--out".into(),
            s(&file("wrong")).into(),
        ],
        vec![
            "share".into(),
            s(&scene).into(),
            "--base".into(),
            format!("https://e.org/{evil}"),
            "--qr".into(),
            s(&file("svg")).into(),
        ],
        // Refusals name the file too.
        vec!["render".into(), "--size".into(), "8".into(), "-o".into(), s(&dir.join(evil).join("no.png")).into()],
        vec!["import".into(), s(&file("missing.py")).into(), "-o".into(), s(&dir.join("ok.toml")).into()],
        // clap's own refusal echoes the value.
        vec!["render".into(), "--size".into(), evil.into(), "-o".into(), s(&dir.join("x.png")).into()],
        vec!["render".into(), format!("--{evil}"), "-o".into(), s(&dir.join("x.png")).into()],
    ];
    let clap_runs = runs.len() - 2;
    for (k, args) in runs.iter().enumerate() {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = phonglab(&args);
        assert!(!holds_control(&o.stderr), "{args:?}: {:?}", stderr(&o));
        assert!(!holds_control(&o.stdout), "{args:?}: {:?}", String::from_utf8_lossy(&o.stdout));
        let said = format!("{}{}", stderr(&o), String::from_utf8_lossy(&o.stdout));
        // clap takes the escape sequences out of what it echoes itself; the rest is shown.
        let shown = if k >= clap_runs { "\\u{202E}" } else { "\\u{1B}]0;pwned\\u{7}\\u{1B}[31m\\u{202E}" };
        assert!(said.contains(shown), "{args:?}: the name, visibly: {said}");
    }
    let o = phonglab(&["cost", "--quick", "--size", "16", "--object", "cylinder", "--out", s(&file("cost"))]);
    assert!(o.status.success() && !holds_control(&o.stderr), "{:?}", stderr(&o));
}

/// Issue 54, 10: JSON keeps its values but writes the bidirectional and separator
/// controls escaped (serde_json escapes only C0): `case` of a scene file whose name holds
/// U+202E and U+2028, then `eval` of those cases.
#[test]
fn json_writes_bidirectional_and_separator_controls_escaped() {
    let dir = folder("json-bidi");
    let stem = "a\u{202e}b\u{2028}c\u{2066}";
    let scene = dir.join(format!("{stem}.toml"));
    std::fs::copy("assets/scenes/spotlight.toml", &scene).unwrap();
    let o = phonglab(&["case", s(&scene)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!holds_control(&o.stdout), "{}", String::from_utf8_lossy(&o.stdout));
    let cases = dir.join("cases.json");
    std::fs::write(&cases, &o.stdout).unwrap();
    let o = phonglab(&["eval", s(&cases)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!holds_control(&o.stdout), "{}", String::from_utf8_lossy(&o.stdout));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["results"][0]["id"], stem, "the id's value is unchanged");
}

/// Issue 54, 12: the notebook follows `explain` on every scene it is written for: where
/// the engine takes a limit (a zero normal normalised, a vertex with w = 0, a directional
/// light (0, 0, 0, 0), a perspective row taking the vertex to infinity, a singular
/// modelview), the export refuses with `explain`'s note (it printed nan, or raised
/// LinAlgError).
#[test]
fn the_notebook_is_refused_where_explain_takes_a_limit_saying_which() {
    let dir = folder("notebook-limits");
    let identity = "[[1,0,0,0],[0,1,0,0],[0,0,1,-5],[0,0,0,1]]";
    let cases = [
        ("zero", identity, "[0, 2, 3, 1]", "[0, 0, 0, 1]", "[0, 0, 0]", "the normal is zero"),
        ("w0", identity, "[0, 2, 3, 1]", "[0, 0, 1, 0]", "[0, 0, 1]", "the vertex has w = 0"),
        ("dir0", identity, "[0, 0, 0, 0]", "[0, 0, 0, 1]", "[0, 0, 1]", "direction is (0, 0, 0)"),
        ("persp", "[[1,0,0,0],[0,1,0,0],[0,0,1,-5],[0,0,-1,0]]", "[0, 2, 3, 1]", "[0, 0, 0, 1]", "[0, 0, 1]", "w = 0"),
        (
            "singular",
            "[[1,0,0,0],[0,1,0,0],[0,0,0,-5],[0,0,0,1]]",
            "[0, 2, 3, 1]",
            "[0, 0, 0, 1]",
            "[0, 0, 1]",
            "singular",
        ),
    ];
    for (name, rows, light, vertex, normal, note) in cases {
        let scene = dir.join(format!("{name}.toml"));
        std::fs::write(
            &scene,
            format!(
                "name = \"{name}\"\nrules = \"opengl\"\nnormals = \"normalize\"\n[camera]\nkind = \"matrix\"\nrows = {rows}\n\
                 [material]\npreset = \"gold\"\n[[lights]]\nposition = {light}\ndiffuse = [1, 1, 1]\nplacement = \"world\"\n\
                 [vertex]\nposition = {vertex}\nnormal = {normal}\n"
            ),
        )
        .unwrap();
        let explained = phonglab(&["explain", s(&scene)]);
        assert!(String::from_utf8_lossy(&explained.stdout).contains(note), "{name}: explain says {note:?}");
        let nb = dir.join(format!("{name}.ipynb"));
        let o = phonglab(&["export", "--scene", s(&scene), "--to", "notebook", "-o", s(&nb)]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{name}: {e}");
        assert!(e.contains("the notebook is not written for this scene") && e.contains(note), "{name}: {e}");
        assert!(!nb.exists(), "{name}");
        let py = dir.join(format!("{name}.py"));
        let o = phonglab(&["export", "--scene", s(&scene), "--to", "pyopengl", "-o", s(&py)]);
        assert!(o.status.success(), "{name}: the program draws it: {}", stderr(&o));
    }
}

/// Issue 54, small: a refused value is said back compactly (1e300, not its 301 digits).
#[test]
fn an_out_of_range_value_is_said_compactly() {
    let dir = folder("1e300");
    let scene = dir.join("s.toml");
    std::fs::write(&scene, "name = \"big\"\n[material]\npreset = \"gold\"\nshininess = 1e300\n").unwrap();
    let o = phonglab(&["explain", s(&scene)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("material.shininess = 1e300 is out of range") && e.len() < 300, "{e}");
}

/// Issue 54's critical hole, as a classmate plants it: a journal in an output folder
/// naming the student's files as the old set and a file elsewhere as the new, with a
/// staging "folder" that is a link to that elsewhere. Every command that writes a set
/// leaves all of it as it was, writes its set, and says what it left alone.
#[test]
#[cfg_attr(windows, ignore = "a symbolic link cannot be made by the tests on Windows (a privilege) or Wine")]
fn a_planted_journal_deletes_and_moves_nothing_for_any_command() {
    let root = folder("planted");
    let plant = |dir: &Path, other: &Path| {
        std::fs::create_dir_all(dir).unwrap();
        std::fs::create_dir_all(other).unwrap();
        std::fs::write(other.join("thesis.txt"), "someone's thesis").unwrap();
        std::fs::write(dir.join("helper.h"), "// mine").unwrap();
        std::fs::write(dir.join("helper.cpp"), "// mine too").unwrap();
        let journal = r#"{"staging":".phonglab-set.9.9.tmp","new":["thesis.txt"],"old":["helper.h","helper.cpp"]}"#;
        std::fs::write(dir.join(".phonglab-set.journal"), journal).unwrap();
        common::symlink(other, dir.join(".phonglab-set.9.9.tmp")).unwrap();
    };
    let runs: [(&str, Vec<&str>); 4] = [
        ("of", vec!["export", "--to", "openframeworks", "-o"]),
        ("sheets", vec!["exercise", "--count", "1", "--out"]),
        ("wrong", vec!["exercise", "--level", "5", "--count", "1", "--out"]),
        ("cost", vec!["cost", "--quick", "--size", "16", "--object", "cylinder", "--out"]),
    ];
    for (name, args) in runs {
        let (out, other) = (root.join(name), root.join(format!("{name}-other")));
        // An openFrameworks project keeps its code in src/.
        let dir = if name == "of" { out.join("src") } else { out.clone() };
        plant(&dir, &other);
        let mut args = args.clone();
        args.push(s(&out));
        let o = phonglab(&args);
        let e = stderr(&o);
        assert!(o.status.success(), "{name}: {e}");
        assert_eq!(std::fs::read(dir.join("helper.h")).unwrap(), b"// mine", "{name}");
        assert_eq!(std::fs::read(dir.join("helper.cpp")).unwrap(), b"// mine too", "{name}");
        assert_eq!(std::fs::read(other.join("thesis.txt")).unwrap(), b"someone's thesis", "{name}");
        assert!(!dir.join("thesis.txt").exists(), "{name}: nothing moved in");
        assert!(e.contains(".phonglab-set.journal") && e.contains("was left as it is"), "{name}: {e}");
    }
}

/// A file that merely has a set's kind of name is the user's: a new set replaces the files
/// of its own names, and removes an earlier set's file it lacks only when phonglab wrote
/// that file and it is unchanged since (the folder's list of what the last set wrote).
#[test]
fn a_file_named_like_a_sets_is_kept_unless_phonglab_wrote_it() {
    let root = folder("named-like");
    // cost: `heat-notes.png` is the user's, never written by phonglab.
    let cost = root.join("cost");
    std::fs::create_dir_all(&cost).unwrap();
    std::fs::write(cost.join("heat-notes.png"), "mine").unwrap();
    std::fs::write(cost.join("heat-.png"), "mine too").unwrap();
    let o = phonglab(&["cost", "--quick", "--size", "16", "--object", "cylinder", "--out", s(&cost)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read(cost.join("heat-notes.png")).unwrap(), b"mine");
    assert_eq!(std::fs::read(cost.join("heat-.png")).unwrap(), b"mine too");
    // exercise: a set of three, then one; the user's exercise-99.md stays, the earlier set's
    // exercise-02.md goes (phonglab wrote it), exercise-03.md stays (the user changed it).
    let sheets = root.join("sheets");
    std::fs::create_dir_all(&sheets).unwrap();
    std::fs::write(sheets.join("exercise-99.md"), "my notes").unwrap();
    let o = phonglab(&["exercise", "--count", "3", "--out", s(&sheets)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(sheets.join("exercise-02.md").exists() && sheets.join("exercise-03.md").exists());
    std::fs::write(sheets.join("exercise-03.md"), "my answers").unwrap();
    let o = phonglab(&["exercise", "--count", "1", "--out", s(&sheets)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read(sheets.join("exercise-99.md")).unwrap(), b"my notes");
    assert!(!sheets.join("exercise-02.md").exists(), "phonglab's own earlier file goes");
    assert_eq!(std::fs::read(sheets.join("exercise-03.md")).unwrap(), b"my answers");
    assert!(sheets.join("exercise-01.md").exists());
}

/// A set's folder planted as a link (an openFrameworks project's `src` pointing elsewhere)
/// is refused before anything is written: nothing lands outside the folder named.
#[test]
#[cfg_attr(windows, ignore = "a symbolic link cannot be made by the tests on Windows (a privilege) or Wine")]
fn a_sets_folder_that_is_a_link_is_refused_and_nothing_is_written_through_it() {
    let root = folder("src-link");
    let (other, project) = (root.join("other"), root.join("a"));
    std::fs::create_dir_all(&other).unwrap();
    std::fs::create_dir_all(&project).unwrap();
    std::fs::write(other.join("ofApp.h"), "old").unwrap();
    common::symlink("../other", project.join("src")).unwrap();
    let o = phonglab(&["export", "--to", "openframeworks", "-o", s(&project)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("link"), "{}", stderr(&o));
    assert_eq!(std::fs::read(other.join("ofApp.h")).unwrap(), b"old");
    let mut names: Vec<String> =
        std::fs::read_dir(&other).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["ofApp.h"]);
}

/// `screenshot`'s success line writes the file's name visibly, as every command does.
#[test]
fn screenshots_line_writes_the_name_visibly() {
    let dir = folder("screenshot-name");
    let out = dir.join("e\u{1b}]0;PWN\u{7}\u{1b}[31m\u{202e}x.png");
    let o = phonglab(&["screenshot", "--size", "320x200", "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!holds_control(&o.stderr), "{:?}", stderr(&o));
    assert!(stderr(&o).contains("\\u{1B}]0;PWN\\u{7}"), "{}", stderr(&o));
}
