//! The catalogue of mistakes: each a change to one stage of the worked calculation (its
//! formula, as the student wrote it), with an id (kebab-case, the same in `check --json`,
//! the class report and the docs) and words in the user's language. A cause is named only
//! when the key worked with that mistake reproduces everything the student printed.

use crate::t;

/// One mistake, as the worked calculation makes it ([`super::worked::work`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mistake {
    /// The normal by M where the rules take the inverse transpose (wrong under a
    /// non-uniform scale).
    NormalByModelview,
    /// The normal by the inverse transpose of the whole 4x4 modelview: its translation
    /// gives the normal a w that enters its length.
    NormalMatrixWithTranslation,
    /// The normal left as typed (not transformed at all).
    NormalNotTransformed,
    /// The normal typed with a w of 1, so the modelview's translation moves it.
    NormalAsPoint,
    /// The normal by the inverse of the modelview's 3x3, not its transpose.
    NormalMatrixNotTransposed,
    /// `np.matmul(v, mview)`: points (and, written the first way, the normal) multiplied
    /// as row vectors, so by the transposed modelview.
    RowVectors,
    /// The normal not normalised after its transform.
    NormalNotNormalised,
    /// The vertex left in object space.
    VertexNotTransformed,
    /// The light's position left in object space.
    LightNotTransformed,
    /// The light's position transformed by the modelview twice.
    LightTransformedTwice,
    /// The vectors cell run twice: the normal, the vertex and the light transformed by
    /// the modelview twice each (a notebook's cell run again, not a formula).
    VectorsCellRunTwice,
    /// The light transformed by the vertex's modelview `mview` instead of the one current
    /// when it was placed (an eye-fixed light moved with the camera).
    LightByMview,
    /// `vlv = P - L`: from the light to the vertex.
    VlvReversed,
    /// `vlv` not normalised.
    VlvNotNormalised,
    /// A directional light (w = 0) treated as a point at its direction.
    DirectionalAsPoint,
    /// A positional light treated as directional: `vlv` its position's direction.
    PointAsDirectional,
    /// The local and the infinite viewer swapped.
    ViewerSwapped,
    /// `vov` from the eye to the vertex (the local viewer's vector reversed).
    ViewerReversed,
    /// `vov = -vertexPos` normalised with its w of -1 in the length.
    ViewerWithW,
    /// `H = vlv + vov`, not normalised.
    HalfwayNotNormalised,
    /// Phong's `R . V` where the rules take Blinn-Phong's `N . H` (written the second
    /// way: `H` itself set to R).
    ReflectionForHalfway,
    /// `H = vlv - vov`.
    HalfwayWithViewReversed,
    /// `R = L - 2 (N . L) N`: the reflection with its sign reversed.
    ReflectionReversed,
    /// `cosTheta` taken with the light's position instead of `vlv`.
    CosThetaWithLightPosition,
    /// Specular where `N . L <= 0` (OpenGL's gate left out).
    SpecularWithoutGate,
    /// The worksheet's angle test on beta in radians compared with 90 (degrees): it
    /// never cuts the specular off.
    SpecularTestInDegrees,
    /// The specular also multiplied by `N . L`.
    SpecularTimesCosine,
    /// The shininess as a factor (`cosBeta*ns`) instead of a power.
    ShininessAsProduct,
    /// The specular's power taken of the diffuse cosine (`cosTheta**ns`).
    SpecularOfDiffuseCosine,
    /// The specular cosine not clamped at 0 before the power.
    SpecularCosineNotClamped,
    /// The diffuse term not clamped: negative past 90 degrees.
    DiffuseNotClamped,
    /// The angle in degrees compared with `pi/2` (radians): the diffuse zeroed past 1.57
    /// degrees.
    ThetaInDegrees,
    /// The diffuse scaled by the angle theta (radians) instead of its cosine.
    DiffuseAngleNotCosine,
    /// The specular's power taken of the angle beta (radians) instead of its cosine.
    SpecularAngleNotCosine,
    /// The ambient term scaled by `N . L` like the diffuse.
    AmbientTimesCosine,
    /// One of a term's two colours taken from another term, or left out
    /// ([`ColourSwap`]).
    ColoursMixedUp,
    /// The spot cutoff's cosine taken of degrees as if they were radians.
    SpotCutoffRadians,
    /// The spot's cosine compared with the cutoff in degrees itself.
    SpotCutoffNotCosine,
    /// The cutoff taken as the cone's full angle: half of it used.
    SpotCutoffHalved,
    /// The spot factor not applied to the light's ambient term.
    SpotNotOnAmbient,
    /// The spot factor on the diffuse term alone.
    SpotOnDiffuseOnly,
    /// The spot exponent applied outside the cone too (no cone test).
    SpotExponentOutsideCone,
    /// The spot exponent left out: the spot factor is the cosine itself.
    SpotExponentIgnored,
    /// The spot exponent as a factor (`cosSpot*spotCoef`) instead of a power.
    SpotExponentAsFactor,
    /// The cone test the wrong way round: lit outside the cone, dark inside.
    ConeTestInverted,
    /// The spot's angle measured with `vlv` (towards the light), not `-vlv`.
    SpotAngleReversed,
    /// The spot direction left in object space.
    SpotDirectionUntransformed,
    /// The spot factor not applied to the light's share.
    SpotLeftOut,
    /// The spot factor applied to the whole colour (emission and scene ambient too).
    SpotOnWholeColour,
    /// The share multiplied by the attenuation instead of divided.
    AttenuationMultiplied,
    /// The share not divided by the attenuation.
    AttenuationLeftOut,
    /// The light's ambient not divided by the attenuation (only diffuse and specular).
    AmbientNotAttenuated,
    /// The light's ambient outside both the spot factor and the attenuation.
    AmbientOutsideShare,
    /// The attenuation dividing the whole colour (emission and scene ambient too).
    AttenuationOnWholeColour,
    /// A directional light attenuated (OpenGL's attenuation is 1 for w = 0).
    AttenuationOnDirectional,
    /// The constant attenuation term left out.
    AttenuationConstantLeftOut,
    /// The quadratic term with `d` instead of `d*d`.
    AttenuationQuadraticNotSquared,
    /// The linear and the quadratic coefficients swapped: `atLin*d*d + atQuad*d`.
    AttenuationTermsSwapped,
    /// `at = 1/(atC + atLin*d + atQuad*d*d)`, then divided by: the attenuation inverted.
    AttenuationInverted,
    /// The light's distance measured in object space.
    AttenuationObjectDistance,
    /// The distance from the light's position not divided by its w (while `vlv` is).
    DistanceWithoutWDivide,
    /// The distance taken from the normalised `vlv` (so 1).
    DistanceFromNormalisedVlv,
    /// The distance squared (no square root).
    DistanceSquared,
    /// The light's ambient left out of its share.
    LightAmbientLeftOut,
    /// The specular left out of the light's share.
    SpecularLeftOut,
    /// A light's share left out of the sum.
    LightLeftOut,
    /// Only the last light's share in the sum (the loop's variable used after the loop).
    OnlyLastLight,
    /// The scene's ambient left out of the sum.
    SceneAmbientLeftOut,
    /// The scene's ambient not multiplied by the material's ambient.
    SceneAmbientWithoutMaterial,
    /// The scene's ambient also multiplied by the (first) light's ambient.
    SceneAmbientTimesLight,
    /// The scene's ambient multiplied by the material's diffuse (first way) or specular
    /// colour instead of its ambient.
    SceneAmbientWrongMaterial,
    /// The emission added twice.
    EmissionTwice,
    /// The emission left out of the sum.
    EmissionLeftOut,
    /// The colour's alpha taken from the sum's fourth component (0) instead of the
    /// material's diffuse alpha.
    AlphaFromSum,
    /// The colour not clamped to [0, 1].
    ColourNotClamped,
    /// The division by w forgotten.
    WDivideForgotten,
    /// Shininess as the 0-1 fraction (`0.4`) instead of `0.4*128`.
    ShininessFraction,
}

impl Mistake {
    /// Is this a mistake under `rules`? One that changes nothing those rules do (no N·L
    /// gate to leave out, the normal transformed by M already) is not offered as a cause.
    pub fn applies(self, rules: crate::model::rules::Rules) -> bool {
        use crate::model::rules::{NormalTransform, SpecularGate, SpecularVector};
        match self {
            Mistake::SpecularWithoutGate => rules.specular_gate() == SpecularGate::LitSide,
            Mistake::SpecularTestInDegrees => rules.specular_gate() == SpecularGate::PositiveCosine,
            Mistake::NormalByModelview => rules.normal_transform() == NormalTransform::InverseTranspose,
            Mistake::ReflectionForHalfway => rules.specular.vector() == SpecularVector::Halfway,
            Mistake::ReflectionReversed => rules.specular.vector() == SpecularVector::Reflection,
            _ => true,
        }
    }

    /// Can the mistake be made for one light alone (each light's values are its own)?
    pub fn per_light(self) -> bool {
        !matches!(
            self,
            Mistake::NormalByModelview
                | Mistake::NormalMatrixWithTranslation
                | Mistake::NormalNotTransformed
                | Mistake::NormalAsPoint
                | Mistake::AttenuationOnWholeColour
                | Mistake::NormalMatrixNotTransposed
                | Mistake::VectorsCellRunTwice
                | Mistake::RowVectors
                | Mistake::OnlyLastLight
                | Mistake::EmissionLeftOut
                | Mistake::AlphaFromSum
                | Mistake::NormalNotNormalised
                | Mistake::VertexNotTransformed
                | Mistake::ViewerSwapped
                | Mistake::ViewerReversed
                | Mistake::ViewerWithW
                | Mistake::SceneAmbientWrongMaterial
                | Mistake::SceneAmbientTimesLight
                | Mistake::SpotOnWholeColour
                | Mistake::SceneAmbientLeftOut
                | Mistake::SceneAmbientWithoutMaterial
                | Mistake::EmissionTwice
                | Mistake::ColourNotClamped
                | Mistake::WDivideForgotten
                | Mistake::ShininessFraction
        )
    }
}

/// One of the three terms a light and a material each give a colour to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Term {
    /// `Lamb`, `matAmb`.
    Ambient,
    /// `Ldif`, `matDif`.
    Diffuse,
    /// `Lspec`, `matSpec`.
    Specular,
}

impl Term {
    /// The three, in the worksheet's order.
    pub const ALL: [Term; 3] = [Term::Ambient, Term::Diffuse, Term::Specular];

    /// The light's colour's name in the notebook.
    pub fn light_name(self) -> &'static str {
        match self {
            Term::Ambient => "Lamb",
            Term::Diffuse => "Ldif",
            Term::Specular => "Lspec",
        }
    }

    /// The material's colour's name in the notebook.
    pub fn material_name(self) -> &'static str {
        match self {
            Term::Ambient => "matAmb",
            Term::Diffuse => "matDif",
            Term::Specular => "matSpec",
        }
    }

    /// The term's value's name in the notebook.
    pub fn value_name(self) -> &'static str {
        match self {
            Term::Ambient => "Iamb",
            Term::Diffuse => "Idif",
            Term::Specular => "Ispec",
        }
    }
}

/// [`Mistake::ColoursMixedUp`]: in `term`, the light's (`light`) or the material's colour
/// is taken from the term `from`, or left out (`None`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ColourSwap {
    /// The term computed with the wrong colour.
    pub term: Term,
    /// The light's colour (`true`) or the material's (`false`).
    pub light: bool,
    /// The term whose colour was taken instead; `None`: the colour left out.
    pub from: Option<Term>,
    /// The two terms' colours exchanged: `from` takes `term`'s too.
    pub exchanged: bool,
}

impl ColourSwap {
    /// Every swap: each term, each of its two colours, taken from each other term or left
    /// out.
    pub fn all() -> Vec<ColourSwap> {
        let mut out = Vec::new();
        for term in Term::ALL {
            for light in [true, false] {
                for from in Term::ALL.into_iter().filter(|&f| f != term).map(Some).chain([None]) {
                    out.push(ColourSwap { term, light, from, exchanged: false });
                }
                for from in Term::ALL.into_iter().filter(|&f| f > term) {
                    out.push(ColourSwap { term, light, from: Some(from), exchanged: true });
                }
            }
        }
        out
    }

    /// The product as the student wrote it: `Lspec*matDif`; `index` follows a light's
    /// colour (`[2]`, or empty for the one light).
    pub fn product(self, index: &str) -> String {
        let (light, material) = (self.term.light_name(), self.term.material_name());
        match (self.light, self.from) {
            (true, Some(from)) => format!("{}{index}*{material}", from.light_name()),
            (true, None) => material.to_string(),
            (false, Some(from)) => format!("{light}{index}*{}", from.material_name()),
            (false, None) => format!("{light}{index}"),
        }
    }
}

/// A mistake as made: for every light or one light alone, and which colours are mixed up
/// ([`Mistake::ColoursMixedUp`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Made {
    /// The mistake.
    pub mistake: Mistake,
    /// The one light it is made for (`None`: all lights).
    pub light: Option<usize>,
    /// The colours mixed up.
    pub swap: Option<ColourSwap>,
    /// Which way the mistake is written (0: the first; R·V for N·H: 1 `H = R` with
    /// `cosBeta = vov . H`, 2 `H = R` with `cosBeta = N . H`; row vectors: 1 the normal
    /// left alone).
    pub way: u8,
}

impl Made {
    /// `mistake` made for every light.
    pub fn everywhere(mistake: Mistake) -> Made {
        Made { mistake, light: None, swap: None, way: 0 }
    }

    /// Every way `mistake` can be made in a scene of `lights` lights: for all lights, then
    /// (of several) for each alone; each colour swap.
    pub fn instances(mistake: Mistake, lights: usize) -> Vec<Made> {
        let one_light_only = matches!(mistake, Mistake::SpotOnWholeColour | Mistake::AttenuationOnWholeColour);
        if one_light_only && lights != 1 || mistake == Mistake::OnlyLastLight && lights < 2 {
            return Vec::new();
        }
        let ways: &[u8] = match mistake {
            Mistake::ReflectionForHalfway => &[0, 1, 2],
            Mistake::RowVectors | Mistake::SceneAmbientWrongMaterial => &[0, 1],
            _ => &[0],
        };
        let mut at: Vec<Option<usize>> = vec![None];
        if mistake.per_light() && lights > 1 {
            at.extend((0..lights).map(Some));
        }
        let swaps: Vec<Option<ColourSwap>> = if mistake == Mistake::ColoursMixedUp {
            ColourSwap::all().into_iter().map(Some).collect()
        } else {
            vec![None]
        };
        let mut out = Vec::new();
        for &way in ways {
            for &swap in &swaps {
                for &light in &at {
                    out.push(Made { mistake, light, swap, way });
                }
            }
        }
        out
    }
}

/// A mistake of the catalogue: its id, its formula as the student wrote it, its words.
#[derive(Clone, Copy, Debug)]
pub struct MistakeInfo {
    /// The id: kebab-case, stable (`vlv-reversed`).
    pub id: &'static str,
    /// The mistake the calculation makes; `None` for one read off an error the run
    /// stopped with rather than computed.
    pub mistake: Option<Mistake>,
    /// What the student wrote, as code (no words: those are in [`Self::words`], in the
    /// user's language).
    pub formula: &'static str,
    /// What it means, in the user's language.
    pub words: fn() -> String,
}

/// The id of the cause read off an error rather than a value: `acos` of a cosine past 1.
pub const ACOS_PAST_ONE: &str = "acos-past-one";

/// The catalogue, in the worksheet's order.
pub const CATALOGUE: [MistakeInfo; 78] = [
    MistakeInfo {
        id: "normal-by-modelview",
        mistake: Some(Mistake::NormalByModelview),
        formula: "vertexNormal = np.matmul(mview, vertexNormal)",
        words: || t!("check-cause-normal-by-modelview"),
    },
    MistakeInfo {
        id: "normal-matrix-with-translation",
        mistake: Some(Mistake::NormalMatrixWithTranslation),
        formula: "normalMatrix = np.linalg.inv(mview).T  # 4x4",
        words: || t!("check-cause-normal-matrix-with-translation"),
    },
    MistakeInfo {
        id: "normal-not-transformed",
        mistake: Some(Mistake::NormalNotTransformed),
        formula: "# vertexNormal = np.matmul(normalMatrix, vertexNormal)",
        words: || t!("check-cause-normal-not-transformed"),
    },
    MistakeInfo {
        id: "normal-as-point",
        mistake: Some(Mistake::NormalAsPoint),
        formula: "vertexNormal = np.array([0, 0, 1, 1])",
        words: || t!("check-cause-normal-as-point"),
    },
    MistakeInfo {
        id: "normal-matrix-not-transposed",
        mistake: Some(Mistake::NormalMatrixNotTransposed),
        formula: "normalMatrix = np.linalg.inv(mview[:3, :3])",
        words: || t!("check-cause-normal-matrix-not-transposed"),
    },
    MistakeInfo {
        id: "row-vectors",
        mistake: Some(Mistake::RowVectors),
        formula: "vertexPos = np.matmul(vertexPos, mview)",
        words: || t!("check-cause-row-vectors"),
    },
    MistakeInfo {
        id: "normal-not-normalised",
        mistake: Some(Mistake::NormalNotNormalised),
        formula: "# vertexNormal = vertexNormal/np.linalg.norm(vertexNormal)",
        words: || t!("check-cause-normal-not-normalised"),
    },
    MistakeInfo {
        id: "vertex-not-transformed",
        mistake: Some(Mistake::VertexNotTransformed),
        formula: "# vertexPos = np.matmul(mview, vertexPos)",
        words: || t!("check-cause-vertex-not-transformed"),
    },
    MistakeInfo {
        id: "light-not-transformed",
        mistake: Some(Mistake::LightNotTransformed),
        formula: "# lightPos = np.matmul(mview, lightPos)",
        words: || t!("check-cause-light-not-transformed"),
    },
    MistakeInfo {
        id: "light-transformed-twice",
        mistake: Some(Mistake::LightTransformedTwice),
        formula: "lightPos = np.matmul(mview, np.matmul(mview, lightPos))",
        words: || t!("check-cause-light-transformed-twice"),
    },
    MistakeInfo {
        id: "vectors-cell-run-twice",
        mistake: Some(Mistake::VectorsCellRunTwice),
        formula: "vertexNormal = np.matmul(mview, np.matmul(mview, vertexNormal))  # vertexPos, lightPos",
        words: || t!("check-cause-vectors-cell-run-twice"),
    },
    MistakeInfo {
        id: "light-by-mview",
        mistake: Some(Mistake::LightByMview),
        formula: "lightPos = np.matmul(mview, lightPos)  # lightMview",
        words: || t!("check-cause-light-by-mview"),
    },
    MistakeInfo {
        id: "vlv-reversed",
        mistake: Some(Mistake::VlvReversed),
        formula: "vlv = vertexPos - lightPos",
        words: || t!("check-cause-vlv-reversed"),
    },
    MistakeInfo {
        id: "vlv-not-normalised",
        mistake: Some(Mistake::VlvNotNormalised),
        formula: "# vlv = vlv/np.linalg.norm(vlv)",
        words: || t!("check-cause-vlv-not-normalised"),
    },
    MistakeInfo {
        id: "directional-as-point",
        mistake: Some(Mistake::DirectionalAsPoint),
        formula: "vlv = lightPos - vertexPos  # lightPos[3] == 0",
        words: || t!("check-cause-directional-as-point"),
    },
    MistakeInfo {
        id: "point-as-directional",
        mistake: Some(Mistake::PointAsDirectional),
        formula: "vlv = lightPos  # lightPos[3] != 0",
        words: || t!("check-cause-point-as-directional"),
    },
    MistakeInfo {
        id: "viewer-swapped",
        mistake: Some(Mistake::ViewerSwapped),
        formula: "obs = np.array([0, 0, 0, 1])  # <-> obs = vertexPos*np.array([1, 1, 0, 1])",
        words: || t!("check-cause-viewer-swapped"),
    },
    MistakeInfo {
        id: "viewer-reversed",
        mistake: Some(Mistake::ViewerReversed),
        formula: "vov = vertexPos - obs",
        words: || t!("check-cause-viewer-reversed"),
    },
    MistakeInfo {
        id: "vov-with-w",
        mistake: Some(Mistake::ViewerWithW),
        formula: "vov = -vertexPos",
        words: || t!("check-cause-vov-with-w"),
    },
    MistakeInfo {
        id: "light-ambient-left-out",
        mistake: Some(Mistake::LightAmbientLeftOut),
        formula: "Ilight = spot*(Idif + Ispec)/at",
        words: || t!("check-cause-light-ambient-left-out"),
    },
    MistakeInfo {
        id: "ambient-times-cosine",
        mistake: Some(Mistake::AmbientTimesCosine),
        formula: "Iamb = (Lamb*matAmb)*cosTheta",
        words: || t!("check-cause-ambient-times-cosine"),
    },
    MistakeInfo {
        id: "colours-mixed-up",
        mistake: Some(Mistake::ColoursMixedUp),
        formula: "Idif = (Lspec*matDif)*cosTheta",
        words: || t!("check-cause-colours-mixed-up"),
    },
    MistakeInfo {
        id: "cos-theta-with-light-position",
        mistake: Some(Mistake::CosThetaWithLightPosition),
        formula: "cosTheta = np.dot(vertexNormal, lightPos)",
        words: || t!("check-cause-cos-theta-with-light-position"),
    },
    MistakeInfo {
        id: "diffuse-not-clamped",
        mistake: Some(Mistake::DiffuseNotClamped),
        formula: "Idif = (Ldif*matDif)*cosTheta",
        words: || t!("check-cause-diffuse-not-clamped"),
    },
    MistakeInfo {
        id: "theta-in-degrees",
        mistake: Some(Mistake::ThetaInDegrees),
        formula: "theta = m.degrees(m.acos(cosTheta)); theta > m.pi*0.5",
        words: || t!("check-cause-theta-in-degrees"),
    },
    MistakeInfo {
        id: "diffuse-angle-not-cosine",
        mistake: Some(Mistake::DiffuseAngleNotCosine),
        formula: "Idif = (Ldif*matDif)*theta",
        words: || t!("check-cause-diffuse-angle-not-cosine"),
    },
    MistakeInfo {
        id: ACOS_PAST_ONE,
        mistake: None,
        formula: "theta = m.acos(cosTheta)  # cosTheta = 1.0000000000000002",
        words: || t!("check-cause-acos-past-one"),
    },
    MistakeInfo {
        id: "halfway-not-normalised",
        mistake: Some(Mistake::HalfwayNotNormalised),
        formula: "H = vlv + vov",
        words: || t!("check-cause-halfway-not-normalised"),
    },
    MistakeInfo {
        id: "halfway-with-view-reversed",
        mistake: Some(Mistake::HalfwayWithViewReversed),
        formula: "H = (vlv - vov)",
        words: || t!("check-cause-halfway-with-view-reversed"),
    },
    MistakeInfo {
        id: "reflection-for-halfway",
        mistake: Some(Mistake::ReflectionForHalfway),
        formula: "cosBeta = np.dot(2*cosTheta*vertexNormal - vlv, vov)",
        words: || t!("check-cause-reflection-for-halfway"),
    },
    MistakeInfo {
        id: "reflection-reversed",
        mistake: Some(Mistake::ReflectionReversed),
        formula: "R = vlv - 2*cosTheta*vertexNormal",
        words: || t!("check-cause-reflection-reversed"),
    },
    MistakeInfo {
        id: "specular-without-gate",
        mistake: Some(Mistake::SpecularWithoutGate),
        formula: "Ispec = (Lspec*matSpec)*(max(cosBeta, 0)**ns)",
        words: || t!("check-cause-specular-without-gate"),
    },
    MistakeInfo {
        id: "specular-test-in-degrees",
        mistake: Some(Mistake::SpecularTestInDegrees),
        formula: "if (beta > 90 or beta < 0):",
        words: || t!("check-cause-specular-test-in-degrees"),
    },
    MistakeInfo {
        id: "specular-times-cosine",
        mistake: Some(Mistake::SpecularTimesCosine),
        formula: "Ispec = (Lspec*matSpec)*(cosBeta**ns)*cosTheta",
        words: || t!("check-cause-specular-times-cosine"),
    },
    MistakeInfo {
        id: "specular-cosine-not-clamped",
        mistake: Some(Mistake::SpecularCosineNotClamped),
        formula: "Ispec = (Lspec*matSpec)*(cosBeta**ns)",
        words: || t!("check-cause-specular-cosine-not-clamped"),
    },
    MistakeInfo {
        id: "specular-angle-not-cosine",
        mistake: Some(Mistake::SpecularAngleNotCosine),
        formula: "Ispec = (Lspec*matSpec)*(beta**ns)",
        words: || t!("check-cause-specular-angle-not-cosine"),
    },
    MistakeInfo {
        id: "specular-left-out",
        mistake: Some(Mistake::SpecularLeftOut),
        formula: "Ilight = spot*(Iamb + Idif)/at",
        words: || t!("check-cause-specular-left-out"),
    },
    MistakeInfo {
        id: "shininess-fraction",
        mistake: Some(Mistake::ShininessFraction),
        formula: "ns = 0.2",
        words: || t!("check-cause-shininess-fraction"),
    },
    MistakeInfo {
        id: "shininess-as-product",
        mistake: Some(Mistake::ShininessAsProduct),
        formula: "Ispec = (Lspec*matSpec)*(cosBeta*ns)",
        words: || t!("check-cause-shininess-as-product"),
    },
    MistakeInfo {
        id: "specular-of-diffuse-cosine",
        mistake: Some(Mistake::SpecularOfDiffuseCosine),
        formula: "Ispec = (Lspec*matSpec)*(cosTheta**ns)",
        words: || t!("check-cause-specular-of-diffuse-cosine"),
    },
    MistakeInfo {
        id: "attenuation-multiplied",
        mistake: Some(Mistake::AttenuationMultiplied),
        formula: "I = (Iamb + Idif + Ispec)*at",
        words: || t!("check-cause-attenuation-multiplied"),
    },
    MistakeInfo {
        id: "attenuation-left-out",
        mistake: Some(Mistake::AttenuationLeftOut),
        formula: "Ilight = spot*(Iamb + Idif + Ispec)",
        words: || t!("check-cause-attenuation-left-out"),
    },
    MistakeInfo {
        id: "ambient-not-attenuated",
        mistake: Some(Mistake::AmbientNotAttenuated),
        formula: "Ilight = spot*(Iamb + (Idif + Ispec)/at)",
        words: || t!("check-cause-ambient-not-attenuated"),
    },
    MistakeInfo {
        id: "ambient-outside-share",
        mistake: Some(Mistake::AmbientOutsideShare),
        formula: "Ilight = Iamb + spot*(Idif + Ispec)/at",
        words: || t!("check-cause-ambient-outside-share"),
    },
    MistakeInfo {
        id: "attenuation-on-whole-colour",
        mistake: Some(Mistake::AttenuationOnWholeColour),
        formula: "I = (Iemi + Iscene + Ilight)/at",
        words: || t!("check-cause-attenuation-on-whole-colour"),
    },
    MistakeInfo {
        id: "attenuation-on-directional",
        mistake: Some(Mistake::AttenuationOnDirectional),
        formula: "at = atC + atLin*d + atQuad*d*d  # lightPos[3] == 0",
        words: || t!("check-cause-attenuation-on-directional"),
    },
    MistakeInfo {
        id: "attenuation-constant-left-out",
        mistake: Some(Mistake::AttenuationConstantLeftOut),
        formula: "at = atLin*d + atQuad*d*d",
        words: || t!("check-cause-attenuation-constant-left-out"),
    },
    MistakeInfo {
        id: "attenuation-quadratic-not-squared",
        mistake: Some(Mistake::AttenuationQuadraticNotSquared),
        formula: "at = atC + atLin*d + atQuad*d",
        words: || t!("check-cause-attenuation-quadratic-not-squared"),
    },
    MistakeInfo {
        id: "attenuation-terms-swapped",
        mistake: Some(Mistake::AttenuationTermsSwapped),
        formula: "at = atC + atLin*d*d + atQuad*d",
        words: || t!("check-cause-attenuation-terms-swapped"),
    },
    MistakeInfo {
        id: "attenuation-inverted",
        mistake: Some(Mistake::AttenuationInverted),
        formula: "at = 1/(atC + atLin*d + atQuad*d*d)",
        words: || t!("check-cause-attenuation-inverted"),
    },
    MistakeInfo {
        id: "attenuation-object-distance",
        mistake: Some(Mistake::AttenuationObjectDistance),
        formula: "d = np.linalg.norm(lightPosObject - vertexPosObject)",
        words: || t!("check-cause-attenuation-object-distance"),
    },
    MistakeInfo {
        id: "distance-without-w-divide",
        mistake: Some(Mistake::DistanceWithoutWDivide),
        formula: "d = np.linalg.norm(lightPos - vertexPos)  # lightPos[3] != 1",
        words: || t!("check-cause-distance-without-w-divide"),
    },
    MistakeInfo {
        id: "distance-from-normalised-vlv",
        mistake: Some(Mistake::DistanceFromNormalisedVlv),
        formula: "d = np.linalg.norm(vlv)",
        words: || t!("check-cause-distance-from-normalised-vlv"),
    },
    MistakeInfo {
        id: "distance-squared",
        mistake: Some(Mistake::DistanceSquared),
        formula: "d = np.sum((lightPos - vertexPos)**2)",
        words: || t!("check-cause-distance-squared"),
    },
    MistakeInfo {
        id: "spot-cutoff-radians",
        mistake: Some(Mistake::SpotCutoffRadians),
        formula: "cosSpot >= m.cos(spotCutoff)",
        words: || t!("check-cause-spot-cutoff-radians"),
    },
    MistakeInfo {
        id: "spot-cutoff-not-cosine",
        mistake: Some(Mistake::SpotCutoffNotCosine),
        formula: "if cosSpot >= spotCutoff:",
        words: || t!("check-cause-spot-cutoff-not-cosine"),
    },
    MistakeInfo {
        id: "spot-cutoff-halved",
        mistake: Some(Mistake::SpotCutoffHalved),
        formula: "m.cos(m.radians(spotCutoff/2))",
        words: || t!("check-cause-spot-cutoff-halved"),
    },
    MistakeInfo {
        id: "spot-direction-untransformed",
        mistake: Some(Mistake::SpotDirectionUntransformed),
        formula: "spotDir = lightSpotDir[:3]",
        words: || t!("check-cause-spot-direction-untransformed"),
    },
    MistakeInfo {
        id: "spot-angle-reversed",
        mistake: Some(Mistake::SpotAngleReversed),
        formula: "cosSpot = np.dot(vlv[:3], spotDir)",
        words: || t!("check-cause-spot-angle-reversed"),
    },
    MistakeInfo {
        id: "cone-test-inverted",
        mistake: Some(Mistake::ConeTestInverted),
        formula: "if cosSpot <= m.cos(m.radians(spotCutoff)):",
        words: || t!("check-cause-cone-test-inverted"),
    },
    MistakeInfo {
        id: "spot-exponent-outside-cone",
        mistake: Some(Mistake::SpotExponentOutsideCone),
        formula: "spot = max(cosSpot, 0)**spotCoef",
        words: || t!("check-cause-spot-exponent-outside-cone"),
    },
    MistakeInfo {
        id: "spot-exponent-ignored",
        mistake: Some(Mistake::SpotExponentIgnored),
        formula: "spot = max(cosSpot, 0)",
        words: || t!("check-cause-spot-exponent-ignored"),
    },
    MistakeInfo {
        id: "spot-exponent-as-factor",
        mistake: Some(Mistake::SpotExponentAsFactor),
        formula: "spot = cosSpot*spotCoef",
        words: || t!("check-cause-spot-exponent-as-factor"),
    },
    MistakeInfo {
        id: "spot-left-out",
        mistake: Some(Mistake::SpotLeftOut),
        formula: "Ilight = (Iamb + Idif + Ispec)/at",
        words: || t!("check-cause-spot-left-out"),
    },
    MistakeInfo {
        id: "spot-on-diffuse-only",
        mistake: Some(Mistake::SpotOnDiffuseOnly),
        formula: "Ilight = (Iamb + spot*Idif + Ispec)/at",
        words: || t!("check-cause-spot-on-diffuse-only"),
    },
    MistakeInfo {
        id: "spot-not-on-ambient",
        mistake: Some(Mistake::SpotNotOnAmbient),
        formula: "Ilight = (Iamb + spot*(Idif + Ispec))/at",
        words: || t!("check-cause-spot-not-on-ambient"),
    },
    MistakeInfo {
        id: "spot-on-whole-colour",
        mistake: Some(Mistake::SpotOnWholeColour),
        formula: "I = spot*(Iemi + Iscene + Ilight)",
        words: || t!("check-cause-spot-on-whole-colour"),
    },
    MistakeInfo {
        id: "light-left-out",
        mistake: Some(Mistake::LightLeftOut),
        formula: "I = Iemi + Iscene + Ilight[0]  # + Ilight[1] ...",
        words: || t!("check-cause-light-left-out"),
    },
    MistakeInfo {
        id: "only-last-light",
        mistake: Some(Mistake::OnlyLastLight),
        formula: "I = Iemi + Iscene + Ilight[i]",
        words: || t!("check-cause-only-last-light"),
    },
    MistakeInfo {
        id: "scene-ambient-left-out",
        mistake: Some(Mistake::SceneAmbientLeftOut),
        formula: "I = Iemi + Ilight",
        words: || t!("check-cause-scene-ambient-left-out"),
    },
    MistakeInfo {
        id: "scene-ambient-without-material",
        mistake: Some(Mistake::SceneAmbientWithoutMaterial),
        formula: "Iscene = sceneAmb",
        words: || t!("check-cause-scene-ambient-without-material"),
    },
    MistakeInfo {
        id: "scene-ambient-wrong-material",
        mistake: Some(Mistake::SceneAmbientWrongMaterial),
        formula: "Iscene = matDif*sceneAmb",
        words: || t!("check-cause-scene-ambient-wrong-material"),
    },
    MistakeInfo {
        id: "scene-ambient-times-light",
        mistake: Some(Mistake::SceneAmbientTimesLight),
        formula: "Iscene = matAmb*sceneAmb*Lamb",
        words: || t!("check-cause-scene-ambient-times-light"),
    },
    MistakeInfo {
        id: "emission-twice",
        mistake: Some(Mistake::EmissionTwice),
        formula: "I = Iemi + Iscene + Ilight + matEmi",
        words: || t!("check-cause-emission-twice"),
    },
    MistakeInfo {
        id: "emission-left-out",
        mistake: Some(Mistake::EmissionLeftOut),
        formula: "I = Iscene + Ilight",
        words: || t!("check-cause-emission-left-out"),
    },
    MistakeInfo {
        id: "colour-not-clamped",
        mistake: Some(Mistake::ColourNotClamped),
        formula: "glColor = np.append(I[:3], 1)",
        words: || t!("check-cause-colour-not-clamped"),
    },
    MistakeInfo {
        id: "alpha-from-sum",
        mistake: Some(Mistake::AlphaFromSum),
        formula: "glColor = np.append(np.clip(I[:3], 0, 1), I[3])",
        words: || t!("check-cause-alpha-from-sum"),
    },
    MistakeInfo {
        id: "w-divide-forgotten",
        mistake: Some(Mistake::WDivideForgotten),
        formula: "# vertexPos = vertexPos/vertexPos[3]",
        words: || t!("check-cause-w-divide-forgotten"),
    },
];

/// The catalogue's entry of `id`.
pub fn info(id: &str) -> Option<&'static MistakeInfo> {
    CATALOGUE.iter().find(|m| m.id == id)
}
