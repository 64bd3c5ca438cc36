//! Every file phonglab writes is written whole or not at all: the one way to write a file.
//!
//! A single file ([`write()`]) goes to a temporary file in the target's own folder, which is
//! flushed, synced to the disk and closed with every error checked, then renamed over the
//! target. A rename within one folder either happens or does not, so the target holds the
//! old bytes or the new ones, never a part. A failure removes the temporary file, leaves
//! the target untouched, and says what failed. A set of files that belong together is
//! swapped in by [`super::file_set`], built on the steps here.
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
    pub(crate) fn new(path: &Path, what: &'static str, source: io::Error, kept: &'static str) -> Self {
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
    /// The writer of a set dies at its n-th step (from 0; [`super::file_set::write_set`] counts its steps):
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
pub(crate) fn next_step() -> u32 {
    STEPS.with(|c| {
        let k = c.get();
        c.set(k + 1);
        k
    })
}

pub(crate) fn fault() -> Option<Fault> {
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
pub(crate) fn temporary_name(dir: &Path, name: &str) -> PathBuf {
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

pub(crate) fn file_name_of(path: &Path) -> io::Result<String> {
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
pub(crate) fn write_new(tmp: &Path, bytes: &[u8]) -> Result<(), (&'static str, io::Error)> {
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

pub(crate) fn rename(from: &Path, to: &Path) -> io::Result<()> {
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    pub(crate) fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("phonglab-atomic-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    pub(crate) fn listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
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

    pub(crate) const FAULTS: [Fault; 6] = [
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
}
