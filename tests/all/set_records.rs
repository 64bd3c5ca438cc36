//! What phonglab reads and writes in an output folder besides the set itself (issue 60, the
//! hostile re-check): its list of what it wrote (`.phonglab-set.written`) is never followed
//! through a link nor passed over when it is a pipe; a file is phonglab's by its bytes, so a
//! copied folder or a file rewritten unchanged is not "edited"; a second run says why it
//! waits; and a link above the folder named is the user's own path.

use crate::common;

use std::path::{Path, PathBuf};

use common::phonglab;

const LIST: &str = ".phonglab-set.written";

fn root(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("set-records-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `phonglab exercise` in `format` (sheets, gift, moodle-xml) with `more` into `out`, two
/// exercises unless `more` says how many.
fn exercise(format: &str, out: &Path, more: &[&str]) -> std::process::Output {
    let args = ["exercise", "--format", format, "--level", "1", "--out", s(out)];
    let count: &[&str] = if more.contains(&"--count") { &[] } else { &["--count", "2"] };
    phonglab(&[&args[..], count, more].concat())
}

fn ok(o: std::process::Output) {
    assert!(o.status.success(), "{}", stderr(&o));
}

/// The names in `dir`, sorted, links and phonglab's own records included.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// Refused, with the list named and said to be never followed, and nothing written.
#[cfg(unix)] // its tests plant links
fn refused_for_the_list(o: &std::process::Output, dir: &Path) {
    let e = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains(&format!("{}/{LIST}", dir.display())), "the list named: {e}");
    assert!(e.contains("never reads or writes through it") && e.contains("the folder is unchanged"), "{e}");
    assert_eq!(names(dir), [LIST], "nothing written beside it");
}

/// A list planted as a link, to another set's key or to nothing, is refused: the key is
/// as it was, and the link's missing target is not made (it was: the list's temporary
/// file and rename happened beside the link's target), for the sheets and both Moodle
/// formats.
#[cfg(unix)]
#[test]
fn a_planted_list_that_is_a_link_is_refused_and_nothing_is_written_through_it() {
    let r = root("link");
    let other = r.join("V2");
    ok(exercise("sheets", &other, &[]));
    let key = std::fs::read(other.join("exercise-01-key.md")).unwrap();
    let other_names = names(&other);
    for format in ["sheets", "gift", "moodle-xml"] {
        for (kind, target) in [("file", "../V2/exercise-01-key.md"), ("dangling", "../made-by-phonglab")] {
            let dir = r.join(format!("{format}-{kind}"));
            std::fs::create_dir(&dir).unwrap();
            std::os::unix::fs::symlink(target, dir.join(LIST)).unwrap();
            let o = exercise(format, &dir, &[]);
            refused_for_the_list(&o, &dir);
            assert_eq!(std::fs::read_link(dir.join(LIST)).unwrap(), Path::new(target), "still the link");
            assert_eq!(std::fs::read(other.join("exercise-01-key.md")).unwrap(), key, "{format} {kind}");
            assert_eq!(names(&other), other_names, "{format} {kind}: nothing beside the target");
            assert!(!r.join("made-by-phonglab").exists(), "{format}: a dangling link's target is not made");
        }
    }
}

/// A FIFO (or a folder) planted as the list is refused by name; it was passed over as an
/// empty list, and the next run blamed the teacher's index.md for it.
#[cfg(unix)]
#[test]
fn a_list_that_is_a_pipe_or_a_folder_is_refused_by_name() {
    let r = root("fifo");
    for format in ["sheets", "gift"] {
        let dir = r.join(format);
        std::fs::create_dir(&dir).unwrap();
        let c = std::ffi::CString::new(s(&dir.join(LIST))).unwrap();
        // SAFETY: `c` is a valid NUL-terminated path for the duration of the call.
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        refused_for_the_list(&exercise(format, &dir, &[]), &dir);
        std::fs::remove_file(dir.join(LIST)).unwrap();
        std::fs::create_dir(dir.join(LIST)).unwrap();
        refused_for_the_list(&exercise(format, &dir, &[]), &dir);
    }
    // Planted after a set was written: refused too, and the set is left as it was.
    let dir = r.join("after");
    ok(exercise("sheets", &dir, &[]));
    let before = std::fs::read(dir.join("index.md")).unwrap();
    std::fs::remove_file(dir.join(LIST)).unwrap();
    let c = std::ffi::CString::new(s(&dir.join(LIST))).unwrap();
    // SAFETY: as above.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let o = exercise("sheets", &dir, &["--seed", "9"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains(LIST) && !e.contains("index.md"), "the list named, not index.md: {e}");
    assert_eq!(std::fs::read(dir.join("index.md")).unwrap(), before);
}

/// A set's file that is a link (to another set's key) is refused, and the key is kept.
#[cfg(unix)]
#[test]
fn an_output_name_that_is_a_link_is_refused() {
    let r = root("output-link");
    let other = r.join("V2");
    ok(exercise("sheets", &other, &[]));
    let key = std::fs::read(other.join("exercise-01-key.md")).unwrap();
    for (format, name) in [("sheets", "exercise-01-key.md"), ("gift", "questions.gift.txt")] {
        let dir = r.join(format);
        std::fs::create_dir(&dir).unwrap();
        std::os::unix::fs::symlink("../V2/exercise-01-key.md", dir.join(name)).unwrap();
        let o = exercise(format, &dir, &[]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains("(a link, a folder, a device or a pipe)"), "{}", stderr(&o));
        assert_eq!(std::fs::read(other.join("exercise-01-key.md")).unwrap(), key);
        assert_eq!(names(&dir), [name]);
    }
}

/// Copies the folder `from` to `to` as `cp -a` does: new files (new identities), the same
/// bytes, phonglab's list included.
fn copy_folder(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for name in names(from) {
        std::fs::copy(from.join(&name), to.join(&name)).unwrap();
    }
}

/// A copied folder, and a file rewritten with the same bytes (a new file, as `sed -i`
/// that changes nothing makes), hold what phonglab wrote: a new set replaces them. A file
/// whose bytes changed is the teacher's, and is kept.
#[test]
fn a_copied_folder_or_a_file_rewritten_unchanged_is_still_phonglabs() {
    let r = root("copied");
    for (format, file) in [("sheets", "exercise-01-key.md"), ("gift", "questions.gift.txt")] {
        let (a, b) = (r.join(format!("{format}-a")), r.join(format!("{format}-b")));
        ok(exercise(format, &a, &[]));
        copy_folder(&a, &b);
        let old = std::fs::read(b.join(file)).unwrap();
        ok(exercise(format, &b, &["--seed", "5"]));
        assert_ne!(std::fs::read(b.join(file)).unwrap(), old, "{format}: the copy's file replaced");
        // Rewritten with the same bytes: a new file.
        let bytes = std::fs::read(a.join(file)).unwrap();
        std::fs::remove_file(a.join(file)).unwrap();
        std::fs::write(a.join(file), &bytes).unwrap();
        ok(exercise(format, &a, &["--seed", "6"]));
        assert_ne!(std::fs::read(a.join(file)).unwrap(), bytes, "{format}: the rewritten file replaced");
        // Edited: kept, and the run refused.
        let mut edited = std::fs::read(a.join(file)).unwrap();
        edited.extend_from_slice(b"\nthe teacher's note\n");
        std::fs::write(a.join(file), &edited).unwrap();
        let o = exercise(format, &a, &["--seed", "7"]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains(file), "{}", stderr(&o));
        assert_eq!(std::fs::read(a.join(file)).unwrap(), edited);
    }
}

/// A copied folder's file that the new set lacks is not phonglab's to delete (its identity
/// is not the one phonglab wrote): it stays.
#[test]
fn a_copied_folders_extra_files_are_not_deleted() {
    let r = root("copied-extra");
    let (a, b) = (r.join("a"), r.join("b"));
    ok(exercise("sheets", &a, &[]));
    copy_folder(&a, &b);
    ok(exercise("sheets", &b, &["--count", "1"]));
    assert!(b.join("exercise-02-key.md").exists(), "{:?}", names(&b));
    ok(exercise("sheets", &a, &["--count", "1"]));
    assert!(!a.join("exercise-02-key.md").exists(), "phonglab's own, unchanged: removed");
}

/// In a copied folder, the sheets rewritten keep the record of the Moodle file beside them
/// (unchanged, but no longer the file phonglab made: a copy), so the Moodle file is still
/// phonglab's to replace, as in the folder it was copied from.
#[test]
fn rewriting_one_output_of_a_copied_folder_keeps_the_others_record() {
    let r = root("copied-other");
    let (a, b) = (r.join("a"), r.join("b"));
    ok(exercise("sheets", &a, &[]));
    ok(exercise("moodle-xml", &a, &[]));
    copy_folder(&a, &b);
    let old = std::fs::read(b.join("questions.xml")).unwrap();
    ok(exercise("sheets", &b, &["--seed", "5"]));
    let list = std::fs::read_to_string(b.join(LIST)).unwrap();
    assert!(list.contains("\"questions.xml\""), "the Moodle file's entry kept: {list}");
    let o = exercise("moodle-xml", &b, &["--seed", "5"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("not written by phonglab"), "{}", stderr(&o));
    assert_ne!(std::fs::read(b.join("questions.xml")).unwrap(), old, "the copy's Moodle file replaced");
    assert!(b.join("exercise-02-key.md").exists(), "the sheets stay: {:?}", names(&b));
}

/// A second run into a folder another phonglab is writing into (here: its lock held)
/// says so once, in the user's language, then writes when the lock is let go.
#[cfg(unix)]
#[test]
fn a_run_that_waits_for_the_folders_lock_says_so_once() {
    use std::io::BufRead as _;
    let r = root("lock");
    let dir = r.join("out");
    ok(exercise("sheets", &dir, &[]));
    for (lang, words) in
        [("en_GB.UTF-8", "another phonglab is writing into"), ("pt_PT.UTF-8", "outro phonglab está a escrever em")]
    {
        let held = std::fs::File::open(&dir).unwrap();
        held.lock().unwrap();
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .env_remove("LC_ALL")
            .env_remove("LC_MESSAGES")
            .env("LANG", lang)
            .args(["exercise", "--level", "1", "--count", "2", "--seed", "3", "--out", s(&dir)])
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let (tx, rx) = std::sync::mpsc::channel();
        let err = child.stderr.take().unwrap();
        let reader = std::thread::spawn(move || {
            for line in std::io::BufReader::new(err).lines() {
                let _ = tx.send(line.unwrap());
            }
        });
        // The first line comes while the lock is held: the run cannot have finished. (A
        // run that said nothing would wait for ever: the test gives up after 5 minutes.)
        let Ok(first) = rx.recv_timeout(std::time::Duration::from_secs(300)) else {
            let _ = child.kill();
            panic!("{lang}: nothing said while waiting for the lock");
        };
        assert!(first.contains(words) && first.contains(s(&dir)), "{first}");
        drop(held);
        reader.join().unwrap();
        let rest: Vec<String> = rx.try_iter().collect();
        assert!(child.wait().unwrap().success(), "{rest:?}");
        assert!(rest.iter().all(|l| !l.contains(words)), "said once: {rest:?}");
    }
    // Not held: nothing said about waiting.
    let o = exercise("sheets", &dir, &["--seed", "4"]);
    assert!(o.status.success() && !stderr(&o).contains("another phonglab"), "{}", stderr(&o));
}

/// The rule of docs/security.md: the folder named with `--out`, and everything phonglab
/// makes or enters inside it, is never a link (`--out linkdir` is refused, nothing lands
/// where it points); a link above it is the user's own path (a home folder that is a
/// link, macOS's `/tmp`): `--out linkdir/sub` writes into `sub` where `linkdir` leads, and
/// the folder the link names gains `sub` alone.
#[cfg(unix)]
#[test]
fn a_link_above_the_output_folder_is_the_users_path() {
    let r = root("above");
    let real = r.join("real");
    std::fs::create_dir(&real).unwrap();
    std::fs::write(real.join("notes.txt"), "mine").unwrap();
    std::os::unix::fs::symlink("real", r.join("linkdir")).unwrap();
    let o = exercise("sheets", &r.join("linkdir"), &[]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("never through a link"), "{}", stderr(&o));
    assert_eq!(names(&real), ["notes.txt"], "nothing written through the link");
    ok(exercise("sheets", &r.join("linkdir/sub"), &[]));
    assert_eq!(names(&real), ["notes.txt", "sub"]);
    assert!(real.join("sub/exercise-01-key.md").is_file() && real.join("sub/index.md").is_file());
    assert!(std::fs::symlink_metadata(r.join("linkdir")).unwrap().file_type().is_symlink(), "still a link");
}

/// fix59x: a list of what phonglab wrote that is a regular file in another form (written by
/// hand) is refused by the list's name, said not to be phonglab's and left as it is; before,
/// phonglab read it as an empty list and blamed the teacher's own earlier sheet
/// (`exercise-01.md`, which phonglab wrote) as a file it did not write.
#[test]
fn a_hand_written_list_is_said_not_to_be_phonglabs_and_left() {
    let dir = root("junk-list");
    ok(exercise("sheets", &dir, &[]));
    let junk = b"exercise-01.md\nexercise-02.md\n";
    std::fs::write(dir.join(LIST), junk).unwrap();
    let before = std::fs::read(dir.join("index.md")).unwrap();
    let o = exercise("sheets", &dir, &["--seed", "9"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains(LIST) && e.contains("not a list phonglab wrote") && e.contains("leaves it as it is"), "{e}");
    assert!(!e.contains("exercise-0") && !e.contains("index.md"), "no file of the set blamed: {e}");
    assert_eq!(std::fs::read(dir.join(LIST)).unwrap(), junk, "the list left as it is");
    assert_eq!(std::fs::read(dir.join("index.md")).unwrap(), before);
}
