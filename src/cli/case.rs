//! `phonglab case`: scene files as glref cases (JSON), to check them against a real
//! OpenGL with the Mesa harness or with `phonglab eval`.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use phonglab_core::glref;

use super::scene_file;

/// `phonglab case`.
#[derive(Args, Debug)]
pub struct CaseArgs {
    /// Scene files (TOML); each becomes one case, its id the file's stem.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
}

/// The scene files as `{"cases": [...]}`.
pub fn cases_json(paths: &[PathBuf]) -> Result<serde_json::Value> {
    let mut cases = Vec::new();
    for p in paths {
        let doc = scene_file(p)?;
        if doc.scene.rules != phonglab_core::Rules::OPENGL {
            super::say(&format!(
                "phonglab: {}",
                crate::t!("case-rules-note", path = crate::io::reasons::shown(p), rules = doc.scene.rules.set.label())
            ));
        }
        let id = p.file_stem().map_or_else(|| format!("case{}", cases.len()), |s| s.to_string_lossy().into_owned());
        cases.push(glref::case_json(&id, &doc.scene));
    }
    Ok(serde_json::json!({ "cases": cases }))
}

/// Runs `phonglab case`.
pub fn run(a: &CaseArgs) -> Result<()> {
    println!("{}", phonglab_core::escape::json::text(&serde_json::to_string_pretty(&cases_json(&a.scenes)?)?));
    Ok(())
}
