//! The centre: the colour and the message, then the shaded view and the vector plot (or
//! the lobe), side by side or stacked as the space allows ([`super::centre_layout::split`]),
//! with a divider between them that can be dragged; with Compare on, A beside B.

use egui::Ui;

use super::state::{AppState, Message};
use super::{centre_layout, files, layout, state};
use crate::app::editing::editor::Editor;
use crate::app::panels::{compare, lobe, result, shaded, things_to_try, vector_plot};
use crate::t;

/// How many rows of widgets stand above the shaded picture, and above the plot's diagram,
/// as heights in points (see [`centre_layout::Chrome`]).
fn chrome(ui: &Ui, state: &mut AppState, pictures: usize, area: egui::Rect) -> centre_layout::Chrome {
    let row = ui.spacing().interact_size.y + ui.spacing().item_spacing.y;
    // The pictures' captions (wrapped), at the width two pictures keep at the least, or
    // one about half the area's.
    let width = if pictures > 1 {
        centre_layout::PICTURE_FLOOR
    } else {
        (0.5 * area.width()).min(0.6 * area.height()).max(centre_layout::PICTURE_FLOOR)
    };
    let room = shaded::CaptionRoom { presenting: state.ui.layout.presenting, pair: pictures > 1 };
    let triangles = shaded::mesh_for(&mut state.shaded.main.mesh, &state.doc.view).triangle_count();
    let room = shaded::caption_room(
        ui,
        (&state.doc, state.settings.pow),
        &state.view_options,
        &state.shaded.main,
        triangles,
        width,
        room,
    );
    let caption = room + ui.spacing().item_spacing.y;
    // The toolbar's rows in a part of the centre (the switches and View options, one row in
    // the normal window; presenting, none: the object and the shading are the top bar's): counted from the frame's own sizes, never from the last frame's, so the
    // split cannot chase itself from frame to frame.
    let rows = if state.ui.layout.presenting { 0.0 } else { 1.0 };
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let legend = body + ui.spacing().item_spacing.y;
    centre_layout::Chrome {
        picture: rows * row + caption + 8.0,
        // The plot's buttons take three rows in large type (two in the normal window).
        plot: if state.ui.layout.presenting { 3.0 } else { 2.0 } * row + legend + 8.0,
        plot_wide: row + 8.0,
        min_part: 10.5 * body,
    }
}

/// The centre: the colour, then the shaded view and the vector plot (or the lobe), side by
/// side or stacked as the space allows ([`centre_layout::split`]), with a divider between
/// them that can be dragged; with Compare on, A beside B.
pub fn centre_ui(ui: &mut Ui, state: &mut AppState, eval: &state::Evaluated) {
    if state.compare.open {
        let current = compare::Current {
            doc: &state.doc,
            precision: state.settings.precision,
            pow: state.settings.pow,
            side: state.settings.side,
            spun: state.view_options.spun,
        };
        let (notice, pictures) = compare::compare_ui(ui, &mut state.compare, &current, eval);
        if let Some(m) = notice {
            state.message = Some(Message::Info(m));
        }
        state.ui.geometry = state::Geometry { pictures, ..Default::default() };
        if std::mem::take(&mut state.compare.recheck) {
            super::student::recheck_picture(state);
        }
        if !state.compare.open && matches!(&state.message, Some(Message::Info(m)) if *m == t!("compare-pinned")) {
            // Closed: its notice goes with it.
            state.message = None;
        }
        return;
    }
    // The colour and the message take a fixed height, so that a longer number or a new
    // message moves nothing below them.
    let mono = ui.text_style_height(&egui::TextStyle::Monospace) + ui.spacing().item_spacing.y;
    let body = ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
    let rows = 3.0 + f32::from(state.doc.scene.light_model.separate_specular);
    // (The title's row holds the colour in large type.)
    let large = ui.text_style_height(&egui::TextStyle::Heading) + ui.spacing().item_spacing.y;
    let strip = egui::vec2(ui.available_width(), (rows - 1.0) * mono + large + 2.0 * body + 6.0);
    let (rect, _) = ui.allocate_exact_size(strip, egui::Sense::hover());
    ui.scope_builder(egui::UiBuilder::new().max_rect(rect), |ui| {
        ui.set_clip_rect(rect.intersect(ui.clip_rect()));
        let hidden = state.quiz.hides_answers();
        result::result_ui(ui, eval, state.doc.scene.light_model.separate_specular, &state.message, hidden);
    });
    ui.separator();
    shaded::departures_ui(ui, &state.doc, &mut state.view_options.demo_fixes);
    // Two pictures side by side (the corrected one, or the heat map) share the view's part.
    let pair = state.heat_map.on || shaded::corrected_document(&state.doc, &state.view_options.demo_fixes).is_some();
    let area = ui.available_rect_before_wrap();
    let chrome = chrome(ui, state, 1 + pair as usize, area);
    let split = centre_layout::split(area, 1 + pair as usize, chrome, state.ui.layout.dividers);
    let show_angles = !state.quiz.hides_answers();
    let mut geometry = state::Geometry { arrangement: Some(split.arrangement), ..Default::default() };
    let shaded_used = ui.scope_builder(egui::UiBuilder::new().max_rect(split.pictures).id_salt("shaded"), |ui| {
        let now = state.now;
        let mut view = shaded::Shaded {
            edit: Editor { doc: &mut state.doc, history: &mut state.history, message: &mut state.message, now },
            view_options: &mut state.view_options,
            heat_map: &mut state.heat_map,
            pow: state.settings.pow,
            presenting: state.ui.layout.presenting,
            gpu: state.gpu.as_ref(),
        };
        let asked = shaded::shaded_ui(ui, &mut view, &mut state.shaded, eval);
        geometry.pictures = asked.rects;
        geometry.arrows = asked.arrows;
        geometry.cones = asked.cones;
        if let Some(p) = asked.open_obj {
            files::open_obj(state, &p);
        }
    });
    let beside_used = ui.scope_builder(egui::UiBuilder::new().max_rect(split.beside).id_salt("beside"), |ui| {
        ui.horizontal_wrapped(|ui| {
            // Each button or label moves to the next row whole rather than breaking inside.
            ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
            ui.selectable_value(&mut state.ui.layout.beside, layout::Beside::Vectors, t!("vectors-at-vertex"));
            ui.selectable_value(&mut state.ui.layout.beside, layout::Beside::Lobe, t!("reflection-lobe"));
            if state.ui.layout.beside == layout::Beside::Vectors {
                ui.separator();
                vector_plot::view_buttons_ui(ui, &mut state.orbit);
            }
        });
        match state.ui.layout.beside {
            layout::Beside::Vectors => {
                let specular = state.doc.scene.rules.specular;
                geometry.plot = Some(vector_plot::vector_plot_ui(ui, &mut state.orbit, eval, specular, show_angles));
            }
            layout::Beside::Lobe => geometry.lobe = lobe::lobe_ui(ui, &state.doc.scene, eval),
        }
    });
    // Side by side, two squares leave a band under them (both are bound by the centre's
    // width): the things to try stand there, where a first-time user looks for what to do.
    let used = shaded_used.response.rect.max.y.max(beside_used.response.rect.max.y);
    let band =
        split.arrangement == centre_layout::Arrangement::Beside && !state.ui.layout.presenting && !state.quiz.open;
    // The divider stands between the squares (down to the band, when there is one).
    let mut divider = split;
    if band {
        divider.divider.max.y = divider.divider.max.y.min(used);
    }
    divider_ui(ui, state, area, &divider);
    if band {
        let band = egui::Rect::from_min_max(egui::pos2(area.min.x, used + 8.0), area.max);
        let lang = state.ui.layout.locale().lang;
        let asked = ui
            .scope_builder(egui::UiBuilder::new().max_rect(band).id_salt("try band"), |ui| {
                things_to_try::suggestions_ui(ui, &mut state.things, lang)
            })
            .inner;
        if let Some(things_to_try::TryAsked::Load(doc, title, control)) = asked {
            state.set_up_experiment(*doc, &title, control.is_some());
        }
        geometry.suggestions = Some(band);
    }
    ui.advance_cursor_after_rect(area);
    state.ui.geometry = geometry;
}

/// The handle between the pictures and the plot: drag it to share the space otherwise
/// (kept across restarts, per arrangement); double-click to put it back.
fn divider_ui(ui: &mut Ui, state: &mut AppState, area: egui::Rect, split: &centre_layout::Split) {
    let id = ui.scope_id().with("centre divider");
    let resp = ui.interact(split.divider, id, egui::Sense::click_and_drag());
    resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Splitter, true, "divider"));
    let beside = split.arrangement == centre_layout::Arrangement::Beside;
    let resp = resp.on_hover_cursor(if beside {
        egui::CursorIcon::ResizeHorizontal
    } else {
        egui::CursorIcon::ResizeVertical
    });
    let strong = resp.hovered() || resp.dragged();
    let c = if strong { ui.visuals().strong_text_color() } else { ui.visuals().weak_text_color() };
    let r = split.divider;
    let (a, b) = if beside {
        (egui::pos2(r.center().x, r.min.y + 4.0), egui::pos2(r.center().x, r.max.y - 4.0))
    } else {
        (egui::pos2(r.min.x + 4.0, r.center().y), egui::pos2(r.max.x - 4.0, r.center().y))
    };
    ui.painter().line_segment([a, b], egui::Stroke::new(if strong { 3.0 } else { 1.0 }, c));
    let dividers = &mut state.ui.layout.dividers;
    let slot = if beside { &mut dividers.beside } else { &mut dividers.stacked };
    if resp.double_clicked() {
        *slot = None;
    } else if resp.dragged()
        && let Some(p) = resp.interact_pointer_pos()
    {
        *slot = Some(centre_layout::dragged_fraction(area, split.arrangement, p));
    }
}
