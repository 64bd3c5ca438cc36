//! The pictures' captions: what the picture is and who drew it in how long ("Teapot
//! Gouraud: 0.8 ms per frame on the CPU"), and what the corrected picture corrects. In the
//! body's size, wrapped to the picture's width, never cut (a small line cut with "…" was 9
//! points on a projector, and cut "the demo's …"): whole, in a room kept for a long time
//! so the picture does not move as the time's digits change; or, presenting and over two
//! pictures side by side, short, the whole in the picture's hover and name.

use egui::{Sense, Ui};
use phonglab_core::library::DemoDeparture;
use phonglab_core::{Document, PowFn};

use super::cache::{COARSE_ABOVE, DrawnBy, ViewCache};
use super::context::ShadedOptions;
use crate::t;

/// Where the captions stand: presenting, or over two pictures side by side (the demo and
/// its correction, or the heat map), a caption says what the picture is in one short line
/// and the rest is in the picture's hover and name; otherwise whole.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaptionRoom {
    /// Presentation mode.
    pub presenting: bool,
    /// Two pictures share the part (each at its narrowest).
    pub pair: bool,
}

impl CaptionRoom {
    fn short(self) -> bool {
        self.presenting || self.pair
    }
}

/// A picture's caption as shown, and whole (the picture's name for screen readers, and
/// its hover).
pub(super) struct Caption {
    /// Above the picture.
    pub shown: String,
    /// The whole caption.
    pub whole: String,
}

/// A picture's caption at the foot of the `height` kept for it (right above the picture),
/// wrapped to the picture's `width`.
pub(super) fn caption_ui(ui: &mut Ui, text: &str, width: f32, height: f32) -> egui::Response {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(width, height), Sense::hover());
    let foot = egui::UiBuilder::new().max_rect(rect).layout(egui::Layout::bottom_up(egui::Align::Min));
    ui.scope_builder(foot, |ui| ui.add(egui::Label::new(text).wrap())).inner
}

/// The main picture's caption: the object, the shading, who drew it in how long (or the
/// channel shown), and "(the demo's own)" beside a corrected picture; shown short (who
/// drew it left to the whole) where [`CaptionRoom::short`].
pub(super) fn main_caption(
    doc: &Document,
    options: &ShadedOptions,
    pow: PowFn,
    cache: &ViewCache,
    room: CaptionRoom,
) -> Caption {
    let corrected = super::context::corrected_document(doc, &options.demo_fixes).is_some();
    let whole = with_head_and_tail(doc, Some(middle(doc, options, pow, drawn_caption(cache))), corrected);
    let shown = if room.short() { with_head_and_tail(doc, None, corrected) } else { whole.clone() };
    Caption { shown, whole }
}

/// What the caption says after the object and the shading: the channel shown (named as
/// the scene's rules form it: Phong's `R·V`, not `N·H`), or `drawn`.
fn middle(doc: &Document, options: &ShadedOptions, pow: PowFn, drawn: String) -> String {
    match options.channel {
        Some(c) => t!("channel-caption", channel = crate::locale::tr(super::channel_view::name_id(c, doc, pow))),
        None => drawn,
    }
}

fn with_head_and_tail(doc: &Document, middle: Option<String>, corrected: bool) -> String {
    let tail = if corrected { t!("the-demos-own") } else { String::new() };
    let head = format!("{} {}", doc.view.object.label(), doc.view.shading.label());
    match middle {
        Some(m) => format!("{head}: {m}{tail}"),
        None => format!("{head}{tail}"),
    }
}

/// The corrected picture's caption: which of the demo's departures it corrects (shown, how
/// many of those the demo makes: the switches above say which).
pub(super) fn corrected_caption(doc: &Document, fixes: &[bool; 3]) -> Caption {
    let present: Vec<(DemoDeparture, bool)> =
        DemoDeparture::ALL.into_iter().zip(*fixes).filter(|(d, _)| d.present_in(doc)).collect();
    let fixed: Vec<String> = present.iter().filter(|(_, on)| *on).map(|(d, _)| d.fix_label()).collect();
    let whole = t!("corrected", fixes = fixed.join(", "));
    let shown = t!("corrected-short", count = fixed.len().to_string(), all = present.len().to_string());
    Caption { shown, whole }
}

/// The height the captions of `doc`'s view take, wrapped to a picture `width` wide: its
/// main picture's as shown, whole in every way it may say who drew it, with a long time
/// (so that neither the time's digits nor who drew it move the picture from frame to
/// frame), and the corrected picture's when there is one. `triangles`: the view's mesh's
/// (a very large mesh's caption may say it is drawn from a copy); `pow`: the power
/// function the view draws with (the rules it forms name a term shown).
pub fn caption_room(
    ui: &Ui,
    (doc, pow): (&Document, PowFn),
    options: &ShadedOptions,
    cache: &ViewCache,
    triangles: usize,
    width: f32,
    room: CaptionRoom,
) -> f32 {
    let corrected = super::context::corrected_document(doc, &options.demo_fixes).is_some();
    let mut texts = if room.short() {
        vec![with_head_and_tail(doc, None, corrected)]
    } else {
        drawn_variants(cache, triangles)
            .into_iter()
            .map(|d| with_head_and_tail(doc, Some(middle(doc, options, pow, d)), corrected))
            .collect()
    };
    if corrected {
        texts.push(corrected_caption(doc, &options.demo_fixes).shown);
    }
    let font = egui::TextStyle::Body.resolve(ui.style());
    let height =
        |t: String| ui.ctx().fonts_mut(|f| f.layout(t, font.clone(), egui::Color32::WHITE, width.max(1.0)).size().y);
    texts.into_iter().map(height).fold(0.0, f32::max)
}

/// Every way the caption may say who drew the picture while the document stays, with a
/// long time: who drew it last, the CPU whole or lit again (nothing drawn moved), and a
/// very large mesh's coarse copy while it turns or spins.
fn drawn_variants(cache: &ViewCache, triangles: usize) -> Vec<String> {
    let ms = crate::locale::decimal("888.8");
    let mut out = vec![
        drawn_caption_taking(cache, &ms),
        t!("caption-cpu", ms = ms.clone()),
        t!("caption-cpu-relit", ms = ms.clone()),
    ];
    if triangles > COARSE_ABOVE {
        let (some, all) = (crate::locale::grouped(9_999_999), crate::locale::grouped(triangles as u64));
        out.push(t!("caption-cpu-coarse", ms = ms.clone(), triangles = some.clone(), all = all.clone()));
        out.push(t!("caption-cpu-coarse-spin", ms = ms, triangles = some, all = all));
    }
    out
}

/// Who drew the picture, for its caption.
pub fn drawn_caption(cache: &ViewCache) -> String {
    drawn_caption_taking(cache, &fmt_ms(cache.last_ms))
}

/// [`drawn_caption`] with the time `ms` (a long one, to measure the room it takes).
fn drawn_caption_taking(cache: &ViewCache, ms: &str) -> String {
    match &cache.drawn_by {
        DrawnBy::Gpu { adapter } => t!("caption-gpu", adapter = adapter.clone()),
        _ if let Some(c) = cache.last_coarse => {
            let triangles = crate::locale::grouped(c.triangles as u64);
            let all = crate::locale::grouped(c.of as u64);
            if c.spinning {
                t!("caption-cpu-coarse-spin", ms = ms, triangles = triangles, all = all)
            } else {
                t!("caption-cpu-coarse", ms = ms, triangles = triangles, all = all)
            }
        }
        _ if cache.last_relit => t!("caption-cpu-relit", ms = ms),
        _ => t!("caption-cpu", ms = ms),
    }
}

fn fmt_ms(ms: f64) -> String {
    crate::locale::decimal(&format!("{ms:.1}"))
}
