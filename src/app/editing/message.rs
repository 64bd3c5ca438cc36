//! What the window says: the last refusal or notice, shown under the colour.

/// What the last message says.
#[derive(Clone, Debug, PartialEq)]
pub enum Message {
    /// An edit was refused; the scene kept its last valid value.
    Refused(String),
    /// Something worth knowing (a preset chosen, a file loaded).
    Info(String),
}
