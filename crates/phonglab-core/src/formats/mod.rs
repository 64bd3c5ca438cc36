//! Text in and out: TOML scene files and the glref harness's JSON cases.

pub mod document;
pub mod glref;
pub mod library;
