//! Stage 4: each covered pixel shaded once.
//!
//! The visibility buffer holds, per pixel, the rasterised triangle and its screen-space
//! barycentrics. Attributes vary linearly in clip space, not on the screen, so they are
//! interpolated perspective-correctly: `b_i = (l_i / w_i) / sum_j (l_j / w_j)`. Those are
//! mapped back to the original mesh triangle through its clipped vertices' barycentrics.
//!
//! - Gouraud: the vertices' colours (each clamped as OpenGL clamps vertex colours).
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

use super::raster::BAND;
use super::setup::Setup;
use super::vertices::Vertices;
use super::{Image, Job, NO_TRIANGLE};
use crate::specialised::Lighter;
use crate::view::{FlatNormal, Shading};

/// Per-band buffers of Phong fragments, and each rasterised triangle's attributes at its
/// three (clipped) vertices, divided by w.
#[derive(Default)]
pub struct Scratch {
    bands: Vec<Fragments>,
    /// Gouraud: the colours of the triangle's side at its vertices, times 1/w.
    tri_color: Vec<[[f32; 4]; 3]>,
    /// Phong and the demo's Flat: eye-space positions at the vertices, times 1/w.
    tri_pos: Vec<[Vec3; 3]>,
    /// Phong: (unnormalised) normals at the vertices, times 1/w.
    tri_nrm: Vec<[Vec3; 3]>,
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
/// triangle's through the clipped vertices' barycentrics and multiplied by 1/w: computed once
/// per triangle, so a pixel blends three values instead of mapping its barycentrics back.
fn triangle_attributes(job: &Job<'_>, verts: &Vertices, setup: &Setup, scratch: &mut Scratch) {
    let tris = &job.mesh.triangles;
    let two = job.scene.light_model.two_sided;
    let blend3 = |t: &super::setup::RasterTri, a: &dyn Fn(usize) -> Vec3| -> [Vec3; 3] {
        let v = tris[t.orig as usize];
        let at = [a(v[0] as usize), a(v[1] as usize), a(v[2] as usize)];
        std::array::from_fn(|k| (at[0] * t.bary[k][0] + at[1] * t.bary[k][1] + at[2] * t.bary[k][2]) * t.inv_w[k])
    };
    match job.shading {
        Shading::Gouraud => {
            scratch.tri_color.clear();
            scratch.tri_color.extend(setup.tris.iter().map(|t| {
                let side = (t.back && two) as usize;
                let v = tris[t.orig as usize];
                let cs = v.map(|i| verts.color[side][i as usize]);
                std::array::from_fn(|k| {
                    let b = t.bary[k];
                    std::array::from_fn(|ch| (cs[0][ch] * b[0] + cs[1][ch] * b[1] + cs[2][ch] * b[2]) * t.inv_w[k])
                })
            }));
        }
        Shading::Phong => {
            scratch.tri_pos.clear();
            scratch.tri_nrm.clear();
            scratch.tri_pos.extend(setup.tris.iter().map(|t| blend3(t, &|i| verts.eye[i])));
            scratch.tri_nrm.extend(setup.tris.iter().map(|t| blend3(t, &|i| verts.normal[i])));
        }
        Shading::Flat => {
            scratch.tri_pos.clear();
            scratch.tri_pos.extend(setup.tris.iter().map(|t| blend3(t, &|i| verts.eye[i])));
        }
    }
}

/// One band's Phong fragments.
#[derive(Default)]
pub struct Fragments {
    pixel: Vec<u32>,
    back: Vec<bool>,
    pos: Vec<Vec3>,
    nrm: Vec<Vec3>,
    front_out: Vec<[f32; 4]>,
    back_out: Vec<[f32; 4]>,
}

#[inline(always)]
#[allow(clippy::manual_clamp)] // clamp keeps NaN; max/min turn it into 0, which the cast below needs
fn to_u8(c: f32) -> u8 {
    // max/min (IEEE maxNum/minNum) also turn NaN into 0, so v is in [0.5, 255.5].
    let v = c.max(0.0).min(1.0) * 255.0 + 0.5;
    // SAFETY: v is finite and within u32's range (see above).
    unsafe { v.to_int_unchecked::<u32>() as u8 }
}

/// Perspective-correct barycentrics of the original mesh triangle at pixel `i`.
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

/// The original triangle's barycentrics at pixel `i` of the last frame (for picking).
pub(crate) fn original_barycentrics(setup: &Setup, image: &Image, i: usize) -> Option<[f32; 3]> {
    let r = *image.raster.get(i)?;
    (r != NO_TRIANGLE).then(|| barycentrics(setup, r, image.bary[i]))
}

/// What every band's resolve shares, computed once per frame ([`prepare`]).
pub struct Prepared {
    bg: [u8; 4],
    two: bool,
    per_pixel: bool,
    /// Flat: each face's colour in 8 bits, per side.
    face8: [Vec<[u8; 4]>; 2],
}

/// The frame's shared resolve state; fills the per-triangle attributes in `scratch`.
pub fn prepare(job: &Job<'_>, verts: &Vertices, setup: &Setup, scratch: &mut Scratch, bands: usize) -> Prepared {
    let bg = job.background.map(to_u8);
    // Shadings that light each pixel: Phong, and Flat with the demo's derivative normals.
    let per_pixel = job.shading == Shading::Phong
        || (job.shading == Shading::Flat && job.flat_normal == FlatNormal::ScreenDerivatives);
    scratch.bands.resize_with(bands, Fragments::default);
    if job.shading != Shading::Flat || per_pixel {
        triangle_attributes(job, verts, setup, scratch);
    }
    // Flat: each face's colour converted to 8 bits once.
    let face8: [Vec<[u8; 4]>; 2] = if job.shading == Shading::Flat && !per_pixel {
        [0, 1].map(|side| setup.face_color[side].iter().map(|c| c.map(to_u8)).collect())
    } else {
        [Vec::new(), Vec::new()]
    };
    Prepared { bg: [bg[0], bg[1], bg[2], 255], two: job.scene.light_model.two_sided, per_pixel, face8 }
}

/// The per-triangle attributes and the per-band fragment buffers, split so that each band
/// borrows its own fragments while all share the attributes.
pub fn split(scratch: &mut Scratch) -> (Shared<'_>, &mut [Fragments]) {
    (Shared { tri_color: &scratch.tri_color, tri_pos: &scratch.tri_pos, tri_nrm: &scratch.tri_nrm }, &mut scratch.bands)
}

/// The per-triangle attributes, read by every band.
pub struct Shared<'a> {
    tri_color: &'a [[[f32; 4]; 3]],
    tri_pos: &'a [[Vec3; 3]],
    tri_nrm: &'a [[Vec3; 3]],
}

/// Shades one band: `px` its pixels, `raster` and `bary` its visibility buffer. Returns the
/// lighting evaluations made (fragments lit).
#[allow(clippy::too_many_arguments)]
pub fn resolve_band(
    job: &Job<'_>,
    setup: &Setup,
    lighter: &Lighter,
    p: &Prepared,
    shared: &Shared<'_>,
    px: &mut [[u8; 4]],
    raster: &[u32],
    bary: &[[f32; 2]],
    frags: &mut Fragments,
) -> usize {
    let (two, per_pixel, bg) = (p.two, p.per_pixel, p.bg);
    let (tri_color, tri_pos, tri_nrm) = (shared.tri_color, shared.tri_pos, shared.tri_nrm);
    frags.pixel.clear();
    frags.back.clear();
    frags.pos.clear();
    frags.nrm.clear();
    if per_pixel {
        for v in [&mut frags.pos, &mut frags.nrm] {
            v.reserve(px.len());
        }
        frags.pixel.reserve(px.len());
        frags.back.reserve(px.len());
    }
    for (k, (out, &r)) in px.iter_mut().zip(raster).enumerate() {
        if r == NO_TRIANGLE {
            *out = bg;
            continue;
        }
        let t = &setup.tris[r as usize];
        let side = (t.back && two) as usize;
        match job.shading {
            Shading::Flat if per_pixel => {
                let (ls, s) = screen_weights(t.inv_w, bary[k]);
                let pw = &tri_pos[r as usize];
                let p = (pw[0] * ls[0] + pw[1] * ls[1] + pw[2] * ls[2]) * s;
                // `back`: clockwise on the screen (y up), where cross(dFdy, dFdx) is the face normal.
                let n = setup.face_normal[t.orig as usize];
                frags.pixel.push(k as u32);
                frags.back.push(side == 1);
                frags.pos.push(p);
                frags.nrm.push(if t.back { n } else { -n });
            }
            Shading::Flat => *out = p.face8[side][t.orig as usize],
            Shading::Gouraud => {
                let (ls, s) = screen_weights(t.inv_w, bary[k]);
                let cw = &tri_color[r as usize];
                let c = |ch: usize| to_u8((cw[0][ch] * ls[0] + cw[1][ch] * ls[1] + cw[2][ch] * ls[2]) * s);
                *out = [c(0), c(1), c(2), c(3)];
            }
            Shading::Phong => {
                let (ls, s) = screen_weights(t.inv_w, bary[k]);
                let (pw, nw) = (&tri_pos[r as usize], &tri_nrm[r as usize]);
                let p = (pw[0] * ls[0] + pw[1] * ls[1] + pw[2] * ls[2]) * s;
                let nv = (nw[0] * ls[0] + nw[1] * ls[1] + nw[2] * ls[2]) * s;
                frags.pixel.push(k as u32);
                frags.back.push(side == 1);
                frags.pos.push(p);
                frags.nrm.push(nv);
            }
        }
    }
    if per_pixel && !frags.pixel.is_empty() {
        let m = frags.pixel.len();
        frags.front_out.resize(m, [0.0; 4]);
        frags.back_out.resize(m, [0.0; 4]);
        let back_out = if two { Some(&mut frags.back_out[..]) } else { None };
        if job.shading == Shading::Phong {
            // The interpolated normals are renormalised inside (in vectorised chunks).
            lighter.light_batch_eye_sum_normalizing(&frags.pos, &frags.nrm, &mut frags.front_out, back_out);
        } else {
            // Face normals are unit already.
            lighter.light_batch_eye_sum(&frags.pos, &frags.nrm, &mut frags.front_out, back_out);
        }
        for j in 0..m {
            let c = if frags.back[j] { frags.back_out[j] } else { frags.front_out[j] };
            px[frags.pixel[j] as usize] = c.map(to_u8);
        }
    }
    frags.pixel.len()
}

/// The lighting evaluations a frame made in the resolve stage, given the fragments lit.
pub fn evaluations(job: &Job<'_>, fragments: usize) -> usize {
    match job.shading {
        Shading::Phong => fragments,
        Shading::Flat if job.flat_normal == FlatNormal::ScreenDerivatives => fragments,
        Shading::Flat => job.mesh.triangles.len(),
        Shading::Gouraud => 0,
    }
}

/// Shades every covered pixel (band by band on all cores); returns the number of lighting
/// evaluations made here.
pub fn resolve(
    job: &Job<'_>,
    verts: &Vertices,
    setup: &Setup,
    lighter: &Lighter,
    image: &mut Image,
    scratch: &mut Scratch,
) -> usize {
    let rows = image.width * BAND;
    let p = prepare(job, verts, setup, scratch, image.height.div_ceil(BAND));
    let (shared, bands) = split(scratch);
    let (raster, bary) = (&image.raster, &image.bary);
    let lit: usize = image
        .rgba
        .par_chunks_mut(rows * 4)
        .zip(bands.par_iter_mut())
        .enumerate()
        .map(|(b, (rgba, frags))| {
            let start = b * rows;
            let (px, _) = rgba.as_chunks_mut::<4>();
            let n = px.len();
            resolve_band(
                job,
                setup,
                lighter,
                &p,
                &shared,
                px,
                &raster[start..start + n],
                &bary[start..start + n],
                frags,
            )
        })
        .sum();
    evaluations(job, lit)
}
