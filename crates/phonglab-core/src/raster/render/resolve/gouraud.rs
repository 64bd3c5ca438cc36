//! Gouraud's pixels: each triangle's colours (clamped per vertex, as OpenGL clamps vertex
//! colours) interpolated perspective-correctly, written as planes. `c/w` and `1/w` are
//! affine on the screen, so each is set up once per triangle ([`ColorPlanes`], f64,
//! through a vertex) and stepped along a run in f32, and a pixel's colour is their
//! quotient. Within a few f32 roundings of the exact value (tested against the f64
//! interpolation: one level off at a handful of pixels, as the barycentric blend was), and
//! a block of pixels costs a third of the vector operations of blending three vertices'
//! colours (the count: docs/performance.md, "Why the code is written so").

use super::pixels::{LANES, ResolveLanes};
use super::runs::Run;
use crate::raster::render::setup::{RasterTri, SUBPIXEL_BITS};
use crate::raster::render::visibility::barycentric_steps;

/// Gouraud's interpolation set up once per triangle: the colour channels times 1/w
/// (`r/w`, `g/w`, `b/w`, `a/w`) and `1/w`, each affine in the window coordinates (linear in
/// the screen barycentrics), as planes through the triangle's vertex 0: their values there
/// and their gradients per pixel, in f64. A pixel's colour is then `(c/w) / (1/w)`, the
/// perspective-correct interpolation, with each plane stepped along a run in f32
/// (`gouraud_block`) instead of blending three vertices from f64 barycentrics: the
/// same quantity, within a few f32 roundings (tested against the exact interpolation).
///
/// The planes go through a vertex, not the pixel origin or the box's corner, so that at a
/// covered pixel no large terms cancel: the value there is the vertex's plus a change no
/// bigger than the differences between the vertices' (f64 keeps a thin triangle's large
/// gradients exact enough; a run's start is rounded to f32 once).
#[derive(Clone, Copy, Debug, Default)]
pub struct ColorPlanes {
    /// Vertex 0 in fixed point (x, y).
    origin: [i64; 2],
    /// `r/w`, `g/w`, `b/w`, `a/w`, `1/w` at vertex 0.
    at_origin: [f64; 5],
    /// Their changes per pixel to the right.
    dx: [f64; 5],
    /// Their changes per row down.
    dy: [f64; 5],
}

impl ColorPlanes {
    /// The planes of `t`, whose colours at its vertices (times 1/w) are `colors`. A
    /// triangle without area (never drawn) gets flat planes.
    #[inline(always)]
    pub fn new(t: &RasterTri, colors: [[f32; 4]; 3]) -> Self {
        // l1 = w1 / area and l2 = w2 / area change by step / area a pixel, exactly as the
        // resolve's barycentrics do (the steps are integers, exact in f64).
        let ([sx1, sx2], [sy1, sy2], inv_area) = barycentric_steps(t);
        let (sx1, sx2, sy1, sy2) = (sx1 as f64, sx2 as f64, sy1 as f64, sy2 as f64);
        let value = |k: usize, c: usize| if c < 4 { colors[k][c] as f64 } else { t.inv_w[k] as f64 };
        let mut planes = Self { origin: [t.x[0].into(), t.y[0].into()], ..Self::default() };
        for c in 0..5 {
            let (v0, d1, d2) = (value(0, c), value(1, c) - value(0, c), value(2, c) - value(0, c));
            planes.at_origin[c] = v0;
            planes.dx[c] = (sx1 * d1 + sx2 * d2) * inv_area;
            planes.dy[c] = (sy1 * d1 + sy2 * d2) * inv_area;
        }
        planes
    }

    /// The planes at the centre of pixel (`px`, `py`), rounded to f32, and their f32 steps
    /// per pixel along the row.
    #[inline(always)]
    pub(super) fn row(&self, px: usize, py: usize) -> ([f32; 5], [f32; 5]) {
        let (one, half) = (1i64 << SUBPIXEL_BITS, 1i64 << (SUBPIXEL_BITS - 1));
        // The pixel's offset from vertex 0, in pixels (exact: integers over 256).
        let inv_one = 1.0 / one as f64;
        let fx = ((px as i64 * one + half) - self.origin[0]) as f64 * inv_one;
        let fy = ((py as i64 * one + half) - self.origin[1]) as f64 * inv_one;
        let mut start = [0.0; 5];
        let mut step = [0.0; 5];
        for c in 0..5 {
            start[c] = (self.at_origin[c] + self.dx[c] * fx + self.dy[c] * fy) as f32;
            step[c] = self.dx[c] as f32;
        }
        (start, step)
    }
}

/// Gouraud's colours of pixels `k0..k0 + LANES` of a run whose planes start at `start`
/// and step by `step` ([`ColorPlanes::row`]): each channel `(c/w) * (1 / (1/w))`, lane by
/// lane, with the same operations in every compiled copy (multiply, then add; no fused
/// multiply-add), so the same bits.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lanes index several arrays; the loop vectorises
pub(super) fn gouraud_block(start: &[f32; 5], step: &[f32; 5], k0: usize) -> [[f32; LANES]; 4] {
    let mut kf = [0.0f32; LANES];
    let mut s = [0.0f32; LANES];
    for j in 0..LANES {
        // i32 to f32 is one instruction for eight lanes; k0 + j is below the image width.
        kf[j] = (k0 as i32 + j as i32) as f32;
        s[j] = 1.0 / (start[4] + step[4] * kf[j]);
    }
    let mut out = [[0.0; LANES]; 4];
    for c in 0..4 {
        for j in 0..LANES {
            out[c][j] = (start[c] + step[c] * kf[j]) * s[j];
        }
    }
    out
}

/// A run of one triangle under Gouraud shading: its colour planes evaluated a block of
/// [`LANES`] pixels at a time, packed to bytes, into the run's pixels of `px_row`.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lane loops: see `blend`
pub(super) fn gouraud_run(lanes: impl ResolveLanes, planes: &ColorPlanes, run: &Run, px_row: &mut [[u8; 4]]) {
    let (start, step) = planes.row(run.x, run.y);
    for (k0, n) in run.blocks() {
        let ch = gouraud_block(&start, &step, k0);
        let rgba = lanes.rgba8(&ch);
        // Whole blocks where the row has room: lanes past the run land on
        // pixels of the row that later runs overwrite.
        let dst = &mut px_row[run.x + k0..];
        if let Some(dst) = dst.first_chunk_mut::<LANES>() {
            for j in 0..LANES {
                dst[j] = rgba[j].to_le_bytes();
            }
        } else {
            for (d, c) in dst.iter_mut().zip(&rgba).take(n) {
                *d = c.to_le_bytes();
            }
        }
    }
}
