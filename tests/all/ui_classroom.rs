//! In front of a class, driven headless: presentation mode and its drawer, zoom, the two
//! themes, walking the steps with the arrow keys, the vectors on the shaded object, the
//! dragged light, the reflection lobe and Compare.

use crate::common;

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::panels::shaded::vector_arrows;
use phonglab::app::shell::layout::{Beside, Theme};
use phonglab::app::{AppState, app_ui};

fn harness_at(w: f32, h: f32) -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([w, h])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(3);
    h
}

#[test]
fn f5_presents_with_large_type_and_the_controls_in_a_drawer() {
    let mut h = harness_at(1280.0, 720.0);
    let heading = h.get_by_label("Worked calculation").rect().height();
    assert!(h.query_by_role_and_label(Role::Slider, "Light z").is_some(), "the controls are open");
    h.key_press(egui::Key::F5);
    h.run_steps(3);
    assert!(h.state().ui.layout.presenting);
    assert!(h.query_by_role_and_label(Role::Slider, "Light z").is_none(), "the controls went into the drawer");
    let big = h.get_by_label("Worked calculation").rect().height();
    assert!(big > heading * 1.3, "large type: {heading} -> {big}");
    // The drawer opens on a click, with the controls in it.
    h.get_by_label("Controls drawer").click();
    h.run_steps(4);
    assert!(h.state().ui.layout.drawer_open);
    assert!(h.query_by_role_and_label(Role::Slider, "Light z").is_some(), "the drawer holds the controls");
    // The button leaves presentation as F5 does.
    h.get_by_label("Leave (F5)").click();
    h.run_steps(3);
    assert!(!h.state().ui.layout.presenting);
    assert!(h.query_by_role_and_label(Role::Slider, "Light z").is_some());
}

#[test]
fn ctrl_plus_minus_and_zero_zoom() {
    let mut h = harness_at(1280.0, 720.0);
    let z0 = h.ctx.zoom_factor();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Plus);
    h.run_steps(2);
    let z1 = h.ctx.zoom_factor();
    assert!(z1 > z0, "{z0} -> {z1}");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Minus);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Minus);
    h.run_steps(2);
    assert!(h.ctx.zoom_factor() < z0);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Num0);
    h.run_steps(2);
    assert_eq!(h.ctx.zoom_factor(), 1.0);
}

#[test]
fn the_light_theme_for_bright_rooms() {
    let mut h = harness_at(1280.0, 720.0);
    assert!(h.ctx.global_style().visuals.dark_mode);
    common::menu_item(&mut h, &["View"], "Light theme");
    h.run_steps(2);
    assert_eq!(h.state().ui.layout.theme, Theme::Light);
    let v = h.ctx.global_style().visuals.clone();
    assert!(!v.dark_mode);
    assert_eq!(v.panel_fill, egui::Color32::WHITE);
    assert_eq!(v.widgets.noninteractive.fg_stroke.color, egui::Color32::BLACK);
    common::menu_item(&mut h, &["View"], "Dark theme");
    h.run_steps(2);
    assert!(h.ctx.global_style().visuals.dark_mode);
}

#[test]
fn arrow_keys_walk_through_the_steps() {
    let mut h = harness_at(1440.0, 900.0);
    assert_eq!(h.state().ui.layout.step, None);
    h.key_press(egui::Key::ArrowDown);
    h.run_steps(1);
    assert_eq!(h.state().ui.layout.step, Some(0));
    h.key_press(egui::Key::ArrowDown);
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(1);
    assert_eq!(h.state().ui.layout.step, Some(2));
    h.key_press(egui::Key::ArrowUp);
    h.run_steps(2);
    assert_eq!(h.state().ui.layout.step, Some(1));
    // The highlighted step is scrolled into view: the last one, after walking to the end.
    for _ in 0..40 {
        h.key_press(egui::Key::ArrowDown);
    }
    h.run_steps(4);
    let n = h.state().evaluate().unwrap().explanation.steps.len();
    assert_eq!(h.state().ui.layout.step, Some(n - 1));
    let last = h.state().evaluate().unwrap().explanation.steps[n - 1].title.clone();
    let r = h.get_by_label(&last).rect();
    assert!(r.max.y < 900.0 && r.min.y > 0.0, "{last} scrolled into view: {r:?}");
    // Not while typing into a field.
    common::click_field(&mut h, "Vertex z");
    h.key_press(egui::Key::ArrowUp);
    h.run_steps(1);
    assert_eq!(h.state().ui.layout.step, Some(n - 1));
}

#[test]
fn the_vectors_are_drawn_on_the_object_after_a_click_and_point_the_right_way() {
    let mut h = harness_at(1440.0, 900.0);
    let image = h.get_all_by_role(Role::Image).next().unwrap().rect();
    let eval = h.state().evaluate().unwrap();
    assert!(vector_arrows(&h.state().doc, &eval, image).is_empty(), "the worksheet's vertex is not on the sphere");
    // Click right of the teapot's centre, on its body: a vertex whose normal points right.
    let at = image.center() + egui::vec2(image.width() * 0.15, 0.0);
    h.drag_at(at);
    h.drop_at(at);
    h.run_steps(2);
    let eval = h.state().evaluate().unwrap();
    let arrows = vector_arrows(&h.state().doc, &eval, image);
    let names: Vec<&str> = arrows.iter().map(|a| a.name.as_str()).collect();
    assert_eq!(names, ["L", "H", "V", "N"]);
    let n = arrows.iter().find(|a| a.name == "N").unwrap();
    assert!(n.to.x > n.from.x + 10.0, "N points out of the teapot's right side: {n:?}");
    let v = arrows.iter().find(|a| a.name == "V").unwrap();
    assert!((v.to - v.from).length() < (n.to - n.from).length(), "V points at the viewer, foreshortened");
    // What is drawn is that projection: each arrow one length in the world, projected, so
    // their lengths on the screen differ (not one screen length for all, as before).
    let drawn = h.state().ui.geometry.arrows.clone();
    assert_eq!(drawn, arrows, "the arrows drawn are the projected ones");
    let doc = h.state().doc.clone();
    let eye_from_object = doc.shaded_scene().eye_from_object();
    let clip_from_object = doc.view.clip_from_object();
    let object_from_eye = eye_from_object.inverse();
    let screen = |eye: glam::DVec3| {
        let c = clip_from_object * (object_from_eye * eye.extend(1.0));
        let (x, y) = (c.x / c.w, c.y / c.w);
        image.min + egui::vec2(((x + 1.0) * 0.5) as f32 * image.width(), ((1.0 - y) * 0.5) as f32 * image.height())
    };
    let p = eye_from_object * doc.scene.vertex.position;
    let at = p.truncate() / p.w;
    let world = 0.5 * eye_from_object.transform_vector3(glam::DVec3::X).length();
    for (a, vec) in drawn.iter().zip([eval.lights[0].l, eval.lights[0].h, eval.v, eval.n]) {
        let want = screen(at + vec.normalize() * world) - screen(at);
        assert!(((a.to - a.from) - want).length() < 0.5, "{}: drawn {:?}, projected {want:?}", a.name, a.to - a.from);
        assert_eq!(a.away, vec.z < 0.0, "{}: away from the viewer", a.name);
    }
    let lengths: Vec<f32> = drawn.iter().map(|a| (a.to - a.from).length()).collect();
    let (lo, hi) = lengths.iter().fold((f32::MAX, 0.0f32), |(l, h), x| (l.min(*x), h.max(*x)));
    assert!(hi > 1.3 * lo, "lengths follow the directions: {lengths:?}");
    assert!(!v.faded(), "V points at the viewer: drawn full");
    // The light moved behind the teapot: L (and H) point away and into the surface, drawn
    // faded, and a line under the picture says what that means.
    let mut d = h.state().doc.clone();
    d.scene.lights[0].position = glam::DVec4::new(0.0, 0.0, -90.0, 1.0);
    assert!(h.state_mut().apply(d));
    h.run_steps(2);
    let l = h.state().ui.geometry.arrows.iter().find(|a| a.name == "L").unwrap().clone();
    assert!(l.away && l.behind && l.faded(), "{l:?}");
    h.get_by_label_contains("Faded, open head");
}

/// A turn of the camera keeps the arrows on the object, on the same vertex, recomputed
/// every frame from the calculation under the turned camera: turning until N points at the
/// viewer shortens N on the screen to nearly nothing.
#[test]
fn the_arrows_stay_on_the_vertex_while_the_camera_turns() {
    let mut h = harness_at(1440.0, 900.0);
    let image = h.get_all_by_role(Role::Image).next().unwrap().rect();
    // The vertex on the teapot's right side: N points right, across the screen.
    let at = image.center() + egui::vec2(image.width() * 0.15, 0.0);
    h.drag_at(at);
    h.drop_at(at);
    h.run_steps(2);
    let vertex = h.state().doc.scene.vertex;
    let n_of = |h: &Harness<'static, AppState>| {
        let a = h.state().ui.geometry.arrows.iter().find(|a| a.name == "N").cloned();
        a.map(|a| (a.to - a.from).length())
    };
    let across = n_of(&h).expect("arrows after the click");
    let yaw = h.state().doc.view.camera.yaw;
    // Drag on the picture (away from the light's marker): the camera turns towards the
    // vertex's side, in steps of a frame each, the button held.
    let from = image.center() + egui::vec2(-image.width() * 0.3, -image.height() * 0.3);
    common::press_and_move(&mut h, from, from + egui::vec2(-66.0, 0.0));
    h.run_steps(1);
    let doc = h.state().doc.clone();
    assert_ne!(doc.view.camera.yaw, yaw, "the camera turned");
    assert_eq!(doc.scene.vertex, vertex, "the same vertex");
    let eval = h.state().evaluate().unwrap();
    let arrows = vector_arrows(&doc, &eval, image);
    let names: Vec<&str> = arrows.iter().map(|a| a.name.as_str()).collect();
    assert_eq!(names, ["L", "H", "V", "N"], "the arrows stay through the turn");
    assert_eq!(h.state().ui.geometry.arrows, arrows, "drawn from the calculation under the turned camera");
    let facing = n_of(&h).unwrap();
    assert!(eval.n.z > 0.9, "N points at the viewer now: {:?}", eval.n);
    assert!(facing < 0.5 * across, "N foreshortened: {across} -> {facing}");
    common::button(&mut h, from + egui::vec2(-66.0, 0.0), false);
    h.run_steps(2);
    assert!(!h.state().ui.geometry.arrows.is_empty(), "and after the button is let go");
    // The object spinning (Auto-rotate) carries the vertex and its arrows with it.
    h.state_mut().doc.view.auto_rotate = true;
    h.run_steps(6);
    let doc = h.state().doc.clone();
    assert_eq!(doc.scene.vertex, vertex);
    assert!(doc.view.spin_degrees > 0.0);
    let eval = h.state().evaluate().unwrap();
    assert_eq!(vector_arrows(&doc, &eval, image).len(), 4, "the arrows spin with the object");
}

#[test]
fn dragging_the_light_marker_moves_the_light() {
    let mut h = harness_at(1440.0, 900.0);
    // A scene whose light sits in front of the object, inside the view.
    let mut doc = h.state().doc.clone();
    doc.scene.lights[0].position = glam::DVec4::new(0.3, 0.3, 1.0, 1.0);
    doc.scene.lights[0].placement = phonglab_core::LightPlacement::World;
    assert!(h.state_mut().apply(doc));
    h.run_steps(2);
    let before = h.state().doc.scene.lights[0].position;
    let marker = h.get_by_label("light 0 marker").rect().center();
    h.drag_at(marker);
    h.run_steps(1);
    h.hover_at(marker + egui::vec2(30.0, 0.0));
    h.run_steps(1);
    h.drop_at(marker + egui::vec2(30.0, 0.0));
    h.run_steps(2);
    let after = h.state().doc.scene.lights[0].position;
    assert_ne!(before, after, "the light moved");
    assert!(after.x > before.x, "to the right: {before:?} -> {after:?}");
    let moved = h.get_by_label("light 0 marker").rect().center();
    assert!((moved.x - marker.x - 30.0).abs() < 3.0 && (moved.y - marker.y).abs() < 3.0, "{marker:?} -> {moved:?}");
    assert_eq!(h.state().doc.view.camera, phonglab_core::Document::default().view.camera, "the view did not orbit");
}

/// At the start, light 0 sits behind the camera: its marker stands at the picture's edge,
/// and dragging it moves the light in the plane facing the viewer (the way the pointer
/// goes), not the camera. A light in front but off the picture comes to the pointer.
#[test]
fn a_light_marker_at_the_edge_drags_the_light() {
    for (w, hgt) in [(1280.0, 720.0), (1024.0, 600.0)] {
        let mut h = harness_at(w, hgt);
        let in_eye = |h: &Harness<'static, AppState>| {
            let d = &h.state().doc;
            let s = d.shaded_scene();
            let p = s.light_pos_in_eye(&s.lights[0]);
            p.truncate() / p.w
        };
        let before = in_eye(&h);
        assert!(before.z > 0.0, "behind the camera: {before:?}");
        let camera = h.state().doc.view.camera;
        let marker = h.get_by_label("light 0 marker").rect().center();
        common::press_and_move(&mut h, marker, marker + egui::vec2(60.0, -30.0));
        common::button(&mut h, marker + egui::vec2(60.0, -30.0), false);
        h.run_steps(2);
        assert_eq!(h.state().doc.view.camera, camera, "{w}x{hgt}: the camera did not turn");
        let after = in_eye(&h);
        assert!(
            after.x > before.x + 1.0 && after.y > before.y + 0.5,
            "{w}x{hgt}: right and up: {before:?} -> {after:?}"
        );
        assert!(
            (after.z - before.z).abs() < 1e-6,
            "{w}x{hgt}: in the plane facing the viewer: {before:?} -> {after:?}"
        );
        // One step to undo.
        assert_eq!(h.state().history.depth(), 1);
        // A quick hand: pressed and moved within one frame, already off the marker when
        // the drag starts. The light moves still, not the camera.
        let marker = h.get_by_label("light 0 marker").rect().center();
        let before = in_eye(&h);
        h.input_mut().events.push(egui::Event::PointerMoved(marker));
        h.run_steps(2);
        common::button(&mut h, marker, true);
        h.input_mut().events.push(egui::Event::PointerMoved(marker + egui::vec2(-20.0, -40.0)));
        h.step();
        for k in 1..=4 {
            h.input_mut().events.push(egui::Event::PointerMoved(marker + egui::vec2(-20.0 - 10.0 * k as f32, -40.0)));
            h.step();
        }
        common::button(&mut h, marker + egui::vec2(-60.0, -40.0), false);
        h.run_steps(2);
        assert_eq!(h.state().doc.view.camera, camera, "{w}x{hgt}: a quick drag does not turn the camera");
        let after = in_eye(&h);
        assert!(after.x < before.x - 1.0, "{w}x{hgt}: left: {before:?} -> {after:?}");
    }
    // A light in front of the camera, off the picture to the right: dragged from its marker
    // onto the picture, it comes to the pointer.
    let mut h = harness_at(1280.0, 720.0);
    let mut doc = h.state().doc.clone();
    doc.scene.lights[0].position = glam::DVec4::new(6.0, 0.0, 0.0, 1.0);
    doc.scene.lights[0].placement = phonglab_core::LightPlacement::World;
    assert!(h.state_mut().apply(doc));
    h.run_steps(2);
    let image = h.get_all_by_role(Role::Image).next().unwrap().rect();
    let marker = h.get_by_label("light 0 marker").rect();
    assert!(marker.max.x > image.max.x - 40.0, "at the right edge: {marker:?} in {image:?}");
    let to = image.center() + egui::vec2(image.width() * 0.25, -image.height() * 0.2);
    common::press_and_move(&mut h, marker.center(), to);
    common::button(&mut h, to, false);
    h.run_steps(2);
    let on = h.get_by_label("light 0 marker").rect().center();
    assert!((on - to).length() < 3.0, "the marker is under the pointer: {on:?}, {to:?}");
}

#[test]
fn the_lobe_follows_the_shininess() {
    let mut h = harness_at(1440.0, 900.0);
    h.get_by_label("Reflection lobe").click();
    h.run_steps(2);
    assert_eq!(h.state().ui.layout.beside, Beside::Lobe);
    let n = h.state().doc.scene.material.shininess;
    h.get_by_label_contains(&format!("n = {n},"));
    h.get_by_role_and_label(Role::Slider, "Material shininess").set_value_accesskit(12.0);
    h.run_steps(2);
    h.get_by_label_contains("n = 12,");
}

/// Energy-conserving Blinn-Phong, reached with the key B: the lobe draws its curve (heavy,
/// the scene's own) beside Blinn-Phong's (thin now), its legend entry after Blinn-Phong's
/// and whole in the lobe's column (left of the worked calculation), the rays' entries on a
/// row under the curves, at 1024x600 and 1280x720; B once more goes back round to
/// Blinn-Phong.
#[test]
fn the_lobe_draws_normalised_blinn_phong_when_it_is_the_scenes() {
    use phonglab_core::SpecularModel;
    for (width, height) in [(1024.0, 600.0), (1280.0, 720.0)] {
        let mut h = harness_at(width, height);
        h.get_by_label("Reflection lobe").click();
        h.run_steps(2);
        assert!(h.query_by_label_contains("Blinn-Phong × (n+8)/8π").is_none(), "only where it is the scene's");
        for _ in 0..2 {
            h.key_press(egui::Key::B);
            h.run_steps(2);
        }
        assert_eq!(h.state().doc.scene.rules.specular, SpecularModel::BlinnPhongNormalised);
        let normalised = h.get_by_label_contains("Blinn-Phong × (n+8)/8π").rect();
        let blinn = h.get_by_label_contains("\u{2500}\u{2500}Blinn-Phong ks (N·H)^n").rect();
        assert!(normalised.width() > 100.0 && normalised.height() > 8.0, "{width}: {normalised:?}");
        let calculation = h.get_by_label("Worked calculation").rect();
        assert!(
            normalised.right() <= calculation.left() && normalised.bottom() <= height,
            "{width}: {normalised:?} {calculation:?}"
        );
        // After Blinn-Phong's in the legend: to its right on its row, or on a row below.
        assert!(
            normalised.left() > blinn.right() || normalised.top() >= blinn.bottom(),
            "{width}: {blinn:?} {normalised:?}"
        );
        // The rays' entries whole in the column too, on a row under the curves.
        for ray in ["\u{2500}\u{2500}N", "\u{254C}\u{254C}L", "\u{2500}\u{2500}V"] {
            let r = h.get_by_label(ray).rect();
            assert!(
                r.right() <= calculation.left() && r.top() >= normalised.bottom(),
                "{width} {ray}: {r:?} {normalised:?}"
            );
        }
        h.key_press(egui::Key::B);
        h.run_steps(2);
        assert_eq!(h.state().doc.scene.rules.specular, SpecularModel::BlinnPhong);
        assert!(h.query_by_label_contains("Blinn-Phong × (n+8)/8π").is_none());
    }
}

#[test]
fn compare_pins_a_and_highlights_the_steps_that_differ() {
    let mut h = harness_at(1440.0, 900.0);
    common::menu_item(&mut h, &["View"], "Compare");
    h.run_steps(2);
    h.get_by_label("Pin the current scene as A again").click();
    h.run_steps(2);
    // Nothing differs yet, and it says so (it said "0 of 17 steps differ: they come first").
    h.get_by_label_contains("Nothing differs: A and B give the same value at each of the");
    assert!(h.query_by_label_contains("0 of").is_none());
    // B: f32 and Phong shading.
    h.key_press(egui::Key::P);
    h.key_press(egui::Key::Num2);
    h.run_steps(3);
    h.get_by_label_contains("A: the worksheet, mview5, Teapot Gouraud, f64");
    h.get_by_label_contains("B: the worksheet, mview5, Teapot Phong, f32");
    h.get_by_label_contains("A's shaded view");
    h.get_by_label_contains("B's shaded view");
    let differ = h.get_by_label_contains("steps differ").value().unwrap_or_default();
    let k: usize = differ.split_whitespace().next().unwrap().parse().unwrap();
    assert!(k > 0, "f32 against f64 changes some steps: {differ}");
    // Back to f64: Gouraud against Phong shades differently, but the vertex's steps agree.
    h.key_press(egui::Key::P);
    h.run_steps(2);
    h.get_by_label_contains("Nothing differs");
    // Another material: the terms it enters differ, the geometry does not.
    h.key_press(egui::Key::M);
    h.run_steps(2);
    let differ = h.get_by_label_contains("steps differ").value().unwrap_or_default();
    let (k, all): (usize, usize) = {
        let w: Vec<&str> = differ.split_whitespace().collect();
        (w[0].parse().unwrap(), w[2].parse().unwrap())
    };
    assert!(k > 0 && k < all, "a material changes the terms only: {differ}");
    h.get_by_label("Close compare").click();
    h.run_steps(2);
    assert!(!h.state().compare.open);
}

/// Compare's difference view on the start scene, Gouraud (A) against Phong (B): a third
/// picture as large as the two, and a legend that says how much differs, 5 % of the teapot
/// or more by more than 24/255.
#[test]
fn compare_shows_how_much_gouraud_and_phong_differ() {
    let mut h = harness_at(1440.0, 900.0);
    common::menu_item(&mut h, &["View"], "Compare");
    h.run_steps(2);
    h.get_by_label("Pin the current scene as A again").click();
    h.run_steps(2);
    // B: Phong (key 2).
    h.key_press(egui::Key::Num2);
    h.run_steps(2);
    h.get_by_label("Difference |A − B|").click();
    h.run_steps(3);
    let legend = h
        .get_by_label_contains("of the object's pixels differ by more than 24/255")
        .accesskit_node()
        .label()
        .unwrap_or_default();
    let percent: f64 = legend
        .split("\u{a0}% ")
        .next()
        .and_then(|head| head.rsplit(' ').next())
        .and_then(|p| p.parse().ok())
        .unwrap_or_else(|| panic!("no percentage in {legend:?}"));
    assert!(percent >= 5.0, "{legend}");
    // The picture is each channel's difference, in colour: the legend says so (it said
    // "white is 32/255 or more").
    assert!(
        legend.starts_with("Each channel's difference, times 8: a channel is at full strength from 32/255"),
        "{legend}"
    );
    let pics: Vec<egui::Rect> = h.state().ui.geometry.pictures.clone();
    assert_eq!(pics.len(), 3, "A, B and the difference: {pics:?}");
    for r in &pics {
        assert!((r.width() - pics[0].width()).abs() < 1.0 && (r.width() - r.height()).abs() < 1.0, "{pics:?}");
    }
    assert!(pics[0].width() >= 240.0, "{pics:?}");
    assert!(pics[0].right() <= pics[1].left() && pics[1].right() <= pics[2].left(), "side by side: {pics:?}");
}

/// Writes the README's screenshots (presentation mode and Compare, at 1280×720) when
/// `PHONGLAB_SCREENSHOTS` names a folder: `PHONGLAB_SCREENSHOTS=docs cargo test --test
/// ui_classroom screenshots -- --ignored`. Rendered by wgpu on the software adapter.
#[test]
#[ignore = "writes the guide's screenshots into PHONGLAB_SCREENSHOTS; run by hand"]
fn screenshots() {
    let Ok(dir) = std::env::var("PHONGLAB_SCREENSHOTS") else { return };
    let dir = std::path::PathBuf::from(dir);
    let mut h = harness_at(1440.0, 900.0);
    h.run_steps(2);
    h.render().unwrap().save(dir.join("screenshot.png")).unwrap();

    let mut h = harness_at(1280.0, 720.0);
    h.key_press(egui::Key::F5);
    h.run_steps(3);
    // A vertex on the sphere, so the vectors stand on the object, and a step highlighted.
    let image = h.get_all_by_role(Role::Image).next().unwrap().rect();
    let at = image.center() + egui::vec2(-image.width() * 0.12, -image.height() * 0.15);
    h.drag_at(at);
    h.drop_at(at);
    h.run_steps(2);
    for _ in 0..9 {
        h.key_press(egui::Key::ArrowDown);
    }
    h.run_steps(4);
    h.render().unwrap().save(dir.join("presentation.png")).unwrap();

    let mut h = harness_at(1280.0, 720.0);
    common::menu_item(&mut h, &["View"], "Compare");
    h.run_steps(2);
    h.get_by_label("Pin the current scene as A again").click();
    h.run_steps(2);
    h.key_press(egui::Key::Num2);
    h.key_press(egui::Key::M);
    h.run_steps(4);
    h.render().unwrap().save(dir.join("compare.png")).unwrap();
}

#[test]
fn a_new_exercise_is_generated_shown_and_quizzed() {
    let mut h = harness_at(1440.0, 900.0);
    common::menu_item(&mut h, &["View"], "Quiz");
    h.run_steps(2);
    let before = h.state().doc.clone();
    h.get_by_label("New exercise").click();
    h.run_steps(3);
    let doc = h.state().doc.clone();
    assert_ne!(doc, before, "the app shows the exercise");
    assert_eq!(h.state().quiz.doc.as_ref(), Some(&doc), "and quizzes it");
    assert!(doc.name.starts_with("exercise 1 (seed"), "{}", doc.name);
    // Level 2 by default: a positional, attenuated light, as the plan's key reads it.
    let key = phonglab_core::plan::Key::of(&doc.scene, phonglab_core::EvalOptions::default());
    assert!(key.lights[0].positional && key.lights[0].attenuated);
    h.get_by_label_contains("Score: 0 of");
}

#[test]
fn the_shader_window_shows_the_program_and_what_an_effect_adds() {
    let mut h = harness_at(1440.0, 900.0);
    common::menu_item(&mut h, &["View"], "Shader");
    h.run_steps(2);
    h.get_by_label_contains("vec3 L0 = toL0 / d0;");
    assert!(h.query_by_label_contains("in_cone0").is_none(), "no spotlight, no cone test");
    // Switch the spotlight on with its checkbox (the window leaves the controls free): the
    // cone test appears, highlighted as added.
    h.get_by_role_and_label(Role::CheckBox, "Spotlight").click();
    h.run_steps(3);
    assert!(h.state().doc.scene.lights[0].is_spot());
    h.get_by_label_contains("bool in_cone0 = spot_cos0 >= u_light0_spot_cos_cutoff;");
    let added = &h.state().shader.added;
    assert!(added.iter().any(|l| l.contains("in_cone0")), "{added:?}");
    h.get_by_label_contains("The last change added");
    // WGSL, and Copy.
    h.get_by_label("WGSL").click();
    h.run_steps(2);
    h.get_by_label_contains("@vertex");
    h.get_by_label("Copy").click();
    h.run_steps(1);
    let copied = common::copied_text(&h);
    assert!(copied.iter().any(|t| t.contains("fn vs_main") && t.contains("in_cone0")), "{copied:?}");
}

/// Every slider's and combo box's label stands before it on its row or above it, in the
/// normal window, in the presentation drawer, and at 1024x600 (labels below their sliders
/// had the attenuation misread).
#[test]
fn every_label_stands_before_or_above_its_control() {
    for (w, hgt, presenting) in [(1280.0, 720.0, false), (1280.0, 720.0, true), (1024.0, 600.0, false)] {
        let mut state = AppState::worksheet();
        state.ui.layout.presenting = presenting;
        state.ui.layout.drawer_open = true;
        let mut h = Harness::builder().with_size([w, hgt]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
        h.run_steps(3);
        let nodes: Vec<_> = h.root().children_recursive().collect();
        let labels: Vec<(String, egui::Rect)> = nodes
            .iter()
            .filter(|n| n.accesskit_node().role() == Role::Label)
            .filter_map(|n| Some((n.accesskit_node().value()?.clone(), n.rect())))
            .collect();
        let mut checked = 0;
        for n in nodes.iter().filter(|n| matches!(n.accesskit_node().role(), Role::Slider | Role::ComboBox)) {
            let Some(name) = n.accesskit_node().label() else { continue };
            let r = n.rect();
            let mine: Vec<egui::Rect> = labels.iter().filter(|(t, _)| *t == name).map(|(_, l)| *l).collect();
            if mine.is_empty() {
                continue;
            }
            let before = |l: &egui::Rect| l.max.x <= r.min.x + 1.0 && l.min.y < r.max.y && l.max.y > r.min.y;
            let above = |l: &egui::Rect| l.max.y <= r.min.y + 1.0 && l.min.x <= r.max.x && r.min.y - l.max.y < 30.0;
            assert!(
                mine.iter().any(|l| before(l) || above(l)),
                "{w}x{hgt} presenting {presenting}: {name:?} at {r:?}, its label at {mine:?}"
            );
            checked += 1;
        }
        assert!(checked >= 8, "{w}x{hgt}: {checked} controls checked");
    }
}

/// Presenting, the windows and the menus are in large type too (the Shader window and the
/// Presets menu kept egui's sizes): the Things to try window's entries, the Shader window's
/// Copy button and the Scene menu's entries are 1.3 times as tall or more.
#[test]
fn presenting_the_windows_and_menus_grow_with_the_text() {
    let heights = |presenting: bool| {
        let mut state = AppState::worksheet();
        state.ui.layout.presenting = presenting;
        let mut h =
            Harness::builder().with_size([1920.0, 1080.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
        h.run_steps(3);
        common::open_menu(&mut h, &["Scene"]);
        let menu = h.get_by_label("Phong demo").rect().height();
        h.key_press(egui::Key::Escape);
        h.state_mut().things.open = true;
        h.state_mut().shader.open = true;
        h.run_steps(3);
        let entry = h.get_by_label_contains("1. The light just behind").rect().height();
        let shader = h.get_by_label("Copy").rect().height();
        [entry, shader, menu]
    };
    let (small, large) = (heights(false), heights(true));
    for (k, what) in ["Things to try's entry", "the Shader window's Copy", "the Scene menu's entry"].iter().enumerate()
    {
        assert!(large[k] >= 1.3 * small[k], "{what}: {} -> {}", small[k], large[k]);
    }
}

/// The spotlight preset shows its cone: the rim where the cone meets the teapot lies on the
/// picture (though the light itself is above the view), inside the teapot's part of it;
/// with the cutoff at 180 (no spotlight) there is none.
#[test]
fn the_spotlight_preset_shows_its_cone_on_the_picture() {
    let mut h = harness_at(1280.0, 720.0);
    common::open_menu(&mut h, &["Scene"]);
    // (The controls have a "Spotlight" switch too: the menu's is a button.)
    h.get_by_role_and_label(Role::Button, "Spotlight").click();
    h.run_steps(3);
    assert_eq!(h.state().doc.scene.lights[0].spot_cutoff, 12.0);
    let g = h.state().ui.geometry.clone();
    let picture = g.pictures[0];
    assert_eq!(g.cones.len(), 1, "{g:?}");
    let rim = g.cones[0];
    assert!(picture.contains_rect(rim), "{rim:?} in {picture:?}");
    // Smaller than the picture, larger than a dot: a cone the class can see.
    assert!(rim.width() > 0.2 * picture.width() && rim.width() < 0.95 * picture.width(), "{rim:?}");
    let mut doc = h.state().doc.clone();
    doc.scene.lights[0].spot_cutoff = 180.0;
    assert!(h.state_mut().apply(doc));
    h.run_steps(2);
    assert!(h.state().ui.geometry.cones.is_empty());
}

/// The vertex colour reads from the back of the room: its value in large type on the
/// title's row, and a dark vertex says so (how bright, the light's angle) on its swatch;
/// a bright one does not.
#[test]
fn the_vertex_colour_is_large_and_a_dark_one_says_so() {
    let mut h = harness_at(1280.0, 720.0);
    // (The calculation has a step named "Vertex colour" too, further down: the centre's is
    // the top one.)
    let title =
        h.get_all_by_label("Vertex colour").map(|n| n.rect()).min_by(|a, b| a.min.y.total_cmp(&b.min.y)).unwrap();
    let value = h.get_by_label("0.06  0.04  0.02").rect();
    assert!(value.min.x > title.max.x && (value.center().y - title.center().y).abs() < 6.0, "{title:?} {value:?}");
    assert!(value.height() > 1.3 * title.height(), "large: {value:?} against {title:?}");
    let swatch = h.get_by_role(Role::ColorWell).rect();
    h.get_by_label("Vertex colour swatch: a dark vertex: 4\u{a0}% as bright as white; the light meets it at 82°");
    assert!(swatch.max.x <= title.min.x, "the swatch before the title");
    // Light the vertex head on: bright, and nothing said.
    let mut doc = h.state().doc.clone();
    doc.scene.material = phonglab_core::materials::classic()[0].material.clone();
    doc.scene.lights[0].position = glam::DVec4::new(0.0, 0.0, 1.0, 0.0);
    doc.scene.lights[0].placement = phonglab_core::LightPlacement::Eye;
    assert!(h.state_mut().apply(doc));
    h.run_steps(2);
    assert_eq!(h.get_by_role(Role::ColorWell).accesskit_node().label().as_deref(), Some("Vertex colour swatch"));
}
