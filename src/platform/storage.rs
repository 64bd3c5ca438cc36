//! Where the app keeps its session: on the desktop a folder ([`storage_dir`], the session
//! file and its lock in it: [`crate::app::shell::session`]); in the browser the page's
//! `localStorage` (`load_browser_session`, `save_browser_session`), one entry that
//! holds the same RON text as the desktop's `session.ron`. A mesh opened in the page (which
//! has no path to read it from again) is kept in `sessionStorage` for the page's session
//! ([`keep_mesh`], and `restore_meshes` at the page's start).

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
    let storage = local_storage().ok_or_else(|| crate::t!("browser-no-storage"))?;
    storage.set_item(BROWSER_KEY, text).map_err(|e| crate::t!("browser-storage-refused", error = format!("{e:?}")))
}

#[cfg(target_arch = "wasm32")]
fn local_storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok().flatten()
}

/// The `sessionStorage` key of the mesh opened in the page: its name, a line break, and
/// the file packed ([`phonglab_core::export::share::pack_bytes`]).
pub const MESH_KEY: &str = "phonglab.mesh";

/// The most characters of a packed mesh kept: browsers keep about 5 million characters
/// an origin in `sessionStorage`, and the session needs some of it.
pub const MESH_KEPT_CHARS: usize = 4_000_000;

/// Keeps the mesh file `bytes`, named `name`, for a reload of the page (the browser); `Err`
/// says, in the user's language, that it is not kept and why. The desktop reads a mesh
/// from its file, so has nothing to keep.
#[cfg(not(target_arch = "wasm32"))]
pub fn keep_mesh(_name: &str, _bytes: &[u8]) -> Result<(), String> {
    Ok(())
}

/// Keeps the mesh file `bytes`, named `name`, for a reload of the page; `Err` says, in the
/// user's language, that it is not kept and why.
#[cfg(target_arch = "wasm32")]
pub fn keep_mesh(name: &str, bytes: &[u8]) -> Result<(), String> {
    let storage = web_sys::window()
        .and_then(|w| w.session_storage().ok().flatten())
        .ok_or_else(|| crate::t!("mesh-not-kept", why = crate::t!("browser-no-storage")))?;
    let packed = phonglab_core::export::share::pack_bytes(bytes);
    if packed.len() > MESH_KEPT_CHARS {
        let _ = storage.remove_item(MESH_KEY);
        return Err(crate::t!(
            "mesh-not-kept",
            why = crate::t!("mesh-too-large-to-keep", packed = packed.len(), most = MESH_KEPT_CHARS)
        ));
    }
    storage.set_item(MESH_KEY, &format!("{name}\n{packed}")).map_err(|e| {
        let _ = storage.remove_item(MESH_KEY);
        crate::t!("mesh-not-kept", why = format!("{e:?}"))
    })
}

/// Holds again the mesh this page's session kept ([`keep_mesh`]), so that the session's
/// scene, which names it, shows it. `Err` with a message for the student, in the current
/// language, when one was kept but could not be read back (then it is forgotten).
#[cfg(target_arch = "wasm32")]
pub fn restore_meshes() -> Result<(), String> {
    let Some(storage) = web_sys::window().and_then(|w| w.session_storage().ok().flatten()) else {
        return Ok(());
    };
    let Some(kept) = storage.get_item(MESH_KEY).ok().flatten() else {
        return Ok(());
    };
    let (name, packed) = kept.split_once('\n').unwrap_or(("?", ""));
    let held = phonglab_core::export::share::unpack_bytes(packed, phonglab_core::mesh::obj::MAX_OBJ_BYTES as usize)
        .map_err(|e| e.to_string())
        .and_then(|bytes| phonglab_core::mesh::obj::hold_obj_bytes(name, &bytes));
    held.map(|_| ()).map_err(|why| {
        let _ = storage.remove_item(MESH_KEY);
        crate::t!("mesh-not-restored", name = name, why = why)
    })
}

#[cfg(test)]
mod tests {
    /// Windows: the session lives in the user's roaming application data (`%APPDATA%`,
    /// `C:\Users\João\AppData\Roaming`), which follows the student from one lab PC to
    /// another where the school roams profiles.
    #[test]
    #[cfg(windows)]
    fn the_windows_session_is_in_appdata() {
        if std::env::var_os("PHONGLAB_SESSION_DIR").is_some() {
            return;
        }
        let appdata = std::path::PathBuf::from(std::env::var_os("APPDATA").expect("Windows sets APPDATA"));
        assert_eq!(super::storage_dir(), Some(appdata.join("phonglab").join("data")));
        assert!(appdata.is_dir(), "{}", appdata.display());
    }
}
