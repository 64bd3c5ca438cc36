//! What the pointer does on the shaded view's picture (a light dragged, the orbit camera
//! turned and zoomed, a vertex picked) and what is drawn over it: N, L, V and H (or R) at
//! the worked calculation's vertex, the lights as markers, a spotlight's cone.

use egui::{Color32, Sense, Ui};
use glam::{DVec3, DVec4};
use phonglab_core::t;
use phonglab_core::{Document, Framing, Vertex};

use super::arrow_on_object::ArrowOnObject;
use super::cache::{DrawnBy, ShadedCache, mesh_for};
use super::context::Shaded;
use super::pictures::Shown;
use crate::app::model::evaluated::Evaluated;
use crate::app::model::message::Message;

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
    let (dragged_light, light_marks, cones) = lights_ui(ui, &overlay, state, scene);
    let arrows = vectors_on_object_ui(ui, overlay.rect, state.edit.doc, eval, &light_marks);

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
        let mut c = state.edit.doc.clone();
        c.view.camera = cam;
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
            && let Err(e) = cache.main.render(ui.ctx(), state.edit.doc, state.pow, px, "shaded view", false)
        {
            *state.edit.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
            return (arrows, cones);
        }
        let mesh = mesh_for(&mut cache.main.mesh, &state.edit.doc.view);
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
    if let Err(e) = cache.main.render(ui.ctx(), state.edit.doc, state.pow, px, "shaded view", false) {
        *state.edit.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
        return;
    }
    let probe = &mut state.view_options.probe;
    if probe.stale(cache.main.generation) {
        let mesh = mesh_for(&mut cache.main.mesh, &state.edit.doc.view).clone();
        let setup = state.edit.doc.shaded_setup(state.pow);
        let job = setup.job(&mesh);
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

/// Where the shaded view's image is, and how object and eye space map onto it.
struct Overlay {
    /// The image on screen.
    rect: egui::Rect,
    /// The view's projection of the object.
    clip_from_object: glam::DMat4,
    /// The inverse of the scene's modelview, as the view lights it.
    object_from_eye: glam::DMat4,
}

impl Overlay {
    /// An object-space point (homogeneous) on screen, or `None` behind the camera.
    fn screen_from_object(&self, p: DVec4) -> Option<egui::Pos2> {
        let c = self.clip_from_object * p;
        if c.w <= 0.0 || !c.is_finite() {
            return None;
        }
        let (x, y) = (c.x / c.w, c.y / c.w);
        let size = self.rect.size();
        Some(self.rect.min + egui::vec2(((x + 1.0) * 0.5) as f32 * size.x, ((1.0 - y) * 0.5) as f32 * size.y))
    }

    /// An eye-space point on screen.
    fn screen_from_eye(&self, p: DVec3) -> Option<egui::Pos2> {
        self.screen_from_object(self.object_from_eye * p.extend(1.0))
    }

    /// The object-space point under the screen point `pos`, at the depth of the
    /// object-space point `at` (so a dragged marker stays at its distance).
    fn object_at(&self, pos: egui::Pos2, at: DVec4) -> Option<DVec4> {
        let c = self.clip_from_object * at;
        if c.w <= 0.0 {
            return None;
        }
        let rel = (pos - self.rect.min) / self.rect.size();
        let ndc = DVec4::new(rel.x as f64 * 2.0 - 1.0, 1.0 - rel.y as f64 * 2.0, c.z / c.w, 1.0);
        let p = self.clip_from_object.inverse() * ndc;
        (p.w != 0.0 && p.is_finite()).then(|| p / p.w)
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
    if doc.with_vertex_as_shaded(doc.scene.vertex) != *doc || doc.scene.vertex.position.w == 0.0 {
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
        galleys.push(p.layout_no_wrap(a.name.clone(), font.clone(), c));
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

/// A light outside the picture: a triangle on the picture's edge pointing towards it, and
/// its name (saying so when it is behind the camera, where no edge is nearer than another).
fn light_off_view_ui(ui: &Ui, rect: egui::Rect, towards: egui::Vec2, i: usize, behind: bool) -> egui::Rect {
    let d = if towards.length() > 1e-3 { towards.normalized() } else { egui::vec2(0.0, -1.0) };
    // Where the ray from the centre along `d` leaves the picture, 14 points inside.
    let half = rect.size() * 0.5 - egui::vec2(14.0, 14.0);
    let t = (half.x / d.x.abs().max(1e-6)).min(half.y / d.y.abs().max(1e-6));
    let tip = rect.center() + d * t;
    let side = egui::vec2(-d.y, d.x) * 7.0;
    let fill = Color32::from_rgb(255, 230, 120);
    ui.painter().add(egui::Shape::convex_polygon(
        vec![tip + d * 10.0, tip - d * 4.0 + side, tip - d * 4.0 - side],
        fill,
        egui::Stroke::new(1.5, Color32::BLACK),
    ));
    let at = tip - d * 16.0;
    let name = if behind { t!("light-behind", index = i.to_string()) } else { t!("light-name", index = i.to_string()) };
    let align = if d.x > 0.3 {
        egui::Align2::RIGHT_CENTER
    } else if d.x < -0.3 {
        egui::Align2::LEFT_CENTER
    } else {
        egui::Align2::CENTER_CENTER
    };
    let name = name_on_picture(ui, at, align, name);
    name.union(egui::Rect::from_center_size(tip, egui::vec2(20.0, 20.0)))
}

/// A light's name on the picture: light text on a dark backdrop, so that it reads on the
/// picture's background whatever the window's theme (dark text on the dark picture did
/// not, in the light theme). Returns where it is.
fn name_on_picture(ui: &Ui, at: egui::Pos2, align: egui::Align2, name: String) -> egui::Rect {
    let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Small));
    let galley = ui.painter().layout_no_wrap(name, font, Color32::WHITE);
    let rect = align.anchor_size(at, galley.size());
    ui.painter().rect_filled(rect.expand(2.0), 3.0, Color32::from_black_alpha(170));
    ui.painter().galley(rect.min, galley, Color32::WHITE);
    rect.expand(2.0)
}

/// A spotlight's cone as the view shows it: the rim of the cut-off circle where the cone
/// reaches the object's distance (48 points on screen), `None` for a light that is no
/// spotlight or whose cone does not project.
fn spot_cone(
    o: &Overlay,
    scene: &phonglab_core::Scene,
    l: &phonglab_core::Light,
    at: DVec4,
) -> Option<Vec<egui::Pos2>> {
    if !l.is_spot() || at.w == 0.0 {
        return None;
    }
    let object_from_light = o.object_from_eye * scene.eye_from_light(l);
    let axis = object_from_light.transform_vector3(l.spot_direction).try_normalize()?;
    let apex = at.truncate() / at.w;
    let reach = apex.length().max(0.5);
    let (a, b) = axis.any_orthonormal_pair();
    let (cos, sin) = (l.spot_cutoff.to_radians().cos(), l.spot_cutoff.to_radians().sin());
    (0..48)
        .map(|k| {
            let t = k as f64 / 48.0 * std::f64::consts::TAU;
            let dir = axis * cos + (a * t.cos() + b * t.sin()) * sin;
            o.screen_from_object((apex + dir * reach).extend(1.0))
        })
        .collect()
}

/// Each light as a marker where the view draws it; a marker can be dragged (in the plane
/// facing the viewer), which moves the light. Returns whether a marker is being dragged,
/// where each light's mark and name are (on the picture or at its edge), and the bounds of
/// each spotlight's cone on it.
fn lights_ui(
    ui: &mut Ui,
    o: &Overlay,
    state: &mut Shaded<'_>,
    scene: &phonglab_core::Scene,
) -> (bool, Vec<egui::Rect>, Vec<egui::Rect>) {
    let mut dragging = false;
    let mut marks = Vec::new();
    let mut cones = Vec::new();
    let mut moved = None;
    for (i, l) in state.edit.doc.scene.lights.iter().enumerate() {
        let eye = scene.light_pos_in_eye(l);
        let in_object = o.object_from_eye * eye;
        // A directional light is drawn in its direction, a little outside the object.
        let p = if in_object.w == 0.0 {
            (in_object.truncate().normalize_or_zero() * 1.2).extend(1.0)
        } else {
            in_object / in_object.w
        };
        let centre = o.rect.center();
        // A spotlight's cone: its rim where it reaches the object, drawn even when the light
        // itself is off the picture (the spotlight preset's is above the view).
        let cone = spot_cone(o, scene, l, p);
        let spot_ink = crate::app::widgets::palette::ink(ui, crate::app::widgets::palette::SPOT);
        if let Some(rim) = &cone {
            ui.painter_at(o.rect).add(egui::Shape::closed_line(rim.clone(), egui::Stroke::new(1.5, spot_ink)));
            cones.push(egui::Rect::from_points(rim).intersect(o.rect));
        }
        let pos = match o.screen_from_object(p) {
            Some(pos) if o.rect.expand(-4.0).contains(pos) => pos,
            seen => {
                // Outside the picture (or behind the camera): an arrow at the edge, towards it.
                let towards = match seen {
                    Some(pos) => pos - centre,
                    None => {
                        let e = (o.object_from_eye.inverse() * p).truncate();
                        egui::vec2(e.x as f32, -e.y as f32)
                    }
                };
                marks.push(light_off_view_ui(ui, o.rect, towards, i, seen.is_none()));
                continue;
            }
        };
        if let Some(rim) = &cone {
            // On the picture, the cone's sides from the light to its rim.
            for q in rim.iter().step_by(6) {
                ui.painter_at(o.rect).line_segment([pos, *q], egui::Stroke::new(1.5, spot_ink));
            }
        }
        let hit = egui::Rect::from_center_size(pos, egui::vec2(18.0, 18.0));
        let r = ui.interact(hit, ui.scope_id().with(("light marker", i)), Sense::drag());
        r.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, format!("light {i} marker")));
        let r = r.on_hover_text(t!("light-drag", index = i.to_string()));
        let ring = if r.hovered() || r.dragged() { 3.0 } else { 1.5 };
        ui.painter().circle(pos, 7.0, Color32::from_rgb(255, 230, 120), egui::Stroke::new(ring, Color32::BLACK));
        let name = name_on_picture(
            ui,
            pos + egui::vec2(9.0, -9.0),
            egui::Align2::LEFT_BOTTOM,
            t!("light-name", index = i.to_string()),
        );
        marks.push(hit.union(name));
        if r.dragged() {
            dragging = true;
            // The marker follows the pointer (it is small, so grabbing it off-centre
            // moves it by at most its radius).
            let target = r.interact_pointer_pos().unwrap_or(pos + r.drag_delta());
            if let Some(to) = o.object_at(target, p) {
                moved = Some((i, to, in_object.w == 0.0));
            }
        }
    }
    if let Some((i, to, directional)) = moved {
        let mut c = state.edit.doc.clone();
        let l = &mut c.scene.lights[i];
        let eye_from_object = o.object_from_eye.inverse();
        let eye = if directional {
            (eye_from_object * to.truncate().extend(0.0)).truncate().normalize_or_zero().extend(0.0)
        } else {
            eye_from_object * to
        };
        let light = scene.eye_from_light(l).inverse() * eye;
        if light.is_finite() {
            l.position = light;
            state.edit.apply(c);
        }
    }
    (dragging, marks, cones)
}
