//! The session kept while the window runs: one loop for the desktop and the browser.
//!
//! At the start the state is restored from the session ([`restore`]); after each frame the
//! scene, the layout and the quiz are put back into the session when the scene or the
//! layout changed (or half a minute passed: the quiz's answers), and the session is written
//! when that is due: on the desktop every [`DESKTOP_EVERY`] (a file, written whole), in the
//! browser at most every [`BROWSER_EVERY`] (`localStorage`, written synchronously, so a drag
//! does not write it every frame). A change not written yet asks for the frame that will
//! write it; a failure is said in the window, once.

use phonglab_core::Document;

use super::layout::Layout;
use super::session::{self, Session};
use super::state::{AppState, Message};
use crate::platform::clock::{Duration, Instant};

/// How often the desktop writes its session file while the window is open.
pub const DESKTOP_EVERY: Duration = Duration::from_secs(30);

/// How often, at most, the browser keeps its session while it changes.
pub const BROWSER_EVERY: Duration = Duration::from_millis(250);

/// How long the quiz's answers wait for a change of the scene before they are kept.
const QUIZ_EVERY: Duration = Duration::from_secs(30);

/// The session and what the loop knows of it.
pub struct SessionLoop {
    session: Session,
    /// The scene and layout last put into the session, so an unchanged frame costs one
    /// comparison.
    kept: Option<(Document, Layout)>,
    /// When the session's values were last updated.
    last_store: Instant,
    /// When the session was last written (or tried).
    last_write: Instant,
    /// The session changed since it was last written.
    pending: bool,
    every: Duration,
}

/// The state restored from `session` (the scene, the layout), with what the user should be
/// told about it (`notices`: what was found when the session was opened).
pub fn restore(session: &Session, notices: Vec<String>) -> AppState {
    let mut state = AppState::worksheet();
    state.ui.layout = Layout::from_ron(session.get(super::layout::LAYOUT_KEY));
    let mut said = notices;
    match session::restore_document(session.get(session::DOCUMENT_KEY), session.dir()) {
        Ok(Some((doc, note))) => {
            state.doc = doc;
            said.extend(note);
        }
        Ok(None) => {}
        Err(m) => said.push(m),
    }
    for m in &said {
        log::warn!("{m}");
    }
    if !said.is_empty() {
        state.message = Some(Message::Refused(said.join(" ")));
    }
    state
}

/// Puts the state's lasting parts (the scene, the layout, the quiz) into the session.
pub fn store(state: &AppState, session: &mut Session) {
    if let Ok(text) = state.doc.to_toml() {
        session.set(session::DOCUMENT_KEY, text);
    }
    session.set(super::layout::LAYOUT_KEY, state.ui.layout.to_ron());
    if let Some(q) = state.quiz.to_ron() {
        session.set(crate::app::panels::quiz::QUIZ_KEY, q);
    }
}

impl SessionLoop {
    /// The loop over `session`, writing it at most every `every`.
    pub fn new(session: Session, every: Duration) -> Self {
        SessionLoop {
            session,
            kept: None,
            last_store: Instant::now(),
            last_write: Instant::now(),
            pending: false,
            every,
        }
    }

    /// The session.
    pub fn session(&self) -> &Session {
        &self.session
    }

    /// After a frame: puts the state's lasting parts into the session when the scene or the
    /// layout changed (or the quiz waited long enough); returns the session's new text then.
    pub fn after_frame(&mut self, state: &AppState) -> Option<String> {
        let now = (&state.doc, &state.ui.layout);
        let unchanged = self.kept.as_ref().is_some_and(|(d, l)| (d, l) == now);
        if unchanged && self.last_store.elapsed() < QUIZ_EVERY {
            return None;
        }
        self.kept = Some((now.0.clone(), now.1.clone()));
        self.last_store = Instant::now();
        store(state, &mut self.session);
        self.pending = true;
        Some(self.session.text())
    }

    /// Writes the session when a change waits and `every` has passed since the last write;
    /// a change that must wait asks for the frame that will write it.
    pub fn write_when_due(&mut self, state: &mut AppState, ctx: &egui::Context) {
        if !self.pending {
            return;
        }
        let since = self.last_write.elapsed();
        if since < self.every {
            ctx.request_repaint_after(self.every.checked_sub(since).unwrap());
            return;
        }
        self.write_now(state);
    }

    /// Writes the session now (the window closes, the system asks the process to end).
    pub fn write_now(&mut self, state: &mut AppState) {
        store(state, &mut self.session);
        self.last_write = Instant::now();
        self.pending = false;
        if let Err(e) = self.session.save() {
            log::error!("{e}");
            state.message = Some(Message::Refused(crate::t!("session-not-saved", error = e)));
        }
    }
}
