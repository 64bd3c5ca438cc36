//! `phonglab explain`: the worked calculation of a vertex, step by step, in the
//! worksheet's order.

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;
use phonglab_core::explain::{Side, explain};
use phonglab_core::{Engine, Precision, Real, Scene, presets};

use super::scene_file;
use crate::t;

/// `phonglab explain`.
#[derive(Args, Debug)]
pub struct ExplainArgs {
    /// A scene file (TOML), as the app saves it.
    #[arg(conflicts_with_all = ["worksheet", "preset"])]
    pub scene: Option<PathBuf>,
    /// The worksheet's scene with modelview N (1-5). The default when no scene is given: 5.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(1..=5))]
    pub worksheet: Option<u8>,
    /// A ready-made scene instead: "phong-demo".
    #[arg(long, conflicts_with = "worksheet")]
    pub preset: Option<String>,
    /// Engine precision.
    #[arg(long, value_enum, default_value = "f64")]
    pub precision: Precision,
    /// Explain the back side (two-sided lighting).
    #[arg(long)]
    pub back: bool,
    /// Print a Markdown table instead of text.
    #[arg(long)]
    pub markdown: bool,
    /// Significant digits.
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
}

/// The scene `explain` works on.
fn explain_scene(a: &ExplainArgs) -> Result<(Scene, String)> {
    if let Some(p) = &a.scene {
        let doc = scene_file(p)?;
        let name = if doc.name.is_empty() {
            p.display().to_string()
        } else {
            phonglab_core::library::localised_name(&doc.name)
        };
        return Ok((doc.scene, name));
    }
    if let Some(p) = &a.preset {
        return match p.as_str() {
            "phong-demo" => Ok((presets::phong_demo(), t!("preset-phong-demo"))),
            other => bail!(t!("err-unknown-preset", value = format!("{other:?}"), names = "phong-demo")),
        };
    }
    let n = a.worksheet.unwrap_or(5) as usize;
    Ok((presets::worksheet(n), crate::t!("doc-worksheet", k = n.to_string())))
}

fn explain_text<S: Real>(scene: &Scene, what: &str, a: &ExplainArgs) -> Result<String> {
    let lit = Engine::<S>::light_scene_vertex(scene)?;
    let ex = explain(scene, &lit, if a.back { Side::Back } else { Side::Front });
    let digits = a.digits as usize;
    Ok(if a.markdown {
        let name = phonglab_core::escape::markdown::text(what);
        format!("# {}\n\n{}", crate::t!("worked-calculation-of", name = name), ex.to_markdown(digits))
    } else {
        let name = phonglab_core::escape::terminal::text(what);
        format!("{}\n{}", crate::t!("worked-calculation-of", name = name), ex.to_text(digits))
    })
}

/// Runs `phonglab explain`.
pub fn run(a: &ExplainArgs) -> Result<()> {
    let (scene, what) = explain_scene(a)?;
    let text = match a.precision {
        Precision::F32 => explain_text::<f32>(&scene, &what, a)?,
        Precision::F64 => explain_text::<f64>(&scene, &what, a)?,
    };
    print!("{text}");
    Ok(())
}
