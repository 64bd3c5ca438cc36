//! A folder's contents for phonglab's own file chooser (where the system's dialog cannot
//! open): its subfolders, then the files a purpose takes, each sorted by name; hidden
//! entries left out.

use std::path::Path;

/// One entry of a folder.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Entry {
    /// Its name.
    pub name: String,
    /// A folder (else a file).
    pub folder: bool,
}

/// The subfolders of `dir` and its files whose extension is one of `extensions` (all
/// files when empty), folders first, each group sorted; or why the folder cannot be read.
pub fn list(dir: &Path, extensions: &[&str]) -> Result<Vec<Entry>, String> {
    // In the user's words ("não existe"), the name with its control characters visible.
    let read = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {}", crate::io::reasons::shown(dir), crate::io::reasons::io_reason(&e)))?;
    let mut out: Vec<Entry> = read
        .filter_map(Result::ok)
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.starts_with('.') {
                return None;
            }
            // Through links, as a user's folders are.
            let folder = std::fs::metadata(e.path()).is_ok_and(|m| m.is_dir());
            let wanted = folder
                || extensions.is_empty()
                || Path::new(&name).extension().is_some_and(|x| extensions.iter().any(|w| x.eq_ignore_ascii_case(w)));
            wanted.then_some(Entry { name, folder })
        })
        .collect();
    out.sort_by(|a, b| b.folder.cmp(&a.folder).then_with(|| a.name.to_lowercase().cmp(&b.name.to_lowercase())));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_folder_that_cannot_be_read_is_said_in_the_users_words() {
        use phonglab_core::locale::{Lang, Locale, with_locale};
        let missing = Path::new("/no/such/phonglab/folder");
        let said = with_locale(Locale::of(Lang::PtPt), || list(missing, &[]).unwrap_err());
        assert_eq!(said, "/no/such/phonglab/folder: não existe");
        let said = with_locale(Locale::of(Lang::En), || list(missing, &[]).unwrap_err());
        assert_eq!(said, "/no/such/phonglab/folder: it does not exist");
    }

    #[test]
    fn folders_first_then_the_files_wanted_without_hidden_ones() {
        let dir = std::env::temp_dir().join(format!("phonglab-listing-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("b-folder")).unwrap();
        std::fs::create_dir_all(dir.join(".hidden")).unwrap();
        for f in ["z.toml", "A.toml", "notes.txt", ".x.toml", "m.OBJ"] {
            std::fs::write(dir.join(f), "").unwrap();
        }
        let got = list(&dir, &["toml", "obj"]).unwrap();
        let names: Vec<&str> = got.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["b-folder", "A.toml", "m.OBJ", "z.toml"]);
        assert!(got[0].folder && !got[1].folder);
        assert!(list(&dir.join("missing"), &[]).unwrap_err().contains("missing"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
