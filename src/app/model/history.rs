//! Undo and redo of every change to the scene: each step keeps the whole document before
//! it (a document is a few kilobytes; 200 steps are well under a megabyte) and a label of
//! what it changed ("shininess 25.6 ➡ 100"), read from the two documents' scene files.
//! A drag is one step: a change of the same fields as the last step, made within a second
//! of it, joins it.

use phonglab_core::Document;
use phonglab_core::explain::fmt_sig;

/// How many steps are kept.
pub const DEPTH: usize = 200;

/// Changes of the same fields closer than this (seconds) are one step.
const JOIN_WITHIN: f64 = 1.0;

/// One step: the document on the other side of it, and what it changes.
#[derive(Clone, Debug, PartialEq)]
struct Entry {
    doc: Document,
    label: String,
    /// The fields it changed (to join a drag's steps).
    fields: Vec<String>,
    /// When it was made (seconds, egui's clock).
    at: f64,
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
        let (fields, label) = match what {
            Some(w) => (Vec::new(), w.to_string()),
            None => describe(before, after),
        };
        self.redo.clear();
        if let Some(last) = self.undo.last_mut()
            && what.is_none()
            && !fields.is_empty()
            && last.fields == fields
            && now - last.at < JOIN_WITHIN
        {
            // The same fields again (a drag): one step, from the first value to this one.
            last.at = now;
            last.label = join_labels(&last.label, &label);
            return;
        }
        self.undo.push(Entry { doc: before.clone(), label, fields, at: now });
        if self.undo.len() > DEPTH {
            self.undo.remove(0);
        }
    }

    /// Undoes the last step: the document to show, and what was undone.
    pub fn undo(&mut self, current: &Document) -> Option<(Document, String)> {
        let e = self.undo.pop()?;
        self.redo.push(Entry { doc: current.clone(), ..e.clone() });
        Some((e.doc, e.label))
    }

    /// Redoes the last undone step.
    pub fn redo(&mut self, current: &Document) -> Option<(Document, String)> {
        let e = self.redo.pop()?;
        self.undo.push(Entry { doc: current.clone(), ..e.clone() });
        Some((e.doc, e.label))
    }

    /// What Undo would undo.
    pub fn undo_label(&self) -> Option<&str> {
        self.undo.last().map(|e| e.label.as_str())
    }

    /// What Redo would redo.
    pub fn redo_label(&self) -> Option<&str> {
        self.redo.last().map(|e| e.label.as_str())
    }

    /// How many steps can be undone.
    pub fn depth(&self) -> usize {
        self.undo.len()
    }
}

/// "a 1 ➡ 2" then "a 2 ➡ 3" is "a 1 ➡ 3".
fn join_labels(first: &str, then: &str) -> String {
    match (first.rsplit_once(" ➡ "), then.rsplit_once(" ➡ ")) {
        (Some((from, _)), Some((_, to))) => format!("{from} ➡ {to}"),
        _ => then.to_string(),
    }
}

/// The fields that differ between two documents, as their scene files name them
/// (`material.shininess`, `lights.0.position`), and a label: one field with its two values,
/// or the first field and how many more.
pub fn describe(before: &Document, after: &Document) -> (Vec<String>, String) {
    let (mut a, mut b) = (leaves(before), leaves(after));
    // A change of preset says so alone; a preset edited into a custom material says which
    // field was edited (the preset's name going is not the change).
    let preset = |l: &[(String, String)]| l.iter().find(|(k, _)| k == "material.preset").map(|(_, v)| v.clone());
    let (pa, pb) = (preset(&a), preset(&b));
    if pa != pb && pa.as_deref() != Some("custom") && pb.as_deref() != Some("custom") {
        a.retain(|(k, _)| !k.starts_with("material.") || k == "material.preset");
        b.retain(|(k, _)| !k.starts_with("material.") || k == "material.preset");
    } else {
        a.retain(|(k, _)| k != "material.preset");
        b.retain(|(k, _)| k != "material.preset");
    }
    // Every field of either, once, in the order the scene files give them.
    let mut seen = std::collections::HashSet::new();
    let keys: Vec<&String> = a.iter().chain(&b).map(|(k, _)| k).filter(|k| seen.insert(*k)).collect();
    let find = |list: &[(String, String)], k: &str| list.iter().find(|(x, _)| x == k).map(|(_, v)| v.clone());
    let changed: Vec<(String, Option<String>, Option<String>)> =
        keys.into_iter().map(|k| (k.clone(), find(&a, k), find(&b, k))).filter(|(_, x, y)| x != y).collect();
    let fields: Vec<String> = changed.iter().map(|(k, ..)| k.clone()).collect();
    let label = match changed.as_slice() {
        [] => "no change".to_string(),
        [(k, x, y)] => {
            let none = || "(none)".to_string();
            format!("{} {} ➡ {}", readable(k), x.clone().unwrap_or_else(none), y.clone().unwrap_or_else(none))
        }
        [(k, ..), rest @ ..] => format!("{} and {} more", readable(k), rest.len()),
    };
    (fields, label)
}

/// Every field of `d` as (dotted path, value text): its scene file's, with the material's
/// own values in place of a preset's name (and the preset, or "custom", as
/// `material.preset`).
fn leaves(d: &Document) -> Vec<(String, String)> {
    let mut out = Vec::new();
    if let Some(mut t) = d.to_toml().ok().and_then(|t| t.parse::<toml::Table>().ok()) {
        t.remove("material");
        flatten("", &toml::Value::Table(t), &mut out);
    }
    let m = &d.scene.material;
    let rgba = |c: glam::DVec4| format!("[{}]", c.to_array().map(|x| fmt_sig(x, 6)).join(" "));
    out.push(("material.preset".into(), phonglab_core::materials::name_of(m).unwrap_or("custom").into()));
    out.push(("material.ambient".into(), rgba(m.ambient)));
    out.push(("material.diffuse".into(), rgba(m.diffuse)));
    out.push(("material.specular".into(), rgba(m.specular)));
    out.push(("material.emission".into(), rgba(m.emission)));
    out.push(("material.shininess".into(), fmt_sig(m.shininess, 6)));
    out
}

/// `lights.0.spot_cutoff` as "light 0 spot cutoff"; `material.shininess` as "shininess".
fn readable(key: &str) -> String {
    let key = key.strip_prefix("material.").unwrap_or(key);
    key.replace("lights.", "light ").replace(['.', '_'], " ")
}

/// Every leaf of `v` as (dotted path, value text); arrays of numbers are one leaf.
fn flatten(path: &str, v: &toml::Value, out: &mut Vec<(String, String)>) {
    let join = |k: &str| if path.is_empty() { k.to_string() } else { format!("{path}.{k}") };
    match v {
        toml::Value::Table(t) => t.iter().for_each(|(k, v)| flatten(&join(k), v, out)),
        toml::Value::Array(items) if items.iter().any(|i| i.is_table()) => {
            items.iter().enumerate().for_each(|(i, v)| flatten(&join(&i.to_string()), v, out));
        }
        toml::Value::Array(items) => {
            let parts: Vec<String> = items.iter().map(value_text).collect();
            out.push((path.to_string(), format!("[{}]", parts.join(" "))));
        }
        other => out.push((path.to_string(), value_text(other))),
    }
}

fn value_text(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(x) => fmt_sig(*x, 6),
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::String(s) => s.clone(),
        toml::Value::Boolean(b) => if *b { "on" } else { "off" }.to_string(),
        toml::Value::Array(items) => format!("[{}]", items.iter().map(value_text).collect::<Vec<_>>().join(" ")),
        other => other.to_string(),
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
    fn a_step_is_labelled_with_its_field_and_values() {
        let (fields, label) = describe(&with_shininess(25.6), &with_shininess(100.0));
        assert_eq!(fields, ["material.shininess"]);
        assert_eq!(label, "shininess 25.6 ➡ 100");
        let mut d = Document::default();
        d.scene.lights[0].position.z = 300.0;
        let (_, label) = describe(&Document::default(), &d);
        assert!(label.starts_with("light 0 position [") && label.ends_with("300 1]"), "{label}");
        // A preset chosen is named; a preset edited names the field.
        let mut gold = Document::default();
        gold.scene.material = phonglab_core::materials::by_name("gold").unwrap().clone();
        assert_eq!(describe(&Document::default(), &gold).1, "preset bronze ➡ gold");
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
        assert_eq!(h.undo_label(), Some("shininess 25.6 ➡ 100"));
        // A typed change two seconds later is its own step.
        let d5 = with_shininess(5.0);
        h.record(&docs[3], &d5, None, 2.6);
        assert_eq!(h.depth(), 2);
        let (back, label) = h.undo(&d5).unwrap();
        assert_eq!((back.scene.material.shininess, label.as_str()), (100.0, "shininess 100 ➡ 5"));
        let (back, _) = h.undo(&back).unwrap();
        assert_eq!(back.scene.material.shininess, 25.6);
        assert!(h.undo(&back).is_none());
        let (fwd, _) = h.redo(&back).unwrap();
        assert_eq!(fwd.scene.material.shininess, 100.0);
        assert_eq!(h.redo_label(), Some("shininess 100 ➡ 5"));
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
            d = h.undo(&d).unwrap().0;
        }
        assert_eq!(d.scene.material.shininess, 25.0, "the oldest kept step");
    }
}
