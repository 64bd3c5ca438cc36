//! What differs between operating systems for the files phonglab reads and writes (the
//! command line, the window and the Python package alike): opening without blocking or
//! without following a link, closing a file with its error reported, syncing a folder,
//! renaming without replacing, and whether a writer's process still runs.

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

/// The metadata of the opened `file` where it is a regular file, `None` where it is
/// anything else (a folder, a device, a FIFO, a socket). Windows: a device (`NUL`, `CON`)
/// or a pipe has no file information to read (`GetFileInformationByHandle` fails, "Invalid
/// function"), so its type (`GetFileType`: a file on a disk, or not) is asked first.
pub fn regular_file_metadata(file: &File) -> io::Result<Option<std::fs::Metadata>> {
    #[cfg(windows)]
    if !winapi_util::file::typ(file)?.is_disk() {
        return Ok(None);
    }
    let meta = file.metadata()?;
    Ok(meta.is_file().then_some(meta))
}

/// Opens `path` to read without following a symbolic link at its last component and
/// without waiting (Unix: `O_NOFOLLOW | O_NONBLOCK`; Windows:
/// `FILE_FLAG_OPEN_REPARSE_POINT`, the link itself opened and then refused through its
/// handle): for files phonglab itself wrote into a folder that others may have planted
/// things in (a set's journal), and for a student's submission, where a link is never to be
/// followed. The refusal is the open's own, so no link swapped in after a check is followed;
/// [`is_link_refused`] tells it from other errors. The caller checks what was opened through
/// the handle.
pub fn open_no_follow(path: &Path) -> io::Result<File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        File::options().read(true).custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK).open(path)
    }
    #[cfg(windows)]
    {
        use std::os::windows::fs::OpenOptionsExt;
        /// `FILE_FLAG_OPEN_REPARSE_POINT`: open a link (a reparse point) itself.
        const OPEN_REPARSE_POINT: u32 = 0x0020_0000;
        let file = File::options().read(true).custom_flags(OPEN_REPARSE_POINT).open(path)?;
        if file.metadata()?.file_type().is_symlink() {
            return Err(io::Error::from_raw_os_error(WINDOWS_LINK_REFUSED));
        }
        Ok(file)
    }
    #[cfg(not(any(unix, windows)))]
    {
        if std::fs::symlink_metadata(path)?.file_type().is_symlink() {
            return Err(io::Error::new(io::ErrorKind::InvalidInput, "a symbolic link"));
        }
        File::open(path)
    }
}

/// The error [`open_no_follow`] gives a link on Windows: `ERROR_CANT_RESOLVE_FILENAME`.
#[cfg(windows)]
const WINDOWS_LINK_REFUSED: i32 = 1921;

/// Is `e` [`open_no_follow`]'s refusal of a link (Unix: `ELOOP`)?
pub fn is_link_refused(e: &io::Error) -> bool {
    #[cfg(unix)]
    {
        e.raw_os_error() == Some(libc::ELOOP)
    }
    #[cfg(windows)]
    {
        e.raw_os_error() == Some(WINDOWS_LINK_REFUSED)
    }
    #[cfg(not(any(unix, windows)))]
    {
        e.kind() == io::ErrorKind::InvalidInput
    }
}

/// Renames `from` to `to` only when nothing is at `to` (not even a link): an error
/// `AlreadyExists` otherwise, and nothing moves (Linux: `renameat2` with `RENAME_NOREPLACE`;
/// where the file system refuses that flag, and elsewhere, a check then a rename, which
/// only another process writing into the folder at the same instant could race).
pub fn rename_no_replace(from: &Path, to: &Path) -> io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::ffi::OsStrExt;
        let c = |p: &Path| std::ffi::CString::new(p.as_os_str().as_bytes()).map_err(io::Error::other);
        let (f, t) = (c(from)?, c(to)?);
        // SAFETY: both are valid NUL-terminated paths that live through the call.
        let r =
            unsafe { libc::renameat2(libc::AT_FDCWD, f.as_ptr(), libc::AT_FDCWD, t.as_ptr(), libc::RENAME_NOREPLACE) };
        if r == 0 {
            return Ok(());
        }
        let e = io::Error::last_os_error();
        if !matches!(e.raw_os_error(), Some(libc::EINVAL | libc::ENOSYS)) {
            return Err(e);
        }
    }
    if std::fs::symlink_metadata(to).is_ok() {
        return Err(io::Error::new(io::ErrorKind::AlreadyExists, "a file is already there"));
    }
    std::fs::rename(from, to)
}

/// Replaces the file `to` with `from` by a rename. On Windows a file another program holds
/// open without sharing its deletion (an image viewer showing the PNG, a virus scanner or
/// the search indexer reading it) cannot be replaced: the rename (`MoveFileExW`, through
/// std) is tried again every 50 ms for 2 s, which outlasts a scanner's look; past that it
/// fails as [`io::ErrorKind::ResourceBusy`] (said "another program has it open"), and the
/// writer removes its temporary file: the file there is left as it was. A read-only file
/// is refused at once (permission denied), as elsewhere.
pub fn replace(from: &Path, to: &Path) -> io::Result<()> {
    let mut tries = 0;
    loop {
        match std::fs::rename(from, to) {
            Err(e) if held_open(&e, to) => {
                if tries == 40 {
                    return Err(io::Error::new(io::ErrorKind::ResourceBusy, e));
                }
                tries += 1;
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            done => return done,
        }
    }
}

/// Is `e`, from replacing `to`, Windows' refusal of a file another program holds open
/// (`ERROR_ACCESS_DENIED` where `to` is not read-only, `ERROR_SHARING_VIOLATION`,
/// `ERROR_LOCK_VIOLATION`)? Never elsewhere.
fn held_open(e: &io::Error, to: &Path) -> bool {
    cfg!(windows)
        && match e.raw_os_error() {
            Some(5) => std::fs::metadata(to).is_ok_and(|m| !m.permissions().readonly()),
            Some(32 | 33) => true,
            _ => false,
        }
}

/// Is the process `pid` still running (on this machine)? Where the system cannot say, it
/// is taken to be running, so its files are left alone.
pub fn process_alive(pid: u32) -> bool {
    #[cfg(unix)]
    {
        let Ok(pid) = libc::pid_t::try_from(pid) else { return true };
        // SAFETY: signal 0 sends nothing; it only asks whether the process exists.
        if unsafe { libc::kill(pid, 0) } == 0 {
            return true;
        }
        io::Error::last_os_error().raw_os_error() != Some(libc::ESRCH)
    }
    #[cfg(windows)]
    {
        use windows_sys::Win32::Foundation::{CloseHandle, ERROR_INVALID_PARAMETER, STILL_ACTIVE};
        use windows_sys::Win32::System::Threading::{
            GetExitCodeProcess, OpenProcess, PROCESS_QUERY_LIMITED_INFORMATION,
        };
        // SAFETY: no pointers; the handle returned, if any, is closed below.
        let h = unsafe { OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, 0, pid) };
        if h.is_null() {
            // No process of that number (ERROR_INVALID_PARAMETER); any other refusal (one
            // of another user's: access denied) is a process that runs.
            return io::Error::last_os_error().raw_os_error() != Some(ERROR_INVALID_PARAMETER as i32);
        }
        let mut code = 0u32;
        // SAFETY: `h` is the process handle just opened; `code` is a u32 it writes.
        let asked = unsafe { GetExitCodeProcess(h, &mut code) } != 0;
        // SAFETY: closed once.
        unsafe { CloseHandle(h) };
        !asked || code == STILL_ACTIVE as u32
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = pid;
        true
    }
}

/// Removes the file `name` in the folder `dir` when it is, through the handle that removes
/// it, a regular file of this user's, reached under its own name (not a link; Wine opens a
/// Unix link as the file it names, which a removal by name would remove): `true` when it
/// did. For a killed write's temporary file ([`crate::formats::files::atomic_write`]).
/// Unix: `O_NOFOLLOW`, the owner (this user's uid: a classmate's file planted with phonglab's
/// naming is not), and `lstat` compared just before `unlink`, which never follows. Windows:
/// opened with `FILE_FLAG_OPEN_REPARSE_POINT` and `DELETE`, its final path compared with
/// its folder's, and deleted through the handle (`FileDispositionInfo`).
pub fn remove_own_file(dir: &Path, name: &std::ffi::OsStr) -> bool {
    let path = dir.join(name);
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let Ok(file) = open_no_follow(&path) else { return false };
        let (Ok(open), Ok(at)) = (file.metadata(), std::fs::symlink_metadata(&path)) else { return false };
        // SAFETY: geteuid only reads the process's user.
        let mine = open.uid() == unsafe { libc::geteuid() };
        let same = at.file_type().is_file() && at.dev() == open.dev() && at.ino() == open.ino();
        open.is_file() && mine && same && std::fs::remove_file(&path).is_ok()
    }
    #[cfg(windows)]
    {
        windows_remove_own_file(dir, name, &path).unwrap_or(false)
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = path;
        false
    }
}

// Whether a record is this user's alone: `private`'s (Unix: mode and owner; Windows: owner
// and DACL), asked where the records are read.
pub use super::private::is_this_users_alone;

/// [`remove_own_file`] on Windows; `Err` or `Ok(false)`: not removed.
#[cfg(windows)]
fn windows_remove_own_file(dir: &Path, name: &std::ffi::OsStr, path: &Path) -> io::Result<bool> {
    use std::os::windows::fs::{MetadataExt, OpenOptionsExt};
    use std::os::windows::io::AsRawHandle;
    use windows_sys::Win32::Foundation::GENERIC_READ;
    use windows_sys::Win32::Storage::FileSystem::{
        DELETE, FILE_DISPOSITION_INFO, FILE_FLAG_BACKUP_SEMANTICS, FILE_FLAG_OPEN_REPARSE_POINT, FileDispositionInfo,
        SetFileInformationByHandle,
    };
    /// `FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE`.
    const SHARE_ALL: u32 = 7;
    /// `FILE_ATTRIBUTE_REPARSE_POINT`.
    const REPARSE_POINT: u32 = 0x400;
    let file = File::options()
        .access_mode(GENERIC_READ | DELETE)
        .share_mode(SHARE_ALL)
        .custom_flags(FILE_FLAG_OPEN_REPARSE_POINT)
        .open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() || meta.file_attributes() & REPARSE_POINT != 0 {
        return Ok(false);
    }
    let folder =
        File::options().access_mode(0).share_mode(SHARE_ALL).custom_flags(FILE_FLAG_BACKUP_SEMANTICS).open(dir)?;
    let (Some(at), Some(folder)) = (final_path(&file), final_path(&folder)) else { return Ok(false) };
    let plain = |p: &Path| p.to_string_lossy().to_lowercase().trim_end_matches('\\').to_string();
    if plain(&at) != plain(&folder.join(name)) {
        return Ok(false);
    }
    // A file of another user's (a classmate's, planted with phonglab's naming) is not
    // this user's temporary, as on Unix (issue 59, fix59x: Windows did not ask).
    if !super::private::is_owned_by_this_user(&file) {
        return Ok(false);
    }
    let info = FILE_DISPOSITION_INFO { DeleteFile: true };
    // SAFETY: the handle is open with DELETE access through the call; `info` is read only.
    let ok = unsafe {
        SetFileInformationByHandle(
            file.as_raw_handle(),
            FileDispositionInfo,
            (&raw const info).cast(),
            size_of::<FILE_DISPOSITION_INFO>() as u32,
        )
    };
    Ok(ok != 0)
}

/// The path Windows gives the open `file` (links resolved; `\\?\` form).
#[cfg(windows)]
fn final_path(file: &File) -> Option<std::path::PathBuf> {
    use std::os::windows::ffi::OsStringExt;
    use std::os::windows::io::AsRawHandle;
    use windows_sys::Win32::Storage::FileSystem::GetFinalPathNameByHandleW;
    let mut buf = vec![0u16; 1024];
    loop {
        let len = u32::try_from(buf.len()).ok()?;
        // SAFETY: the handle is open for the call; `buf` holds `len` u16s.
        let n = unsafe { GetFinalPathNameByHandleW(file.as_raw_handle(), buf.as_mut_ptr(), len, 0) } as usize;
        if n == 0 {
            return None;
        }
        if n < buf.len() {
            buf.truncate(n);
            return Some(std::ffi::OsString::from_wide(&buf).into());
        }
        buf.resize(n + 1, 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::formats::files::atomic_write;

    fn folder(name: &str) -> std::path::PathBuf {
        let d =
            std::env::temp_dir().join(format!("phonglab-os {name} {}", std::process::id())).join("Exercícios de CG");
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// The names in `dir`, sorted.
    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn a_file_is_replaced_whole_in_a_folder_with_accents_and_spaces() {
        let dir = folder("replace");
        let p = dir.join("esfera à luz.png");
        atomic_write::write(&p, b"first").unwrap();
        atomic_write::write(&p, b"second").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"second");
        assert_eq!(names(&dir), ["esfera à luz.png"]);
        std::fs::remove_dir_all(dir.parent().unwrap()).unwrap();
    }

    /// Windows: a file another program holds open (sharing reading only, as an image viewer
    /// does) is not replaced: the write says so in words and leaves the file and the folder
    /// as they were; one that the other program lets go of within the retries is replaced.
    #[test]
    #[cfg(windows)]
    fn a_file_held_open_elsewhere_is_left_as_it_was_or_replaced_once_let_go() {
        use std::os::windows::fs::OpenOptionsExt;
        /// `FILE_SHARE_READ` alone: no writing, no deleting, no renaming over it.
        const SHARE_READ: u32 = 1;
        let dir = folder("held");
        let p = dir.join("cena da aula.png");
        std::fs::write(&p, b"old").unwrap();
        let held = File::options().read(true).share_mode(SHARE_READ).open(&p).unwrap();
        let e = atomic_write::write(&p, b"new").unwrap_err();
        assert_eq!(e.reason.kind(), io::ErrorKind::ResourceBusy, "{e}");
        let said = crate::locale::with_locale(crate::locale::Locale::of(crate::locale::Lang::PtPt), || e.to_string());
        assert!(said.contains("outro programa tem-no aberto"), "{said}");
        assert_eq!(std::fs::read(&p).unwrap(), b"old");
        assert_eq!(names(&dir), ["cena da aula.png"]);
        // Let go of after 300 ms: the retries outlast it.
        let letting_go = std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_millis(300));
            drop(held);
        });
        atomic_write::write(&p, b"new").unwrap();
        letting_go.join().unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"new");
        assert_eq!(names(&dir), ["cena da aula.png"]);
        std::fs::remove_dir_all(dir.parent().unwrap()).unwrap();
    }
}
