//! A Wavefront OBJ subset: `v`, `vn`, and `f` with `v`, `v/vt`, `v//vn` or `v/vt/vn`
//! corners (negative indices count back); polygons are fanned into triangles. Without
//! normals, each vertex gets the area-weighted mean of its faces' normals.

use std::collections::HashMap;

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

/// Parses OBJ text into a mesh (positions as given; normals normalised).
pub fn parse_obj(text: &str) -> Result<Mesh, String> {
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
                    needs_normals |= vn.is_none();
                    let id = *corners
                        .entry((v, vn))
                        .or_insert_with(|| mesh.push_vertex(vs[v], vn.map_or(Vec3::ZERO, |k| vns[k])));
                    face.push(id);
                }
                if face.len() < 3 {
                    return Err(format!("line {ln}: a face needs at least 3 corners"));
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
    if needs_normals {
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
    Ok(mesh)
}
