//! `phonglab share`: a scene as a link to the browser build (the scene in the URL's
//! fragment, [`phonglab_core::export::share`]), printed, and as a QR code.

use std::path::{Path, PathBuf};

use anyhow::Result;
use clap::Args;
use phonglab_core::channels::Channel;
use phonglab_core::export::share::{Shared, link};

use phonglab_core::export::share::DEFAULT_BASE;

use crate::t;

/// `phonglab share`.
#[derive(Args, Debug)]
pub struct ShareArgs {
    /// The scene file (TOML); default: the worksheet's scene.
    pub scene: Option<PathBuf>,
    /// The page the link opens.
    #[arg(long, default_value = DEFAULT_BASE)]
    pub base: String,
    /// Open it in this language (en, pt-PT, pt-BR).
    #[arg(long, value_name = "LANG")]
    pub open_in: Option<String>,
    /// Open it presenting to a class.
    #[arg(long)]
    pub present: bool,
    /// Open it showing this term in place of the picture.
    #[arg(long, value_enum)]
    pub channel: Option<Channel>,
    /// Also write the link as a QR code: FILE.png or FILE.svg.
    #[arg(long, value_name = "FILE")]
    pub qr: Option<PathBuf>,
}

/// Runs `phonglab share`.
pub fn run(a: &ShareArgs) -> Result<()> {
    use crate::io::same_file::{Input, refuse_onto};
    if let Some(qr) = &a.qr {
        let inputs: Vec<(&Path, Input)> = a.scene.iter().map(|p| (p.as_path(), Input::Scene)).collect();
        refuse_onto(&[qr], &inputs).map_err(anyhow::Error::msg)?;
        crate::io::atomic_write::check_file_destination(qr)?;
    }
    let doc = match &a.scene {
        Some(p) => super::scene_file(p)?,
        None => phonglab_core::Document::default(),
    };
    // The scene's mesh is an input too (the link names it; a picture over it loses it).
    if let (Some(qr), Some(mesh)) = (&a.qr, &doc.view.obj) {
        refuse_onto(&[qr], &[(Path::new(mesh), Input::Mesh)]).map_err(anyhow::Error::msg)?;
    }
    if let Some(lang) = &a.open_in
        && !["en", "pt-PT", "pt-BR"].contains(&lang.as_str())
    {
        anyhow::bail!(t!("err-share-lang", value = format!("{lang:?}")));
    }
    let shared = Shared {
        lang: a.open_in.clone(),
        present: a.present,
        channel: a.channel.map(|c| c.name().to_string()),
        ..Shared::of(doc)
    };
    phonglab_core::export::share::check_base(&a.base).map_err(anyhow::Error::msg)?;
    let url = link(&a.base, &shared)?;
    // The page (`--base`) is the user's text: written visibly if it holds a control.
    println!("{}", phonglab_core::escape::terminal::text(&url));
    eprintln!("{}", t!("share-summary", length = url.len() as i64));
    if let Some(qr) = &a.qr {
        crate::io::qr::write(qr, &url)?;
    }
    Ok(())
}
