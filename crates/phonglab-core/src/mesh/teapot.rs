//! The Utah teapot from its 32 bicubic Bezier patches (`assets/teapot.bpt`, z up).
//!
//! Each patch is evaluated on an `n x n` grid of quads (glutSolidTeapot uses n = 7:
//! 32 x 7 x 7 x 2 = 3136 triangles) with analytic normals `dP/du x dP/dv`. Where a patch
//! edge collapses to a point (the lid's knob top and the bottom's centre) one derivative
//! vanishes; there the normal is the limit `d2P/dudv x dP/dv` (or `dP/du x d2P/dudv`),
//! which is finite and points along the axis. The file does not orient every patch the
//! same way, so each patch is flipped if a ray from its centre along its normal crosses
//! the rest of the teapot an odd number of times (pointing inside).
//!
//! glutSolidTeapot(size) places it: rotate 270 degrees about x (z up becomes y up),
//! scale by 0.5 size, after moving it down by 1.575 (freeglut's offset, which centres the
//! teapot vertically; SGI's GLUT used 1.5).

use std::sync::OnceLock;

use glam::DVec3;

use super::Mesh;

/// The patch file as shipped in `assets/teapot.bpt` (compiled in).
pub const TEAPOT_BPT: &str = include_str!("../../../../assets/teapot.bpt");

/// A bicubic Bezier patch: control points `p[row u][column v]`.
pub type Patch = [[DVec3; 4]; 4];

/// Parses the .bpt format: a patch count, then per patch "3 3" and 16 points "x y z".
pub fn parse_bpt(text: &str) -> Result<Vec<Patch>, String> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty());
    let (ln, first) = lines.next().ok_or("empty file")?;
    let count: usize = first.parse().map_err(|_| format!("line {ln}: expected the patch count, found {first:?}"))?;
    let mut patches = Vec::with_capacity(count);
    for k in 0..count {
        let (ln, deg) = lines.next().ok_or(format!("patch {k}: missing degrees line"))?;
        if deg.split_whitespace().collect::<Vec<_>>() != ["3", "3"] {
            return Err(format!("line {ln}: patch {k} is not bicubic (\"{deg}\"); only \"3 3\" is supported"));
        }
        let mut p = [[DVec3::ZERO; 4]; 4];
        for i in 0..16 {
            let (ln, l) = lines.next().ok_or(format!("patch {k}: missing control point {i}"))?;
            let v: Vec<f64> = l
                .split_whitespace()
                .map(str::parse)
                .collect::<Result<_, _>>()
                .map_err(|_| format!("line {ln}: not three numbers: {l:?}"))?;
            if v.len() != 3 {
                return Err(format!("line {ln}: expected 3 numbers, found {}", v.len()));
            }
            p[i / 4][i % 4] = DVec3::new(v[0], v[1], v[2]);
        }
        patches.push(p);
    }
    Ok(patches)
}

fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

fn bernstein_d(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t]
}

/// Position, dP/du, dP/dv and d2P/dudv at (u, v).
pub fn evaluate(p: &Patch, u: f64, v: f64) -> (DVec3, DVec3, DVec3, DVec3) {
    let (bu, bv, du, dv) = (bernstein(u), bernstein(v), bernstein_d(u), bernstein_d(v));
    let mut out = [DVec3::ZERO; 4];
    for i in 0..4 {
        for j in 0..4 {
            out[0] += p[i][j] * (bu[i] * bv[j]);
            out[1] += p[i][j] * (du[i] * bv[j]);
            out[2] += p[i][j] * (bu[i] * dv[j]);
            out[3] += p[i][j] * (du[i] * dv[j]);
        }
    }
    (out[0], out[1], out[2], out[3])
}

/// The unit normal `dP/du x dP/dv` at (u, v), with the limit at a collapsed edge.
pub fn normal(p: &Patch, u: f64, v: f64) -> DVec3 {
    let (_, pu, pv, puv) = evaluate(p, u, v);
    let scale = (pu.length() + pv.length()).max(1e-300);
    let n = pu.cross(pv);
    if n.length() > 1e-9 * scale * scale {
        return n.normalize();
    }
    // One derivative vanishes along a collapsed edge: replace it by its rate of change
    // across the edge (first order in the distance to the edge).
    let lim = if pu.length() < pv.length() { puv.cross(pv) } else { pu.cross(puv) };
    lim.try_normalize().unwrap_or(DVec3::Z)
}

/// The signed volume enclosed by the patches' `dP/du x dP/dv` orientation (divergence
/// theorem over a coarse tessellation): positive when the normals point outward.
fn signed_volume(patches: &[Patch]) -> f64 {
    let n = 8;
    let mut v = 0.0;
    for p in patches {
        let pt = |i: usize, j: usize| evaluate(p, i as f64 / n as f64, j as f64 / n as f64).0;
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (pt(i, j), pt(i + 1, j), pt(i + 1, j + 1), pt(i, j + 1));
                v += a.dot(b.cross(c)) + a.dot(c.cross(d));
            }
        }
    }
    v / 6.0
}

/// The 32 patches, oriented so that `dP/du x dP/dv` points outward.
pub fn patches() -> &'static [Patch] {
    static PATCHES: OnceLock<Vec<Patch>> = OnceLock::new();
    PATCHES.get_or_init(|| {
        let mut ps = parse_bpt(TEAPOT_BPT).expect("the shipped teapot parses (checked by a test)");
        if signed_volume(&ps) < 0.0 {
            for p in &mut ps {
                // Swapping u and v reverses the orientation.
                let q = *p;
                for i in 0..4 {
                    for j in 0..4 {
                        p[i][j] = q[j][i];
                    }
                }
            }
        }
        ps
    })
}

/// freeglut's vertical offset of the teapot (in patch units, before scaling).
pub const Z_OFFSET: f64 = 1.575;

/// glutSolidTeapot(size) as freeglut draws it: the 32 patches on a `grid x grid` quad grid
/// each (freeglut: 7), y up.
pub fn glut_teapot(size: f32, grid: u32) -> Mesh {
    let grid = grid.max(1) as usize;
    let s = 0.5 * size as f64;
    // Rotate 270 degrees about x: (x, y, z) -> (x, z, -y); after z -= 1.575; then scale.
    let place = |p: DVec3| DVec3::new(p.x, p.z - Z_OFFSET, -p.y) * s;
    let place_n = |n: DVec3| DVec3::new(n.x, n.z, -n.y);
    let mut m = Mesh::default();
    for p in patches() {
        let first = m.positions.len() as u32;
        for i in 0..=grid {
            for j in 0..=grid {
                let (u, v) = (i as f64 / grid as f64, j as f64 / grid as f64);
                let pos = place(evaluate(p, u, v).0);
                let n = place_n(normal(p, u, v));
                m.push_vertex(pos.as_vec3(), n.as_vec3());
            }
        }
        let idx = |i: usize, j: usize| first + (i * (grid + 1) + j) as u32;
        for i in 0..grid {
            for j in 0..grid {
                // (u, v) -> (i, j): du x dv outward means (i,j), (i+1,j), (i+1,j+1) is CCW from outside.
                m.triangles.push([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)]);
                m.triangles.push([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]);
                // freeglut sends the same two triangles (its u and v the other way round,
                // wound clockwise) as GL_TRIANGLES, each ending at what is here the middle
                // corner: GL_FLAT's provoking vertex (checked against Mesa in
                // tests/diagnose.rs). Where phonglab's own arrays are drawn instead (another
                // grid than glutSolidTeapot's 7), each triangle's last corner.
                if grid == 7 {
                    m.provoking.extend([idx(i + 1, j), idx(i + 1, j + 1)]);
                }
            }
        }
    }
    m
}
