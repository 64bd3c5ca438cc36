//! Runs: the pixels of a row that show one triangle, found eight at a time, and their
//! perspective-correct weights, a block of [`LANES`] pixels at a time: `b_i = (l_i / w_i) /
//! sum_j (l_j / w_j)` from the screen barycentrics `l`, which come exact from the edge
//! functions.

use glam::Vec3;

use super::pixels::{LANES, ResolveLanes};

/// A run of pixels of one triangle in one row: `len` pixels from (`x`, `y`) of the image,
/// the first at index `at` of the band.
#[derive(Clone, Copy)]
pub(super) struct Run {
    pub(super) x: usize,
    pub(super) y: usize,
    pub(super) at: usize,
    pub(super) len: usize,
}

/// How many entries at the start of `row` (not empty) equal its first: eight compared at
/// a time (`lanes.differ8` and a bit scan), the rest one by one.
#[inline(always)]
pub(super) fn run_length(lanes: impl ResolveLanes, row: &[u32]) -> usize {
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

/// The perspective-correct weights of a pixel with screen barycentrics `l` (of vertices 1
/// and 2) in a triangle whose vertices have `1/w = inv_w`: `b_k = l_k inv_w_k / sum_j l_j
/// inv_w_j`, returned as (`l_k`, `1 / sum`), so that an attribute stored as `a_k inv_w_k`
/// is `sum_k l_k (a_k inv_w_k) / sum_j l_j inv_w_j`.
#[inline(always)]
fn screen_weights(inv_w: [f32; 3], l: [f32; 2]) -> ([f32; 3], f32) {
    let ls = [1.0 - l[0] - l[1], l[0], l[1]];
    (ls, 1.0 / (ls[0] * inv_w[0] + ls[1] * inv_w[1] + ls[2] * inv_w[2]))
}

/// The perspective weights of [`LANES`] pixels of a run, [`screen_weights`] lane by lane:
/// `ls[k][j]` the screen barycentric of vertex k at lane j, `s[j]` one over their sum
/// weighted by 1/w.
pub(super) struct Weights {
    ls: [[f32; LANES]; 3],
    s: [f32; LANES],
}

impl Run {
    /// The weights of pixels `k0..k0 + LANES` of the run (lanes past its end are computed
    /// and ignored). Each screen barycentric is the exact edge function (f64) times
    /// 1/area, rounded once to f32; then [`screen_weights`]' arithmetic, in its order.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lanes index several arrays; the loop vectorises
    pub(super) fn weights(&self, edges: &([f64; 2], [f64; 2], f64), inv_w: [f32; 3], k0: usize) -> Weights {
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
    pub(super) fn blocks(&self) -> impl Iterator<Item = (usize, usize)> {
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
pub(super) fn xyz(v: &[Vec3; 3]) -> [[f32; 3]; 3] {
    [v[0].to_array(), v[1].to_array(), v[2].to_array()]
}

/// [`blend`] for each of `N` channels, `a[k][c]` channel c at vertex k.
#[inline(always)]
pub(super) fn blend_n<const N: usize>(wt: &Weights, a: &[[f32; N]; 3]) -> [[f32; LANES]; N] {
    let mut out = [[0.0; LANES]; N];
    for c in 0..N {
        out[c] = blend(wt, [a[0][c], a[1][c], a[2][c]]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::Portable;
    use crate::raster::render::NO_TRIANGLE;
    use crate::raster::render::setup::RasterTri;
    use crate::raster::render::visibility::ScreenBarycentrics;

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
