//! The scene files shipped under `assets/scenes/`, embedded at build time (`build.rs`), as
//! the Presets menu lists them: grouped by folder, each with a title and its document.

use phonglab_core::Document;

include!(concat!(env!("OUT_DIR"), "/scene_files.rs"));

/// One shipped scene file.
#[derive(Clone, Debug)]
pub struct SceneFile {
    /// The menu group, e.g. "Red Book teapots".
    pub group: &'static str,
    /// The menu title, e.g. "Gold".
    pub title: String,
    /// The path under `assets/scenes/`.
    pub path: &'static str,
    /// The document (every shipped file loads; a test checks it).
    pub doc: Document,
}

/// A title from a file stem: `worksheet-mview2` -> "Worksheet, mview2", `11-gold` -> "Gold",
/// `three-lights` -> "Three lights".
fn title(stem: &str) -> String {
    if let Some(k) = stem.strip_prefix("worksheet-") {
        return format!("Worksheet, {k}");
    }
    let stem = stem.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start_matches('-');
    let words = stem.replace('-', " ");
    let mut c = words.chars();
    c.next().map(|f| f.to_uppercase().collect::<String>() + c.as_str()).unwrap_or_default()
}

fn group(path: &str) -> &'static str {
    if path.starts_with("redbook-teapots/") {
        "Red Book teapots"
    } else if path.starts_with("worksheet-") {
        "The worksheet"
    } else if path.starts_with("phong-demo") {
        "The Phong demo"
    } else {
        "More scenes"
    }
}

/// Every shipped scene file that loads, in menu order (the worksheet, the demo, more, the
/// teapots), parsed once.
pub fn scene_files() -> &'static [SceneFile] {
    static FILES: std::sync::OnceLock<Vec<SceneFile>> = std::sync::OnceLock::new();
    FILES.get_or_init(|| {
        let order = ["The worksheet", "The Phong demo", "More scenes", "Red Book teapots"];
        let mut v: Vec<SceneFile> = SCENE_FILES
            .iter()
            .filter_map(|(path, text)| {
                let doc = Document::from_toml(text).ok()?;
                let stem = path.rsplit('/').next()?.trim_end_matches(".toml");
                Some(SceneFile { group: group(path), title: title(stem), path, doc })
            })
            .collect();
        v.sort_by_key(|f| (order.iter().position(|g| *g == f.group).unwrap_or(order.len()), f.path));
        v
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_file_is_listed_and_loads() {
        assert_eq!(SCENE_FILES.len(), 32);
        assert_eq!(scene_files().len(), SCENE_FILES.len(), "every shipped file loads");
        let titles: Vec<&str> = scene_files().iter().map(|f| f.title.as_str()).collect();
        assert_eq!(titles[0], "Worksheet, mview1");
        assert!(titles.contains(&"Phong demo") && titles.contains(&"Gold") && titles.contains(&"Three lights"));
        assert_eq!(scene_files().iter().filter(|f| f.group == "Red Book teapots").count(), 24);
    }
}
