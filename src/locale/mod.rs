//! The app's words: its own Fluent catalogue (`i18n/*.ftl` at the repository's root: the
//! window's, the command line's and the files' messages), looked up together with the
//! core's (`crates/phonglab-core/i18n/`).
//!
//! Everything else of the core's [`phonglab_core::locale`] is here as it is there (the
//! language, the decimal mark, numbers for people), so the app names one module. A message
//! lives in the core's catalogue when the core's sources use it, the app's included, and in
//! the app's when only the app's do; `scripts/split-catalogue.py` sorts them, and
//! `tests/i18n.rs` checks that each catalogue holds only what its crate uses and no id is in
//! both.
//!
//! One lookup: the app's messages and the core's are read into one bundle per language,
//! once ([`APP`]), so a message costs what it did when there was one catalogue, and an app
//! message may name a core message (`{ specular-model }`).

pub use phonglab_core::locale::*;

/// The app's catalogues' text, in [`Lang::ALL`]'s order.
pub const APP_SOURCES: [&str; 3] =
    [include_str!("../../i18n/en.ftl"), include_str!("../../i18n/pt-PT.ftl"), include_str!("../../i18n/pt-BR.ftl")];

/// The app's messages and then the core's: every lookup of the app.
pub static APP: Catalogue = Catalogue::new(&[APP_SOURCES, CORE_SOURCES]);

/// Message `id` (the app's or the core's) in `lang`, with `args`; English when `lang`'s
/// catalogue lacks it, and the id itself when no catalogue has it.
pub fn tr_in(lang: Lang, id: &str, args: &[(&str, Arg)]) -> String {
    APP.tr_in(lang, id, args)
}

/// Message `id` (the app's or the core's) in the current language.
pub fn tr(id: &str) -> String {
    tr_in(current().lang, id, &[])
}

/// Message `id` (the app's or the core's) in the current language, with arguments.
pub fn tr_args(id: &str, args: &[(&str, Arg)]) -> String {
    tr_in(current().lang, id, args)
}

/// Does `lang`'s app or core catalogue have message `id`?
pub fn has_message(lang: Lang, id: &str) -> bool {
    APP.has_message(lang, id)
}

/// Every message id of `lang`'s app catalogue (the app's own, not the core's), in file order.
pub fn message_ids(lang: Lang) -> Vec<String> {
    ids_of(APP_SOURCES[Lang::ALL.iter().position(|l| *l == lang).unwrap_or(0)])
}

/// Looks up a message of the app or the core: `t!("id")`, or with arguments
/// `t!("id", name = value, ...)` (strings, or counts for plurals). A missing message gives
/// its id. The app's `t!`: the core's (`phonglab_core::t!`) knows only the core's messages.
#[macro_export]
macro_rules! t {
    ($id:literal) => {
        $crate::locale::tr($id)
    };
    ($id:literal, $($k:ident = $v:expr),+ $(,)?) => {
        $crate::locale::tr_args($id, &[$((stringify!($k), $crate::locale::Arg::from($v))),+])
    };
}
