//! The top bar: presenting, the panels shown, the theme, reset, undo and redo, the presets,
//! Compare, the quiz, the shader, the precision and power, the cost study, the scene file's
//! row, Export, the language and help.

use egui::Ui;
use phonglab_core::t;

use super::state::{AppState, Precision};
use super::{files, layout};
use crate::app::panels::export;

/// The top bar's row (or rows, when it wraps).
pub fn top_bar_ui(ui: &mut Ui, state: &mut AppState) {
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
        export::export_menu_ui(
            ui,
            &mut state.export,
            &state.doc,
            state.settings.pow,
            &mut state.files,
            &mut state.chooser,
            &mut state.message,
        );
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
