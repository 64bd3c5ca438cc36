//! The benchmark scene timed: docs/lighting.md's sphere and teapot drawn frame after frame
//! by the CPU renderer, each stage's time kept (what `phonglab bench render` prints, and
//! the browser's `?picture=bench` page measures).

use web_time::Instant;

use crate::mesh::{Mesh, sphere, teapot};
use crate::model::error::SceneError;
use crate::model::presets::bench_scene;
use crate::model::view::Shading;
use crate::raster::render::Renderer;

/// The benchmark's objects: gluSphere(1, 50, 50) and glutSolidTeapot(0.8).
pub fn bench_meshes() -> [(&'static str, Mesh); 2] {
    bench_meshes_with(50)
}

/// The benchmark's objects with the sphere cut into `slices` slices and stacks.
pub fn bench_meshes_with(slices: u32) -> [(&'static str, Mesh); 2] {
    [("sphere", sphere::glu_sphere(1.0, slices, slices)), ("teapot", teapot::glut_teapot(0.8, 7))]
}

/// One figure of `bench render`.
pub struct RenderFigure {
    /// "sphere" or "teapot".
    pub object: &'static str,
    /// The shading.
    pub shading: Shading,
    /// Mean milliseconds per frame.
    pub ms_per_frame: f64,
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Share of pixels covered.
    pub coverage: f64,
    /// Mean milliseconds of each stage: vertices, setup, raster, resolve.
    pub stage_ms: [f64; 4],
    /// Timed frames that kept the last frame's visibility (only the lighting changed).
    pub frames_kept: u32,
}

/// What changes from frame to frame of `bench render`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Moving {
    /// The object turns 3 degrees a frame (docs/lighting.md's benchmark): every frame is
    /// drawn whole.
    #[default]
    Object,
    /// The object stands (at the benchmark's first frame) and the light circles it, 3
    /// degrees a frame, as when a student drags the light: every frame after the first
    /// keeps the visibility and is lit and shaded again.
    Light,
}

/// The benchmark scene of frame `i` with `moving` moving.
pub fn moving_scene(moving: Moving, i: u32) -> crate::model::scene::Scene {
    match moving {
        Moving::Object => bench_scene(i),
        Moving::Light => {
            let mut scene = bench_scene(0);
            let p = scene.lights[0].position;
            let turn = glam::DMat4::from_rotation_y((3.0 * i as f64).to_radians());
            scene.lights[0].position = turn * p;
            scene
        }
    }
}

/// Times the renderer on the benchmark scene, for each object and shading that `only`
/// accepts.
pub fn render_figures(
    frames: u32,
    size: usize,
    only: impl Fn(&str, Shading) -> bool,
) -> Result<Vec<RenderFigure>, SceneError> {
    render_figures_of(bench_meshes(), frames, size, Moving::Object, only)
}

/// [`render_figures`] over `meshes` (the sphere of another tessellation).
pub fn render_figures_of(
    meshes: impl IntoIterator<Item = (&'static str, Mesh)>,
    frames: u32,
    size: usize,
    moving: Moving,
    only: impl Fn(&str, Shading) -> bool,
) -> Result<Vec<RenderFigure>, SceneError> {
    let mut out = Vec::new();
    for (name, mesh) in meshes {
        for shading in Shading::ALL.into_iter().filter(|s| only(name, *s)) {
            let mut r = Renderer::new();
            let frame = |i: u32, r: &mut Renderer| -> Result<crate::raster::render::Stats, SceneError> {
                let scene = moving_scene(moving, i);
                let job = crate::raster::shaded::bench_job(&scene, &mesh, shading);
                Ok(r.render(&job, size, size)?.1)
            };
            for i in 0..5 {
                frame(i, &mut r)?;
            }
            let t = Instant::now();
            let (mut stages, mut frames_kept) = ([0.0; 4], 0);
            for i in 0..frames {
                let s = frame(i, &mut r)?;
                for (sum, ms) in stages.iter_mut().zip(s.stage_ms) {
                    *sum += ms / frames.max(1) as f64;
                }
                frames_kept += s.visibility_kept as u32;
            }
            let ms = t.elapsed().as_secs_f64() * 1e3 / frames.max(1) as f64;
            // Measured after the timed frames: counting pixels is not part of a frame.
            let scene = moving_scene(moving, frames);
            let job = crate::raster::shaded::bench_job(&scene, &mesh, shading);
            let coverage = r.render(&job, size, size)?.0.coverage();
            out.push(RenderFigure {
                object: name,
                shading,
                ms_per_frame: ms,
                triangles: mesh.triangle_count(),
                coverage,
                stage_ms: stages,
                frames_kept,
            });
        }
    }
    Ok(out)
}
