//! Reading a file a user names: a regular file, at most a size cap, checked before reading,
//! opened without blocking: the core's readers ([`phonglab_core::files::read`]), which the
//! Python package shares; here the files the window receives (dropped, or brought by the
//! browser).

use std::path::Path;

use crate::t;

pub use phonglab_core::files::read::{
    MAX_SCENE_BYTES, Unread, read_capped, read_capped_or, read_submission, read_text_capped, read_text_submission,
    within_cap,
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

/// A shared scene's link given where a scene file is taken (`https://…/#v1.…`): what
/// follows its `#` (empty where it has none). `None` for a path. The core's
/// [`phonglab_core::export::share::link_fragment`].
pub fn share_fragment(path: &Path) -> Option<&str> {
    phonglab_core::export::share::link_fragment(path.to_str()?)
}

/// The scene a shared link carries, decoded as the browser build decodes it (bounded:
/// [`phonglab_core::export::share::MAX_FRAGMENT`]), or why not, naming the link.
pub fn load_link(link: &str) -> Result<phonglab_core::Document, String> {
    read_link(link).map(|s| s.doc)
}

/// What a shared link carries (its scene and the window's choices), read as the core's
/// [`phonglab_core::export::share::read_link`] reads it (the Python package too).
pub fn read_link(link: &str) -> Result<phonglab_core::export::share::Shared, String> {
    phonglab_core::export::share::read_link(link)
}

/// Reads and checks a scene file (a relative mesh path is taken from its folder: the
/// core's [`phonglab_core::files::read::load_scene`]), or the scene a shared link carries
/// ([`share_fragment`]); an error names the file or the link.
pub fn load_scene(path: &Path) -> Result<phonglab_core::Document, String> {
    if share_fragment(path).is_some() {
        let shared = read_link(&path.to_string_lossy())?;
        // A mesh the link's scene shows and that is not read here: said, and the sphere shown.
        if let Some(note) = &shared.mesh_note {
            eprintln!("phonglab: {}", phonglab_core::escape::terminal::lines(note));
        }
        return Ok(shared.doc);
    }
    phonglab_core::files::read::load_scene(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shared_link_is_read_as_the_scene_it_carries() {
        use phonglab_core::export::share::{Shared, link};
        let mut doc = phonglab_core::Document { name: "ruby".into(), ..Default::default() };
        doc.scene.material.shininess = 77.0;
        let url = link("https://example.org/phonglab/", &Shared::of(doc)).unwrap();
        let read = load_scene(Path::new(&url)).unwrap();
        assert_eq!((read.name.as_str(), read.scene.material.shininess), ("ruby", 77.0));
        let e = load_scene(Path::new("https://example.org/phonglab/")).unwrap_err();
        assert!(e.contains("holds no scene"), "{e}");
        let cut = &url[..url.len() - 10];
        let e = load_scene(Path::new(cut)).unwrap_err();
        assert!(e.starts_with("https://example.org/phonglab/#v1.") && e.contains("…: the link is damaged"), "{e}");
        let long = format!("https://example.org/#v1.{}", "A".repeat(phonglab_core::export::share::MAX_FRAGMENT));
        assert!(load_scene(Path::new(&long)).unwrap_err().contains("characters long"));
        assert_eq!(share_fragment(Path::new("scenes/https.toml")), None);
    }

    /// Issue 59 (finding 7): on Windows an input named like a device (`CON`, `nul.toml`,
    /// `COM1`) is refused in words before it is opened (before: the system's raw "Invalid
    /// handle (os error 6)"); elsewhere such a name is a file like any other.
    #[test]
    fn an_input_named_like_a_windows_device_is_refused_in_words_there() {
        let dir = crate::io::atomic_write::tests::temp_dir("device-input");
        for name in ["CON", "nul.toml", "COM1"] {
            if cfg!(windows) {
                let e = read_capped(&dir.join(name), MAX_SCENE_BYTES, "scene files").unwrap_err();
                assert!(e.contains(name) && e.contains("a name Windows keeps for a device"), "{e}");
                assert!(!e.contains("os error"), "{e}");
                let e = read_submission(Path::new(name), MAX_SCENE_BYTES, "notebooks").unwrap_err();
                assert!(e.contains("a name Windows keeps for a device"), "{e}");
            } else {
                std::fs::write(dir.join(name), "name = \"con\"").unwrap();
                assert_eq!(
                    read_text_capped(&dir.join(name), MAX_SCENE_BYTES, "scene files").unwrap(),
                    "name = \"con\""
                );
            }
        }
    }

    #[test]
    fn devices_folders_and_large_files_are_refused_before_reading() {
        // (Windows' NUL device: `mesh::obj`'s test in the core.)
        #[cfg(unix)]
        {
            let e = read_capped(Path::new("/dev/zero"), MAX_SCENE_BYTES, "scene files").unwrap_err();
            assert!(e.contains("not a regular file"), "{e}");
        }
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
