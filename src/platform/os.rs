//! What differs between operating systems on the desktop: closing a file with its error
//! reported, syncing a folder's entries to the disk, and hearing the signals that end the
//! process.

use std::fs::File;
use std::io;
use std::path::Path;

/// Closes `file` and reports the close's own error, which `drop` ignores (NFS and some
/// FUSE file systems report a failed write there).
#[cfg(unix)]
pub fn close_file(file: File) -> io::Result<()> {
    use std::os::fd::IntoRawFd;
    let fd = file.into_raw_fd();
    // SAFETY: `fd` was just taken out of a `File`, so it is open and owned here alone;
    // it is closed exactly once.
    if unsafe { libc::close(fd) } == 0 { Ok(()) } else { Err(io::Error::last_os_error()) }
}

/// Closes `file` (where the close cannot report an error of its own).
#[cfg(not(unix))]
pub fn close_file(file: File) -> io::Result<()> {
    // Dropped here: the file closes as it goes out of scope.
    let _closed = file;
    Ok(())
}

/// Syncs the entries of the folder `dir` (a rename in it) to the disk, where the system
/// allows it; a failure here loses nothing that was written, so it is not reported.
pub fn sync_folder(dir: &Path) {
    #[cfg(unix)]
    if let Ok(d) = File::open(dir) {
        let _ = d.sync_all();
    }
    #[cfg(not(unix))]
    let _ = dir;
}

/// Opens `path` to read without waiting: a FIFO with no writer, or a device, would
/// otherwise block the open itself (Unix: `O_NONBLOCK`, which changes nothing for a regular
/// file). The caller checks what was opened from the handle ([`File::metadata`]), so a
/// file swapped between a check and the open is seen.
pub fn open_to_read(path: &Path) -> io::Result<File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        File::options().read(true).custom_flags(libc::O_NONBLOCK).open(path)
    }
    #[cfg(not(unix))]
    {
        File::open(path)
    }
}

/// The memory the system says is available to a new allocation, in bytes (Linux:
/// `MemAvailable` in `/proc/meminfo`); `None` where it does not say.
pub fn available_memory() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        let text = std::fs::read_to_string("/proc/meminfo").ok()?;
        let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
        let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
        Some(kib * 1024)
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}

/// A folder held by this process until the value is dropped (see [`lock_folder`]).
#[derive(Debug)]
pub struct FolderLock {
    #[cfg(unix)]
    _folder: File,
}

/// Waits for, then holds, the exclusive lock of the folder `dir` (Unix: `flock` on the
/// folder itself, so no lock file is left behind; released by the system however the
/// process ends). Elsewhere a no-op: the browser writes no folders.
pub fn lock_folder(dir: &Path) -> io::Result<FolderLock> {
    #[cfg(unix)]
    {
        let folder = File::open(dir)?;
        folder.lock()?;
        Ok(FolderLock { _folder: folder })
    }
    #[cfg(not(unix))]
    {
        let _ = dir;
        Ok(FolderLock {})
    }
}

/// Calls `handler` with the signal's number, on a thread of its own, each time the process
/// is asked to end (SIGTERM, SIGINT, SIGHUP: a logout, Ctrl+C in the terminal, `kill`).
#[cfg(unix)]
pub fn on_termination(handler: impl Fn(i32) + Send + 'static) -> io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGTERM, SIGINT, SIGHUP])?;
    std::thread::Builder::new().name("phonglab signals".into()).spawn(move || {
        for s in signals.forever() {
            handler(s);
        }
    })?;
    Ok(())
}

/// Where the system sends no such signals, nothing is installed.
#[cfg(not(unix))]
pub fn on_termination(_handler: impl Fn(i32) + Send + 'static) -> io::Result<()> {
    Ok(())
}
