//! The stages of the specialised evaluator's program, each one loop over a chunk of
//! vertices ([`super::Chunk`]), as [`super::Lighter::run_portable`] runs them: what each
//! [`Stage`] computes, with the same function of `lighting::terms` (and `robust`) as the
//! general engine, in the same order. The driver, the chunk and the arrays are in
//! [`super`]; the copies compiled for AVX2 and AVX-512 in `specialise::copies`.

use glam::{DVec3, Vec3};

use super::{CHUNK, Chunk, Lighter, Lit};
use crate::equation::lighting::{LightPos, PreparedLight, fast_rsqrt, terms};
use crate::equation::plan::{SpecularTerm, Stage, Viewer};
use crate::model::rules::{SpecularGate, SpecularVector};
use crate::model::scene::{LightId, Side};
use crate::numerics::pow::PowFn;
use crate::numerics::robust::{
    mul0, normalize3, normalize3_unscaled, transform_affine_rows, transform_point_rows, translate_point,
    unscaled_is_exact,
};

impl Lighter {
    /// Zeroes the sums that will be read: per side, the primary, and the secondary with
    /// separate specular.
    #[inline(always)]
    pub(super) fn clear_sums(&self, c: &mut Chunk) {
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
    pub(super) fn stage(&self, c: &mut Chunk, stage: Stage) {
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
            Stage::ViewVector(viewer) => self.view_vector(c, n, viewer),
            Stage::LightVector(li) => self.light_vector(c, n, li),
            Stage::LightConstant(li) => self.light_constant(c, n, li),
            Stage::Attenuate(li) => {
                let k = e.lights[li.index()].k;
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
                c.h_ok[..n].fill(self.consts[li.index()].h.is_some());
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
            Stage::SpecularCosine(li, side, vector) => self.specular_cosine(c, n, li, side, vector),
            Stage::Power(_, side) => self.power(c, n, side),
            Stage::Sum(li, side, term) => self.sum(c, &e.lights[li.index()], side, term),
            // Added as the colours are written (`write`, `write_sum`).
            Stage::SceneColor => {}
        }
    }

    /// V at each vertex: `normalize(-P)` for a local viewer (in f64, unscaled where that
    /// changes no bit), the worksheet's axis `(0, 0, -sign(P.z))`, or OpenGL's infinite
    /// viewer's (0, 0, 1) (terms::view_vector on components, so the loops vectorise).
    #[inline(always)]
    fn view_vector(&self, c: &mut Chunk, n: usize, viewer: Viewer) {
        if viewer == Viewer::Infinite {
            // Only a worked program writes this stage out: V is the constant every chunk
            // starts with.
            c.vx[..n].fill(0.0);
            c.vy[..n].fill(0.0);
            c.vz[..n].fill(1.0);
            c.v_ok[..n].fill(true);
        } else if viewer == Viewer::Local {
            // normalize(-P), in f64 (unscaled where that changes no bit), rounded to f32.
            let plain = all_unscaled_exact(&c.px, &c.py, &c.pz, n);
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
            // The worksheet's rule: V = (0, 0, -sign(P.z)), undefined on the plane z = 0.
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
    fn light_vector(&self, c: &mut Chunk, n: usize, li: LightId) {
        let e = &self.engine;
        let LightPos::Positional(lp) = e.lights[li.index()].pos else { return };
        // terms::light_direction on components: one robust::normalize3 in f64, without
        // its scaling where that changes no bit (robust::unscaled_is_exact).
        for i in 0..n {
            (c.lx64[i], c.ly64[i], c.lz64[i]) = (lp.x - c.px[i], lp.y - c.py[i], lp.z - c.pz[i]);
        }
        let plain = all_unscaled_exact(&c.lx64, &c.ly64, &c.lz64, n);
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
    fn light_constant(&self, c: &mut Chunk, n: usize, li: LightId) {
        let k = &self.consts[li.index()];
        c.l_ok[..n].fill(k.l.is_some());
        c.scale[..n].fill(k.scale);
        // The cosines read the constant itself; per-vertex H or R read it as arrays.
        if k.l_arrays {
            let l = k.l.unwrap_or(Vec3::ZERO);
            c.lx[..n].fill(l.x);
            c.ly[..n].fill(l.y);
            c.lz[..n].fill(l.z);
        }
    }

    /// The cosine of each L to the spot axis and the cone test (terms::spot_cone).
    #[inline(always)]
    fn spot_cone(&self, c: &mut Chunk, n: usize, li: LightId) {
        let e = &self.engine;
        let Some(sp) = e.lights[li.index()].spot else { return };
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
    fn spot_power(&self, c: &mut Chunk, n: usize, li: LightId) {
        let e = &self.engine;
        let Some(sp) = e.lights[li.index()].spot else { return };
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
    fn diffuse_cosine(&self, c: &mut Chunk, n: usize, li: LightId, side: Side) {
        // n_side . L with n_side = n or -n (negation is exact); a directional light's
        // L is the constant `consts[li].l`.
        let ndl = &mut c.ndl[side.index()];
        let (nx, ny, nz) = match side {
            Side::Front => (&c.nx, &c.ny, &c.nz),
            Side::Back => negated(&mut c.neg, &c.nx, &c.ny, &c.nz, n),
        };
        match self.consts.get(li.index()).and_then(|k| k.l) {
            Some(l) if !self.key.lights[li.index()].positional => {
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
    fn specular_cosine(&self, c: &mut Chunk, n: usize, li: LightId, side: Side, vector: SpecularVector) {
        let cos = &mut c.cos[side.index()];
        match vector {
            SpecularVector::Halfway => {
                let (nx, ny, nz) = match side {
                    Side::Front => (&c.nx, &c.ny, &c.nz),
                    Side::Back => negated(&mut c.neg, &c.nx, &c.ny, &c.nz, n),
                };
                match self.consts.get(li.index()).and_then(|k| k.h) {
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
            SpecularVector::Reflection => {
                // R . V, the same on both sides (R is formed with the front normal).
                for i in 0..n {
                    cos[i] = terms::dot3(c.hx[i], c.hy[i], c.hz[i], c.vx[i], c.vy[i], c.vz[i]);
                }
            }
        }
    }

    /// The specular power for `side`, raised where `Sum` reads it.
    #[inline(always)]
    fn power(&self, c: &mut Chunk, n: usize, side: Side) {
        let e = &self.engine;
        // Raised where `Sum` reads the power (its specular is allowed there; the
        // lanes are kept for it in `Chunk::allowed`); the other lanes are raised as 0,
        // which the exact power does not compute at all (pow_f32_chunk_packed packs
        // the others together; without AVX-512 it skips blocks of 8 zeros). `Sum`
        // gives them f_i p = 0 whatever p is.
        let s = side.index();
        let shin = e.sides[s].shininess;
        let mut allowed = [false; CHUNK];
        self.specular_lanes(c, side, &mut allowed);
        let mut x = [0.0f32; CHUNK];
        for i in 0..n {
            x[i] = keep_or_zero(allowed[i], c.cos[s][i]);
        }
        power_loop(e.options.pow, &x, &mut c.p[s], n, shin);
        c.allowed[s] = allowed;
    }

    /// Where the current light's specular is allowed on `side` (the `allowed` of
    /// `terms::shared_factors`): the light reaches the surface (L defined, normal not zero),
    /// H or R is defined, and the rule set's gate is open (`terms::specular_allowed`). Read
    /// by `Power` (which raises only these lanes) and `Sum`. One loop per gate (the gate is
    /// the scene's), `&` rather than `&&`, so each vectorises.
    #[inline(always)]
    fn specular_lanes(&self, c: &Chunk, side: Side, allowed: &mut [bool; CHUNK]) {
        let n = c.lanes();
        let (ndl, cos) = (&c.ndl[side.index()], &c.cos[side.index()]);
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
    fn sum(&self, c: &mut Chunk, pl: &PreparedLight<f32>, side: Side, term: SpecularTerm) {
        let e = &self.engine;
        let n = c.lanes();
        let s = side.index();
        let [amb, dif, spe] = pl.products[s].map(|v| v.to_array());
        let separate = e.separate_specular;
        let specular_on = match term {
            SpecularTerm::Zero => false,
            // The normalisation is in the specular product (`PreparedLight::products`).
            SpecularTerm::Plain | SpecularTerm::Normalised => true,
        };
        let (ndl, scale) = (&c.ndl[s][..n], &c.scale[..n]);
        let (l_ok, zero) = (&c.l_ok[..n], &c.zero[..n]);
        // Shininess 0 (no `Power` stage): max(cos, 0)^0 = 1.
        let p = if self.key.shininess_zero[s] { &ONES[..n] } else { &c.p[s][..n] };
        // Where the specular is allowed: as `Power` found it for this light and side (it
        // ran just before, unless the shininess is 0), or found here.
        let mut own = [false; CHUNK];
        let allowed = if self.key.has_power(LightId(pl.index), side) {
            &c.allowed[s]
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
        let (pri, sec) = c.acc[2 * s..2 * s + 2].split_at_mut(1);
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
    pub(super) fn write(&self, c: &Chunk, side: Side, scene_color: bool, out: &mut [Lit]) {
        let side = side.index();
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
    pub(super) fn write_sum(&self, c: &Chunk, side: Side, scene_color: bool, out: &mut [[f32; 4]]) {
        let side = side.index();
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

/// Whether every one of the first `n` vectors `(x, y, z)` passes `unscaled_is_exact`, so
/// `normalize3_unscaled` gives `normalize3`'s bits for all of them (one branch-free loop).
#[inline(always)]
fn all_unscaled_exact(x: &[f64; CHUNK], y: &[f64; CHUNK], z: &[f64; CHUNK], n: usize) -> bool {
    let mut plain = true;
    for i in 0..n {
        plain &= unscaled_is_exact(x[i]) & unscaled_is_exact(y[i]) & unscaled_is_exact(z[i]);
    }
    plain
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
