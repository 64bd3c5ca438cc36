//! egui without a GPU: runs a UI function headless and paints egui's triangles into an
//! RGBA image on the CPU. Used to write charts as PNGs from the command line
//! (`phonglab cost`) and to time the UI's own CPU work per frame (`phonglab bench ui`).
//!
//! Painting follows egui's renderers: vertex colours and textures are premultiplied,
//! in gamma space; a fragment is `vertex colour x texture sample` (bilinear), blended as
//! `dst = src + (1 - src.a) dst`. Anti-aliasing comes from egui's feathered edges.

use std::collections::HashMap;

use egui::epaint::textures::TexturesDelta;
use egui::epaint::{ClippedPrimitive, ImageData, Primitive, TextureId};
use egui::{Color32, ColorImage, Context, RawInput, Rect, Ui, pos2, vec2};

/// An RGBA8 image (premultiplied, gamma space) that egui output is painted into.
pub struct Canvas {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// `width * height` pixels, rows from the top, as f32 rgba in [0, 1].
    pixels: Vec<[f32; 4]>,
    textures: HashMap<TextureId, ColorImage>,
}

impl Canvas {
    /// A canvas filled with `background`.
    pub fn new(width: usize, height: usize, background: Color32) -> Self {
        let c = background.to_array().map(|x| x as f32 / 255.0);
        Self { width, height, pixels: vec![c; width * height], textures: HashMap::new() }
    }

    /// Applies egui's texture changes (the font atlas, images).
    pub fn apply_textures(&mut self, delta: &TexturesDelta) {
        for (id, deltas) in &delta.set {
            for d in deltas {
                let ImageData::Color(img) = &d.image;
                match d.pos {
                    None => {
                        self.textures.insert(*id, (**img).clone());
                    }
                    Some([x0, y0]) => {
                        let Some(t) = self.textures.get_mut(id) else { continue };
                        for y in 0..img.size[1] {
                            for x in 0..img.size[0] {
                                let (tx, ty) = (x0 + x, y0 + y);
                                if tx < t.size[0] && ty < t.size[1] {
                                    t.pixels[ty * t.size[0] + tx] = img.pixels[y * img.size[0] + x];
                                }
                            }
                        }
                    }
                }
            }
        }
        for id in &delta.free {
            self.textures.remove(id);
        }
    }

    /// Bilinear sample of texture `id` at `uv` (normalised), premultiplied rgba.
    fn sample(&self, id: TextureId, u: f32, v: f32) -> [f32; 4] {
        let Some(t) = self.textures.get(&id) else { return [1.0; 4] };
        let [w, h] = t.size;
        if w == 0 || h == 0 {
            return [1.0; 4];
        }
        let x = (u * w as f32 - 0.5).clamp(0.0, (w - 1) as f32);
        let y = (v * h as f32 - 0.5).clamp(0.0, (h - 1) as f32);
        let (x0, y0) = (x.floor() as usize, y.floor() as usize);
        let (x1, y1) = ((x0 + 1).min(w - 1), (y0 + 1).min(h - 1));
        let (fx, fy) = (x - x0 as f32, y - y0 as f32);
        let px = |x: usize, y: usize| t.pixels[y * w + x].to_array().map(|c| c as f32 / 255.0);
        let (a, b, c, d) = (px(x0, y0), px(x1, y0), px(x0, y1), px(x1, y1));
        [0, 1, 2, 3].map(|k| {
            let top = a[k] + (b[k] - a[k]) * fx;
            let bottom = c[k] + (d[k] - c[k]) * fx;
            top + (bottom - top) * fy
        })
    }

    /// Paints tessellated egui output (`pixels_per_point` from points to pixels).
    pub fn paint(&mut self, primitives: &[ClippedPrimitive], pixels_per_point: f32) {
        for p in primitives {
            let Primitive::Mesh(mesh) = &p.primitive else { continue };
            let clip = Rect::from_min_max(
                (p.clip_rect.min.to_vec2() * pixels_per_point).to_pos2(),
                (p.clip_rect.max.to_vec2() * pixels_per_point).to_pos2(),
            )
            .intersect(Rect::from_min_size(pos2(0.0, 0.0), vec2(self.width as f32, self.height as f32)));
            if !clip.is_positive() {
                continue;
            }
            for tri in mesh.indices.chunks_exact(3) {
                let v = [0, 1, 2].map(|k| &mesh.vertices[tri[k] as usize]);
                self.triangle(v, mesh.texture_id, clip, pixels_per_point);
            }
        }
    }

    fn triangle(&mut self, v: [&egui::epaint::Vertex; 3], texture: TextureId, clip: Rect, ppp: f32) {
        let p = v.map(|v| (v.pos.to_vec2() * ppp).to_pos2());
        let area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
        if area.abs() < 1e-12 {
            return;
        }
        let x0 = p.iter().map(|q| q.x).fold(f32::INFINITY, f32::min).max(clip.min.x).floor().max(0.0) as usize;
        let x1 =
            (p.iter().map(|q| q.x).fold(f32::NEG_INFINITY, f32::max).min(clip.max.x).ceil() as usize).min(self.width);
        let y0 = p.iter().map(|q| q.y).fold(f32::INFINITY, f32::min).max(clip.min.y).floor().max(0.0) as usize;
        let y1 =
            (p.iter().map(|q| q.y).fold(f32::NEG_INFINITY, f32::max).min(clip.max.y).ceil() as usize).min(self.height);
        let colors = v.map(|v| v.color.to_array().map(|c| c as f32 / 255.0));
        for y in y0..y1 {
            for x in x0..x1 {
                let c = pos2(x as f32 + 0.5, y as f32 + 0.5);
                if !clip.contains(c) {
                    continue;
                }
                let e = |a: egui::Pos2, b: egui::Pos2| (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
                let w = [e(p[1], p[2]) / area, e(p[2], p[0]) / area, e(p[0], p[1]) / area];
                if w.iter().any(|w| *w < 0.0) {
                    continue;
                }
                let u = w[0] * v[0].uv.x + w[1] * v[1].uv.x + w[2] * v[2].uv.x;
                let t = w[0] * v[0].uv.y + w[1] * v[1].uv.y + w[2] * v[2].uv.y;
                let tex = self.sample(texture, u, t);
                let src =
                    [0, 1, 2, 3].map(|k| (w[0] * colors[0][k] + w[1] * colors[1][k] + w[2] * colors[2][k]) * tex[k]);
                let dst = &mut self.pixels[y * self.width + x];
                for k in 0..4 {
                    dst[k] = src[k] + (1.0 - src[3]) * dst[k];
                }
            }
        }
    }

    /// The image as RGBA8 (opaque where the background was).
    pub fn rgba8(&self) -> Vec<u8> {
        self.pixels.iter().flat_map(|p| p.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8)).collect()
    }
}

/// One headless frame: input for a `width` x `height` point screen at `pixels_per_point`.
pub fn raw_input(width: f32, height: f32, pixels_per_point: f32) -> RawInput {
    let mut input =
        RawInput { screen_rect: Some(Rect::from_min_size(pos2(0.0, 0.0), vec2(width, height))), ..RawInput::default() };
    input.viewports.entry(egui::ViewportId::ROOT).or_default().native_pixels_per_point = Some(pixels_per_point);
    input
}

/// Runs `ui_fn` for six frames a tenth of a second apart (so layout and animations settle) on a `width` x `height` point screen
/// and paints the last frame at `pixels_per_point`.
pub fn paint_ui(width: f32, height: f32, pixels_per_point: f32, mut ui_fn: impl FnMut(&mut Ui)) -> Canvas {
    let ctx = Context::default();
    ctx.set_visuals(egui::Visuals::light());
    let mut canvas = Canvas::new(
        (width * pixels_per_point).round() as usize,
        (height * pixels_per_point).round() as usize,
        ctx.global_style().visuals.panel_fill,
    );
    let mut last = None;
    // A tenth of a second between frames, so that fades and openings (a window appearing)
    // have finished by the last one.
    for frame in 0..6 {
        let mut input = raw_input(width, height, pixels_per_point);
        input.time = Some(frame as f64 * 0.1);
        let mut out = ctx.run_ui(input, &mut ui_fn);
        let mut delta = std::mem::take(&mut out.textures_delta);
        canvas.apply_textures(&delta);
        delta.clear(); // applied above (egui checks that deltas are not dropped unseen)
        last = Some(out);
    }
    if let Some(out) = last {
        let prims = ctx.tessellate(out.shapes, out.pixels_per_point);
        canvas.paint(&prims, out.pixels_per_point);
    }
    canvas
}
