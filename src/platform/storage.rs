//! Where the app keeps its session: on the desktop a folder ([`storage_dir`], the session
//! file and its lock in it: [`crate::app::shell::session`]); in the browser the page's
//! `localStorage` (`load_browser_session`, `save_browser_session`), one entry that
//! holds the same RON text as the desktop's `session.ron`.

/// The folder the app keeps its session in: `PHONGLAB_SESSION_DIR` when set, else the
/// system's place for an application's data (`$XDG_DATA_HOME/phonglab` or
/// `~/.local/share/phonglab` on Linux, as eframe chose before phonglab kept it itself).
pub fn storage_dir() -> Option<std::path::PathBuf> {
    use std::path::PathBuf;
    let var = |k: &str| std::env::var_os(k).filter(|v| !v.is_empty()).map(PathBuf::from);
    if let Some(d) = var("PHONGLAB_SESSION_DIR") {
        return Some(d);
    }
    if cfg!(target_os = "windows") {
        return var("APPDATA").map(|d| d.join("phonglab").join("data"));
    }
    if cfg!(target_os = "macos") {
        return var("HOME").map(|h| h.join("Library/Application Support/phonglab"));
    }
    var("XDG_DATA_HOME").or_else(|| var("HOME").map(|h| h.join(".local/share"))).map(|d| d.join("phonglab"))
}

/// The folder a teacher puts their own experiments in ("Things to try"): `experiments`
/// beside the session ([`storage_dir`]); none in the browser, which has no folders.
pub fn experiments_dir() -> Option<std::path::PathBuf> {
    if cfg!(target_arch = "wasm32") {
        return None;
    }
    storage_dir().map(|d| d.join("experiments"))
}

/// The `localStorage` key of the browser's session.
pub const BROWSER_KEY: &str = "phonglab.session.ron";

/// The session text kept in this browser, if any.
#[cfg(target_arch = "wasm32")]
pub fn load_browser_session() -> Option<String> {
    local_storage()?.get_item(BROWSER_KEY).ok().flatten()
}

/// Keeps `text` as this browser's session; `Err` says why not (storage full or refused:
/// private windows may refuse it).
#[cfg(target_arch = "wasm32")]
pub fn save_browser_session(text: &str) -> Result<(), String> {
    let storage = local_storage().ok_or_else(|| phonglab_core::t!("browser-no-storage"))?;
    storage
        .set_item(BROWSER_KEY, text)
        .map_err(|e| phonglab_core::t!("browser-storage-refused", error = format!("{e:?}")))
}

#[cfg(target_arch = "wasm32")]
fn local_storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok().flatten()
}
