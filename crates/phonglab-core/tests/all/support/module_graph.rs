//! A crate's modules as a graph of files, read off its paths, for the layer tests of both
//! crates (`tests/layers.rs` of each): which file names which (through `crate::`, `super::`
//! and `self::` paths, `use` trees expanded), and the circles in such a graph. Comments and
//! a file's trailing unit tests (`#[cfg(test)] mod ...`) are left out: they are not the
//! code's structure. A parent's `mod` lines are not naming (a folder's `mod.rs` declares
//! its children); its `pub use` re-exports are.

#![allow(dead_code)] // each crate's test uses what it needs

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
pub fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
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
pub fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).unwrap();
    let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    let last = parts.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if !matches!(stem, "mod" | "lib" | "main") {
        parts.push(stem.to_string());
    }
    parts
}

/// The file that holds module `path`, if one does.
pub fn file_of(src: &Path, path: &[String]) -> Option<PathBuf> {
    if path.is_empty() {
        return Some(src.join("lib.rs"));
    }
    let base = path.iter().fold(src.to_path_buf(), |p, s| p.join(s));
    let flat = base.with_extension("rs");
    let folder = base.join("mod.rs");
    [flat, folder].into_iter().find(|p| p.exists())
}

/// The code of a file: comments and the trailing unit tests removed.
pub fn code(text: &str) -> String {
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
pub fn use_paths(code: &str) -> Vec<String> {
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

pub fn expand(tree: &str, prefix: &str, out: &mut Vec<String>) {
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
pub fn named_paths(src: &Path, file: &Path, code: &str) -> Vec<Vec<String>> {
    let here = module_of(src, file);
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
            Some(first) if file_of(src, &[here.clone(), vec![first.to_string()]].concat()).is_some() => here.clone(),
            _ => continue,
        };
        base.extend(segments.iter().map(std::string::ToString::to_string));
        out.push(base);
    }
    out
}

/// The file each named path leads to: the longest prefix that is a module file.
pub fn imports(src: &Path, file: &Path) -> BTreeSet<PathBuf> {
    let text = std::fs::read_to_string(file).unwrap();
    let mut out = BTreeSet::new();
    for path in named_paths(src, file, &code(&text)) {
        for k in (1..=path.len()).rev() {
            if let Some(f) = file_of(src, &path[..k]) {
                if f != file {
                    out.insert(f);
                }
                break;
            }
        }
    }
    out
}

/// Every file of the crate under `src` and the files it names.
pub fn graph(src: &Path) -> BTreeMap<PathBuf, BTreeSet<PathBuf>> {
    let mut files = Vec::new();
    sources(src, &mut files);
    files.into_iter().map(|f| (f.clone(), imports(src, &f))).collect()
}

/// `p` from `src`.
pub fn short(src: &Path, p: &Path) -> String {
    // Its folders joined by `/` on every system (Windows writes `\`), as the messages and
    // the tests' expectations name them.
    let parts: Vec<String> =
        p.strip_prefix(src).unwrap().components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
    parts.join("/")
}

/// The strongly connected parts of `g` with more than one member (Tarjan's algorithm).
pub fn circles<T: Ord + Clone>(g: &BTreeMap<T, BTreeSet<T>>) -> Vec<Vec<T>> {
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

/// The circles between files of `g`, each as `a -> b -> ...` from `src`.
pub fn file_circles(src: &Path, g: &BTreeMap<PathBuf, BTreeSet<PathBuf>>) -> Vec<String> {
    circles(g).iter().map(|c| c.iter().map(|p| short(src, p)).collect::<Vec<_>>().join(" -> ")).collect()
}

/// The circles between folders of `g` (a file names its folder's files freely).
pub fn folder_circles(src: &Path, g: &BTreeMap<PathBuf, BTreeSet<PathBuf>>) -> Vec<String> {
    let folder = |p: &Path| short(src, p.parent().unwrap_or(p)).trim_start_matches("..").to_string();
    let mut fg: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, names) in g {
        let from = folder(file);
        for to in names {
            let to = folder(to);
            if to != from {
                fg.entry(from.clone()).or_default().insert(to);
            }
        }
    }
    circles(&fg).iter().map(|c| c.join(" -> ")).collect()
}

/// The circles among the rooms of each folder of `g`, as a newcomer meets them one folder
/// at a time: in folder D the rooms are D's own files and D's subfolders (each whole, its
/// files inside), and a file names a room when it names a file in it. A subfolder is a
/// part of its parent, so its files may use its parent's files as any of them may; what
/// is refused is two rooms of one folder that name each other, however far round.
pub fn room_circles(src: &Path, g: &BTreeMap<PathBuf, BTreeSet<PathBuf>>) -> Vec<String> {
    let mut folders: BTreeSet<PathBuf> = BTreeSet::new();
    for f in g.keys() {
        let mut d = f.parent();
        while let Some(p) = d {
            if !p.starts_with(src) {
                break;
            }
            folders.insert(p.to_path_buf());
            d = p.parent();
        }
    }
    let mut found = Vec::new();
    for folder in folders {
        let room = |f: &Path| {
            f.strip_prefix(&folder).ok().and_then(|r| r.iter().next()).map(|c| c.to_string_lossy().into_owned())
        };
        let mut rooms: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (file, names) in g {
            let Some(from) = room(file) else { continue };
            for to in names {
                if let Some(to) = room(to)
                    && to != from
                {
                    rooms.entry(from.clone()).or_default().insert(to);
                }
            }
        }
        for c in circles(&rooms) {
            found.push(format!("in {}: {}", short(src, &folder), c.join(" -> ")));
        }
    }
    found
}
