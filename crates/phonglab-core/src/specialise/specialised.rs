//! The specialised evaluator: runs the [`Program`] a scene's [`Key`] compiles to, and
//! nothing else, over arrays of vertices.
//!
//! As Mesa's `ffvertex_prog.c` builds a vertex program from the fixed-function state key,
//! [`Program::compile`] turns the key into a list of [`Stage`]s once per key, and the chunk
//! loop runs exactly that list. What the key does not call for is not in the list, so it
//! does not run:
//!
//! | key says | stages left out |
//! |---|---|
//! | directional light | `LightVector`, `Attenuate`, `SpotCone`, `SpotPower` (L and the spot factor are constants) |
//! | directional light, infinite viewer, Blinn-Phong | `Halfway` (H is a constant) |
//! | attenuation (1, 0, 0) | `Attenuate` |
//! | cutoff 180 | `SpotCone`, `SpotPower` |
//! | zero specular product | `Halfway`/`Reflect`, `SpecularCosine`, `Power` |
//! | shininess 0 | `Power` (`x^0 = 1`) |
//! | one-sided | every back-side stage |
//! | GL_NORMALIZE off, or GL_RESCALE_NORMAL with a factor of exactly 1 | `NormalizeNormal`, `RescaleNormal` |
//! | directional lights and a constant V (an infinite viewer, not the worksheet's rule) | `TransformPosition` (nothing reads P) |
//! | an affine modelview (last row 0 0 0 1) | the fourth row and the division by w (`TransformPosition`, not `TransformPositionProjective`) |
//! | emission and scene ambient zero (or left out by the rules) | `SceneColor` |
//!
//! Vertices are processed in chunks of [`CHUNK`], as structures of arrays; each stage is
//! one loop over the chunk. Every stage computes its term with the same function of
//! `lighting::terms` (and `robust`) as the general [`Engine`], in the same order, so the two
//! agree bit for bit (tested on every public case and on random scenes), and a stage that
//! is left out is one whose result is known exactly (a product by 1, a sum with +0). The
//! program is rebuilt only when the key changes ([`Lighter::update`]); a value that moves
//! without switching an effect only refreshes the constants.

// The stages index parallel arrays by vertex: index loops are what vectorise here.
#![allow(clippy::needless_range_loop)]

use web_time::{Duration, Instant};

use glam::{DVec3, Vec3};

use super::copies::prefetch;
use crate::equation::lighting::{Engine, EvalOptions, LightPos, PreparedLight, fast_rsqrt, terms};
use crate::model::error::SceneError;
use crate::model::rules::{SpecularGate, SpecularModel};
use crate::model::scene::{Scene, Vertex};
use crate::numerics::pow::PowFn;
use crate::numerics::real::Vec3Ops;
use crate::numerics::robust::{
    mul0, normalize3, normalize3_unscaled, transform_affine_rows, transform_point, transform_point_rows,
    translate_point, unscaled_is_exact,
};
use crate::specialise::plan::{Key, Program, SourceKind, Stage};

/// Vertices per chunk: the arrays of a chunk stay in L1 cache.
pub const CHUNK: usize = 64;

/// One vertex's lit colours on one side.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lit {
    /// Primary colour (unclamped), alpha = the material's diffuse alpha.
    pub primary: [f32; 4],
    /// Secondary colour: the specular sum with separate specular (alpha 1), else 0.
    pub secondary: [f32; 4],
}

/// The specialised evaluator for one scene (f32, like OpenGL).
#[derive(Clone, Debug)]
pub struct Lighter {
    key: Key,
    engine: Engine<f32>,
    /// The programs for each source of vertices, compiled from the key.
    object: Program,
    eye: Program,
    eye_raw: Program,
    /// Per light, the constants of a directional light: L and H.
    consts: Vec<LightConsts>,
    replans: usize,
}

#[derive(Clone, Copy, Debug, Default)]
struct LightConsts {
    /// L for a directional light (`None`: direction (0, 0, 0), or positional).
    l: Option<Vec3>,
    /// H for a directional light with an infinite viewer under Blinn-Phong.
    h: Option<Vec3>,
    /// The spot factor of a directional light (att = 1): its scale, constant over vertices.
    scale: f32,
}

/// Where the colours go.
pub(super) enum Output<'a> {
    /// Primary and secondary per side.
    Lit { front: &'a mut [Lit], back: Option<&'a mut [Lit]> },
    /// The colour sum (primary + secondary rgb, primary alpha) per side: what a fragment
    /// receives.
    Sum { front: &'a mut [[f32; 4]], back: Option<&'a mut [[f32; 4]]> },
}

/// Where a chunk's positions and normals come from.
#[derive(Clone, Copy)]
pub(super) enum Source<'a> {
    /// Object space (w = 1): the program transforms them.
    Object { positions: &'a [Vec3], normals: &'a [Vec3] },
    /// Eye space: the normals as the equation uses them, or (`raw`) to renormalise.
    Eye { positions: &'a [Vec3], normals: &'a [Vec3], raw: bool },
    /// Eye space, as six arrays: the normals as the equation uses them, or (`raw`) to
    /// renormalise.
    EyeArrays { arrays: EyeArrays<'a>, raw: bool },
    /// One eye-space vertex (already divided by w) with its final normal.
    One { pos: DVec3, n: Vec3 },
}

/// Eye-space points (w = 1) and normals as six arrays, x, y and z of each (structure of
/// arrays): what the renderer's per-pixel fragments are, so that the lighting loads them
/// without taking vectors apart.
#[derive(Clone, Copy, Debug)]
pub struct EyeArrays<'a> {
    /// The points' x, y and z.
    pub pos: [&'a [f32]; 3],
    /// The normals' x, y and z.
    pub nrm: [&'a [f32]; 3],
}

impl EyeArrays<'_> {
    /// The number of points (the shortest array's length).
    pub fn len(&self) -> usize {
        self.pos.iter().chain(&self.nrm).map(|a| a.len()).min().unwrap_or(0)
    }

    /// No points?
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl Source<'_> {
    fn len(&self) -> usize {
        match self {
            Source::Object { positions, .. } | Source::Eye { positions, .. } => positions.len(),
            Source::EyeArrays { arrays, .. } => arrays.len(),
            Source::One { .. } => 1,
        }
    }

    /// Asks for the inputs of the vertices `r` to be brought into the cache (see
    /// [`prefetch`]).
    #[inline(always)]
    fn prefetch(&self, r: std::ops::Range<usize>, with_positions: bool) {
        match *self {
            Source::Object { positions, normals } | Source::Eye { positions, normals, .. } => {
                prefetch(&normals[r.clone()]);
                if with_positions {
                    prefetch(&positions[r]);
                }
            }
            Source::EyeArrays { arrays: EyeArrays { pos, nrm }, .. } => {
                for a in &nrm {
                    prefetch(&a[r.clone()]);
                }
                if with_positions {
                    for a in &pos {
                        prefetch(&a[r.clone()]);
                    }
                }
            }
            Source::One { .. } => {}
        }
    }

    /// Loads the chunk's inputs from `start`: normals, and (`positions`: only where a
    /// stage reads them) object-space or eye-space points.
    #[inline(always)]
    fn load(&self, c: &mut Chunk, start: usize, with_positions: bool) {
        let n = c.len();
        match *self {
            Source::Object { positions, normals } | Source::Eye { positions, normals, .. } => {
                let normals = &normals[start..start + n];
                for i in 0..n {
                    let v = normals[i];
                    (c.nx[i], c.ny[i], c.nz[i]) = (v.x, v.y, v.z);
                }
                if with_positions {
                    let positions = &positions[start..start + n];
                    for i in 0..n {
                        let p = positions[i];
                        (c.px[i], c.py[i], c.pz[i]) = (p.x as f64, p.y as f64, p.z as f64);
                    }
                }
            }
            Source::EyeArrays { arrays: EyeArrays { pos, nrm }, .. } => {
                let (cn, cp) = ([&mut c.nx, &mut c.ny, &mut c.nz], [&mut c.px, &mut c.py, &mut c.pz]);
                for (dst, src) in cn.into_iter().zip(nrm) {
                    dst[..n].copy_from_slice(&src[start..start + n]);
                }
                if with_positions {
                    for (dst, src) in cp.into_iter().zip(pos) {
                        for (d, &x) in dst[..n].iter_mut().zip(&src[start..start + n]) {
                            *d = x as f64;
                        }
                    }
                }
            }
            Source::One { pos, n } => {
                (c.px[0], c.py[0], c.pz[0]) = (pos.x, pos.y, pos.z);
                (c.nx[0], c.ny[0], c.nz[0]) = (n.x, n.y, n.z);
            }
        }
    }
}

/// What a run records besides its output: nothing, the stages it ran (what the tests
/// check the program against), or the time each step took.
pub(super) enum Probe<'a> {
    None,
    Trace(&'a mut Vec<Stage>),
    /// The times so far, and when the step being timed began.
    Time(&'a mut StageTimes, Instant),
}

/// The time a run spent in each step, summed over its chunks.
#[derive(Clone, Debug, Default)]
pub struct StageTimes {
    /// Loading each chunk (transforming positions and normals into it) and clearing its sums.
    pub load: Duration,
    /// Each stage of the program, in order.
    pub stages: Vec<(Stage, Duration)>,
    /// Writing the colour sums out.
    pub write: Duration,
}

/// The time since `*at`, which moves on to now.
#[inline(always)]
fn lap(at: &mut Instant) -> Duration {
    let now = Instant::now();
    let d = now - *at;
    *at = now;
    d
}

/// Declares [`Chunk`]'s arrays once, each with the value a new chunk starts with (the
/// lanes past a chunk's length keep what was there: these values until a longer chunk
/// has run).
macro_rules! chunk_arrays {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $init:expr,)*) => {
        /// Per-chunk arrays, one array per component so loops vectorise.
        struct Chunk {
            n: usize,
            $($(#[$doc])* $name: $ty,)*
        }

        impl Chunk {
            fn new() -> Box<Self> {
                Box::new(Chunk { n: 0, $($name: $init,)* })
            }
        }
    };
}

chunk_arrays! {
    /// Positions: object space as loaded, eye space after `TransformPosition` (f64, as the
    /// general engine differences them).
    px: [f64; CHUNK] = [0.0; CHUNK],
    py: [f64; CHUNK] = [0.0; CHUNK],
    pz: [f64; CHUNK] = [0.0; CHUNK],
    /// Normals by component, and whether each is zero.
    nx: [f32; CHUNK] = [0.0; CHUNK],
    ny: [f32; CHUNK] = [0.0; CHUNK],
    nz: [f32; CHUNK] = [0.0; CHUNK],
    zero: [bool; CHUNK] = [false; CHUNK],
    /// V per vertex, and whether it is defined.
    vx: [f32; CHUNK] = [0.0; CHUNK],
    vy: [f32; CHUNK] = [0.0; CHUNK],
    vz: [f32; CHUNK] = [1.0; CHUNK],
    v_ok: [bool; CHUNK] = [true; CHUNK],
    /// The current light's L (f32 and f64), whether it is defined, and d.
    lx: [f32; CHUNK] = [0.0; CHUNK],
    ly: [f32; CHUNK] = [0.0; CHUNK],
    lz: [f32; CHUNK] = [0.0; CHUNK],
    l_ok: [bool; CHUNK] = [false; CHUNK],
    lx64: [f64; CHUNK] = [0.0; CHUNK],
    ly64: [f64; CHUNK] = [0.0; CHUNK],
    lz64: [f64; CHUNK] = [0.0; CHUNK],
    d: [f32; CHUNK] = [0.0; CHUNK],
    /// The spot cosine and cone test; att spot.
    spot_cos: [f32; CHUNK] = [0.0; CHUNK],
    inside: [bool; CHUNK] = [false; CHUNK],
    scale: [f32; CHUNK] = [1.0; CHUNK],
    /// The current light's H (Blinn-Phong) or R (Phong), and whether it is defined.
    hx: [f32; CHUNK] = [0.0; CHUNK],
    hy: [f32; CHUNK] = [0.0; CHUNK],
    hz: [f32; CHUNK] = [0.0; CHUNK],
    h_ok: [bool; CHUNK] = [false; CHUNK],
    /// Per side: where the current light's specular is allowed, as its `Power` stage found
    /// it (read by its `Sum`).
    allowed: [[bool; CHUNK]; 2] = [[false; CHUNK]; 2],
    /// The normals negated (the back side's), by component.
    neg: [[f32; CHUNK]; 3] = [[0.0; CHUNK]; 3],
    /// Per side: n . L, the specular cosine, the power.
    ndl: [[f32; CHUNK]; 2] = [[0.0; CHUNK]; 2],
    cos: [[f32; CHUNK]; 2] = [[0.0; CHUNK]; 2],
    p: [[f32; CHUNK]; 2] = [[1.0; CHUNK]; 2],
    /// Sums per (side, primary or secondary) and channel.
    acc: [[[f32; CHUNK]; 3]; 4] = [[[0.0; CHUNK]; 3]; 4],
}

impl Chunk {
    /// The vertices in the chunk. Always `n`, but written with its bound so that the
    /// compiler knows every index below it is in range (no bounds checks in the loops,
    /// which then vectorise).
    #[inline(always)]
    fn len(&self) -> usize {
        self.n.min(CHUNK)
    }

    /// The lanes the stages compute: all of them, [`CHUNK`], whatever `n` is. The lanes from
    /// `n` on hold the previous chunk's values (or the zeros of [`Chunk::new`]); they are
    /// computed like the others and never written out, and no stage mixes lanes (the
    /// range checks that choose a way, such as `unscaled_is_exact`, choose between ways
    /// that give the same bits). A constant trip count is what lets every loop vectorise
    /// whole: with `n` the compiler kept the last 16 vertices of a chunk (it was 128
    /// then; [`CHUNK`] is 64 now) for a scalar loop (its bound check), and the scalar lanes cost as much as the vector ones. Measured
    /// with `phonglab bench lighting`: 11.7 -> 9.9 ns a vertex on scene (a), 102 -> 79 on (c).
    #[inline(always)]
    fn lanes(&self) -> usize {
        CHUNK
    }
}

impl Lighter {
    /// Plans the evaluator for `scene` (refusing what OpenGL refuses).
    pub fn new(scene: &Scene, options: EvalOptions) -> Result<Self, SceneError> {
        let engine = Engine::<f32>::with_options(scene, options)?;
        let key = Key::of(scene, options);
        let consts = Self::fold(&engine, &key);
        let [object, eye, eye_raw] = Self::compile(&key, options);
        Ok(Lighter { key, engine, object, eye, eye_raw, consts, replans: 1 })
    }

    fn compile(key: &Key, options: EvalOptions) -> [Program; 3] {
        [
            Program::compile(key, SourceKind::Object),
            Program::compile(key, SourceKind::Eye),
            Program::compile(key, SourceKind::EyeRaw(options.renormalize)),
        ]
    }

    /// Takes a changed scene: recompiles if its key differs, else refreshes the constants
    /// only. Returns whether it recompiled.
    pub fn update(&mut self, scene: &Scene, options: EvalOptions) -> Result<bool, SceneError> {
        let engine = Engine::<f32>::with_options(scene, options)?;
        let key = Key::of(scene, options);
        let replan = key != self.key || options.renormalize != self.engine.options.renormalize;
        if replan {
            [self.object, self.eye, self.eye_raw] = Self::compile(&key, options);
            self.key = key;
            self.replans += 1;
        }
        self.consts = Self::fold(&engine, &self.key);
        self.engine = engine;
        Ok(replan)
    }

    /// How many times a program has been compiled (1 after [`Lighter::new`]).
    pub fn replans(&self) -> usize {
        self.replans
    }

    /// The key the program was compiled from.
    pub fn key(&self) -> &Key {
        &self.key
    }

    /// The program object-space vertices run (Gouraud, the vertex panel).
    pub fn program(&self) -> &Program {
        &self.object
    }

    /// The program `source` runs.
    pub fn program_for(&self, source: SourceKind) -> &Program {
        match source {
            SourceKind::Object => &self.object,
            SourceKind::Eye => &self.eye,
            SourceKind::EyeRaw(_) => &self.eye_raw,
        }
    }

    /// Constants that do not depend on the vertex: a directional light's L, its H under
    /// an infinite viewer, its spot factor.
    fn fold(engine: &Engine<f32>, key: &Key) -> Vec<LightConsts> {
        engine
            .lights
            .iter()
            .enumerate()
            .map(|(i, pl)| match pl.pos {
                LightPos::Directional { unit, .. } => {
                    let l = unit.map(Vec3::from_dvec3);
                    let h = match (l, key.per_vertex_halfway(i)) {
                        (Some(l), false) => terms::halfway::<f32>(l, Vec3::Z),
                        _ => None,
                    };
                    let spot = pl.spot.map_or(1.0, |sp| terms::spot(&sp, unit, engine.options.pow).2);
                    LightConsts { l, h, scale: mul0(1.0, spot) }
                }
                LightPos::Positional(_) => LightConsts::default(),
            })
            .collect()
    }

    /// Lights vertices given in object space (w = 1): `front[i]` (and `back[i]` with
    /// two-sided lighting) receive the colours of `positions[i]`, `normals[i]`.
    pub fn light_batch(&self, positions: &[Vec3], normals: &[Vec3], front: &mut [Lit], back: Option<&mut [Lit]>) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        self.run(Source::Object { positions, normals }, Output::Lit { front, back }, Probe::None);
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
        self.run(Source::Object { positions, normals }, Output::Sum { front, back }, Probe::None);
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
        self.run(Source::Eye { positions, normals, raw: true }, Output::Sum { front, back }, Probe::None);
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
        self.run(Source::EyeArrays { arrays, raw: raw_normals }, Output::Sum { front, back }, Probe::None);
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
        self.run(Source::Eye { positions, normals, raw: false }, Output::Sum { front, back }, Probe::None);
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
            Probe::Trace(&mut trace),
        );
        let two = self.key.two_sided;
        (front.into_iter().zip(back).map(|(f, b)| [f, if two { b } else { f }]).collect(), trace)
    }

    /// [`Lighter::light_batch_sum`] that also measures the time each step took over all the
    /// chunks: loading, each stage of the program, writing the sums. For
    /// `phonglab bench lighting --stages` (reading the clock costs some 20 ns a step per
    /// chunk of [`CHUNK`] vertices, so the figures are a little high).
    pub fn light_batch_timed(&self, positions: &[Vec3], normals: &[Vec3], front: &mut [[f32; 4]]) -> StageTimes {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        let mut times = StageTimes::default();
        let probe = Probe::Time(&mut times, Instant::now());
        self.run(Source::Object { positions, normals }, Output::Sum { front, back: None }, probe);
        times
    }

    /// One vertex with any w, as [`Engine::light`] takes it (points at infinity go through
    /// the general engine).
    pub fn light_vertex(&self, v: &Vertex) -> [Lit; 2] {
        let e = &self.engine;
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
            Probe::None,
        );
        if !self.key.two_sided {
            out[1] = out[0];
        }
        out
    }

    /// The chunked driver, as the portable code has it ([`super::copies`] runs it compiled
    /// for the processor).
    #[inline(always)]
    pub(super) fn run_portable(&self, src: Source<'_>, mut out: Output<'_>, mut probe: Probe<'_>) {
        let count = src.len();
        let front_len = match &out {
            Output::Lit { front, .. } => front.len(),
            Output::Sum { front, .. } => front.len(),
        };
        assert!(front_len >= count, "front output too short");
        let program = match src {
            Source::Object { .. } => &self.object,
            Source::Eye { raw: true, .. } | Source::EyeArrays { raw: true, .. } => &self.eye_raw,
            Source::Eye { raw: false, .. } | Source::EyeArrays { raw: false, .. } | Source::One { .. } => &self.eye,
        };
        let two = self.key.two_sided;
        let scene_color = program.has(Stage::SceneColor);
        // Positions are read by the stages that place the vertex: only a positional light or
        // a per-vertex V needs them.
        let with_positions = self.key.needs_positions();
        let mut c = Chunk::new();
        let mut start = 0;
        if let Probe::Time(t, _) = &mut probe {
            t.stages = program.stages.iter().map(|s| (*s, Duration::ZERO)).collect();
        }
        while start < count {
            c.n = CHUNK.min(count - start);
            // The chunk after next is asked for now, its inputs and the outputs it will write.
            let ahead = (start + 2 * CHUNK).min(count)..(start + 3 * CHUNK).min(count);
            src.prefetch(ahead.clone(), with_positions);
            match &out {
                Output::Lit { front, .. } => prefetch(&front[ahead]),
                Output::Sum { front, .. } => prefetch(&front[ahead]),
            }
            src.load(&mut c, start, with_positions);
            self.clear_sums(&mut c);
            if let Probe::Time(t, at) = &mut probe {
                t.load += lap(at);
            }
            for (k, &stage) in program.stages.iter().enumerate() {
                self.stage(&mut c, stage);
                match &mut probe {
                    Probe::Trace(t) => t.push(stage),
                    Probe::Time(t, at) => t.stages[k].1 += lap(at),
                    Probe::None => {}
                }
            }
            let r = start..start + c.n;
            match &mut out {
                Output::Lit { front, back } => {
                    self.write(&c, 0, scene_color, &mut front[r.clone()]);
                    if let Some(b) = back.as_deref_mut().filter(|_| two) {
                        self.write(&c, 1, scene_color, &mut b[r]);
                    }
                }
                Output::Sum { front, back } => {
                    self.write_sum(&c, 0, scene_color, &mut front[r.clone()]);
                    if let Some(b) = back.as_deref_mut().filter(|_| two) {
                        self.write_sum(&c, 1, scene_color, &mut b[r]);
                    }
                }
            }
            if let Probe::Time(t, at) = &mut probe {
                t.write += lap(at);
            }
            start += c.n;
        }
    }

    /// Zeroes the sums that will be read: per side, the primary, and the secondary with
    /// separate specular.
    #[inline(always)]
    fn clear_sums(&self, c: &mut Chunk) {
        let n = c.lanes();
        let sides = if self.key.two_sided { 2 } else { 1 };
        let kinds = if self.key.separate_specular { 2 } else { 1 };
        for side in 0..sides {
            for k in 2 * side..2 * side + kinds {
                for ch in 0..3 {
                    c.acc[k][ch][..n].fill(0.0);
                }
            }
        }
    }

    /// Runs one stage over the chunk.
    #[inline(always)]
    fn stage(&self, c: &mut Chunk, stage: Stage) {
        let e = &self.engine;
        let n = c.lanes();
        match stage {
            Stage::TransformNormal => {
                // glam's `Mat3 * Vec3`: x_axis x + y_axis y + z_axis z, per component.
                let m = e.normal_matrix;
                for i in 0..n {
                    let (x, y, z) = (c.nx[i], c.ny[i], c.nz[i]);
                    c.nx[i] = m.x_axis.x * x + m.y_axis.x * y + m.z_axis.x * z;
                    c.ny[i] = m.x_axis.y * x + m.y_axis.y * y + m.z_axis.y * z;
                    c.nz[i] = m.x_axis.z * x + m.y_axis.z * y + m.z_axis.z * z;
                }
            }
            Stage::RescaleNormal => {
                let s = e.rescale;
                for i in 0..n {
                    c.nx[i] *= s;
                    c.ny[i] *= s;
                    c.nz[i] *= s;
                }
            }
            Stage::NormalizeNormal => {
                // robust::normalize_or_zero.
                for i in 0..n {
                    let (x, y, z, _, ok) = normalize3::<f32>(c.nx[i], c.ny[i], c.nz[i]);
                    c.nx[i] = if ok { x } else { 0.0 };
                    c.ny[i] = if ok { y } else { 0.0 };
                    c.nz[i] = if ok { z } else { 0.0 };
                }
            }
            Stage::NormalizeNormalFast => {
                for i in 0..n {
                    let (x, y, z) = (c.nx[i], c.ny[i], c.nz[i]);
                    let q = x * x + y * y + z * z;
                    let inv = if q > 0.0 { fast_rsqrt(q) } else { 0.0 };
                    c.nx[i] = x * inv;
                    c.ny[i] = y * inv;
                    c.nz[i] = z * inv;
                }
            }
            Stage::TransformPosition => {
                // robust::transform_point of an affine matrix on components (w = 1: the
                // fourth row and the division are left out), the rows taken out once.
                let rows = e.eye_from_object.transpose().to_cols_array_2d();
                for i in 0..n {
                    let [x, y, z] = transform_affine_rows(&rows, [c.px[i], c.py[i], c.pz[i]]);
                    (c.px[i], c.py[i], c.pz[i]) = (x, y, z);
                }
            }
            Stage::TranslatePosition => {
                // robust::translate_point: the translation is the matrix's last column.
                let t = e.eye_from_object.w_axis.truncate().to_array();
                for i in 0..n {
                    let [x, y, z] = translate_point(t, [c.px[i], c.py[i], c.pz[i]]);
                    (c.px[i], c.py[i], c.pz[i]) = (x, y, z);
                }
            }
            Stage::TransformPositionProjective => {
                // robust::transform_point on components, then the division by w.
                let rows = e.eye_from_object.transpose().to_cols_array_2d();
                for i in 0..n {
                    let [x, y, z, w] = transform_point_rows(&rows, [c.px[i], c.py[i], c.pz[i], 1.0]);
                    (c.px[i], c.py[i], c.pz[i]) = (x / w, y / w, z / w);
                }
            }
            Stage::ZeroNormals => {
                for i in 0..n {
                    c.zero[i] = terms::is_zero_normal::<f32>(Vec3::new(c.nx[i], c.ny[i], c.nz[i]));
                }
            }
            Stage::ViewVector => self.view_vector(c, n),
            Stage::LightVector(li) => self.light_vector(c, n, li),
            Stage::LightConstant(li) => self.light_constant(c, n, li),
            Stage::Attenuate(li) => {
                let k = e.lights[li].k;
                for i in 0..n {
                    c.scale[i] = terms::attenuation(k, c.d[i]);
                }
            }
            Stage::SpotCone(li) => self.spot_cone(c, n, li),
            Stage::SpotPower(li) => self.spot_power(c, n, li),
            Stage::Halfway(_) => {
                // terms::halfway: normalize(L + V), defined where L, V and L + V are.
                for i in 0..n {
                    let (x, y, z, _, ok) = normalize3::<f32>(c.lx[i] + c.vx[i], c.ly[i] + c.vy[i], c.lz[i] + c.vz[i]);
                    (c.hx[i], c.hy[i], c.hz[i]) = (x, y, z);
                    c.h_ok[i] = ok & c.l_ok[i] & c.v_ok[i];
                }
            }
            Stage::HalfwayConstant(li) => {
                // `SpecularCosine` reads the constant itself.
                c.h_ok[..n].fill(self.consts[li].h.is_some());
            }
            Stage::Reflect(_) => {
                let clamped = e.rules.reflect_clamped();
                for i in 0..n {
                    let (x, y, z) = terms::reflect3(c.nx[i], c.ny[i], c.nz[i], c.lx[i], c.ly[i], c.lz[i], clamped);
                    (c.hx[i], c.hy[i], c.hz[i]) = (x, y, z);
                    // R is defined where L is and the normal is not zero; R . V needs V.
                    c.h_ok[i] = c.l_ok[i] & !c.zero[i] & c.v_ok[i];
                }
            }
            Stage::DiffuseCosine(li, side) => self.diffuse_cosine(c, n, li, side),
            Stage::SpecularCosine(li, side) => self.specular_cosine(c, n, li, side),
            Stage::Power(_, side) => self.power(c, n, side),
            Stage::Sum(li, side) => self.sum(c, &e.lights[li], side),
            // Added as the colours are written (`write`, `write_sum`).
            Stage::SceneColor => {}
        }
    }

    /// V at each vertex: `normalize(-P)` for a local viewer (in f64, unscaled where that
    /// changes no bit), else the worksheet's axis `(0, 0, -sign(P.z))` (terms::view_vector
    /// on components, so the loops vectorise).
    #[inline(always)]
    fn view_vector(&self, c: &mut Chunk, n: usize) {
        // terms::view_vector on components, so the loops vectorise.
        if self.key.local_viewer {
            // normalize(-P), in f64 (unscaled where that changes no bit), rounded to f32.
            let mut plain = true;
            for i in 0..n {
                plain &= unscaled_is_exact(c.px[i]) & unscaled_is_exact(c.py[i]) & unscaled_is_exact(c.pz[i]);
            }
            macro_rules! view_vectors {
                ($norm:expr) => {
                    for i in 0..n {
                        let (x, y, z, _, ok) = $norm(-c.px[i], -c.py[i], -c.pz[i]);
                        (c.vx[i], c.vy[i], c.vz[i], c.v_ok[i]) = (x as f32, y as f32, z as f32, ok);
                    }
                };
            }
            if plain {
                view_vectors!(normalize3_unscaled);
            } else {
                view_vectors!(normalize3::<f64>);
            }
        } else {
            // The stage runs only for a local viewer or the worksheet's rule
            // (plan::Key::per_vertex_view), so here V = (0, 0, -sign(P.z)),
            // undefined on the plane z = 0.
            for i in 0..n {
                let z = c.pz[i];
                (c.vx[i], c.vy[i]) = (0.0, 0.0);
                c.vz[i] = if z > 0.0 { -1.0 } else { 1.0 };
                c.v_ok[i] = z.abs() > 0.0; // false for 0 and NaN
            }
        }
    }

    /// A positional light's L and d at each vertex, in f64 (terms::light_direction on
    /// components), and the scale reset to 1 for `Attenuate` and `SpotPower`.
    #[inline(always)]
    fn light_vector(&self, c: &mut Chunk, n: usize, li: usize) {
        let e = &self.engine;
        let LightPos::Positional(lp) = e.lights[li].pos else { return };
        // terms::light_direction on components: one robust::normalize3 in f64, without
        // its scaling where that changes no bit (robust::unscaled_is_exact).
        for i in 0..n {
            (c.lx64[i], c.ly64[i], c.lz64[i]) = (lp.x - c.px[i], lp.y - c.py[i], lp.z - c.pz[i]);
        }
        let mut plain = true;
        for i in 0..n {
            plain &= unscaled_is_exact(c.lx64[i]) & unscaled_is_exact(c.ly64[i]) & unscaled_is_exact(c.lz64[i]);
        }
        macro_rules! light_vectors {
            ($norm:expr) => {
                for i in 0..n {
                    let (x, y, z, d, ok) = $norm(c.lx64[i], c.ly64[i], c.lz64[i]);
                    (c.lx64[i], c.ly64[i], c.lz64[i], c.l_ok[i]) = (x, y, z, ok);
                    (c.lx[i], c.ly[i], c.lz[i]) = (x as f32, y as f32, z as f32);
                    c.d[i] = d as f32;
                }
            };
        }
        if plain {
            light_vectors!(normalize3_unscaled);
        } else {
            light_vectors!(normalize3::<f64>);
        }
        c.scale[..n].fill(1.0);
    }

    /// A directional light's constant L (and its scale), as arrays where H or R reads them.
    #[inline(always)]
    fn light_constant(&self, c: &mut Chunk, n: usize, li: usize) {
        let e = &self.engine;
        let k = &self.consts[li];
        c.l_ok[..n].fill(k.l.is_some());
        c.scale[..n].fill(k.scale);
        // The cosines read the constant itself; per-vertex H or R read it as arrays.
        let per_vertex_h_or_r = self.key.lights[li].specular
            && (e.rules.specular == SpecularModel::Phong || self.key.per_vertex_halfway(li));
        if per_vertex_h_or_r {
            let l = k.l.unwrap_or(Vec3::ZERO);
            c.lx[..n].fill(l.x);
            c.ly[..n].fill(l.y);
            c.lz[..n].fill(l.z);
        }
    }

    /// The cosine of each L to the spot axis and the cone test (terms::spot_cone).
    #[inline(always)]
    fn spot_cone(&self, c: &mut Chunk, n: usize, li: usize) {
        let e = &self.engine;
        let Some(sp) = e.lights[li].spot else { return };
        match sp.axis {
            None => c.inside[..n].fill(false),
            Some(axis) => {
                for i in 0..n {
                    let l = DVec3::new(c.lx64[i], c.ly64[i], c.lz64[i]);
                    let (cos, inside) = terms::spot_cone(&sp, axis, l);
                    c.spot_cos[i] = cos;
                    c.inside[i] = c.l_ok[i] & inside;
                }
            }
        }
    }

    /// The spot factor (the cosine raised to the spot exponent inside the cone), folded into
    /// the scale.
    #[inline(always)]
    fn spot_power(&self, c: &mut Chunk, n: usize, li: usize) {
        let e = &self.engine;
        let Some(sp) = e.lights[li].spot else { return };
        if sp.axis.is_none() {
            c.inside[..n].fill(false);
        }
        let mut f = [0.0f32; CHUNK];
        power_loop(e.options.pow, &c.spot_cos, &mut f, n, sp.exponent);
        for i in 0..n {
            let spot = keep_or_zero(c.inside[i], f[i]);
            // scale = mul0(att, spot), att from `Attenuate` (or 1).
            c.scale[i] = mul0(c.scale[i], spot);
        }
    }

    /// `n_side . L` at each vertex for `side`.
    #[inline(always)]
    fn diffuse_cosine(&self, c: &mut Chunk, n: usize, li: usize, side: usize) {
        // n_side . L with n_side = n or -n (negation is exact); a directional light's
        // L is the constant `consts[li].l`.
        let ndl = &mut c.ndl[side];
        let (nx, ny, nz) = if side == 0 { (&c.nx, &c.ny, &c.nz) } else { negated(&mut c.neg, &c.nx, &c.ny, &c.nz, n) };
        match self.consts.get(li).and_then(|k| k.l) {
            Some(l) if !self.key.lights[li].positional => {
                for i in 0..n {
                    ndl[i] = terms::dot3(nx[i], ny[i], nz[i], l.x, l.y, l.z);
                }
            }
            _ => {
                for i in 0..n {
                    ndl[i] = terms::dot3(nx[i], ny[i], nz[i], c.lx[i], c.ly[i], c.lz[i]);
                }
            }
        }
    }

    /// The specular cosine for `side`: `n_side . H` (Blinn-Phong) or `R . V` (Phong).
    #[inline(always)]
    fn specular_cosine(&self, c: &mut Chunk, n: usize, li: usize, side: usize) {
        let e = &self.engine;
        let cos = &mut c.cos[side];
        match e.rules.specular {
            SpecularModel::BlinnPhong => {
                let (nx, ny, nz) =
                    if side == 0 { (&c.nx, &c.ny, &c.nz) } else { negated(&mut c.neg, &c.nx, &c.ny, &c.nz, n) };
                match self.consts.get(li).and_then(|k| k.h) {
                    // HalfwayConstant: H is one vector.
                    Some(h) => {
                        for i in 0..n {
                            cos[i] = terms::dot3(nx[i], ny[i], nz[i], h.x, h.y, h.z);
                        }
                    }
                    None => {
                        for i in 0..n {
                            cos[i] = terms::dot3(nx[i], ny[i], nz[i], c.hx[i], c.hy[i], c.hz[i]);
                        }
                    }
                }
            }
            SpecularModel::Phong => {
                // R . V, the same on both sides (R is formed with the front normal).
                for i in 0..n {
                    cos[i] = terms::dot3(c.hx[i], c.hy[i], c.hz[i], c.vx[i], c.vy[i], c.vz[i]);
                }
            }
        }
    }

    /// The specular power for `side`, raised where `Sum` reads it.
    #[inline(always)]
    fn power(&self, c: &mut Chunk, n: usize, side: usize) {
        let e = &self.engine;
        // Raised where `Sum` reads the power (its specular is allowed there; the
        // lanes are kept for it in `Chunk::allowed`); the other lanes are raised as 0,
        // which the exact power does not compute at all (pow_f32_chunk_packed packs
        // the others together; without AVX-512 it skips blocks of 8 zeros). `Sum`
        // gives them f_i p = 0 whatever p is.
        let shin = e.sides[side].shininess;
        let mut allowed = [false; CHUNK];
        self.specular_lanes(c, side, &mut allowed);
        let mut x = [0.0f32; CHUNK];
        for i in 0..n {
            x[i] = keep_or_zero(allowed[i], c.cos[side][i]);
        }
        power_loop(e.options.pow, &x, &mut c.p[side], n, shin);
        c.allowed[side] = allowed;
    }

    /// Where the current light's specular is allowed on `side` (the `allowed` of
    /// `terms::shared_factors`): the light reaches the surface (L defined, normal not zero),
    /// H or R is defined, and the rule set's gate is open (`terms::specular_allowed`). Read
    /// by `Power` (which raises only these lanes) and `Sum`. One loop per gate (the gate is
    /// the scene's), `&` rather than `&&`, so each vectorises.
    #[inline(always)]
    fn specular_lanes(&self, c: &Chunk, side: usize, allowed: &mut [bool; CHUNK]) {
        let n = c.lanes();
        let (ndl, cos) = (&c.ndl[side], &c.cos[side]);
        let (l_ok, zero, h_ok) = (&c.l_ok, &c.zero, &c.h_ok);
        macro_rules! where_gate {
            ($g:expr) => {
                for i in 0..n {
                    allowed[i] = l_ok[i] & !zero[i] & h_ok[i] & terms::specular_allowed($g, ndl[i], cos[i]);
                }
            };
        }
        match self.engine.rules.specular_gate() {
            SpecularGate::LitSide => where_gate!(SpecularGate::LitSide),
            SpecularGate::PositiveCosine => where_gate!(SpecularGate::PositiveCosine),
            SpecularGate::None => where_gate!(SpecularGate::None),
        }
    }

    /// `Stage::Sum`: the light's terms channel by channel (`terms::channel`), added to the
    /// side's sums. First which vertices the light reaches and where its specular is
    /// allowed, then one loop per channel (so each vectorises).
    #[inline(always)]
    fn sum(&self, c: &mut Chunk, pl: &PreparedLight<f32>, side: usize) {
        let e = &self.engine;
        let n = c.lanes();
        let [amb, dif, spe] = pl.products[side].map(|v| v.to_array());
        let separate = e.separate_specular;
        let specular_on = self.key.lights.get(pl.index).is_some_and(|l| l.specular);
        let (ndl, scale) = (&c.ndl[side][..n], &c.scale[..n]);
        let (l_ok, zero) = (&c.l_ok[..n], &c.zero[..n]);
        // Shininess 0 (no `Power` stage): max(cos, 0)^0 = 1.
        let p = if self.key.shininess_zero[side] { &ONES[..n] } else { &c.p[side][..n] };
        // Where the specular is allowed: as `Power` found it for this light and side (it
        // ran just before, unless the shininess is 0), or found here.
        let mut own = [false; CHUNK];
        let allowed = if self.key.has_power(pl.index, side) {
            &c.allowed[side]
        } else {
            if specular_on {
                self.specular_lanes(c, side, &mut own);
            }
            &own
        };
        // The factors every channel shares (terms::shared_factors), once per vertex. `&`,
        // not `&&`: no short circuit, so the loop vectorises (every operand is defined).
        let mut dn = [0.0f32; CHUNK];
        let mut fp = [0.0f32; CHUNK];
        for i in 0..n {
            let lit = l_ok[i] & !zero[i];
            (dn[i], fp[i]) = terms::shared_factors(ndl[i], lit, allowed[i], p[i]);
        }
        let (dn, fp) = (&dn[..n], &fp[..n]);
        let (pri, sec) = c.acc[2 * side..2 * side + 2].split_at_mut(1);
        let channel = |acc: &mut [f32], ch: usize, k: usize| {
            for i in 0..n {
                let t = terms::channel(amb[ch], dif[ch], spe[ch], dn[i], fp[i], separate, scale[i]);
                acc[i] += if k == 2 { t.2 } else { t.3 };
            }
        };
        for ch in 0..3 {
            channel(&mut pri[0][ch][..n], ch, 2);
        }
        if separate {
            for ch in 0..3 {
                channel(&mut sec[0][ch][..n], ch, 3);
            }
        }
    }

    /// `terms::finish` for the chunk, written on plain arrays: `(e_cm + a_cm a_cs) + sum`
    /// (the first term only with `SceneColor` in the program), NaN shown as 0, the alphas.
    #[inline(always)]
    fn write(&self, c: &Chunk, side: usize, scene_color: bool, out: &mut [Lit]) {
        let m = &self.engine.sides[side];
        let base = (m.emission + m.scene_ambient).to_array();
        let sep = self.key.separate_specular;
        let fix = |x: f32| if x.is_nan() { 0.0 } else { x };
        let (pr, sc) = (&c.acc[2 * side], &c.acc[2 * side + 1]);
        for (i, o) in out.iter_mut().enumerate().take(c.len()) {
            let p = |ch: usize| if scene_color { base[ch] + pr[ch][i] } else { pr[ch][i] };
            o.primary = [fix(p(0)), fix(p(1)), fix(p(2)), m.alpha];
            o.secondary = if sep { [fix(sc[0][i]), fix(sc[1][i]), fix(sc[2][i]), 1.0] } else { [0.0; 4] };
        }
    }

    /// The colour sums of the chunk: `primary + secondary` rgb of [`Lighter::write`].
    #[inline(always)]
    fn write_sum(&self, c: &Chunk, side: usize, scene_color: bool, out: &mut [[f32; 4]]) {
        let m = &self.engine.sides[side];
        let base = if scene_color { (m.emission + m.scene_ambient).to_array() } else { [0.0; 3] };
        let fix = |x: f32| if x.is_nan() { 0.0 } else { x };
        let (pr, sc) = (&c.acc[2 * side], &c.acc[2 * side + 1]);
        // The sums by channel over the whole chunk first (loops of a constant length, which
        // vectorise), then interleaved into the output with the alpha.
        // Without `SceneColor`, base is +0 and `+0 + x = x` for every sum (which is never -0).
        let mut rgb = [[0.0f32; CHUNK]; 3];
        for (ch, sum) in rgb.iter_mut().enumerate() {
            if self.key.separate_specular {
                for i in 0..CHUNK {
                    sum[i] = fix(base[ch] + pr[ch][i]) + fix(sc[ch][i]);
                }
            } else {
                for i in 0..CHUNK {
                    sum[i] = fix(base[ch] + pr[ch][i]);
                }
            }
        }
        let n = out.len().min(c.len());
        let [r, g, b] = &rgb;
        for (i, o) in out[..n].iter_mut().enumerate() {
            *o = [r[i], g[i], b[i], m.alpha];
        }
    }
}

/// The back side's normal `-n` into `neg`, by component (negation is exact).
#[inline(always)]
fn negated<'a>(
    neg: &'a mut [[f32; CHUNK]; 3],
    nx: &[f32; CHUNK],
    ny: &[f32; CHUNK],
    nz: &[f32; CHUNK],
    n: usize,
) -> (&'a [f32; CHUNK], &'a [f32; CHUNK], &'a [f32; CHUNK]) {
    for i in 0..n.min(CHUNK) {
        neg[0][i] = -nx[i];
        neg[1][i] = -ny[i];
        neg[2][i] = -nz[i];
    }
    let [x, y, z] = neg;
    (x, y, z)
}

/// `p[i] = pow(max(x[i], 0), e)` over the chunk, with the scene's power function: the
/// exact one by `exact_pow::pow_f32_chunk` (a whole exponent by squarings over the array),
/// the others one vertex at a time, each loop compiled with its power inlined.
#[inline(always)]
fn power_loop(which: PowFn, x: &[f32; CHUNK], p: &mut [f32; CHUNK], n: usize, e: f32) {
    let n = n.min(CHUNK);
    match which {
        PowFn::Exact => crate::numerics::exact_pow::pow_f32_chunk_packed(x, e, p),
        PowFn::Llvmpipe => {
            for i in 0..n {
                p[i] = PowFn::Llvmpipe.pow(x[i].max(0.0), e);
            }
        }
        PowFn::Schlick => {
            for i in 0..n {
                p[i] = PowFn::Schlick.pow(x[i].max(0.0), e);
            }
        }
    }
}

/// `x` where `keep`, +0 elsewhere: `if keep { x } else { 0.0 }`, as a mask of the bits.
/// The `if` on a bool loaded from a chunk's array was compiled as a branch per vertex
/// (in chunks of 64); the mask is one vector AND.
#[inline(always)]
fn keep_or_zero(keep: bool, x: f32) -> f32 {
    f32::from_bits(x.to_bits() & (keep as u32).wrapping_neg())
}

/// Powers of 1, for a side with shininess 0.
static ONES: [f32; CHUNK] = [1.0; CHUNK];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::presets;

    #[test]
    fn the_timed_run_times_each_stage_of_the_program_and_lights_as_the_plain_one() {
        let scene = presets::LightingBench::PositionalLocal.scene();
        let l = Lighter::new(&scene, EvalOptions::default()).unwrap();
        let (pos, nrm) = presets::sphere_points(1000);
        let (mut plain, mut timed) = (vec![[0.0f32; 4]; 1000], vec![[0.0f32; 4]; 1000]);
        l.light_batch_sum(&pos, &nrm, &mut plain, None);
        let t = l.light_batch_timed(&pos, &nrm, &mut timed);
        assert_eq!(plain, timed);
        let stages: Vec<Stage> = t.stages.iter().map(|(s, _)| *s).collect();
        assert_eq!(stages, l.program().stages);
        assert!(stages.contains(&Stage::Halfway(0)));
        let total: Duration = t.load + t.write + t.stages.iter().map(|(_, d)| *d).sum::<Duration>();
        assert!(total > Duration::ZERO);
    }

    /// Fragments given as six arrays light exactly as the same fragments given as vectors,
    /// with normals to renormalise or not, one side or two, over lengths that end mid-chunk.
    #[test]
    fn arrays_light_as_vectors_do() {
        let mut next = crate::test_support::xorshift(0x6a09e667f3bcc909);
        let mut uniform = move || (next() % 2_000_001) as f32 / 1e6 - 1.0;
        for (scene, two) in [(presets::LightingBench::PositionalLocal.scene(), false), (presets::worksheet(5), true)] {
            let mut scene = scene;
            scene.light_model.two_sided = two;
            let l = Lighter::new(&scene, EvalOptions::default()).unwrap();
            for n in [1, 63, 64, 65, 127, 128, 300] {
                let pos: Vec<Vec3> = (0..n).map(|_| Vec3::new(uniform(), uniform(), uniform() - 3.0)).collect();
                let nrm: Vec<Vec3> = (0..n).map(|_| Vec3::new(uniform(), uniform(), uniform()) * 1.7).collect();
                let xyz = |v: &[Vec3]| [0, 1, 2].map(|c| v.iter().map(|p| p[c]).collect::<Vec<f32>>());
                let (pa, na) = (xyz(&pos), xyz(&nrm));
                let arrays = EyeArrays { pos: pa.each_ref().map(|a| &a[..]), nrm: na.each_ref().map(|a| &a[..]) };
                assert_eq!(arrays.len(), n);
                for raw in [true, false] {
                    let mut want = [vec![[0.0f32; 4]; n], vec![[0.0f32; 4]; n]];
                    let mut got = want.clone();
                    let [wf, wb] = &mut want;
                    match raw {
                        true => l.light_batch_eye_sum_normalizing(&pos, &nrm, wf, Some(wb)),
                        false => l.light_batch_eye_sum(&pos, &nrm, wf, Some(wb)),
                    }
                    let [gf, gb] = &mut got;
                    l.light_arrays_eye_sum(arrays, raw, gf, Some(gb));
                    let bits =
                        |v: &[Vec<[f32; 4]>; 2]| v.iter().flatten().flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&got), bits(&want), "n {n}, raw {raw}, two-sided {two}");
                    assert!(want[0].iter().any(|c| c[0] > 0.0), "something lit");
                }
            }
        }
    }

    #[test]
    fn a_slider_move_does_not_replan_but_a_switch_does() {
        let mut scene = presets::worksheet(5);
        let mut l = Lighter::new(&scene, EvalOptions::default()).unwrap();
        scene.lights[0].position.z = 120.0;
        scene.material.shininess = 40.0;
        assert!(!l.update(&scene, EvalOptions::default()).unwrap());
        assert_eq!(l.replans(), 1);
        scene.lights[0].position.w = 0.0;
        assert!(l.update(&scene, EvalOptions::default()).unwrap());
        assert_eq!(l.replans(), 2);
        assert!(!l.key().lights[0].positional);
        assert!(!l.program().has(Stage::LightVector(0)));
    }
}
