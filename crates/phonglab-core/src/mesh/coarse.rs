//! A coarser copy of a large mesh, for the frames drawn while the camera turns: a student
//! orbiting a scanned statue of a million triangles sees it move at classroom speed, and
//! the whole mesh is drawn again the moment the mouse is let go (the app says which one it
//! shows). Never used for a picture that is kept, exported, probed or picked.
//!
//! Vertex clustering (Rossignac and Borrel, "Multi-resolution 3D approximations for
//! rendering complex scenes", 1993): space is cut into cubes; the vertices in one cube
//! become one vertex, at their mean position, with the normalised sum of their normals;
//! a triangle whose corners fall in fewer than three cubes disappears. One pass over the
//! vertices and one over the triangles, with the cube size chosen so that about `target`
//! triangles remain.

use std::collections::HashMap;

use glam::Vec3;

use super::Mesh;

/// `mesh` with about `target` triangles or fewer (a few more at worst, see the loop): a
/// copy of `mesh` when it has no more than that, or when its positions are not all finite.
pub fn clustered(mesh: &Mesh, target: usize) -> Mesh {
    let (lo, hi) =
        mesh.positions.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let extent = (hi - lo).max_element();
    if mesh.triangle_count() <= target || !(extent.is_finite() && extent > 0.0) {
        return mesh.clone();
    }
    // A closed surface in a box of r cubes a side keeps about 2 pi r^2 triangles (a
    // sphere's); other shapes differ, so the size is corrected from what a try gives.
    let mut cubes = ((target as f64 / (2.0 * std::f64::consts::PI)).sqrt()).max(2.0);
    let mut best: Option<Mesh> = None;
    for _ in 0..5 {
        let m = clustered_in(mesh, lo, extent / cubes as f32);
        let n = m.triangle_count();
        let fits = n <= target + target / 10;
        if fits && best.as_ref().is_none_or(|b| n > b.triangle_count()) {
            best = Some(m);
        }
        // Within 25 % under the target (or over it): good enough, or try a size that
        // scales the count by the square of the cube size.
        if fits && n * 4 >= target * 3 {
            break;
        }
        cubes *= (target as f64 / n.max(1) as f64).sqrt() * 0.97;
    }
    best.unwrap_or_else(|| clustered_in(mesh, lo, extent / 2.0))
}

/// `mesh`'s vertices clustered in cubes of side `side` from corner `lo`.
fn clustered_in(mesh: &Mesh, lo: Vec3, side: f32) -> Mesh {
    let cube_of = |p: Vec3| {
        let c = ((p - lo) / side).floor();
        // 21 bits an axis: far more cubes than a target asks for.
        let k = |x: f32| (x.clamp(0.0, (1 << 21) as f32 - 1.0) as u64) & ((1 << 21) - 1);
        k(c.x) | k(c.y) << 21 | k(c.z) << 42
    };
    let mut cluster_of_cube: HashMap<u64, u32> = HashMap::with_capacity(mesh.positions.len() / 4);
    let mut sums: Vec<(Vec3, Vec3, u32)> = Vec::new();
    let cluster: Vec<u32> = mesh
        .positions
        .iter()
        .zip(&mesh.normals)
        .map(|(p, n)| {
            let next = sums.len() as u32;
            let c = *cluster_of_cube.entry(cube_of(*p)).or_insert(next);
            if c == next {
                sums.push((Vec3::ZERO, Vec3::ZERO, 0));
            }
            let s = &mut sums[c as usize];
            (s.0, s.1, s.2) = (s.0 + *p, s.1 + *n, s.2 + 1);
            c
        })
        .collect();
    let mut out = Mesh::default();
    for (p, n, k) in sums {
        out.positions.push(p / k as f32);
        // Opposite normals can cancel (a thin sheet in one cube): then any unit vector.
        out.normals.push(n.try_normalize().unwrap_or(Vec3::Z));
    }
    out.triangles = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| cluster[i as usize]))
        .filter(|[a, b, c]| a != b && b != c && a != c)
        .collect();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{bumpy_sphere, sphere, teapot};

    /// The 700² sphere (979 k triangles) and the scan-like mesh (1.3 M) come down to
    /// between 75 % and 110 % of the target; every vertex of the coarse sphere lies within
    /// a cube's diagonal of the unit sphere, its normal is unit and points outwards; every
    /// triangle's corners are distinct vertices of the copy.
    #[test]
    fn a_million_triangles_come_down_to_about_the_target_and_stay_on_the_surface() {
        let target = 200_000;
        let big = sphere::glu_sphere(1.0, 700, 700);
        let coarse = clustered(&big, target);
        let n = coarse.triangle_count();
        assert!(n * 4 >= target * 3 && n <= target + target / 10, "{n}");
        // The cube side is about 2 / sqrt(target / 2 pi) = 0.011.
        for (p, nrm) in coarse.positions.iter().zip(&coarse.normals) {
            assert!((p.length() - 1.0).abs() < 0.02, "{p}");
            assert!((nrm.length() - 1.0).abs() < 1e-5 && nrm.dot(*p) > 0.9, "{nrm} at {p}");
        }
        let v = coarse.positions.len() as u32;
        assert!(
            coarse.triangles.iter().all(|t| t.iter().all(|i| *i < v) && t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        );
        let scan = bumpy_sphere::bumpy_sphere(8, 1);
        let n = clustered(&scan, target).triangle_count();
        assert!(n * 4 >= target * 3 && n <= target + target / 10, "scan: {n}");
    }

    /// A mesh already under the target is returned as it is.
    #[test]
    fn a_small_mesh_is_kept_whole() {
        let teapot = teapot::glut_teapot(0.8, 7);
        let copy = clustered(&teapot, teapot.triangle_count());
        assert_eq!((copy.positions, copy.triangles), (teapot.positions, teapot.triangles));
    }
}
