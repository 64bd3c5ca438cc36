//! The shaded view's pictures kept between frames: each a renderer, its mesh and its
//! texture, re-rendered only when what it shows changes. Kept apart from the panel
//! ([`super::shaded`]) so the app state can hold it without depending on the panel.

use egui::{ColorImage, TextureHandle, TextureOptions};
use phonglab_core::mesh::Mesh;
use phonglab_core::render::Renderer;
use phonglab_core::{Document, PowFn, Shading, View};

/// One picture's renderer, mesh and texture, kept between frames.
#[derive(Default)]
pub struct ViewCache {
    pub(crate) renderer: Renderer,
    pub(crate) mesh: Option<(View, Mesh)>,
    pub(crate) texture: Option<TextureHandle>,
    /// What the texture shows; re-rendered only when it changes.
    key: Option<String>,
    /// The last frame's render time in milliseconds.
    pub last_ms: f64,
}

/// The shaded view's pictures: the document's, and the corrected one beside it when the
/// Phong demo's departures are being corrected.
#[derive(Default)]
pub struct ShadedCache {
    /// The document's own picture.
    pub main: ViewCache,
    /// The corrected picture (the right half of the comparison).
    pub corrected: ViewCache,
}

impl ShadedCache {
    /// The last frame's render time of the main picture, in milliseconds.
    pub fn last_ms(&self) -> f64 {
        self.main.last_ms
    }
}

impl ViewCache {
    /// The side of the last picture, in pixels (0 before the first).
    pub fn image_px(&self) -> usize {
        self.texture.as_ref().map_or(0, |t| t.size()[0])
    }

    /// Renders `doc`'s shaded view at `px` pixels square unless the texture already shows it.
    pub(crate) fn render(
        &mut self,
        ctx: &egui::Context,
        doc: &Document,
        pow: PowFn,
        px: usize,
        name: &str,
    ) -> Result<(), String> {
        let setup = doc.shaded_setup(pow);
        let key = format!("{:?}|{:?}|{px}|{pow:?}", setup.scene, doc.view);
        if self.key.as_deref() == Some(key.as_str()) && self.texture.is_some() {
            return Ok(());
        }
        let mesh = mesh_for(&mut self.mesh, &doc.view);
        let t = std::time::Instant::now();
        let (img, _) = self.renderer.render(&setup.job(mesh), px, px).map_err(|e| e.to_string())?;
        self.last_ms = t.elapsed().as_secs_f64() * 1e3;
        let image = ColorImage::from_rgba_unmultiplied([img.width, img.height], &img.rgba);
        match &mut self.texture {
            Some(tex) => tex.set(image, TextureOptions::LINEAR),
            None => self.texture = Some(ctx.load_texture(name, image, TextureOptions::LINEAR)),
        }
        self.key = Some(key);
        Ok(())
    }
}

/// The view's mesh, rebuilt only when what shapes it changes.
pub fn mesh_for<'a>(cache: &'a mut Option<(View, Mesh)>, view: &View) -> &'a Mesh {
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
        *cache = Some((view.clone(), view.mesh()));
    }
    &cache.as_ref().expect("set just above").1
}
