//! Stage 1: every mesh vertex to eye and clip space; Gouraud's per-vertex colours.

use glam::{Mat3, Mat4, Vec3, Vec4};
use rayon::prelude::*;

use super::Job;
use super::window::WindowVert;
use crate::model::transform::NormalMatrix;
use crate::specialise::lighter::{Lighter, Lit};

/// Per-vertex results of stage 1.
#[derive(Default)]
pub struct Vertices {
    /// Eye-space positions.
    pub eye: Vec<Vec3>,
    /// Clip-space positions.
    pub clip: Vec<Vec4>,
    /// Window coordinates of the clip-space positions (see
    /// [`super::window::window_vertices`]).
    pub window: Vec<WindowVert>,
    /// Where each clip-space position lies against the view volume (`outcodes::code`):
    /// setup reads these, not the positions, for the triangles it need not clip.
    pub codes: Vec<u8>,
    /// Eye-space normals, `(M^-1)^T n`, not yet normalised (Phong renormalises per pixel).
    pub normal: Vec<Vec3>,
    /// Gouraud: each vertex's colour per side, as the pipeline interpolates it: OpenGL
    /// clamps primary and secondary each to [0, 1], then adds them; a shader's varying (the
    /// Phong demo's `fragColor`) is interpolated unclamped. (The lighter's own results are
    /// a chunk's scratch, never a whole mesh's: 64 bytes a vertex saved.)
    pub color: [Vec<[f32; 4]>; 2],
}

thread_local! {
    /// Each thread's lighter results for one chunk, front and back (a chunk's scratch,
    /// never a whole mesh's).
    static SCRATCH: std::cell::RefCell<[Vec<Lit>; 2]> = const { std::cell::RefCell::new([Vec::new(), Vec::new()]) };
}

fn unclamped_sum(l: &Lit) -> [f32; 4] {
    let (p, s) = (l.primary, l.secondary);
    [p[0] + s[0], p[1] + s[1], p[2] + s[2], p[3]]
}

fn clamped_sum(l: &Lit) -> [f32; 4] {
    let c = |x: f32| x.clamp(0.0, 1.0);
    let (p, s) = (l.primary, l.secondary);
    [c(p[0]) + c(s[0]), c(p[1]) + c(s[1]), c(p[2]) + c(s[2]), c(p[3])]
}

/// Vertices a chunk of stage 1 takes (a multiple of 64: a chunk's bits of a vertex mask
/// are whole words).
const GRAIN: usize = 512;

impl Vertices {
    /// Transforms the job's mesh and, given `lighter` (Gouraud), lights it in the same pass;
    /// `window_vertices` takes a chunk of clip-space positions to the image's window
    /// coordinates and their codes against the view volume (a copy of
    /// [`super::window::window_vertices`] and `outcodes::codes` for this
    /// processor, chosen by the caller). Returns whether any vertex moved: whether an eye-space position or
    /// normal or a clip-space position differs, in any bit, from the last run's (or their
    /// count does).
    pub fn run(
        &mut self,
        job: &Job<'_>,
        lighter: Option<&Lighter>,
        window_vertices: impl Fn(&[Vec4], &mut [WindowVert], &mut [u8]) + Sync,
    ) -> bool {
        let mesh = job.mesh;
        let n = mesh.positions.len();
        let moved = std::sync::atomic::AtomicBool::new(n != self.eye.len());
        let eye_from_object = job.scene.eye_from_object();
        let mv = eye_from_object.as_mat4();
        let clip_from_object: Mat4 = job.clip_from_object.as_mat4();
        let nm: Mat3 = NormalMatrix::for_rules(&eye_from_object, job.scene.rules).eye_from_object.as_mat3();
        self.eye.resize(n, Vec3::ZERO);
        self.clip.resize(n, Vec4::ZERO);
        self.window.resize(n, (0, 0, 0.0, 0.0));
        self.codes.resize(n, 0);
        self.normal.resize(n, Vec3::ZERO);
        // One pass over chunks of vertices on both threads: transforms and, for Gouraud, the
        // lighting and each side's colour (one fork and join a frame for the whole stage).
        let lighter = lighter.filter(|_| job.mode.per_vertex());
        // Without a lighter the colours are left alone ([`Vertices::light`] makes them).
        let mut gouraud_chunks = if lighter.is_some() { color_chunks(&mut self.color, n) } else { Vec::new() };
        gouraud_chunks.resize_with(n.div_ceil(GRAIN), || None);
        self.eye
            .par_chunks_mut(GRAIN)
            .zip(self.clip.par_chunks_mut(GRAIN))
            .zip(self.normal.par_chunks_mut(GRAIN))
            .zip(self.window.par_chunks_mut(GRAIN))
            .zip(self.codes.par_chunks_mut(GRAIN))
            .zip(gouraud_chunks.into_par_iter())
            .enumerate()
            .for_each(|(k, (((((eye, clip), normal), window), codes), gouraud))| {
                let base = k * GRAIN;
                // Compared bit for bit with what is overwritten, without a branch.
                let mut same = true;
                for i in 0..eye.len() {
                    let p = mesh.positions[base + i];
                    let (e, c, nn) =
                        (mv.transform_point3(p), clip_from_object * p.extend(1.0), nm * mesh.normals[base + i]);
                    same &= bits(e.extend(0.0)) == bits(eye[i].extend(0.0))
                        && bits(c) == bits(clip[i])
                        && bits(nn.extend(0.0)) == bits(normal[i].extend(0.0));
                    (eye[i], clip[i], normal[i]) = (e, c, nn);
                }
                if !same {
                    moved.store(true, std::sync::atomic::Ordering::Relaxed);
                }
                window_vertices(clip, window, codes);
                if let (Some((cf, cb)), Some(lighter)) = (gouraud, lighter) {
                    light_chunk(job, lighter, base, cf, cb, None);
                }
            });
        moved.into_inner()
    }

    /// Gouraud: lights the job's mesh (a pass of its own, after [`Vertices::run`] without
    /// a lighter), every vertex, or with `only` those whose bit is set (the vertices of the
    /// triangles a kept visibility shows; the others' colours are left as they were, and
    /// never read).
    pub fn light(&mut self, job: &Job<'_>, lighter: &Lighter, only: Option<&[u64]>) {
        let chunks = color_chunks(&mut self.color, job.mesh.positions.len());
        chunks.into_par_iter().enumerate().for_each(|(k, c)| {
            if let Some((cf, cb)) = c {
                let mask = only.map(|m| m.get(k * GRAIN / 64..).unwrap_or(&[]));
                light_chunk(job, lighter, k * GRAIN, cf, cb, mask);
            }
        });
    }
}

/// Each side's colour of the vertices `base..base + cf.len()` (or, with `mask`, of those
/// whose bit is set: gathered, lit, scattered back), as the pipeline interpolates it.
fn light_chunk(
    job: &Job<'_>,
    lighter: &Lighter,
    base: usize,
    cf: &mut [[f32; 4]],
    cb: &mut [[f32; 4]],
    mask: Option<&[u64]>,
) {
    let two = job.scene.light_model.two_sided;
    let sum = if job.scene.rules.clamps_vertex_colors() { clamped_sum } else { unclamped_sum };
    let r = base..base + cf.len();
    let (pos, nrm) = (&job.mesh.positions[r.clone()], &job.mesh.normals[r]);
    // The masked vertices gathered (on the stack: a chunk is at most GRAIN).
    let (mut at, mut gp, mut gn) = ([0u16; GRAIN], [Vec3::ZERO; GRAIN], [Vec3::ZERO; GRAIN]);
    let (pos, nrm, at) = match mask {
        None => (pos, nrm, None),
        Some(m) => {
            let mut k = 0;
            for i in 0..pos.len() {
                if super::mask::is_set(m, i) {
                    (at[k], gp[k], gn[k]) = (i as u16, pos[i], nrm[i]);
                    k += 1;
                }
            }
            (&gp[..k], &gn[..k], Some(&at[..k]))
        }
    };
    SCRATCH.with_borrow_mut(|[f, b]| {
        // The thread's scratch, sized once: no allocation or clearing per chunk.
        f.resize(GRAIN, Lit::default());
        b.resize(GRAIN, Lit::default());
        let (f, b) = (&mut f[..pos.len()], &mut b[..pos.len()]);
        lighter.light_batch(pos, nrm, f, if two { Some(&mut *b) } else { None });
        // One-sided: the back side's colour is the front's.
        let back = if two { &*b } else { &*f };
        match at {
            None => {
                for (c, l) in cf.iter_mut().zip(f.iter()) {
                    *c = sum(l);
                }
                for (c, l) in cb.iter_mut().zip(back) {
                    *c = sum(l);
                }
            }
            Some(at) => {
                for (k, &i) in at.iter().enumerate() {
                    (cf[i as usize], cb[i as usize]) = (sum(&f[k]), sum(&back[k]));
                }
            }
        }
    });
}

/// Gouraud's colour arrays (`color`) sized to `n` vertices (emptied when `n` is 0), in
/// chunks of [`GRAIN`].
#[allow(clippy::type_complexity)]
fn color_chunks(color: &mut [Vec<[f32; 4]>; 2], n: usize) -> Vec<Option<(&mut [[f32; 4]], &mut [[f32; 4]])>> {
    for side in color.iter_mut() {
        side.resize(n, [0.0; 4]);
    }
    let [front, back] = color;
    front.chunks_mut(GRAIN).zip(back.chunks_mut(GRAIN)).map(Some).collect()
}

/// A vector's bits, for comparing exactly (NaN equal to itself, -0 unequal to +0).
#[inline(always)]
fn bits(v: Vec4) -> [u32; 4] {
    v.to_array().map(f32::to_bits)
}
