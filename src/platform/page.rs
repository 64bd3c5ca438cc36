//! The page the app runs in: in the browser, its own address, which a shared link opens
//! (the link's base); the desktop has none, and its links open the published page
//! ([`phonglab_core::export::share::DEFAULT_BASE`]).

/// The page's address without its query or fragment (a link must not carry the sharer's
/// `?open=` or `?renderer=`), in the browser; `None` on the desktop.
#[cfg(target_arch = "wasm32")]
pub fn own_address() -> Option<String> {
    let location = web_sys::window()?.location();
    Some(format!("{}{}", location.origin().ok()?, location.pathname().ok()?))
}

/// The page's address without its query or fragment, in the browser; `None` on the desktop.
#[cfg(not(target_arch = "wasm32"))]
pub fn own_address() -> Option<String> {
    None
}
