//! Nothing lost: every kind of output, made to fail on purpose (a full disk after N bytes,
//! a failed sync, a failed close, a failed rename), leaves what was there before untouched,
//! and says so with a non-zero exit. No file system is mounted: the faults are injected
//! into phonglab's one way of writing files (`atomic_write`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Parser;
use phonglab::cli::{self, Cli};
use phonglab::io::atomic_write::{Fault, with_fault};

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("phonglab-lost-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Every file under `dir` (names and bytes), sorted: what a user would find there.
fn listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            let bytes = if e.path().is_file() { std::fs::read(e.path()).unwrap() } else { b"<folder>".to_vec() };
            (e.file_name().to_string_lossy().into_owned(), bytes)
        })
        // phonglab's list of what a set wrote names identities (inodes), not a user's bytes.
        .filter(|(n, _)| n != ".phonglab-set.written")
        .collect();
    v.sort();
    v
}

fn run(args: &[&str]) -> ExitCode {
    let cli = Cli::try_parse_from(std::iter::once("phonglab").chain(args.iter().copied())).unwrap();
    cli::run(cli.command.expect("a subcommand"))
}

/// The faults every output is tried with: the disk full at the first byte, in the middle of
/// the first file and later, a failed sync, a failed close, and a failed rename (for a set:
/// moving an old file aside, and moving a new one in).
fn faults(renames: u32) -> Vec<Fault> {
    let mut f =
        vec![Fault::AfterBytes(0), Fault::AfterBytes(100), Fault::AfterBytes(5000), Fault::OnSync, Fault::OnClose];
    f.extend((0..renames).map(Fault::OnRename));
    f
}

#[test]
fn a_failed_render_leaves_the_old_png_and_exits_non_zero() {
    let dir = temp_dir("render");
    let out = dir.join("out.png");
    let out_s = out.to_str().unwrap();
    assert_eq!(run(&["render", "--size", "64", "-o", out_s]), ExitCode::SUCCESS);
    let before = listing(&dir);
    assert!(before[0].1.ends_with(&[0xAE, 0x42, 0x60, 0x82]), "a whole PNG ends with IEND's CRC");
    for fault in faults(1) {
        let code = with_fault(fault, || run(&["render", "--size", "200", "-o", out_s]));
        assert_eq!(code, ExitCode::from(2), "{fault:?}");
        assert_eq!(listing(&dir), before, "{fault:?}: the old PNG, whole, and no temporary file");
    }
    assert_eq!(run(&["render", "--size", "200", "-o", out_s]), ExitCode::SUCCESS);
    assert_ne!(listing(&dir), before, "without a fault the new picture replaces it");
}

#[test]
fn a_render_into_a_missing_folder_is_refused_before_rendering() {
    let dir = temp_dir("render-dest");
    let out = dir.join("no/such/folder/out.png");
    assert_eq!(run(&["render", "--size", "64", "-o", out.to_str().unwrap()]), ExitCode::from(2));
    assert_eq!(run(&["render", "--size", "64", "-o", dir.to_str().unwrap()]), ExitCode::from(2), "a folder");
    assert!(listing(&dir).is_empty());
}

#[test]
fn a_failed_exercise_set_leaves_the_old_set_whole() {
    let dir = temp_dir("exercise");
    let out = dir.to_str().unwrap();
    std::fs::write(dir.join("notes.txt"), "the teacher's own file").unwrap();
    assert_eq!(run(&["exercise", "--seed", "1", "--count", "3", "--out", out]), ExitCode::SUCCESS);
    let before = listing(&dir);
    let names: Vec<&str> = before.iter().map(|(n, _)| n.as_str()).collect();
    assert!(
        names.contains(&"exercise-03-key.md") && names.contains(&"sheets.pdf") && names.contains(&"keys.pdf"),
        "{names:?}"
    );
    // A set of 3 has 12 files, all moved aside before the 2 new exercises' 9 move in.
    for fault in faults(21) {
        let code = with_fault(fault, || run(&["exercise", "--seed", "2", "--count", "2", "--out", out]));
        assert_eq!(code, ExitCode::from(2), "{fault:?}");
        assert_eq!(listing(&dir), before, "{fault:?}: seed 1's set, whole, and nothing else");
    }
    assert_eq!(run(&["exercise", "--seed", "2", "--count", "2", "--out", out]), ExitCode::SUCCESS);
    let after = listing(&dir);
    let names: Vec<&str> = after.iter().map(|(n, _)| n.as_str()).collect();
    assert!(
        !names.iter().any(|n| n.starts_with("exercise-03")),
        "the old set's third exercise went with it: {names:?}"
    );
    assert!(names.contains(&"notes.txt"), "other files stay");
    let index = String::from_utf8_lossy(&after.iter().find(|(n, _)| n == "index.md").unwrap().1).into_owned();
    assert!(index.contains("seed 2"), "{index}");
}

/// What a user finds in the folder: its files, without a set writer's hidden staging
/// folders and journal.
fn user_listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
    listing(dir).into_iter().filter(|(n, _)| !n.starts_with(".phonglab-set")).collect()
}

#[test]
fn an_exercise_set_killed_at_any_step_is_finished_or_undone_by_the_next_run() {
    let args = |seed: &'static str, out: &str| -> Vec<String> {
        ["exercise", "--seed", seed, "--count", "1", "--out", out]
            .iter()
            .map(std::string::ToString::to_string)
            .collect()
    };
    let dir = temp_dir("exercise-kill-sets");
    let (one, two) = (dir.join("one"), dir.join("two"));
    let run_s = |a: Vec<String>| run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(run_s(args("1", one.to_str().unwrap())), ExitCode::SUCCESS);
    assert_eq!(run_s(args("2", two.to_str().unwrap())), ExitCode::SUCCESS);
    let (old, new) = (listing(&one), listing(&two));
    let mut killed = 0;
    for n in 0.. {
        let out = temp_dir("exercise-kill");
        assert_eq!(run_s(args("1", out.to_str().unwrap())), ExitCode::SUCCESS);
        let code = with_fault(Fault::KilledAtStep(n), || run_s(args("2", out.to_str().unwrap())));
        if code == ExitCode::SUCCESS {
            break;
        }
        killed += 1;
        // The next run (of any set) finishes the swap or throws the staging away first.
        phonglab::io::file_set::recover(&out).unwrap();
        let after = listing(&out);
        assert!(
            after == old || after == new,
            "killed at step {n}: {:?}",
            after.iter().map(|f| &f.0).collect::<Vec<_>>()
        );
        assert_eq!(run_s(args("3", out.to_str().unwrap())), ExitCode::SUCCESS);
        assert_eq!(user_listing(&out), listing(&out), "killed at step {n}: nothing hidden is left");
    }
    // Staging, the 6 files (the scene, the sheet, the key, the index and the two PDFs), the
    // old set listed, the journal, 6 moves aside, 6 in, the journal removed.
    assert_eq!(killed, 22, "every step was killed once");
}

#[test]
fn a_failed_cost_report_leaves_the_old_report_whole() {
    let dir = temp_dir("cost");
    let out = dir.to_str().unwrap();
    let args = ["cost", "--quick", "--object", "cylinder", "--size", "32", "--threads", "1", "--out", out];
    assert_eq!(run(&args), ExitCode::SUCCESS);
    let before = listing(&dir);
    let names: Vec<&str> = before.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        ["cost.csv", "cost.md", "cost.png", "heat-cylinder-gouraud-32.png", "heat-cylinder-phong-32.png"]
    );
    for fault in [Fault::AfterBytes(3000), Fault::OnClose, Fault::OnRename(2), Fault::OnRename(8)] {
        let code = with_fault(fault, || run(&args));
        assert_eq!(code, ExitCode::from(2), "{fault:?}");
        assert_eq!(listing(&dir), before, "{fault:?}: the old report, whole");
    }
}

#[test]
fn a_cost_report_into_a_folder_that_cannot_be_made_is_refused_before_the_study() {
    let t = std::time::Instant::now();
    let code = run(&["cost", "--object", "sphere", "--out", "/proc/phonglab-cannot-be-here"]);
    assert_eq!(code, ExitCode::from(2));
    assert!(t.elapsed().as_secs_f64() < 5.0, "refused before the study ran ({:?})", t.elapsed());
}

#[test]
fn a_failed_scene_save_in_the_app_keeps_the_old_file() {
    let dir = temp_dir("save");
    let path = dir.join("scene.toml");
    let mut state = phonglab::app::AppState::worksheet();
    phonglab::app::shell::files::save(&mut state, &path);
    let before = listing(&dir);
    state.doc.scene.material.shininess = 3.0;
    let faults = [Fault::AfterBytes(0), Fault::AfterBytes(1000), Fault::OnSync, Fault::OnClose, Fault::OnRename(0)];
    for fault in faults {
        with_fault(fault, || phonglab::app::shell::files::save(&mut state, &path));
        let said = format!("{:?}", state.message);
        assert!(said.contains("Not saved") && said.contains("unchanged"), "{fault:?}: {said}");
        assert_eq!(listing(&dir), before, "{fault:?}");
    }
    phonglab::app::shell::files::save(&mut state, &path);
    assert!(std::fs::read_to_string(&path).unwrap().contains("shininess = 3.0"));
}

#[test]
#[cfg(unix)]
fn render_to_a_device_or_a_fifo_is_refused_at_once_and_leaves_it_as_it_was() {
    // An output is a regular file or absent: `-o fifo.png` would wait for a reader for
    // ever, and renaming a file over /dev/null would replace the device for every program.
    use std::os::unix::fs::FileTypeExt;
    let dir = temp_dir("fifo");
    let fifo = dir.join("fifo.png");
    let c = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: `c` is a valid NUL-terminated path for the duration of the call.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    for out in [fifo.as_path(), Path::new("/dev/null")] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .args(["render", "--size", "32", "-o", out.to_str().unwrap()])
            .env("LC_ALL", "C.UTF-8")
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break Some(s);
            }
            if start.elapsed().as_secs() > 60 {
                child.kill().unwrap();
                break None;
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        };
        let said = std::io::read_to_string(child.stderr.take().unwrap()).unwrap();
        assert_eq!(status.and_then(|s| s.code()), Some(2), "{out:?} refused, not waited on: {said}");
        assert!(said.contains("not a regular file"), "{said}");
    }
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "still a FIFO");
    assert!(std::fs::metadata("/dev/null").unwrap().file_type().is_char_device(), "/dev/null still a device");
}
