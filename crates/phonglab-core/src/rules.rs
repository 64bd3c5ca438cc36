//! Rule sets: OpenGL 2.1, the worksheet's, the Phong demo's — presets of one engine.
//!
//! A rule set changes which terms the equation has, never how a term is computed, so
//! all three run through the same code in [`crate::lighting`].

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
    pub fn label(self) -> &'static str {
        match self {
            RuleSet::OpenGl => "OpenGL 2.1",
            RuleSet::Worksheet => "Worksheet",
            RuleSet::PhongDemo => "Phong demo",
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
}

impl SpecularModel {
    /// Both models, in menu order.
    pub const ALL: [SpecularModel; 2] = [SpecularModel::BlinnPhong, SpecularModel::Phong];

    /// A short name for menus and files.
    pub fn label(self) -> &'static str {
        match self {
            SpecularModel::BlinnPhong => "Blinn-Phong (n.H)",
            SpecularModel::Phong => "Phong (R.V)",
        }
    }
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
