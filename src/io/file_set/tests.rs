//! The tests of writing a set of files as one ([`super`]).

use super::*;
use crate::io::atomic_write::tests::{FAULTS, fresh_dir, plant_link, temp_dir};
use crate::io::atomic_write::with_fault;
use crate::io::set_journal::JOURNAL;

/// The old set, written by phonglab (so its files are the next set's to replace or
/// remove), and a file of the user's.
fn old_set(dir: &Path) {
    let mut old = FileSet::default();
    for (n, b) in [("a.md", "old a"), ("b.md", "old b"), ("c.md", "old c, not in the new set")] {
        old.add(n, b);
    }
    write_set(dir, &old, |n| n.ends_with(".md")).unwrap();
    std::fs::write(dir.join("mine.txt"), "user").unwrap();
}

/// The folder as a user sees it: its files, without phonglab's own records.
fn listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
    user_files(dir)
}

fn new_set() -> FileSet {
    let mut s = FileSet::default();
    s.add("a.md", vec![b'A'; 5000]);
    s.add("b.md", "new b");
    s.add("d.md", "new d");
    s
}

/// What the folder holds for a user: its files, without the staging folders a writer
/// works with.
fn user_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    crate::io::atomic_write::tests::listing(dir).into_iter().filter(|(n, _)| !n.starts_with(".phonglab-set")).collect()
}

/// The staging folder in `dir` and its journal, if a writer left one.
fn journal_in(dir: &Path) -> Option<(std::path::PathBuf, Journal)> {
    let staging = std::fs::read_dir(dir).unwrap().flatten().map(|e| e.path()).find(|p| p.is_dir())?;
    let j = serde_json::from_slice(&std::fs::read(staging.join(JOURNAL)).ok()?).unwrap();
    Some((staging, j))
}

/// The new set is whole somewhere: each of its files, with its new bytes, in place or
/// in the staging folder.
fn new_set_is_whole(dir: &Path, staging: &Path, set: &FileSet) -> bool {
    set.files.iter().all(|(name, bytes)| {
        [staging.join(name), dir.join(name)].iter().any(|p| std::fs::read(p).ok().as_ref() == Some(bytes))
    })
}

#[test]
fn a_writer_killed_at_any_step_leaves_a_whole_set_and_the_next_run_finishes_or_cleans() {
    let belongs = |n: &str| n.ends_with(".md");
    let old_dir = temp_dir("kill-old");
    old_set(&old_dir);
    let old = listing(&old_dir);
    let new_dir = temp_dir("kill-new");
    old_set(&new_dir);
    write_set(&new_dir, &new_set(), belongs).unwrap();
    let new = listing(&new_dir);
    let mut steps = 0;
    for n in 0.. {
        let dir = temp_dir("kill");
        old_set(&dir);
        if with_fault(Fault::KilledAtStep(n), || write_set(&dir, &new_set(), belongs)).is_ok() {
            break;
        }
        steps += 1;
        // At the instant of death: the old set in place, or a journal that has decided
        // and the new set whole.
        let names = |l: &[(String, Vec<u8>)]| l.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
        match journal_in(&dir) {
            Some((staging, j)) if j.decided => {
                assert!(new_set_is_whole(&dir, &staging, &new_set()), "killed at step {n}: the set is whole");
            }
            _ => {
                let files = user_files(&dir);
                assert!(files == old || files == new, "killed at step {n}: not decided: {:?}", names(&files));
            }
        }
        // The next run recovers: exactly the old set or exactly the new one, nothing else.
        assert_eq!(recover(&dir).unwrap(), Vec::<String>::new(), "killed at step {n}: nothing left alone");
        let after = listing(&dir);
        assert!(after == old || after == new, "killed at step {n}, then recovered: {:?}", names(&after));
        // And a later set is written over it as usual.
        with_fault(Fault::KilledAtStep(n), || write_set(&dir, &new_set(), belongs)).ok();
        let mut third = FileSet::default();
        third.add("z.md", "third");
        write_set(&dir, &third, belongs).unwrap();
        let names: Vec<String> = listing(&dir).into_iter().map(|(n, _)| n).collect();
        assert_eq!(names, ["mine.txt", "z.md"], "killed twice at step {n}, then a third set");
    }
    // The journal begun, each of 3 files, the old set listed, the journal decided, 3
    // moves aside, 3 in, the old files and the journal removed: 13 places to die.
    assert_eq!(steps, 13);
}

/// Issue 59 (a teacher's finding 1): a writer stopped at any step of its swap, then a
/// DIFFERENT set written the way the commands write one (the folder held, its files
/// judged, the set written): the stopped writer's files are phonglab's, never "not
/// written by phonglab". Before the fix a stop after the swap was decided left the new
/// set in place and the list of what phonglab wrote naming the old one, and the check
/// ran before the recovery, so every later different set was refused.
#[test]
fn a_writer_stopped_at_any_step_never_blocks_a_different_set() {
    let belongs = |n: &str| n.ends_with(".md");
    let mut other = FileSet::default();
    other.add("a.md", "another set's a");
    other.add("e.md", "another set's e");
    let mut steps = 0;
    for n in 0.. {
        let dir = temp_dir("stopped-other");
        old_set(&dir);
        if with_fault(Fault::KilledAtStep(n), || write_set(&dir, &new_set(), belongs)).is_ok() {
            break;
        }
        steps += 1;
        let held = hold_folder(&dir).unwrap();
        let judged = crate::io::exercise_set::refuse_foreign(&dir, &other);
        assert!(judged.is_ok(), "stopped at step {n}: {:?}", judged.map_err(|e| e.to_string()));
        assert_eq!(write_set_held(&held, &other, belongs).unwrap(), Vec::<String>::new(), "step {n}");
        drop(held);
        let after = listing(&dir);
        let names: Vec<&str> = after.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["a.md", "e.md", "mine.txt"], "stopped at step {n}");
        assert_eq!(after[0].1, b"another set's a", "stopped at step {n}");
    }
    assert_eq!(steps, 13, "every step of the swap was tried");
}

/// Issue 59, #70: a writer killed mid-swap, then a file of the half-placed new set
/// edited by the teacher, then a smaller set: the recovery cannot place the edited
/// name (and says so), but records the new files it did place, so the smaller set
/// removes them; the folder ends with the smaller set, the edited file and the user's.
#[test]
fn a_stopped_set_with_an_edited_file_leaves_nothing_unrecorded_behind_the_next_set() {
    let belongs = |n: &str| n.ends_with(".md");
    let mut edited_once = false;
    for n in 0.. {
        let dir = temp_dir("stopped-edited");
        old_set(&dir);
        if with_fault(Fault::KilledAtStep(n), || write_set(&dir, &new_set(), belongs)).is_ok() {
            break;
        }
        // The new a.md in place while the swap is not finished: the teacher edits it.
        let placed = std::fs::read(dir.join("a.md")).is_ok_and(|b| b == vec![b'A'; 5000]);
        let unfinished = journal_in(&dir).is_some_and(|(_, j)| j.decided);
        let edited = placed && unfinished;
        if edited {
            std::fs::write(dir.join("a.md"), "the teacher's edit").unwrap();
            edited_once = true;
        }
        let mut small = FileSet::default();
        small.add("z.md", "small");
        for _ in 0..2 {
            let notices = write_set(&dir, &small, belongs).unwrap();
            assert_eq!(notices.len(), usize::from(edited), "killed at step {n}: {notices:?}");
        }
        let names: Vec<String> = listing(&dir).into_iter().map(|(n, _)| n).collect();
        let want: &[&str] = if edited { &["a.md", "mine.txt", "z.md"] } else { &["mine.txt", "z.md"] };
        assert_eq!(names, want, "killed at step {n} (edited: {edited})");
        if edited {
            assert_eq!(std::fs::read(dir.join("a.md")).unwrap(), b"the teacher's edit");
        }
    }
    assert!(edited_once, "some step leaves the new a.md in place, unfinished");
}

/// Every state a swap or its undo can be in when the process dies (each file of either
/// set in place or in the staging folder, one rename at a time), with the journal:
/// recovery gives the new set, whole.
#[test]
fn recovery_finishes_a_swap_from_every_state_it_can_be_left_in() {
    let belongs = |n: &str| n.ends_with(".md");
    let new_dir = temp_dir("states-new");
    old_set(&new_dir);
    write_set(&new_dir, &new_set(), belongs).unwrap();
    let new = listing(&new_dir);
    // a.md and b.md are in both sets: 0 = the new one in place (the old aside), 1 = the
    // new one staged and the old in place, 2 = both staged; d.md (new only) and c.md (old
    // only): in place or staged.
    for state in 0..3 * 3 * 2 * 2 {
        let (a, b, d, c) = (state % 3, state / 3 % 3, state / 9 % 2, state / 18 % 2);
        let dir = temp_dir("states");
        old_set(&dir);
        let staging = dir.join(".phonglab-set.1.0.tmp");
        std::fs::create_dir_all(staging.join(ASIDE)).unwrap();
        let (_, here) = Identity::at(&staging).unwrap();
        let mut j = Journal { staging: here, decided: true, new: Vec::new(), old: Vec::new() };
        let held = HeldDir::open(&staging).unwrap();
        for (name, bytes) in &new_set().files {
            j.new.push(stage(&held, name, bytes).unwrap());
        }
        j.old = ["a.md", "b.md", "c.md"].iter().map(|n| entry_of(&dir, n).unwrap()).collect();
        write_journal(&held, &j, false).unwrap();
        drop(held);
        let aside = |n: &str| std::fs::rename(dir.join(n), staging.join(ASIDE).join(n)).unwrap();
        let move_in = |n: &str| std::fs::rename(staging.join(n), dir.join(n)).unwrap();
        for (name, s) in [("a.md", a), ("b.md", b)] {
            match s {
                0 => {
                    aside(name);
                    move_in(name);
                }
                2 => aside(name),
                _ => {}
            }
        }
        if d == 0 {
            move_in("d.md");
        }
        if c == 1 {
            aside("c.md");
        }
        assert_eq!(recover(&dir).unwrap(), Vec::<String>::new(), "state {state}");
        assert!(listing(&dir) == new, "state {state} ({a}, {b}, {d}, {c}): the new set, whole, and nothing else");
    }
}

#[test]
fn a_set_is_written_whole_or_the_folder_is_unchanged() {
    let belongs = |n: &str| n.ends_with(".md");
    let renames = (1..6).map(Fault::OnRename);
    for fault in FAULTS.iter().copied().chain(renames) {
        let dir = temp_dir("set");
        old_set(&dir);
        let before = listing(&dir);
        let r = with_fault(fault, || write_set(&dir, &new_set(), belongs));
        assert!(r.is_err(), "{fault:?} must fail");
        assert_eq!(listing(&dir), before, "{fault:?}: the old set, untouched, and no staging left");
    }
    let dir = temp_dir("set-ok");
    old_set(&dir);
    write_set(&dir, &new_set(), belongs).unwrap();
    let after = listing(&dir);
    let names: Vec<&str> = after.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["a.md", "b.md", "d.md", "mine.txt"], "c.md went with the old set; mine.txt stays");
    assert_eq!(after[1].1, b"new b");
    assert_eq!(after[3].1, b"user");
}

#[test]
#[cfg(unix)]
fn a_link_or_a_folder_at_a_sets_name_refuses_the_set_and_nothing_moves() {
    let outside = temp_dir("set-link-outside");
    std::fs::write(outside.join("thesis.txt"), "mine").unwrap();
    let link = |p: &Path| std::os::unix::fs::symlink(outside.join("thesis.txt"), p).unwrap();
    let folder = |p: &Path| std::fs::create_dir(p).unwrap();
    for make in [&link as &dyn Fn(&Path), &folder] {
        let dir = temp_dir("set-link");
        old_set(&dir);
        std::fs::remove_file(dir.join("b.md")).unwrap();
        make(&dir.join("b.md"));
        let before = listing(&dir);
        let e = write_set(&dir, &new_set(), |n| n.ends_with(".md")).unwrap_err();
        assert!(e.to_string().contains("b.md") && e.to_string().contains("not a regular file"), "{e}");
        assert_eq!(listing(&dir), before);
        assert_eq!(std::fs::read(outside.join("thesis.txt")).unwrap(), b"mine");
    }
}

/// Issue 59, #27: the folder moved away and replaced by a link to another set's folder
/// while the set is written (here when the old set is listed, just before the swap):
/// refused, nothing written through the link, the other folder's set untouched.
#[test]
#[cfg(unix)]
fn a_folder_replaced_by_a_link_during_the_write_is_refused_before_the_swap() {
    let other = temp_dir("moved-other");
    old_set(&other);
    let theirs = listing(&other);
    let dir = temp_dir("moved");
    old_set(&dir);
    let away = dir.with_extension("away");
    let _ = std::fs::remove_dir_all(&away);
    let swapped = std::cell::Cell::new(false);
    let belongs = |n: &str| {
        if !swapped.replace(true) {
            std::fs::rename(&dir, &away).unwrap();
            std::os::unix::fs::symlink(&other, &dir).unwrap();
        }
        n.ends_with(".md")
    };
    let e = write_set(&dir, &new_set(), belongs).unwrap_err().to_string();
    assert!(swapped.get());
    assert!(e.contains("moved or replaced"), "{e}");
    assert_eq!(listing(&other), theirs, "nothing written through the link");
    // The folder that was held keeps its old set; its staging folder is thrown away by
    // its next set.
    std::fs::remove_file(&dir).unwrap();
    std::fs::rename(&away, &dir).unwrap();
    write_set(&dir, &new_set(), |n| n.ends_with(".md")).unwrap();
    let mut names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, [".phonglab-set.written", "a.md", "b.md", "d.md", "mine.txt"], "no staging folder left");
}

/// Issue 59 F7: a file of the set that another program holds open without sharing it
/// (share mode 0) is said so, as a single file's replace says it, and not as a file
/// phonglab did not write (untrue); nothing is written.
#[test]
#[cfg(windows)]
fn a_sets_file_held_open_elsewhere_is_said_so_and_nothing_is_written() {
    use std::os::windows::fs::OpenOptionsExt;
    let dir = temp_dir("set-held");
    old_set(&dir);
    let before = listing(&dir);
    let held = std::fs::File::options().read(true).share_mode(0).open(dir.join("a.md")).unwrap();
    let e = crate::io::exercise_set::refuse_foreign(&dir, &new_set()).unwrap_err().to_string();
    assert!(e.contains("a.md") && e.contains("another program has it open"), "{e}");
    assert!(!e.contains("not written by phonglab"), "{e}");
    drop(held);
    assert_eq!(listing(&dir), before);
}

/// Issue 59 (a teacher's finding 2): an old file of the set held open by another program
/// that shares reading (a PDF viewer), or reading and writing, refuses the set in words
/// ("another program has it open"), never the system's raw "Sharing violation"; the
/// folder is as it was.
#[test]
#[cfg(windows)]
fn a_sets_file_held_open_with_any_sharing_is_said_so_and_the_folder_is_as_it_was() {
    use std::os::windows::fs::OpenOptionsExt;
    // FILE_SHARE_READ, then FILE_SHARE_READ | FILE_SHARE_WRITE: no deleting, no renaming.
    for share in [1, 3] {
        let dir = temp_dir("set-held-shared");
        old_set(&dir);
        let before = listing(&dir);
        let held = std::fs::File::options().read(true).share_mode(share).open(dir.join("a.md")).unwrap();
        let e = write_set(&dir, &new_set(), |n| n.ends_with(".md")).unwrap_err();
        let said = e.to_string();
        assert_eq!(e.reason.kind(), io::ErrorKind::ResourceBusy, "share {share}: {said}");
        assert!(said.contains("a.md") && said.contains("another program has it open"), "share {share}: {said}");
        assert!(!said.contains("os error"), "share {share}: {said}");
        drop(held);
        assert_eq!(listing(&dir), before, "share {share}");
        assert!(!std::fs::read_dir(&dir).unwrap().flatten().any(|e| e.path().is_dir()), "share {share}: staging");
    }
}

/// Issue 59 (finding 2): an old file held open with full sharing (deleting too) lets the
/// set be swapped in, but its removal waits for the other program, so the staging
/// folder cannot be removed yet: the run succeeds, with a note saying the new set is in
/// the folder and the next run removes what is left; and it does.
#[test]
#[cfg(windows)]
fn a_clean_up_refused_after_the_set_is_in_place_is_a_note_and_the_next_run_removes_it() {
    use std::os::windows::fs::OpenOptionsExt;
    let belongs = |n: &str| n.ends_with(".md");
    let (want_dir, dir) = (temp_dir("set-held-all-want"), temp_dir("set-held-all"));
    old_set(&want_dir);
    write_set(&want_dir, &new_set(), belongs).unwrap();
    let want = user_files(&want_dir);
    old_set(&dir);
    let held = std::fs::File::options().read(true).share_mode(7).open(dir.join("a.md")).unwrap();
    let notices = write_set(&dir, &new_set(), belongs).unwrap();
    assert_eq!(user_files(&dir), want, "the new set is in place");
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].contains("the new set is whole in") && notices[0].contains("next run"), "{notices:?}");
    drop(held);
    assert_eq!(write_set(&dir, &new_set(), belongs).unwrap(), Vec::<String>::new());
    assert_eq!(listing(&dir), want);
    assert!(!std::fs::read_dir(&dir).unwrap().flatten().any(|e| e.path().is_dir()), "staging folder removed");
}

/// Runs `f` with `act` done to the folder, as another process would, just before each old
/// file of a set moves aside (the journal has decided), given that file's path.
fn meanwhile_at_aside<R>(act: impl FnMut(&Path) + 'static, f: impl FnOnce() -> R) -> R {
    MEANWHILE.with(|m| *m.borrow_mut() = Some(Box::new(act)));
    let r = f();
    MEANWHILE.with(|m| *m.borrow_mut() = None);
    r
}

/// A file outside the set's folder, of the user's, and a link to it planted at `b.md` of
/// the old set by another process after the journal decided, before `b.md` moves aside.
fn swap_b_for_a_link(dir: &Path, outside: &Path) -> Result<Vec<String>, WriteError> {
    let thesis = outside.join("thesis.txt");
    meanwhile_at_aside(
        move |old| {
            if old.file_name().is_some_and(|n| n == "b.md") {
                std::fs::remove_file(old).unwrap();
                assert!(plant_link(&thesis, old), "a link is made");
            }
        },
        || write_set(dir, &new_set(), |n| n.ends_with(".md")),
    )
}

/// Issue 59 (the worst hole, reproduced four times under Wine): an old file of the set
/// replaced by a link to a file outside the folder between the journal's decision and its
/// move aside. Before, the move by name took the link (Wine: the file it names) into the
/// aside folder, which was then removed: the file outside was deleted under Wine, the
/// user's link on Linux. Now the move is checked through the handle that makes it: the link
/// is left where it is, the set is undone (the old files back in place) and refused in
/// words, and the file outside is untouched.
#[test]
#[cfg(any(unix, windows))]
fn an_old_file_swapped_for_a_link_during_the_swap_is_left_and_the_set_undone() {
    let outside = fresh_dir("swap-link-outside");
    std::fs::write(outside.join("thesis.txt"), "mine").unwrap();
    let dir = fresh_dir("swap-link");
    old_set(&dir);
    let probe = fresh_dir("swap-link-probe");
    std::fs::write(probe.join("target"), "probe").unwrap();
    if !plant_link(&probe.join("target"), &probe.join("link")) {
        eprintln!("no symbolic link can be made here: nothing to test");
        return;
    }
    let e = swap_b_for_a_link(&dir, &outside).unwrap_err().to_string();
    assert!(e.contains("b.md") && e.contains("replaced while phonglab was writing the set"), "{e}");
    assert_eq!(std::fs::read(outside.join("thesis.txt")).unwrap(), b"mine", "the file outside is untouched");
    assert_eq!(crate::io::atomic_write::tests::listing(&outside).len(), 1);
    assert!(crate::platform::links::reached_through_link(&dir.join("b.md")), "the link is left where it was");
    let files = listing(&dir);
    let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["a.md", "b.md", "c.md", "mine.txt"]);
    assert_eq!(files[0].1, b"old a", "the old a.md, moved aside before b.md, is back");
    assert_eq!(files[2].1, b"old c, not in the new set");
    assert!(!std::fs::read_dir(&dir).unwrap().flatten().any(|e| e.path().is_dir()), "no staging folder left");
}

/// Issue 59: a stopped writer's staging folder, with a link to a file outside the folder
/// planted in it (or in its aside folder) by another process: the recovery removes only
/// what phonglab put there, each checked through its handle; the link and the file it
/// names are left, said, and the set in place is whole. Before, the recovery removed the
/// staging folder with everything in it (`remove_dir_all`: Wine follows the link).
#[test]
#[cfg(any(unix, windows))]
fn a_link_planted_in_a_stopped_writers_staging_folder_is_left_by_the_recovery() {
    let belongs = |n: &str| n.ends_with(".md");
    let outside = fresh_dir("recover-link-outside");
    std::fs::write(outside.join("thesis.txt"), "mine").unwrap();
    // Stopped with the journal begun (undecided), and with the old files aside (decided).
    for (n, inner) in [(2, ""), (7, ASIDE)] {
        let dir = fresh_dir(&format!("recover-link-{n}"));
        old_set(&dir);
        with_fault(Fault::KilledAtStep(n), || write_set(&dir, &new_set(), belongs)).unwrap_err();
        let (staging, _) = journal_in(&dir).expect("a journal");
        if !plant_link(&outside.join("thesis.txt"), &staging.join(inner).join("planted.md")) {
            eprintln!("no symbolic link can be made here: nothing to test");
            return;
        }
        let notices = recover(&dir).unwrap();
        assert_eq!(notices.len(), 1, "step {n}: {notices:?}");
        assert!(notices[0].contains("something phonglab did not put there"), "step {n}: {notices:?}");
        assert_eq!(std::fs::read(outside.join("thesis.txt")).unwrap(), b"mine", "step {n}");
        assert!(crate::platform::links::reached_through_link(&staging.join(inner).join("planted.md")), "step {n}");
        let names: Vec<String> = listing(&dir).into_iter().map(|(n, _)| n).collect();
        let want: &[&str] =
            if n == 2 { &["a.md", "b.md", "c.md", "mine.txt"] } else { &["a.md", "b.md", "d.md", "mine.txt"] };
        assert_eq!(names, want, "step {n}: the old set whole, or the new one");
    }
}

/// Issue 59 (finding 3): a file whose name differs from a set's only in case (`B.md` beside
/// phonglab's `b.md`), which Windows and Wine take for one file: the set is refused before
/// anything moves, naming it, and both files are as they were. Before, under Wine a failed
/// run deleted phonglab's own old file and said "the folder is unchanged".
#[test]
fn a_name_differing_from_a_sets_only_in_case_refuses_the_set_and_both_files_stay() {
    let dir = temp_dir("case");
    old_set(&dir);
    let theirs = dir.join("B.md");
    if std::fs::write(&theirs, "theirs").is_err() || std::fs::read(dir.join("b.md")).unwrap() != b"old b" {
        eprintln!("this file system takes B.md and b.md for one file: nothing to test");
        return;
    }
    let before = listing(&dir);
    let e = write_set(&dir, &new_set(), |n| n.ends_with(".md")).unwrap_err().to_string();
    assert!(e.contains("B.md") && e.contains("only in case") && e.contains("the folder is unchanged"), "{e}");
    assert_eq!(listing(&dir), before);
}

/// Issue 59 (finding 3): a swap whose undo cannot put an old file back (something put at
/// its name meanwhile) deletes nothing and says so truly: the old file is kept in the
/// staging folder, with the journal, never "the folder is unchanged"; the next run leaves
/// the file there, saying so.
#[test]
fn an_undo_that_cannot_put_an_old_file_back_deletes_nothing_and_says_so() {
    let dir = temp_dir("undo-stuck");
    old_set(&dir);
    let planted = dir.join("a.md");
    let r = meanwhile_at_aside(
        move |old| {
            // When c.md moves aside, a.md (aside already) has a file of someone else's at its
            // name: the new a.md cannot go in, nor the old one back.
            if old.file_name().is_some_and(|n| n == "c.md") {
                std::fs::write(&planted, "someone else's").unwrap();
            }
        },
        || write_set(&dir, &new_set(), |n| n.ends_with(".md")),
    );
    let e = r.unwrap_err().to_string();
    assert!(e.contains("a.md") && e.contains("nothing was deleted"), "{e}");
    assert!(!e.contains("the folder is unchanged"), "{e}");
    let (staging, j) = journal_in(&dir).expect("the staging folder and its journal are kept");
    assert!(j.decided);
    assert_eq!(std::fs::read(staging.join(ASIDE).join("a.md")).unwrap(), b"old a", "the old a.md is kept");
    assert_eq!(std::fs::read(dir.join("a.md")).unwrap(), b"someone else's");
    let notices = recover(&dir).unwrap();
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert_eq!(std::fs::read(dir.join("a.md")).unwrap(), b"someone else's");
}

/// Runs `f` with `act` done to the folder, as another process would, at the `at`-th step of
/// a set's swap (from 0; [`step`]).
fn meanwhile_at_step<R>(at: u32, act: impl FnOnce() + 'static, f: impl FnOnce() -> R) -> R {
    let mut act = Some(act);
    let mut n = 0;
    AT_STEP.with(|m| {
        *m.borrow_mut() = Some(Box::new(move || {
            if n == at
                && let Some(act) = act.take()
            {
                act();
            }
            n += 1;
        }));
    });
    let r = f();
    AT_STEP.with(|m| *m.borrow_mut() = None);
    r
}

/// Every file, folder and link under `dir`, with its bytes (a link: its target), walked
/// without following a link: what "nothing there was written, moved or removed" compares.
/// A folder's files, named, with their bytes ([`user_files`], [`everything_in`]).
type Files = Vec<(String, Vec<u8>)>;

/// The old set and the new one as a folder holds them once a set is written whole: what
/// a swap test's folder must end with, either way.
fn old_and_new_sets(name: &str) -> (Files, Files) {
    let (want_old, want_new) = (fresh_dir(&format!("{name}-old")), fresh_dir(&format!("{name}-new")));
    old_set(&want_old);
    old_set(&want_new);
    write_set(&want_new, &new_set(), |n: &str| n.ends_with(".md")).unwrap();
    (user_files(&want_old), user_files(&want_new))
}

/// A folder outside the set's holding the teacher's files at the names a set writes (and
/// an aside folder), and everything in it: a swap through a link must leave it so.
fn outside_with_the_teachers_files(name: &str) -> (std::path::PathBuf, Files) {
    let outside = fresh_dir(name);
    std::fs::create_dir(outside.join(ASIDE)).unwrap();
    for name in ["a.md", "b.md", "d.md", "thesis.txt", JOURNAL] {
        std::fs::write(outside.join(name), "the teacher's").unwrap();
    }
    let before = everything_in(&outside);
    (outside, before)
}

fn everything_in(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut all = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let p = e.path();
            let meta = std::fs::symlink_metadata(&p).unwrap();
            let rel = p.strip_prefix(dir).unwrap().to_string_lossy().into_owned();
            let seen = if meta.file_type().is_symlink() {
                std::fs::read_link(&p).map(|t| t.to_string_lossy().into_owned().into_bytes()).unwrap_or_default()
            } else if meta.is_dir() {
                todo.push(p.clone());
                b"<dir>".to_vec()
            } else {
                std::fs::read(&p).unwrap_or_default()
            };
            all.push((rel, seen));
        }
    }
    all.sort();
    all
}

/// The staging folder a writer is working in, in `dir` (a real folder, not a link).
fn staging_in(dir: &Path) -> std::path::PathBuf {
    std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .find(|p| {
            let n = p.file_name().unwrap().to_string_lossy();
            n.starts_with(".phonglab-set.")
                && n.ends_with(".tmp")
                && std::fs::symlink_metadata(p).is_ok_and(|m| m.is_dir())
        })
        .expect("a staging folder")
}

/// Issue 59, the hostile's review, fix59x: the staging folder renamed (within the set's
/// folder) and replaced by a link to a folder outside at every step of a set's swap: before
/// the set is staged, between the staging and the journal's decision, during the swap, and
/// after the aside folder is cleared. Nothing in the folder outside is written, moved or
/// removed (the staging folder is held by a descriptor: every step goes through it); the
/// set is refused and undone, saying the working folder was moved or replaced (after the
/// last step the set is in place: the run succeeds); the folder ends with the old set or
/// the new one, the staging folder removed at the name it was given, the link left.
/// Windows: the folder held cannot be renamed (held without sharing its deletion).
#[test]
#[cfg(any(unix, windows))]
fn a_staging_folder_swapped_for_a_link_at_any_step_touches_nothing_outside() {
    let belongs = |n: &str| n.ends_with(".md");
    let (old, new) = old_and_new_sets("staging-swap");
    let probe = fresh_dir("staging-swap-probe");
    if !plant_link(&probe, &probe.join("link")) {
        eprintln!("no symbolic link can be made here: nothing to test");
        return;
    }
    for at in 0..13 {
        let dir = fresh_dir(&format!("staging-swap-{at}"));
        old_set(&dir);
        let (outside, before) = outside_with_the_teachers_files(&format!("staging-swap-out-{at}"));
        let swapped = std::rc::Rc::new(std::cell::Cell::new(false));
        let (d, o, s) = (dir.clone(), outside.clone(), swapped.clone());
        let r = meanwhile_at_step(
            at,
            move || {
                let staging = staging_in(&d);
                if std::fs::rename(&staging, d.join(".away")).is_ok() {
                    assert!(plant_link(&o, &staging), "a link is made");
                    s.set(true);
                }
            },
            || write_set(&dir, &new_set(), belongs),
        );
        assert_eq!(everything_in(&outside), before, "step {at}: nothing outside written, moved or removed");
        assert_eq!(swapped.get(), cfg!(unix), "step {at}: a folder held is renamed on Unix only");
        let files = user_files(&dir);
        match r {
            Err(e) if swapped.get() && at < 12 => {
                let e = e.to_string();
                assert!(e.contains("working folder") && e.contains("moved or replaced"), "step {at}: {e}");
                assert!(e.contains("the folder is unchanged"), "step {at}: {e}");
                assert_eq!(files, old, "step {at}: the old set, as it was");
            }
            Ok(notices) if !swapped.get() || at == 12 => {
                assert_eq!(notices, Vec::<String>::new(), "step {at}");
                assert_eq!(files, new, "step {at}: the new set");
            }
            r => panic!("step {at}: {:?}", r.map_err(|e| e.to_string())),
        }
        assert!(!dir.join(".away").exists(), "step {at}: the staging folder removed at the name it was given");
    }
}

/// Issue 59, F4: the set's folder itself renamed and replaced by a link to another folder
/// after it was held (before the staging folder is made, and at every step of the swap).
/// Before, the staging folder and its journal were made through the link, in the folder it
/// leads to, and left there, while the message said "nothing was written through it". Now
/// the folder is held by a descriptor: nothing in the other folder is written, moved or
/// removed, the message says so truly, and the folder held ends with its old set (or, the
/// swap done, the new one) and no staging folder.
#[test]
#[cfg(unix)]
fn a_sets_folder_swapped_for_a_link_writes_nothing_through_it_and_says_so_truly() {
    let belongs = |n: &str| n.ends_with(".md");
    let (old, new) = old_and_new_sets("folder-swap");
    for at in -1..13 {
        let (dir, other) = (fresh_dir(&format!("folder-swap-{at}")), fresh_dir(&format!("folder-swap-other-{at}")));
        old_set(&dir);
        old_set(&other);
        let before = everything_in(&other);
        let away = dir.with_extension("away");
        let (d, o, a) = (dir.clone(), other.clone(), away.clone());
        let swap = move || {
            std::fs::rename(&d, &a).unwrap();
            std::os::unix::fs::symlink(&o, &d).unwrap();
        };
        let held = hold_folder(&dir).unwrap();
        let r = if at < 0 {
            swap();
            write_set_held(&held, &new_set(), belongs)
        } else {
            meanwhile_at_step(at as u32, swap, || write_set_held(&held, &new_set(), belongs))
        };
        drop(held);
        assert_eq!(everything_in(&other), before, "step {at}: nothing written, moved or removed through the link");
        std::fs::remove_file(&dir).unwrap();
        std::fs::rename(&away, &dir).unwrap();
        let mut names: Vec<String> =
            std::fs::read_dir(&dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
        names.retain(|n| n.starts_with(".phonglab-set") && n != ".phonglab-set.written");
        assert_eq!(names, Vec::<String>::new(), "step {at}: no staging folder left");
        match r {
            Err(e) if at < 12 => {
                let e = e.to_string();
                assert!(e.contains("moved or replaced") && e.contains("nothing was written, moved or removed"), "{e}");
                assert!(e.contains("the folder is unchanged"), "step {at}: {e}");
                assert_eq!(user_files(&dir), old, "step {at}: the folder held keeps its old set");
            }
            Ok(_) if at == 12 => assert_eq!(user_files(&dir), new, "step {at}"),
            r => panic!("step {at}: {:?}", r.map_err(|e| e.to_string())),
        }
    }
}

/// fix59n left, fix59x: a writer stopped before its journal named its staged files; a
/// file of someone else's put in its staging folder at a name it staged (its own `a.md`
/// removed first). The recovery removes only what the list of what was staged names by
/// identity (`b.md`), and leaves the other file, saying so; before, any regular file
/// there was removed as phonglab's kind.
#[test]
fn a_file_put_at_a_staged_name_in_a_stopped_writers_staging_folder_is_left() {
    let belongs = |n: &str| n.ends_with(".md");
    let dir = temp_dir("staged-identity");
    old_set(&dir);
    let old = user_files(&dir);
    // Killed after the journal was begun and a.md and b.md were staged (steps 0, 1, 2).
    with_fault(Fault::KilledAtStep(2), || write_set(&dir, &new_set(), belongs)).unwrap_err();
    let (staging, j) = journal_in(&dir).expect("a journal");
    assert!(!j.decided && j.new.is_empty(), "the journal names no staged file yet");
    // The staged a.md moved away, not removed: alive, its identity cannot be given to the
    // classmate's file (Wine's Windows identity is the inode, which a removal frees for the
    // next file; NTFS's file index never repeats).
    let kept = dir.with_extension("staged-a.md");
    std::fs::rename(staging.join("a.md"), &kept).unwrap();
    std::fs::write(staging.join("a.md"), "a classmate's").unwrap();
    let notices = recover(&dir).unwrap();
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].contains("something phonglab did not put there"), "{notices:?}");
    assert_eq!(std::fs::read(staging.join("a.md")).unwrap(), b"a classmate's", "left as it is");
    assert!(!staging.join("b.md").exists(), "the staged b.md, named by its identity, removed");
    assert_eq!(user_files(&dir), old, "the old set whole");
    std::fs::remove_file(&kept).unwrap();
}

/// Windows under Wine: renames `from` to `to` as a Unix program does (Wine's sharing rules
/// bind Windows programs only, so a folder phonglab holds is renamed): `false` where no Unix
/// program can be run (not under Wine).
#[cfg(windows)]
fn unix_rename(from: &Path, to: &Path) -> bool {
    let unix = |p: &Path| {
        let out = std::process::Command::new("winepath").arg("-u").arg(p).output().ok()?;
        out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim_end().to_string())
    };
    let (Some(f), Some(t)) = (unix(from), unix(to)) else { return false };
    let _ = std::process::Command::new(r"Z:\bin\mv").args([&f, &t]).status();
    (0..500).any(|_| to.exists() || (std::thread::sleep(std::time::Duration::from_millis(20)), false).1)
}

/// Issue 59, round 2 (p25, Wine): a Unix program renames the staging folder (within the
/// set's folder) and puts a link to a folder outside at its name, at every step of a set's
/// swap. Windows works by path, so each step first asks that the path still leads to the
/// folder held: nothing in the folder outside is written, moved or removed (before, the new
/// set's files were moved into it through the link); the run refuses the set in words
/// that say what was checked, never "nothing was written, moved or removed through it";
/// and the folder ends with a whole set, the old one or the new one, at once or after the
/// next run's recovery, which finds the renamed working folder by its journal.
#[test]
#[cfg(windows)]
fn a_staging_folder_a_unix_program_swaps_for_a_link_touches_nothing_outside_and_a_set_stays_whole() {
    let belongs = |n: &str| n.ends_with(".md");
    let (old, new) = old_and_new_sets("unix-swap");
    let probe = fresh_dir("unix-swap-probe");
    std::fs::create_dir(probe.join("a")).unwrap();
    if !unix_rename(&probe.join("a"), &probe.join("b")) || !plant_link(&probe.join("b"), &probe.join("a")) {
        eprintln!("not under Wine: no Unix program renames a folder here: nothing to test");
        return;
    }
    for at in 0..13 {
        let dir = fresh_dir(&format!("unix-swap-{at}"));
        old_set(&dir);
        let (outside, before) = outside_with_the_teachers_files(&format!("unix-swap-out-{at}"));
        let swapped = std::rc::Rc::new(std::cell::Cell::new(false));
        let (d, o, s) = (dir.clone(), outside.clone(), swapped.clone());
        let r = meanwhile_at_step(
            at,
            move || {
                let staging = staging_in(&d);
                if unix_rename(&staging, &d.join("away")) {
                    assert!(plant_link(&o, &staging), "a link is made");
                    s.set(true);
                }
            },
            || write_set(&dir, &new_set(), belongs),
        );
        assert!(swapped.get(), "step {at}: the Unix side renamed the folder held");
        assert_eq!(everything_in(&outside), before, "step {at}: nothing outside written, moved or removed");
        if let Err(e) = &r {
            let e = e.to_string();
            assert!(
                e.contains("moved or replaced") && !e.contains("nothing was written, moved or removed through"),
                "step {at}: {e}"
            );
        }
        let _ = recover(&dir);
        assert_eq!(everything_in(&outside), before, "step {at}: the recovery touched nothing outside");
        let files = user_files(&dir);
        assert!(
            files == old || files == new,
            "step {at}: no whole set: {:?}, {:?}",
            files.iter().map(|f| &f.0).collect::<Vec<_>>(),
            r.map_err(|e| e.to_string())
        );
    }
}

/// Issue 59, round 3 (`HOLD=0.002 p30_wine_flips.sh flip-old`, Wine): a working folder
/// (the aside folder) replaced by a link as it was made was said in the system's raw words,
/// "create a staging folder in: The filename cannot be resolved. (os error 1921)". It is
/// said as a link that changed while phonglab wrote, naming the folder.
#[test]
#[cfg(any(unix, windows))]
fn a_working_folder_taken_by_a_link_as_it_is_made_is_said_in_words() {
    let dir = fresh_dir("staging-taken-words");
    let held = HeldDir::open(&dir).unwrap();
    #[cfg(unix)]
    let refused = io::Error::from_raw_os_error(libc::ELOOP);
    #[cfg(windows)]
    let refused = io::Error::from_raw_os_error(1921);
    assert!(crate::platform::os::is_link_refused(&refused));
    let e = super::staging_error(&held, ".phonglab-set.old", refused).to_string();
    assert!(e.contains(".phonglab-set.old") && e.contains("moved or replaced (by a link"), "{e}");
    assert!(!e.contains("1921") && !e.contains("cannot be resolved") && !e.contains("os error"), "{e}");
}
