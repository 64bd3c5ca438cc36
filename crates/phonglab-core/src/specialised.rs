//! The specialised evaluator: lights arrays of vertices with only the stages the scene's
//! [`Key`] calls for, on the constants the general engine prepares.
//!
//! Vertices are processed in chunks of [`CHUNK`], as structures of arrays. For each light
//! one fused loop runs over the chunk, and what the key says is not needed is not in it:
//!
//! | key says | stage skipped |
//! |---|---|
//! | directional light | L, d, attenuation (L is a constant) |
//! | directional light, infinite viewer, Blinn-Phong | H (a constant) |
//! | attenuation (1, 0, 0) | attenuation |
//! | cutoff 180 | cone test and spot power |
//! | zero specular product | H, n.H and the power |
//! | shininess 0 | the power (`x^0 = 1`) |
//! | one-sided | the back side |
//! | GL_NORMALIZE off, or GL_RESCALE_NORMAL on a length-preserving modelview | normalisation |
//!
//! Each stage calls the same function of `lighting::terms` as the general [`Engine`],
//! in the same order, so the two agree bit for bit (tested on every public case and on
//! random scenes). The plan is rebuilt only when the key changes ([`Lighter::update`]);
//! a value that moves without switching an effect only refreshes the constants.

use glam::{DVec3, Vec3};

use crate::error::SceneError;
use crate::lighting::{Engine, EvalOptions, LightPos, PreparedLight, Renormalize, fast_rsqrt, inside_cone, terms};
use crate::plan::Key;
use crate::real::Vec3Ops;
use crate::robust::{mul0, transform_point};
use crate::rules::{SpecularGate, SpecularModel};
use crate::scene::{Scene, Vertex};

/// The hot loop of [`Lighter::directional_fast`]: per vertex, the arithmetic of
/// `terms::side` for a constant L and H, one channel at a time.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn fast_loop(
    c: &mut Chunk,
    l: Vec3,
    h: Vec3,
    products: [Vec3; 3],
    shin: f32,
    sp: bool,
    scale: f32,
    pow: impl Fn(f32, f32) -> f32,
) {
    let [amb, dif, spe] = products.map(|v| v.to_array());
    let n = c.len();
    let (nx, ny, nz, zero) = (&c.nx[..n], &c.ny[..n], &c.nz[..n], &c.zero[..n]);
    // Pass 1: the two cosines (glam's dot: (x x' + y y') + z z').
    let mut ndl = [0.0f32; CHUNK];
    let mut cos = [0.0f32; CHUNK];
    for i in 0..n {
        ndl[i] = nx[i] * l.x + ny[i] * l.y + nz[i] * l.z;
        cos[i] = (nx[i] * h.x + ny[i] * h.y + nz[i] * h.z).max(0.0);
    }
    // Pass 2: the power, alone in its loop (so the f32 -> f64 -> f32 conversions do not
    // stop the other passes from vectorising).
    let mut p = [1.0f32; CHUNK];
    if shin != 0.0 {
        for i in 0..n {
            p[i] = pow(cos[i], shin);
        }
    }
    // Pass 3: the terms and the sum, channel by channel.
    let acc = &mut c.acc[0];
    for ch in 0..3 {
        for i in 0..n {
            let allowed = !zero[i] && sp && ndl[i] > 0.0;
            let diffuse = if zero[i] { 0.0 } else { mul0(dif[ch], ndl[i].max(0.0)) };
            let specular = if allowed { mul0(spe[ch], p[i]) } else { 0.0 };
            let pri = amb[ch] + diffuse + specular;
            acc[ch][i] += mul0(pri, scale);
        }
    }
}

/// A positional light (a spotlight or not), one side, Blinn-Phong, OpenGL's gate: the
/// stages of `terms::light_vector`, `terms::attenuation`, `terms::spot`, `terms::halfway`
/// and `terms::side` written out on plain arrays (f64 for L and d, as the general engine),
/// so they vectorise. The same operations in the same order.
#[inline(always)]
fn positional_fast(
    c: &mut Chunk,
    pl: &PreparedLight<f32>,
    lp: DVec3,
    e: &Engine<f32>,
    local_viewer: bool,
    pow: impl Fn(f32, f32) -> f32,
) {
    let n = c.len();
    let [amb, dif, spe] = pl.products[0].map(|v| v.to_array());
    let shin = e.sides[0].shininess;
    let attenuated = pl.k != [1.0, 0.0, 0.0];
    let (mut lx, mut ly, mut lz, mut d) = ([0.0f32; CHUNK], [0.0f32; CHUNK], [0.0f32; CHUNK], [0.0f32; CHUNK]);
    let mut l_ok = [false; CHUNK];
    // L in f64, for the spot's cone test.
    let (mut lx64, mut ly64, mut lz64) = ([0.0f64; CHUNK], [0.0f64; CHUNK], [0.0f64; CHUNK]);
    // L = normalize(P_l - P) and d = |P_l - P|, both from one exact power-of-two scaling
    // (robust::try_normalize and robust::scaled_length), in f64.
    for i in 0..n {
        let vp = lp - c.pos[i];
        let m = vp.x.abs().max(vp.y.abs()).max(vp.z.abs());
        let ok = m != 0.0 && m.is_finite();
        let s = <f64 as crate::Real>::inverse_pow2_scale(m);
        let u = vp * s;
        let sq = (u.x * u.x + u.y * u.y + u.z * u.z).sqrt();
        let inv = 1.0 / sq;
        (lx64[i], ly64[i], lz64[i]) = (u.x * inv, u.y * inv, u.z * inv);
        lx[i] = lx64[i] as f32;
        ly[i] = ly64[i] as f32;
        lz[i] = lz64[i] as f32;
        d[i] = if ok { (sq / s) as f32 } else { m as f32 };
        l_ok[i] = ok;
    }
    // The spot factor (terms::spot): (-L . s)^e inside the cone, 0 outside; 1 without a spot.
    let mut spot = [1.0f32; CHUNK];
    if let Some(sp) = pl.spot {
        match sp.axis {
            None => spot[..n].fill(0.0),
            Some(axis) => {
                let (mut cos, mut inside) = ([0.0f32; CHUNK], [false; CHUNK]);
                for i in 0..n {
                    let l = DVec3::new(lx64[i], ly64[i], lz64[i]);
                    cos[i] = (-l.dot(axis)) as f32;
                    inside[i] = l_ok[i] && inside_cone(-l, axis, sp.cutoff, sp.cos_cutoff, sp.sin_cutoff);
                }
                for i in 0..n {
                    let p = pow(cos[i].max(0.0), sp.exponent);
                    spot[i] = if inside[i] { p } else { 0.0 };
                }
            }
        }
    }
    // att = 1 / (k0 + k1 d + k2 d^2); scale = mul0(att, spot).
    let mut scale = [1.0f32; CHUNK];
    for i in 0..n {
        let att = if attenuated { terms::attenuation(pl.k, d[i]) } else { 1.0 };
        scale[i] = mul0(att, spot[i]);
    }
    // H = normalize(L + V) (robust::try_normalize in f32).
    let (mut hx, mut hy, mut hz) = ([0.0f32; CHUNK], [0.0f32; CHUNK], [0.0f32; CHUNK]);
    let mut h_ok = [false; CHUNK];
    for i in 0..n {
        let v = if local_viewer { c.v[i] } else { Some(Vec3::Z) };
        let (vx, vy, vz, v_ok) = match v {
            Some(v) => (v.x, v.y, v.z, true),
            None => (0.0, 0.0, 0.0, false),
        };
        let (x, y, z) = (lx[i] + vx, ly[i] + vy, lz[i] + vz);
        let m = x.abs().max(y.abs()).max(z.abs());
        let ok = m != 0.0 && m.is_finite() && v_ok && l_ok[i];
        let s = <f32 as crate::Real>::inverse_pow2_scale(m);
        let (ux, uy, uz) = (x * s, y * s, z * s);
        let inv = 1.0 / (ux * ux + uy * uy + uz * uz).sqrt();
        hx[i] = ux * inv;
        hy[i] = uy * inv;
        hz[i] = uz * inv;
        h_ok[i] = ok;
    }
    // The cosines and the power.
    let (mut ndl, mut cos) = ([0.0f32; CHUNK], [0.0f32; CHUNK]);
    for i in 0..n {
        ndl[i] = c.nx[i] * lx[i] + c.ny[i] * ly[i] + c.nz[i] * lz[i];
        cos[i] = (c.nx[i] * hx[i] + c.ny[i] * hy[i] + c.nz[i] * hz[i]).max(0.0);
    }
    let mut p = [1.0f32; CHUNK];
    if shin != 0.0 {
        for i in 0..n {
            p[i] = pow(cos[i], shin);
        }
    }
    // The terms and the sums.
    let acc = &mut c.acc[0];
    for ch in 0..3 {
        for i in 0..n {
            let lit = l_ok[i] && !c.zero[i];
            let diffuse = if lit { mul0(dif[ch], ndl[i].max(0.0)) } else { 0.0 };
            let specular = if lit && h_ok[i] && ndl[i] > 0.0 { mul0(spe[ch], p[i]) } else { 0.0 };
            let pri = amb[ch] + diffuse + specular;
            acc[ch][i] += mul0(pri, scale[i]);
        }
    }
}

/// Does this CPU have AVX-512F and DQ (and AVX2, FMA)? (Checked once; `PHONGLAB_NO_AVX512`
/// set in the environment turns the AVX-512 kernels off, for comparisons.)
#[cfg(target_arch = "x86_64")]
fn has_avx512() -> bool {
    use std::sync::OnceLock;
    static HAS: OnceLock<bool> = OnceLock::new();
    *HAS.get_or_init(|| {
        std::env::var_os("PHONGLAB_NO_AVX512").is_none()
            && std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512dq")
            && has_avx2_fma()
    })
}

/// Does this CPU have AVX2 and FMA? (Checked once.)
#[cfg(target_arch = "x86_64")]
fn has_avx2_fma() -> bool {
    use std::sync::OnceLock;
    static HAS: OnceLock<bool> = OnceLock::new();
    *HAS.get_or_init(|| std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma"))
}

/// Vertices per chunk: the arrays of a chunk stay in L1 cache.
pub const CHUNK: usize = 128;

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
    /// Per light, the constants of a directional light: L (f64 and f32) and H.
    consts: Vec<LightConsts>,
    replans: usize,
}

#[derive(Clone, Copy, Debug, Default)]
struct LightConsts {
    /// L for a directional light (`None`: direction (0, 0, 0), or positional).
    l: Option<Vec3>,
    /// H for a directional light with an infinite viewer under Blinn-Phong.
    h: Option<Vec3>,
    /// The spot factor and scale of a directional light (constant over vertices).
    scale: f32,
}

/// Where the colours go.
enum Output<'a> {
    /// Primary and secondary per side.
    Lit { front: &'a mut [Lit], back: Option<&'a mut [Lit]> },
    /// The colour sum (primary + secondary rgb, primary alpha) per side: what a fragment
    /// receives.
    Sum { front: &'a mut [[f32; 4]], back: Option<&'a mut [[f32; 4]]> },
}

/// Where a chunk's positions and normals come from.
#[derive(Clone, Copy)]
enum Source<'a> {
    /// Object space (w = 1), transformed like the general engine does.
    Object { positions: &'a [Vec3], normals: &'a [Vec3], with_positions: bool },
    /// Eye space, final normals.
    Eye { positions: &'a [Vec3], normals: &'a [Vec3] },
    /// Eye space, normals to normalise (as `robust::normalize_or_zero`).
    EyeRaw { positions: &'a [Vec3], normals: &'a [Vec3] },
    /// One eye-space vertex (already divided by w).
    One { pos: DVec3, n: Vec3 },
}

impl Source<'_> {
    fn len(&self) -> usize {
        match self {
            Source::Object { positions, .. } | Source::Eye { positions, .. } | Source::EyeRaw { positions, .. } => {
                positions.len()
            }
            Source::One { .. } => 1,
        }
    }

    /// Sets the chunk's positions and final normals from `start`.
    #[inline(always)]
    fn fill(&self, e: &Engine<f32>, c: &mut Chunk, start: usize) {
        match *self {
            Source::Object { positions, normals, with_positions } => {
                if with_positions {
                    for i in 0..c.len() {
                        let p = positions[start + i].as_dvec3().extend(1.0);
                        let pos_h = transform_point(&e.eye_from_object, p);
                        c.pos[i] = pos_h.truncate() / pos_h.w;
                    }
                }
                transform_normals(e, &normals[start..start + c.n], c);
            }
            Source::Eye { positions, normals } => {
                for i in 0..c.len() {
                    c.pos[i] = positions[start + i].as_dvec3();
                    c.set_nrm(i, normals[start + i]);
                }
            }
            Source::EyeRaw { positions, normals } => {
                for i in 0..c.len() {
                    c.pos[i] = positions[start + i].as_dvec3();
                    c.set_nrm(i, normals[start + i]);
                }
                match e.options.renormalize {
                    Renormalize::Exact => normalize_chunk(c),
                    Renormalize::FastRsqrt => normalize_chunk_fast(c),
                    Renormalize::Skip => {}
                }
            }
            Source::One { pos, n } => {
                c.pos[0] = pos;
                c.set_nrm(0, n);
            }
        }
    }
}

/// `terms::normal_mode(mode, rescale, M n)` for a chunk, written on plain arrays without
/// branches so it vectorises: the same operations in the same order as glam's
/// `Mat3 * Vec3` (`x_axis x + y_axis y + z_axis z`) and `robust::try_normalize`.
#[inline(always)]
fn transform_normals(e: &Engine<f32>, normals: &[Vec3], c: &mut Chunk) {
    let m = e.normal_matrix;
    let n = normals.len().min(CHUNK);
    for (i, &v) in normals.iter().enumerate() {
        c.nx[i] = m.x_axis.x * v.x + m.y_axis.x * v.y + m.z_axis.x * v.z;
        c.ny[i] = m.x_axis.y * v.x + m.y_axis.y * v.y + m.z_axis.y * v.z;
        c.nz[i] = m.x_axis.z * v.x + m.y_axis.z * v.y + m.z_axis.z * v.z;
    }
    match e.normal_mode {
        crate::NormalMode::AsIs => {}
        crate::NormalMode::Rescale => {
            let s = e.rescale;
            for i in 0..n {
                c.nx[i] *= s;
                c.ny[i] *= s;
                c.nz[i] *= s;
            }
        }
        crate::NormalMode::Normalize => {
            c.n = n;
            normalize_chunk(c);
        }
    }
}

/// The chunk's normals times [`fast_rsqrt`] of their squared length (0 stays 0).
#[inline(always)]
fn normalize_chunk_fast(c: &mut Chunk) {
    for i in 0..c.len() {
        let (x, y, z) = (c.nx[i], c.ny[i], c.nz[i]);
        let q = x * x + y * y + z * z;
        let inv = if q > 0.0 { fast_rsqrt(q) } else { 0.0 };
        c.nx[i] = x * inv;
        c.ny[i] = y * inv;
        c.nz[i] = z * inv;
    }
}

/// `robust::normalize_or_zero` over the chunk's normals, on plain arrays.
#[inline(always)]
fn normalize_chunk(c: &mut Chunk) {
    for i in 0..c.len() {
        let (x, y, z) = (c.nx[i], c.ny[i], c.nz[i]);
        let m = x.abs().max(y.abs()).max(z.abs());
        let defined = m != 0.0 && m.is_finite();
        let s = <f32 as crate::Real>::inverse_pow2_scale(m);
        let (ux, uy, uz) = (x * s, y * s, z * s);
        let inv = 1.0 / (ux * ux + uy * uy + uz * uz).sqrt();
        c.nx[i] = if defined { ux * inv } else { 0.0 };
        c.ny[i] = if defined { uy * inv } else { 0.0 };
        c.nz[i] = if defined { uz * inv } else { 0.0 };
    }
}

/// Per-chunk arrays, one array per component so loops vectorise.
struct Chunk {
    n: usize,
    /// Eye-space positions (f64, as the general engine differences them).
    pos: [DVec3; CHUNK],
    /// Final normals, by component, and whether each is zero.
    nx: [f32; CHUNK],
    ny: [f32; CHUNK],
    nz: [f32; CHUNK],
    zero: [bool; CHUNK],
    /// V per vertex (`None` at the eye).
    v: [Option<Vec3>; CHUNK],
    /// Sums per (side, primary or secondary) and channel.
    acc: [[[f32; CHUNK]; 3]; 4],
}

impl Chunk {
    /// The vertices in the chunk. Always `n`, but written with its bound so that the
    /// compiler knows every index below it is in range (no bounds checks in the loops,
    /// which then vectorise).
    #[inline(always)]
    fn len(&self) -> usize {
        self.n.min(CHUNK)
    }

    fn new() -> Box<Self> {
        Box::new(Chunk {
            n: 0,
            pos: [DVec3::ZERO; CHUNK],
            nx: [0.0; CHUNK],
            ny: [0.0; CHUNK],
            nz: [0.0; CHUNK],
            zero: [false; CHUNK],
            v: [None; CHUNK],
            acc: [[[0.0; CHUNK]; 3]; 4],
        })
    }

    /// V at vertex `i`: per vertex for a local viewer, else (0, 0, 1).
    #[inline(always)]
    fn view(&self, i: usize, local: bool) -> Option<Vec3> {
        if local { self.v[i] } else { Some(Vec3::Z) }
    }

    #[inline(always)]
    fn nrm(&self, i: usize) -> Vec3 {
        Vec3::new(self.nx[i], self.ny[i], self.nz[i])
    }

    #[inline(always)]
    fn set_nrm(&mut self, i: usize, n: Vec3) {
        (self.nx[i], self.ny[i], self.nz[i]) = (n.x, n.y, n.z);
    }

    #[inline(always)]
    fn acc(&self, k: usize, i: usize) -> Vec3 {
        Vec3::new(self.acc[k][0][i], self.acc[k][1][i], self.acc[k][2][i])
    }

    /// `acc = acc + x`, as the general engine sums.
    #[inline(always)]
    fn add(&mut self, k: usize, i: usize, x: Vec3) {
        let a = self.acc(k, i) + x;
        (self.acc[k][0][i], self.acc[k][1][i], self.acc[k][2][i]) = (a.x, a.y, a.z);
    }
}

impl Lighter {
    /// Plans the evaluator for `scene` (refusing what OpenGL refuses).
    pub fn new(scene: &Scene, options: EvalOptions) -> Result<Self, SceneError> {
        let engine = Engine::<f32>::with_options(scene, options)?;
        let key = Key::of(scene, options);
        let consts = Self::fold(&engine, &key);
        Ok(Lighter { key, engine, consts, replans: 1 })
    }

    /// Takes a changed scene: re-plans if its key differs, else refreshes the constants
    /// only. Returns whether it re-planned.
    pub fn update(&mut self, scene: &Scene, options: EvalOptions) -> Result<bool, SceneError> {
        let engine = Engine::<f32>::with_options(scene, options)?;
        let key = Key::of(scene, options);
        let replan = key != self.key;
        if replan {
            self.key = key;
            self.replans += 1;
        }
        self.consts = Self::fold(&engine, &self.key);
        self.engine = engine;
        Ok(replan)
    }

    /// Positions matter only to positional lights and a local viewer.
    fn needs_positions(&self) -> bool {
        self.key.per_vertex_view || self.key.lights.iter().any(|l| l.positional)
    }

    /// How many times a plan has been built (1 after [`Lighter::new`]).
    pub fn replans(&self) -> usize {
        self.replans
    }

    /// The key the plan was built from.
    pub fn key(&self) -> &Key {
        &self.key
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
        self.run(
            Source::Object { positions, normals, with_positions: self.needs_positions() },
            Output::Lit { front, back },
        );
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
        self.run(
            Source::Object { positions, normals, with_positions: self.needs_positions() },
            Output::Sum { front, back },
        );
    }

    /// [`Lighter::light_batch_eye_sum`] with normals not yet normalised: each is
    /// normalised first (as `robust::normalize_or_zero`), as Phong shading renormalises its
    /// interpolated normals.
    pub fn light_batch_eye_sum_normalizing(
        &self,
        positions: &[Vec3],
        normals: &[Vec3],
        front: &mut [[f32; 4]],
        back: Option<&mut [[f32; 4]]>,
    ) {
        assert_eq!(positions.len(), normals.len(), "one normal per position");
        self.run(Source::EyeRaw { positions, normals }, Output::Sum { front, back });
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
        self.run(Source::Eye { positions, normals }, Output::Sum { front, back });
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
        self.run(Source::One { pos: pos_h.truncate() / pos_h.w, n }, Output::Lit { front: f, back: Some(b) });
        if !self.key.two_sided {
            out[1] = out[0];
        }
        out
    }

    /// The chunked driver: `fill` sets positions and final normals of a chunk. Runs a copy
    /// compiled for AVX2 and FMA when the CPU has them (the same operations: FMA only
    /// replaces the library call behind `mul_add` in the exact products).
    fn run(&self, src: Source<'_>, out: Output<'_>) {
        #[cfg(target_arch = "x86_64")]
        if has_avx512() {
            // SAFETY: the CPU has AVX-512F/DQ, AVX2 and FMA (checked just above).
            unsafe { self.run_avx512(src, out) };
            return;
        }
        #[cfg(target_arch = "x86_64")]
        if has_avx2_fma() {
            // SAFETY: the CPU has AVX2 and FMA (checked just above).
            unsafe { self.run_avx2_fma(src, out) };
            return;
        }
        self.run_portable(src, out);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512dq,avx2,fma")]
    fn run_avx512(&self, src: Source<'_>, out: Output<'_>) {
        self.run_portable(src, out);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn run_avx2_fma(&self, src: Source<'_>, out: Output<'_>) {
        self.run_portable(src, out);
    }

    #[inline(always)]
    fn run_portable(&self, src: Source<'_>, mut out: Output<'_>) {
        let count = src.len();
        let front_len = match &out {
            Output::Lit { front, .. } => front.len(),
            Output::Sum { front, .. } => front.len(),
        };
        assert!(front_len >= count, "front output too short");
        let two = self.key.two_sided;
        let mut c = Chunk::new();
        let mut start = 0;
        while start < count {
            c.n = CHUNK.min(count - start);
            src.fill(&self.engine, &mut c, start);
            self.light_chunk(&mut c);
            let r = start..start + c.n;
            match &mut out {
                Output::Lit { front, back } => {
                    self.write(&c, 0, &mut front[r.clone()]);
                    if let Some(b) = back.as_deref_mut().filter(|_| two) {
                        self.write(&c, 1, &mut b[r]);
                    }
                }
                Output::Sum { front, back } => {
                    self.write_sum(&c, 0, &mut front[r.clone()]);
                    if let Some(b) = back.as_deref_mut().filter(|_| two) {
                        self.write_sum(&c, 1, &mut b[r]);
                    }
                }
            }
            start += c.n;
        }
    }

    /// `terms::finish` for the chunk, written on plain arrays: `(e_cm + a_cm a_cs) + sum`,
    /// NaN shown as 0, the alphas.
    #[inline(always)]
    fn write(&self, c: &Chunk, side: usize, out: &mut [Lit]) {
        let m = &self.engine.sides[side];
        let base = (m.emission + m.scene_ambient).to_array();
        let sep = self.key.separate_specular;
        let fix = |x: f32| if x.is_nan() { 0.0 } else { x };
        let (pr, sc) = (&c.acc[2 * side], &c.acc[2 * side + 1]);
        for (i, o) in out.iter_mut().enumerate().take(c.len()) {
            o.primary = [fix(base[0] + pr[0][i]), fix(base[1] + pr[1][i]), fix(base[2] + pr[2][i]), m.alpha];
            o.secondary = if sep { [fix(sc[0][i]), fix(sc[1][i]), fix(sc[2][i]), 1.0] } else { [0.0; 4] };
        }
    }

    /// The colour sums of the chunk: `primary + secondary` rgb of [`Lighter::write`].
    #[inline(always)]
    fn write_sum(&self, c: &Chunk, side: usize, out: &mut [[f32; 4]]) {
        let m = &self.engine.sides[side];
        let base = (m.emission + m.scene_ambient).to_array();
        let fix = |x: f32| if x.is_nan() { 0.0 } else { x };
        let (pr, sc) = (&c.acc[2 * side], &c.acc[2 * side + 1]);
        if self.key.separate_specular {
            for (i, o) in out.iter_mut().enumerate().take(c.len()) {
                *o = [
                    fix(base[0] + pr[0][i]) + fix(sc[0][i]),
                    fix(base[1] + pr[1][i]) + fix(sc[1][i]),
                    fix(base[2] + pr[2][i]) + fix(sc[2][i]),
                    m.alpha,
                ];
            }
        } else {
            for (i, o) in out.iter_mut().enumerate().take(c.len()) {
                *o = [fix(base[0] + pr[0][i]), fix(base[1] + pr[1][i]), fix(base[2] + pr[2][i]), m.alpha];
            }
        }
    }

    /// Every light's contribution to the chunk.
    #[inline(always)]
    fn light_chunk(&self, c: &mut Chunk) {
        let e = &self.engine;
        let n = c.len();
        for i in 0..n {
            c.zero[i] = terms::is_zero_normal::<f32>(c.nrm(i));
        }
        if self.key.per_vertex_view {
            let (local, plane) = (self.key.local_viewer, e.rules.viewer_from_eye_plane());
            for i in 0..n {
                c.v[i] = terms::view_vector::<f32>(local, plane, c.pos[i]);
            }
        }
        // Only the sums that will be read: per side, the primary, and the secondary with
        // separate specular.
        let sides = if self.key.two_sided { 2 } else { 1 };
        for side in 0..sides {
            for k in [2 * side, 2 * side + 1].into_iter().take(if self.key.separate_specular { 2 } else { 1 }) {
                for ch in 0..3 {
                    c.acc[k][ch][..n].fill(0.0);
                }
            }
        }
        for (li, pl) in e.lights.iter().enumerate() {
            match pl.pos {
                LightPos::Directional { .. } => self.directional(c, pl, &self.consts[li]),
                LightPos::Positional(_) => self.positional(c, pl),
            }
        }
    }

    #[inline(always)]
    fn spec_inputs(&self, h: Option<Vec3>, r: Option<Vec3>, v: Option<Vec3>) -> terms::SpecularInputs<f32> {
        terms::SpecularInputs { h, r, v, gate: self.engine.rules.specular_gate(), model: self.engine.rules.specular }
    }

    /// Both sides' terms of one vertex, added to the chunk's sums.
    #[inline(always)]
    fn accumulate(
        &self,
        c: &mut Chunk,
        i: usize,
        pl: &PreparedLight<f32>,
        lit: Option<Vec3>,
        spec: &terms::SpecularInputs<f32>,
        scale: f32,
    ) {
        let e = &self.engine;
        let sides = if self.key.two_sided { 2 } else { 1 };
        for side in 0..sides {
            let n_side = if side == 0 { c.nrm(i) } else { -c.nrm(i) };
            let st = terms::side::<f32>(
                pl.products[side],
                n_side,
                lit,
                spec,
                e.sides[side].shininess,
                e.options.pow,
                e.separate_specular,
                scale,
            );
            c.add(2 * side, i, st.primary);
            c.add(2 * side + 1, i, st.secondary);
        }
    }

    /// A directional light: L, H and the spot factor are constants.
    #[inline(always)]
    fn directional(&self, c: &mut Chunk, pl: &PreparedLight<f32>, k: &LightConsts) {
        let blinn = self.engine.rules.specular == SpecularModel::BlinnPhong;
        let per_vertex_h = blinn && self.key.per_vertex_view;
        // The hot path: constant L and H, Blinn-Phong, one side, no separate specular.
        if !per_vertex_h && blinn && !self.key.two_sided && self.fast_path_ok() {
            self.directional_fast(c, pl, k);
            return;
        }
        for i in 0..c.len() {
            let lit = k.l.filter(|_| !c.zero[i]);
            let h = if per_vertex_h {
                k.l.zip(c.view(i, self.key.per_vertex_view)).and_then(|(l, v)| terms::halfway::<f32>(l, v))
            } else if blinn {
                k.h
            } else {
                None
            };
            let r = lit.map(|l| terms::reflect::<f32>(c.nrm(i), l, self.engine.rules.reflect_clamped()));
            let spec = self.spec_inputs(h, r, c.view(i, self.key.per_vertex_view));
            self.accumulate(c, i, pl, lit, &spec, k.scale);
        }
    }

    #[inline(always)]
    fn fast_path_ok(&self) -> bool {
        self.engine.rules.specular_gate() == SpecularGate::LitSide && !self.engine.separate_specular
    }

    /// Directional light, infinite viewer (or constant H), Blinn-Phong, OpenGL's gate, one
    /// side: `terms::side` written out channel by channel on plain arrays so the loop
    /// vectorises. The same operations in the same order as `terms::side`.
    #[inline(always)]
    fn directional_fast(&self, c: &mut Chunk, pl: &PreparedLight<f32>, k: &LightConsts) {
        let e = &self.engine;
        let [amb, dif, spe] = pl.products[0];
        let shin = e.sides[0].shininess;
        let scale = k.scale;
        let Some(l) = k.l else {
            // No direction: ambient only.
            let pri = crate::robust::scale0::<f32>(amb, scale);
            for i in 0..c.len() {
                c.add(0, i, pri);
            }
            return;
        };
        let h = k.h.unwrap_or(Vec3::ZERO);
        let sp = k.h.is_some() && spe != Vec3::ZERO;
        match e.options.pow {
            crate::PowFn::Exact => fast_loop(c, l, h, [amb, dif, spe], shin, sp, scale, crate::pow::pow_f32),
            crate::PowFn::Llvmpipe => {
                fast_loop(c, l, h, [amb, dif, spe], shin, sp, scale, |x, y| crate::PowFn::Llvmpipe.pow(x, y))
            }
            crate::PowFn::Schlick => {
                fast_loop(c, l, h, [amb, dif, spe], shin, sp, scale, |x, y| crate::PowFn::Schlick.pow(x, y))
            }
        }
    }

    /// A positional light: L, d, attenuation and the spot factor per vertex.
    #[inline(always)]
    fn positional(&self, c: &mut Chunk, pl: &PreparedLight<f32>) {
        let e = &self.engine;
        if !self.key.two_sided
            && e.rules.specular == SpecularModel::BlinnPhong
            && self.fast_path_ok()
            && let LightPos::Positional(lp) = pl.pos
        {
            let lv = self.key.per_vertex_view;
            match e.options.pow {
                crate::PowFn::Exact => positional_fast(c, pl, lp, e, lv, crate::pow::pow_f32),
                crate::PowFn::Llvmpipe => positional_fast(c, pl, lp, e, lv, |x, y| crate::PowFn::Llvmpipe.pow(x, y)),
                crate::PowFn::Schlick => positional_fast(c, pl, lp, e, lv, |x, y| crate::PowFn::Schlick.pow(x, y)),
            }
            return;
        }
        let attenuated = pl.k != [1.0, 0.0, 0.0];
        let blinn = e.rules.specular == SpecularModel::BlinnPhong;
        for i in 0..c.len() {
            let (l64, d64) = terms::light_vector(&pl.pos, c.pos[i], false);
            let att = match (attenuated, d64) {
                (true, Some(d)) => terms::attenuation(pl.k, d as f32),
                _ => 1.0,
            };
            let spot = pl.spot.map_or(1.0, |sp| terms::spot(&sp, l64, e.options.pow).2);
            let scale = mul0(att, spot);
            let l = l64.map(Vec3::from_dvec3);
            let lit = l.filter(|_| !c.zero[i]);
            let h = if blinn {
                l.zip(c.view(i, self.key.per_vertex_view)).and_then(|(l, v)| terms::halfway::<f32>(l, v))
            } else {
                None
            };
            let r = lit.map(|l| terms::reflect::<f32>(c.nrm(i), l, self.engine.rules.reflect_clamped()));
            let spec = self.spec_inputs(h, r, c.view(i, self.key.per_vertex_view));
            self.accumulate(c, i, pl, lit, &spec, scale);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets;

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
    }
}
