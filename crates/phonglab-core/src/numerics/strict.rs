//! What the readers of scene files and cases share: a misspelt key answered with the
//! closest known name, and an error's place shown as a short excerpt of its line, never the
//! whole line (a line can be megabytes long).

/// The most characters of a line an error quotes.
pub const EXCERPT_CHARS: usize = 72;

/// The most characters of a message an error repeats from a parser.
pub const MESSAGE_CHARS: usize = 320;

/// The number of single-character edits between `a` and `b` (Levenshtein).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diagonal + usize::from(ca != *cb));
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The known name closest to `unknown`, when it is close enough to be a misspelling
/// (at most a third of its letters, and at least 2, changed).
pub fn closest<'a>(unknown: &str, known: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (unknown.chars().count() / 3).max(2);
    known
        .into_iter()
        .map(|k| (edit_distance(&unknown.to_lowercase(), &k.to_lowercase()), k))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

/// serde's "unknown field `x`, expected one of `a`, `b`" (or "expected `a`"), with the
/// closest known name suggested when there is one.
pub fn with_suggestion(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `") else { return in_words(message) };
    let Some((unknown, expected)) = rest.split_once('`') else { return in_words(message) };
    let known: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
    let listed = known.iter().map(|k| format!("`{k}`")).collect::<Vec<_>>().join(", ");
    let field = format!("`{unknown}`");
    let said = match known.len() {
        0 => return message.to_string(),
        1 => crate::t!("toml-unknown-field-one", field = field, known = listed),
        _ => crate::t!("toml-unknown-field", field = field, known = listed),
    };
    match closest(unknown, known) {
        Some(k) => format!("{said}; {}", crate::t!("toml-did-you-mean", field = format!("`{k}`"))),
        None => said,
    }
}

/// serde's common messages in the current language ("missing field `x`", "invalid type:
/// string \"a\", expected f64"); any other as the parser says it.
fn in_words(message: &str) -> String {
    if let Some(field) = message.strip_prefix("missing field ") {
        return crate::t!("toml-missing-field", field = field);
    }
    if let Some(rest) = message.strip_prefix("invalid type: ")
        && let Some((found, expected)) = rest.split_once(", expected ")
    {
        return crate::t!("toml-invalid-type", found = kind_in_words(found), expected = kind_in_words(expected));
    }
    message.to_string()
}

/// A kind serde names in Rust's words (`f64`, `string "abc"`, `a boolean`) in the user's:
/// "a number", "the text \"abc\"", "true or false"; any other as serde says it.
fn kind_in_words(kind: &str) -> String {
    let numbers = ["f64", "f32", "i64", "i32", "u64", "u32", "u16", "u8", "usize", "a number"];
    if numbers.contains(&kind) || kind.starts_with("integer `") || kind.starts_with("floating point `") {
        let value = kind.split('`').nth(1).unwrap_or("");
        return if value.is_empty() {
            crate::t!("toml-kind-number")
        } else {
            crate::t!("toml-kind-number-value", value = value)
        };
    }
    if let Some(text) = kind.strip_prefix("string ") {
        return crate::t!("toml-kind-text", value = text);
    }
    match kind {
        "a string" | "string" => crate::t!("toml-kind-a-text"),
        "a boolean" | "bool" => crate::t!("toml-kind-boolean"),
        _ if kind.starts_with("boolean `") => crate::t!("toml-kind-boolean"),
        _ => kind.to_string(),
    }
}

/// The most characters of a line (or of a word from one) that a message quotes.
pub const QUOTE_CHARS: usize = 80;

/// A line of a file, or a piece of one (a name, a token), as every message quotes it:
/// trimmed, and cut to [`QUOTE_CHARS`] characters with "…" (a line can be megabytes long,
/// and a message is read by a person, on a terminal or in the window).
pub fn quoted_line(line: &str) -> String {
    shortened(line.trim(), QUOTE_CHARS)
}

/// At most `max` characters of `text`, with "…" where it was cut.
pub fn shortened(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        return text.to_string();
    }
    let mut s: String = text.chars().take(max.saturating_sub(1)).collect();
    s.push('…');
    s
}

/// "line L, column C" of the byte offset `at` in `text`, and an excerpt of that line of at
/// most [`EXCERPT_CHARS`] characters around the column, with a caret under it.
pub fn place(text: &str, at: usize) -> (String, String) {
    let at = at.min(text.len());
    let at = (0..=at).rev().find(|i| text.is_char_boundary(*i)).unwrap_or(0);
    let start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let end = text[at..].find('\n').map_or(text.len(), |i| at + i);
    let line_no = text[..start].matches('\n').count() + 1;
    let line = text[start..end].trim_end_matches('\r');
    let col = text[start..at].chars().count();
    let chars: Vec<char> = line.chars().collect();
    let from = col.saturating_sub(EXCERPT_CHARS / 2).min(chars.len().saturating_sub(EXCERPT_CHARS));
    let to = (from + EXCERPT_CHARS).min(chars.len());
    let mut excerpt: String = chars[from..to].iter().collect();
    let mut caret = col - from;
    if from > 0 {
        excerpt.insert(0, '…');
        caret += 1;
    }
    if to < chars.len() {
        excerpt.push('…');
    }
    let pointer = format!("{}^", " ".repeat(caret));
    let place = crate::t!("toml-place", line = line_no.to_string(), column = (col + 1).to_string());
    (place, format!("    {excerpt}\n    {pointer}"))
}

/// A list of exactly `N` items into an array: serde's own arrays ignore extra items in
/// some formats (TOML's `[1, 2, 3, 4]` read as three numbers); this refuses them, at the
/// list's own place in the file. For `#[serde(deserialize_with = "...")]`.
pub fn exact<'de, D, T, const N: usize>(d: D) -> Result<[T; N], D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::Deserialize<'de>,
{
    let v: Vec<T> = serde::Deserialize::deserialize(d)?;
    let found = v.len();
    v.try_into().map_err(|_| serde::de::Error::custom(format!("expected {N} numbers, found {found}")))
}

/// [`exact`] for an optional field (use with `#[serde(default)]`).
pub fn exact_opt<'de, D, T, const N: usize>(d: D) -> Result<Option<[T; N]>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::Deserialize<'de>,
{
    exact(d).map(Some)
}

/// A 4x4 matrix as exactly 4 rows of exactly 4 numbers.
pub fn rows<'de, D>(d: D) -> Result<[[f64; 4]; 4], D::Error>
where
    D: serde::Deserializer<'de>,
{
    let v: Vec<Vec<f64>> = serde::Deserialize::deserialize(d)?;
    let found = v.len();
    let mut out = [[0.0; 4]; 4];
    if found != 4 {
        return Err(serde::de::Error::custom(format!("expected 4 rows of 4 numbers, found {found} rows")));
    }
    for (i, r) in v.into_iter().enumerate() {
        let n = r.len();
        out[i] = r.try_into().map_err(|_| {
            serde::de::Error::custom(format!("expected 4 rows of 4 numbers, found {n} numbers in row {}", i + 1))
        })?;
    }
    Ok(out)
}

/// [`rows`] for an optional field (use with `#[serde(default)]`).
pub fn rows_opt<'de, D>(d: D) -> Result<Option<[[f64; 4]; 4]>, D::Error>
where
    D: serde::Deserializer<'de>,
{
    rows(d).map(Some)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn misspellings_get_the_closest_name_and_strangers_none() {
        assert_eq!(edit_distance("shinyness", "shininess"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(
            closest("constant_atenuation", ["linear_attenuation", "constant_attenuation"]),
            Some("constant_attenuation")
        );
        assert_eq!(closest("zzz", ["ambient", "diffuse"]), None);
        let m = with_suggestion("unknown field `shinyness`, expected one of `preset`, `ambient`, `shininess`");
        assert!(m.ends_with("did you mean `shininess`?"), "{m}");
        assert_eq!(with_suggestion("unknown field `q`, expected `kind`"), "unknown field `q`, expected `kind`");
        assert_eq!(with_suggestion("invalid type"), "invalid type");
        // In Portuguese, serde's common messages too.
        use crate::locale::{Lang, Locale, with_locale};
        let pt = |m: &str| with_locale(Locale::of(Lang::PtPt), || with_suggestion(m));
        assert_eq!(
            pt("unknown field `shinyness`, expected one of `preset`, `shininess`"),
            "campo desconhecido `shinyness`; os campos aceites são `preset`, `shininess`; queria dizer `shininess`?"
        );
        assert_eq!(pt("missing field `kind`"), "falta o campo `kind`");
        // serde's Rust words (`f64`, `string`) said as kinds a student knows.
        assert_eq!(
            pt("invalid type: string \"a\", expected f64"),
            "tipo inválido: o texto \"a\", esperava-se um número"
        );
        assert_eq!(
            pt("invalid type: boolean `true`, expected a string"),
            "tipo inválido: true ou false, esperava-se um texto (entre aspas)"
        );
        assert_eq!(with_locale(Locale::of(Lang::PtBr), || place("a\nbc", 3).0), "linha 2, coluna 2");
    }

    #[test]
    fn a_place_in_a_huge_line_is_a_short_excerpt() {
        let huge = format!("a = 1\nposition = [{}x]\n", "1, ".repeat(1_000_000));
        let at = huge.find('x').unwrap();
        let (where_, excerpt) = place(&huge, at);
        assert_eq!(where_, format!("line 2, column {}", 13 + 3_000_000));
        assert!(excerpt.len() < 200, "{} bytes", excerpt.len());
        let lines: Vec<&str> = excerpt.lines().collect();
        let caret = lines[1].chars().position(|c| c == '^').unwrap();
        assert_eq!(lines[0].chars().nth(caret), Some('x'), "{excerpt}");
        let (where_, excerpt) = place("k = [1, 2]\n", 4);
        assert_eq!(where_, "line 1, column 5");
        assert_eq!(excerpt, "    k = [1, 2]\n        ^");
        assert_eq!(shortened("abcdef", 4), "abc…");
        let long = format!("  ns = {}  ", "A".repeat(15 << 20));
        let q = quoted_line(&long);
        assert_eq!(q.chars().count(), QUOTE_CHARS);
        assert!(q.starts_with("ns = AAA") && q.ends_with('…'), "{q}");
    }
}
