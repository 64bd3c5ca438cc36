//! The outputs of the commands that read students' work (`check FOLDER --report --csv`, the
//! chart beside the report, `diagnose --diff`), where a class folder unzipped from Moodle
//! may hold anything: a link at an output's name is refused, never written through; a file
//! there that phonglab did not write (another student's picture, the teacher's notes) is
//! never replaced, while phonglab's own earlier output is (a teacher's re-run works); and an
//! output inside the checked folder named like a submission is refused, so that the next
//! check never counts a phantom student.

use std::path::{Path, PathBuf};

#[cfg(unix)] // its tests of links
use crate::common;
use crate::common::TempDir as Scratch;
use crate::common::{phonglab, phonglab_in};

/// A notebook check reads (saved without outputs: listed, "not read", as a student's).
const NOTEBOOK: &str = r#"{"cells": [{"cell_type": "code", "source": ["import numpy as np\n"], "outputs": []}]}"#;

/// A class folder `cls` in `root` with the students `names`.
fn class(root: &Scratch, names: &[&str]) -> PathBuf {
    let dir = root.join("cls");
    std::fs::create_dir_all(&dir).unwrap();
    for n in names {
        std::fs::write(dir.join(n), NOTEBOOK).unwrap();
    }
    dir
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The shipped spotlight scene, copied into `root`.
fn scene(root: &Scratch) -> PathBuf {
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let to = root.join("spotlight.toml");
    std::fs::copy(from, &to).unwrap();
    to
}

/// `phonglab diagnose` of `image` (64 pixels) for `scene`, its difference image at `diff`.
fn diagnose(scene: &Path, image: &Path, diff: &Path) -> std::process::Output {
    phonglab(&["diagnose", "--scene", s(scene), "--image", s(image), "--size", "64", "--diff", s(diff)])
}

/// A student's picture of `scene`, 64 pixels, as `phonglab render` draws it.
fn picture(scene: &Path, out: &Path) {
    let o = phonglab(&["render", "--scene", s(scene), "--size", "64", "-o", s(out)]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// The files of the class as the marks list them, in order.
fn listed(csv: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(csv).unwrap();
    // The teacher's separator: `;` in Portuguese, `,` in English, as the header (in the
    // teacher's language, after a byte order mark) says.
    let sep = if text.lines().next().unwrap_or_default().contains(';') { ';' } else { ',' };
    text.lines().skip(1).map(|l| l.split(sep).next().unwrap().to_string()).collect()
}

#[test]
#[cfg(unix)] // symbolic links (Windows makes them only with a privilege)
fn a_link_at_an_output_of_check_or_diagnose_is_refused_and_its_target_kept() {
    let root = Scratch::new("work-outputs-links");
    let cls = class(&root, &["a.ipynb"]);
    let bashrc = root.join("bashrc");
    std::fs::write(&bashrc, "alias ls='ls --color'\n").unwrap();
    // A link planted in the class folder at the report's, the marks' and the picture's
    // names, to the teacher's file, and a dangling one, whose target must not be made.
    let scene = scene(&root);
    let image = root.join("student.png");
    picture(&scene, &image);
    for name in ["report.md", "marks.csv", "diff.png"] {
        for (target, made) in [("../bashrc", false), ("../made-by-phonglab", true)] {
            let link = cls.join(name);
            std::fs::remove_file(&link).ok();
            common::symlink(target, &link).unwrap();
            let o = match name {
                "report.md" => phonglab(&["check", s(&cls), "--report", s(&link)]),
                "marks.csv" => phonglab(&["check", s(&cls), "--csv", s(&link)]),
                _ => diagnose(&scene, &image, &link),
            };
            assert_eq!(o.status.code(), Some(2), "{name} -> {target}: {}", stderr(&o));
            assert!(stderr(&o).contains(&format!("{} is a link", link.display())), "{}", stderr(&o));
            assert!(stderr(&o).contains("never write"), "{}", stderr(&o));
            assert_eq!(std::fs::read_to_string(&bashrc).unwrap(), "alias ls='ls --color'\n", "{name}");
            assert!(!root.join("made-by-phonglab").exists() || !made, "{name}: a dangling link's target made");
            assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link left as it was");
        }
    }
    assert!(!cls.join("report.png").exists(), "nothing written");
    let names: Vec<_> = std::fs::read_dir(&cls).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names.len(), 4, "no temporary left: {names:?}");
}

#[test]
fn diagnose_never_replaces_another_students_picture() {
    let root = Scratch::new("work-outputs-other-student");
    let scene = scene(&root);
    let cls = root.join("cls");
    std::fs::create_dir_all(&cls).unwrap();
    let (a, b) = (cls.join("a.png"), cls.join("b.png"));
    picture(&scene, &a);
    picture(&scene, &b);
    let before = std::fs::read(&b).unwrap();
    let o = diagnose(&scene, &a, &b);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let said = stderr(&o);
    assert!(said.contains(&format!("{} is already there and phonglab did not write it", b.display())), "{said}");
    assert!(said.contains("never replace"), "{said}");
    assert_eq!(std::fs::read(&b).unwrap(), before, "b.png untouched");
    // The teacher's ordinary re-run: the difference image phonglab wrote is replaced.
    let diff = root.join("diff.png");
    for run in 0..2 {
        let o = diagnose(&scene, &a, &diff);
        assert_eq!(o.status.code(), Some(0), "run {run}: {}", stderr(&o));
        let (w, h, _) = phonglab::io::image::read_png(&diff).unwrap();
        assert_eq!((w, h), (64, 64));
    }
    // Its kind is its own: the marks of a class are not a difference image.
    let other = Scratch::new("work-outputs-other-kind");
    let cls2 = class(&other, &["a.ipynb"]);
    let marks = root.join("marks.csv");
    assert!(phonglab(&["check", s(&cls2), "--csv", s(&marks)]).status.success());
    let marks_before = std::fs::read(&marks).unwrap();
    let o = diagnose(&scene, &a, &marks);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(std::fs::read(&marks).unwrap(), marks_before);
}

#[test]
fn check_never_replaces_a_file_it_did_not_write_and_replaces_its_own() {
    let root = Scratch::new("work-outputs-not-ours");
    let cls = class(&root, &["a.ipynb", "b.ipynb"]);
    let out = root.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let (report, chart, csv) = (out.join("turma.md"), out.join("turma.png"), out.join("notas.csv"));
    let run = |lang: &str| phonglab_in(lang, &["check", s(&cls), "--report", s(&report), "--csv", s(&csv)]);
    // A teacher's run, and the same again (in another language): phonglab's own replaced.
    for lang in ["pt_PT.UTF-8", "en_GB.UTF-8", "pt_BR.UTF-8"] {
        let o = run(lang);
        assert_eq!(o.status.code(), Some(0), "{lang}: {}", stderr(&o));
        assert_eq!(listed(&csv), ["a.ipynb", "b.ipynb"]);
    }
    assert!(std::fs::read_to_string(&report).unwrap().starts_with("# Verificação da turma"));
    // A file of the teacher's own at each name: never replaced, named, exit 2.
    for (at, theirs) in [(&report, "# My notes\n"), (&csv, "name,mark\nana,18\n"), (&chart, "\u{89}PNG not ours")] {
        let before = std::fs::read(at).unwrap();
        std::fs::write(at, theirs).unwrap();
        let o = run("en_GB.UTF-8");
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains(&format!("{} is already there and phonglab did not write it", at.display())));
        assert_eq!(std::fs::read_to_string(at).unwrap(), theirs, "untouched");
        std::fs::write(at, before).unwrap();
    }
    // A report is not marks.
    let o = phonglab(&["check", s(&cls), "--csv", s(&report)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(run("en_GB.UTF-8").status.success(), "all phonglab's own again");
}

#[test]
fn an_output_named_like_a_submission_inside_the_checked_folder_is_refused() {
    let root = Scratch::new("work-outputs-phantom");
    let cls = class(&root, &["ana.ipynb", "rui.ipynb"]);
    for (flag, name, suggested) in
        [("--csv", "x.ipynb", "x.csv"), ("--report", "y.py", "y.md"), ("--csv", "Z.IPYNB", "Z.csv")]
    {
        let o = phonglab(&["check", s(&cls), flag, s(&cls.join(name))]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        let said = stderr(&o);
        assert!(said.contains("inside the checked folder") && said.contains(suggested), "{said}");
        assert!(!cls.join(name).exists(), "{name} not written");
    }
    // Through another path to the same folder too.
    let o = phonglab(&["check", s(&cls), "--csv", &format!("{}/../cls/x.ipynb", s(&cls))]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    // Other names inside the folder are allowed, and never read as submissions.
    let (marks, report) = (cls.join("marks.csv"), cls.join("report.md"));
    for _ in 0..2 {
        let o = phonglab(&["check", s(&cls), "--csv", s(&marks), "--report", s(&report)]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        assert_eq!(listed(&marks), ["ana.ipynb", "rui.ipynb"], "exactly the real students");
    }
    assert!(cls.join("report.png").exists());
    // Outside the folder, the name is the teacher's to choose.
    let o = phonglab(&["check", s(&cls), "--csv", s(&root.join("marks.ipynb"))]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
#[cfg(unix)] // a file name with controls, and symbolic links
fn the_refusals_are_said_in_portuguese_with_the_name_written_visibly() {
    let root = Scratch::new("work-outputs-words");
    let cls = class(&root, &["a.ipynb"]);
    let link = cls.join("r\u{1b}]0;x\u{7}\u{202e}.md");
    common::symlink("../elsewhere.md", &link).unwrap();
    let theirs = root.join("notas\u{1b}[31m.csv");
    std::fs::write(&theirs, "nome,nota\n").unwrap();
    let phantom = cls.join("x.ipynb");
    let cases: [(&str, &[&str], &[&str]); 6] = [
        ("pt_PT.UTF-8", &["--report", s(&link)], &["é uma ligação simbólica", "nunca escrevem"]),
        ("pt_BR.UTF-8", &["--report", s(&link)], &["é um link simbólico", "nunca escrevem"]),
        ("pt_PT.UTF-8", &["--csv", s(&theirs)], &["já existe e não foi o phonglab que o escreveu"]),
        ("pt_BR.UTF-8", &["--csv", s(&theirs)], &["já existe e não foi o phonglab que o escreveu"]),
        ("pt_PT.UTF-8", &["--csv", s(&phantom)], &["dentro da pasta verificada", "lê-lo-ia", "x.csv"]),
        ("pt_BR.UTF-8", &["--csv", s(&phantom)], &["dentro da pasta verificada", "o leria", "x.csv"]),
    ];
    for (lang, args, words) in cases {
        let o = phonglab_in(lang, &[&["check", s(&cls)][..], args].concat());
        assert_eq!(o.status.code(), Some(2), "{lang}: {}", stderr(&o));
        let said = stderr(&o);
        for w in words {
            assert!(said.contains(w), "{lang}: {w:?} in {said}");
        }
        assert!(!said.contains(['\u{1b}', '\u{7}', '\u{202e}']), "{said:?}");
    }
    let said = stderr(&phonglab(&["check", s(&cls), "--report", s(&link)]));
    assert!(said.contains("r\\u{1B}]0;x\\u{7}\\u{202E}.md is a link"), "{said}");
    assert_eq!(std::fs::read_to_string(&theirs).unwrap(), "nome,nota\n");
}

/// Issue 59 (a teacher's finding 3): `check --report --csv` said "2 submissions checked,
/// one not read: relatório.md", once per output, as if the report were the file not
/// read. The count is said once, then what was written where, once each.
#[test]
fn check_says_once_what_it_wrote_where() {
    let root = Scratch::new("work-outputs-said-once");
    let cls = class(&root, &["a.ipynb"]);
    let (report, chart, csv) = (root.join("relatório.md"), root.join("relatório.png"), root.join("notas.csv"));
    let cases: [(&str, [String; 3]); 2] = [
        (
            "en_GB.UTF-8",
            [
                "checked 0 submissions, one not read\n".into(),
                format!("report written to {} (its chart: {})\n", report.display(), chart.display()),
                format!("marks written to {}\n", csv.display()),
            ],
        ),
        (
            "pt_PT.UTF-8",
            [
                "0 trabalhos verificados, um não lido\n".into(),
                format!("relatório escrito em {} (o gráfico, em {})\n", report.display(), chart.display()),
                format!("notas escritas em {}\n", csv.display()),
            ],
        ),
    ];
    for (lang, lines) in cases {
        let o = phonglab_in(lang, &["check", s(&cls), "--report", s(&report), "--csv", s(&csv)]);
        assert_eq!(o.status.code(), Some(0), "{lang}: {}", stderr(&o));
        let said = stderr(&o);
        for line in &lines {
            assert_eq!(said.matches(line.as_str()).count(), 1, "{lang}: {line:?} once in {said}");
        }
        assert!(!said.contains("not read:") && !said.contains("não lido:"), "{lang}: {said}");
        assert!(report.is_file() && chart.is_file() && csv.is_file());
    }
}

/// Issue 59 (a teacher's finding 4): a report phonglab wrote, then given as the marks'
/// name (`--report Relatório.MD --csv relatório.md`, two files on Linux): refused, but
/// with what is true, that it is phonglab's report and not its marks, never "phonglab did
/// not write it"; nothing written, the report kept.
#[test]
fn an_output_of_another_kind_is_said_to_be_phonglabs_and_kept() {
    let root = Scratch::new("work-outputs-other-kind-said");
    let cls = class(&root, &["a.ipynb"]);
    let report = root.join("relatório.md");
    assert!(phonglab(&["check", s(&cls), "--report", s(&report)]).status.success());
    let kept = std::fs::read(&report).unwrap();
    let upper = root.join("Relatório.MD");
    let cases = [
        ("en_GB.UTF-8", "is phonglab's class report (check --report), not its marks (check --csv)", "did not write"),
        (
            "pt_PT.UTF-8",
            "é um resultado do phonglab, mas o relatório da turma (check --report), não as notas (check --csv)",
            "não foi o phonglab",
        ),
        (
            "pt_BR.UTF-8",
            "é um resultado do phonglab, mas o relatório da turma (check --report), não as notas (check --csv)",
            "não foi o phonglab",
        ),
    ];
    for (lang, true_words, untrue) in cases {
        let o = phonglab_in(lang, &["check", s(&cls), "--report", s(&upper), "--csv", s(&report)]);
        assert_eq!(o.status.code(), Some(2), "{lang}: {}", stderr(&o));
        let said = stderr(&o);
        assert!(said.contains(&report.display().to_string()) && said.contains(true_words), "{lang}: {said}");
        assert!(!said.contains(untrue), "{lang}: {said}");
        assert_eq!(std::fs::read(&report).unwrap(), kept, "{lang}: the report kept");
        assert!(!upper.exists(), "{lang}: nothing written");
    }
}

/// fix59x: the report's and the marks' names both links to one file (the teacher's) are
/// refused as links, the first said first, not as "the same file" (which would send the
/// teacher to rename one of them, still a link); the file they lead to is kept.
#[test]
#[cfg(unix)] // symbolic links
fn two_outputs_that_are_links_to_one_file_are_refused_as_links() {
    let root = Scratch::new("work-outputs-two-links");
    let cls = class(&root, &["a.ipynb"]);
    let bashrc = root.join("bashrc");
    std::fs::write(&bashrc, "alias ls='ls --color'\n").unwrap();
    let (report, marks) = (cls.join("report.md"), cls.join("marks.csv"));
    common::symlink("../bashrc", &report).unwrap();
    common::symlink("../bashrc", &marks).unwrap();
    let o = phonglab(&["check", s(&cls), "--report", s(&report), "--csv", s(&marks)]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains(&format!("{} is a link", report.display())), "{e}");
    assert!(!e.contains("the same file"), "{e}");
    assert_eq!(std::fs::read_to_string(&bashrc).unwrap(), "alias ls='ls --color'\n");
}

/// Issue 57: a teacher's line appended to the marks ("Nota do professor: Ana 18"), or a
/// "## My notes" section added to the report, was erased by the next run: the head said
/// phonglab's. Now a file is replaced only where its whole bytes are what phonglab last
/// wrote there (its record, in phonglab's data folder): an edited output, the chart beside
/// the report edited, a copy of phonglab's bytes put in its place, or an output with no
/// record is refused in words, exit 2, and nothing is written.
#[test]
#[cfg(unix)] // the outputs' identities (inodes) tell that nothing was written
fn a_teachers_note_added_to_the_marks_or_the_report_is_never_erased() {
    use std::os::unix::fs::MetadataExt;
    let root = Scratch::new("work-outputs-teachers-note");
    let cls = class(&root, &["a.ipynb"]);
    let (report, chart, csv) = (root.join("turma.md"), root.join("turma.png"), root.join("notas.csv"));
    let run_in = |data: &Path, lang: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .env("PHONGLAB_SESSION_DIR", data)
            .env_remove("LC_ALL")
            .env_remove("LC_MESSAGES")
            .env("LANG", lang)
            .args(["check", s(&cls), "--report", s(&report), "--csv", s(&csv)])
            .output()
            .unwrap()
    };
    let data = root.join("data");
    let run = |lang: &str| run_in(&data, lang);
    for again in 0..2 {
        let o = run("en_GB.UTF-8");
        assert_eq!(o.status.code(), Some(0), "run {again}: {}", stderr(&o));
    }
    let inodes = || [&report, &chart, &csv].map(|p| std::fs::metadata(p).unwrap().ino());
    let note = |at: &Path, line: &str| {
        let mut bytes = std::fs::read(at).unwrap();
        let kept = bytes.clone();
        bytes.extend_from_slice(line.as_bytes());
        std::fs::write(at, &bytes).unwrap();
        (kept, bytes)
    };
    let words = [
        ("en_GB.UTF-8", "changed since phonglab wrote it"),
        ("pt_PT.UTF-8", "foi alterado depois de o phonglab o escrever"),
        ("pt_BR.UTF-8", "foi alterado depois que o phonglab o gravou"),
    ];
    for (at, line) in [(&csv, "Nota do professor: Ana 18\n"), (&report, "\n## My notes\n\nAna: 18\n"), (&chart, "x")] {
        let (kept, edited) = note(at, line);
        let before = inodes();
        for (lang, said) in words {
            let o = run(lang);
            assert_eq!(o.status.code(), Some(2), "{lang}: {}", stderr(&o));
            let e = stderr(&o);
            assert!(e.contains(&at.display().to_string()) && e.contains(said), "{lang}: {e}");
            assert_eq!(std::fs::read(at).unwrap(), edited, "{lang}: the teacher's note kept");
            assert_eq!(inodes(), before, "{lang}: nothing written");
        }
        // The note taken out again: phonglab's own bytes, its own file: replaced.
        std::fs::write(at, &kept).unwrap();
        let o = run("en_GB.UTF-8");
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    // phonglab's bytes, but another file put in its place: not what phonglab wrote there.
    let copy = root.join("copy.csv");
    std::fs::copy(&csv, &copy).unwrap();
    std::fs::rename(&copy, &csv).unwrap();
    assert_eq!(run("en_GB.UTF-8").status.code(), Some(2));
    // No record of it (another data folder): refused, on the safe side.
    std::fs::remove_file(&csv).unwrap();
    assert!(run("en_GB.UTF-8").status.success());
    let o = run_in(&root.join("other-data"), "en_GB.UTF-8");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("phonglab has no record of writing it"), "{}", stderr(&o));
    assert!(!stderr(&o).contains("changed since"), "{}", stderr(&o));
}

/// Issue 57 round 2: the records of the outputs phonglab wrote are its alone (folder 0700,
/// records 0600), and a records folder another user can write (777) is not trusted: a
/// record there may be planted (its hash is unkeyed), so the output is refused in words,
/// and nothing is written; made this user's alone again, it is trusted again.
#[test]
#[cfg(unix)]
fn the_records_of_outputs_are_trusted_only_when_this_users_alone() {
    use std::os::unix::fs::PermissionsExt;
    let root = Scratch::new("records-own");
    let cls = class(&root, &["a.ipynb"]);
    let csv = root.join("notas.csv");
    let data = root.join("data");
    let run = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .env("PHONGLAB_SESSION_DIR", &data)
            .env("LANG", "en_GB.UTF-8")
            .env_remove("LC_ALL")
            .env_remove("LC_MESSAGES")
            .args(["check", s(&cls), "--csv", s(&csv)])
            .output()
            .unwrap()
    };
    let o = run();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let records = data.join("outputs-written");
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&records), 0o700);
    let kept: Vec<PathBuf> = std::fs::read_dir(&records).unwrap().map(|e| e.unwrap().path()).collect();
    assert_eq!(kept.len(), 1, "{kept:?}");
    assert_eq!(mode(&kept[0]), 0o600);
    assert_eq!(run().status.code(), Some(0), "its own record: replaced");
    std::fs::set_permissions(&records, std::fs::Permissions::from_mode(0o777)).unwrap();
    let before = std::fs::read(&csv).unwrap();
    let o = run();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("not this user's alone") && stderr(&o).contains("outputs-written"), "{}", stderr(&o));
    assert_eq!(std::fs::read(&csv).unwrap(), before);
    // A record another user could write (group-writable) is not trusted either.
    std::fs::set_permissions(&records, std::fs::Permissions::from_mode(0o700)).unwrap();
    std::fs::set_permissions(&kept[0], std::fs::Permissions::from_mode(0o620)).unwrap();
    assert_eq!(run().status.code(), Some(2));
    std::fs::set_permissions(&kept[0], std::fs::Permissions::from_mode(0o600)).unwrap();
    assert_eq!(run().status.code(), Some(0), "{}", stderr(&run()));
}

/// Issue 57: a data folder others can write but whose sticky bit keeps them from removing
/// or replacing what is this user's (1777, as /tmp) is used: the records folder phonglab
/// makes in it is 0700. A records folder of this user's that others can read (0755, made
/// by an older phonglab) is made 0700 when a record is kept in it.
#[test]
#[cfg(unix)]
fn a_sticky_data_folder_is_used_and_an_old_readable_records_folder_is_tightened() {
    use std::os::unix::fs::PermissionsExt;
    let root = Scratch::new("records-sticky");
    let cls = class(&root, &["a.ipynb"]);
    let csv = root.join("notas.csv");
    let data = root.join("data");
    std::fs::create_dir_all(&data).unwrap();
    std::fs::set_permissions(&data, std::fs::Permissions::from_mode(0o1777)).unwrap();
    let run = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .env("PHONGLAB_SESSION_DIR", &data)
            .env("LANG", "en_GB.UTF-8")
            .env_remove("LC_ALL")
            .env_remove("LC_MESSAGES")
            .args(["check", s(&cls), "--csv", s(&csv)])
            .output()
            .unwrap()
    };
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o7777;
    let o = run();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let records = data.join("outputs-written");
    assert_eq!(mode(&records), 0o700);
    assert_eq!(mode(&data), 0o1777, "the data folder itself is left as it is");
    std::fs::set_permissions(&records, std::fs::Permissions::from_mode(0o755)).unwrap();
    let o = run();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(mode(&records), 0o700);
}
