//! Reading a file a user names: a regular file, at most a size cap, checked before reading
//! (`/dev/zero` or a stray 2 GB file is refused at once instead of filling the memory).
//! The file is opened without blocking ([`crate::formats::files::os::open_to_read`]: a FIFO
//! cannot hang the reader) and checked through the open handle, not the path. The command
//! line, the window and the Python package read through these.

use std::io::Read;
use std::path::Path;

use crate::t;

/// The largest scene file read: a scene file is a few kilobytes.
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// The largest notebook or script opened (a notebook with its outputs is larger than a scene).
pub const MAX_CODE_BYTES: u64 = 16 * MAX_SCENE_BYTES;

/// Reads the file at `path` as bytes: refused when it is not a regular file or is larger
/// than `cap` bytes (`what` names the kind of file in the message, in the user's language:
/// `t!("file-kind-scenes")`). The messages are in the current language.
pub fn read_capped(path: &Path, cap: u64, what: &str) -> Result<Vec<u8>, String> {
    let shown = crate::formats::files::reasons::shown(path);
    refuse_device_name(path, &shown)?;
    read_capped_or(path, cap).map_err(|e| match e {
        Unread::Io(e) => {
            t!("read-cannot", path = shown.clone(), reason = crate::formats::files::reasons::io_reason(&e))
        }
        Unread::NotAFile => t!("read-not-a-file", path = shown.clone()),
        Unread::TooLarge(size) => within_cap(&shown, size, cap, what).err().unwrap_or_default(),
    })
}

/// Why a file was not read.
#[derive(Debug)]
pub enum Unread {
    /// The system's error (`NotFound`, ...).
    Io(std::io::Error),
    /// It is a folder, a device, a FIFO or a socket.
    NotAFile,
    /// It is larger than the cap: its size in bytes (at least).
    TooLarge(u64),
}

/// Windows: refuses an input named like a device (`CON`, `nul.toml`, `COM1`: Windows opens
/// the device, and said only "Invalid handle (os error 6)"), in words, before it is opened.
/// Elsewhere such a name is a file like any other.
fn refuse_device_name(path: &Path, shown: &str) -> Result<(), String> {
    use crate::formats::files::atomic_write::{Unkept, unkept_name};
    let device = path.file_name().is_some_and(|n| unkept_name(n) == Some(Unkept::Device));
    if cfg!(windows) && device { Err(t!("read-device-name", path = shown)) } else { Ok(()) }
}

/// [`read_capped`], with the reason as a value (for callers that treat each differently,
/// as the session does).
pub fn read_capped_or(path: &Path, cap: u64) -> Result<Vec<u8>, Unread> {
    if refuse_device_name(path, "").is_err() {
        return Err(Unread::NotAFile);
    }
    // Windows cannot open a folder as a file (access denied): said as what it is.
    let refused = |e: std::io::Error| match std::fs::metadata(path) {
        Ok(m) if m.is_dir() => Unread::NotAFile,
        _ => Unread::Io(e),
    };
    read_opened(crate::formats::files::os::open_to_read(path).map_err(refused)?, cap)
}

/// [`read_capped`] of a student's submission, hostile input: a symbolic link at `path` is
/// refused by the open itself ([`crate::formats::files::os::open_no_follow`]), so a link planted
/// between a look at the folder and the read is never followed.
pub fn read_submission(path: &Path, cap: u64, what: &str) -> Result<Vec<u8>, String> {
    let shown = crate::formats::files::reasons::shown(path);
    refuse_device_name(path, &shown)?;
    let opened = crate::formats::files::os::open_no_follow(path).map_err(|e| {
        if crate::formats::files::os::is_link_refused(&e) {
            t!("read-link-refused", path = shown.clone())
        } else {
            t!("read-cannot", path = shown.clone(), reason = crate::formats::files::reasons::io_reason(&e))
        }
    })?;
    read_opened(opened, cap).map_err(|e| match e {
        Unread::Io(e) => {
            t!("read-cannot", path = shown.clone(), reason = crate::formats::files::reasons::io_reason(&e))
        }
        Unread::NotAFile => t!("read-not-a-file", path = shown.clone()),
        Unread::TooLarge(size) => within_cap(&shown, size, cap, what).err().unwrap_or_default(),
    })
}

/// [`read_submission`], as UTF-8 text.
pub fn read_text_submission(path: &Path, cap: u64, what: &str) -> Result<String, String> {
    utf8(read_submission(path, cap, what)?, path)
}

/// Reads the opened `file`, checked through its handle: a regular file of at most `cap` bytes.
fn read_opened(file: std::fs::File, cap: u64) -> Result<Vec<u8>, Unread> {
    let Some(meta) = crate::formats::files::os::regular_file_metadata(&file).map_err(Unread::Io)? else {
        return Err(Unread::NotAFile);
    };
    if meta.len() > cap {
        return Err(Unread::TooLarge(meta.len()));
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(cap + 1).read_to_end(&mut bytes).map_err(Unread::Io)?;
    // The file may have grown since its size was read.
    if bytes.len() as u64 > cap {
        return Err(Unread::TooLarge(bytes.len() as u64));
    }
    Ok(bytes)
}

/// Refuses a file of `size` bytes larger than `cap`, naming it (`name`) and the kind of
/// file (`what`): for files read here and for the browser's, which arrive as bytes.
pub fn within_cap(name: &str, size: u64, cap: u64, what: &str) -> Result<(), String> {
    if size <= cap {
        return Ok(());
    }
    Err(t!(
        "read-too-large",
        path = name,
        size = crate::mesh::obj::describe_bytes(size),
        what = what,
        cap = crate::mesh::obj::describe_bytes(cap)
    ))
}

/// Reads and checks a scene file (a relative mesh path is taken from its folder); an error
/// names the file.
pub fn load_scene(path: &Path) -> Result<crate::formats::document::Document, String> {
    let text = read_text_capped(path, MAX_SCENE_BYTES, &t!("file-kind-scenes"))?;
    crate::formats::document::Document::from_toml_in(&text, path.parent())
        .map_err(|e| format!("{}: {e}", crate::formats::files::reasons::shown(path)))
}

/// [`read_capped`], as UTF-8 text.
pub fn read_text_capped(path: &Path, cap: u64, what: &str) -> Result<String, String> {
    utf8(read_capped(path, cap, what)?, path)
}

/// The bytes read from `path` as UTF-8 text, or where they are not.
fn utf8(bytes: Vec<u8>, path: &Path) -> Result<String, String> {
    String::from_utf8(bytes).map_err(|e| {
        t!("read-not-utf8", path = crate::formats::files::reasons::shown(path), byte = e.utf8_error().valid_up_to())
    })
}

/// The text of the worksheet-style notebook (`.ipynb`) or script (`.py`) at `path`, as
/// `phonglab import` reads it: a regular file of at most [`MAX_CODE_BYTES`].
pub fn read_code_text(path: &Path) -> Result<String, String> {
    read_text_capped(path, MAX_CODE_BYTES, &t!("file-kind-code"))
}
