//! The OpenGL 2.1 fixed-function lighting equation (section 2.14.1) with its breakdown.
//!
//! | symbol | meaning | here |
//! |---|---|---|
//! | `P`   | the vertex in eye space (after w-division) | [`VertexLighting::pos_in_eye`] |
//! | `N`, `n` | the normal in eye space: `(M^-1)^T n_obj`, then normalised or rescaled | `normal_in_eye` |
//! | `L`   | `VP_pli`: unit vector from the vertex to light i (its direction when w = 0) | [`LightTerms::l`] |
//! | `V`   | unit vector from the vertex to the viewer: `normalize(-P)` (local) or (0, 0, 1) | `v` |
//! | `H`   | the halfway vector `normalize(L + V)` (Blinn-Phong) | [`LightTerms::h`] |
//! | `R`   | the reflection of L about n: `2 (n . L) n - L` (Phong) | [`LightTerms::r`] |
//! | `d`   | `|VP|`, the distance to a positional light | [`LightTerms::distance`] |
//! | `att` | `1 / (k0 + k1 d + k2 d^2)` for w != 0, else 1 | [`LightTerms::attenuation`] |
//! | `spot`| `max(-L . s, 0)^s_rl` inside the cone `-L . s >= cos(c_rl)`, 0 outside, 1 for cutoff 180 | [`SpotTerms::factor`] |
//! | `f`   | 1 where `n . L > 0`, else 0: no specular from a light behind the surface | [`SideTerms::f`] |
//!
//! The colour of a side (`n` negated and the back material on the back side):
//!
//! ```text
//! c_pri = e_cm + a_cm a_cs + sum_i att_i spot_i [ a_cm a_cli + max(n.L, 0) d_cm d_cli + f_i max(n.H, 0)^s_rm s_cm s_cli ]
//! ```
//!
//! with the specular term moved to `c_sec` under `SEPARATE_SPECULAR_COLOR`, and alpha
//! `= alpha(d_cm)`. The worksheet's and the Phong demo's rules (see [`crate::model::rules`]) drop
//! terms from this same sum; they never compute a term differently.
//!
//! Numerics (docs/lighting.md): positions are transformed, divided by w and differenced in f64
//! with compensated dot products in both precisions, so huge cancelling coordinates
//! (1e18) stay exact; lengths are scaled before squaring; a product with a zero factor is
//! zero even when the other is infinite; where a direction is undefined the engine takes
//! the limit a person expects and records a [`Limit`].

use glam::{DMat4, DVec3, DVec4, Vec4Swizzles as _};

use crate::equation::breakdown::{LightTerms, Limit, Limits, SideColor, SideTerms, SpotTerms, VertexLighting};
use crate::model::error::SceneError;
use crate::model::rules::{Rules, SpecularGate, SpecularVector};
use crate::model::scene::{Light, Material, NormalMode, Rgba, Scene, Side, Vertex};
use crate::model::transform::NormalMatrix;
use crate::numerics::elementary;
use crate::numerics::pow::PowFn;
use crate::numerics::real::{Real, Vec3Ops};
use crate::numerics::robust::{cos_deg, mul0, mul0_v, scale0, transform_point, transform_vector3, try_normalize};

// The equation's per-vertex arithmetic, one function per step: `lighting/terms.rs`.
pub mod terms;

/// A material side rounded to the engine's precision.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SideMaterial<S: Real> {
    pub(crate) shininess: S,
    pub(crate) alpha: S,
    /// `e_cm` and `a_cm a_cs`, with the rule set's terms only.
    pub(crate) emission: S::V3,
    pub(crate) scene_ambient: S::V3,
}

/// How a light's direction is found.
#[derive(Clone, Copy, Debug)]
pub(crate) enum LightPos {
    /// w != 0: at this eye-space point.
    Positional(DVec3),
    /// w = 0: in direction `dir` (unit: `None` for (0, 0, 0)).
    Directional { dir: DVec3, unit: Option<DVec3> },
}

/// A spotlight's cone, precomputed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PreparedSpot<S: Real> {
    /// The unit axis in eye space (f64), `None` when the direction is zero.
    pub(crate) axis: Option<DVec3>,
    /// The cutoff in degrees, its cosine and sine.
    pub(crate) cutoff: f64,
    pub(crate) cos_cutoff: f64,
    pub(crate) sin_cutoff: f64,
    pub(crate) exponent: S,
}

/// Is the unit vector `a` (= -L) inside the cone of half-angle `cutoff` about the unit
/// axis `s`? OpenGL's test is `a . s >= cos(cutoff)`; near the axis a cosine cannot
/// resolve small angles (cos 0.01 deg = 1 - 1.5e-8 rounds to 1 in f32), so for cutoffs
/// under 45 degrees the equivalent `|a x s| <= sin(cutoff)` (with `a . s >= 0`) is used.
#[inline(always)]
pub(crate) fn inside_cone(a: DVec3, s: DVec3, cutoff: f64, cos_cutoff: f64, sin_cutoff: f64) -> bool {
    let cos = a.dot(s);
    if cutoff >= 45.0 { cos >= cos_cutoff } else { cos >= 0.0 && a.cross(s).length() <= sin_cutoff }
}

/// One light with everything that does not depend on the vertex precomputed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PreparedLight<S: Real> {
    pub(crate) index: usize,
    pub(crate) pos_in_eye: DVec4,
    pub(crate) pos: LightPos,
    pub(crate) k: [S; 3],
    /// The spotlight; `None` when cutoff is 180.
    pub(crate) spot: Option<PreparedSpot<S>>,
    /// Light x material products per side: ambient, diffuse, specular.
    pub(crate) products: [[S::V3; 3]; 2],
}

/// How the engine computes, beyond what the scene says: numerical choices, not GL state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct EvalOptions {
    /// The power function of the specular and spot terms.
    pub pow: PowFn,
    /// How per-pixel (Phong) shading renormalises its interpolated normals.
    pub renormalize: Renormalize,
    /// A slip in one step of the formula (none by default): drawn by the general engine
    /// only, never by the specialised lighter's program.
    pub slip: FormulaSlip,
}

/// A slip in one step of the lighting formula, as a student makes it by editing a line of
/// the exported shader (`templates/lighting.glsl`), which lights per vertex or per fragment
/// as the scene says: the engine makes it at the same step, wherever it lights. What
/// `phonglab diagnose` draws to name such an edit; not OpenGL, and never chosen otherwise.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FormulaSlip {
    /// The formula as OpenGL has it.
    #[default]
    None,
    /// The diffuse term's `max(n . L, 0)` written `n . L`: negative where the light is behind.
    DiffuseNotClamped,
    /// A positional light's `L` from the light to the vertex (`P - P_l`, normalised): the
    /// diffuse, the specular and the spot cone all take it so.
    LightReversed,
    /// The local viewer's `V` from the eye to the vertex (`normalize(P)`).
    ViewerReversed,
    /// The specular cosine `n . (L + V)`, the halfway vector not normalised.
    HalfwayNotNormalised,
    /// A positional light's `L` left unnormalised (`toL` for `toL / d`: its length the
    /// distance): the diffuse `n . L`, the spot's cosine and its cone test, R (and so
    /// `R . V`) and H's direction all take it so; the attenuation keeps the distance.
    LightNotNormalised,
    /// R reflected the wrong way (GLSL's `reflect(L, N)` for `reflect(-L, N)`): `L - 2 (n . L)
    /// n`, OpenGL's R turned round (unclamped, whatever the rules' R), where the specular
    /// takes `R . V`.
    ReflectionReversed,
}

impl EvalOptions {
    /// The default options with power function `pow`.
    pub fn with_pow(pow: PowFn) -> Self {
        Self { pow, ..Self::default() }
    }
}

/// How Phong shading brings its interpolated normals (shorter than 1 inside a triangle)
/// back to unit length: what a shader's `normalize(n)` costs and what skipping it costs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Renormalize {
    /// `n / |n|`, exactly rounded (with a power-of-two prescale, as everywhere).
    #[default]
    Exact,
    /// `n * rsqrt(n . n)` with the classic approximate reciprocal square root: the bit
    /// trick `0x5f3759df - (bits >> 1)` and one Newton step (relative error <= 0.175 %).
    FastRsqrt,
    /// Not renormalised: `n` as interpolated.
    Skip,
}

/// The classic approximate `1 / sqrt(x)` for `x > 0`: an initial guess from the float's
/// bits, refined by one Newton step `y (3/2 - x y^2 / 2)`.
#[inline(always)]
pub fn fast_rsqrt(x: f32) -> f32 {
    let y = f32::from_bits(0x5f37_59df_u32.wrapping_sub(x.to_bits() >> 1));
    y * (1.5 - 0.5 * x * y * y)
}

/// The general lighting engine for a scene, in precision `S`: every term of the
/// equation, with the full breakdown. Build it once per scene, then light vertices.
#[derive(Clone, Debug)]
pub struct Engine<S: Real> {
    pub(crate) options: EvalOptions,
    pub(crate) rules: Rules,
    pub(crate) local_viewer: bool,
    pub(crate) two_sided: bool,
    pub(crate) separate_specular: bool,
    pub(crate) normal_mode: NormalMode,
    pub(crate) eye_from_object: DMat4,
    pub(crate) normal_matrix: S::M3,
    pub(crate) rescale: S,
    pub(crate) singular: bool,
    pub(crate) sides: [SideMaterial<S>; 2],
    pub(crate) lights: Vec<PreparedLight<S>>,
}

fn rgb<S: Real>(c: Rgba) -> S::V3 {
    S::V3::from_dvec3(c.xyz())
}

fn side_material<S: Real>(m: &Material, scene: &Scene) -> SideMaterial<S> {
    let rules = scene.rules;
    SideMaterial {
        shininess: S::from_f64(m.shininess),
        alpha: S::from_f64(m.diffuse.w),
        emission: if rules.emission() { rgb::<S>(m.emission) } else { S::V3::ZERO },
        scene_ambient: if rules.scene_ambient() {
            mul0_v::<S>(rgb::<S>(m.ambient), rgb::<S>(scene.light_model.ambient))
        } else {
            S::V3::ZERO
        },
    }
}

fn prepare_light<S: Real>(scene: &Scene, index: usize, l: &Light) -> PreparedLight<S> {
    let eye_from_light = scene.eye_from_light(l);
    let pos_in_eye = scene.light_pos_in_eye(l);
    let pos = if pos_in_eye.w == 0.0 {
        let dir = pos_in_eye.xyz();
        LightPos::Directional { dir, unit: try_normalize::<f64>(dir) }
    } else {
        LightPos::Positional(pos_in_eye.xyz() / pos_in_eye.w)
    };
    let spot = l.is_spot().then(|| PreparedSpot {
        axis: try_normalize::<f64>(transform_vector3(&eye_from_light, l.spot_direction)),
        cutoff: l.spot_cutoff,
        cos_cutoff: cos_deg(l.spot_cutoff),
        sin_cutoff: if l.spot_cutoff == 0.0 { 0.0 } else { elementary::sin(l.spot_cutoff.to_radians()) },
        exponent: S::from_f64(l.spot_exponent),
    });
    let product = |m: &Material| {
        let specular = mul0_v::<S>(rgb::<S>(m.specular), rgb::<S>(l.specular));
        [
            mul0_v::<S>(rgb::<S>(m.ambient), rgb::<S>(l.ambient)),
            mul0_v::<S>(rgb::<S>(m.diffuse), rgb::<S>(l.diffuse)),
            // Energy-conserving Blinn-Phong's factor, once per side: every specular term of
            // the side (the general engine's and the specialised lighter's) is scaled alike.
            if scene.rules.specular.normalised() {
                scale0::<S>(specular, S::from_f64(terms::specular_normalisation(m.shininess)))
            } else {
                specular
            },
        ]
    };
    PreparedLight {
        index,
        pos_in_eye,
        pos,
        k: l.attenuation.map(S::from_f64),
        spot,
        products: [product(&scene.lit_material(Side::Front)), product(&scene.lit_material(Side::Back))],
    }
}

impl<S: Real> Engine<S> {
    /// Builds the engine for `scene`, refusing what OpenGL refuses ([`Scene::validate`]).
    pub fn new(scene: &Scene) -> Result<Self, SceneError> {
        Self::with_options(scene, EvalOptions::default())
    }

    /// [`Engine::new`] with numerical options.
    pub fn with_options(scene: &Scene, options: EvalOptions) -> Result<Self, SceneError> {
        scene.validate()?;
        let eye_from_object = scene.eye_from_object();
        let nm = NormalMatrix::for_rules(&eye_from_object, scene.rules);
        Ok(Self {
            options,
            rules: scene.rules,
            local_viewer: scene.light_model.local_viewer,
            two_sided: scene.light_model.two_sided,
            separate_specular: scene.light_model.separate_specular,
            normal_mode: scene.normal_mode,
            eye_from_object,
            normal_matrix: S::m3_from_dmat3(nm.eye_from_object),
            rescale: S::from_f64(nm.rescale),
            singular: nm.singular,
            sides: [
                side_material(&scene.lit_material(Side::Front), scene),
                side_material(&scene.lit_material(Side::Back), scene),
            ],
            lights: scene.lights.iter().enumerate().map(|(i, l)| prepare_light(scene, i, l)).collect(),
        })
    }

    /// Lights the scene's own vertex.
    pub fn light_scene_vertex(scene: &Scene) -> Result<VertexLighting<S>, SceneError> {
        Ok(Self::new(scene)?.light(&scene.vertex))
    }

    /// The options the engine was built with.
    pub fn options(&self) -> EvalOptions {
        self.options
    }

    /// Lights one vertex (object-space position and normal), with the full breakdown.
    pub fn light(&self, vertex: &Vertex) -> VertexLighting<S> {
        // P: the vertex in eye space, divided by w (a direction when w = 0).
        let pos_h = transform_point(&self.eye_from_object, vertex.position);
        // n: (M^-1)^T n_obj, then GL_NORMALIZE or GL_RESCALE_NORMAL.
        let n_t = self.normal_matrix * S::V3::from_dvec3(vertex.normal);
        let (n, scaled) = terms::normal_mode::<S>(self.normal_mode, self.rescale, n_t);
        let mut out = self.light_eye(pos_h, n);
        out.normal_transformed = n_t;
        if scaled {
            out.limits.insert(Limit::NormalScaled);
        }
        out
    }

    /// Lights a vertex given in eye space: its homogeneous position and the normal the
    /// equation uses (already transformed, normalised or rescaled). Per-pixel shading
    /// calls this with interpolated values.
    pub fn light_eye(&self, pos_h: DVec4, n: S::V3) -> VertexLighting<S> {
        let mut out = VertexLighting::<S>::default();
        if self.singular {
            out.limits.insert(Limit::SingularModelview);
        }
        let at_infinity = pos_h.w == 0.0;
        let pos = if at_infinity { pos_h.xyz() } else { pos_h.xyz() / pos_h.w };
        if at_infinity {
            out.limits.insert(Limit::VertexAtInfinity);
        }
        out.pos_in_eye_h = pos_h;
        out.pos_in_eye = pos;
        let zero_normal = terms::is_zero_normal::<S>(n);
        if zero_normal {
            out.limits.insert(Limit::ZeroNormal);
        }
        out.normal_transformed = n;
        out.normal_in_eye = n;

        // V: towards the viewer.
        let v = terms::view_vector::<S>(self.local_viewer, self.rules.viewer_from_eye_plane(), pos);
        let v = if self.local_viewer && self.options.slip == FormulaSlip::ViewerReversed { v.map(|v| -v) } else { v };
        if v.is_none() {
            out.limits.insert(Limit::VertexAtEye);
        }
        out.v = v.unwrap_or(S::V3::ZERO);

        let mut acc = [Accum::<S>::default(); 2];
        for pl in &self.lights {
            let t = self.light_one(pl, pos, at_infinity, n, zero_normal, v);
            for (side, a) in acc.iter_mut().enumerate() {
                let st = if side == 0 { &t.front } else { &t.back };
                a.primary = a.primary + st.primary;
                a.secondary = a.secondary + st.secondary;
            }
            out.push_light(t);
        }

        let mut limits = out.limits;
        out.front = self.side_color(0, &acc[0], &mut limits);
        out.back = if self.two_sided { self.side_color(1, &acc[1], &mut limits) } else { out.front };
        out.limits = limits;
        out
    }

    fn side_color(&self, side: usize, acc: &Accum<S>, limits: &mut Limits) -> SideColor<S> {
        let m = &self.sides[side];
        let (primary, secondary, nan) = terms::finish::<S>(m, acc.primary, acc.secondary, self.separate_specular);
        if nan {
            limits.insert(Limit::InfinitiesCancelled);
        }
        SideColor { emission: m.emission, scene_ambient: m.scene_ambient, primary, secondary }
    }

    /// One light's terms at the vertex.
    fn light_one(
        &self,
        pl: &PreparedLight<S>,
        pos: DVec3,
        at_infinity: bool,
        n: S::V3,
        zero_normal: bool,
        v: Option<S::V3>,
    ) -> LightTerms<S> {
        let mut limits = Limits::NONE;
        let (l64, distance, attenuation) = Self::light_vector(pl, pos, at_infinity, &mut limits);
        let reversed = self.options.slip == FormulaSlip::LightReversed && matches!(pl.pos, LightPos::Positional(_));
        let l64 = if reversed { l64.map(|l| -l) } else { l64 };
        let long = match pl.pos {
            LightPos::Positional(lp) if self.options.slip == FormulaSlip::LightNotNormalised && !at_infinity => {
                Some(lp - pos)
            }
            _ => None,
        };
        let l64 = if long.is_some() { l64.and(long) } else { l64 };
        let l: Option<S::V3> = l64.map(S::V3::from_dvec3);
        let spot = self.spot_terms(pl, l64, &mut limits);
        let scale = mul0(attenuation, spot.factor);

        // H or R.
        let lit = l.filter(|_| !zero_normal);
        let h = self.halfway(l, v, &mut limits);
        let r = lit.map(|l| terms::reflect::<S>(n, l, self.rules.reflect_clamped()));
        // GLSL's `reflect(L, N)`: `L - 2 (n . L) n`, unclamped whatever the rules' R.
        let r = if self.options.slip == FormulaSlip::ReflectionReversed {
            lit.map(|l| -terms::reflect::<S>(n, l, false))
        } else {
            r
        };

        let side_terms = |side: usize| -> SideTerms<S> {
            let n_side = if side == 0 { n } else { -n };
            let sp = terms::SpecularInputs {
                h,
                r,
                v,
                gate: self.rules.specular_gate(),
                vector: self.rules.specular.vector(),
                clamp_diffuse: self.options.slip != FormulaSlip::DiffuseNotClamped,
            };
            terms::side::<S>(
                pl.products[side],
                n_side,
                lit,
                &sp,
                self.sides[side].shininess,
                self.options.pow,
                self.separate_specular,
                scale,
            )
        };
        let front = side_terms(0);
        let back = if self.two_sided { side_terms(1) } else { front };

        LightTerms {
            index: pl.index,
            pos_in_eye: pl.pos_in_eye,
            positional: matches!(pl.pos, LightPos::Positional(_)),
            l: l.unwrap_or(S::V3::ZERO),
            distance,
            attenuation,
            spot,
            scale,
            h: h.unwrap_or(S::V3::ZERO),
            r: r.unwrap_or(S::V3::ZERO),
            front,
            back,
            limits,
        }
    }

    /// L (in f64, `None` where it has no direction), the distance d (positional lights) and
    /// the attenuation, noting what this precision could not hold.
    #[inline(always)]
    fn light_vector(
        pl: &PreparedLight<S>,
        pos: DVec3,
        at_infinity: bool,
        limits: &mut Limits,
    ) -> (Option<DVec3>, Option<S>, S) {
        let (l64, d64) = terms::light_vector(&pl.pos, pos, at_infinity);
        if let (LightPos::Positional(lp), false, Some(d)) = (&pl.pos, at_infinity, d64) {
            // Would |VP|^2 have under- or overflowed in this precision?
            let vp_s = S::V3::from_dvec3(*lp - pos);
            let sq = vp_s.dot(vp_s);
            if d > 0.0 && (sq == S::ZERO || !sq.is_finite()) {
                limits.insert(Limit::DistanceScaled);
            }
        }
        if l64.is_none() {
            limits.insert(match pl.pos {
                LightPos::Positional(_) => Limit::LightAtVertex,
                LightPos::Directional { .. } => Limit::LightDirectionZero,
            });
        }
        let distance = d64.map(S::from_f64);
        let attenuation = distance.map_or(S::ONE, |d| terms::attenuation(pl.k, d));
        if attenuation == S::INFINITY {
            limits.insert(Limit::AttenuationInfinite);
        }
        (l64, distance, attenuation)
    }

    /// The spotlight's cosine to its axis, the cone test and the factor (1 for a light that
    /// is not a spot).
    #[inline(always)]
    fn spot_terms(&self, pl: &PreparedLight<S>, l64: Option<DVec3>, limits: &mut Limits) -> SpotTerms<S> {
        let Some(sp) = &pl.spot else {
            return SpotTerms { active: false, factor: S::ONE, ..Default::default() };
        };
        let (cos_angle, inside, factor) = terms::spot(sp, l64, self.options.pow);
        // The shader's cone test on an unnormalised L: `dot(-L, s) >= cos(cutoff)`, the
        // cosine scaled by the distance.
        let (inside, factor) = match (self.options.slip, pl.pos, sp.axis) {
            (FormulaSlip::LightNotNormalised, LightPos::Positional(_), Some(_)) if l64.is_some() => {
                let inside = cos_angle.to_f64() >= sp.cos_cutoff;
                (inside, terms::spot_power(cos_angle, inside, sp.exponent, self.options.pow))
            }
            _ => (inside, factor),
        };
        match (sp.axis, l64) {
            (None, _) => limits.insert(Limit::SpotDirectionZero),
            (Some(_), None) if matches!(pl.pos, LightPos::Positional(_)) => limits.insert(Limit::SpotAtVertex),
            _ => {}
        }
        SpotTerms {
            active: true,
            dir_in_eye: sp.axis.map_or(S::V3::ZERO, S::V3::from_dvec3),
            cos_angle,
            cos_cutoff: S::from_f64(sp.cos_cutoff),
            inside,
            factor,
        }
    }

    /// H, where the specular model takes its cosine with H and L and V have directions
    /// (`None` where L + V is zero, noted).
    #[inline(always)]
    fn halfway(&self, l: Option<S::V3>, v: Option<S::V3>, limits: &mut Limits) -> Option<S::V3> {
        match (self.rules.specular.vector(), l, v) {
            (SpecularVector::Halfway, Some(l), Some(v)) if self.options.slip == FormulaSlip::HalfwayNotNormalised => {
                Some(l + v)
            }
            (SpecularVector::Halfway, Some(l), Some(v)) => {
                let h = terms::halfway::<S>(l, v);
                if h.is_none() {
                    limits.insert(Limit::HalfwayZero);
                }
                h
            }
            (SpecularVector::Halfway | SpecularVector::Reflection, _, _) => None,
        }
    }
}

#[derive(Clone, Copy, Debug, Default)]
struct Accum<S: Real> {
    primary: S::V3,
    secondary: S::V3,
}

impl crate::model::view::View {
    /// The numerical options of the shaded view with power function `pow`.
    pub fn eval_options(&self, pow: crate::numerics::pow::PowFn) -> EvalOptions {
        let renormalize = if self.phong_renormalize { Renormalize::Exact } else { Renormalize::Skip };
        EvalOptions { pow, renormalize, ..EvalOptions::default() }
    }
}
