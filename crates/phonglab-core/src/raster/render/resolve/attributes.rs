//! A rasterised triangle's attributes at its three (clipped) vertices: mapped from the
//! original triangle's through the clipped vertices' barycentrics and divided by w, so that
//! a pixel blends three values (or, for Gouraud, steps planes) instead of mapping its
//! barycentrics back. Made by the resolve for each run of a triangle it meets
//! ([`attributes_of`]), not for every triangle beforehand: on a million triangles about a
//! pixel large most are met once or twice, many never (hidden, or between pixel centres),
//! and a pass over all of them, stored and read back at random, cost more than making them
//! again per run (measured in docs/performance.md, "A million triangles").

use super::gouraud::ColorPlanes;
use crate::model::view::ShadingMode;
use crate::raster::render::Job;
use crate::raster::render::setup::{ClippedCorners, RasterTri};
use crate::raster::render::vertices::Vertices;
use crate::raster::render::visibility::ScreenBarycentrics;
use glam::Vec3;

/// Triangles a word-aligned chunk of [`seen_triangles`] holds (a multiple of 64).
const GRAIN: usize = 256;

/// A bit for each of `triangles` rasterised triangles, set where `visibility` (the
/// triangle at each pixel) shows it: whole words for every chunk of [`GRAIN`].
pub(in crate::raster::render) fn seen_triangles(visibility: &[u32], triangles: usize) -> Vec<u64> {
    let mut seen = vec![0u64; triangles.div_ceil(GRAIN) * GRAIN / 64];
    for &t in visibility {
        crate::raster::render::mask::set(&mut seen, t as usize);
    }
    seen
}

/// One triangle's attributes, those the shading reads (the others left at zero).
#[derive(Clone, Copy, Default)]
pub(in crate::raster::render) struct OneTriangle {
    pub(in crate::raster::render) color: ColorPlanes,
    pub(in crate::raster::render) edges: ScreenBarycentrics,
    pub(in crate::raster::render) pos: [Vec3; 3],
    pub(in crate::raster::render) nrm: [Vec3; 3],
}

/// The attributes of raster triangle `t`, those the shading reads: made for each run the
/// resolve shades, and again, by the same operations (so to the same bits), for the probe.
#[inline(always)]
pub(in crate::raster::render) fn attributes_of(
    job: &Job<'_>,
    verts: &Vertices,
    corners: &ClippedCorners,
    t: &RasterTri,
) -> OneTriangle {
    let tris = &job.mesh.triangles;
    let bary = corners.of(t);
    let two = job.scene.light_model.two_sided;
    let blend3 = |a: &[Vec3]| -> [Vec3; 3] {
        let v = tris[t.orig as usize];
        let at = [a[v[0] as usize], a[v[1] as usize], a[v[2] as usize]];
        std::array::from_fn(|k| (at[0] * bary[k][0] + at[1] * bary[k][1] + at[2] * bary[k][2]) * t.inv_w[k])
    };
    let color = || -> [[f32; 4]; 3] {
        let side = (t.back && two) as usize;
        let v = tris[t.orig as usize];
        let vc = &verts.color[side];
        let cs = [vc[v[0] as usize], vc[v[1] as usize], vc[v[2] as usize]];
        std::array::from_fn(|k| {
            let b = bary[k];
            std::array::from_fn(|ch| (cs[0][ch] * b[0] + cs[1][ch] * b[1] + cs[2][ch] * b[2]) * t.inv_w[k])
        })
    };
    let mut out = OneTriangle::default();
    match job.mode {
        ShadingMode::Gouraud => out.color = ColorPlanes::new(t, color()),
        ShadingMode::Phong => {
            out.edges = ScreenBarycentrics::new(t);
            (out.pos, out.nrm) = (blend3(&verts.eye), blend3(&verts.normal));
        }
        ShadingMode::FlatDerivatives => {
            out.edges = ScreenBarycentrics::new(t);
            out.pos = blend3(&verts.eye);
        }
        // One colour a face, from setup: no attributes.
        ShadingMode::FlatFace | ShadingMode::FlatProvoking => {}
    }
    out
}
