//! The scene files shipped under `assets/scenes/`, embedded at build time (`build.rs`), as
//! the Presets menu lists them: grouped by folder, each with a title and its document.

use phonglab_core::Document;

use crate::locale::{current, has_message, tr, tr_args};
use crate::t;

include!(concat!(env!("OUT_DIR"), "/scene_files.rs"));

/// The Presets menu's groups, in menu order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Group {
    /// `worksheet-mview1..5`.
    Worksheet,
    /// `phong-demo`.
    PhongDemo,
    /// Everything else at the top.
    More,
    /// `redbook-teapots/`: the 24 classic materials on the teapot.
    RedbookTeapots,
}

impl Group {
    fn of(path: &str) -> Group {
        if path.starts_with("redbook-teapots/") {
            Group::RedbookTeapots
        } else if path.starts_with("worksheet-") {
            Group::Worksheet
        } else if path.starts_with("phong-demo") {
            Group::PhongDemo
        } else {
            Group::More
        }
    }

    /// The group's heading in the current language.
    pub fn label(self) -> String {
        match self {
            Group::Worksheet => t!("preset-group-worksheet"),
            Group::PhongDemo => t!("preset-group-phong-demo"),
            Group::More => t!("preset-group-more"),
            Group::RedbookTeapots => t!("redbook-teapots"),
        }
    }
}

/// One shipped scene file.
#[derive(Clone, Debug)]
pub struct SceneFile {
    /// The menu group.
    pub group: Group,
    /// The file's stem, e.g. "11-gold", "worksheet-mview2".
    pub stem: &'static str,
    /// The path under `assets/scenes/`.
    pub path: &'static str,
    /// The document (every shipped file loads; a test checks it).
    pub doc: Document,
}

impl SceneFile {
    /// The menu title in the current language: `worksheet-mview2` -> "Worksheet, mview2"
    /// ("Ficha, mview2"), `11-gold` -> "Gold" ("Ouro"), `three-lights` -> "Three lights"
    /// ("Três luzes").
    pub fn title(&self) -> String {
        if let Some(k) = self.stem.strip_prefix("worksheet-") {
            return tr_args("preset-worksheet", &[("modelview", k.into())]);
        }
        let name = self.stem.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start_matches('-');
        let words = if self.group == Group::RedbookTeapots {
            phonglab_core::materials::display_name(name)
        } else {
            let id = format!("preset-{name}");
            if has_message(current().lang, &id) { tr(&id) } else { name.replace('-', " ") }
        };
        let mut c = words.chars();
        c.next().map(|f| f.to_uppercase().collect::<String>() + c.as_str()).unwrap_or_default()
    }
}

/// Every shipped scene file that loads, in menu order (the worksheet, the demo, more, the
/// teapots), parsed once.
pub fn scene_files() -> &'static [SceneFile] {
    static FILES: std::sync::OnceLock<Vec<SceneFile>> = std::sync::OnceLock::new();
    FILES.get_or_init(|| {
        let mut v: Vec<SceneFile> = SCENE_FILES
            .iter()
            .filter_map(|(path, text)| {
                let doc = Document::from_toml(text).ok()?;
                let stem = path.rsplit('/').next()?.trim_end_matches(".toml");
                Some(SceneFile { group: Group::of(path), stem, path, doc })
            })
            .collect();
        v.sort_by_key(|f| (f.group, f.path));
        v
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_file_is_listed_and_loads() {
        assert_eq!(SCENE_FILES.len(), 34);
        assert_eq!(scene_files().len(), SCENE_FILES.len(), "every shipped file loads");
        use crate::locale::{Lang, Locale, set_thread};
        set_thread(Some(Locale::of(Lang::En)));
        let titles: Vec<String> = scene_files().iter().map(super::SceneFile::title).collect();
        assert_eq!(titles[0], "Worksheet, mview1");
        for t in ["Phong demo", "Gold", "Three lights", "Yellow rubber", "Spotlight"] {
            assert!(titles.iter().any(|x| x == t), "{t} in {titles:?}");
        }
        assert_eq!(scene_files().iter().filter(|f| f.group == Group::RedbookTeapots).count(), 24);
        set_thread(Some(Locale::of(Lang::PtPt)));
        let titles: Vec<String> = scene_files().iter().map(super::SceneFile::title).collect();
        assert_eq!(titles[0], "Ficha, mview1");
        for t in ["Demo de Phong", "Ouro", "Três luzes", "Borracha amarela", "Foco"] {
            assert!(titles.iter().any(|x| x == t), "{t} in {titles:?}");
        }
        assert_eq!(Group::RedbookTeapots.label(), "Bules do Red Book");
        set_thread(None);
    }
}
