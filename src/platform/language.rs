//! The user's language as the system says it: the POSIX variables on the desktop
//! (`LC_ALL`, `LC_MESSAGES`, `LANG`), the browser's preferred languages on the web
//! (`navigator.languages`, then `navigator.language`).

use crate::locale::Lang;

/// The system's language, English when it is none phonglab speaks.
pub fn system() -> Lang {
    #[cfg(not(target_arch = "wasm32"))]
    {
        Lang::from_env()
    }
    #[cfg(target_arch = "wasm32")]
    {
        browser().unwrap_or(Lang::En)
    }
}

/// The first of the browser's languages that phonglab speaks.
#[cfg(target_arch = "wasm32")]
fn browser() -> Option<Lang> {
    let navigator = web_sys::window()?.navigator();
    let listed: Vec<String> = navigator.languages().iter().filter_map(|v| v.as_string()).collect();
    listed.iter().chain(navigator.language().iter()).find_map(|tag| Lang::parse(tag))
}
