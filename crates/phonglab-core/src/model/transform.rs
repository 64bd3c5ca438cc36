//! Transforms: lookAt, the openFrameworks camera, the worksheet's modelviews, normal matrices.

use glam::{DMat3, DMat4, DVec3};

use crate::numerics::elementary;

/// Builds a matrix from rows (the layout matrices are written in: numpy, the worksheet, JSON).
pub fn mat4_from_rows(rows: [[f64; 4]; 4]) -> DMat4 {
    DMat4::from_cols_array_2d(&rows).transpose()
}

/// The rows of a matrix.
pub fn mat4_rows(m: &DMat4) -> [[f64; 4]; 4] {
    m.transpose().to_cols_array_2d()
}

/// `gluLookAt(eye, centre, up)`: the view matrix `eye_from_world` of a camera at `eye`
/// looking at `centre`. `None` when `eye == centre` or `up` is parallel to the view
/// direction (the camera's orientation is then undefined).
pub fn try_look_at(eye: DVec3, centre: DVec3, up: DVec3) -> Option<DMat4> {
    if !(eye.is_finite() && centre.is_finite() && up.is_finite()) {
        return None;
    }
    // gluLookAt: forward f, side s = f x up, true up u = s x f; rows s, u, -f, then -eye.
    let f = (centre - eye).try_normalize()?;
    let s = f.cross(up).try_normalize()?;
    let u = s.cross(f);
    Some(mat4_from_rows([
        [s.x, s.y, s.z, -s.dot(eye)],
        [u.x, u.y, u.z, -u.dot(eye)],
        [-f.x, -f.y, -f.z, f.dot(eye)],
        [0.0, 0.0, 0.0, 1.0],
    ]))
}

/// The distance of openFrameworks' default camera from the screen plane for a window
/// `height` pixels high: `(height/2) / tan(30 deg)` (a 60 degree vertical field of view).
/// 665.10751 for 768.
pub fn of_camera_distance(height: f64) -> f64 {
    (height / 2.0) / elementary::tan(30f64.to_radians())
}

/// openFrameworks' default camera for a `width` x `height` window, as the worksheet uses
/// it: the eye on the +z axis at [`of_camera_distance`], looking down -z at the screen
/// plane z = 0, with vertices given relative to the window centre. (openFrameworks also
/// moves the origin to the top-left corner and flips y; the worksheet's vertex
/// (-512, -384) is already centre-relative, so that part is left out.) `width` does not
/// change the view matrix; it only decides the window's aspect ratio.
pub fn of_default_camera(_width: f64, height: f64) -> DMat4 {
    DMat4::from_translation(DVec3::new(0.0, 0.0, -of_camera_distance(height)))
}

/// The worksheet's modelviews, `mview1` to `mview5` (index 1..=5), exactly as its cell
/// `In [4]` prints them (rows):
///
/// - `mview1`: translate z by -665.108, the openFrameworks camera for a 768-high window;
/// - `mview2`: a rotation about x by about 59 degrees (rows (0, 0.514496, 0.857493) and
///   (0, -0.85749, 0.514496): the second is printed with one digit less, so it is a
///   rotation to 6 digits and the worksheet's normal differs from OpenGL's in the 6th digit);
/// - `mview3`, `mview4`: built from 15/17 and 8/17 (0.882353, 0.470588), but not rotations:
///   rows 1 and 3 are 72° (120°) apart, rows 2 and 3 55° (42°), and the worksheet's M n and
///   OpenGL's (M^-1)^T n point 13.5° (48°) apart ([`RotationCheck`]);
/// - `mview5`: a 3-4-5 rotation about x (cos 0.8, sin 0.6) and translate z by -960.
pub fn worksheet_modelview(index: usize) -> Option<DMat4> {
    let rows = match index {
        1 => [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, -665.108], [0.0, 0.0, 0.0, 1.0]],
        2 => {
            [[1.0, 0.0, 0.0, 0.0], [0.0, 0.514496, 0.857493, 0.0], [0.0, -0.85749, 0.514496, 0.0], [0.0, 0.0, 0.0, 1.0]]
        }
        3 => [
            [0.882353, 0.470588, 0.0, 0.0],
            [-0.220182, 0.412842, 0.882353, 0.0],
            [0.470588, -0.220182, 0.882353, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        4 => [
            [0.882353, -0.470588, 0.0, 0.0],
            [0.220182, 0.412842, 0.882353, 0.0],
            [-0.470588, 0.220182, 0.882353, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        5 => [[1.0, 0.0, 0.0, 0.0], [0.0, 0.8, 0.6, 0.0], [0.0, -0.6, 0.8, -960.0], [0.0, 0.0, 0.0, 1.0]],
        _ => return None,
    };
    Some(mat4_from_rows(rows))
}

/// The demo's "eye space": object space moved so that its eye (-4, 0, -8) is the origin.
pub fn phong_demo_eye_from_object() -> DMat4 {
    // -PHONG_DEMO_EYE, written out (negating 0 would give -0).
    DMat4::from_translation(DVec3::new(4.0, 0.0, 8.0))
}

/// The matrix that takes object-space normals to eye space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalMatrix {
    /// `(M^-1)^T` of the modelview's upper 3x3 `M`; its cofactor matrix when `M` is singular.
    pub eye_from_object: DMat3,
    /// `GL_RESCALE_NORMAL`'s factor `1 / sqrt(m31^2 + m32^2 + m33^2)`, the `m3j` being the
    /// third row of `M^-1` (OpenGL 2.1 section 2.11.3).
    pub rescale: f64,
    /// `M` is singular (det = 0): normals keep only their direction, through the cofactors.
    pub singular: bool,
    /// `M` preserves lengths (a rotation, possibly with reflection): `(M^-1)^T = M`.
    pub orthonormal: bool,
}

impl NormalMatrix {
    /// The normal matrix a rule set uses: OpenGL's inverse transpose, or (the worksheet)
    /// the modelview's 3x3 itself. `rescale` and `orthonormal` describe `M` either way.
    pub fn for_rules(eye_from_object: &DMat4, rules: crate::model::rules::Rules) -> Self {
        let nm = Self::new(eye_from_object);
        match rules.normal_transform() {
            crate::model::rules::NormalTransform::InverseTranspose => nm,
            crate::model::rules::NormalTransform::Modelview => {
                Self { eye_from_object: DMat3::from_mat4(*eye_from_object), singular: false, ..nm }
            }
        }
    }

    /// Computes the normal matrix of `eye_from_object` (the modelview) in f64.
    pub fn new(eye_from_object: &DMat4) -> Self {
        let m = DMat3::from_mat4(*eye_from_object);
        let (a, b, c) = (m.x_axis, m.y_axis, m.z_axis);
        // Columns of the cofactor matrix: M^-1 = cofactor^T / det, so (M^-1)^T = cofactor / det.
        let cof = DMat3::from_cols(b.cross(c), c.cross(a), a.cross(b));
        let det = a.dot(b.cross(c));
        let singular = det == 0.0 || !det.is_finite();
        let eye_from_object = if singular { cof } else { cof * (1.0 / det) };
        // Third row of M^-1 = third column of (M^-1)^T.
        let row3 = eye_from_object.z_axis;
        let len = crate::numerics::robust::scaled_length::<f64>(row3);
        let rescale = if len > 0.0 && len.is_finite() { 1.0 / len } else { 1.0 };
        let mt_m = m.transpose() * m;
        let orthonormal = (mt_m - DMat3::IDENTITY).to_cols_array().iter().all(|x| x.abs() <= 1e-12);
        Self { eye_from_object, rescale, singular, orthonormal }
    }
}

/// `gluPerspective(fovy, aspect, near, far)`: eye to clip space.
pub fn perspective(fovy_deg: f64, aspect: f64, near: f64, far: f64) -> DMat4 {
    let f = 1.0 / elementary::tan(fovy_deg.to_radians() / 2.0);
    mat4_from_rows([
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [0.0, 0.0, (far + near) / (near - far), 2.0 * far * near / (near - far)],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn of_camera_matches_worksheet() {
        assert!((of_camera_distance(768.0) - 665.108).abs() < 1e-3);
        let m = of_default_camera(1024.0, 768.0);
        assert!((m.w_axis.z + 665.1075).abs() < 1e-4);
    }

    #[test]
    fn normal_matrix_is_inverse_transpose() {
        let m = DMat4::from_scale(DVec3::new(1.0, 4.0, 0.25));
        let n = NormalMatrix::new(&m);
        assert!((n.eye_from_object.y_axis.y - 0.25).abs() < 1e-15);
        assert!((n.eye_from_object.z_axis.z - 4.0).abs() < 1e-15);
        assert!(!n.singular && !n.orthonormal);
        let r = worksheet_modelview(5).unwrap();
        let n = NormalMatrix::new(&r);
        assert!(n.orthonormal);
        assert!((n.eye_from_object - DMat3::from_mat4(r)).to_cols_array().iter().all(|x| x.abs() < 1e-15));
        assert_eq!(n.rescale, 1.0);
    }

    #[test]
    fn singular_modelview_keeps_directions() {
        let m = DMat4::from_scale(DVec3::new(1.0, 1.0, 0.0));
        let n = NormalMatrix::new(&m);
        assert!(n.singular);
        let v = n.eye_from_object * DVec3::Z;
        assert!(v.is_finite() && v.z > 0.0);
    }

    #[test]
    fn look_at_refuses_degenerate_cameras() {
        assert!(try_look_at(DVec3::ZERO, DVec3::ZERO, DVec3::Y).is_none());
        assert!(try_look_at(DVec3::ZERO, DVec3::Y, DVec3::Y).is_none());
        let m = try_look_at(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, DVec3::Y).unwrap();
        assert!((m.w_axis.z + 5.0).abs() < 1e-15);
    }
}

/// How far the upper 3×3 of a modelview is from a rotation, and what that does to a
/// normal: the worksheet transforms normals by M itself, OpenGL by (M^-1)^T, and the two
/// agree (in direction) only when M's rows are orthogonal and of one length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotationCheck {
    /// The lengths of rows 1, 2 and 3.
    pub row_lengths: [f64; 3],
    /// The angles between rows (1, 2), (1, 3) and (2, 3), in degrees.
    pub row_angles: [f64; 3],
    /// The angle between normalize(M n) and normalize((M^-1)^T n), in degrees (`None` when
    /// either is zero or M is singular).
    pub normal_gap: Option<f64>,
}

impl RotationCheck {
    /// Checks `m` with the normal `n`.
    pub fn of(m: &DMat4, n: glam::DVec3) -> Self {
        let rows = mat4_rows(m).map(|r| glam::DVec3::new(r[0], r[1], r[2]));
        let angle = |a: glam::DVec3, b: glam::DVec3| {
            let c = a.dot(b) / (a.length() * b.length());
            c.clamp(-1.0, 1.0).acos().to_degrees()
        };
        let by_m = glam::DMat3::from_mat4(*m) * n;
        let by_gl = NormalMatrix::new(m).eye_from_object * n;
        let normal_gap = match (by_m.try_normalize(), by_gl.try_normalize()) {
            (Some(a), Some(b)) if a.is_finite() && b.is_finite() => Some(angle(a, b)),
            _ => None,
        };
        RotationCheck {
            row_lengths: [rows[0].length(), rows[1].length(), rows[2].length()],
            row_angles: [angle(rows[0], rows[1]), angle(rows[0], rows[2]), angle(rows[1], rows[2])],
            normal_gap,
        }
    }

    /// The largest departure from a rotation: of a row's length from 1 (relative) and of
    /// an angle from 90 degrees (as a fraction of 90).
    pub fn departure(&self) -> f64 {
        let lengths = self.row_lengths.iter().map(|l| (l - 1.0).abs());
        let angles = self.row_angles.iter().map(|a| (a - 90.0).abs() / 90.0);
        lengths.chain(angles).fold(0.0, f64::max)
    }

    /// Is M a rotation to 6 digits (as the worksheet prints its matrices)?
    pub fn is_rotation(&self) -> bool {
        self.departure() < 1e-5
    }

    /// The rows' angles as "72.3° (rows 1 and 3), 55.2° (rows 2 and 3)": those that are
    /// not 90 degrees to 0.05.
    pub fn skewed_rows(&self) -> Vec<(usize, usize, f64)> {
        [(1, 2), (1, 3), (2, 3)]
            .into_iter()
            .zip(self.row_angles)
            .filter(|(_, a)| (a - 90.0).abs() >= 0.05)
            .map(|((i, j), a)| (i, j, a))
            .collect()
    }
}

#[cfg(test)]
mod rotation_check_tests {
    use super::*;

    #[test]
    fn the_worksheets_mview3_and_mview4_are_not_rotations() {
        let n = glam::DVec3::Z;
        let check = |k| RotationCheck::of(&worksheet_modelview(k).unwrap(), n);
        let (m3, m4) = (check(3), check(4));
        assert!(!m3.is_rotation() && !m4.is_rotation());
        // Rows 1 and 3 are 72° apart, rows 2 and 3 55° (mview3); 120° and 42° (mview4).
        assert!((m3.row_angles[1] - 72.283).abs() < 1e-3 && (m3.row_angles[2] - 55.173).abs() < 1e-3, "{m3:?}");
        assert!((m4.row_angles[1] - 120.444).abs() < 1e-3 && (m4.row_angles[2] - 41.508).abs() < 1e-3, "{m4:?}");
        assert_eq!(m3.skewed_rows().len(), 2);
        // The worksheet's normal: M n and (M^-1)^T n are 13.5° and 48° apart.
        assert!((m3.normal_gap.unwrap() - 13.5335).abs() < 1e-3, "{m3:?}");
        assert!((m4.normal_gap.unwrap() - 48.4535).abs() < 1e-3, "{m4:?}");
        // mview2 is a rotation to the 6 digits it is printed with; mview1 and mview5 exactly.
        let m2 = check(2);
        assert!(m2.is_rotation() && m2.normal_gap.unwrap() < 1e-3, "{m2:?}");
        assert!(check(5).departure() < 1e-15 && check(1).departure() < 1e-15);
    }
}
