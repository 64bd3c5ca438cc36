//! The core's groups form one order, each group using only the groups below it, and
//! modules name each other by group (`crate::equation::lighting`, not `crate::lighting`),
//! so the order can be read off every path. From the bottom:
//!
//! | rank | group | what it is |
//! |---|---|---|
//! | 0 | locale | the user's language: every group says things |
//! | 1 | numerics | floating point with care, numbers as typed, the processor's features |
//! | 2 | mesh | gluSphere, gluCylinder, the teapot, OBJ files |
//! | 3 | model | what is lit: scene, rules, materials, camera, view, presets, errors |
//! | 4 | equation | the lighting equation, the stage list a scene compiles to (`plan`, which every writer walks), its worked calculation |
//! | 5 | formats | documents (scene files), the document library, glref cases |
//! | 6 | specialise | the plan's stage list run over arrays |
//! | 7 | raster | the CPU renderer and the shaded view's setup |
//! | 8 | teach, study | exercises, quiz, shaders; the cost of accuracy |
//! | 9 | export | the student's own code, and back |
//!
//! The crate's root re-exports every module for users; inside the crate no path goes
//! through it, but for the locale's `t!` macro (exported at the root, as every
//! `macro_rules!` macro is) and the unit tests' shared helpers (`test_support`).
//!
//! Code written for one processor's vector units (`#[target_feature]` functions, the
//! `std::arch` intrinsics, inline assembly) lives in the `copies` modules, apart from the
//! scalar code a student reads, as glam keeps its `sse2/` apart.

use std::path::{Path, PathBuf};

use crate::support::module_graph;

const ORDER: [(&str, u32); 12] = [
    ("locale", 0),
    ("cpu", 0),
    ("numerics", 1),
    ("mesh", 2),
    ("model", 3),
    ("equation", 4),
    ("formats", 5),
    ("specialise", 6),
    ("raster", 7),
    ("teach", 8),
    ("study", 8),
    ("export", 9),
];

fn rank(group: &str) -> Option<u32> {
    ORDER.iter().find(|(g, _)| *g == group).map(|(_, r)| *r)
}

/// The first path segment after each `crate::` in `text` (macros, `crate::t!`, left out),
/// with its line number.
fn crate_paths(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(at) = rest.find("crate::") {
            // `$crate::` is a macro's own path.
            let before = &rest[..at];
            let after = &rest[at + "crate::".len()..];
            let name: String = after.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            let is_macro = after[name.len()..].starts_with('!');
            if !before.ends_with('$') && !before.ends_with(|c: char| c.is_alphanumeric() || c == '_') && !is_macro {
                out.push((n + 1, name));
            }
            rest = after;
        }
    }
    out
}

#[test]
fn every_group_uses_only_the_groups_below_it_and_names_them() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut groups: Vec<String> = std::fs::read_dir(&src)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    groups.sort();
    let mut listed: Vec<&str> = ORDER.iter().map(|(g, _)| *g).collect();
    listed.sort_unstable();
    assert_eq!(groups, listed, "every group has its place in the order (this file's table)");
    let mut wrong = Vec::new();
    let mut checked = 0;
    for group in &groups {
        let own = rank(group).unwrap();
        let mut files = Vec::new();
        module_graph::sources(&src.join(group), &mut files);
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            let shown = file.strip_prefix(&src).unwrap().display().to_string();
            for (line, name) in crate_paths(&text) {
                checked += 1;
                if name == "t" || name == "test_support" {
                    continue;
                }
                match rank(&name) {
                    None => {
                        wrong.push(format!("src/{shown}:{line}: crate::{name} goes through the root: name its group"));
                    }
                    Some(r) if r > own => wrong.push(format!(
                        "src/{shown}:{line}: {group} (rank {own}) uses {name} (rank {r}), a group above it"
                    )),
                    Some(_) => {}
                }
            }
        }
    }
    assert!(checked > 200, "only {checked} paths read");
    assert!(wrong.is_empty(), "{} paths against the order:\n{}", wrong.len(), wrong.join("\n"));
}

#[test]
fn the_check_sees_a_path_through_the_root_and_a_macro_apart() {
    let found =
        crate_paths("use crate::scene::Scene; let x = crate::t!(\"id\"); $crate::locale::tr(x); // crate::model::view");
    assert_eq!(found, vec![(1, "scene".to_string()), (1, "model".to_string())]);
}

/// The lines of `text` that are written for one processor: a `#[target_feature]`, an
/// `std::arch` intrinsic (`_mm…`), inline assembly.
fn processor_specific(text: &str) -> Vec<usize> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| {
            let code = l.split("//").next().unwrap_or("");
            code.contains("target_feature(")
                || code.contains("arch::x86_64")
                || code.contains("_mm")
                || code.contains("asm!")
        })
        .map(|(n, _)| n + 1)
        .collect()
}

#[test]
fn processor_specific_code_lives_in_the_copies_modules() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    module_graph::sources(&src, &mut files);
    let (mut wrong, mut in_copies) = (Vec::new(), 0);
    for file in files {
        let lines = processor_specific(&std::fs::read_to_string(&file).unwrap());
        if file.file_name().is_some_and(|n| n == "copies.rs") {
            in_copies += lines.len();
        } else {
            let shown = file.strip_prefix(&src).unwrap().display().to_string();
            wrong.extend(lines.iter().map(|n| format!("src/{shown}:{n}")));
        }
    }
    // The check reads what it should: the copies do hold such lines.
    assert!(in_copies > 20, "only {in_copies} processor-specific lines in the copies modules");
    assert!(wrong.is_empty(), "processor-specific code outside the copies modules:\n{}", wrong.join("\n"));
}

#[test]
fn the_check_sees_an_intrinsic_and_not_a_comment() {
    let text = "let a = 1;\n#[target_feature(enable = \"avx2\")]\nlet v = _mm256_setzero_ps();\n// _mm512 in a comment";
    assert_eq!(processor_specific(text), vec![2, 3]);
}

fn core_src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// No file names a file that names it back, however far round: within a group too (the
/// renderer's stages never call back into their SIMD copies; the copies and the driver
/// name the stages).
#[test]
fn no_file_names_a_file_that_names_it_back() {
    let g = module_graph::graph(&core_src());
    assert!(g.len() > 60, "only {} files read", g.len());
    let found = module_graph::file_circles(&core_src(), &g);
    assert!(found.is_empty(), "circles between files:\n{}", found.join("\n"));
}

/// In each folder, no two of its rooms (its files, its subfolders taken whole) name each
/// other: the groups at the top (which `every_group_uses_only_the_groups_below_it` orders),
/// the renderer's stages and its resolve folder inside `raster/render`.
#[test]
fn no_two_rooms_of_a_folder_name_each_other() {
    let found = module_graph::room_circles(&core_src(), &module_graph::graph(&core_src()));
    assert!(found.is_empty(), "circles between the rooms of a folder:\n{}", found.join("\n"));
}

/// The graph sees a circle where there is one: the renderer's driver and its copies name
/// each other's files in a made-up crate.
#[test]
fn the_circle_check_sees_a_circle() {
    let dir = std::env::temp_dir().join(format!("phonglab-layers-{}", std::process::id()));
    let render = dir.join("raster/render");
    std::fs::create_dir_all(&render).unwrap();
    std::fs::write(dir.join("lib.rs"), "pub mod raster;\n").unwrap();
    std::fs::write(dir.join("raster/mod.rs"), "pub mod render;\n").unwrap();
    std::fs::write(render.join("mod.rs"), "mod copies;\nmod resolve;\n").unwrap();
    std::fs::write(render.join("resolve.rs"), "use super::copies::differ8;\n").unwrap();
    std::fs::write(render.join("copies.rs"), "fn f() { super::resolve::run(); }\n").unwrap();
    let graph = module_graph::graph(&dir);
    let (files, rooms) = (module_graph::file_circles(&dir, &graph), module_graph::room_circles(&dir, &graph));
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(files.len(), 1, "{files:?}");
    assert!(files[0].contains("copies.rs") && files[0].contains("resolve.rs"), "{files:?}");
    assert_eq!(rooms, ["in raster/render: resolve.rs -> copies.rs"], "{rooms:?}");
}
