//! The explorer window: controls on the left, the worked calculation on the right, the
//! colour and the vector plot in the middle. `app_ui` draws everything from an
//! [`AppState`] and takes `&mut egui::Ui`, so tests drive it headless.

use egui::Ui;
use phonglab_core::t;
use phonglab_core::{CameraSpec, NormalMode, RuleSet, SpecularModel, materials};

use super::state::{AppState, Message, Precision};
use crate::app::model::editor::Editor;
use crate::app::panels::{
    calculation, compare, controls, cost, export, help, lobe, quiz, result, shaded, shader_panel, vector_plot,
};
use crate::app::widgets::number_field;

use super::{centre_layout, files, layout, state};

/// Applies one keyboard shortcut.
fn apply_action(state: &mut AppState, action: help::Action) {
    use help::Action as A;
    let mut c = state.doc.clone();
    match action {
        A::Help => {
            state.ui.show_help = !state.ui.show_help;
            return;
        }
        A::Reset => {
            state.reset_to_worksheet();
            return;
        }
        A::Quit => {
            state.ui.quit = true;
            return;
        }
        A::Open => return files::open_typed(state),
        A::Undo => return state.undo(),
        A::Redo => return state.redo(),
        A::Save => return files::save_typed(state),
        A::Precision => {
            state.settings.precision = match state.settings.precision {
                Precision::F32 => Precision::F64,
                Precision::F64 => Precision::F32,
            };
            return;
        }
        A::LocalViewer => c.scene.light_model.local_viewer = !c.scene.light_model.local_viewer,
        A::TwoSided => c.scene.light_model.two_sided = !c.scene.light_model.two_sided,
        A::NextMaterial | A::PreviousMaterial => {
            let table = materials::classic();
            let n = table.len();
            let now = table.iter().position(|m| m.material == c.scene.material);
            let next = match (now, action == A::NextMaterial) {
                (Some(i), true) => (i + 1) % n,
                (Some(i), false) => (i + n - 1) % n,
                (None, true) => 0,
                (None, false) => n - 1,
            };
            c.scene.material = table[next].material.clone();
        }
        A::NextModelview => {
            c.camera = match c.camera {
                CameraSpec::Worksheet(k) => CameraSpec::Worksheet(k % 5 + 1),
                _ => CameraSpec::Worksheet(1),
            }
        }
        A::SpecularModel => {
            c.scene.rules.specular = match c.scene.rules.specular {
                SpecularModel::BlinnPhong => SpecularModel::Phong,
                SpecularModel::Phong => SpecularModel::BlinnPhong,
            }
        }
        A::NextRuleSet => {
            let i = RuleSet::ALL.iter().position(|r| *r == c.scene.rules.set).unwrap_or(0);
            c.scene.rules.set = RuleSet::ALL[(i + 1) % RuleSet::ALL.len()];
        }
        A::Object(o) => c.view.object = o,
        A::Shading(sh) => c.view.shading = sh,
        A::AutoRotate => c.view.auto_rotate = !c.view.auto_rotate,
        A::NextNormals => {
            c.scene.normal_mode = match c.scene.normal_mode {
                NormalMode::AsIs => NormalMode::Normalize,
                NormalMode::Normalize => NormalMode::Rescale,
                NormalMode::Rescale => NormalMode::AsIs,
            }
        }
    }
    state.apply(c);
}

fn top_bar_ui(ui: &mut Ui, state: &mut AppState) {
    // Labels move to the next row whole rather than breaking across rows.
    ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
    ui.horizontal_wrapped(|ui| {
        ui.strong("phonglab");
        ui.separator();
        let layout = &mut state.ui.layout;
        let present = if layout.presenting { t!("leave-presenting") } else { t!("present") };
        if ui.selectable_label(layout.presenting, present).on_hover_text(t!("present-hover")).clicked() {
            layout.presenting = !layout.presenting;
        }
        if layout.presenting {
            ui.toggle_value(&mut layout.drawer_open, t!("controls-drawer")).on_hover_text(t!("controls-drawer-hover"));
        } else {
            ui.toggle_value(&mut layout.controls_open, t!("controls"));
            ui.toggle_value(&mut layout.calculation_open, t!("calculation"));
        }
        if ui.button(layout.theme.toggled().label()).on_hover_text(t!("theme-hover")).clicked() {
            layout.theme = layout.theme.toggled();
        }
        ui.separator();
        if ui.button(t!("reset-worksheet")).on_hover_text("Ctrl+R").clicked() {
            state.reset_to_worksheet();
        }
        undo_buttons_ui(ui, state);
        ui.menu_button(t!("presets"), |ui| presets_menu_ui(ui, state));
        let was_open = state.compare.open;
        ui.toggle_value(&mut state.compare.open, t!("compare")).on_hover_text(t!("compare-hover"));
        if state.compare.open && !was_open && state.compare.a.is_none() {
            // Opened: A is the scene as it is, so the first change already compares.
            state.compare.pin(&state.doc, state.settings.precision, state.settings.pow);
        }
        if ui.toggle_value(&mut state.quiz.open, t!("quiz")).on_hover_text(t!("quiz-hover")).clicked()
            && state.quiz.open
            && state.quiz.doc.is_none()
        {
            state.quiz.start(state.doc.clone());
        }
        ui.toggle_value(&mut state.shader.open, t!("shader")).on_hover_text(t!("shader-hover"));
        ui.separator();
        if !state.ui.layout.presenting {
            ui.label(t!("precision"));
        }
        ui.radio_value(&mut state.settings.precision, Precision::F32, "f32").on_hover_text(t!("f32-hover"));
        ui.radio_value(&mut state.settings.precision, Precision::F64, "f64").on_hover_text(t!("f64-hover"));
        if state.ui.layout.presenting {
            return;
        }
        egui::ComboBox::from_label("pow").selected_text(state.settings.pow.label()).show_ui(ui, |ui| {
            for p in phonglab_core::PowFn::ALL {
                ui.selectable_value(&mut state.settings.pow, p, p.label());
            }
        });
        ui.separator();
        ui.toggle_value(&mut state.cost.open, t!("cost-of-accuracy")).on_hover_text(t!("cost-hover"));
        ui.separator();
        if let Some(asked) = crate::app::panels::files::file_ui(ui, &mut state.files, &state.doc, &mut state.message) {
            files::carry_out(state, asked);
        }
        export::export_menu_ui(ui, &mut state.export, &state.doc, state.settings.pow, &state.files, &mut state.message);
        ui.separator();
        language_menu_ui(ui, &mut state.ui.layout);
        if ui.button(t!("help-button")).clicked() {
            state.ui.show_help = !state.ui.show_help;
        }
        ui.label(egui::RichText::new(phonglab_core::library::localised_name(&state.doc.name)).weak());
    });
}

/// The language and decimal mark menu (kept across restarts).
fn language_menu_ui(ui: &mut Ui, layout: &mut layout::Layout) {
    use phonglab_core::locale::{DecimalMark, Lang};
    let now = layout.locale();
    ui.menu_button(now.lang.code(), |ui| {
        for lang in Lang::ALL {
            if ui.radio(now.lang == lang, lang.name()).clicked() {
                layout.language = Some(lang.code().to_string());
                layout.decimal = None;
            }
        }
        ui.separator();
        for (mark, text) in [(DecimalMark::Comma, "0,5"), (DecimalMark::Point, "0.5")] {
            if ui.radio(now.decimal == mark, text).clicked() {
                layout.decimal = Some(if mark == DecimalMark::Comma { "comma" } else { "point" }.to_string());
            }
        }
    })
    .response
    .on_hover_text(phonglab_core::t!("language-menu-hover"));
}

/// Undo and Redo, each saying what it would change.
fn undo_buttons_ui(ui: &mut Ui, state: &mut AppState) {
    let undo = state.history.undo_label().map(|l| t!("undo-what", what = l));
    let redo = state.history.redo_label().map(|l| t!("redo-what", what = l));
    // Presenting, the icons alone: the top bar keeps one row at 1280 points.
    let short = state.ui.layout.presenting;
    let b = ui.add_enabled(undo.is_some(), egui::Button::new(if short { "⟲".to_string() } else { t!("undo-button") }));
    if b.on_hover_text(undo.unwrap_or_else(|| t!("nothing-to-undo"))).clicked() {
        state.undo();
    }
    let b = ui.add_enabled(redo.is_some(), egui::Button::new(if short { "⟳".to_string() } else { t!("redo-button") }));
    if b.on_hover_text(redo.unwrap_or_else(|| t!("nothing-to-redo"))).clicked() {
        state.redo();
    }
}

/// A small square of a material's diffuse colour (clamped, as displayed).
fn swatch_ui(ui: &mut Ui, doc: &phonglab_core::Document) {
    let c = doc.scene.material.diffuse;
    let to8 = |x: f64| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    let (rect, _) = ui.allocate_exact_size(egui::vec2(12.0, 12.0), egui::Sense::hover());
    ui.painter().rect_filled(rect, 2.0, egui::Color32::from_rgb(to8(c.x), to8(c.y), to8(c.z)));
}

/// Every scene file shipped under `assets/scenes/`, grouped, each with its material's swatch;
/// the 24 Red Book teapots in a submenu.
fn presets_menu_ui(ui: &mut Ui, state: &mut AppState) {
    let files = crate::io::scenes::scene_files();
    let mut entry = |ui: &mut Ui, f: &crate::io::scenes::SceneFile| {
        ui.horizontal(|ui| {
            swatch_ui(ui, &f.doc);
            let title = f.title();
            if ui.button(&title).on_hover_text(format!("assets/scenes/{}", f.path)).clicked() {
                state.load(f.doc.clone(), &title);
                ui.close();
            }
        });
    };
    use crate::io::scenes::Group;
    let mut group = None;
    for f in files.iter().filter(|f| f.group != Group::RedbookTeapots) {
        if group != Some(f.group) {
            if group.is_some() {
                ui.separator();
            }
            ui.label(egui::RichText::new(f.group.label()).small().strong());
            group = Some(f.group);
        }
        entry(ui, f);
    }
    ui.separator();
    ui.menu_button(Group::RedbookTeapots.label(), |ui| {
        egui::ScrollArea::vertical().max_height(480.0).show(ui, |ui| {
            for f in files.iter().filter(|f| f.group == Group::RedbookTeapots) {
                entry(ui, f);
            }
        });
    });
}

/// The keys of presentation: F5 toggles it; the arrow keys walk through the calculation's
/// steps (when no widget has the keyboard).
fn presentation_keys(ctx: &egui::Context, state: &mut AppState, steps: usize) {
    let layout = &mut state.ui.layout;
    if ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, egui::Key::F5)) {
        layout.presenting = !layout.presenting;
    }
    if ctx.egui_wants_keyboard_input() || ctx.memory(|m| m.focused().is_some()) {
        return;
    }
    let (down, up) = ctx.input_mut(|i| {
        let down = i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowDown)
            || i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowRight);
        let up = i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowUp)
            || i.consume_key(egui::Modifiers::NONE, egui::Key::ArrowLeft);
        (down, up)
    });
    if down || up {
        layout.step_by(if down { 1 } else { -1 }, steps);
        state.ui.scroll_to_step = true;
    }
}

/// The whole explorer UI.
pub fn app_ui(ui: &mut Ui, state: &mut AppState) {
    let Some(eval) = frame_start_ui(ui, state) else { return };
    let ctx = ui.ctx().clone();
    presentation_keys(&ctx, state, eval.explanation.steps.len());
    if state.ui.layout.presenting {
        layout::scale_text(ui.style_mut(), layout::PRESENTATION_TEXT_SCALE);
    }
    let width = ui.max_rect().width();
    egui::Panel::top("top bar").show(ui, |ui| top_bar_ui(ui, state));
    controls_panel_ui(ui, state, width);
    calculation_panel_ui(ui, state, &eval, width);
    egui::CentralPanel::default().show(ui, |ui| centre_ui(ui, state, &eval));
    windows_ui(&ctx, state);
}

/// The frame's start: the theme and the language, the keys, a quit asked for, dropped
/// files, and the document evaluated (`None` only if even the worksheet cannot be).
fn frame_start_ui(ui: &mut Ui, state: &mut AppState) -> Option<state::Evaluated> {
    let ctx = ui.ctx().clone();
    let visuals = state.ui.layout.theme.visuals();
    if ctx.global_style().visuals != visuals {
        ctx.set_visuals(visuals.clone());
    }
    *ui.visuals_mut() = visuals;
    state.now = ctx.input(|i| i.time);
    // The window's language, switched at once when the menu changes it.
    phonglab_core::locale::set_thread(Some(state.ui.layout.locale()));
    for a in help::pressed(&ctx, state.quiz.open) {
        apply_action(state, a);
    }
    if state.ui.quit {
        // eframe then calls `on_exit`, which saves the session.
        ctx.send_viewport_cmd(egui::ViewportCommand::Close);
    }
    files::dropped_files_ui(&ctx, state);

    let eval = match state.evaluate() {
        Ok(e) => e,
        Err(e) => {
            // The document is validated on every edit, so this is not expected; say so and
            // fall back to the worksheet rather than panic.
            state.message = Some(Message::Refused(t!("could-not-evaluate", error = e.to_string())));
            state.doc = Default::default();
            match state.evaluate() {
                Ok(e) => e,
                Err(_) => return None,
            }
        }
    };
    Some(eval)
}

/// The controls: a side panel, or presenting, a drawer (its own panel, so each keeps its
/// width). Every edit goes through `AppState::apply_or_why`.
fn controls_panel_ui(ui: &mut Ui, state: &mut AppState, width: f32) {
    let controls = |ui: &mut Ui, state: &mut AppState| {
        // Sliders sized to the panel, so a narrow panel does not widen to fit them.
        // From the panel's starting width, not its width now: a slider sized from the
        // panel it widens grew the panel by a few points a frame until the clamp.
        let panel = layout::Layout::controls_width(width).min(ui.available_width());
        ui.spacing_mut().slider_width = (panel - 230.0).clamp(60.0, 160.0);
        egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
            let mut candidate = state.doc.clone();
            controls::controls_ui(ui, &mut candidate, &mut state.controls);
            match state.apply_or_why(candidate) {
                Ok(()) => number_field::accept_last_commit(ui.ctx()),
                Err(why) => number_field::refuse_last_commit(ui.ctx(), &why),
            }
        });
    };
    let presenting = state.ui.layout.presenting;
    // Presenting, the controls are a drawer (its own panel, so each keeps its width).
    let (id, min, mut open) = if presenting {
        ("drawer", 240.0, state.ui.layout.drawer_open)
    } else {
        ("controls", 220.0, state.ui.layout.controls_open)
    };
    egui::Panel::left(id)
        .resizable(true)
        .default_size(layout::Layout::controls_width(width))
        .min_size(min)
        .show_collapsible(ui, &mut open, |ui| controls(ui, state));
    *(if presenting { &mut state.ui.layout.drawer_open } else { &mut state.ui.layout.controls_open }) = open;
}

/// The worked calculation's panel (the quiz in its place while the quiz is open).
fn calculation_panel_ui(ui: &mut Ui, state: &mut AppState, eval: &state::Evaluated, width: f32) {
    let presenting = state.ui.layout.presenting;
    // Compare lists the steps of A and B itself, in the calculation's place.
    let mut open = (state.ui.layout.calculation_open || presenting) && !state.compare.open;
    egui::Panel::right(if presenting { "calculation (presenting)" } else { "calculation" })
        .resizable(true)
        .default_size(layout::Layout::calculation_width(width))
        .min_size(260.0)
        .show_collapsible(ui, &mut open, |ui| {
            if state.quiz.open {
                if let Some(doc) = quiz::quiz_ui(ui, &mut state.quiz, &state.doc) {
                    let name = doc.name.clone();
                    state.load(doc, &name);
                }
                return;
            }
            let two_sided = state.doc.scene.light_model.two_sided;
            let key = phonglab_core::plan::Key::of(
                &state.doc.scene,
                phonglab_core::EvalOptions::with_pow(state.settings.pow),
            );
            let program = key.program();
            let effects = key.effects_of(&program);
            let walk =
                calculation::Walk { step: state.ui.layout.step, scroll: std::mem::take(&mut state.ui.scroll_to_step) };
            calculation::calculation_ui(
                ui,
                &eval.explanation,
                &mut state.settings.side,
                two_sided,
                &effects,
                &program.stages,
                walk,
            );
        });
    if !presenting && !state.compare.open {
        state.ui.layout.calculation_open = open;
    }
}

/// The windows over the layout: the cost study (its finished work collected first), the
/// shader, the keys.
fn windows_ui(ctx: &egui::Context, state: &mut AppState) {
    // Finished work is collected before the window is drawn, and a frame is asked for at
    // once when something finished (the result would otherwise wait for the next input).
    let was_running = state.cost.busy() || state.heat_map.busy();
    let running = state.cost.poll() | state.heat_map.poll();
    if was_running && !running {
        ctx.request_repaint();
    } else if running {
        ctx.request_repaint_after(std::time::Duration::from_millis(100));
    }
    cost::cost_window_ui(ctx, &mut state.cost, &state.doc, state.settings.pow);
    shader_panel::shader_window_ui(ctx, &mut state.shader, &state.doc);

    if state.ui.show_help {
        let mut open = true;
        egui::Window::new(t!("keyboard-shortcuts"))
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .show(ctx, help::help_ui);
        state.ui.show_help = open;
    }
}

/// How many rows of widgets stand above the shaded picture, and above the plot's diagram,
/// as heights in points (see [`centre_layout::Chrome`]).
fn chrome(ui: &Ui, state: &AppState) -> centre_layout::Chrome {
    let row = ui.spacing().interact_size.y + ui.spacing().item_spacing.y;
    let small = ui.text_style_height(&egui::TextStyle::Small) + ui.spacing().item_spacing.y;
    // The toolbar's rows as they wrap in a part of the centre (object and shading; then the
    // switches and View options in the normal window): counted from the frame's own sizes,
    // never from the last frame's, so the split cannot chase itself from frame to frame.
    let rows = if state.ui.layout.presenting { 2.0 } else { 3.0 };
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let legend = body + ui.spacing().item_spacing.y;
    centre_layout::Chrome {
        picture: rows * row + 2.0 * small + 8.0,
        plot: 2.0 * row + legend + 8.0,
        min_part: 10.5 * body,
    }
}

/// The centre: the colour, then the shaded view and the vector plot (or the lobe), side by
/// side or stacked as the space allows ([`centre_layout::split`]), with a divider between
/// them that can be dragged; with Compare on, A beside B.
fn centre_ui(ui: &mut Ui, state: &mut AppState, eval: &state::Evaluated) {
    if state.compare.open {
        let current = compare::Current {
            doc: &state.doc,
            precision: state.settings.precision,
            pow: state.settings.pow,
            side: state.settings.side,
        };
        let (notice, pictures) = compare::compare_ui(ui, &mut state.compare, &current, eval);
        if let Some(m) = notice {
            state.message = Some(Message::Info(m));
        }
        state.ui.geometry = state::Geometry { pictures, plot: None, arrangement: None };
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
    let strip = egui::vec2(ui.available_width(), rows * mono + 2.0 * body + 6.0);
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
    let chrome = chrome(ui, state);
    let split = centre_layout::split(area, 1 + pair as usize, chrome, state.ui.layout.dividers);
    divider_ui(ui, state, area, &split);
    let show_angles = !state.quiz.hides_answers();
    let mut geometry = state::Geometry { pictures: Vec::new(), plot: None, arrangement: Some(split.arrangement) };
    ui.scope_builder(egui::UiBuilder::new().max_rect(split.pictures).id_salt("shaded"), |ui| {
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
        if let Some(p) = asked.open_obj {
            files::open_obj(state, &p);
        }
    });
    ui.scope_builder(egui::UiBuilder::new().max_rect(split.beside).id_salt("beside"), |ui| {
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
            layout::Beside::Lobe => lobe::lobe_ui(ui, &state.doc.scene, eval),
        }
    });
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
