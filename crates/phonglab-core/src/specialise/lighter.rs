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

use crate::equation::lighting::{Engine, EvalOptions, LightPos, terms};
use crate::equation::plan::{Key, Program, SourceKind, Stage};
use crate::model::error::SceneError;
use crate::model::scene::{LightId, Scene, Side};
use crate::numerics::copies::prefetch;
use crate::numerics::real::Vec3Ops;
use crate::numerics::robust::mul0;

mod stages;

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
    /// A directional light's L is wanted as arrays: the program forms H or R per vertex.
    l_arrays: bool,
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
    pub(super) fn len(&self) -> usize {
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
pub(super) enum Recorder<'a> {
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
    /// then; [`CHUNK`] is 64 now) for a scalar loop (its bound check), and the scalar lanes
    /// cost as much as the vector ones (the figures: docs/performance.md, "Why the code is
    /// written so").
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
        let [object, eye, eye_raw] = Self::compile(&key, options);
        let consts = Self::fold(&engine, &object);
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
        self.consts = Self::fold(&engine, &self.object);
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

    /// Constants that do not depend on the vertex: a directional light's L, its H where
    /// `program` takes it as one constant (`HalfwayConstant`), its spot factor. (H and R
    /// are the same stages whatever the source, so the object program tells for all.)
    fn fold(engine: &Engine<f32>, program: &Program) -> Vec<LightConsts> {
        engine
            .lights
            .iter()
            .enumerate()
            .map(|(i, pl)| match pl.pos {
                LightPos::Directional { unit, .. } => {
                    let i = LightId(i);
                    let l = unit.map(Vec3::from_dvec3);
                    let h = match (l, program.has(Stage::HalfwayConstant(i))) {
                        (Some(l), true) => terms::halfway::<f32>(l, Vec3::Z),
                        _ => None,
                    };
                    let spot = pl.spot.map_or(1.0, |sp| terms::spot(&sp, unit, engine.options.pow).2);
                    let l_arrays = program.has(Stage::Halfway(i)) || program.has(Stage::Reflect(i));
                    LightConsts { l, h, scale: mul0(1.0, spot), l_arrays }
                }
                LightPos::Positional(_) => LightConsts::default(),
            })
            .collect()
    }

    /// The engine the plan was made from (its matrices, its normal mode).
    pub(super) fn engine(&self) -> &Engine<f32> {
        &self.engine
    }

    /// The chunked driver, as the portable code has it (`specialise::copies` compiles it
    /// again for each processor, and `specialise::batch` runs the processor's copy).
    #[inline(always)]
    pub(super) fn run_portable(&self, src: Source<'_>, mut out: Output<'_>, mut probe: Recorder<'_>) {
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
        if let Recorder::Time(t, _) = &mut probe {
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
            if let Recorder::Time(t, at) = &mut probe {
                t.load += lap(at);
            }
            for (k, &stage) in program.stages.iter().enumerate() {
                self.stage(&mut c, stage);
                match &mut probe {
                    Recorder::Trace(t) => t.push(stage),
                    Recorder::Time(t, at) => t.stages[k].1 += lap(at),
                    Recorder::None => {}
                }
            }
            let r = start..start + c.n;
            match &mut out {
                Output::Lit { front, back } => {
                    self.write(&c, Side::Front, scene_color, &mut front[r.clone()]);
                    if let Some(b) = back.as_deref_mut().filter(|_| two) {
                        self.write(&c, Side::Back, scene_color, &mut b[r]);
                    }
                }
                Output::Sum { front, back } => {
                    self.write_sum(&c, Side::Front, scene_color, &mut front[r.clone()]);
                    if let Some(b) = back.as_deref_mut().filter(|_| two) {
                        self.write_sum(&c, Side::Back, scene_color, &mut b[r]);
                    }
                }
            }
            if let Recorder::Time(t, at) = &mut probe {
                t.write += lap(at);
            }
            start += c.n;
        }
    }
}

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
        assert!(stages.contains(&Stage::Halfway(LightId(0))));
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
                    if raw {
                        l.light_batch_eye_sum_normalizing(&pos, &nrm, wf, Some(wb));
                    } else {
                        l.light_batch_eye_sum(&pos, &nrm, wf, Some(wb));
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
        assert!(!l.program().has(Stage::LightVector(LightId(0))));
    }
}
