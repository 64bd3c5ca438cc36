//! The explorer window: controls on the left, the worked calculation on the right, the
//! colour and the vector plot in the middle. `app_ui` draws everything from an
//! [`AppState`] and takes `&mut egui::Ui`, so tests drive it headless.

pub mod calculation;
pub mod compare;
pub mod controls;
pub mod cost;
pub mod evaluated;
pub mod files;
pub mod gpu_view;
pub mod help;
pub mod layout;
pub mod lobe;
pub mod palette;
pub mod persist;
pub mod quiz;
pub mod result;
pub mod shaded;
pub mod shader_panel;
pub mod state;
pub mod vector_plot;
pub mod view_cache;
pub mod widgets;

use egui::Ui;
use phonglab_core::{CameraSpec, NormalMode, RuleSet, SpecularModel, materials};

pub use state::AppState;
use state::{Message, Precision};

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
        A::Open => return files::open_typed(state),
        A::Save => return files::save_typed(state),
        A::Precision => {
            state.ui.precision = match state.ui.precision {
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
        let present = if layout.presenting { "Leave presentation (F5)" } else { "Present (F5)" };
        if ui
            .selectable_label(layout.presenting, present)
            .on_hover_text("Large type; the controls in a drawer")
            .clicked()
        {
            layout.presenting = !layout.presenting;
        }
        if layout.presenting {
            ui.toggle_value(&mut layout.drawer_open, "Controls drawer");
        } else {
            ui.toggle_value(&mut layout.controls_open, "Controls");
            ui.toggle_value(&mut layout.calculation_open, "Calculation");
        }
        if ui.button(layout.theme.toggled().label()).on_hover_text("Both themes are high-contrast").clicked() {
            layout.theme = layout.theme.toggled();
        }
        ui.separator();
        if ui.button("Reset to worksheet").on_hover_text("Ctrl+R").clicked() {
            state.reset_to_worksheet();
        }
        ui.menu_button("Presets", |ui| presets_menu_ui(ui, state));
        ui.toggle_value(&mut state.compare.open, "Compare")
            .on_hover_text("Pin the scene as A, change anything, and see A and B side by side");
        if ui
            .toggle_value(&mut state.quiz.open, "Quiz")
            .on_hover_text("Every value of the calculation behind a field: type them step by step")
            .clicked()
            && state.quiz.open
            && state.quiz.doc.is_none()
        {
            state.quiz.start(state.doc.clone());
        }
        if state.ui.layout.presenting {
            ui.label(egui::RichText::new(&state.doc.name).weak());
            return;
        }
        ui.separator();
        ui.label("Precision:");
        ui.radio_value(&mut state.ui.precision, Precision::F32, "f32");
        ui.radio_value(&mut state.ui.precision, Precision::F64, "f64");
        egui::ComboBox::from_label("pow").selected_text(state.ui.pow.label()).show_ui(ui, |ui| {
            for p in phonglab_core::PowFn::ALL {
                ui.selectable_value(&mut state.ui.pow, p, p.label());
            }
        });
        ui.separator();
        ui.toggle_value(&mut state.cost.open, "Cost of accuracy")
            .on_hover_text("What each shading, tessellation and approximation costs in time and in error");
        ui.toggle_value(&mut state.shader.open, "Shader")
            .on_hover_text("The GLSL or WGSL program this scene compiles to: only the stages it needs");
        ui.separator();
        files::file_ui(ui, state);
        ui.separator();
        if ui.button("Help (F1)").clicked() {
            state.ui.show_help = !state.ui.show_help;
        }
        ui.label(egui::RichText::new(&state.doc.name).weak());
    });
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
    let files = crate::scenes::scene_files();
    let mut entry = |ui: &mut Ui, f: &crate::scenes::SceneFile| {
        ui.horizontal(|ui| {
            swatch_ui(ui, &f.doc);
            if ui.button(&f.title).on_hover_text(format!("assets/scenes/{}", f.path)).clicked() {
                state.load(f.doc.clone(), &f.title);
                ui.close();
            }
        });
    };
    let mut group = "";
    for f in files.iter().filter(|f| f.group != "Red Book teapots") {
        if f.group != group {
            if !group.is_empty() {
                ui.separator();
            }
            ui.label(egui::RichText::new(f.group).small().strong());
            group = f.group;
        }
        entry(ui, f);
    }
    ui.separator();
    ui.menu_button("Red Book teapots", |ui| {
        egui::ScrollArea::vertical().max_height(480.0).show(ui, |ui| {
            for f in files.iter().filter(|f| f.group == "Red Book teapots") {
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
    let ctx = ui.ctx().clone();
    let visuals = state.ui.layout.theme.visuals();
    if ctx.global_style().visuals != visuals {
        ctx.set_visuals(visuals.clone());
    }
    *ui.visuals_mut() = visuals;
    for a in help::pressed(&ctx) {
        apply_action(state, a);
    }
    files::dropped_files_ui(&ctx, state);

    let eval = match state.evaluate() {
        Ok(e) => e,
        Err(e) => {
            // The document is validated on every edit, so this is not expected; say so and
            // fall back to the worksheet rather than panic.
            state.message =
                Some(Message::Refused(format!("Could not evaluate the scene ({e}); back to the worksheet.")));
            state.doc = Default::default();
            match state.evaluate() {
                Ok(e) => e,
                Err(_) => return,
            }
        }
    };
    presentation_keys(&ctx, state, eval.explanation.steps.len());
    if state.ui.layout.presenting {
        layout::scale_text(ui.style_mut(), layout::PRESENTATION_TEXT_SCALE);
    }
    let width = ui.max_rect().width();

    egui::Panel::top("top bar").show(ui, |ui| top_bar_ui(ui, state));

    let controls = |ui: &mut Ui, state: &mut AppState| {
        // Sliders sized to the panel, so a narrow panel does not widen to fit them.
        ui.spacing_mut().slider_width = (ui.available_width() - 200.0).clamp(60.0, 160.0);
        egui::ScrollArea::vertical().auto_shrink(false).show(ui, |ui| {
            let mut candidate = state.doc.clone();
            controls::controls_ui(ui, &mut candidate, &mut state.ui);
            state.apply(candidate);
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

    // Compare lists the steps of A and B itself, in the calculation's place.
    let mut open = (state.ui.layout.calculation_open || presenting) && !state.compare.open;
    egui::Panel::right(if presenting { "calculation (presenting)" } else { "calculation" })
        .resizable(true)
        .default_size(layout::Layout::calculation_width(width) * if presenting { 1.25 } else { 1.0 })
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
            let key =
                phonglab_core::plan::Key::of(&state.doc.scene, phonglab_core::EvalOptions::with_pow(state.ui.pow));
            let program = key.program();
            let effects = key.effects_of(&program);
            let walk =
                calculation::Walk { step: state.ui.layout.step, scroll: std::mem::take(&mut state.ui.scroll_to_step) };
            calculation::calculation_ui(
                ui,
                &eval.explanation,
                &mut state.ui.side,
                two_sided,
                &effects,
                &program.stages,
                walk,
            );
        });
    if !presenting && !state.compare.open {
        state.ui.layout.calculation_open = open;
    }

    egui::CentralPanel::default().show(ui, |ui| centre_ui(ui, state, &eval));

    cost::cost_window_ui(&ctx, state);
    shader_panel::shader_window_ui(&ctx, &mut state.shader, &state.doc);
    if state.cost.poll() {
        ctx.request_repaint_after(std::time::Duration::from_millis(100));
    }

    if state.ui.show_help {
        let mut open = true;
        egui::Window::new("Keyboard shortcuts")
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .show(&ctx, help::help_ui);
        state.ui.show_help = open;
    }
}

/// The centre: the colour, then the shaded view with the vector plot (or the lobe) beside
/// it when the centre is wide, or below it when it is tall; with Compare on, A beside B.
fn centre_ui(ui: &mut Ui, state: &mut AppState, eval: &state::Evaluated) {
    if state.compare.open {
        let current =
            compare::Current { doc: &state.doc, precision: state.ui.precision, pow: state.ui.pow, side: state.ui.side };
        if let Some(m) = compare::compare_ui(ui, &mut state.compare, &current, eval) {
            state.message = Some(Message::Info(m));
        }
        return;
    }
    result::result_ui(ui, eval, state.doc.scene.light_model.separate_specular, &state.message);
    ui.separator();
    let beside = |ui: &mut Ui, state: &mut AppState| {
        ui.push_id("beside", |ui| {
            ui.horizontal(|ui| {
                ui.selectable_value(&mut state.ui.layout.beside, layout::Beside::Vectors, "Vectors at the vertex");
                ui.selectable_value(&mut state.ui.layout.beside, layout::Beside::Lobe, "Reflection lobe");
            });
            match state.ui.layout.beside {
                layout::Beside::Vectors => {
                    vector_plot::vector_plot_ui(ui, &mut state.ui.orbit, eval, state.doc.scene.rules.specular)
                }
                layout::Beside::Lobe => lobe::lobe_ui(ui, &state.doc.scene, eval),
            }
        });
    };
    let shaded = |ui: &mut Ui, state: &mut AppState| {
        ui.push_id("shaded", |ui| {
            let mut cache = std::mem::take(&mut state.shaded);
            shaded::shaded_ui(ui, state, &mut cache, eval);
            state.shaded = cache;
        });
    };
    let avail = ui.available_size();
    // Two pictures side by side (the corrected one, or the heat map) want the full width.
    let pair = state.cost.heat_map || shaded::corrected_document(&state.doc, &state.ui.demo_fixes).is_some();
    if avail.x >= 1.5 * avail.y && !pair {
        // Side by side: the shaded view takes the larger share.
        let w = (avail.x * 0.58).min(avail.y + 40.0);
        ui.horizontal_top(|ui| {
            let down = egui::Layout::top_down(egui::Align::Min);
            ui.allocate_ui_with_layout(egui::vec2(w, avail.y), down, |ui| shaded(ui, state));
            ui.separator();
            let rest = egui::vec2(ui.available_width(), avail.y);
            ui.allocate_ui_with_layout(rest, down, |ui| beside(ui, state));
        });
    } else {
        // Stacked: the shaded view on top, its image about 42 % of the window's height
        // where the centre allows (its controls take about 130 points above it).
        let window = ui.ctx().content_rect().height();
        let h = (0.42 * window + 130.0).min(avail.y - 120.0);
        ui.allocate_ui(egui::vec2(avail.x, h), |ui| shaded(ui, state));
        ui.separator();
        beside(ui, state);
    }
}

/// The eframe application.
pub struct PhongLabApp {
    state: AppState,
}

impl PhongLabApp {
    /// Restores the last session's document when there is one and it loads; otherwise
    /// starts on the worksheet, saying why (`notice`: what was found before eframe started,
    /// see [`persist::set_aside_unreadable_storage`]).
    pub fn new(
        cc: &eframe::CreationContext<'_>,
        notice: Option<String>,
        file: Option<std::path::PathBuf>,
        renderer: gpu_view::RendererChoice,
    ) -> Self {
        let mut state = AppState::worksheet();
        // The shaded view can run the scene's generated WGSL on eframe's adapter.
        state.gpu = cc.wgpu_render_state.as_ref().map(gpu_view::install);
        state.ui.renderer = renderer;
        let text = cc.storage.and_then(|s| s.get_string(persist::DOCUMENT_KEY));
        state.ui.layout =
            layout::Layout::from_ron(cc.storage.and_then(|s| s.get_string(layout::LAYOUT_KEY)).as_deref());
        let dir = eframe::storage_dir(persist::APP_ID);
        match persist::restore_document(text.as_deref(), dir.as_deref()) {
            Ok(Some(doc)) => state.doc = doc,
            Ok(None) => {}
            Err(m) => state.message = Some(Message::Refused(m)),
        }
        if let Some(m) = notice {
            state.message = Some(Message::Refused(m));
        }
        // A file named on the command line wins over the restored session.
        if let Some(path) = file {
            files::open_at_start(&mut state, &path);
        }
        Self { state }
    }
}

impl eframe::App for PhongLabApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        app_ui(ui, &mut self.state);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        if let Ok(text) = self.state.doc.to_toml() {
            storage.set_string(persist::DOCUMENT_KEY, text);
        }
        storage.set_string(layout::LAYOUT_KEY, self.state.ui.layout.to_ron());
        if let Some(q) = self.state.quiz.to_ron() {
            storage.set_string(quiz::QUIZ_KEY, q);
        }
    }
}

/// Opens the window, on the scene file `file` when one is given, with the shaded view
/// drawn as `renderer` says.
pub fn run(file: Option<std::path::PathBuf>, renderer: gpu_view::RendererChoice) -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("phonglab")
            .with_inner_size([1440.0, 900.0])
            .with_min_inner_size([900.0, 600.0]),
        ..Default::default()
    };
    let notice = eframe::storage_dir(persist::APP_ID).and_then(|d| persist::set_aside_unreadable_storage(&d));
    eframe::run_native(
        persist::APP_ID,
        options,
        Box::new(|cc| Ok(Box::new(PhongLabApp::new(cc, notice, file, renderer)))),
    )
}
