//! Arrows and their labels as the diagrams draw them: the vector plot and the arrows over
//! the shaded view share them.

use egui::{Color32, Pos2, Rect, Stroke, Vec2, vec2};

use super::label_placement::{self, Segment, Wanted};

/// A line from `a` to `b`, dashed or not.
fn line(p: &egui::Painter, a: Pos2, b: Pos2, stroke: Stroke, dashed: bool) {
    if dashed {
        let dash = stroke.width * 3.0;
        p.extend(egui::Shape::dashed_line(&[a, b], stroke, dash, dash * 0.6));
    } else {
        p.line_segment([a, b], stroke);
    }
}

/// Draws an arrow from `from` to `to` (a filled head; hollow when it points away from the
/// viewer) and returns its segment for the labels to avoid.
pub fn draw_arrow(
    p: &egui::Painter,
    from: Pos2,
    to: Pos2,
    width: f32,
    color: Color32,
    dashed: bool,
    away: bool,
) -> Segment {
    let d = to - from;
    let dir = d.normalized();
    let head = (width * 4.0).min(d.length() * 0.45);
    let wing = vec2(-dir.y, dir.x) * head * 0.5;
    let base = to - dir * head;
    line(p, from, base, Stroke::new(width, color), dashed);
    let tri = vec![to, base + wing, base - wing];
    if away {
        p.add(egui::Shape::closed_line(tri, Stroke::new(width * 0.6, color)));
    } else {
        p.add(egui::Shape::convex_polygon(tri, color, Stroke::NONE));
    }
    Segment { a: from, b: to, half_width: width * 0.5 + head * 0.5 * (1.0 / 3.0) }
}

/// ⊙ (towards the viewer) or ⊗ (away) at `at`, radius `r`.
pub fn draw_end_on(p: &egui::Painter, at: Pos2, r: f32, width: f32, color: Color32, towards: bool) {
    p.circle_stroke(at, r, Stroke::new(width * 0.7, color));
    if towards {
        p.circle_filled(at, r * 0.3, color);
    } else {
        let k = r * 0.6;
        for (a, b) in [(vec2(-k, -k), vec2(k, k)), (vec2(-k, k), vec2(k, -k))] {
            p.line_segment([at + a, at + b], Stroke::new(width * 0.7, color));
        }
    }
}

/// The `k`-th vector seen end on at `at`, drawn as ⊙ or ⊗ (each further one a little aside,
/// so two never sit on one another); returns the line its label must avoid and the label it
/// wants, beside it.
pub fn end_on_marker(
    p: &egui::Painter,
    at: Pos2,
    k: usize,
    width: f32,
    color: Color32,
    towards: bool,
) -> (Segment, Wanted) {
    let ring = at + vec2(1.0, 1.0) * (k as f32 * width * 8.0);
    draw_end_on(p, ring, width * 3.0, width, color, towards);
    (
        Segment { a: ring, b: ring, half_width: width * 3.5 },
        Wanted { anchor: ring, direction: vec2(0.7, -0.7), size: Vec2::ZERO, gap: width * 3.5 },
    )
}

/// Places the laid-out labels `galleys` (one per `wanted`) clear of each other and of
/// `lines` within `bounds` ([`label_placement::place`]) and paints them, each on a rounded
/// `backdrop` (with 2 points of room either side) when one is given; returns their boxes.
pub fn paint_labels(
    p: &egui::Painter,
    mut wanted: Vec<Wanted>,
    galleys: Vec<std::sync::Arc<egui::Galley>>,
    lines: &[Segment],
    bounds: Rect,
    backdrop: Option<Color32>,
) -> Vec<Rect> {
    let pad = if backdrop.is_some() { 2.0 } else { 0.0 };
    for (w, g) in wanted.iter_mut().zip(&galleys) {
        w.size = g.size() + vec2(2.0 * pad, 0.0);
    }
    let boxes = label_placement::place(&wanted, lines, bounds);
    for (b, g) in boxes.iter().zip(galleys) {
        if let Some(fill) = backdrop {
            p.rect_filled(*b, 3.0, fill);
        }
        p.galley(b.min + vec2(pad, 0.0), g, Color32::PLACEHOLDER);
    }
    boxes
}

/// [`paint_labels`] for `texts` (each one's text, colour and font): in their fonts where
/// every label finds a free place, else in smaller ones (down to 60 %), so a crowded
/// diagram's labels shrink rather than cover each other (β was written over N and H in a
/// small plot).
pub fn paint_labels_fitted(
    p: &egui::Painter,
    wanted: Vec<Wanted>,
    texts: Vec<(String, Color32, egui::FontId)>,
    lines: &[Segment],
    bounds: Rect,
    backdrop: Option<Color32>,
) -> Vec<Rect> {
    let pad = if backdrop.is_some() { 2.0 } else { 0.0 };
    let scales = [1.0, 0.85, 0.72, 0.6];
    let laid = |k: f32| {
        let galleys: Vec<_> = texts
            .iter()
            .map(|(t, c, f)| p.layout_no_wrap(t.clone(), egui::FontId::new(f.size * k, f.family.clone()), *c))
            .collect();
        let mut w = wanted.clone();
        for (w, g) in w.iter_mut().zip(&galleys) {
            w.size = g.size() + vec2(2.0 * pad, 0.0);
        }
        let boxes = label_placement::place(&w, lines, bounds);
        (galleys, boxes)
    };
    let (galleys, boxes) = scales
        .iter()
        .map(|k| laid(*k))
        .find(|(_, boxes)| label_placement::all_clear(boxes, lines, bounds))
        .unwrap_or_else(|| laid(scales[scales.len() - 1]));
    for (b, g) in boxes.iter().zip(galleys) {
        if let Some(fill) = backdrop {
            p.rect_filled(*b, 3.0, fill);
        }
        p.galley(b.min + vec2(pad, 0.0), g, Color32::PLACEHOLDER);
    }
    boxes
}
