//! A Wavefront OBJ subset: `v`, `vn`, and `f` with `v`, `v/vt`, `v//vn` or `v/vt/vn`
//! corners (negative indices count back); polygons are fanned into triangles. Without
//! normals, each vertex gets the area-weighted mean of its faces' normals.
//!
//! Bad input is refused with the line it is on: an index out of range, a number that is
//! not one or not finite (NaN), a face of fewer than 3 corners, a file over
//! [`MAX_OBJ_BYTES`] or [`MAX_OBJ_TRIANGLES`]. What was done to the file without refusing
//! it (polygons fanned, normals computed, the mesh fitted to the view) is said in notes.

use std::collections::HashMap;
use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use glam::{DVec3, Vec3};

use super::Mesh;

fn index(s: &str, len: usize, ln: usize, what: &str) -> Result<usize, String> {
    let i: i64 = s.parse().map_err(|_| format!("line {ln}: {what} index {s:?} is not a number"))?;
    let resolved = if i > 0 { i - 1 } else { len as i64 + i };
    if resolved < 0 || resolved as usize >= len {
        return Err(format!("line {ln}: {what} index {i} is out of range (there are {len})"));
    }
    Ok(resolved as usize)
}

/// The most triangles an OBJ file may make: shading stays linear in them (about 0.2 µs
/// and 1.1 KB of memory a triangle at a million).
pub const MAX_OBJ_TRIANGLES: usize = 4_000_000;

/// The largest OBJ file read, in bytes: what [`MAX_OBJ_TRIANGLES`] take as exporters write
/// them (6 decimals, `vn`, `f a/b/c`: 80 to 130 bytes a triangle), so the triangle cap, not
/// the byte cap, is the one a real mesh meets. The file is read as a stream, never whole.
pub const MAX_OBJ_BYTES: u64 = 512 << 20;

/// The longest line read, in bytes.
pub const MAX_OBJ_LINE: usize = 64 << 10;

/// A file size in words: "536 870 913 bytes (512.0 MiB)".
pub fn describe_bytes(n: u64) -> String {
    format!("{} bytes ({:.1} MiB)", crate::locale::grouped(n), n as f64 / (1u64 << 20) as f64)
}

/// At most 40 characters of a word, for a message.
fn short(word: &str) -> String {
    if word.chars().count() <= 40 {
        word.to_string()
    } else {
        format!("{}…", word.chars().take(39).collect::<String>())
    }
}

/// The file as read: positions in f64 (fitted before they become f32), one entry per mesh
/// vertex (a distinct position and normal pair).
#[derive(Default)]
struct Parsed {
    positions: Vec<DVec3>,
    /// Zero where the file gave no normal.
    normals: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
    polygon_line: Option<usize>,
    no_normal_line: Option<usize>,
}

/// Reads OBJ lines from `reader`, at most [`MAX_OBJ_LINE`] bytes a line.
fn parse<R: BufRead>(mut reader: R) -> Result<Parsed, String> {
    let mut out = Parsed::default();
    let (mut vs, mut vns, mut vts) = (Vec::<DVec3>::new(), Vec::<Vec3>::new(), 0usize);
    let mut corners: HashMap<(usize, Option<usize>), u32> = HashMap::new();
    let mut bytes = Vec::new();
    let mut ln = 0;
    loop {
        bytes.clear();
        ln += 1;
        let n = std::io::Read::take(&mut reader, MAX_OBJ_LINE as u64 + 1)
            .read_until(b'\n', &mut bytes)
            .map_err(|e| format!("line {ln}: cannot read: {e}"))?;
        if n == 0 {
            break;
        }
        if n > MAX_OBJ_LINE {
            return Err(format!("line {ln} is longer than {MAX_OBJ_LINE} bytes: not an OBJ file"));
        }
        let line = String::from_utf8_lossy(&bytes);
        let mut it = line.split_whitespace();
        let Some(tag) = it.next() else { continue };
        let nums = |it: std::str::SplitWhitespace<'_>| -> Result<Vec<f64>, String> {
            it.map(|x| x.parse::<f64>().map_err(|_| format!("line {ln}: {:?} is not a number", short(x)))).collect()
        };
        match tag {
            "v" => {
                let v = nums(it)?;
                if v.len() < 3 || v[..3].iter().any(|x| !x.is_finite()) {
                    return Err(format!("line {ln}: a vertex needs 3 finite numbers"));
                }
                vs.push(DVec3::new(v[0], v[1], v[2]));
            }
            "vn" => {
                let v = nums(it)?;
                if v.len() != 3 || v.iter().any(|x| !x.is_finite()) {
                    return Err(format!("line {ln}: a normal needs 3 finite numbers"));
                }
                let n = DVec3::new(v[0], v[1], v[2]);
                // Scaled first, so 1e-30 or 1e300 components still give a direction.
                let m = n.abs().max_element();
                vns.push(if m > 0.0 { (n / m).normalize().as_vec3() } else { Vec3::ZERO });
            }
            "vt" => vts += 1,
            "f" => {
                let mut face = Vec::new();
                for c in it {
                    let mut parts = c.split('/');
                    let v = index(parts.next().unwrap_or(""), vs.len(), ln, "vertex")?;
                    if let Some(t) = parts.next().filter(|t| !t.is_empty()) {
                        index(t, vts, ln, "texture")?;
                    }
                    let vn = match parts.next() {
                        Some(s) if !s.is_empty() => Some(index(s, vns.len(), ln, "normal")?),
                        _ => None,
                    };
                    if vn.is_none() {
                        out.no_normal_line.get_or_insert(ln);
                    }
                    let id = *corners.entry((v, vn)).or_insert_with(|| {
                        out.positions.push(vs[v]);
                        out.normals.push(vn.map_or(Vec3::ZERO, |k| vns[k]));
                        (out.positions.len() - 1) as u32
                    });
                    face.push(id);
                }
                if face.len() < 3 {
                    return Err(format!("line {ln}: a face needs at least 3 corners"));
                }
                if face.len() > 3 {
                    out.polygon_line.get_or_insert(ln);
                }
                if out.triangles.len() + face.len() - 2 > MAX_OBJ_TRIANGLES {
                    return Err(format!(
                        "line {ln}: more than {MAX_OBJ_TRIANGLES} triangles, the most phonglab shades"
                    ));
                }
                for k in 1..face.len() - 1 {
                    out.triangles.push([face[0], face[k], face[k + 1]]);
                }
            }
            _ => {}
        }
    }
    if out.triangles.is_empty() {
        return Err("no faces".into());
    }
    Ok(out)
}

/// Centres `positions` on their bounding box's centre and scales them to fit a sphere of
/// radius `radius`, in f64 and without squaring raw coordinates, so any finite coordinates
/// fit (1e300 or 1e-300 alike); returns the scale.
pub fn fit(positions: &mut [DVec3], radius: f64) -> f64 {
    let (lo, hi) = positions
        .iter()
        .fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    // Halves, so neither the centre nor an offset overflows at 1e308.
    let centre_half = lo * 0.25 + hi * 0.25;
    let offset_half = |p: DVec3| p * 0.5 - centre_half;
    let length = |d: DVec3| {
        let m = d.abs().max_element();
        if m > 0.0 { m * (d / m).length() } else { 0.0 }
    };
    let r_half = positions.iter().map(|p| length(offset_half(*p))).fold(0.0, f64::max);
    if !(r_half > 0.0 && r_half.is_finite()) {
        for p in positions.iter_mut() {
            *p -= centre_half * 2.0;
        }
        return 1.0;
    }
    for p in positions.iter_mut() {
        *p = offset_half(*p) / r_half * radius;
    }
    radius / r_half * 0.5
}

/// The mesh of `parsed` (positions already as they are to be drawn), with the notes on
/// what was done: fanned polygons and computed normals.
fn into_mesh(parsed: Parsed, notes: &mut Vec<String>) -> Mesh {
    let mut mesh = Mesh::default();
    for (p, n) in parsed.positions.iter().zip(&parsed.normals) {
        mesh.push_vertex(p.as_vec3(), *n);
    }
    mesh.triangles = parsed.triangles;
    if let Some(ln) = parsed.polygon_line {
        notes.push(format!("faces of more than 3 corners (the first on line {ln}) were fanned into triangles"));
    }
    if let Some(ln) = parsed.no_normal_line {
        notes.push(format!(
            "faces without normals (the first on line {ln}): their vertices' normals were computed as the area-weighted mean of their faces' normals"
        ));
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
    let parsed = parse(text.as_bytes())?;
    if parsed.positions.iter().any(|p| !p.as_vec3().is_finite()) {
        return Err("coordinates beyond single precision's range: load the file to fit it to the view".into());
    }
    let mut notes = Vec::new();
    let mesh = into_mesh(parsed, &mut notes);
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
pub fn load_obj(path: &Path) -> Result<LoadedObj, String> {
    let cannot = |e: std::io::Error| format!("cannot read {}: {e}", path.display());
    let meta = std::fs::metadata(path).map_err(cannot)?;
    if !meta.is_file() {
        return Err(format!("{} is not a regular file", path.display()));
    }
    if meta.len() > MAX_OBJ_BYTES {
        return Err(format!(
            "{} is {}; phonglab reads OBJ files of at most {} (about {} million triangles)",
            path.display(),
            describe_bytes(meta.len()),
            describe_bytes(MAX_OBJ_BYTES),
            MAX_OBJ_TRIANGLES / 1_000_000
        ));
    }
    let file = std::fs::File::open(path).map_err(cannot)?;
    let reader = std::io::BufReader::with_capacity(1 << 16, std::io::Read::take(file, MAX_OBJ_BYTES));
    let mut parsed = parse(reader).map_err(|e| format!("{}: {e}", path.display()))?;
    let k = fit(&mut parsed.positions, 0.5);
    let mut notes = Vec::new();
    let mesh = into_mesh(parsed, &mut notes);
    let scale = if (1e-3..1e4).contains(&k) { format!("{k:.4}") } else { format!("{k:.4e}") };
    notes.push(format!("centred and scaled by {scale} to fit the view (radius 0.5)"));
    Ok(LoadedObj { mesh, notes })
}

type ObjCache = Mutex<HashMap<PathBuf, (Option<std::time::SystemTime>, Arc<LoadedObj>)>>;

/// [`load_obj`], read once per file and modification time: the shaded view asks for its
/// mesh every time the view changes.
pub fn load_obj_cached(path: &Path) -> Result<Arc<LoadedObj>, String> {
    static CACHE: std::sync::OnceLock<ObjCache> = std::sync::OnceLock::new();
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
        let e = load_obj(Path::new("/dev/zero")).unwrap_err();
        assert!(e.contains("not a regular file"), "{e}");
        let e = load_obj(&dir).unwrap_err();
        assert!(e.contains("not a regular file"), "{e}");
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
