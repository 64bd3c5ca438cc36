//! Program templates: each generated program kept whole in a file of its own
//! (`export/templates/`), with named holes that the writer fills.
//!
//! A hole is written `{{name}}` or `{{name:context}}`:
//! - `{{name}}` takes code the writer generates from the scene's numbers (calls, arrays,
//!   a shader), never user text: [`Fill::Code`];
//! - `{{name:context}}` takes text (a title with the scene's name, a comment in the
//!   reader's language): [`Fill::Text`], which the template's language escapes for the
//!   context the template gives, with the helpers of [`crate::formats::escape`]. The
//!   contexts: Python's `str` (a `"..."` literal), `doc` (one line inside `"""`), `block`
//!   (lines inside `"""`) and `comment` (after `#`); C++'s `str` and `comment` (after `//`).
//!
//! So whether a piece of text is escaped, and how, is decided by the template, where its
//! place in the program can be seen, and never by the code that fills it. A hole without
//! a value, a value without a hole, text for a code hole or code for a text hole is an
//! error ([`TemplateError`]), which the tests meet first.

use crate::formats::escape;

/// The programming language a template is written in (not a reader's language, `Lang`, nor a shading language, `ShadingLanguage`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProgramLanguage {
    /// Python 3.
    Python,
    /// C++ (the openFrameworks app).
    Cpp,
}

/// A template: its name (for errors), its language and its text.
#[derive(Clone, Copy, Debug)]
pub struct Template {
    /// The file's name under `export/templates/`.
    pub name: &'static str,
    /// What the holes' contexts are escaped for.
    pub language: ProgramLanguage,
    /// The text with its holes.
    pub text: &'static str,
}

/// What fills a hole.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Fill {
    /// Code the writer generated (for a `{{name}}` hole).
    Code(String),
    /// Text, escaped for the hole's context (for a `{{name:context}}` hole).
    Text(String),
}

/// A template filled wrongly: a fault of phonglab's, not of the scene.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", crate::t!("export-template-broken", template = *template, problem = problem.clone()))]
pub struct TemplateError {
    /// The template's name.
    pub template: &'static str,
    /// What is wrong, for the developer who reads it.
    pub problem: String,
}

/// A hole as written: its name and its context (`None` for code).
struct Hole<'a> {
    name: &'a str,
    context: Option<&'a str>,
}

/// Splits `text` at its holes: the literal pieces and the holes between them.
fn holes(text: &str) -> Result<(Vec<&str>, Vec<Hole<'_>>), String> {
    let mut pieces = Vec::new();
    let mut found = Vec::new();
    let mut rest = text;
    while let Some(open) = rest.find("{{") {
        let Some(close) = rest[open..].find("}}") else {
            return Err(format!("a hole opened at byte {} is not closed", text.len() - rest.len() + open));
        };
        pieces.push(&rest[..open]);
        let inside = &rest[open + 2..open + close];
        let (name, context) = match inside.split_once(':') {
            Some((n, c)) => (n, Some(c)),
            None => (inside, None),
        };
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return Err(format!("{{{{{inside}}}}} is not a hole's name"));
        }
        found.push(Hole { name, context });
        rest = &rest[open + close + 2..];
    }
    pieces.push(rest);
    Ok((pieces, found))
}

/// `text` escaped for `context` in `language`.
fn escaped(language: ProgramLanguage, context: &str, text: &str) -> Option<String> {
    Some(match (language, context) {
        (ProgramLanguage::Python, "str") => escape::python::string(text),
        (ProgramLanguage::Python, "doc") => escape::python::triple_quoted(text, false),
        (ProgramLanguage::Python, "block") => escape::python::triple_quoted(text, true),
        (ProgramLanguage::Python, "comment") => escape::python::comment(text),
        (ProgramLanguage::Cpp, "str") => escape::cpp::string(text),
        (ProgramLanguage::Cpp, "comment") => escape::cpp::comment(text),
        _ => return None,
    })
}

impl Template {
    /// The template with every hole filled from `fills` (see the module's documentation).
    pub fn fill(&self, fills: &[(&str, Fill)]) -> Result<String, TemplateError> {
        let broken = |problem: String| TemplateError { template: self.name, problem };
        let (pieces, found) = holes(self.text).map_err(broken)?;
        for (name, _) in fills {
            if !found.iter().any(|h| h.name == *name) {
                return Err(broken(format!("a value for {name}, which the template has no hole for")));
            }
        }
        let mut out = String::with_capacity(self.text.len() + fills.iter().map(|(_, f)| fill_len(f)).sum::<usize>());
        for (piece, hole) in pieces.iter().zip(found.iter().map(Some).chain([None])) {
            out.push_str(piece);
            let Some(hole) = hole else { break };
            let Some((_, fill)) = fills.iter().find(|(n, _)| *n == hole.name) else {
                return Err(broken(format!("no value for the hole {}", hole.name)));
            };
            match (fill, hole.context) {
                (Fill::Code(code), None) => out.push_str(code),
                (Fill::Text(text), Some(context)) => out.push_str(
                    &escaped(self.language, context, text)
                        .ok_or_else(|| broken(format!("{} has an unknown context {context}", hole.name)))?,
                ),
                (Fill::Text(_), None) => return Err(broken(format!("text for the code hole {}", hole.name))),
                (Fill::Code(_), Some(_)) => return Err(broken(format!("code for the text hole {}", hole.name))),
            }
        }
        Ok(out)
    }
}

fn fill_len(f: &Fill) -> usize {
    match f {
        Fill::Code(s) | Fill::Text(s) => s.len(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const T: Template = Template {
        name: "test.py",
        language: ProgramLanguage::Python,
        text: "\"\"\"{{title:doc}}\"\"\"\nx = {{x}}\n# {{c:comment}}\n",
    };

    #[test]
    fn text_is_escaped_for_its_hole_and_code_is_not() {
        let out = T
            .fill(&[
                ("title", Fill::Text("a\"\"\" + b".into())),
                ("x", Fill::Code("[1, 2]".into())),
                ("c", Fill::Text("one\rtwo".into())),
            ])
            .unwrap();
        assert_eq!(out, "\"\"\"a\\\"\\\"\\\" + b\"\"\"\nx = [1, 2]\n# one\\u{D}two\n");
    }

    #[test]
    fn a_wrong_fill_is_an_error() {
        let code = |s: &str| Fill::Code(s.into());
        let text = |s: &str| Fill::Text(s.into());
        assert!(T.fill(&[("title", text("t")), ("x", code("1"))]).is_err(), "a hole without a value");
        assert!(T.fill(&[("title", code("t")), ("x", code("1")), ("c", text(""))]).is_err(), "code for text");
        assert!(T.fill(&[("title", text("t")), ("x", text("1")), ("c", text(""))]).is_err(), "text for code");
        assert!(
            T.fill(&[("title", text("t")), ("x", code("1")), ("c", text("")), ("y", code(""))]).is_err(),
            "a value without a hole"
        );
        let bad = Template { name: "bad", language: ProgramLanguage::Cpp, text: "{{a:doc}}" };
        assert!(bad.fill(&[("a", text(""))]).is_err(), "C++ has no doc context");
    }
}
