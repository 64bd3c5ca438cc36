//! The Fluent catalogues, one per language, embedded at build time, and message lookup.

use std::sync::OnceLock;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};

use super::lang::{Lang, current};

/// The catalogues' text, in [`Lang::ALL`]'s order.
const SOURCES: [&str; 3] =
    [include_str!("../../i18n/en.ftl"), include_str!("../../i18n/pt-PT.ftl"), include_str!("../../i18n/pt-BR.ftl")];

fn bundles() -> &'static [FluentBundle<FluentResource>; 3] {
    static BUNDLES: OnceLock<[FluentBundle<FluentResource>; 3]> = OnceLock::new();
    BUNDLES.get_or_init(|| {
        Lang::ALL.map(|lang| {
            let k = Lang::ALL.iter().position(|l| *l == lang).unwrap_or(0);
            let id = lang.code().parse().unwrap_or_default();
            let mut b = FluentBundle::new_concurrent(vec![id]);
            // No Unicode isolation marks around arguments: the fonts have no glyph for them.
            b.set_use_isolating(false);
            // A catalogue that does not parse keeps the messages that do (tests fail on it).
            let res = FluentResource::try_new(SOURCES[k].to_string()).unwrap_or_else(|(res, _)| res);
            let _ = b.add_resource(res);
            b
        })
    })
}

fn bundle(lang: Lang) -> &'static FluentBundle<FluentResource> {
    &bundles()[Lang::ALL.iter().position(|l| *l == lang).unwrap_or(0)]
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

/// Message `id` in `lang`, with `args`; English when `lang`'s catalogue lacks it, and the
/// id itself when no catalogue has it.
pub fn tr_in(lang: Lang, id: &str, args: &[(&str, Arg)]) -> String {
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
        let b = bundle(l);
        if let Some(pattern) = b.get_message(id).and_then(|m| m.value()) {
            let mut errors = Vec::new();
            return b.format_pattern(pattern, fargs.as_ref(), &mut errors).into_owned();
        }
    }
    id.to_string()
}

/// Message `id` in the current language.
pub fn tr(id: &str) -> String {
    tr_in(current().lang, id, &[])
}

/// Message `id` in the current language, with arguments.
pub fn tr_args(id: &str, args: &[(&str, Arg)]) -> String {
    tr_in(current().lang, id, args)
}

/// Does `lang`'s catalogue have message `id`?
pub fn has_message(lang: Lang, id: &str) -> bool {
    bundle(lang).get_message(id).is_some_and(|m| m.value().is_some())
}

/// Every message id of `lang`'s catalogue, in file order.
pub fn message_ids(lang: Lang) -> Vec<String> {
    let k = Lang::ALL.iter().position(|l| *l == lang).unwrap_or(0);
    SOURCES[k]
        .lines()
        .filter(|l| l.starts_with(|c: char| c.is_ascii_alphabetic()))
        .filter_map(|l| l.split_once(" =").map(|(id, _)| id.trim().to_string()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_catalogue_parses_and_has_every_message() {
        for (k, lang) in Lang::ALL.iter().enumerate() {
            if let Err((_, errors)) = FluentResource::try_new(SOURCES[k].to_string()) {
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
