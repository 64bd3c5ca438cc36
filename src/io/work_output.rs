//! The outputs of the commands that read students' work: `check FOLDER`'s report, the
//! chart beside it and the marks, and `diagnose`'s difference image. A class folder is
//! unzipped from a learning platform, and a picture sits among the other students', so
//! anything at an output's name may be a student's. One rule for all of them, kept here:
//!
//! - a symbolic link at the output's name is refused, never written through (a planted
//!   `report.md -> ../../.bashrc` would replace the teacher's file; a dangling link would
//!   make its target);
//! - a file already there is replaced only where it is phonglab's own earlier output of the
//!   same kind, known by its bytes ([`Kind::is_own`]: the report's title line, the marks'
//!   header, the PNG's `Software` text), and its whole bytes are still what phonglab wrote
//!   there: the record phonglab kept of it (size, hash and identity, in its data folder:
//!   [`written_as_recorded`]); anything else (another student's picture, the teacher's
//!   notes, phonglab's output with a teacher's line added) is refused, named, and left as
//!   it is;
//! - inside the checked folder, a name that `check` reads as a submission (`.ipynb`), or a
//!   student's script (`.py`), is refused: the next check would count it as a student.
//!
//! What passes is written whole, at the name itself, following no link
//! ([`crate::io::atomic_write::write_here`]), and the look is taken again just before the
//! write (a folder's check takes seconds). The window writes none of these outputs.

use std::io::Read;
use std::path::Path;

use crate::t;

/// Which output it is: how phonglab knows its own earlier one, and what it is called.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `check FOLDER --report R.md`.
    Report,
    /// `check FOLDER --csv M.csv`.
    Marks,
    /// The bar chart beside the report (`R.png`).
    Chart,
    /// `diagnose --diff D.png`.
    Difference,
}

/// The marks' columns, their header's names in the catalogue (`check FOLDER --csv`):
/// `verdict` in the teacher's words, `verdict_id` the same for machines (`right`, `wrong`,
/// `incomplete`, `unread`), joined by the teacher's separator ([`marks_separator`]). In
/// English the names are the ids they always were (`file`, `verdict`, ...).
pub const MARKS_COLUMNS: [&str; 6] = [
    "marks-column-file",
    "marks-column-verdict",
    "marks-column-first-wrong",
    "marks-column-causes",
    "marks-column-cause-ids",
    "marks-column-verdict-id",
];

/// The header of marks written before `verdict` was in the teacher's words (it held the
/// id): still phonglab's own, replaced by a run again.
const MARKS_HEADER_BEFORE: &str = "file,verdict,first_wrong,causes,cause_ids";

/// The marks' first bytes: UTF-8's byte order mark. Excel in Portuguese reads a CSV
/// without it in the system's code page ("não" garbled); Moodle's import and LibreOffice
/// skip it.
pub const MARKS_BOM: &str = "\u{feff}";

/// The marks' separator in the language set: `,` in English, `;` in Portuguese, as a
/// spreadsheet in that language reads a CSV opened with a double click (its decimal mark
/// is the comma). Moodle's grade import takes either, chosen on its form.
pub fn marks_separator() -> char {
    match phonglab_core::locale::current().lang {
        phonglab_core::locale::Lang::En => ',',
        _ => ';',
    }
}

/// The marks' header in the language set, its columns joined by `separator`.
pub fn marks_header(separator: char) -> String {
    marks_header_in(phonglab_core::locale::current().lang, separator)
}

/// The marks' header in `lang`, its columns joined by `separator` (each a CSV field).
fn marks_header_in(lang: phonglab_core::locale::Lang, separator: char) -> String {
    let names: Vec<String> = MARKS_COLUMNS
        .iter()
        .map(|id| phonglab_core::escape::csv::text_field(&crate::locale::tr_in(lang, id, &[])))
        .collect();
    names.join(&separator.to_string())
}

/// The most bytes read of a file at an output's name to know whether phonglab wrote it.
const HEAD_BYTES: u64 = 4096;

impl Kind {
    /// The `Software` text of this kind's PNG (`None`: not a picture).
    pub fn png_text(self) -> Option<&'static str> {
        match self {
            Kind::Chart => Some("phonglab check --report (the causes' chart)"),
            Kind::Difference => Some("phonglab diagnose --diff"),
            Kind::Report | Kind::Marks => None,
        }
    }

    /// The output in the user's words.
    fn words(self) -> String {
        match self {
            Kind::Report => t!("work-output-kind-report"),
            Kind::Marks => t!("work-output-kind-marks"),
            Kind::Chart => t!("work-output-kind-chart"),
            Kind::Difference => t!("work-output-kind-difference"),
        }
    }

    /// The extension a name for it takes (suggested in place of a submission's).
    fn extension(self) -> &'static str {
        match self {
            Kind::Report => "md",
            Kind::Marks => "csv",
            Kind::Chart | Kind::Difference => "png",
        }
    }

    /// Whether `head`, the first bytes of a file, are this kind of phonglab's output: the
    /// report's first line is its title in one of phonglab's languages (a teacher re-runs
    /// in another), the marks' is their header, a picture holds this kind's `Software`
    /// text before its pixels. (Anyone can write these bytes: a student who does makes
    /// only their own file replaceable.)
    pub fn is_own(self, head: &[u8]) -> bool {
        let first_line = || {
            let line = head.split(|&b| b == b'\n').next().unwrap_or_default();
            String::from_utf8_lossy(line.strip_suffix(b"\r").unwrap_or(line)).into_owned()
        };
        match self {
            Kind::Report => phonglab_core::locale::Lang::ALL.iter().any(|&lang| {
                let title = crate::locale::tr_in(lang, "check-report-title", &[]);
                first_line() == format!("# {}", phonglab_core::escape::markdown::text(&title))
            }),
            Kind::Marks => {
                // Written with a byte order mark, or before there was one.
                let line = first_line();
                let line = line.strip_prefix(MARKS_BOM).unwrap_or(&line);
                let any = phonglab_core::locale::Lang::ALL
                    .iter()
                    .any(|&lang| [',', ';'].iter().any(|&sep| line == marks_header_in(lang, sep)));
                any || line == MARKS_HEADER_BEFORE
            }
            Kind::Chart | Kind::Difference => self.png_text().is_some_and(|text| png_says(head, text)),
        }
    }
}

/// Whether the PNG whose first bytes are `head` holds the text chunk `Software` = `text`
/// before its pixels (where phonglab's encoder writes it, right after the header).
fn png_says(head: &[u8], text: &str) -> bool {
    let want = [crate::io::image::PNG_SIGNATURE_KEYWORD.as_bytes(), &[0], text.as_bytes()].concat();
    let Some(mut rest) = head.strip_prefix(b"\x89PNG\r\n\x1a\n".as_slice()) else { return false };
    while let (Some(len), Some(kind)) = (rest.get(0..4), rest.get(4..8)) {
        let len = u32::from_be_bytes([len[0], len[1], len[2], len[3]]) as usize;
        if kind == b"IDAT" {
            return false;
        }
        let Some(data) = rest.get(8..8 + len) else { return false };
        if kind == b"tEXt" && data == want.as_slice() {
            return true;
        }
        rest = rest.get(8 + len + 4..).unwrap_or_default();
    }
    false
}

/// The first bytes of the regular file at `path`, opened following no link.
fn head_of(path: &Path) -> std::io::Result<Vec<u8>> {
    let mut head = Vec::new();
    crate::platform::os::open_no_follow(path)?.take(HEAD_BYTES).read_to_end(&mut head)?;
    Ok(head)
}

/// Whether `path`'s folder is the folder `dir` (by any path to it).
fn in_folder(path: &Path, dir: &Path) -> bool {
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    match (std::fs::canonicalize(parent), std::fs::canonicalize(dir)) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// Why the output `path` of this `kind` may not be written, if it may not (see the
/// module's rule); `checked`: the folder `check` reads, where there is one. A file name in
/// the words is written visibly for the terminal.
fn refusal(path: &Path, kind: Kind, checked: Option<&Path>) -> Option<String> {
    let shown = crate::io::reasons::shown(path);
    if let Some(why) = link_refusal(path, kind) {
        return Some(why);
    }
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_file() => {
            let head = match head_of(path) {
                Ok(head) => head,
                Err(e) if crate::platform::os::is_link_refused(&e) => {
                    return Some(t!("work-output-link", path = shown));
                }
                Err(_) => Vec::new(),
            };
            if !kind.is_own(&head) {
                return Some(not_own(&shown, kind, &head));
            }
            match recorded(path) {
                Recorded::Same => {}
                Recorded::Changed => return Some(t!("work-output-changed", path = shown, kind = kind.words())),
                Recorded::None => return Some(t!("work-output-no-record", path = shown, kind = kind.words())),
                Recorded::Untrusted(dir) => {
                    let records = crate::io::reasons::shown(&dir);
                    return Some(t!(
                        "work-output-records-untrusted",
                        path = shown,
                        kind = kind.words(),
                        records = records
                    ));
                }
            }
        }
        // Nothing there; anything else there (a folder, a device) the write refuses.
        _ => {}
    }
    let submission = crate::io::student_code::student_code(path).is_some();
    if submission && checked.is_some_and(|dir| in_folder(path, dir)) {
        let name = path.with_extension(kind.extension());
        let suggested = name.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let suggested = phonglab_core::escape::terminal::text(&suggested);
        return Some(t!("work-output-submission", path = shown, suggested = suggested));
    }
    None
}

/// Why the output `path` of this `kind` may not be written where it is a link: a link as
/// Linux shows it, or as Windows does (Wine shows a Unix link as a plain file: only its
/// final path tells it, issue 59 finding 4, where the link was replaced).
fn link_refusal(path: &Path, kind: Kind) -> Option<String> {
    let m = std::fs::symlink_metadata(path).ok()?;
    if !m.file_type().is_symlink() && !crate::platform::links::reached_through_link(path) {
        return None;
    }
    let shown = crate::io::reasons::shown(path);
    // The chart's name is derived from the report's, not given: said so.
    Some(if kind == Kind::Chart { t!("check-chart-link", path = shown) } else { t!("work-output-link", path = shown) })
}

/// Refuses the first of `outputs` that is a link ([`refuse`]'s first rule), before the
/// outputs are compared with each other and with the inputs: two output names that are
/// links to one file are links (never written through), not "the same file" (a refusal
/// that would send the teacher to rename one of them, still a link).
pub fn refuse_links(outputs: &[(&Path, Kind)]) -> Result<(), String> {
    outputs.iter().find_map(|&(path, kind)| link_refusal(path, kind)).map_or(Ok(()), Err)
}

/// Why a file at an output's name that is not phonglab's earlier output of this `kind` is
/// refused: where it is phonglab's output of another kind (a report given as the marks'
/// name, issue 59), that, since "phonglab did not write it" would be untrue; one output
/// never takes another's place (the teacher's report stays theirs to keep).
fn not_own(shown: &str, kind: Kind, head: &[u8]) -> String {
    let kinds = [Kind::Report, Kind::Marks, Kind::Chart, Kind::Difference];
    match kinds.into_iter().find(|&other| other != kind && other.is_own(head)) {
        Some(found) => t!("work-output-other-kind", path = shown, found = found.words(), kind = kind.words()),
        None => t!("work-output-not-ours", path = shown, kind = kind.words()),
    }
}

/// Refuses, before any work, the outputs the rule forbids (the first one's reason), and
/// tries each destination ([`crate::io::atomic_write::check_file_destination`]).
pub fn refuse(outputs: &[(&Path, Kind)], checked: Option<&Path>) -> Result<(), String> {
    for &(path, kind) in outputs {
        if let Some(why) = refusal(path, kind, checked) {
            return Err(why);
        }
        crate::io::atomic_write::check_file_destination(path).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// Writes the output `path` of this `kind` whole, at the name itself, after looking again
/// ([`refuse`]'s rule; nothing written where it refuses).
pub fn write(path: &Path, kind: Kind, checked: Option<&Path>, bytes: &[u8]) -> Result<(), String> {
    if let Some(why) = refusal(path, kind, checked) {
        return Err(why);
    }
    crate::io::atomic_write::write_here(path, bytes).map_err(|e| e.to_string())?;
    remember(path);
    Ok(())
}

/// The folder, in phonglab's data folder ([`crate::platform::storage::storage_dir`]), of
/// the records of the outputs it wrote: one small file for each output's place, named by
/// the hash of that place (so two runs writing two outputs never write one record).
const RECORDS: &str = "outputs-written";

/// The most bytes of a record read (one is about 300).
const MAX_RECORD_BYTES: u64 = 64 * 1024;

/// What phonglab wrote at an output's place: the place (its folder's real path and its
/// name), and the file's size, hash and identity just after the write.
#[derive(serde::Serialize, serde::Deserialize)]
struct Record {
    place: String,
    entry: crate::io::set_journal::Entry,
}

/// The place of `path`: its folder's real path, joined with its name (the name itself is
/// never followed: a link there is refused before).
fn place_of(path: &Path) -> Option<String> {
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    Some(std::fs::canonicalize(parent).ok()?.join(path.file_name()?).to_string_lossy().into_owned())
}

/// The record file of the output at `path`, and its place; `None` where phonglab has no
/// data folder (nothing is then kept, and nothing already there is replaced).
fn record_of(path: &Path) -> Option<(std::path::PathBuf, String)> {
    let place = place_of(path)?;
    let dir = crate::platform::storage::storage_dir()?.join(RECORDS);
    let name = format!("{}.json", crate::io::set_journal::hash_bytes(place.as_bytes()));
    Some((dir.join(name), place))
}

/// Keeps the record of the output just written at `path`, written whole, in a records
/// folder made this user's alone (Unix: 0700, the record 0600; Windows: owner-only). Where it cannot be kept,
/// or the folder is not this user's alone (a 777 folder, another user's), none is kept:
/// the next run finds no record it trusts and refuses to replace the output, the safe side.
fn remember(path: &Path) {
    let Some((record, place)) = record_of(path) else { return };
    let (folder, name) = match (path.parent(), path.file_name()) {
        (Some(f), Some(n)) => (f, n.to_string_lossy().into_owned()),
        _ => return,
    };
    let Ok(entry) = crate::io::set_journal::entry_of(folder, &name) else { return };
    let Ok(bytes) = serde_json::to_vec(&Record { place, entry }) else { return };
    let Some(dir) = record.parent() else { return };
    if make_records_folder(dir).is_err() || !folder_is_this_users_alone(dir) {
        return;
    }
    if crate::io::atomic_write::write_here(&record, &bytes).is_ok() {
        make_private(&record);
    }
}

/// Makes the records folder `dir` (its parents as the system makes them), this user's
/// alone (Unix: 0700; Windows: an owner-only descriptor, `files::private`); one already
/// there is left as it is (and trusted only if it is this user's alone), but for one of
/// this user's that others can only read (0755, made by an older phonglab): that one is
/// made 0700 ([`tighten_records_folder`]).
fn make_records_folder(dir: &Path) -> std::io::Result<()> {
    if let Some(parent) = dir.parent() {
        std::fs::create_dir_all(parent)?;
    }
    #[cfg(unix)]
    let builder = {
        let mut b = std::fs::DirBuilder::new();
        std::os::unix::fs::DirBuilderExt::mode(&mut b, 0o700);
        b
    };
    #[cfg(not(any(unix, windows)))]
    let builder = std::fs::DirBuilder::new();
    #[cfg(windows)]
    let made = phonglab_core::files::private::create_dir(dir);
    #[cfg(not(windows))]
    let made = builder.create(dir);
    match made {
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            tighten_records_folder(dir);
            Ok(())
        }
        other => other,
    }
}

/// Makes the records folder `dir` 0700 (Unix) where it is this user's alone already
/// (owned by this user, writable by no one else: 0755) but readable by others: through a
/// handle to the folder itself, never a link. A folder others can write is left as it is:
/// a record planted there is never made trusted by tightening it afterwards.
fn tighten_records_folder(dir: &Path) {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let Ok(folder) = crate::platform::os::open_no_follow(dir) else { return };
        let open_to_others = folder.metadata().is_ok_and(|m| m.is_dir() && m.permissions().mode() & 0o077 != 0);
        if open_to_others && crate::platform::os::is_this_users_alone(&folder) {
            let _ = folder.set_permissions(std::fs::Permissions::from_mode(0o700));
        }
    }
    #[cfg(not(unix))]
    let _ = dir;
}

/// Makes the record just written readable and writable by this user alone (Unix: 0600,
/// whatever the umask; Windows: the owner-only descriptor, which under Wine makes it 0660).
fn make_private(record: &Path) {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let _ = std::fs::set_permissions(record, std::fs::Permissions::from_mode(0o600));
    }
    #[cfg(windows)]
    let _ = phonglab_core::files::private::make_owner_only(record, false);
    #[cfg(not(any(unix, windows)))]
    let _ = record;
}

/// Is the folder `dir` this user's alone ([`crate::platform::os::is_this_users_alone`],
/// asked through a handle to the folder itself, never through a link)?
fn folder_is_this_users_alone(dir: &Path) -> bool {
    if std::fs::symlink_metadata(dir).map_or(true, |m| !m.is_dir()) {
        return false;
    }
    #[cfg(windows)]
    let opened = {
        use std::os::windows::fs::OpenOptionsExt;
        // FILE_FLAG_BACKUP_SEMANTICS (a folder) | FILE_FLAG_OPEN_REPARSE_POINT (not followed).
        std::fs::File::options().read(true).custom_flags(0x0200_0000 | 0x0020_0000).open(dir)
    };
    #[cfg(not(windows))]
    let opened = std::fs::File::open(dir);
    opened.is_ok_and(|f| crate::platform::os::is_this_users_alone(&f))
}

/// What phonglab's records say of the file at an output's place.
#[derive(Debug, PartialEq)]
enum Recorded {
    /// No record of writing it there (a file planted with phonglab's first line).
    None,
    /// The records folder or this record is not this user's alone: anyone can write a
    /// record in phonglab's form (its hash is unkeyed), so none there is trusted.
    Untrusted(std::path::PathBuf),
    /// A record, and the file is no longer what it says (a line added, another file).
    Changed,
    /// The file is, whole, what phonglab last wrote there.
    Same,
}

/// What phonglab's records say of the file at `path` ([`Recorded`]).
fn recorded(path: &Path) -> Recorded {
    let Some((record, place)) = record_of(path) else { return Recorded::None };
    let Some(dir) = record.parent() else { return Recorded::None };
    let Ok(file) = crate::platform::os::open_no_follow(&record) else {
        return if dir.exists() && !folder_is_this_users_alone(dir) {
            Recorded::Untrusted(dir.to_path_buf())
        } else {
            Recorded::None
        };
    };
    if !folder_is_this_users_alone(dir) || !crate::platform::os::is_this_users_alone(&file) {
        return Recorded::Untrusted(dir.to_path_buf());
    }
    let mut bytes = Vec::new();
    let read = file.take(MAX_RECORD_BYTES).read_to_end(&mut bytes);
    let Ok(r) = read.map_err(|_| ()).and_then(|_| serde_json::from_slice::<Record>(&bytes).map_err(|_| ())) else {
        return Recorded::None;
    };
    if r.place == place && crate::io::set_journal::is_entry(path, &r.entry) {
        Recorded::Same
    } else {
        Recorded::Changed
    }
}

/// Whether the file at `path` is, whole, what phonglab last wrote at that place: its
/// record's size, hash and identity, in a record this user's alone. A line added, a byte
/// changed, the file replaced by another with the same bytes (another identity), or a
/// record another user could have written, and it is not.
pub fn written_as_recorded(path: &Path) -> bool {
    recorded(path) == Recorded::Same
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 59 (finding 4): the marks named at a link to phonglab's own earlier marks are
    /// refused as a link, on Linux and under Wine (which shows a Unix link as a plain file,
    /// whose bytes were the marks': the link was replaced), and nothing is written.
    #[test]
    #[cfg(any(unix, windows))]
    fn an_output_at_a_link_to_phonglabs_own_output_is_refused_as_a_link() {
        let dir = crate::io::atomic_write::tests::fresh_dir("output-link");
        let (real, link) = (dir.join("last-year.csv"), dir.join("marks.csv"));
        std::fs::write(&real, format!("{}\na,right,,,\n", marks_header(','))).unwrap();
        if !crate::io::atomic_write::tests::plant_link(&real, &link) {
            eprintln!("no symbolic link can be made here: nothing to test");
            return;
        }
        let e = refuse(&[(&link, Kind::Marks)], None).unwrap_err();
        assert!(e.contains("marks.csv") && e.contains("link"), "{e}");
        assert!(write(&link, Kind::Marks, None, b"new").is_err());
        assert_eq!(std::fs::read(&real).unwrap(), format!("{}\na,right,,,\n", marks_header(',')).as_bytes());
        assert!(crate::platform::links::reached_through_link(&link), "the link is left");
    }

    /// Issue 59, round 3: under Wine a teacher's umask 000 makes a new folder 0777 and a
    /// new file 0666, which Wine shows as a DACL letting everyone write, and Windows asked
    /// only the owner, so a classmate could rewrite a record of the teacher's. The records
    /// folder and each record are made this user's alone (an owner-only descriptor), and
    /// one that everyone may write is not trusted.
    #[test]
    #[cfg(windows)]
    fn the_records_folder_and_a_record_are_made_this_users_alone() {
        let dir = crate::io::atomic_write::tests::temp_dir("records-alone").join(RECORDS);
        make_records_folder(&dir).unwrap();
        assert!(folder_is_this_users_alone(&dir), "the records folder phonglab makes");
        let record = dir.join("r.json");
        std::fs::write(&record, b"{}").unwrap();
        crate::io::atomic_write::tests::everyone_may_write(&record);
        let alone =
            || crate::platform::os::open_no_follow(&record).is_ok_and(|f| crate::platform::os::is_this_users_alone(&f));
        assert!(!alone(), "a record everyone may write");
        make_private(&record);
        assert!(alone(), "a record made private");
        crate::io::atomic_write::tests::everyone_may_write(&dir);
        assert!(!folder_is_this_users_alone(&dir), "a records folder everyone may write");
    }

    #[test]
    fn each_kind_knows_its_own_bytes_and_no_other() {
        let pixels = [9u8; 4 * 4 * 4];
        let png = |signed| crate::io::image::encode_png_signed(4, 4, &pixels, signed).unwrap();
        let (chart, diff, plain) = (png(Kind::Chart.png_text()), png(Kind::Difference.png_text()), png(None));
        assert!(Kind::Chart.is_own(&chart) && !Kind::Difference.is_own(&chart));
        assert!(Kind::Difference.is_own(&diff) && !Kind::Chart.is_own(&diff));
        assert!(!Kind::Chart.is_own(&plain) && !Kind::Difference.is_own(&plain), "a render is not an output");
        // The pixels decode as before.
        let dir = crate::io::atomic_write::tests::temp_dir("signed");
        std::fs::write(dir.join("d.png"), &diff).unwrap();
        assert_eq!(crate::io::image::read_png(&dir.join("d.png")).unwrap(), (4, 4, pixels.to_vec()));
        // The text after the pixels, or cut short, is not phonglab's.
        assert!(!Kind::Difference.is_own(&diff[..30]));
        assert!(Kind::Marks.is_own(format!("{}\r\na,right,,,,right\n", marks_header(',')).as_bytes()));
        assert!(Kind::Marks.is_own(format!("{}\na;certo;;;;right\n", marks_header(';')).as_bytes()));
        assert!(Kind::Marks.is_own(b"file,verdict,first_wrong,causes,cause_ids\na,right,,,\n"), "an earlier run's");
        assert!(!Kind::Marks.is_own(b"file,verdict\n"));
        // Its own header after the byte order mark it writes, in each language.
        assert!(Kind::Marks.is_own("\u{feff}file,verdict,first_wrong,causes,cause_ids,verdict_id\n".as_bytes()));
        let pt = "\u{feff}ficheiro;veredicto;primeiro passo errado;causas;ids das causas;id do veredicto\r\n";
        assert!(Kind::Marks.is_own(pt.as_bytes()), "{pt}");
        assert!(
            Kind::Marks
                .is_own("arquivo;veredito;primeiro passo errado;causas;ids das causas;id do veredito\n".as_bytes())
        );
        assert!(!Kind::Marks.is_own("\u{feff}ficheiro;veredicto\n".as_bytes()));
        for lang in phonglab_core::locale::Lang::ALL {
            let title = crate::locale::tr_in(lang, "check-report-title", &[]);
            assert!(Kind::Report.is_own(format!("# {title}\n\nrest").as_bytes()), "{lang:?}");
        }
        assert!(!Kind::Report.is_own(b"# My notes\n") && !Kind::Report.is_own(b""));
        // What check writes is what is known again, in each language.
        for lang in phonglab_core::locale::Lang::ALL {
            phonglab_core::locale::with_locale(phonglab_core::locale::Locale::of(lang), || {
                let report = crate::cli::check_class::markdown(&[], &[], "r.png", None);
                assert!(Kind::Report.is_own(report.as_bytes()), "{lang:?}: {report}");
                let marks = crate::cli::check_class::marks_csv(&[]);
                assert!(marks.starts_with(MARKS_BOM), "{lang:?}: {marks}");
                assert!(Kind::Marks.is_own(marks.as_bytes()));
                assert!(!Kind::Marks.is_own(report.as_bytes()));
                assert!(!Kind::Report.is_own(marks_header(marks_separator()).as_bytes()));
            });
        }
    }
}
