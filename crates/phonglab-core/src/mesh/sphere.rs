//! gluSphere: slices around z, stacks from the +z pole to the -z pole.
//!
//! The layout of SGI GLU's `gluSphere` (GLU_FILL, GLU_SMOOTH, outside): a triangle fan at
//! each pole and quad strips between, so `2 slices + 2 slices (stacks - 2)` triangles
//! (4900 for 50 x 50). Vertex (slice i, stack j) is
//! `r (sin(theta_i) sin(rho_j), cos(theta_i) sin(rho_j), cos(rho_j))`, theta_i = 2 pi i / slices,
//! rho_j = pi j / stacks; the normal is the same without r.

use glam::Vec3;

use crate::numerics::elementary;

use super::Mesh;

/// A sphere of `radius` about the origin (slices >= 3, stacks >= 2).
pub fn glu_sphere(radius: f32, slices: u32, stacks: u32) -> Mesh {
    let slices = slices.max(3);
    let stacks = stacks.max(2);
    let mut m = Mesh::default();
    let dir = |i: u32, j: u32| {
        let theta = 2.0 * std::f64::consts::PI * (i % slices) as f64 / slices as f64;
        let rho = std::f64::consts::PI * j as f64 / stacks as f64;
        let ((st, ct), (sr, cr)) = (elementary::sin_cos(theta), elementary::sin_cos(rho));
        Vec3::new((st * sr) as f32, (ct * sr) as f32, cr as f32)
    };
    let top = m.push_vertex(Vec3::new(0.0, 0.0, radius), Vec3::Z);
    let bottom = m.push_vertex(Vec3::new(0.0, 0.0, -radius), -Vec3::Z);
    // Rings 1..stacks-1, each with slices + 1 vertices (the seam repeated, as GLU does).
    let ring = |m: &mut Mesh, j: u32| -> u32 {
        let first = m.positions.len() as u32;
        for i in 0..=slices {
            let n = dir(i, j);
            m.push_vertex(n * radius, n);
        }
        first
    };
    let rings: Vec<u32> = (1..stacks).map(|j| ring(&mut m, j)).collect();
    // With theta increasing, (sin, cos) turns clockwise seen from +z; so (top, i+1, i) is CCW from outside.
    let r1 = rings[0];
    for i in 0..slices {
        m.triangles.push([top, r1 + i + 1, r1 + i]);
    }
    // GLU sends each band as a quad strip from the lower ring's vertex to the upper's
    // (b_i, a_i, b_i+1, a_i+1, ...), and OpenGL (Mesa's draw module, last-vertex convention)
    // splits quad (b_i, a_i, a_i+1, b_i+1) along b_i to a_i+1: (b_i+1, b_i, a_i+1) and
    // (b_i, a_i, a_i+1). The diagonal shows in Gouraud on a coarse sphere.
    for w in rings.windows(2) {
        let (a, b) = (w[0], w[1]);
        for i in 0..slices {
            m.triangles.push([b + i + 1, b + i, a + i + 1]);
            m.triangles.push([b + i, a + i, a + i + 1]);
        }
    }
    let rl = *rings.last().unwrap_or(&r1);
    for i in 0..slices {
        m.triangles.push([bottom, rl + i, rl + i + 1]);
    }
    m
}
