//! `phonglab export` and `phonglab import`: a scene to the student's own code (the
//! worksheet's notebook, a PyOpenGL program, an openFrameworks app, the GLSL), and a
//! worksheet-style notebook or script back to a scene file.

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use phonglab_core::export::{Target, files};

use crate::io::file_set::FileSet;
use crate::t;

/// What `--to` names.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum TargetArg {
    /// The worksheet's Jupyter notebook (.ipynb), with this scene's values.
    Notebook,
    /// A PyOpenGL + GLUT program in the Phong demo's style (.py).
    Pyopengl,
    /// ofApp.h, ofApp.cpp and main.cpp for openFrameworks 0.12 (a folder).
    Openframeworks,
    /// The GLSL that `phonglab shader` prints.
    Glsl,
}

impl From<TargetArg> for Target {
    fn from(t: TargetArg) -> Self {
        match t {
            TargetArg::Notebook => Target::Notebook,
            TargetArg::Pyopengl => Target::PyOpenGl,
            TargetArg::Openframeworks => Target::OpenFrameworks,
            TargetArg::Glsl => Target::Glsl,
        }
    }
}

/// `phonglab export`.
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// A scene file (TOML); default: the worksheet's scene.
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// What to write.
    #[arg(long, value_enum)]
    pub to: TargetArg,
    /// Where: a file (a folder for openframeworks); without it the text goes to the
    /// standard output.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// Runs `phonglab export`.
pub fn export(a: &ExportArgs) -> Result<()> {
    let target = Target::from(a.to);
    use crate::io::same_file::Input;
    if let (Some(scene), Some(output)) = (&a.scene, &a.output) {
        refuse_onto(target, output, scene, Input::Scene)?;
    }
    let doc = match &a.scene {
        Some(p) => crate::io::input_file::load_scene(p).map_err(anyhow::Error::msg)?,
        None => phonglab_core::Document::default(),
    };
    if let (Some(mesh), Some(output)) = (&doc.view.obj, &a.output) {
        refuse_onto(target, output, std::path::Path::new(mesh), Input::Mesh)?;
    }
    let written = files(&doc, target).map_err(anyhow::Error::msg)?;
    match (&a.output, target) {
        (None, Target::OpenFrameworks) => bail!(t!("err-export-folder")),
        (None, _) => {
            for (_, text) in &written {
                print!("{text}");
            }
        }
        (Some(project), Target::OpenFrameworks) => {
            // An oF project keeps its code in src/.
            let dir = &project.join("src");
            crate::io::atomic_write::check_folder_destination(dir)?;
            let mut set = FileSet::default();
            for (name, text) in &written {
                set.add(name.clone(), text.clone().into_bytes());
            }
            let names: Vec<String> = written.iter().map(|(n, _)| n.clone()).collect();
            let notices = crate::io::file_set::write_set(dir, &set, |n| names.iter().any(|m| m == n))?;
            for n in &notices {
                super::say(n);
            }
            super::say(&t!("export-written", path = crate::io::reasons::shown(dir)));
        }
        (Some(path), _) => {
            crate::io::atomic_write::check_file_destination(path)?;
            crate::io::atomic_write::write(path, written[0].1.as_bytes())?;
            super::say(&t!("export-written", path = crate::io::reasons::shown(path)));
        }
    }
    Ok(())
}

/// Refuses an export whose output (a file, or for openFrameworks the files of its `src/`)
/// is the file `input`.
fn refuse_onto(
    target: Target,
    output: &std::path::Path,
    input: &std::path::Path,
    kind: crate::io::same_file::Input,
) -> Result<()> {
    let refused = if target == Target::OpenFrameworks {
        crate::io::same_file::refuse_outputs_in_folder(
            &output.join("src"),
            &["ofApp.h", "ofApp.cpp", "main.cpp"],
            &[(input, kind)],
        )
    } else {
        crate::io::same_file::refuse_onto(&[output], &[(input, kind)])
    };
    refused.map_err(anyhow::Error::msg)
}

/// `phonglab import`.
#[derive(Args, Debug)]
pub struct ImportArgs {
    /// A worksheet-style notebook (.ipynb) or Python script (.py).
    pub file: PathBuf,
    /// The scene file to write (TOML).
    #[arg(short, long)]
    pub output: PathBuf,
}

/// Reads a worksheet-style notebook or script (`.ipynb` by its extension, else a script)
/// into a scene: what it says about lines it could not read goes to the standard error.
pub fn read_student_code(path: &std::path::Path) -> Result<phonglab_core::export::read_python::Imported> {
    let text =
        crate::io::input_file::read_text_capped(path, crate::io::student_code::MAX_CODE_BYTES, &t!("file-kind-code"))
            .map_err(anyhow::Error::msg)?;
    // Any file that is not a notebook is read as a script.
    let notebook = crate::io::student_code::student_code(path) == Some(true);
    crate::io::student_code::import_text(&text, notebook, path).map_err(anyhow::Error::msg)
}

/// Runs `phonglab import`.
pub fn import(a: &ImportArgs) -> Result<()> {
    let code = crate::io::same_file::Input::Code;
    crate::io::same_file::refuse_onto(&[&a.output], &[(&a.file, code)]).map_err(anyhow::Error::msg)?;
    let imported = read_student_code(&a.file)?;
    for notice in &imported.notices {
        super::say(&format!("{}: {notice}", crate::io::reasons::shown(&a.file)));
    }
    crate::io::atomic_write::check_file_destination(&a.output)?;
    let text = imported.doc.to_toml().map_err(|e| anyhow::anyhow!("{e}"))?;
    crate::io::atomic_write::write(&a.output, text.as_bytes())?;
    super::say(&t!(
        "import-written",
        path = crate::io::reasons::shown(&a.output),
        lights = t!("lights-count", count = imported.doc.scene.lights.len())
    ));
    Ok(())
}
