//! The app's integration tests, all in one test binary: each file here is a module, so
//! egui, wgpu and krilla are linked once instead of once a file (41 binaries of about
//! 100 MB each before). One file's tests:
//! `cargo test --test all ui_student::`; one test: `cargo test --test all ui_student::name`.
//!
//! `tests/memory.rs` stays a binary of its own: it counts every byte the process allocates
//! (its own global allocator), which other tests running beside it would disturb.
//!
//! The tests of all files share one process and run on parallel threads: a test changes
//! nothing process-wide (the language is set per thread, `locale::with_locale`), and each
//! file's scratch folders have names of their own (`phonglab-share-PID`, ...).

mod common;

mod check;
mod cli;
mod cli_errors;
mod cli_help;
mod diagnose;
mod director;
mod escaping;
mod exam_sheets;
mod exercise_recheck;
mod export;
mod gl_fields;
mod i18n;
mod layers;
mod misconceptions;
mod moodle;
mod moodle_checks;
mod notebook;
mod nothing_lost;
mod openframeworks;
mod phong_demo_vs_mesa;
mod probe;
mod pyopengl_edits;
mod pyopengl_general;
mod pyopengl_mesa;
mod render_vs_mesa;
mod safe_to_share;
mod scenes;
mod set_links;
mod set_records;
mod shader;
mod shader_gpu;
mod shader_mesa;
mod share;
mod sheet_margins;
mod things_to_try;
mod ui;
mod ui_classroom;
mod ui_gpu;
mod ui_layout;
mod ui_overlap;
mod ui_pictures;
mod ui_probe;
mod ui_quiz_picture;
mod ui_random;
mod ui_student;
mod ui_student_verdicts;
mod ui_typing;
mod vocabulary;
mod windows_names;
mod work_outputs;
