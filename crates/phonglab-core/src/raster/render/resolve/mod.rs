//! Stage 4: each covered pixel shaded once.
//!
//! The visibility buffer holds, per pixel, the rasterised triangle. The pixels of a row go
//! in runs of one triangle: its screen-space barycentrics `l` come from its edge functions
//! ([`ScreenBarycentrics`](super::visibility::ScreenBarycentrics), exact), and its attributes are made once for the run.
//! Attributes vary linearly in clip space, not on the screen, so they are interpolated
//! perspective-correctly: `b_i = (l_i / w_i) / sum_j (l_j / w_j)`. Those are mapped back to
//! the original mesh triangle through its clipped vertices' barycentrics.
//!
//! - Gouraud: the vertices' colours (each clamped as OpenGL clamps vertex colours). The
//!   same interpolation written as planes: `c/w` and `1/w` are affine on the screen, so
//!   each is set up once per triangle ([`ColorPlanes`], f64, through a vertex) and stepped
//!   along a run in f32, and a pixel's colour is their quotient (`gouraud`'s notes say
//!   how close, and why).
//! - Phong: position and normal, the normal renormalised, the lighting engine per pixel
//!   (in batches through the specialised evaluator).
//! - Flat: the face's colour; or, as the Phong demo's shader does, the pixel lit with
//!   `normalize(cross(dFdy(p), dFdx(p)))`. Within a triangle `p` is affine in the window
//!   coordinates, so that cross product is `-((b - a) x (c - a)) / A`, A the triangle's
//!   signed window area (y up): the face normal, negated on triangles counter-clockwise on
//!   the screen.
//!
//! Colours go to 8 bits as OpenGL converts them: `round(255 clamp(c, 0, 1))`.
//!
//! The parts: `pixels` (blocks of eight pixels to bytes), `runs` (runs of one triangle and
//! their weights), `attributes` (a triangle's, per run), `gouraud` (colour planes),
//! `fragments` (per-pixel lighting), `picking`, `sample` (one pixel again, for the probe); this file shades a band with them.

mod attributes;
mod fragments;
mod gouraud;
mod picking;
mod pixels;
mod runs;
mod sample;

use fragments::{BATCH, flat_fragments, light_fragments};
use gouraud::gouraud_run;
use pixels::{fill_px, to_u8};
use runs::{Run, blend_n, run_length, xyz};

pub(in crate::raster::render) use attributes::{attributes_of, seen_triangles};
pub use fragments::Fragments;
pub use gouraud::ColorPlanes;
pub(crate) use picking::original_barycentrics;
pub use pixels::LANES;
pub(in crate::raster::render) use pixels::ResolveLanes;
pub use sample::PixelSample;
pub(in crate::raster::render) use sample::{PixelInput, shade_pixel};

use super::setup::Setup;
use super::{Job, NO_TRIANGLE};
use crate::model::view::ShadingMode;
use crate::numerics::copies::prefetch;

/// How many pixels ahead in a row the resolve asks for a triangle's memory.
const RESOLVE_AHEAD: usize = 12;
use crate::specialise::lighter::Lighter;

/// Per-band buffers of Phong fragments.
#[derive(Default)]
pub struct Scratch {
    bands: Vec<Fragments>,
}

/// What every band's resolve shares, computed once per frame (`prepare`).
pub struct Prepared {
    bg: [u8; 4],
    two: bool,
    per_pixel: bool,
    /// Flat: each face's colour in 8 bits, per side.
    face8: [Vec<[u8; 4]>; 2],
}

/// The frame's shared resolve state, and a buffer of fragments for each of `bands` bands.
pub(super) fn prepare(job: &Job<'_>, setup: &Setup, scratch: &mut Scratch, bands: usize) -> Prepared {
    let bg = job.background.map(to_u8);
    // Shadings that light each pixel: Phong, and Flat with the demo's derivative normals.
    let per_pixel = job.mode.per_fragment();
    scratch.bands.resize_with(bands, Fragments::default);
    // Flat: each face's colour converted to 8 bits once.
    let face8: [Vec<[u8; 4]>; 2] = if job.mode.per_face() {
        [0, 1].map(|side| setup.face_color[side].iter().map(|c| c.map(to_u8)).collect())
    } else {
        [Vec::new(), Vec::new()]
    };
    Prepared { bg: [bg[0], bg[1], bg[2], 255], two: job.scene.light_model.two_sided, per_pixel, face8 }
}

/// The per-band fragment buffers.
pub fn fragments(scratch: &mut Scratch) -> &mut [Fragments] {
    &mut scratch.bands
}

/// What shading one band reads: the frame's job, triangles (`setup`), lighting plan and
/// prepared state, and the band's own visibility buffer `raster`, whose first row is
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
    /// The frame's vertices (their colours, eye-space positions and normals).
    pub verts: &'a crate::raster::render::vertices::Vertices,
    /// The band's visibility buffer: the rasterised triangle at each pixel.
    pub raster: &'a [u32],
    /// The image row of the band's first row.
    pub y0: usize,
    /// The image's width.
    pub width: usize,
}

/// One band's pixels: runs of one triangle shaded, Phong's fragments lit; `lanes` packs
/// and compares blocks of pixels ([`ResolveLanes`]). (Written once, `#[inline(always)]`
/// with all its steps; `copies` compiles it for each processor.)
#[inline(always)]
pub(super) fn resolve_band_any<L: ResolveLanes>(
    lanes: L,
    band: &BandInput<'_>,
    px: &mut [[u8; 4]],
    frags: &mut Fragments,
) -> BandCounts {
    let per_pixel = band.p.per_pixel;
    if per_pixel {
        frags.size(px.len());
    }
    let mut progress = BandProgress::default();
    for (row, row_triangles) in band.raster.chunks(band.width).enumerate() {
        let row_start = row * band.width;
        let row_px = &mut px[row_start..row_start + row_triangles.len()];
        shade_row(lanes, band, row, row_triangles, row_px, frags, &mut progress);
        // Light the fragments of the rows so far once there are enough of them, while they
        // are still in the core's nearest caches.
        if per_pixel && progress.pending >= BATCH {
            progress.light_pending(band, frags, px);
        }
    }
    if per_pixel && progress.pending > 0 {
        progress.light_pending(band, frags, px);
    }
    BandCounts { covered: progress.covered, lit: progress.lit }
}

/// Where a band's resolve stands.
#[derive(Default)]
struct BandProgress {
    /// Fragments stored and not yet lit (per-pixel shadings light them in batches).
    pending: usize,
    /// Pixels covered so far.
    covered: usize,
    /// Fragments lit in the batches so far.
    lit: usize,
}

impl BandProgress {
    /// Lights the pending fragments into the band's pixels `px`.
    #[inline(always)]
    fn light_pending(&mut self, band: &BandInput<'_>, frags: &mut Fragments, px: &mut [[u8; 4]]) {
        light_fragments(band.job.mode, band.lighter, band.p.two, frags, self.pending, px);
        (self.lit, self.pending) = (self.lit + self.pending, 0);
    }
}

/// Row `row` of the band (`row_triangles` its visibility, `row_px` its pixels), run by run:
/// the background filled, each triangle's run shaded (a per-pixel shading's fragments
/// stored, to be lit by the caller).
#[inline(always)]
fn shade_row<L: ResolveLanes>(
    lanes: L,
    band: &BandInput<'_>,
    row: usize,
    row_triangles: &[u32],
    row_px: &mut [[u8; 4]],
    frags: &mut Fragments,
    progress: &mut BandProgress,
) {
    let mut x = 0;
    while x < row_triangles.len() {
        let triangle = row_triangles[x];
        let len = run_length(lanes, &row_triangles[x..]);
        let run = Run { x, y: band.y0 + row, at: row * band.width + x, len };
        x += len;
        if triangle == NO_TRIANGLE {
            fill_px(&mut row_px[run.x..run.x + len], band.p.bg);
            continue;
        }
        progress.covered += len;
        // The memory of the triangle some pixels ahead asked for now: on a mesh of
        // triangles about a pixel large, each run is a new triangle's, read at random.
        // (Its vertices, read through it, come from a mesh whose neighbours are mostly
        // near in memory.)
        if let Some(&ahead) = row_triangles.get(x + RESOLVE_AHEAD)
            && ahead != NO_TRIANGLE
        {
            prefetch_triangle(band, ahead as usize);
        }
        progress.pending = shade_run(lanes, band, triangle as usize, &run, row_px, frags, progress.pending);
    }
}

/// Asks for the memory the resolve will read of rasterised triangle `triangle`.
#[inline(always)]
fn prefetch_triangle(band: &BandInput<'_>, triangle: usize) {
    prefetch(std::slice::from_ref(&band.setup.tris[triangle]));
}

/// A run of rasterised triangle `triangle` in `row_px`: Flat and Gouraud write its
/// pixels, the per-pixel shadings store its fragments after the `pending` ones. Returns
/// the fragments now pending.
#[inline(always)]
fn shade_run<L: ResolveLanes>(
    lanes: L,
    band: &BandInput<'_>,
    triangle: usize,
    run: &Run,
    row_px: &mut [[u8; 4]],
    frags: &mut Fragments,
    pending: usize,
) -> usize {
    let BandInput { job, setup, verts, p, .. } = *band;
    let t = &setup.tris[triangle];
    match job.mode {
        ShadingMode::FlatFace | ShadingMode::FlatProvoking => {
            let side = (t.back && p.two) as usize;
            fill_px(&mut row_px[run.x..run.x + run.len], p.face8[side][t.orig as usize]);
        }
        ShadingMode::Gouraud => {
            gouraud_run(lanes, &attributes_of(job, verts, &setup.corners, t).color, run, row_px);
        }
        ShadingMode::Phong => return phong_run(band, triangle, run, frags, pending),
        ShadingMode::FlatDerivatives => return flat_derivatives_run(band, triangle, run, frags, pending),
    }
    pending
}

/// Phong: the run's positions and normals, perspective-correct, stored as fragments after
/// the `pending` ones. Returns the fragments now pending.
#[inline(always)]
fn phong_run(band: &BandInput<'_>, triangle: usize, run: &Run, frags: &mut Fragments, pending: usize) -> usize {
    let BandInput { job, setup, verts, p, .. } = *band;
    let t = &setup.tris[triangle];
    let a = attributes_of(job, verts, &setup.corners, t);
    let edges = a.edges.row(run.x, run.y);
    for (k0, _) in run.blocks() {
        let weights = run.weights(&edges, t.inv_w, k0);
        Fragments::store(&mut frags.pos, pending + k0, &blend_n(&weights, &xyz(&a.pos)));
        Fragments::store(&mut frags.nrm, pending + k0, &blend_n(&weights, &xyz(&a.nrm)));
    }
    run.fragments(frags, pending, t.back && p.two)
}

/// The demo's Flat: the run's positions, and the face normal from the screen derivatives,
/// stored as fragments after the `pending` ones. Returns the fragments now pending.
#[inline(always)]
fn flat_derivatives_run(
    band: &BandInput<'_>,
    triangle: usize,
    run: &Run,
    frags: &mut Fragments,
    pending: usize,
) -> usize {
    let BandInput { job, setup, verts, p, .. } = *band;
    let t = &setup.tris[triangle];
    // `back`: clockwise on the screen (y up), where cross(dFdy, dFdx) is the face normal.
    let n = setup.face_normal[t.orig as usize];
    let face = if t.back { n } else { -n };
    let a = attributes_of(job, verts, &setup.corners, t);
    let edges = a.edges.row(run.x, run.y);
    flat_fragments(run, &edges, t.inv_w, &a.pos, face, frags, pending);
    run.fragments(frags, pending, t.back && p.two)
}

/// What a band's resolve did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BandCounts {
    /// Pixels covered by the mesh.
    pub covered: usize,
    /// Fragments lit (per-pixel shading), each one lighting evaluation.
    pub lit: usize,
}

/// The lighting evaluations a frame made in the resolve stage, given the fragments lit.
pub fn evaluations(job: &Job<'_>, fragments: usize) -> usize {
    match job.mode {
        ShadingMode::Phong | ShadingMode::FlatDerivatives => fragments,
        ShadingMode::FlatFace => job.mesh.triangles.len(),
        ShadingMode::Gouraud | ShadingMode::FlatProvoking => 0,
    }
}
