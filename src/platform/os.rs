//! What differs between operating systems on the desktop: closing a file with its error
//! reported, syncing a folder's entries to the disk, a file's identity, the memory
//! available, hearing the signals (Windows: the console's events) that end the process,
//! and a Windows command's terminal.

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
/// `MemAvailable` in `/proc/meminfo`; Windows: the available physical memory of
/// `GlobalMemoryStatusEx`); `None` where it does not say.
pub fn available_memory() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        let text = std::fs::read_to_string("/proc/meminfo").ok()?;
        let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
        let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
        Some(kib * 1024)
    }
    #[cfg(windows)]
    {
        use windows_sys::Win32::System::SystemInformation::{GlobalMemoryStatusEx, MEMORYSTATUSEX};
        let mut status = MEMORYSTATUSEX { dwLength: size_of::<MEMORYSTATUSEX>() as u32, ..Default::default() };
        // SAFETY: `status` is a MEMORYSTATUSEX with its length set, as the call requires; it
        // writes only into it.
        let ok = unsafe { GlobalMemoryStatusEx(&mut status) };
        (ok != 0).then_some(status.ullAvailPhys)
    }
    #[cfg(not(any(target_os = "linux", windows)))]
    {
        None
    }
}

/// The most address space this process may take, in bytes (Unix: the soft `RLIMIT_AS`
/// that `ulimit -v` sets, read by `getrlimit`); `None` where none is set, or elsewhere.
pub fn address_space_limit() -> Option<u64> {
    #[cfg(unix)]
    {
        let mut limit = libc::rlimit { rlim_cur: 0, rlim_max: 0 };
        // SAFETY: getrlimit writes only into `limit`, a valid rlimit it is given.
        let ok = unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut limit) } == 0;
        // rlim_t is u64 on Linux and macOS, not on every Unix.
        #[allow(clippy::unnecessary_cast)]
        let bytes = limit.rlim_cur as u64;
        (ok && limit.rlim_cur != libc::RLIM_INFINITY).then_some(bytes)
    }
    #[cfg(not(unix))]
    {
        None
    }
}

/// The address space this process takes now, in bytes (Linux: the first field of
/// `/proc/self/statm`, in pages); `None` where the system does not say.
pub fn address_space_in_use() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        let text = std::fs::read_to_string("/proc/self/statm").ok()?;
        let pages: u64 = text.split_whitespace().next()?.parse().ok()?;
        // SAFETY: sysconf reads a constant of the system.
        let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) };
        Some(pages * u64::try_from(page).ok()?)
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
/// process ends). The folder is opened without following a link (a link swapped in for it
/// is refused, not locked through). Where another process holds the lock, `waiting` is
/// called once before the wait, so that the user hears why nothing happens. Elsewhere a
/// no-op: the browser writes no folders.
pub fn lock_folder(dir: &Path, waiting: impl FnOnce()) -> io::Result<FolderLock> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        let folder = File::options().read(true).custom_flags(libc::O_NOFOLLOW | libc::O_DIRECTORY).open(dir)?;
        match folder.try_lock() {
            Ok(()) => {}
            Err(std::fs::TryLockError::WouldBlock) => {
                waiting();
                folder.lock()?;
            }
            Err(std::fs::TryLockError::Error(e)) => return Err(e),
        }
        Ok(FolderLock { _folder: folder })
    }
    #[cfg(not(unix))]
    {
        let _ = (dir, waiting);
        Ok(FolderLock {})
    }
}

/// Calls `handler` with the signal's number, on a thread of its own, each time the process
/// is asked to end (SIGTERM, SIGINT, SIGHUP: a logout, Ctrl+C in the terminal, `kill`).
#[cfg(unix)]
pub fn on_termination(handler: impl Fn(i32) + Send + Sync + 'static) -> io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGTERM, SIGINT, SIGHUP])?;
    std::thread::Builder::new().name("phonglab signals".into()).spawn(move || {
        for s in signals.forever() {
            handler(s);
        }
    })?;
    Ok(())
}

/// Calls `handler` with the console event's number (0 Ctrl+C, 1 Ctrl+Break, 2 the console
/// closed, 5 logoff, 6 shutdown) each time Windows asks the process to end through its
/// console. The handler runs before the call returns: for a closed console, a logoff or a
/// shutdown Windows ends the process as soon as the handler routine returns (and after 5 s
/// at most), so the session is written inside it, not on another thread afterwards (the
/// `ctrlc` crate's handler returns at once and would race that end). A program started
/// without a console (the window, double-clicked) has no console events: closing it, or a
/// logoff's WM_CLOSE, goes through the window's own exit, which saves.
#[cfg(windows)]
pub fn on_termination(handler: impl Fn(i32) + Send + Sync + 'static) -> io::Result<()> {
    use windows_sys::Win32::System::Console::SetConsoleCtrlHandler;
    if CONSOLE_HANDLER.set(Box::new(handler)).is_err() {
        return Err(io::Error::new(io::ErrorKind::AlreadyExists, "a termination handler is already installed"));
    }
    // SAFETY: `console_event` is a handler routine of the signature Windows calls, for the
    // life of the process (a plain function; it reads a static set once above).
    if unsafe { SetConsoleCtrlHandler(Some(console_event), 1) } == 0 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

/// The handler [`on_termination`] installed.
#[cfg(windows)]
static CONSOLE_HANDLER: std::sync::OnceLock<Box<dyn Fn(i32) + Send + Sync>> = std::sync::OnceLock::new();

/// The handler routine Windows calls, on a thread of its own, for each console event: the
/// handler runs to its end before it returns TRUE (handled).
#[cfg(windows)]
unsafe extern "system" fn console_event(event: u32) -> windows_sys::core::BOOL {
    if let Some(h) = CONSOLE_HANDLER.get() {
        h(event as i32);
    }
    1
}

/// Where the system sends no such signals, nothing is installed.
#[cfg(not(any(unix, windows)))]
pub fn on_termination(_handler: impl Fn(i32) + Send + Sync + 'static) -> io::Result<()> {
    Ok(())
}

/// Windows: phonglab is a GUI program (no console window opens when it is double-clicked),
/// so a command typed in a terminal has no console of its own: this attaches to the
/// terminal's (the parent's), so that what the command prints appears there. Output already
/// redirected to a file or a pipe keeps its handle (Windows passes it at the start).
/// Elsewhere nothing to do.
pub fn attach_to_terminal() {
    #[cfg(windows)]
    {
        use windows_sys::Win32::System::Console::{ATTACH_PARENT_PROCESS, AttachConsole};
        // SAFETY: no arguments but a constant; it fails harmlessly where there is no parent
        // console (double-clicked) or one is attached already.
        unsafe {
            AttachConsole(ATTACH_PARENT_PROCESS);
        }
    }
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

#[cfg(test)]
mod tests {
    /// The memory the budget divides: the system's figure where it gives one (Linux's
    /// /proc/meminfo, Windows' GlobalMemoryStatusEx), a plausible amount of it.
    #[test]
    #[cfg(any(target_os = "linux", windows))]
    fn the_available_memory_is_the_systems() {
        let bytes = super::available_memory().expect("the system says");
        assert!(bytes > 64 << 20 && bytes < 1 << 50, "{bytes}");
    }

    /// `ulimit -v` is read back as the process's limit, and the process takes less.
    #[test]
    #[cfg(target_os = "linux")]
    fn the_address_space_limit_is_getrlimits() {
        let in_use = super::address_space_in_use().expect("Linux says");
        assert!(in_use > 1 << 20, "{in_use}");
        if let Some(limit) = super::address_space_limit() {
            assert!(limit >= in_use, "{limit} < {in_use}");
        }
    }

    /// Windows: a console event (here a closed console, as Windows sends it: the routine
    /// called on a thread of its own) reaches the handler, which has run by the time the
    /// routine returns, as a closed console or a logoff needs. (Wine's consoles refuse
    /// GenerateConsoleCtrlEvent to a test runner, so the routine is called as Windows does.)
    #[test]
    #[cfg(windows)]
    fn a_console_event_reaches_the_termination_handler_before_the_routine_returns() {
        use windows_sys::Win32::System::Console::CTRL_CLOSE_EVENT;
        let (tx, rx) = std::sync::mpsc::channel();
        let tx = std::sync::Mutex::new(tx);
        super::on_termination(move |event| {
            std::thread::sleep(std::time::Duration::from_millis(200));
            let _ = tx.lock().map(|t| t.send(event));
        })
        .unwrap();
        // SAFETY: the routine as Windows calls it, with an event it sends.
        let handled = std::thread::spawn(|| unsafe { super::console_event(CTRL_CLOSE_EVENT) }).join().unwrap();
        assert_eq!(handled, 1);
        assert_eq!(rx.try_recv(), Ok(CTRL_CLOSE_EVENT as i32), "the handler ran before the routine returned");
    }
}
