//! Sets of files written as one.
//!
//! A set of files that belong together (an exercise set, a cost report, an openFrameworks
//! project: [`write_set`]) is swapped in so that at every instant either the old set or the new one is whole, even
//! when the process is killed:
//! 1. a staging folder, `.phonglab-set.<pid>.<n>.tmp`, is made in the target folder, and a
//!    journal in it (`.phonglab-set.journal`) naming the folder itself;
//! 2. the new set is written whole into the staging folder, and synced;
//! 3. the folder is checked to be still the one held at the start (its identity, and no
//!    link at its name): one moved away and replaced by a link meanwhile refuses the set;
//! 4. the journal is written again, whole (a temporary file renamed), naming the new set's
//!    files and the old set's, each with its size, hash and identity: from this instant the
//!    new set is decided, and it is whole (in the staging folder, or already in place);
//! 5. the old set's files are moved aside into the staging folder and the new ones renamed
//!    into place, where nothing is (each rename happens or does not);
//! 6. the old files, the journal and the staging folder are removed.
//!
//! A failure before the journal decides leaves the old set untouched; a failure after it
//! (a rename refused) moves everything back, so the folder is as it was. A process killed
//! at any step leaves either a staging folder whose journal has not decided (the old set
//! whole in place) or one whose journal has (the new set whole across the folder and the
//! staging folder): the next write of a set into the folder ([`recover`], under the
//! folder's lock) finishes the swap, or throws the staging folder away. Files of the old
//! set that the new one lacks (`exercise-07.md` after a set of five) go with the old set
//! only when phonglab wrote them and they are unchanged since (the folder's list of what
//! the last set wrote, `set_journal::WRITTEN`); other files are never touched. Two processes never swap sets in one folder at once:
//! each holds the folder's lock (Unix) while it writes.
//!
//! Recovery acts only on what phonglab itself wrote ([`super::set_journal`]): a journal,
//! staging folder or link planted in the folder (an unzipped handout can carry one) is left
//! as it is, and the messages [`write_set`] returns say so.
use std::fmt;
use std::io;
use std::path::Path;

use super::atomic_write::{Fault, WriteError, fault, next_step, rename_no_replace, set_steps, temporary_name};
use super::set_journal::{
    ASIDE, Entry, Identity, JOURNAL, Journal, STAGING, entry_of, plain_name, stage, write_journal,
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
    /// The folder is no longer the one held (moved, or replaced by a link): refused with
    /// no clean-up, since the staging folder's path now leads elsewhere; the staging folder
    /// stays, undecided, in the folder held, whose next set throws it away.
    Moved(WriteError),
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
    WriteError::new(
        dir,
        set_steps::KILLED,
        io::Error::other("killed (injected by a test)"),
        set_steps::KEPT_RECOVERABLE,
    )
}

const UNTOUCHED: &str = set_steps::KEPT_FOLDER;

/// Writes `set` into the folder `dir` (created if missing) as one: the folder ends with
/// the whole new set, or, on any failure, exactly the files it had. Files already in `dir`
/// for which `belongs` is true are the old set: they are replaced, or removed when the new
/// set has no file of that name. Other files in `dir` are never touched, and a name of the
/// set that is not a regular file there (a link, a folder) refuses the set before anything
/// is written. What a killed earlier writer left in `dir` is recovered first
/// ([`recover`]); the messages returned name what was left as it is there.
pub fn write_set(dir: &Path, set: &FileSet, belongs: impl Fn(&str) -> bool) -> Result<Vec<String>, WriteError> {
    let held = hold_folder(dir)?;
    write_set_held(&held, set, belongs)
}

/// The folder `dir`, made if missing and locked against every other phonglab writing into
/// it ([`crate::platform::os::lock_folder`]) until this is dropped: a writer that checks
/// what the folder holds (a file it did not write) and then writes takes it before the
/// check, so that no other run changes the folder between the two ([`write_set_held`]).
/// What a stopped writer left in it is finished or undone when it is held ([`recover`]),
/// so that the check judges the folder's files as they are after that.
pub struct HeldFolder {
    dir: std::path::PathBuf,
    /// The folder's identity when it was held: checked again just before the swap.
    id: Identity,
    /// What the recovery left as it is, said by [`write_set_held`].
    recovered: Vec<String>,
    _lock: crate::platform::os::FolderLock,
}

impl HeldFolder {
    /// The folder held.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}

/// Makes the folder `dir` if missing and takes its lock ([`HeldFolder`]), saying once on
/// the terminal that it waits where another phonglab holds it, then finishes or undoes
/// what a stopped writer left there (issue 59: a set stopped after its swap was decided
/// left the new set in place and the list of what phonglab wrote naming the old one, so a
/// check made before the recovery blamed the teacher for phonglab's own files). Refuses a
/// link or a file at `dir`, and records that are not phonglab's
/// ([`super::set_journal::check_records`]).
pub fn hold_folder(dir: &Path) -> Result<HeldFolder, WriteError> {
    // A set is written into a real folder only: one planted as a link (an oF project's
    // `src` pointing elsewhere) would send the set, and the old set's removal, outside it.
    // (Windows: a folder reached under another name than its own, `platform::links`.)
    if crate::platform::links::reached_through_link(dir) {
        let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-folder-is-a-link"));
        return Err(WriteError::new(dir, "write-step-create-folder", e, UNTOUCHED));
    }
    // A name Windows cannot keep (`set ` made `set`, then failed, leaving it: #53).
    super::atomic_write::refuse_unkept(dir)?;
    // A file of that name: `create_dir_all` would say only "it already exists".
    if std::fs::metadata(dir).is_ok_and(|m| !m.is_dir()) {
        let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-folder-is-a-file"));
        return Err(WriteError::new(dir, "write-step-create-folder", e, UNTOUCHED));
    }
    std::fs::create_dir_all(dir).map_err(|e| WriteError::new(dir, "write-step-create-folder", e, UNTOUCHED))?;
    let lock = crate::platform::os::lock_folder(dir, || say_waiting(dir))
        .map_err(|e| WriteError::new(dir, set_steps::LOCK_FOLDER, e, UNTOUCHED))?;
    let (_, id) = Identity::at(dir).map_err(|e| WriteError::new(dir, set_steps::LOCK_FOLDER, e, UNTOUCHED))?;
    super::set_journal::check_records(dir)?;
    let recovered =
        super::set_journal::recover_locked(dir).map_err(|e| WriteError::new(dir, set_steps::RECOVER, e, UNTOUCHED))?;
    Ok(HeldFolder { dir: dir.to_path_buf(), id, recovered, _lock: lock })
}

/// [`write_set`] into a folder this process already holds ([`hold_folder`]).
pub fn write_set_held(
    held: &HeldFolder,
    set: &FileSet,
    belongs: impl Fn(&str) -> bool,
) -> Result<Vec<String>, WriteError> {
    let dir = held.dir();
    super::set_journal::check_records(dir)?;
    // Recovered when the folder was held, before the caller judged its files.
    let notices = held.recovered.clone();
    refuse_unwritable_names(dir, set)?;
    let staging = new_staging(dir)?;
    match stage_and_swap(held, &staging, set, &belongs) {
        Ok(left) => Ok(notices.into_iter().chain(left).collect()),
        Err(Stop::Killed) => Err(killed(dir)),
        Err(Stop::Moved(e)) => Err(e),
        Err(Stop::Failed(e)) => {
            let _ = std::fs::remove_dir_all(&staging);
            Err(e)
        }
    }
}

/// The first file of `set` that `dir` holds as a regular file whose bytes are neither what
/// phonglab wrote there (named with its size and hash in the folder's list of what it
/// wrote, [`super::set_journal::WRITTEN`]; see [`super::set_journal::written_as_is`]) nor
/// the new one's: a key the teacher edited, a file of theirs with a set's name. A set
/// replaces only its own earlier files, so its writer refuses before anything is written.
/// Each file is read without following a link (a link is refused by [`write_set`]); one
/// that cannot be read is said with why ([`Foreign::Unreadable`]: another program holds
/// it open, on Windows), never taken for a file phonglab did not write.
pub fn foreign_file(dir: &Path, set: &FileSet) -> Option<Foreign> {
    use super::set_journal::{hash_bytes, written_as_is};
    let written = super::set_journal::written_list(dir);
    set.files.iter().find_map(|(name, bytes)| {
        let path = dir.join(name);
        if !std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file())
            || crate::platform::links::reached_through_link(&path)
        {
            return None;
        }
        let now = match entry_of(dir, name) {
            Ok(now) => now,
            Err(e) => return Some(Foreign::Unreadable(path.clone(), held_open(e, &path))),
        };
        let same = now.size == bytes.len() as u64 && now.hash == hash_bytes(bytes);
        (!written_as_is(&written, &now) && !same).then_some(Foreign::NotOurs(path))
    })
}

/// A file of a set in the way of a new one ([`foreign_file`]).
#[derive(Debug)]
pub enum Foreign {
    /// Neither what phonglab wrote there nor the new set's bytes.
    NotOurs(std::path::PathBuf),
    /// Not read, for this reason.
    Unreadable(std::path::PathBuf, io::Error),
}

/// `e`, from reading or moving `path`, as [`io::ErrorKind::ResourceBusy`] where it is
/// Windows' refusal of a file another program holds open (`ERROR_SHARING_VIOLATION`,
/// `ERROR_LOCK_VIOLATION`, or `ERROR_ACCESS_DENIED` on a file that is not read-only), with
/// whatever sharing it holds it (a PDF viewer shares reading: the set's move of it aside
/// is refused), so that it is said as the replace of a single file says it ("another
/// program has it open"), never in the system's raw English (issue 59).
fn held_open(e: io::Error, path: &Path) -> io::Error {
    let held = cfg!(windows)
        && match e.raw_os_error() {
            Some(32 | 33) => true,
            Some(5) => std::fs::metadata(path).is_ok_and(|m| !m.permissions().readonly()),
            _ => false,
        };
    if held { io::Error::new(io::ErrorKind::ResourceBusy, e) } else { e }
}

/// Makes this writer's staging folder in `dir`: a name nothing has, made by `mkdir`, which
/// fails on anything already there (a planted folder or link of the same name is passed
/// over for the next name).
fn new_staging(dir: &Path) -> Result<std::path::PathBuf, WriteError> {
    let mut tries = 0;
    loop {
        let staging = temporary_name(dir, STAGING);
        match std::fs::create_dir(&staging) {
            Ok(()) => return Ok(staging),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && tries < 100 => tries += 1,
            Err(e) => return Err(WriteError::new(dir, set_steps::CREATE_STAGING, e, UNTOUCHED)),
        }
    }
}

/// Refuses a set with a name that is not a plain file name, or whose place in `dir` holds
/// something other than a regular file (a link stays a link: a set cannot be swapped in
/// through one).
fn refuse_unwritable_names(dir: &Path, set: &FileSet) -> Result<(), WriteError> {
    for (name, _) in &set.files {
        let target = dir.join(name);
        if !plain_name(name) {
            let e = io::Error::new(io::ErrorKind::InvalidFilename, "not a plain file name");
            return Err(WriteError::new(&target, "write-step-name", e, UNTOUCHED));
        }
        if std::fs::symlink_metadata(&target).is_ok_and(|m| !m.is_file())
            || crate::platform::links::reached_through_link(&target)
        {
            let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("write-not-a-regular-file"));
            return Err(WriteError::new(&target, "write-step-create", e, UNTOUCHED));
        }
    }
    Ok(())
}

/// Says once, on the terminal, that this run waits for another phonglab writing into `dir`
/// (which holds the folder's lock): a wait with nothing said looks like a hang.
fn say_waiting(dir: &Path) {
    let dir = super::reasons::shown(dir);
    eprintln!("phonglab: {}", phonglab_core::escape::terminal::lines(&crate::t!("set-waiting-for-lock", dir = dir)));
}

/// Finishes or throws away what a killed writer of a set left in `dir` (with a journal
/// that has decided, the swap is finished; without, the staging folder is removed), acting
/// only on what phonglab wrote; returns a message for each thing left as it is. Takes the
/// folder's lock, so a writer still at work is waited for, never disturbed.
pub fn recover(dir: &Path) -> io::Result<Vec<String>> {
    let _lock = crate::platform::os::lock_folder(dir, || say_waiting(dir))?;
    super::set_journal::recover_locked(dir)
}

fn stage_and_swap(
    held: &HeldFolder,
    staging: &Path,
    set: &FileSet,
    belongs: &dyn Fn(&str) -> bool,
) -> Result<Option<String>, Stop> {
    let dir = held.dir();
    let (_, here) = Identity::at(staging).map_err(|e| WriteError::new(dir, set_steps::CREATE_STAGING, e, UNTOUCHED))?;
    let mut journal = Journal { staging: here, decided: false, new: Vec::new(), old: Vec::new() };
    write_journal(staging, &journal, false).map_err(|(what, e)| WriteError::new(dir, what, e, UNTOUCHED))?;
    step()?;
    for (name, bytes) in &set.files {
        journal.new.push(
            stage(staging, name, bytes).map_err(|(what, e)| WriteError::new(&dir.join(name), what, e, UNTOUCHED))?,
        );
        step()?;
    }
    crate::platform::os::sync_folder(staging);
    journal.old = old_set(dir, &journal.new, belongs)?;
    step()?;
    refuse_moved_folder(held)?;
    journal.decided = true;
    write_journal(staging, &journal, true).map_err(|(what, e)| WriteError::new(dir, what, e, UNTOUCHED))?;
    step()?;
    swap(dir, staging, &journal)?;
    // The list of what this set wrote, for the next one, while the journal still stands (a
    // kill before it is finished by the recovery, which writes it too).
    super::set_journal::write_written_list(dir, staging, &journal.new);
    // The old files first, with the journal still there: a kill now is finished by the
    // next run, and one after leaves an empty folder, which the next run removes.
    // A clean-up refused now (Windows: an old file another program holds open, sharing its
    // deletion, stays in the staging folder until it lets go) does not fail the run: the new
    // set is in place and recorded, and the journal, kept, lets the next run finish.
    let cleaned =
        std::fs::remove_dir_all(staging.join(ASIDE)).and_then(|()| std::fs::remove_file(staging.join(JOURNAL)));
    step()?;
    let _ = std::fs::remove_dir(staging);
    crate::platform::os::sync_folder(dir);
    Ok(cleaned.is_err().then(|| staging_left(dir, staging)))
}

/// The note for a staging folder whose clean-up was refused after the new set was placed
/// (Windows: "directory not empty", a file in it held open): the set is in the folder, and
/// the next run removes what is left.
fn staging_left(dir: &Path, staging: &Path) -> String {
    let name = phonglab_core::escape::terminal::text(&staging.file_name().unwrap_or_default().to_string_lossy());
    crate::t!("set-staging-left", dir = super::reasons::shown(dir), name = name)
}

/// Refuses the swap when the folder at the held folder's path is no longer the folder held
/// (its identity, or a link there): moved and replaced by a link to another set's folder
/// while the set was written (issue 59, #27), the new set would go through the link.
fn refuse_moved_folder(held: &HeldFolder) -> Result<(), Stop> {
    let dir = held.dir();
    let same = Identity::at(dir).is_ok_and(|(meta, id)| meta.is_dir() && id == held.id);
    if same && !crate::platform::links::reached_through_link(dir) {
        return Ok(());
    }
    let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-folder-replaced"));
    Err(Stop::Moved(WriteError::new(dir, set_steps::LIST, e, set_steps::KEPT_FOLDER)))
}

/// The old set in `dir`: every regular file the new one replaces, and every other member
/// of it, each as the journal names it.
fn old_set(dir: &Path, new: &[Entry], belongs: &dyn Fn(&str) -> bool) -> Result<Vec<Entry>, WriteError> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| WriteError::new(dir, set_steps::LIST, e, set_steps::KEPT_FOLDER))?;
    // A member of the old set that the new one lacks goes only when phonglab wrote it and
    // it is unchanged since: a file that merely has a set's kind of name is never removed.
    let written = super::set_journal::written_list(dir);
    let ours = |name: &str| {
        belongs(name) && written.iter().any(|e| e.name == name && super::set_journal::is_entry(&dir.join(name), e))
    };
    let mut old = Vec::new();
    for entry in entries.flatten() {
        let Ok(name) = entry.file_name().into_string() else { continue };
        let is_file = entry.file_type().is_ok_and(|t| t.is_file())
            && !crate::platform::links::reached_through_link(&dir.join(&name));
        if is_file && plain_name(&name) && (new.iter().any(|e| e.name == name) || ours(&name)) {
            old.push(
                entry_of(dir, &name).map_err(|e| WriteError::new(&dir.join(&name), set_steps::LIST, e, UNTOUCHED))?,
            );
        }
    }
    old.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(old)
}

/// Step 4: the old files aside (into the staging folder's aside folder), the new ones into
/// place, where nothing is. A refused rename moves everything back (the new files into the
/// staging folder, so a journal left by a kill during the undo still finds them).
fn swap(dir: &Path, staging: &Path, j: &Journal) -> Result<(), Stop> {
    let aside = staging.join(ASIDE);
    let mut moved_aside: Vec<&str> = Vec::new();
    let mut moved_in: Vec<&str> = Vec::new();
    let undo = |moved_aside: &[&str], moved_in: &[&str]| {
        for name in moved_in {
            let _ = std::fs::rename(dir.join(name), staging.join(name));
        }
        for name in moved_aside {
            let _ = crate::platform::os::rename_no_replace(&aside.join(name), &dir.join(name));
        }
        crate::platform::os::sync_folder(dir);
    };
    if let Err(e) = std::fs::create_dir(&aside) {
        return Err(WriteError::new(dir, set_steps::CREATE_STAGING, e, UNTOUCHED).into());
    }
    for old in &j.old {
        if let Err(e) = rename_no_replace(&dir.join(&old.name), &aside.join(&old.name)) {
            undo(&moved_aside, &moved_in);
            let e = held_open(e, &dir.join(&old.name));
            return Err(WriteError::new(&dir.join(&old.name), "write-step-rename", e, UNTOUCHED).into());
        }
        moved_aside.push(&old.name);
        step()?;
    }
    for new in &j.new {
        if let Err(e) = rename_no_replace(&staging.join(&new.name), &dir.join(&new.name)) {
            undo(&moved_aside, &moved_in);
            let e = held_open(e, &staging.join(&new.name));
            return Err(WriteError::new(&dir.join(&new.name), "write-step-rename", e, UNTOUCHED).into());
        }
        moved_in.push(&new.name);
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
    use crate::io::atomic_write::tests::{FAULTS, temp_dir};
    use crate::io::atomic_write::with_fault;

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
        crate::io::atomic_write::tests::listing(dir)
            .into_iter()
            .filter(|(n, _)| !n.starts_with(".phonglab-set"))
            .collect()
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
            for (name, bytes) in &new_set().files {
                j.new.push(stage(&staging, name, bytes).unwrap());
            }
            j.old = ["a.md", "b.md", "c.md"].iter().map(|n| entry_of(&dir, n).unwrap()).collect();
            write_journal(&staging, &j, false).unwrap();
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
}
