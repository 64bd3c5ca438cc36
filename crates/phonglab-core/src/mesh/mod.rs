//! Triangle meshes in object space: gluSphere, gluCylinder, the Utah teapot, OBJ files.
//!
//! Triangles are counter-clockwise seen from outside (OpenGL's default front face);
//! normals are unit length and point outward.

pub mod bumpy_sphere;
pub mod coarse;
pub mod cylinder;
pub mod obj;
pub mod obj_text;
pub mod sphere;
pub mod teapot;
pub mod weld;

use glam::Vec3;

/// An indexed triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions, object space.
    pub positions: Vec<Vec3>,
    /// Unit vertex normals, object space.
    pub normals: Vec<Vec3>,
    /// Triangles as vertex indices, counter-clockwise from outside.
    pub triangles: Vec<[u32; 3]>,
    /// Each triangle's provoking vertex, where OpenGL's `glShadeModel(GL_FLAT)` takes the
    /// colour for the whole triangle from another vertex than its last corner: the last
    /// vertex of the primitive as GLU or GLUT sends it (a quad strip's quad gives both its
    /// triangles its fourth vertex, which one of them may not have as a corner). Empty:
    /// every triangle's last corner ([`Mesh::provoking_vertex`]).
    pub provoking: Vec<u32>,
}

impl Mesh {
    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Triangle `t`'s provoking vertex: the one whose colour `GL_FLAT` gives it.
    pub fn provoking_vertex(&self, t: usize) -> u32 {
        match (self.provoking.get(t), self.triangles.get(t)) {
            (Some(&v), _) if (v as usize) < self.positions.len() => v,
            (_, Some(tri)) => tri[2],
            _ => 0,
        }
    }

    /// Appends a vertex, returning its index.
    pub fn push_vertex(&mut self, p: Vec3, n: Vec3) -> u32 {
        self.positions.push(p);
        self.normals.push(n);
        (self.positions.len() - 1) as u32
    }

    /// The demo's shortcut: every normal replaced by normalize(position). Right for a
    /// sphere about the origin, wrong for the teapot and the cylinder (shown on purpose).
    pub fn with_position_normals(mut self) -> Self {
        for (n, p) in self.normals.iter_mut().zip(&self.positions) {
            *n = p.try_normalize().unwrap_or(Vec3::Z);
        }
        // Drawn as phonglab's own triangles (the export sends its arrays): each triangle's
        // last corner provokes.
        self.provoking.clear();
        self
    }

    /// The vertex nearest to `p` (object space), if any.
    pub fn nearest_vertex(&self, p: Vec3) -> Option<usize> {
        self.positions
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.distance_squared(p).total_cmp(&b.1.distance_squared(p)))
            .map(|(i, _)| i)
    }
}
