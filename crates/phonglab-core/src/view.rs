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

/// Tessellation limits: at least a closed shape, at most what stays interactive.
pub const SLICES_RANGE: std::ops::RangeInclusive<u32> = 3..=400;
/// Stacks of the sphere and cylinder.
pub const STACKS_RANGE: std::ops::RangeInclusive<u32> = 1..=400;
/// Quads per teapot patch side.
pub const GRID_RANGE: std::ops::RangeInclusive<u32> = 1..=64;

/// The shaded view's settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct View {
    /// The object shown.
    pub object: ObjectKind,
    /// The shading.
    pub shading: Shading,
    /// gluSphere slices (the demo: 50).
    pub sphere_slices: u32,
    /// gluSphere stacks (the demo: 50).
    pub sphere_stacks: u32,
    /// Quads per teapot patch side (glutSolidTeapot: 7).
    pub teapot_grid: u32,
    /// gluCylinder slices (the demo: 20).
    pub cylinder_slices: u32,
    /// gluCylinder stacks (the demo: 5).
    pub cylinder_stacks: u32,
    /// Close the cylinder with disks (gluCylinder has none).
    pub cylinder_caps: bool,
    /// Use the demo's normals, normalize(position), instead of the true surface normals
    /// (wrong for the teapot and the cylinder: shown to see the artefact).
    pub demo_normals: bool,
    /// Spin the object about y by 0.5 degrees a frame, as the demo does.
    pub auto_rotate: bool,
    /// The object's spin about y so far, in degrees.
    pub spin_degrees: f64,
}

impl Default for View {
    fn default() -> Self {
        Self {
            object: ObjectKind::Sphere,
            shading: Shading::Gouraud,
            sphere_slices: 50,
            sphere_stacks: 50,
            teapot_grid: 7,
            cylinder_slices: 20,
            cylinder_stacks: 5,
            cylinder_caps: false,
            demo_normals: false,
            auto_rotate: false,
            spin_degrees: 0.0,
        }
    }
}

impl View {
    /// Refuses a tessellation outside the ranges above, and a non-finite spin.
    pub fn validate(&self) -> Result<(), SceneError> {
        let check = |field: &str, v: u32, r: &std::ops::RangeInclusive<u32>, allowed: &'static str| {
            if r.contains(&v) {
                Ok(())
            } else {
                Err(SceneError::OutOfRange { field: format!("view.{field}"), value: v as f64, allowed })
            }
        };
        check("sphere_slices", self.sphere_slices, &SLICES_RANGE, "[3, 400]")?;
        check("sphere_stacks", self.sphere_stacks, &SLICES_RANGE, "[3, 400]")?;
        check("teapot_grid", self.teapot_grid, &GRID_RANGE, "[1, 64]")?;
        check("cylinder_slices", self.cylinder_slices, &SLICES_RANGE, "[3, 400]")?;
        check("cylinder_stacks", self.cylinder_stacks, &STACKS_RANGE, "[1, 400]")?;
        if !self.spin_degrees.is_finite() {
            return Err(SceneError::NotFinite { field: "view.spin_degrees".into(), value: self.spin_degrees });
        }
        Ok(())
    }
}
