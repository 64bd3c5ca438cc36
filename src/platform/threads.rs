//! Work that takes a while (the Cost of accuracy study): on the desktop on a thread of its
//! own with rayon's pool of `threads`; in the browser, where a page has one thread unless
//! it is cross-origin isolated, on the calling thread (rayon then runs on it too).

/// Runs `work` in the background where threads exist, else now, on this thread.
pub fn run_in_background(work: impl FnOnce() + Send + 'static) {
    #[cfg(not(target_arch = "wasm32"))]
    {
        if let Err(e) = std::thread::Builder::new().name("phonglab work".into()).spawn(work) {
            log::error!("cannot start a thread: {e}");
        }
    }
    #[cfg(target_arch = "wasm32")]
    work();
}

/// Runs `work` in a rayon pool of `threads` threads where threads exist, else on this
/// thread; `Err` says why the pool could not be made.
pub fn with_pool<R: Send>(threads: usize, work: impl FnOnce() -> R + Send) -> Result<R, String> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
            Ok(pool) => Ok(pool.install(work)),
            Err(e) => Err(e.to_string()),
        }
    }
    #[cfg(target_arch = "wasm32")]
    {
        let _ = threads;
        Ok(work())
    }
}

/// The threads a `--threads` asks for, checked: at most as many as the machine runs at
/// once (`0`, or none asked: one per core). More would only cost memory and time (a
/// hundred thousand threads each with its stack), so they are refused, saying the most.
pub fn asked(threads: Option<usize>) -> Result<usize, String> {
    let most = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
    match threads {
        Some(n) if n > most => Err(crate::t!("err-threads", asked = n, most = most)),
        Some(n) => Ok(n),
        None => Ok(0),
    }
}

/// Whether work started with [`run_in_background`] runs beside the window (true on the
/// desktop) or before the next frame (the browser).
pub const BACKGROUND: bool = cfg!(not(target_arch = "wasm32"));
