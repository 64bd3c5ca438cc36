//! The document as a panel edits it: every edit is a whole candidate document, kept only
//! when it is valid (else refused with a message naming the field and the range, the last
//! valid document kept), and recorded in the undo history. A panel that edits the scene
//! borrows an [`Editor`] over the shell's document, history and message, and so takes
//! nothing else of the app's state.

use phonglab_core::Document;

use super::history::History;
use super::message::Message;

/// The document, its undo history and the window's message, borrowed for an edit.
pub struct Editor<'a> {
    /// The last valid document.
    pub doc: &'a mut Document,
    /// Undo and redo.
    pub history: &'a mut History,
    /// The last refusal or notice.
    pub message: &'a mut Option<Message>,
    /// This frame's time (seconds): a drag's changes within a second are one undo step.
    pub now: f64,
}

impl Editor<'_> {
    /// Keeps `candidate` if it is valid; otherwise refuses it with a message naming the
    /// field and the allowed range, and keeps the last valid document. Returns whether it
    /// was kept.
    pub fn apply(&mut self, candidate: Document) -> bool {
        self.apply_or_why(candidate).is_ok()
    }

    /// [`Self::apply`], with the validator's reason when it refuses.
    pub fn apply_or_why(&mut self, mut candidate: Document) -> Result<(), String> {
        if candidate == *self.doc {
            return Ok(());
        }
        let checked = candidate.camera.matrix().and_then(|m| {
            candidate.scene.eye_from_world = m;
            candidate.validate()
        });
        match checked {
            Ok(()) => {
                let before = std::mem::replace(self.doc, candidate);
                self.history.record(&before, self.doc, None, self.now);
                if matches!(self.message, Some(Message::Refused(_))) {
                    *self.message = None;
                }
                Ok(())
            }
            Err(e) => {
                *self.message = Some(Message::Refused(crate::t!("refused-kept", error = e.to_string())));
                Err(e.to_string())
            }
        }
    }

    /// Says `message` in the window.
    pub fn say(&mut self, message: Message) {
        *self.message = Some(message);
    }
}
