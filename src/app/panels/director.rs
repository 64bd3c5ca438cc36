//! The director's view: the scene from outside (the eye and its frustum, the lights with
//! their rings and cones, the object, the worked vertex with N, L, V and H), in object,
//! world or eye space. Drag the background to turn around it, scroll to zoom, drag a light
//! or the eye to move it (the document changes, and every other view with it).
//!
//! The geometry is the core's ([`phonglab_core::director::stage`]); this projects it and
//! draws it, and turns a dragged light's new place back into its own coordinates.

use std::sync::Arc;

use egui::{Color32, Pos2, Rect, Sense, Stroke, Ui};
use glam::{DMat3, DMat4, DVec3, DVec4};
use phonglab_core::director::{self, Kind, Space, Stage};
use phonglab_core::mesh::Mesh;
use phonglab_core::transform::{of_camera_distance, perspective};
use phonglab_core::{Document, Framing, Scene, View};

use crate::app::panels::shaded::cache::mesh_for;
use crate::app::widgets::label_placement::Segment;
use crate::app::widgets::palette;
use crate::{locale, t};

/// The window's switch, the space shown, and the director's own camera.
#[derive(Clone, Debug, PartialEq)]
pub struct DirectorState {
    /// The window is open.
    pub open: bool,
    /// The space shown.
    pub space: Space,
    /// The director's camera: turned about the vertical (degrees) ...
    pub yaw: f64,
    /// ... and tilted (degrees).
    pub pitch: f64,
    /// Zoom: 1 frames the scene.
    pub zoom: f64,
    /// What is being dragged.
    dragging: Option<Dragged>,
}

/// What a drag in the director's view moves.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Dragged {
    /// Light `i`.
    Light(usize),
    /// The eye.
    Eye,
}

impl Default for DirectorState {
    fn default() -> Self {
        Self { open: false, space: Space::World, yaw: 35.0, pitch: 25.0, zoom: 1.0, dragging: None }
    }
}

/// The scene the view shows and how: the shaded view's world (its mesh, its camera's
/// frustum) when the worked vertex is on the shaded object, else the worked calculation's
/// own scene under the worksheet's window (openFrameworks' 60-degree camera, 1024x768).
/// The mesh comes from `meshes`, the shaded view's cache ([`mesh_for`]): the director
/// draws the very mesh the shaded view shows, built only when its shape changes.
pub fn scene_of(doc: &Document, meshes: &mut Option<(View, Arc<Mesh>)>) -> (Scene, Option<Arc<Mesh>>, DMat4) {
    if on_object(doc) {
        let mesh = mesh_for(meshes, &doc.view).clone();
        (doc.shaded_scene(), Some(mesh), phonglab_core::view::view_projection(1.0))
    } else {
        let d = of_camera_distance(768.0);
        (doc.scene.clone(), None, perspective(60.0, 1024.0 / 768.0, d / 10.0, d * 10.0))
    }
}

/// Is the worked vertex on the shaded object (seen by the shaded view's orbit camera)?
fn on_object(doc: &Document) -> bool {
    doc.with_vertex_as_shaded(doc.scene.vertex) == *doc && doc.view.framing == Framing::Orbit
}

/// Projects the stage's space onto a square on screen: the director's camera orbiting the
/// stage's centre.
struct Projection {
    rect: Rect,
    centre: DVec3,
    turn: DMat3,
    distance: f64,
    focal: f64,
}

impl Projection {
    fn new(rect: Rect, st: &Stage, d: &DirectorState) -> Self {
        let turn = DMat3::from_rotation_x(d.pitch.to_radians()) * DMat3::from_rotation_y(-d.yaw.to_radians());
        let focal = 1.0 / (20.0f64).to_radians().tan();
        Self { rect, centre: st.centre, turn, distance: st.radius * focal * 1.15 / d.zoom.max(0.05), focal }
    }

    /// A point on screen, or `None` behind the director's eye.
    fn screen(&self, p: DVec3) -> Option<Pos2> {
        let q = self.turn * (p - self.centre);
        let depth = self.distance - q.z;
        if depth <= self.distance * 1e-3 {
            return None;
        }
        let s = self.focal * self.rect.width() as f64 * 0.5 / depth;
        let c = self.rect.center();
        Some(Pos2::new(c.x + (q.x * s) as f32, c.y - (q.y * s) as f32))
    }

    /// The point of the space shown under screen point `pos`, at the depth of `at`.
    fn unproject(&self, pos: Pos2, at: DVec3) -> DVec3 {
        let q = self.turn * (at - self.centre);
        let depth = self.distance - q.z;
        let s = self.focal * self.rect.width() as f64 * 0.5 / depth;
        let c = self.rect.center();
        let moved = DVec3::new((pos.x - c.x) as f64 / s, -(pos.y - c.y) as f64 / s, q.z);
        self.turn.transpose() * moved + self.centre
    }
}

/// Where the window draws the point `p` of stage `st` in a picture at `rect`, seen as `d`
/// says (for tests and for placing marks).
pub fn screen_point(rect: Rect, st: &Stage, d: &DirectorState, p: DVec3) -> Option<Pos2> {
    Projection::new(rect, st, d).screen(p)
}

/// How a segment of each kind is drawn: whole, or (H, and M n beside N) in dashes or
/// dots, so that no two vectors are told apart by colour alone, as in the vector plot.
pub fn pattern_of(kind: Kind) -> Option<(f32, f32)> {
    match kind {
        Kind::Halfway(_) => Some((6.0, 4.0)),
        Kind::NaiveNormal => Some((2.0, 3.0)),
        _ => None,
    }
}

/// Colour and width of a segment of each kind; the vectors' colours are the vector plot's
/// (Okabe and Ito's), at 3:1 against the picture's background `bg`.
fn stroke_of(kind: Kind, ink: Color32, light: Color32, bg: Color32) -> Stroke {
    let on = |c: Color32| palette::ink_on(c, bg);
    let alpha = |c: Color32, a: f64| Color32::from_rgba_unmultiplied(c.r(), c.g(), c.b(), (a * 255.0) as u8);
    match kind {
        Kind::Object => Stroke::new(0.6, alpha(ink, 0.25)),
        Kind::Eye | Kind::Vertex => Stroke::new(1.5, ink),
        Kind::Frustum => Stroke::new(1.0, alpha(ink, 0.45)),
        Kind::Viewport => Stroke::new(1.5, alpha(palette::N, 0.9)),
        Kind::Light(_) => Stroke::new(1.5, light),
        Kind::Ring(_, f) => Stroke::new(1.0, alpha(light, if f >= 0.5 { 0.8 } else { 0.4 })),
        Kind::Cone(_, s) => Stroke::new(1.0 + s as f32, alpha(light, 0.15 + 0.85 * s)),
        Kind::Normal => Stroke::new(2.5, on(palette::N)),
        Kind::NaiveNormal => Stroke::new(2.5, on(palette::NAIVE_NORMAL)),
        Kind::ToLight(_) => Stroke::new(2.5, on(palette::L)),
        Kind::ToEye => Stroke::new(2.5, on(palette::V)),
        Kind::Halfway(_) => Stroke::new(2.0, on(palette::H)),
        Kind::Patch => Stroke::new(1.5, alpha(palette::V, 0.8)),
    }
}

/// The director's window, while open; returns the document with a dragged light moved.
/// `meshes`: the shaded view's mesh cache, whose mesh it draws on the shaded object.
pub fn director_window_ui(
    ctx: &egui::Context,
    d: &mut DirectorState,
    doc: &Document,
    meshes: &mut Option<(View, Arc<Mesh>)>,
) -> Option<Document> {
    if !d.open {
        return None;
    }
    let mut open = true;
    let mut changed = None;
    let screen = ctx.content_rect();
    let side = (screen.height() * 0.62).clamp(220.0, 640.0);
    egui::Window::new(t!("director"))
        .open(&mut open)
        .default_pos(egui::pos2(screen.center().x - side * 0.5, screen.top() + 40.0))
        .resizable(false)
        .show(ctx, |ui| changed = director_ui(ui, d, doc, meshes, side));
    d.open = open;
    changed
}

/// The switch, the picture and its legend.
fn director_ui(
    ui: &mut Ui,
    d: &mut DirectorState,
    doc: &Document,
    meshes: &mut Option<(View, Arc<Mesh>)>,
    side: f32,
) -> Option<Document> {
    ui.horizontal(|ui| {
        ui.label(t!("director-space"));
        for s in Space::ALL {
            ui.selectable_value(&mut d.space, s, locale::tr(s.message_id()));
        }
    });
    let (scene, mesh, clip_from_eye) = scene_of(doc, meshes);
    let st = match director::stage(&scene, mesh.as_deref(), clip_from_eye, d.space) {
        Ok(st) => st,
        Err(e) => {
            ui.colored_label(palette::ERROR, e.to_string());
            return None;
        }
    };
    let (rect, resp) = ui.allocate_exact_size(egui::vec2(side, side), Sense::click_and_drag());
    resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, t!("director")));
    crate::app::widgets::fields::landmark(ui.ctx(), "director-picture", rect);
    let bg = ui.visuals().extreme_bg_color;
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 4.0, bg);
    let proj = Projection::new(rect, &st, d);
    let ink = ui.visuals().text_color();
    // The lights' yellow, darkened where the theme is light.
    let light = palette::ink(ui, palette::SPOT);
    // The lines the marks' names keep clear of: all but the object's mesh and the
    // lights' rings and cones (too many to leave room).
    let mut lines = Vec::new();
    for s in &st.segments {
        if let (Some(a), Some(b)) = (proj.screen(s.a), proj.screen(s.b)) {
            let stroke = stroke_of(s.kind, ink, light, bg);
            if !matches!(s.kind, Kind::Object | Kind::Ring(..) | Kind::Cone(..)) {
                let half_width = stroke.width * 0.5 + 1.0;
                lines.push(crate::app::widgets::label_placement::Segment { a, b, half_width });
            }
            match pattern_of(s.kind) {
                Some((dash, gap)) => {
                    painter.extend(egui::Shape::dashed_line(&[a, b], stroke, dash, gap));
                }
                None => {
                    painter.line_segment([a, b], stroke);
                }
            }
        }
    }
    let mut light_marks = Vec::new();
    let mut eye_mark = None;
    let mut named = Vec::new();
    for m in &st.marks {
        let Some(at) = proj.screen(m.at) else { continue };
        let (name, colour) = match m.kind {
            Kind::Eye => {
                eye_mark = Some(at);
                (t!("director-eye"), ink)
            }
            Kind::Light(i) => {
                light_marks.push((i, at));
                (t!("director-light", n = i as i64), light)
            }
            _ => (t!("director-vertex"), ink),
        };
        painter.circle_filled(at, 5.0, colour);
        // The name at a text's contrast on the picture (the lights' yellow is a symbol's).
        named.push((at, name, palette::ink_with_contrast(colour, bg, palette::TEXT_CONTRAST)));
    }
    mark_names_ui(ui, rect, &named, &lines);
    let marks = Marks { lights: &light_marks, eye: eye_mark };
    let changed = drag_ui(ui, d, doc, &scene, &st, &proj, &resp, &marks);
    legend_ui(ui, &st);
    changed
}

/// The marks' names (the eye, each light, the vertex), each beside its dot, clear of every
/// dot, of the lines drawn (`lines`) and of each other (a light far behind the eye projects
/// near it), as labels on a backdrop of the picture's colour.
fn mark_names_ui(ui: &mut Ui, rect: Rect, named: &[(Pos2, String, Color32)], lines: &[Segment]) {
    use crate::app::widgets::label_placement::{Wanted, place};
    let font = egui::TextStyle::Small.resolve(ui.style());
    let galleys: Vec<_> =
        named.iter().map(|(_, name, c)| ui.painter().layout_no_wrap(name.clone(), font.clone(), *c)).collect();
    let mut keep_clear: Vec<Segment> =
        named.iter().map(|(at, ..)| Segment { a: *at, b: *at, half_width: 6.0 }).collect();
    keep_clear.extend_from_slice(lines);
    let wanted: Vec<Wanted> = named
        .iter()
        .zip(&galleys)
        .map(|((at, ..), g)| Wanted { anchor: *at, direction: egui::vec2(1.0, -1.0), size: g.size(), gap: 4.0 })
        .collect();
    let backdrop = ui.visuals().extreme_bg_color.gamma_multiply(0.85);
    for (((_, name, c), g), r) in named.iter().zip(galleys).zip(place(&wanted, &keep_clear, rect.shrink(2.0))) {
        let r = Rect::from_min_size(r.min, g.size());
        ui.painter().rect_filled(r.expand(1.0), 2.0, backdrop);
        let label = egui::Label::new(egui::RichText::new(name).font(font.clone()).color(*c)).selectable(false);
        // (Placed: the cursor stays below the picture, where the legend goes.)
        ui.place(r, label);
    }
}

/// Where the marks that can be dragged were drawn.
struct Marks<'a> {
    lights: &'a [(usize, Pos2)],
    eye: Option<Pos2>,
}

/// Dragging: a light's mark moves the light, the eye's moves the eye (each in the plane
/// facing the director, at its depth); anywhere else turns the director's camera;
/// scrolling zooms.
#[allow(clippy::too_many_arguments)]
fn drag_ui(
    ui: &Ui,
    d: &mut DirectorState,
    doc: &Document,
    scene: &Scene,
    st: &Stage,
    proj: &Projection,
    resp: &egui::Response,
    marks: &Marks<'_>,
) -> Option<Document> {
    // Where the press began: the drag starts only once the pointer has moved some way.
    if resp.drag_started()
        && let Some(p) = ui.input(|i| i.pointer.press_origin())
    {
        let light = marks.lights.iter().find(|(_, at)| at.distance(p) <= 10.0).map(|(i, _)| Dragged::Light(*i));
        let eye = marks.eye.filter(|at| at.distance(p) <= 10.0).map(|_| Dragged::Eye);
        d.dragging = light.or(eye);
    }
    if resp.drag_stopped() {
        d.dragging = None;
    }
    if resp.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            d.zoom = (d.zoom * (scroll as f64 * 0.002).exp()).clamp(0.2, 20.0);
        }
    }
    if !resp.dragged() {
        return None;
    }
    let eye_from_display = match d.space {
        Space::Eye => DMat4::IDENTITY,
        Space::World => scene.eye_from_world,
        Space::Object => scene.eye_from_object(),
    };
    let i = match d.dragging {
        None => {
            let delta = resp.drag_delta();
            d.yaw = (d.yaw + delta.x as f64 * 0.5).rem_euclid(360.0);
            d.pitch = (d.pitch + delta.y as f64 * 0.5).clamp(-89.0, 89.0);
            return None;
        }
        Some(Dragged::Eye) => {
            let (Some(p), Some(at)) = (resp.interact_pointer_pos(), st.marks.iter().find(|m| m.kind == Kind::Eye))
            else {
                return None;
            };
            let moved = proj.unproject(p, at.at);
            let world = scene.eye_from_world.inverse() * eye_from_display * moved.extend(1.0);
            return moved_eye(doc, scene, world.truncate() / world.w);
        }
        Some(Dragged::Light(i)) => i,
    };
    let (Some(at), Some(p)) = (st.lights.get(i).copied().flatten(), resp.interact_pointer_pos()) else { return None };
    let moved = proj.unproject(p, at);
    // Back to the light's own coordinates: the space shown to eye space, then by the
    // inverse of the modelview it was placed under.
    let light = doc.scene.lights.get(i)?;
    let own = scene.eye_from_light(&scene.lights[i]).inverse() * eye_from_display * moved.extend(1.0);
    let own = DVec4::new(own.x / own.w, own.y / own.w, own.z / own.w, light.position.w);
    let mut c = doc.clone();
    c.scene.lights[i].position = own;
    c.validate().is_ok().then_some(c)
}

/// `doc` with the eye moved to `eye` (world coordinates), still looking at what it looked
/// at: on the shaded object, the orbit camera's distance and angles (the worked vertex kept
/// on the object); else a lookAt camera towards the point straight ahead at the worked
/// vertex's distance, the same way up.
fn moved_eye(doc: &Document, scene: &Scene, eye: DVec3) -> Option<Document> {
    let mut c = doc.clone();
    if on_object(doc) {
        let d = eye.length();
        let u = eye / d.max(1e-12);
        c.view.camera.distance = d.clamp(0.6, 20.0);
        c.view.camera.pitch = u.y.clamp(-1.0, 1.0).asin().to_degrees().clamp(-89.0, 89.0);
        c.view.camera.yaw = (-u.x).atan2(u.z).to_degrees().rem_euclid(360.0);
        let c = c.with_vertex_as_shaded(c.scene.vertex);
        return c.validate().is_ok().then_some(c);
    }
    let world_from_eye = scene.eye_from_world.inverse();
    let old = world_from_eye.transform_point3(DVec3::ZERO);
    let forward = world_from_eye.transform_vector3(-DVec3::Z).normalize_or_zero();
    let up = world_from_eye.transform_vector3(DVec3::Y).normalize_or_zero();
    let p = scene.vertex.position;
    let vertex = scene.world_from_object.transform_point3(if p.w == 0.0 { p.truncate() } else { p.truncate() / p.w });
    let centre = old + forward * (vertex - old).length().max(1e-6);
    c.camera = phonglab_core::camera::CameraSpec::LookAt { eye, centre, up };
    c.scene.eye_from_world = c.camera.matrix().ok()?;
    c.validate().is_ok().then_some(c)
}

/// What the colours and rings mean, with the rings' radii.
fn legend_ui(ui: &mut Ui, st: &Stage) {
    ui.horizontal_wrapped(|ui| {
        // As drawn: H dashed (as in the vector plot).
        for (text, colour) in [("N", palette::N), ("L", palette::L), ("V", palette::V), ("- - H", palette::H)] {
            ui.colored_label(palette::ink(ui, colour), text);
        }
        ui.small(t!("director-legend"));
    });
    if st.naive_normal_off_deg > 0.5 {
        ui.horizontal_wrapped(|ui| {
            ui.colored_label(palette::ink(ui, palette::NAIVE_NORMAL), "· · · M n");
            ui.label(t!("director-naive-normal", degrees = locale::num(st.naive_normal_off_deg, 3)));
        });
        if st.rules_use_naive {
            ui.small(t!("director-rules-naive"));
        }
    }
    for (i, f, r) in &st.rings {
        ui.small(t!(
            "director-ring",
            n = *i as i64,
            percent = locale::num(100.0 * f, 3),
            distance = locale::num(*r, 4)
        ));
    }
}
