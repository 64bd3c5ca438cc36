//! How the view matrix (`eye_from_world`) was chosen: a worksheet modelview, lookAt, the
//! openFrameworks camera, or a typed matrix.

use glam::{DMat4, DVec3};

use crate::model::error::SceneError;
use crate::model::transform::{of_default_camera, try_look_at, worksheet_modelview};

/// A camera description; [`CameraSpec::matrix`] turns it into `eye_from_world`.
#[derive(Clone, Debug, PartialEq)]
pub enum CameraSpec {
    /// The worksheet's `mview1`..`mview5`.
    Worksheet(u8),
    /// `gluLookAt(eye, centre, up)`.
    LookAt {
        /// Where the eye is.
        eye: DVec3,
        /// The point looked at.
        centre: DVec3,
        /// Which way is up.
        up: DVec3,
    },
    /// openFrameworks' default camera for a `width` x `height` window.
    OpenFrameworks {
        /// Window width in pixels.
        width: f64,
        /// Window height in pixels.
        height: f64,
    },
    /// A matrix typed in.
    Matrix(DMat4),
}

impl Default for CameraSpec {
    fn default() -> Self {
        CameraSpec::Worksheet(5)
    }
}

impl CameraSpec {
    /// A short name for menus.
    /// The kind's name for people, in the current language.
    pub fn kind_name(&self) -> String {
        match self {
            CameraSpec::Worksheet(_) => crate::t!("camera-kind-worksheet"),
            CameraSpec::LookAt { .. } => "lookAt".into(),
            CameraSpec::OpenFrameworks { .. } => crate::t!("camera-kind-of"),
            CameraSpec::Matrix(_) => crate::t!("camera-kind-matrix"),
        }
    }

    /// The kind's key (English; the name shown is [`Self::kind_name`]).
    pub fn kind_label(&self) -> &'static str {
        match self {
            CameraSpec::Worksheet(_) => "Worksheet modelview",
            CameraSpec::LookAt { .. } => "lookAt",
            CameraSpec::OpenFrameworks { .. } => "openFrameworks camera",
            CameraSpec::Matrix(_) => "Typed 4x4",
        }
    }

    /// The view matrix, or why there is none (a degenerate lookAt, a window of no height,
    /// a worksheet index outside 1..5, a non-finite entry).
    pub fn matrix(&self) -> Result<DMat4, SceneError> {
        let m = match self {
            CameraSpec::Worksheet(i) => worksheet_modelview(*i as usize).ok_or_else(|| SceneError::OutOfRange {
                field: "camera.worksheet".into(),
                value: *i as f64,
                allowed: "1, 2, 3, 4 or 5",
            })?,
            CameraSpec::LookAt { eye, centre, up } => {
                try_look_at(*eye, *centre, *up).ok_or_else(|| SceneError::OutOfRange {
                    field: "camera.look_at".into(),
                    value: (*centre - *eye).length(),
                    allowed: "an eye away from the centre, with up not along the view direction",
                })?
            }
            CameraSpec::OpenFrameworks { width, height } => {
                for (f, v) in [("camera.width", *width), ("camera.height", *height)] {
                    if !v.is_finite() {
                        return Err(SceneError::NotFinite { field: f.into(), value: v });
                    }
                    if v < 1.0 {
                        return Err(SceneError::OutOfRange { field: f.into(), value: v, allowed: "at least 1 pixel" });
                    }
                }
                of_default_camera(*width, *height)
            }
            CameraSpec::Matrix(m) => *m,
        };
        if let Some((i, x)) = m.transpose().to_cols_array().iter().enumerate().find(|(_, x)| !x.is_finite()) {
            return Err(SceneError::NotFinite { field: format!("camera.matrix[{i}]"), value: *x });
        }
        Ok(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_gives_its_matrix_or_a_reason() {
        assert_eq!(CameraSpec::Worksheet(5).matrix().unwrap(), worksheet_modelview(5).unwrap());
        assert_eq!(CameraSpec::Worksheet(6).matrix().unwrap_err().field(), "camera.worksheet");
        let of = CameraSpec::OpenFrameworks { width: 1024.0, height: 768.0 }.matrix().unwrap();
        assert!((of.w_axis.z + 665.1075).abs() < 1e-4);
        assert!(CameraSpec::OpenFrameworks { width: 1024.0, height: 0.0 }.matrix().is_err());
        let e = CameraSpec::LookAt { eye: DVec3::ONE, centre: DVec3::ONE, up: DVec3::Y }.matrix().unwrap_err();
        assert_eq!(e.field(), "camera.look_at");
        let mut m = DMat4::IDENTITY;
        m.w_axis.x = f64::NAN;
        assert_eq!(CameraSpec::Matrix(m).matrix().unwrap_err().field(), "camera.matrix[3]");
    }
}
