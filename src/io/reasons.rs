//! The system's reasons for a failed read or write, said in the user's language: the
//! core's ([`phonglab_core::files::reasons`]), shared with the Python package.

pub use phonglab_core::files::reasons::{io_reason, shown};
