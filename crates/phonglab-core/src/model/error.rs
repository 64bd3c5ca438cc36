//! Typed errors: a refused parameter names its field and the allowed range.

use thiserror::Error;

/// Why a scene was refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SceneError {
    /// A parameter OpenGL refuses with `GL_INVALID_VALUE`, or the app refuses as meaningless.
    #[error("{}", crate::t!("error-out-of-range", field = field, value = crate::locale::exact(*value), allowed = allowed_in_words(allowed)))]
    OutOfRange {
        /// Where, e.g. `lights[0].spot_cutoff`.
        field: String,
        /// The refused value.
        value: f64,
        /// The allowed range in words, e.g. `[0, 90] or 180`.
        allowed: &'static str,
    },
    /// NaN or an infinity where a finite number is needed.
    #[error("{}", crate::t!("error-not-finite", field = field, value = value.to_string()))]
    NotFinite {
        /// Where, e.g. `material.diffuse[1]`.
        field: String,
        /// The refused value.
        value: f64,
    },
    /// More lights than OpenGL has.
    #[error("{}", crate::t!("error-too-many-lights", count = *count, max = max.to_string()))]
    TooManyLights {
        /// How many were given.
        count: usize,
        /// The limit, 8.
        max: usize,
    },
    /// A document whose scene's view matrix is not the one its camera description gives.
    #[error("{}", crate::t!("error-camera-mismatch", camera = *camera))]
    CameraMismatch {
        /// The camera's kind, e.g. "lookAt".
        camera: &'static str,
    },
    /// All three attenuation factors zero: the light would be infinitely bright.
    #[error("{}", crate::t!("error-zero-attenuation", field = field))]
    ZeroAttenuation {
        /// Where, e.g. `lights[0].attenuation`.
        field: String,
    },
    /// A mesh file that cannot be used (missing, too large, malformed: the message names
    /// the line).
    #[error("{field}: {message}")]
    Mesh {
        /// Where, e.g. `view.obj`.
        field: String,
        /// What is wrong, e.g. `line 12: vertex index 40 is out of range (there are 8)`.
        message: String,
    },
}

/// An allowed range as the current language says it: the ranges in words translated, the
/// numeric ones in its decimal mark.
fn allowed_in_words(allowed: &str) -> String {
    match allowed {
        "[0, 90], or 180 for no spotlight" => crate::t!("allowed-spot-cutoff"),
        FLOAT_RANGE => crate::t!("allowed-float"),
        "1, 2, 3, 4 or 5" => crate::t!("allowed-mview"),
        "an eye away from the centre, with up not along the view direction" => crate::t!("allowed-look-at"),
        "at least 1 pixel" => crate::t!("allowed-pixel"),
        numeric => crate::locale::decimal(numeric),
    }
}

impl SceneError {
    /// The field the error is about.
    pub fn field(&self) -> &str {
        match self {
            SceneError::OutOfRange { field, .. }
            | SceneError::NotFinite { field, .. }
            | SceneError::ZeroAttenuation { field }
            | SceneError::Mesh { field, .. } => field,
            SceneError::TooManyLights { .. } => "lights",
            SceneError::CameraMismatch { .. } => "camera",
        }
    }
}

/// The range of a float OpenGL takes (as f32), in words.
pub const FLOAT_RANGE: &str = "a float: 0, or 1.2e-38 <= |x| <= 3.4e38";
