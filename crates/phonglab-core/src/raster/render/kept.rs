//! The kept visibility: the last frame's triangle at every pixel, and what it was drawn
//! from, so that a frame in which only the lighting changed shades it again without
//! setting up, binning or drawing a triangle.
//!
//! Which triangle covers a pixel does not depend on the lights, the material or the
//! colours. It depends on the vertices' positions (the vertex stage says, bit for bit,
//! whether any moved), the triangles, the image's size, the shading (the triangles setup
//! makes) and culling. [`KeptVisibility`] holds the pixels and those inputs, and answers
//! one question a frame: may this frame shade the kept pixels again?
//!
//! Its invariants:
//!
//! 1. `pixels` is always the last frame's visibility (the rasterised triangle at each
//!    pixel, rows from the top, [`NO_TRIANGLE`] where uncovered), whether or not that
//!    frame kept the one before: picking reads it.
//! 2. `drawn.valid` says that `drawn` describes the frame `pixels` was drawn from. It is
//!    false before the first frame and from the moment a frame decides to draw whole
//!    ([`KeptVisibility::decide`]) until it records what it drew
//!    ([`KeptVisibility::record`]).
//! 3. `drawn.seen` (and `drawn.seen_vertices` with it) is `None` or the triangles and mesh
//!    vertices that `pixels` shows: cleared by every record, made on the first frame that
//!    needs it.
//! 4. `last_kept` says the last frame kept the visibility of the one before. Gouraud then
//!    lights its vertices apart from their transforms ([`KeptVisibility::lights_apart`]):
//!    only once it is known whether this frame keeps too can it light just the vertices
//!    the kept pixels show.

use super::setup::Setup;
use super::{Job, NO_TRIANGLE, mask, resolve};
use crate::mesh::Mesh;
use crate::model::view::ShadingMode;

/// Triangles compared or copied a chunk at a time on all cores.
const TRIANGLE_GRAIN: usize = 1 << 16;

/// The last frame's visibility and what it was drawn from (see the module's invariants).
#[derive(Default)]
pub(super) struct KeptVisibility {
    /// The last frame's visibility: the rasterised triangle at each pixel, rows from the
    /// top ([`NO_TRIANGLE`] where uncovered).
    pixels: Vec<u32>,
    /// What the last frame was drawn from, besides its vertices.
    drawn: Drawn,
    /// The last frame kept the visibility of the one before.
    last_kept: bool,
}

/// What a frame's visibility depends on besides its vertices' positions: the image's size,
/// the shading (the triangles and attributes it sets up), culling, and the triangles.
#[derive(Default)]
struct Drawn {
    /// Does it describe the last frame? (Not before the first, nor while one is drawn.)
    valid: bool,
    width: usize,
    height: usize,
    mode: Option<ShadingMode>,
    cull_back: bool,
    depth_test: bool,
    triangles: Vec<[u32; 3]>,
    /// A bit for each rasterised triangle the frame shows at some pixel (made on the first
    /// frame that needs it: [`resolve::seen_triangles`]).
    seen: Option<Vec<u64>>,
    /// A bit for each mesh vertex of those triangles (made with `seen`).
    seen_vertices: Vec<u64>,
}

impl KeptVisibility {
    /// Does a frame of `mode` light its vertices in a pass apart from their transforms?
    /// Gouraud after a frame that kept its visibility: then, if this one keeps it too,
    /// only the vertices it shows are lit.
    pub fn lights_apart(&self, mode: ShadingMode) -> bool {
        mode == ShadingMode::Gouraud && self.last_kept
    }

    /// Decides whether `job` at this size shades the kept pixels again: no vertex `moved`,
    /// and the triangles, size, shading and culling are the last frame's. When it does
    /// not, nothing is kept until the frame drawn whole is recorded.
    pub fn decide(&mut self, job: &Job<'_>, width: usize, height: usize, moved: bool) -> bool {
        let kept = !moved && self.drawn.is_for(job, width, height, self.pixels.len());
        self.drawn.valid &= kept;
        self.last_kept = kept;
        kept
    }

    /// Records what `job` at this size was drawn from, once its pixels are in place.
    pub fn record(&mut self, job: &Job<'_>, width: usize, height: usize) {
        self.drawn.record(job, width, height);
    }

    /// The triangles and the mesh vertices the kept pixels (of `setup`'s triangles, drawn
    /// from `mesh`) show, a bit each: made once per frame drawn whole.
    pub fn seen(&mut self, setup: &Setup, mesh: &Mesh) -> (&[u64], &[u64]) {
        self.drawn.seen(&self.pixels, setup, mesh)
    }

    /// The last frame's visibility, rows from the top.
    pub fn pixels(&self) -> &[u32] {
        &self.pixels
    }

    /// The pixels to draw a `width` x `height` frame's visibility into (sized, their old
    /// contents left for the drawing to overwrite).
    pub fn pixels_to_draw(&mut self, width: usize, height: usize) -> &mut Vec<u32> {
        self.pixels.resize(width * height, NO_TRIANGLE);
        &mut self.pixels
    }
}

impl Drawn {
    /// Records what `job` at this size was drawn from (its triangles copied on all cores,
    /// into the same allocation from frame to frame).
    fn record(&mut self, job: &Job<'_>, width: usize, height: usize) {
        use rayon::prelude::*;
        let from = &job.mesh.triangles;
        self.triangles.resize(from.len(), [0; 3]);
        self.triangles
            .par_chunks_mut(TRIANGLE_GRAIN)
            .zip(from.par_chunks(TRIANGLE_GRAIN))
            .for_each(|(to, from)| to.copy_from_slice(from));
        (self.width, self.height, self.mode, self.cull_back, self.depth_test) =
            (width, height, Some(job.mode), job.cull_back, job.depth_test);
        self.seen = None;
        self.valid = true;
    }

    /// The triangles and the mesh vertices the kept visibility `kept` (of `setup`'s
    /// triangles, drawn from `mesh`) shows, a bit each: made once per frame drawn whole.
    fn seen(&mut self, kept: &[u32], setup: &Setup, mesh: &Mesh) -> (&[u64], &[u64]) {
        if self.seen.is_none() {
            let seen = resolve::seen_triangles(kept, setup.tris.len());
            let n = mesh.positions.len();
            self.seen_vertices.clear();
            self.seen_vertices.resize(n.div_ceil(64), 0);
            for (_, t) in setup.tris.iter().enumerate().filter(|(r, _)| mask::is_set(&seen, *r)) {
                for v in mesh.triangles.get(t.orig as usize).into_iter().flatten() {
                    mask::set(&mut self.seen_vertices, *v as usize);
                }
            }
            self.seen = Some(seen);
        }
        (self.seen.as_deref().unwrap_or(&[]), &self.seen_vertices)
    }

    /// Would `job` at this size draw the last frame's visibility (its vertices having not
    /// moved), with `kept` pixels kept?
    fn is_for(&self, job: &Job<'_>, width: usize, height: usize, kept: usize) -> bool {
        use rayon::prelude::*;
        let same_triangles = || {
            self.triangles.len() == job.mesh.triangles.len()
                && self
                    .triangles
                    .par_chunks(TRIANGLE_GRAIN)
                    .zip(job.mesh.triangles.par_chunks(TRIANGLE_GRAIN))
                    .all(|(a, b)| a == b)
        };
        self.valid
            && (self.width, self.height, self.mode, self.cull_back, self.depth_test)
                == (width, height, Some(job.mode), job.cull_back, job.depth_test)
            && kept == width * height
            && same_triangles()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::sphere;
    use crate::model::presets::bench_scene;
    use crate::model::view::Shading;
    use crate::raster::shaded::bench_job;

    /// The invariants, one by one: nothing is kept before a frame is recorded, nor after a
    /// frame that decided to draw whole until it records; a recorded frame is kept by the
    /// same job unless a vertex moved or the size, a triangle, culling or the shading
    /// changed; Gouraud lights apart only after a frame that kept.
    #[test]
    fn a_visibility_is_kept_only_for_what_it_was_drawn_from() {
        let scene = bench_scene(37);
        let mesh = sphere::glu_sphere(1.0, 8, 8);
        let job = bench_job(&scene, &mesh, Shading::Gouraud);
        let (w, h) = (20, 10);
        let mut k = KeptVisibility::default();
        assert!(!k.decide(&job, w, h, false), "nothing recorded yet");
        assert_eq!(k.pixels_to_draw(w, h).len(), w * h);
        k.record(&job, w, h);
        assert!(!k.lights_apart(ShadingMode::Gouraud), "the last frame was drawn whole");
        assert!(k.decide(&job, w, h, false));
        assert!(k.lights_apart(ShadingMode::Gouraud) && !k.lights_apart(ShadingMode::Phong));
        assert!(k.decide(&job, w, h, false), "kept again");
        assert!(!k.decide(&job, w + 1, h, false), "another size");
        assert!(!k.decide(&job, w, h, false), "nothing kept until the next frame is recorded");
        let mut turned = mesh.clone();
        turned.triangles[3].rotate_left(1);
        let others = [
            (job, true, "a vertex moved"),
            (bench_job(&scene, &turned, Shading::Gouraud), false, "a triangle's corners turned"),
            (Job { cull_back: true, ..job }, false, "culling"),
            (Job { depth_test: false, ..job }, false, "the depth test"),
            (bench_job(&scene, &mesh, Shading::Phong), false, "the shading"),
        ];
        for (other, moved, what) in others {
            k.record(&job, w, h);
            assert!(!k.decide(&other, w, h, moved), "{what}");
            assert!(!k.lights_apart(ShadingMode::Gouraud), "{what}");
        }
    }
}
