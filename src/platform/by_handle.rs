//! A file moved or removed as the very file it is, never as whatever its name leads to: it
//! is opened itself ([`open_in`], in a folder held: a link is not followed), its caller checks it through that
//! handle (its identity, size and bytes), and only then is it moved ([`Opened::rename_no_replace`])
//! or removed ([`Opened::remove`]).
//!
//! - Windows: opened with `FILE_FLAG_OPEN_REPARSE_POINT` (a link is opened itself, and
//!   refused), sharing everything, with `DELETE` access; the move and the removal go through
//!   that handle (`SetFileInformationByHandle`: `FileRenameInfo`, not replacing;
//!   `FileDispositionInfo`), so they act on the file the caller checked, whatever was put at
//!   its name since. Under Wine a Unix link opens as the file it names (and a rename or a
//!   removal by its name moves or removes that file): its handle has that file's identity,
//!   and it is reached under another name than the one asked for, so it is refused.
//! - Unix: opened with `O_NOFOLLOW` relative to the folder's descriptor (a link is refused
//!   by the open itself); a move or a removal is by name relative to the folders'
//!   descriptors (`renameat2`, `unlinkat`: neither follows the last component, and a folder
//!   renamed or replaced by a link meanwhile changes nothing: [`HeldDir`]), asked first
//!   (`fstatat`: the same device and inode as the handle), and a move is checked again at
//!   its new name and undone where something else went.

use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io;

use super::held_dir::HeldDir;

/// A file opened itself in a folder held ([`HeldDir`]), to be checked through
/// [`Opened::file`], then moved or removed.
pub struct Opened<'a> {
    file: File,
    /// The folder it was opened in, and its name there (Unix: asked again before the move
    /// or the removal, through the folder's descriptor; Windows acts through the handle,
    /// asking first that the folders are still at their paths, and moves back a file whose
    /// new folder was found moved meanwhile).
    dir: &'a HeldDir,
    name: OsString,
}

/// Opens the file `name` in the folder held `dir` itself (see the module's documentation).
/// `Err` where nothing is there, where it is a link (Windows: also one reached under
/// another name, Wine's Unix link), or where it cannot be opened (Windows: another program
/// holds it open without sharing its deletion: `ERROR_SHARING_VIOLATION`).
pub fn open_in<'a>(dir: &'a HeldDir, name: &OsStr) -> io::Result<Opened<'a>> {
    // Windows opens by path: the folder is asked first to be the one held (under Wine a
    // Unix program can rename it and put a link at its name; issue 59, round 2).
    #[cfg(windows)]
    let file = {
        dir.unmoved()?;
        windows::open(&dir.path().join(name))?
    };
    #[cfg(not(windows))]
    let file = dir.open_file(name)?;
    Ok(Opened { file, dir, name: name.to_os_string() })
}

impl Opened<'_> {
    /// The open file, to be checked (its identity, size and bytes) before it is acted on.
    pub fn file(&self) -> &File {
        &self.file
    }

    /// Removes the file opened: `Ok(true)`. Unix: only where its name still holds it
    /// (`Ok(false)` otherwise: nothing removed). Windows: marked for deletion through the
    /// handle, gone when the last handle to it is closed.
    pub fn remove(self) -> io::Result<bool> {
        #[cfg(windows)]
        {
            self.dir.unmoved()?;
            windows::remove(&self.file).map(|()| true)
        }
        #[cfg(not(windows))]
        {
            if !self.dir.holds(&self.name, &self.file) {
                return Ok(false);
            }
            self.dir.remove_file(&self.name).map(|()| true)
        }
    }

    /// Moves the file opened to `to_name` in the folder held `to`, where nothing is (not
    /// even a link; `AlreadyExists` otherwise): `Ok(true)`. Unix: only where its name still
    /// holds it, and checked at its new name afterwards: `Ok(false)` where something else
    /// was there (moved back: nothing moved). Windows: both folders asked first to be the
    /// ones held ([`HeldDir::unmoved`]), and the new name checked afterwards to hold the file
    /// checked (Wine renames by the path it was opened at): `Ok(false)` and moved back where
    /// not; `Err` where the new folder was found moved and the file was moved back
    /// (`Ok(true)` where it could not be: it is in the folder it was moved to).
    pub fn rename_no_replace(self, to: &HeldDir, to_name: &OsStr) -> io::Result<bool> {
        #[cfg(windows)]
        {
            self.dir.unmoved()?;
            to.unmoved()?;
            windows::rename_no_replace(&self.file, &to.path().join(to_name))?;
            // Moved between the look and the move: the file is put back where it was, by
            // its handle, when its own folder is still where it was; the error says so.
            if let Err(e) = to.unmoved() {
                if self.dir.unmoved().is_ok()
                    && windows::rename_no_replace(&self.file, &self.dir.path().join(&self.name)).is_ok()
                {
                    return Err(e);
                }
                // Not put back: it is in its new folder, wherever that went, and the
                // caller's undo looks for it there (found by its identity).
                return Ok(true);
            }
            // Wine renames by the path the handle was opened at: where its folder was swapped
            // for a link between the look and the move, the file the link leads to moved
            // instead. What is now at the new name must be the file checked; anything else
            // goes back by the way it came, and nothing is said moved.
            // (Its new folder moved away just after the move: the file is taken to be in it,
            // where the caller's undo, finding that folder by its identity, asks for it.)
            let (at, mine) = (to.path().join(to_name), crate::platform::os::file_identity(&self.file)?.1);
            let arrived = || crate::platform::os::identity_at(&at).is_ok_and(|(m, id)| m.is_file() && id == mine);
            if !arrived() && to.still_at_its_path() {
                let _ = crate::platform::os::rename_no_replace(&at, &self.dir.path().join(&self.name));
                return Ok(false);
            }
            Ok(true)
        }
        #[cfg(not(windows))]
        {
            if !self.dir.holds(&self.name, &self.file) {
                return Ok(false);
            }
            self.dir.rename_no_replace(&self.name, to, to_name)?;
            if to.holds(to_name, &self.file) {
                return Ok(true);
            }
            let _ = to.rename_no_replace(to_name, self.dir, &self.name);
            Ok(false)
        }
    }
}

#[cfg(windows)]
mod windows {
    use std::fs::File;
    use std::io;
    use std::os::windows::ffi::OsStrExt;
    use std::os::windows::fs::{MetadataExt, OpenOptionsExt};
    use std::os::windows::io::AsRawHandle;
    use std::path::Path;

    use windows_sys::Win32::Foundation::GENERIC_READ;
    use windows_sys::Win32::Storage::FileSystem::{
        DELETE, FILE_DISPOSITION_INFO, FILE_FLAG_OPEN_REPARSE_POINT, FILE_RENAME_INFO, FileDispositionInfo,
        FileRenameInfo, SetFileInformationByHandle,
    };

    /// `FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE`.
    const SHARE_ALL: u32 = 7;
    /// `FILE_ATTRIBUTE_REPARSE_POINT`.
    const REPARSE_POINT: u32 = 0x400;
    /// `ERROR_CANT_RESOLVE_FILENAME`: a link, refused (as `open_no_follow` says it).
    const LINK_REFUSED: i32 = 1921;

    pub fn open(path: &Path) -> io::Result<File> {
        let file = File::options()
            .access_mode(GENERIC_READ | DELETE)
            .share_mode(SHARE_ALL)
            .custom_flags(FILE_FLAG_OPEN_REPARSE_POINT)
            .open(path)?;
        let link = file.metadata()?.file_attributes() & REPARSE_POINT != 0;
        if link || !crate::platform::links::opened_under_its_own_name(&file, path) {
            return Err(io::Error::from_raw_os_error(LINK_REFUSED));
        }
        Ok(file)
    }

    pub fn remove(file: &File) -> io::Result<()> {
        let info = FILE_DISPOSITION_INFO { DeleteFile: true };
        let size = size_of::<FILE_DISPOSITION_INFO>() as u32;
        // SAFETY: the handle is open (with DELETE access) through the call; `info` is a
        // FILE_DISPOSITION_INFO of `size` bytes, read only during it.
        let ok = unsafe {
            SetFileInformationByHandle(file.as_raw_handle(), FileDispositionInfo, (&raw const info).cast(), size)
        };
        if ok == 0 { Err(io::Error::last_os_error()) } else { Ok(()) }
    }

    pub fn rename_no_replace(file: &File, to: &Path) -> io::Result<()> {
        let to = std::path::absolute(to)?;
        let name: Vec<u16> = to.as_os_str().encode_wide().collect();
        let name_bytes = name.len() * size_of::<u16>();
        let size = size_of::<FILE_RENAME_INFO>() + name_bytes;
        // A buffer of u64s: aligned for FILE_RENAME_INFO, with room for the name after it.
        let mut buf = vec![0u64; size.div_ceil(8)];
        let info = buf.as_mut_ptr().cast::<FILE_RENAME_INFO>();
        // SAFETY: `buf` holds `size` bytes, aligned for FILE_RENAME_INFO; the name is copied
        // into the space from its FileName field on, which `size` counts; the handle is open
        // with DELETE access through the call, which only reads the buffer.
        let ok = unsafe {
            (*info).Anonymous.ReplaceIfExists = false;
            (*info).RootDirectory = std::ptr::null_mut();
            (*info).FileNameLength = u32::try_from(name_bytes).map_err(io::Error::other)?;
            std::ptr::copy_nonoverlapping(name.as_ptr(), (&raw mut (*info).FileName).cast::<u16>(), name.len());
            SetFileInformationByHandle(
                file.as_raw_handle(),
                FileRenameInfo,
                info.cast_const().cast(),
                u32::try_from(size).map_err(io::Error::other)?,
            )
        };
        if ok == 0 { Err(io::Error::last_os_error()) } else { Ok(()) }
    }
}
