//! Which language and decimal mark: per thread, over a process-wide default.

use std::cell::Cell;
use std::sync::atomic::{AtomicU8, Ordering};

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
    THREAD.with(std::cell::Cell::get).unwrap_or_else(|| unpack(DEFAULT.load(Ordering::Relaxed)))
}

/// Runs `f` with `l` as this thread's locale, then puts the old one back.
pub fn with_locale<R>(l: Locale, f: impl FnOnce() -> R) -> R {
    let old = THREAD.with(|c| c.replace(Some(l)));
    let r = f();
    THREAD.with(|c| c.set(old));
    r
}
