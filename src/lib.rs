//! The phonglab app and CLI, as a library so tests drive them headless.

pub mod app;
pub mod atomic_write;
pub mod bench;
pub mod budget;
pub mod cli;
pub mod cli_help;
pub mod cost_cmd;
pub mod egui_cpu;
pub mod exercise_cmd;
pub mod export_cmd;
pub mod gpu;
pub mod image_io;
pub mod input_file;
pub mod io_text;
pub mod platform;
pub mod same_file;
pub mod scenes;
pub mod screenshot_cmd;
pub mod sheet_pdf;
#[cfg(target_arch = "wasm32")]
pub mod web;
pub mod zip_store;
