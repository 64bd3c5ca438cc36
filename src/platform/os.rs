//! What differs between operating systems on the desktop: closing a file with its error
//! reported, syncing a folder's entries to the disk, a file's identity, the memory
//! available, hearing the signals (Windows: the console's events) that end the process,
//! and a Windows command's terminal.

use std::fs::File;
use std::io;
use std::path::Path;

// Opening, closing, syncing and renaming files: the core's, which the Python package
// shares (one implementation for every reader and writer of files).
pub use phonglab_core::files::os::{
    close_file, is_link_refused, is_this_users_alone, open_no_follow, open_to_read, process_alive,
    regular_file_metadata, rename_no_replace, sync_folder,
};

/// What makes a file or folder itself where the system says it, which a rename keeps and
/// which no one can choose for a file they plant: Unix its device and inode; Windows its
/// volume's serial number and its file index (`GetFileInformationByHandle`); `(0, 0)`
/// elsewhere. Read through `file`, an open handle, with its metadata.
pub fn file_identity(file: &File) -> io::Result<(std::fs::Metadata, (u64, u64))> {
    let meta = file.metadata()?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let id = (meta.dev(), meta.ino());
        Ok((meta, id))
    }
    #[cfg(windows)]
    {
        let info = winapi_util::file::information(file)?;
        Ok((meta, (info.volume_serial_number(), info.file_index())))
    }
    #[cfg(not(any(unix, windows)))]
    {
        Ok((meta, (0, 0)))
    }
}

/// [`file_identity`] of the file or folder at `path` itself: a link is not followed (its
/// own identity is given). Unix: `lstat`. Windows: a handle opened for its attributes only,
/// sharing everything (a rename or a delete by anyone else goes on), with
/// `FILE_FLAG_BACKUP_SEMANTICS` so that a folder opens too and
/// `FILE_FLAG_OPEN_REPARSE_POINT` so that a link (a reparse point) is opened itself.
pub fn identity_at(path: &Path) -> io::Result<(std::fs::Metadata, (u64, u64))> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let meta = std::fs::symlink_metadata(path)?;
        let id = (meta.dev(), meta.ino());
        Ok((meta, id))
    }
    #[cfg(windows)]
    {
        use std::os::windows::fs::OpenOptionsExt;
        /// `FILE_FLAG_BACKUP_SEMANTICS` (a folder opens) and `FILE_FLAG_OPEN_REPARSE_POINT`.
        const FOLDER_OR_LINK_ITSELF: u32 = 0x0200_0000 | 0x0020_0000;
        /// `FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE`.
        const SHARE_ALL: u32 = 7;
        let file =
            File::options().access_mode(0).share_mode(SHARE_ALL).custom_flags(FOLDER_OR_LINK_ITSELF).open(path)?;
        file_identity(&file)
    }
    #[cfg(not(any(unix, windows)))]
    {
        Ok((std::fs::symlink_metadata(path)?, (0, 0)))
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
    /// The named mutex this thread owns (see [`lock_folder`]); a raw handle, so the lock
    /// stays on the thread that took it, as a mutex must be released by its owner.
    #[cfg(windows)]
    mutex: windows_sys::Win32::Foundation::HANDLE,
}

/// Waits for, then holds, the exclusive lock of the folder `dir`, released when the value
/// is dropped and by the system however the process ends (killed, crashed): two phonglab
/// processes never write sets into one folder at once.
/// - Unix: `flock` on the folder itself, so no lock file is left behind.
/// - Windows: a named mutex, `Global\phonglab-folder-<volume serial>-<file index>`, named by
///   the folder's identity (so every path to the folder, through a link or another
///   spelling, names one mutex) and waited on. Windows releases a mutex whose owner ended
///   without releasing it, and the next waiter gets it "abandoned": that counts as
///   acquired (the dead writer's staging folder is then recovered, as on Unix). A file
///   lock (`LockFileEx`) would need a lock file, left in the student's folder, and cannot
///   be waited on; a folder cannot be locked itself. `Global\` reaches every session of the
///   machine (a lab's shared terminal server); where Windows refuses it (another user's
///   mutex, a sandbox), the session's own (`Local\`).
/// - Elsewhere a no-op: the browser writes no folders.
///
/// The folder is opened without following a link (Unix: a link swapped in for it is
/// refused, not locked through). Where another process holds the lock, `waiting` is called
/// once before the wait, so that the user hears why nothing happens.
pub fn lock_folder(dir: &Path, waiting: impl FnOnce()) -> io::Result<FolderLock> {
    if let Some(lock) = take_folder_lock(dir, false)? {
        return Ok(lock);
    }
    waiting();
    take_folder_lock(dir, true)?.ok_or_else(|| io::Error::other("the folder's lock was not taken"))
}

/// [`lock_folder`] without waiting: `None` when another process holds the folder.
pub fn try_lock_folder(dir: &Path) -> io::Result<Option<FolderLock>> {
    take_folder_lock(dir, false)
}

/// [`lock_folder`] (`wait`) or [`try_lock_folder`].
fn take_folder_lock(dir: &Path, wait: bool) -> io::Result<Option<FolderLock>> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        let folder = File::options().read(true).custom_flags(libc::O_NOFOLLOW | libc::O_DIRECTORY).open(dir)?;
        if wait {
            folder.lock()?;
        } else if let Err(e) = folder.try_lock() {
            return match e {
                std::fs::TryLockError::WouldBlock => Ok(None),
                std::fs::TryLockError::Error(e) => Err(e),
            };
        }
        Ok(Some(FolderLock { _folder: folder }))
    }
    #[cfg(windows)]
    {
        windows_folder_lock(dir, wait)
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = (dir, wait);
        Ok(Some(FolderLock {}))
    }
}

/// Windows: the folder's named mutex (see [`lock_folder`]), waited for or tried.
#[cfg(windows)]
fn windows_folder_lock(dir: &Path, wait: bool) -> io::Result<Option<FolderLock>> {
    use windows_sys::Win32::Foundation::{
        CloseHandle, ERROR_ACCESS_DENIED, WAIT_ABANDONED, WAIT_OBJECT_0, WAIT_TIMEOUT,
    };
    use windows_sys::Win32::System::Threading::{CreateMutexW, INFINITE, WaitForSingleObject};
    // The folder itself, a link followed: the folder the set goes into.
    let info = winapi_util::file::information(winapi_util::Handle::from_path_any(dir)?)?;
    let name = |space: &str| {
        let n = format!("{space}\\phonglab-folder-{:08x}-{:016x}", info.volume_serial_number(), info.file_index());
        n.encode_utf16().chain([0]).collect::<Vec<u16>>()
    };
    let create = |wide: &[u16]| {
        // SAFETY: `wide` is a NUL-terminated UTF-16 name that lives through the call; no
        // security attributes (the default), not owned at creation.
        let h = unsafe { CreateMutexW(std::ptr::null(), 0, wide.as_ptr()) };
        if h.is_null() { Err(io::Error::last_os_error()) } else { Ok(h) }
    };
    let mutex = match create(&name("Global")) {
        Err(e) if e.raw_os_error() == Some(ERROR_ACCESS_DENIED as i32) => create(&name("Local"))?,
        other => other?,
    };
    // SAFETY: `mutex` is the handle just opened, owned here.
    match unsafe { WaitForSingleObject(mutex, if wait { INFINITE } else { 0 }) } {
        WAIT_OBJECT_0 | WAIT_ABANDONED => Ok(Some(FolderLock { mutex })),
        r => {
            let e = if r == WAIT_TIMEOUT { None } else { Some(io::Error::last_os_error()) };
            // SAFETY: closed once, not owned (the wait did not take it).
            unsafe { CloseHandle(mutex) };
            e.map_or(Ok(None), Err)
        }
    }
}

#[cfg(windows)]
impl Drop for FolderLock {
    fn drop(&mut self) {
        use windows_sys::Win32::Foundation::CloseHandle;
        use windows_sys::Win32::System::Threading::ReleaseMutex;
        // SAFETY: the mutex this thread took (the handle cannot leave the thread: a raw
        // handle is not `Send`), released and closed once.
        unsafe {
            ReleaseMutex(self.mutex);
            CloseHandle(self.mutex);
        }
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

/// What [`on_termination`]'s `event` means for a command that it stops: whether it was the
/// user's Ctrl+C (or Ctrl+Break) rather than the system asking it to end (a logout, a closed
/// console, `kill`), and the exit code it ends with. Unix: 128 + the signal, as a shell
/// reports a process the signal ended (130 for Ctrl+C). Windows: 130 for Ctrl+C and
/// Ctrl+Break, as on Unix, 1 for the others.
pub fn stopped_by(event: i32) -> (bool, i32) {
    #[cfg(unix)]
    {
        (event == libc::SIGINT, 128 + event)
    }
    #[cfg(not(unix))]
    {
        let ctrl_c = event == 0 || event == 1;
        (ctrl_c, if ctrl_c { 130 } else { 1 })
    }
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

    /// The folder's lock, held by another process, is not taken here; it is once that
    /// process lets go of it, and once that process ends without letting go (killed: on
    /// Windows an abandoned mutex), and a process waiting for it gets it when it is let go
    /// of. The other process is this test binary again, running [`folder_lock_holder`],
    /// which says each step on its standard output.
    #[test]
    #[cfg(any(unix, windows))]
    fn a_folder_locked_by_another_process_is_not_taken_until_let_go_or_the_process_ends() {
        use super::{lock_folder, try_lock_folder};
        let dir = std::env::temp_dir().join(format!("phonglab-lock {}", std::process::id())).join("Exercícios de CG");
        std::fs::create_dir_all(&dir).unwrap();
        let mut other = Holder::start(&dir);
        other.ask("lock", "held");
        assert!(try_lock_folder(&dir).unwrap().is_none(), "held by the other process");
        other.ask("release", "released");
        let mine = try_lock_folder(&dir).unwrap().expect("let go of: taken");
        other.say("lock");
        other.hear("waiting");
        drop(mine);
        other.hear("held");
        assert!(try_lock_folder(&dir).unwrap().is_none(), "the waiting process has it");
        other.child.kill().unwrap();
        other.child.wait().unwrap();
        assert!(try_lock_folder(&dir).unwrap().is_some(), "its holder killed: taken");
        drop(lock_folder(&dir, || {}).unwrap());
        std::fs::remove_dir_all(dir.parent().unwrap()).unwrap();
    }

    /// The other process of the test above: this test binary, running [`folder_lock_holder`].
    struct Holder {
        child: std::process::Child,
        out: std::io::Lines<std::io::BufReader<std::process::ChildStdout>>,
    }

    impl Holder {
        fn start(dir: &std::path::Path) -> Holder {
            let mut child = std::process::Command::new(std::env::current_exe().unwrap())
                .args(["--exact", "platform::os::tests::folder_lock_holder", "--nocapture", "--test-threads=1"])
                .env(HOLDER_DIR, dir)
                .stdin(std::process::Stdio::piped())
                .stdout(std::process::Stdio::piped())
                .spawn()
                .unwrap();
            let out = std::io::BufRead::lines(std::io::BufReader::new(child.stdout.take().unwrap()));
            Holder { child, out }
        }

        fn say(&mut self, what: &str) {
            use std::io::Write;
            let stdin = self.child.stdin.as_mut().unwrap();
            writeln!(stdin, "{what}").and_then(|()| stdin.flush()).unwrap();
        }

        /// Reads the holder's output until it says `what` (libtest's own lines skipped).
        fn hear(&mut self, what: &str) {
            let said = format!("lock holder: {what}");
            for line in self.out.by_ref() {
                if line.unwrap().trim_end() == said {
                    return;
                }
            }
            panic!("the holder ended before saying {what:?}");
        }

        fn ask(&mut self, what: &str, answer: &str) {
            self.say(what);
            self.hear(answer);
        }
    }

    /// The folder the holder locks (set only for the holder's process).
    const HOLDER_DIR: &str = "PHONGLAB_TEST_LOCK_HOLDER_DIR";

    /// Not a test of its own (it does nothing without [`HOLDER_DIR`]): the process that
    /// holds the folder's lock for the test above, one standard-input line at a time
    /// (`lock`: waits for it; `release`), saying each step.
    #[test]
    #[cfg(any(unix, windows))]
    fn folder_lock_holder() {
        let Some(dir) = std::env::var_os(HOLDER_DIR) else { return };
        let say = |what: &str| {
            use std::io::Write;
            let mut out = std::io::stdout().lock();
            writeln!(out, "lock holder: {what}").and_then(|()| out.flush()).unwrap();
        };
        let mut held = None;
        for line in std::io::stdin().lines() {
            match line.unwrap().trim() {
                "lock" => {
                    say("waiting");
                    held = Some(super::lock_folder(std::path::Path::new(&dir), || {}).unwrap());
                    say("held");
                }
                "release" => {
                    held = None;
                    say("released");
                }
                _ => {}
            }
        }
        drop(held);
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
