//! `phonglab.check(globals())`: a notebook's work checked in the notebook itself, step by
//! step as `phonglab check` checks a saved one, and the table it prints (the words of
//! `phonglab check`, in the language asked).

use phonglab_core::export::read_python;
use phonglab_core::study::check::check;
use phonglab_core::study::check::printed::read_printed_text;
use phonglab_core::study::check::said::words;

/// Checks the work whose code is `code` (the cells run, in order: the givens are read from
/// it, nothing is run) and whose values are `printed` (`name = value` lines): the table
/// and whether every step is right.
pub fn check_work(code: &str, printed: &str) -> Result<(String, bool), String> {
    let imported = read_python::read(code, false, "notebook").map_err(|e| e.to_string())?;
    if let Some(why) = imported.not_checkable() {
        return Err(why);
    }
    let mut student = read_printed_text(printed).map_err(|e| e.to_string())?;
    student.code = code.to_string();
    let own = imported.doc.scene;
    let c = check(&own, &own, &student);
    Ok((words(&c), c.right()))
}
