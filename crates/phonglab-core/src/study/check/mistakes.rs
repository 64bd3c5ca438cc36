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
    /// The normal not normalised after its transform.
    NormalNotNormalised,
    /// The light's position left in object space.
    LightNotTransformed,
    /// The light's position transformed by the modelview twice.
    LightTransformedTwice,
    /// `vlv = P - L`: from the light to the vertex.
    VlvReversed,
    /// `vlv` not normalised.
    VlvNotNormalised,
    /// A directional light (w = 0) treated as a point at its direction.
    DirectionalAsPoint,
    /// The local and the infinite viewer swapped.
    ViewerSwapped,
    /// `H = vlv + vov`, not normalised.
    HalfwayNotNormalised,
    /// Specular where `N . L <= 0` (OpenGL's gate left out).
    SpecularWithoutGate,
    /// The diffuse term not clamped: negative past 90 degrees.
    DiffuseNotClamped,
    /// The spot cutoff's cosine taken of degrees as if they were radians.
    SpotCutoffRadians,
    /// The spot exponent applied outside the cone too (no cone test).
    SpotExponentOutsideCone,
    /// The share multiplied by the attenuation instead of divided.
    AttenuationMultiplied,
    /// The light's distance measured in object space.
    AttenuationObjectDistance,
    /// The division by w forgotten.
    WDivideForgotten,
    /// Shininess as the 0-1 fraction (`0.4`) instead of `0.4*128`.
    ShininessFraction,
}

impl Mistake {
    /// Is this a mistake under `rules`? One that changes nothing those rules do (no N·L
    /// gate to leave out, the normal transformed by M already) is not offered as a cause.
    pub fn applies(self, rules: crate::model::rules::Rules) -> bool {
        use crate::model::rules::{NormalTransform, SpecularGate};
        match self {
            Mistake::SpecularWithoutGate => rules.specular_gate() == SpecularGate::LitSide,
            Mistake::NormalByModelview => rules.normal_transform() == NormalTransform::InverseTranspose,
            _ => true,
        }
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
pub const CATALOGUE: [MistakeInfo; 18] = [
    MistakeInfo {
        id: "normal-by-modelview",
        mistake: Some(Mistake::NormalByModelview),
        formula: "vertexNormal = np.matmul(mview, vertexNormal)",
        words: || t!("check-cause-normal-by-modelview"),
    },
    MistakeInfo {
        id: "normal-not-normalised",
        mistake: Some(Mistake::NormalNotNormalised),
        formula: "# vertexNormal = vertexNormal/np.linalg.norm(vertexNormal)",
        words: || t!("check-cause-normal-not-normalised"),
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
        id: "viewer-swapped",
        mistake: Some(Mistake::ViewerSwapped),
        formula: "obs = np.array([0, 0, 0, 1])  # <-> obs = vertexPos*np.array([1, 1, 0, 1])",
        words: || t!("check-cause-viewer-swapped"),
    },
    MistakeInfo {
        id: "halfway-not-normalised",
        mistake: Some(Mistake::HalfwayNotNormalised),
        formula: "H = vlv + vov",
        words: || t!("check-cause-halfway-not-normalised"),
    },
    MistakeInfo {
        id: "specular-without-gate",
        mistake: Some(Mistake::SpecularWithoutGate),
        formula: "Ispec = (Lspec*matSpec)*(max(cosBeta, 0)**ns)",
        words: || t!("check-cause-specular-without-gate"),
    },
    MistakeInfo {
        id: "diffuse-not-clamped",
        mistake: Some(Mistake::DiffuseNotClamped),
        formula: "Idif = (Ldif*matDif)*cosTheta",
        words: || t!("check-cause-diffuse-not-clamped"),
    },
    MistakeInfo {
        id: ACOS_PAST_ONE,
        mistake: None,
        formula: "theta = m.acos(cosTheta)  # cosTheta = 1.0000000000000002",
        words: || t!("check-cause-acos-past-one"),
    },
    MistakeInfo {
        id: "spot-cutoff-radians",
        mistake: Some(Mistake::SpotCutoffRadians),
        formula: "cosSpot >= m.cos(spotCutoff)",
        words: || t!("check-cause-spot-cutoff-radians"),
    },
    MistakeInfo {
        id: "spot-exponent-outside-cone",
        mistake: Some(Mistake::SpotExponentOutsideCone),
        formula: "spot = max(cosSpot, 0)**spotCoef",
        words: || t!("check-cause-spot-exponent-outside-cone"),
    },
    MistakeInfo {
        id: "attenuation-multiplied",
        mistake: Some(Mistake::AttenuationMultiplied),
        formula: "I = (Iamb + Idif + Ispec)*at",
        words: || t!("check-cause-attenuation-multiplied"),
    },
    MistakeInfo {
        id: "attenuation-object-distance",
        mistake: Some(Mistake::AttenuationObjectDistance),
        formula: "d = np.linalg.norm(lightPosObject - vertexPosObject)",
        words: || t!("check-cause-attenuation-object-distance"),
    },
    MistakeInfo {
        id: "w-divide-forgotten",
        mistake: Some(Mistake::WDivideForgotten),
        formula: "# vertexPos = vertexPos/vertexPos[3]",
        words: || t!("check-cause-w-divide-forgotten"),
    },
    MistakeInfo {
        id: "shininess-fraction",
        mistake: Some(Mistake::ShininessFraction),
        formula: "ns = 0.2",
        words: || t!("check-cause-shininess-fraction"),
    },
];

/// The catalogue's entry of `id`.
pub fn info(id: &str) -> Option<&'static MistakeInfo> {
    CATALOGUE.iter().find(|m| m.id == id)
}
