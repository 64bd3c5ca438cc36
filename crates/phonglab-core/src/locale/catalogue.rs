//! The Fluent catalogues, one per language, embedded at build time, and message lookup.
//!
//! A [`Catalogue`] is one or more Fluent sources per language, read into one bundle per
//! language the first time a message is asked for, and never again. The core's is
//! [`CORE`], its own messages only (`crates/phonglab-core/i18n/`); the app builds its own
//! from its messages and the core's (`phonglab::locale`), so one lookup finds both.

use std::sync::OnceLock;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};

use super::lang::{Lang, current};

/// The core's catalogues' text, in [`Lang::ALL`]'s order.
pub const CORE_SOURCES: [&str; 3] =
    [include_str!("../../i18n/en.ftl"), include_str!("../../i18n/pt-PT.ftl"), include_str!("../../i18n/pt-BR.ftl")];

/// The core's messages, which all the core's own lookups read.
pub static CORE: Catalogue = Catalogue::new(&[CORE_SOURCES]);

/// Fluent sources, each in the three languages of [`Lang::ALL`] in its order, looked up as
/// one: a message is found in whichever source has it (the first, if two did; the tests
/// keep every id in one), and may name a message of any of them.
pub struct Catalogue {
    sources: &'static [[&'static str; 3]],
    bundles: OnceLock<[FluentBundle<FluentResource>; 3]>,
}

impl Catalogue {
    /// The catalogue of `sources`; nothing is read until a message is asked for.
    pub const fn new(sources: &'static [[&'static str; 3]]) -> Self {
        Catalogue { sources, bundles: OnceLock::new() }
    }

    fn bundle(&self, lang: Lang) -> &FluentBundle<FluentResource> {
        let bundles = self.bundles.get_or_init(|| {
            Lang::ALL.map(|lang| {
                let id = lang.code().parse().unwrap_or_default();
                let mut b = FluentBundle::new_concurrent(vec![id]);
                // No Unicode isolation marks around arguments: the fonts have no glyph for them.
                b.set_use_isolating(false);
                for source in self.sources {
                    // A catalogue that does not parse keeps the messages that do (tests fail on it).
                    let text = source[index(lang)].to_string();
                    let res = FluentResource::try_new(text).unwrap_or_else(|(res, _)| res);
                    let _ = b.add_resource(res);
                }
                b
            })
        });
        &bundles[index(lang)]
    }

    /// Message `id` in `lang`, with `args`; English when `lang`'s sources lack it, and the
    /// id itself when none has it.
    pub fn tr_in(&self, lang: Lang, id: &str, args: &[(&str, Arg)]) -> String {
        let fargs = (!args.is_empty()).then(|| {
            let mut a = FluentArgs::new();
            for (k, v) in args {
                match v {
                    Arg::Text(s) => a.set(*k, FluentValue::from(s.clone())),
                    Arg::Count(n) => a.set(*k, FluentValue::from(*n)),
                }
            }
            a
        });
        for l in [lang, Lang::En] {
            let b = self.bundle(l);
            if let Some(pattern) = b.get_message(id).and_then(|m| m.value()) {
                let mut errors = Vec::new();
                return b.format_pattern(pattern, fargs.as_ref(), &mut errors).into_owned();
            }
        }
        id.to_string()
    }

    /// Does one of `lang`'s sources have message `id`?
    pub fn has_message(&self, lang: Lang, id: &str) -> bool {
        self.bundle(lang).get_message(id).is_some_and(|m| m.value().is_some())
    }
}

/// `lang`'s place in [`Lang::ALL`], and so in a catalogue's sources.
fn index(lang: Lang) -> usize {
    Lang::ALL.iter().position(|l| *l == lang).unwrap_or(0)
}

/// Every message id of one Fluent source, in file order.
pub fn ids_of(source: &str) -> Vec<String> {
    source
        .lines()
        .filter(|l| l.starts_with(|c: char| c.is_ascii_alphabetic()))
        .filter_map(|l| l.split_once(" =").map(|(id, _)| id.trim().to_string()))
        .collect()
}

/// An argument of a message.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// Text (numbers formatted for people are text too, in the locale's decimal mark).
    Text(String),
    /// A count, for plurals ("1 luz", "3 luzes").
    Count(i64),
}

impl From<&str> for Arg {
    fn from(s: &str) -> Self {
        Arg::Text(s.to_string())
    }
}

impl From<String> for Arg {
    fn from(s: String) -> Self {
        Arg::Text(s)
    }
}

impl From<&String> for Arg {
    fn from(s: &String) -> Self {
        Arg::Text(s.clone())
    }
}

impl From<usize> for Arg {
    fn from(n: usize) -> Self {
        Arg::Count(n as i64)
    }
}

impl From<i64> for Arg {
    fn from(n: i64) -> Self {
        Arg::Count(n)
    }
}

impl From<u32> for Arg {
    fn from(n: u32) -> Self {
        Arg::Count(i64::from(n))
    }
}

/// Message `id` of the core's catalogue in `lang`, with `args`; English when `lang`'s
/// catalogue lacks it, and the id itself when no catalogue has it.
pub fn tr_in(lang: Lang, id: &str, args: &[(&str, Arg)]) -> String {
    CORE.tr_in(lang, id, args)
}

/// Message `id` in the current language.
pub fn tr(id: &str) -> String {
    tr_in(current().lang, id, &[])
}

/// Message `id` in the current language, with arguments.
pub fn tr_args(id: &str, args: &[(&str, Arg)]) -> String {
    tr_in(current().lang, id, args)
}

/// Does `lang`'s core catalogue have message `id`?
pub fn has_message(lang: Lang, id: &str) -> bool {
    CORE.has_message(lang, id)
}

/// Every message id of `lang`'s core catalogue, in file order.
pub fn message_ids(lang: Lang) -> Vec<String> {
    ids_of(CORE_SOURCES[index(lang)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_catalogue_parses_and_has_every_message() {
        for (k, lang) in Lang::ALL.iter().enumerate() {
            if let Err((_, errors)) = FluentResource::try_new(CORE_SOURCES[k].to_string()) {
                panic!("{}: {errors:?}", lang.code());
            }
        }
        let en = message_ids(Lang::En);
        assert!(en.len() > 50, "{}", en.len());
        for lang in [Lang::PtPt, Lang::PtBr] {
            let ids = message_ids(lang);
            let missing: Vec<&String> = en.iter().filter(|id| !ids.contains(id)).collect();
            let extra: Vec<&String> = ids.iter().filter(|id| !en.contains(id)).collect();
            assert!(missing.is_empty(), "{} lacks {missing:?}", lang.code());
            assert!(extra.is_empty(), "{} has messages English lacks: {extra:?}", lang.code());
        }
    }

    #[test]
    fn plurals_follow_the_language() {
        assert_eq!(tr_in(Lang::PtPt, "lights-count", &[("count", Arg::Count(1))]), "1 luz");
        assert_eq!(tr_in(Lang::PtPt, "lights-count", &[("count", Arg::Count(3))]), "3 luzes");
        assert_eq!(tr_in(Lang::En, "lights-count", &[("count", Arg::Count(1))]), "1 light");
        assert_eq!(tr_in(Lang::En, "lights-count", &[("count", Arg::Count(3))]), "3 lights");
    }
}
