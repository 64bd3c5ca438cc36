//! The explorer window: controls on the left, the worked calculation on the right, the
//! colour and the vector plot in the middle. `app_ui` draws everything from an
//! [`AppState`] and takes `&mut egui::Ui`, so tests drive it headless.

use egui::Ui;

use super::state::{AppState, Message};
use super::{centre, keys, layout, state, top_bar, windows};
use crate::app::panels::{calculation, controls, quiz};
use crate::app::widgets::number_field;
use crate::t;

/// The whole explorer UI.
pub fn app_ui(ui: &mut Ui, state: &mut AppState) {
    let Some(eval) = frame_start_ui(ui, state) else { return };
    let ctx = ui.ctx().clone();
    keys::presentation_keys(&ctx, state, eval.explanation.steps.len());
    presentation_type(&ctx, ui, state.ui.layout.presenting);
    let width = ui.max_rect().width();
    egui::Panel::top("top bar").show(ui, |ui| top_bar::top_bar_ui(ui, state));
    controls_panel_ui(ui, state, width);
    calculation_panel_ui(ui, state, &eval, width);
    // Between the panels: the windows keep clear of the controls on its left.
    let centre = ui.available_rect_before_wrap();
    egui::CentralPanel::default().show(ui, |ui| centre::centre_ui(ui, state, &eval));
    windows::windows_ui(&ctx, state, &eval.explanation, centre);
    // A whole frame has passed for what was deferred: its field has committed.
    if !state.ui.deferred.is_empty() {
        state.ui.deferred.iter_mut().for_each(|(_, ready)| *ready = true);
        ctx.request_repaint();
    }
}

/// Presenting, every text and control in large type, the windows (Shader, Things to try)
/// and the menus (Scene) included: the context's style, which they read, is scaled, and
/// this frame's root (made before) takes it too. Back to egui's sizes when not presenting.
fn presentation_type(ctx: &egui::Context, ui: &mut Ui, presenting: bool) {
    let k = if presenting { layout::PRESENTATION_TEXT_SCALE } else { 1.0 };
    layout::set_text_scale(ui.style_mut(), k);
    let body = |s: &egui::Style| s.text_styles[&egui::TextStyle::Body].size;
    if body(&ctx.global_style()) != body(ui.style()) {
        ctx.global_style_mut(|s| layout::set_text_scale(s, k));
    }
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
    crate::locale::set_thread(Some(state.ui.layout.locale()));
    super::student::restate(state);
    // Open and Save pressed while typing wait for the field to commit what was typed: the
    // field lets the keyboard go now, commits next frame, and they run the frame after.
    let (ready, waiting): (Vec<_>, Vec<_>) = std::mem::take(&mut state.ui.deferred).into_iter().partition(|(_, r)| *r);
    state.ui.deferred = waiting;
    for (a, _) in ready {
        keys::apply_action(state, a);
    }
    let typing = ctx.egui_wants_keyboard_input();
    for a in crate::app::panels::help::pressed(&ctx, state.asking()) {
        use crate::app::panels::help::Action;
        if typing && matches!(a, Action::Open | Action::Save) {
            ctx.memory_mut(|m| {
                if let Some(id) = m.focused() {
                    m.surrender_focus(id);
                }
            });
            state.ui.deferred.push((a, false));
            ctx.request_repaint();
        } else {
            keys::apply_action(state, a);
        }
    }
    if state.ui.quit {
        // eframe then calls `on_exit`, which saves the session.
        ctx.send_viewport_cmd(egui::ViewportCommand::Close);
    }
    super::files::dropped_files_ui(&ctx, state);
    if let Some((name, bytes)) = super::student::ask_ui(&ctx, state) {
        super::files::open_bytes(state, &bytes, std::path::Path::new(&name));
    }

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
    // The centre keeps its floor, and the calculation (when it shows) its least width.
    let calculation = if calculation_shown(state, width) { CALCULATION_MIN } else { 0.0 };
    let most = (width - state.ui.layout.centre_floor(width) - calculation).max(min);
    egui::Panel::left(id)
        .resizable(true)
        .default_size(layout::Layout::controls_width(width).min(most))
        .min_size(min)
        .max_size(most)
        .show_collapsible(ui, &mut open, |ui| controls(ui, state));
    *(if presenting { &mut state.ui.layout.drawer_open } else { &mut state.ui.layout.controls_open }) = open;
}

/// The calculation panel's least width.
const CALCULATION_MIN: f32 = 260.0;

/// Whether the calculation's panel shows in a window `width` wide: presenting always
/// (unless the drawer pushed it aside), else when open (Compare lists the steps of A and B
/// itself, in its place).
fn calculation_shown(state: &AppState, width: f32) -> bool {
    let layout = &state.ui.layout;
    (layout.calculation_open || layout.presenting) && !state.compare.open && !layout.drawer_pushes_calculation(width)
}

/// The worked calculation's panel (the quiz in its place while the quiz is open).
fn calculation_panel_ui(ui: &mut Ui, state: &mut AppState, eval: &state::Evaluated, width: f32) {
    let presenting = state.ui.layout.presenting;
    let mut open = calculation_shown(state, width);
    // What the controls left, less the centre's floor.
    let most = (ui.available_width() - state.ui.layout.centre_floor(width)).max(CALCULATION_MIN);
    egui::Panel::right(if presenting { "calculation (presenting)" } else { "calculation" })
        .resizable(true)
        .default_size(layout::Layout::calculation_width(width).min(most))
        .min_size(CALCULATION_MIN)
        .max_size(most)
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
            if let Some(s) = &mut state.student {
                s.follow(&state.doc.scene);
            }
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
                &mut state.student,
            );
        });
    if !presenting && !state.compare.open {
        state.ui.layout.calculation_open = open;
    }
}
