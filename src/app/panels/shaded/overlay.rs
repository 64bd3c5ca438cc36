//! What the pointer does on the shaded view's picture (a light dragged, the orbit camera
//! turned and zoomed, a vertex picked) and what is drawn over it: N, L, V and H (or R) at
//! the worked calculation's vertex, and the lights ([`super::light_marks`]).

use egui::{Color32, Ui};
use glam::DVec3;
use phonglab_core::{Document, Framing, Vertex};

use super::arrow_on_object::ArrowOnObject;
use super::cache::{DrawnBy, ShadedCache, Viewed};
use super::context::Shaded;
use super::pictures::Shown;
use super::screen::Overlay;
use crate::app::editing::evaluated::Evaluated;
use crate::app::editing::message::Message;
use crate::t;

/// What the pointer does on the picture: the vectors and lights drawn on it, a light
/// dragged, the orbit camera turned and zoomed, a vertex picked. Returns the arrows drawn
/// and the bounds of each spotlight's cone drawn.
pub(super) fn interaction_ui(
    ui: &mut Ui,
    state: &mut Shaded<'_>,
    cache: &mut ShadedCache,
    shown: &Shown,
    eval: &Evaluated,
) -> (Vec<ArrowOnObject>, Vec<egui::Rect>) {
    let (resp, size, px, scene) = (&shown.response, shown.size, shown.px, &shown.scene);
    let camera = state.edit.doc.view.camera;
    let overlay = Overlay {
        rect: resp.rect,
        clip_from_object: state.edit.doc.view.clip_from_object(),
        object_from_eye: scene.eye_from_object().inverse(),
    };
    // The lights first: the arrows' letters are then placed clear of their marks and names.
    let lights = super::light_marks::lights_ui(ui, &overlay, resp, state, scene);
    let (dragged_light, cones) = (lights.dragging, lights.cones);
    let arrows = vectors_on_object_ui(ui, overlay.rect, state.edit.doc, eval, &lights.marks);

    let mut cam = camera;
    // While the camera turns, a very large mesh is drawn from its coarse copy; the frame
    // after the drag ends draws the whole mesh again.
    let turning = resp.dragged() && !dragged_light && state.edit.doc.view.framing == Framing::Orbit;
    for view in [&mut cache.main, &mut cache.corrected] {
        if view.turning && !turning {
            ui.ctx().request_repaint();
        }
        view.turning = turning;
    }
    if turning {
        let d = resp.drag_delta();
        cam.yaw = (cam.yaw + d.x as f64 * 0.5).rem_euclid(360.0);
        cam.pitch = (cam.pitch + d.y as f64 * 0.5).clamp(-89.0, 89.0);
    }
    if resp.hovered() && state.edit.doc.view.framing == Framing::Orbit {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            cam.distance = (cam.distance * (-scroll as f64 * 0.002).exp()).clamp(0.6, 20.0);
        }
    }
    if cam != camera {
        // The vertex on the object stays the worked one, seen from the turned camera: its
        // arrows are drawn again next frame, from the calculation made under it.
        let on_object = vertex_on_object(state.edit.doc);
        let mut c = state.edit.doc.clone();
        c.view.camera = cam;
        if on_object {
            c = c.with_vertex_as_shaded(c.scene.vertex);
        }
        state.edit.apply(c);
    }
    // With the probe on, a click pins the probe's pixel instead (`probe_ui`).
    if resp.clicked()
        && !state.view_options.probe.on
        && let Some(p) = resp.interact_pointer_pos()
    {
        let rel = (p - resp.rect.min) / size;
        let (x, y) = ((rel.x * px as f32) as usize, (rel.y * px as f32) as usize);
        // Picking reads the CPU renderer's triangle buffer: after a GPU frame, the CPU
        // renderer draws the same picture first (only on a click).
        if matches!(cache.main.drawn_by, DrawnBy::Gpu { .. })
            && let Err(e) = cache.main.render(ui.ctx(), viewed(state, shown), state.pow, px, "shaded view", false)
        {
            *state.edit.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
            return (arrows, cones);
        }
        let mesh = &shown.mesh;
        if let Some(i) = cache.main.renderer.pick(mesh, x, y) {
            let c = state.edit.doc.with_vertex_as_shaded(Vertex::from_f32(mesh.positions[i], mesh.normals[i]));
            if state.edit.apply(c) {
                let object = state.edit.doc.view.object.label().to_lowercase();
                *state.edit.message = Some(Message::Info(t!("picked-vertex", index = i.to_string(), object = object)));
            }
        }
    }
    (arrows, cones)
}

/// The document as it stands, with the mesh the frame looked up for its picture.
fn viewed<'a>(state: &'a Shaded<'_>, shown: &'a Shown) -> Viewed<'a> {
    Viewed { doc: state.edit.doc, mesh: &shown.mesh }
}

/// The pixel of a picture `px` pixels square, drawn `shown.size` points at
/// `shown.response.rect`, under the screen point `p`.
fn pixel_at(shown: &Shown, p: egui::Pos2) -> [usize; 2] {
    let rel = (p - shown.response.rect.min) / shown.size;
    let px = shown.px;
    [((rel.x * px as f32) as usize).min(px - 1), ((rel.y * px as f32) as usize).min(px - 1)]
}

/// The pixel probe on the picture: the pixel under the pointer (or the one clicked, pinned)
/// probed again whenever the picture or the pixel changes, and marked.
pub(super) fn probe_ui(ui: &mut Ui, state: &mut Shaded<'_>, cache: &mut ShadedCache, shown: &Shown) {
    if !state.view_options.probe.on {
        return;
    }
    let resp = &shown.response;
    let probe = &mut state.view_options.probe;
    if resp.clicked()
        && let Some(p) = resp.interact_pointer_pos()
    {
        (probe.at, probe.pinned) = (Some((pixel_at(shown, p), shown.px)), true);
    } else if !probe.pinned
        && let Some(p) = resp.hover_pos()
    {
        probe.at = Some((pixel_at(shown, p), shown.px));
    }
    // A pinned pixel of a picture since drawn at another size: the same place on it.
    if let Some((p, old)) = probe.at
        && old != shown.px
    {
        let scale = |c: usize| (((c as f64 + 0.5) * shown.px as f64 / old as f64) as usize).min(shown.px - 1);
        probe.at = Some((p.map(scale), shown.px));
    }
    let Some(([x, y], px)) = probe.at else { return };
    // The probe reads the CPU renderer's last frame: drawn first when the GPU drew the
    // picture (once for each new picture).
    if let Err(e) = cache.main.render(ui.ctx(), viewed(state, shown), state.pow, px, "shaded view", false) {
        *state.edit.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
        return;
    }
    let probe = &mut state.view_options.probe;
    if probe.stale(cache.main.generation) {
        let setup = state.edit.doc.shaded_setup(state.pow);
        let job = setup.job(&shown.mesh);
        probe.lines = match phonglab_core::probe::probe(&cache.main.renderer, &job, x, y) {
            Ok(Some(p)) => phonglab_core::probe_report::report(&p),
            Ok(None) | Err(_) => Vec::new(),
        };
        probe.made_for = Some(([x, y], px, cache.main.generation));
    }
    // The mark: a ring around the pixel, with a cross through it.
    let centre = resp.rect.min + egui::vec2((x as f32 + 0.5) / px as f32, (y as f32 + 0.5) / px as f32) * shown.size;
    let painter = ui.painter_at(resp.rect);
    for (width, colour) in [(3.0, Color32::BLACK), (1.5, Color32::WHITE)] {
        let stroke = egui::Stroke::new(width, colour);
        painter.circle_stroke(centre, 6.0, stroke);
        painter.line_segment([centre - egui::vec2(11.0, 0.0), centre - egui::vec2(6.0, 0.0)], stroke);
        painter.line_segment([centre + egui::vec2(6.0, 0.0), centre + egui::vec2(11.0, 0.0)], stroke);
        painter.line_segment([centre - egui::vec2(0.0, 11.0), centre - egui::vec2(0.0, 6.0)], stroke);
        painter.line_segment([centre + egui::vec2(0.0, 6.0), centre + egui::vec2(0.0, 11.0)], stroke);
    }
}

/// N, V, and each light's L and H (or R) as arrows on the image `rect`, from the vertex on
/// the object, each the same length in the world (0.5 of the object's unit, where the
/// demo's sphere has radius 0.5) and projected as the picture is: a vector that points
/// at the viewer is short on the screen, one across the screen long. Empty unless the
/// worked calculation's vertex is one the view draws (after a click on the surface, or in
/// any scene whose frame is the view's).
pub fn vector_arrows(doc: &Document, eval: &Evaluated, rect: egui::Rect) -> Vec<ArrowOnObject> {
    let mut out = Vec::new();
    if !vertex_on_object(doc) {
        return out;
    }
    let scene = doc.shaded_scene();
    let eye_from_object = scene.eye_from_object();
    let o = Overlay { rect, clip_from_object: doc.view.clip_from_object(), object_from_eye: eye_from_object.inverse() };
    let p = eye_from_object * doc.scene.vertex.position;
    let pos_in_eye = p.truncate() / p.w;
    let len = 0.5 * eye_from_object.transform_vector3(DVec3::X).length();
    let Some(from) = o.screen_from_eye(pos_in_eye).filter(|f| rect.contains(*f)) else { return out };
    let n = eval.n.normalize_or_zero();
    let mut add = |vec: DVec3, colour: Color32, name: String| {
        if vec.length() > 0.0
            && let Some(to) = o.screen_from_eye(pos_in_eye + vec.normalize() * len)
        {
            let unit = vec.normalize();
            // Eye space looks down -z: a vector with z < 0 points away from the viewer.
            let away = unit.z < -1e-9;
            let behind = name != "N" && unit.dot(n) < -1e-9;
            out.push(ArrowOnObject { name, colour, from, to, away, behind });
        }
    };
    let many = eval.lights.len() > 1;
    for lv in &eval.lights {
        let sfx = if many { lv.index.to_string() } else { String::new() };
        add(lv.l, crate::app::widgets::palette::L, format!("L{sfx}"));
        match doc.scene.rules.specular.vector() {
            phonglab_core::SpecularVector::Halfway => add(lv.h, crate::app::widgets::palette::H, format!("H{sfx}")),
            phonglab_core::SpecularVector::Reflection => add(lv.r, crate::app::widgets::palette::R, format!("R{sfx}")),
        }
    }
    add(eval.v, crate::app::widgets::palette::V, "V".into());
    add(eval.n, crate::app::widgets::palette::N, "N".into());
    out
}

/// Whether the worked calculation's vertex is one the shaded view draws, as the view lights
/// it (after a click on the surface, or in any scene whose frame is the view's): then its
/// arrows stand on the object, and a turn of the camera or of the object keeps them there.
pub fn vertex_on_object(doc: &Document) -> bool {
    doc.scene.vertex.position.w != 0.0 && doc.with_vertex_as_shaded(doc.scene.vertex) == *doc
}

/// Draws [`vector_arrows`] on the image as they are projected (one world length each, so
/// foreshortened), in the plot's colours and styles; an arrow that points away from the
/// viewer or into the surface faded with an open head, and one seen end on (shorter than 3
/// points) as ⊙ or ⊗; each letter placed clear of the others and of the arrows
/// ([`crate::app::widgets::label_placement`]); a line under the picture says what the
/// faded ones are. Returns the arrows drawn.
fn vectors_on_object_ui(
    ui: &mut Ui,
    rect: egui::Rect,
    doc: &Document,
    eval: &Evaluated,
    keep_clear: &[egui::Rect],
) -> Vec<ArrowOnObject> {
    use crate::app::widgets::arrows::{draw_arrow, end_on_marker, paint_labels};
    let arrows = vector_arrows(doc, eval, rect);
    let Some(first) = arrows.first() else { return arrows };
    let from = first.from;
    let p = ui.painter_at(rect);
    let width = (3.0 / ui.ctx().pixels_per_point()).max(rect.width().min(rect.height()) * 0.006);
    let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Body) * 1.5);
    // Inks against the picture's background, not the window's: in the light theme the
    // picture stays as dark as its scene says, and pale inks vanished on it.
    let bg = crate::app::widgets::palette::gl_to_color32(doc.view.background.map(f64::from));
    let dark_picture = bg.r() as u32 + bg.g() as u32 + bg.b() as u32 <= 3 * 128;
    let on_picture = |c: Color32| crate::app::widgets::palette::ink_on(c, bg);
    let outline = if dark_picture { Color32::BLACK } else { Color32::WHITE };
    // What the letters keep clear of: each light's mark and name (as a thick stroke through
    // its middle), then the arrows.
    let mut lines: Vec<crate::app::widgets::label_placement::Segment> = keep_clear
        .iter()
        .map(|r| crate::app::widgets::label_placement::Segment {
            a: r.left_center(),
            b: r.right_center(),
            half_width: r.height() * 0.5,
        })
        .collect();
    let mut wanted = Vec::new();
    let mut galleys = Vec::new();
    let mut end_on = 0;
    for a in &arrows {
        let ink = on_picture(a.colour);
        let c = if a.faded() { ink.gamma_multiply(0.5) } else { ink };
        let d = a.to - from;
        let dashed = a.name.starts_with('H') || a.name.starts_with('R');
        if d.length() < 3.0 {
            let (line, label) = end_on_marker(&p, from, end_on, width, c, !a.away);
            end_on += 1;
            lines.push(line);
            wanted.push(label);
        } else {
            // A dark (or light) edge under the colour, so the arrow reads on any surface.
            let edge = if a.faded() { outline.gamma_multiply(0.5) } else { outline };
            draw_arrow(&p, from, a.to, width * 1.8, edge, false, a.faded());
            lines.push(draw_arrow(&p, from, a.to, width, c, dashed, a.faded()));
            wanted.push(crate::app::widgets::label_placement::Wanted {
                anchor: a.to,
                direction: d,
                size: egui::Vec2::ZERO,
                gap: width,
            });
        }
        // The letter whole even where its arrow is faded, at a text's contrast on the
        // picture (faded letters were unreadable on the demo's black picture).
        let letter =
            crate::app::widgets::palette::ink_with_contrast(a.colour, bg, crate::app::widgets::palette::TEXT_CONTRAST);
        galleys.push(p.layout_no_wrap(a.name.clone(), font.clone(), letter));
    }
    paint_labels(&p, wanted, galleys, &lines, rect, Some(outline.gamma_multiply(0.6)));
    p.circle_filled(from, width * 1.3, on_picture(crate::app::widgets::palette::N));
    // (A picture narrower than 180 points has no room for the line: it would cover it.)
    if arrows.iter().any(ArrowOnObject::faded) && rect.width() >= 180.0 {
        // A label (read by screen readers and the tests) on a backdrop, at the picture's
        // foot (growing upwards as it wraps, inside the picture), drawn in a child that
        // takes no room from the panel.
        let foot = egui::UiBuilder::new()
            .max_rect(rect.shrink(4.0))
            .layout(egui::Layout::bottom_up(egui::Align::LEFT))
            .id_salt("arrows faded");
        let mut child = ui.new_child(foot);
        child.set_clip_rect(rect);
        let ink = if dark_picture { Color32::from_gray(230) } else { Color32::from_gray(20) };
        egui::Frame::new().fill(outline.gamma_multiply(0.7)).corner_radius(3.0).inner_margin(3.0).show(
            &mut child,
            |ui| {
                ui.add(egui::Label::new(egui::RichText::new(t!("arrows-faded")).small().color(ink)).wrap());
            },
        );
    }
    arrows
}
