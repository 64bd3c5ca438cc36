//! The explorer window, in layers (each names only the ones below it; `tests/all/layers.rs`
//! keeps them):
//!
//! | layer | folder | what it holds |
//! |---|---|---|
//! | 3 | [`shell`] | the frame: the state, the top bar, the keys, the centre's arrangement, the windows, the session, the desktop's and the browser's runners, the screenshot |
//! | 2 | [`panels`] | each panel: it takes what it reads and writes, and gives back what it changes |
//! | 1 | [`widgets`] | number fields, labelled rows, the palette, label placement |
//! | 0 | [`editing`] | what the panels show: the evaluated document, the undo history, the message |

pub mod editing;
pub mod panels;
pub mod shell;
pub mod widgets;

#[cfg(not(target_arch = "wasm32"))]
pub use shell::desktop::run;
pub use shell::frame::app_ui;
pub use shell::state::AppState;
