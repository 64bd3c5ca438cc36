//! The files the package reads and writes, through the command line's own readers and
//! writer ([`phonglab_core::files`]): a regular file under its cap, opened without blocking
//! (a FIFO, a device, a folder refused at once); written whole or not at all, through a
//! link to the file it names, never over a FIFO or a device, never over the scene's mesh.

use std::path::Path;

use phonglab_core::Document;
use phonglab_core::export::read_python::{self, Imported};
use phonglab_core::files::{atomic_write, read, reasons, same_file};

/// Reads the scene file at `path` as `phonglab explain FILE` does (a relative mesh path
/// from its folder), or the scene a shared link (`https://…/#v1.…`) given in its place
/// carries, decoded by the core's bounded decoder as the command line decodes it; an error
/// names the file or the link.
pub fn load(path: &Path) -> Result<Document, String> {
    if let Some(link) = path.to_str().filter(|p| phonglab_core::export::share::link_fragment(p).is_some()) {
        return phonglab_core::export::share::read_link(link).map(|s| s.doc);
    }
    // A notebook or a script is not TOML: said so, never as the TOML parser's complaint.
    if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("ipynb") || e.eq_ignore_ascii_case("py")) {
        return Err(phonglab_core::t!("python-load-notebook", path = reasons::shown(path)));
    }
    let text = read::read_text_capped(path, read::MAX_SCENE_BYTES, &phonglab_core::t!("file-kind-scenes"))?;
    // The mesh a scene names is found from the scene's folder, made absolute: a notebook
    // may change its working folder before it renders the mesh.
    let folder = std::path::absolute(path).ok().and_then(|p| p.parent().map(Path::to_path_buf));
    Document::from_toml_in(&text, folder.as_deref()).map_err(|e| format!("{}: {e}", reasons::shown(path)))
}

/// Reads the worksheet-style notebook (`.ipynb`) or script at `path` as `phonglab import`
/// does: the scene named after the file (its printable form), and the notices of lines not read.
pub fn import(path: &Path) -> Result<Imported, String> {
    let text = read::read_code_text(path)?;
    let notebook = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("ipynb"));
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let name = phonglab_core::escape::printable(&stem);
    read_python::read(&text, notebook, &name).map_err(|e| format!("{}: {e}", reasons::shown(path)))
}

/// Writes `doc` to `path` as the app's Save and `phonglab export -o` write a file: refused
/// onto the scene's own mesh and onto the notebook or script it was imported from (`code`),
/// as `phonglab import -o` refuses its input; whole or not at all; a link followed to the
/// file it names.
pub fn save(doc: &Document, path: &Path, code: Option<&Path>) -> Result<(), String> {
    let mut inputs: Vec<(&Path, same_file::Input)> =
        doc.view.obj.iter().map(|m| (Path::new(m), same_file::Input::Mesh)).collect();
    inputs.extend(code.map(|c| (c, same_file::Input::Code)));
    same_file::refuse_onto(&[path], &inputs)?;
    let text = doc.to_toml().map_err(|e| e.to_string())?;
    atomic_write::write(path, text.as_bytes()).map_err(|e| e.to_string())
}
