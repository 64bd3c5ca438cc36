//! The lights on the shaded view's picture: each a marker where the view draws it, or a
//! triangle at the picture's edge towards it (behind the camera, saying so), with its name
//! and a spotlight's cone. Either kind of marker drags its light, in the plane facing the
//! viewer.

use egui::{Color32, Sense, Ui};
use glam::DVec4;

use super::context::Shaded;
use super::screen::Overlay;
use crate::t;

/// The light markers' yellow.
const MARKER: Color32 = Color32::from_rgb(255, 230, 120);

/// What the lights drew and did this frame.
pub(super) struct Lights {
    /// A light's marker is being dragged (the camera must not turn).
    pub dragging: bool,
    /// Where each light's mark and name are (on the picture or at its edge).
    pub marks: Vec<egui::Rect>,
    /// The bounds of each spotlight's cone on the picture.
    pub cones: Vec<egui::Rect>,
}

/// A light's marker held this frame: how far the pointer moved, and where it is.
struct Held {
    delta: egui::Vec2,
    pointer: Option<egui::Pos2>,
}

/// Which light's marker the drag on the picture began on, if one did: a hand that presses
/// and moves within one frame is already off a small marker when the drag starts, and the
/// picture takes it; the press's origin, against the marks as they were, gives it back to
/// the light. Kept while the drag lasts.
fn grabbed_from_picture(ui: &Ui, picture: &egui::Response) -> Option<usize> {
    let id = ui.scope_id().with("light marker grabbed");
    if picture.drag_started() {
        let marks: Vec<(usize, egui::Rect)> = ui.data(|d| d.get_temp(id.with("marks"))).unwrap_or_default();
        let origin = ui.input(|i| i.pointer.press_origin());
        let grabbed = origin.and_then(|p| marks.iter().find(|(_, r)| r.contains(p)).map(|(i, _)| *i));
        ui.data_mut(|d| d.insert_temp(id, grabbed));
    }
    if picture.dragged() { ui.data(|d| d.get_temp::<Option<usize>>(id)).flatten() } else { None }
}

/// Remembers where the markers were, for [`grabbed_from_picture`] next frame.
fn remember_marks(ui: &Ui, marks: Vec<(usize, egui::Rect)>) {
    let id = ui.scope_id().with("light marker grabbed");
    ui.data_mut(|d| d.insert_temp(id.with("marks"), marks));
}

/// The pointer's hold on light `i`'s marker at `hit` (on the picture, or at its edge): a
/// drag moves the light. Held by its own widget, or by the picture's drag begun on it.
fn marker_ui(
    ui: &Ui,
    hit: egui::Rect,
    i: usize,
    picture: &egui::Response,
    grabbed: Option<usize>,
) -> (bool, Option<Held>) {
    let r = ui.interact(hit, ui.scope_id().with(("light marker", i)), Sense::drag());
    r.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, format!("light {i} marker")));
    let r = r.on_hover_text(t!("light-drag", index = i.to_string()));
    let held = if r.dragged() {
        Some(Held { delta: r.drag_delta(), pointer: r.interact_pointer_pos() })
    } else if grabbed == Some(i) {
        Some(Held { delta: picture.drag_delta(), pointer: picture.interact_pointer_pos() })
    } else {
        None
    };
    (r.hovered() || held.is_some(), held)
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
    let fill = MARKER;
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
    let name = name_on_picture(ui, at, align, name, rect);
    name.union(egui::Rect::from_center_size(tip, egui::vec2(20.0, 20.0)))
}

/// A light's name on the picture: light text on a dark backdrop, so that it reads on the
/// picture's background whatever the window's theme (dark text on the dark picture did
/// not, in the light theme), moved onto the `picture` where it would reach past an edge
/// (a small picture cut "light 0 (behind the camera)" at its sides). Returns where it is.
fn name_on_picture(ui: &Ui, at: egui::Pos2, align: egui::Align2, name: String, picture: egui::Rect) -> egui::Rect {
    let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Small));
    let galley = ui.painter().layout_no_wrap(name, font, Color32::WHITE);
    let rect = align.anchor_size(at, galley.size());
    let inside = picture.shrink(3.0);
    let dx = (inside.right() - rect.right()).min(0.0);
    let dx = dx + (inside.left() - (rect.left() + dx)).max(0.0);
    let dy = (inside.bottom() - rect.bottom()).min(0.0);
    let dy = dy + (inside.top() - (rect.top() + dy)).max(0.0);
    let rect = rect.translate(egui::vec2(dx, dy));
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

/// Each light as a marker where the view draws it, or at the picture's edge towards it; a
/// marker can be dragged (in the plane facing the viewer), which moves the light.
pub(super) fn lights_ui(
    ui: &mut Ui,
    o: &Overlay,
    picture: &egui::Response,
    state: &mut Shaded<'_>,
    scene: &phonglab_core::Scene,
) -> Lights {
    let grabbed = grabbed_from_picture(ui, picture);
    let mut out = Lights { dragging: false, marks: Vec::new(), cones: Vec::new() };
    let mut hits = Vec::new();
    let mut moved = None;
    for (i, l) in state.edit.doc.scene.lights.iter().enumerate() {
        let in_object = o.object_from_eye * scene.light_pos_in_eye(l);
        // A directional light is drawn in its direction, a little outside the object.
        let p = if in_object.w == 0.0 {
            (in_object.truncate().normalize_or_zero() * 1.2).extend(1.0)
        } else {
            in_object / in_object.w
        };
        // A spotlight's cone: its rim where it reaches the object, drawn even when the light
        // itself is off the picture (the spotlight preset's is above the view).
        let cone = spot_cone(o, scene, l, p);
        let spot_ink = crate::app::widgets::palette::ink(ui, crate::app::widgets::palette::SPOT);
        if let Some(rim) = &cone {
            ui.painter_at(o.rect).add(egui::Shape::closed_line(rim.clone(), egui::Stroke::new(1.5, spot_ink)));
            out.cones.push(egui::Rect::from_points(rim).intersect(o.rect));
        }
        let seen = o.screen_from_object(p);
        let to = match seen.filter(|pos| o.rect.expand(-4.0).contains(*pos)) {
            Some(pos) => {
                if let Some(rim) = &cone {
                    // On the picture, the cone's sides from the light to its rim.
                    for q in rim.iter().step_by(6) {
                        ui.painter_at(o.rect).line_segment([pos, *q], egui::Stroke::new(1.5, spot_ink));
                    }
                }
                let hit = egui::Rect::from_center_size(pos, egui::vec2(18.0, 18.0));
                let (strong, held) = marker_ui(ui, hit, i, picture, grabbed);
                let ring = if strong { 3.0 } else { 1.5 };
                ui.painter().circle(pos, 7.0, MARKER, egui::Stroke::new(ring, Color32::BLACK));
                let at = pos + egui::vec2(9.0, -9.0);
                let name = t!("light-name", index = i.to_string());
                let name = name_on_picture(ui, at, egui::Align2::LEFT_BOTTOM, name, o.rect);
                out.marks.push(hit.union(name));
                hits.push((i, hit));
                // The marker follows the pointer (it is small, so grabbing it off-centre
                // moves it by at most its radius).
                held.map(|h| h.pointer.unwrap_or(pos + h.delta)).and_then(|at| o.object_at(at, p))
            }
            None => {
                // Outside the picture (or behind the camera): an arrow at the edge, towards it.
                let towards = match seen {
                    Some(pos) => pos - o.rect.center(),
                    None => {
                        let e = (o.object_from_eye.inverse() * p).truncate();
                        egui::vec2(e.x as f32, -e.y as f32)
                    }
                };
                let mark = light_off_view_ui(ui, o.rect, towards, i, seen.is_none());
                out.marks.push(mark);
                hits.push((i, mark));
                let (strong, held) = marker_ui(ui, mark, i, picture, grabbed);
                if strong {
                    ui.painter().rect_stroke(mark, 4.0, egui::Stroke::new(2.0, MARKER), egui::StrokeKind::Outside);
                }
                // Dragged, it moves the light too, in the plane facing the viewer: one in
                // front to the pointer at its depth (it comes onto the picture under the
                // hand), one behind the camera by the drag, at its distance.
                held.and_then(|h| match seen {
                    Some(_) => h.pointer.and_then(|at| o.object_at(at, p)),
                    None => o.moved_behind(p, h.delta),
                })
            }
        };
        if let Some(to) = to {
            out.dragging = true;
            moved = Some((i, to, in_object.w == 0.0));
        }
    }
    remember_marks(ui, hits);
    if let Some((i, to, directional)) = moved {
        move_light(o, state, scene, i, to, directional);
    }
    out
}

/// Moves light `i` to the object-space point `to` (for a directional light, its direction
/// from the object), in its own coordinates.
fn move_light(
    o: &Overlay,
    state: &mut Shaded<'_>,
    scene: &phonglab_core::Scene,
    i: usize,
    to: DVec4,
    directional: bool,
) {
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
