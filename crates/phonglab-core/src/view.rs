//! The shaded view's settings: which object, which shading, how finely tessellated.

use serde::{Deserialize, Serialize};

use crate::error::SceneError;

/// The objects of the Phong demo.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ObjectKind {
    /// gluSphere(0.5, slices, stacks).
    #[default]
    Sphere,
    /// The Utah teapot (glutSolidTeapot(0.5)) from its 32 Bezier patches.
    Teapot,
    /// gluCylinder(0.3, 0.3, 0.5, slices, stacks).
    Cylinder,
}

impl ObjectKind {
    /// All three, in menu order (the demo's keys s, t, c).
    pub const ALL: [ObjectKind; 3] = [ObjectKind::Sphere, ObjectKind::Teapot, ObjectKind::Cylinder];

    /// A name for menus.
    pub fn label(self) -> &'static str {
        match self {
            ObjectKind::Sphere => "Sphere",
            ObjectKind::Teapot => "Teapot",
            ObjectKind::Cylinder => "Cylinder",
        }
    }
}

/// How lighting is spread over a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Shading {
    /// Lighting per vertex, colours interpolated.
    #[default]
    Gouraud,
    /// Position and normal interpolated, lighting per pixel.
    Phong,
    /// One normal per face.
    Flat,
}

impl Shading {
    /// All three, in the demo's key order 1, 2, 3.
    pub const ALL: [Shading; 3] = [Shading::Gouraud, Shading::Phong, Shading::Flat];

    /// A name for menus.
    pub fn label(self) -> &'static str {
        match self {
            Shading::Gouraud => "Gouraud",
            Shading::Phong => "Phong",
            Shading::Flat => "Flat",
        }
    }
}

/// Tessellation limits: at least a triangle's worth, at most what stays interactive.
pub const DETAIL_RANGE: std::ops::RangeInclusive<u32> = 3..=400;

/// The shaded view's settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct View {
    /// The object shown.
    pub object: ObjectKind,
    /// The shading.
    pub shading: Shading,
    /// Sphere and cylinder slices, and teapot subdivisions per patch side (x4 / 10).
    pub detail: u32,
    /// Use the demo's normals, normalize(position), instead of the true surface normals
    /// (wrong for the teapot and the cylinder: shown to see the artefact).
    pub demo_normals: bool,
    /// Spin the object about y by 0.5 degrees a frame, as the demo does.
    pub auto_rotate: bool,
}

impl Default for View {
    fn default() -> Self {
        Self {
            object: ObjectKind::Sphere,
            shading: Shading::Gouraud,
            detail: 50,
            demo_normals: false,
            auto_rotate: false,
        }
    }
}

impl View {
    /// Refuses a tessellation outside [`DETAIL_RANGE`].
    pub fn validate(&self) -> Result<(), SceneError> {
        if !DETAIL_RANGE.contains(&self.detail) {
            return Err(SceneError::OutOfRange {
                field: "view.detail".into(),
                value: self.detail as f64,
                allowed: "[3, 400]",
            });
        }
        Ok(())
    }
}
