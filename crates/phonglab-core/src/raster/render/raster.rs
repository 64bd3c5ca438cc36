//! Stage 3: triangles into the visibility buffer.
//!
//! Edge functions in fixed point (8 sub-pixel bits), evaluated at pixel centres, with the
//! top-left rule: a centre exactly on an edge belongs to the triangle only if that edge
//! is a top edge (horizontal, interior below) or a left edge (interior to its right), so
//! two triangles sharing an edge never both draw, nor both miss, a pixel on it. The image
//! is cut into bands of rows; each band is drawn by one thread with the triangles that
//! touch it, so threads never write the same pixel.

use rayon::prelude::*;

use super::setup::{RasterTri, SUBPIXEL_BITS, Setup};
use super::{Image, NO_TRIANGLE};

/// Rows per band.
pub const BAND: usize = 16;

/// `E(a, b, p) = (b - a) x (p - a)`: positive when p is inside a positively oriented triangle.
#[inline(always)]
fn edge(ax: i64, ay: i64, bx: i64, by: i64, px: i64, py: i64) -> i64 {
    (bx - ax) * (py - ay) - (by - ay) * (px - ax)
}

/// 0 for a top or left edge (a centre on it is inside), -1 otherwise.
#[inline(always)]
fn bias(ax: i64, ay: i64, bx: i64, by: i64) -> i64 {
    let (dx, dy) = (bx - ax, by - ay);
    if (dy == 0 && dx > 0) || dy < 0 { 0 } else { -1 }
}

/// Draws every triangle of `setup` into `image` (resized to width x height).
pub fn rasterise(setup: &Setup, width: usize, height: usize, image: &mut Image, bins: &mut Vec<Vec<u32>>) {
    let n = width * height;
    image.width = width;
    image.height = height;
    // Sized here, cleared per band below (in parallel); barycentrics are read only where a
    // triangle was drawn, so they need no clearing.
    image.depth.resize(n, 1.0);
    image.raster.resize(n, NO_TRIANGLE);
    image.bary.resize(n, [0.0; 2]);
    image.rgba.resize(n * 4, 0);

    // Bin triangles by band.
    let bands = height.div_ceil(BAND);
    bins.resize_with(bands, Vec::new);
    for b in bins.iter_mut() {
        b.clear();
    }
    // Front faces first: a closed surface's back faces then mostly fail the depth test and
    // write nothing (the image is the same; only exact depth ties could differ).
    for back in [false, true] {
        for (i, t) in setup.tris.iter().enumerate().filter(|(_, t)| t.back == back) {
            for bin in &mut bins[t.y0 as usize / BAND..=t.y1 as usize / BAND] {
                bin.push(i as u32);
            }
        }
    }

    let rows = width * BAND;
    image
        .depth
        .par_chunks_mut(rows)
        .zip(image.raster.par_chunks_mut(rows))
        .zip(image.bary.par_chunks_mut(rows))
        .zip(bins.par_iter())
        .enumerate()
        .for_each(|(b, (((depth, raster), bary), bin))| {
            depth.fill(1.0);
            raster.fill(NO_TRIANGLE);
            let y_start = (b * BAND) as i32;
            let y_end = y_start + (depth.len() / width) as i32 - 1;
            for &ti in bin {
                draw(&setup.tris[ti as usize], ti, width, y_start, y_end, depth, raster, bary);
            }
        });
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

#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn draw(
    t: &RasterTri,
    ti: u32,
    width: usize,
    y_start: i32,
    y_end: i32,
    depth: &mut [f32],
    raster: &mut [u32],
    bary: &mut [[f32; 2]],
) {
    let (x, y) = (t.x, t.y);
    let area = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
    if area <= 0 {
        return;
    }
    let inv_area = 1.0 / area as f64;
    let half = 1i64 << (SUBPIXEL_BITS - 1);
    let one = 1i64 << SUBPIXEL_BITS;
    // w0 is opposite vertex 0 (edge 1 -> 2), and so on.
    let e = [(1, 2), (2, 0), (0, 1)];
    let biases = e.map(|(a, b)| bias(x[a], y[a], x[b], y[b]));
    // Steps of each edge function per pixel in x and per row in y.
    let step_x = e.map(|(a, b)| -(y[b] - y[a]) * one);
    let step_y = e.map(|(a, b)| (x[b] - x[a]) * one);
    let (py0, py1) = (t.y0.max(y_start), t.y1.min(y_end));
    if py0 > py1 {
        return;
    }
    let px0 = t.x0 as i64;
    let cx = px0 * one + half;
    let mut row_w = e.map(|(a, b)| edge(x[a], y[a], x[b], y[b], cx, py0 as i64 * one + half));
    // Screen-space barycentrics l1 = w1 / area, l2 = w2 / area and depth, per pixel step.
    let (z0, dz1, dz2) = (t.z[0], t.z[1] - t.z[0], t.z[2] - t.z[0]);
    let (sl1, sl2) = ((step_x[1] as f64 * inv_area) as f32, (step_x[2] as f64 * inv_area) as f32);
    let width_span = (t.x1 - t.x0) as i64;
    for py in py0..=py1 {
        let (mut lo, mut hi) = (0i64, width_span);
        for k in 0..3 {
            span(row_w[k], step_x[k], biases[k], &mut lo, &mut hi);
        }
        if lo <= hi {
            let row = (py - y_start) as usize * width + t.x0 as usize;
            let l1_0 = ((row_w[1] + step_x[1] * lo) as f64 * inv_area) as f32;
            let l2_0 = ((row_w[2] + step_x[2] * lo) as f64 * inv_area) as f32;
            let range = row + lo as usize..=row + hi as usize;
            let (d, r, b) = (&mut depth[range.clone()], &mut raster[range.clone()], &mut bary[range]);
            // Branch-free: every cell is rewritten with either the new fragment or its own
            // old value, so the loop vectorises.
            for (k, ((d, r), b)) in d.iter_mut().zip(r.iter_mut()).zip(b.iter_mut()).enumerate() {
                let kf = k as f32;
                let (l1, l2) = (l1_0 + sl1 * kf, l2_0 + sl2 * kf);
                let z = z0 + dz1 * l1 + dz2 * l2;
                let pass = z < *d;
                *d = if pass { z } else { *d };
                *r = if pass { ti } else { *r };
                *b = if pass { [l1, l2] } else { *b };
            }
        }
        for k in 0..3 {
            row_w[k] += step_y[k];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::span;

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
        let mut seed = 0x9e3779b97f4a7c15u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
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
