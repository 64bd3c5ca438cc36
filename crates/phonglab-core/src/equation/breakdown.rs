//! The worked breakdown of one vertex's lighting, and the limits the engine chose.
//!
//! Every value a student checks line by line is here: eye-space N and position, then per
//! light L (= VP), d, attenuation, spot, H or R, the cosines, `f`, the three terms, and
//! the totals per face side. Where the numerics policy picked a limit, a [`Limit`] says
//! which and why, attached to the light (or the vertex) it concerns.

use std::fmt;

use glam::{DVec3, DVec4};

use crate::model::scene::MAX_LIGHTS;
use crate::numerics::real::Real;

/// A value the engine could not compute directly and replaced by the limit a person
/// expects (docs/lighting.md, "Numerics policy"), or a fact worth knowing about how it computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Limit {
    /// VP = 0.
    LightAtVertex,
    /// A directional light with direction (0, 0, 0).
    LightDirectionZero,
    /// Blinn-Phong with L exactly opposite V.
    HalfwayZero,
    /// n = 0 (given so, or transformed to 0).
    ZeroNormal,
    /// GL_NORMALIZE on a normal whose squared length under- or overflows.
    NormalScaled,
    /// |VP| whose square under- or overflows.
    DistanceScaled,
    /// k0 + k1 d + k2 d^2 = 0.
    AttenuationInfinite,
    /// A spotlight whose direction is (0, 0, 0).
    SpotDirectionZero,
    /// A spotlight at the vertex: no direction to test against the cone.
    SpotAtVertex,
    /// A local viewer exactly at the vertex.
    VertexAtEye,
    /// The vertex has w = 0: a point at infinity.
    VertexAtInfinity,
    /// The modelview's 3x3 part is singular.
    SingularModelview,
    /// An infinite term of one sign met one of the other sign.
    InfinitiesCancelled,
}

impl Limit {
    /// Every limit, in the order they are reported.
    pub const ALL: [Limit; 13] = [
        Limit::SingularModelview,
        Limit::ZeroNormal,
        Limit::NormalScaled,
        Limit::VertexAtInfinity,
        Limit::VertexAtEye,
        Limit::LightAtVertex,
        Limit::LightDirectionZero,
        Limit::DistanceScaled,
        Limit::AttenuationInfinite,
        Limit::SpotDirectionZero,
        Limit::SpotAtVertex,
        Limit::HalfwayZero,
        Limit::InfinitiesCancelled,
    ];

    /// What happened and what the engine did, in one sentence.
    pub fn message(self) -> String {
        match self {
            Limit::LightAtVertex => crate::t!("limit-light-at-vertex"),
            Limit::LightDirectionZero => crate::t!("limit-light-direction-zero"),
            Limit::HalfwayZero => crate::t!("limit-halfway-zero"),
            Limit::ZeroNormal => crate::t!("limit-zero-normal"),
            Limit::NormalScaled => crate::t!("limit-normal-scaled"),
            Limit::DistanceScaled => crate::t!("limit-distance-scaled"),
            Limit::AttenuationInfinite => crate::t!("limit-attenuation-infinite"),
            Limit::SpotDirectionZero => crate::t!("limit-spot-direction-zero"),
            Limit::SpotAtVertex => crate::t!("limit-spot-at-vertex"),
            Limit::VertexAtEye => crate::t!("limit-vertex-at-eye"),
            Limit::VertexAtInfinity => crate::t!("limit-vertex-at-infinity"),
            Limit::SingularModelview => crate::t!("limit-singular-modelview"),
            Limit::InfinitiesCancelled => crate::t!("limit-infinities-cancelled"),
        }
    }

    /// A short tag for tables and JSON.
    pub fn code(self) -> &'static str {
        match self {
            Limit::LightAtVertex => "light_at_vertex",
            Limit::LightDirectionZero => "light_direction_zero",
            Limit::HalfwayZero => "halfway_zero",
            Limit::ZeroNormal => "zero_normal",
            Limit::NormalScaled => "normal_scaled",
            Limit::DistanceScaled => "distance_scaled",
            Limit::AttenuationInfinite => "attenuation_infinite",
            Limit::SpotDirectionZero => "spot_direction_zero",
            Limit::SpotAtVertex => "spot_at_vertex",
            Limit::VertexAtEye => "vertex_at_eye",
            Limit::VertexAtInfinity => "vertex_at_infinity",
            Limit::SingularModelview => "singular_modelview",
            Limit::InfinitiesCancelled => "infinities_cancelled",
        }
    }
}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message())
    }
}

/// A set of [`Limit`]s.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Limits(u32);

impl Limits {
    /// No limits.
    pub const NONE: Limits = Limits(0);

    /// Adds one.
    #[inline]
    pub fn insert(&mut self, l: Limit) {
        self.0 |= 1 << (l as u8);
    }

    /// Is it there?
    #[inline]
    pub fn contains(self, l: Limit) -> bool {
        self.0 & (1 << (l as u8)) != 0
    }

    /// None at all?
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The limits present, in [`Limit::ALL`] order.
    pub fn iter(self) -> impl Iterator<Item = Limit> {
        Limit::ALL.into_iter().filter(move |l| self.contains(*l))
    }
}

/// One light's spotlight evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SpotTerms<S: Real> {
    /// A spotlight (cutoff other than 180).
    pub active: bool,
    /// `s_dli` in eye space, normalised (zero when undefined).
    pub dir_in_eye: S::V3,
    /// `-L . s`, the cosine of the angle between the spot axis and the vertex.
    pub cos_angle: S,
    /// `cos(c_rli)`.
    pub cos_cutoff: S,
    /// `cos_angle >= cos_cutoff` (OpenGL 2.1: inside the cone, boundary included).
    pub inside: bool,
    /// `spot_i`: `max(cos_angle, 0)^s_rli` inside the cone, 0 outside, 1 when not a spotlight.
    pub factor: S,
}

/// One light's terms on one face side.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SideTerms<S: Real> {
    /// `n . L` (`cos theta` for unit vectors), with `n` negated on the back side.
    pub n_dot_l: S,
    /// The specular cosine: `n . H` (`cos beta`, Blinn-Phong) or `R . V` (Phong).
    pub spec_cos: S,
    /// `f_i` (or the rule set's gate): 1 where specular is allowed, else 0.
    pub f: S,
    /// `a_cm * a_cli` (unattenuated).
    pub ambient: S::V3,
    /// `max(n . L, 0) * d_cm * d_cli` (unattenuated).
    pub diffuse: S::V3,
    /// `f * max(spec_cos, 0)^s_rm * s_cm * s_cli` (unattenuated).
    pub specular: S::V3,
    /// This light's contribution to the primary colour: `att * spot * (ambient + diffuse [+ specular])`.
    pub primary: S::V3,
    /// Its contribution to the secondary colour: `att * spot * specular` with separate specular, else 0.
    pub secondary: S::V3,
}

/// Everything one light did to the vertex.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LightTerms<S: Real> {
    /// `GL_LIGHTi` index.
    pub index: usize,
    /// The light's position in eye space, homogeneous, as transformed (before w-division).
    pub pos_in_eye: DVec4,
    /// Positional (w != 0) rather than directional.
    pub positional: bool,
    /// `L = VP_pli`, unit vector from the vertex to the light (zero when undefined).
    pub l: S::V3,
    /// `d = |VP|` for a positional light; `None` for a directional one.
    pub distance: Option<S>,
    /// `att_i = 1 / (k0 + k1 d + k2 d^2)`; 1 for a directional light.
    pub attenuation: S,
    /// The spotlight.
    pub spot: SpotTerms<S>,
    /// `att_i * spot_i`, the factor every term of this light is scaled by.
    pub scale: S,
    /// `H = normalize(L + V)` (zero when undefined).
    pub h: S::V3,
    /// `R = 2 (n . L) n - L` (zero when L is undefined).
    pub r: S::V3,
    /// Front-side terms.
    pub front: SideTerms<S>,
    /// Back-side terms (equal to the front's without two-sided lighting).
    pub back: SideTerms<S>,
    /// Limits chosen for this light.
    pub limits: Limits,
}

/// The colour of one face side.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SideColor<S: Real> {
    /// `e_cm` as it enters the sum (zero where the rule set leaves emission out).
    pub emission: S::V3,
    /// `a_cm * a_cs` as it enters the sum (zero where the rule set leaves it out).
    pub scene_ambient: S::V3,
    /// The primary colour, unclamped; alpha is the material's diffuse alpha.
    pub primary: [S; 4],
    /// The secondary colour, unclamped: the specular sum and alpha 1 with separate
    /// specular, else (0, 0, 0, 0).
    pub secondary: [S; 4],
}

impl<S: Real> SideColor<S> {
    /// The primary colour clamped to [0, 1], as OpenGL clamps it.
    pub fn primary_clamped(&self) -> [S; 4] {
        clamp4(self.primary)
    }

    /// The secondary colour clamped to [0, 1].
    pub fn secondary_clamped(&self) -> [S; 4] {
        clamp4(self.secondary)
    }

    /// The colour a fixed-function fragment gets: primary + secondary rgb (the colour sum).
    pub fn sum(&self) -> [S; 4] {
        let (p, s) = (self.primary, self.secondary);
        [p[0] + s[0], p[1] + s[1], p[2] + s[2], p[3]]
    }
}

fn clamp4<S: Real>(c: [S; 4]) -> [S; 4] {
    c.map(|x| x.max(S::ZERO).min(S::ONE))
}

/// The full worked breakdown of one vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexLighting<S: Real> {
    /// The vertex in eye space, homogeneous, as transformed.
    pub pos_in_eye_h: DVec4,
    /// The vertex in eye space after w-division (its direction when w = 0).
    pub pos_in_eye: DVec3,
    /// `(M^-1)^T n`, before normalising or rescaling.
    pub normal_transformed: S::V3,
    /// `n`, the normal the equation uses (after GL_NORMALIZE / GL_RESCALE_NORMAL).
    pub normal_in_eye: S::V3,
    /// `V`, unit vector from the vertex to the viewer: (0, 0, 1) for an infinite viewer.
    pub v: S::V3,
    lights: [LightTerms<S>; MAX_LIGHTS],
    light_count: usize,
    /// The front side's colour.
    pub front: SideColor<S>,
    /// The back side's colour (equal to the front's without two-sided lighting).
    pub back: SideColor<S>,
    /// Limits that concern the vertex rather than one light.
    pub limits: Limits,
}

impl<S: Real> Default for VertexLighting<S> {
    fn default() -> Self {
        Self {
            pos_in_eye_h: DVec4::ZERO,
            pos_in_eye: DVec3::ZERO,
            normal_transformed: Default::default(),
            normal_in_eye: Default::default(),
            v: Default::default(),
            lights: [LightTerms::default(); MAX_LIGHTS],
            light_count: 0,
            front: SideColor::default(),
            back: SideColor::default(),
            limits: Limits::NONE,
        }
    }
}

impl<S: Real> VertexLighting<S> {
    /// Each enabled light's terms, in light order.
    pub fn lights(&self) -> &[LightTerms<S>] {
        &self.lights[..self.light_count]
    }

    pub(crate) fn push_light(&mut self, t: LightTerms<S>) {
        self.lights[self.light_count] = t;
        self.light_count += 1;
    }

    /// Every limit chosen anywhere, with the light it concerns (`None`: the vertex).
    pub fn all_limits(&self) -> Vec<(Option<usize>, Limit)> {
        let mut out: Vec<_> = self.limits.iter().map(|l| (None, l)).collect();
        for t in self.lights() {
            out.extend(t.limits.iter().map(|l| (Some(t.index), l)));
        }
        out
    }

    /// Is this limit anywhere in the breakdown?
    pub fn has_limit(&self, l: Limit) -> bool {
        self.limits.contains(l) || self.lights().iter().any(|t| t.limits.contains(l))
    }
}
