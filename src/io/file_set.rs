//! Sets of files written as one.
//!
//! A set of files that belong together (an exercise set, a cost report, an openFrameworks
//! project: [`write_set`]) is swapped in so that at every instant either the old set or the new one is whole, even
//! when the process is killed:
//! 1. the new set is written whole into a staging folder inside the target folder, and
//!    synced;
//! 2. a journal, `.phonglab-set.journal`, naming the staging folder, the new set's files
//!    and the old set's, is written whole (a temporary file renamed): from this instant the
//!    new set is decided, and it is whole (in the staging folder, or already in place);
//! 3. the old set's files are moved aside into the staging folder and the new ones renamed
//!    into place (each rename happens or does not);
//! 4. the journal is removed, then the staging folder.
//!
//! A failure before the journal leaves the old set untouched; a failure after it (a rename
//! refused) moves everything back and removes the journal, so the folder is as it was. A
//! process killed at any step leaves either no journal (the old set whole in place, and a
//! staging folder to throw away) or the journal (the new set whole across the folder and
//! the staging folder): the next write of a set into the folder ([`recover`], under the
//! folder's lock) finishes the swap the journal names, or throws the stale staging away.
//! Files of the old set that the new one lacks (`exercise-07.md` after a set of five) go
//! with the old set; other files are never touched. Two processes never swap sets in one
//! folder at once: each holds the folder's lock (Unix) while it writes.
//!
use std::fmt;
use std::io;
use std::path::Path;

use super::atomic_write::{
    Fault, WriteError, fault, file_name_of, next_step, rename, temporary_name, write, write_new,
};

/// Files that belong together, written by [`write_set`]: names (no folders) and bytes.
#[derive(Clone, Debug, Default)]
pub struct FileSet {
    /// The files, in the order they are written.
    pub files: Vec<(String, Vec<u8>)>,
}

impl FileSet {
    /// Adds a file.
    pub fn add(&mut self, name: impl Into<String>, bytes: impl Into<Vec<u8>>) {
        self.files.push((name.into(), bytes.into()));
    }

    /// The file's bytes, if the set has it.
    pub fn get(&self, name: &str) -> Option<&[u8]> {
        self.files.iter().find(|(n, _)| n == name).map(|(_, b)| b.as_slice())
    }
}

/// The journal of a set's swap, in the target folder (see the module's documentation).
pub const JOURNAL: &str = ".phonglab-set.journal";

/// The stem of a staging folder's name (`.phonglab-set.<pid>.<n>.tmp`).
const STAGING: &str = "phonglab-set";

/// What the journal says: the staging folder (a name in the target folder), the new set's
/// files and the old set's.
#[derive(Debug, serde::Serialize, serde::Deserialize)]
struct Journal {
    staging: String,
    new: Vec<String>,
    old: Vec<String>,
}

/// A set's writer killed at this step (by a test): stop here, as a dead process would.
#[derive(Debug)]
struct Killed;

/// Counts a step of a set's swap; `Err(Killed)` where a test kills the writer there.
fn step() -> Result<(), Killed> {
    let Some(Fault::KilledAtStep(n)) = fault() else { return Ok(()) };
    if next_step() == n { Err(Killed) } else { Ok(()) }
}

/// Why a set's swap stopped: an error to report (after the clean-up), or a kill (nothing
/// more runs).
enum Stop {
    Failed(WriteError),
    Killed,
}

impl From<Killed> for Stop {
    fn from(_: Killed) -> Self {
        Stop::Killed
    }
}

impl From<WriteError> for Stop {
    fn from(e: WriteError) -> Self {
        Stop::Failed(e)
    }
}

/// The killed writer's error, for tests: the step's name says it.
fn killed(dir: &Path) -> WriteError {
    WriteError::new(dir, "write-step-killed", io::Error::other("killed (injected by a test)"), "write-kept-recoverable")
}

/// Writes `set` into the folder `dir` (created if missing) as one: the folder ends with
/// the whole new set, or, on any failure, exactly the files it had. Files already in `dir`
/// for which `belongs` is true are the old set: they are replaced, or removed when the new
/// set has no file of that name. Other files in `dir` are never touched. What a killed
/// earlier writer left in `dir` is recovered first ([`recover`]).
pub fn write_set(dir: &Path, set: &FileSet, belongs: impl Fn(&str) -> bool) -> Result<(), WriteError> {
    const UNTOUCHED: &str = "write-kept-folder";
    std::fs::create_dir_all(dir).map_err(|e| WriteError::new(dir, "write-step-create-folder", e, UNTOUCHED))?;
    let _lock = crate::platform::os::lock_folder(dir)
        .map_err(|e| WriteError::new(dir, "write-step-lock-folder", e, UNTOUCHED))?;
    recover_locked(dir).map_err(|e| WriteError::new(dir, "write-step-recover", e, UNTOUCHED))?;
    let staging = temporary_name(dir, STAGING);
    std::fs::create_dir(&staging).map_err(|e| WriteError::new(dir, "write-step-create-staging", e, UNTOUCHED))?;
    match stage_and_swap(dir, &staging, set, &belongs) {
        Ok(()) => Ok(()),
        Err(Stop::Killed) => Err(killed(dir)),
        Err(Stop::Failed(e)) => {
            let _ = std::fs::remove_dir_all(&staging);
            Err(e)
        }
    }
}

/// Finishes or throws away what a killed writer of a set left in `dir`: with a journal,
/// the swap it names is finished (the new set is whole); without one, staging folders and
/// a journal's temporary file are removed (the old set is whole in place). Takes the
/// folder's lock, so a writer still at work is waited for, never disturbed.
pub fn recover(dir: &Path) -> io::Result<()> {
    let _lock = crate::platform::os::lock_folder(dir)?;
    recover_locked(dir)
}

fn recover_locked(dir: &Path) -> io::Result<()> {
    let journal = dir.join(JOURNAL);
    match std::fs::read(&journal) {
        Ok(bytes) => {
            let j: Journal = serde_json::from_slice(&bytes).map_err(io::Error::other)?;
            // A journal is read from a folder that may have come from anyone (an unzipped
            // set): it may only name plain files and a staging folder of phonglab's.
            let staging_ok = j.staging.starts_with(&format!(".{STAGING}.")) && j.staging.ends_with(".tmp");
            if !plain_name(&j.staging) || !staging_ok || !j.new.iter().chain(&j.old).all(|n| plain_name(n)) {
                return Err(io::Error::new(io::ErrorKind::InvalidData, "the journal names files outside its folder"));
            }
            finish_swap(dir, &j)?;
            std::fs::remove_file(&journal)?;
            crate::platform::os::sync_folder(dir);
        }
        Err(e) if e.kind() == io::ErrorKind::NotFound => {}
        Err(e) => return Err(e),
    }
    // Under the lock, every staging folder and journal temporary is a dead writer's.
    for entry in std::fs::read_dir(dir)?.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let stale = name.ends_with(".tmp")
            && (name.starts_with(&format!(".{STAGING}.")) || name.starts_with(&format!(".{JOURNAL}.")));
        if stale {
            let _ = if entry.file_type().is_ok_and(|t| t.is_dir()) {
                std::fs::remove_dir_all(entry.path())
            } else {
                std::fs::remove_file(entry.path())
            };
        }
    }
    Ok(())
}

/// Rolls the swap that `j` names forward from wherever it stopped: each new file still in
/// the staging folder is renamed into place (over the old file of its name, if any), and
/// each old file that the new set lacks is removed. Idempotent.
fn finish_swap(dir: &Path, j: &Journal) -> io::Result<()> {
    let staging = dir.join(&j.staging);
    for name in &j.new {
        let staged = staging.join(name);
        if staged.exists() {
            std::fs::rename(&staged, dir.join(name))?;
        }
    }
    for name in j.old.iter().filter(|n| !j.new.contains(n)) {
        match std::fs::remove_file(dir.join(name)) {
            Err(e) if e.kind() != io::ErrorKind::NotFound => return Err(e),
            _ => {}
        }
    }
    crate::platform::os::sync_folder(dir);
    let _ = std::fs::remove_dir_all(&staging);
    Ok(())
}

/// A plain file name: no folder, not `.` or `..` (a set's files live in its folder).
fn plain_name(name: &str) -> bool {
    !name.is_empty() && name != "." && name != ".." && !name.contains(['/', '\\'])
}

fn stage_and_swap(dir: &Path, staging: &Path, set: &FileSet, belongs: &dyn Fn(&str) -> bool) -> Result<(), Stop> {
    const UNTOUCHED: &str = "write-kept-folder";
    step()?;
    for (name, bytes) in &set.files {
        let target = dir.join(name);
        if !plain_name(name) {
            let e = io::Error::new(io::ErrorKind::InvalidFilename, "not a plain file name");
            return Err(WriteError::new(&target, "write-step-name", e, UNTOUCHED).into());
        }
        write_new(&staging.join(name), bytes).map_err(|(what, e)| WriteError::new(&target, what, e, UNTOUCHED))?;
        step()?;
    }
    crate::platform::os::sync_folder(staging);
    let new_names: Vec<String> = set.files.iter().map(|(n, _)| n.clone()).collect();
    let old = old_set(dir, &new_names, belongs)?;
    step()?;
    let journal = Journal {
        staging: file_name_of(staging).map_err(|e| WriteError::new(staging, "write-step-name", e, UNTOUCHED))?,
        new: new_names,
        old,
    };
    let text = serde_json::to_vec(&journal)
        .map_err(io::Error::other)
        .map_err(|e| WriteError::new(dir, "write-step-write", e, UNTOUCHED))?;
    write(&dir.join(JOURNAL), &text).map_err(|e| WriteError { kept: UNTOUCHED, ..e })?;
    step()?;
    swap(dir, staging, &journal)?;
    std::fs::remove_file(dir.join(JOURNAL))
        .map_err(|e| WriteError::new(dir, "write-step-remove-journal", e, "write-kept-recoverable"))?;
    crate::platform::os::sync_folder(dir);
    step()?;
    let _ = std::fs::remove_dir_all(staging);
    Ok(())
}

/// The old set in `dir`: every file the new one replaces, and every other member of it.
fn old_set(dir: &Path, new_names: &[String], belongs: &dyn Fn(&str) -> bool) -> Result<Vec<String>, WriteError> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| WriteError::new(dir, "write-step-list", e, "write-kept-folder"))?;
    let mut old = Vec::new();
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let is_file = entry.file_type().is_ok_and(|t| t.is_file());
        if is_file && name != JOURNAL && (new_names.contains(&name) || belongs(&name)) {
            old.push(name);
        }
    }
    old.sort();
    Ok(old)
}

/// Step 3: the old files aside (into `staging/.old`), the new ones into place. A refused
/// rename moves everything back (the new files into the staging folder, so a journal left
/// by a kill during the undo still finds them) and removes the journal.
fn swap(dir: &Path, staging: &Path, j: &Journal) -> Result<(), Stop> {
    const UNTOUCHED: &str = "write-kept-folder";
    let aside = staging.join(".old");
    let mut moved_aside: Vec<&str> = Vec::new();
    let mut moved_in: Vec<&str> = Vec::new();
    let undo = |moved_aside: &[&str], moved_in: &[&str]| {
        for name in moved_in {
            let _ = std::fs::rename(dir.join(name), staging.join(name));
        }
        for name in moved_aside {
            let _ = std::fs::rename(aside.join(name), dir.join(name));
        }
        let _ = std::fs::remove_file(dir.join(JOURNAL));
        crate::platform::os::sync_folder(dir);
    };
    if let Err(e) = std::fs::create_dir(&aside) {
        undo(&[], &[]);
        return Err(WriteError::new(dir, "write-step-create-staging", e, UNTOUCHED).into());
    }
    for name in &j.old {
        if let Err(e) = rename(&dir.join(name), &aside.join(name)) {
            undo(&moved_aside, &moved_in);
            return Err(WriteError::new(&dir.join(name), "write-step-rename", e, UNTOUCHED).into());
        }
        moved_aside.push(name);
        step()?;
    }
    for name in &j.new {
        if let Err(e) = rename(&staging.join(name), &dir.join(name)) {
            undo(&moved_aside, &moved_in);
            return Err(WriteError::new(&dir.join(name), "write-step-rename", e, UNTOUCHED).into());
        }
        moved_in.push(name);
        step()?;
    }
    crate::platform::os::sync_folder(dir);
    Ok(())
}

impl fmt::Display for FileSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.files.iter().map(|(n, _)| n.as_str()).collect();
        write!(f, "{}", names.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::atomic_write::tests::{FAULTS, listing, temp_dir};
    use crate::io::atomic_write::with_fault;

    fn old_set(dir: &Path) {
        for (n, b) in
            [("a.md", "old a"), ("b.md", "old b"), ("c.md", "old c, not in the new set"), ("mine.txt", "user")]
        {
            std::fs::write(dir.join(n), b).unwrap();
        }
    }

    fn new_set() -> FileSet {
        let mut s = FileSet::default();
        s.add("a.md", vec![b'A'; 5000]);
        s.add("b.md", "new b");
        s.add("d.md", "new d");
        s
    }

    /// What the folder holds for a user: its files, without the staging folders and the
    /// journal a writer works with.
    fn user_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
        listing(dir).into_iter().filter(|(n, _)| !n.starts_with(".phonglab-set")).collect()
    }

    /// The new set is whole somewhere: each of its files, with its new bytes, in place or
    /// in the staging folder the journal names.
    fn new_set_is_whole(dir: &Path, set: &FileSet) -> bool {
        let j: Journal = serde_json::from_slice(&std::fs::read(dir.join(JOURNAL)).unwrap()).unwrap();
        set.files.iter().all(|(name, bytes)| {
            [dir.join(&j.staging).join(name), dir.join(name)]
                .iter()
                .any(|p| std::fs::read(p).ok().as_ref() == Some(bytes))
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
            // At the instant of death: no journal and the old set in place, or the journal
            // and the new set whole.
            let names = |l: &[(String, Vec<u8>)]| l.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
            if dir.join(JOURNAL).exists() {
                assert!(new_set_is_whole(&dir, &new_set()), "killed at step {n}: the journal's set is whole");
            } else {
                let files = user_files(&dir);
                assert!(files == old || files == new, "killed at step {n}: no journal: {:?}", names(&files));
            }
            // The next run recovers: exactly the old set or exactly the new one, nothing else.
            recover(&dir).unwrap();
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
        // Staging, each of 3 files, the old set listed, the journal, 4 moves aside, 3 in,
        // the journal removed: 13 places to die, each tried.
        assert_eq!(steps, 13);
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
            std::fs::create_dir_all(staging.join(".old")).unwrap();
            for (name, bytes) in &new_set().files {
                std::fs::write(staging.join(name), bytes).unwrap();
            }
            let aside = |n: &str| std::fs::rename(dir.join(n), staging.join(".old").join(n)).unwrap();
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
            let j = Journal {
                staging: ".phonglab-set.1.0.tmp".into(),
                new: vec!["a.md".into(), "b.md".into(), "d.md".into()],
                old: vec!["a.md".into(), "b.md".into(), "c.md".into()],
            };
            std::fs::write(dir.join(JOURNAL), serde_json::to_vec(&j).unwrap()).unwrap();
            recover(&dir).unwrap();
            assert!(listing(&dir) == new, "state {state} ({a}, {b}, {d}, {c}): the new set, whole, and nothing else");
        }
    }

    #[test]
    fn a_journal_that_names_files_outside_its_folder_is_refused_and_nothing_moves() {
        let outside = temp_dir("journal-outside");
        std::fs::write(outside.join("precious.txt"), "mine").unwrap();
        for (staging, old) in [
            (".phonglab-set.1.0.tmp", "../phonglab-atomic-journal-outside-X/precious.txt"),
            ("../phonglab-atomic-journal-outside-X", "a.md"),
            (".phonglab-set.1.0.tmp", "/etc/passwd"),
        ] {
            let pid = std::process::id().to_string();
            let (staging, old) = (staging.replace('X', &pid), old.replace('X', &pid));
            let dir = temp_dir("journal-hostile");
            old_set(&dir);
            let j = Journal { staging, new: vec!["a.md".into()], old: vec![old] };
            std::fs::write(dir.join(JOURNAL), serde_json::to_vec(&j).unwrap()).unwrap();
            let e = write_set(&dir, &new_set(), |n| n.ends_with(".md")).unwrap_err();
            assert_eq!(e.what, "write-step-recover");
            assert_eq!(std::fs::read(outside.join("precious.txt")).unwrap(), b"mine");
            assert!(dir.join("c.md").exists(), "the folder is untouched");
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
}
