//! A document's shaded view, set up for the renderer: the scene as the view lights it (eye
//! space, or the demo's object space), where the view draws the object, and the options.
//! One setup for the app, the CLI and the cost study, so they all draw the same picture.

use crate::model::view::ShadingMode;
use crate::model::view::{Framing, LightingSpace, View};

/// Everything the renderer needs to draw a document's shaded view: one setup for the app,
/// the CLI and the cost study, so they all draw the same picture.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadedSetup {
    /// The lighting state, with the modelview the object is lit under.
    pub scene: crate::model::scene::Scene,
    /// Where it is drawn.
    pub clip_from_object: glam::DMat4,
    /// The view it came from.
    pub view: View,
    /// Numerical options.
    pub options: crate::equation::lighting::EvalOptions,
}

impl ShadedSetup {
    /// The render job for `mesh` (the view's mesh, usually).
    pub fn job<'a>(&'a self, mesh: &'a crate::mesh::Mesh) -> crate::raster::render::Job<'a> {
        crate::raster::render::Job {
            scene: &self.scene,
            mesh,
            clip_from_object: self.clip_from_object,
            mode: ShadingMode::of(self.view.shading, self.view.flat_normal),
            background: self.view.background,
            cull_back: false,
            depth_test: true,
            options: self.options,
        }
    }
}

impl crate::formats::document::Document {
    /// The scene as the shaded view lights it. In eye space (OpenGL): the document's
    /// lighting under the view's camera (the orbit camera, or in clip space the document's
    /// own), with the object spun. In object space (the demo): the document's scene as it
    /// is, spin left out.
    pub fn shaded_scene(&self) -> crate::model::scene::Scene {
        let mut s = self.scene.clone();
        if self.view.lighting_space == LightingSpace::Eye {
            if self.view.framing == Framing::Orbit {
                s.eye_from_world = self.view.camera.eye_from_world();
            }
            s.world_from_object = self.view.spin();
        }
        s
    }

    /// The shaded view's whole setup with power function `pow`.
    pub fn shaded_setup(&self, pow: crate::numerics::pow::PowFn) -> ShadedSetup {
        ShadedSetup {
            scene: self.shaded_scene(),
            clip_from_object: self.view.clip_from_object(),
            view: self.view.clone(),
            options: self.view.eval_options(pow),
        }
    }

    /// This document with the worked calculation moved to `vertex` (object space) as the
    /// shaded view lights it: the same camera and spin, so both panels show one vertex.
    pub fn with_vertex_as_shaded(&self, vertex: crate::model::scene::Vertex) -> crate::formats::document::Document {
        let mut d = self.clone();
        let s = self.shaded_scene();
        d.scene.vertex = vertex;
        if s.eye_from_world != d.scene.eye_from_world {
            d.camera = crate::model::camera::CameraSpec::Matrix(s.eye_from_world);
            d.scene.eye_from_world = s.eye_from_world;
        }
        d.scene.world_from_object = s.world_from_object;
        d
    }
}

/// The benchmark's render job for `scene` (a [`crate::model::presets::bench_scene`] frame): its projection, Flat
/// per face, no culling, exact pow.
pub fn bench_job<'a>(
    scene: &'a crate::model::scene::Scene,
    mesh: &'a crate::mesh::Mesh,
    shading: crate::model::view::Shading,
) -> crate::raster::render::Job<'a> {
    crate::raster::render::Job {
        scene,
        mesh,
        clip_from_object: crate::model::presets::bench_projection() * scene.eye_from_object(),
        mode: ShadingMode::of(shading, crate::model::view::FlatNormal::Face),
        background: crate::model::presets::BENCH_BACKGROUND,
        cull_back: false,
        depth_test: true,
        options: crate::equation::lighting::EvalOptions::default(),
    }
}
