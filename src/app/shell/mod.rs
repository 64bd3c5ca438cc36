//! The shell: the frame and what it owns (the state, the keys, the top bar, the centre's
//! arrangement, the windows over it, the session), and the runners that put it on the
//! desktop and in the browser.

pub mod bench_ui;
pub mod centre;
pub mod centre_layout;
#[cfg(not(target_arch = "wasm32"))]
pub mod desktop;
pub mod files;
pub mod frame;
pub mod keys;
pub mod layout;
pub mod screenshot;
pub mod session;
pub mod session_loop;
pub mod shared_link;
pub mod shutdown;
pub mod state;
pub mod student;
pub mod top_bar;
#[cfg(target_arch = "wasm32")]
pub mod web;
pub mod windows;
