//! A folder held by a handle, and everything made, opened, moved or removed inside it done
//! through that handle, never through its path again: a folder of phonglab's own (a set's
//! staging folder, its aside folder) or the folder a set is written into, which someone
//! who can write beside it could rename and replace by a link to another folder while
//! phonglab works in it (issue 59, the hostile's review).
//!
//! - Unix: the folder is opened once with `O_DIRECTORY | O_NOFOLLOW` (a link is refused by
//!   the open itself), and every step is relative to that descriptor: `mkdirat`, `openat`
//!   (`O_NOFOLLOW`; a new file `O_CREAT | O_EXCL`), `fstatat` (`AT_SYMLINK_NOFOLLOW`),
//!   `unlinkat`, `renameat2` (`RENAME_NOREPLACE`; elsewhere than Linux `renameat` after a
//!   look), and its entries are read through a descriptor opened from it. The folder
//!   renamed, or replaced by a link, meanwhile changes nothing: the steps still act in it.
//! - Windows: the folder is opened with `FILE_FLAG_BACKUP_SEMANTICS |
//!   FILE_FLAG_OPEN_REPARSE_POINT`, a reparse point refused (and, for Wine, one reached
//!   under another name than its own: `platform::links`), and held with `GENERIC_READ`
//!   WITHOUT `FILE_SHARE_DELETE`: while it is held no one can rename or remove it (opening
//!   it with `DELETE`, which both need, is a sharing violation), nor rename a folder above
//!   it (NTFS refuses to rename a folder with an open handle beneath it), so its path goes
//!   on naming the folder held, and the steps go by that path, but for what is made in it:
//!   a file or folder is made through the folder's handle (`NtCreateFile` with
//!   `RootDirectory`; Wine opens it relative to the folder's own descriptor), so a folder a
//!   Unix program renamed under Wine and replaced by a link between phonglab's look and its
//!   step still gets it, never the folder the link leads to. (The handle asks for no
//!   `DELETE` itself: a rename into the folder opens it for `FILE_ADD_FILE` sharing reading
//!   and writing only, which a held `DELETE` would refuse.) Its removal lets go of it, then
//!   opens it again with `DELETE`, checks it is the very folder held (its identity), and
//!   removes it through that handle (`FileDispositionInfo`).

use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io;
use std::path::{Path, PathBuf};

/// A folder held by a handle (see the module's documentation).
pub struct HeldDir {
    dir: File,
    path: PathBuf,
    /// Its identity, read through the handle when it was held (under Wine a handle whose
    /// folder a Unix program renamed is read by a path that no longer leads to it, so it is
    /// not read again).
    id: Option<(u64, u64)>,
}

impl HeldDir {
    /// Holds the folder at `path` itself. `Err` where it is a link (Unix: `ELOOP` or
    /// `ENOTDIR`; Windows: a reparse point, or reached under another name), not a folder,
    /// or missing.
    pub fn open(path: &Path) -> io::Result<HeldDir> {
        #[cfg(unix)]
        let dir = unix::open_dir(None, path.as_os_str())?;
        #[cfg(windows)]
        let dir = windows::open_dir(path)?;
        #[cfg(not(any(unix, windows)))]
        let dir = File::open(path)?;
        let id = crate::platform::os::file_identity(&dir).ok().map(|(_, id)| id);
        Ok(HeldDir { dir, path: path.to_path_buf(), id })
    }

    /// The path it was held at (for messages; Windows: the path the steps go by).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The open folder, to ask its identity through.
    pub fn handle(&self) -> &File {
        &self.dir
    }

    /// The folder `name` in this one, held itself (a link there is refused).
    pub fn open_dir(&self, name: &OsStr) -> io::Result<HeldDir> {
        let path = self.path.join(name);
        #[cfg(unix)]
        let dir = unix::open_dir(Some(&self.dir), plain(name)?)?;
        #[cfg(windows)]
        let dir = windows::open_dir(&path)?;
        #[cfg(not(any(unix, windows)))]
        let dir = File::open(&path)?;
        let id = crate::platform::os::file_identity(&dir).ok().map(|(_, id)| id);
        Ok(HeldDir { dir, path, id })
    }

    /// Makes the folder `name` in this one, where nothing is (`AlreadyExists` otherwise, a
    /// link included), for this user alone (Unix: mode 0700; Windows: an owner-only
    /// descriptor, `phonglab_core::files::private::OwnerOnly`: a staging or aside folder,
    /// trusted later only when no one else can have put anything in it), and holds it
    /// (Windows: by the handle that made it, through the handle of this one).
    pub fn create_dir(&self, name: &OsStr) -> io::Result<HeldDir> {
        #[cfg(unix)]
        {
            unix::mkdir(&self.dir, plain(name)?)?;
            self.open_dir(name)
        }
        #[cfg(windows)]
        {
            self.unmoved()?;
            let dir = self.said_moved(|| windows::create_in(&self.dir, plain(name)?, windows::Make::Folder))?;
            let id = crate::platform::os::file_identity(&dir).ok().map(|(_, id)| id);
            Ok(HeldDir { dir, path: self.path.join(name), id })
        }
        #[cfg(not(any(unix, windows)))]
        {
            std::fs::create_dir(self.path.join(plain(name)?))?;
            self.open_dir(name)
        }
    }

    /// Creates the new file `name` in this folder, to write (never through a link:
    /// `AlreadyExists` where anything is there; Windows: made through this folder's handle,
    /// so a link put at the folder's name meanwhile never leads it elsewhere).
    pub fn create_new(&self, name: &OsStr) -> io::Result<File> {
        #[cfg(unix)]
        {
            unix::create_new(&self.dir, plain(name)?)
        }
        #[cfg(windows)]
        {
            self.unmoved()?;
            self.said_moved(|| windows::create_in(&self.dir, plain(name)?, windows::Make::File))
        }
        #[cfg(not(any(unix, windows)))]
        {
            File::options().write(true).create_new(true).open(self.path.join(plain(name)?))
        }
    }

    /// Creates the new file `name` in this folder, to write, for this user alone (Unix:
    /// mode 0600, whatever the umask; Windows: an owner-only descriptor): one of phonglab's records, which it trusts later only
    /// when no one else can have written it ([`crate::platform::os::is_this_users_alone`]).
    pub fn create_private(&self, name: &OsStr) -> io::Result<File> {
        #[cfg(unix)]
        {
            unix::create_private(&self.dir, plain(name)?)
        }
        #[cfg(windows)]
        {
            self.unmoved()?;
            self.said_moved(|| windows::create_in(&self.dir, plain(name)?, windows::Make::Private))
        }
        #[cfg(not(any(unix, windows)))]
        {
            self.create_new(name)
        }
    }

    /// Opens the file `name` in this folder to append to, made if missing (never through a
    /// link) for this user alone (Unix: mode 0600; Windows: an owner-only descriptor): a
    /// record of phonglab's.
    pub fn append(&self, name: &OsStr) -> io::Result<File> {
        #[cfg(unix)]
        {
            unix::append(&self.dir, plain(name)?)
        }
        #[cfg(windows)]
        {
            self.unmoved()?;
            let path = self.path.join(plain(name)?);
            // Opened itself (`FILE_OPEN_REPARSE_POINT`), through this folder's handle; a
            // link (Wine: a Unix one, which opens as the file it names) is refused here.
            let file = self.said_moved(|| windows::create_in(&self.dir, plain(name)?, windows::Make::Append))?;
            let link = !crate::platform::links::opened_under_its_own_name(&file, &path)
                || std::os::windows::fs::MetadataExt::file_attributes(&file.metadata()?) & 0x400 != 0;
            if link || crate::platform::os::regular_file_metadata(&file)?.is_none() {
                return Err(io::Error::new(io::ErrorKind::InvalidInput, "not a regular file"));
            }
            Ok(file)
        }
        #[cfg(not(any(unix, windows)))]
        {
            let _ = name;
            Err(io::Error::new(io::ErrorKind::Unsupported, "no files on this platform"))
        }
    }

    /// Opens the file `name` in this folder to read, without following a link and without
    /// waiting (a FIFO); the caller checks what was opened through the handle.
    pub fn open_file(&self, name: &OsStr) -> io::Result<File> {
        #[cfg(unix)]
        {
            unix::open_read(&self.dir, plain(name)?)
        }
        #[cfg(not(unix))]
        {
            self.unmoved()?;
            crate::platform::os::open_no_follow(&self.path.join(plain(name)?))
        }
    }

    /// Is `name` in this folder a regular file (not a link; Windows: nor reached under
    /// another name)?
    pub fn is_file(&self, name: &OsStr) -> bool {
        #[cfg(unix)]
        {
            plain(name).is_ok_and(|n| unix::stat(&self.dir, n).is_ok_and(|s| s.is_file))
        }
        #[cfg(not(unix))]
        {
            let path = self.path.join(name);
            std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file())
                && !crate::platform::links::reached_through_link(&path)
        }
    }

    /// Is something (anything, a link included) at `name` in this folder?
    pub fn has(&self, name: &OsStr) -> bool {
        #[cfg(unix)]
        {
            plain(name).is_ok_and(|n| unix::stat(&self.dir, n).is_ok())
        }
        #[cfg(not(unix))]
        {
            std::fs::symlink_metadata(self.path.join(name)).is_ok()
        }
    }

    /// The names in this folder (not `.` and `..`), read through the handle.
    pub fn names(&self) -> io::Result<Vec<OsString>> {
        #[cfg(unix)]
        {
            unix::names(&self.dir)
        }
        #[cfg(not(unix))]
        {
            Ok(std::fs::read_dir(&self.path)?.flatten().map(|e| e.file_name()).collect())
        }
    }

    /// Unix: does `name` in this folder hold the open `file` itself (not a link to it)?
    /// Elsewhere than Unix and Windows (the browser, which writes no set) it cannot be
    /// told: never.
    #[cfg(not(windows))]
    pub fn holds(&self, name: &OsStr, file: &File) -> bool {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let (Ok(name), Ok(open)) = (plain(name), file.metadata()) else { return false };
            unix::stat(&self.dir, name).is_ok_and(|s| !s.is_link && s.dev == open.dev() && s.ino == open.ino())
        }
        #[cfg(not(unix))]
        {
            let _ = (name, file);
            false
        }
    }

    /// Unix: removes the entry `name` (a file, or a link itself) from this folder.
    /// Elsewhere than Unix and Windows: refused.
    #[cfg(not(windows))]
    pub fn remove_file(&self, name: &OsStr) -> io::Result<()> {
        #[cfg(unix)]
        {
            unix::unlink(&self.dir, plain(name)?, false)
        }
        #[cfg(not(unix))]
        {
            let _ = name;
            Err(io::Error::new(io::ErrorKind::Unsupported, "no files on this platform"))
        }
    }

    /// Moves `name` in this folder to `to_name` in the folder `to`, only where nothing is
    /// there (`AlreadyExists` otherwise, and nothing moves).
    pub fn rename_no_replace(&self, name: &OsStr, to: &HeldDir, to_name: &OsStr) -> io::Result<()> {
        #[cfg(unix)]
        {
            unix::rename(&self.dir, plain(name)?, &to.dir, plain(to_name)?, true)
        }
        #[cfg(not(unix))]
        {
            self.unmoved()?;
            to.unmoved()?;
            crate::platform::os::rename_no_replace(&self.path.join(plain(name)?), &to.path.join(plain(to_name)?))
        }
    }

    /// Moves `name` in this folder to `to_name` in the folder `to`, replacing the name there
    /// (a link there is replaced itself, never followed).
    pub fn rename_over(&self, name: &OsStr, to: &HeldDir, to_name: &OsStr) -> io::Result<()> {
        #[cfg(unix)]
        {
            unix::rename(&self.dir, plain(name)?, &to.dir, plain(to_name)?, false)
        }
        #[cfg(not(unix))]
        {
            self.unmoved()?;
            to.unmoved()?;
            std::fs::rename(self.path.join(plain(name)?), to.path.join(plain(to_name)?))
        }
    }

    /// Syncs the folder's entries to the disk, where the system allows it.
    pub fn sync(&self) {
        #[cfg(unix)]
        let _ = self.dir.sync_all();
    }

    /// Is the entry at this folder's own path still this folder itself (not moved away,
    /// not a link or another folder put at its name)?
    pub fn still_at_its_path(&self) -> bool {
        let (Ok(here), Some(held)) = (crate::platform::os::identity_at(&self.path), self.id) else {
            return false;
        };
        here.0.is_dir() && !here.0.file_type().is_symlink() && here.1 == held
    }

    /// `Ok` where this folder is still at its path ([`Self::still_at_its_path`]); otherwise
    /// an error saying, in the user's words, that it was moved or replaced and this step
    /// was not made. Windows asks it before every step it takes by path (a Unix program
    /// under Wine can rename a held folder: Wine's sharing rules bind Windows programs
    /// only), so that no file is moved, removed or made through a link put at its name.
    pub fn unmoved(&self) -> io::Result<()> {
        if self.still_at_its_path() {
            return Ok(());
        }
        Err(self.moved_error())
    }

    /// The error that says, in the user's words, that this folder was moved or replaced
    /// while phonglab worked in it, and this step was not made.
    fn moved_error(&self) -> io::Error {
        let name = self.path.file_name().unwrap_or_default().to_string_lossy().into_owned();
        let name = phonglab_core::escape::terminal::text(&name);
        io::Error::new(io::ErrorKind::InvalidInput, crate::t!("set-held-folder-moved", name = name))
    }

    /// Windows: what `make` makes in this folder through its handle; where it fails and this
    /// folder is found moved or replaced meanwhile, the error that says so in words
    /// ([`Self::unmoved`]). Under Wine a Unix program that renames the folder held (and puts
    /// it back) makes the system answer "Invalid handle. (os error 6)" for the handle phonglab
    /// holds open, which nothing else does: `make` is asked again up to 3 times, 10 ms
    /// apart, and then said as the folder moved ("did not take this step": nothing was made).
    #[cfg(windows)]
    fn said_moved<T>(&self, make: impl Fn() -> io::Result<T>) -> io::Result<T> {
        /// `ERROR_INVALID_HANDLE`.
        const LOST: i32 = 6;
        let mut tries = 0;
        loop {
            match make() {
                Err(e) if e.raw_os_error() == Some(LOST) && tries < 3 => {
                    tries += 1;
                    std::thread::sleep(std::time::Duration::from_millis(10));
                }
                Err(e) if e.raw_os_error() == Some(LOST) => return Err(self.moved_error()),
                made => return made.map_err(|e| self.unmoved().err().unwrap_or(e)),
            }
        }
    }

    /// Where the folder `sub`, held, is now in this folder: at its own name, or at the
    /// name of a folder here with its identity (someone renamed it within this folder);
    /// `None` where it is in neither (moved out of this folder, or unreadable).
    pub fn now_in(&self, sub: &HeldDir) -> Option<PathBuf> {
        if sub.still_at_its_path() {
            return Some(sub.path.clone());
        }
        let held = sub.id?;
        self.names().ok()?.into_iter().map(|n| self.path.join(n)).find(|p| {
            crate::platform::os::identity_at(p)
                .is_ok_and(|(m, id)| m.is_dir() && !m.file_type().is_symlink() && id == held)
        })
    }

    /// The folder `sub`, held, held again where it is now in this folder ([`Self::now_in`]),
    /// checked to be the very folder by its identity: Windows works by path, so a working
    /// folder a Unix program renamed within this folder (under Wine) is worked in at its new
    /// name. `None` where it is not in this folder.
    pub fn found_again(&self, sub: &HeldDir) -> Option<HeldDir> {
        let at = self.now_in(sub)?;
        let again = HeldDir::open(&at).ok()?;
        (again.id? == sub.id?).then_some(again)
    }

    /// Removes the folder `sub`, held, from this folder, where it is empty: at its own name,
    /// or (Unix) at whatever name it has now in this folder (someone renamed it), found by
    /// its identity. `Err` where it is not empty, or not found in this folder (moved out of
    /// it: left where it is).
    pub fn remove_dir(&self, sub: HeldDir) -> io::Result<()> {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let name = sub.path.file_name().map(OsStr::to_os_string).unwrap_or_default();
            let open = sub.dir.metadata()?;
            let is_it = |n: &OsStr| {
                plain(n).is_ok_and(|n| {
                    unix::stat(&self.dir, n).is_ok_and(|s| s.is_dir && s.dev == open.dev() && s.ino == open.ino())
                })
            };
            let at = if is_it(&name) { Some(name) } else { self.names()?.into_iter().find(|n| is_it(n)) };
            let Some(at) = at else {
                return Err(io::Error::new(io::ErrorKind::NotFound, "the folder is no longer in its folder"));
            };
            unix::unlink(&self.dir, plain(&at)?, true)
        }
        #[cfg(windows)]
        {
            // Renamed within this folder by a Unix program (under Wine): removed at its new
            // name, found by its identity, as on Unix.
            let sub = if sub.still_at_its_path() { sub } else { self.found_again(&sub).unwrap_or(sub) };
            windows::remove_dir(sub.dir, sub.id, &sub.path)
        }
        #[cfg(not(any(unix, windows)))]
        {
            std::fs::remove_dir(&sub.path)
        }
    }
}

/// `name` where it is one entry's name (not empty, not `.` or `..`, no separator).
fn plain(name: &OsStr) -> io::Result<&OsStr> {
    let s = name.as_encoded_bytes();
    let bad = s.is_empty() || s == b"." || s == b".." || s.contains(&b'/') || (cfg!(windows) && s.contains(&b'\\'));
    if bad { Err(io::Error::new(io::ErrorKind::InvalidFilename, "not a plain file name")) } else { Ok(name) }
}

#[cfg(unix)]
mod unix {
    use std::ffi::{CString, OsStr, OsString};
    use std::fs::File;
    use std::io;
    use std::os::fd::{AsRawFd, FromRawFd, RawFd};
    use std::os::unix::ffi::{OsStrExt, OsStringExt};

    fn c(name: &OsStr) -> io::Result<CString> {
        CString::new(name.as_bytes()).map_err(|_| io::Error::new(io::ErrorKind::InvalidFilename, "a NUL in a name"))
    }

    fn fd(dir: Option<&File>) -> RawFd {
        dir.map_or(libc::AT_FDCWD, AsRawFd::as_raw_fd)
    }

    fn check(r: libc::c_int) -> io::Result<libc::c_int> {
        if r < 0 { Err(io::Error::last_os_error()) } else { Ok(r) }
    }

    fn open_at(dir: Option<&File>, name: &OsStr, flags: libc::c_int, mode: libc::c_uint) -> io::Result<File> {
        let name = c(name)?;
        // SAFETY: `name` is NUL-terminated and lives through the call; the descriptor, if
        // any, is open (borrowed from a `File`).
        let f = check(unsafe { libc::openat(fd(dir), name.as_ptr(), flags | libc::O_CLOEXEC, mode) })?;
        // SAFETY: `f` was just opened and is owned here alone.
        Ok(unsafe { File::from_raw_fd(f) })
    }

    pub fn open_dir(dir: Option<&File>, name: &OsStr) -> io::Result<File> {
        open_at(dir, name, libc::O_RDONLY | libc::O_DIRECTORY | libc::O_NOFOLLOW, 0)
    }

    pub fn create_new(dir: &File, name: &OsStr) -> io::Result<File> {
        open_at(Some(dir), name, libc::O_WRONLY | libc::O_CREAT | libc::O_EXCL | libc::O_NOFOLLOW, 0o666)
    }

    pub fn create_private(dir: &File, name: &OsStr) -> io::Result<File> {
        open_at(Some(dir), name, libc::O_WRONLY | libc::O_CREAT | libc::O_EXCL | libc::O_NOFOLLOW, 0o600)
    }

    pub fn append(dir: &File, name: &OsStr) -> io::Result<File> {
        open_at(Some(dir), name, libc::O_WRONLY | libc::O_APPEND | libc::O_CREAT | libc::O_NOFOLLOW, 0o600)
    }

    pub fn open_read(dir: &File, name: &OsStr) -> io::Result<File> {
        open_at(Some(dir), name, libc::O_RDONLY | libc::O_NOFOLLOW | libc::O_NONBLOCK, 0)
    }

    pub fn mkdir(dir: &File, name: &OsStr) -> io::Result<()> {
        let name = c(name)?;
        // SAFETY: as in `open_at`.
        check(unsafe { libc::mkdirat(dir.as_raw_fd(), name.as_ptr(), 0o700) }).map(drop)
    }

    pub fn unlink(dir: &File, name: &OsStr, folder: bool) -> io::Result<()> {
        let name = c(name)?;
        let flags = if folder { libc::AT_REMOVEDIR } else { 0 };
        // SAFETY: as in `open_at`.
        check(unsafe { libc::unlinkat(dir.as_raw_fd(), name.as_ptr(), flags) }).map(drop)
    }

    /// What `fstatat` says of an entry (a link not followed).
    pub struct Stat {
        pub dev: u64,
        pub ino: u64,
        pub is_file: bool,
        pub is_dir: bool,
        pub is_link: bool,
    }

    pub fn stat(dir: &File, name: &OsStr) -> io::Result<Stat> {
        let name = c(name)?;
        let mut st = std::mem::MaybeUninit::<libc::stat>::uninit();
        // SAFETY: as in `open_at`; `st` is written by the call before it is read.
        check(unsafe { libc::fstatat(dir.as_raw_fd(), name.as_ptr(), st.as_mut_ptr(), libc::AT_SYMLINK_NOFOLLOW) })?;
        // SAFETY: the call succeeded, so `st` is filled.
        let st = unsafe { st.assume_init() };
        let kind = st.st_mode & libc::S_IFMT;
        #[allow(clippy::useless_conversion, clippy::unnecessary_cast)]
        Ok(Stat {
            dev: st.st_dev as u64,
            ino: st.st_ino as u64,
            is_file: kind == libc::S_IFREG,
            is_dir: kind == libc::S_IFDIR,
            is_link: kind == libc::S_IFLNK,
        })
    }

    pub fn rename(from: &File, name: &OsStr, to: &File, to_name: &OsStr, no_replace: bool) -> io::Result<()> {
        let (f, t) = (c(name)?, c(to_name)?);
        #[cfg(target_os = "linux")]
        if no_replace {
            // SAFETY: as in `open_at`, for both names and descriptors.
            let r = unsafe {
                libc::renameat2(from.as_raw_fd(), f.as_ptr(), to.as_raw_fd(), t.as_ptr(), libc::RENAME_NOREPLACE)
            };
            if r == 0 {
                return Ok(());
            }
            let e = io::Error::last_os_error();
            if !matches!(e.raw_os_error(), Some(libc::EINVAL | libc::ENOSYS)) {
                return Err(e);
            }
        }
        // Where the flag is refused, and elsewhere: a look, then the rename (only someone
        // writing into the folder at that very instant could race it).
        if no_replace && stat(to, to_name).is_ok() {
            return Err(io::Error::new(io::ErrorKind::AlreadyExists, "a file is already there"));
        }
        // SAFETY: as above.
        check(unsafe { libc::renameat(from.as_raw_fd(), f.as_ptr(), to.as_raw_fd(), t.as_ptr()) }).map(drop)
    }

    /// The names in the folder `dir` (through a descriptor of its own, opened from `dir`).
    pub fn names(dir: &File) -> io::Result<Vec<OsString>> {
        let own = open_dir(Some(dir), OsStr::new("."))?;
        use std::os::fd::IntoRawFd;
        let raw = own.into_raw_fd();
        // SAFETY: `raw` is an open folder's descriptor, owned here; `fdopendir` takes it
        // (closed by `closedir`), or it is closed here where it fails.
        let stream = unsafe { libc::fdopendir(raw) };
        if stream.is_null() {
            let e = io::Error::last_os_error();
            // SAFETY: not taken by `fdopendir`: closed once here.
            unsafe { libc::close(raw) };
            return Err(e);
        }
        let mut names = Vec::new();
        loop {
            // SAFETY: `stream` is open until `closedir` below.
            let entry = unsafe { libc::readdir(stream) };
            if entry.is_null() {
                break;
            }
            // SAFETY: `d_name` is a NUL-terminated name inside the entry, valid until the
            // next `readdir`; it is copied at once.
            let name = unsafe { std::ffi::CStr::from_ptr((*entry).d_name.as_ptr()) }.to_bytes().to_vec();
            if name != b"." && name != b".." {
                names.push(OsString::from_vec(name));
            }
        }
        // SAFETY: closed once.
        unsafe { libc::closedir(stream) };
        Ok(names)
    }
}

#[cfg(windows)]
mod windows {
    use std::fs::File;
    use std::io;
    use std::os::windows::fs::{MetadataExt, OpenOptionsExt};
    use std::os::windows::io::AsRawHandle;
    use std::path::Path;

    use windows_sys::Win32::Foundation::GENERIC_READ;
    use windows_sys::Win32::Storage::FileSystem::{
        DELETE, FILE_DISPOSITION_INFO, FILE_FLAG_BACKUP_SEMANTICS, FILE_FLAG_OPEN_REPARSE_POINT, FileDispositionInfo,
        SetFileInformationByHandle,
    };

    /// `FILE_SHARE_READ | FILE_SHARE_WRITE`: not `FILE_SHARE_DELETE`.
    const SHARE_NO_DELETE: u32 = 3;
    /// `FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE`.
    const SHARE_ALL: u32 = 7;
    /// `FILE_READ_ATTRIBUTES`.
    const READ_ATTRIBUTES: u32 = 0x80;
    /// `FILE_ATTRIBUTE_REPARSE_POINT`.
    const REPARSE_POINT: u32 = 0x400;
    /// `ERROR_CANT_RESOLVE_FILENAME`: a link, refused (as `open_no_follow` says it).
    const LINK_REFUSED: i32 = 1921;

    /// Opens the folder at `path` itself with `access` and `share`, refusing a link.
    fn open_itself(path: &Path, access: u32, share: u32) -> io::Result<File> {
        let dir = File::options()
            .access_mode(access)
            .share_mode(share)
            .custom_flags(FILE_FLAG_BACKUP_SEMANTICS | FILE_FLAG_OPEN_REPARSE_POINT)
            .open(path)?;
        let meta = dir.metadata()?;
        if meta.file_attributes() & REPARSE_POINT != 0 || !crate::platform::links::opened_under_its_own_name(&dir, path)
        {
            return Err(io::Error::from_raw_os_error(LINK_REFUSED));
        }
        if !meta.is_dir() {
            return Err(io::Error::new(io::ErrorKind::NotADirectory, "not a folder"));
        }
        Ok(dir)
    }

    pub fn open_dir(path: &Path) -> io::Result<File> {
        open_itself(path, GENERIC_READ, SHARE_NO_DELETE)
    }

    /// What [`create_in`] makes.
    pub enum Make {
        /// A new file, to write.
        File,
        /// A new file, to write, for this user alone (one of phonglab's records).
        Private,
        /// A file for this user alone, to append to, made if missing.
        Append,
        /// A new folder for this user alone, held as [`open_dir`] holds one.
        Folder,
    }

    /// Makes `name` in the folder held `dir` through its handle: `NtCreateFile` with
    /// `RootDirectory` = that handle (Wine: `openat`-like, relative to the folder's own
    /// descriptor), never by the folder's path, so a folder renamed and replaced by a link
    /// between the look ([`super::HeldDir::unmoved`]) and this step still gets it, and
    /// nothing is made in the folder the link leads to (issue 59, round 3: `.staged`, the
    /// journal's temporary file and an empty set file were made there). A link at `name`
    /// is never followed to make a file (`FILE_OPEN_REPARSE_POINT`; a new one fails on
    /// anything there, `AlreadyExists`). What is this user's alone is made with the
    /// owner-only descriptor ([`phonglab_core::files::private::OwnerOnly`]).
    pub fn create_in(dir: &File, name: &std::ffi::OsStr, make: Make) -> io::Result<File> {
        use std::os::windows::ffi::OsStrExt;
        use std::os::windows::io::FromRawHandle;
        use windows_sys::Wdk::Foundation::OBJECT_ATTRIBUTES;
        use windows_sys::Wdk::Storage::FileSystem::{
            FILE_CREATE, FILE_DIRECTORY_FILE, FILE_NON_DIRECTORY_FILE, FILE_OPEN_IF, FILE_OPEN_REPARSE_POINT,
            FILE_SYNCHRONOUS_IO_NONALERT, NtCreateFile,
        };
        use windows_sys::Win32::Foundation::{
            GENERIC_WRITE, OBJ_CASE_INSENSITIVE, RtlNtStatusToDosError, UNICODE_STRING,
        };
        use windows_sys::Win32::Storage::FileSystem::{
            FILE_ATTRIBUTE_NORMAL, FILE_GENERIC_READ, FILE_GENERIC_WRITE, FILE_WRITE_DATA, SYNCHRONIZE,
        };
        let private = match make {
            Make::File => None,
            Make::Private | Make::Append => Some(phonglab_core::files::private::OwnerOnly::new(false)?),
            Make::Folder => Some(phonglab_core::files::private::OwnerOnly::folder_in(dir)?),
        };
        let (access, share, disposition, options, attributes) = match make {
            Make::File | Make::Private => (
                GENERIC_READ | GENERIC_WRITE | DELETE | SYNCHRONIZE,
                SHARE_ALL,
                FILE_CREATE,
                FILE_NON_DIRECTORY_FILE,
                FILE_ATTRIBUTE_NORMAL,
            ),
            // As std opens to append: every right to write but writing at a position.
            Make::Append => (
                (FILE_GENERIC_WRITE & !FILE_WRITE_DATA) | FILE_GENERIC_READ | DELETE,
                SHARE_ALL,
                FILE_OPEN_IF,
                FILE_NON_DIRECTORY_FILE,
                FILE_ATTRIBUTE_NORMAL,
            ),
            Make::Folder => (GENERIC_READ | SYNCHRONIZE, SHARE_NO_DELETE, FILE_CREATE, FILE_DIRECTORY_FILE, 0),
        };
        let mut wide: Vec<u16> = name.encode_wide().collect();
        let bytes = u16::try_from(wide.len() * 2)
            .map_err(|_| io::Error::new(io::ErrorKind::InvalidFilename, "a name past 32767 characters"))?;
        let object_name = UNICODE_STRING { Length: bytes, MaximumLength: bytes, Buffer: wide.as_mut_ptr() };
        let attrs = OBJECT_ATTRIBUTES {
            Length: size_of::<OBJECT_ATTRIBUTES>() as u32,
            RootDirectory: dir.as_raw_handle(),
            ObjectName: &raw const object_name,
            Attributes: OBJ_CASE_INSENSITIVE,
            SecurityDescriptor: private.as_ref().map_or(std::ptr::null(), |p| p.descriptor().cast()),
            SecurityQualityOfService: std::ptr::null(),
        };
        let mut handle = std::ptr::null_mut();
        let mut status_block = Default::default();
        // SAFETY: `attrs` points at `object_name` (whose buffer, `wide`, holds `bytes`
        // bytes), at the open folder's handle and at the descriptor in `private`, all alive
        // through the call; `handle` and `status_block` are written by it.
        let status = unsafe {
            NtCreateFile(
                &mut handle,
                access,
                &raw const attrs,
                &mut status_block,
                std::ptr::null(),
                attributes,
                share,
                disposition,
                options | FILE_SYNCHRONOUS_IO_NONALERT | FILE_OPEN_REPARSE_POINT,
                std::ptr::null(),
                0,
            )
        };
        if status < 0 {
            // SAFETY: no pointers.
            let code = unsafe { RtlNtStatusToDosError(status) };
            return Err(io::Error::from_raw_os_error(code as i32));
        }
        // SAFETY: `handle` was just opened by the call, and is owned here alone.
        Ok(unsafe { File::from_raw_handle(handle) })
    }

    pub fn remove_dir(held: File, id: Option<(u64, u64)>, path: &Path) -> io::Result<()> {
        let id = id.ok_or_else(|| io::Error::new(io::ErrorKind::NotFound, "its identity was not read"))?;
        drop(held);
        let dir = open_itself(path, DELETE | READ_ATTRIBUTES, SHARE_ALL)?;
        if crate::platform::os::file_identity(&dir)?.1 != id {
            return Err(io::Error::new(io::ErrorKind::NotFound, "another folder is at its name"));
        }
        let info = FILE_DISPOSITION_INFO { DeleteFile: true };
        let size = size_of::<FILE_DISPOSITION_INFO>() as u32;
        // SAFETY: the handle is open (with DELETE access) through the call; `info` is a
        // FILE_DISPOSITION_INFO of `size` bytes, read only during it.
        let ok = unsafe {
            SetFileInformationByHandle(dir.as_raw_handle(), FileDispositionInfo, (&raw const info).cast(), size)
        };
        if ok == 0 { Err(io::Error::last_os_error()) } else { Ok(()) }
    }
}

#[cfg(test)]
mod tests {
    use super::HeldDir;
    use std::ffi::OsStr;

    fn fresh(name: &str) -> std::path::PathBuf {
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap_or_default().as_nanos();
        let d = std::env::temp_dir().join(format!("phonglab-held {name} {}-{nanos}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// Unix: a folder held, then renamed away and replaced by a link to another folder:
    /// every step still acts in the folder held; nothing is made, moved or removed in the
    /// folder the link leads to.
    #[test]
    #[cfg(unix)]
    fn a_held_folder_renamed_and_replaced_by_a_link_is_still_the_one_worked_in() {
        let root = fresh("swapped");
        let (dir, away, outside) = (root.join("staging"), root.join("away"), root.join("outside"));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::create_dir_all(&outside).unwrap();
        std::fs::write(outside.join("a.md"), "the teacher's").unwrap();
        let held = HeldDir::open(&dir).unwrap();
        std::fs::rename(&dir, &away).unwrap();
        std::os::unix::fs::symlink(&outside, &dir).unwrap();
        assert!(!held.still_at_its_path(), "a link at its name is not the folder held");
        use std::io::Write;
        held.create_new(OsStr::new("a.md")).unwrap().write_all(b"new").unwrap();
        let sub = held.create_dir(OsStr::new("sub")).unwrap();
        held.rename_no_replace(OsStr::new("a.md"), &sub, OsStr::new("a.md")).unwrap();
        assert!(held.rename_no_replace(OsStr::new("sub"), &held, OsStr::new("sub")).is_err(), "nothing over a name");
        assert_eq!(std::fs::read(away.join("sub/a.md")).unwrap(), b"new");
        sub.remove_file(OsStr::new("a.md")).unwrap();
        held.remove_dir(sub).unwrap();
        assert_eq!(held.names().unwrap(), Vec::<std::ffi::OsString>::new());
        assert_eq!(std::fs::read(outside.join("a.md")).unwrap(), b"the teacher's");
        assert_eq!(std::fs::read_dir(&outside).unwrap().count(), 1, "nothing made outside");
        // Removed where it is now (renamed away), found by its identity; the link is left.
        root_holds(&root, held);
        assert!(!away.exists() && std::fs::symlink_metadata(&dir).unwrap().file_type().is_symlink());
    }

    #[cfg(unix)]
    fn root_holds(root: &std::path::Path, held: HeldDir) {
        HeldDir::open(root).unwrap().remove_dir(held).unwrap();
    }

    /// A link is never held (Unix: `O_NOFOLLOW`; Windows: a reparse point, or under Wine a
    /// Unix link reached under another name).
    #[test]
    #[cfg(any(unix, windows))]
    fn a_link_to_a_folder_is_not_held() {
        let root = fresh("link");
        std::fs::create_dir_all(root.join("real")).unwrap();
        if !crate::io::atomic_write::tests::plant_link(&root.join("real"), &root.join("link")) {
            eprintln!("no symbolic link can be made here: nothing to test");
            return;
        }
        assert!(HeldDir::open(&root.join("link")).is_err());
        assert!(HeldDir::open(&root).unwrap().open_dir(OsStr::new("link")).is_err());
        assert!(HeldDir::open(&root.join("real")).is_ok());
    }

    /// Windows under Wine (issue 59, round 2, p25): a Unix program, which Wine's sharing
    /// rules do not bind, renames a held folder away and puts a link to another folder at its
    /// name. Every step taken by its path is refused in words first (nothing is made, opened,
    /// moved in or out through the link: before, a new set's files and an old set's PDFs were
    /// moved into the folder the link led to), and the folder is found where it went.
    #[test]
    #[cfg(windows)]
    fn a_held_folder_a_unix_program_renamed_is_never_worked_in_through_its_name() {
        use std::io::Write;
        let root = fresh("unix-swapped");
        let (dir, away, outside) = (root.join("staging"), root.join("away"), root.join("outside"));
        for d in [&dir, &outside, &root.join("other")] {
            std::fs::create_dir_all(d).unwrap();
        }
        std::fs::write(outside.join("a.md"), "the teacher's").unwrap();
        std::fs::write(root.join("other").join("b.md"), "to move in").unwrap();
        let parent = HeldDir::open(&root).unwrap();
        let held = parent.open_dir(OsStr::new("staging")).unwrap();
        let other = parent.open_dir(OsStr::new("other")).unwrap();
        held.create_new(OsStr::new("kept.md")).unwrap().write_all(b"in the folder held").unwrap();
        let unix = |p: &std::path::Path| {
            let out = std::process::Command::new("winepath").arg("-u").arg(p).output().ok()?;
            out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim_end().to_string())
        };
        let (Some(dir_u), Some(away_u)) = (unix(&dir), unix(&away)) else {
            eprintln!("not under Wine: no Unix program can rename a folder held here: nothing to test");
            return;
        };
        // A Unix program run from Wine: its exit status is not Wine's to give, so its work
        // is waited for, up to 10 s.
        let unix_side = |program: &str, args: &[&str], done: &dyn Fn() -> bool| {
            let _ = std::process::Command::new(program).args(args).status();
            (0..500).any(|_| done() || (std::thread::sleep(std::time::Duration::from_millis(20)), false).1)
        };
        let outside_u = unix(&outside).unwrap_or_default();
        if !unix_side(r"Z:\bin\mv", &[&dir_u, &away_u], &|| away.is_dir())
            || !unix_side(r"Z:\bin\ln", &["-s", &outside_u, &dir_u], &|| {
                crate::platform::links::reached_through_link(&dir)
            })
        {
            eprintln!("the Unix side could not rename the folder or plant a link: nothing to test");
            return;
        }
        assert!(!held.still_at_its_path(), "a link at its name is not the folder held");
        let e = held.create_new(OsStr::new("new.md")).unwrap_err().to_string();
        assert!(e.contains("staging") && e.contains("moved or replaced"), "{e}");
        assert!(held.open_file(OsStr::new("a.md")).is_err(), "a file read through the link");
        assert!(held.create_dir(OsStr::new("sub")).is_err(), "a folder made through the link");
        assert!(crate::platform::by_handle::open_in(&held, OsStr::new("a.md")).is_err(), "opened to move or remove");
        let b = crate::platform::by_handle::open_in(&other, OsStr::new("b.md")).unwrap();
        assert!(b.rename_no_replace(&held, OsStr::new("b.md")).is_err(), "moved in through the link");
        assert!(held.rename_over(OsStr::new("kept.md"), &other, OsStr::new("kept.md")).is_err());
        let names = |d: &std::path::Path| {
            let mut v: Vec<String> =
                std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
            v.sort();
            v
        };
        assert_eq!(names(&outside), ["a.md"], "nothing made or moved outside");
        assert_eq!(std::fs::read(outside.join("a.md")).unwrap(), b"the teacher's");
        assert_eq!(names(&root.join("other")), ["b.md"], "nothing moved out of the other folder");
        assert_eq!(std::fs::read(away.join("kept.md")).unwrap(), b"in the folder held");
        assert_eq!(parent.now_in(&held), Some(away.clone()), "found where it went, by its identity");
        let again = parent.found_again(&held).expect("held again where it went");
        assert_eq!(again.path(), away);
        again.create_new(OsStr::new("new.md")).unwrap().write_all(b"made where it went").unwrap();
        assert_eq!(std::fs::read(away.join("new.md")).unwrap(), b"made where it went");
    }

    /// Windows under Wine (issue 59, round 3, p30 flip-staging): a Unix program renames a
    /// held folder away and puts a link to another folder at its name, between phonglab's
    /// look and its step. What is made in the folder is made through its handle
    /// (`NtCreateFile`, `RootDirectory`), so it lands in the folder held, wherever it went,
    /// and nothing is made in the folder the link leads to (before, by path: a `.staged`
    /// list, a journal's temporary file and an empty set file were made there); the records
    /// and folders phonglab makes are this user's alone.
    #[test]
    #[cfg(windows)]
    fn what_is_made_in_a_held_folder_swapped_for_a_link_is_made_in_the_folder_held() {
        use super::windows::{Make, create_in};
        use std::io::Write;
        let root = fresh("unix-swapped-make");
        let (dir, away, outside) = (root.join("staging"), root.join("away"), root.join("outside"));
        for d in [&dir, &outside] {
            std::fs::create_dir_all(d).unwrap();
        }
        std::fs::write(outside.join("a.md"), "the teacher's").unwrap();
        let held = HeldDir::open(&root).unwrap().open_dir(OsStr::new("staging")).unwrap();
        let unix = |p: &std::path::Path| {
            let out = std::process::Command::new("winepath").arg("-u").arg(p).output().ok()?;
            out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim_end().to_string())
        };
        let (Some(dir_u), Some(away_u), Some(outside_u)) = (unix(&dir), unix(&away), unix(&outside)) else {
            eprintln!("not under Wine: no Unix program can rename a folder held here: nothing to test");
            return;
        };
        let _ = std::process::Command::new(r"Z:\bin\mv").args([&dir_u, &away_u]).status();
        // A Unix program's work is waited for (Wine does not give its exit status), up to 10 s.
        let _ = (0..500).any(|_| away.is_dir() || (std::thread::sleep(std::time::Duration::from_millis(20)), false).1);
        let _ = std::process::Command::new(r"Z:\bin\ln").args(["-s", &outside_u, &dir_u]).status();
        let swapped = (0..500).any(|_| {
            crate::platform::links::reached_through_link(&dir)
                || (std::thread::sleep(std::time::Duration::from_millis(20)), false).1
        });
        if !swapped || !away.is_dir() {
            eprintln!("the Unix side could not rename the folder or plant a link: nothing to test");
            return;
        }
        create_in(held.handle(), OsStr::new("new.md"), Make::File).unwrap().write_all(b"new").unwrap();
        let record = create_in(held.handle(), OsStr::new("record"), Make::Private).unwrap();
        assert!(crate::platform::os::is_this_users_alone(&record), "a record is this user's alone");
        drop(record);
        create_in(held.handle(), OsStr::new("list"), Make::Append).unwrap().write_all(b"line\n").unwrap();
        create_in(held.handle(), OsStr::new("list"), Make::Append).unwrap().write_all(b"more\n").unwrap();
        let sub = create_in(held.handle(), OsStr::new("sub"), Make::Folder).unwrap();
        assert!(crate::platform::os::is_this_users_alone(&sub), "a working folder is this user's alone");
        drop(sub);
        let names = |d: &std::path::Path| {
            let mut v: Vec<String> =
                std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
            v.sort();
            v
        };
        assert_eq!(names(&outside), ["a.md"], "nothing made through the link");
        assert_eq!(names(&away), ["list", "new.md", "record", "sub"], "made in the folder held");
        assert_eq!(std::fs::read(away.join("new.md")).unwrap(), b"new");
        assert_eq!(std::fs::read(away.join("list")).unwrap(), b"line\nmore\n", "appended to");
        let e = held.create_new(OsStr::new("other.md")).unwrap_err().to_string();
        assert!(e.contains("staging") && e.contains("moved or replaced"), "said in words: {e}");
    }

    /// Windows: a folder held cannot be renamed or removed by anyone (held without
    /// `FILE_SHARE_DELETE`), and its own removal goes once it is empty.
    #[test]
    #[cfg(windows)]
    fn a_held_folder_cannot_be_renamed_or_removed_until_let_go() {
        let root = fresh("held");
        let dir = root.join("staging");
        std::fs::create_dir_all(&dir).unwrap();
        let parent = HeldDir::open(&root).unwrap();
        let held = parent.open_dir(OsStr::new("staging")).unwrap();
        assert!(std::fs::rename(&dir, root.join("away")).is_err(), "renamed while held");
        assert!(std::fs::remove_dir(&dir).is_err(), "removed while held");
        let f = held.create_new(OsStr::new("a.md")).unwrap();
        drop(f);
        assert!(dir.join("a.md").is_file());
        std::fs::remove_file(dir.join("a.md")).unwrap();
        parent.remove_dir(held).unwrap();
        assert!(!dir.exists());
    }
}
