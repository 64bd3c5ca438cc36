//! Text in and out: TOML scene files, the glref harness's JSON cases, user text escaped
//! for every language phonglab writes, and the files that hold them (read capped, written
//! whole).

pub mod document;
pub mod escape;
pub mod explain_html;
pub mod files;
pub mod gift;
pub mod glref;
pub mod library;
pub mod moodle_xml;
pub mod question;
