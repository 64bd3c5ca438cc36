//! Whether a file or folder is reached through a link at its own name: what a set's writer
//! asks of its folder, its files and its records before it writes, moves or deletes one.
//!
//! Unix: the entry is a symbolic link (`lstat`). Windows: the entry, opened itself
//! (`FILE_FLAG_OPEN_REPARSE_POINT | FILE_FLAG_BACKUP_SEMANTICS`), is a reparse point (a
//! symbolic link, a junction), or the handle's final path (`GetFinalPathNameByHandleW`) is
//! not its folder's final path joined with the name asked for (compared without case): the
//! file was reached under another name than its own. The name asked for is first made
//! long (`GetLongPathNameW`): a real folder given by its 8.3 short name (`FICHAS~1`,
//! Wine's `PHON~0IC`) is itself, while a link's long name is still the link's own. Wine shows a Unix symbolic link as a
//! plain file with no reparse point, and a handle opened through it is the target's, so
//! only the second test sees it there; on Windows it also catches a link that a filter
//! driver hides.

use std::path::Path;

/// Is `path` a link (or reached through one at its last component)? `false` where nothing
/// is there or it cannot be opened to ask.
pub fn reached_through_link(path: &Path) -> bool {
    #[cfg(windows)]
    {
        windows::reached_through_link(path)
    }
    #[cfg(not(windows))]
    {
        std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink())
    }
}

/// Windows: is the open `file`, opened at `path`, the entry at that name itself, not a file
/// a link there leads to (Wine opens a Unix link as its target)? Asked through the handle's
/// final path (see the module's documentation).
#[cfg(windows)]
pub fn opened_under_its_own_name(file: &std::fs::File, path: &Path) -> bool {
    windows::opened_under_its_own_name(file, path)
}

#[cfg(windows)]
mod windows {
    use std::fs::File;
    use std::os::windows::ffi::OsStringExt;
    use std::os::windows::fs::{MetadataExt, OpenOptionsExt};
    use std::os::windows::io::AsRawHandle;
    use std::path::{Path, PathBuf};

    /// `FILE_FLAG_BACKUP_SEMANTICS` (a folder opens).
    const FOLDER: u32 = 0x0200_0000;
    /// `FILE_FLAG_OPEN_REPARSE_POINT` (a link is opened itself).
    const ITSELF: u32 = 0x0020_0000;
    /// `FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE`.
    const SHARE_ALL: u32 = 7;
    /// `FILE_ATTRIBUTE_REPARSE_POINT`.
    const REPARSE_POINT: u32 = 0x400;

    pub fn reached_through_link(path: &Path) -> bool {
        let Ok(path) = std::path::absolute(path) else { return false };
        let (Some(parent), Some(name)) = (path.parent(), path.file_name()) else { return false };
        let open =
            |p: &Path, flags: u32| File::options().access_mode(0).share_mode(SHARE_ALL).custom_flags(flags).open(p);
        let Ok(file) = open(&path, FOLDER | ITSELF) else { return false };
        if file.metadata().is_ok_and(|m| m.file_attributes() & REPARSE_POINT != 0) {
            return true;
        }
        under_another_name(&file, parent, name, &path)
    }

    /// Is the open `file`, opened at `path` (in the folder `parent`, named `name`), reached
    /// under another name than its own (its final path is not its folder's joined with the
    /// entry's long name)? `false` where the system cannot say.
    fn under_another_name(file: &File, parent: &Path, name: &std::ffi::OsStr, path: &Path) -> bool {
        let open =
            |p: &Path, flags: u32| File::options().access_mode(0).share_mode(SHARE_ALL).custom_flags(flags).open(p);
        let Ok(folder) = open(parent, FOLDER) else { return false };
        // The entry's long name: a short name (`PHON~0IC`) names the same entry.
        let long = long_path(path);
        let name = long.as_deref().and_then(Path::file_name).unwrap_or(name);
        match (final_path(file), final_path(&folder)) {
            (Some(at), Some(folder)) => !same_name(&at, &folder.join(name)),
            _ => false,
        }
    }

    /// Is the open `file`, opened at `path`, the entry at that name itself (not a file a
    /// link there leads to: Wine's Unix link opens as its target)? `false` where it cannot
    /// be told (the path has no folder or no name).
    pub fn opened_under_its_own_name(file: &File, path: &Path) -> bool {
        let Ok(path) = std::path::absolute(path) else { return false };
        let (Some(parent), Some(name)) = (path.parent(), path.file_name()) else { return false };
        !under_another_name(file, parent, name, &path)
    }

    /// `path` with each 8.3 short name in it made long (`GetLongPathNameW`): names, not
    /// links, are resolved. `None` where the system cannot say.
    pub(super) fn long_path(path: &Path) -> Option<PathBuf> {
        use std::os::windows::ffi::OsStrExt;
        use windows_sys::Win32::Storage::FileSystem::GetLongPathNameW;
        let wide: Vec<u16> = path.as_os_str().encode_wide().chain([0]).collect();
        // SAFETY: `wide` ends with a 0; `buf` holds `len` u16s.
        filled_path(|buf, len| unsafe { GetLongPathNameW(wide.as_ptr(), buf, len) })
    }

    /// The path the system gives the open `file` (links and junctions resolved).
    fn final_path(file: &File) -> Option<PathBuf> {
        use windows_sys::Win32::Storage::FileSystem::GetFinalPathNameByHandleW;
        // SAFETY: the handle is open for the call; `buf` holds `len` u16s.
        filled_path(|buf, len| unsafe { GetFinalPathNameByHandleW(file.as_raw_handle(), buf, len, 0) })
    }

    /// A path a Windows call writes into a buffer of u16s: `call(buf, len)` returns the
    /// length written, or the length needed when the buffer is too short, or 0 on failure;
    /// the buffer grows until the path fits.
    fn filled_path(mut call: impl FnMut(*mut u16, u32) -> u32) -> Option<PathBuf> {
        let mut buf = vec![0u16; 1024];
        loop {
            let len = u32::try_from(buf.len()).ok()?;
            let n = call(buf.as_mut_ptr(), len) as usize;
            if n == 0 {
                return None;
            }
            if n < buf.len() {
                buf.truncate(n);
                return Some(PathBuf::from(std::ffi::OsString::from_wide(&buf)));
            }
            buf.resize(n + 1, 0);
        }
    }

    /// Do `a` and `b` name the same place, without case and the `\\?\` prefix?
    fn same_name(a: &Path, b: &Path) -> bool {
        let plain = |p: &Path| {
            let s = p.to_string_lossy().replace('/', "\\").to_lowercase();
            s.trim_start_matches(r"\\?\").trim_end_matches('\\').to_string()
        };
        plain(a) == plain(b)
    }
}

#[cfg(test)]
mod tests {
    use super::reached_through_link;
    use std::path::PathBuf;

    /// The links of `scripts/wine/plant-links.sh`: planted here on Unix; under Wine the
    /// folder `scripts/test-windows` planted on the Linux side (`PHONGLAB_PLANTED_LINKS`).
    /// `None` on a Windows without it (no link can be made there without a privilege).
    pub fn planted(name: &str) -> Option<PathBuf> {
        if let Some(d) = std::env::var_os("PHONGLAB_PLANTED_LINKS") {
            return Some(PathBuf::from(d));
        }
        if cfg!(windows) {
            eprintln!("no PHONGLAB_PLANTED_LINKS (scripts/test-windows plants them): nothing to test");
            return None;
        }
        let d = std::env::temp_dir().join(format!("phonglab-links {name} {}", std::process::id()));
        let script = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/wine/plant-links.sh");
        let ok = std::process::Command::new("bash").arg(script).arg(&d).status().is_ok_and(|s| s.success());
        assert!(ok, "the links are planted");
        Some(d)
    }

    /// Each planted link is seen as one (on Wine a Unix link is a plain file with no reparse
    /// point: only its final path tells it), and a file, a folder and a missing name are not.
    #[test]
    fn links_to_files_and_folders_are_seen_and_plain_ones_are_not() {
        let Some(d) = planted("seen") else { return };
        for link in ["f1/p/src/ofApp.h", "f2/ew/exercise-01.md", "f3/lw", "f4/ofw/src", "f5/ew/.phonglab-set.written"] {
            assert!(reached_through_link(&d.join(link)), "{link} is a link");
        }
        for plain in ["plain/file.txt", "plain/folder", "plain", "f3/v3", "f3/v3/notes.txt", "plain/missing"] {
            assert!(!reached_through_link(&d.join(plain)), "{plain} is not a link");
        }
        // A file reached through a linked folder above it is under its own name in the
        // folder it is in (the folder is the link); a path with a dot is the same path.
        assert!(!reached_through_link(&d.join("f3/lw/notes.txt")), "a file in a linked folder is itself");
        assert!(reached_through_link(&d.join("f3/./lw")), "a path with a dot");
    }

    /// Issue 59, #59: a real folder given by its 8.3 short name (Wine makes `PHON~0IC`) is
    /// not a link: before, it was refused as "a link to another folder".
    #[test]
    #[cfg(windows)]
    fn a_real_folder_named_by_its_short_name_is_not_a_link() {
        use std::os::windows::ffi::{OsStrExt, OsStringExt};
        use windows_sys::Win32::Storage::FileSystem::GetShortPathNameW;
        let long = std::env::temp_dir().join(format!("phonglab folder with a long name {}", std::process::id()));
        std::fs::create_dir_all(&long).unwrap();
        let wide: Vec<u16> = long.as_os_str().encode_wide().chain([0]).collect();
        let mut buf = vec![0u16; 1024];
        // SAFETY: `wide` ends with a 0; `buf` holds 1024 u16s.
        let n = unsafe { GetShortPathNameW(wide.as_ptr(), buf.as_mut_ptr(), 1024) } as usize;
        assert!(n > 0 && n < buf.len(), "the system gives a short name");
        buf.truncate(n);
        let short = PathBuf::from(std::ffi::OsString::from_wide(&buf));
        let short_name = short.file_name().unwrap().to_string_lossy().into_owned();
        assert!(short_name.contains('~'), "{short_name} is a short name");
        assert!(!reached_through_link(&short), "{} is the folder itself", short.display());
        assert!(!reached_through_link(&short.join(".")), "and with a dot");
        std::fs::remove_dir_all(&long).unwrap();
    }
}
