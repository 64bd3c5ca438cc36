//! Sets of files written as one.
//!
//! A set of files that belong together (an exercise set, a cost report, an openFrameworks
//! project: [`write_set`]) is swapped in so that at every instant either the old set or the new one is whole, even
//! when the process is killed:
//! 1. a staging folder, `.phonglab-set.<pid>.<n>.tmp`, is made in the target folder, and a
//!    journal in it (`.phonglab-set.journal`) naming the folder itself;
//! 2. the new set is written whole into the staging folder, and synced;
//! 3. the folder and the staging folder are checked to be still at their paths (their
//!    identities, and no link at their names): one moved away and replaced by a link
//!    meanwhile refuses the set (asked again before each move of step 5, which is then
//!    undone). Nothing goes through such a link meanwhile: the folder, the staging folder
//!    and its aside folder are held by a handle, and every file is made, written, moved and
//!    removed through those handles ([`crate::platform::held_dir`]);
//! 4. the journal is written again, whole (a temporary file renamed), naming the new set's
//!    files and the old set's, each with its size, hash and identity: from this instant the
//!    new set is decided, and it is whole (in the staging folder, or already in place);
//! 5. the old set's files are moved aside into the staging folder and the new ones renamed
//!    into place, where nothing is (each rename happens or does not);
//! 6. the old files, the journal and the staging folder are removed.
//!
//! Every move and removal of step 5 and 6, of their undo and of the recovery is of the very
//! file the journal names, checked through the handle that moves or removes it
//! ([`super::set_journal::move_entry`], [`super::set_journal::remove_entry`]): a link or
//! another file put at a name meanwhile is left where it is, and the set is undone.
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

use super::atomic_write::{Fault, WriteError, fault, next_step, rename_fault, set_steps, temporary_name};
use super::set_journal::{
    ASIDE, Entry, Identity, Journal, STAGING, Took, entry_in, entry_of, is_entry_in, move_entry, plain_name, stage,
    write_journal,
};
use crate::platform::held_dir::HeldDir;

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
    at_step();
    let Some(Fault::KilledAtStep(n)) = fault() else { return Ok(()) };
    if next_step() == n { Err(Killed) } else { Ok(()) }
}

/// Why a set's swap stopped: an error to report (after the clean-up), or a kill (nothing
/// more runs).
enum Stop {
    Failed(WriteError),
    Killed,
    /// Refused with no clean-up: the folder is no longer the one held (moved, or replaced
    /// by a link), so the staging folder's path now leads elsewhere (it stays, undecided,
    /// in the folder held, whose next set throws it away); or an undo could not put every
    /// old file back (they stay in the staging folder, with the decided journal, for the
    /// next run).
    Left(WriteError),
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

/// A set refused before anything was written: at `path`, at the step `what` (a message id),
/// for `why` (in words); the folder is as it was.
fn refused(path: &Path, what: &'static str, why: String) -> WriteError {
    WriteError::new(path, what, io::Error::new(io::ErrorKind::InvalidInput, why), UNTOUCHED)
}

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
    /// The folder itself, held by a handle ([`HeldDir`]): the staging folder is made in it,
    /// and every file moved into or out of it, through that handle, so that the folder
    /// renamed and replaced by a link meanwhile is never written through (issue 59, F4).
    held: HeldDir,
    /// What the recovery left as it is, said by [`write_set_held`].
    recovered: Vec<String>,
    _lock: crate::platform::os::FolderLock,
}

impl HeldFolder {
    /// The folder held.
    pub fn dir(&self) -> &Path {
        self.held.path()
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
        return Err(refused(dir, "write-step-create-folder", crate::t!("set-folder-is-a-link")));
    }
    // A name Windows cannot keep (`set ` made `set`, then failed, leaving it: #53).
    super::atomic_write::refuse_unkept(dir)?;
    // A file of that name: `create_dir_all` would say only "it already exists".
    if std::fs::metadata(dir).is_ok_and(|m| !m.is_dir()) {
        return Err(refused(dir, "write-step-create-folder", crate::t!("set-folder-is-a-file")));
    }
    std::fs::create_dir_all(dir).map_err(|e| WriteError::new(dir, "write-step-create-folder", e, UNTOUCHED))?;
    let lock = crate::platform::os::lock_folder(dir, || say_waiting(dir))
        .map_err(|e| WriteError::new(dir, set_steps::LOCK_FOLDER, e, UNTOUCHED))?;
    let held = HeldDir::open(dir).map_err(|e| {
        if crate::platform::os::is_link_refused(&e) || e.kind() == io::ErrorKind::NotADirectory {
            refused(dir, "write-step-create-folder", crate::t!("set-folder-is-a-link"))
        } else {
            WriteError::new(dir, set_steps::LOCK_FOLDER, e, UNTOUCHED)
        }
    })?;
    super::set_journal::check_records(dir)?;
    let recovered = super::set_journal::recover_locked(&held)
        .map_err(|e| WriteError::new(dir, set_steps::RECOVER, e, UNTOUCHED))?;
    Ok(HeldFolder { held, recovered, _lock: lock })
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
    let staging = new_staging(&held.held)?;
    match stage_and_swap(held, &staging, set, &belongs) {
        Ok(cleaned) => {
            // Where it is now (Windows: a Unix program may have renamed it, under Wine).
            let at = held.held.now_in(&staging).unwrap_or_else(|| staging.path().to_path_buf());
            let name = at.file_name().unwrap_or_default().to_string_lossy().into_owned();
            // The staging folder, empty, removed through the folder held (where someone
            // renamed it within the folder meanwhile, at its new name: found by identity).
            if cleaned {
                let _ = super::set_journal::remove_own_folder(&held.held, staging);
            }
            held.held.sync();
            Ok(notices.into_iter().chain((!cleaned).then(|| staging_left(dir, &name))).collect())
        }
        Err(Stop::Killed) => Err(killed(dir)),
        Err(Stop::Left(e)) => Err(e),
        Err(Stop::Failed(e)) => {
            super::set_journal::throw_away(&held.held, staging);
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
fn new_staging(dir: &HeldDir) -> Result<HeldDir, WriteError> {
    let mut tries = 0;
    loop {
        let name = temporary_name(Path::new(""), STAGING);
        match dir.create_dir(name.as_os_str()) {
            Ok(staging) => return Ok(staging),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && tries < 100 => tries += 1,
            Err(e) => return Err(staging_error(dir, &name.to_string_lossy(), e)),
        }
    }
}

/// Why a working folder (`name`, a staging folder or its aside folder) could not be made
/// in the folder held `dir`, in words: one made, then renamed and replaced by a link before
/// it was held, or a link put where it was being made (under Wine a Unix program can: the
/// system says only "The filename cannot be resolved. (os error 1921)"), is said as a link
/// that changed while phonglab wrote.
fn staging_error(dir: &HeldDir, name: &str, e: io::Error) -> WriteError {
    let e = if crate::platform::os::is_link_refused(&e) || e.kind() == io::ErrorKind::NotADirectory {
        let shown = phonglab_core::escape::terminal::text(name);
        io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-staging-taken", name = shown))
    } else {
        e
    };
    WriteError::new(dir.path(), set_steps::CREATE_STAGING, e, UNTOUCHED)
}

/// Refuses a set with a name that is not a plain file name, or whose place in `dir` holds
/// something other than a regular file (a link stays a link: a set cannot be swapped in
/// through one).
fn refuse_unwritable_names(dir: &Path, set: &FileSet) -> Result<(), WriteError> {
    refuse_names_differing_in_case(dir, set)?;
    for (name, _) in &set.files {
        let target = dir.join(name);
        if !plain_name(name) {
            let e = io::Error::new(io::ErrorKind::InvalidFilename, "not a plain file name");
            return Err(WriteError::new(&target, "write-step-name", e, UNTOUCHED));
        }
        if std::fs::symlink_metadata(&target).is_ok_and(|m| !m.is_file())
            || crate::platform::links::reached_through_link(&target)
        {
            return Err(refused(&target, "write-step-create", crate::t!("write-not-a-regular-file")));
        }
    }
    Ok(())
}

/// Refuses a set one of whose names is in `dir` under another case too (`Exercise-01.md`
/// beside `exercise-01.md`): Windows, and Wine, take the two for one file, so a swap could
/// move or replace the wrong one (issue 59: a failed run under Wine lost phonglab's own
/// `exercise-01.md` and said "the folder is unchanged"). On every system, since the folder
/// is opened on the lab's Windows PCs.
fn refuse_names_differing_in_case(dir: &Path, set: &FileSet) -> Result<(), WriteError> {
    let Ok(entries) = std::fs::read_dir(dir) else { return Ok(()) };
    let here: Vec<String> = entries.flatten().filter_map(|e| e.file_name().into_string().ok()).collect();
    for (name, _) in &set.files {
        let folded = name.to_lowercase();
        if let Some(other) = here.iter().find(|h| *h != name && h.to_lowercase() == folded) {
            use phonglab_core::escape::terminal::text;
            let why = crate::t!("set-name-differs-in-case", other = text(other), name = text(name));
            return Err(refused(&dir.join(other), "write-step-name", why));
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
    super::set_journal::recover_locked(&HeldDir::open(dir)?)
}

/// Stages the set in `staging` (held), decides the journal and swaps the set in, every
/// step through the folders' handles; `Ok(true)`: done and cleaned up, the staging folder
/// empty; `Ok(false)`: done, but the clean-up was refused (the note of [`staging_left`]).
fn stage_and_swap(
    held: &HeldFolder,
    staging: &HeldDir,
    set: &FileSet,
    belongs: &dyn Fn(&str) -> bool,
) -> Result<bool, Stop> {
    let dir = held.dir();
    let (_, here) = Identity::of_file(staging.handle())
        .map_err(|e| WriteError::new(dir, set_steps::CREATE_STAGING, e, UNTOUCHED))?;
    let mut journal = Journal { staging: here, decided: false, new: Vec::new(), old: Vec::new() };
    write_journal(staging, &journal, false).map_err(|(what, e)| WriteError::new(dir, what, e, UNTOUCHED))?;
    step()?;
    for (name, bytes) in &set.files {
        journal.new.push(
            stage(staging, name, bytes).map_err(|(what, e)| WriteError::new(&dir.join(name), what, e, UNTOUCHED))?,
        );
        step()?;
    }
    staging.sync();
    journal.old = old_set(&held.held, &journal.new, belongs)?;
    step()?;
    refuse_moved(held, staging)?;
    journal.decided = true;
    write_journal(staging, &journal, true).map_err(|(what, e)| WriteError::new(dir, what, e, UNTOUCHED))?;
    step()?;
    swap(held, staging, &journal)?;
    // The list of what this set wrote, for the next one, while the journal still stands (a
    // kill before it is finished by the recovery, which writes it too).
    super::set_journal::write_written_list(&held.held, staging, &journal.new);
    // The old files first, with the journal still there: a kill now is finished by the
    // next run, and one after leaves an empty folder, which the next run removes.
    // A clean-up refused now (Windows: an old file another program holds open, sharing its
    // deletion, stays in the staging folder until it lets go) does not fail the run: the new
    // set is in place and recorded, and the journal, kept, lets the next run finish.
    let cleaned = super::set_journal::clear_aside(staging, &journal.old);
    step()?;
    Ok(cleaned)
}

/// The note for a staging folder whose clean-up was refused after the new set was placed
/// (Windows: "directory not empty", a file in it held open): the set is in the folder, and
/// the next run removes what is left.
fn staging_left(dir: &Path, name: &str) -> String {
    let name = phonglab_core::escape::terminal::text(name);
    crate::t!("set-staging-left", dir = super::reasons::shown(dir), name = name)
}

/// Why the swap cannot go on where the folder or its staging folder is no longer at its
/// path (its identity, or a link there): moved and replaced by a link to another folder
/// while the set was written (issue 59, #27, F4, the hostile's review). Nothing was written
/// through the link (every step goes through the folders held), but the teacher would not
/// find the set where they asked for it: the set is refused, and undone. `None`: all are
/// where they were. Windows (a Unix program under Wine can rename a folder Windows holds)
/// says what it checked instead: each step by path asked first that the folder was the one
/// held ([`HeldDir::unmoved`]), and where the working folder is now (issue 59, round 2).
fn moved(held: &HeldFolder, staging: &HeldDir, aside: Option<&HeldDir>) -> Option<(std::path::PathBuf, String)> {
    let dir = held.dir();
    if !held.held.still_at_its_path() || crate::platform::links::reached_through_link(dir) {
        let why = if cfg!(windows) { crate::t!("set-folder-replaced-asked") } else { crate::t!("set-folder-replaced") };
        return Some((dir.to_path_buf(), why));
    }
    let name = |d: &HeldDir| d.path().file_name().unwrap_or_default().to_string_lossy().into_owned();
    let (parent, gone) = if !staging.still_at_its_path() || crate::platform::links::reached_through_link(staging.path())
    {
        (&held.held, staging)
    } else if let Some(aside) = aside.filter(|a| !a.still_at_its_path()) {
        (staging, aside)
    } else {
        return None;
    };
    let shown = phonglab_core::escape::terminal::text(&name(gone));
    if !cfg!(windows) {
        return Some((dir.to_path_buf(), crate::t!("set-staging-replaced", name = shown)));
    }
    let now = match parent.now_in(gone) {
        Some(at) => crate::t!("set-staging-now-at", path = super::reasons::shown(&at)),
        None => crate::t!("set-staging-now-gone"),
    };
    Some((dir.to_path_buf(), crate::t!("set-staging-replaced-asked", name = shown, now = now)))
}

/// Refuses the swap before it is decided where the folder or its staging folder moved
/// ([`moved`]): the staging folder is thrown away through its handle, so the folder is as
/// it was.
fn refuse_moved(held: &HeldFolder, staging: &HeldDir) -> Result<(), Stop> {
    match moved(held, staging, None) {
        None => Ok(()),
        Some((at, why)) => {
            let e = io::Error::new(io::ErrorKind::InvalidInput, why);
            Err(Stop::Failed(WriteError::new(&at, set_steps::LIST, e, set_steps::KEPT_FOLDER)))
        }
    }
}

/// The old set in the folder held `dir`: every regular file the new one replaces, and every
/// other member of it, each as the journal names it; listed and read through the folder's
/// handle.
fn old_set(dir: &HeldDir, new: &[Entry], belongs: &dyn Fn(&str) -> bool) -> Result<Vec<Entry>, WriteError> {
    let at = dir.path();
    let names = dir.names().map_err(|e| WriteError::new(at, set_steps::LIST, e, set_steps::KEPT_FOLDER))?;
    // A member of the old set that the new one lacks goes only when phonglab wrote it and
    // it is unchanged since: a file that merely has a set's kind of name is never removed.
    let written = super::set_journal::written_list_in(dir);
    let ours = |name: &str| belongs(name) && written.iter().any(|e| e.name == name && is_entry_in(dir, e));
    let mut old = Vec::new();
    for name in names.into_iter().filter_map(|n| n.into_string().ok()) {
        let is_file = dir.is_file(std::ffi::OsStr::new(&name));
        if is_file && plain_name(&name) && (new.iter().any(|e| e.name == name) || ours(&name)) {
            old.push(
                entry_in(dir, &name).map_err(|e| WriteError::new(&at.join(&name), set_steps::LIST, e, UNTOUCHED))?,
            );
        }
    }
    old.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(old)
}

/// Step 4: the old files aside (into the staging folder's aside folder), the new ones into
/// place, where nothing is, every move between folders held ([`HeldDir`]). A refused rename
/// moves everything back (the new files into the staging folder, so a journal left by a
/// kill during the undo still finds them), and so does the folder or its staging folder
/// found moved ([`moved`], asked before each move and after the last).
///
/// Each file moves only when it is, right then, the file the journal names
/// ([`super::set_journal::move_entry`], checked through the handle that moves it): an old
/// file replaced meanwhile (by a link to a file outside the folder, or another file) is left
/// where it is and the set is undone (issue 59: under Wine a link moved by its name took
/// the file it named into the aside folder, which was then removed).
fn swap(held: &HeldFolder, staging: &HeldDir, j: &Journal) -> Result<(), Stop> {
    let (dir, path) = (&held.held, held.dir());
    let aside =
        staging.create_dir(std::ffi::OsStr::new(ASIDE)).map_err(|e| Stop::Failed(staging_error(dir, ASIDE, e)))?;
    let mut moved_aside: Vec<&Entry> = Vec::new();
    let mut moved_in: Vec<&Entry> = Vec::new();
    // Every file moved back: `false` where one could not be (something put at its name).
    let undo = |moved_aside: &[&Entry], moved_in: &[&Entry]| {
        // Windows works by path: a working folder a Unix program renamed within the set's
        // folder (under Wine) is worked in at its new name, found by its identity.
        let staging_now = (cfg!(windows) && !staging.still_at_its_path()).then(|| dir.found_again(staging)).flatten();
        let staging_at = staging_now.as_ref().unwrap_or(staging);
        let aside_now = (cfg!(windows) && !aside.still_at_its_path()).then(|| staging_at.found_again(&aside)).flatten();
        let aside_at = aside_now.as_ref().unwrap_or(&aside);
        let mut all = true;
        for new in moved_in {
            all &= matches!(move_entry(dir, staging_at, new), Ok(Took::Done));
        }
        for old in moved_aside {
            all &= matches!(move_entry(aside_at, dir, old), Ok(Took::Done));
        }
        dir.sync();
        all
    };
    // The refusal, said truly: the folder as it was, or (an undo incomplete) nothing deleted
    // and the files not put back kept in the staging folder with the decided journal.
    let refused = |at: &Path, e: io::Error, undone: bool| {
        if undone {
            Stop::Failed(WriteError::new(at, "write-step-rename", e, UNTOUCHED))
        } else {
            Stop::Left(WriteError::new(at, "write-step-rename", e, set_steps::KEPT_STAGING))
        }
    };
    let gone =
        || moved(held, staging, Some(&aside)).map(|(at, why)| (at, io::Error::new(io::ErrorKind::InvalidInput, why)));
    for old in &j.old {
        meanwhile(&path.join(&old.name));
        if let Some((at, e)) = gone() {
            return Err(refused(&at, e, undo(&moved_aside, &moved_in)));
        }
        if let Err(e) = counted_move(dir, &aside, old) {
            return Err(refused(&path.join(&old.name), e, undo(&moved_aside, &moved_in)));
        }
        moved_aside.push(old);
        step()?;
    }
    for new in &j.new {
        if let Some((at, e)) = gone() {
            return Err(refused(&at, e, undo(&moved_aside, &moved_in)));
        }
        if let Err(e) = counted_move(staging, dir, new) {
            return Err(refused(&path.join(&new.name), e, undo(&moved_aside, &moved_in)));
        }
        moved_in.push(new);
        step()?;
    }
    if let Some((at, e)) = gone() {
        return Err(refused(&at, e, undo(&moved_aside, &moved_in)));
    }
    dir.sync();
    Ok(())
}

/// One move of the swap ([`super::set_journal::move_entry`]), a rename a test may make fail
/// ([`Fault::OnRename`]): `Err` with why, in words, where the file is not the one the
/// journal names (or is gone) or the system refused (another program holds it open).
fn counted_move(from: &HeldDir, to: &HeldDir, entry: &Entry) -> io::Result<()> {
    rename_fault()?;
    match move_entry(from, to, entry) {
        Ok(Took::Done) => Ok(()),
        Ok(Took::Absent | Took::Other) => {
            Err(io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-file-replaced-meanwhile")))
        }
        Err(e) => Err(held_open(e, &from.path().join(&entry.name))),
    }
}

/// Tests: something done to the folder, given the path of the old file about to move aside.
#[cfg(test)]
type Meanwhile = Box<dyn FnMut(&Path)>;

#[cfg(test)]
thread_local! {
    /// Tests: what another process does to the folder just before an old file is moved
    /// aside (after the journal decided), set by the tests' `meanwhile_at_aside`.
    static MEANWHILE: std::cell::RefCell<Option<Meanwhile>> = const { std::cell::RefCell::new(None) };
}

#[cfg(test)]
thread_local! {
    /// Tests: what another process does to the folder at each step of a set's swap (where
    /// [`step`] counts one), set by the tests' `meanwhile_at_each_step`.
    static AT_STEP: std::cell::RefCell<Option<Box<dyn FnMut()>>> = const { std::cell::RefCell::new(None) };
}

/// Runs the test's [`AT_STEP`]; nothing otherwise.
fn at_step() {
    #[cfg(test)]
    AT_STEP.with(|m| {
        if let Some(f) = m.borrow_mut().as_mut() {
            f();
        }
    });
}

/// Runs the test's [`MEANWHILE`] with the old file about to move aside; nothing otherwise.
fn meanwhile(old: &Path) {
    #[cfg(test)]
    MEANWHILE.with(|m| {
        if let Some(f) = m.borrow_mut().as_mut() {
            f(old);
        }
    });
    #[cfg(not(test))]
    let _ = old;
}

impl fmt::Display for FileSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.files.iter().map(|(n, _)| n.as_str()).collect();
        write!(f, "{}", names.join(", "))
    }
}

#[cfg(test)]
mod tests;
