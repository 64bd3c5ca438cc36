//! A [`Bank`] as Moodle XML, the format of Moodle's question bank (Question bank →
//! Import → "Moodle XML format"), written as Moodle's own export writes it
//! (`question/format/xml/format.php`, `writequestion`): a `<quiz>` of `<question>`s, a
//! `type="category"` question before each category's questions, `type="cloze"` for a
//! statement with numbered parts (its text holds each part as
//! `{1:NUMERICAL:=ANSWER:TOLERANCE#right~%0%*#wrong}`, Moodle's embedded-answers syntax),
//! `type="multichoice"` for a choice, whose pictures are `<file name=... path="/"
//! encoding="base64">` inside its `<questiontext>` and named `@@PLUGINFILE@@/NAME` in the
//! text. HTML goes in CDATA sections (as Moodle's export puts it), plain text as entities.

use std::fmt::Write as _;

use base64::Engine as _;
use base64::engine::general_purpose::STANDARD;

use super::escape::moodle_xml::{cdata, cloze_html, cloze_part, text};
use super::question::{Bank, Body, Category, Choice, Part, Question, number};

/// The penalty for each wrong try in an interactive quiz, Moodle's default.
const PENALTY: &str = "0.3333333";

/// The bank as a Moodle XML file.
pub fn write(bank: &Bank) -> String {
    let mut o = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n");
    for c in &bank.categories {
        category(&mut o, c);
        for q in &c.questions {
            question(&mut o, q);
        }
    }
    o.push_str("</quiz>\n");
    o
}

/// A category's path as Moodle writes it: `$course$/top/` and the names joined by `/`,
/// a `/` inside a name doubled (Moodle's `split_category_path` reads `//` as one).
pub fn category_path(path: &[String]) -> String {
    let names: Vec<String> = path.iter().map(|n| n.replace('/', "//")).collect();
    format!("$course$/top/{}", names.join("/"))
}

fn category(o: &mut String, c: &Category) {
    let _ = writeln!(o, "  <question type=\"category\">");
    let _ = writeln!(o, "    <category>\n      <text>{}</text>\n    </category>", text(&category_path(&c.path)));
    let _ = writeln!(o, "    <info format=\"html\">\n      <text></text>\n    </info>");
    let _ = writeln!(o, "    <idnumber></idnumber>\n  </question>");
}

fn html_text(o: &mut String, tag: &str, html: &str, indent: &str) {
    let _ = writeln!(o, "{indent}<{tag} format=\"html\">\n{indent}  <text><![CDATA[{}]]></text>", cdata(html));
    let _ = writeln!(o, "{indent}</{tag}>");
}

fn question(o: &mut String, q: &Question) {
    let kind = match q.body {
        Body::Numbers { .. } => "cloze",
        Body::Choice { .. } => "multichoice",
    };
    let _ = writeln!(o, "  <question type=\"{kind}\">");
    let _ = writeln!(o, "    <name>\n      <text>{}</text>\n    </name>", text(&q.name));
    match &q.body {
        Body::Numbers { statement_html, parts } => {
            html_text(o, "questiontext", &cloze_statement(statement_html, parts), "    ");
            html_text(o, "generalfeedback", &q.general_feedback_html, "    ");
            let _ = writeln!(o, "    <penalty>{PENALTY}</penalty>\n    <hidden>0</hidden>\n    <idnumber></idnumber>");
        }
        Body::Choice { statement_html, files, choices } => {
            let _ = writeln!(o, "    <questiontext format=\"html\">");
            let _ = writeln!(o, "      <text><![CDATA[{}]]></text>", cdata(statement_html));
            for f in files {
                let name = text(&super::question::file_name(&f.name));
                let _ = writeln!(
                    o,
                    "      <file name=\"{name}\" path=\"/\" encoding=\"base64\">{}</file>",
                    STANDARD.encode(&f.bytes)
                );
            }
            let _ = writeln!(o, "    </questiontext>");
            html_text(o, "generalfeedback", &q.general_feedback_html, "    ");
            choice_options(o, choices);
        }
    }
    let _ = writeln!(o, "  </question>");
}

/// The statement, then the parts, a paragraph for each row: the row's label, then each
/// part's label and field.
pub fn cloze_statement(statement_html: &str, parts: &[Part]) -> String {
    let mut h = cloze_html(statement_html);
    for (i, p) in parts.iter().enumerate() {
        if i == 0 || parts[i - 1].row_html != p.row_html {
            if i > 0 {
                h.push_str("</p>");
            }
            let _ = write!(h, "\n<p>{}", cloze_html(&p.row_html));
        }
        let _ = write!(h, " {} {}", cloze_html(&p.label_html), cloze_field(p));
    }
    if !parts.is_empty() {
        h.push_str("</p>");
    }
    h
}

/// One part: `{1:NUMERICAL:=ANSWER:TOLERANCE#right~%0%*#wrong}` (`*`: any other answer,
/// which Moodle's numerical type accepts as the catch-all).
pub fn cloze_field(p: &Part) -> String {
    format!(
        "{{1:NUMERICAL:={}:{}#{}~%0%*#{}}}",
        number(p.answer),
        number(p.tolerance),
        cloze_part(&p.right_feedback),
        cloze_part(&p.wrong_feedback)
    )
}

fn choice_options(o: &mut String, choices: &[Choice]) {
    let _ = writeln!(o, "    <defaultgrade>1</defaultgrade>\n    <penalty>{PENALTY}</penalty>");
    let _ = writeln!(o, "    <hidden>0</hidden>\n    <idnumber></idnumber>");
    let _ = writeln!(o, "    <single>true</single>\n    <shuffleanswers>true</shuffleanswers>");
    let _ = writeln!(
        o,
        "    <answernumbering>ABCD</answernumbering>\n    <showstandardinstruction>0</showstandardinstruction>"
    );
    for tag in ["correctfeedback", "partiallycorrectfeedback", "incorrectfeedback"] {
        html_text(o, tag, "", "    ");
    }
    for c in choices {
        let fraction = if c.right { 100 } else { 0 };
        let _ = writeln!(o, "    <answer fraction=\"{fraction}\" format=\"html\">");
        let _ = writeln!(o, "      <text><![CDATA[{}]]></text>", cdata(&super::escape::html::text(&c.text)));
        let _ = writeln!(o, "      <feedback format=\"html\">");
        let _ = writeln!(o, "        <text><![CDATA[{}]]></text>", cdata(&super::escape::html::text(&c.feedback)));
        let _ = writeln!(o, "      </feedback>\n    </answer>");
    }
}
