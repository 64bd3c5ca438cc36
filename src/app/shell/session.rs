//! The app's session, kept by phonglab: what the window shows, restored at the next start.
//!
//! The session is a RON map of strings (the scene file's TOML under [`DOCUMENT_KEY`], the
//! layout, the quiz) in `session.ron` in the storage folder ([`crate::platform::storage::storage_dir`],
//! or `PHONGLAB_SESSION_DIR`). It is written whole or not at all
//! ([`crate::io::atomic_write::write`]), so a full disk leaves the last good session.
//!
//! One window owns the session at a time: it holds `session.lock` ([`std::fs::File::try_lock`],
//! released by the system when the process ends, however it ends). A second window reads
//! the session but never writes it, and says so.
//!
//! What can go wrong at the start, each said in the window and in the log:
//! - `session.ron` does not parse, cannot be read (no permission, a loop of links), is not
//!   a regular file (a FIFO, a link to a device: it is opened without blocking, so neither
//!   hangs the start) or is larger than [`MAX_SESSION_BYTES`]: it is renamed
//!   `session-unreadable-<time>.ron`, and the window starts on the worksheet; where it
//!   cannot be renamed, it is never written over: this window keeps its session in a new
//!   `session-<time>.ron` instead, and says so;
//! - the scene in it does not load: the text is kept in `phonglab-unreadable-<time>.toml`;
//! - its mesh file has moved: the scene is kept, shown on the sphere, and the message names
//!   the missing file;
//! - `session.ron` is a folder, or the storage folder cannot be made: the window works but
//!   does not save its session.

use std::collections::BTreeMap;
use std::fs::File;
use std::path::{Path, PathBuf};

use phonglab_core::Document;

use crate::t;

/// The key the scene is kept under (a scene file's TOML).
pub const DOCUMENT_KEY: &str = "phonglab.document.toml";

/// The session file's name in the storage folder.
pub const SESSION_FILE: &str = "session.ron";

/// The lock file's name in the storage folder.
pub const LOCK_FILE: &str = "session.lock";

/// The largest session file read: a scene, the layout and the quiz take a few kilobytes.
pub const MAX_SESSION_BYTES: u64 = 4 << 20;

/// Whether this window may write the session.
#[derive(Debug)]
enum Owner {
    /// This window holds the lock (the file stays open while the window runs).
    Owns(#[allow(dead_code)] File),
    /// Another window holds it, or the session cannot be written; the reason.
    ReadOnly(String),
    /// The browser's session, kept in `localStorage` ([`crate::platform::storage`]).
    Browser,
}

/// The session: its values, where it lives, and whether this window may write it.
#[derive(Debug)]
pub struct Session {
    dir: Option<PathBuf>,
    /// The session file's name in `dir`: [`SESSION_FILE`], or another where that one could
    /// be neither read nor set aside.
    file: String,
    values: BTreeMap<String, String>,
    owner: Owner,
    /// The text last written or read, so an unchanged session is not written again.
    saved: Option<String>,
}

/// A file name in `dir` that does not exist yet: `{stem}-{unix seconds}[-n].{ext}`.
fn fresh_path(dir: &Path, stem: &str, ext: &str) -> PathBuf {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let mut p = dir.join(format!("{stem}-{secs}.{ext}"));
    let mut n = 1;
    while p.exists() {
        p = dir.join(format!("{stem}-{secs}-{n}.{ext}"));
        n += 1;
    }
    p
}

impl Session {
    /// A session that is neither read nor written (tests, and a machine with no storage).
    pub fn in_memory() -> Self {
        Session {
            dir: None,
            file: SESSION_FILE.into(),
            values: BTreeMap::new(),
            owner: Owner::ReadOnly("no storage folder".into()),
            saved: None,
        }
    }

    /// A session read from `text` (the browser's, kept in `localStorage`), with what the user
    /// should be told when it does not parse (the window then starts on the worksheet). It
    /// is written by the caller, who has the text ([`Session::text`]); [`Session::save`]
    /// writes nothing.
    pub fn from_text(text: Option<&str>) -> (Session, Vec<String>) {
        let mut session = Session::in_memory();
        session.owner = Owner::Browser;
        let mut notices = Vec::new();
        if let Some(text) = text {
            session.saved = Some(text.to_string());
            match parse(text.as_bytes()) {
                Ok(values) => session.values = values,
                Err(why) => notices.push(t!("session-unreadable", why = why)),
            }
        }
        (session, notices)
    }

    /// Opens the session in `dir`: takes the lock if no other window has it, reads the
    /// values. Returns the session and what the user should be told (empty when all is well).
    pub fn open(dir: &Path) -> (Session, Vec<String>) {
        let mut notices = Vec::new();
        let mut session = Session {
            dir: Some(dir.to_path_buf()),
            file: SESSION_FILE.into(),
            values: BTreeMap::new(),
            owner: Owner::ReadOnly(String::new()),
            saved: None,
        };
        session.owner = match std::fs::create_dir_all(dir).and_then(|()| lock(dir)) {
            Ok(Some(file)) => Owner::Owns(file),
            Ok(None) => {
                notices.push(t!("session-other-window", dir = dir.display().to_string()));
                Owner::ReadOnly("another window owns the session".into())
            }
            Err(e) => {
                notices.push(t!("session-folder-unusable", dir = dir.display().to_string(), error = e.to_string()));
                Owner::ReadOnly(e.to_string())
            }
        };
        let path = dir.join(SESSION_FILE);
        if path.is_dir() {
            notices.push(t!("session-file-is-folder", path = path.display().to_string()));
            session.owner = Owner::ReadOnly("the session file is a folder".into());
            return (session, notices);
        }
        use crate::io::input_file::Unread;
        let unreadable = match crate::io::input_file::read_capped_or(&path, MAX_SESSION_BYTES) {
            Ok(bytes) => match parse(&bytes) {
                Ok(values) => {
                    session.values = values;
                    session.saved = std::str::from_utf8(&bytes).ok().map(str::to_string);
                    None
                }
                Err(why) => Some(why),
            },
            Err(Unread::Io(e)) if e.kind() == std::io::ErrorKind::NotFound => {
                session.read_eframe_storage(dir);
                None
            }
            Err(Unread::NotAFile) => Some(t!("session-not-a-file")),
            Err(Unread::TooLarge(size)) => Some(t!(
                "session-too-large",
                size = phonglab_core::mesh::obj::describe_bytes(size),
                cap = phonglab_core::mesh::obj::describe_bytes(MAX_SESSION_BYTES)
            )),
            // Unreadable by this user (mode 000), a loop of links...: kept, never written over.
            Err(Unread::Io(e)) => Some(crate::io::reasons::io_reason(&e)),
        };
        if let Some(why) = unreadable {
            let said = session.set_aside(&path, &why);
            notices.push(said);
        }
        (session, notices)
    }

    /// Moves an unreadable session file (`why`) aside as `session-unreadable-<time>.ron`,
    /// when this window owns the session, and says so; the window starts fresh. Where it
    /// cannot be moved, it is left as it is and never written over: this window's session
    /// goes to a new file, which the message names.
    fn set_aside(&mut self, path: &Path, why: &str) -> String {
        use crate::io::reasons::shown;
        let Some(dir) = self.dir.clone().filter(|_| self.may_write()) else {
            return t!("session-unreadable", why = why);
        };
        let kept = fresh_path(&dir, "session-unreadable", "ron");
        match crate::io::atomic_write::rename_no_replace(path, &kept) {
            Ok(()) => t!("session-unreadable-kept", why = why, kept = shown(&kept)),
            Err(e) => {
                let instead = fresh_path(&dir, "session", "ron");
                self.file = instead.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
                t!(
                    "session-unreadable-not-kept",
                    path = shown(path),
                    why = why,
                    error = crate::io::reasons::io_reason(&e),
                    instead = shown(&instead)
                )
            }
        }
    }

    /// Reads the session of phonglab versions that let eframe keep it (`app.ron`, the same
    /// map), once: it is left as it was.
    fn read_eframe_storage(&mut self, dir: &Path) {
        if let Ok(bytes) = crate::io::input_file::read_capped_or(&dir.join("app.ron"), MAX_SESSION_BYTES)
            && let Ok(values) = parse(&bytes)
        {
            self.values = values;
        }
    }

    /// May this window write the session?
    pub fn may_write(&self) -> bool {
        matches!(self.owner, Owner::Owns(_))
    }

    /// Why this window does not write the session, when it does not.
    pub fn not_saved_because(&self) -> Option<&str> {
        match &self.owner {
            Owner::Owns(_) | Owner::Browser => None,
            Owner::ReadOnly(why) => Some(why),
        }
    }

    /// Where the session is kept, when it is kept anywhere.
    pub fn path(&self) -> Option<PathBuf> {
        self.dir.as_ref().map(|d| d.join(&self.file))
    }

    /// The storage folder.
    pub fn dir(&self) -> Option<&Path> {
        self.dir.as_deref()
    }

    /// A value.
    pub fn get(&self, key: &str) -> Option<&str> {
        self.values.get(key).map(String::as_str)
    }

    /// Sets a value (written by the next [`Session::save`]).
    pub fn set(&mut self, key: &str, value: String) {
        self.values.insert(key.to_string(), value);
    }

    /// The session's text as it would be written.
    pub fn text(&self) -> String {
        ron::ser::to_string_pretty(&self.values, ron::ser::PrettyConfig::default()).unwrap_or_default()
    }

    /// Writes the session when it changed and this window owns it. `Ok(true)`: written.
    pub fn save(&mut self) -> Result<bool, String> {
        let text = self.text();
        if self.saved.as_deref() == Some(text.as_str()) {
            return Ok(false);
        }
        if matches!(self.owner, Owner::Browser) {
            // Said once when refused: not tried again until the session changes.
            self.saved = Some(text.clone());
            return save_in_browser(&text);
        }
        let (Some(path), true) = (self.path(), self.may_write()) else { return Ok(false) };
        crate::io::atomic_write::write(&path, text.as_bytes()).map_err(|e| e.to_string())?;
        self.saved = Some(text);
        Ok(true)
    }

    /// A writer for this session's file that another thread can use (the signal handler),
    /// when this window owns it.
    pub fn writer(&self) -> Option<PathBuf> {
        self.may_write().then(|| self.path()).flatten()
    }
}

/// Keeps `text` in the browser's `localStorage` (on the desktop there is none: nothing).
fn save_in_browser(text: &str) -> Result<bool, String> {
    #[cfg(target_arch = "wasm32")]
    {
        crate::platform::storage::save_browser_session(text).map(|()| true)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = text;
        Ok(false)
    }
}

/// Takes the session's lock: `Ok(None)` when another process holds it.
fn lock(dir: &Path) -> std::io::Result<Option<File>> {
    let file = File::options().read(true).write(true).create(true).truncate(false).open(dir.join(LOCK_FILE))?;
    match file.try_lock() {
        Ok(()) => Ok(Some(file)),
        Err(std::fs::TryLockError::WouldBlock) => Ok(None),
        Err(std::fs::TryLockError::Error(e)) => Err(e),
    }
}

fn parse(bytes: &[u8]) -> Result<BTreeMap<String, String>, String> {
    let text = std::str::from_utf8(bytes).map_err(|e| e.to_string())?;
    ron::from_str::<BTreeMap<String, String>>(text).map_err(|e| e.to_string())
}

/// The last session's document, from the text stored under [`DOCUMENT_KEY`], and a note
/// when it was restored with a change (its mesh file is missing).
///
/// `Ok(None)`: nothing stored. `Err(message)`: the text does not load; it has been written
/// to `phonglab-unreadable-<time>.toml` in `dir` (when given) and the message says where.
pub fn restore_document(text: Option<&str>, dir: Option<&Path>) -> Result<Option<(Document, Option<String>)>, String> {
    let Some(text) = text else { return Ok(None) };
    let e = match Document::from_toml_keeping_missing_mesh(text, None) {
        Ok(restored) => return Ok(Some(restored)),
        Err(e) => e,
    };
    let kept = match dir {
        Some(dir) => {
            let p = fresh_path(dir, "phonglab-unreadable", "toml");
            match std::fs::create_dir_all(dir)
                .map_err(|e| e.to_string())
                .and_then(|()| crate::io::atomic_write::write(&p, text.as_bytes()).map_err(|e| e.to_string()))
            {
                Ok(()) => t!("session-scene-kept", path = p.display().to_string()),
                Err(err) => t!("session-scene-not-kept", error = err.clone()),
            }
        }
        None => t!("session-no-folder"),
    };
    Err(t!("session-scene-not-restored", error = e.to_string(), kept = kept))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("phonglab-session-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn files(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn a_good_session_is_restored_and_an_empty_one_is_none() {
        let doc = phonglab_core::Document::default();
        let text = doc.to_toml().unwrap();
        assert_eq!(restore_document(Some(&text), None), Ok(Some((doc, None))));
        assert_eq!(restore_document(None, None), Ok(None));
    }

    #[test]
    fn a_bad_scene_is_kept_beside_the_storage() {
        let dir = temp_dir("scene");
        let bad = "name = \"mine\"\n[material]\nshininess = 500\n";
        let msg = restore_document(Some(bad), Some(&dir)).unwrap_err();
        assert!(msg.contains("material.shininess") && msg.contains("starting on the worksheet"), "{msg}");
        let kept = files(&dir);
        assert_eq!(kept.len(), 1);
        assert!(msg.contains(&kept[0]), "{msg}");
        assert_eq!(std::fs::read_to_string(dir.join(&kept[0])).unwrap(), bad, "kept byte for byte");
    }

    #[test]
    fn a_scene_whose_mesh_moved_is_kept_on_the_sphere() {
        let mut doc = phonglab_core::Document::default();
        doc.scene.material.shininess = 77.0;
        doc.view.object = phonglab_core::ObjectKind::Obj;
        doc.view.obj = Some("/nowhere/phonglab-moved-mesh.obj".into());
        let text = doc.to_toml().unwrap();
        let (back, note) = restore_document(Some(&text), None).unwrap().unwrap();
        assert_eq!(back.scene.material.shininess, 77.0, "the scene is kept");
        assert_eq!(back.view.object, phonglab_core::ObjectKind::Sphere);
        assert_eq!(back.view.obj.as_deref(), Some("/nowhere/phonglab-moved-mesh.obj"));
        let note = note.unwrap();
        assert!(note.contains("/nowhere/phonglab-moved-mesh.obj") && note.contains("missing"), "{note}");
    }

    #[test]
    fn the_session_is_saved_whole_and_read_back() {
        let dir = temp_dir("save");
        let (mut s, notices) = Session::open(&dir);
        assert!(notices.is_empty() && s.may_write(), "{notices:?}");
        s.set(DOCUMENT_KEY, "name = \"x\"".into());
        assert_eq!(s.save(), Ok(true));
        assert_eq!(s.save(), Ok(false), "unchanged: not written again");
        s.set(DOCUMENT_KEY, "name = \"y\"".into());
        let e = crate::io::atomic_write::with_fault(crate::io::atomic_write::Fault::AfterBytes(5), || s.save())
            .unwrap_err();
        assert!(e.contains("unchanged"), "{e}");
        drop(s);
        let (s, _) = Session::open(&dir);
        assert_eq!(s.get(DOCUMENT_KEY), Some("name = \"x\""), "the failed save left the last good session");
        assert_eq!(files(&dir), [LOCK_FILE, SESSION_FILE], "no temporary file left");
    }

    #[test]
    fn a_second_window_reads_but_does_not_write() {
        let dir = temp_dir("two");
        let (mut first, _) = Session::open(&dir);
        first.set("k", "first".into());
        first.save().unwrap();
        // The lock is per open file description, so a second open in this process stands
        // for a second process.
        let (mut second, notices) = Session::open(&dir);
        assert!(!second.may_write());
        assert_eq!(second.not_saved_because(), Some("another window owns the session"));
        assert!(notices[0].contains("Another phonglab window"), "{notices:?}");
        assert_eq!(second.get("k"), Some("first"));
        second.set("k", "second".into());
        assert_eq!(second.save(), Ok(false));
        drop(first);
        let (third, notices) = Session::open(&dir);
        assert!(third.may_write() && notices.is_empty(), "the lock went with the first window");
        assert_eq!(third.get("k"), Some("first"));
    }

    /// Opens the session in `dir` on a thread of its own: a start that hangs fails the test
    /// instead of the test run.
    #[cfg(unix)] // its tests are Unix's
    fn open_within_seconds(dir: &Path) -> (Session, Vec<String>) {
        let (tx, rx) = std::sync::mpsc::channel();
        let d = dir.to_path_buf();
        std::thread::spawn(move || tx.send(Session::open(&d)).ok());
        rx.recv_timeout(std::time::Duration::from_secs(5)).expect("the session opened within 5 seconds")
    }

    #[test]
    #[cfg(unix)]
    fn a_fifo_a_device_or_a_huge_session_file_is_set_aside_and_the_window_starts_fresh() {
        let make_fifo = |p: &Path| {
            let c = std::ffi::CString::new(p.as_os_str().as_encoded_bytes()).unwrap();
            // SAFETY: `c` is a valid NUL-terminated path for the duration of the call.
            assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        };
        type Make<'a> = &'a dyn Fn(&Path);
        let cases: [(&str, Make, &str); 3] = [
            ("fifo", &make_fifo, "not a regular file"),
            ("zero", &|p: &Path| std::os::unix::fs::symlink("/dev/zero", p).unwrap(), "not a regular file"),
            (
                "huge",
                &|p: &Path| std::fs::File::create(p).unwrap().set_len(MAX_SESSION_BYTES + 1).unwrap(),
                "a session is at most 4 194 304 bytes",
            ),
        ];
        for (name, make, said) in cases {
            let dir = temp_dir(name);
            make(&dir.join(SESSION_FILE));
            let (mut s, notices) = open_within_seconds(&dir);
            let all = notices.join(" ");
            assert!(all.contains(said) && all.contains("session-unreadable-"), "{name}: {all}");
            assert!(s.may_write(), "{name}: this window owns the session");
            assert!(s.get(DOCUMENT_KEY).is_none(), "{name}: it starts fresh");
            assert!(std::fs::symlink_metadata(dir.join(SESSION_FILE)).is_err(), "{name}: set aside");
            s.set("k", "v".into());
            assert_eq!(s.save(), Ok(true), "{name}: a fresh session is written");
            assert!(std::fs::metadata(dir.join(SESSION_FILE)).unwrap().is_file());
        }
    }

    #[test]
    fn an_unreadable_session_is_set_aside_and_a_folder_is_reported() {
        let dir = temp_dir("bad");
        std::fs::write(dir.join(SESSION_FILE), "{\"phonglab.document.toml\": \"unterminated").unwrap();
        let (s, notices) = Session::open(&dir);
        assert!(s.may_write());
        assert!(notices[0].contains("could not be read") && notices[0].contains("session-unreadable"), "{notices:?}");
        assert!(!dir.join(SESSION_FILE).exists(), "moved, so it is not overwritten");
        drop(s);

        let dir = temp_dir("folder");
        std::fs::create_dir(dir.join(SESSION_FILE)).unwrap();
        let (mut s, notices) = Session::open(&dir);
        assert!(notices[0].contains("is a folder"), "{notices:?}");
        s.set("k", "v".into());
        assert_eq!(s.save(), Ok(false), "not written into a folder's place");
        assert!(dir.join(SESSION_FILE).is_dir());
    }

    /// Issue 54, 2: a session this user cannot read (mode 000; as root, which reads any
    /// mode, a loop of links stands for it) is set aside, not written over at exit.
    #[test]
    #[cfg(unix)]
    fn a_session_the_system_cannot_read_is_set_aside_not_written_over() {
        use std::os::unix::fs::PermissionsExt;
        let mut made: Vec<&str> = vec!["loop"];
        // SAFETY: geteuid only reads the process's user id.
        if unsafe { libc::geteuid() } != 0 {
            made.push("mode 000");
        }
        for how in made {
            let dir = temp_dir(&format!("cannot-read-{}", how.replace(' ', "-")));
            if how == "loop" {
                std::os::unix::fs::symlink(SESSION_FILE, dir.join(SESSION_FILE)).unwrap();
            } else {
                std::fs::write(dir.join(SESSION_FILE), "{\"k\": \"the lesson\"}").unwrap();
                std::fs::set_permissions(dir.join(SESSION_FILE), std::fs::Permissions::from_mode(0o000)).unwrap();
            }
            let (mut s, notices) = Session::open(&dir);
            let all = notices.join(" ");
            assert!(all.contains("session-unreadable-"), "{how}: {all}");
            assert!(std::fs::symlink_metadata(dir.join(SESSION_FILE)).is_err(), "{how}: set aside");
            let kept = files(&dir).into_iter().find(|n| n.starts_with("session-unreadable-")).unwrap();
            assert!(std::fs::symlink_metadata(dir.join(&kept)).is_ok(), "{how}: kept");
            s.set("k", "v".into());
            assert_eq!(s.save(), Ok(true), "{how}");
        }
    }

    /// Where the unreadable session cannot be set aside, it is left as it is, and the
    /// window's session goes to another file, which the message names.
    #[test]
    #[cfg(unix)]
    fn an_unreadable_session_that_cannot_be_set_aside_is_left_and_the_session_goes_elsewhere() {
        use crate::io::atomic_write::{Fault, with_fault};
        let dir = temp_dir("not-aside");
        std::fs::write(dir.join(SESSION_FILE), "not ron at all {").unwrap();
        let (mut s, notices) = with_fault(Fault::OnRename(0), || Session::open(&dir));
        let all = notices.join(" ");
        let instead = s.path().unwrap();
        assert_ne!(instead, dir.join(SESSION_FILE));
        assert!(all.contains("nor set aside") && all.contains(&instead.display().to_string()), "{all}");
        s.set("k", "v".into());
        assert_eq!(s.save(), Ok(true));
        assert_eq!(std::fs::read(dir.join(SESSION_FILE)).unwrap(), b"not ron at all {", "never written over");
        assert!(std::fs::read_to_string(&instead).unwrap().contains("\"k\""));
    }

    #[test]
    fn an_older_eframe_session_is_read() {
        let dir = temp_dir("eframe");
        let old = ron::to_string(&BTreeMap::from([(DOCUMENT_KEY.to_string(), "name = \"old\"".to_string())])).unwrap();
        std::fs::write(dir.join("app.ron"), old).unwrap();
        let (s, notices) = Session::open(&dir);
        assert!(notices.is_empty());
        assert_eq!(s.get(DOCUMENT_KEY), Some("name = \"old\""));
    }

    #[test]
    fn the_browsers_session_text_is_read_back_and_a_bad_one_is_said() {
        // The browser keeps the session's text in localStorage: what `text` gives,
        // `from_text` reads back, and it writes no file.
        let mut s = Session::in_memory();
        s.set(DOCUMENT_KEY, "name = \"from the browser\"".into());
        let (back, notices) = Session::from_text(Some(&s.text()));
        assert!(notices.is_empty(), "{notices:?}");
        assert_eq!(back.get(DOCUMENT_KEY), Some("name = \"from the browser\""));
        assert_eq!(back.path(), None, "nothing on a disk");
        let mut back = back;
        assert_eq!(back.save(), Ok(false), "the page writes localStorage itself");
        // Nothing kept yet: an empty session. A damaged text: said, and an empty session.
        let (none, notices) = Session::from_text(None);
        assert!(notices.is_empty() && none.get(DOCUMENT_KEY).is_none());
        let (bad, notices) = Session::from_text(Some("{\"phonglab.document.toml\": \"unterminated"));
        assert_eq!(notices.len(), 1, "{notices:?}");
        assert!(bad.get(DOCUMENT_KEY).is_none());
    }
}
