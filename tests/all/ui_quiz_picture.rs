//! The quiz's picture question in the window: both pictures side by side within the panel,
//! the seven causes as labelled choices, Check says right or wrong and shows the key.

use crate::common;

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::{AppState, app_ui};

#[test]
fn a_picture_question_is_asked_and_checked() {
    let mut h = Harness::builder()
        .with_size([1280.0, 720.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    common::menu_item(&mut h, &["View"], "Quiz");
    h.run_steps(3);
    h.get_by_label("What is wrong with this picture?").click();
    h.run_steps(3);
    let kind = h.state().quiz.wrong.as_ref().expect("a question").kind;
    let right = h.get_by_label("Drawn right").rect();
    let wrong = h.get_by_label("Drawn with one mistake").rect();
    assert!((right.top() - wrong.top()).abs() < 1.0 && wrong.left() > right.right(), "{right:?} {wrong:?}");
    assert!(wrong.right() <= 1280.0);
    // A wrong cause first.
    let other = phonglab_core::misconception::Misconception::ALL.iter().find(|m| **m != kind).unwrap();
    h.get_by_role_and_label(Role::RadioButton, &other.choice()).click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    assert!(h.query_by_label("Not that one. The key:").is_some());
    // The verdict scrolled into view; the student scrolls back up to the causes.
    let right = kind.choice();
    h.get_by_role_and_label(Role::RadioButton, &right).scroll_to_me();
    h.run_steps(30);
    h.get_by_role_and_label(Role::RadioButton, &right).click();
    h.run_steps(2);
    h.get_by_label("Check").scroll_to_me();
    h.run_steps(30);
    h.get_by_label("Check").click();
    h.run_steps(2);
    assert!(h.query_by_label("Right.").is_some());
    assert!(h.query_by_label_contains("Cause: ").is_some());
    h.get_by_label("Back to the calculation").click();
    h.run_steps(2);
    assert!(h.state().quiz.wrong.is_none());
}

/// After Check the verdict is brought into view (it appeared below the fold), with the key's
/// first line under it, at the projector sizes.
#[test]
fn the_verdict_comes_into_view_after_check() {
    for (w, ht) in [(1024.0, 600.0), (1280.0, 720.0)] {
        let mut h = Harness::builder()
            .with_size([w, ht])
            .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
        h.run_steps(2);
        common::menu_item(&mut h, &["View"], "Quiz");
        h.run_steps(3);
        h.get_by_label("What is wrong with this picture?").click();
        h.run_steps(3);
        let kind = h.state().quiz.wrong.as_ref().expect("a question").kind;
        let other = phonglab_core::misconception::Misconception::ALL.iter().find(|m| **m != kind).unwrap();
        let choice = other.choice();
        h.get_by_role_and_label(Role::RadioButton, &choice).scroll_to_me();
        h.run_steps(30);
        h.get_by_role_and_label(Role::RadioButton, &choice).click();
        h.run_steps(2);
        h.get_by_label("Check").scroll_to_me();
        h.run_steps(30);
        h.get_by_label("Check").click();
        // Scrolling is animated.
        h.run_steps(30);
        let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(w, ht));
        let verdict = h.get_by_label("Not that one. The key:").rect();
        let cause = h.get_by_label_contains("Cause: ").rect();
        assert!(screen.contains_rect(verdict) && screen.contains_rect(cause), "{w}x{ht}: {verdict:?} {cause:?}");
    }
}
