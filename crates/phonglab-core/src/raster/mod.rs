//! The CPU renderer and the shaded view's setup.

pub mod channels;
pub mod probe;
pub mod probe_report;
pub mod reference;
pub mod render;
pub mod shaded;
