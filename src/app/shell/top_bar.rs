//! The top bar: what a first-time user needs, and the rest one click away. The scene (its
//! menu of shipped scenes, and its name), the object and the shading, things to try, then
//! the File menu
//! (the scene file, export, undo and redo) and the View menu (the panels and windows, the
//! theme, the arithmetic), presenting, the language and help.

use egui::Ui;
use egui::containers::menu::{MenuButton, MenuConfig};
use phonglab_core::{ObjectKind, Shading};

use super::state::{AppState, Precision};
use super::{files, layout};
use crate::app::panels::export;
use crate::t;

/// The longest scene name shown whole beside the Scene menu (the rest in its hover).
const NAME_CHARS: usize = 32;

/// The top bar's row: one row at every window size, presenting and not, in every
/// language. Where its items do not fit at the mode's type size, the bar's own type is
/// made smaller until they do (down to [`SMALLEST_BAR_TEXT`] of it), rather than an item
/// giving way; the menus it opens keep the mode's size. Only past that does it wrap.
pub fn top_bar_ui(ui: &mut Ui, state: &mut AppState) {
    // Labels move to the next row whole rather than breaking across rows.
    ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
    let width = ui.available_width();
    // Narrower than 1150 points, the app's name gives way and the controls close up.
    let narrow = width < 1150.0;
    let full = if state.ui.layout.presenting { layout::PRESENTATION_TEXT_SCALE } else { 1.0 };
    let k = fitting_scale(ui, state, full, width, narrow);
    layout::set_text_scale(ui.style_mut(), k);
    ui.horizontal_wrapped(|ui| bar_row_ui(ui, state, narrow));
}

/// The least the bar's type is made, as a fraction of the mode's.
pub const SMALLEST_BAR_TEXT: f32 = 0.7;

/// The text scale at which the bar's row fits `width`: `full` where it does, else the one
/// found from the row's width measured at two scales (laid out unseen: the width is a
/// fixed part, paddings and gaps, and a part that grows with the type), then checked.
fn fitting_scale(ui: &mut Ui, state: &mut AppState, full: f32, width: f32, narrow: bool) -> f32 {
    // A little room at the row's end (the panel's margin is outside `width`).
    let room = width - 4.0;
    let at_full = row_width(ui, state, full, narrow);
    if at_full <= room {
        return full;
    }
    let low = full * SMALLEST_BAR_TEXT;
    let at_low = row_width(ui, state, low, narrow);
    if at_low >= room || at_full <= at_low {
        return low;
    }
    // w(k) = a + b k through the two measures.
    let b = (at_full - at_low) / (full - low);
    let mut k = (low + (room - at_low) / b).clamp(low, full);
    // Text does not scale quite linearly (glyphs snap to pixels): step down until it fits.
    for _ in 0..4 {
        if row_width(ui, state, k, narrow) <= room {
            break;
        }
        k = (k * 0.98).max(low);
    }
    k
}

/// The width of the bar's row at text scale `k`, laid out in an unseen child (no paint, no
/// input, nothing for screen readers).
fn row_width(ui: &mut Ui, state: &mut AppState, k: f32, narrow: bool) -> f32 {
    let builder = egui::UiBuilder::new()
        .id_salt(("top bar measured", k.to_bits()))
        .invisible()
        .sizing_pass()
        .layout(egui::Layout::left_to_right(egui::Align::Center));
    let mut child = ui.new_child(builder);
    layout::set_text_scale(child.style_mut(), k);
    bar_row_ui(&mut child, state, narrow);
    child.min_rect().width()
}

/// The bar's items, in order.
fn bar_row_ui(ui: &mut Ui, state: &mut AppState, narrow: bool) {
    // Presenting, in large type, the app's and the scene's names give way (the scene's is
    // in the Scene menu's hover); narrower than 1150 points, the app's name too.
    let presenting = state.ui.layout.presenting;
    // (Presenting in a narrow window, no separators either.)
    let separator = |ui: &mut Ui| {
        if !(presenting && narrow) {
            ui.separator();
        }
    };
    if presenting || narrow {
        ui.spacing_mut().item_spacing.x *= 0.5;
    } else {
        ui.strong("phonglab");
        ui.separator();
    }
    let name = phonglab_core::library::localised_name(&state.doc.name);
    let hover = if presenting { format!("{}\n{name}", t!("scene-menu-hover")) } else { t!("scene-menu-hover") };
    ui.menu_button(t!("scene-menu"), |ui| scene_menu_ui(ui, state)).response.on_hover_text(hover);
    if !presenting {
        scene_name_ui(ui, &name);
    }
    separator(ui);
    object_and_shading_ui(ui, state);
    separator(ui);
    if ui.selectable_label(state.things.open, t!("things-to-try")).on_hover_text(t!("things-to-try-hover")).clicked() {
        state.things.toggle();
    }
    // Menus that hold fields and switches stay open while they are used.
    let stay = MenuConfig::new().close_behavior(egui::PopupCloseBehavior::CloseOnClickOutside);
    MenuButton::new(t!("file-menu"))
        .config(stay.clone())
        .ui(ui, |ui| file_menu_ui(ui, state))
        .0
        .on_hover_text(t!("file-menu-hover"));
    MenuButton::new(t!("view-menu"))
        .config(stay)
        .ui(ui, |ui| view_menu_ui(ui, state))
        .0
        .on_hover_text(t!("view-menu-hover"));
    separator(ui);
    let layout = &mut state.ui.layout;
    let present = if layout.presenting { t!("leave-presenting") } else { t!("present") };
    if ui.selectable_label(layout.presenting, present).on_hover_text(t!("present-hover")).clicked() {
        layout.presenting = !layout.presenting;
    }
    if layout.presenting {
        // In front of a class the controls are a drawer, opened from here in one click
        // (named "Controls" where the bar is narrow).
        let name = if narrow { t!("controls") } else { t!("controls-drawer") };
        ui.toggle_value(&mut layout.drawer_open, name).on_hover_text(t!("controls-drawer-hover"));
    }
    language_menu_ui(ui, &mut state.ui.layout);
    if ui.selectable_label(state.ui.show_help, t!("help-button")).clicked() {
        state.ui.show_help = !state.ui.show_help;
    }
}

/// The scene's name (localised), cut to [`NAME_CHARS`] with the whole in its hover.
fn scene_name_ui(ui: &mut Ui, name: &str) {
    let shown: String = if name.chars().count() > NAME_CHARS {
        name.chars().take(NAME_CHARS - 1).chain(std::iter::once('…')).collect()
    } else {
        name.to_string()
    };
    ui.label(egui::RichText::new(shown).weak()).on_hover_text(name.to_string());
}

/// The object and the shading, each a row of choices (with its key in the hover): the
/// choices a class switches most, one click each.
fn object_and_shading_ui(ui: &mut Ui, state: &mut AppState) {
    let mut view = state.doc.view.clone();
    for (k, o) in [("s", ObjectKind::Sphere), ("t", ObjectKind::Teapot), ("c", ObjectKind::Cylinder)] {
        ui.selectable_value(&mut view.object, o, o.label()).on_hover_text(t!("key-hint", key = k));
    }
    let mut close = false;
    if let Some(path) = &view.obj {
        let tip = t!("mesh-tip", path = path);
        ui.selectable_value(&mut view.object, ObjectKind::Obj, ObjectKind::Obj.label()).on_hover_text(tip);
        // Kept through changes of scene until closed here.
        let x = ui.add(egui::Button::new("×").small().frame(false));
        x.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, t!("close-mesh")));
        close = x.on_hover_text(t!("close-mesh-hover")).clicked();
    }
    ui.separator();
    for (k, s) in [("1", Shading::Gouraud), ("2", Shading::Phong), ("3", Shading::Flat)] {
        ui.selectable_value(&mut view.shading, s, s.label()).on_hover_text(t!("key-hint", key = k));
    }
    if close {
        state.close_mesh();
    } else if view != state.doc.view {
        let mut c = state.doc.clone();
        c.view = view;
        state.apply(c);
    }
}

/// The Scene menu: back to the worksheet, then every shipped scene.
fn scene_menu_ui(ui: &mut Ui, state: &mut AppState) {
    if ui.button(t!("reset-worksheet")).on_hover_text("Ctrl+R").clicked() {
        state.reset_to_worksheet();
        ui.close();
    }
    ui.separator();
    presets_menu_ui(ui, state);
}

/// The File menu: the scene file's row, Export, Undo and Redo.
fn file_menu_ui(ui: &mut Ui, state: &mut AppState) {
    ui.horizontal(|ui| {
        if let Some(asked) = crate::app::panels::files::file_ui(ui, &mut state.files, &state.doc, &mut state.message) {
            files::carry_out(state, asked);
            ui.close();
        }
    });
    export::export_menu_ui(
        ui,
        &mut state.export,
        &state.doc,
        state.settings.pow,
        &mut state.files,
        &mut state.chooser,
        &mut state.message,
    );
    super::student::check_menu_ui(ui, state);
    ui.separator();
    if ui.button(t!("share-menu")).on_hover_text(t!("share-menu-hover")).clicked() {
        state.share.open_with(state.ui.layout.presenting);
        ui.close();
    }
    ui.separator();
    ui.horizontal(|ui| undo_buttons_ui(ui, state));
}

/// The View menu: the panels and windows, the theme, the precision and the power.
fn view_menu_ui(ui: &mut Ui, state: &mut AppState) {
    ui.label(egui::RichText::new(t!("panels-heading")).small().strong());
    let layout = &mut state.ui.layout;
    if !layout.presenting {
        // (Presenting, the controls drawer is the top bar's.)
        ui.checkbox(&mut layout.controls_open, t!("controls"));
        ui.checkbox(&mut layout.calculation_open, t!("calculation"));
    }
    let was_open = state.compare.open;
    ui.checkbox(&mut state.compare.open, t!("compare")).on_hover_text(t!("compare-hover"));
    if state.compare.open && !was_open && state.compare.a.is_none() {
        // Opened: A is the scene as it is, so the first change already compares.
        state.compare.pin(&state.doc, state.settings.precision, state.settings.pow);
    }
    if ui.checkbox(&mut state.quiz.open, t!("quiz")).on_hover_text(t!("quiz-hover")).clicked()
        && state.quiz.open
        && state.quiz.doc.is_none()
    {
        state.quiz.start(state.doc.clone());
    }
    ui.checkbox(&mut state.shader.open, t!("shader")).on_hover_text(t!("shader-hover"));
    ui.checkbox(&mut state.director.open, t!("director")).on_hover_text(t!("director-hover"));
    ui.checkbox(&mut state.cost.open, t!("cost-of-accuracy")).on_hover_text(t!("cost-hover"));
    ui.separator();
    let layout = &mut state.ui.layout;
    if ui.button(layout.theme.toggled().label()).on_hover_text(t!("theme-hover")).clicked() {
        layout.theme = layout.theme.toggled();
    }
    ui.separator();
    ui.label(egui::RichText::new(t!("arithmetic-heading")).small().strong());
    ui.horizontal(|ui| {
        ui.label(t!("precision"));
        ui.radio_value(&mut state.settings.precision, Precision::F32, "f32").on_hover_text(t!("f32-hover"));
        ui.radio_value(&mut state.settings.precision, Precision::F64, "f64").on_hover_text(t!("f64-hover"));
    });
    ui.menu_button(format!("pow: {}", state.settings.pow.label()), |ui| {
        for p in phonglab_core::PowFn::ALL {
            ui.radio_value(&mut state.settings.pow, p, p.label());
        }
    });
}

/// The language and decimal mark menu (kept across restarts).
fn language_menu_ui(ui: &mut Ui, layout: &mut layout::Layout) {
    use crate::locale::{DecimalMark, Lang};
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
    .on_hover_text(crate::t!("language-menu-hover"));
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
