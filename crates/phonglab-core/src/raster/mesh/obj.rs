//! A Wavefront OBJ subset: `v`, `vn`, and `f` with `v`, `v/vt`, `v//vn` or `v/vt/vn`
//! corners (negative indices count back); polygons are fanned into triangles. Without
//! normals, each vertex gets the area-weighted mean of its faces' normals.
//!
//! Bad input is refused with the line it is on: an index out of range, a number that is
//! not one or not finite (NaN), a face of fewer than 3 corners, a file over
//! [`MAX_OBJ_BYTES`] or [`MAX_OBJ_TRIANGLES`]. What was done to the file without refusing
//! it (polygons fanned, normals computed, the mesh fitted to the view) is said in notes.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use glam::Vec3;

use super::Mesh;

fn index(s: &str, len: usize, ln: usize, what: &str) -> Result<usize, String> {
    let i: i64 = s.parse().map_err(|_| format!("line {ln}: {what} index {s:?} is not a number"))?;
    let resolved = if i > 0 { i - 1 } else { len as i64 + i };
    if resolved < 0 || resolved as usize >= len {
        return Err(format!("line {ln}: {what} index {i} is out of range (there are {len})"));
    }
    Ok(resolved as usize)
}

/// The largest OBJ file read, in bytes.
pub const MAX_OBJ_BYTES: u64 = 64 << 20;

/// The most triangles an OBJ file may make.
pub const MAX_OBJ_TRIANGLES: usize = 4_000_000;

/// Parses OBJ text into a mesh (positions as given; normals normalised).
pub fn parse_obj(text: &str) -> Result<Mesh, String> {
    parse_obj_noted(text).map(|(m, _)| m)
}

/// [`parse_obj`], with notes on what was done to the file: polygons fanned into triangles,
/// normals computed where the file has none (each naming the first line concerned).
pub fn parse_obj_noted(text: &str) -> Result<(Mesh, Vec<String>), String> {
    let mut notes = Vec::new();
    let mut polygon_line = None;
    let mut no_normal_line = None;
    let (mut vs, mut vns) = (Vec::new(), Vec::new());
    let mut mesh = Mesh::default();
    let mut corners: HashMap<(usize, Option<usize>), u32> = HashMap::new();
    let mut needs_normals = false;
    for (i, line) in text.lines().enumerate() {
        let ln = i + 1;
        let mut it = line.split_whitespace();
        let Some(tag) = it.next() else { continue };
        let nums = |it: std::str::SplitWhitespace<'_>| -> Result<Vec<f32>, String> {
            it.map(|x| x.parse::<f32>().map_err(|_| format!("line {ln}: {x:?} is not a number"))).collect()
        };
        match tag {
            "v" => {
                let v = nums(it)?;
                if v.len() < 3 || v[..3].iter().any(|x| !x.is_finite()) {
                    return Err(format!("line {ln}: a vertex needs 3 finite numbers"));
                }
                vs.push(Vec3::new(v[0], v[1], v[2]));
            }
            "vn" => {
                let v = nums(it)?;
                if v.len() != 3 || v.iter().any(|x| !x.is_finite()) {
                    return Err(format!("line {ln}: a normal needs 3 finite numbers"));
                }
                vns.push(Vec3::new(v[0], v[1], v[2]).try_normalize().unwrap_or(Vec3::ZERO));
            }
            "f" => {
                let mut face = Vec::new();
                for c in it {
                    let mut parts = c.split('/');
                    let v = index(parts.next().unwrap_or(""), vs.len(), ln, "vertex")?;
                    let _vt = parts.next();
                    let vn = match parts.next() {
                        Some(s) if !s.is_empty() => Some(index(s, vns.len(), ln, "normal")?),
                        _ => None,
                    };
                    if vn.is_none() {
                        needs_normals = true;
                        no_normal_line.get_or_insert(ln);
                    }
                    let id = *corners
                        .entry((v, vn))
                        .or_insert_with(|| mesh.push_vertex(vs[v], vn.map_or(Vec3::ZERO, |k| vns[k])));
                    face.push(id);
                }
                if face.len() < 3 {
                    return Err(format!("line {ln}: a face needs at least 3 corners"));
                }
                if face.len() > 3 {
                    polygon_line.get_or_insert(ln);
                }
                if mesh.triangles.len() + face.len() - 2 > MAX_OBJ_TRIANGLES {
                    return Err(format!("line {ln}: more than {MAX_OBJ_TRIANGLES} triangles, too many to shade"));
                }
                for k in 1..face.len() - 1 {
                    mesh.triangles.push([face[0], face[k], face[k + 1]]);
                }
            }
            _ => {}
        }
    }
    if mesh.triangles.is_empty() {
        return Err("no faces".into());
    }
    if let Some(ln) = polygon_line {
        notes.push(format!("faces of more than 3 corners (the first on line {ln}) were fanned into triangles"));
    }
    if needs_normals {
        notes.push(format!(
            "faces without normals (the first on line {}): their vertices' normals were computed as the area-weighted mean of their faces' normals",
            no_normal_line.unwrap_or(0)
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
    Ok((mesh, notes))
}

/// Centres `mesh` on its bounding box's centre and scales it to fit a sphere of radius
/// `radius` (the view's objects are 0.5 across the middle); returns the scale.
pub fn fit(mesh: &mut Mesh, radius: f32) -> f32 {
    let (lo, hi) = mesh
        .positions
        .iter()
        .fold((Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let centre = (lo + hi) * 0.5;
    let r = mesh.positions.iter().map(|p| (*p - centre).length()).fold(0.0, f32::max);
    let k = if r > 0.0 && r.is_finite() { radius / r } else { 1.0 };
    for p in &mut mesh.positions {
        *p = (*p - centre) * k;
    }
    k
}

/// A mesh read from a file, fitted to the view, with notes on what was done to it.
#[derive(Clone, Debug)]
pub struct LoadedObj {
    /// The mesh, centred and scaled to radius 0.5.
    pub mesh: Mesh,
    /// What was done to the file (fanned, normals computed, fitted).
    pub notes: Vec<String>,
}

/// Reads an OBJ file: refused (with a line number where there is one) when it cannot be
/// read, is over [`MAX_OBJ_BYTES`], or does not parse; fitted to radius 0.5.
pub fn load_obj(path: &Path) -> Result<LoadedObj, String> {
    let size = std::fs::metadata(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?.len();
    if size > MAX_OBJ_BYTES {
        return Err(format!(
            "{} is {:.0} MB; phonglab reads OBJ files up to {} MB",
            path.display(),
            size as f64 / (1 << 20) as f64,
            MAX_OBJ_BYTES >> 20
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let text = String::from_utf8_lossy(&bytes);
    let (mut mesh, mut notes) = parse_obj_noted(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let k = fit(&mut mesh, 0.5);
    notes.push(format!("centred and scaled by {k:.4} to fit the view (radius 0.5)"));
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
        let (mut m, notes) = parse_obj_noted(text).unwrap();
        assert_eq!(m.triangle_count(), 3);
        assert!(notes[0].contains("line 6") && notes[0].contains("fanned"), "{notes:?}");
        assert!(notes[1].contains("line 6") && notes[1].contains("computed"), "{notes:?}");
        let k = fit(&mut m, 0.5);
        let r = m.positions.iter().map(|p| p.length()).fold(0.0, f32::max);
        assert!((r - 0.5).abs() < 1e-6 && k > 0.0, "{r}");
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
        assert!(e.contains("up to 64 MB"), "{e}");
        let e = load_obj(&dir.join("missing.obj")).unwrap_err();
        assert!(e.contains("cannot read"), "{e}");
    }
}
