//! Work in the background: a computation on its own thread (the page's one thread in the
//! browser: [`crate::platform::threads`]), with its progress, its cancellation when
//! dropped, and its result collected by the frame that asks.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError};
use std::sync::{Arc, Mutex};

use phonglab_core::cost::Progress;

/// A computation on its own thread, with progress and cancellation.
pub struct Worker<T> {
    progress: Arc<Mutex<Progress>>,
    cancel: Arc<AtomicBool>,
    result: Receiver<Result<Option<T>, String>>,
}

impl<T: Send + 'static> Worker<T> {
    /// Starts `job` on its own thread, rendering with `threads` threads of its own (0: one
    /// per core) so that it does not queue behind, or in front of, the UI's own renders.
    /// It reports progress through the callback, which returns `false` once the worker is
    /// cancelled (or dropped).
    pub fn spawn(
        threads: usize,
        job: impl FnOnce(&mut dyn FnMut(&Progress) -> bool) -> Result<Option<T>, String> + Send + 'static,
    ) -> Self {
        let progress = Arc::new(Mutex::new(Progress { done: 0, total: 1, what: crate::t!("work-starting") }));
        let cancel = Arc::new(AtomicBool::new(false));
        let (tx, rx) = std::sync::mpsc::channel();
        let (p, c) = (progress.clone(), cancel.clone());
        crate::platform::threads::run_in_background(move || {
            let mut report = |now: &Progress| {
                if let Ok(mut g) = p.lock() {
                    *g = now.clone();
                }
                !c.load(Ordering::Relaxed)
            };
            let run = || {
                // A panic in the job must not take the app down: it becomes a message.
                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job(&mut report)))
                    .unwrap_or_else(|_| Err(crate::t!("work-failed")))
            };
            let r = crate::platform::threads::with_pool(threads, run)
                .unwrap_or_else(|e| Err(crate::t!("work-no-pool", error = e.clone())));
            let _ = tx.send(r);
        });
        Self { progress, cancel, result: rx }
    }

    /// Where it is.
    pub fn progress(&self) -> Progress {
        self.progress.lock().map_or(Progress { done: 0, total: 1, what: String::new() }, |g| g.clone())
    }

    /// The result once finished (`Ok(None)`: cancelled).
    pub fn poll(&self) -> Option<Result<Option<T>, String>> {
        match self.result.try_recv() {
            Ok(r) => Some(r),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(Err(crate::t!("work-stopped"))),
        }
    }
}

impl<T> Drop for Worker<T> {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
}
