//! A student's own code read back: which files are worksheet-style notebooks (`.ipynb`) or
//! scripts (`.py`), the largest read, and their text into a scene named after the file
//! ([`phonglab_core::export::read_python`]), for `phonglab import` and the window's Open
//! and drop alike.

use std::path::Path;

/// The largest notebook or script opened (a notebook with its outputs is larger than a scene).
pub use phonglab_core::files::read::MAX_CODE_BYTES;

/// Is `path` a worksheet-style notebook (`Some(true)`) or Python script (`Some(false)`)?
pub fn student_code(path: &Path) -> Option<bool> {
    let ext = path.extension()?.to_string_lossy().to_lowercase();
    match ext.as_str() {
        "ipynb" => Some(true),
        "py" => Some(false),
        _ => None,
    }
}

/// Reads the text of the worksheet-style notebook or script at `path` into a scene named
/// after the file (the app's open and drop, and `phonglab import`); an error names the file.
pub fn import_text(
    text: &str,
    notebook: bool,
    path: &Path,
) -> Result<phonglab_core::export::read_python::Imported, String> {
    // A file's name may hold anything but `/`: the scene's name is its printable form.
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let name = phonglab_core::escape::printable(&stem);
    phonglab_core::export::read_python::read(text, notebook, &name).map_err(|e| format!("{}: {e}", path.display()))
}

/// One piece of work read: the scene it typed and what it printed.
pub struct Work {
    /// The scene its code typed (the worksheet's for printed text).
    pub own: phonglab_core::scene::Scene,
    /// What it printed.
    pub printed: phonglab_core::study::check::printed::Printed,
}

/// Reads the notebook at `path`, a submission (a link is refused by the open itself): its
/// scene through `import`'s bounded reader, its outputs.
pub fn read_notebook(path: &Path) -> anyhow::Result<Work> {
    let cap = MAX_CODE_BYTES;
    let text =
        super::input_file::read_text_submission(path, cap, &crate::t!("file-kind-code")).map_err(anyhow::Error::msg)?;
    let notebook = student_code(path) == Some(true);
    let imported = import_text(&text, notebook, path).map_err(anyhow::Error::msg)?;
    if let Some(why) = imported.not_checkable() {
        anyhow::bail!("{}: {why}", super::reasons::shown(path));
    }
    let printed = if notebook {
        phonglab_core::study::check::printed::notebook_outputs(&text)
            .map_err(|e| anyhow::anyhow!("{}: {e}", super::reasons::shown(path)))?
    } else {
        anyhow::bail!("{}: {}", super::reasons::shown(path), crate::t!("check-no-outputs"))
    };
    Ok(Work { own: imported.doc.scene, printed })
}
