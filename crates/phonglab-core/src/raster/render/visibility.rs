//! Stage 3: triangles into the visibility buffer.
//!
//! Edge functions in fixed point (8 sub-pixel bits), evaluated at pixel centres, with the
//! top-left rule: a centre exactly on an edge belongs to the triangle only if that edge
//! is a top edge (horizontal, interior below) or a left edge (interior to its right), so
//! two triangles sharing an edge never both draw, nor both miss, a pixel on it. The image
//! is cut into bands of rows; each band is drawn by one thread with the triangles that
//! touch it, so threads never write the same pixel.
//!
//! The buffer holds only what the depth test needs and what identifies the surface: the
//! depth and the triangle of each pixel (a visibility buffer). The resolve stage gets the
//! barycentrics back from the triangle's edge functions ([`ScreenBarycentrics`]), exactly,
//! so the raster writes 8 bytes a pixel instead of 16.
//!
//! Each row of a triangle is an exact integer span (no pixel tested outside it), filled in
//! blocks of [`LANES`] pixels: depth and the depth test for the whole block at once, the
//! pixels outside the span masked off. On a processor with AVX2 the bands run a copy of
//! this code compiled for it, so a block is one register; the arithmetic (same operations,
//! same order, no fused multiply-adds) gives the same bits either way.

use super::setup::{GRAIN, RasterTri, SUBPIXEL_BITS, Setup};
use super::{Image, NO_TRIANGLE};
use crate::cpu::Portable;
use crate::numerics::copies::prefetch;

/// How a row's span of pixels is filled: the portable loop ([`Portable`]), or a copy's own
/// instructions for the same operations (the AVX2 one is in `copies`, for the proof of
/// AVX2). The raster is written once, generic over it.
pub(super) trait SpanFill: Copy {
    /// Fills pixels `at..at + n` of `band` with triangle `ti` where it passes the depth test.
    fn fill_span(self, ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, n: usize);
}

impl SpanFill for Portable {
    #[inline(always)]
    fn fill_span(self, ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, n: usize) {
        fill_span(ti, plane, band, at, n);
    }
}

/// Rows per band.
pub const BAND: usize = 16;

/// How many triangles ahead in a bin [`draw_band_any`] asks for a triangle's memory.
const PREFETCH_AHEAD: usize = 8;

/// `E(a, b, p) = (b - a) x (p - a)`: positive when p is inside a positively oriented triangle.
#[inline(always)]
fn edge(ax: i64, ay: i64, bx: i64, by: i64, px: i64, py: i64) -> i64 {
    (bx - ax) * (py - ay) - (by - ay) * (px - ax)
}

/// `f(a, b)` for the triangle's three edges a -> b, 1 -> 2, 2 -> 0 and 0 -> 1 (the edge
/// opposite vertex 0 first), written out: `array::map` was left as a call, once per
/// triangle and band.
#[inline(always)]
fn per_edge<T>(mut f: impl FnMut(usize, usize) -> T) -> [T; 3] {
    [f(1, 2), f(2, 0), f(0, 1)]
}

/// 0 for a top or left edge (a centre on it is inside), -1 otherwise.
#[inline(always)]
fn bias(ax: i64, ay: i64, bx: i64, by: i64) -> i64 {
    let (dx, dy) = (bx - ax, by - ay);
    if (dy == 0 && dx > 0) || dy < 0 { 0 } else { -1 }
}

/// Sizes `image` to width x height and sorts the triangles of `setup` into the bands of
/// rows they touch.
pub fn bin(setup: &Setup, width: usize, height: usize, image: &mut Image, bins: &mut Vec<Vec<u32>>) {
    image.width = width;
    image.height = height;
    image.rgba.resize(width * height * 4, 0);

    let bands = height.div_ceil(BAND);
    // The bands' bins, then as many for the back faces (kept from frame to frame too; a
    // band's bin is `bins[band]`, the rest is scratch).
    bins.resize_with(2 * bands, Vec::new);
    for b in bins.iter_mut() {
        b.clear();
    }
    // Front faces first: a closed surface's back faces then mostly fail the depth test and
    // write nothing (the image is the same; only exact depth ties could differ). One pass
    // over the triangles (each is 76 bytes: a million are read once, not twice), the back
    // faces into bins of their own, put after the front faces' band by band. In the mesh's
    // order: each mesh triangle's slot, then its further pieces if clipping cut it.
    let (front, back) = bins.split_at_mut(bands);
    let mut put = |i: usize| {
        let t = &setup.tris[i];
        let side = if t.back { &mut *back } else { &mut *front };
        for bin in &mut side[t.y0 as usize / BAND..=t.y1 as usize / BAND] {
            bin.push(i as u32);
        }
    };
    let slots = setup.slots();
    for k in 0..slots.div_ceil(GRAIN) {
        let mut pieces = setup.extra.get(k).cloned().unwrap_or(0..0).map(|p| p as usize).peekable();
        for i in k * GRAIN..(k * GRAIN + GRAIN).min(slots) {
            if !setup.tris[i].is_hole() {
                put(i);
            }
            while let Some(p) = pieces.next_if(|&p| setup.tris[p].orig as usize == i) {
                put(p);
            }
        }
    }
    for (f, b) in front.iter_mut().zip(back.iter()) {
        f.extend_from_slice(b);
    }
}

std::thread_local! {
    /// Each thread's visibility buffer (depths, triangles) for the band it is drawing.
    static BAND_BUFFER: std::cell::RefCell<(Vec<f32>, Vec<u32>)> = const { std::cell::RefCell::new((Vec::new(), Vec::new())) };
}

/// Runs `f` on a visibility buffer of `n` pixels (depths and triangles, contents left
/// over): the calling thread's own, kept from band to band and frame to frame, so that a
/// band is drawn and shaded in memory that stays in the core's cache, and the frame's
/// visibility never goes out to main memory. (A fresh buffer if the thread's is in use.)
///
/// Both arrays start on a cache line, so that the raster's blocks of [`LANES`] pixels
/// (32 bytes, at multiples of [`LANES`] in the band) never straddle two lines. The
/// allocator only promises 16 bytes; a block across a line boundary costs two accesses.
pub fn with_band_buffer<R>(n: usize, f: impl FnOnce(&mut [f32], &mut [u32]) -> R) -> R {
    BAND_BUFFER.with(|cell| match cell.try_borrow_mut() {
        Ok(mut buffer) => {
            let (depth, raster) = &mut *buffer;
            f(line_aligned(depth, n, 1.0), line_aligned(raster, n, NO_TRIANGLE))
        }
        Err(_) => f(line_aligned(&mut Vec::new(), n, 1.0), line_aligned(&mut Vec::new(), n, NO_TRIANGLE)),
    })
}

/// `n` entries of `v` starting on a 64-byte boundary (`v` grown with `fill` as needed).
fn line_aligned<T: Copy>(v: &mut Vec<T>, n: usize, fill: T) -> &mut [T] {
    const LINE: usize = 64;
    let room = n + LINE / size_of::<T>();
    if v.len() < room {
        v.resize(room, fill);
    }
    // Within `LINE / size_of::<T>()` entries of the start (T is 4 bytes here, and the
    // allocation at least 4-aligned); `min` keeps a slice in range whatever it returns.
    let skip = v.as_ptr().align_offset(LINE).min(room - n);
    &mut v[skip..skip + n]
}

/// One band of the visibility buffer: rows `y_start..` of the image, `width` pixels each.
pub struct Band<'a> {
    /// The image row of the band's first row.
    pub y_start: i32,
    /// The image's width.
    pub width: usize,
    /// The band's depths.
    pub depth: &'a mut [f32],
    /// The band's triangles.
    pub raster: &'a mut [u32],
}

/// Clears a band and draws the triangles `bin` of `setup` into it (front faces first);
/// returns the number of back faces skipped as hidden whole. `lanes` fills each row's span
/// ([`SpanFill`]).
///
/// The front faces are drawn first ([`bin`] puts them first). Before the back faces, the
/// band's farthest depth in each column tile is noted ([`Tiles`]), and a back face whose
/// nearest vertex is behind the farthest depth of every tile it touches is skipped whole:
/// no pixel of it could pass the depth test (a hierarchical depth test, as GPUs make).
/// Back faces only ever bring depths nearer, so the noted depths stay an upper bound.
#[inline(always)]
pub(super) fn draw_band_any<L: SpanFill>(lanes: L, setup: &Setup, bin: &[u32], mut band: Band<'_>) -> usize {
    band.depth.fill(1.0);
    band.raster.fill(NO_TRIANGLE);
    let front = bin.partition_point(|&ti| !setup.tris[ti as usize].back);
    // Each triangle's memory asked for some triangles ahead: a band's triangles are a
    // sparse walk through the frame's array, which the processor does not foresee, and
    // the first read of each was most of the drawing's time on a million triangles.
    let ahead = |i: usize| {
        if let Some(&tj) = bin.get(i + PREFETCH_AHEAD) {
            prefetch(std::slice::from_ref(&setup.tris[tj as usize]));
        }
    };
    for (i, &ti) in bin[..front].iter().enumerate() {
        ahead(i);
        draw(lanes, &setup.tris[ti as usize], ti, &mut band);
    }
    if front == bin.len() {
        return 0;
    }
    let tiles = Tiles::farthest(&band);
    let mut hidden = 0;
    for (i, &ti) in bin.iter().enumerate().skip(front) {
        ahead(i);
        let t = &setup.tris[ti as usize];
        if tiles.hides(t) {
            hidden += 1;
        } else {
            draw(lanes, t, ti, &mut band);
        }
    }
    hidden
}

/// The farthest depth in each column tile of a band (a tile: [`Tiles::width`] columns,
/// all the band's rows), for the hierarchical depth test of [`draw_band_any`].
struct Tiles {
    /// Columns per tile: a multiple of [`LANES`], so that at most [`MAX_TILES`] span the row.
    width: usize,
    /// Each tile's farthest depth.
    farthest: [f32; MAX_TILES],
}

/// Tiles in a band at most (no allocation: the array is on the stack).
const MAX_TILES: usize = 256;

/// Columns whose farthest depths [`Tiles::farthest`] gathers at once, on the stack.
const SEGMENT: usize = 2048;

/// How far below its vertices' depths a triangle's interpolated depth can fall by rounding,
/// with a wide margin. At a covered pixel the exact barycentrics are in [0, 1] (the
/// coverage test is exact), the f32 ones are off by a few units in the last place, and so
/// is the depth interpolated from them: about 2^-20 at most for depths in [-1, 1], against
/// the 2^-12 allowed here.
const DEPTH_ROUNDING_MARGIN: f32 = 1.0 / 4096.0;

impl Tiles {
    /// The tiles of `band` as it stands: each column's farthest depth down the band, a
    /// segment of columns at a time (a loop over whole rows, which vectorises), then each
    /// tile's farthest column.
    fn farthest(band: &Band<'_>) -> Self {
        // Compares rather than f32::max, so that the loops vectorise. (The buffer never
        // holds a NaN: a NaN depth fails the test that writes it.)
        let max = |m: f32, z: f32| if z > m { z } else { m };
        let width = band.width.div_ceil(MAX_TILES).next_multiple_of(LANES);
        let mut farthest = [f32::NEG_INFINITY; MAX_TILES];
        let mut column = [f32::NEG_INFINITY; SEGMENT];
        // Whole tiles per segment (a tile wider than a segment is one segment).
        let segment = (SEGMENT / width * width).max(width);
        for x0 in (0..band.width).step_by(segment) {
            let n = segment.min(band.width - x0);
            let mut far_columns = |col: &mut [f32]| {
                col.fill(f32::NEG_INFINITY);
                for row in band.depth.chunks_exact(band.width) {
                    for (c, &z) in col.iter_mut().zip(&row[x0..x0 + n]) {
                        *c = max(*c, z);
                    }
                }
                for (tile, far) in col.chunks(width).zip(&mut farthest[x0 / width..]) {
                    *far = tile.iter().fold(f32::NEG_INFINITY, |m, &z| max(m, z));
                }
            };
            match column.get_mut(..n) {
                Some(col) => far_columns(col),
                None => far_columns(&mut vec![0.0; n]),
            }
        }
        Self { width, farthest }
    }

    /// Could no pixel of `t` pass the depth test? (Its nearest vertex, less the rounding
    /// margin, is at or behind the farthest depth of every tile its bounding box touches;
    /// the test is strict, so a pixel at the same depth fails it.)
    fn hides(&self, t: &RasterTri) -> bool {
        let nearest = t.z[0].min(t.z[1]).min(t.z[2]) - DEPTH_ROUNDING_MARGIN;
        let tiles = &self.farthest[t.x0.max(0) as usize / self.width..=t.x1.max(0) as usize / self.width];
        tiles.iter().all(|&far| nearest >= far)
    }
}

/// The first and last x (in pixels from `px0`) where `w + bias >= 0`, for `w(k) = w0 + step k`:
/// a lower bound when the function grows along the row, an upper one when it falls.
#[inline(always)]
fn span(w0: i64, step: i64, bias: i64, lo: &mut i64, hi: &mut i64) {
    let w = w0 + bias;
    if step > 0 {
        // k >= ceil(-w / step)
        let k = if w >= 0 { 0 } else { (-w + step - 1) / step };
        *lo = (*lo).max(k);
    } else if step < 0 {
        // k <= floor(w / -step)
        if w < 0 {
            *hi = -1;
        } else {
            *hi = (*hi).min(w / -step);
        }
    } else if w < 0 {
        *hi = -1;
    }
}

/// Pixels tested at once: eight f32 lanes, one AVX2 register.
pub const LANES: usize = 8;

/// A triangle's screen-space barycentrics (of vertices 1 and 2) and depth along a row:
/// at the span's first pixel, and their steps per pixel. (The depth is interpolated from
/// barycentrics stepped in f32, as it always was here; the resolve's barycentrics are
/// exact, [`ScreenBarycentrics`].)
#[derive(Clone, Copy)]
pub(super) struct RowPlane {
    pub(super) l1: f32,
    pub(super) l2: f32,
    pub(super) step1: f32,
    pub(super) step2: f32,
    pub(super) z0: f32,
    pub(super) dz1: f32,
    pub(super) dz2: f32,
}

/// Depth-tests the `n` pixels starting at index `at` of the band against the triangle
/// `ti`, writing depth and triangle where it passes (strictly nearer).
#[inline(always)]
fn fill_span(ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, n: usize) {
    let RowPlane { l1: l1_0, l2: l2_0, step1, step2, z0, dz1, dz2 } = plane;
    let mut base = 0;
    while base < n {
        let i = at + base;
        let blocks = (
            band.depth.get_mut(i..).and_then(|s| s.first_chunk_mut::<LANES>()),
            band.raster.get_mut(i..).and_then(|s| s.first_chunk_mut::<LANES>()),
        );
        let (Some(d), Some(r)) = blocks else {
            // The band's last pixels: one at a time.
            for k in base..n {
                fill_one(ti, plane, band, at, k);
            }
            return;
        };
        // A whole block, the lanes past the span's end masked off (they keep their values:
        // the band is this thread's alone, so rewriting them is harmless).
        let left = n - base;
        for j in 0..LANES {
            let kf = (base + j) as f32;
            let (l1, l2) = (l1_0 + step1 * kf, l2_0 + step2 * kf);
            let z = z0 + dz1 * l1 + dz2 * l2;
            let pass = (j < left) & (z < d[j]);
            d[j] = if pass { z } else { d[j] };
            r[j] = if pass { ti } else { r[j] };
        }
        base += LANES;
    }
}

/// Pixel `k` of the span starting at `at`: [`fill_span`]'s arithmetic for one pixel.
#[inline(always)]
pub(super) fn fill_one(ti: u32, plane: RowPlane, band: &mut Band<'_>, at: usize, k: usize) {
    let RowPlane { l1: l1_0, l2: l2_0, step1, step2, z0, dz1, dz2 } = plane;
    let kf = k as f32;
    let (l1, l2) = (l1_0 + step1 * kf, l2_0 + step2 * kf);
    let z = z0 + dz1 * l1 + dz2 * l2;
    let i = at + k;
    if z < band.depth[i] {
        band.depth[i] = z;
        band.raster[i] = ti;
    }
}

/// Draws triangle `ti` into the band: by [`draw_small`] if its box holds at most two
/// columns and two rows of pixel centres, else row by row in spans ([`draw_spans`]).
#[inline(always)]
fn draw<L: SpanFill>(lanes: L, t: &RasterTri, ti: u32, band: &mut Band<'_>) {
    if t.x1 - t.x0 < 2 && t.y1 - t.y0 < 2 {
        draw_small(t, ti, band);
    } else {
        draw_spans(lanes, t, ti, band);
    }
}

/// A triangle whose box holds at most 2 x 2 pixel centres: each centre tested against the
/// three edge functions directly, without [`span`]'s divisions, the per-row set-up or a
/// block of [`LANES`] masked down to one or two pixels: on a million triangles at 1024²
/// most are this small, and drawing took 0.85-0.90 of its time with this path
/// (docs/performance.md, "A million triangles"). The same pixels, depths and triangles as
/// [`draw_spans`], bit for bit: a row's first covered pixel takes its barycentrics from
/// the exact edge functions and the second steps them by one pixel, as a span does.
#[inline(always)]
fn draw_small(t: &RasterTri, ti: u32, band: &mut Band<'_>) {
    let (width, y_start) = (band.width, band.y_start);
    let y_end = y_start + (band.depth.len() / width) as i32 - 1;
    let (py0, py1) = (t.y0.max(y_start), t.y1.min(y_end));
    let (x, y) = t.xy();
    let area = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
    if area <= 0 || py0 > py1 {
        return;
    }
    let half = 1i64 << (SUBPIXEL_BITS - 1);
    let one = 1i64 << SUBPIXEL_BITS;
    let biases = per_edge(|a, b| bias(x[a], y[a], x[b], y[b]));
    let step_x = per_edge(|a, b| -(y[b] - y[a]) * one);
    let step_y = per_edge(|a, b| (x[b] - x[a]) * one);
    let cx = t.x0 as i64 * one + half;
    let mut row_w = per_edge(|a, b| edge(x[a], y[a], x[b], y[b], cx, py0 as i64 * one + half));
    let inside = |w: &[i64; 3]| (w[0] + biases[0] >= 0) & (w[1] + biases[1] >= 0) & (w[2] + biases[2] >= 0);
    let two_columns = t.x1 > t.x0;
    let (z0, dz1, dz2) = (t.z[0], t.z[1] - t.z[0], t.z[2] - t.z[0]);
    for py in py0..=py1 {
        let next_w = [row_w[0] + step_x[0], row_w[1] + step_x[1], row_w[2] + step_x[2]];
        let (first, second) = (inside(&row_w), two_columns && inside(&next_w));
        if first || second {
            // `draw_spans`' arithmetic: the barycentrics at the span's first pixel from the
            // exact edge functions, stepped in f32 to the next.
            let inv_area = 1.0 / area as f64;
            let w = if first { row_w } else { next_w };
            let l1 = (w[1] as f64 * inv_area) as f32;
            let l2 = (w[2] as f64 * inv_area) as f32;
            let at = (py - y_start) as usize * width + t.x0 as usize + !first as usize;
            test_depth(band, at, ti, z0 + dz1 * l1 + dz2 * l2);
            if first && second {
                let step1 = (step_x[1] as f64 * inv_area) as f32;
                let step2 = (step_x[2] as f64 * inv_area) as f32;
                let (l1, l2) = (l1 + step1, l2 + step2);
                test_depth(band, at + 1, ti, z0 + dz1 * l1 + dz2 * l2);
            }
        }
        for k in 0..3 {
            row_w[k] += step_y[k];
        }
    }
}

/// The depth test at pixel `i` of the band: `ti` and `z` written there if strictly nearer.
#[inline(always)]
fn test_depth(band: &mut Band<'_>, i: usize, ti: u32, z: f32) {
    if z < band.depth[i] {
        band.depth[i] = z;
        band.raster[i] = ti;
    }
}

/// Draws triangle `ti` into the band row by row, each row's exact span of covered pixels
/// found by [`span`] and filled by `lanes` in blocks of [`LANES`].
#[inline(always)]
fn draw_spans<L: SpanFill>(lanes: L, t: &RasterTri, ti: u32, band: &mut Band<'_>) {
    let (width, y_start) = (band.width, band.y_start);
    let y_end = y_start + (band.depth.len() / width) as i32 - 1;
    let (x, y) = t.xy();
    let area = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
    if area <= 0 {
        return;
    }
    let inv_area = 1.0 / area as f64;
    let half = 1i64 << (SUBPIXEL_BITS - 1);
    let one = 1i64 << SUBPIXEL_BITS;
    // w0 is opposite vertex 0 (edge 1 -> 2), and so on.
    let biases = per_edge(|a, b| bias(x[a], y[a], x[b], y[b]));
    // Steps of each edge function per pixel in x and per row in y.
    let step_x = per_edge(|a, b| -(y[b] - y[a]) * one);
    let step_y = per_edge(|a, b| (x[b] - x[a]) * one);
    let (py0, py1) = (t.y0.max(y_start), t.y1.min(y_end));
    if py0 > py1 {
        return;
    }
    let px0 = t.x0 as i64;
    let cx = px0 * one + half;
    let mut row_w = per_edge(|a, b| edge(x[a], y[a], x[b], y[b], cx, py0 as i64 * one + half));
    // Screen-space barycentrics l1 = w1 / area, l2 = w2 / area and depth, per pixel step.
    let (z0, dz1, dz2) = (t.z[0], t.z[1] - t.z[0], t.z[2] - t.z[0]);
    let (step1, step2) = ((step_x[1] as f64 * inv_area) as f32, (step_x[2] as f64 * inv_area) as f32);
    let width_span = (t.x1 - t.x0) as i64;
    for py in py0..=py1 {
        let (mut lo, mut hi) = (0i64, width_span);
        for k in 0..3 {
            span(row_w[k], step_x[k], biases[k], &mut lo, &mut hi);
        }
        if lo <= hi {
            let row = (py - y_start) as usize * width + t.x0 as usize;
            let l1 = ((row_w[1] + step_x[1] * lo) as f64 * inv_area) as f32;
            let l2 = ((row_w[2] + step_x[2] * lo) as f64 * inv_area) as f32;
            let plane = RowPlane { l1, l2, step1, step2, z0, dz1, dz2 };
            let (at, n) = (row + lo as usize, (hi - lo + 1) as usize);
            lanes.fill_span(ti, plane, band, at, n);
        }
        for k in 0..3 {
            row_w[k] += step_y[k];
        }
    }
}

/// A triangle's screen-space barycentrics at pixel centres, from its edge functions:
/// `l1 = w1 / area`, `l2 = w2 / area`, with `w1` the edge function of edge 2 -> 0 and `w2`
/// of edge 0 -> 1 (`edge`), the same as the raster's coverage test.
///
/// The edge functions are integers (fixed-point products, below 2^46 inside the guard
/// band), so they are exact in f64, at every pixel and for every step along a row; each
/// barycentric is the exact edge function times 1/area (f64), rounded to f32. (The raster
/// steps its barycentrics in f32 along the row for the depth test, as OpenGL's
/// rasterisers step depth; shading does not inherit that drift.)
#[derive(Clone, Copy, Debug, Default)]
pub struct ScreenBarycentrics {
    /// `w1`, `w2` at the centre of pixel (0, 0).
    w_origin: [i64; 2],
    /// Their steps per pixel to the right.
    step_x: [i64; 2],
    /// Their steps per row down.
    step_y: [i64; 2],
    /// `1 / area`, area the triangle's doubled fixed-point area.
    inv_area: f64,
}

/// The steps of a triangle's edge functions `w1` (edge 2 -> 0) and `w2` (edge 0 -> 1) per
/// pixel to the right and per row down, and `1 / area` (0 for a triangle without area):
/// `l1 = w1 / area`, `l2 = w2 / area` change by `step_x[k] / area` a pixel. Shared by
/// [`ScreenBarycentrics`] and the resolve's Gouraud planes.
#[inline(always)]
pub(crate) fn barycentric_steps(t: &RasterTri) -> ([i64; 2], [i64; 2], f64) {
    let (x, y) = t.xy();
    let one = 1i64 << SUBPIXEL_BITS;
    let area = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
    // The edges 2 -> 0 and 0 -> 1 of [`per_edge`].
    let [_, sx1, sx2] = per_edge(|a, b| -(y[b] - y[a]) * one);
    let [_, sy1, sy2] = per_edge(|a, b| (x[b] - x[a]) * one);
    ([sx1, sx2], [sy1, sy2], if area != 0 { 1.0 / area as f64 } else { 0.0 })
}

impl ScreenBarycentrics {
    /// The edge functions of `t`.
    pub fn new(t: &RasterTri) -> Self {
        let (x, y) = t.xy();
        let half = 1i64 << (SUBPIXEL_BITS - 1);
        // The edges 2 -> 0 and 0 -> 1 of [`per_edge`].
        let [_, w1, w2] = per_edge(|a, b| edge(x[a], y[a], x[b], y[b], half, half));
        let (step_x, step_y, inv_area) = barycentric_steps(t);
        Self { w_origin: [w1, w2], step_x, step_y, inv_area }
    }

    /// `w1` and `w2` at the centre of pixel (`px`, `py`), as f64 (exact), their steps per
    /// pixel along the row, and `1 / area`.
    #[inline(always)]
    pub fn row(&self, px: usize, py: usize) -> ([f64; 2], [f64; 2], f64) {
        let (px, py) = (px as i64, py as i64);
        let w = std::array::from_fn(|k| (self.w_origin[k] + self.step_x[k] * px + self.step_y[k] * py) as f64);
        (w, [self.step_x[0] as f64, self.step_x[1] as f64], self.inv_area)
    }

    /// The barycentrics `[l1, l2]` at the centre of pixel (`px`, `py`).
    pub fn at(&self, px: usize, py: usize) -> [f32; 2] {
        let (w, _, inv_area) = self.row(px, py);
        w.map(|w| (w * inv_area) as f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::xorshift as rng;

    /// A random positively oriented triangle in a `w` x `h` image (fixed point, vertices
    /// up to a few pixels outside), with its pixel bounding box as setup computes it.
    fn random_tri(next: &mut impl FnMut() -> u64, w: usize, h: usize) -> Option<RasterTri> {
        let one = 1i64 << SUBPIXEL_BITS;
        let coord = |r: u64, n: usize| (r % ((n as u64 + 8) << SUBPIXEL_BITS)) as i64 - 4 * one;
        let x = [0; 3].map(|_| coord(next(), w));
        let y = [0; 3].map(|_| coord(next(), h));
        let (x, y) = oriented(x, y)?;
        // Half of them flat at one of two depths, so that exact ties (which the strict
        // depth test must refuse) are common.
        let z = if next().is_multiple_of(2) {
            [[0.25; 3], [0.375; 3]][(next() % 2) as usize]
        } else {
            [0; 3].map(|_| (next() % 1_000_000) as f32 / 1e6)
        };
        boxed(x, y, z, w, h)
    }

    /// The corners `x`, `y` (fixed point) turned positive (`None` when they are in a line).
    fn oriented(mut x: [i64; 3], mut y: [i64; 3]) -> Option<([i64; 3], [i64; 3])> {
        let area = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
        if area == 0 {
            return None;
        }
        if area < 0 {
            x.swap(1, 2);
            y.swap(1, 2);
        }
        Some((x, y))
    }

    /// The raster triangle of corners `x`, `y` and depths `z` in a `w` x `h` image, with its
    /// pixel bounding box as setup computes it (`None` when the box holds no pixel centre).
    fn boxed(x: [i64; 3], y: [i64; 3], z: [f32; 3], w: usize, h: usize) -> Option<RasterTri> {
        let one = 1i64 << SUBPIXEL_BITS;
        let px = |v: i64| (v - one / 2 + one - 1) >> SUBPIXEL_BITS;
        let (x0, x1) = (px(*x.iter().min()?).max(0), ((*x.iter().max()? - one / 2) >> SUBPIXEL_BITS).min(w as i64 - 1));
        let (y0, y1) = (px(*y.iter().min()?).max(0), ((*y.iter().max()? - one / 2) >> SUBPIXEL_BITS).min(h as i64 - 1));
        (x0 <= x1 && y0 <= y1).then_some(RasterTri {
            x: x.map(|v| v as i32),
            y: y.map(|v| v as i32),
            z,
            x0: x0 as i32,
            x1: x1 as i32,
            y0: y0 as i32,
            y1: y1 as i32,
            ..RasterTri::default()
        })
    }

    /// [`draw_band`] with the portable loop or (`avx2`, only where [`avx2_here`]) the AVX2
    /// one; returns the back faces skipped.
    fn draw_band_with(setup: &Setup, bin: &[u32], band: Band<'_>, avx2: bool) -> usize {
        if avx2 {
            let proof = crate::cpu::Avx2::detect().expect("the AVX2 raster asked for where it cannot run");
            return draw_band_any(proof, setup, bin, band);
        }
        draw_band_any(Portable, setup, bin, band)
    }

    /// Draws `tris` into one band of `w` x `h` with the portable loop or the AVX2 one.
    fn draw_all(tris: &[RasterTri], w: usize, h: usize, avx2: bool) -> (Vec<f32>, Vec<u32>) {
        let (mut depth, mut raster) = (vec![0.5; w * h], vec![7; w * h]);
        let mut setup = Setup::default();
        setup.tris = tris.to_vec();
        let bin: Vec<u32> = (0..tris.len() as u32).collect();
        draw_band_with(&setup, &bin, Band { y_start: 0, width: w, depth: &mut depth, raster: &mut raster }, avx2);
        (depth, raster)
    }

    /// Can the AVX2 raster run here?
    fn avx2_here() -> bool {
        crate::cpu::Avx2::detect().is_some()
    }

    /// The band buffers start on a cache line, hold `n` entries, keep what was written
    /// when asked for the same size again, and fill new room with the given value.
    #[test]
    fn band_buffers_start_on_a_cache_line() {
        for start in 0..20 {
            // Vectors whose allocations start at different offsets.
            let mut v: Vec<u32> = Vec::with_capacity(start + 1);
            v.extend(0..start as u32);
            for n in [1, 7, 64, 1000, 16 * 1024] {
                let s = line_aligned(&mut v, n, 9);
                assert_eq!((s.len(), s.as_ptr() as usize % 64), (n, 0));
                s[n - 1] = 5;
                let again = line_aligned(&mut v, n, 9);
                assert_eq!(again[n - 1], 5);
            }
        }
        let mut empty = Vec::new();
        assert!(line_aligned(&mut empty, 33, 1.0f32).iter().all(|&z| z == 1.0));
        with_band_buffer(100, |depth, raster| {
            assert_eq!((depth.as_ptr() as usize % 64, raster.as_ptr() as usize % 64), (0, 0));
            assert_eq!((depth.len(), raster.len()), (100, 100));
        });
    }

    /// Back faces skipped whole by the hierarchical depth test are exactly those that would
    /// have drawn nothing: the band is the same, bit for bit, as when every triangle is
    /// drawn (front faces first, as `bin` orders them), in both the portable and the AVX2
    /// raster; and the test does skip many.
    #[test]
    fn hidden_back_faces_are_skipped_without_changing_a_pixel() {
        let mut next = rng(0x51afd7ed558ccd1d);
        let one = 1i64 << SUBPIXEL_BITS;
        let mut skipped_total = 0;
        for (w, h) in [(64, 16), (61, 16), (300, 16), (2100, 16), (97, 9)] {
            // A wall of two front faces over the whole band at one depth, then random front
            // faces, then random back faces: some far behind the wall, some just behind or
            // level with it (within the rounding margin), some in front.
            let (x1, y1) = ((w as i64 + 1) * one, (h as i64 + 1) * one);
            let wall = |x: [i64; 3], y: [i64; 3]| RasterTri {
                x: x.map(|v| v as i32),
                y: y.map(|v| v as i32),
                z: [0.5; 3],
                x0: 0,
                x1: w as i32 - 1,
                y0: 0,
                y1: h as i32 - 1,
                ..RasterTri::default()
            };
            let mut tris = vec![wall([-one, x1, x1], [-one, -one, y1]), wall([-one, x1, -one], [-one, y1, y1])];
            let mut backs = Vec::new();
            for k in 0..600 {
                let Some(mut t) = random_tri(&mut next, w, h) else { continue };
                if k % 3 == 0 {
                    tris.push(t);
                    continue;
                }
                t.back = true;
                let base =
                    [0.5 + 1.0 / 4096.0, 0.5, 0.5 + 1e-7, 0.5 - 1e-4, 0.5 - 1e-6, 0.75, 0.25][(next() % 7) as usize];
                // The nearest vertex at the base depth, the others up to 0.1 or 1e-4 behind.
                let slope = [1e-4, 1e-7][(next() % 2) as usize];
                t.z = [0; 3].map(|_| base + (next() % 1000) as f32 * slope);
                t.z[(next() % 3) as usize] = base;
                backs.push(t);
            }
            tris.extend(backs);
            let mut setup = Setup::default();
            setup.tris = tris;
            let bin: Vec<u32> = (0..setup.tris.len() as u32).collect();
            // Every triangle drawn, none skipped.
            let (mut d_all, mut r_all) = (vec![0.0; w * h], vec![0; w * h]);
            let mut band = Band { y_start: 0, width: w, depth: &mut d_all, raster: &mut r_all };
            band.depth.fill(1.0);
            band.raster.fill(NO_TRIANGLE);
            for &ti in &bin {
                draw(Portable, &setup.tris[ti as usize], ti, &mut band);
            }
            let bits = |d: &[f32]| d.iter().map(|z| z.to_bits()).collect::<Vec<_>>();
            for avx2 in [false, true] {
                if avx2 && !avx2_here() {
                    continue;
                }
                let (mut depth, mut raster) = (vec![0.0; w * h], vec![0; w * h]);
                let band = Band { y_start: 0, width: w, depth: &mut depth, raster: &mut raster };
                let skipped = draw_band_with(&setup, &bin, band, avx2);
                assert_eq!(raster, r_all, "{w}x{h} avx2 {avx2}: triangles");
                assert_eq!(bits(&depth), bits(&d_all), "{w}x{h} avx2 {avx2}: depths");
                skipped_total += skipped;
            }
            assert!(
                r_all.iter().any(|&r| setup.tris.get(r as usize).is_some_and(|t| t.back)),
                "{w}x{h}: a back face shows"
            );
        }
        assert!(skipped_total > 1000, "{skipped_total} skipped");
    }

    /// The margin's premise: at every pixel a triangle covers, its interpolated depth is
    /// less than a sixteenth of the margin (2^-16) below its nearest vertex, on thousands of
    /// random triangles of every shape and slope. (Measured: it never falls below at all.)
    #[test]
    fn interpolated_depth_stays_within_the_rounding_margin_of_the_vertices() {
        let mut next = rng(0x7f4a7c159e3779b9);
        let (w, h) = (331, 16);
        let mut worst = 0.0f32;
        let mut pixels = 0;
        for _ in 0..3000 {
            let Some(mut t) = random_tri(&mut next, w, h) else { continue };
            t.z = [0; 3].map(|_| (next() % 1_000_000) as f32 / 1.0000001e6);
            let (depth, raster) = draw_all(std::slice::from_ref(&t), w, h, false);
            let nearest = t.z[0].min(t.z[1]).min(t.z[2]);
            for (z, _) in depth.iter().zip(&raster).filter(|(_, r)| **r == 0) {
                worst = worst.max(nearest - z);
                pixels += 1;
            }
        }
        assert!(pixels > 100_000, "{pixels}");
        assert!(worst <= DEPTH_ROUNDING_MARGIN / 16.0, "depth {worst:e} below the nearest vertex");
    }

    /// The AVX2 raster is the portable one, bit for bit: every depth and triangle, on
    /// widths that are and are not multiples of the block, with spans that start and end
    /// anywhere in a block and run into the band's last pixels.
    #[test]
    fn the_avx2_raster_draws_what_the_portable_one_draws() {
        #[cfg(target_arch = "x86_64")]
        if crate::cpu::Avx2::detect().is_some() {
            let mut next = rng(0x2545f4914f6cdd1d);
            for (w, h) in [(64, 16), (61, 16), (97, 9), (8, 3), (1, 5)] {
                let tris: Vec<RasterTri> = (0..400).filter_map(|_| random_tri(&mut next, w, h)).collect();
                assert!(tris.len() > 100, "{w}x{h}: {} triangles", tris.len());
                let (d_port, r_port) = draw_all(&tris, w, h, false);
                let (d_avx, r_avx) = draw_all(&tris, w, h, true);
                assert_eq!(r_port, r_avx, "{w}x{h}: triangles");
                let bits = |d: &[f32]| d.iter().map(|z| z.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&d_port), bits(&d_avx), "{w}x{h}: depths");
                assert!(r_port.iter().any(|&r| r != NO_TRIANGLE && r != 7), "{w}x{h}: something drawn");
            }
        }
    }

    /// The resolve's barycentrics come from the exact edge functions: at every covered
    /// pixel they are the integer edge function (the coverage test's) times 1/area in f64,
    /// rounded to f32, whatever the distance from the span's start; and inside [0, 1].
    #[test]
    fn screen_barycentrics_are_the_exact_edge_functions() {
        let mut next = rng(0x9e3779b97f4a7c15);
        let (w, h) = (97, 40);
        let (half, one) = (1i64 << (SUBPIXEL_BITS - 1), 1i64 << SUBPIXEL_BITS);
        let mut checked = 0;
        for _ in 0..300 {
            let Some(t) = random_tri(&mut next, w, h) else { continue };
            let (_, raster) = draw_all(std::slice::from_ref(&t), w, h, false);
            let sb = ScreenBarycentrics::new(&t);
            let (tx, ty) = t.xy();
            let inv_area = 1.0 / edge(tx[0], ty[0], tx[1], ty[1], tx[2], ty[2]) as f64;
            for (i, _) in raster.iter().enumerate().filter(|(_, r)| **r == 0) {
                let (px, py) = (i % w, i / w);
                let (cx, cy) = (px as i64 * one + half, py as i64 * one + half);
                let w1 = edge(tx[2], ty[2], tx[0], ty[0], cx, cy);
                let w2 = edge(tx[0], ty[0], tx[1], ty[1], cx, cy);
                let l = sb.at(px, py);
                assert_eq!(l, [(w1 as f64 * inv_area) as f32, (w2 as f64 * inv_area) as f32], "pixel {px},{py}");
                assert!(l.iter().all(|v| (0.0..=1.0).contains(v)) && l[0] + l[1] <= 1.0 + 1e-6, "{l:?}");
                checked += 1;
            }
        }
        assert!(checked > 10_000, "{checked}");
    }

    /// The path for triangles of at most 2 x 2 pixel centres draws what the spans draw, bit
    /// for bit: the same pixels (every fill-rule case: corners and edges on pixel centres),
    /// the same depths, the same winner at exact depth ties; in bands whose rows cut the
    /// triangles, in the band's last pixels, and with one and two columns and rows.
    #[test]
    fn small_triangles_are_drawn_as_the_spans_draw_them() {
        let mut next = rng(0x3c6ef372fe94f82b);
        let one = 1i64 << SUBPIXEL_BITS;
        let (w, h) = (13, 7);
        let mut drawn = [0usize; 4];
        for round in 0..60_000 {
            // Corners in a square of 2 x 2 pixels (so that the box holds at most 2 x 2
            // centres), some of it outside the image, on a grid of quarter pixels half the
            // time (so that corners and edges often lie on pixel centres).
            let (bx, by) = ((next() % (w as u64 + 2)) as i64 - 1, (next() % (h as u64 + 2)) as i64 - 1);
            let coarse = round % 2 == 0;
            let mut corner = |b: i64| {
                let c = b * one + (next() % (2 * one as u64)) as i64;
                if coarse { c / 64 * 64 } else { c }
            };
            let Some((x, y)) = oriented([corner(bx), corner(bx), corner(bx)], [corner(by), corner(by), corner(by)])
            else {
                continue;
            };
            let Some(mut t) = boxed(x, y, [0.0; 3], w, h) else { continue };
            if t.x1 - t.x0 >= 2 || t.y1 - t.y0 >= 2 {
                continue;
            }
            t.z = if next().is_multiple_of(2) { [0.25; 3] } else { [0; 3].map(|_| (next() % 1_000_000) as f32 / 1e6) };
            // Bands of 3 rows from row 0 and row 4 (rows that cut the triangle's box).
            for (y_start, rows) in [(0, 3), (3, 3), (4, 3)] {
                let n = w * rows;
                let init = |k: usize| if k.is_multiple_of(3) { 0.25 } else { 0.5 };
                let (mut d_small, mut r_small) = ((0..n).map(init).collect::<Vec<f32>>(), vec![7u32; n]);
                let (mut d_spans, mut r_spans) = (d_small.clone(), r_small.clone());
                let band = |depth, raster| Band { y_start, width: w, depth, raster };
                draw_small(&t, 3, &mut band(&mut d_small, &mut r_small));
                draw_spans(Portable, &t, 3, &mut band(&mut d_spans, &mut r_spans));
                assert_eq!(r_small, r_spans, "{t:?}, band from row {y_start}");
                let bits = |d: &[f32]| d.iter().map(|z| z.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&d_small), bits(&d_spans), "{t:?}, band from row {y_start}");
            }
            let (mut depth, mut raster) = (vec![1.0; w * h], vec![NO_TRIANGLE; w * h]);
            draw_spans(Portable, &t, 3, &mut Band { y_start: 0, width: w, depth: &mut depth, raster: &mut raster });
            drawn[raster.iter().filter(|&&r| r == 3).count().min(3)] += 1;
        }
        // Triangles that cover no pixel centre, one, two, and three or four.
        assert!(drawn[..3].iter().all(|&n| n > 1000) && drawn[3] > 50, "{drawn:?}");
    }

    /// The spans by exact integer search, for comparison.
    fn by_search(w0: i64, step: i64, bias: i64, n: i64) -> (i64, i64) {
        let inside: Vec<i64> = (0..=n).filter(|k| w0 + bias + step * k >= 0).collect();
        match (inside.first(), inside.last()) {
            (Some(a), Some(b)) => (*a, *b),
            _ => (0, -1),
        }
    }

    #[test]
    fn spans_are_exactly_the_integer_ones() {
        let mut next = rng(0x9e3779b97f4a7c15);
        for _ in 0..200_000 {
            let step = (next() % 20_001) as i64 - 10_000;
            let w0 = (next() % 4_000_001) as i64 - 2_000_000;
            let bias = -((next() % 2) as i64);
            let n = 600;
            let (mut lo, mut hi) = (0, n);
            span(w0, step, bias, &mut lo, &mut hi);
            let (a, b) = by_search(w0, step, bias, n);
            if a <= b {
                assert_eq!((lo, hi), (a, b), "w0 {w0} step {step} bias {bias}");
            } else {
                assert!(lo > hi, "empty: w0 {w0} step {step} bias {bias} -> {lo}..{hi}");
            }
        }
        // Exact multiples, where a rounded quotient could be off by one.
        for step in [1i64, 3, 256, 7 * 256, -1, -3, -256, -7 * 256] {
            for m in -50..50 {
                let w0 = step.abs() * m;
                for bias in [0, -1] {
                    let (mut lo, mut hi) = (0, 100);
                    span(w0, step, bias, &mut lo, &mut hi);
                    let (a, b) = by_search(w0, step, bias, 100);
                    if a <= b {
                        assert_eq!((lo, hi), (a, b), "w0 {w0} step {step} bias {bias}");
                    } else {
                        assert!(lo > hi);
                    }
                }
            }
        }
    }
}
