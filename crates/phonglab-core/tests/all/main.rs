//! The core's integration tests, all in one test binary: each file here is a module, built
//! and linked once instead of once a file. One file's tests:
//! `cargo test -p phonglab-core --test all diagnose::`.
//!
//! The tests of all files share one process and run on parallel threads: a test changes
//! nothing process-wide.

mod common;
/// What the layer tests share with the app's (`tests/all/layers.rs` there).
mod support {
    pub mod module_graph;
}

mod check;
mod check_whole;
mod cost;
mod diagnose;
mod diagnose_cause;
mod diagnose_measured;
mod documents;
mod exam;
mod exercises;
mod hard_cases;
mod layers;
mod llvmpipe_pow;
mod mesa_ordinary;
mod meshes;
mod normalised_blinn_phong;
mod properties;
mod reference_renderer;
mod specialised;
mod worksheet;
