//! A shared link opened: the scene it carries and the window's choices it asks for (the
//! language, presenting, the term shown), or, where the link is old, damaged or hostile, the
//! scene as it was and a message that says why. (The browser reads its address's fragment;
//! [`phonglab_core::export::share`] reads the link.) A scene that shows a mesh opens on the
//! sphere and asks for the mesh's file by name, unless that file was opened already.

use phonglab_core::channels::Channel;
use phonglab_core::export::share;

use super::state::AppState;
use crate::app::editing::message::Message;
use crate::t;

/// Opens the link's `fragment` (after `#`) in `state`.
pub fn open_fragment(state: &mut AppState, fragment: &str) {
    match share::decode(fragment) {
        Ok(s) => open_shared(state, s),
        Err(e) => state.message = Some(Message::Refused(t!("share-not-opened", why = e.to_string()))),
    }
}

/// Opens what a link carries, `s` (read by [`share::decode`]), in `state`: its scene, and
/// the language, presenting and term it asks for.
pub fn open_shared(state: &mut AppState, s: share::Shared) {
    // The link's language first, so that what is said of it is said in it.
    if let Some(lang) = &s.lang {
        state.ui.layout.language = Some(lang.clone());
    }
    let locale = state.ui.layout.locale();
    let name = s.doc.name.clone();
    crate::locale::with_locale(locale, || {
        state.load(s.doc, &t!("share-opened", name = name));
        if let Some(mesh) = &s.missing_mesh {
            state.message = Some(Message::Info(t!("share-needs-mesh", name = mesh.clone())));
        }
    });
    state.ui.layout.presenting |= s.present;
    state.view_options.channel = s.channel.and_then(|c| Channel::ALL.into_iter().find(|k| k.name() == c));
}

/// The window's choices a link carries (its language, presenting, the term shown), taken
/// by `state` without opening its scene again (`phonglab screenshot --scene LINK`).
pub fn take_choices(state: &mut AppState, s: &share::Shared) {
    if let Some(lang) = &s.lang {
        state.ui.layout.language = Some(lang.clone());
    }
    state.ui.layout.presenting |= s.present;
    state.view_options.channel = s.channel.as_deref().and_then(|c| Channel::ALL.into_iter().find(|k| k.name() == c));
}
