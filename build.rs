//! Embeds every scene file under `assets/scenes/` in the binary, so the Presets menu lists
//! them all (grouped by folder) wherever the binary runs.

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

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let scenes = root.join("assets/scenes");
    println!("cargo:rerun-if-changed=assets/scenes");
    let mut files = Vec::new();
    walk(&scenes, &mut files);
    files.sort();
    let mut code = String::from("/// Every scene file under assets/scenes: (path relative to it, its text).\n");
    code.push_str("pub const SCENE_FILES: &[(&str, &str)] = &[\n");
    for f in &files {
        let rel = f.strip_prefix(&scenes).expect("under assets/scenes").to_string_lossy().replace('\\', "/");
        println!("cargo:rerun-if-changed={}", f.display());
        code.push_str(&format!("    ({rel:?}, include_str!({:?})),\n", f.display().to_string()));
    }
    code.push_str("];\n");
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("scene_files.rs");
    std::fs::write(out, code).expect("OUT_DIR is writable");
}
