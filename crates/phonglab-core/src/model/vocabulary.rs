//! The worksheet's vocabulary, defined once: for each quantity of the lighting
//! calculation, the name the worksheet's Python gives it, what OpenGL calls it, its symbol
//! in the OpenGL specification (section 2.14.1, "Lighting") and the catalogue message that
//! labels it for people. The explanation, the quiz, the exercise sets (text and PDF), the
//! notebook writer and reader, the program exporters and the window all read this table,
//! so a name cannot drift between them.
//!
//! | quantity | worksheet | OpenGL | symbol |
//! |---|---|---|---|
//! | vertex position | `vertexPos` | `glVertex` | V |
//! | vertex normal | `vertexNormal` | `glNormal` | n |
//! | light position | `lightPos` | `GL_POSITION` | P_pli |
//! | light ambient, diffuse, specular | `Lamb`, `Ldif`, `Lspec` | `GL_AMBIENT`, `GL_DIFFUSE`, `GL_SPECULAR` | a_cli, d_cli, s_cli |
//! | attenuation | `atC`, `atLin`, `atQuad` | `GL_CONSTANT_ATTENUATION`, `GL_LINEAR_ATTENUATION`, `GL_QUADRATIC_ATTENUATION` | k_0i, k_1i, k_2i |
//! | spotlight | `lightSpotDir`, `spotCutoff`, `spotCoef` | `GL_SPOT_DIRECTION`, `GL_SPOT_CUTOFF`, `GL_SPOT_EXPONENT` | s_dli, c_rli, s_rli |
//! | material | `matAmb`, `matDif`, `matSpec`, `matEmi`, `matAlpha`, `ns` | `GL_AMBIENT`, `GL_DIFFUSE`, `GL_SPECULAR`, `GL_EMISSION`, the diffuse alpha, `GL_SHININESS` | a_cm, d_cm, s_cm, e_cm, alpha, s_rm |
//! | scene ambient | `sceneAmb` | `GL_LIGHT_MODEL_AMBIENT` | a_cs |
//! | modelview | `mview`, `lightMview` | `GL_MODELVIEW_MATRIX` | M |
//!
//! and the values the calculation finds, from `vov` (V) and `vlv` (L) to `glColor`. One of
//! them, `at`, names one quantity everywhere: the worksheet's `k0 + k1 d + k2 d²`, which
//! divides. OpenGL's `att_i` is its inverse; wherever that factor is shown it is `1/at`.

use crate::locale::tr;

/// A quantity of the lighting calculation: a given of the worksheet or a value it finds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Quantity {
    /// The vertex's position (object space; in eye space once transformed).
    VertexPos,
    /// The vertex's normal (object space; N once transformed).
    VertexNormal,
    /// The light's position (or direction, w = 0).
    LightPos,
    /// The light's ambient colour.
    LightAmbient,
    /// The light's diffuse colour.
    LightDiffuse,
    /// The light's specular colour.
    LightSpecular,
    /// The constant attenuation factor.
    AttConstant,
    /// The linear attenuation factor.
    AttLinear,
    /// The quadratic attenuation factor.
    AttQuadratic,
    /// The spotlight's direction.
    SpotDirection,
    /// The spotlight's cutoff angle, in degrees (180: not a spotlight).
    SpotCutoff,
    /// The spotlight's exponent.
    SpotExponent,
    /// The material's ambient reflectance.
    MatAmbient,
    /// The material's diffuse reflectance.
    MatDiffuse,
    /// The material's specular reflectance.
    MatSpecular,
    /// The material's emission.
    MatEmission,
    /// The material's alpha (its diffuse colour's).
    MatAlpha,
    /// The material's shininess (the specular exponent).
    Shininess,
    /// The light model's (scene's) ambient colour.
    SceneAmbient,
    /// The modelview matrix.
    Modelview,
    /// The modelview that was current when the light was placed.
    LightModelview,
    /// V, the unit vector from the vertex to the eye.
    V,
    /// L, the unit vector from the vertex to the light.
    L,
    /// The distance from the vertex to the light.
    Distance,
    /// The ambient term.
    Ambient,
    /// cos(θ) = N · L.
    CosTheta,
    /// The diffuse term.
    Diffuse,
    /// The halfway vector.
    H,
    /// cos(β) = N · H (Blinn-Phong).
    CosBeta,
    /// The reflection vector.
    R,
    /// cos(α) = R · V (Phong).
    CosAlpha,
    /// The specular term.
    Specular,
    /// The attenuation.
    Attenuation,
    /// The spotlight factor.
    Spot,
    /// One light's share of the colour.
    LightShare,
    /// The scene ambient's term.
    SceneAmbientTerm,
    /// The emission's term.
    EmissionTerm,
    /// The primary colour.
    Primary,
    /// The secondary colour.
    Secondary,
    /// The colour as drawn, clamped.
    Clamped,
}

/// How one quantity is named, in each of the four places names live.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Term {
    /// The worksheet's Python name (the notebook's variable, the exercise's line).
    pub worksheet: &'static str,
    /// OpenGL's name: the enum a program passes, or the expression the specification
    /// writes.
    pub gl: &'static str,
    /// The symbol: the specification's for a given, the worksheet's for a value found.
    pub symbol: &'static str,
    /// The catalogue message that labels it, where one does; else people read the symbol.
    pub message: Option<&'static str>,
}

const fn term(worksheet: &'static str, gl: &'static str, symbol: &'static str, message: &'static str) -> Term {
    Term { worksheet, gl, symbol, message: Some(message) }
}

impl Quantity {
    /// Every quantity: the givens in the worksheet's order, then the values found in the
    /// calculation's.
    pub const ALL: [Quantity; 40] = [
        Quantity::VertexPos,
        Quantity::VertexNormal,
        Quantity::LightPos,
        Quantity::LightAmbient,
        Quantity::LightDiffuse,
        Quantity::LightSpecular,
        Quantity::AttConstant,
        Quantity::AttLinear,
        Quantity::AttQuadratic,
        Quantity::SpotDirection,
        Quantity::SpotCutoff,
        Quantity::SpotExponent,
        Quantity::MatAmbient,
        Quantity::MatDiffuse,
        Quantity::MatSpecular,
        Quantity::Shininess,
        Quantity::Modelview,
        Quantity::LightModelview,
        Quantity::MatEmission,
        Quantity::MatAlpha,
        Quantity::SceneAmbient,
        Quantity::V,
        Quantity::L,
        Quantity::Distance,
        Quantity::Ambient,
        Quantity::CosTheta,
        Quantity::Diffuse,
        Quantity::H,
        Quantity::CosBeta,
        Quantity::R,
        Quantity::CosAlpha,
        Quantity::Specular,
        Quantity::Attenuation,
        Quantity::Spot,
        Quantity::LightShare,
        Quantity::SceneAmbientTerm,
        Quantity::EmissionTerm,
        Quantity::Primary,
        Quantity::Secondary,
        Quantity::Clamped,
    ];

    /// The givens: what the worksheet assigns before it computes.
    pub fn givens() -> impl Iterator<Item = Quantity> {
        Quantity::ALL.into_iter().take_while(|q| *q != Quantity::V)
    }

    /// The givens a material has once per side (`matDifBack`, ... for the back).
    pub const MATERIAL: [Quantity; 6] = [
        Quantity::MatAmbient,
        Quantity::MatDiffuse,
        Quantity::MatSpecular,
        Quantity::Shininess,
        Quantity::MatEmission,
        Quantity::MatAlpha,
    ];

    /// How this quantity is named.
    pub fn term(self) -> Term {
        use Quantity::{
            Ambient, AttConstant, AttLinear, AttQuadratic, Attenuation, Clamped, CosAlpha, CosBeta, CosTheta, Diffuse,
            Distance, EmissionTerm, H, L, LightAmbient, LightDiffuse, LightModelview, LightPos, LightShare,
            LightSpecular, MatAlpha, MatAmbient, MatDiffuse, MatEmission, MatSpecular, Modelview, Primary, R,
            SceneAmbient, SceneAmbientTerm, Secondary, Shininess, Specular, Spot, SpotCutoff, SpotDirection,
            SpotExponent, V, VertexNormal, VertexPos,
        };
        match self {
            VertexPos => term("vertexPos", "glVertex", "V", "quantity-vertex-position"),
            VertexNormal => term("vertexNormal", "glNormal", "n", "quantity-vertex-normal"),
            LightPos => term("lightPos", "GL_POSITION", "P_pli", "quantity-light-position"),
            LightAmbient => term("Lamb", "GL_AMBIENT", "a_cli", "light-ambient"),
            LightDiffuse => term("Ldif", "GL_DIFFUSE", "d_cli", "light-diffuse"),
            LightSpecular => term("Lspec", "GL_SPECULAR", "s_cli", "light-specular"),
            AttConstant => term("atC", "GL_CONSTANT_ATTENUATION", "k_0i", "attenuation-constant"),
            AttLinear => term("atLin", "GL_LINEAR_ATTENUATION", "k_1i", "attenuation-linear"),
            AttQuadratic => term("atQuad", "GL_QUADRATIC_ATTENUATION", "k_2i", "attenuation-quadratic"),
            SpotDirection => term("lightSpotDir", "GL_SPOT_DIRECTION", "s_dli", "spot-direction"),
            SpotCutoff => term("spotCutoff", "GL_SPOT_CUTOFF", "c_rli", "spot-cutoff"),
            SpotExponent => term("spotCoef", "GL_SPOT_EXPONENT", "s_rli", "spot-exponent"),
            MatAmbient => term("matAmb", "GL_AMBIENT", "a_cm", "material-ambient"),
            MatDiffuse => term("matDif", "GL_DIFFUSE", "d_cm", "material-diffuse"),
            MatSpecular => term("matSpec", "GL_SPECULAR", "s_cm", "material-specular"),
            MatEmission => term("matEmi", "GL_EMISSION", "e_cm", "material-emission"),
            MatAlpha => term("matAlpha", "GL_DIFFUSE", "alpha", "quantity-material-alpha"),
            Shininess => term("ns", "GL_SHININESS", "s_rm", "material-shininess"),
            SceneAmbient => term("sceneAmb", "GL_LIGHT_MODEL_AMBIENT", "a_cs", "scene-ambient"),
            Modelview => term("mview", "GL_MODELVIEW_MATRIX", "M", "quantity-modelview"),
            LightModelview => term("lightMview", "GL_MODELVIEW_MATRIX", "M", "quantity-light-modelview"),
            V => term("vov", "normalize(-P)", "V", "step-v"),
            L => term("vlv", "normalize(P_pli - P)", "L", "step-l"),
            Distance => term("d", "||P_pli - P||", "d", "step-distance"),
            Ambient => term("Iamb", "a_cli a_cm", "Iamb", "step-ambient"),
            CosTheta => Term { worksheet: "cosTheta", gl: "n · L", symbol: "cos(θ)", message: None },
            Diffuse => term("Idif", "(n · L) d_cli d_cm", "Idif", "step-diffuse"),
            H => term("H", "normalize(L + V)", "H", "step-h"),
            CosBeta => Term { worksheet: "cosBeta", gl: "n · h", symbol: "cos(β)", message: None },
            R => term("R", "2 (n · L) n - L", "R", "step-r"),
            CosAlpha => Term { worksheet: "cosAlpha", gl: "R · V", symbol: "cos(α)", message: None },
            Specular => term("Ispec", "(n · h)^s_rm s_cli s_cm", "Ispec", "step-specular"),
            // The worksheet's `at` divides; OpenGL's att_i is its inverse, shown as 1/at.
            Attenuation => term("at", "k_0i + k_1i d + k_2i d²", "at", "step-attenuation"),
            Spot => term("spot", "(-L · s_dli)^s_rli", "spot", "step-spot"),
            LightShare => term("Ilight", "spot_i (ambient + diffuse + specular) / at", "Ilight", "step-share"),
            SceneAmbientTerm => term("Iscene", "a_cm a_cs", "Iscene", "step-scene-ambient"),
            EmissionTerm => term("Iemi", "e_cm", "Iemi", "step-emission"),
            Primary => term("I", "c_pri", "I", "step-primary"),
            Secondary => term("Isec", "c_sec", "Isec", "step-secondary"),
            Clamped => term("glColor", "clamp(c, 0, 1)", "glColor", "step-clamped"),
        }
    }

    /// The worksheet's name.
    pub fn name(self) -> &'static str {
        self.term().worksheet
    }

    /// The worksheet's name for the back side's value (`matDifBack`).
    pub fn back_name(self) -> String {
        format!("{}Back", self.name())
    }

    /// The label people read, in their language: the catalogue's, or the symbol.
    pub fn label(self) -> String {
        match self.term().message {
            Some(id) => tr(id),
            None => self.term().symbol.to_string(),
        }
    }

    /// The quantity the worksheet calls `name`, if any.
    pub fn named(name: &str) -> Option<Quantity> {
        Quantity::ALL.into_iter().find(|q| q.name() == name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_quantity_is_listed_once_and_named_once() {
        let mut names: Vec<&str> = Quantity::ALL.iter().map(|q| q.name()).collect();
        names.sort_unstable();
        let n = names.len();
        names.dedup();
        assert_eq!(names.len(), n, "a worksheet name given to two quantities");
        for q in Quantity::ALL {
            assert_eq!(Quantity::named(q.name()), Some(q));
        }
        assert_eq!(Quantity::givens().count(), 21);
        assert_eq!(Quantity::named("spotCoef"), Some(Quantity::SpotExponent));
        assert_eq!(Quantity::SpotExponent.term().gl, "GL_SPOT_EXPONENT");
        assert_eq!(Quantity::MatDiffuse.back_name(), "matDifBack");
    }

    /// `at` is one quantity: the sum that divides, never the factor that multiplies.
    #[test]
    fn at_is_the_sum_that_divides() {
        let at = Quantity::Attenuation.term();
        assert_eq!((at.worksheet, at.symbol, at.gl), ("at", "at", "k_0i + k_1i d + k_2i d²"));
        assert!(Quantity::LightShare.term().gl.ends_with("/ at"));
        for q in Quantity::ALL {
            assert!(!q.term().gl.contains("1 / (k"), "{q:?}: {}", q.term().gl);
        }
    }

    #[test]
    fn every_label_is_in_every_language() {
        for lang in crate::locale::Lang::ALL {
            for q in Quantity::ALL {
                if let Some(id) = q.term().message {
                    assert!(crate::locale::has_message(lang, id), "{} lacks {id}", lang.code());
                }
            }
        }
    }
}
