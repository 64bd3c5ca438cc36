//! The panels: each draws one part of the window from what it is given, and gives back
//! what it changed (an edited document, a message, an action for the shell).

pub mod calculation;
pub mod chooser;
pub mod compare;
pub mod controls;
pub mod cost;
pub mod director;
pub mod export;
pub mod files;
pub mod help;
pub mod lobe;
pub mod quiz;
pub mod quiz_picture;
pub mod result;
pub mod shaded;
pub mod shader_panel;
pub mod share;
pub mod student_column;
pub mod student_picture;
pub mod things_to_try;
pub mod vector_plot;
