//! The shaded view's pictures: the view sized to the space it was given (whole pixels),
//! drawn by the GPU or the CPU, and beside it the demo corrected or the error heat map.

use std::sync::Arc;

use egui::{Sense, Ui};
use phonglab_core::mesh::Mesh;

use super::cache::{DrawnBy, ShadedCache, ViewCache, Viewed, mesh_for};
use super::captions::{Caption, CaptionRoom, caption_room, caption_ui, corrected_caption, main_caption};
use super::channel_view::{legend_height, legend_ui, name_id};
use super::context::{Shaded, corrected_document};
use super::gpu::{self, GpuImage};
use super::heat_map::heat_map_ui;
use crate::app::editing::message::Message;
use crate::t;

/// What [`pictures_ui`] drew: the main picture's response and size, the second picture's
/// place (the demo corrected, or the heat map), and the scene as the view lights it.
pub(super) struct Shown {
    pub(super) response: egui::Response,
    pub(super) second: Option<egui::Rect>,
    /// The picture's side on screen, and in the renderer's pixels.
    pub(super) size: egui::Vec2,
    pub(super) px: usize,
    pub(super) scene: phonglab_core::Scene,
    /// The view's mesh, looked up once for the frame: what the picture shows, and what the
    /// overlay picks and the probe probes on.
    pub(super) mesh: Arc<Mesh>,
}

/// The pictures: the shaded view sized to the space it was given (whole pixels), drawn by
/// the GPU or the CPU, and beside it the demo corrected or the error heat map. `mesh`: the
/// view's, looked up once for the frame.
pub(super) fn pictures_ui(ui: &mut Ui, state: &mut Shaded<'_>, cache: &mut ShadedCache, mesh: Arc<Mesh>) -> Shown {
    // The corrected document, when a departure the document makes is switched off.
    let corrected = corrected_document(state.edit.doc, &state.view_options.demo_fixes);

    // The part of the centre this view was given (a row above cannot have widened it).
    let avail = egui::vec2(ui.max_rect().width(), ui.available_size().y);
    let heat = state.heat_map.on;
    let beside = heat || corrected.is_some();
    // Leave room for the caption above the image (and the picture beside it).
    let width = if beside { (avail.x - 8.0) / 2.0 } else { avail.x };
    let channel = state.view_options.channel;
    // The legend wraps to the picture's width: sized at the side found so far.
    let channel_id = channel.map(|c| name_id(c, state.edit.doc, state.pow));
    let legend = |ui: &Ui, w: f32| channel.zip(channel_id).map_or(0.0, |(c, id)| legend_height(ui, c, id, w));
    // The captions' room: as tall as the tallest caption this view may show at the
    // picture's width, so the picture does not move when who drew it changes.
    let room = CaptionRoom { presenting: state.presenting, pair: beside };
    let mut side = width;
    let mut caption_h = 0.0;
    for _ in 0..3 {
        caption_h = caption_room(
            ui,
            (state.edit.doc, state.pow),
            state.view_options,
            &cache.main,
            mesh.triangle_count(),
            side,
            room,
        );
        side = width.min(avail.y - caption_h - 8.0 - legend(ui, side)).max(64.0);
    }
    let ppp = ui.ctx().pixels_per_point();
    let px = ((side * ppp) as usize).clamp(64, 1024);
    // One texel a screen pixel (no resampling), unless the view is wider than 1024 pixels.
    let side = if (side * ppp) as usize <= 1024 { px as f32 / ppp } else { side };
    let viewed = Viewed { doc: state.edit.doc, mesh: &mesh };
    let main = prepare_picture(ui.ctx(), state, &mut cache.main, viewed, px, 0, "shaded view");
    let mut main_gpu = picture_or_refusal(state, main, &t!("shaded-cannot-render"));
    let mut corrected_gpu = corrected.as_ref().and_then(|c| {
        // The corrected picture's own cache (its document is another).
        let mesh = mesh_for(&mut cache.corrected.mesh, &c.view).clone();
        let viewed = Viewed { doc: c, mesh: &mesh };
        let picture = prepare_picture(ui.ctx(), state, &mut cache.corrected, viewed, px, 1, "corrected view");
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
    let caption = main_caption(state.edit.doc, state.view_options, state.pow, &cache.main, room);
    let channel_texture = channel.and_then(|c| {
        let view = &mut cache.channel;
        match view.prepare(state.edit.doc, &mesh, state.pow, c) {
            Ok(range) => view.texture(ui.ctx(), range).map(|t| (c, t.id())),
            Err(e) => {
                *state.edit.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
                None
            }
        }
    });
    // Where the caption is short, the whole is said in the picture's hover.
    let hover = if caption.shown == caption.whole {
        t!("picture-hover")
    } else {
        format!("{}\n{}", caption.whole, t!("picture-hover"))
    };
    let mut second = None;
    let resp = ui
        .horizontal_top(|ui| {
            let resp = ui
                .vertical(|ui| {
                    // Captions wrap within the picture's width rather than widen its column.
                    ui.set_max_width(side);
                    let label = caption_ui(ui, &caption.shown, side, caption_h);
                    let picture = match channel_texture {
                        Some((_, id)) => ui.add(egui::Image::new((id, size)).sense(Sense::click_and_drag())),
                        None => picture_ui(ui, &cache.main, main_gpu.take(), size, Sense::click_and_drag()),
                    };
                    crate::app::widgets::hint::above_pointer(&picture, hover);
                    let picture = named(ui, picture, &label, &caption);
                    if let Some((c, _)) = channel_texture {
                        legend_ui(ui, c, cache.channel.name_id(c), cache.channel.range, side);
                    }
                    crate::app::widgets::fields::landmark(ui.ctx(), "shaded-picture", picture.rect);
                    picture
                })
                .inner;
            if corrected.is_some() {
                ui.vertical(|ui| {
                    ui.set_max_width(side);
                    let text = corrected_caption(state.edit.doc, &state.view_options.demo_fixes);
                    let label = caption_ui(ui, &text.shown, side, caption_h);
                    let r = picture_ui(ui, &cache.corrected, corrected_gpu.take(), size, Sense::hover())
                        .on_hover_text(&text.whole);
                    let r = named(ui, r, &label, &text);
                    second = Some(r.rect);
                });
            } else if heat {
                second = Some(ui.scope(|ui| heat_map_ui(ui, state.heat_map, side)).response.rect);
            }
            resp
        })
        .inner;
    Shown { response: resp, second, size, px, scene, mesh }
}

/// Names a picture by its whole caption (for screen readers and the tests): by the caption
/// `label` above it where that is whole, else by the whole text.
fn named(ui: &Ui, picture: egui::Response, label: &egui::Response, caption: &Caption) -> egui::Response {
    if caption.shown == caption.whole {
        return picture.labelled_by(label.id);
    }
    ui.ctx().accesskit_node_builder(picture.id, |b| b.set_label(caption.whole.clone()));
    picture
}

/// Draws the picture of `viewed` for `cache`: on the GPU when the adapter, the renderer
/// choice and the scene allow it (the picture to paint is returned), otherwise on the CPU
/// renderer (into `cache`'s texture). `cache.drawn_by` says which, and why not the GPU.
fn prepare_picture(
    ctx: &egui::Context,
    state: &Shaded<'_>,
    cache: &mut ViewCache,
    viewed: Viewed<'_>,
    px: usize,
    slot: u64,
    name: &str,
) -> Result<Option<GpuImage>, String> {
    let pow = state.pow;
    let why = match gpu::why_cpu(state.gpu, state.view_options.renderer, viewed.doc, pow) {
        Some(why) => why,
        None => match (cache.gpu_picture(viewed, pow, px, slot), state.gpu) {
            (Ok(p), Some(gpu)) => {
                cache.drawn_by = DrawnBy::Gpu { adapter: format!("{}, {}", gpu.name, gpu.backend) };
                return Ok(Some(p));
            }
            (Ok(_), None) => t!("gpu-none"),
            (Err(e), _) => e,
        },
    };
    cache.render(ctx, viewed, pow, px, name, true)?;
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
