//! A scene in a link: the document and the window's choices, compact and versioned, for the
//! URL fragment (never sent to the host) of the browser build.
//!
//! A fragment is `v1.` and then the payload, deflated and base64url-encoded (no padding).
//! The payload is a first line `phonglab-share 1`, `key = value` lines for the window's
//! choices ([`Shared`]: language, presenting, the term shown), a blank line, and the scene
//! file's TOML, read by the same strict rules as a scene file ([`Document::from_toml`]) and
//! validated. Bounded: a fragment over [`MAX_FRAGMENT`] characters, or one that inflates
//! past [`MAX_INFLATED`] bytes, is refused before it is read. Whatever is wrong, the answer
//! is an error that says what (an old version, damage, an unknown choice, the scene's own
//! error), never a panic.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;

use crate::formats::document::Document;

/// Where the browser build is published (GitHub Pages: the README says how), the page a
/// link opens unless another is given.
pub const DEFAULT_BASE: &str = "https://phonglab.github.io/phonglab/";

/// The version this build writes and reads.
pub const VERSION: u32 = 1;
/// The longest fragment read, in characters.
pub const MAX_FRAGMENT: usize = 16 * 1024;
/// The largest payload inflated, in bytes.
pub const MAX_INFLATED: usize = 256 * 1024;

/// What a link carries.
#[derive(Clone, Debug, PartialEq)]
pub struct Shared {
    /// The scene: the document (its scene, view, object, shading and worked vertex).
    pub doc: Document,
    /// The language to show it in (`en`, `pt-PT`, `pt-BR`), if set.
    pub lang: Option<String>,
    /// Presenting to a class.
    pub present: bool,
    /// The term shown in place of the picture (a channel's name), if one is.
    pub channel: Option<String>,
    /// Read from a link: the mesh file the scene shows, where it is not here to be read (a
    /// link carries the mesh's file name, never the mesh): the scene is opened on the
    /// sphere, and the file must be opened to show it. Not written.
    pub missing_mesh: Option<String>,
    /// Read from a link: why [`Shared::missing_mesh`] was not read (the file not here, or a
    /// link that named folders, which phonglab never follows). Not written.
    pub mesh_note: Option<String>,
}

impl Shared {
    /// A link's contents: `doc` with none of the window's choices.
    pub fn of(doc: Document) -> Shared {
        Shared { doc, lang: None, present: false, channel: None, missing_mesh: None, mesh_note: None }
    }
}

/// Why a fragment was not opened.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ShareError {
    /// Longer than [`MAX_FRAGMENT`].
    #[error("{}", crate::t!("share-too-long", length = *.0 as i64, most = MAX_FRAGMENT as i64))]
    TooLong(usize),
    /// Not `vN.` with a version this build reads.
    #[error("{}", crate::t!("share-version", found = .0.clone(), version = VERSION as i64))]
    Version(String),
    /// Not base64url, or not deflate, or inflating past the limit.
    #[error("{}", crate::t!("share-damaged", what = .0.clone()))]
    Damaged(String),
    /// A header line this build does not know, or a bad value.
    #[error("{}", crate::t!("share-choice", line = .0.clone()))]
    Choice(String),
    /// Inflating past its limit ([`MAX_INFLATED`] bytes for a link's scene).
    #[error("{}", crate::t!("share-too-big", most = *.0 as i64))]
    TooBig(usize),
    /// Longer than a link phonglab reads: [`MAX_FRAGMENT`] (made, never opened).
    #[error("{}", crate::t!("share-make-too-long", length = *.0 as i64, most = MAX_FRAGMENT as i64))]
    MakeTooLong(usize),
    /// The scene itself is refused (the scene file's message).
    #[error("{0}")]
    Scene(String),
}

/// The languages a link may ask for.
const LANGS: [&str; 3] = ["en", "pt-PT", "pt-BR"];

/// The fragment (without `#`) that carries `s`.
///
/// A mesh file is named by its file name alone: a link never carries the sharer's folders.
pub fn encode(s: &Shared) -> Result<String, ShareError> {
    let mut doc = s.doc.clone();
    if let Some(obj) = &doc.view.obj {
        let name = std::path::Path::new(obj).file_name().map(|n| n.to_string_lossy().into_owned());
        doc.view.obj = Some(name.unwrap_or_default());
    }
    let toml = doc.to_toml().map_err(|e| ShareError::Scene(e.to_string()))?;
    let mut payload = format!("phonglab-share {VERSION}\n");
    if let Some(lang) = &s.lang {
        payload.push_str(&format!("lang = {lang}\n"));
    }
    if s.present {
        payload.push_str("present = true\n");
    }
    if let Some(c) = &s.channel {
        payload.push_str(&format!("channel = {c}\n"));
    }
    payload.push('\n');
    payload.push_str(&toml);
    let fragment = format!("v{VERSION}.{}", pack(payload.as_bytes(), 9));
    // A link no phonglab would open is not made (a very long name, say).
    if fragment.len() > MAX_FRAGMENT {
        return Err(ShareError::MakeTooLong(fragment.len()));
    }
    Ok(fragment)
}

/// What the fragment `fragment` (with or without its `#`) carries.
pub fn decode(fragment: &str) -> Result<Shared, ShareError> {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    if fragment.len() > MAX_FRAGMENT {
        return Err(ShareError::TooLong(fragment.len()));
    }
    let shown = |s: &str| crate::formats::escape::terminal::text(&s.chars().take(12).collect::<String>());
    let body = match fragment.split_once('.') {
        Some((v, body)) if v == format!("v{VERSION}") => body,
        Some((v, _)) => return Err(ShareError::Version(shown(v))),
        None => return Err(ShareError::Version(shown(fragment))),
    };
    let bytes = unpack_bytes(body, MAX_INFLATED)?;
    let text = String::from_utf8(bytes).map_err(|_| ShareError::Damaged("not UTF-8".into()))?;
    let (header, toml) = text.split_once("\n\n").ok_or_else(|| ShareError::Damaged("no scene".into()))?;
    let mut lines = header.lines();
    if lines.next() != Some(&*format!("phonglab-share {VERSION}")) {
        return Err(ShareError::Damaged("no header".into()));
    }
    let mut out = Shared::of(Document::default());
    for line in lines {
        let bad =
            || ShareError::Choice(crate::formats::escape::terminal::text(&crate::numerics::strict::quoted_line(line)));
        let (key, value) = line.split_once(" = ").ok_or_else(bad)?;
        match key {
            "lang" if LANGS.contains(&value) => out.lang = Some(value.to_string()),
            "present" if value == "true" => out.present = true,
            "channel" if crate::raster::channels::Channel::ALL.iter().any(|c| c.name() == value) => {
                out.channel = Some(value.to_string());
            }
            _ => return Err(bad()),
        }
    }
    // A mesh named with folders is never read: only its file name is kept.
    let (toml, folders) = mesh_by_name_alone(toml);
    // Read and validated as a scene file is (a mesh that is not here aside).
    let (doc, missing) =
        Document::from_toml_keeping_missing_mesh(&toml, None).map_err(|e| ShareError::Scene(e.to_string()))?;
    if let Some((path, shown_obj)) = folders {
        if shown_obj {
            out.missing_mesh.clone_from(&doc.view.obj);
        }
        let name = doc.view.obj.clone().unwrap_or_default();
        out.mesh_note = Some(crate::t!("share-mesh-folders", path = path, name = name));
    } else if let Some(note) = missing {
        out.missing_mesh.clone_from(&doc.view.obj);
        out.mesh_note = Some(note);
    }
    out.doc = doc;
    Ok(out)
}

/// The scene's TOML with a mesh path that names folders (`../x.obj`, `/home/x.obj`,
/// `a\x.obj`) cut to its file name, the object shown being the sphere if it was that
/// mesh; and that path (printable) and whether the mesh was the object shown. A link
/// carries a file name alone: phonglab never reads a path a link names.
fn mesh_by_name_alone(toml: &str) -> (std::borrow::Cow<'_, str>, Option<(String, bool)>) {
    let Ok(mut table) = toml.parse::<toml::Table>() else { return (toml.into(), None) };
    let Some(view) = table.get_mut("view").and_then(toml::Value::as_table_mut) else { return (toml.into(), None) };
    let Some(obj) = view.get("obj").and_then(toml::Value::as_str).map(str::to_string) else {
        return (toml.into(), None);
    };
    let name = obj.rsplit(['/', '\\']).next().unwrap_or_default().to_string();
    if name == obj && name != "." && name != ".." {
        return (toml.into(), None);
    }
    let shown_obj = view.get("object").and_then(toml::Value::as_str) == Some("obj");
    if shown_obj {
        view.insert("object".into(), toml::Value::String("sphere".into()));
    }
    if name.is_empty() || name == "." || name == ".." {
        view.remove("obj");
    } else {
        view.insert("obj".into(), toml::Value::String(name));
    }
    let text = toml::to_string(&table).unwrap_or_default();
    let shown = crate::formats::escape::terminal::text(&obj.chars().take(120).collect::<String>());
    (text.into(), Some((shown, shown_obj)))
}

/// A shared scene's link given where a scene file is taken (`https://…/#v1.…`): what
/// follows its `#` (empty where it has none). `None` for anything else (a file's path).
pub fn link_fragment(text: &str) -> Option<&str> {
    let lower = text.get(..8)?.to_ascii_lowercase();
    if !(lower.starts_with("http://") || lower.starts_with("https://")) {
        return None;
    }
    Some(text.split_once('#').map_or("", |(_, f)| f))
}

/// What the shared link `link` carries (its scene and the window's choices), decoded by
/// [`decode`] (bounded: [`MAX_FRAGMENT`]), or why not, naming the link by its start (its
/// control characters written visibly): what the app, the command line and the Python
/// package read where a scene file is taken.
pub fn read_link(link: &str) -> Result<Shared, String> {
    let fragment = link_fragment(link).unwrap_or("");
    // Its page and the start of its data: the whole link is kilobytes.
    let shown = crate::formats::escape::terminal::text(&link.chars().take(48).collect::<String>());
    let shown = if link.chars().count() > 48 { format!("{shown}…") } else { shown };
    if fragment.is_empty() {
        return Err(crate::t!("scene-link-refused", link = shown, why = crate::t!("scene-link-empty")));
    }
    decode(fragment).map_err(|e| crate::t!("scene-link-refused", link = shown, why = e.to_string()))
}

/// Refuses a page a link cannot open on: not an `http://` or `https://` address (a
/// `javascript:` or `data:` one runs or carries what it holds), or one holding a control
/// character, a space or a quote (it would not stay one address where it is pasted).
pub fn check_base(base: &str) -> Result<(), String> {
    let lower = base.to_ascii_lowercase();
    let scheme = lower.starts_with("http://") || lower.starts_with("https://");
    let plain = !base.chars().any(|c| crate::formats::escape::is_control(c) || c.is_whitespace() || c == '"');
    // A host after the scheme (`https:///` has none: no browser opens it).
    let host = base.split_once("://").map(|(_, rest)| rest.split(['/', '?', '#']).next().unwrap_or_default());
    if scheme && plain && host.is_some_and(|h| !h.is_empty()) {
        return Ok(());
    }
    let shown: String = base.chars().take(80).collect();
    Err(crate::t!("share-base-refused", base = crate::formats::escape::terminal::text(&shown)))
}

/// The link: `base` (a page's address) with the fragment of `s`.
pub fn link(base: &str, s: &Shared) -> Result<String, ShareError> {
    let base = base.split('#').next().unwrap_or(base);
    Ok(format!("{base}#{}", encode(s)?))
}

/// `bytes` deflated and base64url-encoded: a file as text, for storage that keeps only text
/// (the browser's `sessionStorage` keeps a mesh opened in the page this way).
pub fn pack_bytes(bytes: &[u8]) -> String {
    pack(bytes, 6)
}

/// `bytes` deflated at `level` (a link's payload takes the smallest, 9) and base64url-encoded.
fn pack(bytes: &[u8], level: u8) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(bytes, level))
}

/// What [`pack_bytes`] (or a link's payload) packed, refused when it is damaged or inflates
/// past `limit` bytes.
///
/// Bytes after the end of the deflated stream are refused too: the link was changed.
pub fn unpack_bytes(text: &str, limit: usize) -> Result<Vec<u8>, ShareError> {
    use miniz_oxide::inflate::stream::{InflateState, inflate};
    use miniz_oxide::{DataFormat, MZFlush, MZStatus};
    let deflated = URL_SAFE_NO_PAD.decode(text).map_err(|e| ShareError::Damaged(e.to_string()))?;
    let mut state = InflateState::new_boxed(DataFormat::Raw);
    // One byte more than the limit: a payload that fills it inflates past the limit.
    let mut out = vec![0u8; limit + 1];
    let r = inflate(&mut state, &deflated, &mut out, MZFlush::Finish);
    match r.status {
        Ok(MZStatus::StreamEnd) if r.bytes_written <= limit && r.bytes_consumed == deflated.len() => {
            out.truncate(r.bytes_written);
            Ok(out)
        }
        Ok(MZStatus::StreamEnd) if r.bytes_written <= limit => Err(ShareError::Damaged("trailing data".into())),
        _ if r.bytes_written > limit => Err(ShareError::TooBig(limit)),
        _ => Err(ShareError::Damaged("deflate".into())),
    }
}
