//! The app crate's layers, read off its paths (as the core's `tests/layers.rs` reads the
//! core's):
//!
//! | layer | folders | may name |
//! |---|---|---|
//! | 2 | `cli/`, `app/` | the layers below; never each other |
//! | 1 | `io/`, `paint/`, `platform/` | each other, and the core |
//!
//! `main.rs` and `lib.rs` join them. And there is no circle anywhere: not between files (a
//! file naming another, through `crate::` or `super::` paths, `use` trees included), nor
//! between folders. A parent's `mod` lines are not naming: a folder's `mod.rs` declares its
//! children, so it may only name them through `pub use` re-exports, which count.
//!
//! Comments and the unit tests (`#[cfg(test)] mod ...` at a file's end) are left out: they
//! are not the code's structure.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let p = entry.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// A file's module path: `src/app/shell/top_bar.rs` is `[app, shell, top_bar]`,
/// `src/app/mod.rs` is `[app]`, `src/lib.rs` and `src/main.rs` are `[]`.
fn module_of(file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src()).unwrap();
    let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    let last = parts.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if !matches!(stem, "mod" | "lib" | "main") {
        parts.push(stem.to_string());
    }
    parts
}

/// The file that holds module `path`, if one does.
fn file_of(path: &[String]) -> Option<PathBuf> {
    if path.is_empty() {
        return Some(src().join("lib.rs"));
    }
    let base = path.iter().fold(src(), |p, s| p.join(s));
    let flat = base.with_extension("rs");
    let folder = base.join("mod.rs");
    [flat, folder].into_iter().find(|p| p.exists())
}

/// The code of a file: comments and the trailing unit tests removed.
fn code(text: &str) -> String {
    let end = text.find("#[cfg(test)]\nmod ").unwrap_or(text.len());
    text[..end]
        .lines()
        .map(|l| match l.find("//") {
            // A `//` inside a string is rare in this crate's paths; cut at it either way.
            Some(at) => &l[..at],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths of `use` trees, expanded: `use crate::a::{b, c::d};` gives `crate::a::b` and
/// `crate::a::c::d`.
fn use_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let before = &rest[..at];
        let starts_statement = before.trim_end().is_empty()
            || before.trim_end().ends_with([';', '{', '}'])
            || before.trim_end().ends_with("pub")
            || before.trim_end().ends_with(')');
        let after = &rest[at + 4..];
        let Some(end) = after.find(';') else { break };
        if starts_statement {
            expand(&after[..end].split_whitespace().collect::<String>(), "", &mut out);
        }
        rest = &after[end..];
    }
    out
}

fn expand(tree: &str, prefix: &str, out: &mut Vec<String>) {
    match tree.find('{') {
        None => out.push(format!("{prefix}{}", tree.split(" as ").next().unwrap_or(tree))),
        Some(open) => {
            let head = &tree[..open];
            let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
            let mut depth = 0;
            let mut start = 0;
            for (i, c) in inner.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        expand(&inner[start..i], &format!("{prefix}{head}"), out);
                        start = i + 1;
                    }
                    _ => {}
                }
            }
            if start < inner.len() {
                expand(&inner[start..], &format!("{prefix}{head}"), out);
            }
        }
    }
}

/// Every `crate::` and `super::` path in the code (in `use` trees or inline), as a module
/// path from the crate's root.
fn named_paths(file: &Path, code: &str) -> Vec<Vec<String>> {
    let here = module_of(file);
    let mut raw: Vec<String> = use_paths(code);
    for root in ["crate::", "super::"] {
        let mut rest = code;
        while let Some(at) = rest.find(root) {
            let ok_before = rest[..at].chars().last().is_none_or(|c| !(c.is_alphanumeric() || c == '_' || c == '$'));
            let tail: String =
                rest[at..].chars().take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':').collect();
            if ok_before {
                raw.push(tail.clone());
            }
            rest = &rest[at + root.len()..];
        }
    }
    let mut out = Vec::new();
    for path in raw {
        let mut segments: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
        let mut base: Vec<String> = match segments.first() {
            Some(&"crate") => {
                segments.remove(0);
                Vec::new()
            }
            Some(&"super") => {
                // A file's `super` is its parent module; a `mod.rs` file's, its folder's parent.
                let mut m = here.clone();
                while segments.first() == Some(&"super") {
                    segments.remove(0);
                    m.pop();
                }
                m
            }
            Some(&"self") => {
                segments.remove(0);
                here.clone()
            }
            // A path that starts at a child module of this one (`use state::AppState;` in a
            // `mod.rs`).
            Some(first) if file_of(&[here.clone(), vec![first.to_string()]].concat()).is_some() => here.clone(),
            _ => continue,
        };
        base.extend(segments.iter().map(|s| s.to_string()));
        out.push(base);
    }
    out
}

/// The file each named path leads to: the longest prefix that is a module file.
fn imports(file: &Path) -> BTreeSet<PathBuf> {
    let text = std::fs::read_to_string(file).unwrap();
    let mut out = BTreeSet::new();
    for path in named_paths(file, &code(&text)) {
        for k in (1..=path.len()).rev() {
            if let Some(f) = file_of(&path[..k]) {
                if f != file {
                    out.insert(f);
                }
                break;
            }
        }
    }
    out
}

/// The layer folder a file is in: `cli`, `app`, `io`, `paint`, `platform`, or `` (the root).
fn top(file: &Path) -> String {
    module_of(file).first().cloned().unwrap_or_default()
}

fn graph() -> BTreeMap<PathBuf, BTreeSet<PathBuf>> {
    let mut files = Vec::new();
    sources(&src(), &mut files);
    files.into_iter().map(|f| (f.clone(), imports(&f))).collect()
}

fn short(p: &Path) -> String {
    p.strip_prefix(src()).unwrap().display().to_string()
}

#[test]
fn the_command_line_and_the_window_never_name_each_other_and_the_layers_below_neither() {
    let mut wrong = Vec::new();
    for (file, names) in graph() {
        let from = top(&file);
        for to in names {
            let to_layer = top(&to);
            let allowed = match (from.as_str(), to_layer.as_str()) {
                (_, "") => from.is_empty(),
                ("cli", "app") | ("app", "cli") => false,
                ("io" | "paint" | "platform", "cli" | "app") => false,
                _ => true,
            };
            if !allowed {
                wrong.push(format!("{} names {}", short(&file), short(&to)));
            }
        }
    }
    assert!(wrong.is_empty(), "paths against the layers:\n{}", wrong.join("\n"));
}

/// The strongly connected parts of `g` with more than one member (Tarjan's algorithm).
fn circles<T: Ord + Clone>(g: &BTreeMap<T, BTreeSet<T>>) -> Vec<Vec<T>> {
    struct State<T> {
        index: BTreeMap<T, usize>,
        low: BTreeMap<T, usize>,
        stack: Vec<T>,
        on: BTreeSet<T>,
        out: Vec<Vec<T>>,
    }
    fn visit<T: Ord + Clone>(v: &T, g: &BTreeMap<T, BTreeSet<T>>, s: &mut State<T>) {
        let i = s.index.len();
        s.index.insert(v.clone(), i);
        s.low.insert(v.clone(), i);
        s.stack.push(v.clone());
        s.on.insert(v.clone());
        for w in g.get(v).into_iter().flatten() {
            if !s.index.contains_key(w) {
                visit(w, g, s);
                let l = s.low[w].min(s.low[v]);
                s.low.insert(v.clone(), l);
            } else if s.on.contains(w) {
                let l = s.index[w].min(s.low[v]);
                s.low.insert(v.clone(), l);
            }
        }
        if s.low[v] == s.index[v] {
            let mut part = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on.remove(&w);
                let done = w == *v;
                part.push(w);
                if done {
                    break;
                }
            }
            if part.len() > 1 {
                s.out.push(part);
            }
        }
    }
    let mut s =
        State { index: BTreeMap::new(), low: BTreeMap::new(), stack: Vec::new(), on: BTreeSet::new(), out: Vec::new() };
    for v in g.keys() {
        if !s.index.contains_key(v) {
            visit(v, g, &mut s);
        }
    }
    s.out
}

#[test]
fn no_file_names_a_file_that_names_it_back_however_far_round() {
    let g = graph();
    let found: Vec<String> =
        circles(&g).iter().map(|c| c.iter().map(|p| short(p)).collect::<Vec<_>>().join(" -> ")).collect();
    assert!(found.is_empty(), "circles between files:\n{}", found.join("\n"));
}

#[test]
fn no_folder_names_a_folder_that_names_it_back() {
    let folder = |p: &Path| short(p.parent().unwrap_or(p)).trim_start_matches("..").to_string();
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, names) in graph() {
        let from = folder(&file);
        for to in names {
            let to = folder(&to);
            if to != from {
                g.entry(from.clone()).or_default().insert(to);
            }
        }
    }
    let found: Vec<String> = circles(&g).iter().map(|c| c.join(" -> ")).collect();
    assert!(found.is_empty(), "circles between folders:\n{}", found.join("\n"));
}

#[test]
fn the_reading_of_paths_is_itself_right() {
    let mut out = Vec::new();
    expand("crate::a::{b::{C,D},e}", "", &mut out);
    assert_eq!(out, ["crate::a::b::C", "crate::a::b::D", "crate::a::e"]);
    // From a file two folders down, `super` is its folder's module.
    let file = src().join("x/y/z.rs");
    let named = named_paths(&file, "use super::w::T;\nfn f() { crate::io::budget::check(); }");
    assert!(named.contains(&vec!["x".into(), "y".into(), "w".into(), "T".into()]), "{named:?}");
    assert!(named.contains(&vec!["io".into(), "budget".into(), "check".into()]), "{named:?}");
    assert_eq!(module_of(&src().join("x/mod.rs")), ["x"]);
}
