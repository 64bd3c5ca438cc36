//! The page the app runs in: in the browser, its own address, which a shared link opens
//! (the link's base); the desktop has none, and its links open the published page
//! ([`phonglab_core::export::share::DEFAULT_BASE`]).

/// The page's address without its fragment, in the browser; `None` on the desktop.
#[cfg(target_arch = "wasm32")]
pub fn own_address() -> Option<String> {
    let href = web_sys::window()?.location().href().ok()?;
    Some(href.split('#').next().unwrap_or(&href).to_string())
}

/// The page's address without its fragment, in the browser; `None` on the desktop.
#[cfg(not(target_arch = "wasm32"))]
pub fn own_address() -> Option<String> {
    None
}
