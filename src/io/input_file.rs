//! Reading a file a user names: a regular file, at most a size cap, checked before reading,
//! opened without blocking: the core's readers ([`phonglab_core::files::read`]), which the
//! Python package shares; here the files the window receives (dropped, or brought by the
//! browser).

use std::path::Path;

use crate::t;

pub use phonglab_core::files::read::{
    MAX_SCENE_BYTES, Unread, load_scene, read_capped, read_capped_or, read_submission, read_text_capped,
    read_text_submission, within_cap,
};

/// The largest case file (glref JSON) read: the public cases are 1.3 MB.
pub const MAX_CASE_BYTES: u64 = 256 << 20;

/// A file dropped on the window: its name and bytes now on the desktop (read from its path,
/// under `cap`); in the browser `None` now, the bytes arriving later through
/// [`crate::platform::files::take_arrived`], their size checked first: against `cap`, or
/// for an OBJ mesh against the mesh's own limit ([`phonglab_core::mesh::obj::MAX_OBJ_BYTES`],
/// with the desktop's message). (The desktop opens a dropped mesh at its path instead.)
pub fn read_dropped(
    ctx: &egui::Context,
    file: &egui::DroppedFileHandle,
    cap: u64,
) -> Option<Result<crate::platform::files::Arrived, String>> {
    let check = move |name: &str, size: u64| check_arriving(name, size, cap);
    let path = crate::platform::files::dropped_path(ctx, file, check)?;
    Some(path.and_then(|p| read_capped(&p, cap, &t!("file-kind-scenes")).map(|b| (p.display().to_string(), b))))
}

/// The check of a file the browser brings (dropped or chosen), by its name and size,
/// before it is read: a mesh against the mesh's own limit
/// ([`phonglab_core::mesh::obj::MAX_OBJ_BYTES`], with the desktop's message), anything else
/// against `cap`.
pub fn check_arriving(name: &str, size: u64, cap: u64) -> Result<(), String> {
    if is_obj_name(name) {
        phonglab_core::mesh::obj::refuse_too_large(name, size)
    } else {
        within_cap(name, size, cap, &t!("file-kind-scenes"))
    }
}

/// Does the file name (or path) `name` name an OBJ mesh?
pub fn is_obj_name(name: &str) -> bool {
    Path::new(name).extension().is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_folders_and_large_files_are_refused_before_reading() {
        let e = read_capped(Path::new("/dev/zero"), MAX_SCENE_BYTES, "scene files").unwrap_err();
        assert!(e.contains("not a regular file"), "{e}");
        let dir = std::env::temp_dir().join(format!("phonglab-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert!(read_capped(&dir, MAX_SCENE_BYTES, "scene files").unwrap_err().contains("not a regular file"));
        let big = dir.join("big.toml");
        std::fs::File::create(&big).unwrap().set_len(MAX_SCENE_BYTES + 1).unwrap();
        let e = read_capped(&big, MAX_SCENE_BYTES, "scene files").unwrap_err();
        assert!(e.contains("is 1 048 577 bytes") && e.contains("scene files of at most 1 048 576 bytes"), "{e}");
        let ok = dir.join("ok.toml");
        std::fs::write(&ok, "name = \"é\"").unwrap();
        assert_eq!(read_text_capped(&ok, MAX_SCENE_BYTES, "scene files").unwrap(), "name = \"é\"");
        std::fs::write(&ok, [b'a', 0xff]).unwrap();
        assert!(read_text_capped(&ok, MAX_SCENE_BYTES, "scene files").unwrap_err().contains("not UTF-8"));
    }
}
