//! Each rasterised triangle's attributes at its three (clipped) vertices, set up once a
//! frame: mapped from the original triangle's through the clipped vertices' barycentrics
//! and divided by w, so that a pixel blends three values (or, for Gouraud, steps planes)
//! instead of mapping its barycentrics back.

use glam::Vec3;
use rayon::prelude::*;

use super::gouraud::ColorPlanes;
use crate::model::view::ShadingMode;
use crate::raster::render::Job;
use crate::raster::render::setup::{ClippedCorners, RasterTri, Setup};
use crate::raster::render::vertices::Vertices;
use crate::raster::render::visibility::ScreenBarycentrics;

/// Each rasterised triangle's attributes (only those the shading reads are written).
#[derive(Default)]
pub struct TriangleAttributes {
    /// Gouraud: the colours of the triangle's side times 1/w, and 1/w, as screen planes.
    pub(super) color: Vec<ColorPlanes>,
    /// Phong and the demo's Flat: eye-space positions at the vertices, times 1/w.
    pub(super) pos: Vec<[Vec3; 3]>,
    /// Phong: (unnormalised) normals at the vertices, times 1/w.
    pub(super) nrm: Vec<[Vec3; 3]>,
    /// Each triangle's edge functions, set up once a frame rather than once a run.
    pub(super) edges: Vec<ScreenBarycentrics>,
}

/// Each rasterised triangle's attributes at its three vertices, mapped from the original
/// triangle's through the clipped vertices' barycentrics and multiplied by 1/w, and (for
/// Phong and Flat) its edge functions; for Gouraud, its colour planes ([`ColorPlanes`]):
/// computed once per triangle, so a pixel blends three values (or steps planes) instead
/// of mapping its barycentrics back. One pass over chunks of triangles on both threads
/// (each result depends on its triangle alone).
/// `attributes` does one chunk (a copy of [`attributes_chunk_any`] for this processor).
/// With `seen` (a bit a triangle, [`seen_triangles`]), only the triangles seen at some
/// pixel are done: the others' attributes are never read.
pub(super) fn triangle_attributes(
    setup: &Setup,
    mode: ShadingMode,
    out: &mut TriangleAttributes,
    seen: Option<&[u64]>,
    attributes: impl Fn(&[RasterTri], &ClippedCorners, Attributes<'_>) + Sync,
) {
    // The arrays the shading reads sized to the triangles (their capacity kept from frame
    // to frame), the others empty: Gouraud's colour planes alone are 136 bytes a triangle
    // of the 280 all four would take.
    let n = setup.tris.len();
    let [color, edges, pos, nrm] = match mode {
        ShadingMode::Gouraud => [n, 0, 0, 0],
        ShadingMode::Phong => [0, n, n, n],
        ShadingMode::FlatDerivatives => [0, n, n, 0],
        ShadingMode::FlatFace | ShadingMode::FlatProvoking => [0; 4],
    };
    out.color.resize(color, ColorPlanes::default());
    out.edges.resize(edges, ScreenBarycentrics::default());
    out.pos.resize(pos, [Vec3::ZERO; 3]);
    out.nrm.resize(nrm, [Vec3::ZERO; 3]);
    let chunks = n.div_ceil(GRAIN);
    setup
        .tris
        .par_chunks(GRAIN)
        .zip(chunks_or_empty(&mut out.edges, chunks))
        .zip(chunks_or_empty(&mut out.color, chunks))
        .zip(chunks_or_empty(&mut out.pos, chunks))
        .zip(chunks_or_empty(&mut out.nrm, chunks))
        .enumerate()
        .for_each(|(k, ((((ts, edges), colors), pos), nrm))| {
            let seen = seen.and_then(|s| s.get(k * GRAIN / 64..(k + 1) * GRAIN / 64));
            attributes(ts, &setup.corners, Attributes { edges, colors, pos, nrm, seen });
        });
}

/// `v` in chunks of [`GRAIN`], or `chunks` empty slices where the shading does not read
/// it (left empty): the zip of every array then still meets each chunk of triangles.
fn chunks_or_empty<T: Send>(v: &mut [T], chunks: usize) -> impl IndexedParallelIterator<Item = &mut [T]> {
    if v.is_empty() {
        rayon::iter::Either::Left(rayon::iter::repeat_n((), chunks).map(|()| <&mut [T]>::default()))
    } else {
        rayon::iter::Either::Right(v.par_chunks_mut(GRAIN))
    }
}

/// Triangles a chunk of the attributes takes (a multiple of 64: a chunk's bits of
/// [`seen_triangles`] are whole words).
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

/// Where one chunk of triangles' attributes go ([`triangle_attributes`]).
pub(in crate::raster::render) struct Attributes<'a> {
    pub(in crate::raster::render) edges: &'a mut [ScreenBarycentrics],
    pub(in crate::raster::render) colors: &'a mut [ColorPlanes],
    pub(in crate::raster::render) pos: &'a mut [[Vec3; 3]],
    pub(in crate::raster::render) nrm: &'a mut [[Vec3; 3]],
    /// A bit for each triangle of the chunk: only those set are done (all, if `None`).
    pub(in crate::raster::render) seen: Option<&'a [u64]>,
}

/// One triangle's attributes, those the shading reads (the others left at zero).
#[derive(Clone, Copy, Default)]
pub(in crate::raster::render) struct OneTriangle {
    pub(in crate::raster::render) color: ColorPlanes,
    pub(in crate::raster::render) edges: ScreenBarycentrics,
    pub(in crate::raster::render) pos: [Vec3; 3],
    pub(in crate::raster::render) nrm: [Vec3; 3],
}

/// The attributes of raster triangle `t`: what [`attributes_chunk_any`] stores for a front
/// face, and what the resolve computes where a back face wins a pixel (the same operations,
/// so the same bits).
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

/// The attributes of triangles `ts` (a chunk) into `out`: the front faces'. A back face's
/// are computed only where it wins a pixel ([`attributes_of`], by the resolve): on a closed
/// surface, about half the triangles are back faces and almost none of them is seen.
/// (Written once, `#[inline(always)]`; `copies` compiles it for each processor.)
#[inline(always)]
pub(in crate::raster::render) fn attributes_chunk_any(
    job: &Job<'_>,
    verts: &Vertices,
    ts: &[RasterTri],
    corners: &ClippedCorners,
    out: Attributes<'_>,
) {
    let Attributes { edges, colors, pos, nrm, seen } = out;
    let wanted = |i: usize| seen.is_none_or(|s| crate::raster::render::mask::is_set(s, i));
    for (i, t) in ts.iter().enumerate().filter(|(i, t)| !t.back && wanted(*i)) {
        let a = attributes_of(job, verts, corners, t);
        match job.mode {
            ShadingMode::Gouraud => colors[i] = a.color,
            ShadingMode::Phong => (edges[i], pos[i], nrm[i]) = (a.edges, a.pos, a.nrm),
            ShadingMode::FlatDerivatives => (edges[i], pos[i]) = (a.edges, a.pos),
            ShadingMode::FlatFace | ShadingMode::FlatProvoking => {}
        }
    }
}

impl TriangleAttributes {
    /// Raster triangle `r`'s attributes (`t`): stored for a front face, computed for a back
    /// face ([`attributes_chunk_any`]).
    #[inline(always)]
    pub(in crate::raster::render) fn of(
        &self,
        job: &Job<'_>,
        verts: &Vertices,
        corners: &ClippedCorners,
        r: usize,
        t: &RasterTri,
    ) -> Option<OneTriangle> {
        if t.back {
            return Some(attributes_of(job, verts, corners, t));
        }
        let mut a = OneTriangle::default();
        match job.mode {
            ShadingMode::Gouraud => a.color = *self.color.get(r)?,
            ShadingMode::Phong => (a.edges, a.pos, a.nrm) = (*self.edges.get(r)?, *self.pos.get(r)?, *self.nrm.get(r)?),
            ShadingMode::FlatDerivatives => (a.edges, a.pos) = (*self.edges.get(r)?, *self.pos.get(r)?),
            ShadingMode::FlatFace | ShadingMode::FlatProvoking => {}
        }
        Some(a)
    }
}
