//! What the window lays over itself at start (1280x720) leaves its own controls readable:
//! the hints of the picture and the vector plot ("Drag to orbit...") shown where the pointer
//! rests on them do not cover the Things-to-try band under them (they did, drawn under the
//! picture), and the
//! specular model's drop-down keeps its margin around its longest item, the normalised model.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::widgets::fields::{landmarks, record_landmarks};
use phonglab::app::{AppState, app_ui};

fn harness() -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([1280.0, 720.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h
}

/// Every labelled button and label the window shows, with its rect.
fn band(h: &Harness<'static, AppState>) -> Vec<(String, egui::Rect)> {
    use egui::accesskit::Role;
    let mut out = vec![];
    for n in h.root().children_recursive() {
        let ak = n.accesskit_node();
        if !matches!(ak.role(), Role::Button | Role::Label) || ak.bounding_box().is_none() {
            continue;
        }
        let text = if ak.role() == Role::Label { ak.value() } else { ak.label() };
        if let Some(label) = text.filter(|l| !l.trim().is_empty()) {
            out.push((label, n.rect()));
        }
    }
    out
}

#[test]
fn the_pictures_hint_leaves_the_things_to_try_band_uncovered() {
    let mut h = harness();
    record_landmarks(&h.ctx);
    h.run_steps(2);
    let picture = landmarks(&h.ctx)["shaded-picture"];
    let heading = h.get_by_label_contains("Things to try: one click").rect();
    assert!(heading.top() > picture.bottom(), "the band is under the picture: {heading:?} {picture:?}");
    let buttons: Vec<(String, egui::Rect)> = band(&h)
        .into_iter()
        .filter(|(_, r)| {
            r.top() >= heading.top() && r.left() >= heading.left() - 1.0 && r.left() < heading.left() + 600.0
        })
        .collect();
    assert!(buttons.len() >= 5, "{buttons:?}");
    // The pointer rests on the picture, at its centre and low in it (the middle of a
    // 1280x720 screen is on the picture at start).
    let low = |f: f32| egui::pos2(picture.center().x - 0.3 * picture.width(), picture.top() + f * picture.height());
    let plot = h.get_by_label("vector plot").rect();
    let plot_low = |f: f32| egui::pos2(plot.center().x, plot.top() + f * plot.height());
    for (at, said) in [
        (picture.center(), "Drag to orbit, scroll to zoom"),
        (low(0.75), "Drag to orbit, scroll to zoom"),
        (low(0.97), "Drag to orbit, scroll to zoom"),
        (plot.center(), "Drag to orbit (yaw"),
        (plot_low(0.97), "Drag to orbit (yaw"),
    ] {
        h.hover_at(at);
        h.run_steps(60);
        let hint = h.get_by_label_contains(said).rect();
        assert!(hint.is_positive(), "{hint:?}");
        assert!(hint.bottom() <= at.y, "the hint {hint:?} is above the pointer {at:?}, over the picture");
        for (name, r) in &buttons {
            assert!(!hint.intersects(*r), "the hint {hint:?} covers {name:?} at {r:?} (pointer at {at:?})");
        }
    }
}

/// The popup (a foreground area) that holds `inner`.
fn popup_around(h: &Harness<'static, AppState>, inner: egui::Rect) -> egui::Rect {
    h.ctx.memory(|m| {
        let layers: Vec<egui::LayerId> = m.areas().visible_layer_ids().into_iter().collect();
        layers
            .into_iter()
            .filter(|l| l.order == egui::Order::Foreground)
            .filter_map(|l| m.area_rect(l.id))
            .find(|r| r.contains(inner.center()))
            .unwrap_or_else(|| panic!("no popup around {inner:?}"))
    })
}

#[test]
fn the_specular_models_drop_down_keeps_its_margin_around_every_item() {
    let mut h = harness();
    h.get_by_label("Specular model").click();
    h.run_steps(4);
    let items = ["Blinn-Phong (n.H)", "Phong (R.V)", "Normalised Blinn-Phong (n.H)·(ns+8)/8π"];
    let rects: Vec<egui::Rect> = items
        .iter()
        .map(|i| h.query_all_by_label(i).map(|n| n.rect()).max_by(|a, b| a.top().total_cmp(&b.top())).unwrap())
        .collect();
    let popup = popup_around(&h, rects[2]);
    for (item, r) in items.iter().zip(&rects) {
        assert!(popup.contains_rect(*r), "{item} {r:?} outside the popup {popup:?}");
        let (left, right) = (r.left() - popup.left(), popup.right() - r.right());
        assert!(
            right >= 4.0 && left >= 4.0,
            "{item}: {left} points from the popup's left border, {right} from its right"
        );
    }
}
