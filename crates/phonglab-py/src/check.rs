//! `phonglab.check(globals())`: a notebook's work checked in the notebook itself, step by
//! step as `phonglab check` checks a saved one, and the table it prints (the words of
//! `phonglab check`, in the language asked).
//!
//! The package reads the values from the notebook's variables itself (their numbers, as
//! NumPy prints them with its default options, one value a name): only the names this
//! scene's key has ([`steps`]) are read, so nothing else the notebook holds is counted.

use phonglab_core::Scene;
use phonglab_core::export::read_python;
use phonglab_core::study::check::check;
use phonglab_core::study::check::printed::read_printed_text;
use phonglab_core::study::check::said::words;
use phonglab_core::study::check::worked::work;

/// The scene the cells' `code` types (its givens; nothing is run), or why it cannot be
/// checked (not worksheet-style, a given changed in place or not finite).
fn own_scene(code: &str) -> Result<Scene, String> {
    let imported = read_python::read(code, false, "notebook").map_err(|e| e.to_string())?;
    if let Some(why) = imported.not_checkable() {
        return Err(why);
    }
    Ok(imported.doc.scene)
}

/// The names the key of the work whose code is `code` prints, in the order it prints them
/// (`vlv`, or `vlv[0]` for a light of several; `IBack` for the back side).
pub fn steps(code: &str) -> Result<Vec<String>, String> {
    let own = own_scene(code)?;
    Ok(work(&own, None, None).values.into_iter().map(|(name, _)| name).collect())
}

/// Checks the work whose code is `code` (the cells run, in order: the givens are read from
/// it, nothing is run) and whose values are `printed` (`name = value` lines): the table
/// and whether every step is right. `missing` names the key's steps the notebook holds no
/// value for (a cell skipped): then it is "not checked", never right.
pub fn check_work(code: &str, printed: &str, missing: Vec<String>) -> Result<(String, bool), String> {
    let own = own_scene(code)?;
    let mut student = read_printed_text(printed).map_err(|e| e.to_string())?;
    student.code = code.to_string();
    student.missing = missing;
    let c = check(&own, &own, &student);
    Ok((words(&c), c.right()))
}
