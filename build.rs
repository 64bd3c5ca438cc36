//! Embeds every scene file under `assets/scenes/` in the binary, so the Scene menu lists
//! them all (grouped by folder) wherever the binary runs, and every experiment under
//! `assets/experiments/` (the "Things to try" window's); and sets `PHONGLAB_COMMIT`, the
//! commit `phonglab --version` prints (`git rev-parse --short HEAD`, or "unknown" where
//! git or the repository is not there, as in a crate's source tarball).

use std::path::{Path, PathBuf};

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|x| x == "toml") {
            out.push(p);
        }
    }
}

/// Writes `OUT_DIR/<out>`: the const `name`, every `.toml` under `dir` (relative to the
/// crate) as (its path under `dir`, its text).
fn embed(root: &Path, dir: &str, name: &str, out: &str) {
    let base = root.join(dir);
    println!("cargo:rerun-if-changed={dir}");
    let mut files = Vec::new();
    walk(&base, &mut files);
    files.sort();
    let mut code = format!("/// Every file under {dir}: (path relative to it, its text).\n");
    code.push_str(&format!("pub const {name}: &[(&str, &str)] = &[\n"));
    for f in &files {
        let rel = f.strip_prefix(&base).expect("under the folder").to_string_lossy().replace('\\', "/");
        println!("cargo:rerun-if-changed={}", f.display());
        code.push_str(&format!("    ({rel:?}, include_str!({:?})),\n", f.display().to_string()));
    }
    code.push_str("];\n");
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join(out);
    std::fs::write(out, code).expect("OUT_DIR is writable");
}

/// The output of `git ARGS` run in `root`, trimmed; None where git is missing or fails.
fn git(root: &Path, args: &[&str]) -> Option<String> {
    let out = std::process::Command::new("git").arg("-C").arg(root).args(args).output().ok()?;
    let text = String::from_utf8(out.stdout).ok()?;
    (out.status.success() && !text.trim().is_empty()).then(|| text.trim().to_string())
}

/// Sets `PHONGLAB_COMMIT` for the crate, and asks cargo to run this again when HEAD moves
/// (a checkout, or a commit on the current branch). Only files that exist are watched: cargo
/// runs a build script whose watched file is missing on every build.
fn commit(root: &Path) {
    let hash = git(root, &["rev-parse", "--short", "HEAD"]);
    if hash.is_some() {
        let mut watched = vec!["HEAD".to_string(), "packed-refs".to_string()];
        watched.extend(git(root, &["symbolic-ref", "-q", "HEAD"]));
        for name in watched {
            let path = git(root, &["rev-parse", "--path-format=absolute", "--git-path", &name]);
            if let Some(path) = path.filter(|p| Path::new(p).is_file()) {
                println!("cargo:rerun-if-changed={path}");
            }
        }
    }
    println!("cargo:rustc-env=PHONGLAB_COMMIT={}", hash.as_deref().unwrap_or("unknown"));
}

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    embed(&root, "assets/scenes", "SCENE_FILES", "scene_files.rs");
    embed(&root, "assets/experiments", "EXPERIMENT_FILES", "experiment_files.rs");
    commit(&root);
}
