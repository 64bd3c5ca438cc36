//! Exam exercises: numbers a student can work with a pencil, no calculator.
//!
//! Every vector is a unit vector with rational components, `(a, b, c) / m` with
//! `a² + b² + c² = m²` and `m` 1, 5 or 25 (Pythagorean quadruples: `(0, 3, 4) / 5`,
//! `(24, 0, 7) / 25`); the modelview turns by a whole quarter or by the 3-4-5 angle
//! (cosine 0.8, sine 0.6), so it keeps them rational; a positional light sits a whole
//! multiple of its direction's denominator from the vertex, so its distance is an integer;
//! the halfway vector `H = (L + V) / |L + V|` is kept only where `|L + V|` is rational
//! (`2 + 2 L·V` a square); the attenuation is kept only where dividing by it ends in at
//! most three decimals; the shininess is 1, 2 or 4, as the cosine's decimals allow. So
//! every cosine is exact in four decimals, every value the key holds ends in at most eight
//! decimals (a rational whose denominator divides 10^8), and no step needs more than the
//! square root of a perfect square. The draws are then screened as every exercise is
//! ([`super::exercise::screen`]) and by their key ([`pencil_ready`]).

use glam::{DMat4, DVec3, DVec4};

use crate::equation::explain::{Explanation, Side, explain};
use crate::equation::lighting::Engine;
use crate::formats::document::Document;
use crate::model::camera::CameraSpec;
use crate::model::scene::{Light, LightModel, LightPlacement, Material, NormalMode, Scene, Vertex};
use crate::teach::exercise::{Effect, Exercise, Rng, Spec, draw_each, screen};

/// The most decimals a value of an exam's key has.
pub const MAX_DECIMALS: u32 = 8;

/// The decimals a cosine has at most.
pub const COSINE_DECIMALS: u32 = 4;

/// A unit vector with rational components: `(a, b, c) / m`, `a² + b² + c² = m²`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unit {
    /// The numerators.
    pub v: [i64; 3],
    /// The denominator, the length of `v`.
    pub m: i64,
}

impl Unit {
    /// As a vector.
    pub fn vec(self) -> DVec3 {
        DVec3::new(self.v[0] as f64, self.v[1] as f64, self.v[2] as f64) / self.m as f64
    }

    fn dot_num(self, o: Unit) -> i64 {
        self.v[0] * o.v[0] + self.v[1] * o.v[1] + self.v[2] * o.v[2]
    }

    /// The dot product, exactly: (numerator, denominator).
    fn dot(self, o: Unit) -> (i64, i64) {
        (self.dot_num(o), self.m * o.m)
    }
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

fn isqrt(n: i64) -> Option<i64> {
    if n < 0 {
        return None;
    }
    let r = (n as f64).sqrt().round() as i64;
    (r - 1..=r + 1).find(|&k| k >= 0 && k * k == n)
}

/// The decimals `num / den` ends in, if it ends (its reduced denominator divides a power of
/// ten).
fn decimals_of(num: i64, den: i64) -> Option<u32> {
    let mut q = den.abs() / gcd(num, den).max(1);
    let (mut twos, mut fives) = (0, 0);
    while q % 2 == 0 {
        q /= 2;
        twos += 1;
    }
    while q % 5 == 0 {
        q /= 5;
        fives += 1;
    }
    (q == 1).then_some(twos.max(fives))
}

/// Every rational unit vector with `m` 1, 5 or 25, in lowest terms.
pub fn units() -> Vec<Unit> {
    let mut out = Vec::new();
    for m in [1i64, 5, 25] {
        for a in -m..=m {
            for b in -m..=m {
                let Some(c) = isqrt(m * m - a * a - b * b) else { continue };
                for c in if c == 0 { vec![0] } else { vec![c, -c] } {
                    if gcd(gcd(a, b), gcd(c, m)) == 1 {
                        out.push(Unit { v: [a, b, c], m });
                    }
                }
            }
        }
    }
    out
}

/// A rotation about one axis by a rational cosine and sine (over `den`), as rows over
/// `den`, with its words.
#[derive(Clone, Debug)]
struct Turn {
    rows: [[i64; 3]; 3],
    den: i64,
    words: String,
}

fn turn(rng: &mut Rng, translation: &str) -> Turn {
    let axis = rng.int(0, 2) as usize;
    // (cos, sin, den): whole quarters, and the 3-4-5 angles.
    let (c, s, den) =
        rng.pick(&[(1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1), (4, 3, 5), (3, 4, 5), (4, -3, 5), (3, -4, 5)]);
    let rows = match axis {
        0 => [[den, 0, 0], [0, c, -s], [0, s, c]],
        1 => [[c, 0, s], [0, den, 0], [-s, 0, c]],
        _ => [[c, -s, 0], [s, c, 0], [0, 0, den]],
    };
    let name = ["x", "y", "z"][axis];
    let words = if den == 1 {
        let degrees = match (c, s) {
            (1, 0) => 0,
            (0, 1) => 90,
            (-1, 0) => 180,
            _ => -90,
        };
        crate::t!("exercise-modelview", degrees = degrees.to_string(), axis = name, translation = translation)
    } else {
        let num = |k: i64| crate::locale::num(k as f64 / den as f64, 4);
        crate::t!("exam-modelview", axis = name, cos = num(c), sin = num(s), translation = translation)
    };
    Turn { rows, den, words }
}

impl Turn {
    /// The modelview: this rotation, then `(0, 0, -depth)`.
    fn matrix(&self, depth: i64) -> DMat4 {
        let r = |i: usize, j: usize| self.rows[i][j] as f64 / self.den as f64;
        DMat4::from_cols(
            DVec4::new(r(0, 0), r(1, 0), r(2, 0), 0.0),
            DVec4::new(r(0, 1), r(1, 1), r(2, 1), 0.0),
            DVec4::new(r(0, 2), r(1, 2), r(2, 2), 0.0),
            DVec4::new(0.0, 0.0, -depth as f64, 1.0),
        )
    }

    /// The eye's +z in world coordinates: the third row.
    fn eye_z(&self) -> Unit {
        let [a, b, c] = self.rows[2];
        let g = gcd(gcd(a, b), gcd(c, self.den));
        Unit { v: [a / g, b / g, c / g], m: self.den / g }
    }
}

fn scaled(u: Unit, k: i64) -> DVec3 {
    DVec3::new((u.v[0] * k / u.m) as f64, (u.v[1] * k / u.m) as f64, (u.v[2] * k / u.m) as f64)
}

fn int_vec(u: Unit) -> DVec3 {
    DVec3::new(u.v[0] as f64, u.v[1] as f64, u.v[2] as f64)
}

/// One light's geometry: its direction from the vertex, and the halfway vector's cosine
/// with the normal's decimals.
#[derive(Clone, Copy, Debug)]
struct Aim {
    l: Unit,
    cos_beta_decimals: u32,
}

/// A direction to a light from `n`'s side whose halfway vector with `v` is rational and
/// whose cosines with `n` end in at most four decimals.
fn aim(rng: &mut Rng, all: &[Unit], n: Unit, v: Unit) -> Option<Aim> {
    for _ in 0..400 {
        let l = all[rng.int(0, all.len() as i64 - 1) as usize];
        let (nl, nl_den) = n.dot(l);
        if (nl as f64) < 0.1 * nl_den as f64 {
            continue;
        }
        // |L + V|² = 2 + 2 L·V = (2 D + 2 l·v) / D with D = m_l m_v: rational when its
        // numerator times D is a square.
        let d = l.m * v.m;
        let Some(s) = isqrt((2 * d + 2 * l.dot_num(v)) * d) else { continue };
        if s == 0 {
            continue;
        }
        // H = (l m_v + v m_l) / s.
        let h: [i64; 3] = std::array::from_fn(|i| l.v[i] * v.m + v.v[i] * l.m);
        if h.iter().any(|&x| decimals_of(x, s).is_none()) {
            continue;
        }
        let nh = n.v[0] * h[0] + n.v[1] * h[1] + n.v[2] * h[2];
        let nh_den = n.m * s;
        let Some(decimals) = decimals_of(nh, nh_den) else { continue };
        if decimals > COSINE_DECIMALS || (nh as f64) < 0.1 * nh_den as f64 {
            continue;
        }
        return Some(Aim { l, cos_beta_decimals: decimals });
    }
    None
}

/// Attenuation coefficients at distance `d` whose sum `k0 + k1 d + k2 d²` one divides by in
/// at most three decimals.
fn attenuation(rng: &mut Rng, d: i64) -> Option<[f64; 3]> {
    // In thousandths.
    let options =
        [(1000, 10, 0), (1000, 20, 0), (1000, 40, 0), (1000, 50, 0), (500, 20, 0), (500, 10, 0), (1000, 0, 1)];
    let start = rng.int(0, options.len() as i64 - 1) as usize;
    (0..options.len()).map(|i| options[(start + i) % options.len()]).find_map(|(k0, k1, k2)| {
        let sum = k0 + k1 * d + k2 * d * d;
        let ok = decimals_of(1000, sum).is_some_and(|dec| dec <= 3) && sum != 1000;
        ok.then(|| [k0 as f64 / 1000.0, k1 as f64 / 1000.0, k2 as f64 / 1000.0])
    })
}

/// A spotlight's axis, cutoff and exponent that hold the vertex, its cosine exact.
fn spot(rng: &mut Rng, all: &[Unit], l: Unit) -> Option<(DVec3, f64, f64)> {
    let near: Vec<Unit> = all.iter().copied().filter(|u| u.m <= 5).collect();
    for _ in 0..200 {
        let axis = near[rng.int(0, near.len() as i64 - 1) as usize];
        let (num, den) = axis.dot(l);
        let cos = -(num as f64) / den as f64;
        let cutoff = rng.pick(&[30.0, 45.0, 60.0]);
        if cos > f64::to_radians(cutoff).cos() + 1e-3 {
            return Some((int_vec(axis), cutoff, rng.pick(&[1.0, 2.0])));
        }
    }
    None
}

/// The viewer's direction and the vertex, in world coordinates.
fn viewer(rng: &mut Rng, all: &[Unit], t: &Turn, depth: i64, local: bool) -> Option<(Unit, DVec3)> {
    let z = t.eye_z();
    if !local {
        let p = DVec3::new(rng.int(-4, 4) as f64, rng.int(-4, 4) as f64, rng.int(-4, 4) as f64);
        return Some((z, p));
    }
    // The eye at `depth` along the eye's z; the vertex a whole multiple of V's denominator
    // from it, so its distance is an integer.
    let eye = scaled(z, depth);
    for _ in 0..200 {
        let v = all[rng.int(0, all.len() as i64 - 1) as usize];
        let (c, den) = v.dot(z);
        if (c as f64) < 0.8 * den as f64 {
            continue;
        }
        let k = v.m * rng.int(1, (40 / v.m).max(1));
        return Some((v, eye - scaled(v, k)));
    }
    None
}

/// Colours with one decimal.
fn material(rng: &mut Rng, shininess: f64) -> Material {
    let mut channel = |set: &[f64]| DVec4::new(rng.pick(set), rng.pick(set), rng.pick(set), 1.0);
    let tenths = [0.2, 0.4, 0.5, 0.6, 0.8];
    Material {
        ambient: channel(&tenths),
        diffuse: channel(&tenths),
        specular: channel(&[0.2, 0.5, 0.8, 1.0]),
        emission: DVec4::new(0.0, 0.0, 0.0, 1.0),
        shininess,
    }
}

/// One light, placed from `aim`.
fn light(rng: &mut Rng, all: &[Unit], i: usize, a: Aim, p: DVec3, spec: &Spec) -> Option<Light> {
    let has = |e: Effect| spec.effects.contains(&e);
    let positional = has(Effect::Positional) && (i == 0 || rng.int(0, 1) == 1);
    let gray = |v: f64| DVec4::new(v, v, v, 1.0);
    let mut l = Light {
        ambient: gray(rng.pick(&[0.0, 0.2, 0.5])),
        diffuse: gray(rng.pick(&[0.5, 1.0])),
        specular: gray(rng.pick(&[0.5, 1.0])),
        position: int_vec(a.l).extend(0.0),
        placement: LightPlacement::World,
        ..Light::gl_default(i)
    };
    if positional {
        let d = a.l.m * rng.int(1, (50 / a.l.m).max(1));
        l.position = (p + scaled(a.l, d)).extend(1.0);
        if has(Effect::Attenuation) && (i == 0 || rng.int(0, 1) == 1) {
            l.attenuation = attenuation(rng, d)?;
        }
        if has(Effect::Spot) && i == 0 {
            (l.spot_direction, l.spot_cutoff, l.spot_exponent) = spot(rng, all, a.l)?;
        }
    }
    Some(l)
}

/// One draw for `spec` (not yet screened).
fn draw(rng: &mut Rng, all: &[Unit], spec: &Spec) -> Option<(Scene, String)> {
    let has = |e: Effect| spec.effects.contains(&e);
    let depth = 5 * rng.int(4, 8);
    let t = turn(rng, &format!("(0, 0, {})", -depth));
    let (v, p) = viewer(rng, all, &t, depth, has(Effect::LocalViewer))?;
    let normals: Vec<Unit> = all.iter().copied().filter(|u| u.m <= 5 && 10 * u.dot(v).0 > u.m * v.m).collect();
    let n = normals[rng.int(0, normals.len() as i64 - 1) as usize];
    let count = if has(Effect::SeveralLights) { 2 } else { 1 };
    let aims: Vec<Aim> = (0..count).map(|_| aim(rng, all, n, v)).collect::<Option<_>>()?;
    let decimals = aims.iter().map(|a| a.cos_beta_decimals).max().unwrap_or(0);
    let shininess: Vec<f64> = [1.0, 2.0, 4.0].into_iter().filter(|s| *s as u32 * decimals <= MAX_DECIMALS).collect();
    let shininess = rng.pick(&shininess);
    let lights: Vec<Light> =
        aims.iter().enumerate().map(|(i, a)| light(rng, all, i, *a, p, spec)).collect::<Option<_>>()?;
    let scene = Scene {
        light_model: LightModel {
            ambient: DVec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: has(Effect::LocalViewer),
            two_sided: has(Effect::TwoSided),
            separate_specular: false,
        },
        lights,
        material: material(rng, shininess),
        back_material: None,
        color_material: None,
        eye_from_world: t.matrix(depth),
        world_from_object: DMat4::IDENTITY,
        normal_mode: NormalMode::Normalize,
        rules: spec.rules,
        vertex: Vertex { position: p.extend(1.0), normal: int_vec(n) },
    };
    Some((scene, t.words))
}

/// The decimals `x` ends in, up to [`MAX_DECIMALS`] (`None`: more, or none).
pub fn decimals(x: f64) -> Option<u32> {
    (0..=MAX_DECIMALS).find(|&k| {
        let scaled = x * 10f64.powi(k as i32);
        (scaled - scaled.round()).abs() <= 1e-6 * x.abs().max(1.0)
    })
}

/// The worked calculation of every side a scene's key shows.
fn keys(scene: &Scene) -> Result<Vec<Explanation>, String> {
    let lit = Engine::<f64>::new(scene).map_err(|e| e.to_string())?.light(&scene.vertex);
    let sides: &[Side] = if scene.light_model.two_sided { &[Side::Front, Side::Back] } else { &[Side::Front] };
    Ok(sides.iter().map(|&s| explain(scene, &lit, s)).collect())
}

/// Is every value of the scene's key a decimal of at most [`MAX_DECIMALS`] decimals?
pub fn pencil_ready(scene: &Scene) -> bool {
    keys(scene).is_ok_and(|ks| {
        ks.iter().flat_map(|k| &k.steps).filter_map(|s| s.value.as_ref()).flatten().all(|x| decimals(*x).is_some())
    })
}

/// `count` exam exercises from `seed`, numbered from 1: drawn, screened as every exercise
/// is and by their key ([`pencil_ready`]), by the draw loop of every exercise
/// (`exercise::draw_each`).
pub fn generate(seed: u64, count: usize, spec: &Spec) -> Result<Vec<Exercise>, String> {
    let all = units();
    draw_each(seed, count, spec, "exam exercise", |rng, k| {
        let Some((scene, words)) = draw(rng, &all, spec) else { return Ok(None) };
        if screen(&scene, spec).is_some() || !pencil_ready(&scene) {
            return Ok(None);
        }
        let name = crate::t!("exam-name", number = k.to_string(), seed = seed.to_string());
        let doc = Document::from_scene(&name, CameraSpec::Matrix(scene.eye_from_world), scene);
        let key = keys(&doc.scene)?.swap_remove(0);
        Ok(Some(Exercise { doc, modelview: words, material: crate::t!("exam-material"), key, redraws: 0 }))
    })
}
