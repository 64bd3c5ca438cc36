//! Stage 4: each covered pixel shaded once.
//!
//! The visibility buffer holds, per pixel, the rasterised triangle. The pixels of a row go
//! in runs of one triangle: its screen-space barycentrics `l` come from its edge functions
//! ([`ScreenBarycentrics`](super::visibility::ScreenBarycentrics), exact), and its attributes are loaded once for the run.
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
//!
//! The parts: `pixels` (blocks of eight pixels to bytes), `runs` (runs of one triangle and
//! their weights), `attributes` (per triangle, once a frame), `gouraud` (colour planes),
//! `fragments` (per-pixel lighting), `picking`, `sample` (one pixel again, for the probe); this file shades a band with them.

mod attributes;
mod fragments;
mod gouraud;
mod picking;
mod pixels;
mod runs;
mod sample;

use attributes::{TriangleAttributes, triangle_attributes};
use fragments::{BATCH, flat_fragments, light_fragments};
use gouraud::gouraud_run;
use pixels::{fill_px, to_u8};
use runs::{Run, blend_n, run_length, xyz};

pub(in crate::raster::render) use attributes::Attributes;
pub(in crate::raster::render) use attributes::{attributes_chunk_any, attributes_of, seen_triangles};
pub use fragments::Fragments;
pub use gouraud::ColorPlanes;
pub(crate) use picking::original_barycentrics;
pub use pixels::LANES;
pub(in crate::raster::render) use pixels::ResolveLanes;
pub use sample::PixelSample;
pub(in crate::raster::render) use sample::{PixelInput, shade_pixel};

use super::setup::{ClippedCorners, RasterTri, Setup};
use super::{Job, NO_TRIANGLE};
use crate::model::view::ShadingMode;
use crate::numerics::copies::prefetch;

/// How many pixels ahead in a row the resolve asks for a triangle's memory.
const RESOLVE_AHEAD: usize = 12;
use crate::specialise::lighter::Lighter;

/// Per-band buffers of Phong fragments, and each rasterised triangle's attributes at its
/// three (clipped) vertices, divided by w.
#[derive(Default)]
pub struct Scratch {
    bands: Vec<Fragments>,
    pub(super) tris: TriangleAttributes,
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
/// chunk at a time through `attributes` (a copy of [`attributes_chunk_any`]). With
/// `kept_seen` (the triangles, and their vertices' positions and normals, are the last
/// frame's, bit for bit, and so is its visibility, which shows the triangles whose bits
/// are set: [`seen_triangles`]), only Gouraud's, the colours, are made again, and only
/// for the triangles seen: the others read only the geometry.
pub(super) fn prepare(
    job: &Job<'_>,
    setup: &Setup,
    scratch: &mut Scratch,
    bands: usize,
    kept_seen: Option<&[u64]>,
    attributes: impl Fn(&[RasterTri], &ClippedCorners, Attributes<'_>) + Sync,
) -> Prepared {
    let bg = job.background.map(to_u8);
    // Shadings that light each pixel: Phong, and Flat with the demo's derivative normals.
    let per_pixel = job.mode.per_fragment();
    scratch.bands.resize_with(bands, Fragments::default);
    if job.mode != ShadingMode::FlatFace && (job.mode == ShadingMode::Gouraud || kept_seen.is_none()) {
        triangle_attributes(setup, &mut scratch.tris, kept_seen, attributes);
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
pub fn split(scratch: &mut Scratch) -> (&TriangleAttributes, &mut [Fragments]) {
    (&scratch.tris, &mut scratch.bands)
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
    /// The per-triangle attributes ([`split`]): the front faces'; a back face's are
    /// computed where it wins a pixel, from the vertices.
    pub shared: &'a TriangleAttributes,
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
/// and compares blocks of pixels ([`ResolveLanes`]). (Written once, `#[inline(always)]`;
/// `copies` compiles it for each processor.)
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lane loops: see `blend`
pub(super) fn resolve_band_any<L: ResolveLanes>(
    lanes: L,
    band: &BandInput<'_>,
    px: &mut [[u8; 4]],
    frags: &mut Fragments,
) -> BandCounts {
    let BandInput { job, setup, lighter, p, shared, verts, raster, y0, width } = *band;
    let (two, per_pixel, bg) = (p.two, p.per_pixel, p.bg);
    let (tri_color, tri_pos, tri_nrm) = (&shared.color, &shared.pos, &shared.nrm);
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
            // The memory of the triangle some pixels ahead asked for now: on a mesh of
            // triangles about a pixel large, each run is a new triangle's, read at random.
            if let Some(&ahead) = r_row.get(x + RESOLVE_AHEAD)
                && ahead != NO_TRIANGLE
            {
                let a = ahead as usize;
                prefetch(std::slice::from_ref(&setup.tris[a]));
                match job.mode {
                    ShadingMode::Gouraud => prefetch(&tri_color[a..=a]),
                    ShadingMode::Phong | ShadingMode::FlatDerivatives => {
                        prefetch(&shared.edges[a..=a]);
                        prefetch(&tri_pos[a..=a]);
                        prefetch(&tri_nrm[a..=a]);
                    }
                    ShadingMode::FlatFace => {}
                }
            }
            let t = &setup.tris[r as usize];
            let side = (t.back && two) as usize;
            let r = r as usize;
            match job.mode {
                ShadingMode::FlatFace => fill_px(&mut px_row[run.x..run.x + len], p.face8[side][t.orig as usize]),
                ShadingMode::Gouraud if t.back => {
                    gouraud_run(lanes, &attributes_of(job, verts, &setup.corners, t).color, &run, px_row)
                }
                ShadingMode::Gouraud => gouraud_run(lanes, &tri_color[r], &run, px_row),
                ShadingMode::Phong => {
                    let own = t.back.then(|| attributes_of(job, verts, &setup.corners, t));
                    let (edges, pw, nw) = match &own {
                        Some(a) => (&a.edges, &a.pos, &a.nrm),
                        None => (&shared.edges[r], &tri_pos[r], &tri_nrm[r]),
                    };
                    let edges = edges.row(run.x, run.y);
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
                    let own = t.back.then(|| attributes_of(job, verts, &setup.corners, t));
                    let (edges, pw) = match &own {
                        Some(a) => (&a.edges, &a.pos),
                        None => (&shared.edges[r], &tri_pos[r]),
                    };
                    let edges = edges.row(run.x, run.y);
                    flat_fragments(&run, &edges, t.inv_w, pw, face, frags, m);
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
    BandCounts { covered, lit }
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
        ShadingMode::Gouraud => 0,
    }
}
