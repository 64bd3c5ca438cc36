//! A mesh written as OBJ text: `v` and `vn` lines and `f v//vn` triangles. Each f32 is
//! written as the shortest decimal of its value as an f64, which is that value exactly:
//! read as an f32, or as an f64 and then narrowed (Python's way), it is the same f32. What `phonglab bench render
//! --write-mesh` gives Mesa's harness, so that llvmpipe draws the very vertex arrays the
//! renderer was timed on.

use std::fmt::Write;

use crate::mesh::Mesh;

/// `mesh` as OBJ text: one position and one normal per vertex, sharing its index.
pub fn obj_text(mesh: &Mesh) -> String {
    let mut s = String::with_capacity(mesh.positions.len() * 70 + mesh.triangles.len() * 30);
    s.push_str("# phonglab: a mesh as timed by `phonglab bench render`\n");
    for p in &mesh.positions {
        let [x, y, z] = p.to_array().map(f64::from);
        let _ = writeln!(s, "v {x:?} {y:?} {z:?}");
    }
    for n in &mesh.normals {
        let [x, y, z] = n.to_array().map(f64::from);
        let _ = writeln!(s, "vn {x:?} {y:?} {z:?}");
    }
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| i + 1);
        let _ = writeln!(s, "f {a}//{a} {b}//{b} {c}//{c}");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::obj::parse_obj;

    #[test]
    fn every_number_reads_back_as_the_same_f32_either_way() {
        // The scan-like mesh: irregular positions and computed normals, every bit of them.
        let mesh = crate::mesh::bumpy_sphere::bumpy_sphere(2, 7);
        let text = obj_text(&mesh);
        let numbers = |tag: &str| -> Vec<[(u32, u32); 3]> {
            text.lines()
                .filter_map(|l| l.strip_prefix(tag))
                .map(|l| {
                    let w: Vec<&str> = l.split_whitespace().collect();
                    [0, 1, 2].map(|i| {
                        (w[i].parse::<f32>().unwrap().to_bits(), (w[i].parse::<f64>().unwrap() as f32).to_bits())
                    })
                })
                .collect()
        };
        let bits =
            |v: &[glam::Vec3]| v.iter().map(|p| p.to_array().map(|x| (x.to_bits(), x.to_bits()))).collect::<Vec<_>>();
        assert_eq!(numbers("v "), bits(&mesh.positions));
        assert_eq!(numbers("vn "), bits(&mesh.normals));
        // And phonglab's own reader gives the triangles' corners back (it numbers the
        // vertices in the order the faces first use them).
        let back = parse_obj(&text).unwrap();
        let corners = |m: &Mesh| {
            m.triangles.iter().flat_map(|t| t.map(|i| m.positions[i as usize].to_array())).collect::<Vec<_>>()
        };
        assert_eq!(corners(&back), corners(&mesh));
        assert!(text.contains("\nf 1//1 "), "1-based indices, position and normal alike");
    }
}
