//! Planted files: journals, staging folders and links that phonglab did not write, put in
//! a folder a set is written into, never make it delete, move or change a file.

// The property test and the tests of links plant symbolic links (Unix only): their helpers
// are unused on Windows.
#![cfg_attr(not(unix), allow(dead_code, unused_imports))]

use std::path::{Path, PathBuf};

use proptest::prelude::*;

use super::*;
use crate::io::atomic_write::tests::temp_dir;
use crate::io::file_set::{FileSet, recover, write_set};

/// What a file is, for a user: a link's target, a file's bytes, or "a folder".
#[derive(Debug, PartialEq, Eq)]
enum Seen {
    Link(PathBuf),
    File(Vec<u8>),
    Folder,
}

/// Every file, link and folder under `dir` (its folders walked, links not followed).
fn everything(dir: &Path) -> Vec<(PathBuf, Seen)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let p = e.path();
            let t = std::fs::symlink_metadata(&p).unwrap().file_type();
            let seen = if t.is_symlink() {
                Seen::Link(std::fs::read_link(&p).unwrap())
            } else if t.is_dir() {
                stack.push(p.clone());
                Seen::Folder
            } else {
                Seen::File(std::fs::read(&p).unwrap())
            };
            out.push((p, seen));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// Every file and link that was under `dir` before is there after, unchanged.
fn untouched(before: &[(PathBuf, Seen)], dir: &Path, why: &str) {
    let after = everything(dir);
    for (p, seen) in before.iter().filter(|(_, s)| *s != Seen::Folder) {
        let now = after.iter().find(|(q, _)| q == p).map(|(_, s)| s);
        assert_eq!(now, Some(seen), "{why}: {} was changed, moved or removed", p.display());
    }
}

fn of_set() -> FileSet {
    let mut s = FileSet::default();
    s.add("ofApp.h", "// new h");
    s.add("ofApp.cpp", "// new cpp");
    s.add("main.cpp", "// new main");
    s
}

fn names_of(set: &FileSet) -> impl Fn(&str) -> bool + '_ {
    |n| set.files.iter().any(|(m, _)| m == n)
}

/// Issue 54's attack: a journal of the old form naming the student's files as the old set
/// and a file elsewhere as the new, with a staging "folder" that is a link to elsewhere.
#[test]
#[cfg(unix)]
fn a_planted_journal_and_staging_link_delete_and_move_nothing() {
    let other = temp_dir("planted-other");
    std::fs::write(other.join("thesis.txt"), "someone's thesis").unwrap();
    let dir = temp_dir("planted-src");
    std::fs::write(dir.join("helper.h"), "// the student's helper").unwrap();
    std::fs::write(dir.join("helper.cpp"), "// the student's helper code").unwrap();
    std::fs::write(
        dir.join(JOURNAL),
        r#"{"staging":".phonglab-set.9.9.tmp","new":["thesis.txt"],"old":["helper.h","helper.cpp"]}"#,
    )
    .unwrap();
    std::os::unix::fs::symlink(&other, dir.join(".phonglab-set.9.9.tmp")).unwrap();
    let (before, before_other) = (everything(&dir), everything(&other));
    let set = of_set();
    let notices = write_set(&dir, &set, names_of(&set)).unwrap();
    untouched(&before, &dir, "the folder");
    untouched(&before_other, &other, "the other folder");
    assert!(!dir.join("thesis.txt").exists(), "nothing moved in");
    assert_eq!(std::fs::read(dir.join("ofApp.h")).unwrap(), b"// new h", "the set is written");
    let said = notices.join("\n");
    assert!(said.contains(JOURNAL) && said.contains(".phonglab-set.9.9.tmp"), "{said}");
    assert!(said.contains("left as it is"), "{said}");
}

/// A journal of the new form, planted with its staging folder: it names the student's
/// file with its true size and hash (its contents were known), but not the identity the
/// unpacked folder got, so nothing it names is touched.
#[test]
fn a_planted_journal_with_the_right_hashes_is_still_not_phonglabs() {
    let dir = temp_dir("planted-hashes");
    std::fs::write(dir.join("main.cpp"), "// a well-known main.cpp").unwrap();
    let staging = dir.join(".phonglab-set.9.9.tmp");
    std::fs::create_dir(&staging).unwrap();
    std::fs::write(staging.join("thesis.txt"), "moved in?").unwrap();
    let mut old = entry_of(&dir, "main.cpp").unwrap();
    let mut new = entry_of(&staging, "thesis.txt").unwrap();
    // What a planter cannot know: the identities the files get when they are unpacked.
    old.id.ino ^= 1;
    new.id.ino ^= 1;
    let j = Journal { staging: Identity { dev: 1, ino: 2, born: None }, decided: true, new: vec![new], old: vec![old] };
    std::fs::write(staging.join(JOURNAL), serde_json::to_vec(&j).unwrap()).unwrap();
    let before = everything(&dir);
    let notices = recover(&dir).unwrap();
    untouched(&before, &dir, "recovery");
    assert!(notices.len() == 1 && notices[0].contains("not the folder"), "{notices:?}");
}

/// A journal phonglab wrote for another staging folder (the staged file and the old one
/// named truly): it names that folder's identity, not this one's, so recovery moves
/// nothing. The same journal naming this folder's identity is finished: only the identity
/// refused it. (Windows: the volume's serial number and the file index; the folder's
/// creation time alone, under Wine its last write time, did not hold as files were staged.)
#[test]
fn a_journal_naming_another_folders_identity_is_refused_and_its_own_finished() {
    let dir = temp_dir("other-identity");
    std::fs::write(dir.join("main.cpp"), "// the student's main").unwrap();
    let other = temp_dir("other-identity-elsewhere").join(".phonglab-set.1.0.tmp");
    std::fs::create_dir(&other).unwrap();
    let (_, there) = Identity::at(&other).unwrap();
    let staging = dir.join(".phonglab-set.1.0.tmp");
    std::fs::create_dir(&staging).unwrap();
    let (_, here) = Identity::at(&staging).unwrap();
    assert_ne!(here, there, "two folders, two identities");
    let held = HeldDir::open(&staging).unwrap();
    let new = stage(&held, "main.cpp", b"// the new main").unwrap();
    let old = entry_of(&dir, "main.cpp").unwrap();
    let journal =
        |staging_id| Journal { staging: staging_id, decided: true, new: vec![new.clone()], old: vec![old.clone()] };
    write_journal(&held, &journal(there), false).unwrap();
    drop(held);
    let before = everything(&dir);
    let notices = recover(&dir).unwrap();
    untouched(&before, &dir, "recovery");
    assert!(notices.len() == 1 && notices[0].contains("not the folder"), "{notices:?}");
    write_journal(&HeldDir::open(&staging).unwrap(), &journal(here), false).unwrap();
    assert_eq!(recover(&dir).unwrap(), Vec::<String>::new());
    assert_eq!(std::fs::read(dir.join("main.cpp")).unwrap(), b"// the new main");
    assert!(!staging.exists(), "the staging folder removed");
}

/// A journal phonglab really wrote, whose old file was changed by its owner after the
/// writer died: that file is not replaced, and the staging folder keeps the new one.
#[test]
fn a_file_changed_since_the_journal_is_not_replaced() {
    let dir = temp_dir("changed-since");
    std::fs::write(dir.join("a.md"), "old").unwrap();
    let staging = dir.join(".phonglab-set.1.0.tmp");
    std::fs::create_dir(&staging).unwrap();
    let (_, here) = Identity::at(&staging).unwrap();
    let held = HeldDir::open(&staging).unwrap();
    let new = stage(&held, "a.md", b"new").unwrap();
    let old = entry_of(&dir, "a.md").unwrap();
    write_journal(&held, &Journal { staging: here, decided: true, new: vec![new], old: vec![old] }, false).unwrap();
    drop(held);
    std::fs::write(dir.join("a.md"), "old, edited by its owner").unwrap();
    let notices = recover(&dir).unwrap();
    assert_eq!(std::fs::read(dir.join("a.md")).unwrap(), b"old, edited by its owner");
    assert_eq!(std::fs::read(staging.join("a.md")).unwrap(), b"new", "kept where it was");
    assert!(notices.len() == 1 && notices[0].contains("a.md"), "{notices:?}");
}

/// One planted thing in the folder a set is written into.
#[derive(Clone, Debug)]
enum Planted {
    /// A file of the user's, with a name drawn from phonglab's own and others.
    File(String, Vec<u8>),
    /// A link named like a staging folder, to the folder outside.
    Link(String),
    /// A folder named like a staging folder, holding a journal and files.
    Staging { name: String, journal: PlantedJournal, files: Vec<(String, Vec<u8>)>, aside: bool },
    /// A journal of the old form in the folder itself.
    LooseJournal(PlantedJournal),
    /// The list of what phonglab wrote, as a link to a file outside (or to nothing there).
    ListLink(bool),
}

/// A journal's contents, from noise to one of phonglab's form naming real files.
#[derive(Clone, Debug)]
enum PlantedJournal {
    Noise(Vec<u8>),
    /// Names (of the folder's files, the set's, the staging's, or anything), sizes and
    /// hashes the true ones or not, decided or not; the identities guessed.
    Shaped {
        decided: bool,
        new: Vec<String>,
        old: Vec<String>,
        true_hashes: bool,
        guess: u64,
    },
}

fn name() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("helper.h".to_string()),
        Just("notes.md".to_string()),
        Just("ofApp.h".to_string()),
        Just("main.cpp".to_string()),
        Just(JOURNAL.to_string()),
        Just(ASIDE.to_string()),
        Just(".phonglab-set.9.9.tmp".to_string()),
        Just("../outside/kept.txt".to_string()),
        "[a-z.]{1,8}",
        "\\.phonglab-set\\.[0-9]{1,3}\\.[0-9]\\.tmp",
    ]
}

fn journal() -> impl Strategy<Value = PlantedJournal> {
    prop_oneof![
        proptest::collection::vec(any::<u8>(), 0..64).prop_map(PlantedJournal::Noise),
        (
            any::<bool>(),
            proptest::collection::vec(name(), 0..4),
            proptest::collection::vec(name(), 0..4),
            any::<bool>(),
            any::<u64>()
        )
            .prop_map(|(decided, new, old, true_hashes, guess)| PlantedJournal::Shaped {
                decided,
                new,
                old,
                true_hashes,
                guess
            }),
    ]
}

fn planted() -> impl Strategy<Value = Planted> {
    let bytes = proptest::collection::vec(any::<u8>(), 0..32);
    prop_oneof![
        (name(), bytes.clone()).prop_map(|(n, b)| Planted::File(n, b)),
        "\\.phonglab-set\\.[0-9]{1,3}\\.[0-9]\\.tmp".prop_map(Planted::Link),
        (
            "\\.phonglab-set\\.[0-9]{1,3}\\.[0-9]\\.tmp",
            journal(),
            proptest::collection::vec((name(), bytes), 0..3),
            any::<bool>()
        )
            .prop_map(|(name, journal, files, aside)| Planted::Staging { name, journal, files, aside }),
        journal().prop_map(Planted::LooseJournal),
        any::<bool>().prop_map(Planted::ListLink),
    ]
}

/// An entry for `name` as a planter writes it: the file's true size and hash where it
/// exists in `dir` and `true_hashes`, a guessed identity always.
fn planted_entry(dir: &Path, name: &str, true_hashes: bool, guess: u64) -> Entry {
    let id = Identity { dev: guess, ino: guess.rotate_left(7), born: None };
    match std::fs::read(dir.join(name)) {
        Ok(b) if true_hashes => Entry { name: name.into(), size: b.len() as u64, hash: hash_bytes(&b), id },
        _ => Entry { name: name.into(), size: guess % 64, hash: format!("{guess:032x}"), id },
    }
}

fn journal_bytes(dir: &Path, j: &PlantedJournal, old_form: bool) -> Vec<u8> {
    match j {
        PlantedJournal::Noise(b) => b.clone(),
        PlantedJournal::Shaped { new, old, .. } if old_form => {
            serde_json::to_vec(&serde_json::json!({"staging": ".phonglab-set.9.9.tmp", "new": new, "old": old}))
                .unwrap()
        }
        PlantedJournal::Shaped { decided, new, old, true_hashes, guess } => {
            let entries =
                |names: &[String]| names.iter().map(|n| planted_entry(dir, n, *true_hashes, *guess)).collect();
            let staging = Identity { dev: *guess, ino: guess.rotate_left(3), born: Some((*guess, 0)) };
            serde_json::to_vec(&Journal { staging, decided: *decided, new: entries(new), old: entries(old) }).unwrap()
        }
    }
}

/// Plants `things` in `dir` (the folder outside is `outside`); what could not be made (a
/// name taken twice, a name with a folder in it) is skipped.
#[cfg(unix)]
fn plant(dir: &Path, outside: &Path, things: &[Planted]) {
    let free = |p: &Path| std::fs::symlink_metadata(p).is_err() && p.parent() == Some(dir);
    for thing in things {
        match thing {
            Planted::File(n, b) if free(&dir.join(n)) => std::fs::write(dir.join(n), b).unwrap(),
            Planted::Link(n) if free(&dir.join(n)) => std::os::unix::fs::symlink(outside, dir.join(n)).unwrap(),
            Planted::Staging { name, journal, files, aside } if free(&dir.join(name)) => {
                let s = dir.join(name);
                std::fs::create_dir(&s).unwrap();
                for (n, b) in files.iter().filter(|(n, _)| !n.contains('/') && n != JOURNAL && n != ASIDE) {
                    let _ = std::fs::write(s.join(n), b);
                }
                if *aside {
                    std::fs::create_dir_all(s.join(ASIDE)).unwrap();
                    std::fs::write(s.join(ASIDE).join("helper.h"), "aside").unwrap();
                }
                std::fs::write(s.join(JOURNAL), journal_bytes(dir, journal, false)).unwrap();
            }
            Planted::ListLink(dangling) if free(&dir.join(WRITTEN)) => {
                let target = outside.join(if *dangling { "made.txt" } else { "kept.txt" });
                std::os::unix::fs::symlink(target, dir.join(WRITTEN)).unwrap();
            }
            Planted::LooseJournal(j) if free(&dir.join(JOURNAL)) => {
                std::fs::write(dir.join(JOURNAL), journal_bytes(dir, j, true)).unwrap();
            }
            _ => {}
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Random journals (noise, or phonglab's form naming the folder's own files with their
    /// true sizes and hashes), staging folders and links to a folder outside, and files
    /// with phonglab's names, planted among the user's files: writing a set and recovering
    /// never deletes, moves or changes any of them, nor anything outside.
    #[test]
    #[cfg(unix)]
    fn planted_journals_staging_and_links_never_cost_a_file(things in proptest::collection::vec(planted(), 1..8)) {
        let root = temp_dir("planted-prop");
        let (dir, outside) = (root.join("src"), root.join("outside"));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::create_dir_all(&outside).unwrap();
        std::fs::write(outside.join("kept.txt"), "outside").unwrap();
        std::fs::write(dir.join("helper.h"), "// the student's").unwrap();
        plant(&dir, &outside, &things);
        // The set's own names are the user's to replace: planted files there are not kept.
        let set = of_set();
        for (n, _) in &set.files {
            if std::fs::symlink_metadata(dir.join(n)).is_ok_and(|m| m.is_file()) {
                std::fs::remove_file(dir.join(n)).unwrap();
            }
        }
        let (before, before_outside) = (everything(&dir), everything(&outside));
        recover(&dir).unwrap();
        untouched(&before, &dir, "recovery");
        match write_set(&dir, &set, names_of(&set)) {
            Ok(_) => {
                for (n, b) in &set.files {
                    prop_assert_eq!(&std::fs::read(dir.join(n)).unwrap(), b);
                }
            }
            // Refused: a planted link or folder holds one of the set's names, or the list's.
            Err(e) => prop_assert!(e.to_string().contains("not a regular file") || e.to_string().contains(WRITTEN), "{}", e),
        }
        prop_assert!(!outside.join("made.txt").exists(), "nothing made through a link");
        untouched(&before, &dir, "a set written");
        untouched(&before_outside, &outside, "outside");
    }
}

/// Issue 59, the hostile's review (F1, F3): a staging folder swapped for a link to another
/// folder, the clean-up of a set that failed (`throw_away`) or the recovery then removed
/// every regular file in the folder the link led to (Linux), or that folder itself when
/// empty (Wine). A link at a staging folder's name is never held as one (so the recovery
/// leaves it, and every file it leads to); and a staging folder held, then renamed and
/// replaced by such a link (fix59x: the check-then-act gap the path's checks left), is
/// still the one thrown away: every removal goes through its handle, nothing in the folder
/// the link leads to is touched.
#[test]
#[cfg(any(unix, windows))]
fn a_staging_folder_swapped_for_a_link_leaves_the_folder_it_leads_to_whole() {
    let root = crate::io::atomic_write::tests::fresh_dir("staging-link");
    let (dir, outside) = (root.join("set"), root.join("outside"));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::create_dir_all(outside.join(ASIDE)).unwrap();
    for name in ["marks-1.txt", "marks-2.txt", JOURNAL, STAGED] {
        std::fs::write(outside.join(name), "the teacher's").unwrap();
    }
    let staging = dir.join(format!(".{STAGING}.77.1.tmp"));
    if !crate::io::atomic_write::tests::plant_link(&outside, &staging) {
        eprintln!("no symbolic link can be made here: nothing to test");
        return;
    }
    assert!(HeldDir::open(&staging).is_err(), "a link at a staging folder's name is not held as a folder");
    let _ = recover(&dir);
    let whole = |why: &str| {
        for name in ["marks-1.txt", "marks-2.txt", JOURNAL, STAGED] {
            assert_eq!(
                std::fs::read(outside.join(name)).unwrap(),
                b"the teacher's",
                "{why}: {name} removed through the link"
            );
        }
        assert!(outside.join(ASIDE).is_dir(), "{why}: the empty folder the link led to was removed");
    };
    whole("recovery");
    // A real staging folder, held and staged into, then renamed away and replaced by the
    // link (Unix; Windows refuses the rename of a folder held without sharing deletion).
    // (Another name: Wine removes a Unix link to a folder by removing the folder.)
    let staging = dir.join(format!(".{STAGING}.77.2.tmp"));
    std::fs::create_dir(&staging).unwrap();
    let parent = HeldDir::open(&dir).unwrap();
    let held = parent.open_dir(staging.file_name().unwrap()).unwrap();
    stage(&held, "marks-1.txt", b"staged").unwrap();
    held.create_dir(std::ffi::OsStr::new(ASIDE)).unwrap();
    let away = dir.join(".away");
    let moved = std::fs::rename(&staging, &away).is_ok();
    assert_eq!(moved, cfg!(unix), "a folder held is renamed on Unix only");
    if moved {
        assert!(crate::io::atomic_write::tests::plant_link(&outside, &staging));
    }
    assert!(throw_away(&parent, held), "its own staged file, aside folder and records removed through its handle");
    whole("a staging folder swapped for a link after it was held");
    assert!(!away.exists(), "the staging folder removed at the name it was given");
}

/// Makes the record or folder at `path` not this user's alone, as a classmate's forgery
/// in a shared folder is: writable by others (`others`), or, where the tests run as root,
/// owned by `nobody` (65534).
#[cfg(unix)]
fn not_mine(path: &Path, others: bool) {
    use std::os::unix::fs::PermissionsExt;
    if others {
        let mode = std::fs::symlink_metadata(path).unwrap().permissions().mode();
        std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode | 0o002)).unwrap();
    } else {
        std::os::unix::fs::chown(path, Some(65_534), Some(65_534)).unwrap();
    }
}

/// May this process give a file away (`chown`: root)?
#[cfg(unix)]
fn can_give_away() -> bool {
    // SAFETY: geteuid only reads the process's user.
    (unsafe { libc::geteuid() }) == 0
}

/// Issue 59, round 2 (p20, p21): a list of what phonglab wrote, in phonglab's exact form
/// (the identity and SipHash of the teacher's own `exercise-07.md`, which anyone can
/// compute), planted by a classmate where the teacher writes sets. It is not the teacher's
/// alone, so it is not trusted: the set is refused in words naming it, and the teacher's
/// files and the list are left as they are. (Before: `exercise-07.md` deleted, rc 0.)
#[test]
#[cfg(unix)]
fn a_forged_list_of_what_phonglab_wrote_is_not_trusted_when_not_this_users_alone() {
    for others in [true, false] {
        if !others && !can_give_away() {
            continue;
        }
        let dir = temp_dir(&format!("forged-written-{others}"));
        std::fs::write(dir.join("exercise-01.md"), "# Exercise 1 (my own version)").unwrap();
        std::fs::write(dir.join("exercise-07.md"), "# Exercise 7 (mine)").unwrap();
        let forged = vec![entry_of(&dir, "exercise-01.md").unwrap(), entry_of(&dir, "exercise-07.md").unwrap()];
        std::fs::write(dir.join(WRITTEN), serde_json::to_vec(&forged).unwrap()).unwrap();
        not_mine(&dir.join(WRITTEN), others);
        let before = everything(&dir);
        let mut set = FileSet::default();
        set.add("exercise-01.md", "# Exercise 1");
        let e = write_set(&dir, &set, |n| n.starts_with("exercise-")).unwrap_err().to_string();
        untouched(&before, &dir, "a forged list");
        assert!(e.contains(WRITTEN) && e.contains("not this user's alone"), "{e}");
        assert!(e.contains("Nothing was written, moved or removed"), "{e}");
    }
}

/// Issue 59, round 2 (p23 B, D): a classmate's own staging folder with a journal in
/// phonglab's exact form, decided, naming the teacher's `key.md` truly as the old set and
/// the classmate's file as the new one: not this user's alone (the journal, or the folder),
/// so the recovery leaves it and every file as they are, and says why. The same folder and
/// journal made by this user are finished: only the owner refused them.
#[test]
#[cfg(unix)]
fn a_forged_journal_or_staging_folder_not_this_users_alone_is_left() {
    for (what, others) in [("journal", true), ("folder", true), ("journal", false), ("folder", false)] {
        if !others && !can_give_away() {
            continue;
        }
        let dir = temp_dir(&format!("forged-journal-{what}-{others}"));
        std::fs::write(dir.join("key.md"), "the teacher's key").unwrap();
        let staging = dir.join(".phonglab-set.99999.1.tmp");
        std::fs::create_dir(&staging).unwrap();
        let (_, here) = Identity::at(&staging).unwrap();
        let held = HeldDir::open(&staging).unwrap();
        let new = stage(&held, "key.md", b"the classmate's key").unwrap();
        let old = entry_of(&dir, "key.md").unwrap();
        let j = Journal { staging: here, decided: true, new: vec![new], old: vec![old] };
        write_journal(&held, &j, false).unwrap();
        drop(held);
        not_mine(&if what == "journal" { staging.join(JOURNAL) } else { staging.clone() }, others);
        let before = everything(&dir);
        let notices = recover(&dir).unwrap();
        untouched(&before, &dir, "a forged journal");
        assert_eq!(std::fs::read(dir.join("key.md")).unwrap(), b"the teacher's key");
        assert!(
            notices.len() == 1 && notices[0].contains(".phonglab-set.99999.1.tmp") && notices[0].contains("alone"),
            "{what}: {notices:?}"
        );
    }
}

/// Is the file or folder at `path` this user's alone ([`crate::platform::os::is_this_users_alone`])?
#[cfg(windows)]
fn alone(path: &Path) -> bool {
    use std::os::windows::fs::OpenOptionsExt;
    let f = std::fs::File::options().read(true).custom_flags(0x0200_0000).open(path).unwrap();
    crate::platform::os::is_this_users_alone(&f)
}

/// Issue 59, round 3 (p31, Wine 8): a teacher's umask 000 on a lab share made her own list
/// of what phonglab wrote writable by everyone (Wine maps the Unix mode to the DACL); a
/// classmate rewrote it in place in phonglab's exact form, naming her own `exercise-07.md`,
/// and the next set deleted it (Windows asked only the owner). The list phonglab writes is
/// now this user's alone (an owner-only descriptor) and trusted; one others may write is
/// not: the set is refused in words, and every file is left as it is.
#[test]
#[cfg(windows)]
fn a_list_of_what_phonglab_wrote_that_others_may_write_is_not_trusted_and_its_own_is() {
    let dir = temp_dir("written-others-may-write");
    let mut set = FileSet::default();
    set.add("exercise-01.md", "# Exercise 1");
    set.add("exercise-02.md", "# Exercise 2");
    write_set(&dir, &set, |n| n.starts_with("exercise-")).unwrap();
    assert!(alone(&dir.join(WRITTEN)), "the list phonglab writes is this user's alone");
    assert!(staging_made_alone(&dir), "a working folder phonglab makes is this user's alone");
    check_records(&dir).unwrap();
    std::fs::write(dir.join("exercise-07.md"), "# Exercise 7 (mine)").unwrap();
    let forged: Vec<Entry> =
        ["exercise-01.md", "exercise-02.md", "exercise-07.md"].iter().map(|n| entry_of(&dir, n).unwrap()).collect();
    // Rewritten in place: the owner stays this user; then everyone may write it.
    std::fs::write(dir.join(WRITTEN), serde_json::to_vec(&forged).unwrap()).unwrap();
    crate::io::atomic_write::tests::everyone_may_write(&dir.join(WRITTEN));
    assert!(!alone(&dir.join(WRITTEN)), "a list everyone may write is not this user's alone");
    let before = everything(&dir);
    let mut next = FileSet::default();
    next.add("exercise-01.md", "# Exercise 1, again");
    let e = write_set(&dir, &next, |n| n.starts_with("exercise-")).unwrap_err().to_string();
    untouched(&before, &dir, "a list others may write");
    assert!(e.contains(WRITTEN) && e.contains("others may write it"), "{e}");
    // The same list as phonglab writes it (this user's alone) is trusted: the next set
    // replaces the one the list names, and leaves the teacher's file.
    std::fs::remove_file(dir.join(WRITTEN)).unwrap();
    write_set(&dir, &set, |n| n.starts_with("exercise-")).unwrap();
    write_set(&dir, &next, |n| n.starts_with("exercise-")).unwrap();
    assert!(!dir.join("exercise-02.md").exists(), "the file phonglab's own list names is replaced");
    assert_eq!(std::fs::read(dir.join("exercise-07.md")).unwrap(), b"# Exercise 7 (mine)");
}

/// Is a working folder phonglab makes in `dir` this user's alone? (Made, asked, removed.)
#[cfg(windows)]
fn staging_made_alone(dir: &Path) -> bool {
    let parent = HeldDir::open(dir).unwrap();
    let made = parent.create_dir(std::ffi::OsStr::new(".phonglab-set.probe.tmp")).unwrap();
    let is = alone(made.path());
    parent.remove_dir(made).unwrap();
    is
}

/// Issue 59, round 3 (p32, p35, Wine 8): a stopped writer's staging folder and journal,
/// the teacher's own, that everyone may write (umask 000 before phonglab made them its
/// own): a classmate rewrote the journal in place as a decided one, and the recovery
/// deleted or replaced the teacher's files. Either one that others may write is left by
/// the recovery, with every file, and said; the same ones as phonglab makes them (this
/// user's alone) are finished.
#[test]
#[cfg(windows)]
fn a_journal_or_staging_folder_others_may_write_is_left_and_its_own_is_finished() {
    for what in ["journal", "folder", "neither"] {
        let dir = temp_dir(&format!("journal-others-may-write-{what}"));
        std::fs::write(dir.join("key.md"), "the teacher's key").unwrap();
        let parent = HeldDir::open(&dir).unwrap();
        let held = parent.create_dir(std::ffi::OsStr::new(".phonglab-set.99999.1.tmp")).unwrap();
        let staging = held.path().to_path_buf();
        let (_, here) = Identity::of_file(held.handle()).unwrap();
        let new = stage(&held, "key.md", b"the classmate's key").unwrap();
        let old = entry_of(&dir, "key.md").unwrap();
        let j = Journal { staging: here, decided: true, new: vec![new], old: vec![old] };
        write_journal(&held, &j, false).unwrap();
        assert!(alone(&staging.join(JOURNAL)) && alone(&staging), "phonglab's own are this user's alone");
        drop((held, parent));
        match what {
            "journal" => crate::io::atomic_write::tests::everyone_may_write(&staging.join(JOURNAL)),
            "folder" => crate::io::atomic_write::tests::everyone_may_write(&staging),
            _ => {}
        }
        let before = everything(&dir);
        let notices = recover(&dir).unwrap();
        if what == "neither" {
            assert!(notices.is_empty(), "{notices:?}");
            assert_eq!(std::fs::read(dir.join("key.md")).unwrap(), b"the classmate's key", "its own is finished");
            continue;
        }
        untouched(&before, &dir, "a journal others may write");
        assert_eq!(std::fs::read(dir.join("key.md")).unwrap(), b"the teacher's key");
        assert!(
            notices.len() == 1 && notices[0].contains(".phonglab-set.99999.1.tmp") && notices[0].contains("alone"),
            "{what}: {notices:?}"
        );
    }
}
