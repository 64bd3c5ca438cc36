//! What a picture is drawn from, owned: the scene, the mesh, the camera, the shading; each
//! picture mistake changes one and draws it again.

use crate::equation::lighting::EvalOptions;
use crate::mesh::Mesh;
use crate::model::error::SceneError;
use crate::model::scene::Scene;
use crate::model::view::ShadingMode;
use crate::raster::render::{Job, Renderer};

/// Everything a picture is drawn from, owned: the renderer's [`Job`] without the borrows.
#[derive(Clone, Debug)]
pub struct Drawing {
    /// The lighting state and the modelview the object is lit under.
    pub scene: Scene,
    /// The mesh, object space.
    pub mesh: Mesh,
    /// Object to clip space.
    pub clip_from_object: glam::DMat4,
    /// The shading.
    pub mode: ShadingMode,
    /// The background colour (linear, as written).
    pub background: [f32; 3],
    /// Numerical options.
    pub options: EvalOptions,
    /// `GL_DEPTH_TEST` on (the export enables it).
    pub depth_test: bool,
    /// The mesh as GLU draws it turned inside out (`GLU_INSIDE`), where the object is a
    /// GLU quadric ([`crate::model::view::View::mesh_inside`]); `None` otherwise.
    pub inside: Option<Mesh>,
}

impl Drawing {
    /// The drawing of `job`.
    pub fn of(job: &Job<'_>) -> Drawing {
        Drawing {
            scene: job.scene.clone(),
            mesh: job.mesh.clone(),
            clip_from_object: job.clip_from_object,
            mode: job.mode,
            background: job.background,
            options: job.options,
            depth_test: job.depth_test,
            inside: None,
        }
    }

    /// The renderer's job for it.
    pub fn job(&self) -> Job<'_> {
        Job {
            scene: &self.scene,
            mesh: &self.mesh,
            clip_from_object: self.clip_from_object,
            mode: self.mode,
            background: self.background,
            cull_back: false,
            depth_test: self.depth_test,
            options: self.options,
        }
    }

    /// Drawn `size` pixels square: the renderer (its visibility kept, for probing), the
    /// pixels (RGBA8) and which pixels the object covers.
    pub fn draw(&self, size: usize) -> Result<(Renderer, Vec<u8>, Vec<bool>), SceneError> {
        let mut r = Renderer::new();
        r.keep_visibility(true);
        let rgba = r.render(&self.job(), size, size)?.0.rgba.clone();
        let covered = (0..size * size).map(|i| r.surface_at(i).is_some()).collect();
        Ok((r, rgba, covered))
    }

    /// The background as 8-bit levels.
    pub fn background8(&self) -> [u8; 3] {
        self.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)
    }
}
