//! gluCylinder: a (possibly tapered) tube along z from 0 to `height`, quad strips per
//! stack; `caps` adds gluDisk-style fans at both ends (gluCylinder itself has none).

use glam::Vec3;

use crate::numerics::elementary;

use super::Mesh;

/// A cylinder with radii `base` (z = 0) and `top` (z = height); `2 slices stacks`
/// triangles, plus `2 slices` with caps.
pub fn glu_cylinder(base: f32, top: f32, height: f32, slices: u32, stacks: u32, caps: bool) -> Mesh {
    glu_cylinder_oriented(base, top, height, [slices, stacks], caps, false)
}

/// The cylinder as gluCylinder (and gluDisk for the caps) draws it after
/// `gluQuadricOrientation(q, GLU_INSIDE)`: the same vertices, each normal pointing inwards,
/// each quad strip sent with its pairs the other way round (each quad split along its other
/// diagonal) and each triangle wound the other way.
pub fn glu_cylinder_inside(base: f32, top: f32, height: f32, slices: u32, stacks: u32, caps: bool) -> Mesh {
    glu_cylinder_oriented(base, top, height, [slices, stacks], caps, true)
}

fn glu_cylinder_oriented(
    base: f32,
    top: f32,
    height: f32,
    [slices, stacks]: [u32; 2],
    caps: bool,
    inside: bool,
) -> Mesh {
    let slices = slices.max(3);
    let stacks = stacks.max(1);
    let mut m = Mesh::default();
    // GLU's normal: the side's slope tilts it by atan((base - top) / height).
    let slope = elementary::atan2((base - top) as f64, height as f64);
    let (sin_s, cos_s) = elementary::sin_cos(slope);
    let angle = |i: u32| 2.0 * std::f64::consts::PI * (i % slices) as f64 / slices as f64;
    let mut rows = Vec::new();
    for j in 0..=stacks {
        let t = j as f64 / stacks as f64;
        let r = base as f64 + (top as f64 - base as f64) * t;
        let z = (height as f64 * t) as f32;
        rows.push(m.positions.len() as u32);
        for i in 0..=slices {
            let (s, c) = elementary::sin_cos(angle(i));
            let n = Vec3::new((s * cos_s) as f32, (c * cos_s) as f32, sin_s as f32);
            m.push_vertex(Vec3::new((r * s) as f32, (r * c) as f32, z), n);
        }
    }
    // GLU sends each stack as a quad strip (a_i, b_i, a_i+1, b_i+1, ...): GL_FLAT colours
    // both triangles of a quad with its last vertex, b_i+1. With caps the export draws
    // phonglab's own triangles (gluCylinder has none): each its last corner.
    for w in rows.windows(2) {
        // GLU_INSIDE sends each pair of the strip the other way round: the quads' corners
        // with the two rows exchanged.
        let (a, b) = if inside { (w[1], w[0]) } else { (w[0], w[1]) };
        for i in 0..slices {
            m.triangles.push([a + i + 1, a + i, b + i]);
            m.triangles.push([a + i + 1, b + i, b + i + 1]);
            if !caps {
                m.provoking.extend([b + i + 1, b + i + 1]);
            }
        }
    }
    if caps {
        for (z, r, n) in [(0.0f32, base, -Vec3::Z), (height, top, Vec3::Z)] {
            let centre = m.push_vertex(Vec3::new(0.0, 0.0, z), n);
            let first = m.positions.len() as u32;
            for i in 0..=slices {
                let (s, c) = elementary::sin_cos(angle(i));
                m.push_vertex(Vec3::new(r * s as f32, r * c as f32, z), n);
            }
            for i in 0..slices {
                // Facing +z (the top, from outside; the bottom turned inside out): (i+1, i).
                if (n.z > 0.0) == inside {
                    m.triangles.push([centre, first + i, first + i + 1]);
                } else {
                    m.triangles.push([centre, first + i + 1, first + i]);
                }
            }
        }
    }
    if inside {
        for n in &mut m.normals {
            *n = -*n;
        }
    }
    m
}
