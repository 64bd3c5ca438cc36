//! The pixel probe and the term channels in the window, driven headless: the probe follows
//! the pointer, a click pins it, its window tells the pixel's stored bytes (the picture's,
//! read from the view's own pixels) and lies on screen clear of the picture; a vertex's line
//! opens its calculation; a channel replaces the picture with its false colour and a legend
//! of the picture's width under it.

use crate::common;

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::{AppState, app_ui};
use phonglab_core::channels::Channel;

fn harness_at(w: f32, h: f32) -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([w, h])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(3);
    h
}

/// The shaded picture's rect (its caption names the object and shading).
fn picture(h: &Harness<'static, AppState>) -> egui::Rect {
    h.state().ui.geometry.pictures[0]
}

fn probe_at(w: f32, ht: f32) {
    let mut h = harness_at(w, ht);
    h.get_by_role_and_label(Role::CheckBox, "Probe").click();
    h.run_steps(3);
    assert!(h.state().view_options.probe.on);
    let window = h.get_by_label("Pixel probe").rect();
    assert!(h.query_by_label("Point at the shaded picture.").is_some());
    // Pin the pixel at the picture's centre.
    let rect = picture(&h);
    h.hover_at(rect.center());
    h.run_steps(2);
    h.event(egui::Event::PointerButton {
        pos: rect.center(),
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Default::default(),
    });
    h.event(egui::Event::PointerButton {
        pos: rect.center(),
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Default::default(),
    });
    h.run_steps(4);
    let probe = h.state().view_options.probe.clone();
    assert!(probe.pinned, "a click pins the pixel");
    let ([x, y], px) = probe.at.expect("a pixel");
    assert!(x.abs_diff(px / 2) <= 1 && y.abs_diff(px / 2) <= 1, "({x}, {y}) of {px}");
    // The stored bytes the window shows are the picture's at that pixel.
    let rgba = h.state().shaded.main.rgba();
    let i = (y * px + x) * 4;
    let want = format!("({}, {}, {}, {})", rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]);
    let stored = h.get_by_label(&want).rect();
    assert!(h.query_by_label("Stored, clamped and rounded to 8 bits").is_some());
    assert!(h.query_by_label("Perspective-correct weights").is_some());
    // The worksheet's at, and the factor OpenGL multiplies by under its own name.
    assert!(h.query_all_by_label("Attenuation").count() >= 1 && h.query_by_label_contains("1/at = ").is_some());
    // The window lies on screen, to the right of the picture.
    let window_now = h.get_by_label("Pixel probe").rect();
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(w, ht));
    assert!(screen.contains_rect(window_now.expand(-1.0)) || screen.contains(window_now.min), "{window_now:?}");
    assert!(window.left() >= rect.right() - 1.0, "the window {window:?} clear of the picture {rect:?}");
    assert!(stored.left() > rect.right() && stored.bottom() <= ht, "{stored:?}");
    // The pointer moving away leaves the pinned pixel.
    h.hover_at(rect.left_top() + egui::vec2(3.0, 3.0));
    h.run_steps(2);
    assert_eq!(h.state().view_options.probe.at, probe.at);
    // A vertex's line opens its calculation: the worked vertex moves to it.
    let before = h.state().doc.scene.vertex;
    let vertex_link =
        h.query_all_by_role(Role::Link).find(|n| n.accesskit_node().label().is_some_and(|l| l.starts_with("vertex ")));
    vertex_link.expect("a vertex line").click();
    h.run_steps(3);
    assert_ne!(h.state().doc.scene.vertex, before, "the vertex's calculation opened");
}

#[test]
fn the_probe_pins_a_pixel_and_tells_its_bytes() {
    probe_at(1280.0, 720.0);
    probe_at(1920.0, 1080.0);
}

#[test]
fn a_channel_replaces_the_picture_with_its_legend() {
    let mut h = harness_at(1280.0, 720.0);
    let before = picture(&h);
    h.state_mut().view_options.channel = Some(Channel::Diffuse);
    h.run_steps(4);
    let rect = picture(&h);
    assert!(h.query_by_label_contains("term Diffuse").is_some(), "the caption names the term");
    // The legend sits under the picture, as wide as it.
    let legend = h.get_by_label_contains("from 0 to").rect();
    assert!((legend.top() - rect.bottom()).abs() <= 6.0, "{legend:?} under {rect:?}");
    assert!((legend.width() - rect.width()).abs() <= 1.0, "{legend:?} {rect:?}");
    assert!(rect.width() <= before.width() && rect.width() > before.width() - 40.0, "{before:?} -> {rect:?}");
    let (lo, hi) = h.state().shaded.channel.range;
    assert_eq!(lo, 0.0);
    assert!(hi > 0.1 && hi < 2.0, "{hi}");
}

/// Compare shows one term for A and B side by side, over one range (both legends say the
/// same numbers), as the shaded view does.
#[test]
fn compare_shows_a_channel_for_both_over_one_range() {
    let mut h = harness_at(1280.0, 720.0);
    common::menu_item(&mut h, &["View"], "Compare");
    h.run_steps(3);
    assert!(h.state().compare.a.is_some(), "A pinned on opening");
    // B: the light moved closer, so its diffuse term is larger.
    let mut b = h.state().doc.clone();
    b.scene.lights[0].position.z = 30.0;
    assert!(h.state_mut().apply(b));
    h.state_mut().compare.channel = Some(Channel::Diffuse);
    h.run_steps(4);
    let a = h.get_by_label("A: Diffuse").rect();
    let b = h.get_by_label("B: Diffuse").rect();
    assert!((a.top() - b.top()).abs() < 1.0 && b.left() > a.right(), "{a:?} {b:?}");
    let legends: Vec<String> =
        h.query_all_by_label_contains("from 0 to").filter_map(|n| n.accesskit_node().label()).collect();
    assert_eq!(legends.len(), 2, "{legends:?}");
    assert_eq!(legends[0], legends[1], "one range for both");
    let (ra, rb) = (h.state().compare.a_channel.range, h.state().compare.b_channel.range);
    assert_eq!(ra, rb);
}

/// Every channel's legend says what it shows, in the legend itself and in body type: the
/// luminance of a colour term, a factor (1/at, spot), a cosine, the normal's axes, a count;
/// whole under the picture at the projector sizes. (It said so only on hover, and its
/// numbers were in small type; the attenuation channel said "Attenuation" for 1/at.)
#[test]
fn every_channel_legend_says_what_it_shows_in_body_type() {
    use phonglab::app::panels::shaded::channel_view::meaning;
    for (w, ht) in [(1024.0, 600.0), (1280.0, 720.0)] {
        let mut h = harness_at(w, ht);
        let body = h.ctx.global_style().text_styles[&egui::TextStyle::Body].size;
        for c in Channel::ALL {
            h.state_mut().view_options.channel = Some(c);
            h.run_steps(4);
            let rect = picture(&h);
            let what = meaning(c, c.message_id());
            let label = h.get_by_label(&what).rect();
            assert!(label.top() >= rect.bottom() && label.bottom() <= ht, "{c:?} at {w}: {label:?} under {rect:?}");
            assert!(label.left() >= rect.left() - 1.0 && label.right() <= rect.right() + 1.0, "{c:?}: {label:?}");
            // At least one line of body type (a small label is about 10 points tall).
            assert!(label.height() >= body, "{c:?}: {label:?} for a {body}-point font");
            let kind = match c {
                Channel::Attenuation => "1/at: the factor",
                Channel::Spot => "factor",
                Channel::NDotL | Channel::NDotH => "cosine",
                Channel::Normal => "as a colour",
                Channel::LightCount => "a count",
                _ => "the luminance (Rec. 709) of a colour term",
            };
            assert!(what.contains(kind), "{c:?}: {what}");
        }
    }
}

/// The Show menu names the specular cosine as the scene's rules form it, as the command
/// line's channels do: `R·V` under Phong's rule, `N·H` under Blinn-Phong's. (It said N·H
/// under both.) The menu's item stands on screen below its box.
#[test]
fn the_channel_menu_names_the_cosine_the_rules_use() {
    use phonglab_core::rules::SpecularModel;
    for (model, said, not_said) in [(SpecularModel::Phong, "R·V", "N·H"), (SpecularModel::BlinnPhong, "N·H", "R·V")]
    {
        let mut h = harness_at(1280.0, 720.0);
        let mut doc = h.state().doc.clone();
        doc.scene.rules.specular = model;
        assert!(h.state_mut().apply(doc));
        h.state_mut().view_options.options_open = true;
        h.run_steps(3);
        let combo = h.get_by_role_and_label(Role::ComboBox, "Show");
        let combo_rect = combo.rect();
        combo.click();
        h.run_steps(3);
        let item = h.get_by_label(said).rect();
        assert!(h.query_by_label(not_said).is_none(), "{model:?}: {not_said} is not this scene's term");
        assert!(item.top() >= combo_rect.bottom() - 1.0 && item.bottom() <= 720.0, "{item:?} under {combo_rect:?}");
    }
}

/// The picture's caption and its legend name the specular cosine as the Show menu does:
/// under Phong's rule "term R·V" and the legend of R·V, in English and in Portuguese.
/// (They said "term N·H" and "N·H = cos β … (R·V under the Phong rule)" under both.)
#[test]
fn the_channel_caption_and_legend_name_the_cosine_the_rules_use() {
    use phonglab_core::rules::SpecularModel;
    for lang in ["en", "pt-PT", "pt-BR"] {
        for (model, said, not_said) in [(SpecularModel::Phong, "R·V", "N·H"), (SpecularModel::BlinnPhong, "N·H", "R·V")]
        {
            let mut h = harness_at(1280.0, 720.0);
            h.state_mut().ui.layout.language = Some(lang.into());
            let mut doc = h.state().doc.clone();
            doc.scene.rules.specular = model;
            assert!(h.state_mut().apply(doc));
            h.state_mut().view_options.channel = Some(Channel::NDotH);
            h.run_steps(4);
            let rect = picture(&h);
            let term = if lang == "en" { "term" } else { "termo" };
            let caption = format!(": {term} {said}");
            // The picture is named by its caption (the caption over it, or the picture itself).
            let above = h.query_all_by_label_contains(&caption).any(|n| n.rect().top() <= rect.top() + 1.0);
            assert!(above, "{lang} {model:?}: nothing says {caption:?} at or above {rect:?}");
            let wrong = format!(": {term} {not_said}");
            assert!(h.query_by_label_contains(&wrong).is_none(), "{lang} {model:?}: the caption says {wrong:?}");
            // The legend begins with the term it explains.
            let legend = h
                .query_all_by_label_contains(said)
                .filter(|n| n.accesskit_node().label().is_some_and(|l| l.starts_with(said)))
                .map(|n| n.rect())
                .find(|r| r.top() >= rect.bottom())
                .unwrap_or_else(|| panic!("{lang} {model:?}: no legend of {said} under {rect:?}"));
            assert!(legend.top() >= rect.bottom() && legend.bottom() <= 720.0, "{lang} {model:?}: {legend:?}");
        }
    }
}
