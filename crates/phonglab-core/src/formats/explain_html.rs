//! The worked calculation as an HTML table, for a notebook's display
//! ([`crate::equation::explain::Explanation`] in the package's `_repr_html_`): in the
//! formats group because it escapes every text for HTML ([`super::escape::html::text`]).

use std::fmt::Write as _;

use crate::equation::explain::{Explanation, fmt_value};

/// An HTML table of the steps of `ex`: the heading, the headers in the user's language,
/// each step's title, formula (left-aligned), value (in the language's decimal mark, never
/// wrapped inside a number) and notes, every text escaped, values to `sig` digits.
pub fn explanation_html(ex: &Explanation, sig: usize) -> String {
    use super::escape::html::text as h;
    let left = "text-align:left;vertical-align:top";
    let mut s = format!("<div class=\"phonglab-explain\"><p><strong>{}</strong></p>\n<table>\n", h(&ex.heading));
    let heads: String = Explanation::columns().iter().map(|c| format!("<th style=\"{left}\">{}</th>", h(c))).collect();
    let _ = writeln!(s, "<thead><tr><th style=\"{left}\">#</th>{heads}</tr></thead>\n<tbody>");
    for (k, st) in ex.steps.iter().enumerate() {
        let value = st.value.as_ref().map_or_else(
            || format!("{} = n/a", st.name),
            |v| format!("{} = {}", st.name, crate::locale::decimal(&fmt_value(v, sig))),
        );
        let notes: Vec<String> = st.notes.iter().map(|n| h(n)).collect();
        let _ = writeln!(
            s,
            "<tr><td style=\"{left}\">{}</td><td style=\"{left}\">{}</td><td style=\"{left}\"><code>{}</code></td>\
             <td style=\"{left};white-space:nowrap\"><code>{}</code></td><td style=\"{left}\">{}</td></tr>",
            k + 1,
            h(&st.title),
            h(&st.formula),
            h(&value),
            notes.join("<br>")
        );
    }
    s.push_str("</tbody>\n</table></div>\n");
    s
}
