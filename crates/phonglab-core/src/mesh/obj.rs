//! A Wavefront OBJ subset: `v`, `vn`, and `f` with `v`, `v/vt`, `v//vn` or `v/vt/vn`
//! corners (negative indices count back); polygons are fanned into triangles. Without
//! normals, each vertex gets the area-weighted mean of its faces' normals.
//!
//! Bad input is refused with the line it is on: an index out of range, a number that is
//! not one or not finite (NaN), a face of fewer than 3 corners, a file over
//! [`MAX_OBJ_BYTES`] or [`MAX_OBJ_TRIANGLES`]. What was done to the file without refusing
//! it (polygons fanned, normals computed, the mesh fitted to the view) is said in notes.
//!
//! The file is read twice as a stream, never whole. The first pass counts ([`Counts`]):
//! the memory the reading will take is then known ([`Counts::load_bytes`]) and refused
//! past the budget ([`set_memory_budget`]) before anything is allocated; the second pass
//! fills arrays of exactly that size. Its peak is under 200 bytes a triangle, a triangle
//! soup (three vertices of its own each, as STL conversions write) or a shared mesh alike:
//! the file's vertices in f64 (to fit any finite coordinates), a remap from the file's
//! vertices to the mesh's (no hash map, but for a vertex met with several normals), and
//! the mesh itself. A soup's repeated corners are welded as they are read
//! ([`super::weld`]: its hash map is counted in the estimate), so it keeps what its shared
//! mesh keeps.

use std::collections::HashMap;
use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use glam::{DVec3, Vec3};

use super::Mesh;
use super::weld::Welder;
use crate::t;

fn index(s: &str, len: usize, ln: usize, what: &str) -> Result<usize, String> {
    let i: i64 = s.parse().map_err(|_| t!("obj-index-not-number", line = ln, what = what, index = format!("{s:?}")))?;
    let resolved = if i > 0 { i - 1 } else { len as i64 + i };
    if resolved < 0 || resolved as usize >= len {
        return Err(t!("obj-index-out-of-range", line = ln, what = what, index = i.to_string(), count = len));
    }
    Ok(resolved as usize)
}

/// The most triangles an OBJ file may make: shading time and memory grow linearly in them
/// (the cost a triangle: docs/performance.md, "Why the code is written so").
pub const MAX_OBJ_TRIANGLES: usize = 4_000_000;

/// The largest OBJ file read, in bytes: what [`MAX_OBJ_TRIANGLES`] take as exporters write
/// them (6 decimals, `vn`, `f a/b/c`: 80 to 130 bytes a triangle), so the triangle cap, not
/// the byte cap, is the one a real mesh meets. The file is read as a stream, never whole.
pub const MAX_OBJ_BYTES: u64 = 512 << 20;

/// The longest line read, in bytes.
pub const MAX_OBJ_LINE: usize = 64 << 10;

/// The memory the reading of an OBJ file may take, in bytes (no limit until the app sets
/// one from its budget).
static MEMORY_BUDGET: AtomicU64 = AtomicU64::new(u64::MAX);

/// Sets the memory an OBJ file's reading may take: a file whose [`Counts::load_bytes`]
/// is larger is refused before it is read, saying how much it needs.
pub fn set_memory_budget(bytes: u64) {
    MEMORY_BUDGET.store(bytes, Ordering::Relaxed);
}

/// A size in words: "536 870 913 bytes (512.0 MiB)"; under 1 MiB in KiB, "11 675 bytes
/// (11.4 KiB)" (it was "(0.0 MiB)"); under 1 KiB the bytes alone, "90 bytes".
pub fn describe_bytes(n: u64) -> String {
    const KIB: u64 = 1 << 10;
    const MIB: u64 = 1 << 20;
    let count = i64::try_from(n).unwrap_or(i64::MAX);
    let bytes = crate::locale::grouped(n);
    if n < KIB {
        return t!("bytes-counted", count = count, bytes = bytes);
    }
    let (unit, name) = if n < MIB { (KIB, "KiB") } else { (MIB, "MiB") };
    let scaled = format!("{:.1}", n as f64 / unit as f64);
    let scaled = format!("{} {name}", crate::locale::decimal(&scaled));
    t!("bytes-described", count = count, bytes = bytes, scaled = scaled)
}

/// At most 40 characters of a word, for a message.
fn short(word: &str) -> String {
    if word.chars().count() <= 40 {
        word.to_string()
    } else {
        format!("{}…", word.chars().take(39).collect::<String>())
    }
}

/// What an OBJ file holds, counted in a first pass before anything is allocated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// `v` lines.
    pub vertices: usize,
    /// `vn` lines.
    pub normals: usize,
    /// `vt` lines.
    pub texture_coordinates: usize,
    /// Face corners (`f` entries).
    pub corners: usize,
    /// Triangles, once the faces are fanned.
    pub triangles: usize,
}

impl Counts {
    /// The most vertices the mesh can have: a corner without a normal is its file vertex
    /// (so at most one mesh vertex each), a corner with a normal a (vertex, normal) pair.
    pub fn mesh_vertices(&self) -> usize {
        if self.normals == 0 { self.vertices.min(self.corners) } else { self.corners }
    }

    /// The memory the reading takes at its peak, in bytes: the file's vertices (f64) and
    /// normals, the remap from file vertices to mesh vertices, and the mesh (positions,
    /// normals, triangles, and each mesh vertex's file vertex), all allocated at once;
    /// the computed normals' sums come after the f64 vertices are freed.
    pub fn load_bytes(&self) -> u64 {
        let (v, vn, mv, tris) =
            (self.vertices as u64, self.normals as u64, self.mesh_vertices() as u64, self.triangles as u64);
        let file = v * (24 + 8) + vn * 12;
        let mesh = mv * (12 + 12 + 4) + tris * 12;
        let weld = if Welder::wanted(self.vertices, self.triangles) { Welder::peak_bytes(v) } else { 0 };
        file + mesh + mv * 12 + weld
    }

    /// The memory the mesh itself keeps once read: positions, normals, triangles.
    pub fn mesh_bytes(&self) -> u64 {
        self.mesh_vertices() as u64 * 24 + self.triangles as u64 * 12
    }
}

/// Reads the lines of `reader`, at most [`MAX_OBJ_LINE`] bytes each, calling `each` with
/// every line's number, tag and the rest of its words.
fn for_each_line<R: BufRead>(
    mut reader: R,
    mut each: impl FnMut(usize, &str, std::str::SplitWhitespace<'_>) -> Result<(), String>,
) -> Result<(), String> {
    let mut bytes = Vec::new();
    let mut ln = 0;
    loop {
        bytes.clear();
        ln += 1;
        let n = std::io::Read::take(&mut reader, MAX_OBJ_LINE as u64 + 1)
            .read_until(b'\n', &mut bytes)
            .map_err(|e| t!("obj-cannot-read-line", line = ln, error = e.to_string()))?;
        if n == 0 {
            return Ok(());
        }
        if n > MAX_OBJ_LINE {
            return Err(t!("obj-line-too-long", line = ln, bytes = MAX_OBJ_LINE));
        }
        let line = String::from_utf8_lossy(&bytes);
        let mut it = line.split_whitespace();
        if let Some(tag) = it.next() {
            each(ln, tag, it)?;
        }
    }
}

/// The first pass: what the file holds, and its size refused past [`MAX_OBJ_TRIANGLES`]
/// on the line that passes it.
pub fn count<R: BufRead>(reader: R) -> Result<Counts, String> {
    let mut c = Counts::default();
    for_each_line(reader, |ln, tag, it| {
        match tag {
            "v" => c.vertices += 1,
            "vn" => c.normals += 1,
            "vt" => c.texture_coordinates += 1,
            "f" => {
                let corners = it.count();
                c.corners += corners;
                c.triangles += corners.saturating_sub(2);
                if c.triangles > MAX_OBJ_TRIANGLES {
                    return Err(t!(
                        "obj-too-many-triangles",
                        line = ln,
                        max = crate::locale::grouped(MAX_OBJ_TRIANGLES as u64)
                    ));
                }
            }
            _ => {}
        }
        Ok(())
    })?;
    Ok(c)
}

/// The file as read: its vertices in f64 (fitted before they become f32), and one entry
/// per mesh vertex (a distinct vertex and normal pair): its file vertex and its normal.
struct Parsed {
    /// The file's `v`.
    file_positions: Vec<DVec3>,
    /// Each mesh vertex's index in `file_positions`.
    file_vertex: Vec<u32>,
    /// Zero where the file gave no normal.
    normals: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
    polygon_line: Option<usize>,
    no_normal_line: Option<usize>,
}

/// From a corner's file vertex and normal to its mesh vertex: for each file vertex the
/// first (normal, mesh vertex) pair met, and a map only for the pairs after it (a vertex
/// of a flat-shaded mesh, met with several normals).
struct Remap {
    /// Per file vertex: `(normal + 1, mesh vertex + 1)`, normal 0 for none, `(_, 0)` unmet.
    first: Vec<(u32, u32)>,
    more: HashMap<(u32, u32), u32>,
}

impl Remap {
    fn with_vertices(n: usize) -> Remap {
        Remap { first: vec![(0, 0); n], more: HashMap::new() }
    }

    /// The mesh vertex of `(v, vn)`, made by `new` the first time the pair is met.
    fn vertex(&mut self, v: usize, vn: Option<usize>, new: impl FnOnce() -> u32) -> u32 {
        let key = vn.map_or(0, |k| k as u32 + 1);
        let slot = &mut self.first[v];
        if slot.1 == 0 {
            let id = new();
            *slot = (key, id + 1);
            return id;
        }
        if slot.0 == key {
            return slot.1 - 1;
        }
        *self.more.entry((v as u32, key)).or_insert_with(new)
    }
}

/// The second pass, into arrays of the sizes `counts` gives.
fn parse<R: BufRead>(reader: R, counts: &Counts) -> Result<Parsed, String> {
    // A soup's repeated corners are welded as they are read: its arrays then grow to the
    // distinct vertices rather than being sized for every line.
    let mut welder = Welder::wanted(counts.vertices, counts.triangles).then(Welder::default);
    let (lines, mesh_vertices) = if welder.is_some() { (0, 0) } else { (counts.vertices, counts.mesh_vertices()) };
    let mut out = Parsed {
        file_positions: Vec::with_capacity(lines),
        file_vertex: Vec::with_capacity(mesh_vertices),
        normals: Vec::with_capacity(mesh_vertices),
        triangles: Vec::with_capacity(counts.triangles),
        polygon_line: None,
        no_normal_line: None,
    };
    let mut vns = Vec::<Vec3>::with_capacity(counts.normals);
    let mut vts = 0usize;
    let mut remap = Remap::with_vertices(counts.vertices);
    let mut face = Vec::new();
    for_each_line(reader, |ln, tag, it| {
        let nums = |it: std::str::SplitWhitespace<'_>| -> Result<Vec<f64>, String> {
            it.map(|x| {
                x.parse::<f64>().map_err(|_| t!("obj-not-a-number", line = ln, word = format!("{:?}", short(x))))
            })
            .collect()
        };
        match tag {
            "v" => {
                let v = nums(it)?;
                if v.len() < 3 || v[..3].iter().any(|x| !x.is_finite()) {
                    return Err(t!("obj-vertex-needs", line = ln));
                }
                let p = DVec3::new(v[0], v[1], v[2]);
                let positions = &mut out.file_positions;
                match welder.as_mut() {
                    Some(w) => {
                        w.add(p, |p| {
                            positions.push(p);
                            (positions.len() - 1) as u32
                        });
                    }
                    None => positions.push(p),
                }
            }
            "vn" => {
                let v = nums(it)?;
                if v.len() != 3 || v.iter().any(|x| !x.is_finite()) {
                    return Err(t!("obj-normal-needs", line = ln));
                }
                let n = DVec3::new(v[0], v[1], v[2]);
                // Scaled first, so 1e-30 or 1e300 components still give a direction.
                let m = n.abs().max_element();
                vns.push(if m > 0.0 { (n / m).normalize().as_vec3() } else { Vec3::ZERO });
            }
            "vt" => vts += 1,
            "f" => {
                face.clear();
                for c in it {
                    let mut parts = c.split('/');
                    let lines = welder.as_ref().map_or(out.file_positions.len(), Welder::lines);
                    let v = index(parts.next().unwrap_or(""), lines, ln, &t!("obj-what-vertex"))?;
                    let v = welder.as_ref().map_or(v, |w| w.distinct(v));
                    if let Some(tc) = parts.next().filter(|tc| !tc.is_empty()) {
                        index(tc, vts, ln, &t!("obj-what-texture"))?;
                    }
                    let vn = match parts.next() {
                        Some(s) if !s.is_empty() => Some(index(s, vns.len(), ln, &t!("obj-what-normal"))?),
                        _ => None,
                    };
                    if vn.is_none() {
                        out.no_normal_line.get_or_insert(ln);
                    }
                    let id = remap.vertex(v, vn, || {
                        out.file_vertex.push(v as u32);
                        out.normals.push(vn.map_or(Vec3::ZERO, |k| vns[k]));
                        (out.file_vertex.len() - 1) as u32
                    });
                    face.push(id);
                }
                if face.len() < 3 {
                    return Err(t!("obj-face-needs", line = ln));
                }
                if face.len() > 3 {
                    out.polygon_line.get_or_insert(ln);
                }
                for k in 1..face.len() - 1 {
                    out.triangles.push([face[0], face[k], face[k + 1]]);
                }
            }
            _ => {}
        }
        Ok(())
    })?;
    if out.triangles.is_empty() {
        return Err(t!("obj-no-faces"));
    }
    Ok(out)
}

/// How positions are centred on their bounding box's centre and scaled to fit a sphere of
/// `radius`, in f64 and without squaring raw coordinates, so any finite coordinates fit
/// (1e300 or 1e-300 alike).
#[derive(Clone, Copy, Debug)]
struct Fit {
    centre_half: DVec3,
    /// Half the largest distance from the centre; not positive (or not finite): every
    /// position is only moved, by the centre.
    r_half: f64,
    radius: f64,
}

impl Fit {
    fn of(positions: impl Iterator<Item = DVec3> + Clone, radius: f64) -> Fit {
        let (lo, hi) = positions
            .clone()
            .fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), p| (lo.min(p), hi.max(p)));
        // Halves, so neither the centre nor an offset overflows at 1e308.
        let centre_half = lo * 0.25 + hi * 0.25;
        let fit = Fit { centre_half, r_half: 0.0, radius };
        let r_half = positions.map(|p| length(fit.offset_half(p))).fold(0.0, f64::max);
        Fit { r_half, ..fit }
    }

    fn offset_half(&self, p: DVec3) -> DVec3 {
        p * 0.5 - self.centre_half
    }

    fn scales(&self) -> bool {
        self.r_half > 0.0 && self.r_half.is_finite()
    }

    /// `p`, placed.
    fn place(&self, p: DVec3) -> DVec3 {
        if self.scales() { self.offset_half(p) / self.r_half * self.radius } else { p - self.centre_half * 2.0 }
    }

    /// The scale applied (1 where only moved).
    fn scale(&self) -> f64 {
        if self.scales() { self.radius / self.r_half * 0.5 } else { 1.0 }
    }
}

/// A vector's length, scaled first so that no component's square overflows.
fn length(d: DVec3) -> f64 {
    let m = d.abs().max_element();
    if m > 0.0 { m * (d / m).length() } else { 0.0 }
}

/// Centres `positions` on their bounding box's centre and scales them to fit a sphere of
/// radius `radius`, in f64 and without squaring raw coordinates, so any finite coordinates
/// fit (1e300 or 1e-300 alike); returns the scale.
pub fn fit(positions: &mut [DVec3], radius: f64) -> f64 {
    let fit = Fit::of(positions.iter().copied(), radius);
    for p in positions.iter_mut() {
        *p = fit.place(*p);
    }
    fit.scale()
}

/// The mesh of `parsed`, each position `place`d (fitted to the view, or as given), with
/// the notes on what was done: fanned polygons and computed normals. The f64 positions
/// are freed before the normals are summed.
fn into_mesh(parsed: Parsed, place: impl Fn(DVec3) -> DVec3, notes: &mut Vec<String>) -> Mesh {
    let Parsed { file_positions, file_vertex, normals, triangles, polygon_line, no_normal_line } = parsed;
    let positions: Vec<Vec3> = file_vertex.iter().map(|&v| place(file_positions[v as usize]).as_vec3()).collect();
    drop(file_positions);
    drop(file_vertex);
    let mut mesh = Mesh { positions, normals, triangles, provoking: Vec::new() };
    if let Some(ln) = polygon_line {
        notes.push(t!("obj-note-fanned", line = ln));
    }
    if let Some(ln) = no_normal_line {
        notes.push(t!("obj-note-normals", line = ln));
        let mut acc = vec![Vec3::ZERO; mesh.positions.len()];
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            let n = (b - a).cross(c - a);
            for &i in t {
                acc[i as usize] += n;
            }
        }
        for (n, a) in mesh.normals.iter_mut().zip(acc) {
            if *n == Vec3::ZERO {
                *n = a.try_normalize().unwrap_or(Vec3::Z);
            }
        }
    }
    mesh
}

/// Parses OBJ text into a mesh (positions as given; normals normalised).
pub fn parse_obj(text: &str) -> Result<Mesh, String> {
    parse_obj_noted(text).map(|(m, _)| m)
}

/// [`parse_obj`], with notes on what was done to the file: polygons fanned into triangles,
/// normals computed where the file has none (each naming the first line concerned).
/// Positions are kept as given, so they must lie within single precision's range
/// ([`load_obj`] fits them first, and takes any finite ones).
pub fn parse_obj_noted(text: &str) -> Result<(Mesh, Vec<String>), String> {
    let counts = count(text.as_bytes())?;
    let parsed = parse(text.as_bytes(), &counts)?;
    if parsed.file_vertex.iter().any(|&v| !parsed.file_positions[v as usize].as_vec3().is_finite()) {
        return Err(t!("obj-beyond-single"));
    }
    let mut notes = Vec::new();
    let mesh = into_mesh(parsed, |p| p, &mut notes);
    Ok((mesh, notes))
}

/// A mesh read from a file, fitted to the view, with notes on what was done to it.
#[derive(Clone, Debug)]
pub struct LoadedObj {
    /// The mesh, centred and scaled to radius 0.5.
    pub mesh: Mesh,
    /// What was done to the file (fanned, normals computed, fitted).
    pub notes: Vec<String>,
}

/// Reads an OBJ file as a stream: refused (with a line number where there is one) when it
/// is not a regular file, cannot be read, is over [`MAX_OBJ_BYTES`] or
/// [`MAX_OBJ_TRIANGLES`], or does not parse; fitted to radius 0.5 in f64.
///
/// The file is opened once, without waiting (a FIFO would otherwise block the open), and
/// checked and read through that one handle: both passes read the file that was checked,
/// even if the path is given another file between them.
pub fn load_obj(path: &Path) -> Result<LoadedObj, String> {
    use std::io::{Read, Seek};
    let shown = path.display().to_string();
    let cannot = |e: std::io::Error| t!("obj-cannot-read", path = shown.clone(), error = e.to_string());
    let file = match open_to_read(path) {
        Ok(f) => f,
        // Windows cannot open a folder as a file (access denied): said as what it is.
        Err(_) if std::fs::metadata(path).is_ok_and(|m| m.is_dir()) => {
            return Err(t!("obj-not-a-file", path = shown.clone()));
        }
        Err(e) => return Err(cannot(e)),
    };
    let Some(meta) = regular_file_metadata(&file).map_err(cannot)? else {
        return Err(t!("obj-not-a-file", path = shown.clone()));
    };
    refuse_too_large(&shown, meta.len())?;
    let open = || -> Result<_, String> {
        let mut handle = &file;
        handle.rewind().map_err(cannot)?;
        #[cfg(test)]
        between_passes::run();
        Ok(std::io::BufReader::with_capacity(1 << 16, handle.take(MAX_OBJ_BYTES)))
    };
    read_fitted(&shown, open)
}

/// Opens `path` to read without waiting (Unix: `O_NONBLOCK`, which changes nothing for a
/// regular file and keeps a FIFO with no writer from blocking the open).
fn open_to_read(path: &Path) -> std::io::Result<std::fs::File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        std::fs::File::options().read(true).custom_flags(libc::O_NONBLOCK).open(path)
    }
    #[cfg(not(unix))]
    {
        std::fs::File::open(path)
    }
}

/// The metadata of the opened `file` where it is a regular file (a device, such as Windows'
/// `NUL`, has no file information to read: its type is asked first). The mesh group's
/// own, as [`open_to_read`] is: `formats::files::os::regular_file_metadata` is a group above.
fn regular_file_metadata(file: &std::fs::File) -> std::io::Result<Option<std::fs::Metadata>> {
    #[cfg(windows)]
    if !winapi_util::file::typ(file)?.is_disk() {
        return Ok(None);
    }
    let meta = file.metadata()?;
    Ok(meta.is_file().then_some(meta))
}

/// A test's action each time [`load_obj`] starts a pass over its file (to swap the file
/// under it).
#[cfg(test)]
mod between_passes {
    use std::cell::RefCell;

    thread_local! {
        static ACTION: RefCell<Option<Box<dyn FnMut()>>> = RefCell::new(None);
    }

    /// Runs `f` at the start of each pass while `body` runs (its one test swaps in a FIFO:
    /// Unix only).
    #[cfg(unix)]
    pub fn with<R>(f: impl FnMut() + 'static, body: impl FnOnce() -> R) -> R {
        ACTION.with(|a| *a.borrow_mut() = Some(Box::new(f)));
        let r = body();
        ACTION.with(|a| *a.borrow_mut() = None);
        r
    }

    pub fn run() {
        ACTION.with(|a| {
            if let Some(f) = a.borrow_mut().as_mut() {
                f();
            }
        });
    }
}

/// [`load_obj`] for a file given as its bytes (the browser's chooser and drops, which have
/// no paths): the same limits, the same messages, `name` standing for the path in them.
pub fn load_obj_bytes(name: &str, bytes: &[u8]) -> Result<LoadedObj, String> {
    refuse_too_large(name, bytes.len() as u64)?;
    read_fitted(name, || Ok(bytes))
}

/// Refuses a file over [`MAX_OBJ_BYTES`], before any of it is read.
pub fn refuse_too_large(shown: &str, len: u64) -> Result<(), String> {
    if len > MAX_OBJ_BYTES {
        return Err(t!(
            "obj-too-large",
            path = shown.to_string(),
            size = describe_bytes(len),
            max = describe_bytes(MAX_OBJ_BYTES),
            millions = (MAX_OBJ_TRIANGLES / 1_000_000).to_string()
        ));
    }
    Ok(())
}

/// The two passes over a source `open` gives afresh: counted, refused past the memory
/// budget, parsed, and fitted to radius 0.5 (errors name the file as `shown`).
fn read_fitted<R: BufRead>(shown: &str, open: impl Fn() -> Result<R, String>) -> Result<LoadedObj, String> {
    let in_file = |e: String| format!("{shown}: {e}");
    let counts = count(open()?).map_err(in_file)?;
    let budget = MEMORY_BUDGET.load(Ordering::Relaxed);
    if counts.load_bytes() > budget {
        return Err(in_file(t!(
            "obj-over-budget",
            count = counts.triangles,
            triangles = crate::locale::grouped(counts.triangles as u64),
            bytes = describe_bytes(counts.load_bytes()),
            budget = describe_bytes(budget)
        )));
    }
    let parsed = parse(open()?, &counts).map_err(in_file)?;
    let fit = Fit::of(parsed.file_vertex.iter().map(|&v| parsed.file_positions[v as usize]), 0.5);
    let mut notes = Vec::new();
    let mesh = into_mesh(parsed, |p| fit.place(p), &mut notes);
    let k = fit.scale();
    let scale = if (1e-3..1e4).contains(&k) { format!("{k:.4}") } else { format!("{k:.4e}") };
    notes.push(t!("obj-note-fitted", scale = crate::locale::decimal(&scale)));
    Ok(LoadedObj { mesh, notes })
}

type ObjCache = Mutex<HashMap<PathBuf, (Option<std::time::SystemTime>, Arc<LoadedObj>)>>;

/// Meshes given as bytes rather than read from a path ([`hold_obj_bytes`]), by the name a
/// view's `obj` gives them.
static HELD: Mutex<Vec<(String, Arc<LoadedObj>)>> = Mutex::new(Vec::new());

/// Reads the OBJ file given as `bytes` ([`load_obj_bytes`]) and holds it under `name`, so
/// that a view whose `obj` is `name` shows it: where files have no paths (the browser). A
/// mesh held under the same name before is replaced; only the last few are kept.
pub fn hold_obj_bytes(name: &str, bytes: &[u8]) -> Result<Arc<LoadedObj>, String> {
    /// The meshes held at once: each can be hundreds of megabytes.
    const KEPT: usize = 4;
    let obj = Arc::new(load_obj_bytes(name, bytes)?);
    let mut held = HELD.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    held.retain(|(n, _)| n != name);
    if held.len() >= KEPT {
        held.remove(0);
    }
    held.push((name.to_string(), obj.clone()));
    Ok(obj)
}

/// The mesh held under `name` ([`hold_obj_bytes`]), if any.
pub fn held_obj(name: &str) -> Option<Arc<LoadedObj>> {
    HELD.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .iter()
        .find(|(n, _)| n == name)
        .map(|(_, o)| o.clone())
}

/// [`load_obj`], read once per file and modification time: the shaded view asks for its
/// mesh every time the view changes. A mesh held under the path's name
/// ([`hold_obj_bytes`]) is taken first.
pub fn load_obj_cached(path: &Path) -> Result<Arc<LoadedObj>, String> {
    static CACHE: std::sync::OnceLock<ObjCache> = std::sync::OnceLock::new();
    if let Some(held) = path.to_str().and_then(held_obj) {
        return Ok(held);
    }
    let cache = CACHE.get_or_init(Default::default);
    let modified = std::fs::metadata(path).and_then(|m| m.modified()).ok();
    if let Ok(c) = cache.lock()
        && let Some((m, obj)) = c.get(path)
        && *m == modified
        && modified.is_some()
    {
        return Ok(obj.clone());
    }
    let obj = Arc::new(load_obj(path)?);
    if let Ok(mut c) = cache.lock() {
        c.insert(path.to_path_buf(), (modified, obj.clone()));
    }
    Ok(obj)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_say_what_was_done_and_fitting_centres_and_scales() {
        let text = "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 1 1 2\nf 1 2 3 4\nf 1 2 5\n";
        let (m, notes) = parse_obj_noted(text).unwrap();
        assert_eq!(m.triangle_count(), 3);
        assert!(notes[0].contains("line 6") && notes[0].contains("fanned"), "{notes:?}");
        assert!(notes[1].contains("line 6") && notes[1].contains("computed"), "{notes:?}");
        let mut p: Vec<DVec3> = m.positions.iter().map(|v| v.as_dvec3()).collect();
        let k = fit(&mut p, 0.5);
        let r = p.iter().map(|p| p.length()).fold(0.0, f64::max);
        assert!((r - 0.5).abs() < 1e-12 && (k - 0.5 / 3f64.sqrt()).abs() < 1e-12, "{r} {k}");
        let with_normals = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";
        assert!(parse_obj_noted(with_normals).unwrap().1.is_empty(), "nothing to say");
    }

    #[test]
    fn sizes_under_a_mib_are_said_in_kib_and_under_a_kib_in_bytes() {
        // 11 675 bytes were "(0.0 MiB)".
        assert_eq!(describe_bytes(11_675), "11 675 bytes (11.4 KiB)");
        assert_eq!(describe_bytes(90), "90 bytes");
        assert_eq!(describe_bytes(1), "1 byte");
        assert_eq!(describe_bytes(1 << 20), "1 048 576 bytes (1.0 MiB)");
    }

    #[test]
    fn a_huge_file_is_refused_before_it_is_read() {
        let dir = std::env::temp_dir().join(format!("phonglab-obj-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("huge.obj");
        // Sparse: the size is what is checked, before any byte is read.
        std::fs::File::create(&p).unwrap().set_len(MAX_OBJ_BYTES + 1).unwrap();
        let e = load_obj(&p).unwrap_err();
        assert!(e.contains("is 536 870 913 bytes (512.0 MiB)") && e.contains("at most 536 870 912 bytes"), "{e}");
        let e = load_obj(&dir.join("missing.obj")).unwrap_err();
        assert!(e.contains("cannot read"), "{e}");
        // A device: refused, never read: /dev/zero, Windows' NUL (by either name).
        let devices: &[&str] = if cfg!(windows) { &["NUL", r"\\.\NUL"] } else { &["/dev/zero"] };
        for device in devices {
            let e = load_obj(Path::new(device)).unwrap_err();
            assert!(e.contains(device) && e.contains("not a regular file"), "{e}");
        }
        let e = load_obj(&dir).unwrap_err();
        assert!(e.contains("not a regular file"), "{e}");
    }

    /// A mesh file given another file (a mesh of two triangles, or a FIFO) by its path
    /// between the two passes: both passes read the file that was opened and checked.
    #[test]
    #[cfg(unix)]
    fn a_mesh_swapped_between_its_passes_is_read_from_the_one_handle() {
        let one = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        let two = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
        type Swap = fn(&Path);
        let swaps: [(&str, Swap); 2] = [
            ("other", |p| std::fs::write(p, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n").unwrap()),
            ("fifo", |p| {
                let c = std::ffi::CString::new(p.as_os_str().as_encoded_bytes()).unwrap();
                // SAFETY: `c` is a valid NUL-terminated path for the duration of the call.
                assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
            }),
        ];
        assert_eq!(parse_obj(two).unwrap().triangle_count(), 2);
        for (what, swap) in swaps {
            let path = write(&format!("swapped-{what}.obj"), one);
            let (tx, rx) = std::sync::mpsc::channel();
            let p = path.clone();
            std::thread::spawn(move || {
                let mut passes = 0;
                let swapped = p.clone();
                let r = between_passes::with(
                    move || {
                        passes += 1;
                        if passes == 2 {
                            std::fs::remove_file(&swapped).unwrap();
                            swap(&swapped);
                        }
                    },
                    || load_obj(&p),
                );
                tx.send(r.map(|o| o.mesh.triangle_count())).ok();
            });
            let read = rx.recv_timeout(std::time::Duration::from_secs(20)).expect("the reading did not hang");
            assert_eq!(read, Ok(1), "{what}: the file that was opened, whole");
        }
    }

    fn write(name: &str, text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("phonglab-obj-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    #[test]
    fn any_finite_coordinates_fit_the_view() {
        for scale in [1e20, 1e-25, 1e300, 1e-300, 1.0] {
            let f = |x: f64| format!("{:e}", x * scale);
            let text = format!(
                "v {} {} {}\nv {} {} {}\nv {} {} {}\nf 1 2 3\n",
                f(1.0),
                f(1.0),
                f(0.0),
                f(3.0),
                f(1.0),
                f(0.0),
                f(1.0),
                f(3.0),
                f(0.0)
            );
            let obj = load_obj(&write("scaled.obj", &text)).unwrap();
            let r = obj.mesh.positions.iter().map(|p| p.length()).fold(0.0, f32::max);
            assert!((r - 0.5).abs() < 1e-6, "scale {scale}: radius {r}");
            assert!(obj.mesh.normals.iter().all(|n| (n.z - 1.0).abs() < 1e-6), "scale {scale}: {:?}", obj.mesh.normals);
        }
    }

    #[test]
    fn texture_indices_are_checked_and_long_lines_refused() {
        let e = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/99 2/1 3/1\n").unwrap_err();
        assert!(e.contains("line 5") && e.contains("texture index 99"), "{e}");
        assert!(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/-1\n").is_ok());
        let e = parse_obj(&format!("# {}\n", "x".repeat(MAX_OBJ_LINE + 10))).unwrap_err();
        assert!(e.contains("line 1 is longer"), "{e}");
    }
}
