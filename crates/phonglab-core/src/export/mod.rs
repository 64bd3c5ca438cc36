//! From a scene to the student's own code and back: the worksheet's Jupyter notebook, a
//! PyOpenGL program in the Phong demo's style, an openFrameworks app, and the reading of
//! a worksheet-style notebook or script into a scene.
//!
//! Each writer builds its text from the scene's state, as Mesa's `ffvertex_prog.c` builds a
//! program from a state key: only the cells, calls and lines this scene needs.

pub mod general_shader;
pub mod notebook;
pub mod openframeworks;
pub mod pyopengl;
pub mod python;
pub mod read_python;
pub mod share;
pub mod template;

/// What `phonglab export --to` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Target {
    /// A Jupyter notebook in the worksheet's form (`.ipynb`).
    Notebook,
    /// A PyOpenGL + GLUT program in the Phong demo's style (`.py`).
    PyOpenGl,
    /// `ofApp.h`, `ofApp.cpp` and `main.cpp` for openFrameworks 0.12.
    OpenFrameworks,
    /// The GLSL that `phonglab shader` prints.
    Glsl,
}

impl Target {
    /// Every target, in menu order.
    pub const ALL: [Target; 4] = [Target::Notebook, Target::PyOpenGl, Target::OpenFrameworks, Target::Glsl];

    /// A name for menus.
    pub fn label(self) -> String {
        match self {
            Target::Notebook => crate::t!("export-target-notebook"),
            Target::PyOpenGl => crate::t!("export-target-pyopengl"),
            Target::OpenFrameworks => crate::t!("export-target-openframeworks"),
            Target::Glsl => crate::t!("export-target-glsl"),
        }
    }
}

/// One written file: its name (with `/` between folders) and its text.
pub type File = (String, String);

/// The files `target` writes for `doc`, named as the target's own project names them
/// (`vertex_color_calculator.ipynb`, `phong_scene.py`, `src/ofApp.h`, ...). An error says
/// why the scene cannot be written so (the engine's refusal, in the reader's language).
pub fn files(doc: &Document, target: Target) -> Result<Vec<File>, String> {
    doc.scene.validate().map_err(|e| e.to_string())?;
    let key = key(doc);
    if let Some(why) = (target == Target::Notebook).then(|| notebook::refusal(doc)).flatten() {
        return Err(why);
    }
    Ok(match target {
        Target::Notebook => vec![("vertex_color_calculator.ipynb".into(), notebook::notebook(doc, &key))],
        Target::PyOpenGl => vec![("phong_scene.py".into(), pyopengl::program(doc, &shaded_key(doc))?)],
        Target::OpenFrameworks => openframeworks::app(doc, &shaded_key(doc)).map_err(|e| e.to_string())?,
        Target::Glsl => {
            let lang = crate::teach::shader::ShadingLanguage::Glsl;
            let shading = match doc.view.shading {
                crate::model::view::Shading::Phong => crate::teach::shader::ShaderShading::Phong,
                _ => crate::teach::shader::ShaderShading::Gouraud,
            };
            let shader = crate::teach::shader::for_view(doc, lang, shading).map_err(|e| e.to_string())?;
            vec![("phong_scene.glsl".into(), shader.text(lang))]
        }
    })
}

/// What `doc`'s scene needs, as the lighting plan decides it ([`Key`]): every exporter
/// writes the terms the key has, as the renderer and the shaders run them.
pub fn key(doc: &Document) -> Key {
    Key::of(&doc.scene, crate::equation::lighting::EvalOptions::default())
}

/// The key of the scene the shaded view draws ([`Document::shaded_scene`]): what the
/// programs that draw the object (PyOpenGL, openFrameworks) light.
pub fn shaded_key(doc: &Document) -> Key {
    Key::of(&doc.shaded_scene(), crate::equation::lighting::EvalOptions::default())
}

/// The text the app's Copy puts on the clipboard: the notebook as one script (to paste
/// into a cell or a file), the openFrameworks files one after the other under their
/// names, the others as they are.
pub fn copy_text(doc: &Document, target: Target) -> Result<String, String> {
    if target == Target::Notebook {
        doc.scene.validate().map_err(|e| e.to_string())?;
        if let Some(why) = notebook::refusal(doc) {
            return Err(why);
        }
        return Ok(notebook::script(&notebook::cells(doc, &key(doc))));
    }
    let written = files(doc, target)?;
    if written.len() == 1 {
        return Ok(written.into_iter().next().map(|(_, t)| t).unwrap_or_default());
    }
    Ok(written.iter().map(|(name, text)| format!("// ---- {name} ----\n{text}\n")).collect())
}

use crate::equation::plan::Key;
use crate::formats::document::Document;
