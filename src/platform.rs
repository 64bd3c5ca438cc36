//! What differs between operating systems, kept out of the rest of the code: closing a
//! file with its error reported, and syncing a folder's entries to the disk.

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
    drop(file);
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

/// The folder the app keeps its session in: `PHONGLAB_SESSION_DIR` when set, else the
/// system's place for an application's data (`$XDG_DATA_HOME/phonglab` or
/// `~/.local/share/phonglab` on Linux, as eframe chose before phonglab kept it itself).
pub fn storage_dir() -> Option<std::path::PathBuf> {
    use std::path::PathBuf;
    let var = |k: &str| std::env::var_os(k).filter(|v| !v.is_empty()).map(PathBuf::from);
    if let Some(d) = var("PHONGLAB_SESSION_DIR") {
        return Some(d);
    }
    if cfg!(target_os = "windows") {
        return var("APPDATA").map(|d| d.join("phonglab").join("data"));
    }
    if cfg!(target_os = "macos") {
        return var("HOME").map(|h| h.join("Library/Application Support/phonglab"));
    }
    var("XDG_DATA_HOME").or_else(|| var("HOME").map(|h| h.join(".local/share"))).map(|d| d.join("phonglab"))
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
