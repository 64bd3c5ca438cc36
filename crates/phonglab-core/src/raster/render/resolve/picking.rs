//! Where a pixel lands on the original mesh triangle: its perspective-correct
//! barycentrics (for picking and the probe).

use crate::raster::render::setup::Setup;
use crate::raster::render::visibility::ScreenBarycentrics;

/// Perspective-correct barycentrics of the original mesh triangle of raster triangle
/// `raster`, at the point whose screen barycentrics (of corners 1 and 2) are `l`.
#[inline(always)]
fn barycentrics(setup: &Setup, raster: u32, l: [f32; 2]) -> [f32; 3] {
    let t = &setup.tris[raster as usize];
    let ls = [1.0 - l[0] - l[1], l[0], l[1]];
    let p = [ls[0] * t.inv_w[0], ls[1] * t.inv_w[1], ls[2] * t.inv_w[2]];
    let s = 1.0 / (p[0] + p[1] + p[2]);
    let b = [p[0] * s, p[1] * s, p[2] * s];
    let (mut out, bary) = ([0.0f32; 3], setup.corners.of(t));
    for (k, bk) in b.iter().enumerate() {
        for (j, o) in out.iter_mut().enumerate() {
            *o += bk * bary[k][j];
        }
    }
    out
}

/// The original triangle's barycentrics at pixel (`x`, `y`) of the last frame, where the
/// rasterised triangle `r` shows (for picking).
pub(crate) fn original_barycentrics(setup: &Setup, r: u32, x: usize, y: usize) -> Option<[f32; 3]> {
    let t = setup.tris.get(r as usize)?;
    let l = ScreenBarycentrics::new(t).at(x, y);
    Some(barycentrics(setup, r, l))
}
