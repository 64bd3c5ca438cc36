//! The renderer as a student reads it, top to bottom: no SIMD, no threads, no `unsafe`.
//!
//! For each triangle of the mesh:
//! 1. its corners to clip space (`clip_from_object`), then to window coordinates: x and y
//!    in fixed point with 8 fractional bits, y down, depth in [0, 1], and 1/w
//!    ([`to_window`], the fast renderer's own, so both snap every corner alike);
//! 2. facing: front where the corners turn counter-clockwise as OpenGL sees them (y up);
//! 3. the bounding box of its pixels, and for each pixel centre the three edge
//!    functions, inside when all are >= 0 with the top-left rule deciding a centre exactly
//!    on an edge;
//! 4. the barycentrics (each edge function over the doubled area), made
//!    perspective-correct by dividing each by its corner's w;
//! 5. the depth test (less than what the pixel holds);
//! 6. the colour, lit by `Engine<f64>`: per vertex and interpolated (Gouraud), per pixel
//!    from the interpolated eye-space position and normal (Phong, and Flat with the
//!    demo's screen-derivative normal, the face's plane), or once per face at its centroid
//!    with its plane's normal (Flat).
//!
//! The fast renderer ([`crate::raster::render`]) computes the same picture in bands, on
//! threads, with the lighting run over arrays in f32; `tests/all/reference_renderer.rs` holds
//! the two to the same coverage and colours within 1/255. Triangles are not clipped here: one
//! with a corner behind the eye or beyond the far plane is left out whole (the fast renderer
//! clips it), so the scenes compared stay inside the view volume.

use glam::{DVec3, Vec4};

use crate::equation::breakdown::{SideColor, VertexLighting};
use crate::equation::lighting::{Engine, Renormalize};
use crate::model::error::SceneError;
use crate::model::scene::{Side, Vertex};
use crate::model::view::ShadingMode;
use crate::raster::render::Job;
use crate::raster::render::window::{ONE, to_window};

/// An RGBA8 image, rows top to bottom (the fields of the fast renderer's [`crate::raster::render::Image`]).
pub struct Image {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// RGBA8, `width * height * 4` bytes.
    pub rgba: Vec<u8>,
}

/// A colour channel in [0, 1] to a byte, rounding to nearest (the framebuffer's clamp).
fn to_byte(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// The side `side` of a vertex's lighting.
fn side_of(l: &VertexLighting<f64>, side: Side) -> &SideColor<f64> {
    match side {
        Side::Front => &l.front,
        Side::Back => &l.back,
    }
}

/// A vertex colour as Gouraud interpolates it: primary plus secondary, each clamped to
/// [0, 1] first where OpenGL clamps vertex colours (the Phong demo's varying is not
/// clamped).
fn vertex_colour(s: &SideColor<f64>, clamp: bool) -> [f64; 4] {
    if !clamp {
        return s.sum();
    }
    let c = |x: f64| x.clamp(0.0, 1.0);
    let (p, q) = (s.primary, s.secondary);
    [c(p[0]) + c(q[0]), c(p[1]) + c(q[1]), c(p[2]) + c(q[2]), c(p[3])]
}

/// The edge function of a -> b at p: twice the signed area of (a, b, p).
fn edge(a: (i64, i64), b: (i64, i64), p: (i64, i64)) -> i64 {
    (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)
}

/// The top-left rule: a centre exactly on edge a -> b is inside only if the edge is a top
/// edge (horizontal, going right) or a left edge (going up the image): 0, else -1.
fn top_left(a: (i64, i64), b: (i64, i64)) -> i64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    if (dy == 0 && dx > 0) || dy < 0 { 0 } else { -1 }
}

/// Draws `job` at `width` x `height`.
pub fn render(job: &Job<'_>, width: usize, height: usize) -> Result<Image, SceneError> {
    let bg = job.background.map(|c| to_byte(c as f64));
    let rgba = colours(job, width, height)?
        .iter()
        .flat_map(|c| match c {
            Some(c) => c.map(to_byte),
            None => [bg[0], bg[1], bg[2], 255],
        })
        .collect();
    Ok(Image { width, height, rgba })
}

/// Each pixel's colour in f64 as it reaches the framebuffer (before the clamp to [0, 1]
/// and the rounding to 8 bits), rows top to bottom; `None` where no triangle covers it.
/// The cost study's reference image is this, for Phong shading of a very fine mesh.
pub fn colours(job: &Job<'_>, width: usize, height: usize) -> Result<Vec<Option<[f64; 4]>>, SceneError> {
    let engine = Engine::<f64>::with_options(job.scene, job.options)?;
    let scene = job.scene;
    let two_sided = scene.light_model.two_sided;
    let mesh = job.mesh;
    let clip_from_object = job.clip_from_object.as_mat4();
    let mut out: Vec<Option<[f64; 4]>> = vec![None; width * height];
    let mut depth = vec![f64::INFINITY; width * height];

    // Per vertex: window coordinates, the eye-space position and normal, and for Gouraud
    // the colour of each side.
    let clip: Vec<Vec4> = mesh.positions.iter().map(|p| clip_from_object * p.extend(1.0)).collect();
    let window: Vec<_> = clip.iter().map(|&c| to_window(c, width as f32, height as f32)).collect();
    let lit: Vec<_> = (0..mesh.positions.len())
        .map(|i| engine.light(&Vertex::from_f32(mesh.positions[i], mesh.normals[i])))
        .collect();
    let eye_pos: Vec<DVec3> = lit.iter().map(|l| l.pos_in_eye).collect();

    // Front faces first, then back faces (as the fast renderer draws them), each in mesh
    // order; without the depth test, every triangle in mesh order, the last drawn kept.
    let passes: &[Option<bool>] = if job.depth_test { &[Some(true), Some(false)] } else { &[None] };
    for &pass_front in passes {
        for (t, tri) in mesh.triangles.iter().enumerate() {
            let [i0, i1, i2] = tri.map(|i| i as usize);
            // Left out whole if a corner is behind the eye or beyond the near or far plane.
            if [i0, i1, i2].iter().any(|&i| clip[i].w <= 0.0 || clip[i].z.abs() > clip[i].w) {
                continue;
            }
            let v = [window[i0], window[i1], window[i2]];
            let p = |k: usize| (v[k].0, v[k].1);
            let area = edge(p(0), p(1), p(2));
            if area == 0 {
                continue;
            }
            // y grows down the image, so OpenGL's counter-clockwise is negative here.
            let front = area < 0;
            if pass_front.is_some_and(|f| f != front) || (job.cull_back && !front) {
                continue;
            }
            // Ordered so that the area is positive: the edge functions are then >= 0 inside.
            let order = if area > 0 { [0, 1, 2] } else { [0, 2, 1] };
            let (a, b, c) = (p(order[0]), p(order[1]), p(order[2]));
            let area = area.abs();
            let side = Side::back_if(!front && two_sided);
            let ids = order.map(|k| [i0, i1, i2][k]);
            let face_colour = match job.mode {
                ShadingMode::FlatFace => {
                    let [ea, eb, ec] = ids.map(|i| eye_pos[i]);
                    let n = plane_normal(ea, eb, ec, order != [0, 1, 2]);
                    Some(side_of(&engine.light_eye(((ea + eb + ec) / 3.0).extend(1.0), n), side).sum())
                }
                // GL_FLAT: the provoking vertex's colour, as Gouraud gives a vertex.
                ShadingMode::FlatProvoking => {
                    let lit_at = &lit[mesh.provoking_vertex(t) as usize];
                    Some(vertex_colour(side_of(lit_at, side), scene.rules.clamps_vertex_colors()))
                }
                _ => None,
            };
            // The top-left rule's bias of each edge (b -> c, c -> a, a -> b), for the triangle.
            let bias = [top_left(b, c), top_left(c, a), top_left(a, b)];

            // The bounding box of the pixel centres the triangle may cover.
            let to_px = |f: i64| f.div_euclid(ONE);
            let (x0, x1) = (to_px(a.0.min(b.0).min(c.0)).max(0), to_px(a.0.max(b.0).max(c.0)).min(width as i64 - 1));
            let (y0, y1) = (to_px(a.1.min(b.1).min(c.1)).max(0), to_px(a.1.max(b.1).max(c.1)).min(height as i64 - 1));
            for py in y0..=y1 {
                for px in x0..=x1 {
                    let centre = (px * ONE + ONE / 2, py * ONE + ONE / 2);
                    // Each edge function is the barycentric weight of the corner opposite it.
                    let e = [edge(b, c, centre), edge(c, a, centre), edge(a, b, centre)];
                    if (0..3).any(|k| e[k] + bias[k] < 0) {
                        continue;
                    }
                    let screen = e.map(|e| e as f64 / area as f64);
                    let z: f64 = (0..3).map(|k| screen[k] * v[order[k]].2 as f64).sum();
                    let at = py as usize * width + px as usize;
                    if job.depth_test {
                        if z >= depth[at] {
                            continue;
                        }
                        depth[at] = z;
                    }
                    // Perspective-correct: each weight over its corner's w, renormalised.
                    let over_w: [f64; 3] = [0, 1, 2].map(|k| screen[k] * v[order[k]].3 as f64);
                    let sum: f64 = over_w.iter().sum();
                    let bary = over_w.map(|x| x / sum);
                    let face = Face { ids, swapped: order != [0, 1, 2], side, flat: face_colour };
                    let colour = shade(job, &engine, &lit, &face, bary);
                    out[at] = Some(colour);
                }
            }
        }
    }
    Ok(out)
}

/// One triangle as a pixel of it is shaded: its mesh vertices (in the order that makes
/// its area positive; `swapped` when that is not the mesh's), the side it shows, and its
/// colour when it has one for the whole face (Flat).
struct Face {
    ids: [usize; 3],
    swapped: bool,
    side: Side,
    flat: Option<[f64; 4]>,
}

/// The colour of a pixel of `face` at perspective-correct barycentrics `bary`: the face's
/// own (Flat), the vertices' colours interpolated (Gouraud), or lit here from the
/// interpolated eye-space position and normal (Phong; the demo's Flat with the plane's
/// normal).
fn shade(job: &Job<'_>, engine: &Engine<f64>, lit: &[VertexLighting<f64>], face: &Face, bary: [f64; 3]) -> [f64; 4] {
    let clamp = job.scene.rules.clamps_vertex_colors();
    match (job.mode, face.flat) {
        (_, Some(c)) => c,
        (ShadingMode::Gouraud, None) => {
            let mut c = [0.0; 4];
            for k in 0..3 {
                let vc = vertex_colour(side_of(&lit[face.ids[k]], face.side), clamp);
                for ch in 0..4 {
                    c[ch] += bary[k] * vc[ch];
                }
            }
            c
        }
        _ => {
            let pos: DVec3 = (0..3).map(|k| bary[k] * lit[face.ids[k]].pos_in_eye).sum();
            let n = if job.mode == ShadingMode::FlatDerivatives {
                let [ea, eb, ec] = face.ids.map(|i| lit[i].pos_in_eye);
                plane_normal(ea, eb, ec, face.swapped)
            } else {
                let n: DVec3 = (0..3).map(|k| bary[k] * lit[face.ids[k]].normal_transformed).sum();
                // The interpolated normal renormalised as the options say (the
                // reference takes the exact length for the fast reciprocal root too).
                match job.options.renormalize {
                    Renormalize::Skip => n,
                    Renormalize::Exact | Renormalize::FastRsqrt => n.normalize_or_zero(),
                }
            };
            side_of(&engine.light_eye(pos.extend(1.0), n), face.side).sum()
        }
    }
}

/// The unit normal of the plane through the mesh triangle's eye-space corners `a`, `b`,
/// `c` as the mesh orders them (`swapped`: given in the other order).
fn plane_normal(a: DVec3, b: DVec3, c: DVec3, swapped: bool) -> DVec3 {
    let (b, c) = if swapped { (c, b) } else { (b, c) };
    (b - a).cross(c - a).normalize_or_zero()
}
