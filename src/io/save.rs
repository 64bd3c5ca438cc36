//! Saving a file the user names: on the desktop where the system's dialog says, written
//! whole or not at all and never over an input; in the browser as a download.

use std::path::Path;

use crate::platform::files;

/// What became of a file to save.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Saved {
    /// Saved there (or, in the browser, downloaded under that name).
    At(String),
    /// The user closed the dialog.
    Cancelled,
    /// No system dialog could open, and why: the caller offers phonglab's own chooser.
    Choose(String),
}

/// Saves `bytes` as a file the user names, offering `name` (see the module's
/// documentation). `system` is false where the system's dialog must not open (headless
/// tests, or after it failed once): then the answer is [`Saved::Choose`] at once. A path
/// that is one of `inputs` (the scene file, its mesh) is refused
/// ([`super::same_file::refuse_output_onto_input`]).
pub fn save_bytes(name: &str, bytes: &[u8], mime: &str, system: bool, inputs: &[&Path]) -> Result<Saved, String> {
    if !files::TYPED_PATHS {
        return files::download(name, bytes, mime).map(|()| Saved::At(name.to_string()));
    }
    if !system {
        return Ok(Saved::Choose(crate::t!("dialog-in-app")));
    }
    match files::pick_path_to_save(name) {
        files::Picked::Chosen(path) => save_at(&path, bytes, inputs).map(Saved::At),
        files::Picked::Cancelled => Ok(Saved::Cancelled),
        files::Picked::NoDialog(why) => Ok(Saved::Choose(why)),
    }
}

/// Writes `bytes` at `path`, whole or not at all, never over one of `inputs`; says where.
pub fn save_at(path: &Path, bytes: &[u8], inputs: &[&Path]) -> Result<String, String> {
    super::same_file::refuse_output_onto_input(&[path], inputs)?;
    super::atomic_write::write(path, bytes).map_err(|e| e.to_string())?;
    Ok(path.display().to_string())
}
