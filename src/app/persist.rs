//! Restoring the last session without ever losing it.
//!
//! eframe keeps the app's state in `app.ron` in its storage folder, and phonglab keeps its
//! scene there under [`DOCUMENT_KEY`] as a scene file (TOML). Two things can go wrong:
//!
//! - `app.ron` does not parse (damaged, or written by something else). eframe would start
//!   empty and overwrite it on exit; [`set_aside_unreadable_storage`] renames it first.
//! - The scene in it does not load (an older or damaged format). [`restore_document`]
//!   starts from the worksheet and writes the text to a file beside the storage.
//!
//! Either way the app starts on defaults and says what happened and where the file is.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use phonglab_core::Document;

/// eframe's app id: the storage folder's name.
pub const APP_ID: &str = "phonglab";

/// The key the document is persisted under.
pub const DOCUMENT_KEY: &str = "phonglab.document.toml";

/// A file name beside the storage that does not exist yet: `{stem}-{unix seconds}[-n].{ext}`.
fn fresh_path(dir: &Path, stem: &str, ext: &str) -> PathBuf {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let mut p = dir.join(format!("{stem}-{secs}.{ext}"));
    let mut n = 1;
    while p.exists() {
        p = dir.join(format!("{stem}-{secs}-{n}.{ext}"));
        n += 1;
    }
    p
}

/// When `dir/app.ron` exists but is not eframe's storage (a RON map of strings), renames
/// it to `app-unreadable-<time>.ron` beside it and returns a message saying so.
pub fn set_aside_unreadable_storage(dir: &Path) -> Option<String> {
    let path = dir.join("app.ron");
    let bytes = std::fs::read(&path).ok()?;
    let parsed = std::str::from_utf8(&bytes)
        .map_err(|e| e.to_string())
        .and_then(|t| ron::from_str::<HashMap<String, String>>(t).map_err(|e| e.to_string()));
    let why = parsed.err()?;
    let kept = fresh_path(dir, "app-unreadable", "ron");
    Some(match std::fs::rename(&path, &kept) {
        Ok(()) => format!(
            "The saved session could not be read ({why}); starting on the worksheet. The file is kept as {}.",
            kept.display()
        ),
        Err(e) => format!(
            "The saved session {} could not be read ({why}) nor set aside ({e}); starting on the worksheet.",
            path.display()
        ),
    })
}

/// The last session's document, from the text stored under [`DOCUMENT_KEY`].
///
/// `Ok(None)`: nothing stored. `Err(message)`: the text does not load; it has been written
/// to `phonglab-unreadable-<time>.toml` in `dir` (when given) and the message says where.
pub fn restore_document(text: Option<&str>, dir: Option<&Path>) -> Result<Option<Document>, String> {
    let Some(text) = text else { return Ok(None) };
    let e = match Document::from_toml(text) {
        Ok(doc) => return Ok(Some(doc)),
        Err(e) => e,
    };
    let kept = match dir {
        Some(dir) => {
            let p = fresh_path(dir, "phonglab-unreadable", "toml");
            match std::fs::create_dir_all(dir).and_then(|()| std::fs::write(&p, text)) {
                Ok(()) => format!("The scene is kept in {}.", p.display()),
                Err(err) => format!("It could not be kept ({err})."),
            }
        }
        None => "There is no storage folder to keep it in.".into(),
    };
    Err(format!("The last session's scene could not be restored ({e}); starting on the worksheet. {kept}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("phonglab-persist-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_good_session_is_restored_and_an_empty_one_is_none() {
        let doc = phonglab_core::Document::default();
        let text = doc.to_toml().unwrap();
        assert_eq!(restore_document(Some(&text), None), Ok(Some(doc)));
        assert_eq!(restore_document(None, None), Ok(None));
    }

    #[test]
    fn a_bad_scene_is_kept_beside_the_storage() {
        let dir = temp_dir("scene");
        let bad = "name = \"mine\"\n[material]\nshininess = 500\n";
        let msg = restore_document(Some(bad), Some(&dir)).unwrap_err();
        assert!(msg.contains("material.shininess") && msg.contains("starting on the worksheet"), "{msg}");
        let kept: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
        assert_eq!(kept.len(), 1);
        assert!(msg.contains(&kept[0].display().to_string()), "{msg}");
        assert_eq!(std::fs::read_to_string(&kept[0]).unwrap(), bad, "kept byte for byte");
    }

    #[test]
    fn an_unreadable_storage_file_is_set_aside_and_a_good_one_left_alone() {
        let dir = temp_dir("ron");
        let good = ron::to_string(&HashMap::from([(DOCUMENT_KEY.to_string(), "name = \"x\"".to_string())])).unwrap();
        std::fs::write(dir.join("app.ron"), &good).unwrap();
        assert_eq!(set_aside_unreadable_storage(&dir), None);
        assert!(dir.join("app.ron").exists());

        std::fs::write(dir.join("app.ron"), "{\"phonglab.document.toml\": \"unterminated").unwrap();
        let msg = set_aside_unreadable_storage(&dir).unwrap();
        assert!(!dir.join("app.ron").exists(), "moved, so eframe does not overwrite it");
        let kept: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
        assert_eq!(kept.len(), 1);
        assert!(msg.contains(&kept[0].display().to_string()), "{msg}");
        assert!(std::fs::read_to_string(&kept[0]).unwrap().contains("unterminated"));
        assert_eq!(set_aside_unreadable_storage(&temp_dir("none")), None, "no file, nothing to say");
    }
}
