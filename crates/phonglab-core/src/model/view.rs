//! The shaded view's settings: which object, which shading, how finely tessellated.

use serde::{Deserialize, Serialize};

use crate::model::error::SceneError;
use crate::numerics::elementary;

/// The objects of the Phong demo.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum ObjectKind {
    /// gluSphere(0.5, slices, stacks).
    #[default]
    Sphere,
    /// The Utah teapot (glutSolidTeapot(0.5)) from its 32 Bezier patches.
    Teapot,
    /// gluCylinder(0.3, 0.3, 0.5, slices, stacks).
    Cylinder,
    /// The user's mesh: the OBJ file at [`View::obj`], fitted to radius 0.5.
    #[cfg_attr(feature = "clap", value(skip))]
    Obj,
}

impl ObjectKind {
    /// All three, in menu order (the demo's keys s, t, c).
    pub const ALL: [ObjectKind; 3] = [ObjectKind::Sphere, ObjectKind::Teapot, ObjectKind::Cylinder];

    /// The name in files and data (scene files, CSV columns, file names): the serde name.
    pub fn key(self) -> &'static str {
        match self {
            ObjectKind::Sphere => "sphere",
            ObjectKind::Teapot => "teapot",
            ObjectKind::Cylinder => "cylinder",
            ObjectKind::Obj => "obj",
        }
    }

    /// A name for menus, in the current language.
    pub fn label(self) -> String {
        match self {
            ObjectKind::Sphere => crate::t!("object-sphere"),
            ObjectKind::Teapot => crate::t!("object-teapot"),
            ObjectKind::Cylinder => crate::t!("object-cylinder"),
            ObjectKind::Obj => crate::t!("object-mesh"),
        }
    }
}

/// How lighting is spread over a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
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

/// Where the shaded view's picture comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Framing {
    /// The orbit camera ([`ViewCamera`]) and `gluPerspective(40, 1, 0.1, 100)`.
    #[default]
    Orbit,
    /// The Phong demo's: no projection at all (`gl_Position = mvMatrix * p`), so the picture
    /// is clip space itself: x to the right, y up, and the nearer fragment has the smaller
    /// z (depth test LESS), as if seen from z = -infinity.
    ClipSpace,
}

impl Framing {
    /// Both, in menu order.
    pub const ALL: [Framing; 2] = [Framing::Orbit, Framing::ClipSpace];

    /// A name for menus.
    pub fn label(self) -> String {
        match self {
            Framing::Orbit => crate::t!("framing-orbit"),
            Framing::ClipSpace => crate::t!("framing-clip"),
        }
    }
}

/// Which coordinates the shaded view lights the object in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LightingSpace {
    /// OpenGL's: eye space after the whole modelview, the object's spin included, with each
    /// light placed as its placement says (a light placed in the world stays put while the
    /// object turns).
    #[default]
    Eye,
    /// The Phong demo's: positions and normals are not transformed by the spin; the object
    /// is lit in its own coordinates (the scene's modelview only), so the light turns with
    /// the object.
    Object,
}

/// How Flat shading finds a fragment's normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FlatNormal {
    /// One colour per face: lit once, at its centroid, with its geometric normal.
    #[default]
    Face,
    /// The Phong demo's: lit per fragment with `normalize(cross(dFdy(p), dFdx(p)))` of the
    /// interpolated position: the face's plane normal, turned by the triangle's winding on
    /// the screen (towards a viewer at -z in clip space, away from an ordinary camera).
    ScreenDerivatives,
}

/// How the renderer spreads the light over a triangle: one choice, where the view (and its
/// scene file) keeps two, the shading and, for Flat, its normal ([`ShadingMode::of`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ShadingMode {
    /// Lit per vertex, the colours interpolated.
    #[default]
    Gouraud,
    /// Position and normal interpolated, lit per fragment.
    Phong,
    /// One colour per face: lit once, at its centroid, with its geometric normal.
    FlatFace,
    /// The Phong demo's Flat: lit per fragment with the normal of the screen derivatives.
    FlatDerivatives,
    /// OpenGL's `glShadeModel(GL_FLAT)`: each face the colour lit (per vertex, with the
    /// vertex's normal) at its provoking vertex ([`crate::mesh::Mesh::provoking_vertex`]).
    /// No view chooses it; `phonglab diagnose` draws it.
    FlatProvoking,
}

impl ShadingMode {
    /// The mode of a view's `shading` and `flat` normal (the normal matters for Flat only).
    pub fn of(shading: Shading, flat: FlatNormal) -> ShadingMode {
        match (shading, flat) {
            (Shading::Gouraud, _) => ShadingMode::Gouraud,
            (Shading::Phong, _) => ShadingMode::Phong,
            (Shading::Flat, FlatNormal::Face) => ShadingMode::FlatFace,
            (Shading::Flat, FlatNormal::ScreenDerivatives) => ShadingMode::FlatDerivatives,
        }
    }

    /// The shading it is a mode of.
    pub fn shading(self) -> Shading {
        match self {
            ShadingMode::Gouraud => Shading::Gouraud,
            ShadingMode::Phong => Shading::Phong,
            ShadingMode::FlatFace | ShadingMode::FlatDerivatives | ShadingMode::FlatProvoking => Shading::Flat,
        }
    }

    /// Does it give each face one colour, made in setup (Flat per face, GL_FLAT)?
    pub fn per_face(self) -> bool {
        matches!(self, ShadingMode::FlatFace | ShadingMode::FlatProvoking)
    }

    /// Does it light each vertex (Gouraud, and GL_FLAT's provoking vertices)?
    pub fn per_vertex(self) -> bool {
        matches!(self, ShadingMode::Gouraud | ShadingMode::FlatProvoking)
    }

    /// Does it light each fragment (Phong, and the demo's Flat)?
    pub fn per_fragment(self) -> bool {
        matches!(self, ShadingMode::Phong | ShadingMode::FlatDerivatives)
    }
}

/// The Phong demo's spin after `degrees` (0.5 a frame): its `mvMatrix` is
/// `rotY(0.5 deg)^frame` in NumPy's row-major layout, uploaded with transpose `GL_FALSE`,
/// so the shader applies its transpose: a turn by `-degrees` about y.
pub fn demo_spin(degrees: f64) -> glam::DMat4 {
    elementary::rotation_y(-degrees.to_radians())
}

/// The shaded view's orbit camera: it looks at the origin from `distance` away, turned by
/// `yaw` about y and `pitch` about x (degrees).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ViewCamera {
    /// Degrees about y.
    pub yaw: f64,
    /// Degrees about x, in [-89, 89].
    pub pitch: f64,
    /// Distance from the origin, in [0.6, 20].
    pub distance: f64,
}

impl Default for ViewCamera {
    fn default() -> Self {
        Self { yaw: 0.0, pitch: 15.0, distance: 2.4 }
    }
}

impl ViewCamera {
    /// World to eye.
    pub fn eye_from_world(&self) -> glam::DMat4 {
        glam::DMat4::from_translation(glam::DVec3::new(0.0, 0.0, -self.distance))
            * elementary::rotation_x(self.pitch.to_radians())
            * elementary::rotation_y(self.yaw.to_radians())
    }
}

/// The shaded view's projection: gluPerspective(40, aspect, 0.1, 100).
pub fn view_projection(aspect: f64) -> glam::DMat4 {
    crate::model::transform::perspective(40.0, aspect, 0.1, 100.0)
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
    /// The orbit camera.
    pub camera: ViewCamera,
    /// Orbit camera, or the demo's clip space.
    pub framing: Framing,
    /// Eye space (OpenGL) or object space (the demo: the light turns with the object).
    pub lighting_space: LightingSpace,
    /// Flat shading's normal.
    pub flat_normal: FlatNormal,
    /// Phong shading renormalises its interpolated normal (the demo's shader does not).
    pub phong_renormalize: bool,
    /// Move gluCylinder (z from 0 to 0.5) to be centred on the origin (the demo does not).
    pub cylinder_centered: bool,
    /// The colour of uncovered pixels (the demo: black).
    #[serde(deserialize_with = "crate::numerics::strict::exact")]
    pub background: [f32; 3],
    /// The OBJ file shown when the object is [`ObjectKind::Obj`] (a path; relative paths
    /// in a scene file are taken from the scene file's folder when it is opened).
    pub obj: Option<String>,
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
            camera: ViewCamera::default(),
            framing: Framing::Orbit,
            lighting_space: LightingSpace::Eye,
            flat_normal: FlatNormal::Face,
            phong_renormalize: true,
            cylinder_centered: true,
            background: [0.1, 0.1, 0.15],
            obj: None,
        }
    }
}

impl View {
    /// The mesh this view shows: the Phong demo's objects at the demo's sizes (sphere r 0.5,
    /// teapot 0.5, cylinder r 0.3 h 0.5, centred), tessellated as the view says.
    pub fn mesh(&self) -> crate::mesh::Mesh {
        let m = match self.object {
            ObjectKind::Sphere | ObjectKind::Cylinder => self.quadric(false).unwrap_or_default(),
            ObjectKind::Teapot => crate::mesh::teapot::glut_teapot(0.5, self.teapot_grid),
            // Validated when the view was accepted; a file that went away since shows
            // nothing rather than failing.
            ObjectKind::Obj => self.obj_mesh().map(|o| o.mesh.clone()).unwrap_or_default(),
        };
        if self.demo_normals { m.with_position_normals() } else { m }
    }

    /// The mesh as GLU draws it after `gluQuadricOrientation(q, GLU_INSIDE)` (normals
    /// inwards, quads split along their other diagonal, triangles wound the other way);
    /// `None` for an object that is not a GLU quadric (the teapot, an OBJ file).
    pub fn mesh_inside(&self) -> Option<crate::mesh::Mesh> {
        let m = self.quadric(true)?;
        Some(if self.demo_normals { m.with_position_normals() } else { m })
    }

    /// The sphere or the cylinder, facing out or (`inside`) in; `None` for other objects.
    fn quadric(&self, inside: bool) -> Option<crate::mesh::Mesh> {
        use crate::mesh::{cylinder, sphere};
        match self.object {
            ObjectKind::Sphere if inside => {
                Some(sphere::glu_sphere_inside(0.5, self.sphere_slices, self.sphere_stacks))
            }
            ObjectKind::Sphere => Some(sphere::glu_sphere(0.5, self.sphere_slices, self.sphere_stacks)),
            ObjectKind::Cylinder => {
                let (slices, stacks, caps) = (self.cylinder_slices, self.cylinder_stacks, self.cylinder_caps);
                let mut c = if inside {
                    cylinder::glu_cylinder_inside(0.3, 0.3, 0.5, slices, stacks, caps)
                } else {
                    cylinder::glu_cylinder(0.3, 0.3, 0.5, slices, stacks, caps)
                };
                // gluCylinder runs from z = 0 to z = h; centred unless drawn as the demo does.
                if self.cylinder_centered {
                    for p in &mut c.positions {
                        p.z -= 0.25;
                    }
                }
                Some(c)
            }
            ObjectKind::Teapot | ObjectKind::Obj => None,
        }
    }

    /// The OBJ file's mesh and notes (read once per modification), or why it cannot be used.
    pub fn obj_mesh(&self) -> Result<std::sync::Arc<crate::mesh::obj::LoadedObj>, SceneError> {
        let path = self.obj.as_deref().ok_or_else(|| SceneError::Mesh {
            field: "view.obj".into(),
            message: "the object is a mesh file, but no file is given".into(),
        })?;
        crate::mesh::obj::load_obj_cached(std::path::Path::new(path))
            .map_err(|message| SceneError::Mesh { field: "view.obj".into(), message })
    }

    /// Refuses a tessellation outside the ranges above, a non-finite spin, and a mesh file
    /// that cannot be read.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.object == ObjectKind::Obj {
            self.obj_mesh()?;
        }
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
        if let Some((i, v)) = self.background.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(SceneError::NotFinite { field: format!("view.background[{i}]"), value: *v as f64 });
        }
        let c = &self.camera;
        for (f, v) in [
            ("view.spin_degrees", self.spin_degrees),
            ("view.camera.yaw", c.yaw),
            ("view.camera.pitch", c.pitch),
            ("view.camera.distance", c.distance),
        ] {
            if !v.is_finite() {
                return Err(SceneError::NotFinite { field: f.into(), value: v });
            }
        }
        if !(-89.0..=89.0).contains(&c.pitch) {
            return Err(SceneError::OutOfRange {
                field: "view.camera.pitch".into(),
                value: c.pitch,
                allowed: "[-89, 89]",
            });
        }
        if !(0.6..=20.0).contains(&c.distance) {
            return Err(SceneError::OutOfRange {
                field: "view.camera.distance".into(),
                value: c.distance,
                allowed: "[0.6, 20]",
            });
        }
        Ok(())
    }
}

impl View {
    /// The object's spin: [`demo_spin`] of `spin_degrees`.
    pub fn spin(&self) -> glam::DMat4 {
        demo_spin(self.spin_degrees)
    }

    /// World to clip space: the orbit camera and its projection, or nothing (clip space).
    pub fn clip_from_world(&self) -> glam::DMat4 {
        match self.framing {
            Framing::Orbit => view_projection(1.0) * self.camera.eye_from_world(),
            Framing::ClipSpace => glam::DMat4::IDENTITY,
        }
    }

    /// Where the view draws the object: object to clip space (the orbit camera's
    /// projection, camera and spin; or the demo's spin alone). It does not depend on where
    /// the object is lit.
    pub fn clip_from_object(&self) -> glam::DMat4 {
        match self.framing {
            Framing::Orbit => view_projection(1.0) * (self.camera.eye_from_world() * self.spin()),
            Framing::ClipSpace => self.spin(),
        }
    }
}
