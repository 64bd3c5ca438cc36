//! Text in and out: TOML scene files, the glref harness's JSON cases, and user text
//! escaped for every language phonglab writes.

pub mod document;
pub mod escape;
pub mod glref;
pub mod library;
