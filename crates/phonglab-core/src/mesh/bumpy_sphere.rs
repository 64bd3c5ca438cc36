//! A bumpy sphere, standing in for a scanned statue in the renderer's benchmarks
//! (`bench render --scan LEVEL`, the "scan-like" mesh): an icosahedron split `level`
//! times (20 x 4^level triangles; level 8 is 1 310 720) whose vertices are moved along the
//! sphere, by a seeded jitter, and out from it, by a sum of seeded waves, so the triangles
//! are irregular in size and shape and the surface is bumpy as a scan is; the normals are
//! the faces' area-weighted means, as a scanner's export computes them. At a million
//! triangles on a 1024-pixel view, most triangles are smaller than a pixel.
//! Deterministic: the same level and seed give the same bits.

use std::collections::HashMap;

use glam::Vec3;

use crate::numerics::elementary;

use super::Mesh;

/// The bumpy sphere of `20 x 4^level` triangles (level at most 9), radius about 0.5.
pub fn bumpy_sphere(level: u32, seed: u64) -> Mesh {
    let level = level.min(9);
    let t = f32::midpoint(1.0, 5f32.sqrt());
    let mut positions: Vec<Vec3> = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
    .collect();
    let mut triangles: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..level {
        let mut middle: HashMap<(u32, u32), u32> = HashMap::with_capacity(triangles.len() * 3 / 2);
        let mut split = Vec::with_capacity(triangles.len() * 4);
        let mut mid = |a: u32, b: u32, positions: &mut Vec<Vec3>| {
            *middle.entry((a.min(b), a.max(b))).or_insert_with(|| {
                positions.push(((positions[a as usize] + positions[b as usize]) * 0.5).normalize());
                positions.len() as u32 - 1
            })
        };
        for [a, b, c] in triangles {
            let (ab, bc, ca) = (mid(a, b, &mut positions), mid(b, c, &mut positions), mid(c, a, &mut positions));
            split.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        triangles = split;
    }
    let mut random = Random(seed ^ 0x9e37_79b9_7f4a_7c15);
    // Waves: random directions and frequencies, amplitudes falling with frequency.
    let waves: Vec<(Vec3, f32, f32, f32)> = (0..24)
        .map(|k| {
            let d = Vec3::new(random.signed(), random.signed(), random.signed()).normalize_or(Vec3::Z);
            let f = 2.0 + 1.6 * k as f32;
            (d, f, 0.05 / (1.0 + 0.35 * k as f32), random.unit() * std::f32::consts::TAU)
        })
        .collect();
    // The jitter along the sphere: up to 40 % of an edge of the last split.
    let edge = 1.1 / 2f32.powi(level as i32);
    for p in &mut positions {
        let tangent_a = p.any_orthonormal_vector();
        let tangent_b = p.cross(tangent_a);
        let moved = (*p + (tangent_a * random.signed() + tangent_b * random.signed()) * 0.4 * edge).normalize();
        let bump: f32 = waves.iter().map(|(d, f, a, phase)| a * elementary::sin_f32(f * moved.dot(*d) + phase)).sum();
        *p = moved * 0.5 * (1.0 + bump);
    }
    let mut normals = vec![Vec3::ZERO; positions.len()];
    for &[a, b, c] in &triangles {
        let (pa, pb, pc) = (positions[a as usize], positions[b as usize], positions[c as usize]);
        // Twice the area, along the face's normal: the weight is the area.
        let n = (pb - pa).cross(pc - pa);
        for v in [a, b, c] {
            normals[v as usize] += n;
        }
    }
    let normals = normals.into_iter().map(|n| n.normalize_or(Vec3::Z)).collect();
    Mesh { positions, normals, triangles, provoking: Vec::new() }
}

/// A small xorshift generator (the mesh needs no better).
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// In [0, 1).
    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }

    /// In [-1, 1).
    fn signed(&mut self) -> f32 {
        self.unit() * 2.0 - 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_counts_the_shape_and_the_irregularity_are_a_scans() {
        let m = bumpy_sphere(4, 1);
        assert_eq!(m.triangle_count(), 20 * 4usize.pow(4));
        // Euler: V - E + F = 2 on a closed surface of genus 0, E = 3F/2.
        assert_eq!(m.positions.len(), 2 + m.triangle_count() / 2);
        let r: Vec<f32> = m.positions.iter().map(|p| p.length()).collect();
        let (lo, hi) = r.iter().fold((f32::MAX, 0f32), |(lo, hi), &x| (lo.min(x), hi.max(x)));
        assert!(lo > 0.3 && hi < 0.7 && hi - lo > 0.05, "bumpy, about 0.5: {lo} {hi}");
        // Areas vary by more than a regular subdivision's.
        let areas: Vec<f32> = m
            .triangles
            .iter()
            .map(|&[a, b, c]| {
                let (pa, pb, pc) = (m.positions[a as usize], m.positions[b as usize], m.positions[c as usize]);
                (pb - pa).cross(pc - pa).length() * 0.5
            })
            .collect();
        let mean = areas.iter().sum::<f32>() / areas.len() as f32;
        let spread = areas.iter().map(|a| (a - mean).abs()).sum::<f32>() / areas.len() as f32 / mean;
        assert!(spread > 0.2, "irregular: mean absolute deviation {spread} of the mean");
        assert!(m.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5));
        // Outward: the normal agrees with the position's direction almost everywhere.
        let outward = m.positions.iter().zip(&m.normals).filter(|(p, n)| p.dot(**n) > 0.0).count();
        assert!(outward * 100 > 99 * m.positions.len(), "{outward} of {}", m.positions.len());
        assert_eq!(bumpy_sphere(4, 1), m, "deterministic");
        assert_ne!(bumpy_sphere(4, 2).positions, m.positions, "seeded");
    }
}
