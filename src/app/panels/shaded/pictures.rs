//! The shaded view's pictures: the view sized to the space it was given (whole pixels),
//! drawn by the GPU or the CPU, and beside it the demo corrected or the error heat map.

use egui::{Sense, Ui};
use phonglab_core::library::DemoDeparture;
use phonglab_core::{Document, t};

use super::cache::{DrawnBy, ShadedCache, ViewCache, mesh_for};
use super::channel_view::{legend_height, legend_ui};
use super::context::{Shaded, corrected_document};
use super::gpu::{self, GpuImage};
use super::heat_map::heat_map_ui;
use crate::app::model::message::Message;

/// What [`pictures_ui`] drew: the main picture's response and size, the second picture's
/// place (the demo corrected, or the heat map), and the scene as the view lights it.
pub(super) struct Shown {
    pub(super) response: egui::Response,
    pub(super) second: Option<egui::Rect>,
    /// The picture's side on screen, and in the renderer's pixels.
    pub(super) size: egui::Vec2,
    pub(super) px: usize,
    pub(super) scene: phonglab_core::Scene,
}

/// The pictures: the shaded view sized to the space it was given (whole pixels), drawn by
/// the GPU or the CPU, and beside it the demo corrected or the error heat map.
pub(super) fn pictures_ui(ui: &mut Ui, state: &mut Shaded<'_>, cache: &mut ShadedCache) -> Shown {
    // The corrected document, when a departure the document makes is switched off.
    let corrected = corrected_document(state.edit.doc, &state.view_options.demo_fixes);

    // The part of the centre this view was given (a row above cannot have widened it).
    let avail = egui::vec2(ui.max_rect().width(), ui.available_size().y);
    let heat = state.heat_map.on;
    let beside = heat || corrected.is_some();
    // Leave room for the caption line above the image (and the picture beside it).
    let width = if beside { (avail.x - 8.0) / 2.0 } else { avail.x };
    // Room for the caption's one line above the image (cut to the picture's width, whole in
    // its hover): a caption that wrapped took the picture's height.
    let channel = state.view_options.channel;
    let caption_room = ui.text_style_height(&egui::TextStyle::Small) + 8.0;
    // The legend wraps to the picture's width: sized at the width, then at the side found.
    let legend = |w: f32| channel.map_or(0.0, |c| legend_height(ui, c, w));
    let side = width.min(avail.y - caption_room - legend(width)).max(64.0);
    let side = width.min(avail.y - caption_room - legend(side)).max(64.0);
    let ppp = ui.ctx().pixels_per_point();
    let px = ((side * ppp) as usize).clamp(64, 1024);
    // One texel a screen pixel (no resampling), unless the view is wider than 1024 pixels.
    let side = if (side * ppp) as usize <= 1024 { px as f32 / ppp } else { side };
    let main = prepare_picture(ui.ctx(), state, &mut cache.main, state.edit.doc, px, 0, "shaded view");
    let mut main_gpu = picture_or_refusal(state, main, &t!("shaded-cannot-render"));
    let mut corrected_gpu = corrected.as_ref().and_then(|c| {
        let picture = prepare_picture(ui.ctx(), state, &mut cache.corrected, c, px, 1, "corrected view");
        picture_or_refusal(state, picture, &t!("corrected-cannot-render"))
    });
    // The scene as the view lights it, once: with the heat map on, from the setup it asks for.
    let scene = if heat {
        let setup = state.edit.doc.shaded_setup(state.pow);
        state.heat_map.want(&setup);
        setup.scene
    } else {
        state.edit.doc.shaded_scene()
    };
    let size = egui::vec2(side, side);
    let caption = format!(
        "{} {}: {}{}",
        state.edit.doc.view.object.label(),
        state.edit.doc.view.shading.label(),
        match channel {
            Some(c) => t!("channel-caption", channel = phonglab_core::locale::tr(c.message_id())),
            None => drawn_caption(&cache.main),
        },
        if corrected.is_some() { t!("the-demos-own") } else { String::new() }
    );
    let channel_texture = channel.and_then(|c| {
        let mesh = mesh_for(&mut cache.main.mesh, &state.edit.doc.view).clone();
        let view = &mut cache.channel;
        match view.prepare(state.edit.doc, &mesh, state.pow, c) {
            Ok(range) => view.texture(ui.ctx(), range).map(|t| (c, t.id())),
            Err(e) => {
                *state.edit.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
                None
            }
        }
    });
    let mut second = None;
    let resp = ui
        .horizontal_top(|ui| {
            let resp = ui
                .vertical(|ui| {
                    // Captions wrap within the picture's width rather than widen its column.
                    ui.set_max_width(side);
                    let label = caption_ui(ui, &caption);
                    let picture = match channel_texture {
                        Some((_, id)) => ui.add(egui::Image::new((id, size)).sense(Sense::click_and_drag())),
                        None => picture_ui(ui, &cache.main, main_gpu.take(), size, Sense::click_and_drag()),
                    }
                    .on_hover_text(t!("picture-hover"))
                    .labelled_by(label.id);
                    if let Some((c, _)) = channel_texture {
                        legend_ui(ui, c, cache.channel.range, side);
                    }
                    crate::app::widgets::fields::landmark(ui.ctx(), "shaded-picture", picture.rect);
                    picture
                })
                .inner;
            if corrected.is_some() {
                ui.vertical(|ui| {
                    ui.set_max_width(side);
                    let fixed: Vec<String> = DemoDeparture::ALL
                        .into_iter()
                        .zip(state.view_options.demo_fixes)
                        .filter(|(d, on)| *on && d.present_in(state.edit.doc))
                        .map(|(d, _)| d.fix_label())
                        .collect();
                    let label = caption_ui(ui, &t!("corrected", fixes = fixed.join(", ")));
                    let r = picture_ui(ui, &cache.corrected, corrected_gpu.take(), size, Sense::hover())
                        .labelled_by(label.id);
                    second = Some(r.rect);
                });
            } else if heat {
                second = Some(ui.scope(|ui| heat_map_ui(ui, state.heat_map, side)).response.rect);
            }
            resp
        })
        .inner;
    Shown { response: resp, second, size, px, scene }
}

/// A picture's caption: one small line, cut to the width with "…", the whole in its hover.
fn caption_ui(ui: &mut Ui, text: &str) -> egui::Response {
    let small = egui::RichText::new(text).small();
    ui.add(egui::Label::new(small).truncate()).on_hover_text(text)
}

/// Draws `doc`'s picture for `cache`: on the GPU when the adapter, the renderer choice and
/// the scene allow it (the picture to paint is returned), otherwise on the CPU renderer
/// (into `cache`'s texture). `cache.drawn_by` says which, and why not the GPU.
fn prepare_picture(
    ctx: &egui::Context,
    state: &Shaded<'_>,
    cache: &mut ViewCache,
    doc: &Document,
    px: usize,
    slot: u64,
    name: &str,
) -> Result<Option<GpuImage>, String> {
    let pow = state.pow;
    let why = match gpu::why_cpu(state.gpu, state.view_options.renderer, doc, pow) {
        Some(why) => why,
        None => match (cache.gpu_picture(doc, pow, px, slot), state.gpu) {
            (Ok(p), Some(gpu)) => {
                cache.drawn_by = DrawnBy::Gpu { adapter: format!("{}, {}", gpu.name, gpu.backend) };
                return Ok(Some(p));
            }
            (Ok(_), None) => t!("gpu-none"),
            (Err(e), _) => e,
        },
    };
    cache.render(ctx, doc, pow, px, name, true)?;
    cache.drawn_by = DrawnBy::Cpu { why };
    Ok(None)
}

/// The GPU picture [`prepare_picture`] made, if any; a failure becomes the message `what:
/// reason` (the view then shows the last picture it has).
fn picture_or_refusal(state: &mut Shaded<'_>, r: Result<Option<GpuImage>, String>, what: &str) -> Option<GpuImage> {
    r.unwrap_or_else(|e| {
        *state.edit.message = Some(Message::Refused(format!("{what}: {e}")));
        None
    })
}

/// The picture, `size` points: the GPU's through its paint callback, or the CPU
/// renderer's texture.
fn picture_ui(ui: &mut Ui, cache: &ViewCache, gpu: Option<GpuImage>, size: egui::Vec2, sense: Sense) -> egui::Response {
    match (gpu, &cache.texture) {
        (Some(p), _) => {
            let (rect, resp) = ui.allocate_exact_size(size, sense);
            gpu::paint(ui, rect, p);
            resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "shaded view (GPU)"));
            resp
        }
        (None, Some(tex)) => ui.add(egui::Image::new((tex.id(), size)).sense(sense)),
        (None, None) => ui.allocate_exact_size(size, sense).1,
    }
}

/// Who drew the picture, for its caption.
pub fn drawn_caption(cache: &ViewCache) -> String {
    match &cache.drawn_by {
        DrawnBy::Gpu { adapter } => t!("caption-gpu", adapter = adapter.to_string()),
        _ if let Some(c) = cache.last_coarse => {
            let (ms, triangles) = (fmt_ms(cache.last_ms), phonglab_core::locale::grouped(c.triangles as u64));
            let all = phonglab_core::locale::grouped(c.of as u64);
            match c.spinning {
                true => t!("caption-cpu-coarse-spin", ms = ms, triangles = triangles, all = all),
                false => t!("caption-cpu-coarse", ms = ms, triangles = triangles, all = all),
            }
        }
        _ if cache.last_relit => t!("caption-cpu-relit", ms = fmt_ms(cache.last_ms)),
        _ => t!("caption-cpu", ms = fmt_ms(cache.last_ms)),
    }
}

fn fmt_ms(ms: f64) -> String {
    phonglab_core::locale::decimal(&format!("{ms:.1}"))
}
