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
//! - the journal names the staging folder by its identity (Unix: device, inode and birth
//!   time; Windows: the volume's serial number and the file index; what a file gets when it
//!   is made, which nobody planting a file can choose) and names
//!   only plain files of the target folder, each with its identity, size and hash
//!   (SipHash-1-3, 128 bits): the new set's files, written in that run into the staging
//!   folder, and the old set's files it replaces;
//! - recovery acts on a staging folder only when its journal is there, read without
//!   following a link, and names that very folder; it moves or removes a file only when
//!   the file is the one the journal names (identity, size and hash), and it never renames
//!   over a file. Anything else (a journal in another form, a link or a file named like a
//!   staging folder, a staging folder without a journal or with a journal that is not its
//!   own, a file changed since) is left as it is, and a message says so.

use std::hash::Hasher as _;
use std::io::{self, Read};
use std::path::Path;

use serde::{Deserialize, Serialize};
use siphasher::sip128::{Hasher128, SipHasher13};

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

/// The entry of the file `name` in `folder`, read there now.
pub fn entry_of(folder: &Path, name: &str) -> io::Result<Entry> {
    let (size, hash, id) = read_entry(&folder.join(name))?;
    Ok(Entry { name: name.to_string(), size, hash, id })
}

/// Is the file at `path` exactly the one `entry` names (identity, size and hash)?
pub fn is_entry(path: &Path, entry: &Entry) -> bool {
    let Ok((meta, id)) = Identity::at(path) else { return false };
    if !meta.is_file() || id != entry.id || meta.len() != entry.size {
        return false;
    }
    read_entry(path).is_ok_and(|(size, hash, id)| size == entry.size && hash == entry.hash && id == entry.id)
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

/// The file at `path`, opened itself ([`crate::platform::by_handle`]), when `is_it` says,
/// through that handle, that it is the file asked for; `Err(Took)` when it is absent or
/// something else is there (a link refused by the open itself, on Windows one reached
/// under another name too).
fn open_checked(
    path: &Path,
    is_it: impl FnOnce(&std::fs::File) -> bool,
) -> io::Result<Result<crate::platform::by_handle::Opened, Took>> {
    // A staging or aside folder on the way swapped for a link (issue 59, the hostile's
    // review: a staging folder renamed and a link to another folder put at its name made
    // the clean-up remove every file there): asked before the open and after it, so a swap
    // between the two is seen too.
    let folders_real = || path.parent().is_none_or(own_folders_real);
    if !folders_real() {
        return Ok(Err(Took::Other));
    }
    let opened = match crate::platform::by_handle::open(path) {
        Ok(opened) => opened,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Err(Took::Absent)),
        Err(e) if crate::platform::os::is_link_refused(&e) => return Ok(Err(Took::Other)),
        Err(e) => return Err(e),
    };
    Ok(if folders_real() && is_it(opened.file()) { Ok(opened) } else { Err(Took::Other) })
}

/// Are `folder` and the folders of phonglab's own it is in (a staging folder, its aside
/// folder: it and its ancestors named like them, up to the first that is not) real folders,
/// reached under their own names, not links? The folder they are in is the one held,
/// checked by its identity ([`super::file_set::hold_folder`]).
pub fn own_folders_real(folder: &Path) -> bool {
    folder.ancestors().take_while(|a| a.file_name().and_then(|n| n.to_str()).is_some_and(is_own_folder_name)).all(|a| {
        std::fs::symlink_metadata(a).is_ok_and(|m| m.is_dir() && !m.file_type().is_symlink())
            && !crate::platform::links::reached_through_link(a)
    })
}

/// Removes the empty `folder`, a staging or aside folder of phonglab's own, only when it
/// and the folders of phonglab's own it is in are real ([`own_folders_real`]): a link at
/// its name (Wine: `RemoveDirectory` through it removed the folder it led to) is left.
pub fn remove_own_folder(folder: &Path) -> io::Result<()> {
    if !own_folders_real(folder) {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, "not a folder of phonglab's own"));
    }
    std::fs::remove_dir(folder)
}

/// A name phonglab gives a folder of its own inside a set's folder: a staging folder, or
/// the aside folder in one.
fn is_own_folder_name(name: &str) -> bool {
    is_staging_name(name) || name == ASIDE
}

/// Is the open `file` exactly the one `entry` names (a regular file; its identity, size and
/// hash, read through the handle)?
fn is_entry_file(file: &std::fs::File, entry: &Entry) -> bool {
    read_open(file).is_ok_and(|(size, hash, id)| size == entry.size && hash == entry.hash && id == entry.id)
}

/// Moves the file at `from` to `to` (where nothing is) only when it is, right then, the file
/// `entry` names, checked through the handle that moves it: the one way a set's files move
/// (the swap, its undo, the recovery). A link planted at `from` (Wine: one that opens as
/// the file it names, which a move by name would have moved) or any other file there is
/// left where it is ([`Took::Other`]). `Err`: the system refused (Windows: another program
/// holds the file open without sharing its deletion).
pub fn move_entry(from: &Path, to: &Path, entry: &Entry) -> io::Result<Took> {
    // Nor into a staging or aside folder swapped for a link: the file would leave the folder.
    if !to.parent().is_none_or(own_folders_real) {
        return Ok(Took::Other);
    }
    match open_checked(from, |f| is_entry_file(f, entry))? {
        Ok(opened) => Ok(if opened.rename_no_replace(to)? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Removes the file at `path` only when it is, right then, the file `entry` names, through
/// the handle that checked it (see [`move_entry`]): the one way a set's old files go.
pub fn remove_entry(path: &Path, entry: &Entry) -> io::Result<Took> {
    match open_checked(path, |f| is_entry_file(f, entry))? {
        Ok(opened) => Ok(if opened.remove()? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Removes the file at `path`, one of phonglab's own in a staging folder this writer made (a
/// journal, a temporary file, a file staged before the journal named it), only when it is
/// a regular file reached under its own name (not a link; Wine: not one that opens as the
/// file it names), through the handle that checked it.
pub fn remove_own(path: &Path) -> io::Result<Took> {
    match open_checked(path, |f| crate::platform::os::regular_file_metadata(f).is_ok_and(|m| m.is_some()))? {
        Ok(opened) => Ok(if opened.remove()? { Took::Done } else { Took::Other }),
        Err(took) => Ok(took),
    }
}

/// Is the file `now` (its entry, read in the folder now) one that the folder's list of
/// what phonglab wrote (`written`) names with these very bytes (name, size and hash)? Its
/// identity is not asked: a folder copied whole (`cp -a`), or a file rewritten with the
/// same bytes, still holds what phonglab wrote, not the teacher's work. (Removing a file
/// asks its identity too: [`is_entry`].)
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

/// Writes `journal` into its staging folder whole: a temporary file created exclusively,
/// synced, renamed over the journal (both in the folder this writer made). `counted`: the
/// rename is one a test may make fail ([`super::atomic_write::Fault::OnRename`]).
pub fn write_journal(staging: &Path, journal: &Journal, counted: bool) -> Result<(), (&'static str, io::Error)> {
    let bytes = serde_json::to_vec(journal).map_err(|e| ("write-step-write", io::Error::other(e)))?;
    let tmp = staging.join(JOURNAL_TMP);
    super::atomic_write::write_new(&tmp, &bytes)?;
    let renamed = if counted {
        super::atomic_write::rename(&tmp, &staging.join(JOURNAL))
    } else {
        std::fs::rename(&tmp, staging.join(JOURNAL))
    };
    renamed.map_err(|e| {
        let _ = remove_own(&tmp);
        ("write-step-rename", e)
    })?;
    crate::platform::os::sync_folder(staging);
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
}

/// The bytes of one of phonglab's records at `path`: opened without following a link,
/// checked through the open handle to be a regular file of at most 1 MiB, and read whole.
fn read_record(path: &Path) -> Result<Vec<u8>, Record> {
    // Windows (Wine): a link may open as the file it points to, so it is asked first.
    if crate::platform::links::reached_through_link(path) {
        return Err(Record::NotOne);
    }
    let file = match crate::platform::os::open_no_follow(path) {
        Ok(f) => f,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Err(Record::Missing),
        Err(e) => return Err(Record::Unreadable(e)),
    };
    let meta = file.metadata().map_err(Record::Unreadable)?;
    if !meta.is_file() || meta.len() > MAX_JOURNAL_BYTES {
        return Err(Record::NotOne);
    }
    let mut bytes = Vec::new();
    file.take(MAX_JOURNAL_BYTES).read_to_end(&mut bytes).map_err(Record::Unreadable)?;
    Ok(bytes)
}

/// The journal of the staging folder `staging`, when phonglab wrote it there: read without
/// following a link, under its cap, naming that very folder and only plain files, each
/// once. `Ok(None)`: the folder has no journal. `Err`: why it is not trusted.
fn read_journal(staging: &Path) -> Result<Option<Journal>, String> {
    let bytes = match read_record(&staging.join(JOURNAL)) {
        Ok(bytes) => bytes,
        Err(Record::Missing) => return Ok(None),
        Err(Record::Unreadable(e)) => return Err(untrusted(&crate::io::reasons::io_reason(&e))),
        Err(Record::NotOne) => return Err(untrusted(&t!("set-why-not-a-journal"))),
    };
    let j: Journal = serde_json::from_slice(&bytes).map_err(|_| untrusted(&t!("set-why-not-a-journal")))?;
    let (here, id) = Identity::at(staging).map_err(|e| untrusted(&crate::io::reasons::io_reason(&e)))?;
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

/// A message about `name` in `dir`, left as it is, and why.
fn left(dir: &Path, name: &str, why: &str) -> String {
    use phonglab_core::escape::terminal::text;
    t!("set-left-alone", name = text(name), dir = text(&dir.display().to_string()), why = why)
}

/// Finishes or throws away what killed writers of a set left in `dir`, acting only on
/// what phonglab wrote (see the module's documentation); the caller holds the folder's
/// lock, so every staging folder with a journal is a dead writer's. Returns a message for
/// each thing left as it is.
pub fn recover_locked(dir: &Path) -> io::Result<Vec<String>> {
    let mut notices = Vec::new();
    let mut names: Vec<String> =
        std::fs::read_dir(dir)?.flatten().filter_map(|e| e.file_name().into_string().ok()).collect();
    names.sort();
    for name in names {
        if name == JOURNAL {
            notices.push(left(dir, &name, &t!("set-why-loose-journal")));
            continue;
        }
        if !is_staging_name(&name) {
            continue;
        }
        let staging = dir.join(&name);
        let Ok(meta) = std::fs::symlink_metadata(&staging) else { continue };
        if !meta.is_dir() {
            notices.push(left(dir, &name, &t!("set-why-not-a-folder")));
            continue;
        }
        match read_journal(&staging) {
            Ok(Some(j)) if j.decided => {
                if let Err(why) = finish(dir, &staging, &j) {
                    notices.push(left(dir, &name, &why));
                }
            }
            // Stopped before the swap was decided: the old set is whole in place, and
            // the staging folder holds what this writer put in it (removed file by file,
            // each checked; anything else left, and said).
            Ok(Some(_)) => {
                if !throw_away(&staging) {
                    notices.push(left(dir, &name, &t!("set-why-not-all-own")));
                }
            }
            Ok(None) => {
                if !remove_if_empty(&staging) {
                    notices.push(left(dir, &name, &t!("set-why-no-journal")));
                }
            }
            Err(why) => notices.push(left(dir, &name, &why)),
        }
    }
    crate::platform::os::sync_folder(dir);
    Ok(notices)
}

/// Refuses the folder `dir` when its list of what phonglab wrote ([`WRITTEN`]) is there but
/// is not one phonglab can have written: a link (dangling or not), a pipe, a device, a
/// folder, or a file past 1 MiB. Such a thing is never followed, read or replaced: a planted
/// link would send the list (its temporary file and its rename) to the file it names, and
/// a planted pipe would pass for an empty list, so that the teacher's files were blamed for
/// it. Called before anything is written, and again under the folder's lock.
pub fn check_records(dir: &Path) -> Result<(), super::atomic_write::WriteError> {
    use super::atomic_write::{WriteError, set_steps};
    let path = dir.join(WRITTEN);
    let refused = |e| Err(WriteError::new(&path, "write-step-name", e, set_steps::KEPT_FOLDER));
    match read_record(&path) {
        Ok(_) | Err(Record::Missing) => Ok(()),
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

/// Throws away the staging folder `staging` of a set not swapped in (stopped before its
/// journal decided, or undone): its journal first, then each regular file in it that is
/// phonglab's own ([`remove_own`]: never a link, nor what one leads to), then the empty
/// aside folder and the folder itself. `false`: something else is in it (a link, a folder, a
/// file of the old set not moved back), left there with the folder.
pub fn throw_away(staging: &Path) -> bool {
    if !own_folders_real(staging) {
        return false;
    }
    let _ = remove_own(&staging.join(JOURNAL));
    if let Ok(entries) = std::fs::read_dir(staging) {
        for entry in entries.flatten() {
            if entry.file_name() != ASIDE {
                let _ = remove_own(&entry.path());
            }
        }
    }
    remove_if_empty(staging)
}

/// Removes the old set's files from the aside folder of `staging` (each only when it is,
/// right then, the file the journal names: [`remove_entry`]), then the aside folder, then
/// the journal. `false`: something was not removed (another program holds a file open, or
/// something else is there), and the journal is kept, so the next run finishes.
pub fn clear_aside(staging: &Path, old: &[Entry]) -> bool {
    let aside = staging.join(ASIDE);
    for entry in old {
        let _ = remove_entry(&aside.join(&entry.name), entry);
    }
    let gone = match remove_own_folder(&aside) {
        Ok(()) => true,
        Err(e) => e.kind() == io::ErrorKind::NotFound,
    };
    gone && matches!(remove_own(&staging.join(JOURNAL)), Ok(Took::Done | Took::Absent))
}

/// Removes `staging` when it holds nothing but, at most, an empty aside folder (a writer
/// killed after it removed its journal, or before it wrote one): no file is lost.
fn remove_if_empty(staging: &Path) -> bool {
    // Only real folders of phonglab's own (remove_own_folder: a link planted at a staging
    // folder's name, under Wine, removed the empty folder it led to).
    let _ = remove_own_folder(&staging.join(ASIDE));
    remove_own_folder(staging).is_ok()
}

/// Rolls the decided swap `j` forward from wherever it stopped: each old file still in
/// place, and still the one the journal names, moved aside; each new file still staged,
/// and still the one written, moved into its place where nothing is; then the staging
/// folder removed. `Err`: the files it could not place (something else is at their name),
/// and the staging folder is kept with them.
fn finish(dir: &Path, staging: &Path, j: &Journal) -> Result<(), String> {
    let aside = staging.join(ASIDE);
    let mut stuck = Vec::new();
    for old in &j.old {
        if is_entry(&dir.join(&old.name), old) {
            let _ = std::fs::create_dir(&aside);
            if !matches!(move_entry(&dir.join(&old.name), &aside.join(&old.name), old), Ok(Took::Done)) {
                stuck.push(old.name.clone());
            }
        }
    }
    for new in &j.new {
        let (staged, target) = (staging.join(&new.name), dir.join(&new.name));
        if is_entry(&target, new) {
            continue;
        }
        if !matches!(move_entry(&staged, &target, new), Ok(Took::Done)) {
            stuck.push(new.name.clone());
        }
    }
    crate::platform::os::sync_folder(dir);
    if !stuck.is_empty() {
        // The new files now in place, exactly as written, are recorded as phonglab's, so
        // that the next set removes those it lacks (issue 59, #70: a stopped set of 40
        // whose file the teacher edited stayed beside the next set of 2, named by no
        // record); what could not be placed is named to the user, and kept.
        let placed: Vec<Entry> = j.new.iter().filter(|e| is_entry(&dir.join(&e.name), e)).cloned().collect();
        write_written_list(dir, staging, &placed);
        stuck.sort();
        stuck.dedup();
        let names = phonglab_core::escape::terminal::text(&stuck.join(", "));
        return Err(t!("set-why-unfinished", names = names));
    }
    write_written_list(dir, staging, &j.new);
    if !clear_aside(staging, &j.old) {
        return Err(t!("set-why-not-all-own"));
    }
    let _ = remove_own_folder(staging);
    Ok(())
}

/// Records, whole, the files a set wrote into `dir` ([`WRITTEN`]), with those the list
/// named before that are still there with the bytes phonglab wrote (in a copied folder
/// too: their entries kept as they were, so they stay phonglab's to replace; another kind of set's
/// files: the sheets beside a Moodle file, which the Moodle file leaves in place, stay
/// phonglab's to replace); a failure only leaves them for the next set to keep. The list is
/// written in the set's staging folder (made by this writer) and renamed over the name in
/// `dir`: a rename replaces a name, never follows it, so a link planted there since
/// [`check_records`] is replaced itself, and nothing is written where it points.
pub fn write_written_list(dir: &Path, staging: &Path, new: &[Entry]) {
    let mut all = new.to_vec();
    for earlier in written_list(dir) {
        // Still there with the bytes phonglab wrote, as [`written_as_is`] recognises it (a
        // folder copied whole has new identities): kept as the list named it.
        let unchanged =
            || entry_of(dir, &earlier.name).is_ok_and(|now| written_as_is(std::slice::from_ref(&earlier), &now));
        if !all.iter().any(|e| e.name == earlier.name) && unchanged() {
            all.push(earlier);
        }
    }
    let Ok(list) = serde_json::to_vec(&all) else { return };
    let tmp = staging.join(WRITTEN);
    // One a killed writer left in its own staging folder (the journal said it is one).
    let _ = remove_own(&tmp);
    if super::atomic_write::write_new(&tmp, &list).is_ok() && std::fs::rename(&tmp, dir.join(WRITTEN)).is_err() {
        let _ = remove_own(&tmp);
    }
}

/// Writes `bytes` as a new file `name` in the staging folder: created exclusively (never
/// through a link), synced; its entry for the journal (the identity read back from it).
pub fn stage(staging: &Path, name: &str, bytes: &[u8]) -> Result<Entry, (&'static str, io::Error)> {
    let path = staging.join(name);
    super::atomic_write::write_new(&path, bytes)?;
    let (_, id) = Identity::at(&path).map_err(|e| ("write-step-create", e))?;
    Ok(Entry { name: name.to_string(), size: bytes.len() as u64, hash: hash_bytes(bytes), id })
}

#[cfg(test)]
mod tests;
