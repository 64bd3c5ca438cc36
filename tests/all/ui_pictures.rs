//! What the back row sees: the pictures and the plot, at the four projector sizes (2560x1440
//! at scale 2), presenting and not, in five situations: a fresh start, after a pick on the
//! surface, the Phong demo with every correction on, Compare, and the lobe. The UI records
//! where it drew each picture and the plot (`state.ui.geometry`); these tests hold it to
//! the sizes a class needs, and the plot's labels to never overlapping.

use crate::common;

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::shell::screenshot::state_for;
use phonglab::app::{AppState, app_ui};
use phonglab::io::screenshot::Opened as Open;

const SIZES: [(f32, f32, f32); 4] =
    [(1024.0, 768.0, 1.0), (1280.0, 720.0, 1.0), (1920.0, 1080.0, 1.0), (2560.0, 1440.0, 2.0)];

/// The situations: what is open, and whether the surface is clicked first.
const SITUATIONS: [(&str, Option<Open>, bool); 5] = [
    ("fresh start", None, false),
    ("after a pick", None, true),
    ("the demo with its corrections", Some(Open::DemoFixes), false),
    ("compare", Some(Open::Compare), false),
    ("the lobe", Some(Open::Lobe), false),
];

fn harness(w: f32, h: f32, scale: f32, state: AppState) -> Harness<'static, AppState> {
    let mut h = Harness::builder()
        .with_size([w, h])
        .with_pixels_per_point(scale)
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(3);
    h
}

/// Clicks the middle of the shaded picture (a pick on the surface).
fn pick(h: &mut Harness<'static, AppState>) {
    let Some(r) = h.state().ui.geometry.pictures.first().copied() else { return };
    let at = r.center();
    h.input_mut().events.push(egui::Event::PointerMoved(at));
    for pressed in [true, false] {
        common::button(h, at, pressed);
        h.step();
    }
    h.run_steps(3);
}

/// The least sizes, as shares of the window's height: a single picture's side, each of two
/// pictures', and the plot's unit circle.
///
/// Presenting, the full figures (55 %, 40 %, 40 %) wherever they fit beside the worked
/// calculation: one picture from 1280 points wide, two from 1920. Where they cannot fit,
/// less is asked, and the arithmetic says why: at 1280x720 presenting, two pictures of 288
/// and a plot square of 360 need 952 points of a centre of about 880; at 1024x768 one
/// picture of 422 and a plot square of 384 need 814 of about 720. The normal window keeps
/// both side panels open (the controls and the calculation, 560 to 860 points), which
/// leaves the centre 460 to 1060 points: there the pictures and the plot share what is
/// left, and these floors keep them from shrinking back to a strip.
fn least(w: f32, presenting: bool, pictures: usize) -> (f32, f32, f32) {
    match (presenting, pictures > 1) {
        (true, false) if w >= 1280.0 => (0.55, 0.40, 0.40),
        (true, true) if w >= 1920.0 => (0.55, 0.40, 0.40),
        (true, _) => (0.36, 0.20, 0.22),
        (false, false) if w >= 1280.0 => (0.36, 0.25, 0.25),
        // Two pictures (the Phong demo and its correction) keep 240 points each from
        // 1280x720 up (checked on its own below): the plot gives way, below them.
        (false, true) if w >= 1280.0 => (0.36, 0.22, 0.16),
        (false, _) => (0.22, 0.13, 0.15),
    }
}

#[test]
fn pictures_and_the_plot_are_large_inside_the_window_and_labelled_clear() {
    let mut failures = Vec::new();
    for (w, hgt, scale) in SIZES {
        for presenting in [true, false] {
            for (what, open, picks) in SITUATIONS {
                let state = state_for(phonglab_core::Document::default(), presenting, false, open);
                let mut h = harness(w, hgt, scale, state);
                if picks {
                    pick(&mut h);
                }
                let g = h.state().ui.geometry.clone();
                let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(w, hgt));
                let case = format!("{w}x{hgt}@{scale} {} {what}", if presenting { "presenting" } else { "normal" });
                let (one, two, circle) = least(w, presenting, g.pictures.len());
                let want = if g.pictures.len() > 1 { two } else { one };
                if g.pictures.is_empty() {
                    failures.push(format!("{case}: no picture drawn"));
                }
                for r in &g.pictures {
                    if !window.contains_rect(r.shrink(0.5)) {
                        failures.push(format!("{case}: a picture {r:?} leaves the window"));
                    }
                    let side = r.width().min(r.height());
                    if g.pictures.len() > 1 && w >= 1280.0 && hgt >= 720.0 && side < 239.5 {
                        failures.push(format!("{case}: two pictures, one {side:.0} < 240 points"));
                    }
                    if side < want * hgt {
                        failures.push(format!("{case}: a picture's side {side:.0} < {:.0}", want * hgt));
                    }
                }
                let plot_expected = open != Some(Open::Compare) && open != Some(Open::Lobe);
                match (&g.plot, plot_expected) {
                    (Some(p), true) => {
                        if !window.contains_rect(p.rect.shrink(0.5)) {
                            failures.push(format!("{case}: the plot {:?} leaves the window", p.rect));
                        }
                        if 2.0 * p.unit < circle * hgt {
                            failures.push(format!("{case}: the unit circle {:.0} < {:.0}", 2.0 * p.unit, circle * hgt));
                        }
                        if p.stroke * scale < 3.0 {
                            failures.push(format!("{case}: arrows {:.1} px wide", p.stroke * scale));
                        }
                        for (i, a) in p.labels.iter().enumerate() {
                            for b in &p.labels[i + 1..] {
                                if a.intersects(*b) {
                                    failures.push(format!("{case}: labels overlap {a:?} {b:?}"));
                                }
                            }
                        }
                    }
                    (None, true) => failures.push(format!("{case}: no plot")),
                    _ => {}
                }
                for p in &g.pictures {
                    if let Some(plot) = &g.plot
                        && p.intersects(plot.rect.shrink(1.0))
                    {
                        failures.push(format!("{case}: a picture and the plot overlap"));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn the_layout_of_the_first_frame_is_the_layout_after_a_click() {
    for presenting in [true, false] {
        let state = state_for(phonglab_core::Document::default(), presenting, false, None);
        let mut h = harness(1280.0, 720.0, 1.0, state);
        let first = h.state().ui.geometry.clone();
        pick(&mut h);
        let after = h.state().ui.geometry.clone();
        assert_eq!(first.arrangement, after.arrangement, "presenting {presenting}");
        if presenting {
            assert_eq!(first.pictures, after.pictures);
            assert_eq!(first.plot.map(|p| p.rect), after.plot.map(|p| p.rect));
        } else {
            // The controls panel widens to the picked vertex's longer numbers (its fields
            // show every digit); the centre follows, within a few per cent.
            let side = |g: &phonglab::app::shell::state::Geometry| g.pictures[0].width();
            assert!((side(&first) - side(&after)).abs() < 0.1 * side(&first), "{first:?} -> {after:?}");
        }
    }
}

#[test]
fn the_divider_moves_the_split_and_is_kept() {
    let state = state_for(phonglab_core::Document::default(), true, false, None);
    let mut h = harness(1280.0, 720.0, 1.0, state);
    let before = h.state().ui.geometry.pictures[0];
    // The divider lies between the picture and the plot.
    let divider = h.get_by_label("divider").rect();
    assert!(divider.min.x >= before.max.x - 1.0, "{divider:?} {before:?}");
    let from = divider.center();
    let to = from - egui::vec2(120.0, 0.0);
    common::press_and_move(&mut h, from, to);
    common::button(&mut h, to, false);
    h.run_steps(3);
    let kept = h.state().ui.layout.dividers;
    assert!(kept.beside.is_some(), "{kept:?}");
    let after = h.state().ui.geometry.pictures[0];
    assert!(after.width() < before.width() - 40.0, "{before:?} -> {after:?}");
    // Kept across restarts: the layout's stored text carries it.
    let back = phonglab::app::shell::layout::Layout::from_ron(Some(&h.state().ui.layout.to_ron()));
    assert_eq!(back.dividers, kept);
}

#[test]
fn at_most_half_the_window_is_empty_in_presentation() {
    for open in [None, Some(Open::Compare), Some(Open::DemoFixes)] {
        let state = state_for(phonglab_core::Document::default(), true, false, open);
        let (w, h, rgba, state) = phonglab::app::shell::screenshot::take(state, 1280.0, 720.0, 1.0);
        let bg = state.ui.layout.theme.visuals().panel_fill;
        let pictures = &state.ui.geometry.pictures;
        let empty = phonglab::app::shell::screenshot::empty_share(&rgba, w, h, bg, 16, pictures);
        assert!(empty <= 0.5, "{open:?}: {:.0} % empty", 100.0 * empty);
    }
}

/// The height `text` needs in the body's size wrapped to `width` (the way egui lays it out).
fn wrapped_height(h: &Harness<'static, AppState>, text: &str, width: f32) -> f32 {
    let font = egui::TextStyle::Body.resolve(&h.ctx.global_style());
    h.ctx.fonts_mut(|f| f.layout(text.to_string(), font, egui::Color32::WHITE, width).size().y)
}

/// The captions read from the back: in the body's size (the timing caption, "1 of 8" and
/// the rules note were 9 points), and never cut. The mesh's caption while the camera turns
/// ("…while the c…" at 1280x720) and the demo's two ("the demo's …", "true norm…" in the
/// light theme) take the lines they need above their pictures; beside each other they are
/// short, the whole in the picture's name and hover.
#[test]
fn captions_read_whole_in_the_bodys_size() {
    use egui::accesskit::Role;
    use egui_kittest::kittest::NodeT;
    let body = egui::Style::default().text_styles[&egui::TextStyle::Body].size;
    // A mesh of more than COARSE_ABOVE triangles turned by a drag: the long caption.
    let mut state = state_for(phonglab_core::Document::default(), false, false, None);
    state.doc.view.object = phonglab_core::ObjectKind::Sphere;
    (state.doc.view.sphere_slices, state.doc.view.sphere_stacks) = (400, 400);
    let mut h = harness(1280.0, 720.0, 1.0, state);
    let picture = h.state().ui.geometry.pictures[0];
    let (from, to) = (picture.center(), picture.center() + egui::vec2(60.0, 20.0));
    common::press_and_move(&mut h, from, to);
    let caption = h
        .get_all_by_role(Role::Label)
        .find(|n| n.value().is_some_and(|v| v.contains("triangles while the camera turns")))
        .expect("the coarse copy's caption");
    let (text, r) = (caption.value().unwrap(), caption.rect());
    let picture = h.state().ui.geometry.pictures[0];
    assert!(r.width() <= picture.width() + 0.5 && r.max.y <= picture.min.y + 0.5, "{r:?} above {picture:?}");
    assert!(r.height() >= wrapped_height(&h, &text, picture.width()) - 0.5, "whole: {r:?} for {text:?}");
    assert!(r.height() > 1.5 * body, "it wraps rather than being cut: {r:?}");
    common::button(&mut h, to, false);
    h.run_steps(2);
    // The timing caption, "1 of 8" and the rules note: at least a body line high.
    for label in ["ms per frame on the CPU", "1 of 8", "The worksheet: no scene ambient"] {
        let n = h.get_all_by_role(Role::Label).find(|n| n.value().is_some_and(|v| v.contains(label))).unwrap();
        assert!(n.rect().height() >= body, "{label:?}: {:?}", n.rect());
    }
    // The Phong demo beside its correction, in the light theme: each caption whole on its
    // line; each picture named (and hovered) by the whole.
    let mut state = state_for(phonglab_core::Document::default(), false, true, Some(Open::DemoFixes));
    state.doc.view.auto_rotate = false;
    let h = harness(1280.0, 720.0, 1.0, state);
    let g = h.state().ui.geometry.clone();
    assert_eq!(g.pictures.len(), 2);
    for (shown, whole, picture) in [
        ("Sphere Gouraud (the demo's own)", "ms per frame on the CPU (the demo's own)", g.pictures[0]),
        (
            "Corrected (3 of 3)",
            "Corrected: light fixed in the world, the surface's true normals, highlight in the light's colour",
            g.pictures[1],
        ),
    ] {
        let r = h.get_by_role_and_label(Role::Label, shown).rect();
        assert!(r.width() <= picture.width() + 0.5 && r.max.y <= picture.min.y + 0.5, "{shown}: {r:?} {picture:?}");
        assert!(r.height() >= wrapped_height(&h, shown, picture.width()) - 0.5, "{shown}: whole");
        let named = h.get_all_by_label_contains(whole).find(|n| n.accesskit_node().role() == Role::Image);
        assert_eq!(named.map(|n| n.rect()), Some(picture), "{whole}");
    }
}
