//! Rule sets: OpenGL 2.1, the worksheet's, the Phong demo's — presets of one engine.
//!
//! A rule set changes which terms the equation has, never how a term is computed, so
//! all three run through the same code in the equation group's `lighting` (a layer above).

use std::fmt;

/// Which equation the engine evaluates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum RuleSet {
    /// The OpenGL 2.1 compatibility-profile equation (section 2.14.1), all of it.
    #[default]
    OpenGl,
    /// The openFrameworks class worksheet: no scene ambient, no emission; diffuse is 0
    /// past 90 degrees (theta), specular is 0 past 90 degrees (beta), with no `f_i` factor.
    Worksheet,
    /// The Python/GLSL Phong demo: `ambient + diffuse*max(N.L,0) + specular*pow(max(.,0), e)`,
    /// no scene ambient, no emission, no `f_i` factor.
    PhongDemo,
}

impl RuleSet {
    /// Every rule set, in menu order.
    pub const ALL: [RuleSet; 3] = [RuleSet::OpenGl, RuleSet::Worksheet, RuleSet::PhongDemo];

    /// A short name for menus and files.
    pub fn label(self) -> String {
        match self {
            RuleSet::OpenGl => "OpenGL 2.1".into(),
            RuleSet::Worksheet => crate::t!("ruleset-worksheet"),
            RuleSet::PhongDemo => crate::t!("ruleset-demo"),
        }
    }
}

/// How the specular cosine is formed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum SpecularModel {
    /// Blinn-Phong (OpenGL's): `cos(beta) = n . H`, `H = normalize(L + V)`.
    #[default]
    BlinnPhong,
    /// Phong: `cos = R . V`, `R = 2 (n . L) n - L` (the reflection of L about n).
    Phong,
    /// Energy-conserving Blinn-Phong, as modern engines light: Blinn-Phong's term times
    /// `(s_rm + 8) / (8 pi)`, so a narrower highlight is brighter and reflects the same light.
    BlinnPhongNormalised,
}

impl SpecularModel {
    /// Every model, in menu order.
    pub const ALL: [SpecularModel; 3] =
        [SpecularModel::BlinnPhong, SpecularModel::Phong, SpecularModel::BlinnPhongNormalised];

    /// A short name for menus and headings, with its symbol.
    pub fn label(self) -> String {
        match self {
            SpecularModel::BlinnPhong => "Blinn-Phong (n.H)".into(),
            SpecularModel::Phong => "Phong (R.V)".into(),
            SpecularModel::BlinnPhongNormalised => crate::t!("specular-blinn-phong-normalised"),
        }
    }

    /// The name a notebook's `specular = "..."` setting gives it (the scene file's too).
    pub fn name(self) -> &'static str {
        match self {
            SpecularModel::BlinnPhong => "blinn-phong",
            SpecularModel::Phong => "phong",
            SpecularModel::BlinnPhongNormalised => "blinn-phong-normalised",
        }
    }

    /// The model named `name` ([`SpecularModel::name`]).
    pub fn from_name(name: &str) -> Option<SpecularModel> {
        SpecularModel::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The next model in menu order, the last followed by the first (the window's key B).
    pub fn next(self) -> SpecularModel {
        let at = SpecularModel::ALL.iter().position(|m| *m == self).unwrap_or(0);
        SpecularModel::ALL[(at + 1) % SpecularModel::ALL.len()]
    }

    /// The vector its cosine is taken with: H (Blinn-Phong) or R (Phong). The engine, the
    /// plan and the window's vectors ask this, never which model it is.
    pub fn vector(self) -> SpecularVector {
        match self {
            SpecularModel::BlinnPhong | SpecularModel::BlinnPhongNormalised => SpecularVector::Halfway,
            SpecularModel::Phong => SpecularVector::Reflection,
        }
    }

    /// Is the term normalised, multiplied by `(s_rm + 8) / (8 pi)`
    /// (`lighting::terms::specular_normalisation`)?
    pub fn normalised(self) -> bool {
        match self {
            SpecularModel::BlinnPhong | SpecularModel::Phong => false,
            SpecularModel::BlinnPhongNormalised => true,
        }
    }
}

/// The vector a specular cosine is taken with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpecularVector {
    /// The halfway vector `H = normalize(L + V)`: the cosine is `n . H` (Blinn-Phong).
    Halfway,
    /// The reflection of L about n, `R = 2 (n . L) n - L`: the cosine is `R . V` (Phong).
    Reflection,
}

/// When a light's specular term is allowed at all.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpecularGate {
    /// OpenGL's `f_i`: only where `n . L > 0` (the light is on the lit side).
    LitSide,
    /// The worksheet's angle test: only where the specular cosine is positive (beta < 90).
    PositiveCosine,
    /// No gate: `pow(max(cos, 0), e)` alone (the demo's shader).
    None,
}

/// How a normal reaches eye space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NormalTransform {
    /// OpenGL's: by the inverse transpose of the modelview's 3x3, `(M^-1)^T n`.
    InverseTranspose,
    /// The worksheet's: by the modelview itself, `M n` (the same for a rotation; not for a
    /// matrix whose rows are not orthonormal, such as the worksheet's printed `mview2`).
    Modelview,
}

/// The rule set and the specular model: everything that selects the equation's form.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Rules {
    /// Which equation.
    pub set: RuleSet,
    /// Blinn-Phong or Phong specular.
    pub specular: SpecularModel,
}

impl Rules {
    /// OpenGL 2.1 with Blinn-Phong.
    pub const OPENGL: Rules = Rules { set: RuleSet::OpenGl, specular: SpecularModel::BlinnPhong };
    /// The worksheet (Blinn-Phong halfway vector).
    pub const WORKSHEET: Rules = Rules { set: RuleSet::Worksheet, specular: SpecularModel::BlinnPhong };
    /// The Phong demo (reflection vector).
    pub const PHONG_DEMO: Rules = Rules { set: RuleSet::PhongDemo, specular: SpecularModel::Phong };

    /// Does the scene's ambient `a_cm * a_cs` enter the sum?
    pub fn scene_ambient(self) -> bool {
        self.set == RuleSet::OpenGl
    }

    /// Does the material's emission `e_cm` enter the sum?
    pub fn emission(self) -> bool {
        self.set == RuleSet::OpenGl
    }

    /// How normals are transformed to eye space.
    pub fn normal_transform(self) -> NormalTransform {
        match self.set {
            RuleSet::Worksheet => NormalTransform::Modelview,
            RuleSet::OpenGl | RuleSet::PhongDemo => NormalTransform::InverseTranspose,
        }
    }

    /// Is the reflection vector formed with `max(N . L, 0)`, as the Phong demo's shaders
    /// write it (`R = 2 max(N.L, 0) N - L`), rather than with `N . L`?
    pub fn reflect_clamped(self) -> bool {
        self.set == RuleSet::PhongDemo
    }

    /// Does the infinite viewer follow the worksheet's code, `V = normalize(obs - P)` with
    /// `obs = P * (1, 1, 0, 1)`, i.e. `(0, 0, -sign(P.z))`? OpenGL's is (0, 0, 1) always; the
    /// worksheet's turns to (0, 0, -1) for a vertex behind the eye plane (z > 0, as under
    /// its mview2 and mview4).
    pub fn viewer_from_eye_plane(self) -> bool {
        self.set == RuleSet::Worksheet
    }

    /// Are vertex colours clamped to [0, 1] before they are interpolated? OpenGL's
    /// fixed-function pipeline clamps them; the Phong demo's colour is a shader varying,
    /// interpolated as it is (only the framebuffer clamps).
    pub fn clamps_vertex_colors(self) -> bool {
        self.set != RuleSet::PhongDemo
    }

    /// The rule set with the specular model it comes with (the Phong demo's Phong,
    /// Blinn-Phong for the others).
    pub fn of_set(set: RuleSet) -> Rules {
        match set {
            RuleSet::OpenGl => Rules::OPENGL,
            RuleSet::Worksheet => Rules::WORKSHEET,
            RuleSet::PhongDemo => Rules::PHONG_DEMO,
        }
    }

    /// Is the specular model the one the rule set comes with ([`Rules::of_set`])?
    pub fn specular_is_the_sets(self) -> bool {
        self == Rules::of_set(self.set)
    }

    /// Does the worked calculation stop at the sum I, as the worksheet's does (it never
    /// clamps, so the clamped colour is not a step of its own to ask)?
    pub fn stops_at_sum(self) -> bool {
        self.set == RuleSet::Worksheet
    }

    /// When the specular term is allowed.
    pub fn specular_gate(self) -> SpecularGate {
        match self.set {
            RuleSet::OpenGl => SpecularGate::LitSide,
            RuleSet::Worksheet => SpecularGate::PositiveCosine,
            RuleSet::PhongDemo => SpecularGate::None,
        }
    }
}

impl fmt::Display for Rules {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}, {}", self.set.label(), self.specular.label())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_specular_model_is_found_by_its_name_and_the_next_one_goes_round() {
        for m in SpecularModel::ALL {
            assert_eq!(SpecularModel::from_name(m.name()), Some(m));
        }
        assert_eq!(SpecularModel::from_name("blinn"), None);
        let mut m = SpecularModel::ALL[0];
        for _ in 0..SpecularModel::ALL.len() {
            m = m.next();
        }
        assert_eq!(m, SpecularModel::ALL[0]);
        assert_eq!(SpecularModel::BlinnPhong.next(), SpecularModel::Phong);
    }
}
