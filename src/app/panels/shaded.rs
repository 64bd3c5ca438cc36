//! The shaded view: the sphere, teapot or cylinder under the document's lights and
//! material, Flat, Gouraud or Phong, rendered by the core's CPU renderer.
//!
//! Drag to orbit, scroll to zoom; auto-rotate spins the object 0.5 degrees a frame, as the
//! Phong demo does. Clicking the surface makes the nearest mesh vertex the vertex of the
//! worked calculation, with this view's camera and spin, so both panels show one vertex.

use egui::{Color32, Sense, Ui};
use glam::{DVec3, DVec4};
use phonglab_core::library::DemoDeparture;
use phonglab_core::t;
use phonglab_core::{Document, FlatNormal, Framing, ObjectKind, Shading, Vertex, View};

use crate::app::panels::gpu_view::{self, Picture};
pub use crate::app::panels::view_cache::{DrawnBy, ShadedCache, ViewCache, mesh_for};
use crate::app::shell::state::{AppState, Evaluated, Message};

/// The pipeline's choices where OpenGL and the Phong demo differ, and the demo's
/// departures as switches: each flipped one is corrected in a second picture beside the
/// demo's own.
fn pipeline_ui(ui: &mut Ui, view: &mut View) {
    egui::CollapsingHeader::new(t!("pipeline")).id_salt("pipeline").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            let l = ui.label(t!("picture"));
            egui::ComboBox::from_id_salt("framing")
                .selected_text(view.framing.label())
                .show_ui(ui, |ui| {
                    for f in Framing::ALL {
                        ui.selectable_value(&mut view.framing, f, f.label());
                    }
                })
                .response
                .labelled_by(l.id);
            ui.checkbox(&mut view.phong_renormalize, t!("phong-renormalises"))
                .on_hover_text(t!("phong-renormalises-hover"));
            let mut derivative = view.flat_normal == FlatNormal::ScreenDerivatives;
            if ui
                .checkbox(&mut derivative, t!("flat-derivatives"))
                .on_hover_text(t!("flat-derivatives-hover"))
                .changed()
            {
                view.flat_normal = if derivative { FlatNormal::ScreenDerivatives } else { FlatNormal::Face };
            }
        });
    });
}

/// The demo's departures as switches (only those the document makes): one row that stays
/// where it is whatever is switched, and the reasons folded into one line that opens on a
/// click.
///
/// They stand across the whole centre, above the pictures, so that switching one (which
/// puts a second picture beside the first) moves nothing.
pub fn departures_ui(ui: &mut Ui, state: &mut AppState) {
    let departures: Vec<DemoDeparture> = DemoDeparture::ALL.into_iter().filter(|d| d.present_in(&state.doc)).collect();
    if departures.is_empty() {
        return;
    }
    let fixes = &mut state.view_options.demo_fixes;
    ui.horizontal_wrapped(|ui| {
        ui.label(t!("correct-the-demo"));
        for (k, d) in DemoDeparture::ALL.into_iter().enumerate() {
            if departures.contains(&d) {
                ui.checkbox(&mut fixes[k], d.fix_label()).on_hover_text(d.why());
            }
        }
    });
    egui::CollapsingHeader::new(t!("why-demo-differs")).id_salt("departures").default_open(false).show(ui, |ui| {
        ui.small(t!("why-demo-differs-intro"));
        for d in DemoDeparture::ALL {
            if departures.contains(&d) {
                ui.small(format!("{}: {}", d.fix_label(), d.why()));
            }
        }
    });
}

/// The mesh's resolution and the pipeline's choices.
fn view_options_ui(ui: &mut Ui, view: &mut View) {
    ui.horizontal_wrapped(|ui| {
        let count = |ui: &mut Ui, label: &str, v: &mut u32, r: std::ops::RangeInclusive<u32>| {
            crate::app::widgets::fields::whole_number_ui(ui, label, v, r);
        };
        match view.object {
            ObjectKind::Sphere => {
                count(ui, &t!("sphere-slices"), &mut view.sphere_slices, phonglab_core::view::SLICES_RANGE);
                count(ui, &t!("sphere-stacks"), &mut view.sphere_stacks, phonglab_core::view::SLICES_RANGE);
            }
            ObjectKind::Teapot => count(ui, &t!("teapot-grid"), &mut view.teapot_grid, phonglab_core::view::GRID_RANGE),
            ObjectKind::Cylinder => {
                count(ui, &t!("cylinder-slices"), &mut view.cylinder_slices, phonglab_core::view::SLICES_RANGE);
                count(ui, &t!("cylinder-stacks"), &mut view.cylinder_stacks, phonglab_core::view::STACKS_RANGE);
                ui.checkbox(&mut view.cylinder_caps, t!("caps"));
            }
            ObjectKind::Obj => {
                if let Ok(o) = view.obj_mesh() {
                    ui.small(t!("mesh-triangles", count = o.mesh.triangle_count(), notes = o.notes.join("; ")));
                }
            }
        }
    });
    pipeline_ui(ui, view);
}

/// The shaded view's own choices, kept between frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShadedOptions {
    /// Which of the Phong demo's departures the corrected picture corrects, in the order
    /// of [`phonglab_core::library::DemoDeparture::ALL`].
    pub demo_fixes: [bool; 3],
    /// Which renderer draws the view.
    pub renderer: crate::app::panels::gpu_view::RendererChoice,
    /// The OBJ file path typed under View options.
    pub obj_path: String,
}

/// The view's controls and the image (beside it, the corrected picture or the heat map),
/// with N, L, V and H (or R) drawn at the worked calculation's vertex and the lights as
/// markers that can be dragged.
///
/// Returns where the picture (and the one beside it) was drawn.
pub fn shaded_ui(ui: &mut Ui, state: &mut AppState, cache: &mut ShadedCache, eval: &Evaluated) -> Vec<egui::Rect> {
    toolbar_ui(ui, state, cache);
    let shown = pictures_ui(ui, state, cache);
    let rects = std::iter::once(shown.response.rect).chain(shown.second).collect();
    interaction_ui(ui, state, cache, &shown, eval);
    rects
}

/// The view's toolbar: the object and the shading (and, not presenting, the switches and
/// the view options); applies what changed, and turns the object when it spins.
fn toolbar_ui(ui: &mut Ui, state: &mut AppState, cache: &ShadedCache) {
    let mut view = state.doc.view.clone();
    let presenting = state.ui.layout.presenting;
    let mut open_obj_requested = None;
    ui.horizontal_wrapped(|ui| {
        for (k, o) in [("s", ObjectKind::Sphere), ("t", ObjectKind::Teapot), ("c", ObjectKind::Cylinder)] {
            ui.selectable_value(&mut view.object, o, o.label()).on_hover_text(t!("key-hint", key = k));
        }
        if let Some(path) = &view.obj {
            let tip = t!("mesh-tip", path = path);
            ui.selectable_value(&mut view.object, ObjectKind::Obj, ObjectKind::Obj.label()).on_hover_text(tip);
        }
        ui.separator();
        for (k, s) in [("1", Shading::Gouraud), ("2", Shading::Phong), ("3", Shading::Flat)] {
            ui.selectable_value(&mut view.shading, s, s.label()).on_hover_text(t!("key-hint", key = k));
        }
        if presenting {
            // In front of a class: the object and the shading only (the rest is in the drawer
            // and on the keys).
            return;
        }
        ui.separator();
        ui.checkbox(&mut view.auto_rotate, t!("auto-rotate")).on_hover_text(t!("auto-rotate-hover"));
        ui.checkbox(&mut view.demo_normals, t!("demo-normals")).on_hover_text(t!("demo-normals-hover"));
        ui.checkbox(&mut state.cost.heat_map, t!("heat-map")).on_hover_text(t!("heat-map-hover"));
    });
    if !presenting {
        // Opened, the options scroll within a part of the view's space, so the picture
        // stays on screen (smaller) rather than being pushed below the window.
        let most = ui.available_height() * 0.45;
        egui::CollapsingHeader::new(t!("view-options")).id_salt("view options").show(ui, |ui| {
            egui::ScrollArea::vertical().max_height(most).show(ui, |ui| {
                renderer_ui(ui, state, &cache.main.drawn_by);
                view_options_ui(ui, &mut view);
                ui.horizontal_wrapped(|ui| {
                    let l = ui.label(t!("mesh-file"));
                    let field = ui
                        .add(
                            egui::TextEdit::singleline(&mut state.view_options.obj_path)
                                .desired_width(180.0)
                                .hint_text("path/to/mesh.obj"),
                        )
                        .labelled_by(l.id);
                    let enter = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                    if ui.button(t!("show-mesh")).on_hover_text(t!("show-mesh-hover")).clicked() || enter {
                        open_obj_requested = Some(std::path::PathBuf::from(state.view_options.obj_path.trim()));
                    }
                });
            });
        });
    }
    if view != state.doc.view {
        let mut c = state.doc.clone();
        c.view = view;
        state.apply(c);
    }
    if let Some(p) = open_obj_requested {
        crate::app::panels::files::open_obj(state, &p);
    }
    // The spin is not an edit: it stays finite and in range, and must not clear a message.
    if state.doc.view.auto_rotate {
        state.doc.view.spin_degrees = (state.doc.view.spin_degrees + 0.5).rem_euclid(360.0);
        ui.ctx().request_repaint();
    }
}

/// What [`pictures_ui`] drew: the main picture's response and size, the second picture's
/// place (the demo corrected, or the heat map), and the scene as the view lights it.
struct Shown {
    response: egui::Response,
    second: Option<egui::Rect>,
    /// The picture's side on screen, and in the renderer's pixels.
    size: egui::Vec2,
    px: usize,
    scene: phonglab_core::Scene,
}

/// The pictures: the shaded view sized to the space it was given (whole pixels), drawn by
/// the GPU or the CPU, and beside it the demo corrected or the error heat map.
fn pictures_ui(ui: &mut Ui, state: &mut AppState, cache: &mut ShadedCache) -> Shown {
    // The corrected document, when a departure the document makes is switched off.
    let corrected = corrected_document(&state.doc, &state.view_options.demo_fixes);

    // The part of the centre this view was given (a row above cannot have widened it).
    let avail = egui::vec2(ui.max_rect().width(), ui.available_size().y);
    let heat = state.cost.heat_map;
    let beside = heat || corrected.is_some();
    // Leave room for the caption line above the image (and the picture beside it).
    let width = if beside { (avail.x - 8.0) / 2.0 } else { avail.x };
    // Room for the caption above the image (up to three lines when it wraps beside another).
    let caption_lines = if beside { 3.0 } else { 2.0 };
    let side = width.min(avail.y - caption_lines * ui.text_style_height(&egui::TextStyle::Small) - 8.0).max(64.0);
    let ppp = ui.ctx().pixels_per_point();
    let px = ((side * ppp) as usize).clamp(64, 1024);
    // One texel a screen pixel (no resampling), unless the view is wider than 1024 pixels.
    let side = if (side * ppp) as usize <= 1024 { px as f32 / ppp } else { side };
    let main = prepare_picture(ui.ctx(), state, &mut cache.main, &state.doc, px, 0, "shaded view");
    let mut main_gpu = picture_or_refusal(state, main, &t!("shaded-cannot-render"));
    let mut corrected_gpu = corrected.as_ref().and_then(|c| {
        let picture = prepare_picture(ui.ctx(), state, &mut cache.corrected, c, px, 1, "corrected view");
        picture_or_refusal(state, picture, &t!("corrected-cannot-render"))
    });
    // The scene as the view lights it, once: with the heat map on, from the setup it asks for.
    let scene = if heat {
        let setup = state.doc.shaded_setup(state.settings.pow);
        state.cost.want_heat_map(&setup);
        setup.scene
    } else {
        state.doc.shaded_scene()
    };
    let size = egui::vec2(side, side);
    let caption = format!(
        "{} {}: {}{}",
        state.doc.view.object.label(),
        state.doc.view.shading.label(),
        drawn_caption(&cache.main),
        if corrected.is_some() { t!("the-demos-own") } else { String::new() }
    );
    let mut second = None;
    let resp = ui
        .horizontal_top(|ui| {
            let resp = ui
                .vertical(|ui| {
                    // Captions wrap within the picture's width rather than widen its column.
                    ui.set_max_width(side);
                    let label = ui.small(caption);
                    let picture = picture_ui(ui, &cache.main, main_gpu.take(), size, Sense::click_and_drag())
                        .on_hover_text(t!("picture-hover"))
                        .labelled_by(label.id);
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
                        .filter(|(d, on)| *on && d.present_in(&state.doc))
                        .map(|(d, _)| d.fix_label())
                        .collect();
                    let label = ui.small(t!("corrected", fixes = fixed.join(", ")));
                    let r = picture_ui(ui, &cache.corrected, corrected_gpu.take(), size, Sense::hover())
                        .labelled_by(label.id);
                    second = Some(r.rect);
                });
            } else if heat {
                second = Some(ui.scope(|ui| crate::app::panels::cost::heat_map_ui(ui, state, side)).response.rect);
            }
            resp
        })
        .inner;
    Shown { response: resp, second, size, px, scene }
}

/// What the pointer does on the picture: the vectors and lights drawn on it, a light
/// dragged, the orbit camera turned and zoomed, a vertex picked.
fn interaction_ui(ui: &mut Ui, state: &mut AppState, cache: &mut ShadedCache, shown: &Shown, eval: &Evaluated) {
    let (resp, size, px, scene) = (&shown.response, shown.size, shown.px, &shown.scene);
    let camera = state.doc.view.camera;
    let overlay = Overlay {
        rect: resp.rect,
        clip_from_object: state.doc.view.clip_from_object(),
        object_from_eye: scene.eye_from_object().inverse(),
    };
    vectors_on_object_ui(ui, overlay.rect, &state.doc, eval);
    let dragged_light = lights_ui(ui, &overlay, state, scene);

    let mut cam = camera;
    if resp.dragged() && !dragged_light && state.doc.view.framing == Framing::Orbit {
        let d = resp.drag_delta();
        cam.yaw = (cam.yaw + d.x as f64 * 0.5).rem_euclid(360.0);
        cam.pitch = (cam.pitch + d.y as f64 * 0.5).clamp(-89.0, 89.0);
    }
    if resp.hovered() && state.doc.view.framing == Framing::Orbit {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            cam.distance = (cam.distance * (-scroll as f64 * 0.002).exp()).clamp(0.6, 20.0);
        }
    }
    if cam != camera {
        let mut c = state.doc.clone();
        c.view.camera = cam;
        state.apply(c);
    }
    if resp.clicked()
        && let Some(p) = resp.interact_pointer_pos()
    {
        let rel = (p - resp.rect.min) / size;
        let (x, y) = ((rel.x * px as f32) as usize, (rel.y * px as f32) as usize);
        // Picking reads the CPU renderer's triangle buffer: after a GPU frame, the CPU
        // renderer draws the same picture first (only on a click).
        if matches!(cache.main.drawn_by, DrawnBy::Gpu { .. })
            && let Err(e) = cache.main.render(ui.ctx(), &state.doc, state.settings.pow, px, "shaded view")
        {
            state.message = Some(Message::Refused(format!("{}: {e}", t!("shaded-cannot-render"))));
            return;
        }
        let mesh = mesh_for(&mut cache.main.mesh, &state.doc.view);
        if let Some(i) = cache.main.renderer.pick(mesh, x, y) {
            let c = state.doc.with_vertex_as_shaded(Vertex::from_f32(mesh.positions[i], mesh.normals[i]));
            if state.apply(c) {
                let object = state.doc.view.object.label().to_lowercase();
                state.message = Some(Message::Info(t!("picked-vertex", index = i.to_string(), object = object)));
            }
        }
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

/// N, V, and each light's L and H (or R) as arrows on the image `rect`: (name, colour,
/// from, to), from the vertex on the object, a third of the object's size long. Empty
/// unless the worked calculation's vertex is one the view draws (after a click on the
/// surface, or in any scene whose frame is the view's).
pub fn vector_arrows(
    doc: &Document,
    eval: &Evaluated,
    rect: egui::Rect,
) -> Vec<(String, Color32, egui::Pos2, egui::Pos2)> {
    let mut out = Vec::new();
    if doc.with_vertex_as_shaded(doc.scene.vertex) != *doc || doc.scene.vertex.position.w == 0.0 {
        return out;
    }
    let scene = doc.shaded_scene();
    let eye_from_object = scene.eye_from_object();
    let o = Overlay { rect, clip_from_object: doc.view.clip_from_object(), object_from_eye: eye_from_object.inverse() };
    let p = eye_from_object * doc.scene.vertex.position;
    let pos_in_eye = p.truncate() / p.w;
    let len = 0.35 * eye_from_object.transform_vector3(DVec3::X).length();
    let Some(from) = o.screen_from_eye(pos_in_eye).filter(|f| rect.contains(*f)) else { return out };
    let mut add = |vec: DVec3, c: Color32, name: String| {
        if vec.length() > 0.0
            && let Some(to) = o.screen_from_eye(pos_in_eye + vec.normalize() * len)
        {
            out.push((name, c, from, to));
        }
    };
    let many = eval.lights.len() > 1;
    for lv in &eval.lights {
        let sfx = if many { lv.index.to_string() } else { String::new() };
        add(lv.l, crate::app::widgets::palette::L, format!("L{sfx}"));
        match doc.scene.rules.specular {
            phonglab_core::SpecularModel::BlinnPhong => add(lv.h, crate::app::widgets::palette::H, format!("H{sfx}")),
            phonglab_core::SpecularModel::Phong => add(lv.r, crate::app::widgets::palette::R, format!("R{sfx}")),
        }
    }
    add(eval.v, crate::app::widgets::palette::V, "V".into());
    add(eval.n, crate::app::widgets::palette::N, "N".into());
    out
}

/// Draws [`vector_arrows`] on the image, every arrow the same length on screen (a fifth of
/// the image) in the direction the view shows it, ⊙ or ⊗ for one that points at the viewer
/// or away, in the plot's colours and styles, each letter placed clear of the others and of
/// the arrows ([`crate::app::widgets::label_placement`]).
fn vectors_on_object_ui(ui: &Ui, rect: egui::Rect, doc: &Document, eval: &Evaluated) {
    use crate::app::panels::vector_plot::{draw_arrow, end_on_marker, paint_labels};
    let arrows = vector_arrows(doc, eval, rect);
    let Some((_, _, from, _)) = arrows.first() else { return };
    let from = *from;
    let p = ui.painter_at(rect);
    let len = rect.width().min(rect.height()) * 0.2;
    let width = (3.0 / ui.ctx().pixels_per_point()).max(len * 0.03);
    let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Body) * 1.5);
    let outline = if ui.visuals().dark_mode { Color32::BLACK } else { Color32::WHITE };
    let mut lines = Vec::new();
    let mut wanted = Vec::new();
    let mut galleys = Vec::new();
    let mut end_on = 0;
    for (name, c, _, to) in &arrows {
        let c = crate::app::widgets::palette::ink(ui, *c);
        let d = *to - from;
        let dashed = name.starts_with('H') || name.starts_with('R');
        if d.length() < 3.0 {
            let (line, label) = end_on_marker(&p, from, end_on, width, c, true);
            end_on += 1;
            lines.push(line);
            wanted.push(label);
        } else {
            let tip = from + d.normalized() * len;
            // A dark (or light) edge under the colour, so the arrow reads on any surface.
            draw_arrow(&p, from, tip, width * 1.8, outline, false, false);
            lines.push(draw_arrow(&p, from, tip, width, c, dashed, false));
            wanted.push(crate::app::widgets::label_placement::Wanted {
                anchor: tip,
                direction: d,
                size: egui::Vec2::ZERO,
                gap: width,
            });
        }
        galleys.push(p.layout_no_wrap(name.clone(), font.clone(), c));
    }
    paint_labels(&p, wanted, galleys, &lines, rect, Some(outline.gamma_multiply(0.6)));
    p.circle_filled(from, width * 1.3, crate::app::widgets::palette::ink(ui, crate::app::widgets::palette::N));
}

/// A light outside the picture: a triangle on the picture's edge pointing towards it, and
/// its name (saying so when it is behind the camera, where no edge is nearer than another).
fn light_off_view_ui(ui: &Ui, rect: egui::Rect, towards: egui::Vec2, i: usize, behind: bool) {
    let d = if towards.length() > 1e-3 { towards.normalized() } else { egui::vec2(0.0, -1.0) };
    // Where the ray from the centre along `d` leaves the picture, 14 points inside.
    let half = rect.size() * 0.5 - egui::vec2(14.0, 14.0);
    let t = (half.x / d.x.abs().max(1e-6)).min(half.y / d.y.abs().max(1e-6));
    let tip = rect.center() + d * t;
    let side = egui::vec2(-d.y, d.x) * 7.0;
    let (fill, ink) =
        (Color32::from_rgb(255, 230, 120), if ui.visuals().dark_mode { Color32::WHITE } else { Color32::BLACK });
    ui.painter().add(egui::Shape::convex_polygon(
        vec![tip + d * 10.0, tip - d * 4.0 + side, tip - d * 4.0 - side],
        fill,
        egui::Stroke::new(1.5, Color32::BLACK),
    ));
    let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Small));
    let at = tip - d * 16.0;
    let name = if behind { t!("light-behind", index = i.to_string()) } else { t!("light-name", index = i.to_string()) };
    let align = if d.x > 0.3 {
        egui::Align2::RIGHT_CENTER
    } else if d.x < -0.3 {
        egui::Align2::LEFT_CENTER
    } else {
        egui::Align2::CENTER_CENTER
    };
    ui.painter().text(at, align, name, font, ink);
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
/// facing the viewer), which moves the light. Returns whether a marker is being dragged.
fn lights_ui(ui: &mut Ui, o: &Overlay, state: &mut AppState, scene: &phonglab_core::Scene) -> bool {
    let mut dragging = false;
    let mut moved = None;
    for (i, l) in state.doc.scene.lights.iter().enumerate() {
        let eye = scene.light_pos_in_eye(l);
        let in_object = o.object_from_eye * eye;
        // A directional light is drawn in its direction, a little outside the object.
        let p = if in_object.w == 0.0 {
            (in_object.truncate().normalize_or_zero() * 1.2).extend(1.0)
        } else {
            in_object / in_object.w
        };
        let centre = o.rect.center();
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
                light_off_view_ui(ui, o.rect, towards, i, seen.is_none());
                continue;
            }
        };
        if let Some(cone) = spot_cone(o, scene, l, p) {
            let c = crate::app::widgets::palette::ink(ui, crate::app::widgets::palette::SPOT);
            let stroke = egui::Stroke::new(1.5, c);
            for q in cone.iter().step_by(6) {
                ui.painter_at(o.rect).line_segment([pos, *q], stroke);
            }
            ui.painter_at(o.rect).add(egui::Shape::closed_line(cone, stroke));
        }
        let hit = egui::Rect::from_center_size(pos, egui::vec2(18.0, 18.0));
        let r = ui.interact(hit, ui.scope_id().with(("light marker", i)), Sense::drag());
        r.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, format!("light {i} marker")));
        let r = r.on_hover_text(t!("light-drag", index = i.to_string()));
        let ring = if r.hovered() || r.dragged() { 3.0 } else { 1.5 };
        ui.painter().circle(pos, 7.0, Color32::from_rgb(255, 230, 120), egui::Stroke::new(ring, Color32::BLACK));
        let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Small));
        let text = if ui.visuals().dark_mode { Color32::WHITE } else { Color32::BLACK };
        ui.painter().text(
            pos + egui::vec2(9.0, -9.0),
            egui::Align2::LEFT_BOTTOM,
            t!("light-name", index = i.to_string()),
            font,
            text,
        );
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
        let mut c = state.doc.clone();
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
            state.apply(c);
        }
    }
    dragging
}

/// `doc` with each departure switched on in `fixes` (and present in `doc`) corrected, or
/// `None` when there is nothing to correct.
pub fn corrected_document(doc: &Document, fixes: &[bool; 3]) -> Option<Document> {
    let mut c = doc.clone();
    let mut any = false;
    for (d, on) in DemoDeparture::ALL.into_iter().zip(fixes) {
        if *on && d.present_in(doc) {
            d.correct(&mut c);
            any = true;
        }
    }
    any.then_some(c)
}

/// The renderer choice, and who drew the last picture (and why not the GPU).
fn renderer_ui(ui: &mut Ui, state: &mut AppState, drawn_by: &DrawnBy) {
    ui.horizontal_wrapped(|ui| {
        let l = ui.label(t!("renderer"));
        egui::ComboBox::from_id_salt("renderer")
            .selected_text(state.view_options.renderer.label())
            .show_ui(ui, |ui| {
                for c in gpu_view::RendererChoice::ALL {
                    ui.selectable_value(&mut state.view_options.renderer, c, c.label());
                }
            })
            .response
            .labelled_by(l.id)
            .on_hover_text(t!("renderer-hover"));
    });
    match drawn_by {
        DrawnBy::Gpu { adapter } => {
            ui.small(t!("drawn-gpu", adapter = adapter.to_string()));
        }
        DrawnBy::Cpu { why } => {
            ui.small(t!("drawn-cpu", why = why.to_string()));
        }
        DrawnBy::Nothing => {}
    }
}

/// Draws `doc`'s picture for `cache`: on the GPU when the adapter, the renderer choice and
/// the scene allow it (the picture to paint is returned), otherwise on the CPU renderer
/// (into `cache`'s texture). `cache.drawn_by` says which, and why not the GPU.
fn prepare_picture(
    ctx: &egui::Context,
    state: &AppState,
    cache: &mut ViewCache,
    doc: &Document,
    px: usize,
    slot: u64,
    name: &str,
) -> Result<Option<Picture>, String> {
    let pow = state.settings.pow;
    let why = match gpu_view::why_cpu(state.gpu.as_ref(), state.view_options.renderer, doc, pow) {
        Some(why) => why,
        None => match cache.gpu_picture(doc, pow, px, slot) {
            Ok(p) => {
                let gpu = state.gpu.as_ref().expect("why_cpu says there is one");
                cache.drawn_by = DrawnBy::Gpu { adapter: format!("{}, {}", gpu.name, gpu.backend) };
                return Ok(Some(p));
            }
            Err(e) => e,
        },
    };
    cache.render(ctx, doc, pow, px, name)?;
    cache.drawn_by = DrawnBy::Cpu { why };
    Ok(None)
}

/// The GPU picture [`prepare_picture`] made, if any; a failure becomes the message `what:
/// reason` (the view then shows the last picture it has).
fn picture_or_refusal(state: &mut AppState, r: Result<Option<Picture>, String>, what: &str) -> Option<Picture> {
    r.unwrap_or_else(|e| {
        state.message = Some(Message::Refused(format!("{what}: {e}")));
        None
    })
}

/// The picture, `size` points: the GPU's through its paint callback, or the CPU
/// renderer's texture.
fn picture_ui(ui: &mut Ui, cache: &ViewCache, gpu: Option<Picture>, size: egui::Vec2, sense: Sense) -> egui::Response {
    match (gpu, &cache.texture) {
        (Some(p), _) => {
            let (rect, resp) = ui.allocate_exact_size(size, sense);
            gpu_view::paint(ui, rect, p);
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
        _ => t!("caption-cpu", ms = fmt_ms(cache.last_ms)),
    }
}

fn fmt_ms(ms: f64) -> String {
    phonglab_core::locale::decimal(&format!("{ms:.1}"))
}
