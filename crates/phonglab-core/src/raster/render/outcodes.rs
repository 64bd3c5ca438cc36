//! Each vertex's place against the view volume, as one byte: which of the volume's six
//! planes it is outside of, whether it is outside the near or far plane (or has w <= 0),
//! and whether it lies beyond the guard band. Made once per vertex in the vertices
//! stage, so that setup decides each triangle (rejected whole, clipped, or snapped as it
//! is) from three bytes instead of three clip-space positions: a vertex of a closed mesh
//! has about six triangles, and the tests, made per corner, were setup's hottest
//! instructions on a million triangles; setup took 0.6 of its time after this
//! (docs/performance.md, "A million triangles").

use glam::Vec4;

/// Vertices may lie this many viewports away from the centre before x/y clipping.
pub const GUARD: f32 = 8.0;

/// The six bits of the planes of the view volume: x < -w, x > w, y < -w, y > w, z < -w,
/// z > w (a NaN is outside of none).
pub const OUTSIDE_PLANES: u8 = 0b0011_1111;
/// Outside the near or far plane, or w <= 0: a triangle with this corner is clipped in depth.
pub const OUTSIDE_DEPTH: u8 = 1 << 6;
/// Beyond the guard band in x or y: a triangle with this corner is clipped in x and y.
pub const BEYOND_GUARD: u8 = 1 << 7;

/// The code of clip-space vertex `v`.
#[inline(always)]
pub fn code(v: Vec4) -> u8 {
    let planes = (v.x < -v.w) as u8
        | ((v.x > v.w) as u8) << 1
        | ((v.y < -v.w) as u8) << 2
        | ((v.y > v.w) as u8) << 3
        | ((v.z < -v.w) as u8) << 4
        | ((v.z > v.w) as u8) << 5;
    let depth = v.z < -v.w || v.z > v.w || v.w <= 0.0;
    let guard = v.x.abs() > GUARD * v.w || v.y.abs() > GUARD * v.w;
    planes | (depth as u8) << 6 | (guard as u8) << 7
}

/// The codes of the vertices `clip` into `out`.
#[inline(always)]
pub fn codes(clip: &[Vec4], out: &mut [u8]) {
    for (o, &c) in out.iter_mut().zip(clip) {
        *o = code(c);
    }
}
