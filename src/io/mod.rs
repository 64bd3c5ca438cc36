//! Files in and out, the same for the command line and the window: every file is written
//! whole or not at all ([`atomic_write`]), read under a cap and without blocking
//! ([`input_file`]), never over one of the inputs ([`same_file`]), within the memory budget
//! ([`budget`]), never through a link nor over a file phonglab did not write where it reads
//! students' work ([`work_output`]); PNG pictures ([`image`]), zip archives ([`zip`]), typeset PDF sheets
//! ([`sheet_pdf`]), what a screenshot opens ([`screenshot`]), the shipped scenes ([`scenes`]) and the system's reasons for a failure
//! in words ([`reasons`]).

pub mod atomic_write;
pub mod budget;
pub mod exam_key;
pub mod exercise_set;
pub mod experiments;
pub mod file_set;
pub mod image;
pub mod input_file;
pub mod listing;
pub mod misconception_set;
pub mod moodle_checks;
pub mod moodle_set;
pub mod qr;
pub mod reasons;
pub mod same_file;
pub mod save;
pub mod scenes;
pub mod screenshot;
pub mod set_journal;
pub mod sheet_pdf;
pub mod student_code;
pub mod student_png;
pub mod work_output;
pub mod zip;
