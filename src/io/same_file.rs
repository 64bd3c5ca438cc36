//! An output never overwrites an input: every command that writes a file checks, before it
//! reads or writes anything, that none of its outputs is one of its inputs.
//!
//! "The same file" is decided by the file itself, not by its name: two paths name one file
//! when they lead to the same device and inode (Unix), so a hard link, a symbolic link, a
//! `./` or a `..` in the path are all seen through. An output that does not exist yet is
//! no input. Where the system has no inodes (the browser has no paths at all), the
//! canonical paths are compared.

use std::path::{Path, PathBuf};

use phonglab_core::t;

/// What makes a file itself: its device and inode, or its canonical path.
#[derive(Debug, PartialEq, Eq)]
enum FileId {
    #[cfg(unix)]
    Inode(u64, u64),
    #[cfg_attr(unix, allow(dead_code))]
    Canonical(PathBuf),
}

/// The identity of the file `path` leads to (following symbolic links), if it exists.
fn file_id(path: &Path) -> Option<FileId> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let m = std::fs::metadata(path).ok()?;
        Some(FileId::Inode(m.dev(), m.ino()))
    }
    #[cfg(not(unix))]
    {
        std::fs::canonicalize(path).ok().map(FileId::Canonical)
    }
}

/// Refuses when an output in `outputs` is the same file as an input in `inputs`, naming
/// both (in the current language). Paths that do not exist are never the same file.
pub fn refuse_output_onto_input(outputs: &[&Path], inputs: &[&Path]) -> Result<(), String> {
    for output in outputs {
        let Some(out_id) = file_id(output) else { continue };
        for input in inputs {
            if file_id(input).is_some_and(|id| id == out_id) {
                return Err(t!(
                    "err-output-is-input",
                    output = output.display().to_string(),
                    input = input.display().to_string()
                ));
            }
        }
    }
    Ok(())
}

/// [`refuse_output_onto_input`] for the files a command writes into the folder `dir`
/// (`names`, without folders).
pub fn refuse_outputs_in_folder(dir: &Path, names: &[&str], inputs: &[&Path]) -> Result<(), String> {
    let outputs: Vec<PathBuf> = names.iter().map(|n| dir.join(n)).collect();
    let outputs: Vec<&Path> = outputs.iter().map(PathBuf::as_path).collect();
    refuse_output_onto_input(&outputs, inputs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_file_by_any_path_is_refused() {
        let dir = std::env::temp_dir().join(format!("phonglab-same-file-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        let input = dir.join("in.toml");
        std::fs::write(&input, "name = \"x\"").unwrap();
        let refused = |out: &Path| refuse_output_onto_input(&[out], &[input.as_path()]).is_err();
        assert!(refused(&input), "the path itself");
        assert!(refused(&dir.join("sub/../in.toml")), "through ..");
        #[cfg(unix)]
        {
            std::fs::hard_link(&input, dir.join("hard.toml")).unwrap();
            std::os::unix::fs::symlink(&input, dir.join("soft.toml")).unwrap();
            assert!(refused(&dir.join("hard.toml")), "a hard link");
            assert!(refused(&dir.join("soft.toml")), "a symbolic link");
        }
        assert!(!refused(&dir.join("new.png")), "a file that does not exist yet");
        std::fs::write(dir.join("other.toml"), "name = \"x\"").unwrap();
        assert!(!refused(&dir.join("other.toml")), "another file with the same bytes");
        let e = refuse_outputs_in_folder(&dir, &["a.md", "in.toml"], &[input.as_path()]).unwrap_err();
        assert!(e.contains("in.toml"), "{e}");
    }
}
