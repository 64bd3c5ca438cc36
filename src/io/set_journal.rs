//! The journal of a set's swap ([`super::file_set`]), and the recovery that finishes or
//! throws away what a killed writer left: acting only on what phonglab itself wrote.
//!
//! A folder that receives a set may hold anything: an unzipped handout or a downloaded
//! openFrameworks project can carry files named like phonglab's own (a journal, a staging
//! folder, a link named like one). So what a writer leaves is made so that no planted file
//! can pass for it:
//! - the staging folder (`.phonglab-set.<pid>.<n>.tmp`) is created by this writer alone
//!   (`mkdir` fails on anything already there, a link included), and the journal lives in
//!   it (`.phonglab-set.journal`), created exclusively, never read through a link;
//! - the staging folder, its aside folder and the target folder are held by a handle while
//!   phonglab works in them ([`crate::platform::held_dir`]: Unix, a descriptor every step
//!   is relative to; Windows, a handle that does not share deletion, so none of them can be
//!   renamed or removed meanwhile): one renamed and replaced by a link to another folder
//!   never sends a write, a move or a removal into the folder the link leads to;
//! - each file staged is named, by its identity, in a list appended before its bytes are
//!   written (`STAGED`): a writer stopped before its journal decided leaves nothing the
//!   recovery removes but those;
//! - the journal names the staging folder by its identity (Unix: device, inode and birth
//!   time; Windows: the volume's serial number and the file index; what a file gets when it
//!   is made, which nobody planting a file can choose) and names
//!   only plain files of the target folder, each with its identity, size and hash
//!   (SipHash-1-3, 128 bits): the new set's files, written in that run into the staging
//!   folder, and the old set's files it replaces;
//! - the identities are public and the hash is unkeyed, so anyone can write a record in
//!   phonglab's exact form: a record (the journal, the list of what a set wrote, the list of
//!   what was staged) and a staging folder are trusted only when they are this user's alone
//!   (`platform::os::is_this_users_alone`, asked through the handle they are read by: on
//!   Unix owned by this user and writable by no one else, which phonglab makes them, 0600
//!   and 0700; on Windows owned by this user, with a DACL that lets no one else write,
//!   which phonglab makes them: an owner-only descriptor). A classmate's forged list or journal in a
//!   shared folder (mode 1777, where they cannot delete the teacher's files themselves) is
//!   left as it is, and said (issue 59, round 2);
//! - recovery acts on a staging folder only when its journal is there, read without
//!   following a link, and names that very folder; it moves or removes a file only when
//!   the file is the one the journal names (identity, size and hash), and it never renames
//!   over a file. Anything else (a journal in another form, a link or a file named like a
//!   staging folder, a staging folder without a journal or with a journal that is not its
//!   own, a file changed since) is left as it is, and a message says so.

use std::ffi::OsStr;
use std::hash::Hasher as _;
use std::io::{self, Read};
use std::path::Path;

use serde::{Deserialize, Serialize};
use siphasher::sip128::{Hasher128, SipHasher13};

use crate::platform::held_dir::HeldDir;
use crate::t;

/// The stem of a staging folder's name (`.phonglab-set.<pid>.<n>.tmp`).
pub const STAGING: &str = "phonglab-set";

/// The journal's name, inside its staging folder (and the name of the journal of earlier
/// versions, in the target folder: left alone now).
pub const JOURNAL: &str = ".phonglab-set.journal";

/// The folder inside the staging folder that the old set's files are moved aside into.
pub const ASIDE: &str = ".phonglab-set.old";

/// The journal's temporary file, inside the staging folder, renamed into place whole.
const JOURNAL_TMP: &str = ".phonglab-set.journal.tmp";

/// The list of what a writer staged, inside its staging folder: each file's name and
/// identity, appended (and synced) as each is created, before its bytes are written, so
/// that a writer stopped before its journal decided leaves every file it staged named by
/// its identity, and the recovery removes those and nothing else (fix59n left them to be
/// told by their kind: a regular file under a name of the set).
const STAGED: &str = ".phonglab-set.staged";

/// The largest journal read: a set of a thousand files takes about 200 KB.
const MAX_JOURNAL_BYTES: u64 = 1 << 20;

/// The list of the files the last set written into a folder holds, each with its identity,
/// size and hash (the journal's `new`): the next set removes a file it lacks only when this
/// list names it and the file is still exactly what phonglab wrote.
pub const WRITTEN: &str = ".phonglab-set.written";

/// What makes a file or folder itself: device (Windows: the volume's serial number), inode
/// (Windows: the file index) and birth time (seconds and nanoseconds, where the file system
/// keeps it: on Unix only, see the private `born`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Identity {
    dev: u64,
    ino: u64,
    born: Option<(u64, u32)>,
}

impl Identity {
    /// The identity of the file or folder at `path` itself (a link is not followed), with
    /// its metadata.
    pub fn at(path: &Path) -> io::Result<(std::fs::Metadata, Identity)> {
        let (meta, (dev, ino)) = crate::platform::os::identity_at(path)?;
        let born = born(&meta);
        Ok((meta, Identity { dev, ino, born }))
    }

    /// The identity of the open file `file`, with its metadata.
    pub fn of_file(file: &std::fs::File) -> io::Result<(std::fs::Metadata, Identity)> {
        let (meta, (dev, ino)) = crate::platform::os::file_identity(file)?;
        let born = born(&meta);
        Ok((meta, Identity { dev, ino, born }))
    }
}

/// A file's birth time, part of its identity where it tells files apart: on Unix an inode
/// number freed by a deletion is given to the next file made, and the birth time tells the
/// two apart. Not on Windows: there the file index already does (NTFS's carries a sequence
/// number that changes each time its record is used again), and Wine gives the last write
/// time as the creation time, so a folder's "birth" moves each time a file is added to it.
fn born(meta: &std::fs::Metadata) -> Option<(u64, u32)> {
    if cfg!(windows) {
        return None;
    }
    let since = meta.created().ok()?.duration_since(std::time::UNIX_EPOCH).ok()?;
    Some((since.as_secs(), since.subsec_nanos()))
}

/// One file the journal names: its name in the target folder, size, hash and identity.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Entry {
    /// A plain file name (no folder).
    pub name: String,
    /// Its size in bytes.
    pub size: u64,
    /// Its SipHash-1-3 (128 bits), in hexadecimal.
    pub hash: String,
    /// Its identity.
    pub id: Identity,
}

/// What the journal says (see the module's documentation).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Journal {
    /// The staging folder it lives in.
    pub staging: Identity,
    /// The new set is whole in the staging folder and the swap is decided: a recovery
    /// finishes it. Before that, a recovery throws the staging folder away.
    pub decided: bool,
    /// The new set's files, as written into the staging folder.
    pub new: Vec<Entry>,
    /// The old set's files, in the target folder, that the new set replaces.
    pub old: Vec<Entry>,
}

/// The hash of `bytes` as a journal writes it.
pub fn hash_bytes(bytes: &[u8]) -> String {
    let mut h = SipHasher13::new();
    h.write(bytes);
    format!("{:032x}", h.finish128().as_u128())
}

/// The file `name` in the folder held `dir`, read without following a link: its size, hash
/// and identity. `Err` when it is not a regular file.
fn read_entry_in(dir: &HeldDir, name: &str) -> io::Result<(u64, String, Identity)> {
    read_open(&dir.open_file(OsStr::new(name))?)
}

/// The file at `path`, read without following a link: its size, hash and identity. `Err`
/// when it is not a regular file.
fn read_entry(path: &Path) -> io::Result<(u64, String, Identity)> {
    read_open(&crate::platform::os::open_no_follow(path)?)
}

/// [`read_entry`] of a file already open, through its handle.
fn read_open(file: &std::fs::File) -> io::Result<(u64, String, Identity)> {
    let (meta, id) = Identity::of_file(file)?;
    if !meta.is_file() {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, "not a regular file"));
    }
    let mut h = SipHasher13::new();
    let (mut buf, mut size, mut reader) = (vec![0u8; 1 << 16], 0u64, file);
    loop {
        let n = reader.read(&mut buf)?;
        if n == 0 {
            break;
        }
        h.write(&buf[..n]);
        size += n as u64;
    }
    Ok((size, format!("{:032x}", h.finish128().as_u128()), id))
}

/// The entry of the file `name` in `folder`, read there now (by its path: for a look that
/// moves nothing).
pub fn entry_of(folder: &Path, name: &str) -> io::Result<Entry> {
    let (size, hash, id) = read_entry(&folder.join(name))?;
    Ok(Entry { name: name.to_string(), size, hash, id })
}

/// Is the file at `path` exactly the one `entry` names (identity, size and hash)? By its
/// path: for a look that moves nothing (an output's record, `io::work_output`).
pub fn is_entry(path: &Path, entry: &Entry) -> bool {
    let Ok((meta, id)) = Identity::at(path) else { return false };
    if !meta.is_file() || id != entry.id || meta.len() != entry.size {
        return false;
    }
    read_entry(path).is_ok_and(|(size, hash, id)| size == entry.size && hash == entry.hash && id == entry.id)
}

/// The entry of the file `name` in the folder held `dir`, read there now.
pub fn entry_in(dir: &HeldDir, name: &str) -> io::Result<Entry> {
    let (size, hash, id) = read_entry_in(dir, name)?;
    Ok(Entry { name: name.to_string(), size, hash, id })
}

/// Is the file `entry.name` in the folder held `dir` exactly the one `entry` names
/// (identity, size and hash)?
pub fn is_entry_in(dir: &HeldDir, entry: &Entry) -> bool {
    read_entry_in(dir, &entry.name)
        .is_ok_and(|(size, hash, id)| size == entry.size && hash == entry.hash && id == entry.id)
}

/// What became of a file asked to move or go ([`move_entry`], [`remove_entry`],
/// [`remove_own`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Took {
    /// Moved or removed: it was, right then, the file asked for.
    Done,
    /// Nothing is at its name.
    Absent,
    /// Something else is at its name (a link, another file, the file changed): left where
    /// it is, untouched.
    Other,
}

/// The file `name` in the folder held `dir`, opened itself ([`crate::platform::by_handle`]),
/// when `is_it` says, through that handle, that it is the file asked for; `Err(Took)` when
/// it is absent or something else is there (a link refused by the open itself, on Windows
/// one reached under another name too). The folder is held ([`HeldDir`]): a staging folder
/// renamed and replaced by a link to another folder meanwhile (issue 59, the hostile's
/// review) changes nothing, the open is still in the folder held.
fn open_checked<'a>(
    dir: &'a HeldDir,
    name: &str,
    is_it: impl FnOnce(&std::fs::File) -> bool,
) -> io::Result<Result<crate::platform::by_handle::Opened<'a>, Took>> {
    let opened = match crate::platform::by_handle::open_in(dir, OsStr::new(name)) {
        Ok(opened) => opened,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Err(Took::Absent)),
        Err(e) if crate::platform::os::is_link_refused(&e) => return Ok(Err(Took::Other)),
        Err(e) => return Err(e),
    };
    Ok(if is_it(opened.file()) { Ok(opened) } else { Err(Took::Other) })
}

/// Removes the empty folder `folder`, one of phonglab's own (a staging or aside folder),
/// held, from the folder held `parent` ([`HeldDir::remove_dir`]: never through a link put at
/// its name; Unix: where someone renamed it within `parent`, at its new name).
pub fn remove_own_folder(parent: &HeldDir, folder: HeldDir) -> io::Result<()> {
    parent.remove_dir(folder)
}

/// Is the open `file` exactly the one `entry` names (a regular file; its identity, size and
/// hash, read through the handle)?
fn is_entry_file(file: &std::fs::File, entry: &Entry) -> bool {
    read_open(file).is_ok_and(|(size, hash, id)| size == entry.size && hash == entry.hash && id == entry.id)
}

/// Moves the file `entry.name` from the folder held `from` to the same name in the folder
/// held `to` (where nothing is) only when it is, right then, the file `entry` names, checked
/// through the handle that moves it: the one way a set's files move (the swap, its undo,
/// the recovery). A link planted at its name (Wine: one that opens as the file it names,
/// which a move by name would have moved) or any other file there is left where it is
/// ([`Took::Other`]). `Err`: the system refused (Windows: another program holds the file
/// open without sharing its deletion).
pub fn move_entry(from: &HeldDir, to: &HeldDir, entry: &Entry) -> io::Result<Took> {
    match open_checked(from, &entry.name, |f| is_entry_file(f, entry))? {
        Ok(opened) => Ok(if opened.rename_no_replace(to, OsStr::new(&entry.name))? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// [`move_entry`] of a new file the recovery puts in place from a staging folder: only where
/// it is, through the handle that moves it, also owned by this user, so a file of anyone
/// else's in a staging folder is never put among the teacher's files, whatever a journal
/// says (issue 59, round 3, p32 D: the classmate's key replaced the teacher's). Owned, not
/// "alone": a set's file is made as the system makes any file (under a umask 000, others
/// may write it), shielded by its staging folder, which is this user's alone.
fn move_own_entry(from: &HeldDir, to: &HeldDir, entry: &Entry) -> io::Result<Took> {
    let own = |f: &std::fs::File| phonglab_core::files::private::is_owned_by_this_user(f) && is_entry_file(f, entry);
    match open_checked(from, &entry.name, own)? {
        Ok(opened) => Ok(if opened.rename_no_replace(to, OsStr::new(&entry.name))? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Removes the file `entry.name` in the folder held `dir` only when it is, right then, the
/// file `entry` names, through the handle that checked it (see [`move_entry`]): the one way
/// a set's old files go.
pub fn remove_entry(dir: &HeldDir, entry: &Entry) -> io::Result<Took> {
    match open_checked(dir, &entry.name, |f| is_entry_file(f, entry))? {
        Ok(opened) => Ok(if opened.remove()? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Removes the file `name` in a staging folder this writer made, held, when it is one of
/// phonglab's records there (a journal, its temporary file, the list of what was staged, the
/// list of what was written on its way into the folder): a regular file reached under its
/// own name (not a link; Wine: not one that opens as the file it names), through the handle
/// that checked it. A staged file goes only by its identity (`remove_staged`).
pub fn remove_own(dir: &HeldDir, name: &str) -> io::Result<Took> {
    match open_checked(dir, name, |f| crate::platform::os::regular_file_metadata(f).is_ok_and(|m| m.is_some()))? {
        Ok(opened) => Ok(if opened.remove()? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Removes the file `name` in the staging folder held `dir` when the list of what this
/// writer staged there ([`STAGED`]) names it with the identity it has now: a file staged by
/// the writer, never one put there by anyone else under a name it staged.
fn remove_staged(dir: &HeldDir, name: &str, staged: &[Staged]) -> io::Result<Took> {
    let listed = |f: &std::fs::File| {
        crate::platform::os::regular_file_metadata(f).is_ok_and(|m| m.is_some())
            && Identity::of_file(f).is_ok_and(|(_, id)| staged.iter().any(|s| s.name == name && s.id == id))
    };
    match open_checked(dir, name, listed)? {
        Ok(opened) => Ok(if opened.remove()? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Is the file `now` (its entry, read in the folder now) one that the folder's list of
/// what phonglab wrote (`written`) names with these very bytes (name, size and hash)? Its
/// identity is not asked: a folder copied whole (`cp -a`), or a file rewritten with the
/// same bytes, still holds what phonglab wrote, not the teacher's work. (Removing a file
/// asks its identity too: [`is_entry_in`].)
pub fn written_as_is(written: &[Entry], now: &Entry) -> bool {
    written.iter().any(|e| e.name == now.name && e.size == now.size && e.hash == now.hash)
}

/// Is `name` one of phonglab's own names in a set's folder (a staging folder, a journal)?
pub fn is_reserved(name: &str) -> bool {
    name.starts_with(&format!(".{STAGING}"))
}

/// A plain file name a set may hold: no folder, not `.` or `..`, not one of phonglab's own.
pub fn plain_name(name: &str) -> bool {
    !name.is_empty() && name != "." && name != ".." && !name.contains(['/', '\\']) && !is_reserved(name)
}

/// Is `name` a staging folder's name (`.phonglab-set.<...>.tmp`)?
fn is_staging_name(name: &str) -> bool {
    name.starts_with(&format!(".{STAGING}.")) && name.ends_with(".tmp")
}

/// Writes `bytes` as the new file `name` in the folder held `dir`: created exclusively
/// (never through a link), written, synced and closed; on failure removed (as phonglab's
/// own, in its own folder). Its identity, read through the handle that made it.
fn write_new_in(dir: &HeldDir, name: &str, bytes: &[u8]) -> Result<Identity, (&'static str, io::Error)> {
    let file = dir.create_private(OsStr::new(name)).map_err(|e| ("write-step-create", e))?;
    let id = Identity::of_file(&file).map(|(_, id)| id);
    let result = super::atomic_write::write_file(file, bytes);
    if result.is_err() {
        let _ = remove_own(dir, name);
    }
    result?;
    id.map_err(|e| ("write-step-create", e))
}

/// Writes `journal` into its staging folder, held, whole: a temporary file created
/// exclusively, synced, renamed over the journal (both in the folder this writer made,
/// through its handle). `counted`: the rename is one a test may make fail
/// ([`super::atomic_write::Fault::OnRename`]).
pub fn write_journal(staging: &HeldDir, journal: &Journal, counted: bool) -> Result<(), (&'static str, io::Error)> {
    let bytes = serde_json::to_vec(journal).map_err(|e| ("write-step-write", io::Error::other(e)))?;
    write_new_in(staging, JOURNAL_TMP, &bytes)?;
    let fault = if counted { super::atomic_write::rename_fault() } else { Ok(()) };
    let renamed = fault.and_then(|()| staging.rename_over(OsStr::new(JOURNAL_TMP), staging, OsStr::new(JOURNAL)));
    renamed.map_err(|e| {
        let _ = remove_own(staging, JOURNAL_TMP);
        ("write-step-rename", e)
    })?;
    staging.sync();
    Ok(())
}

/// Why a staging folder's journal is not trusted (in words, for the message).
fn untrusted(why: &str) -> String {
    t!("set-untrusted-journal", why = why)
}

/// Why one of phonglab's records (a journal, the list of what a set wrote) was not read.
enum Record {
    /// There is none.
    Missing,
    /// It could not be opened or read.
    Unreadable(io::Error),
    /// Not a regular file (a link is not followed), or past the cap.
    NotOne,
    /// Not this user's alone (another user's, or others may write it): anyone can write
    /// phonglab's form, so only the owner says phonglab wrote it (issue 59, round 2).
    NotOwn,
}

/// The bytes of one of phonglab's records at `path`: opened without following a link,
/// checked through the open handle to be a regular file of at most 1 MiB, and read whole.
fn read_record(path: &Path) -> Result<Vec<u8>, Record> {
    // Windows (Wine): a link may open as the file it points to, so it is asked first.
    if crate::platform::links::reached_through_link(path) {
        return Err(Record::NotOne);
    }
    match crate::platform::os::open_no_follow(path) {
        Ok(file) => read_record_open(file),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Err(Record::Missing),
        Err(e) => Err(Record::Unreadable(e)),
    }
}

/// [`read_record`] of the record `name` in the folder held `dir`, through its handle.
fn read_record_in(dir: &HeldDir, name: &str) -> Result<Vec<u8>, Record> {
    if cfg!(windows) && crate::platform::links::reached_through_link(&dir.path().join(name)) {
        return Err(Record::NotOne);
    }
    match dir.open_file(OsStr::new(name)) {
        Ok(file) => read_record_open(file),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Err(Record::Missing),
        Err(e) => Err(Record::Unreadable(e)),
    }
}

/// A record's bytes, read through its open handle: a regular file of at most 1 MiB.
fn read_record_open(file: std::fs::File) -> Result<Vec<u8>, Record> {
    let meta = file.metadata().map_err(Record::Unreadable)?;
    if !meta.is_file() || meta.len() > MAX_JOURNAL_BYTES {
        return Err(Record::NotOne);
    }
    if !crate::platform::os::is_this_users_alone(&file) {
        return Err(Record::NotOwn);
    }
    let mut bytes = Vec::new();
    file.take(MAX_JOURNAL_BYTES).read_to_end(&mut bytes).map_err(Record::Unreadable)?;
    Ok(bytes)
}

/// The journal of the staging folder held `staging`, when phonglab wrote it there: read
/// without following a link, under its cap, naming that very folder (its identity, read
/// through the handle) and only plain files, each once. `Ok(None)`: the folder has no
/// journal. `Err`: why it is not trusted.
fn read_journal(staging: &HeldDir) -> Result<Option<Journal>, String> {
    let bytes = match read_record_in(staging, JOURNAL) {
        Ok(bytes) => bytes,
        Err(Record::Missing) => return Ok(None),
        Err(Record::Unreadable(e)) => return Err(untrusted(&crate::io::reasons::io_reason(&e))),
        Err(Record::NotOne) => return Err(untrusted(&t!("set-why-not-a-journal"))),
        Err(Record::NotOwn) => return Err(untrusted(&t!("set-why-not-own"))),
    };
    let j: Journal = serde_json::from_slice(&bytes).map_err(|_| untrusted(&t!("set-why-not-a-journal")))?;
    let (here, id) = Identity::of_file(staging.handle()).map_err(|e| untrusted(&crate::io::reasons::io_reason(&e)))?;
    if !here.is_dir() || id != j.staging {
        return Err(untrusted(&t!("set-why-other-folder")));
    }
    if !j.new.iter().chain(&j.old).all(|e| plain_name(&e.name)) {
        return Err(untrusted(&t!("set-why-outside")));
    }
    let each_once = |entries: &[Entry]| {
        let mut n: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
        n.sort_unstable();
        n.dedup();
        n.len() == entries.len()
    };
    if !each_once(&j.new) || !each_once(&j.old) {
        return Err(untrusted(&t!("set-why-not-a-journal")));
    }
    Ok(Some(j))
}

/// Is the folder `name` in the folder held `dir` a staging folder renamed within it (under
/// Wine a Unix program can rename a folder phonglab holds: issue 59, round 2, p25), proved
/// phonglab's by this user's journal in it naming that very folder by its identity?
fn renamed_staging(dir: &HeldDir, name: &str) -> bool {
    dir.open_dir(OsStr::new(name)).is_ok_and(|sub| {
        crate::platform::os::is_this_users_alone(sub.handle())
            && sub.has(OsStr::new(JOURNAL))
            && matches!(read_journal(&sub), Ok(Some(_)))
    })
}

/// `staging`, held in `parent`, where it is now: Windows works by path, so a staging folder
/// a Unix program renamed within `parent` (under Wine) is held again at its new name, found
/// by its identity ([`HeldDir::found_again`]); as it is otherwise.
fn where_now(parent: &HeldDir, staging: HeldDir) -> HeldDir {
    if cfg!(windows)
        && !staging.still_at_its_path()
        && let Some(again) = parent.found_again(&staging)
    {
        return again;
    }
    staging
}

/// A message about `name` in `dir`, left as it is, and why.
fn left(dir: &Path, name: &str, why: &str) -> String {
    use phonglab_core::escape::terminal::text;
    t!("set-left-alone", name = text(name), dir = text(&dir.display().to_string()), why = why)
}

/// Finishes or throws away what killed writers of a set left in the folder held `dir`,
/// acting only on what phonglab wrote (see the module's documentation), every step through
/// the folders' handles ([`HeldDir`]); the caller holds the folder's lock, so every staging
/// folder with a journal is a dead writer's. Returns a message for each thing left as it is.
pub fn recover_locked(dir: &HeldDir) -> io::Result<Vec<String>> {
    let mut notices = Vec::new();
    let mut names: Vec<String> = dir.names()?.into_iter().filter_map(|n| n.into_string().ok()).collect();
    names.sort();
    let shown = dir.path();
    for name in names {
        if name == JOURNAL {
            notices.push(left(shown, &name, &t!("set-why-loose-journal")));
            continue;
        }
        if !dir.has(OsStr::new(&name)) || !(is_staging_name(&name) || renamed_staging(dir, &name)) {
            continue;
        }
        // Held itself: a link or a file of that name is not opened as a folder.
        let Ok(staging) = dir.open_dir(OsStr::new(&name)) else {
            notices.push(left(shown, &name, &t!("set-why-not-a-folder")));
            continue;
        };
        // Made by this user alone (mode 0700): another user's folder, or one others may
        // write into, holds nothing phonglab can trust, and is not its to empty or remove.
        if !crate::platform::os::is_this_users_alone(staging.handle()) {
            notices.push(left(shown, &name, &t!("set-why-folder-not-own")));
            continue;
        }
        match read_journal(&staging) {
            Ok(Some(j)) if j.decided => {
                if let Err(why) = finish(dir, staging, &j) {
                    notices.push(left(shown, &name, &why));
                }
            }
            // Stopped before the swap was decided: the old set is whole in place, and
            // the staging folder holds what this writer put in it (removed file by file,
            // each checked; anything else left, and said).
            Ok(Some(_)) => {
                if !throw_away(dir, staging) {
                    notices.push(left(shown, &name, &t!("set-why-not-all-own")));
                }
            }
            Ok(None) => {
                if !remove_if_empty(dir, staging) {
                    notices.push(left(shown, &name, &t!("set-why-no-journal")));
                }
            }
            Err(why) => notices.push(left(shown, &name, &why)),
        }
    }
    dir.sync();
    Ok(notices)
}

/// Refuses the folder `dir` when its list of what phonglab wrote ([`WRITTEN`]) is there but
/// is not one phonglab can have written: a link (dangling or not), a pipe, a device, a
/// folder, a file past 1 MiB, a file not in phonglab's form (hand-written), or one that is
/// not this user's alone (another user's, or others may write it: a forged list). Such a thing is never followed, read or replaced: a planted
/// link would send the list (its temporary file and its rename) to the file it names, and
/// a planted pipe would pass for an empty list, so that the teacher's files were blamed for
/// it. Called before anything is written, and again under the folder's lock.
pub fn check_records(dir: &Path) -> Result<(), super::atomic_write::WriteError> {
    use super::atomic_write::{WriteError, set_steps};
    let path = dir.join(WRITTEN);
    let refused = |e| Err(WriteError::new(&path, "write-step-name", e, set_steps::KEPT_FOLDER));
    match read_record(&path) {
        // One in another form than phonglab's (written by hand, or by another program):
        // not trusted, so the files it would name are not judged by it (before, each set
        // file was then blamed as the teacher's own), and left as it is.
        Ok(bytes) if serde_json::from_slice::<Vec<Entry>>(&bytes).is_err() => {
            refused(io::Error::new(io::ErrorKind::InvalidData, t!("set-record-not-phonglabs")))
        }
        Ok(_) | Err(Record::Missing) => Ok(()),
        Err(Record::NotOwn) => refused(io::Error::new(io::ErrorKind::InvalidData, t!("set-record-not-own"))),
        Err(Record::Unreadable(e)) if !crate::platform::os::is_link_refused(&e) => refused(e),
        Err(_) => refused(io::Error::new(io::ErrorKind::InvalidInput, t!("set-record-not-one"))),
    }
}

/// The files of the last set phonglab wrote into `dir`, as its list names them: empty when
/// there is no list, or it is a link, not a regular file, too large or unreadable (then nothing
/// beyond the new set's own names is replaced; a writer refuses such a list first,
/// [`check_records`]).
pub fn written_list(dir: &Path) -> Vec<Entry> {
    read_record(&dir.join(WRITTEN))
        .ok()
        .and_then(|bytes| serde_json::from_slice::<Vec<Entry>>(&bytes).ok())
        .unwrap_or_default()
}

/// [`written_list`] of the folder held `dir`, read through its handle.
pub fn written_list_in(dir: &HeldDir) -> Vec<Entry> {
    read_record_in(dir, WRITTEN)
        .ok()
        .and_then(|bytes| serde_json::from_slice::<Vec<Entry>>(&bytes).ok())
        .unwrap_or_default()
}

/// Throws away the staging folder `staging` (held, in the folder held `parent`) of a set not
/// swapped in (stopped before its journal decided, or undone): its journal first, then each
/// file in it that phonglab put there (a file it staged, by the identity the list of what it
/// staged names, `remove_staged`; its own records, [`remove_own`]: never a link, nor what
/// one leads to), then the empty aside folder and the folder itself. `false`: something else
/// is in it (a link, a folder, a file of the old set not moved back, a file at a staged
/// name that is not the one staged), left there with the folder.
pub fn throw_away(parent: &HeldDir, staging: HeldDir) -> bool {
    let staging = where_now(parent, staging);
    let _ = remove_own(&staging, JOURNAL);
    let staged = staged_list(&staging);
    if let Ok(names) = staging.names() {
        for name in names.into_iter().filter_map(|n| n.into_string().ok()) {
            if [JOURNAL_TMP, WRITTEN, STAGED].contains(&name.as_str()) {
                continue;
            }
            if name != ASIDE {
                let _ = remove_staged(&staging, &name, &staged);
            }
        }
    }
    for own in [JOURNAL_TMP, WRITTEN, STAGED] {
        let _ = remove_own(&staging, own);
    }
    remove_if_empty(parent, staging)
}

/// Removes the old set's files from the aside folder of `staging` (each only when it is,
/// right then, the file the journal names: [`remove_entry`]), then the aside folder, then
/// the journal and the list of what was staged. `false`: something was not removed
/// (another program holds a file open, or something else is there), and the journal is
/// kept, so the next run finishes.
pub fn clear_aside(staging: &HeldDir, old: &[Entry]) -> bool {
    let gone = match staging.open_dir(OsStr::new(ASIDE)) {
        Ok(aside) => {
            for entry in old {
                let _ = remove_entry(&aside, entry);
            }
            remove_own_folder(staging, aside).is_ok()
        }
        Err(e) => e.kind() == io::ErrorKind::NotFound,
    };
    let cleared = gone && matches!(remove_own(staging, JOURNAL), Ok(Took::Done | Took::Absent));
    if cleared {
        let _ = remove_own(staging, STAGED);
    }
    cleared
}

/// Removes `staging` (held, in the folder held `parent`) when it holds nothing but, at
/// most, an empty aside folder (a writer killed after it removed its journal, or before it
/// wrote one): no file is lost.
fn remove_if_empty(parent: &HeldDir, staging: HeldDir) -> bool {
    if let Ok(aside) = staging.open_dir(OsStr::new(ASIDE)) {
        let _ = remove_own_folder(&staging, aside);
    }
    remove_own_folder(parent, staging).is_ok()
}

/// Rolls the decided swap `j` forward from wherever it stopped: each old file still in
/// place, and still the one the journal names, moved aside; each new file still staged,
/// and still the one written, moved into its place where nothing is; then the staging
/// folder removed. Every step through the folders' handles. `Err`: the files it could not
/// place (something else is at their name), and the staging folder is kept with them.
fn finish(dir: &HeldDir, staging: HeldDir, j: &Journal) -> Result<(), String> {
    let mut stuck = Vec::new();
    let mut aside = None;
    for old in &j.old {
        if is_entry_in(dir, old) {
            if aside.is_none() {
                aside = staging.open_dir(OsStr::new(ASIDE)).or_else(|_| staging.create_dir(OsStr::new(ASIDE))).ok();
            }
            let moved = aside.as_ref().is_some_and(|a| matches!(move_entry(dir, a, old), Ok(Took::Done)));
            if !moved {
                stuck.push(old.name.clone());
            }
        }
    }
    drop(aside);
    for new in &j.new {
        if is_entry_in(dir, new) {
            continue;
        }
        if !matches!(move_own_entry(&staging, dir, new), Ok(Took::Done)) {
            stuck.push(new.name.clone());
        }
    }
    dir.sync();
    if !stuck.is_empty() {
        // The new files now in place, exactly as written, are recorded as phonglab's, so
        // that the next set removes those it lacks (issue 59, #70: a stopped set of 40
        // whose file the teacher edited stayed beside the next set of 2, named by no
        // record); what could not be placed is named to the user, and kept.
        let placed: Vec<Entry> = j.new.iter().filter(|e| is_entry_in(dir, e)).cloned().collect();
        write_written_list(dir, &staging, &placed);
        stuck.sort();
        stuck.dedup();
        let names = phonglab_core::escape::terminal::text(&stuck.join(", "));
        return Err(t!("set-why-unfinished", names = names));
    }
    write_written_list(dir, &staging, &j.new);
    if !clear_aside(&staging, &j.old) {
        return Err(t!("set-why-not-all-own"));
    }
    let _ = remove_own_folder(dir, staging);
    Ok(())
}

/// Records, whole, the files a set wrote into the folder held `dir` ([`WRITTEN`]), with
/// those the list named before that are still there with the bytes phonglab wrote (in a
/// copied folder too: their entries kept as they were, so they stay phonglab's to replace;
/// another kind of set's files: the sheets beside a Moodle file, which the Moodle file
/// leaves in place, stay phonglab's to replace); a failure only leaves them for the next set
/// to keep. The list is written in the set's staging folder (made by this writer, held) and
/// renamed over the name in `dir`, both through the folders' handles: a rename replaces a
/// name, never follows it, so a link planted there since [`check_records`] is replaced
/// itself, and nothing is written where it points.
pub fn write_written_list(dir: &HeldDir, staging: &HeldDir, new: &[Entry]) {
    let mut all = new.to_vec();
    for earlier in written_list_in(dir) {
        // Still there with the bytes phonglab wrote, as [`written_as_is`] recognises it (a
        // folder copied whole has new identities): kept as the list named it.
        let unchanged =
            || entry_in(dir, &earlier.name).is_ok_and(|now| written_as_is(std::slice::from_ref(&earlier), &now));
        if !all.iter().any(|e| e.name == earlier.name) && unchanged() {
            all.push(earlier);
        }
    }
    let Ok(list) = serde_json::to_vec(&all) else { return };
    // One a killed writer left in its own staging folder (the journal said it is one).
    let _ = remove_own(staging, WRITTEN);
    if write_new_in(staging, WRITTEN, &list).is_ok()
        && staging.rename_over(OsStr::new(WRITTEN), dir, OsStr::new(WRITTEN)).is_err()
    {
        let _ = remove_own(staging, WRITTEN);
    }
}

/// One file a writer staged, as the list of what it staged names it ([`STAGED`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
struct Staged {
    name: String,
    id: Identity,
}

/// The list of what the writer of the staging folder held `staging` staged there: one
/// JSON line per file; a line cut short by a kill, or anything else, is no file's.
fn staged_list(staging: &HeldDir) -> Vec<Staged> {
    let Ok(bytes) = read_record_in(staging, STAGED) else { return Vec::new() };
    bytes.split(|b| *b == b'\n').filter_map(|line| serde_json::from_slice(line).ok()).collect()
}

/// Appends `staged` to the list of what this writer staged ([`STAGED`]), synced: before a
/// byte of the staged file is written, so that a writer killed from then on leaves the
/// file named there by its identity, and the recovery removes it as the one staged.
fn note_staged(staging: &HeldDir, staged: &Staged) -> io::Result<()> {
    use std::io::Write as _;
    let mut line = serde_json::to_vec(staged).map_err(io::Error::other)?;
    line.push(b'\n');
    let mut list = staging.append(OsStr::new(STAGED))?;
    list.write_all(&line)?;
    list.sync_all()
}

/// Writes `bytes` as a new file `name` in the staging folder held `staging`: created
/// exclusively (never through a link), noted in the list of what was staged with the
/// identity read through the handle that made it (`note_staged`), then written and
/// synced; its entry for the journal.
pub fn stage(staging: &HeldDir, name: &str, bytes: &[u8]) -> Result<Entry, (&'static str, io::Error)> {
    let file = staging.create_new(OsStr::new(name)).map_err(|e| ("write-step-create", e))?;
    let noted = Identity::of_file(&file).and_then(|(_, id)| {
        note_staged(staging, &Staged { name: name.to_string(), id })?;
        Ok(id)
    });
    let id = match noted {
        Ok(id) => id,
        Err(e) => {
            {
                // Closed before it is removed (a block, not `drop`: in the browser's
                // build a File has nothing to drop, and clippy says so).
                let _closed = file;
            }
            let _ = remove_own(staging, name);
            return Err(("write-step-create", e));
        }
    };
    if let Err(e) = super::atomic_write::write_file(file, bytes) {
        let _ = remove_staged(staging, name, &[Staged { name: name.to_string(), id }]);
        return Err(e);
    }
    Ok(Entry { name: name.to_string(), size: bytes.len() as u64, hash: hash_bytes(bytes), id })
}

#[cfg(test)]
mod tests;
