//! The CPU renderer: a mesh, lit by the same engine as the vertex panel, shaded Flat,
//! Gouraud or Phong, into an RGBA8 image. No GPU.
//!
//! Read it top to bottom:
//!
//! 1. [`vertices`]: each vertex to eye space (where it is lit) and clip space (where it is
//!    drawn); for Gouraud, its colour.
//! 2. [`setup`]: each triangle clipped (near and far planes, and x/y beyond a guard band),
//!    its facing decided, back faces culled if asked, snapped to fixed point.
//! 3. [`visibility`]: triangles into a visibility buffer (depth, triangle), in horizontal
//!    bands on all cores, each band in a buffer of its thread's own that stays in cache;
//!    top-left fill rule, so shared edges are drawn once; back faces hidden whole behind
//!    the band's front faces skipped.
//! 4. [`resolve`]: right after each band is drawn, while it is in cache, each covered pixel
//!    shaded once, in runs of one triangle, with exact
//!    screen barycentrics from the triangle's edge functions, made perspective-correct:
//!    Gouraud interpolates colours, Phong interpolates position and normal and lights the
//!    pixel, Flat takes its face's colour (or, as the Phong demo does, lights the pixel
//!    with the face's normal taken from the screen derivatives).
//!
//! Each band's visibility is copied out as it is shaded and kept: picking reads it, and a
//! frame in which nothing drawn moved (no vertex, bit for bit, nor the triangles, size,
//! shading or culling: only the lights, the material or the colours changed) skips stages
//! 2 and 3 and shades the kept visibility again ([`Stats::visibility_kept`]); `kept` holds
//! that visibility, what it was drawn from, and the invariants that make it safe.

pub mod copies;
mod kept;
mod mask;
mod outcodes;
pub mod resolve;
pub mod setup;
mod timing;
pub mod vertices;
pub mod visibility;
pub mod window;

use glam::DMat4;

use crate::cpu::Isa;
use crate::equation::lighting::EvalOptions;
use crate::mesh::Mesh;
use crate::model::error::SceneError;
use crate::model::scene::Scene;
use crate::model::view::ShadingMode;
use crate::specialise::lighter::Lighter;

pub use crate::model::transform::perspective;

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
    /// Gouraud, Phong, or Flat per face or from the screen derivatives.
    pub mode: ShadingMode,
    /// Colour of uncovered pixels (linear, as written).
    pub background: [f32; 3],
    /// Skip triangles facing away (OpenGL's GL_CULL_FACE with GL_BACK).
    pub cull_back: bool,
    /// Keep the nearest triangle at each pixel (`GL_DEPTH_TEST`); without it, the last one
    /// drawn (in mesh order) covers the ones before, as OpenGL draws with the test off.
    pub depth_test: bool,
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
    /// Pixels covered by the mesh.
    covered: usize,
    /// The rasterised (clipped) triangle at each pixel ([`NO_TRIANGLE`] where uncovered),
    /// kept only when the renderer is asked to ([`Renderer::keep_visibility`]); else empty.
    pub(crate) raster: Vec<u32>,
}

/// The triangle recorded at an uncovered pixel (in the image's kept visibility, `raster`).
pub const NO_TRIANGLE: u32 = u32::MAX;

impl Image {
    /// The share of pixels covered by the mesh.
    pub fn coverage(&self) -> f64 {
        let n = self.width * self.height;
        if n == 0 { 0.0 } else { self.covered as f64 / n as f64 }
    }

    /// Is pixel (x, y) (y from the top) covered? `None` unless the renderer kept the
    /// frame's visibility ([`Renderer::keep_visibility`]), or outside the image.
    pub fn covered(&self, x: usize, y: usize) -> Option<bool> {
        if x >= self.width {
            return None;
        }
        self.raster.get(y * self.width + x).map(|t| *t != NO_TRIANGLE)
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
    /// Only the lighting changed since the last frame (the same triangles, vertices, size,
    /// shading and culling, bit for bit): its visibility was kept, and only the vertices'
    /// lighting and the resolve ran (setup's Flat face colours aside).
    pub visibility_kept: bool,
}

/// The renderer: keeps its buffers and its specialised lighting plan from frame to frame
/// (re-planned only when the scene's key changes), and runs the copies of its stages
/// compiled for this processor ([`Isa::best`], detected once).
pub struct Renderer {
    isa: Isa,
    lighter: Option<Lighter>,
    vertices: vertices::Vertices,
    setup: setup::Setup,
    image: Image,
    scratch: resolve::Scratch,
    bins: Vec<Vec<u32>>,
    /// The last frame's visibility, kept always: picking reads it, and a frame that only
    /// lights differently shades it again without drawing.
    visibility: kept::KeptVisibility,
    keep_visibility: bool,
}

impl Default for Renderer {
    fn default() -> Self {
        Self {
            isa: Isa::best(),
            lighter: None,
            vertices: Default::default(),
            setup: Default::default(),
            image: Default::default(),
            scratch: Default::default(),
            bins: Vec::new(),
            visibility: Default::default(),
            keep_visibility: false,
        }
    }
}

impl Renderer {
    /// A renderer with empty buffers.
    pub fn new() -> Self {
        Self::default()
    }

    /// A renderer that runs the copies `isa` (for comparing them: every copy gives the
    /// same bits); `isa` is a proof that this processor runs them.
    pub fn with_isa(isa: Isa) -> Self {
        Self { isa, ..Self::default() }
    }

    /// Put each frame's visibility (the triangle at every pixel) in its image too, for
    /// [`Image::covered`]. Off by default (the renderer keeps its own copy either way, for
    /// picking and for frames that only light differently).
    pub fn keep_visibility(&mut self, keep: bool) {
        self.keep_visibility = keep;
    }

    /// The last frame's width and height.
    pub fn size(&self) -> (usize, usize) {
        (self.image.width, self.image.height)
    }

    /// The lighting plan of the last frame.
    pub fn lighter(&self) -> Option<&Lighter> {
        self.lighter.as_ref()
    }

    /// Draws `job` into a `width` x `height` image: the stages in their order, each
    /// timed. A frame that keeps the last one's visibility skips setup and drawing
    /// ([`Stats::visibility_kept`]).
    pub fn render(&mut self, job: &Job<'_>, width: usize, height: usize) -> Result<(&Image, Stats), SceneError> {
        let lighter = self.take_lighter(job)?;
        let (width, height) = (width.max(1), height.max(1));
        let mut times = timing::StageTimes::start();
        let kept = self.vertices_stage(job, &lighter, width, height);
        times.vertices_done();
        self.setup_stage(job, &lighter, kept, width, height);
        times.setup_done();
        let (lit, shares) = if kept {
            self.shade_kept_stage(job, &lighter, height)
        } else {
            self.draw_and_shade_stage(job, &lighter, width, height)
        };
        self.expose_visibility();
        times.bands_done(shares);
        self.lighter = Some(lighter);
        Ok((&self.image, self.stats(job, lit, kept, times.ms())))
    }

    /// The lighting plan for `job`'s scene, taken out of the renderer for the frame (it
    /// goes back at the end): the last one brought up to date, or a new one.
    fn take_lighter(&mut self, job: &Job<'_>) -> Result<Lighter, SceneError> {
        match self.lighter.take() {
            Some(mut lighter) => match lighter.update(job.scene, job.options) {
                Ok(_) => Ok(lighter),
                Err(e) => {
                    self.lighter = Some(lighter);
                    Err(e)
                }
            },
            None => Lighter::new(job.scene, job.options),
        }
    }

    /// Stage 1: the vertices transformed (and, for Gouraud, lit); decides whether this
    /// frame keeps the last one's visibility, and returns that.
    fn vertices_stage(&mut self, job: &Job<'_>, lighter: &Lighter, width: usize, height: usize) -> bool {
        let isa = self.isa;
        let apart = self.visibility.lights_apart(job.mode);
        let window = |clip: &[glam::Vec4], out: &mut [window::WindowVert], codes: &mut [u8]| {
            copies::window_vertices(isa, clip, out, codes, width, height);
        };
        let moved = self.vertices.run(job, (!apart).then_some(lighter), window);
        let kept = self.visibility.decide(job, width, height, moved);
        if apart {
            let only = kept.then(|| self.visibility.seen(&self.setup, job.mesh).1);
            self.vertices.light(job, lighter, only);
        }
        kept
    }

    /// Stage 2: the triangles set up, or on a kept frame only the Flat faces' colours.
    fn setup_stage(&mut self, job: &Job<'_>, lighter: &Lighter, kept: bool, width: usize, height: usize) {
        let (isa, verts) = (self.isa, &self.vertices);
        if kept {
            self.setup.light_faces(job, verts, lighter);
        } else {
            self.setup
                .run(job, verts, lighter, |faces, out| copies::setup_faces(isa, job, verts, faces, width, height, out));
        }
    }

    /// Stage 4 alone over the kept visibility. Returns the fragments lit and the bands'
    /// time shares (all of it the resolve's).
    fn shade_kept_stage(&mut self, job: &Job<'_>, lighter: &Lighter, height: usize) -> (usize, [f64; 2]) {
        let (isa, verts) = (self.isa, &self.vertices);
        let bands = height.div_ceil(visibility::BAND);
        let prepared = resolve::prepare(job, &self.setup, &mut self.scratch, bands);
        let frame = Frame { isa, job, setup: &self.setup, verts, lighter, prepared: &prepared };
        let pixels = self.visibility.pixels();
        (shade_kept(&frame, &mut self.image, &mut self.scratch, pixels), [0.0, 1.0])
    }

    /// Stages 3 and 4: binning (serial, while the other thread prepares the resolve: Flat's
    /// face colours in 8 bits), then each band drawn and shaded; records what the frame was
    /// drawn from. Returns the fragments lit and the bands' time shares.
    fn draw_and_shade_stage(
        &mut self,
        job: &Job<'_>,
        lighter: &Lighter,
        width: usize,
        height: usize,
    ) -> (usize, [f64; 2]) {
        let (isa, verts) = (self.isa, &self.vertices);
        let bands = height.div_ceil(visibility::BAND);
        let (setup, image, bins, scratch) = (&self.setup, &mut self.image, &mut self.bins, &mut self.scratch);
        let ((), prepared) = rayon::join(
            || visibility::bin(setup, width, height, image, bins),
            || resolve::prepare(job, setup, scratch, bands),
        );
        let frame = Frame { isa, job, setup, verts, lighter, prepared: &prepared };
        let pixels = self.visibility.pixels_to_draw(width, height);
        let out = draw_and_shade(&frame, &mut self.image, &mut self.scratch, &self.bins[..bands], pixels);
        self.visibility.record(job, width, height);
        out
    }

    /// The frame's visibility put in its image when asked ([`Renderer::keep_visibility`]).
    fn expose_visibility(&mut self) {
        if self.keep_visibility {
            let pixels = self.visibility.pixels();
            self.image.raster.clear();
            self.image.raster.extend_from_slice(pixels);
        } else {
            self.image.raster.clear();
        }
    }

    /// What the frame drew and cost.
    fn stats(&self, job: &Job<'_>, lit: usize, kept: bool, stage_ms: [f64; 4]) -> Stats {
        let gouraud_vertices = if job.mode == ShadingMode::Gouraud { self.vertices.eye.len() } else { 0 };
        Stats {
            stage_ms,
            triangles: job.mesh.triangle_count(),
            rasterised: self.setup.drawn,
            evaluations: resolve::evaluations(job, lit) + gouraud_vertices,
            visibility_kept: kept,
        }
    }
}

/// What every band of a frame reads.
#[derive(Clone, Copy)]
struct Frame<'a> {
    isa: Isa,
    job: &'a Job<'a>,
    setup: &'a setup::Setup,
    verts: &'a vertices::Vertices,
    lighter: &'a Lighter,
    prepared: &'a resolve::Prepared,
}

/// Stages 3 and 4, band by band on all cores: each band is drawn into its thread's own
/// visibility buffer ([`visibility::with_band_buffer`]) and then shaded at once, while the
/// buffer is still in the core's cache, and copied into `kept`. Returns the fragments lit
/// and the shares of the bands' time spent drawing and shading; sets the image's coverage.
fn draw_and_shade(
    f: &Frame<'_>,
    image: &mut Image,
    scratch: &mut resolve::Scratch,
    bins: &[Vec<u32>],
    kept: &mut [u32],
) -> (usize, [f64; 2]) {
    use rayon::prelude::*;
    let (width, rows) = (image.width, image.width * visibility::BAND);
    let fragments = resolve::fragments(scratch);
    let (covered, lit, drawing, shading) = image
        .rgba
        .par_chunks_mut(rows * 4)
        .zip(bins.par_iter())
        .zip(fragments.par_iter_mut())
        .zip(kept.par_chunks_mut(rows))
        .enumerate()
        .map(|(b, (((rgba, bin), frags), kept))| {
            let (px, _) = rgba.as_chunks_mut::<4>();
            visibility::with_band_buffer(px.len(), |depth, raster| {
                let start = web_time::Instant::now();
                let y_start = b * visibility::BAND;
                copies::draw_band(
                    f.isa,
                    f.setup,
                    bin,
                    visibility::Band { y_start: y_start as i32, width, depth, raster: &mut *raster },
                );
                let drawn = web_time::Instant::now();
                let (job, setup, lighter, p, verts) = (f.job, f.setup, f.lighter, f.prepared, f.verts);
                let input = resolve::BandInput { job, setup, lighter, p, verts, raster, y0: y_start, width };
                let shaded = copies::resolve_band(f.isa, &input, px, frags);
                kept.copy_from_slice(raster);
                (shaded.covered, shaded.lit, (drawn - start).as_secs_f64(), drawn.elapsed().as_secs_f64())
            })
        })
        .reduce(|| (0, 0, 0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2, a.3 + b.3));
    image.covered = covered;
    let total = drawing + shading;
    let shares = if total > 0.0 { [drawing / total, shading / total] } else { [0.5, 0.5] };
    (lit, shares)
}

/// Stage 4 alone, band by band on all cores, over the last frame's visibility `kept`: a
/// frame whose triangles all stayed where they were. Returns the fragments lit.
fn shade_kept(f: &Frame<'_>, image: &mut Image, scratch: &mut resolve::Scratch, kept: &[u32]) -> usize {
    use rayon::prelude::*;
    let (width, rows) = (image.width, image.width * visibility::BAND);
    let fragments = resolve::fragments(scratch);
    image
        .rgba
        .par_chunks_mut(rows * 4)
        .zip(fragments.par_iter_mut())
        .zip(kept.par_chunks(rows))
        .enumerate()
        .map(|(b, ((rgba, frags), raster))| {
            let (px, _) = rgba.as_chunks_mut::<4>();
            let (job, setup, lighter, p, verts) = (f.job, f.setup, f.lighter, f.prepared, f.verts);
            let input = resolve::BandInput { job, setup, lighter, p, verts, raster, y0: b * visibility::BAND, width };
            copies::resolve_band(f.isa, &input, px, frags).lit
        })
        .sum()
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
    /// The rasterised triangle at each pixel of row `y` of the last frame
    /// ([`NO_TRIANGLE`] where uncovered), from the kept visibility.
    fn row_triangles(&self, y: usize) -> Option<&[u32]> {
        let w = self.image.width;
        self.visibility.pixels().get(y * w..(y + 1) * w)
    }

    /// The rasterised triangle at pixel (`x`, `y`) of the last frame, if covered.
    fn triangle_at(&self, x: usize, y: usize) -> Option<u32> {
        if x >= self.image.width {
            return None;
        }
        let r = *self.row_triangles(y)?.get(x)?;
        (r != NO_TRIANGLE).then_some(r)
    }

    /// Pixel (`x`, `y`) of the last frame (drawn from `job`), shaded again alone by the
    /// resolve's own arithmetic ([`resolve::PixelSample`]): its triangle, barycentrics and
    /// the colour and bytes the frame stored there. `None` where uncovered or outside.
    pub fn sample(&self, job: &Job<'_>, x: usize, y: usize) -> Option<resolve::PixelSample> {
        if x >= self.image.width {
            return None;
        }
        let row = self.row_triangles(y)?;
        if row[x] == NO_TRIANGLE {
            return None;
        }
        let input = resolve::PixelInput {
            job,
            setup: &self.setup,
            lighter: self.lighter.as_ref()?,
            verts: &self.vertices,
            row,
        };
        resolve::shade_pixel(&input, x, y)
    }

    /// What pixel `i` (row-major, rows from the top) of the last frame shows, if covered.
    pub fn surface_at(&self, i: usize) -> Option<Surface> {
        let width = self.image.width.max(1);
        let (x, y) = (i % width, i / width);
        let r = self.triangle_at(x, y)?;
        let t = self.setup.tris.get(r as usize)?;
        let b = resolve::original_barycentrics(&self.setup, r, x, y)?;
        Some(Surface { triangle: t.orig as usize, barycentrics: b, back: t.back })
    }

    /// The mesh vertex nearest to what pixel (x, y) of the last frame shows (y from the
    /// top): the vertex of the drawn triangle with the largest barycentric weight there.
    pub fn pick(&self, mesh: &Mesh, x: usize, y: usize) -> Option<usize> {
        let r = self.triangle_at(x, y)?;
        let tri = mesh.triangles.get(self.setup.tris.get(r as usize)?.orig as usize)?;
        let b = resolve::original_barycentrics(&self.setup, r, x, y)?;
        let k = (0..3).max_by(|i, j| b[*i].total_cmp(&b[*j]))?;
        Some(tri[k] as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{sphere, teapot};
    use crate::model::presets::bench_scene;
    use crate::model::view::{FlatNormal, Shading};
    use crate::raster::shaded::bench_job;

    /// Triangles that clipping cut keep where their corners lie in their mesh triangles
    /// (numbered per chunk of faces, then renumbered when gathered): each corner, blended
    /// from its mesh triangle's clip-space corners with those barycentrics, lands where the
    /// raster triangle has it, to a few 1/256 of a pixel. A floor under the eye, from behind
    /// it to far in front, in 30 x 10 quads (600 faces, 7 coprime with it), crosses the near plane (0.5) and the guard band.
    #[test]
    fn clipped_triangles_point_at_their_own_corners() {
        let mut scene = bench_scene(0);
        scene.eye_from_world = glam::DMat4::IDENTITY;
        let (nx, nz) = (30u32, 10u32);
        let mut floor = crate::mesh::Mesh::default();
        for k in 0..=nz {
            for i in 0..=nx {
                let (x, z) = (-3.0 + 6.0 * i as f32 / nx as f32, 2.0 - 8.0 * k as f32 / nz as f32);
                floor.positions.push(glam::Vec3::new(x, -0.3, z));
                floor.normals.push(glam::Vec3::Y);
            }
        }
        for k in 0..nz {
            for i in 0..nx {
                let a = k * (nx + 1) + i;
                let (b, c, d) = (a + 1, a + nx + 1, a + nx + 2);
                floor.triangles.extend([[a, c, b], [b, c, d]]);
            }
        }
        // Shuffled, so that the cut triangles fall in several chunks of 256 faces.
        let n = floor.triangles.len();
        floor.triangles = (0..n).map(|k| floor.triangles[k * 7 % n]).collect();
        let job = bench_job(&scene, &floor, Shading::Gouraud);
        let (w, h) = (300, 200);
        let mut r = Renderer::new();
        r.render(&job, w, h).unwrap();
        let (mut cut, mut chunks) = (0, std::collections::BTreeSet::new());
        for t in &r.setup.tris {
            let own = t.corners == setup::Corners::default();
            let bary = r.setup.corners.of(t);
            if bary == [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] && own {
                continue;
            }
            let v = floor.triangles[t.orig as usize].map(|i| r.vertices.clip[i as usize]);
            for (k, b) in bary.iter().enumerate() {
                let clip = v[0] * b[0] + v[1] * b[1] + v[2] * b[2];
                let (x, y, _, _) = window::to_window(clip, w as f32, h as f32);
                assert!(
                    (x - t.x[k] as i64).abs() <= 4 && (y - t.y[k] as i64).abs() <= 4,
                    "triangle of face {}: corner {k}",
                    t.orig
                );
            }
            if bary.iter().flatten().any(|&b| b != 0.0 && b != 1.0) {
                cut += 1;
                chunks.insert(t.orig / 256);
            }
        }
        assert!(cut > 10 && chunks.len() > 2, "{cut} cut triangles in {} chunks", chunks.len());
    }

    /// Every compiled copy of the resolve this processor can run (portable, AVX2, AVX-512)
    /// shades every band of a frame into the same bytes, with the same counts, for each
    /// shading (the demo's derivative Flat included) and a two-sided scene.
    #[test]
    fn every_copy_of_the_resolve_shades_alike() {
        let mut two_sided = bench_scene(37);
        two_sided.light_model.two_sided = true;
        let (sphere, teapot) = (sphere::glu_sphere(1.0, 50, 50), teapot::glut_teapot(0.8, 7));
        let cases = [
            (bench_scene(37), &sphere, Shading::Phong, FlatNormal::Face),
            (bench_scene(37), &teapot, Shading::Gouraud, FlatNormal::Face),
            (two_sided.clone(), &teapot, Shading::Phong, FlatNormal::Face),
            (two_sided, &sphere, Shading::Gouraud, FlatNormal::Face),
            (bench_scene(37), &teapot, Shading::Flat, FlatNormal::ScreenDerivatives),
            (bench_scene(37), &sphere, Shading::Flat, FlatNormal::Face),
        ];
        let mut copies_run = 0;
        for (scene, mesh, shading, flat_normal) in cases {
            let job = Job { mode: ShadingMode::of(shading, flat_normal), ..bench_job(&scene, mesh, shading) };
            // Wide enough for a band to take more than one batch of Phong fragments; 101
            // rows, so the last band is a short one.
            let (w, h) = (211, 101);
            let mut r = Renderer::new();
            r.keep_visibility(true);
            let image = r.render(&job, w, h).unwrap().0.clone();
            let lighter = r.lighter.as_ref().unwrap();
            let bands = h.div_ceil(visibility::BAND);
            let prepared = resolve::prepare(&job, &r.setup, &mut r.scratch, bands);
            let fragments = resolve::fragments(&mut r.scratch);
            for (b, frags) in fragments.iter_mut().enumerate().take(bands) {
                let rows = b * visibility::BAND * w..((b + 1) * visibility::BAND * w).min(w * h);
                let want = &image.rgba[rows.start * 4..rows.end * 4];
                let mut shaded = Vec::new();
                for copy in Isa::all_here() {
                    let mut px = vec![[0u8; 4]; rows.len()];
                    let raster = &image.raster[rows.clone()];
                    let y0 = b * visibility::BAND;
                    let input = resolve::BandInput {
                        job: &job,
                        setup: &r.setup,
                        lighter,
                        p: &prepared,
                        verts: &r.vertices,
                        raster,
                        y0,
                        width: w,
                    };
                    let s = copies::resolve_band(copy, &input, &mut px, frags);
                    assert_eq!(px.as_flattened(), want, "{copy:?}, {shading:?}, band {b}");
                    shaded.push(s);
                    copies_run += 1;
                }
                assert!(shaded.windows(2).all(|p| p[0] == p[1]), "{shaded:?}");
            }
        }
        assert!(copies_run >= 6 * 7, "{copies_run}");
    }

    /// Gouraud's pixels are the perspective-correct interpolation of the vertices' colours,
    /// computed here in f64 from the exact barycentrics of each pixel's triangle and
    /// converted as OpenGL converts: within one level everywhere, and off by that one level
    /// at a handful of pixels (where the exact value lies within a few f32 roundings of a
    /// rounding boundary), on the benchmark's sphere and teapot, a cylinder and a two-sided
    /// scene, at sizes up to 1024.
    #[test]
    fn gouraud_pixels_are_the_exact_perspective_correct_interpolation() {
        let mut two_sided = bench_scene(91);
        two_sided.light_model.two_sided = true;
        let (sphere, teapot) = (sphere::glu_sphere(1.0, 50, 50), teapot::glut_teapot(0.8, 7));
        let cylinder = crate::mesh::cylinder::glu_cylinder(0.6, 0.3, 1.2, 24, 6, true);
        let cases = [
            (bench_scene(199), &sphere, 1024, 1024),
            (bench_scene(199), &teapot, 512, 512),
            (bench_scene(13), &cylinder, 333, 251),
            (two_sided, &teapot, 400, 300),
        ];
        let (mut pixels, mut off) = (0, 0);
        for (scene, mesh, w, h) in cases {
            let job = bench_job(&scene, mesh, Shading::Gouraud);
            let mut r = Renderer::new();
            r.keep_visibility(true);
            let image = r.render(&job, w, h).unwrap().0.clone();
            let two = scene.light_model.two_sided;
            for (i, &ri) in image.raster.iter().enumerate().filter(|(_, ri)| **ri != NO_TRIANGLE) {
                let t = &r.setup.tris[ri as usize];
                let (x, y) = (i % w, i / w);
                // Exact screen barycentrics: the integer edge functions over the area.
                let (wf, _, _) = visibility::ScreenBarycentrics::new(t).row(x, y);
                let xy = |k: usize| (t.x[k] as f64, t.y[k] as f64);
                let ((x0, y0), (x1, y1), (x2, y2)) = (xy(0), xy(1), xy(2));
                let area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
                let l = [1.0 - wf[0] / area - wf[1] / area, wf[0] / area, wf[1] / area];
                let q: [f64; 3] = std::array::from_fn(|k| l[k] * t.inv_w[k] as f64);
                let sum = q[0] + q[1] + q[2];
                let v = job.mesh.triangles[t.orig as usize];
                let side = (t.back && two) as usize;
                let vc = |j: usize| r.vertices.color[side][v[j] as usize];
                for c in 0..3 {
                    let at =
                        |k: usize| (0..3).map(|j| r.setup.corners.of(t)[k][j] as f64 * vc(j)[c] as f64).sum::<f64>();
                    let exact = (0..3).map(|k| q[k] / sum * at(k)).sum::<f64>();
                    let want = (255.0 * exact.clamp(0.0, 1.0)).round() as i32;
                    let got = image.rgba[4 * i + c] as i32;
                    assert!((got - want).abs() <= 1, "pixel {x},{y} channel {c}: {got} against exact {exact}");
                    off += (got != want) as usize;
                    pixels += 1;
                }
            }
        }
        eprintln!("{off} of {pixels} channels one level off the exact interpolation");
        assert!(pixels > 1_000_000, "{pixels}");
        assert!(off * 10_000 <= pixels, "{off} of {pixels} one level off");
    }

    /// A frame in which only the lighting changed (the light moved, its colour, the
    /// material, two-sided lighting) shades the last frame's kept
    /// visibility again without drawing: into the very bytes a new renderer draws from
    /// nothing, with the same counts, in every shading. A frame in which anything drawn
    /// changed (the object turned, one vertex moved by one bit, one triangle's corners
    /// turned, the size, culling, the shading) is drawn whole again.
    #[test]
    fn a_frame_that_only_lights_differently_shades_the_kept_visibility_into_the_same_bytes() {
        let (sphere, teapot) = (sphere::glu_sphere(1.0, 50, 50), teapot::glut_teapot(0.8, 7));
        let light_moved = |s: &mut Scene| s.lights[0].position = glam::DVec4::new(-1.5, 2.0, 2.5, 1.0);
        let two_sided = |s: &mut Scene| s.light_model.two_sided = true;
        let shinier = |s: &mut Scene| s.material.shininess = 90.0;
        let lighting: [&dyn Fn(&mut Scene); 3] = [&light_moved, &two_sided, &shinier];
        let (w, h) = (157, 131);
        let (mut frames_kept, mut drawn_again) = (0, 0);
        for (mesh, shading, flat_normal) in [
            (&sphere, Shading::Gouraud, FlatNormal::Face),
            (&teapot, Shading::Phong, FlatNormal::Face),
            (&teapot, Shading::Flat, FlatNormal::Face),
            (&sphere, Shading::Flat, FlatNormal::ScreenDerivatives),
        ] {
            fn job_with<'a>(scene: &'a Scene, mesh: &'a Mesh, shading: Shading, flat: FlatNormal) -> Job<'a> {
                Job { mode: ShadingMode::of(shading, flat), ..bench_job(scene, mesh, shading) }
            }
            let mut r = Renderer::new();
            let mut scene = bench_scene(37);
            assert!(
                !r.render(&job_with(&scene, mesh, shading, flat_normal), w, h).unwrap().1.visibility_kept,
                "the first frame is drawn"
            );
            for change in lighting {
                change(&mut scene);
                let job = job_with(&scene, mesh, shading, flat_normal);
                let (kept, stats) = r.render(&job, w, h).map(|(i, s)| (i.clone(), s)).unwrap();
                let (fresh, fresh_stats) = Renderer::new().render(&job, w, h).map(|(i, s)| (i.clone(), s)).unwrap();
                assert!(stats.visibility_kept, "{shading:?}");
                let differ = kept.rgba.iter().zip(&fresh.rgba).filter(|(a, b)| a != b).count();
                assert_eq!((differ, kept.rgba.len()), (0, fresh.rgba.len()), "{shading:?}: bytes that differ");
                assert_eq!(kept.coverage(), fresh.coverage());
                assert_eq!(
                    (stats.evaluations, stats.rasterised),
                    (fresh_stats.evaluations, fresh_stats.rasterised),
                    "{shading:?}"
                );
                frames_kept += 1;
            }
            // What is drawn changes: drawn again, into a fresh renderer's bytes.
            let mut nudged = mesh.clone();
            nudged.positions[7].x = f32::from_bits(nudged.positions[7].x.to_bits() + 1);
            let rotated = bench_scene(38);
            let mut turned = mesh.clone();
            turned.triangles[3].rotate_left(1);
            let mut culled = job_with(&scene, mesh, shading, flat_normal);
            culled.cull_back = true;
            let redrawn: [(Job<'_>, usize, usize); 6] = [
                (job_with(&rotated, mesh, shading, flat_normal), w, h),
                (job_with(&scene, &nudged, shading, flat_normal), w, h),
                (job_with(&scene, &turned, shading, flat_normal), w, h),
                (job_with(&scene, mesh, shading, flat_normal), w + 1, h),
                (culled, w, h),
                (Job { mode: ShadingMode::Phong, ..bench_job(&scene, mesh, Shading::Phong) }, w, h),
            ];
            for (job, w, h) in redrawn {
                let (image, stats) = r.render(&job, w, h).map(|(i, s)| (i.clone(), s)).unwrap();
                assert!(!stats.visibility_kept, "{shading:?}");
                let fresh = Renderer::new().render(&job, w, h).unwrap().0.rgba.clone();
                let differ = image.rgba.iter().zip(&fresh).filter(|(a, b)| a != b).count();
                assert_eq!((differ, image.rgba.len()), (0, fresh.len()), "{shading:?}: bytes that differ");
                drawn_again += 1;
            }
        }
        assert_eq!((frames_kept, drawn_again), (12, 24));
    }

    /// Picking and `surface_at` read the renderer's own kept visibility: at every pixel they
    /// answer alike whether the image keeps its visibility too or not; the images and the
    /// coverage are the same either way, and the coverage is the kept buffer's count.
    #[test]
    fn picking_answers_alike_whether_the_image_keeps_the_visibility_or_not() {
        let scene = bench_scene(37);
        for (mesh, shading) in
            [(sphere::glu_sphere(1.0, 50, 50), Shading::Phong), (teapot::glut_teapot(0.8, 7), Shading::Gouraud)]
        {
            let job = bench_job(&scene, &mesh, shading);
            // 61 rows: the last band is a short one.
            let (w, h) = (83, 61);
            let mut kept = Renderer::new();
            kept.keep_visibility(true);
            let mut redrawn = Renderer::new();
            let a = kept.render(&job, w, h).unwrap().0.clone();
            let b = redrawn.render(&job, w, h).unwrap().0.clone();
            assert_eq!(a.rgba, b.rgba);
            let counted = a.raster.iter().filter(|t| **t != NO_TRIANGLE).count();
            assert!(counted > 500, "{counted}");
            assert_eq!(a.coverage(), counted as f64 / (w * h) as f64);
            assert_eq!(b.coverage(), a.coverage());
            assert_eq!(b.covered(3, 3), None, "not kept");
            let mut surfaces = 0;
            for y in 0..h {
                for x in 0..w {
                    let i = y * w + x;
                    assert_eq!(a.covered(x, y), Some(a.raster[i] != NO_TRIANGLE));
                    assert_eq!(kept.surface_at(i), redrawn.surface_at(i), "pixel {x},{y}");
                    assert_eq!(kept.pick(&mesh, x, y), redrawn.pick(&mesh, x, y), "pixel {x},{y}");
                    surfaces += kept.surface_at(i).is_some() as usize;
                }
            }
            assert_eq!(surfaces, counted);
            assert_eq!(redrawn.pick(&mesh, w, 0), None, "outside the image");
        }
    }
}
