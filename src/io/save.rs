//! Saving a file the user names: on the desktop where the system's dialog says, written
//! whole or not at all and never over an input; in the browser as a download.

use std::path::Path;

use crate::platform::files;

/// Saves `bytes` as a file the user names, offering `name` (see the module's
/// documentation). `Ok(None)`: the user cancelled; `Ok(Some(where))`: saved there.
/// `dialogs` is false where no dialog may open (headless tests): then nothing is saved, and
/// the reason is returned. A path that is one of `inputs` (the scene file, its mesh) is
/// refused ([`super::same_file::refuse_output_onto_input`]).
pub fn save_bytes(
    name: &str,
    bytes: &[u8],
    mime: &str,
    dialogs: bool,
    inputs: &[&Path],
) -> Result<Option<String>, String> {
    if !files::TYPED_PATHS {
        return files::download(name, bytes, mime).map(|()| Some(name.to_string()));
    }
    if !dialogs {
        return Err("no file dialog here".into());
    }
    let Some(path) = files::pick_path_to_save(name) else { return Ok(None) };
    super::same_file::refuse_output_onto_input(&[&path], inputs)?;
    super::atomic_write::write(&path, bytes).map_err(|e| e.to_string())?;
    Ok(Some(path.display().to_string()))
}
