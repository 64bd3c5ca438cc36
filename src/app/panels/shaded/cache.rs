//! The shaded view's pictures kept between frames: each a renderer, its mesh and its
//! texture, re-rendered only when what it shows changes. Kept apart from the panel
//! ([`crate::app::panels::shaded`]) so the app state can hold it without depending on the panel.

use std::sync::{Arc, Mutex};

use egui::{ColorImage, TextureHandle, TextureOptions};
use phonglab_core::mesh::Mesh;
use phonglab_core::render::Renderer;
use phonglab_core::{Document, EvalOptions, PowFn, Scene, Shading, View};

use crate::app::panels::shaded::channel_view::ChannelView;
use crate::app::panels::shaded::gpu::GpuImage;

/// What a picture shows: a document, and its view's mesh looked up once for the frame
/// ([`mesh_for`]) and handed to everything that draws, picks or probes it.
#[derive(Clone, Copy)]
pub struct Viewed<'a> {
    /// The document.
    pub doc: &'a Document,
    /// Its view's mesh (the whole mesh, never the coarse copy).
    pub mesh: &'a Arc<Mesh>,
}

/// One picture's renderer, mesh and texture, kept between frames.
#[derive(Default)]
pub struct ViewCache {
    pub(crate) renderer: Renderer,
    pub(crate) mesh: Option<(View, Arc<Mesh>)>,
    pub(crate) texture: Option<TextureHandle>,
    /// What the texture shows; re-rendered only when it changes.
    key: Option<PictureKey>,
    /// The last frame's render time in milliseconds (on the CPU).
    pub last_ms: f64,
    /// The last CPU picture was drawn from the coarse copy of the mesh, while the camera
    /// turned or the object spun.
    pub last_coarse: Option<Coarse>,
    /// The orbit camera is being turned by a drag on the picture: a mesh of more than
    /// [`COARSE_ABOVE`] triangles is drawn from its coarse copy until the drag ends (and
    /// while the object spins by itself).
    pub(crate) turning: bool,
    /// The coarse copy of the view's mesh (the mesh it was made from, and the copy).
    coarse: Option<(Arc<Mesh>, Arc<Mesh>)>,
    /// The last CPU picture only lit the last one's triangles again (nothing drawn had
    /// moved: the light, the material or the colours changed), so it took a fraction of a
    /// whole frame.
    pub last_relit: bool,
    /// The last picture's pixels (RGBA8, `image_px()` square), for Compare's difference.
    pub(crate) rgba: Vec<u8>,
    /// How many pictures this cache has drawn: a picture derived from it (the difference)
    /// is made again when this changes.
    pub(crate) generation: u64,
    /// Who drew the last picture: the GPU (the adapter's name) or the CPU renderer (and
    /// why not the GPU).
    pub drawn_by: DrawnBy,
    /// The generated program of the last GPU picture.
    gpu_program: Option<GpuProgram>,
    /// A failure of the GPU picture reported by its paint callback, with the program that
    /// failed (that program is not tried again).
    gpu_error: Arc<Mutex<Option<String>>>,
    failed_program: Option<Arc<str>>,
}

/// A picture drawn from the coarse copy of a large mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Coarse {
    /// The copy's triangles.
    pub triangles: usize,
    /// The whole mesh's.
    pub of: usize,
    /// The object spun by itself (auto-rotate) rather than the camera being turned.
    pub spinning: bool,
}

/// Who drew a picture of the shaded view.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum DrawnBy {
    /// Nothing drawn yet.
    #[default]
    Nothing,
    /// The core's CPU renderer, and why not the GPU.
    Cpu {
        /// Why the GPU did not draw it.
        why: String,
    },
    /// The scene's generated WGSL on the GPU, through a paint callback.
    Gpu {
        /// The adapter's name and API.
        adapter: String,
    },
}

/// The shaded view's pictures: the document's, and the corrected one beside it when the
/// Phong demo's departures are being corrected.
#[derive(Default)]
pub struct ShadedCache {
    /// The document's own picture.
    pub main: ViewCache,
    /// The corrected picture (the right half of the comparison).
    pub corrected: ViewCache,
    /// The term shown instead of the picture, when one is.
    pub channel: ChannelView,
}

impl ShadedCache {
    /// The last frame's render time of the main picture, in milliseconds.
    pub fn last_ms(&self) -> f64 {
        self.main.last_ms
    }
}

impl ViewCache {
    /// The last CPU picture's pixels (RGBA8, [`ViewCache::image_px`] square).
    pub fn rgba(&self) -> &[u8] {
        &self.rgba
    }

    /// The side of the last picture, in pixels (0 before the first).
    pub fn image_px(&self) -> usize {
        self.texture.as_ref().map_or(0, |t| t.size()[0])
    }

    /// Renders the shaded view of `viewed` at `px` pixels square unless the texture
    /// already shows it. With `may_be_coarse`, while the camera turns
    /// ([`ViewCache::turning`]), a mesh of more than [`COARSE_ABOVE`] triangles is drawn
    /// from its coarse copy (the picture shown, never the one probed or picked, which pass
    /// `false`).
    pub(crate) fn render(
        &mut self,
        ctx: &egui::Context,
        viewed: Viewed<'_>,
        pow: PowFn,
        px: usize,
        name: &str,
        may_be_coarse: bool,
    ) -> Result<(), String> {
        let Viewed { doc, mesh: whole } = viewed;
        let setup = doc.shaded_setup(pow);
        let moving = may_be_coarse && (self.turning || doc.view.auto_rotate);
        let coarse = moving && whole.triangle_count() > COARSE_ABOVE;
        let key = PictureKey { scene: setup.scene.clone(), view: doc.view.clone(), px, pow, coarse };
        if self.key.as_ref() == Some(&key) && self.texture.is_some() {
            return Ok(());
        }
        let mesh = if coarse { self.coarse_copy(whole) } else { whole.clone() };
        let t = crate::platform::clock::Instant::now();
        let (img, stats) = self.renderer.render(&setup.job(&mesh), px, px).map_err(|e| e.to_string())?;
        self.last_ms = t.elapsed().as_secs_f64() * 1e3;
        self.last_relit = stats.visibility_kept;
        self.last_coarse = coarse.then(|| Coarse {
            triangles: mesh.triangle_count(),
            of: whole.triangle_count(),
            spinning: !self.turning,
        });
        let image = ColorImage::from_rgba_unmultiplied([img.width, img.height], &img.rgba);
        self.rgba.clone_from(&img.rgba);
        self.generation += 1;
        match &mut self.texture {
            Some(tex) => tex.set(image, TextureOptions::LINEAR),
            None => self.texture = Some(ctx.load_texture(name, image, TextureOptions::LINEAR)),
        }
        self.key = Some(key);
        Ok(())
    }

    /// The coarse copy of `whole` (made once per mesh, on the first turn of the camera).
    fn coarse_copy(&mut self, whole: &Arc<Mesh>) -> Arc<Mesh> {
        match &self.coarse {
            Some((of, copy)) if Arc::ptr_eq(of, whole) => copy.clone(),
            _ => {
                let copy = Arc::new(phonglab_core::mesh::coarse::clustered(whole, COARSE_TARGET));
                self.coarse = Some((whole.clone(), copy.clone()));
                copy
            }
        }
    }

    /// The GPU picture of the shaded view of `viewed` at `px` pixels square (slot `slot`),
    /// or why it cannot be drawn on the GPU (a program the driver refused is not tried
    /// again).
    pub(crate) fn gpu_picture(
        &mut self,
        viewed: Viewed<'_>,
        pow: PowFn,
        px: usize,
        slot: u64,
    ) -> Result<GpuImage, String> {
        let doc = viewed.doc;
        if let Some(e) = self.gpu_error.lock().unwrap_or_else(std::sync::PoisonError::into_inner).take() {
            self.failed_program = self.gpu_program.take().map(|p| p.wgsl);
            return Err(format!("the GPU refused the generated program: {e}"));
        }
        let setup = doc.shaded_setup(pow);
        let key = ProgramKey { scene: setup.scene.clone(), options: setup.options, shading: doc.view.shading };
        if self.gpu_program.as_ref().is_none_or(|p| p.key != key) {
            let shader = crate::paint::gpu::wgsl_for(&setup.scene, setup.options, doc.view.shading)?;
            // WGSL keeps both entry points in one module: `vertex`.
            self.gpu_program = Some(GpuProgram { key, wgsl: shader.vertex.into(), uniforms: shader.uniforms });
        }
        let program = self.gpu_program.as_ref().expect("set just above");
        if self.failed_program.as_ref() == Some(&program.wgsl) {
            return Err("the GPU refused the generated program".into());
        }
        let uniforms = crate::paint::gpu::uniform_bytes(&program.uniforms, &setup.scene, &setup.clip_from_object)?;
        let wgsl = program.wgsl.clone();
        Ok(GpuImage {
            slot,
            wgsl,
            uniforms,
            mesh: viewed.mesh.clone(),
            background: doc.view.background,
            px: px as u32,
            error: self.gpu_error.clone(),
        })
    }
}

/// What a picture shows (the scene as lit, the view, its size, the power function): it is
/// drawn again only when this changes. Compared by value (`PartialEq`): a NaN anywhere
/// never compares equal, so such a picture is simply drawn again.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PictureKey {
    scene: Scene,
    view: View,
    px: usize,
    pow: PowFn,
    /// Drawn from the mesh's coarse copy.
    coarse: bool,
}

/// Meshes of more triangles than this are drawn from a coarse copy while the camera turns
/// on the CPU: a whole frame of a million triangles is too slow to follow the mouse, a copy
/// of [`COARSE_TARGET`] is not (the figures: docs/performance.md, "A million triangles").
pub const COARSE_ABOVE: usize = 300_000;

/// About how many triangles the coarse copy keeps.
pub const COARSE_TARGET: usize = 150_000;

/// What a generated program was generated for.
#[derive(Clone, Debug, PartialEq)]
struct ProgramKey {
    scene: Scene,
    options: EvalOptions,
    shading: Shading,
}

/// A generated program kept between frames (regenerated when the scene changes; the GPU
/// pipeline is rebuilt only when its text does).
struct GpuProgram {
    /// The scene, options and shading it was generated for.
    key: ProgramKey,
    /// The WGSL module.
    wgsl: Arc<str>,
    /// Its uniforms, in order (as `Shader::uniforms`).
    uniforms: Vec<(String, &'static str)>,
}

thread_local! {
    /// How many times this thread looked a view's mesh up ([`mesh_for`]).
    static MESH_LOOKUPS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// How many times this thread has looked a view's mesh up ([`mesh_for`]): a frame's
/// count is the difference across it (the tests hold it to one a picture).
pub fn mesh_lookups() -> u64 {
    MESH_LOOKUPS.with(std::cell::Cell::get)
}

/// The view's mesh, rebuilt only when what shapes it changes.
pub fn mesh_for<'a>(cache: &'a mut Option<(View, Arc<Mesh>)>, view: &View) -> &'a Arc<Mesh> {
    MESH_LOOKUPS.with(|n| n.set(n.get() + 1));
    let stale = cache.as_ref().is_none_or(|(v, _)| {
        let mut a = v.clone();
        let mut b = view.clone();
        // Only what changes the geometry matters.
        for v in [&mut a, &mut b] {
            v.shading = Shading::Gouraud;
            v.auto_rotate = false;
            v.spin_degrees = 0.0;
            v.camera = Default::default();
            v.framing = Default::default();
            v.lighting_space = Default::default();
            v.flat_normal = Default::default();
            v.phong_renormalize = true;
            v.background = [0.0; 3];
        }
        a != b
    });
    if stale {
        *cache = Some((view.clone(), Arc::new(view.mesh())));
    }
    &cache.as_ref().expect("set just above").1
}
