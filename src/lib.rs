//! The phonglab app and command line, as a library so tests drive them headless.
//!
//! The crate is in layers; each names only the layers below it, and `tests/all/layers.rs`
//! fails on a path against the order (ARCHITECTURE.md says what each holds):
//!
//! | layer | modules | what it is |
//! |---|---|---|
//! | 2 | [`cli`], [`app`] | the command line and the window: neither names the other (the binary, `main.rs`, joins them) |
//! | 1 | [`io`], [`paint`], [`platform`] | files in and out; pictures painted on the CPU or the GPU; what differs between the desktop and the browser |
//! | 0 | `phonglab_core` | the lighting, the renderer, the formats |

pub mod app;
pub mod cli;
pub mod io;
pub mod locale;
pub mod paint;
pub mod platform;
