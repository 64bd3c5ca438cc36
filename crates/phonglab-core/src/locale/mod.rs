//! The user's language and how numbers are written for them.
//!
//! Three languages: English, Português (Portugal) and Português (Brasil). Every string a
//! user reads comes from a Fluent catalogue (`crates/phonglab-core/i18n/*.ftl`, embedded at
//! build time) through [`tr`] or the [`t!`](crate::t) macro; a message missing from a
//! catalogue falls back to English (tests fail on any). Scene files, JSON and CSV keep
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

use std::cell::Cell;
use std::sync::atomic::{AtomicU8, Ordering};

pub use catalogue::{Arg, has_message, message_ids, tr, tr_args, tr_in};

/// A language phonglab speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// European Portuguese (the worksheet's).
    PtPt,
    /// Brazilian Portuguese (the Phong demo's).
    PtBr,
}

impl Lang {
    /// Every language, in the menu's order.
    pub const ALL: [Lang; 3] = [Lang::En, Lang::PtPt, Lang::PtBr];

    /// Its BCP 47 tag: `en`, `pt-PT`, `pt-BR`.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::PtPt => "pt-PT",
            Lang::PtBr => "pt-BR",
        }
    }

    /// Its name in itself, for the menu.
    pub fn name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::PtPt => "Português (Portugal)",
            Lang::PtBr => "Português (Brasil)",
        }
    }

    /// Reads a tag or a POSIX locale: `pt-BR`, `pt_BR.UTF-8`, `pt_PT`, `pt` (Portugal's),
    /// `en_GB`, `C`. `None` for a language phonglab does not speak.
    pub fn parse(text: &str) -> Option<Lang> {
        let t = text.trim().split(['.', '@']).next().unwrap_or("").replace('_', "-").to_ascii_lowercase();
        match t.as_str() {
            "pt-br" => Some(Lang::PtBr),
            "pt" | "pt-pt" => Some(Lang::PtPt),
            "c" | "posix" => Some(Lang::En),
            _ if t.starts_with("pt-") => Some(Lang::PtPt),
            _ if t == "en" || t.starts_with("en-") => Some(Lang::En),
            _ => None,
        }
    }

    /// The system's language: the first of `LC_ALL`, `LC_MESSAGES` and `LANG` that is set
    /// (as POSIX orders them), English when none names a language phonglab speaks.
    pub fn from_env() -> Lang {
        Self::from_vars(|k| std::env::var(k).ok())
    }

    /// [`Self::from_env`] over a given environment.
    pub fn from_vars(get: impl Fn(&str) -> Option<String>) -> Lang {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .into_iter()
            .filter_map(get)
            .find(|v| !v.is_empty())
            .and_then(|v| Lang::parse(&v))
            .unwrap_or_default()
    }

    /// The decimal mark the language writes: a comma in Portuguese.
    pub fn decimal_mark(self) -> DecimalMark {
        match self {
            Lang::En => DecimalMark::Point,
            Lang::PtPt | Lang::PtBr => DecimalMark::Comma,
        }
    }
}

/// How numbers meant for people are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum DecimalMark {
    /// 0.5
    #[default]
    Point,
    /// 0,5
    Comma,
}

impl DecimalMark {
    /// Reads `point` or `comma`.
    pub fn parse(text: &str) -> Option<DecimalMark> {
        match text.trim().to_ascii_lowercase().as_str() {
            "point" | "." => Some(DecimalMark::Point),
            "comma" | "," => Some(DecimalMark::Comma),
            _ => None,
        }
    }
}

/// A language and its decimal mark.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Locale {
    /// The language.
    pub lang: Lang,
    /// The decimal mark.
    pub decimal: DecimalMark,
}

impl Locale {
    /// `lang` with its own decimal mark.
    pub fn of(lang: Lang) -> Locale {
        Locale { lang, decimal: lang.decimal_mark() }
    }
}

static DEFAULT: AtomicU8 = AtomicU8::new(0);

thread_local! {
    static THREAD: Cell<Option<Locale>> = const { Cell::new(None) };
}

fn pack(l: Locale) -> u8 {
    let lang = Lang::ALL.iter().position(|x| *x == l.lang).unwrap_or(0) as u8;
    lang | (u8::from(l.decimal == DecimalMark::Comma) << 4)
}

fn unpack(b: u8) -> Locale {
    let lang = Lang::ALL.get(usize::from(b & 0x0f)).copied().unwrap_or_default();
    Locale { lang, decimal: if b & 0x10 != 0 { DecimalMark::Comma } else { DecimalMark::Point } }
}

/// Sets the process's default locale (the command line's, or the system's).
pub fn set_default(l: Locale) {
    DEFAULT.store(pack(l), Ordering::Relaxed);
}

/// The process's default locale.
pub fn default_locale() -> Locale {
    unpack(DEFAULT.load(Ordering::Relaxed))
}

/// Sets this thread's locale (`None`: the process's default).
pub fn set_thread(l: Option<Locale>) {
    THREAD.with(|c| c.set(l));
}

/// The locale in force on this thread.
pub fn current() -> Locale {
    THREAD.with(|c| c.get()).unwrap_or_else(|| unpack(DEFAULT.load(Ordering::Relaxed)))
}

/// Runs `f` with `l` as this thread's locale, then puts the old one back.
pub fn with_locale<R>(l: Locale, f: impl FnOnce() -> R) -> R {
    let old = THREAD.with(|c| c.replace(Some(l)));
    let r = f();
    THREAD.with(|c| c.set(old));
    r
}

/// `text` with every decimal point between two digits written as the locale's mark
/// (`0.5` as `0,5` in Portuguese): for numbers formatted for people.
pub fn decimal(text: &str) -> String {
    if current().decimal == DecimalMark::Point {
        return text.to_string();
    }
    let chars: Vec<char> = text.chars().collect();
    let digit = |i: Option<&char>| i.is_some_and(|c| c.is_ascii_digit());
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
        trim(&format!("{:.*}", decimals, x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
