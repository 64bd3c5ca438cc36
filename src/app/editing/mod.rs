//! What the panels show and the shell keeps: the document evaluated in the chosen
//! precision ([`evaluated`]), its undo history ([`history`], each step said by [`change`]), the window's message
//! ([`message`]), the three borrowed together for an edit ([`editor`]), and work in
//! the background ([`worker`]).

pub mod change;
pub mod editor;
pub mod evaluated;
pub mod history;
pub mod message;
pub mod worker;
