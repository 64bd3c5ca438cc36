//! Typed errors: a refused parameter names its field and the allowed range.

use thiserror::Error;

/// Why a scene was refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SceneError {
    /// A parameter OpenGL refuses with `GL_INVALID_VALUE`, or the app refuses as meaningless.
    #[error("{field} = {value} is out of range: allowed {allowed}")]
    OutOfRange {
        /// Where, e.g. `lights[0].spot_cutoff`.
        field: String,
        /// The refused value.
        value: f64,
        /// The allowed range in words, e.g. `[0, 90] or 180`.
        allowed: &'static str,
    },
    /// NaN or an infinity where a finite number is needed.
    #[error("{field} must be a finite number, not {value}")]
    NotFinite {
        /// Where, e.g. `material.diffuse[1]`.
        field: String,
        /// The refused value.
        value: f64,
    },
    /// More lights than OpenGL has.
    #[error("{count} lights: OpenGL has at most {max}")]
    TooManyLights {
        /// How many were given.
        count: usize,
        /// The limit, 8.
        max: usize,
    },
    /// A document whose scene's view matrix is not the one its camera description gives.
    #[error(
        "the scene's view matrix is not the one its camera gives ({camera}): set the camera, or give the matrix as a typed camera"
    )]
    CameraMismatch {
        /// The camera's kind, e.g. "lookAt".
        camera: &'static str,
    },
    /// All three attenuation factors zero: the light would be infinitely bright.
    #[error(
        "{field}: constant, linear and quadratic attenuation are all 0, so the light would be infinitely bright; make at least one positive"
    )]
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
