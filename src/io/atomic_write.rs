//! Every file phonglab writes is written whole or not at all: the one way to write a file.
//!
//! A single file ([`write()`]) goes to a temporary file in the target's own folder, which is
//! flushed, synced to the disk and closed with every error checked, then renamed over the
//! target. A rename within one folder either happens or does not, so the target holds the
//! old bytes or the new ones, never a part. A failure removes the temporary file, leaves
//! the target untouched, and says what failed.
//!
//! A set of files that belong together (an exercise set, a cost report: [`write_set`]) is
//! swapped in so that at every instant either the old set or the new one is whole, even
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
//! [`check_file_destination`] and [`check_folder_destination`] try the destination before
//! long work starts (`cost` runs for a quarter of a minute before it writes).
//!
//! Tests make the disk fail on purpose with [`with_fault`]: after N bytes, on the sync, on
//! the close or on a rename, on the calling thread only; and kill the writer of a set at
//! any step ([`Fault::KilledAtStep`]: nothing after that step runs, no clean-up, no undo).

use std::cell::Cell;
use std::fmt;
use std::fs::File;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Why a file could not be written. The message names the file and says that the old one
/// (or the old set) is untouched.
#[derive(Debug, thiserror::Error)]
pub struct WriteError {
    /// The file or folder that was to be written.
    pub path: PathBuf,
    /// The step that failed, as a message id: "write-step-create", "write-step-write",
    /// "write-step-sync", "write-step-close", "write-step-rename", ...
    pub what: &'static str,
    /// The system's reason (in the message, not a separate source, so it is said once).
    pub reason: io::Error,
    /// What the reader can rely on, as a message id: "write-kept-file" (the old file is
    /// unchanged), "write-kept-nothing", ...
    pub kept: &'static str,
}

impl fmt::Display for WriteError {
    /// "cannot write PATH: STEP: REASON; WHAT WAS KEPT", in the current language.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use phonglab_core::locale::tr;
        f.write_str(&phonglab_core::t!(
            "write-error",
            path = self.path.display().to_string(),
            what = tr(self.what),
            reason = crate::io::reasons::io_reason(&self.reason),
            kept = tr(self.kept)
        ))
    }
}

impl WriteError {
    fn new(path: &Path, what: &'static str, source: io::Error, kept: &'static str) -> Self {
        WriteError { path: path.to_path_buf(), what, reason: source, kept }
    }
}

/// A failure injected by tests (see [`with_fault`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// Writing fails once this many bytes of the file in hand have been written (a full
    /// disk): each file of a set starts counting again.
    AfterBytes(u64),
    /// Syncing a file to the disk fails (a write-back error).
    OnSync,
    /// Closing a file fails (NFS reports late errors there).
    OnClose,
    /// The n-th rename (from 0) fails: for a set, the journal's rename first, then the
    /// moves of the old files aside, then the moves of the new files into place.
    OnRename(u32),
    /// The writer of a set dies at its n-th step (from 0; [`write_set`] counts its steps):
    /// it returns at once, as a killed process would stop, leaving the folder as it is.
    KilledAtStep(u32),
}

thread_local! {
    static FAULT: Cell<Option<Fault>> = const { Cell::new(None) };
    static RENAMES: Cell<u32> = const { Cell::new(0) };
    static STEPS: Cell<u32> = const { Cell::new(0) };
}

/// Runs `f` with `fault` injected into every write on this thread (for tests).
pub fn with_fault<R>(fault: Fault, f: impl FnOnce() -> R) -> R {
    let before = FAULT.with(|c| c.replace(Some(fault)));
    RENAMES.with(|c| c.set(0));
    STEPS.with(|c| c.set(0));
    let r = f();
    FAULT.with(|c| c.set(before));
    r
}

fn fault() -> Option<Fault> {
    FAULT.with(Cell::get)
}

fn injected(what: &str) -> io::Error {
    io::Error::other(format!("{what} failed (injected by a test)"))
}

/// A file being written, counting bytes so a test can make the disk full at any point.
struct Counted {
    file: File,
    written: u64,
}

impl Write for Counted {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let buf = match fault() {
            Some(Fault::AfterBytes(n)) if self.written + buf.len() as u64 > n => {
                let room = n.saturating_sub(self.written) as usize;
                if room == 0 {
                    return Err(io::Error::new(io::ErrorKind::StorageFull, "no space left on device (injected)"));
                }
                &buf[..room]
            }
            _ => buf,
        };
        let n = self.file.write(buf)?;
        self.written += n as u64;
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file.flush()
    }
}

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// A name in `dir` for a temporary file or folder beside `name`, hidden and unique to this
/// process and call.
fn temporary_name(dir: &Path, name: &str) -> PathBuf {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    dir.join(format!(".{name}.{}.{n}.tmp", std::process::id()))
}

/// The folder a file path lives in (`.` for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

fn file_name_of(path: &Path) -> io::Result<String> {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidFilename, "not a file name"))
}

/// Closes `file`, reporting the close's own error (which `drop` would ignore).
fn close(file: File) -> io::Result<()> {
    if fault() == Some(Fault::OnClose) {
        return Err(injected("close"));
    }
    crate::platform::os::close_file(file)
}

/// Writes `bytes` to a new file at `tmp`: create, write, flush, sync, close, each checked.
/// On failure the file at `tmp` is removed and the failing step named.
fn write_new(tmp: &Path, bytes: &[u8]) -> Result<(), (&'static str, io::Error)> {
    let file = File::options().write(true).create_new(true).open(tmp).map_err(|e| ("write-step-create", e))?;
    let mut out = Counted { file, written: 0 };
    let result = (|| {
        out.write_all(bytes).map_err(|e| ("write-step-write", e))?;
        out.flush().map_err(|e| ("write-step-write", e))?;
        if fault() == Some(Fault::OnSync) {
            return Err(("write-step-sync", injected("sync")));
        }
        out.file.sync_all().map_err(|e| ("write-step-sync", e))?;
        close(out.file).map_err(|e| ("write-step-close", e))
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(tmp);
    }
    result
}

fn rename(from: &Path, to: &Path) -> io::Result<()> {
    if let Some(Fault::OnRename(n)) = fault() {
        let k = RENAMES.with(|c| {
            let k = c.get();
            c.set(k + 1);
            k
        });
        if k == n {
            return Err(injected("rename"));
        }
    }
    std::fs::rename(from, to)
}

/// Is `path` something that is written in place rather than replaced: a device, a pipe or
/// a socket (`-o /dev/null`, `-o /dev/stdout`)? Renaming a file over `/dev/null` would
/// replace the device with a file for every program on the machine.
pub fn written_in_place(path: &Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// Writes to a device or a pipe as it is (there is no old file to keep).
fn write_in_place(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-not-a-file";
    let mut f =
        File::options().write(true).open(path).map_err(|e| WriteError::new(path, "write-step-open", e, KEPT))?;
    f.write_all(bytes).and_then(|()| f.flush()).map_err(|e| WriteError::new(path, "write-step-write", e, KEPT))?;
    close(f).map_err(|e| WriteError::new(path, "write-step-close", e, KEPT))
}

/// Writes `bytes` to `path` whole or not at all (see the module's documentation). A
/// symbolic link is followed (the file it names is replaced, the link stays a link); a
/// device or a pipe is written in place.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-file";
    if written_in_place(path) {
        return write_in_place(path, bytes);
    }
    let resolved;
    let path = if std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink()) {
        resolved = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
        resolved.as_path()
    } else {
        path
    };
    let name = file_name_of(path).map_err(|e| WriteError::new(path, "write-step-name", e, "write-kept-nothing"))?;
    if path.is_dir() {
        let e = io::Error::new(io::ErrorKind::IsADirectory, "it is a folder");
        return Err(WriteError::new(path, "write-step-create", e, "write-kept-nothing"));
    }
    let dir = folder_of(path);
    let tmp = temporary_name(dir, &name);
    write_new(&tmp, bytes).map_err(|(what, e)| WriteError::new(path, what, e, KEPT))?;
    if let Err(e) = rename(&tmp, path) {
        let _ = std::fs::remove_file(&tmp);
        return Err(WriteError::new(path, "write-step-rename", e, KEPT));
    }
    crate::platform::os::sync_folder(dir);
    Ok(())
}

/// Checks, before long work, that a file can be created in `path`'s folder (by creating
/// and removing a temporary file there) and that `path` is not a folder.
pub fn check_file_destination(path: &Path) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-nothing";
    if written_in_place(path) {
        return File::options()
            .write(true)
            .open(path)
            .map(drop)
            .map_err(|e| WriteError::new(path, "write-step-open", e, KEPT));
    }
    let name = file_name_of(path).map_err(|e| WriteError::new(path, "write-step-name", e, KEPT))?;
    if path.is_dir() {
        return Err(WriteError::new(
            path,
            "write-step-create",
            io::Error::new(io::ErrorKind::IsADirectory, "it is a folder"),
            KEPT,
        ));
    }
    probe(folder_of(path), &name).map_err(|e| WriteError::new(path, "write-step-create", e, KEPT))
}

/// Checks, before long work, that the folder `dir` exists or can be made, and that files
/// can be created in it.
pub fn check_folder_destination(dir: &Path) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-nothing";
    std::fs::create_dir_all(dir).map_err(|e| WriteError::new(dir, "write-step-create-folder", e, KEPT))?;
    probe(dir, "probe").map_err(|e| WriteError::new(dir, "write-step-create-file-in", e, KEPT))
}

fn probe(dir: &Path, name: &str) -> io::Result<()> {
    let tmp = temporary_name(dir, name);
    File::options().write(true).create_new(true).open(&tmp)?;
    std::fs::remove_file(&tmp)
}

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
    let k = STEPS.with(|c| {
        let k = c.get();
        c.set(k + 1);
        k
    });
    if k == n { Err(Killed) } else { Ok(()) }
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

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("phonglab-atomic-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
        let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| {
                let e = e.unwrap();
                let bytes = if e.path().is_file() { std::fs::read(e.path()).unwrap() } else { b"<dir>".to_vec() };
                (e.file_name().to_string_lossy().into_owned(), bytes)
            })
            .collect();
        v.sort();
        v
    }

    const FAULTS: [Fault; 6] = [
        Fault::AfterBytes(0),
        Fault::AfterBytes(1),
        Fault::AfterBytes(4000),
        Fault::OnSync,
        Fault::OnClose,
        Fault::OnRename(0),
    ];

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let dir = temp_dir("one");
        let target = dir.join("out.png");
        std::fs::write(&target, b"the good old file").unwrap();
        let new = vec![7u8; 10_000];
        for fault in FAULTS {
            let e = with_fault(fault, || write(&target, &new)).unwrap_err();
            assert_eq!(std::fs::read(&target).unwrap(), b"the good old file", "{fault:?}");
            assert_eq!(listing(&dir).len(), 1, "{fault:?}: no temporary left: {:?}", listing(&dir));
            let msg = e.to_string();
            assert!(msg.contains("out.png") && msg.contains("unchanged"), "{msg}");
        }
        write(&target, &new).unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), new);
        assert_eq!(listing(&dir).len(), 1);
    }

    #[test]
    #[cfg(unix)]
    fn a_device_is_written_in_place_and_a_link_stays_a_link() {
        // Renaming over /dev/null would turn it into a file for the whole machine: it is
        // recognised as written in place (this test does not write to it).
        assert!(written_in_place(Path::new("/dev/null")));
        assert!(!written_in_place(Path::new("/tmp")));
        let dir = temp_dir("link");
        let real = dir.join("real.png");
        std::fs::write(&real, b"old").unwrap();
        let link = dir.join("link.png");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        assert!(!written_in_place(&link));
        write(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "still a link");
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        assert_eq!(listing(&dir).len(), 2, "no temporary left: {:?}", listing(&dir));
    }

    #[test]
    fn the_injected_fault_names_the_failing_step() {
        let dir = temp_dir("steps");
        let t = dir.join("a.txt");
        let step = |f| with_fault(f, || write(&t, b"abc")).unwrap_err().what;
        assert_eq!(step(Fault::AfterBytes(2)), "write-step-write");
        assert_eq!(step(Fault::OnSync), "write-step-sync");
        assert_eq!(step(Fault::OnClose), "write-step-close");
        assert_eq!(step(Fault::OnRename(0)), "write-step-rename");
        assert!(!t.exists(), "nothing was there, and nothing is");
    }

    #[test]
    fn a_folder_or_a_missing_folder_is_refused_before_work() {
        let dir = temp_dir("dest");
        assert!(check_file_destination(&dir).is_err(), "a folder is not a file");
        assert!(check_file_destination(&dir.join("missing/out.png")).is_err());
        check_file_destination(&dir.join("out.png")).unwrap();
        check_folder_destination(&dir.join("new/deeper")).unwrap();
        std::fs::write(dir.join("plain"), b"x").unwrap();
        assert!(check_folder_destination(&dir.join("plain")).is_err(), "a file is not a folder");
        assert!(check_folder_destination(Path::new("/proc/phonglab-cannot-be-here")).is_err());
        assert_eq!(listing(&dir).iter().filter(|(n, _)| n.ends_with(".tmp")).count(), 0);
    }

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
