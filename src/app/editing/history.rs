//! Undo and redo of every change to the scene: each step keeps the whole document on both
//! sides of it (a document is a few kilobytes; 200 steps are about a megabyte), so it can
//! say what it changes ("Material shininess 25.6 ➡ 100", "light 0 removed": [`super::change`])
//! in the window's language of the moment. A drag is one step: a change of the same fields
//! as the last step, made within a second of it, joins it.

use phonglab_core::Document;

use super::change;

/// How many steps are kept.
pub const DEPTH: usize = 200;

/// Changes of the same fields closer than this (seconds) are one step.
const JOIN_WITHIN: f64 = 1.0;

/// One step: the documents on both sides of it, and what it changes.
#[derive(Clone, Debug, PartialEq)]
struct Entry {
    before: Document,
    after: Document,
    /// What the step was when it is not a change of fields (opening a file, a reset).
    said: Option<String>,
    /// The fields it changed (to join a drag's steps).
    fields: Vec<String>,
    /// When it was made (seconds, egui's clock).
    at: f64,
}

impl Entry {
    /// What the step changes, in the current language.
    fn label(&self) -> String {
        self.said.clone().unwrap_or_else(|| change::label(&self.before, &self.after))
    }
}

/// The undo and redo stacks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History {
    undo: Vec<Entry>,
    redo: Vec<Entry>,
}

impl History {
    /// Records a change from `before` to `after` made at `now`; `what` labels it when it
    /// is not a change of fields (opening a file, a reset), otherwise the fields say.
    pub fn record(&mut self, before: &Document, after: &Document, what: Option<&str>, now: f64) {
        let fields = if what.is_some() { Vec::new() } else { change::changed_fields(before, after) };
        self.redo.clear();
        if let Some(last) = self.undo.last_mut()
            && what.is_none()
            && !fields.is_empty()
            && last.fields == fields
            && now - last.at < JOIN_WITHIN
        {
            // The same fields again (a drag): one step, from the first value to this one.
            last.at = now;
            last.after = after.clone();
            return;
        }
        let said = what.map(str::to_string);
        self.undo.push(Entry { before: before.clone(), after: after.clone(), said, fields, at: now });
        if self.undo.len() > DEPTH {
            self.undo.remove(0);
        }
    }

    /// Undoes the last step: the document to show, and what was undone.
    pub fn undo(&mut self) -> Option<(Document, String)> {
        let e = self.undo.pop()?;
        let said = (e.before.clone(), e.label());
        self.redo.push(e);
        Some(said)
    }

    /// Redoes the last undone step.
    pub fn redo(&mut self) -> Option<(Document, String)> {
        let e = self.redo.pop()?;
        let said = (e.after.clone(), e.label());
        self.undo.push(e);
        Some(said)
    }

    /// What Undo would undo.
    pub fn undo_label(&self) -> Option<String> {
        self.undo.last().map(Entry::label)
    }

    /// What Redo would redo.
    pub fn redo_label(&self) -> Option<String> {
        self.redo.last().map(Entry::label)
    }

    /// How many steps can be undone.
    pub fn depth(&self) -> usize {
        self.undo.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn with_shininess(s: f64) -> Document {
        let mut d = Document::default();
        d.scene.material.shininess = s;
        d
    }

    #[test]
    fn undo_and_redo_walk_the_steps_and_a_drag_is_one_step() {
        let mut h = History::default();
        let docs: Vec<Document> = [25.6, 30.0, 40.0, 100.0].into_iter().map(with_shininess).collect();
        // A drag: three changes of the shininess within a second.
        h.record(&docs[0], &docs[1], None, 0.0);
        h.record(&docs[1], &docs[2], None, 0.3);
        h.record(&docs[2], &docs[3], None, 0.6);
        assert_eq!(h.depth(), 1);
        assert_eq!(h.undo_label().as_deref(), Some("Material shininess 25.6 ➡ 100"));
        // A typed change two seconds later is its own step.
        let d5 = with_shininess(5.0);
        h.record(&docs[3], &d5, None, 2.6);
        assert_eq!(h.depth(), 2);
        let (back, label) = h.undo().unwrap();
        assert_eq!((back.scene.material.shininess, label.as_str()), (100.0, "Material shininess 100 ➡ 5"));
        let (back, _) = h.undo().unwrap();
        assert_eq!(back.scene.material.shininess, 25.6);
        assert!(h.undo().is_none());
        let (fwd, _) = h.redo().unwrap();
        assert_eq!(fwd.scene.material.shininess, 100.0);
        assert_eq!(h.redo_label().as_deref(), Some("Material shininess 100 ➡ 5"));
        // A new change forgets what could be redone.
        h.record(&fwd, &with_shininess(7.0), None, 9.0);
        assert_eq!(h.redo_label(), None);
    }

    #[test]
    fn at_least_a_hundred_steps_are_kept() {
        let mut h = History::default();
        for i in 0..(DEPTH + 50) {
            h.record(&with_shininess(i as f64 / 2.0), &with_shininess((i + 1) as f64 / 2.0), None, 10.0 * i as f64);
        }
        assert_eq!(h.depth(), DEPTH);
        let mut d = with_shininess(((DEPTH + 50) as f64) / 2.0);
        for _ in 0..DEPTH {
            d = h.undo().unwrap().0;
        }
        assert_eq!(d.scene.material.shininess, 25.0, "the oldest kept step");
    }
}
