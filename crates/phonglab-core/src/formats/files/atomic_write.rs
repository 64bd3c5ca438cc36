//! Every file phonglab writes is written whole or not at all: the one way to write a file.
//!
//! A single file ([`write()`]) goes to a temporary file in the target's own folder, which is
//! flushed, synced to the disk and closed with every error checked, then renamed over the
//! target. A rename within one folder either happens or does not, so the target holds the
//! old bytes or the new ones, never a part. A failure removes the temporary file, leaves
//! the target untouched, and says what failed. A set of files that belong together is
//! swapped in by the app's `io::file_set`, built on the steps here.
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
    /// "cannot write PATH: STEP: REASON; WHAT WAS KEPT", in the current language. A file
    /// whose folder is missing says which folder ("it does not exist" read as the file).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::formats::files::reasons::{io_reason, shown};
        use crate::locale::tr;
        let missing = |folder: &Path| !folder.as_os_str().is_empty() && std::fs::symlink_metadata(folder).is_err();
        let reason = match self.path.parent() {
            Some(folder) if self.reason.kind() == io::ErrorKind::NotFound && missing(folder) => {
                crate::t!("io-folder-missing", folder = shown(folder))
            }
            _ => io_reason(&self.reason),
        };
        f.write_str(&crate::t!(
            "write-error",
            path = shown(&self.path),
            what = tr(self.what),
            reason = reason,
            kept = tr(self.kept)
        ))
    }
}

/// The steps and outcomes of writing a set of files as one (the app's `io::file_set`), as
/// message ids: [`WriteError`]'s text looks its ids up in the core's catalogue, so these
/// are the core's messages whoever builds the error (an id the core lacked would be said
/// as it is: "…; write-kept-folder").
pub mod set_steps {
    /// Making the staging folder.
    pub const CREATE_STAGING: &str = "write-step-create-staging";
    /// Listing the folder.
    pub const LIST: &str = "write-step-list";
    /// Locking the folder.
    pub const LOCK_FOLDER: &str = "write-step-lock-folder";
    /// Finishing what a stopped run left.
    pub const RECOVER: &str = "write-step-recover";
    /// Removing the journal.
    pub const REMOVE_JOURNAL: &str = "write-step-remove-journal";
    /// Killed by a test.
    pub const KILLED: &str = "write-step-killed";
    /// The folder is as it was.
    pub const KEPT_FOLDER: &str = "write-kept-folder";
    /// The old set or the new one is whole; the next run finishes.
    pub const KEPT_RECOVERABLE: &str = "write-kept-recoverable";
    /// Nothing deleted: files that could not be put back are kept in the staging folder.
    pub const KEPT_STAGING: &str = "write-kept-staging";
}

impl WriteError {
    #[doc(hidden)]
    pub fn new(path: &Path, what: &'static str, source: io::Error, kept: &'static str) -> Self {
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
    /// The writer of a set dies at its n-th step (from 0; the app's `io::file_set::write_set` counts its steps):
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

/// Counts a step of a set's swap on this thread; returns its number (from 0).
#[doc(hidden)]
pub fn next_step() -> u32 {
    STEPS.with(|c| {
        let k = c.get();
        c.set(k + 1);
        k
    })
}

#[doc(hidden)]
pub fn fault() -> Option<Fault> {
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
#[doc(hidden)]
pub fn temporary_name(dir: &Path, name: &str) -> PathBuf {
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

#[doc(hidden)]
pub fn file_name_of(path: &Path) -> io::Result<String> {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidFilename, "not a file name"))
}

/// Closes `file`, reporting the close's own error (which `drop` would ignore).
fn close(file: File) -> io::Result<()> {
    if fault() == Some(Fault::OnClose) {
        return Err(injected("close"));
    }
    crate::formats::files::os::close_file(file)
}

/// Writes `bytes` to a new file at `tmp`: create, write, flush, sync, close, each checked.
/// On failure the file at `tmp` is removed and the failing step named.
#[doc(hidden)]
pub fn write_new(tmp: &Path, bytes: &[u8]) -> Result<(), (&'static str, io::Error)> {
    let file = File::options().write(true).create_new(true).open(tmp).map_err(|e| ("write-step-create", e))?;
    let result = write_file(file, bytes);
    if result.is_err() {
        let _ = std::fs::remove_file(tmp);
    }
    result
}

/// Writes `bytes` into `file`, new and empty, opened to write: write, flush, sync, close,
/// each checked (the faults of [`with_fault`] injected). On failure the caller removes the
/// file (it knows where it made it: the app's sets make theirs relative to a folder held).
#[doc(hidden)]
pub fn write_file(file: File, bytes: &[u8]) -> Result<(), (&'static str, io::Error)> {
    let mut out = Counted { file, written: 0 };
    out.write_all(bytes).map_err(|e| ("write-step-write", e))?;
    out.flush().map_err(|e| ("write-step-write", e))?;
    if fault() == Some(Fault::OnSync) {
        return Err(("write-step-sync", injected("sync")));
    }
    out.file.sync_all().map_err(|e| ("write-step-sync", e))?;
    close(out.file).map_err(|e| ("write-step-close", e))
}

/// Counts a rename on this thread; `Err` where a test makes this one fail.
#[doc(hidden)]
pub fn rename_fault() -> io::Result<()> {
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
    Ok(())
}

#[doc(hidden)]
pub fn rename(from: &Path, to: &Path) -> io::Result<()> {
    rename_fault()?;
    crate::formats::files::os::replace(from, to)
}

/// [`rename`] only where nothing is at `to` ([`crate::formats::files::os::rename_no_replace`]).
#[doc(hidden)]
pub fn rename_no_replace(from: &Path, to: &Path) -> io::Result<()> {
    rename_fault()?;
    crate::formats::files::os::rename_no_replace(from, to)
}

/// The file a path leads to: `path` itself, or, for a symbolic link, the file it names
/// (a chain of links followed, the last one's target even where nothing is there yet, so a
/// link stays a link and its file is written). Refused past 40 links (a loop).
#[doc(hidden)]
pub fn through_links(path: &Path) -> io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&p)?;
                p = if target.is_absolute() { target } else { folder_of(&p).join(target) };
            }
            _ => return Ok(p),
        }
    }
    Err(io::Error::new(io::ErrorKind::InvalidInput, "too many levels of symbolic links"))
}

/// Refuses an output that is there but is not a regular file: a folder, a device, a pipe
/// or a socket. Writing into a FIFO waits for a reader that may never come, and renaming a
/// file over `/dev/null` would replace the device for every program on the machine: an
/// output is a regular file or absent.
fn refuse_not_a_file(path: &Path, kept: &'static str) -> Result<(), WriteError> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_dir() => {
            let e = io::Error::new(io::ErrorKind::IsADirectory, "it is a folder");
            Err(WriteError::new(path, "write-step-create", e, kept))
        }
        Ok(m) if !m.is_file() => {
            let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("write-not-a-regular-file"));
            Err(WriteError::new(path, "write-step-create", e, kept))
        }
        _ => Ok(()),
    }
}

/// Is `entry` (a name in the folder of the file `name`) the temporary file of a write of
/// `name` by another process that is no longer running (`.name.<pid>.<n>.tmp`)?
fn stale_temporary_of(entry: &str, name: &str) -> bool {
    let Some(rest) = entry.strip_prefix('.').and_then(|r| r.strip_prefix(name)).and_then(|r| r.strip_prefix('.'))
    else {
        return false;
    };
    let parts: Vec<&str> = rest.split('.').collect();
    let [pid, n, "tmp"] = parts[..] else { return false };
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let Ok(pid) = pid.parse::<u32>() else { return false };
    digits(n) && pid != std::process::id() && !crate::formats::files::os::process_alive(pid)
}

/// Removes what killed writes of `name` left in `dir`: the temporary files
/// `.name.<pid>.<n>.tmp` whose writer is no longer running, each only when it is provably
/// phonglab's own kind of file, checked through the handle that removes it
/// ([`crate::formats::files::os::remove_own_file`]: a regular file of this user's, under its
/// own name, never a link nor the file one leads to); anything else of that name is left.
/// Only temporaries of the file being written now: another file's are left to its next
/// write.
fn remove_stale_temporaries(dir: &Path, name: &str) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        if entry.file_name().to_str().is_some_and(|e| stale_temporary_of(e, name)) {
            crate::formats::files::os::remove_own_file(dir, &entry.file_name());
        }
    }
}

/// Writes `bytes` to `path` whole or not at all (see the module's documentation), the
/// permissions of a file replaced kept (a new file gets the umask's). A symbolic link is followed (the file it names is replaced, or made where it names
/// nothing yet; the link stays a link); anything there that is not a regular file (a
/// device, a pipe, a folder) is refused. Temporary files that killed writes of the same
/// file left beside it are removed first.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    let resolved =
        through_links(path).map_err(|e| WriteError::new(path, "write-step-name", e, "write-kept-nothing"))?;
    write_here(&resolved, bytes)
}

/// [`write()`] at the name `path` itself, following no link: a symbolic link there is
/// refused as not a regular file, and one planted after that look is replaced by the
/// new file, never written through (the outputs of the commands that read students'
/// work, where a link at an output's name may be a student's).
pub fn write_here(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-file";
    refuse_unkept(path)?;
    let name = file_name_of(path).map_err(|e| WriteError::new(path, "write-step-name", e, "write-kept-nothing"))?;
    refuse_not_a_file(path, "write-kept-nothing")?;
    let dir = folder_of(path);
    remove_stale_temporaries(dir, &name);
    let tmp = temporary_name(dir, &name);
    // The file replaced keeps its permissions (a file its owner made private stays so); a
    // new one gets the system's usual ones (the umask).
    let mode = std::fs::metadata(path).ok().filter(std::fs::Metadata::is_file).map(|m| m.permissions());
    write_new(&tmp, bytes).map_err(|(what, e)| WriteError::new(path, what, e, KEPT))?;
    if let Some(mode) = mode
        && let Err(e) = std::fs::set_permissions(&tmp, mode)
    {
        let _ = std::fs::remove_file(&tmp);
        return Err(WriteError::new(path, "write-step-create", e, KEPT));
    }
    if let Err(e) = rename(&tmp, path) {
        let _ = std::fs::remove_file(&tmp);
        return Err(WriteError::new(path, "write-step-rename", e, KEPT));
    }
    crate::formats::files::os::sync_folder(dir);
    Ok(())
}

/// Why Windows cannot keep a file's or folder's name as it is given ([`unkept_name`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unkept {
    /// A name Windows keeps for a device (`CON`, `NUL`, `AUX`, `PRN`, `COM1`-`COM9`,
    /// `LPT1`-`LPT9`, with any extension: `con.png`, `nul.txt`): opening it opens the device.
    Device,
    /// A name ending in a dot or a space, which Windows drops (`rep.md.` is `rep.md`,
    /// `set ` is `set`): another file than the one named.
    DroppedEnd,
    /// A name holding a character Windows does not allow in one (`: ? * < > | "`):
    /// `out.png:x` writes a hidden stream of `out.png` (an alternate data stream), the
    /// others Windows refuses.
    Char(char),
}

/// The characters Windows does not allow in a file name that a name may hold elsewhere (a
/// control character is left to the messages' escaping; `/` and `\` part a path).
const NOT_IN_NAMES: [char; 7] = [':', '?', '*', '<', '>', '|', '"'];

/// The names Windows keeps for devices (compared without case, before any extension).
const DEVICES: [&str; 32] = [
    "CON", "PRN", "AUX", "NUL", "COM0", "COM1", "COM2", "COM3", "COM4", "COM5", "COM6", "COM7", "COM8", "COM9", "COM¹",
    "COM²", "COM³", "LPT0", "LPT1", "LPT2", "LPT3", "LPT4", "LPT5", "LPT6", "LPT7", "LPT8", "LPT9", "LPT¹", "LPT²",
    "LPT³", "CONIN$", "CONOUT$",
];

/// Why Windows cannot keep the file or folder name `name` as it is, if it cannot: a
/// device's name, a character it does not allow, or a dot or space at its end. Asked on every system, since a set or a
/// picture written on Linux is opened on the lab's Windows PCs (docs/security.md).
pub fn unkept_name(name: &std::ffi::OsStr) -> Option<Unkept> {
    let name = name.to_string_lossy();
    if name == "." || name == ".." {
        return None;
    }
    if let Some(c) = name.chars().find(|c| NOT_IN_NAMES.contains(c)) {
        return Some(Unkept::Char(c));
    }
    if name.ends_with(['.', ' ']) {
        return Some(Unkept::DroppedEnd);
    }
    let stem = name.split('.').next().unwrap_or_default().trim_end_matches(' ').to_uppercase();
    DEVICES.contains(&stem.as_str()).then_some(Unkept::Device)
}

/// Refuses the output `path` when its name, or the name of a folder above it that is not
/// there yet (one phonglab would make), is one Windows cannot keep ([`unkept_name`]): said
/// before anything is written, with the name and why.
pub fn refuse_unkept_name(path: &Path) -> Result<(), String> {
    use crate::formats::escape::terminal::text;
    let mut at = Some(path);
    let mut last = true;
    while let Some(here) = at {
        let Some(name) = here.file_name() else { break };
        if !last && std::fs::symlink_metadata(here).is_ok() {
            break;
        }
        let shown_name = text(&name.to_string_lossy());
        match unkept_name(name) {
            Some(Unkept::Device) => return Err(crate::t!("err-name-windows-device", name = shown_name)),
            // A '"' is most often cmd's trap: a backslash just before a closing quote
            // (`--out "C:\Exercícios de CG\"`) keeps the quote in the argument and joins the
            // next ones to it; the message says how to write it.
            Some(Unkept::Char('"')) => return Err(crate::t!("err-name-windows-quote", name = shown_name)),
            Some(Unkept::Char(c)) => {
                return Err(crate::t!("err-name-windows-char", name = shown_name, char = text(&c.to_string())));
            }
            Some(Unkept::DroppedEnd) => {
                let kept = text(name.to_string_lossy().trim_end_matches(['.', ' ']));
                return Err(crate::t!("err-name-windows-end", name = shown_name, kept = kept));
            }
            None => {}
        }
        last = false;
        at = here.parent();
    }
    Ok(())
}

/// Refuses `path` where Windows cannot keep its name, or a folder's above it that is not
/// there yet (a device's name, a dot or a space at the end:
/// [`refuse_unkept_name`]), before anything is made.
pub fn refuse_unkept(path: &Path) -> Result<(), WriteError> {
    refuse_unkept_name(path).map_err(|why| {
        let e = io::Error::new(io::ErrorKind::InvalidInput, why);
        WriteError::new(path, "write-step-name", e, "write-kept-nothing")
    })
}

/// Checks, before long work, that a file can be created in `path`'s folder (by creating
/// and removing a temporary file there; through a link, in the folder of the file it
/// names) and that what is at `path` is a regular file or nothing.
pub fn check_file_destination(path: &Path) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-nothing";
    refuse_unkept(path)?;
    let resolved = through_links(path).map_err(|e| WriteError::new(path, "write-step-name", e, KEPT))?;
    let name = file_name_of(&resolved).map_err(|e| WriteError::new(path, "write-step-name", e, KEPT))?;
    refuse_not_a_file(&resolved, KEPT)?;
    probe(folder_of(&resolved), &name).map_err(|e| WriteError::new(path, "write-step-create", e, KEPT))
}

/// Checks, before long work, that the folder `dir` exists or can be made, and that files
/// can be created in it.
pub fn check_folder_destination(dir: &Path) -> Result<(), WriteError> {
    const KEPT: &str = "write-kept-nothing";
    refuse_unkept(dir)?;
    // A file of that name (or a link to one): `create_dir_all` would say only "it already
    // exists", as though the folder were the trouble.
    if std::fs::metadata(dir).is_ok_and(|m| !m.is_dir()) {
        let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-folder-is-a-file"));
        return Err(WriteError::new(dir, "write-step-create-folder", e, KEPT));
    }
    // A link to nothing, at `dir` or above it: `create_dir_all` would say "it already
    // exists" of the link. Nothing is made where it points.
    if let Some(link) = dangling_link_at_or_above(dir) {
        let e = io::Error::new(io::ErrorKind::InvalidInput, crate::t!("folder-link-dangling"));
        return Err(WriteError::new(&link, "write-step-create-folder", e, KEPT));
    }
    std::fs::create_dir_all(dir).map_err(|e| WriteError::new(dir, "write-step-create-folder", e, KEPT))?;
    probe(dir, "writable").map_err(|e| WriteError::new(dir, "write-step-create-file-in", e, KEPT))
}

/// The nearest of `dir` and the folders above it that is something, when that is a link
/// whose target does not exist.
fn dangling_link_at_or_above(dir: &Path) -> Option<std::path::PathBuf> {
    let nearest =
        dir.ancestors().filter(|a| !a.as_os_str().is_empty()).find(|a| std::fs::symlink_metadata(a).is_ok())?;
    let is_link = std::fs::symlink_metadata(nearest).is_ok_and(|m| m.file_type().is_symlink());
    (is_link && std::fs::metadata(nearest).is_err()).then(|| nearest.to_path_buf())
}

fn probe(dir: &Path, name: &str) -> io::Result<()> {
    let tmp = temporary_name(dir, name);
    File::options().write(true).create_new(true).open(&tmp)?;
    std::fs::remove_file(&tmp)
}
