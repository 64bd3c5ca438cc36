//! The user's language as the system says it: the POSIX variables on the desktop
//! (`LC_ALL`, `LC_MESSAGES`, `LANG`); on Windows and macOS, where those are seldom set
//! (a program started from the Start menu or the Finder has none), the language of the
//! user's settings when none of them is (`sys-locale`: on Windows the display language,
//! `GetUserPreferredUILanguages`, not the regional format; on macOS the first preferred
//! language, `CFLocaleCopyPreferredLanguages`); the browser's preferred languages on the web (`navigator.languages`, then
//! `navigator.language`).

use crate::locale::Lang;

/// The system's language, English when it is none phonglab speaks.
pub fn system() -> Lang {
    #[cfg(not(target_arch = "wasm32"))]
    {
        let from_variables =
            ["LC_ALL", "LC_MESSAGES", "LANG"].into_iter().any(|k| std::env::var_os(k).is_some_and(|v| !v.is_empty()));
        chosen(from_variables.then(Lang::from_env), settings().as_deref())
    }
    #[cfg(target_arch = "wasm32")]
    {
        browser().unwrap_or(Lang::En)
    }
}

/// The variables' language where one is set, else the settings' (a BCP 47 tag: `pt-BR`),
/// else English.
#[cfg(not(target_arch = "wasm32"))]
pub fn chosen(from_variables: Option<Lang>, settings: Option<&str>) -> Lang {
    from_variables.or_else(|| settings.and_then(Lang::parse)).unwrap_or_default()
}

/// The language of the user's settings (Windows, macOS); none elsewhere (the variables
/// are the settings there).
#[cfg(not(target_arch = "wasm32"))]
pub fn settings() -> Option<String> {
    #[cfg(any(windows, target_os = "macos"))]
    {
        sys_locale::get_locale()
    }
    #[cfg(not(any(windows, target_os = "macos")))]
    {
        None
    }
}

/// The first of the browser's languages that phonglab speaks.
#[cfg(target_arch = "wasm32")]
fn browser() -> Option<Lang> {
    let navigator = web_sys::window()?.navigator();
    let listed: Vec<String> = navigator.languages().iter().filter_map(|v| v.as_string()).collect();
    listed.iter().chain(navigator.language().iter()).find_map(|tag| Lang::parse(tag))
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::*;

    #[test]
    fn the_variables_win_then_the_settings_then_english() {
        assert_eq!(chosen(Some(Lang::PtPt), Some("pt-BR")), Lang::PtPt);
        assert_eq!(chosen(None, Some("pt-BR")), Lang::PtBr);
        assert_eq!(chosen(None, Some("pt-PT")), Lang::PtPt);
        assert_eq!(chosen(None, Some("de-DE")), Lang::En);
        assert_eq!(chosen(None, None), Lang::En);
    }

    /// Windows' settings give a tag phonglab reads (under Wine, the one its prefix was
    /// made with); the variables are English here so the two are told apart.
    #[test]
    #[cfg(windows)]
    fn windows_settings_give_a_language_tag() {
        let tag = settings().expect("GetUserDefaultLocaleName gives a tag");
        assert!(tag.len() >= 2 && tag.chars().all(|c| c.is_ascii_alphanumeric() || c == '-'), "{tag}");
    }
}
