//! Per-pixel lighting (Phong, and Flat with the demo's derivative normals): a band's
//! fragments (eye-space position and normal per covered pixel) gathered run by run, then
//! lit in batches through the specialised evaluator and written to their pixels.

use glam::Vec3;

use super::pixels::{LANES, to_u8};
use super::runs::{Run, blend_n, xyz};
use crate::model::view::ShadingMode;
use crate::specialise::lighter::{EyeArrays, Lighter};

/// One band's per-pixel fragments, presized to the band and written by index, and the runs
/// they came from (a list cleared for each band). Positions and normals are six arrays
/// (x, y, z of each), written a block of `LANES` at a time and read so by the lighting.
#[derive(Default)]
pub struct Fragments {
    runs: Vec<FragmentRun>,
    pub(super) pos: [Vec<f32>; 3],
    pub(super) nrm: [Vec<f32>; 3],
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
    pub(super) fn size(&mut self, n: usize) {
        self.runs.clear();
        for a in self.pos.iter_mut().chain(&mut self.nrm) {
            a.resize(n + LANES, 0.0);
        }
    }

    /// Stores a block's channels (`v[c]`: channel c of its lanes) as fragments `at..at +
    /// LANES` of `to`, whole: lanes past the run land where the next run's fragments go.
    #[inline(always)]
    pub(super) fn store(to: &mut [Vec<f32>; 3], at: usize, v: &[[f32; LANES]; 3]) {
        debug_assert!(to.iter().all(|a| at + LANES <= a.len()), "sized by Fragments::size");
        for (a, c) in to.iter_mut().zip(v) {
            if let Some(dst) = a.get_mut(at..).and_then(|d| d.first_chunk_mut::<LANES>()) {
                *dst = *c;
            }
        }
    }
}

impl Run {
    /// Records the run's pixels, and their side, as fragments `m..m + len` (their positions
    /// and normals already written); returns the fragments written after it.
    #[inline(always)]
    pub(super) fn fragments(&self, frags: &mut Fragments, m: usize, back: bool) -> usize {
        frags.runs.push(FragmentRun { first: m as u32, pixel: self.at as u32, len: self.len as u32, back });
        m + self.len
    }
}

/// A run's fragments for the demo's Flat shading, from fragment `m` on: each pixel's
/// eye-space position interpolated, and one normal, the face's.
#[inline(always)]
pub(super) fn flat_fragments(
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
pub(super) const BATCH: usize = 1024;

/// Lights fragments `..m` of `frags` and writes their colours to their pixels of `px`
/// (the band's); then clears the runs, for the next batch.
#[inline(always)]
pub(super) fn light_fragments(
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
