//! An output never overwrites an input: every command that writes a file checks, before it
//! reads or writes anything, that none of its outputs is one of its inputs.
//!
//! "The same file" is decided by the file itself, not by its name: two paths name one file
//! when they lead to the same device and inode (Unix), or the same volume serial number and
//! file index (Windows), so a hard link, a symbolic link, a `./` or a `..` in the path are
//! all seen through. An output that does not exist yet is no input. Where the system has
//! neither (the browser has no paths at all), the canonical paths are compared.

use std::path::{Path, PathBuf};

use crate::t;

/// What makes a file itself: its device and inode, or its canonical path; for a file
/// that is not there yet, its folder's canonical path and its name (two outputs may be
/// one file before either is written).
#[derive(Debug, PartialEq, Eq)]
enum FileId {
    #[cfg(unix)]
    Inode(u64, u64),
    /// Windows: the file opened, compared by its volume's serial number and its file index
    /// (the `same-file` crate), which a hard link shares and a link's target gives.
    #[cfg(windows)]
    Handle(same_file::Handle),
    #[cfg_attr(any(unix, windows), allow(dead_code))]
    Canonical(PathBuf),
    Named(PathBuf, std::ffi::OsString),
}

/// The identity of the file `path` leads to (following symbolic links), if it exists.
fn file_id(path: &Path) -> Option<FileId> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let m = std::fs::metadata(path).ok()?;
        Some(FileId::Inode(m.dev(), m.ino()))
    }
    #[cfg(windows)]
    {
        same_file::Handle::from_path(path).ok().map(FileId::Handle)
    }
    #[cfg(not(any(unix, windows)))]
    {
        std::fs::canonicalize(path).ok().map(FileId::Canonical)
    }
}

/// The identity of the file an output at `path` will be: the file there, or, where none
/// is yet, the place it will be made (through a link, the place the link names).
fn output_id(path: &Path) -> Option<FileId> {
    if let Some(id) = file_id(path) {
        return Some(id);
    }
    let target = crate::formats::files::atomic_write::through_links(path).ok()?;
    let folder = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    Some(FileId::Named(std::fs::canonicalize(folder).ok()?, name_on_disk(target.file_name()?)))
}

/// A file name as the disk tells names apart: Windows and macOS (case-insensitive by
/// default) take `r.md` and `R.MD` for one file, so the name is compared in lower case
/// there; elsewhere as it is.
fn name_on_disk(name: &std::ffi::OsStr) -> std::ffi::OsString {
    match name.to_str() {
        Some(s) if CASE_INSENSITIVE => s.to_lowercase().into(),
        _ => name.to_os_string(),
    }
}

/// Does the system's disk (by default) take names that differ only in case for one file?
const CASE_INSENSITIVE: bool = cfg!(any(windows, target_os = "macos"));

/// What an input is, for the message that refuses an output onto it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// A file the command reads, without a more particular name.
    Any,
    /// A scene file.
    Scene,
    /// A mesh (OBJ) that a scene or `--obj` names.
    Mesh,
    /// A notebook or Python script.
    Code,
    /// A case file (glref JSON).
    Cases,
}

impl Input {
    /// "the scene", "the mesh"... in the current language.
    fn words(self) -> String {
        match self {
            Input::Any => t!("input-kind-input"),
            Input::Scene => t!("input-kind-scene"),
            Input::Mesh => t!("input-kind-mesh"),
            Input::Code => t!("input-kind-code"),
            Input::Cases => t!("input-kind-cases"),
        }
    }
}

/// Refuses when an output in `outputs` is the same file as an input in `inputs`, naming
/// both (in the current language). Paths that do not exist are never the same file.
pub fn refuse_output_onto_input(outputs: &[&Path], inputs: &[&Path]) -> Result<(), String> {
    let inputs: Vec<(&Path, Input)> = inputs.iter().map(|p| (*p, Input::Any)).collect();
    refuse_onto(outputs, &inputs)
}

/// Refuses when an output in `outputs` is the same file as an input in `inputs` (each
/// said as what it is: "the mesh"), or as another of the outputs ("the other output"),
/// or has a name Windows cannot keep
/// ([`refuse_unkept_name`](crate::formats::files::atomic_write::refuse_unkept_name): `rep.md.` beside `rep.md`
/// is one file there).
pub fn refuse_onto(outputs: &[&Path], inputs: &[(&Path, Input)]) -> Result<(), String> {
    use crate::formats::files::reasons::shown;
    for output in outputs {
        crate::formats::files::atomic_write::refuse_unkept_name(output)
            .map_err(|why| format!("{}: {why}", shown(output)))?;
    }
    for (k, output) in outputs.iter().enumerate() {
        let out_id = file_id(output);
        for (input, kind) in inputs {
            if out_id.is_some() && file_id(input) == out_id {
                return Err(t!(
                    "err-output-is-input",
                    output = shown(output),
                    what = kind.words(),
                    input = shown(input)
                ));
            }
        }
        let Some(id) = output_id(output) else { continue };
        if let Some(other) = outputs[..k].iter().find(|o| output_id(o).as_ref() == Some(&id)) {
            return Err(t!("err-output-is-other-output", output = shown(output), other = shown(other)));
        }
    }
    Ok(())
}

/// [`refuse_output_onto_input`] for the files a command writes into the folder `dir`
/// (`names`, without folders).
pub fn refuse_outputs_in_folder(dir: &Path, names: &[&str], inputs: &[(&Path, Input)]) -> Result<(), String> {
    let outputs: Vec<PathBuf> = names.iter().map(|n| dir.join(n)).collect();
    let outputs: Vec<&Path> = outputs.iter().map(PathBuf::as_path).collect();
    refuse_onto(&outputs, inputs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hard link is the same file under another name (on Windows: the same volume serial
    /// number and file index), in a folder with an accent and a space as on a student's PC.
    #[test]
    fn an_output_onto_a_hard_link_of_an_input_is_refused() {
        let dir =
            std::env::temp_dir().join(format!("phonglab-same-file {}", std::process::id())).join("Exercícios de CG");
        std::fs::create_dir_all(&dir).unwrap();
        let scene = dir.join("cena da aula.toml");
        std::fs::write(&scene, "name = \"x\"\n").unwrap();
        let link = dir.join("outra cena.toml");
        let _ = std::fs::remove_file(&link);
        std::fs::hard_link(&scene, &link).unwrap();
        let e = refuse_output_onto_input(&[&link], &[&scene]).unwrap_err();
        assert!(e.contains("outra cena.toml") && e.contains("cena da aula.toml"), "{e}");
        // Through `..` and `.` in the path, too.
        let roundabout = dir.join("..").join("Exercícios de CG").join(".").join("cena da aula.toml");
        assert!(refuse_output_onto_input(&[&roundabout], &[&scene]).is_err());
        // A copy is another file; a file not there yet is no input.
        let copy = dir.join("cópia.toml");
        std::fs::copy(&scene, &copy).unwrap();
        assert_eq!(refuse_output_onto_input(&[&copy], &[&scene]), Ok(()));
        assert_eq!(refuse_output_onto_input(&[&dir.join("nova.png")], &[&scene]), Ok(()));
        // Two outputs that will be one file.
        let again = dir.join(".").join("nova.png");
        assert!(refuse_onto(&[&dir.join("nova.png"), &again], &[]).is_err());
        std::fs::remove_dir_all(dir.parent().unwrap()).unwrap();
    }

    /// Issue 59 F6: on Windows (and macOS) a report `r.md` and marks `R.MD`, neither there
    /// yet, are one file: refused as the other output (before, the marks were written over
    /// the report); on Linux they are two files.
    #[test]
    fn two_outputs_differing_only_in_case_are_one_file_where_the_disk_ignores_case() {
        let dir = std::env::temp_dir().join(format!("phonglab-same-case {}", std::process::id())).join("Relatório");
        std::fs::create_dir_all(&dir).unwrap();
        let (report, marks) = (dir.join("relatório.md"), dir.join("RELATÓRIO.MD"));
        let e = refuse_onto(&[&report, &marks], &[]);
        if CASE_INSENSITIVE {
            let e = e.unwrap_err();
            assert!(e.contains("the other output") && e.contains(".MD"), "{e}");
        } else {
            assert_eq!(e, Ok(()));
        }
        assert_eq!(refuse_onto(&[&report, &dir.join("relatório.csv")], &[]), Ok(()), "two names, two files");
        std::fs::remove_dir_all(dir.parent().unwrap()).unwrap();
    }

    /// Issue 59, #40, #49, #50, #53: names Windows cannot keep (a device's, a dot or a
    /// space at the end) are refused as outputs on every system, before anything is
    /// written; `rep.md.` beside `rep.md` was one file on Windows, written twice.
    #[test]
    fn names_windows_cannot_keep_are_refused_as_outputs_everywhere() {
        use crate::formats::files::atomic_write::{Unkept, refuse_unkept_name, unkept_name};
        use std::ffi::OsStr;
        for device in ["CON", "nul", "Aux", "prn", "COM1", "lpt9", "con.png", "NUL.txt", "con .txt", "com¹"] {
            assert_eq!(unkept_name(OsStr::new(device)), Some(Unkept::Device), "{device}");
        }
        for end in ["rep.md.", "set ", "a. ", "x..."] {
            assert_eq!(unkept_name(OsStr::new(end)), Some(Unkept::DroppedEnd), "{end}");
        }
        // Issue 59, finding 6: an alternate data stream (`out.png:x`) and the characters
        // Windows refuses.
        for (name, c) in [("out.png:x", ':'), ("a?.png", '?'), ("*.md", '*'), ("a<b", '<'), ("a>b", '>')] {
            assert_eq!(unkept_name(OsStr::new(name)), Some(Unkept::Char(c)), "{name}");
        }
        for (name, c) in [("a|b", '|'), ("say \"hi\".md", '"')] {
            assert_eq!(unkept_name(OsStr::new(name)), Some(Unkept::Char(c)), "{name}");
        }
        for fine in ["console.png", "nully.txt", "com10", "lpt", "aux_files", ".", "..", "con-sheet.md", ".hidden"] {
            assert_eq!(unkept_name(OsStr::new(fine)), None, "{fine}");
        }
        let dir = std::env::temp_dir().join(format!("phonglab-unkept {}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (report, marks) = (dir.join("rep.md"), dir.join("rep.md."));
        let e = refuse_onto(&[&report, &marks], &[]).unwrap_err();
        assert!(e.contains("rep.md.") && e.contains("Windows drops") && e.contains("rep.md"), "{e}");
        let e = refuse_onto(&[&dir.join("out.png:x")], &[]).unwrap_err();
        assert!(e.contains("out.png:x holds “:”, which Windows does not allow in a file name"), "{e}");
        let e = refuse_onto(&[&dir.join("con.png")], &[]).unwrap_err();
        assert!(e.contains("con.png") && e.contains("a name Windows keeps for a device; choose another"), "{e}");
        // A folder phonglab would make, not one that is there (a Linux folder named aux).
        let e = refuse_unkept_name(&dir.join("set ").join("a.md")).unwrap_err();
        assert!(e.contains("set "), "{e}");
        // (Windows cannot make one: `aux` opens the device.)
        if !cfg!(windows) {
            std::fs::create_dir_all(dir.join("aux")).unwrap();
            assert_eq!(refuse_unkept_name(&dir.join("aux").join("a.md")), Ok(()), "a folder already there");
        }
        assert_eq!(refuse_onto(&[&report, &dir.join("rep.csv")], &[]), Ok(()));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
