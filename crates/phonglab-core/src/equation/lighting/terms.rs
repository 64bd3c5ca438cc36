//! The equation's per-vertex arithmetic, one function per step. The general engine and
//! the specialised kernels (the specialise group's `specialised`, a layer above) both call
//! these, so the two compute the same operations in the same order and agree bit for bit;
//! the app's reflection lobe calls them too, so it draws the engine's own terms.

use super::*;

/// n as the equation uses it, and whether GL_NORMALIZE had to scale before squaring.
#[inline(always)]
pub fn normal_mode<S: Real>(mode: NormalMode, rescale: S, n_t: S::V3) -> (S::V3, bool) {
    match mode {
        NormalMode::AsIs => (n_t, false),
        NormalMode::Rescale => (n_t * rescale, false),
        NormalMode::Normalize => match try_normalize::<S>(n_t) {
            Some(u) => {
                let sq = n_t.dot(n_t);
                (u, sq == S::ZERO || !sq.is_finite())
            }
            None => (S::V3::ZERO, false),
        },
    }
}

/// A zero (or non-finite) normal has no direction.
#[inline(always)]
pub fn is_zero_normal<S: Real>(n: S::V3) -> bool {
    n == S::V3::ZERO || !n.max_abs().is_finite()
}

/// V: `normalize(-P)` for a local viewer (`None` at the eye), else (0, 0, 1); with
/// `eye_plane` (the worksheet's code) the infinite viewer is `normalize(obs - P)`,
/// `obs = P * (1, 1, 0, 1)`: (0, 0, -sign(P.z)), `None` on the plane z = 0 (0/0 there).
#[inline(always)]
pub fn view_vector<S: Real>(local: bool, eye_plane: bool, pos: DVec3) -> Option<S::V3> {
    if local {
        try_normalize::<f64>(-pos).map(S::V3::from_dvec3)
    } else if eye_plane {
        match pos.z.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Less) => Some(S::V3::new(S::ZERO, S::ZERO, S::ONE)),
            Some(std::cmp::Ordering::Greater) => Some(S::V3::new(S::ZERO, S::ZERO, -S::ONE)),
            _ => None,
        }
    } else {
        Some(S::V3::new(S::ZERO, S::ZERO, S::ONE))
    }
}

/// L (unit, f64; `None` when undefined) and d (f64; `None` for a directional light).
#[inline(always)]
pub(crate) fn light_vector(lp: &LightPos, pos: DVec3, at_infinity: bool) -> (Option<DVec3>, Option<f64>) {
    match lp {
        LightPos::Positional(lp) => {
            if at_infinity {
                // From a point at infinity, every finite point lies in the opposite direction.
                (try_normalize::<f64>(-pos), Some(f64::INFINITY))
            } else {
                let (l, d) = light_direction(*lp, pos);
                (l, Some(d))
            }
        }
        LightPos::Directional { dir, unit } => {
            if at_infinity {
                (try_normalize::<f64>(*dir - pos), None)
            } else {
                (*unit, None)
            }
        }
    }
}

/// L and d of a positional light at `lp` seen from the eye-space point `pos`:
/// `VP = P_l - P`, normalised and measured by one [`crate::numerics::robust::normalize3`] in f64.
#[inline(always)]
pub fn light_direction(lp: DVec3, pos: DVec3) -> (Option<DVec3>, f64) {
    let vp = lp - pos;
    let (x, y, z, d, ok) = crate::numerics::robust::normalize3::<f64>(vp.x, vp.y, vp.z);
    (ok.then_some(DVec3::new(x, y, z)), d)
}

/// The dot product as glam computes it: `(a.x b.x + a.y b.y) + a.z b.z`.
#[inline(always)]
pub fn dot3<S: Real>(ax: S, ay: S, az: S, bx: S, by: S, bz: S) -> S {
    ax * bx + ay * by + az * bz
}

/// `1 / (k0 + k1 d + k2 d^2)`; +infinity where the denominator is 0.
#[inline(always)]
pub fn attenuation<S: Real>(k: [S; 3], d: S) -> S {
    let [k0, k1, k2] = k;
    let denom = k0 + mul0(k1, d) + mul0(mul0(k2, d), d);
    if denom == S::ZERO { S::INFINITY } else { S::ONE / denom }
}

/// The spot cosine `-L . s` (in f64, rounded) and whether the vertex is inside the cone
/// `-L . s >= cos(cutoff)` (section 2.14.1, the spotlight factor).
#[inline(always)]
pub(crate) fn spot_cone<S: Real>(sp: &PreparedSpot<S>, axis: DVec3, l: DVec3) -> (S, bool) {
    (S::from_f64(-l.dot(axis)), inside_cone(-l, axis, sp.cutoff, sp.cos_cutoff, sp.sin_cutoff))
}

/// The spot factor: `max(-L . s, 0)^s_rl` inside the cone, 0 outside.
#[inline(always)]
pub fn spot_power<S: Real>(cos_angle: S, inside: bool, exponent: S, pow: PowFn) -> S {
    let p = pow.pow(cos_angle.max(S::ZERO), exponent);
    if inside { p } else { S::ZERO }
}

/// The spot cosine `-L . s`, whether the vertex is inside the cone, and the factor
/// (0 where the axis or L is undefined).
#[inline(always)]
pub(crate) fn spot<S: Real>(sp: &PreparedSpot<S>, l64: Option<DVec3>, pow: PowFn) -> (S, bool, S) {
    match (sp.axis, l64) {
        (Some(axis), Some(l)) => {
            let (cos_angle, inside) = spot_cone(sp, axis, l);
            (cos_angle, inside, spot_power(cos_angle, inside, sp.exponent, pow))
        }
        _ => (S::ZERO, false, S::ZERO),
    }
}

/// H = normalize(L + V), `None` when L = -V.
#[inline(always)]
pub fn halfway<S: Real>(l: S::V3, v: S::V3) -> Option<S::V3> {
    try_normalize::<S>(l + v)
}

/// R = 2 (n . L) n - L; with `clamped` (the Phong demo's shaders) 2 max(n . L, 0) n - L.
#[inline(always)]
pub fn reflect<S: Real>(n: S::V3, l: S::V3, clamped: bool) -> S::V3 {
    let (x, y, z) = reflect3::<S>(n.x(), n.y(), n.z(), l.x(), l.y(), l.z(), clamped);
    S::V3::new(x, y, z)
}

/// [`reflect`] on components.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn reflect3<S: Real>(nx: S, ny: S, nz: S, lx: S, ly: S, lz: S, clamped: bool) -> (S, S, S) {
    let c = dot3(nx, ny, nz, lx, ly, lz);
    let k = S::from_f64(2.0) * if clamped { c.max(S::ZERO) } else { c };
    (nx * k - lx, ny * k - ly, nz * k - lz)
}

/// Energy-conserving Blinn-Phong's factor `(s_rm + 8) / (8 pi)` for shininess `s_rm`: the
/// normalised lobe reflects about the same light whatever its width (1/pi at s_rm = 0,
/// 4.4 at 100). In f64, rounded once where the engine takes it.
#[inline(always)]
pub fn specular_normalisation(shininess: f64) -> f64 {
    (shininess + 8.0) / (8.0 * std::f64::consts::PI)
}

/// Whether the specular term is allowed, by the rule set's gate: OpenGL's `f_i` (where
/// `n . L > 0`), the worksheet's `cos > 0`, or always (the demo's).
#[inline(always)]
pub fn specular_allowed<S: Real>(gate: SpecularGate, n_dot_l: S, cos: S) -> bool {
    match gate {
        SpecularGate::LitSide => n_dot_l > S::ZERO,
        SpecularGate::PositiveCosine => cos > S::ZERO,
        SpecularGate::None => true,
    }
}

/// The two factors of one light's terms on one side that every colour channel shares
/// (section 2.14.1): `max(n . L, 0)` where the light reaches the surface (`lit`), else
/// 0; and `f_i p` (`p` the power) where the specular is allowed, else 0. Taken once per
/// vertex, not once per channel.
#[inline(always)]
pub fn shared_factors<S: Real>(n_dot_l: S, lit: bool, allowed: bool, p: S) -> (S, S) {
    (if lit { n_dot_l.max(S::ZERO) } else { S::ZERO }, if allowed { p } else { S::ZERO })
}

/// One colour channel of one light's terms on one side, each factor of the sum in
/// section 2.14.1, from the [`shared_factors`] `(dn, fp)`: `diffuse = dn d_cm d_cli`,
/// `specular = fp s_cm s_cli`, and `att spot (ambient + diffuse + specular)` (the
/// specular apart with a separate specular colour). Returns (diffuse, specular,
/// primary, secondary).
#[inline(always)]
pub fn channel<S: Real>(amb: S, dif: S, spe: S, dn: S, fp: S, separate: bool, scale: S) -> (S, S, S, S) {
    // mul0(x, 0) = +0: a light that does not reach the side adds +0, as no term at all.
    let diffuse = mul0(dif, dn);
    let specular = mul0(spe, fp);
    let pri = if separate { amb + diffuse } else { amb + diffuse + specular };
    (diffuse, specular, mul0(pri, scale), if separate { mul0(specular, scale) } else { S::ZERO })
}

/// What the specular term needs besides n and L, and whether the diffuse cosine is clamped.
pub struct SpecularInputs<S: Real> {
    /// H, for Blinn-Phong (`None`: undefined, or not Blinn-Phong).
    pub h: Option<S::V3>,
    /// R, for Phong.
    pub r: Option<S::V3>,
    /// V (`None` at the eye).
    pub v: Option<S::V3>,
    /// When the specular is allowed.
    pub gate: SpecularGate,
    /// H (Blinn-Phong) or R (Phong).
    pub vector: SpecularVector,
    /// `max(n . L, 0)` in the diffuse term, as OpenGL has it; false for the formula slip
    /// that leaves it `n . L` ([`super::FormulaSlip::DiffuseNotClamped`]).
    pub clamp_diffuse: bool,
}

/// One light's terms on one side: `lit` is L where the light reaches the surface with a
/// direction (`None`: ambient only), `scale` is att * spot.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn side<S: Real>(
    products: [S::V3; 3],
    n_side: S::V3,
    lit: Option<S::V3>,
    spec: &SpecularInputs<S>,
    shininess: S,
    pow: PowFn,
    separate: bool,
    scale: S,
) -> SideTerms<S> {
    let [amb, dif, spe] = products;
    let mut st = SideTerms { ambient: amb, ..Default::default() };
    let mut allowed = false;
    let mut p = S::ONE;
    if let Some(l) = lit {
        st.n_dot_l = dot3(n_side.x(), n_side.y(), n_side.z(), l.x(), l.y(), l.z());
        let cos = match spec.vector {
            SpecularVector::Halfway => spec.h.map(|h| dot3(n_side.x(), n_side.y(), n_side.z(), h.x(), h.y(), h.z())),
            SpecularVector::Reflection => {
                spec.v.zip(spec.r).map(|(v, r)| dot3(r.x(), r.y(), r.z(), v.x(), v.y(), v.z()))
            }
        };
        if let Some(c) = cos {
            st.spec_cos = c;
            allowed = specular_allowed(spec.gate, st.n_dot_l, c);
            if allowed {
                st.f = S::ONE;
                p = pow.pow(c.max(S::ZERO), shininess);
            }
        }
    }
    let (dn, fp) = shared_factors(st.n_dot_l, lit.is_some(), allowed, p);
    let dn = if spec.clamp_diffuse || lit.is_none() { dn } else { st.n_dot_l };
    let ch = |k: usize| {
        let pick = |v: S::V3| [v.x(), v.y(), v.z()][k];
        channel(pick(amb), pick(dif), pick(spe), dn, fp, separate, scale)
    };
    let (c0, c1, c2) = (ch(0), ch(1), ch(2));
    st.diffuse = S::V3::new(c0.0, c1.0, c2.0);
    st.specular = S::V3::new(c0.1, c1.1, c2.1);
    st.primary = S::V3::new(c0.2, c1.2, c2.2);
    st.secondary = S::V3::new(c0.3, c1.3, c2.3);
    st
}

/// The side's colours from the lights' sums: `e_cm + a_cm a_cs + sum`, NaN (from
/// opposite infinities) shown as 0; and whether that happened.
#[inline(always)]
pub(crate) fn finish<S: Real>(
    m: &SideMaterial<S>,
    primary: S::V3,
    secondary: S::V3,
    separate: bool,
) -> ([S; 4], [S; 4], bool) {
    let p = m.emission + m.scene_ambient + primary;
    let mut nan = false;
    let mut fix = |x: S| {
        if x.is_nan() {
            nan = true;
            S::ZERO
        } else {
            x
        }
    };
    let primary = [fix(p.x()), fix(p.y()), fix(p.z()), m.alpha];
    let secondary =
        if separate { [fix(secondary.x()), fix(secondary.y()), fix(secondary.z()), S::ONE] } else { [S::ZERO; 4] };
    (primary, secondary, nan)
}
