//! The shaded view: the sphere, teapot or cylinder under the document's lights and
//! material, Flat, Gouraud or Phong, rendered by the core's CPU renderer.
//!
//! Drag to orbit, scroll to zoom; auto-rotate spins the object 0.5 degrees a frame, as the
//! Phong demo does. Clicking the surface makes the nearest mesh vertex the vertex of the
//! worked calculation, with this view's camera and spin, so both panels show one vertex.

use egui::{Color32, ColorImage, Sense, TextureHandle, TextureOptions, Ui};
use glam::{DMat4, DVec4};
use phonglab_core::mesh::Mesh;
use phonglab_core::render::{Job, Renderer};
use phonglab_core::view::view_projection;
use phonglab_core::{CameraSpec, EvalOptions, LightPlacement, ObjectKind, Shading, Vertex, View};

use super::state::{AppState, Message};

/// The renderer, its mesh and its texture, kept between frames.
#[derive(Default)]
pub struct ShadedCache {
    renderer: Renderer,
    mesh: Option<(View, Mesh)>,
    texture: Option<TextureHandle>,
    /// What the texture shows; re-rendered only when it changes.
    key: Option<String>,
    /// The last frame's render time in milliseconds.
    pub last_ms: f64,
}

fn mesh_for<'a>(cache: &'a mut Option<(View, Mesh)>, view: &View) -> &'a Mesh {
    let stale = cache.as_ref().is_none_or(|(v, _)| {
        let mut a = v.clone();
        let mut b = view.clone();
        // Only what changes the geometry matters.
        a.shading = Shading::Gouraud;
        b.shading = Shading::Gouraud;
        a.auto_rotate = false;
        b.auto_rotate = false;
        a.spin_degrees = 0.0;
        b.spin_degrees = 0.0;
        a.camera = Default::default();
        b.camera = Default::default();
        a != b
    });
    if stale {
        *cache = Some((view.clone(), view.mesh()));
    }
    &cache.as_ref().expect("set just above").1
}

/// The view's controls and the image.
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

    let avail = ui.available_size();
    let heat = state.cost.heat_map;
    // Leave room for the caption line above the image (and the heat map beside it).
    let width = if heat { (avail.x - 8.0) / 2.0 } else { avail.x };
    let side = width.min(avail.y - 2.0 * ui.text_style_height(&egui::TextStyle::Small) - 8.0).max(64.0);
    let ppp = ui.ctx().pixels_per_point();
    let px = ((side * ppp) as usize).clamp(64, 1024);
    let camera = state.doc.view.camera;
    let scene = state.doc.shaded_scene();
    let job_key = format!("{:?}|{:?}|{px}|{:?}", scene, state.doc.view, state.ui.pow);
    let mesh = mesh_for(&mut cache.mesh, &state.doc.view);
    if cache.key.as_deref() != Some(job_key.as_str()) || cache.texture.is_none() {
        let job = Job {
            scene: &scene,
            mesh,
            clip_from_eye: view_projection(1.0),
            shading: state.doc.view.shading,
            background: [0.1, 0.1, 0.15],
            cull_back: false,
            options: EvalOptions::with_pow(state.ui.pow),
        };
        let t = std::time::Instant::now();
        match cache.renderer.render(&job, px, px) {
            Ok((img, _)) => {
                cache.last_ms = t.elapsed().as_secs_f64() * 1e3;
                let image = ColorImage::from_rgba_unmultiplied([img.width, img.height], &img.rgba);
                match &mut cache.texture {
                    Some(tex) => tex.set(image, TextureOptions::LINEAR),
                    None => cache.texture = Some(ui.ctx().load_texture("shaded view", image, TextureOptions::LINEAR)),
                }
                cache.key = Some(job_key);
            }
            Err(e) => state.message = Some(Message::Refused(format!("The shaded view cannot render this scene: {e}"))),
        }
    }
    if heat {
        state.cost.want_heat_map(&scene, &state.doc.view, EvalOptions::with_pow(state.ui.pow));
    }
    let Some(tex) = &cache.texture else { return };
    let size = egui::vec2(side, side);
    let caption = format!(
        "{} {}: {} ms per frame",
        state.doc.view.object.label(),
        state.doc.view.shading.label(),
        fmt_ms(cache.last_ms)
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
            if heat {
                super::cost::heat_map_ui(ui, state, side);
            }
            resp
        })
        .inner;

    // The light(s), as markers.
    let clip_from_world = view_projection(1.0) * camera.eye_from_world();
    for (i, l) in state.doc.scene.lights.iter().enumerate() {
        let world = match &l.placement {
            LightPlacement::Eye => camera.eye_from_world().inverse() * l.position,
            LightPlacement::Object => DMat4::from_rotation_y(state.doc.view.spin_degrees.to_radians()) * l.position,
            _ => l.position,
        };
        let p = if world.w == 0.0 { (world.truncate().normalize_or_zero() * 1.2).extend(1.0) } else { world / world.w };
        let c = clip_from_world * DVec4::new(p.x, p.y, p.z, 1.0);
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
    if resp.dragged() {
        let d = resp.drag_delta();
        cam.yaw = (cam.yaw + d.x as f64 * 0.5).rem_euclid(360.0);
        cam.pitch = (cam.pitch + d.y as f64 * 0.5).clamp(-89.0, 89.0);
    }
    if resp.hovered() {
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
        let mesh = mesh_for(&mut cache.mesh, &state.doc.view);
        if let Some(i) = cache.renderer.pick(mesh, x, y) {
            let mut c = state.doc.clone();
            c.scene.vertex = Vertex::from_f32(mesh.positions[i], mesh.normals[i]);
            c.camera = CameraSpec::Matrix(camera.eye_from_world());
            c.scene.world_from_object = DMat4::from_rotation_y(state.doc.view.spin_degrees.to_radians());
            if state.apply(c) {
                state.message = Some(Message::Info(format!(
                    "Vertex {i} of the {}: the worked calculation now uses it, with the shaded view's camera.",
                    state.doc.view.object.label().to_lowercase()
                )));
            }
        }
    }
}

fn fmt_ms(ms: f64) -> String {
    format!("{ms:.1}")
}
