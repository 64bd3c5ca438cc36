//! One pixel of the last frame shaded again, alone, by the resolve's own arithmetic: the
//! same f32 operations in the same order as the band that drew it, so the same bits (the
//! probe's value is the rendered pixel, not an estimate of it).
//!
//! - Gouraud steps colour planes from the start of the pixel's run (`ColorPlanes::row`),
//!   so the run is found in the pixel's row first: the pixel is block `k0` lane `j` of it.
//! - Phong and the demo's Flat interpolate position (and normal) with the pixel's own
//!   weights (they do not depend on the run: `block_weights_are_the_pixels_weights`), then
//!   light that one fragment through the specialised lighter, as a batch of one.
//! - Flat takes the face's colour.

use glam::Vec3;

use super::attributes::attributes_of;
use super::gouraud::gouraud_block;
use super::pixels::{LANES, to_u8};
use super::runs::{Run, blend_n, xyz};
use crate::model::view::ShadingMode;
use crate::raster::render::Job;
use crate::raster::render::setup::Setup;
use crate::specialise::lighter::{EyeArrays, Lighter};

/// What the resolve computed at one pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelSample {
    /// The rasterised (clipped) triangle.
    pub raster: u32,
    /// The mesh triangle.
    pub triangle: usize,
    /// It faces away from the viewer.
    pub back: bool,
    /// The side whose colours it shows: 1 (back) only with two-sided lighting.
    pub side: usize,
    /// The perspective-correct barycentrics of the mesh triangle's vertices at the pixel.
    pub barycentrics: [f32; 3],
    /// The colour the resolve converted to 8 bits (f32, before the clamp).
    pub colour: [f32; 4],
    /// The pixel as stored: `round(255 clamp(colour, 0, 1))`.
    pub rgba8: [u8; 4],
    /// Gouraud: the first pixel (x) of the pixel's run, where its planes start.
    pub run_start: Option<usize>,
    /// Phong and the demo's Flat: the interpolated eye-space position.
    pub position: Option<Vec3>,
    /// Phong: the interpolated normal before it is normalised; the demo's Flat: the face's.
    pub normal: Option<Vec3>,
}

/// What shading one pixel again reads: the frame's job, triangles, lighting plan and
/// vertices, and the visibility of the pixel's row.
pub(in crate::raster::render) struct PixelInput<'a> {
    pub(in crate::raster::render) job: &'a Job<'a>,
    pub(in crate::raster::render) setup: &'a Setup,
    pub(in crate::raster::render) lighter: &'a Lighter,
    /// The frame's vertices (the triangle's attributes are made from them).
    pub(in crate::raster::render) verts: &'a crate::raster::render::vertices::Vertices,
    /// The rasterised triangle at each pixel of row `y`.
    pub(in crate::raster::render) row: &'a [u32],
}

/// Pixel (`x`, `y`), covered by rasterised triangle `row[x]`, shaded as the resolve shaded it.
pub(in crate::raster::render) fn shade_pixel(input: &PixelInput<'_>, x: usize, y: usize) -> Option<PixelSample> {
    let PixelInput { job, setup, lighter, verts, row } = *input;
    let r = *row.get(x)?;
    let t = setup.tris.get(r as usize)?;
    let two = job.scene.light_model.two_sided;
    let side = (t.back && two) as usize;
    let barycentrics = super::picking::original_barycentrics(setup, r, x, y)?;
    let mut out = PixelSample {
        raster: r,
        triangle: t.orig as usize,
        back: t.back,
        side,
        barycentrics,
        colour: [0.0; 4],
        rgba8: [0; 4],
        run_start: None,
        position: None,
        normal: None,
    };
    // The triangle's attributes as the resolve made them; none where the frame made no
    // vertex colours for them (a frame drawn in another shading than Gouraud).
    let coloured = verts.color[side].len() == job.mesh.positions.len();
    let attributes = (!job.mode.per_face() && (job.mode != ShadingMode::Gouraud || coloured))
        .then(|| attributes_of(job, verts, &setup.corners, t));
    out.colour = match job.mode {
        ShadingMode::FlatFace | ShadingMode::FlatProvoking => *setup.face_color[side].get(out.triangle)?,
        ShadingMode::Gouraud => {
            // The run: back along the row while the triangle stays the same.
            let start = row[..x].iter().rposition(|&q| q != r).map_or(0, |p| p + 1);
            let (start_planes, step) = attributes?.color.row(start, y);
            let k = x - start;
            let block = gouraud_block(&start_planes, &step, k - k % LANES);
            out.run_start = Some(start);
            block.map(|c| c[k % LANES])
        }
        ShadingMode::Phong | ShadingMode::FlatDerivatives => {
            let run = Run { x, y, at: 0, len: 1 };
            let a = attributes?;
            let edges = a.edges.row(x, y);
            let wt = run.weights(&edges, t.inv_w, 0);
            let pos = blend_n(&wt, &xyz(&a.pos)).map(|c| c[0]);
            let nrm = if job.mode == ShadingMode::Phong {
                blend_n(&wt, &xyz(&a.nrm)).map(|c| c[0])
            } else {
                let n = setup.face_normal[out.triangle];
                (if t.back { n } else { -n }).to_array()
            };
            out.position = Some(Vec3::from_array(pos));
            out.normal = Some(Vec3::from_array(nrm));
            light_one(lighter, job.mode, two, side, pos, nrm)
        }
    };
    out.rgba8 = out.colour.map(to_u8);
    Some(out)
}

/// One fragment lit as `light_fragments` lights a batch: through the lighter's arrays,
/// Phong's normal renormalised inside.
fn light_one(lighter: &Lighter, mode: ShadingMode, two: bool, side: usize, pos: [f32; 3], nrm: [f32; 3]) -> [f32; 4] {
    let (p, n) = (pos.map(|c| [c]), nrm.map(|c| [c]));
    let arrays = EyeArrays { pos: p.each_ref().map(|a| &a[..]), nrm: n.each_ref().map(|a| &a[..]) };
    let (mut front, mut back) = ([[0.0f32; 4]], [[0.0f32; 4]]);
    lighter.light_arrays_eye_sum(arrays, mode == ShadingMode::Phong, &mut front, two.then_some(&mut back[..]));
    if side == 1 { back[0] } else { front[0] }
}
