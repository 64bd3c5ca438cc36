//! Files the user gives and takes. On the desktop they have paths: a typed path, or the
//! system's file dialog (through `rfd`: the desktop portal on Linux, the native dialogs on
//! Windows and macOS), read and written where they are. In the browser there are no paths:
//! a file chooser and dropped files bring a file's name and bytes, read asynchronously (they
//! arrive in an inbox that the window empties each frame, [`take_arrived`]), and a file
//! goes out as a download ([`download`]).

#[cfg(not(target_arch = "wasm32"))]
use std::path::PathBuf;

/// Whether files have paths that the user can type (the desktop) or only names (the web).
pub const TYPED_PATHS: bool = cfg!(not(target_arch = "wasm32"));

/// A file that arrived: its name and its bytes.
pub type Arrived = (String, Vec<u8>);

/// What the system's file dialog gave.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Picked {
    /// A file chosen.
    Chosen(std::path::PathBuf),
    /// The user closed the dialog.
    Cancelled,
    /// No dialog could open here, and why (in the user's language): phonglab's own chooser
    /// stands in.
    NoDialog(String),
}

/// Why the system's dialog cannot open here, if it cannot: on Linux, `rfd` asks the desktop
/// portal over the session's D-Bus, and without a session bus there is no one to ask (a lab
/// PC with a bare window manager, a remote session).
#[cfg(not(target_arch = "wasm32"))]
fn no_dialog_why() -> Option<String> {
    if cfg!(target_os = "linux") {
        let bus = std::env::var_os("DBUS_SESSION_BUS_ADDRESS").is_some()
            || std::env::var_os("XDG_RUNTIME_DIR").is_some_and(|d| std::path::Path::new(&d).join("bus").exists());
        if !bus {
            return Some(crate::t!("dialog-no-session-bus"));
        }
    }
    None
}

/// Runs a dialog: its choice, a cancel, or (no session bus, or a dialog that came back at
/// once, faster than anyone can cancel one: the portal did not answer) no dialog at all.
#[cfg(not(target_arch = "wasm32"))]
fn run_dialog(dialog: impl FnOnce() -> Option<PathBuf>) -> Picked {
    if let Some(why) = no_dialog_why() {
        return Picked::NoDialog(why);
    }
    let asked = std::time::Instant::now();
    match dialog() {
        Some(p) => Picked::Chosen(p),
        None if asked.elapsed() < std::time::Duration::from_millis(150) => {
            Picked::NoDialog(crate::t!("dialog-did-not-open"))
        }
        None => Picked::Cancelled,
    }
}

/// The scene file to open (the desktop; the browser's chooser is [`choose_file`]).
#[cfg(not(target_arch = "wasm32"))]
pub fn pick_scene_to_open(start: Option<&std::path::Path>) -> Picked {
    run_dialog(|| dialog(start).add_filter("Scene, mesh or worksheet", &["toml", "obj", "ipynb", "py"]).pick_file())
}

/// A student's work to check: a notebook with its outputs, or a script's printed text.
#[cfg(not(target_arch = "wasm32"))]
pub fn pick_work_to_check(start: Option<&std::path::Path>, title: &str, filter: &str) -> Picked {
    run_dialog(|| dialog(start).set_title(title).add_filter(filter, &["ipynb", "txt", "png"]).pick_file())
}

/// Where to save the scene.
#[cfg(not(target_arch = "wasm32"))]
pub fn pick_scene_to_save(start: Option<&std::path::Path>) -> Picked {
    let name = start.and_then(|p| p.file_name()).map_or("scene.toml".into(), |n| n.to_string_lossy().into_owned());
    run_dialog(|| dialog(start).add_filter("Scene", &["toml"]).set_file_name(name).save_file())
}

#[cfg(not(target_arch = "wasm32"))]
fn dialog(start: Option<&std::path::Path>) -> rfd::FileDialog {
    let d = rfd::FileDialog::new();
    match start.and_then(|p| std::path::absolute(p).ok()).and_then(|p| p.parent().map(std::path::Path::to_path_buf)) {
        Some(dir) if dir.is_dir() => d.set_directory(dir),
        _ => d,
    }
}

/// The desktop has no chooser of its own beside the dialog: nothing happens.
#[cfg(not(target_arch = "wasm32"))]
pub fn choose_file(_ctx: &egui::Context, _accept: &str, _check: fn(&str, u64) -> Result<(), String>) {}

/// What a file dropped on the window gives at once: its path on the desktop (read then,
/// by [`crate::io::input_file`]); in the browser nothing yet, its bytes arriving later in
/// the inbox ([`take_arrived`]), each first passed to `check` with its name and size.
#[cfg(not(target_arch = "wasm32"))]
pub fn dropped_path(
    _ctx: &egui::Context,
    file: &egui::DroppedFileHandle,
    _check: impl Fn(&str, u64) -> Result<(), String> + 'static,
) -> Option<Result<PathBuf, String>> {
    let path = file.path().to_path_buf();
    if path.as_os_str().is_empty() {
        return Some(Err(crate::t!("cannot-read", path = String::new(), error = "no path".to_string())));
    }
    Some(Ok(path))
}

/// Files that arrived since the last frame (the browser's chooser and drops; none on the
/// desktop, where files are read when asked for).
#[cfg(not(target_arch = "wasm32"))]
pub fn take_arrived() -> Vec<Result<Arrived, String>> {
    Vec::new()
}

/// Offers `bytes` as a file named `name` to download (the browser); the desktop writes
/// files at paths instead, so this says so.
#[cfg(not(target_arch = "wasm32"))]
pub fn download(_name: &str, _bytes: &[u8], _mime: &str) -> Result<(), String> {
    Err("downloads are for the browser; the desktop saves at a path".into())
}

/// Where to save a file the user names, offering `name` (the desktop's dialog, filtered by
/// its extension).
#[cfg(not(target_arch = "wasm32"))]
pub fn pick_path_to_save(name: &str) -> Picked {
    let ext = std::path::Path::new(name).extension().map(|e| e.to_string_lossy().into_owned()).unwrap_or_default();
    run_dialog(|| {
        rfd::FileDialog::new().add_filter(ext.to_uppercase(), &[ext.as_str()]).set_file_name(name).save_file()
    })
}

/// The browser has no dialog that returns a path: files go out as downloads ([`download`]).
#[cfg(target_arch = "wasm32")]
pub fn pick_path_to_save(_name: &str) -> Picked {
    Picked::Cancelled
}

/// The browser has no dialog that returns a path: see [`choose_file`].
#[cfg(target_arch = "wasm32")]
pub fn pick_scene_to_open(_start: Option<&std::path::Path>) -> Picked {
    Picked::Cancelled
}

/// The browser has no dialog that returns a path: a student's work is dropped on the page.
#[cfg(target_arch = "wasm32")]
pub fn pick_work_to_check(_start: Option<&std::path::Path>, _title: &str, _filter: &str) -> Picked {
    Picked::Cancelled
}

/// The browser has no dialog that returns a path: scenes go out as downloads.
#[cfg(target_arch = "wasm32")]
pub fn pick_scene_to_save(_start: Option<&std::path::Path>) -> Picked {
    Picked::Cancelled
}

#[cfg(target_arch = "wasm32")]
pub use web::{choose_file, download, dropped_path, take_arrived};

#[cfg(target_arch = "wasm32")]
mod web {
    use std::cell::RefCell;

    use wasm_bindgen::JsCast;
    use wasm_bindgen::prelude::Closure;

    use super::Arrived;

    thread_local! {
        static INBOX: RefCell<Vec<Result<Arrived, String>>> = const { RefCell::new(Vec::new()) };
    }

    fn arrive(ctx: &egui::Context, file: Result<Arrived, String>) {
        INBOX.with(|i| i.borrow_mut().push(file));
        ctx.request_repaint();
    }

    /// The files that arrived since the last frame.
    pub fn take_arrived() -> Vec<Result<Arrived, String>> {
        INBOX.with(|i| std::mem::take(&mut *i.borrow_mut()))
    }

    /// Opens the browser's file chooser for files of the types in `accept` (".toml"); the
    /// chosen file arrives in the inbox once read, or `check`'s refusal of its name and size
    /// arrives instead, before it is read.
    pub fn choose_file(ctx: &egui::Context, accept: &str, check: fn(&str, u64) -> Result<(), String>) {
        let Some(document) = web_sys::window().and_then(|w| w.document()) else { return };
        let Ok(input) = document.create_element("input") else { return };
        let Ok(input) = input.dyn_into::<web_sys::HtmlInputElement>() else { return };
        input.set_type("file");
        input.set_accept(accept);
        let ctx = ctx.clone();
        let chosen = input.clone();
        let on_change = Closure::once_into_js(move || {
            let Some(file) = chosen.files().and_then(|l| l.get(0)) else { return };
            wasm_bindgen_futures::spawn_local(async move {
                let name = file.name();
                if let Err(why) = check(&name, file.size() as u64) {
                    arrive(&ctx, Err(why));
                    return;
                }
                let read = wasm_bindgen_futures::JsFuture::from(file.array_buffer()).await;
                let bytes = read
                    .map(|b| js_sys::Uint8Array::new(&b).to_vec())
                    .map_err(|e| crate::t!("cannot-read", path = name.clone(), error = format!("{e:?}")));
                arrive(&ctx, bytes.map(|b| (name, b)));
            });
        });
        input.set_onchange(Some(on_change.unchecked_ref()));
        input.click();
    }

    /// Reads a dropped file's bytes (asynchronously: they arrive in the inbox, once `check`
    /// passes their name and size); no path now.
    pub fn dropped_path(
        ctx: &egui::Context,
        file: &egui::DroppedFileHandle,
        check: impl Fn(&str, u64) -> Result<(), String> + 'static,
    ) -> Option<Result<std::path::PathBuf, String>> {
        let (ctx, file) = (ctx.clone(), file.clone());
        wasm_bindgen_futures::spawn_local(async move {
            let name = file.path().display().to_string();
            let read = file.bytes_async().await;
            let checked = read
                .map_err(|e| crate::t!("cannot-read", path = name.clone(), error = e))
                .and_then(|b| check(&name, b.len() as u64).map(|()| b));
            arrive(&ctx, checked.map(|b| (name, b)));
        });
        None
    }

    /// Offers `bytes` as a download named `name`.
    pub fn download(name: &str, bytes: &[u8], mime: &str) -> Result<(), String> {
        let fail = |e: wasm_bindgen::JsValue| crate::t!("browser-download-failed", error = format!("{e:?}"));
        let array = js_sys::Uint8Array::from(bytes);
        let parts = js_sys::Array::of1(&array);
        let options = web_sys::BlobPropertyBag::new();
        options.set_type(mime);
        let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options).map_err(fail)?;
        let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(fail)?;
        let document = web_sys::window().and_then(|w| w.document()).ok_or_else(|| fail("no document".into()))?;
        let a = document
            .create_element("a")
            .map_err(fail)?
            .dyn_into::<web_sys::HtmlAnchorElement>()
            .map_err(|e| fail(e.into()))?;
        a.set_href(&url);
        a.set_download(name);
        a.click();
        let _ = web_sys::Url::revoke_object_url(&url);
        Ok(())
    }
}
