//! The clock: `std::time::Instant` on the desktop; on the web, where std's clock panics,
//! the browser's `performance.now()` (the `web-time` crate re-exports std's on the desktop,
//! so this is one type everywhere).

pub use web_time::{Duration, Instant};
