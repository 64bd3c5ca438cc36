//! `phonglab shader`: the GLSL or WGSL program that draws a scene's shaded view, with only
//! the stages it needs.

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;

use super::scene_file;
use crate::t;

/// `phonglab shader`.
#[derive(Args, Debug)]
pub struct ShaderArgs {
    /// A scene file (default: the worksheet's, mview5).
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// glsl (3.30 core: a vertex and a fragment shader) or wgsl (one module). (`--lang`
    /// is the language phonglab speaks, on every command.)
    #[arg(long, default_value = "glsl")]
    pub target: String,
    /// gouraud (lit per vertex) or phong (lit per fragment).
    #[arg(long, default_value = "gouraud")]
    pub shading: String,
}

/// Runs `phonglab shader`.
pub fn run(a: &ShaderArgs) -> Result<()> {
    use phonglab_core::shader::{ShaderShading, ShadingLanguage};
    let doc = match &a.scene {
        Some(p) => scene_file(p)?,
        None => phonglab_core::Document::default(),
    };
    let lang = match a.target.as_str() {
        "glsl" => ShadingLanguage::Glsl,
        "wgsl" => ShadingLanguage::Wgsl,
        other => bail!(t!("err-target", value = format!("{other:?}"))),
    };
    let shading = match a.shading.as_str() {
        "gouraud" => ShaderShading::Gouraud,
        "phong" => ShaderShading::Phong,
        other => bail!(t!("err-shading", value = format!("{other:?}"))),
    };
    // A scene that does not evaluate is refused with the engine's reason.
    let shader = phonglab_core::shader::for_view(&doc, lang, shading)?;
    print!("{}", shader.text(lang));
    Ok(())
}
