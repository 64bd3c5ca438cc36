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

/// Per-band buffers of Phong fragments.
#[derive(Default)]
pub struct Scratch {
    bands: Vec<Fragments>,
}

#[derive(Default)]
struct Fragments {
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

/// Shades every covered pixel; returns the number of lighting evaluations made here.
pub fn resolve(
    job: &Job<'_>,
    verts: &Vertices,
    setup: &Setup,
    lighter: &Lighter,
    image: &mut Image,
    scratch: &mut Scratch,
) -> usize {
    let width = image.width;
    let rows = width * BAND;
    let bg = job.background.map(to_u8);
    let tris = &job.mesh.triangles;
    let two = job.scene.light_model.two_sided;
    // Shadings that light each pixel: Phong, and Flat with the demo's derivative normals.
    let per_pixel = job.shading == Shading::Phong
        || (job.shading == Shading::Flat && job.flat_normal == FlatNormal::ScreenDerivatives);
    let bands = image.height.div_ceil(BAND);
    scratch.bands.resize_with(bands, Fragments::default);
    let (raster, bary) = (&image.raster, &image.bary);
    // Flat: each face's colour converted to 8 bits once.
    let face8: [Vec<[u8; 4]>; 2] = if job.shading == Shading::Flat && !per_pixel {
        [0, 1].map(|side| setup.face_color[side].iter().map(|c| c.map(to_u8)).collect())
    } else {
        [Vec::new(), Vec::new()]
    };
    let bg = [bg[0], bg[1], bg[2], 255];
    image.rgba.par_chunks_mut(rows * 4).zip(scratch.bands.par_iter_mut()).enumerate().for_each(|(b, (rgba, frags))| {
        let start = b * rows;
        let (px, _) = rgba.as_chunks_mut::<4>();
        let raster = &raster[start..start + px.len()];
        let bary = &bary[start..start + px.len()];
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
                    let w = barycentrics(setup, r, bary[k]);
                    let v = tris[t.orig as usize];
                    let p = verts.eye[v[0] as usize] * w[0]
                        + verts.eye[v[1] as usize] * w[1]
                        + verts.eye[v[2] as usize] * w[2];
                    // `back`: clockwise on the screen (y up), where cross(dFdy, dFdx) is the face normal.
                    let n = setup.face_normal[t.orig as usize];
                    frags.pixel.push(k as u32);
                    frags.back.push(side == 1);
                    frags.pos.push(p);
                    frags.nrm.push(if t.back { n } else { -n });
                }
                Shading::Flat => *out = face8[side][t.orig as usize],
                Shading::Gouraud => {
                    let w = barycentrics(setup, r, bary[k]);
                    let v = tris[t.orig as usize];
                    let cs = v.map(|i| verts.color[side][i as usize]);
                    let c = |ch: usize| to_u8(cs[0][ch] * w[0] + cs[1][ch] * w[1] + cs[2][ch] * w[2]);
                    *out = [c(0), c(1), c(2), c(3)];
                }
                Shading::Phong => {
                    let w = barycentrics(setup, r, bary[k]);
                    let v = tris[t.orig as usize];
                    let p = verts.eye[v[0] as usize] * w[0]
                        + verts.eye[v[1] as usize] * w[1]
                        + verts.eye[v[2] as usize] * w[2];
                    let nv = verts.normal[v[0] as usize] * w[0]
                        + verts.normal[v[1] as usize] * w[1]
                        + verts.normal[v[2] as usize] * w[2];
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
    });
    match job.shading {
        Shading::Phong => scratch.bands.iter().map(|f| f.pixel.len()).sum(),
        Shading::Flat if per_pixel => scratch.bands.iter().map(|f| f.pixel.len()).sum(),
        Shading::Flat => tris.len(),
        Shading::Gouraud => 0,
    }
}
