//! Files a person names, read and written the one way phonglab has (the command line, the
//! window and the Python package alike): read under a cap and without blocking
//! ([`read`]), written whole or not at all ([`atomic_write`]), never over one of the inputs
//! ([`same_file`]), with the system's reasons in words ([`reasons`]) and what differs between
//! operating systems ([`os`]), and phonglab's records made and trusted as this user's alone
//! ([`private`]).

pub mod atomic_write;
pub mod os;
pub mod private;
pub mod read;
pub mod reasons;
pub mod same_file;
