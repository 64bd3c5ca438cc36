//! The lighter's ways in: arrays of vertices (object or eye space, colours or their sums,
//! traced or timed) and one vertex. Each runs the chunked driver (`Lighter::run`) in the
//! copy compiled for this processor (`specialise::copies`).

use glam::Vec3;
use web_time::Instant;

use crate::equation::lighting::terms;
use crate::equation::plan::Stage;
use crate::model::scene::Vertex;
use crate::numerics::real::Vec3Ops;
use crate::numerics::robust::transform_point;
use crate::specialise::lighter::{EyeArrays, Lighter, Lit, Output, Recorder, Source, StageTimes};

impl Lighter {
    /// Lights vertices given in object space (w = 1): `front[i]` (and `back[i]` with
    /// two-sided lighting) receive the colours of `positions[i]`, `normals[i]`.
    pub fn light_batch(&self, positions: &[Vec3], normals: &[Vec3], front: &mut [Lit], back: Option<&mut [Lit]>) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        self.run(Source::Object { positions, normals }, Output::Lit { front, back }, Recorder::None);
    }

    /// [`Lighter::light_batch`] writing only each side's colour sum (primary + secondary
    /// rgb, unclamped): what Gouraud shading interpolates.
    pub fn light_batch_sum(
        &self,
        positions: &[Vec3],
        normals: &[Vec3],
        front: &mut [[f32; 4]],
        back: Option<&mut [[f32; 4]]>,
    ) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        self.run(Source::Object { positions, normals }, Output::Sum { front, back }, Recorder::None);
    }

    /// [`Lighter::light_batch_eye_sum`] with normals not yet normalised: each is
    /// renormalised first as the options say (exactly, by fast rsqrt, or not at all), as
    /// Phong shading treats its interpolated normals.
    pub fn light_batch_eye_sum_normalizing(
        &self,
        positions: &[Vec3],
        normals: &[Vec3],
        front: &mut [[f32; 4]],
        back: Option<&mut [[f32; 4]]>,
    ) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        self.run(Source::Eye { positions, normals, raw: true }, Output::Sum { front, back }, Recorder::None);
    }

    /// [`Lighter::light_batch_eye_sum`] (or, `raw_normals`,
    /// [`Lighter::light_batch_eye_sum_normalizing`]) from six arrays: the same stages, so
    /// the same bits.
    pub fn light_arrays_eye_sum(
        &self,
        arrays: EyeArrays<'_>,
        raw_normals: bool,
        front: &mut [[f32; 4]],
        back: Option<&mut [[f32; 4]]>,
    ) {
        self.run(Source::EyeArrays { arrays, raw: raw_normals }, Output::Sum { front, back }, Recorder::None);
    }

    /// Lights vertices given in eye space, positions (w = 1) and the normals the equation
    /// uses (already normalised as the caller wants), writing only each side's colour sum
    /// as [`Lighter::light_batch_sum`] does: per-pixel shading.
    pub fn light_batch_eye_sum(
        &self,
        positions: &[Vec3],
        normals: &[Vec3],
        front: &mut [[f32; 4]],
        back: Option<&mut [[f32; 4]]>,
    ) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        self.run(Source::Eye { positions, normals, raw: false }, Output::Sum { front, back }, Recorder::None);
    }

    /// [`Lighter::light_batch`] that also records every stage it ran, once per chunk, in
    /// order: what the tests check the program against.
    pub fn light_batch_traced(&self, positions: &[Vec3], normals: &[Vec3]) -> (Vec<[Lit; 2]>, Vec<Stage>) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        let mut front = vec![Lit::default(); positions.len()];
        let mut back = vec![Lit::default(); positions.len()];
        let mut trace = Vec::new();
        self.run(
            Source::Object { positions, normals },
            Output::Lit { front: &mut front, back: Some(&mut back) },
            Recorder::Trace(&mut trace),
        );
        let two = self.key().two_sided;
        (front.into_iter().zip(back).map(|(f, b)| [f, if two { b } else { f }]).collect(), trace)
    }

    /// [`Lighter::light_batch_sum`] that also measures the time each step took over all the
    /// chunks: loading, each stage of the program, writing the sums. For
    /// `phonglab bench lighting --stages` (the clock is read once a step per chunk of
    /// [`crate::specialise::lighter::CHUNK`] vertices, and that reading is counted in the
    /// step, so the figures are a little high).
    pub fn light_batch_timed(&self, positions: &[Vec3], normals: &[Vec3], front: &mut [[f32; 4]]) -> StageTimes {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        let mut times = StageTimes::default();
        let probe = Recorder::Time(&mut times, Instant::now());
        self.run(Source::Object { positions, normals }, Output::Sum { front, back: None }, probe);
        times
    }

    /// One vertex with any w, as [`crate::equation::lighting::Engine::light`] takes it (points at infinity go through
    /// the general engine).
    pub fn light_vertex(&self, v: &Vertex) -> [Lit; 2] {
        let e = self.engine();
        let pos_h = transform_point(&e.eye_from_object, v.position);
        let n_t = e.normal_matrix * Vec3::from_dvec3(v.normal);
        let n = terms::normal_mode::<f32>(e.normal_mode, e.rescale, n_t).0;
        if pos_h.w == 0.0 {
            let lit = e.light_eye(pos_h, n);
            return [
                Lit { primary: lit.front.primary, secondary: lit.front.secondary },
                Lit { primary: lit.back.primary, secondary: lit.back.secondary },
            ];
        }
        let mut out = [Lit::default(); 2];
        let (f, b) = out.split_at_mut(1);
        self.run(
            Source::One { pos: pos_h.truncate() / pos_h.w, n },
            Output::Lit { front: f, back: Some(b) },
            Recorder::None,
        );
        if !self.key().two_sided {
            out[1] = out[0];
        }
        out
    }
}
