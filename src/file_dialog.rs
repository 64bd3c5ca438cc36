//! The system's file dialog (through `rfd`: the desktop portal on Linux, the native dialogs
//! on Windows and macOS), kept here so the panels do not depend on how it opens. It blocks
//! the window while it is open, as a modal dialog does.

use std::path::PathBuf;

/// The scene file to open, or `None` when the dialog was cancelled or could not open.
pub fn pick_scene_to_open(start: Option<&std::path::Path>) -> Option<PathBuf> {
    dialog(start).add_filter("Scene or mesh", &["toml", "obj"]).pick_file()
}

/// Where to save the scene, or `None` when the dialog was cancelled or could not open.
pub fn pick_scene_to_save(start: Option<&std::path::Path>) -> Option<PathBuf> {
    let name = start.and_then(|p| p.file_name()).map_or("scene.toml".into(), |n| n.to_string_lossy().into_owned());
    dialog(start).add_filter("Scene", &["toml"]).set_file_name(name).save_file()
}

fn dialog(start: Option<&std::path::Path>) -> rfd::FileDialog {
    let d = rfd::FileDialog::new();
    match start.and_then(|p| std::path::absolute(p).ok()).and_then(|p| p.parent().map(|d| d.to_path_buf())) {
        Some(dir) if dir.is_dir() => d.set_directory(dir),
        _ => d,
    }
}
