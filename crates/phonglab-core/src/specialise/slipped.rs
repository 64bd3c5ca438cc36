//! The lighter's way round its program for a formula slip
//! ([`crate::equation::lighting::FormulaSlip`]): every vertex lit by the general engine,
//! one at a time, which alone makes the slip. The specialised stages never see a slip, so
//! they stay exactly OpenGL's (and as fast); `copies` sends a slipped lighter here.

use glam::{DVec4, Vec3};

use crate::equation::lighting::{Renormalize, fast_rsqrt};
use crate::model::scene::Vertex;
use crate::numerics::robust::normalize3;
use crate::specialise::lighter::{Lighter, Lit, Output, Source};

/// An interpolated normal renormalised as `how` says, as the program's stages do.
fn renormalised(how: Renormalize, n: Vec3) -> Vec3 {
    match how {
        Renormalize::Exact => {
            let (x, y, z, _, ok) = normalize3::<f32>(n.x, n.y, n.z);
            if ok { Vec3::new(x, y, z) } else { Vec3::ZERO }
        }
        Renormalize::FastRsqrt => {
            let q = n.dot(n);
            n * if q > 0.0 { fast_rsqrt(q) } else { 0.0 }
        }
        Renormalize::Skip => n,
    }
}

impl Lighter {
    /// Lights `src` into `out` with the general engine, vertex by vertex.
    pub(super) fn run_general(&self, src: Source<'_>, mut out: Output<'_>) {
        let e = self.engine();
        let renormalize = e.options().renormalize;
        let eye = |p: Vec3, n: Vec3, raw: bool| {
            e.light_eye(
                DVec4::new(f64::from(p.x), f64::from(p.y), f64::from(p.z), 1.0),
                if raw { renormalised(renormalize, n) } else { n },
            )
        };
        let count = src.len();
        for i in 0..count {
            let lit = match src {
                Source::Object { positions, normals } => e.light(&Vertex::from_f32(positions[i], normals[i])),
                Source::Eye { positions, normals, raw } => eye(positions[i], normals[i], raw),
                Source::EyeArrays { arrays, raw } => {
                    let at = |a: [&[f32]; 3]| Vec3::new(a[0][i], a[1][i], a[2][i]);
                    eye(at(arrays.pos), at(arrays.nrm), raw)
                }
                Source::One { pos, n } => e.light_eye(pos.extend(1.0), n),
            };
            let sides = [&lit.front, &lit.back];
            match &mut out {
                Output::Lit { front, back } => {
                    let as_lit = |s: &crate::equation::breakdown::SideColor<f32>| Lit {
                        primary: s.primary,
                        secondary: s.secondary,
                    };
                    front[i] = as_lit(sides[0]);
                    if let Some(b) = back.as_deref_mut() {
                        b[i] = as_lit(sides[1]);
                    }
                }
                Output::Sum { front, back } => {
                    front[i] = sides[0].sum();
                    if let Some(b) = back.as_deref_mut() {
                        b[i] = sides[1].sum();
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::equation::lighting::{Engine, EvalOptions, FormulaSlip};
    use crate::model::presets;

    const SLIPS: [FormulaSlip; 5] = [
        FormulaSlip::DiffuseNotClamped,
        FormulaSlip::LightReversed,
        FormulaSlip::ViewerReversed,
        FormulaSlip::HalfwayNotNormalised,
        FormulaSlip::LightNotNormalised,
    ];

    /// A lighter made with a slip runs no stage of its program: each vertex is the general
    /// engine's, bit for bit, and differs from OpenGL's somewhere on the sphere.
    #[test]
    fn a_slip_is_lit_by_the_general_engine_alone_and_changes_the_colours() {
        // A positional light with attenuation, a local viewer, Blinn-Phong: every slip shows.
        let scene = presets::LightingBench::PositionalLocal.scene();
        let (pos, nrm) = presets::sphere_points(300);
        let plain = Lighter::new(&scene, EvalOptions::default()).unwrap();
        let mut right = vec![[0.0f32; 4]; pos.len()];
        plain.light_batch_sum(&pos, &nrm, &mut right, None);
        for slip in SLIPS {
            let options = EvalOptions { slip, ..EvalOptions::default() };
            let l = Lighter::new(&scene, options).unwrap();
            let (lit, stages) = l.light_batch_traced(&pos, &nrm);
            assert!(stages.is_empty(), "{slip:?} ran the program's stages");
            let e = Engine::<f32>::with_options(&scene, options).unwrap();
            for (i, got) in lit.iter().enumerate() {
                let want = e.light(&Vertex::from_f32(pos[i], nrm[i]));
                assert_eq!(got[0].primary.map(f32::to_bits), want.front.primary.map(f32::to_bits), "{slip:?} {i}");
            }
            let mut sums = vec![[0.0f32; 4]; pos.len()];
            l.light_batch_sum(&pos, &nrm, &mut sums, None);
            assert!(sums.iter().zip(&right).any(|(a, b)| (a[0] - b[0]).abs() > 1e-3), "{slip:?} changed nothing");
        }
    }

    /// Each slip makes its own step wrong and no other: the diffuse goes negative behind the
    /// light, L and the local V turn round, the specular cosine takes L + V's length.
    #[test]
    fn each_slip_changes_its_own_step() {
        let scene = presets::LightingBench::PositionalLocal.scene();
        let light = |slip, v: &Vertex| {
            Engine::<f64>::with_options(&scene, EvalOptions { slip, ..EvalOptions::default() }).unwrap().light(v)
        };
        let (pos, nrm) = presets::sphere_points(200);
        for (p, n) in pos.iter().zip(&nrm) {
            let v = Vertex::from_f32(*p, *n);
            let (right, unclamped) = (light(FormulaSlip::None, &v), light(FormulaSlip::DiffuseNotClamped, &v));
            let (r, u) = (&right.lights()[0], &unclamped.lights()[0]);
            if r.front.n_dot_l < -1e-3 {
                assert!(u.front.diffuse.x < 0.0 && r.front.diffuse.x == 0.0, "{r:?}");
            }
            let reversed = light(FormulaSlip::LightReversed, &v);
            assert!((reversed.lights()[0].l + r.l).length() < 1e-12);
            let away = light(FormulaSlip::ViewerReversed, &v);
            assert!((away.v + right.v).length() < 1e-12);
            let long = light(FormulaSlip::HalfwayNotNormalised, &v);
            let h = r.l + right.v;
            assert!((long.lights()[0].front.spec_cos - right.normal_in_eye.dot(h)).abs() < 1e-12);
            // L unnormalised: its length the distance, n . L scaled by it, the attenuation kept.
            let unnormalised = light(FormulaSlip::LightNotNormalised, &v);
            let (u, d) = (&unnormalised.lights()[0], r.distance.expect("a positional light"));
            assert!((u.l - r.l * d).length() < 1e-9 * d, "{:?} {:?} {d}", u.l, r.l);
            assert!((u.front.n_dot_l - r.front.n_dot_l * d).abs() < 1e-9 * d);
            assert_eq!(u.attenuation, r.attenuation);
        }
    }

    /// `reflect(L, N)` for `reflect(-L, N)`: R turned round, where the specular takes R . V
    /// (the Phong demo's rules); its cosine negated.
    #[test]
    fn the_reversed_reflection_turns_r_round() {
        let mut scene = presets::LightingBench::PositionalLocal.scene();
        scene.rules.specular = crate::model::rules::SpecularModel::Phong;
        let light = |slip, v: &Vertex| {
            Engine::<f64>::with_options(&scene, EvalOptions { slip, ..EvalOptions::default() }).unwrap().light(v)
        };
        let (pos, nrm) = presets::sphere_points(100);
        for (p, n) in pos.iter().zip(&nrm) {
            let v = Vertex::from_f32(*p, *n);
            let (right, slipped) = (light(FormulaSlip::None, &v), light(FormulaSlip::ReflectionReversed, &v));
            let (r, s) = (&right.lights()[0], &slipped.lights()[0]);
            assert!((s.r + r.r).length() < 1e-12, "{:?} {:?}", s.r, r.r);
            assert!((s.front.spec_cos + r.front.spec_cos).abs() < 1e-12);
        }
    }
}
