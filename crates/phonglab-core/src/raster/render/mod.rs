//! The CPU renderer: a mesh, lit by the same engine as the vertex panel, shaded Flat,
//! Gouraud or Phong, into an RGBA8 image. No GPU.
//!
//! Read it top to bottom:
//!
//! 1. [`vertices`]: each vertex to eye space (where it is lit) and clip space (where it is
//!    drawn); for Gouraud, its colour.
//! 2. [`setup`]: each triangle clipped (near and far planes, and x/y beyond a guard band),
//!    its facing decided, back faces culled if asked, snapped to fixed point.
//! 3. [`raster`]: triangles into a visibility buffer (depth, triangle), in horizontal
//!    bands on all cores; top-left fill rule, so shared edges are drawn once.
//! 4. [`resolve`]: right after each band is drawn, while it is in cache, each covered pixel
//!    shaded once, in runs of one triangle, with exact
//!    screen barycentrics from the triangle's edge functions, made perspective-correct:
//!    Gouraud interpolates colours, Phong interpolates position and normal and lights the
//!    pixel, Flat takes its face's colour (or, as the Phong demo does, lights the pixel
//!    with the face's normal taken from the screen derivatives).

pub mod raster;
pub mod resolve;
pub mod setup;
pub mod vertices;

use glam::DMat4;

use crate::error::SceneError;
use crate::lighting::EvalOptions;
use crate::mesh::Mesh;
use crate::scene::Scene;
use crate::specialised::Lighter;
use crate::view::{FlatNormal, Shading};

pub use crate::transform::perspective;

/// What to draw.
#[derive(Clone, Copy, Debug)]
pub struct Job<'a> {
    /// Lighting state and the modelview the object is lit under (`scene.eye_from_object()`).
    pub scene: &'a Scene,
    /// The mesh, object space.
    pub mesh: &'a Mesh,
    /// Object to clip space: where the mesh is drawn. Usually `projection *
    /// scene.eye_from_object()`; the Phong demo draws with its spin alone and lights in
    /// object space, so the two are separate.
    pub clip_from_object: DMat4,
    /// Flat, Gouraud or Phong.
    pub shading: Shading,
    /// Flat shading's normal: per face, or per fragment from the screen derivatives.
    pub flat_normal: FlatNormal,
    /// Colour of uncovered pixels (linear, as written).
    pub background: [f32; 3],
    /// Skip triangles facing away (OpenGL's GL_CULL_FACE with GL_BACK).
    pub cull_back: bool,
    /// The power function and other numerical choices.
    pub options: EvalOptions,
}

/// A rendered image, rows top to bottom.
#[derive(Clone, Debug, Default)]
pub struct Image {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// RGBA8, `width * height * 4` bytes.
    pub rgba: Vec<u8>,
    /// Window-space depth of each pixel (1 where uncovered).
    pub depth: Vec<f32>,
    /// The rasterised (clipped) triangle at each pixel ([`NO_TRIANGLE`] where uncovered).
    pub(crate) raster: Vec<u32>,
}

/// `Image::triangle` of an uncovered pixel.
pub const NO_TRIANGLE: u32 = u32::MAX;

impl Image {
    /// The share of pixels covered by the mesh.
    pub fn coverage(&self) -> f64 {
        if self.raster.is_empty() {
            return 0.0;
        }
        self.raster.iter().filter(|t| **t != NO_TRIANGLE).count() as f64 / self.raster.len() as f64
    }

    /// Is pixel (x, y) (y from the top) covered?
    pub fn covered(&self, x: usize, y: usize) -> bool {
        self.raster.get(y * self.width + x).is_some_and(|t| *t != NO_TRIANGLE)
    }

    /// The RGB of pixel (x, y), y from the top.
    pub fn rgb(&self, x: usize, y: usize) -> [u8; 3] {
        let i = (y * self.width + x) * 4;
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2]]
    }
}

/// What a frame cost and drew.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Triangles rasterised (after culling and clipping; a clipped one may become several).
    pub rasterised: usize,
    /// Lighting evaluations made (vertices, faces or pixels).
    pub evaluations: usize,
    /// Milliseconds spent in each stage: vertices, setup, rasterisation, resolve. The last
    /// two run together, band by band (each band drawn, then shaded); the time of the pair
    /// is split between them in proportion to the time the bands spent in each.
    pub stage_ms: [f64; 4],
}

/// The renderer: keeps its buffers and its specialised lighting plan from frame to frame
/// (re-planned only when the scene's key changes).
#[derive(Default)]
pub struct Renderer {
    lighter: Option<Lighter>,
    vertices: vertices::Vertices,
    setup: setup::Setup,
    image: Image,
    scratch: resolve::Scratch,
    bins: Vec<Vec<u32>>,
}

impl Renderer {
    /// A renderer with empty buffers.
    pub fn new() -> Self {
        Self::default()
    }

    /// The lighting plan of the last frame.
    pub fn lighter(&self) -> Option<&Lighter> {
        self.lighter.as_ref()
    }

    /// Draws `job` into a `width` x `height` image.
    pub fn render(&mut self, job: &Job<'_>, width: usize, height: usize) -> Result<(&Image, Stats), SceneError> {
        match &mut self.lighter {
            Some(l) => {
                l.update(job.scene, job.options)?;
            }
            None => self.lighter = Some(Lighter::new(job.scene, job.options)?),
        }
        let lighter = self.lighter.as_ref().expect("set just above");
        let width = width.max(1);
        let height = height.max(1);
        let mut clock = std::time::Instant::now();
        let mut lap = || {
            let now = std::time::Instant::now();
            let ms = (now - clock).as_secs_f64() * 1e3;
            clock = now;
            ms
        };
        self.vertices.run(job, lighter);
        let t_vertices = lap();
        self.setup.run(job, &self.vertices, lighter, width, height);
        let t_setup = lap();
        raster::bin(&self.setup, width, height, &mut self.image, &mut self.bins);
        let (lit, [raster_share, resolve_share]) =
            draw_and_shade(job, &self.vertices, &self.setup, lighter, &mut self.image, &mut self.scratch, &self.bins);
        let t_bands = lap();
        let (t_raster, t_resolve) = (t_bands * raster_share, t_bands * resolve_share);
        let evaluations = resolve::evaluations(job, lit);
        let stats = Stats {
            stage_ms: [t_vertices, t_setup, t_raster, t_resolve],
            triangles: job.mesh.triangle_count(),
            rasterised: self.setup.tris.len(),
            evaluations: evaluations + if job.shading == Shading::Gouraud { self.vertices.eye.len() } else { 0 },
        };
        Ok((&self.image, stats))
    }
}

/// Stages 3 and 4, band by band on all cores: each band is drawn and then shaded at once,
/// while its depths and triangles are still in the core's cache. Returns the fragments lit
/// and the shares of the bands' time spent drawing and shading.
fn draw_and_shade(
    job: &Job<'_>,
    verts: &vertices::Vertices,
    setup: &setup::Setup,
    lighter: &Lighter,
    image: &mut Image,
    scratch: &mut resolve::Scratch,
    bins: &[Vec<u32>],
) -> (usize, [f64; 2]) {
    use rayon::prelude::*;
    let (width, rows) = (image.width, image.width * raster::BAND);
    let prepared = resolve::prepare(job, verts, setup, scratch, image.height.div_ceil(raster::BAND));
    let (shared, fragments) = resolve::split(scratch);
    let (lit, drawing, shading) = image
        .depth
        .par_chunks_mut(rows)
        .zip(image.raster.par_chunks_mut(rows))
        .zip(image.rgba.par_chunks_mut(rows * 4))
        .zip(bins.par_iter())
        .zip(fragments.par_iter_mut())
        .enumerate()
        .map(|(b, ((((depth, raster), rgba), bin), frags))| {
            let start = std::time::Instant::now();
            let y_start = b * raster::BAND;
            raster::draw_band(setup, bin, raster::Band { y_start: y_start as i32, width, depth, raster: &mut *raster });
            let drawn = std::time::Instant::now();
            let (px, _) = rgba.as_chunks_mut::<4>();
            let lit = resolve::resolve_band(job, setup, lighter, &prepared, &shared, px, raster, y_start, width, frags);
            (lit, (drawn - start).as_secs_f64(), drawn.elapsed().as_secs_f64())
        })
        .reduce(|| (0, 0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2));
    let total = drawing + shading;
    let shares = if total > 0.0 { [drawing / total, shading / total] } else { [0.5, 0.5] };
    (lit, shares)
}

/// What a pixel of the last frame shows: a point of a mesh triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    /// The mesh triangle.
    pub triangle: usize,
    /// The point's barycentric coordinates in it (perspective-correct).
    pub barycentrics: [f32; 3],
    /// The triangle faces away from the viewer.
    pub back: bool,
}

impl Renderer {
    /// What pixel `i` (row-major, rows from the top) of the last frame shows, if covered.
    pub fn surface_at(&self, i: usize) -> Option<Surface> {
        let r = *self.image.raster.get(i)?;
        let t = self.setup.tris.get(r as usize)?;
        let b = resolve::original_barycentrics(&self.setup, &self.image, i)?;
        Some(Surface { triangle: t.orig as usize, barycentrics: b, back: t.back })
    }

    /// The mesh vertex nearest to what pixel (x, y) of the last frame shows (y from the
    /// top): the vertex of the drawn triangle with the largest barycentric weight there.
    pub fn pick(&self, mesh: &Mesh, x: usize, y: usize) -> Option<usize> {
        let img = &self.image;
        if x >= img.width || y >= img.height {
            return None;
        }
        let i = y * img.width + x;
        let r = img.raster[i];
        let tri = mesh.triangles.get(self.setup.tris.get(r as usize)?.orig as usize)?;
        let b = resolve::original_barycentrics(&self.setup, img, i)?;
        let k = (0..3).max_by(|i, j| b[*i].total_cmp(&b[*j]))?;
        Some(tri[k] as usize)
    }
}
