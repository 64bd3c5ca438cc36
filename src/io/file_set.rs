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
    ASIDE, Entry, Identity, Journal, STAGING, Took, entry_of, move_entry, plain_name, stage, write_journal,
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
        Err(Stop::Left(e)) => Err(e),
        Err(Stop::Failed(e)) => {
            super::set_journal::throw_away(&staging);
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
    let cleaned = super::set_journal::clear_aside(staging, &journal.old);
    step()?;
    let _ = super::set_journal::remove_own_folder(staging);
    crate::platform::os::sync_folder(dir);
    Ok((!cleaned).then(|| staging_left(dir, staging)))
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
    Err(Stop::Left(WriteError::new(dir, set_steps::LIST, e, set_steps::KEPT_FOLDER)))
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
///
/// Each file moves only when it is, right then, the file the journal names
/// ([`super::set_journal::move_entry`], checked through the handle that moves it): an old
/// file replaced meanwhile (by a link to a file outside the folder, or another file) is left
/// where it is and the set is undone (issue 59: under Wine a link moved by its name took
/// the file it named into the aside folder, which was then removed).
fn swap(dir: &Path, staging: &Path, j: &Journal) -> Result<(), Stop> {
    let aside = staging.join(ASIDE);
    let mut moved_aside: Vec<&Entry> = Vec::new();
    let mut moved_in: Vec<&Entry> = Vec::new();
    // Every file moved back: `false` where one could not be (something put at its name).
    let undo = |moved_aside: &[&Entry], moved_in: &[&Entry]| {
        let mut all = true;
        for new in moved_in {
            all &= matches!(move_entry(&dir.join(&new.name), &staging.join(&new.name), new), Ok(Took::Done));
        }
        for old in moved_aside {
            all &= matches!(move_entry(&aside.join(&old.name), &dir.join(&old.name), old), Ok(Took::Done));
        }
        crate::platform::os::sync_folder(dir);
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
    if let Err(e) = std::fs::create_dir(&aside) {
        return Err(WriteError::new(dir, set_steps::CREATE_STAGING, e, UNTOUCHED).into());
    }
    for old in &j.old {
        meanwhile(&dir.join(&old.name));
        let (from, to) = (dir.join(&old.name), aside.join(&old.name));
        if let Err(e) = counted_move(&from, &to, old) {
            return Err(refused(&from, e, undo(&moved_aside, &moved_in)));
        }
        moved_aside.push(old);
        step()?;
    }
    for new in &j.new {
        let (from, to) = (staging.join(&new.name), dir.join(&new.name));
        if let Err(e) = counted_move(&from, &to, new) {
            return Err(refused(&to, e, undo(&moved_aside, &moved_in)));
        }
        moved_in.push(new);
        step()?;
    }
    crate::platform::os::sync_folder(dir);
    Ok(())
}

/// One move of the swap ([`super::set_journal::move_entry`]), a rename a test may make fail
/// ([`Fault::OnRename`]): `Err` with why, in words, where the file at `from` is not the one
/// the journal names (or is gone) or the system refused (another program holds it open).
fn counted_move(from: &Path, to: &Path, entry: &Entry) -> io::Result<()> {
    rename_fault()?;
    match move_entry(from, to, entry) {
        Ok(Took::Done) => Ok(()),
        Ok(Took::Absent | Took::Other) => {
            Err(io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-file-replaced-meanwhile")))
        }
        Err(e) => Err(held_open(e, from)),
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
