//! An output never overwrites an input: the core's check ([`phonglab_core::files::same_file`]),
//! which the Python package shares.

pub use phonglab_core::files::same_file::*;

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

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
        let e = refuse_outputs_in_folder(&dir, &["a.md", "in.toml"], &[(input.as_path(), Input::Scene)]).unwrap_err();
        assert!(e.contains("in.toml") && e.contains("is the scene"), "{e}");
    }

    #[test]
    fn two_outputs_that_are_one_file_are_refused_before_either_exists() {
        let dir = std::env::temp_dir().join(format!("phonglab-same-output-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        let (a, b) = (dir.join("pic.png"), dir.join("sub/../pic.png"));
        let e = refuse_onto(&[&a, &b], &[]).unwrap_err();
        assert!(e.contains("the other output") && e.contains("the same file"), "{e}");
        assert!(refuse_onto(&[&a, &dir.join("pic.pfm")], &[]).is_ok());
        let mesh = dir.join("m.obj");
        std::fs::write(&mesh, "v 0 0 0").unwrap();
        let e = refuse_onto(&[&a, &mesh], &[(mesh.as_path(), Input::Mesh)]).unwrap_err();
        assert!(e.contains("is the mesh"), "{e}");
    }
}
