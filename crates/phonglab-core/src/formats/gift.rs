//! A [`Bank`] as GIFT, Moodle's plain-text question format (Question bank → Import →
//! "GIFT format"; `question/format/gift/format.php`). GIFT has no question of several
//! parts, so each part of a statement is its own numerical question
//! (`::NAME::[html]STATEMENT PART{#=ANSWER:TOLERANCE#right ~#wrong ####general}`), and a choice is
//! `{=right#feedback ~wrong#feedback}`. GIFT embeds no file: a picture is a `data:` URI in
//! the statement's `<img>`. Each category is a `$CATEGORY:` line before its questions;
//! every text is escaped by [`super::escape::gift`], so no name breaks a question: a
//! question's name as the plain text GIFT reads it, the rest as the `[html]` it is.

use std::fmt::Write as _;

use base64::Engine as _;
use base64::engine::general_purpose::STANDARD;

use super::escape::gift::{html, plain, text};
use super::question::{Bank, Body, Choice, Part, Question, number};

/// The bank as a GIFT file.
pub fn write(bank: &Bank) -> String {
    let mut o = String::from("// phonglab: questions for Moodle's question bank (GIFT format)\n\n");
    for c in &bank.categories {
        let path = super::moodle_xml::category_path(&c.path);
        let _ = writeln!(o, "$CATEGORY: {}\n", one_line(&path));
        for q in &c.questions {
            question(&mut o, q);
        }
    }
    o
}

/// Text on one line: a category line ends at its line's end.
fn one_line(s: &str) -> String {
    crate::formats::escape::printable(s)
}

/// Phonglab's HTML on one line (a blank line would end the question), escaped for GIFT:
/// each line break written `\n`, which Moodle's import reads back as a line break
/// (`escapedchar_post`), so a `<pre>` matrix keeps its rows.
fn gift_html(h: &str) -> String {
    let lines: Vec<String> = h.split('\n').map(|l| html(l.trim_end_matches('\r'))).collect();
    lines.join("\\n")
}

fn question(o: &mut String, q: &Question) {
    match &q.body {
        Body::Numbers { statement_html, parts } => {
            for (k, p) in parts.iter().enumerate() {
                let name = format!("{} ({})", q.name, k + 1);
                numerical(o, &name, statement_html, p, &q.general_feedback_html);
            }
        }
        Body::Choice { statement_html, files, choices } => {
            let mut h = statement_html.clone();
            for f in files {
                let at = format!("@@PLUGINFILE@@/{}", super::question::file_name(&f.name));
                h = h.replace(&at, &format!("data:image/png;base64,{}", STANDARD.encode(&f.bytes)));
            }
            let _ = writeln!(o, "::{}::[html]{}{{", plain(&q.name), gift_html(&h));
            for c in choices {
                choice(o, c);
            }
            let _ = writeln!(o, "\t####{}\n}}\n", gift_html(&q.general_feedback_html));
        }
    }
}

/// One numerical question, as Moodle's GIFT export writes one
/// (`{#` `=ANSWER:TOLERANCE#right feedback`, `~#feedback for any other answer`,
/// `####general feedback` `}`): each answer's feedback its own.
fn numerical(o: &mut String, name: &str, statement_html: &str, p: &Part, general: &str) {
    let _ = writeln!(
        o,
        "::{}::[html]{} <p>{}</p>{{#\n\t={}:{}#{}\n\t~#{}\n\t####{}\n}}\n",
        plain(name),
        gift_html(statement_html),
        gift_html(&format!("{} {}", p.row_html, p.label_html)),
        number(p.answer),
        number(p.tolerance),
        text(&p.right_feedback),
        text(&p.wrong_feedback),
        gift_html(general)
    );
}

fn choice(o: &mut String, c: &Choice) {
    let mark = if c.right { '=' } else { '~' };
    let _ = writeln!(o, "\t{mark}{}#{}", text(&c.text), text(&c.feedback));
}
