//! Window coordinates: a clip-space vertex divided by w and mapped to the viewport, x and y
//! in fixed point (y down), as the vertices stage computes them once per mesh vertex and
//! the setup stage for the corners that clipping makes.

use glam::Vec4;

/// Sub-pixel precision: 8 fractional bits, as llvmpipe.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed point.
pub const ONE: i64 = 1 << SUBPIXEL_BITS;

/// A clip-space vertex in window coordinates: fixed-point x and y (y down), depth in
/// [0, 1], and 1/w.
pub type WindowVert = (i64, i64, f32, f32);

/// Each clip-space vertex of `clip` in window coordinates for a `width` x `height` image
/// ([`to_window`], the same bits as setup's own), into `out`: once per mesh vertex, for the
/// triangles that need no clipping, instead of once per triangle corner (a vertex of a
/// closed mesh has about six triangles). Vertices outside the view volume get values no
/// unclipped triangle reads. (Written once, `#[inline(always)]`; `copies` compiles it for each processor.)
#[inline(always)]
pub fn window_vertices(clip: &[Vec4], out: &mut [WindowVert], width: usize, height: usize) {
    let (w, h) = (width as f32, height as f32);
    for (o, &c) in out.iter_mut().zip(clip) {
        *o = to_window(c, w, h);
    }
}

/// `clip` divided by w and mapped to the `width` x `height` viewport. (Inline: in the
/// AVX2 copies it rounds without calls.)
#[inline(always)]
pub fn to_window(clip: Vec4, w: f32, h: f32) -> WindowVert {
    let iw = 1.0 / clip.w;
    let (xn, yn, zn) = (clip.x * iw, clip.y * iw, clip.z * iw);
    let xw = (xn + 1.0) * 0.5 * w;
    let yw = (1.0 - yn) * 0.5 * h; // image rows go down
    ((xw * ONE as f32).round() as i64, (yw * ONE as f32).round() as i64, ((zn + 1.0) * 0.5).clamp(0.0, 1.0), iw)
}
