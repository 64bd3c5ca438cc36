//! The app crate's layers, read off its paths (as the core's `tests/layers.rs` reads the
//! core's):
//!
//! | layer | folders | may name |
//! |---|---|---|
//! | 2 | `cli/`, `app/` | the layers below; never each other |
//! | 1 | `io/`, `paint/`, `platform/` | each other, and the core |
//! | 0 | `locale/` | the core (the app's words: every layer names it) |
//!
//! `main.rs` and `lib.rs` join them. And there is no circle anywhere: not between files (a
//! file naming another, through `crate::` or `super::` paths, `use` trees included), nor
//! between folders. A parent's `mod` lines are not naming: a folder's `mod.rs` declares its
//! children, so it may only name them through `pub use` re-exports, which count.
//!
//! Comments and the unit tests (`#[cfg(test)] mod ...` at a file's end) are left out: they
//! are not the code's structure.

use std::path::{Path, PathBuf};

#[path = "../../crates/phonglab-core/tests/all/support/module_graph.rs"]
mod module_graph;

use module_graph::{expand, file_circles, folder_circles, graph, module_of, named_paths, room_circles};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The layer folder a file is in: `cli`, `app`, `io`, `paint`, `platform`, or `` (the root).
fn top(file: &Path) -> String {
    module_of(&src(), file).first().cloned().unwrap_or_default()
}

fn short(p: &Path) -> String {
    module_graph::short(&src(), p)
}

#[test]
fn the_command_line_and_the_window_never_name_each_other_and_the_layers_below_neither() {
    let mut wrong = Vec::new();
    for (file, names) in graph(&src()) {
        let from = top(&file);
        for to in names {
            let to_layer = top(&to);
            let allowed = match (from.as_str(), to_layer.as_str()) {
                (_, "") => from.is_empty(),
                ("cli", "app") | ("app", "cli") => false,
                ("io" | "paint" | "platform", "cli" | "app") => false,
                ("locale", _) => to_layer == "locale",
                _ => true,
            };
            if !allowed {
                wrong.push(format!("{} names {}", short(&file), short(&to)));
            }
        }
    }
    assert!(wrong.is_empty(), "paths against the layers:\n{}", wrong.join("\n"));
}

#[test]
fn no_file_names_a_file_that_names_it_back_however_far_round() {
    let found = file_circles(&src(), &graph(&src()));
    assert!(found.is_empty(), "circles between files:\n{}", found.join("\n"));
}

#[test]
fn no_folder_names_a_folder_that_names_it_back() {
    let found = folder_circles(&src(), &graph(&src()));
    assert!(found.is_empty(), "circles between folders:\n{}", found.join("\n"));
}

#[test]
fn no_two_rooms_of_a_folder_name_each_other() {
    let found = room_circles(&src(), &graph(&src()));
    assert!(found.is_empty(), "circles between the rooms of a folder:\n{}", found.join("\n"));
}

#[test]
fn the_reading_of_paths_is_itself_right() {
    let mut out = Vec::new();
    expand("crate::a::{b::{C,D},e}", "", &mut out);
    assert_eq!(out, ["crate::a::b::C", "crate::a::b::D", "crate::a::e"]);
    // From a file two folders down, `super` is its folder's module.
    let file = src().join("x/y/z.rs");
    let named = named_paths(&src(), &file, "use super::w::T;\nfn f() { crate::io::budget::check(); }");
    assert!(named.contains(&vec!["x".into(), "y".into(), "w".into(), "T".into()]), "{named:?}");
    assert!(named.contains(&vec!["io".into(), "budget".into(), "check".into()]), "{named:?}");
    assert_eq!(module_of(&src(), &src().join("x/mod.rs")), ["x"]);
}

/// The names ARCHITECTURE.md gives code: every word inside a `...` span, and every word of
/// its fenced drawings (the layer tables).
fn architecture_names() -> std::collections::BTreeSet<String> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md")).unwrap();
    let mut names = std::collections::BTreeSet::new();
    let mut words = |s: &str| {
        for w in s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).filter(|w| !w.is_empty()) {
            names.insert(w.to_string());
        }
    };
    for (k, part) in text.split("```").enumerate() {
        if k % 2 == 1 {
            words(part);
        } else {
            part.split('`').skip(1).step_by(2).for_each(&mut words);
        }
    }
    names
}

/// Every module of both crates, file or folder, by its name (`mod.rs`, `lib.rs` and
/// `main.rs` are their folder's).
fn module_names(dir: &Path, out: &mut Vec<(String, PathBuf)>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let p = entry.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if p.is_dir() {
            // Program templates, not modules.
            if name != "templates" {
                out.push((name, p.clone()));
                module_names(&p, out);
            }
        } else if let Some(stem) = name.strip_suffix(".rs")
            && !matches!(stem, "mod" | "lib" | "main")
        {
            out.push((stem.to_string(), p));
        }
    }
}

/// ARCHITECTURE.md names every module of the core and the app, in code type (it did not
/// name the probe, its report, the channels, the director or four of the app's panels).
#[test]
fn architecture_names_every_module() {
    let named = architecture_names();
    let mut modules = Vec::new();
    module_names(&src(), &mut modules);
    module_names(&Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/phonglab-core/src"), &mut modules);
    assert!(modules.len() > 200, "{}", modules.len());
    let missing: Vec<String> =
        modules.iter().filter(|(name, _)| !named.contains(name)).map(|(_, p)| p.display().to_string()).collect();
    assert!(missing.is_empty(), "ARCHITECTURE.md does not name:\n{}", missing.join("\n"));
}
