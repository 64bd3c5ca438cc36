//! What differs between the desktop and the browser (and between operating systems), kept
//! out of the panels: each file is one concept, with its desktop and its browser way side
//! by side.
//!
//! | module | desktop | browser |
//! |---|---|---|
//! | [`os`] | closing and syncing files, the storage folder, termination signals | (not used) |
//! | [`files`] | typed paths and the system's file dialog | a file chooser, downloads, dropped files read asynchronously |
//! | [`storage`] | the session in a file ([`crate::app::shell::session`]) | the session in `localStorage` |
//! | [`threads`] | work on a thread of its own, rayon's pool | work on the calling thread (no cross-origin isolation needed) |
//! | [`clock`] | `std::time::Instant` | `performance.now()`, through `web-time` |
//! | [`language`] | `LC_ALL`, `LC_MESSAGES`, `LANG` | `navigator.language` |
//! | [`by_handle`] | a file moved or removed as the very file it is, checked through its open handle (Windows: by that handle) | (not used) |
//! | [`held_dir`] | a folder held by a handle, everything inside it done through that handle (Unix: `openat`, `renameat2`, `unlinkat`; Windows: held without sharing its deletion) | (not used) |
//! | [`links`] | whether a file is reached through a link (Windows: a reparse point, or a final path under another name) | (not used) |
//! | [`page`] | no page: links open the published site | the page's own address, a link's base |

pub mod by_handle;
pub mod clock;
pub mod files;
pub mod held_dir;
pub mod language;
pub mod links;
pub mod os;
pub mod page;
pub mod storage;
pub mod threads;
