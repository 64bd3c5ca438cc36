//! The shaded view: the sphere, teapot or cylinder under the document's lights and
//! material, Flat, Gouraud or Phong, rendered by the core's CPU renderer.
//!
//! Drag to orbit, scroll to zoom; auto-rotate spins the object 0.5 degrees a frame, as the
//! Phong demo does. Clicking the surface makes the nearest mesh vertex the vertex of the
//! worked calculation, with this view's camera and spin, so both panels show one vertex.

use egui::{Color32, Sense, Ui};
use glam::DVec4;
use phonglab_core::library::DemoDeparture;
use phonglab_core::{Document, FlatNormal, Framing, ObjectKind, Shading, Vertex, View};

use super::state::{AppState, Message};
pub use super::view_cache::{ShadedCache, ViewCache, mesh_for};

/// The pipeline's choices where OpenGL and the Phong demo differ, and the demo's
/// departures as switches: each flipped one is corrected in a second picture beside the
/// demo's own.
fn pipeline_ui(ui: &mut Ui, view: &mut View, fixes: &mut [bool; 3], departures: &[DemoDeparture]) {
    egui::CollapsingHeader::new("Pipeline: OpenGL's or the demo's").id_salt("pipeline").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            let l = ui.label("Picture");
            egui::ComboBox::from_id_salt("framing")
                .selected_text(view.framing.label())
                .show_ui(ui, |ui| {
                    for f in Framing::ALL {
                        ui.selectable_value(&mut view.framing, f, f.label());
                    }
                })
                .response
                .labelled_by(l.id);
            ui.checkbox(&mut view.phong_renormalize, "Phong renormalises N")
                .on_hover_text("OpenGL shaders normalise the interpolated normal; the demo's does not");
            let mut derivative = view.flat_normal == FlatNormal::ScreenDerivatives;
            if ui
                .checkbox(&mut derivative, "Flat from dFdx/dFdy")
                .on_hover_text(
                    "The demo's Flat: each fragment lit with cross(dFdy(p), dFdx(p)); otherwise one colour per face",
                )
                .changed()
            {
                view.flat_normal = if derivative { FlatNormal::ScreenDerivatives } else { FlatNormal::Face };
            }
        });
    });
    if departures.is_empty() {
        return;
    }
    egui::CollapsingHeader::new("The demo's departures from OpenGL").id_salt("departures").default_open(true).show(
        ui,
        |ui| {
            ui.small("Flip a switch to see the corrected picture on the right, beside the demo's own on the left.");
            for (k, d) in DemoDeparture::ALL.into_iter().enumerate() {
                if departures.contains(&d) {
                    ui.checkbox(&mut fixes[k], d.fix_label());
                    ui.small(d.why());
                }
            }
        },
    );
}

/// The view's controls and the image (beside it, the corrected picture or the heat map).
pub fn shaded_ui(ui: &mut Ui, state: &mut AppState, cache: &mut ShadedCache) {
    let mut view = state.doc.view.clone();
    ui.horizontal_wrapped(|ui| {
        for (k, o) in [("s", ObjectKind::Sphere), ("t", ObjectKind::Teapot), ("c", ObjectKind::Cylinder)] {
            ui.selectable_value(&mut view.object, o, o.label()).on_hover_text(format!("key {k}"));
        }
        ui.separator();
        for (k, s) in [("1", Shading::Gouraud), ("2", Shading::Phong), ("3", Shading::Flat)] {
            ui.selectable_value(&mut view.shading, s, s.label()).on_hover_text(format!("key {k}"));
        }
        ui.separator();
        ui.checkbox(&mut view.auto_rotate, "Auto-rotate").on_hover_text("0.5 degrees a frame, as the demo (key A)");
        ui.checkbox(&mut view.demo_normals, "Demo's normals")
            .on_hover_text("normalize(position), as the demo: wrong for the teapot and the cylinder");
        ui.checkbox(&mut state.cost.heat_map, "Error heat map")
            .on_hover_text("Beside the view: how far each pixel is from per-pixel Phong in f64 on a very fine mesh");
    });
    ui.horizontal_wrapped(|ui| {
        let count = |ui: &mut Ui, label: &str, v: &mut u32, r: std::ops::RangeInclusive<u32>| {
            let l = ui.label(label);
            ui.add(egui::DragValue::new(v).range(r)).labelled_by(l.id);
        };
        match view.object {
            ObjectKind::Sphere => {
                count(ui, "Sphere slices", &mut view.sphere_slices, phonglab_core::view::SLICES_RANGE);
                count(ui, "Sphere stacks", &mut view.sphere_stacks, phonglab_core::view::SLICES_RANGE);
            }
            ObjectKind::Teapot => count(ui, "Teapot grid", &mut view.teapot_grid, phonglab_core::view::GRID_RANGE),
            ObjectKind::Cylinder => {
                count(ui, "Cylinder slices", &mut view.cylinder_slices, phonglab_core::view::SLICES_RANGE);
                count(ui, "Cylinder stacks", &mut view.cylinder_stacks, phonglab_core::view::STACKS_RANGE);
                ui.checkbox(&mut view.cylinder_caps, "Caps");
            }
        }
    });
    let departures: Vec<DemoDeparture> = DemoDeparture::ALL.into_iter().filter(|d| d.present_in(&state.doc)).collect();
    pipeline_ui(ui, &mut view, &mut state.ui.demo_fixes, &departures);
    if view != state.doc.view {
        let mut c = state.doc.clone();
        c.view = view;
        state.apply(c);
    }
    // The spin is not an edit: it stays finite and in range, and must not clear a message.
    if state.doc.view.auto_rotate {
        state.doc.view.spin_degrees = (state.doc.view.spin_degrees + 0.5).rem_euclid(360.0);
        ui.ctx().request_repaint();
    }
    // The corrected document, when a departure the document makes is switched off.
    let corrected = corrected_document(&state.doc, &state.ui.demo_fixes);

    let avail = ui.available_size();
    let heat = state.cost.heat_map;
    let beside = heat || corrected.is_some();
    // Leave room for the caption line above the image (and the picture beside it).
    let width = if beside { (avail.x - 8.0) / 2.0 } else { avail.x };
    let side = width.min(avail.y - 2.0 * ui.text_style_height(&egui::TextStyle::Small) - 8.0).max(64.0);
    let ppp = ui.ctx().pixels_per_point();
    let px = ((side * ppp) as usize).clamp(64, 1024);
    let camera = state.doc.view.camera;
    if let Err(e) = cache.main.render(ui.ctx(), &state.doc, state.ui.pow, px, "shaded view") {
        state.message = Some(Message::Refused(format!("The shaded view cannot render this scene: {e}")));
    }
    if let Some(c) = &corrected
        && let Err(e) = cache.corrected.render(ui.ctx(), c, state.ui.pow, px, "corrected view")
    {
        state.message = Some(Message::Refused(format!("The corrected view cannot render: {e}")));
    }
    let scene = state.doc.shaded_scene();
    if heat {
        state.cost.want_heat_map(&scene, &state.doc.view, state.doc.view.eval_options(state.ui.pow));
    }
    let Some(tex) = &cache.main.texture else { return };
    let size = egui::vec2(side, side);
    let caption = format!(
        "{} {}: {} ms per frame{}",
        state.doc.view.object.label(),
        state.doc.view.shading.label(),
        fmt_ms(cache.main.last_ms),
        if corrected.is_some() { " (the demo's own)" } else { "" }
    );
    let resp = ui
        .horizontal_top(|ui| {
            let resp = ui
                .vertical(|ui| {
                    let label = ui.small(caption);
                    ui.add(egui::Image::new((tex.id(), size)).sense(Sense::click_and_drag()))
                        .on_hover_text(
                            "Drag to orbit, scroll to zoom, click the surface to make that vertex the worked calculation's",
                        )
                        .labelled_by(label.id)
                })
                .inner;
            if let (Some(c), Some(tex)) = (&corrected, &cache.corrected.texture) {
                ui.vertical(|ui| {
                    let fixed: Vec<&str> = DemoDeparture::ALL
                        .into_iter()
                        .zip(state.ui.demo_fixes)
                        .filter(|(d, on)| *on && d.present_in(&state.doc))
                        .map(|(d, _)| d.fix_label())
                        .collect();
                    let label = ui.small(format!("Corrected: {}", fixed.join(", ")));
                    ui.add(egui::Image::new((tex.id(), size))).labelled_by(label.id);
                    let _ = c;
                });
            } else if heat {
                super::cost::heat_map_ui(ui, state, side);
            }
            resp
        })
        .inner;

    // The light(s), as markers: each light's position in object space, drawn where the
    // view draws the object.
    let clip_from_object = state.doc.view.clip_from_object();
    let object_from_eye = scene.eye_from_object().inverse();
    for (i, l) in state.doc.scene.lights.iter().enumerate() {
        let world = object_from_eye * scene.light_pos_in_eye(l);
        let p = if world.w == 0.0 { (world.truncate().normalize_or_zero() * 1.2).extend(1.0) } else { world / world.w };
        let c = clip_from_object * DVec4::new(p.x, p.y, p.z, 1.0);
        if c.w <= 0.0 {
            continue;
        }
        let (x, y) = (c.x / c.w, c.y / c.w);
        let pos = resp.rect.min + egui::vec2(((x + 1.0) * 0.5) as f32 * size.x, ((1.0 - y) * 0.5) as f32 * size.y);
        if resp.rect.expand(-4.0).contains(pos) {
            ui.painter().circle(pos, 6.0, Color32::from_rgb(255, 230, 120), egui::Stroke::new(1.5, Color32::BLACK));
            ui.painter().text(
                pos + egui::vec2(8.0, -8.0),
                egui::Align2::LEFT_BOTTOM,
                format!("light {i}"),
                egui::FontId::proportional(12.0),
                Color32::WHITE,
            );
        }
    }

    let mut cam = camera;
    if resp.dragged() && state.doc.view.framing == Framing::Orbit {
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
        let mesh = mesh_for(&mut cache.main.mesh, &state.doc.view);
        if let Some(i) = cache.main.renderer.pick(mesh, x, y) {
            let c = state.doc.with_vertex_as_shaded(Vertex::from_f32(mesh.positions[i], mesh.normals[i]));
            if state.apply(c) {
                state.message = Some(Message::Info(format!(
                    "Vertex {i} of the {}: the worked calculation now uses it, as the shaded view lights it.",
                    state.doc.view.object.label().to_lowercase()
                )));
            }
        }
    }
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

fn fmt_ms(ms: f64) -> String {
    format!("{ms:.1}")
}
