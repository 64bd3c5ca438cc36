//! What differs between operating systems on the desktop: closing a file with its error
//! reported, syncing a folder's entries to the disk, and hearing the signals that end the
//! process.

#[cfg(unix)]
use std::fs::File;
use std::io;
use std::path::Path;

// Opening, closing, syncing and renaming files: the core's, which the Python package
// shares (one implementation for every reader and writer of files).
pub use phonglab_core::files::os::{
    close_file, is_link_refused, open_no_follow, open_to_read, process_alive, rename_no_replace, sync_folder,
};

/// What makes a file itself where the system says it: its device and inode (Unix), which a
/// rename keeps and which no one can choose for a file they plant; `(0, 0)` elsewhere.
pub fn file_identity(meta: &std::fs::Metadata) -> (u64, u64) {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        (meta.dev(), meta.ino())
    }
    #[cfg(not(unix))]
    {
        let _ = meta;
        (0, 0)
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

/// A command whose reader went away (`phonglab explain | head -1`) ends quietly, as Unix
/// tools do, instead of panicking in `println!` with a broken pipe. Rust ignores `SIGPIPE`
/// so that a write returns the error; the command line restores the default, which ends
/// the process at the first write to a closed pipe. (Files are written whole or not at all
/// by `io::atomic_write`, so ending there loses nothing.) The window keeps Rust's choice.
#[cfg(unix)]
pub fn end_quietly_on_closed_pipe() {
    // SAFETY: setting a signal's disposition to its default is async-signal-safe and
    // touches no Rust state; it is done once, before any thread is started by a command.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

/// Elsewhere a closed pipe is an error the write returns (nothing to change).
#[cfg(not(unix))]
pub fn end_quietly_on_closed_pipe() {}
