//! Ending without losing the session: Ctrl+Q, closing the window, and the signals a lab
//! PC's logout sends (SIGTERM, SIGHUP) or Ctrl+C in the terminal (SIGINT).
//!
//! The window keeps a copy of its session's text, brought up to date whenever it changes
//! ([`Shutdown::keep`]). On a signal the handler's thread writes that copy at once (the
//! window's event loop may already be gone with the display), then asks the window to close,
//! which saves once more through its normal exit; a window that has not closed 3 seconds
//! later, or a second signal, ends the process.

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// The shared state between the window and the signal handler.
#[derive(Clone, Default)]
pub struct Shutdown {
    requested: Arc<AtomicBool>,
    latest: Arc<Mutex<Option<(PathBuf, String)>>>,
}

impl Shutdown {
    /// Installs the handler: a signal saves the latest session text and asks `ctx`'s window
    /// to close. Failing to install it (no signals on this system) is logged, not fatal.
    pub fn install(ctx: &egui::Context) -> Shutdown {
        let me = Shutdown::default();
        let (handler, ctx) = (me.clone(), ctx.clone());
        let installed = crate::platform::os::on_termination(move |signal| handler.on_signal(signal, &ctx));
        if let Err(e) = installed {
            log::warn!("the session will not be saved on SIGTERM/SIGHUP: {e}");
        }
        me
    }

    fn on_signal(&self, signal: i32, ctx: &egui::Context) {
        if self.requested.swap(true, Ordering::SeqCst) {
            log::warn!("signal {signal} again: ending now");
            std::process::exit(1);
        }
        log::info!("signal {signal}: saving the session and closing");
        self.write_latest();
        ctx.request_repaint();
        std::thread::sleep(Duration::from_secs(3));
        log::warn!("the window did not close within 3 s of signal {signal}; ending (the session was saved)");
        std::process::exit(0);
    }

    /// Writes the latest session text, if there is one.
    fn write_latest(&self) {
        let latest = self.latest.lock().ok().and_then(|l| l.clone());
        if let Some((path, text)) = latest
            && let Err(e) = crate::io::atomic_write::write(&path, text.as_bytes())
        {
            log::error!("{e}");
        }
    }

    /// Keeps `text` as what a signal saves to `path`.
    pub fn keep(&self, path: PathBuf, text: String) {
        if let Ok(mut l) = self.latest.lock() {
            *l = Some((path, text));
        }
    }

    /// Has a signal asked the window to close?
    pub fn requested(&self) -> bool {
        self.requested.load(Ordering::SeqCst)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_latest_text_is_what_a_signal_writes() {
        // Emptied first: Wine gives processes the same few ids, run after run.
        let dir = std::env::temp_dir().join(format!("phonglab-shutdown-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("session.ron");
        let s = Shutdown::default();
        s.write_latest();
        assert!(!path.exists(), "nothing kept, nothing written");
        s.keep(path.clone(), "first".into());
        s.keep(path.clone(), "second".into());
        s.write_latest();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "second");
        assert!(!s.requested());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
