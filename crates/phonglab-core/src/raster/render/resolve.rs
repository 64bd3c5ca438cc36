//! Stage 4: each covered pixel shaded once.
//!
//! The visibility buffer holds, per pixel, the rasterised triangle. The pixels of a row go
//! in runs of one triangle: its screen-space barycentrics `l` come from its edge functions
//! ([`ScreenBarycentrics`], exact), and its attributes are loaded once for the run.
//! Attributes vary linearly in clip space, not on the screen, so they are interpolated
//! perspective-correctly: `b_i = (l_i / w_i) / sum_j (l_j / w_j)`. Those are mapped back to
//! the original mesh triangle through its clipped vertices' barycentrics.
//!
//! - Gouraud: the vertices' colours (each clamped as OpenGL clamps vertex colours). The
//!   same interpolation written as planes: `c/w` and `1/w` are affine on the screen, so
//!   each is set up once per triangle ([`ColorPlanes`], f64, through a vertex) and stepped
//!   along a run in f32, and a pixel's colour is their quotient. Within a few f32 roundings
//!   of the exact value (tested: 7 channels in 1.5 million one level off the f64
//!   interpolation, as the barycentric blend had 6); 8 pixels' colours are 16 vector
//!   operations before the packing to bytes, where the blend took about 50 (counted in
//!   the source).
//! - Phong: position and normal, the normal renormalised, the lighting engine per pixel
//!   (in batches through the specialised evaluator).
//! - Flat: the face's colour; or, as the Phong demo's shader does, the pixel lit with
//!   `normalize(cross(dFdy(p), dFdx(p)))`. Within a triangle `p` is affine in the window
//!   coordinates, so that cross product is `-((b - a) x (c - a)) / A`, A the triangle's
//!   signed window area (y up): the face normal, negated on triangles counter-clockwise on
//!   the screen.
//!
//! Colours go to 8 bits as OpenGL converts them: `round(255 clamp(c, 0, 1))`.

use glam::Vec3;
use rayon::prelude::*;

use super::setup::{RasterTri, SUBPIXEL_BITS, Setup};
use super::vertices::Vertices;
use super::visibility::{ScreenBarycentrics, barycentric_steps};
use super::{Job, NO_TRIANGLE};
use crate::cpu::Portable;
use crate::model::view::ShadingMode;
use crate::specialise::lighter::{EyeArrays, Lighter};

/// Per-band buffers of Phong fragments, and each rasterised triangle's attributes at its
/// three (clipped) vertices, divided by w.
#[derive(Default)]
pub struct Scratch {
    bands: Vec<Fragments>,
    /// Gouraud: the colours of the triangle's side times 1/w, and 1/w, as screen planes.
    tri_color: Vec<ColorPlanes>,
    /// Phong and the demo's Flat: eye-space positions at the vertices, times 1/w.
    tri_pos: Vec<[Vec3; 3]>,
    /// Phong: (unnormalised) normals at the vertices, times 1/w.
    tri_nrm: Vec<[Vec3; 3]>,
    /// Each triangle's edge functions, set up once a frame rather than once a run.
    tri_edges: Vec<ScreenBarycentrics>,
}

/// The perspective-correct weights of a pixel with screen barycentrics `l` (of vertices 1
/// and 2) in a triangle whose vertices have `1/w = inv_w`: `b_k = l_k inv_w_k / sum_j l_j
/// inv_w_j`, returned as (`l_k`, `1 / sum`), so that an attribute stored as `a_k inv_w_k`
/// is `sum_k l_k (a_k inv_w_k) / sum_j l_j inv_w_j`.
#[inline(always)]
fn screen_weights(inv_w: [f32; 3], l: [f32; 2]) -> ([f32; 3], f32) {
    let ls = [1.0 - l[0] - l[1], l[0], l[1]];
    (ls, 1.0 / (ls[0] * inv_w[0] + ls[1] * inv_w[1] + ls[2] * inv_w[2]))
}

/// Each rasterised triangle's attributes at its three vertices, mapped from the original
/// triangle's through the clipped vertices' barycentrics and multiplied by 1/w, and (for
/// Phong and Flat) its edge functions; for Gouraud, its colour planes ([`ColorPlanes`]):
/// computed once per triangle, so a pixel blends three values (or steps planes) instead
/// of mapping its barycentrics back. One pass over chunks of triangles on both threads
/// (each result depends on its triangle alone).
/// `attributes` does one chunk (a copy of [`attributes_chunk_any`] for this processor).
fn triangle_attributes(setup: &Setup, scratch: &mut Scratch, attributes: impl Fn(&[RasterTri], Attributes<'_>) + Sync) {
    const GRAIN: usize = 256;
    // Every array sized to the triangles (growing only on the first frames); only those the
    // shading reads are written.
    let n = setup.tris.len();
    scratch.tri_color.resize(n, ColorPlanes::default());
    scratch.tri_pos.resize(n, [Vec3::ZERO; 3]);
    scratch.tri_nrm.resize(n, [Vec3::ZERO; 3]);
    scratch.tri_edges.resize(n, ScreenBarycentrics::default());
    setup
        .tris
        .par_chunks(GRAIN)
        .zip(scratch.tri_edges.par_chunks_mut(GRAIN))
        .zip(scratch.tri_color.par_chunks_mut(GRAIN))
        .zip(scratch.tri_pos.par_chunks_mut(GRAIN))
        .zip(scratch.tri_nrm.par_chunks_mut(GRAIN))
        .for_each(|((((ts, edges), colors), pos), nrm)| {
            attributes(ts, Attributes { edges, colors, pos, nrm });
        });
}

/// Where one chunk of triangles' attributes go ([`triangle_attributes`]).
pub(super) struct Attributes<'a> {
    pub(super) edges: &'a mut [ScreenBarycentrics],
    pub(super) colors: &'a mut [ColorPlanes],
    pub(super) pos: &'a mut [[Vec3; 3]],
    pub(super) nrm: &'a mut [[Vec3; 3]],
}

/// The attributes of triangles `ts` (a chunk) into `out`. (Written once,
/// `#[inline(always)]`; `copies` compiles it for each processor.)
#[inline(always)]
pub(super) fn attributes_chunk_any(job: &Job<'_>, verts: &Vertices, ts: &[RasterTri], out: Attributes<'_>) {
    let tris = &job.mesh.triangles;
    let two = job.scene.light_model.two_sided;
    let blend3 = |t: &RasterTri, a: &[Vec3]| -> [Vec3; 3] {
        let v = tris[t.orig as usize];
        let at = [a[v[0] as usize], a[v[1] as usize], a[v[2] as usize]];
        std::array::from_fn(|k| (at[0] * t.bary[k][0] + at[1] * t.bary[k][1] + at[2] * t.bary[k][2]) * t.inv_w[k])
    };
    let color = |t: &RasterTri| -> [[f32; 4]; 3] {
        let side = (t.back && two) as usize;
        let v = tris[t.orig as usize];
        let vc = &verts.color[side];
        let cs = [vc[v[0] as usize], vc[v[1] as usize], vc[v[2] as usize]];
        std::array::from_fn(|k| {
            let b = t.bary[k];
            std::array::from_fn(|ch| (cs[0][ch] * b[0] + cs[1][ch] * b[1] + cs[2][ch] * b[2]) * t.inv_w[k])
        })
    };
    let Attributes { edges, colors, pos, nrm } = out;
    for (i, t) in ts.iter().enumerate() {
        match job.mode {
            ShadingMode::Gouraud => colors[i] = ColorPlanes::new(t, color(t)),
            ShadingMode::Phong => {
                edges[i] = ScreenBarycentrics::new(t);
                (pos[i], nrm[i]) = (blend3(t, &verts.eye), blend3(t, &verts.normal));
            }
            ShadingMode::FlatDerivatives => {
                edges[i] = ScreenBarycentrics::new(t);
                pos[i] = blend3(t, &verts.eye);
            }
            // One colour a face, from setup: no attributes.
            ShadingMode::FlatFace => {}
        }
    }
}

/// One band's per-pixel fragments, presized to the band and written by index, and the runs
/// they came from (a list cleared for each band). Positions and normals are six arrays
/// (x, y, z of each), written a block of `LANES` at a time and read so by the lighting.
#[derive(Default)]
pub struct Fragments {
    runs: Vec<FragmentRun>,
    pos: [Vec<f32>; 3],
    nrm: [Vec<f32>; 3],
    front_out: Vec<[f32; 4]>,
    back_out: Vec<[f32; 4]>,
}

/// `len` fragments from index `first`, lit for the pixels from index `pixel` of the band
/// on (a run: consecutive pixels, consecutive fragments), on the back side or the front.
#[derive(Clone, Copy)]
struct FragmentRun {
    first: u32,
    pixel: u32,
    len: u32,
    back: bool,
}

impl Fragments {
    /// Room for `n` fragments and a block past them (a run's last block is stored whole),
    /// and no runs yet.
    fn size(&mut self, n: usize) {
        self.runs.clear();
        for a in self.pos.iter_mut().chain(&mut self.nrm) {
            a.resize(n + LANES, 0.0);
        }
    }

    /// Stores a block's channels (`v[c]`: channel c of its lanes) as fragments `at..at +
    /// LANES` of `to`, whole: lanes past the run land where the next run's fragments go.
    #[inline(always)]
    fn store(to: &mut [Vec<f32>; 3], at: usize, v: &[[f32; LANES]; 3]) {
        debug_assert!(to.iter().all(|a| at + LANES <= a.len()), "sized by Fragments::size");
        for (a, c) in to.iter_mut().zip(v) {
            if let Some(dst) = a.get_mut(at..).and_then(|d| d.first_chunk_mut::<LANES>()) {
                *dst = *c;
            }
        }
    }
}

#[inline(always)]
#[allow(clippy::manual_clamp)] // clamp keeps NaN; max/min turn it into 0, which the cast below needs
fn to_u8(c: f32) -> u8 {
    // max/min (IEEE maxNum/minNum) also turn NaN into 0, so v is in [0.5, 255.5].
    let v = c.max(0.0).min(1.0) * 255.0 + 0.5;
    // SAFETY: v is finite and within i32's range (see above); i32, not u32, because
    // processors convert f32 lanes to i32 in one instruction.
    unsafe { v.to_int_unchecked::<i32>() as u8 }
}

/// Eight pixels' channels (`ch[c][j]`: channel c of pixel j) as [`to_u8`] bytes, each
/// pixel's four as one little-endian u32, built in the lanes by shifts (bytes assembled in
/// memory would be stored in two halves and reloaded whole, which stalls).
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lanes index several arrays; the loop vectorises
pub(super) fn rgba8(ch: &[[f32; LANES]; 4]) -> [u32; LANES] {
    let mut rgba = [0u32; LANES];
    for j in 0..LANES {
        rgba[j] = to_u8(ch[0][j]) as u32
            | (to_u8(ch[1][j]) as u32) << 8
            | (to_u8(ch[2][j]) as u32) << 16
            | (to_u8(ch[3][j]) as u32) << 24;
    }
    rgba
}

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
        let mut planes = Self { origin: [t.x[0], t.y[0]], ..Self::default() };
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
    fn row(&self, px: usize, py: usize) -> ([f32; 5], [f32; 5]) {
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
fn gouraud_block(start: &[f32; 5], step: &[f32; 5], k0: usize) -> [[f32; LANES]; 4] {
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

/// Perspective-correct barycentrics of the original mesh triangle of raster triangle
/// `raster`, at the point whose screen barycentrics (of corners 1 and 2) are `l`.
#[inline(always)]
fn barycentrics(setup: &Setup, raster: u32, l: [f32; 2]) -> [f32; 3] {
    let t = &setup.tris[raster as usize];
    let ls = [1.0 - l[0] - l[1], l[0], l[1]];
    let p = [ls[0] * t.inv_w[0], ls[1] * t.inv_w[1], ls[2] * t.inv_w[2]];
    let s = 1.0 / (p[0] + p[1] + p[2]);
    let b = [p[0] * s, p[1] * s, p[2] * s];
    let mut out = [0.0f32; 3];
    for (k, bk) in b.iter().enumerate() {
        for (j, o) in out.iter_mut().enumerate() {
            *o += bk * t.bary[k][j];
        }
    }
    out
}

/// The original triangle's barycentrics at pixel (`x`, `y`) of the last frame, where the
/// rasterised triangle `r` shows (for picking).
pub(crate) fn original_barycentrics(setup: &Setup, r: u32, x: usize, y: usize) -> Option<[f32; 3]> {
    let t = setup.tris.get(r as usize)?;
    let l = ScreenBarycentrics::new(t).at(x, y);
    Some(barycentrics(setup, r, l))
}

/// What every band's resolve shares, computed once per frame (`prepare`).
pub struct Prepared {
    bg: [u8; 4],
    two: bool,
    per_pixel: bool,
    /// Flat: each face's colour in 8 bits, per side.
    face8: [Vec<[u8; 4]>; 2],
}

/// The frame's shared resolve state; fills the per-triangle attributes in `scratch`, a
/// chunk at a time through `attributes` (a copy of [`attributes_chunk_any`]).
pub(super) fn prepare(
    job: &Job<'_>,
    setup: &Setup,
    scratch: &mut Scratch,
    bands: usize,
    attributes: impl Fn(&[RasterTri], Attributes<'_>) + Sync,
) -> Prepared {
    let bg = job.background.map(to_u8);
    // Shadings that light each pixel: Phong, and Flat with the demo's derivative normals.
    let per_pixel = job.mode.per_fragment();
    scratch.bands.resize_with(bands, Fragments::default);
    if job.mode != ShadingMode::FlatFace {
        triangle_attributes(setup, scratch, attributes);
    }
    // Flat: each face's colour converted to 8 bits once.
    let face8: [Vec<[u8; 4]>; 2] = if job.mode == ShadingMode::FlatFace {
        [0, 1].map(|side| setup.face_color[side].iter().map(|c| c.map(to_u8)).collect())
    } else {
        [Vec::new(), Vec::new()]
    };
    Prepared { bg: [bg[0], bg[1], bg[2], 255], two: job.scene.light_model.two_sided, per_pixel, face8 }
}

/// The per-triangle attributes and the per-band fragment buffers, split so that each band
/// borrows its own fragments while all share the attributes.
pub fn split(scratch: &mut Scratch) -> (Shared<'_>, &mut [Fragments]) {
    let shared = Shared {
        tri_color: &scratch.tri_color,
        tri_pos: &scratch.tri_pos,
        tri_nrm: &scratch.tri_nrm,
        tri_edges: &scratch.tri_edges,
    };
    (shared, &mut scratch.bands)
}

/// The per-triangle attributes, read by every band.
pub struct Shared<'a> {
    tri_color: &'a [ColorPlanes],
    tri_pos: &'a [[Vec3; 3]],
    tri_nrm: &'a [[Vec3; 3]],
    tri_edges: &'a [ScreenBarycentrics],
}

/// How many entries at the start of `row` (not empty) equal its first: eight compared at
/// a time (`lanes.differ8` and a bit scan), the rest one by one.
#[inline(always)]
fn run_length(lanes: impl ResolveLanes, row: &[u32]) -> usize {
    let r = row[0];
    let mut n = 1;
    while let Some(block) = row.get(n..).and_then(|s| s.first_chunk::<8>()) {
        let differ = lanes.differ8(block, r);
        if differ != 0 {
            return n + differ.trailing_zeros() as usize;
        }
        n += 8;
    }
    n + row[n..].iter().position(|&q| q != r).unwrap_or(row.len() - n)
}

/// How blocks of [`LANES`] pixels are packed to bytes and compared: the portable loops
/// ([`Portable`]), or a copy's own instructions for the same operations (the AVX2 ones are
/// in `copies`, for the proof of AVX2). The resolve is written once, generic over it.
pub(super) trait ResolveLanes: Copy {
    /// [`rgba8`]'s bytes.
    fn rgba8(self, ch: &[[f32; LANES]; 4]) -> [u32; LANES];
    /// One bit per entry of `block` that differs from `r`.
    fn differ8(self, block: &[u32; 8], r: u32) -> u32;
}

impl ResolveLanes for Portable {
    #[inline(always)]
    fn rgba8(self, ch: &[[f32; LANES]; 4]) -> [u32; LANES] {
        rgba8(ch)
    }

    #[inline(always)]
    fn differ8(self, block: &[u32; 8], r: u32) -> u32 {
        (0..8).fold(0u32, |m, j| m | (((block[j] != r) as u32) << j))
    }
}

/// Sets every pixel of `px` to `c`, eight at a time (32-byte stores; a plain `fill` of
/// 4-byte arrays stored them one by one).
#[inline(always)]
fn fill_px(px: &mut [[u8; 4]], c: [u8; 4]) {
    let (blocks, rest) = px.as_chunks_mut::<8>();
    for b in blocks {
        *b = [c; 8];
    }
    rest.fill(c);
}

/// A run of pixels of one triangle in one row: `len` pixels from (`x`, `y`) of the image,
/// the first at index `at` of the band.
#[derive(Clone, Copy)]
struct Run {
    x: usize,
    y: usize,
    at: usize,
    len: usize,
}

/// Pixels of a run shaded together: eight f32 lanes, one AVX2 register.
pub(super) const LANES: usize = 8;

/// The perspective weights of [`LANES`] pixels of a run, [`screen_weights`] lane by lane:
/// `ls[k][j]` the screen barycentric of vertex k at lane j, `s[j]` one over their sum
/// weighted by 1/w.
struct Weights {
    ls: [[f32; LANES]; 3],
    s: [f32; LANES],
}

impl Run {
    /// The weights of pixels `k0..k0 + LANES` of the run (lanes past its end are computed
    /// and ignored). Each screen barycentric is the exact edge function (f64) times
    /// 1/area, rounded once to f32; then [`screen_weights`]' arithmetic, in its order.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lanes index several arrays; the loop vectorises
    fn weights(&self, edges: &([f64; 2], [f64; 2], f64), inv_w: [f32; 3], k0: usize) -> Weights {
        let (w, step, inv_area) = *edges;
        // Coordinate by coordinate, lanes side by side (computing both of a lane's
        // coordinates together made the compiler shuffle them apart again).
        let mut l = [[0.0f32; LANES]; 2];
        for c in 0..2 {
            for j in 0..LANES {
                // i32 to f64 is one instruction for four lanes; k0 + j is below the image width.
                let kf = (k0 as i32 + j as i32) as f64;
                l[c][j] = ((w[c] + step[c] * kf) * inv_area) as f32;
            }
        }
        let mut out = Weights { ls: [[0.0; LANES]; 3], s: [0.0; LANES] };
        for j in 0..LANES {
            let (ls, s) = screen_weights(inv_w, [l[0][j], l[1][j]]);
            for k in 0..3 {
                out.ls[k][j] = ls[k];
            }
            out.s[j] = s;
        }
        out
    }

    /// The run's pixels in blocks of [`LANES`]: `(k0, n)`, the block's first pixel and how
    /// many of its lanes are in the run.
    #[inline(always)]
    fn blocks(&self) -> impl Iterator<Item = (usize, usize)> {
        let len = self.len;
        (0..len).step_by(LANES).map(move |k0| (k0, (len - k0).min(LANES)))
    }
}

/// `sum_k ls_k a_k`, times `s`, lane by lane: an attribute stored per vertex as `a_k / w_k`,
/// interpolated perspective-correctly.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lanes index several arrays; the loop vectorises
fn blend(wt: &Weights, a: [f32; 3]) -> [f32; LANES] {
    // Plain loops, not array::from_fn: its closure is not always inlined, and then the
    // lanes go through memory.
    let mut out = [0.0; LANES];
    for j in 0..LANES {
        out[j] = (a[0] * wt.ls[0][j] + a[1] * wt.ls[1][j] + a[2] * wt.ls[2][j]) * wt.s[j];
    }
    out
}

/// A triangle's three vectors as arrays, for [`blend_n`].
#[inline(always)]
fn xyz(v: &[Vec3; 3]) -> [[f32; 3]; 3] {
    [v[0].to_array(), v[1].to_array(), v[2].to_array()]
}

/// [`blend`] for each of `N` channels, `a[k][c]` channel c at vertex k.
#[inline(always)]
fn blend_n<const N: usize>(wt: &Weights, a: &[[f32; N]; 3]) -> [[f32; LANES]; N] {
    let mut out = [[0.0; LANES]; N];
    for c in 0..N {
        out[c] = blend(wt, [a[0][c], a[1][c], a[2][c]]);
    }
    out
}

/// What shading one band reads: the frame's job, triangles (`setup`), lighting plan and
/// prepared attributes, and the band's own visibility buffer `raster`, whose first row is
/// row `y0` of an image `width` pixels wide.
#[derive(Clone, Copy)]
pub struct BandInput<'a> {
    /// The frame's job.
    pub job: &'a Job<'a>,
    /// The frame's rasterised triangles.
    pub setup: &'a Setup,
    /// The specialised lighting, for per-pixel shading.
    pub lighter: &'a Lighter,
    /// What `prepare` set up for the frame.
    pub p: &'a Prepared,
    /// The per-triangle attributes ([`split`]).
    pub shared: &'a Shared<'a>,
    /// The band's visibility buffer: the rasterised triangle at each pixel.
    pub raster: &'a [u32],
    /// The image row of the band's first row.
    pub y0: usize,
    /// The image's width.
    pub width: usize,
}

/// One band's pixels: runs of one triangle shaded, Phong's fragments lit; `lanes` packs
/// and compares blocks of pixels ([`ResolveLanes`]). (Written once, `#[inline(always)]`;
/// `copies` compiles it for each processor.)
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lane loops: see `blend`
pub(super) fn resolve_band_any<L: ResolveLanes>(
    lanes: L,
    band: &BandInput<'_>,
    px: &mut [[u8; 4]],
    frags: &mut Fragments,
) -> Shaded {
    let BandInput { job, setup, lighter, p, shared, raster, y0, width } = *band;
    let (two, per_pixel, bg) = (p.two, p.per_pixel, p.bg);
    let (tri_color, tri_pos, tri_nrm) = (shared.tri_color, shared.tri_pos, shared.tri_nrm);
    if per_pixel {
        frags.size(px.len());
    }
    // Fragments written so far, pixels covered.
    let (mut m, mut covered) = (0, 0);
    // Fragments lit in the batches before this one.
    let mut lit = 0;
    for (row, r_row) in raster.chunks(width).enumerate() {
        let px_row = &mut px[row * width..row * width + r_row.len()];
        let mut x = 0;
        while x < r_row.len() {
            let r = r_row[x];
            let len = run_length(lanes, &r_row[x..]);
            let run = Run { x, y: y0 + row, at: row * width + x, len };
            x += len;
            if r == NO_TRIANGLE {
                fill_px(&mut px_row[run.x..run.x + len], bg);
                continue;
            }
            covered += len;
            let t = &setup.tris[r as usize];
            let side = (t.back && two) as usize;
            let r = r as usize;
            match job.mode {
                ShadingMode::FlatFace => fill_px(&mut px_row[run.x..run.x + len], p.face8[side][t.orig as usize]),
                ShadingMode::Gouraud => gouraud_run(lanes, &tri_color[r], &run, px_row),
                ShadingMode::Phong => {
                    let edges = shared.tri_edges[r].row(run.x, run.y);
                    let (pw, nw) = (&tri_pos[r], &tri_nrm[r]);
                    for (k0, _) in run.blocks() {
                        let wt = run.weights(&edges, t.inv_w, k0);
                        Fragments::store(&mut frags.pos, m + k0, &blend_n(&wt, &xyz(pw)));
                        Fragments::store(&mut frags.nrm, m + k0, &blend_n(&wt, &xyz(nw)));
                    }
                    m = run.fragments(frags, m, side == 1);
                }
                ShadingMode::FlatDerivatives => {
                    // The demo's Flat: the face normal, from the screen derivatives.
                    // `back`: clockwise on the screen (y up), where cross(dFdy, dFdx) is the face normal.
                    let n = setup.face_normal[t.orig as usize];
                    let face = if t.back { n } else { -n };
                    let edges = shared.tri_edges[r].row(run.x, run.y);
                    flat_fragments(&run, &edges, t.inv_w, &tri_pos[r], face, frags, m);
                    m = run.fragments(frags, m, side == 1);
                }
            }
        }
        // Light the fragments of the rows so far once there are enough of them, while they
        // are still in the core's nearest caches.
        if per_pixel && m >= BATCH {
            light_fragments(job.mode, lighter, two, frags, m, px);
            (lit, m) = (lit + m, 0);
        }
    }
    if per_pixel && m > 0 {
        light_fragments(job.mode, lighter, two, frags, m, px);
        lit += m;
    }
    Shaded { covered, lit }
}

/// A run of one triangle under Gouraud shading: its colour planes evaluated a block of
/// [`LANES`] pixels at a time, packed to bytes, into the run's pixels of `px_row`.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lane loops: see `blend`
fn gouraud_run(lanes: impl ResolveLanes, planes: &ColorPlanes, run: &Run, px_row: &mut [[u8; 4]]) {
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

/// A run's fragments for the demo's Flat shading, from fragment `m` on: each pixel's
/// eye-space position interpolated, and one normal, the face's.
#[inline(always)]
fn flat_fragments(
    run: &Run,
    edges: &([f64; 2], [f64; 2], f64),
    inv_w: [f32; 3],
    pos: &[Vec3; 3],
    face: Vec3,
    frags: &mut Fragments,
    m: usize,
) {
    let face = [[face.x; LANES], [face.y; LANES], [face.z; LANES]];
    for (k0, _) in run.blocks() {
        let wt = run.weights(edges, inv_w, k0);
        Fragments::store(&mut frags.pos, m + k0, &blend_n(&wt, &xyz(pos)));
        Fragments::store(&mut frags.nrm, m + k0, &face);
    }
}

/// Fragments lit in one batch, at least (whole rows are gathered first): enough for the
/// lighting's chunks ([`CHUNK`](crate::specialise::lighter::CHUNK), 64) to run full, few enough
/// that the fragments, their colours and their pixels stay in the core's nearest caches (a
/// whole band's, at 1024², did not).
const BATCH: usize = 1024;

/// Lights fragments `..m` of `frags` and writes their colours to their pixels of `px`
/// (the band's); then clears the runs, for the next batch.
#[inline(always)]
fn light_fragments(
    mode: ShadingMode,
    lighter: &Lighter,
    two: bool,
    frags: &mut Fragments,
    m: usize,
    px: &mut [[u8; 4]],
) {
    frags.front_out.resize(m.max(frags.front_out.len()), [0.0; 4]);
    frags.back_out.resize(m.max(frags.back_out.len()), [0.0; 4]);
    let back_out = if two { Some(&mut frags.back_out[..m]) } else { None };
    let arrays = EyeArrays { pos: frags.pos.each_ref().map(|a| &a[..m]), nrm: frags.nrm.each_ref().map(|a| &a[..m]) };
    // Phong's interpolated normals are renormalised inside (in vectorised chunks); the
    // Flat face normals are unit already.
    lighter.light_arrays_eye_sum(arrays, mode == ShadingMode::Phong, &mut frags.front_out[..m], back_out);
    // Run by run: consecutive fragments to consecutive pixels, channel by channel (a
    // loop the compiler vectorises).
    for run in &frags.runs {
        let out = if run.back { &frags.back_out } else { &frags.front_out };
        let (first, pixel, len) = (run.first as usize, run.pixel as usize, run.len as usize);
        let src = out[first..first + len].as_flattened();
        let dst = px[pixel..pixel + len].as_flattened_mut();
        for (d, &c) in dst.iter_mut().zip(src) {
            *d = to_u8(c);
        }
    }
    frags.runs.clear();
}

/// What a band's resolve did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Shaded {
    /// Pixels covered by the mesh.
    pub covered: usize,
    /// Fragments lit (per-pixel shading), each one lighting evaluation.
    pub lit: usize,
}

impl Run {
    /// Records the run's pixels, and their side, as fragments `m..m + len` (their positions
    /// and normals already written); returns the fragments written after it.
    #[inline(always)]
    fn fragments(&self, frags: &mut Fragments, m: usize, back: bool) -> usize {
        frags.runs.push(FragmentRun { first: m as u32, pixel: self.at as u32, len: self.len as u32, back });
        m + self.len
    }
}

/// The lighting evaluations a frame made in the resolve stage, given the fragments lit.
pub fn evaluations(job: &Job<'_>, fragments: usize) -> usize {
    match job.mode {
        ShadingMode::Phong | ShadingMode::FlatDerivatives => fragments,
        ShadingMode::FlatFace => job.mesh.triangles.len(),
        ShadingMode::Gouraud => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::super::setup::RasterTri;
    use super::*;

    /// Runs are found whole: the length of the first run of every suffix of rows with
    /// runs of every length from 1 to 40 (across the eight-wide blocks and into the tail).
    #[test]
    fn run_length_is_the_first_run() {
        let mut next = crate::test_support::xorshift(0x853c49e6748fea9b);
        for _ in 0..2_000 {
            let mut row = Vec::new();
            while row.len() < 100 {
                let seed = next();
                let len = 1 + (seed % 40) as usize;
                let value = if seed.is_multiple_of(3) { NO_TRIANGLE } else { (seed >> 20) as u32 % 5 };
                row.extend(std::iter::repeat_n(value, len));
            }
            for start in 0..row.len() {
                let s = &row[start..];
                let naive = s.iter().position(|&q| q != s[0]).unwrap_or(s.len());
                assert_eq!(run_length(Portable, s), naive, "{s:?}");
                if let Some(avx2) = crate::cpu::Avx2::detect() {
                    assert_eq!(run_length(avx2, s), naive, "{s:?}");
                }
            }
        }
    }

    /// The AVX2 packing gives [`to_u8`]'s bytes for every kind of channel value: NaN,
    /// infinities, huge and tiny, negative, just around each rounding boundary, and random.
    #[test]
    fn avx2_bytes_are_the_portable_bytes() {
        if let Some(avx2) = crate::cpu::Avx2::detect() {
            let mut values = vec![
                f32::NAN,
                -f32::NAN,
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::MAX,
                f32::MIN,
                3e9,
                -3e9,
                1e-40,
                -1e-40,
                0.0,
                -0.0,
                1.0,
                -1.0,
                -0.5,
                1.5,
            ];
            // Each boundary between two bytes, and the floats next to it.
            for b in 0..=256 {
                let x = (b as f32 - 0.5) / 255.0;
                values.extend([x, x.next_up(), x.next_down(), x.next_up().next_up()]);
            }
            let mut next = crate::test_support::xorshift(0x9e3779b97f4a7c15);
            values.extend((0..4000).map(|_| f32::from_bits(next() as u32)));
            values.extend((0..4000).map(|_| (next() % 3_000_000) as f32 / 1e6 - 1.0));
            for block in values.chunks(4 * LANES) {
                let mut ch = [[0.0; LANES]; 4];
                for (i, &v) in block.iter().enumerate() {
                    ch[i % 4][i / 4] = v;
                }
                assert_eq!(avx2.rgba8(&ch), rgba8(&ch), "{ch:?}");
            }
        }
    }

    /// The weights of a block are [`screen_weights`] of the exact barycentrics, lane by
    /// lane, and lane j is pixel k0 + j of the run.
    #[test]
    fn block_weights_are_the_pixels_weights() {
        let t = RasterTri {
            x: [3 << 8, 90 << 8, 20 << 8],
            y: [2 << 8, 10 << 8, 33 << 8],
            inv_w: [0.5, 0.25, 0.8],
            x0: 3,
            x1: 89,
            y0: 2,
            y1: 32,
            ..RasterTri::default()
        };
        let sb = ScreenBarycentrics::new(&t);
        let run = Run { x: 12, y: 9, at: 0, len: 30 };
        let edges = sb.row(run.x, run.y);
        for (k0, n) in run.blocks() {
            assert_eq!(n, (30 - k0).min(LANES));
            let wt = run.weights(&edges, t.inv_w, k0);
            for j in 0..n {
                let (ls, s) = screen_weights(t.inv_w, sb.at(run.x + k0 + j, run.y));
                assert_eq!(
                    [wt.ls[0][j], wt.ls[1][j], wt.ls[2][j], wt.s[j]],
                    [ls[0], ls[1], ls[2], s],
                    "pixel {}",
                    k0 + j
                );
            }
        }
        assert_eq!(run.blocks().count(), 4);
    }
}
