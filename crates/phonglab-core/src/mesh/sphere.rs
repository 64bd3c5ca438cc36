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

/// A sphere of `radius` about the origin (slices >= 3, stacks >= 2). Each triangle's last
/// corner is the vertex GL sends last for it (the fans' last, the quad's fourth), the
/// provoking vertex `GL_FLAT` takes its colour from: the mesh leaves `provoking` empty.
pub fn glu_sphere(radius: f32, slices: u32, stacks: u32) -> Mesh {
    glu_sphere_oriented(radius, slices, stacks, false)
}

/// The sphere as gluSphere draws it after `gluQuadricOrientation(q, GLU_INSIDE)`: the same
/// vertices, each normal pointing inwards, each quad strip sent with its pairs of vertices
/// the other way round (so each quad is split along its other diagonal) and each triangle
/// wound the other way (facing inwards).
pub fn glu_sphere_inside(radius: f32, slices: u32, stacks: u32) -> Mesh {
    glu_sphere_oriented(radius, slices, stacks, true)
}

fn glu_sphere_oriented(radius: f32, slices: u32, stacks: u32, inside: bool) -> Mesh {
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
        m.triangles.push(if inside { [top, r1 + i, r1 + i + 1] } else { [top, r1 + i + 1, r1 + i] });
    }
    // GLU sends each band as a quad strip from the lower ring's vertex to the upper's
    // (b_i, a_i, b_i+1, a_i+1, ...), and OpenGL (Mesa's draw module, last-vertex convention)
    // splits quad (b_i, a_i, a_i+1, b_i+1) along b_i to a_i+1: (b_i+1, b_i, a_i+1) and
    // (b_i, a_i, a_i+1). The diagonal shows in Gouraud on a coarse sphere. GLU_INSIDE sends
    // each pair the other way round (a_i, b_i, ...): the same split with the rings exchanged.
    for w in rings.windows(2) {
        let (a, b) = if inside { (w[1], w[0]) } else { (w[0], w[1]) };
        for i in 0..slices {
            m.triangles.push([b + i + 1, b + i, a + i + 1]);
            m.triangles.push([b + i, a + i, a + i + 1]);
        }
    }
    let rl = *rings.last().unwrap_or(&r1);
    for i in 0..slices {
        m.triangles.push(if inside { [bottom, rl + i + 1, rl + i] } else { [bottom, rl + i, rl + i + 1] });
    }
    if inside {
        for n in &mut m.normals {
            *n = -*n;
        }
    }
    m
}
