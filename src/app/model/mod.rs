//! What the panels show and the shell keeps: the document evaluated in the chosen
//! precision ([`evaluated`]), its undo history ([`history`]), the window's message
//! ([`message`]).

pub mod evaluated;
pub mod history;
pub mod message;
