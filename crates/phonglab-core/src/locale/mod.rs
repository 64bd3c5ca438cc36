//! The user's language and how numbers are written for them.
//!
//! Three languages: English, Português (Portugal) and Português (Brasil). Every string a
//! user reads comes from a Fluent catalogue, embedded at build time: the core's messages
//! (`crates/phonglab-core/i18n/*.ftl`) through [`tr`] or the [`t!`](crate::t) macro, the
//! app's (`i18n/*.ftl` at the repository's root) through the app's own `t!`, which reads
//! the core's too (a [`Catalogue`] of both); a message missing from a catalogue falls back
//! to English (tests fail on any). Scene files, JSON and CSV keep
//! their English keys and decimal points.
//!
//! The language is chosen by the system locale (`LC_ALL`, `LC_MESSAGES`, `LANG`:
//! [`Lang::from_env`]), overridden by `--lang` or the app's menu. It is kept per thread
//! (the app's UI thread, a test's thread) over a process-wide default, so a test in
//! Portuguese does not change the language of a test beside it.
//!
//! In Portuguese, numbers meant for people use the decimal comma (0,05958709); a setting
//! ([`DecimalMark`], `--decimal`) keeps the point. Typed numbers are read with either.

mod catalogue;
mod lang;

/// The no-break space phonglab writes between a number and its `%` (in code and in the
/// catalogues), so that a line never breaks between them and leaves `%` alone.
pub const BEFORE_PERCENT: char = '\u{a0}';

/// A share (0 to 1) as a percentage with `digits` decimals in the user's decimal mark, a
/// no-break space before the `%` (`99,4 %`): the one way phonglab writes a share.
pub fn percent(share: f64, digits: usize) -> String {
    decimal(&format!("{:.digits$}{BEFORE_PERCENT}%", 100.0 * share))
}

pub use catalogue::{Arg, CORE, CORE_SOURCES, Catalogue, has_message, ids_of, message_ids, tr, tr_args, tr_in};
pub use lang::{DecimalMark, Lang, Locale, current, default_locale, set_default, set_thread, with_locale};

/// `text` with every decimal point between two digits written as the locale's mark
/// (`0.5` as `0,5` in Portuguese): for numbers formatted for people.
pub fn decimal(text: &str) -> String {
    if current().decimal == DecimalMark::Point {
        return text.to_string();
    }
    let chars: Vec<char> = text.chars().collect();
    let digit = |i: Option<&char>| i.is_some_and(char::is_ascii_digit);
    chars
        .iter()
        .enumerate()
        .map(|(i, c)| if *c == '.' && i > 0 && digit(chars.get(i - 1)) && digit(chars.get(i + 1)) { ',' } else { *c })
        .collect()
}

/// A whole number for people, its digits in groups of three (`10 000`, `1 048 576`), as
/// both the English and the Portuguese style guides accept.
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(' ');
        }
        out.push(c);
    }
    out
}

/// A value someone gave, said back exactly but compactly, in the locale's decimal mark:
/// the shortest digits that read back as it (`0.1`, `900`), in exponent form where they
/// would run to more than 15 places (`1e300`, not its 301 digits; `2.5e-9`).
pub fn exact(x: f64) -> String {
    let a = x.abs();
    let text = if x.is_finite() && x != 0.0 && !(1e-5..1e15).contains(&a) { format!("{x:e}") } else { x.to_string() };
    decimal(&text)
}

/// A number for people: [`fmt_sig`] in the locale's decimal mark.
pub fn num(x: f64, sig: usize) -> String {
    decimal(&fmt_sig(x, sig))
}

/// Looks up a message: `t!("id")`, or with arguments `t!("id", name = value, ...)`
/// (strings, or counts for plurals). A missing message gives its id.
#[macro_export]
macro_rules! t {
    ($id:literal) => {
        $crate::locale::tr($id)
    };
    ($id:literal, $($k:ident = $v:expr),+ $(,)?) => {
        $crate::locale::tr_args($id, &[$((stringify!($k), $crate::locale::Arg::from($v))),+])
    };
}

/// Formats `x` with `sig` significant digits, trailing zeros trimmed (`0.09942795`,
/// `4.5151924e+28`, `0`); non-finite values as `NaN`, `Infinity`, `-Infinity`.
pub fn fmt_sig(x: f64, sig: usize) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "Infinity".into() } else { "-Infinity".into() };
    }
    if x == 0.0 {
        return "0".into();
    }
    let sig = sig.max(1);
    let sci = format!("{:.*e}", sig - 1, x);
    let (mant, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let trim = |s: &str| -> String {
        if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s.to_string() }
    };
    if exp < -5 || exp >= sig as i32 {
        format!("{}e{}{}", trim(mant), if exp < 0 { "-" } else { "+" }, exp.abs())
    } else {
        let decimals = (sig as i32 - 1 - exp).max(0) as usize;
        trim(&format!("{x:.decimals$}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_is_said_back_exactly_and_compactly() {
        let point = Locale { lang: Lang::En, decimal: DecimalMark::Point };
        let said = |x: f64| with_locale(point, || exact(x));
        assert_eq!(said(1e300), "1e300");
        assert_eq!(said(-1.5e300), "-1.5e300");
        assert_eq!(said(2.5e-9), "2.5e-9");
        assert_eq!(said(900.0), "900");
        assert_eq!(said(0.1), "0.1");
        assert_eq!(said(123456789012345.0), "123456789012345");
        assert_eq!(with_locale(Locale::of(Lang::PtPt), || exact(1.5e300)), "1,5e300");
    }

    #[test]
    fn the_language_is_read_from_the_system_locale() {
        assert_eq!(Lang::parse("pt_PT.UTF-8"), Some(Lang::PtPt));
        assert_eq!(Lang::parse("pt_BR.utf8"), Some(Lang::PtBr));
        assert_eq!(Lang::parse("pt"), Some(Lang::PtPt));
        assert_eq!(Lang::parse("en_GB.UTF-8"), Some(Lang::En));
        assert_eq!(Lang::parse("de_DE.UTF-8"), None);
        let env = |vars: &'static [(&'static str, &'static str)]| {
            move |k: &str| vars.iter().find(|(n, _)| *n == k).map(|(_, v)| v.to_string())
        };
        assert_eq!(Lang::from_vars(env(&[("LANG", "pt_BR.UTF-8")])), Lang::PtBr);
        assert_eq!(Lang::from_vars(env(&[("LANG", "pt_BR.UTF-8"), ("LC_ALL", "pt_PT.UTF-8")])), Lang::PtPt);
        assert_eq!(Lang::from_vars(env(&[("LC_MESSAGES", "en_US.UTF-8"), ("LANG", "pt_PT.UTF-8")])), Lang::En);
        assert_eq!(Lang::from_vars(env(&[("LC_ALL", ""), ("LANG", "pt_PT.UTF-8")])), Lang::PtPt);
        assert_eq!(Lang::from_vars(env(&[])), Lang::En);
    }

    #[test]
    fn numbers_for_people_take_the_decimal_comma_in_portuguese() {
        with_locale(Locale::of(Lang::PtPt), || {
            assert_eq!(num(0.05958709, 8), "0,05958709");
            assert_eq!(
                decimal("I = [0.05958709 0.03575929 1] in OpenGL 2.1"),
                "I = [0,05958709 0,03575929 1] in OpenGL 2,1"
            );
            assert_eq!(decimal("scene.toml, 1.5e-3, -0.25"), "scene.toml, 1,5e-3, -0,25");
        });
        with_locale(Locale { lang: Lang::PtPt, decimal: DecimalMark::Point }, || assert_eq!(num(0.5, 3), "0.5"));
        assert_eq!(num(0.5, 3), "0.5");
    }
}
