//! User text as data: one escaping rule per target language that phonglab writes.
//!
//! A scene's name, a file name, a comment: text that a person typed, or that arrived in a
//! downloaded notebook's file name or a shared link, reaches code that students run (a
//! PyOpenGL program, an openFrameworks app, a notebook), documents they open (Markdown,
//! PDF) and their terminal. Every generator passes such text through the helper for the
//! place it lands in, and never formats it into code as it is.
//!
//! | target | helper | what it guarantees |
//! |---|---|---|
//! | Python string literal | [`python::string`] | a `"..."` literal whose value is the text, on one line |
//! | Python triple-quoted string | [`python::triple_quoted`] | the body of a `"""` string that cannot close it; the value is the text |
//! | Python comment | [`python::comment`] | one line after `#` |
//! | C++ string literal | [`cpp::string`] | a `"..."` literal whose value is the text (UTF-8) |
//! | C++ `//` comment | [`cpp::comment`] | one line that no backslash or trigraph splices onto the next |
//! | GLSL and WGSL `//` comment | [`glsl::comment`] | as C++'s |
//! | Markdown (and a notebook's Markdown cells) | [`markdown::text`] | inline text: no emphasis, link, HTML, heading, maths or new block |
//! | TOML string | [`toml::string`] | a basic string (the `toml` crate writes it) |
//! | PDF text | [`pdf::text`] | only characters a font draws |
//! | the terminal | [`terminal::text`] | no escape sequence, no line break |
//! | the window (a name shown in a list) | [`window::text`] | as the terminal's: one line, no bidirectional control |
//! | JSON (as `serde_json` wrote it) | [`json::text`] | every control as `\u202e`, C0 included (serde's) |
//! | a CSV field | [`csv::field`] | controls written `\u{202E}`, quoted where it holds `,`, `;` or `"` |
//! | HTML text or attribute | [`html::text`] | no tag, entity or attribute end; controls written `\u{1B}` |
//! | Moodle XML text | [`moodle_xml::text`] | as HTML's: entities, no control or non-character XML 1.0 refuses (U+FFFE) |
//! | Moodle XML CDATA | [`moodle_xml::cdata`] | a section that no `]]>` closes early |
//! | a Cloze part, its feedback | [`moodle_xml::cloze_part`] | `} # ~ / \\` escaped, no brace: the part stays whole |
//! | Cloze question text (HTML) | [`moodle_xml::cloze_html`] | no brace, so no text reads as a part |
//! | GIFT text | [`gift::text`] | `~ = # { } :` and `\\` escaped, one line, HTML-safe |
//! | GIFT title (plain text) | [`gift::plain`] | `~ = # { } :` and `\\` escaped, one line, nothing else |
//!
//! JSON is written by `serde_json`, which escapes the C0 controls in every string but not
//! the others (DEL, C1, the separators, the bidirectional controls): [`json::text`]
//! escapes those in its output.
//!
//! What is escaped everywhere ([`is_control`]): the C0 controls (NUL, ESC, CR, LF, tab ...),
//! DEL, the C1 controls (U+0080-U+009F: NEL, CSI ...), the line and paragraph separators
//! U+2028 and U+2029, the bidirectional controls (U+061C, U+200E, U+200F, U+202A-U+202E,
//! U+2066-U+2069: "Trojan Source") and the byte-order mark U+FEFF. In a literal each
//! becomes the language's own escape, so the value is unchanged; in a comment, a document
//! or the terminal each becomes the visible `\u{1B}`.

/// Is `c` a character that must never reach a file or a terminal as it is: a control
/// character, a line or paragraph separator, a bidirectional control, the byte-order mark.
pub fn is_control(c: char) -> bool {
    matches!(c,
        '\u{0}'..='\u{1F}' | '\u{7F}'..='\u{9F}'
        | '\u{2028}' | '\u{2029}'
        | '\u{61C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}'
        | '\u{FEFF}')
}

/// Is `c` a non-character that XML 1.0 refuses (U+FFFE and U+FFFF: outside its `Char`
/// production, so no parser reads a document holding one, not even as an entity) or tells
/// documents to avoid (§2.2: U+FDD0-U+FDEF and the last two code points of every plane,
/// U+1FFFE ... U+10FFFF)? The rest of what XML 1.0 refuses is a control ([`is_control`]:
/// the C0 controls but tab, line feed and carriage return) or a surrogate, which a Rust
/// string cannot hold.
pub fn is_noncharacter(c: char) -> bool {
    let n = c as u32;
    (0xFDD0..=0xFDEF).contains(&n) || n & 0xFFFE == 0xFFFE
}

/// `text` with every non-character ([`is_noncharacter`]) written visibly (`\u{FFFE}`).
fn visible_noncharacters(text: &str) -> std::borrow::Cow<'_, str> {
    if !text.chars().any(is_noncharacter) {
        return std::borrow::Cow::Borrowed(text);
    }
    text.chars().map(|c| if is_noncharacter(c) { visible(c) } else { c.to_string() }).collect::<String>().into()
}

/// Text from outside made a name that a scene file keeps (a notebook's file name becomes
/// the scene's name): each control character written visibly, `\u{1B}`, so the name is one
/// line of printable text, as a scene file requires.
pub fn printable(text: &str) -> String {
    visible_controls(text, |_| false)
}

/// `c` as the visible escape `\u{1B}` (upper-case hexadecimal).
fn visible(c: char) -> String {
    format!("\\u{{{:X}}}", c as u32)
}

/// `text` with every control character written visibly (`\u{1B}`), and each character for
/// which `also` is true too.
fn visible_controls(text: &str, also: impl Fn(char) -> bool) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if is_control(c) || also(c) {
            out.push_str(&visible(c));
        } else {
            out.push(c);
        }
    }
    out
}

/// `text` with every control character but the line feed and the tab written visibly
/// (`\u{1B}`): phonglab's own HTML, whose lines are its own.
fn kept_lines(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if is_control(c) && c != '\n' && c != '\t' {
            out.push_str(&visible(c));
        } else {
            out.push(c);
        }
    }
    out
}

/// Python 3 source.
pub mod python {
    use super::is_control;

    /// One character inside a Python string literal: the language's escapes for the quote,
    /// the backslash and the control characters (`\n`, `\x1b`, `\u2028`), itself otherwise.
    fn push_escaped(out: &mut String, c: char, keep_newlines: bool) {
        match c {
            '\\' => out.push_str("\\\\"),
            '"' => out.push_str("\\\""),
            '\n' if keep_newlines => out.push('\n'),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if is_control(c) && (c as u32) < 0x100 => out.push_str(&format!("\\x{:02x}", c as u32)),
            c if is_control(c) => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }

    /// A double-quoted Python string literal whose value is `text`, on one line.
    pub fn string(text: &str) -> String {
        let mut out = String::from("\"");
        for c in text.chars() {
            push_escaped(&mut out, c, false);
        }
        out.push('"');
        out
    }

    /// The body of a `"""` string (a docstring, a shader's source) whose value is `text`:
    /// every quote and backslash escaped, so nothing in it closes the string; line breaks
    /// kept as they are when `keep_newlines` (a shader's lines), escaped otherwise (a
    /// title).
    pub fn triple_quoted(text: &str, keep_newlines: bool) -> String {
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            push_escaped(&mut out, c, keep_newlines);
        }
        out
    }

    /// Text for one line after `# `: control characters written `\u{1B}` (a comment ends at
    /// a line break; Python has no continuation inside a comment).
    pub fn comment(text: &str) -> String {
        super::visible_controls(text, |_| false)
    }
}

/// C++ source (the openFrameworks app).
pub mod cpp {
    use super::is_control;

    /// A double-quoted C++ string literal whose value is `text` in UTF-8: the quote and the
    /// backslash escaped, controls as three-digit octal (`\033`: a hexadecimal escape would
    /// swallow the digits after it) or as `\u2028`, and `??` as `?\?` (no trigraph).
    pub fn string(text: &str) -> String {
        let mut out = String::from("\"");
        let mut after_question = false;
        for c in text.chars() {
            match c {
                '\\' => out.push_str("\\\\"),
                '"' => out.push_str("\\\""),
                '\n' => out.push_str("\\n"),
                '\r' => out.push_str("\\r"),
                '\t' => out.push_str("\\t"),
                '?' if after_question => out.push_str("\\?"),
                c if is_control(c) && (c as u32) < 0x80 => out.push_str(&format!("\\{:03o}", c as u32)),
                c if is_control(c) => out.push_str(&format!("\\u{:04x}", c as u32)),
                c => out.push(c),
            }
            after_question = c == '?';
        }
        out.push('"');
        out
    }

    /// Text for one line after `// `: control characters, every backslash (a backslash at
    /// the end of a line splices the next line into the comment) and the second `?` of a
    /// `??` (a trigraph `??/` is a backslash before C++17) written visibly, `\u{5C}`.
    pub fn comment(text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        let mut after_question = false;
        for c in text.chars() {
            if is_control(c) || c == '\\' || (c == '?' && after_question) {
                out.push_str(&super::visible(c));
            } else {
                out.push(c);
            }
            after_question = c == '?' && !after_question;
        }
        out
    }
}

/// GLSL and WGSL source.
pub mod glsl {
    /// Text for one line after `// `: as [`super::cpp::comment`] (GLSL 4.20 splices lines at
    /// a backslash; WGSL ends a comment at any of its line breaks, all of them controls).
    pub fn comment(text: &str) -> String {
        super::cpp::comment(text)
    }
}

/// Markdown (CommonMark with GitHub's tables and strikethrough, as Jupyter renders it).
pub mod markdown {
    /// The characters that start or end something inline anywhere: code, emphasis, links
    /// and images, HTML and autolinks, entities, maths (`$`, Jupyter's MathJax), a
    /// strikethrough, a table cell, a heading's closing `#`.
    const INLINE: &[char] = &['\\', '`', '*', '_', '[', ']', '<', '>', '&', '$', '~', '|', '#', '!'];

    /// Inline text: each character of `INLINE` backslash-escaped (CommonMark makes
    /// every such escape its literal character), and at the start a list, quote or
    /// heading marker too (`-`, `+`, `=`, `1.`); control characters written `\u{1B}`, so
    /// it stays on its line and starts no new block. Other text (`:`, `.`, accents) is
    /// left as it is, so the Markdown source stays readable.
    pub fn text(text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        let digits = text.chars().take_while(char::is_ascii_digit).count();
        for (k, c) in text.chars().enumerate() {
            let starts_block =
                (k == 0 && matches!(c, '-' | '+' | '=')) || (k == digits && k > 0 && matches!(c, '.' | ')'));
            if super::is_control(c) {
                out.push_str(&super::visible(c));
                continue;
            }
            if INLINE.contains(&c) || starts_block {
                out.push('\\');
            }
            out.push(c);
        }
        out
    }
}

/// HTML (a notebook's rich display).
pub mod html {
    /// Text in an element or a quoted attribute: `&`, `<`, `>`, `"` and `'` as entities,
    /// control characters written `\u{1B}`, so it opens no tag and ends no attribute.
    pub fn text(text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            match c {
                '&' => out.push_str("&amp;"),
                '<' => out.push_str("&lt;"),
                '>' => out.push_str("&gt;"),
                '"' => out.push_str("&quot;"),
                '\'' => out.push_str("&#39;"),
                c if super::is_control(c) => out.push_str(&super::visible(c)),
                c => out.push(c),
            }
        }
        out
    }
}

/// Moodle XML, the question bank's import format (`question/format/xml/format.php`).
pub mod moodle_xml {
    /// Text in an element or a quoted attribute: `&`, `<`, `>`, `"` and `'` as entities,
    /// control characters written `\u{1B}` (XML 1.0 allows no C0 control but tab, line
    /// feed and carriage return, not even as an entity) and non-characters too
    /// (`\u{FFFE}`: [`super::is_noncharacter`]), so it opens no tag, ends no attribute or
    /// line, and leaves the document well-formed.
    pub fn text(text: &str) -> String {
        super::html::text(&super::visible_noncharacters(text))
    }

    /// The inside of a `<![CDATA[ ... ]]>` section whose value is `html`: every `]]>`
    /// split across two sections (`]]]]><![CDATA[>`, as Moodle's own export writes it),
    /// and control characters other than tab and line feed, and non-characters, written
    /// `\u{1B}` (a CDATA section holds only what XML 1.0 allows in a document).
    pub fn cdata(html: &str) -> String {
        super::kept_lines(&super::visible_noncharacters(html)).replace("]]>", "]]]]><![CDATA[>")
    }

    /// Text inside an embedded answer (Cloze) part's braces: a part's feedback. Moodle's
    /// import (`qtype_multianswer_extract_question`) ends a feedback at the first `~` or
    /// `}` not after a backslash and then decodes its HTML entities once
    /// (`html_entity_decode`), so the text is HTML-escaped twice, with `{`, `}`, `~` and
    /// `\\` as numeric entities: the part holds no character that ends it, and after
    /// Moodle's one decoding the feedback is HTML text that shows `text` and opens no tag.
    pub fn cloze_part(text: &str) -> String {
        let once = super::html::text(text);
        let mut out = String::with_capacity(once.len() * 2);
        for c in once.chars() {
            match c {
                '&' => out.push_str("&amp;"),
                '{' => out.push_str("&amp;#123;"),
                '}' => out.push_str("&amp;#125;"),
                '~' => out.push_str("&amp;#126;"),
                '\\' => out.push_str("&amp;#92;"),
                c => out.push(c),
            }
        }
        out
    }

    /// HTML that phonglab wrote (tags kept, text already escaped) put in a Cloze
    /// question's text outside its parts: `{` and `}` as entities, so no text can be read
    /// as a part (`{1:NUMERICAL:...}`).
    pub fn cloze_html(html: &str) -> String {
        html.replace('{', "&#123;").replace('}', "&#125;")
    }
}

/// GIFT, Moodle's plain-text question format (`question/format/gift/format.php`).
pub mod gift {
    /// Text in a question's name, text, answer or feedback: GIFT's special characters
    /// `~ = # { } :` and the backslash after a backslash (as Moodle's GIFT export writes
    /// them), every control character (a line break too, which would end the question at
    /// a blank line) written `\u{1B}`; then HTML's `<` and `&` as entities, since phonglab
    /// writes every GIFT text as `[html]`.
    pub fn text(text: &str) -> String {
        let html = super::html::text(text);
        specials(&html)
    }

    /// A question's name (its title, `::NAME::`), which GIFT reads as plain text, not
    /// HTML: GIFT's special characters after a backslash and every control character
    /// written `\u{1B}` (one line), nothing else: `O'Neil & <b>` stays `O'Neil & <b>`.
    pub fn plain(text: &str) -> String {
        specials(&super::visible_controls(text, |_| false))
    }

    /// HTML that phonglab wrote itself (tags kept): GIFT's special characters after a
    /// backslash, and control characters (a line feed too) written visibly: the writer
    /// joins its lines first.
    pub fn html(html: &str) -> String {
        let kept = super::visible_controls(html, |_| false);
        specials(&kept)
    }

    /// GIFT's special characters (`~ = # { } :` and the backslash) after a backslash.
    fn specials(text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            if matches!(c, '~' | '=' | '#' | '{' | '}' | ':' | '\\') {
                out.push('\\');
            }
            out.push(c);
        }
        out
    }
}

/// TOML.
pub mod toml {
    /// A TOML basic string whose value is `text`, on one line: the quote and the backslash
    /// escaped, and every control character as TOML's `\n`, `\t`... or `\u2028` (the
    /// `toml` crate would write a line break raw in a multi-line string, and the C1 and
    /// bidirectional controls raw).
    pub fn string(text: &str) -> String {
        let mut out = String::from("\"");
        for c in text.chars() {
            match c {
                '"' => out.push_str("\\\""),
                '\\' => out.push_str("\\\\"),
                '\n' => out.push_str("\\n"),
                '\r' => out.push_str("\\r"),
                '\t' => out.push_str("\\t"),
                c if super::is_control(c) => out.push_str(&format!("\\u{:04X}", c as u32)),
                c => out.push(c),
            }
        }
        out.push('"');
        out
    }
}

/// Text drawn into a PDF.
pub mod pdf {
    /// Control characters written `\u{1B}`: a font has no glyph for them, and a line break
    /// would leave the block's measured box.
    pub fn text(text: &str) -> String {
        super::visible_controls(text, |_| false)
    }
}

/// JSON: what `serde_json` writes, made safe to show.
pub mod json {
    /// `json` (text `serde_json` wrote) with every control character it leaves as it is
    /// (DEL, the C1 controls, U+2028 and U+2029, the bidirectional controls, the byte-order
    /// mark) written as JSON's `\u202e`: they occur only inside strings, whose values are
    /// unchanged, and a viewer or terminal showing the file shows no reordered text. The C0
    /// controls serde_json escapes in strings itself; outside them its line breaks are the
    /// layout's, and stay.
    pub fn text(json: &str) -> String {
        let mut out = String::with_capacity(json.len());
        for c in json.chars() {
            if super::is_control(c) && u32::from(c) >= 0x7F {
                out.push_str(&format!("\\u{:04x}", c as u32));
            } else {
                out.push(c);
            }
        }
        out
    }
}

/// CSV (RFC 4180), as spreadsheets read it.
pub mod csv {
    /// One field: control characters written visibly (`\u{202E}`: CSV has no escapes, and
    /// a spreadsheet shows a bidirectional control as reordered text), then quoted, with
    /// quotes doubled, where it holds a comma, a semicolon or a quote: a field reads the
    /// same whichever of the two separators the file uses (a Portuguese spreadsheet's is `;`).
    pub fn field(text: &str) -> String {
        let s = super::visible_controls(text, |_| false);
        if s.contains([',', ';', '"']) { format!("\"{}\"", s.replace('"', "\"\"")) } else { s }
    }

    /// One field of text a person typed (a file's name): as [`field`], but a text that a
    /// spreadsheet would run as a formula (it starts with `=`, `+`, `-`, `@`, a tab or a
    /// carriage return) gets a `'` before it, so it is shown and never computed.
    pub fn text_field(text: &str) -> String {
        if text.starts_with(['=', '+', '-', '@', '\t', '\r']) { field(&format!("'{text}")) } else { field(text) }
    }
}

/// The window: a name from outside shown in a list (the chooser's files), written as the
/// terminal writes it, so a line break does not make two entries of one, a right-to-left
/// override (U+202E) does not turn `gnp.exe` round, and ESC is `\u{1B}`, not a box.
pub mod window {
    /// A name on one line, every control character written `\u{1B}` (as [`super::terminal::text`]).
    pub fn text(text: &str) -> String {
        super::terminal::text(text)
    }
}

/// The terminal (`phonglab explain`, every message on the standard error).
pub mod terminal {
    /// User text on one line: control characters written `\u{1B}`, so no escape sequence
    /// (ESC, or the C1 CSI U+009B) reaches the terminal and no line break splits a line.
    pub fn text(text: &str) -> String {
        super::visible_controls(text, |_| false)
    }

    /// A whole message, whose line breaks and tabs are its own: every other control
    /// character written `\u{1B}`. For messages that may quote a file's contents or name.
    pub fn lines(text: &str) -> String {
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            if super::is_control(c) && c != '\n' && c != '\t' {
                out.push_str(&super::visible(c));
            } else {
                out.push(c);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HOSTILE: &str = "a\"\"\"b'''c*/d\re\nf\u{2028}g\u{0}h\u{1b}[31mi\\j??/k\u{9b}l\u{202e}m\t";

    #[test]
    fn every_helper_leaves_no_control_character() {
        let outputs = [
            python::string(HOSTILE),
            python::triple_quoted(HOSTILE, false),
            python::comment(HOSTILE),
            cpp::string(HOSTILE),
            cpp::comment(HOSTILE),
            glsl::comment(HOSTILE),
            markdown::text(HOSTILE),
            toml::string(HOSTILE),
            pdf::text(HOSTILE),
            terminal::text(HOSTILE),
            moodle_xml::text(HOSTILE),
            moodle_xml::cloze_part(HOSTILE),
            gift::text(HOSTILE),
            gift::html(HOSTILE),
        ];
        for out in outputs {
            assert!(!out.chars().any(is_control), "{out:?}");
        }
        assert_eq!(terminal::lines("one\ntwo\u{1b}"), "one\ntwo\\u{1B}");
    }

    #[test]
    fn literals_are_the_languages_own_escapes() {
        assert_eq!(python::string("x"), "\"x\"");
        assert_eq!(python::string("\"\"\"\\\n\r\u{0}\u{1b}\u{85}\u{2028}"), r#""\"\"\"\\\n\r\x00\x1b\x85\u2028""#);
        assert_eq!(python::triple_quoted("a\"\nb", true), "a\\\"\nb");
        assert_eq!(cpp::string("é\"\\\n\u{1b}1??/"), "\"é\\\"\\\\\\n\\0331?\\?/\"");
        assert_eq!(cpp::string("\u{2028}"), "\"\\u2028\"");
    }

    #[test]
    fn comments_cannot_continue_onto_the_next_line() {
        assert_eq!(cpp::comment("ends with \\"), "ends with \\u{5C}");
        assert_eq!(cpp::comment("??/"), "?\\u{3F}/");
        assert_eq!(cpp::comment("???"), "?\\u{3F}?");
        assert_eq!(cpp::comment("a\r\nb"), "a\\u{D}\\u{A}b");
        assert_eq!(python::comment("a\rb"), "a\\u{D}b");
        assert_eq!(cpp::comment("Cena à luz"), "Cena à luz");
    }

    #[test]
    fn markdown_text_starts_nothing() {
        assert_eq!(markdown::text("**b** <script> $x$ # [l](u)"), r"\*\*b\*\* \<script\> \$x\$ \# \[l\](u)");
        assert_eq!(markdown::text("à\n# h"), "à\\u{A}\\# h");
        assert_eq!(markdown::text("- 12. x"), r"\- 12. x");
        assert_eq!(markdown::text("12. x"), r"12\. x");
        assert_eq!(markdown::text("Exercise 1: a light (level 2)"), "Exercise 1: a light (level 2)");
    }

    #[test]
    fn json_and_csv_keep_no_bidirectional_or_separator_control() {
        let value = serde_json::json!({ "id": HOSTILE, "more": "\u{7f}\u{2066}x\u{2069}\u{feff}" });
        let raw = serde_json::to_string_pretty(&value).unwrap();
        assert!(raw.contains('\u{202e}') && raw.contains('\u{2028}'), "serde_json leaves them: {raw}");
        let safe = json::text(&raw);
        assert!(!safe.chars().any(|c| is_control(c) && c != '\n'), "{safe}");
        assert_eq!(serde_json::from_str::<serde_json::Value>(&safe).unwrap(), value, "the values are unchanged");
        assert_eq!(csv::field("a,\u{202e}b\"c"), "\"a,\\u{202E}b\"\"c\"");
        assert_eq!(csv::field("Phong 32"), "Phong 32");
        // Read the same with either separator: a Portuguese spreadsheet splits on `;`.
        assert_eq!(csv::field("a; b"), "\"a; b\"");
        assert_eq!(csv::text_field("=1;2"), "\"'=1;2\"");
        assert!(!csv::field(HOSTILE).chars().any(is_control));
    }

    #[test]
    fn toml_strings_read_back() {
        for s in [HOSTILE, "plain", "é \u{7f}"] {
            let doc: ::toml::Table = ::toml::from_str(&format!("k = {}", toml::string(s))).unwrap();
            assert_eq!(doc["k"].as_str(), Some(s));
        }
    }

    #[test]
    fn moodle_xml_ends_no_element_cdata_or_cloze_part() {
        assert_eq!(moodle_xml::text("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
        assert_eq!(moodle_xml::cdata("x]]>y\n\t\u{1b}"), "x]]]]><![CDATA[>y\n\t\\u{1B}");
        // Moodle ends a part's feedback at `~` or `}` and decodes its entities once.
        let part = moodle_xml::cloze_part("}~{\\<b>&");
        assert!(!part.contains(['}', '~', '{', '\\', '<']), "{part}");
        assert_eq!(part, "&amp;#125;&amp;#126;&amp;#123;&amp;#92;&amp;lt;b&amp;gt;&amp;amp;");
        assert_eq!(moodle_xml::cloze_html("<p>{1:NUMERICAL:=1}</p>"), "<p>&#123;1:NUMERICAL:=1&#125;</p>");
    }

    /// XML 1.0's `Char`: what a well-formed document may hold.
    fn xml_char(c: char) -> bool {
        matches!(c as u32, 0x9 | 0xA | 0xD | 0x20..=0xD7FF | 0xE000..=0xFFFD | 0x10000..=0x10FFFF)
    }

    /// Every class of code point XML 1.0 refuses (the C0 controls but tab, line feed and
    /// carriage return; U+FFFE and U+FFFF) and those it tells documents to avoid (the C1
    /// controls, U+FDD0-U+FDEF, the last two of every plane) is written visibly by the
    /// element's and the CDATA section's escapers, so the document stays well-formed.
    #[test]
    fn moodle_xml_writes_no_code_point_xml_refuses() {
        let mut refused: Vec<char> = ('\u{0}'..='\u{1F}').filter(|c| !matches!(c, '\t' | '\n' | '\r')).collect();
        refused.extend(['\u{FFFE}', '\u{FFFF}']);
        let mut avoided: Vec<char> = ('\u{7F}'..='\u{9F}').chain('\u{FDD0}'..='\u{FDEF}').collect();
        avoided.extend(
            (1..=16u32).flat_map(|plane| [plane << 16 | 0xFFFE, plane << 16 | 0xFFFF]).filter_map(char::from_u32),
        );
        for c in refused.iter().chain(&avoided) {
            let within = format!("a{c}b");
            for (which, out) in [("text", moodle_xml::text(&within)), ("cdata", moodle_xml::cdata(&within))] {
                assert!(
                    out.chars().all(|o| xml_char(o) && !is_noncharacter(o)),
                    "{which} of U+{:04X}: {out:?}",
                    *c as u32
                );
                assert!(out.contains(&format!("\\u{{{:X}}}", *c as u32)), "{which} of U+{:04X}: {out:?}", *c as u32);
            }
        }
        assert!(refused.iter().all(|&c| !xml_char(c)), "the refused are XML's own");
        // What XML allows is kept: the last characters before each refused range.
        for c in ['\u{D7FF}', '\u{E000}', '\u{FFFD}', '\u{10000}', '\u{10FFFD}', 'é'] {
            assert_eq!(moodle_xml::text(&c.to_string()), c.to_string());
            assert_eq!(moodle_xml::cdata(&c.to_string()), c.to_string());
        }
    }

    #[test]
    fn gift_escapes_its_own_characters_on_one_line() {
        assert_eq!(gift::text("a~b=c#d{e}f:g\\h"), "a\\~b\\=c\\#d\\{e\\}f\\:g\\\\h");
        // The line break written visibly, `\u{A}`, and that escaped in turn: GIFT reads `\u{A}`.
        assert_eq!(gift::text("<i>\n"), r"&lt;i&gt;\\u\{A\}");
        assert_eq!(gift::html("<p>x = 1:</p>"), "<p>x \\= 1\\:</p>");
    }
}
