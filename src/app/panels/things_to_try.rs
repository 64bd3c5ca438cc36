//! "Things to try": experiments a class runs in one click ([`crate::io::experiments`]).
//! Each sets up its scene, says what to look for, and asks a question whose answer is a
//! step of the worked calculation, shown on request from the calculation as it stands (so
//! after the class has moved a slider, the answer is the one for what they see).

use egui::Ui;
use phonglab_core::Document;
use phonglab_core::explain::{Explanation, fmt_value};

use crate::io::experiments::{self, Experiment};
use crate::locale::Lang;
use crate::t;

/// The window's state: open or not, the experiment chosen, whether its answer is shown,
/// and the teacher's own experiments (read when the window opens).
#[derive(Debug, Default)]
pub struct TryState {
    /// The window is open.
    pub open: bool,
    /// The experiment chosen: its place among the shipped experiments, then the own.
    pub chosen: Option<usize>,
    /// Its answer is shown.
    pub answer_shown: bool,
    /// The teacher's own experiments and the files that did not load (with why), read
    /// from [`crate::platform::storage::experiments_dir`] when the window opened.
    own: Option<(Vec<Experiment>, Vec<String>)>,
}

/// What the window asks the shell for.
#[derive(Debug)]
pub enum TryAsked {
    /// Load this experiment's scene, under its title; the label of the control its words
    /// tell the class to move (asked into view), if they name one.
    Load(Box<Document>, String, Option<String>),
    /// Highlight this step of the worked calculation (and scroll to it).
    Step(usize),
}

impl TryState {
    /// The teacher's own experiments and the files that did not load, read from their
    /// folder once per opening of the window.
    fn own(&mut self) -> &(Vec<Experiment>, Vec<String>) {
        self.own.get_or_insert_with(|| match crate::platform::storage::experiments_dir() {
            Some(dir) => experiments::in_folder(&dir),
            None => (Vec::new(), Vec::new()),
        })
    }

    /// Opens or closes the window; opening reads the teacher's folder again.
    pub fn toggle(&mut self) {
        self.open = !self.open;
        if self.open {
            self.own = None;
        }
    }
}

/// The step of `ex` that answers `e`'s question: its index and its printed value.
pub fn answer(e: &Experiment, ex: &Explanation) -> Option<(usize, String)> {
    let k = ex.steps.iter().position(|s| s.name == e.answer && (e.light.is_none() || s.light == e.light))?;
    let s = &ex.steps[k];
    let value = match &s.value {
        Some(v) => crate::locale::decimal(&fmt_value(v, 8)),
        None => t!("not-applicable"),
    };
    Some((k, format!("{} = {value}", s.name)))
}

/// The window: the experiments, the one chosen with what to look for, its question and,
/// on request, the calculation's answer; where a teacher's own go. It stays right of the
/// controls and under the top bar (`centre` is the space between the panels), so the
/// control an experiment tells the class to move is never under it, and opens over the
/// calculation's column, as wide as it (at least 300 points), leaving the picture, the
/// plot and the controls above them in sight.
pub fn things_to_try_window_ui(
    ctx: &egui::Context,
    state: &mut TryState,
    ex: &Explanation,
    lang: Lang,
    centre: egui::Rect,
) -> Option<TryAsked> {
    if !state.open {
        return None;
    }
    let mut open = true;
    let mut asked = None;
    let area = egui::Rect::from_min_max(centre.min, ctx.content_rect().max);
    let column = area.max.x - centre.max.x;
    let width = (column - 24.0).clamp(300.0, 420.0).min(area.width() - 16.0);
    egui::Window::new(t!("things-to-try"))
        .open(&mut open)
        .constrain_to(area)
        .pivot(egui::Align2::RIGHT_TOP)
        .default_pos(area.right_top() + egui::vec2(-8.0, 8.0))
        .default_width(width)
        .max_width(area.width())
        .max_height(area.height() * 0.9)
        .show(ctx, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| asked = contents_ui(ui, state, ex, lang));
        });
    state.open = open;
    asked
}

fn contents_ui(ui: &mut Ui, state: &mut TryState, ex: &Explanation, lang: Lang) -> Option<TryAsked> {
    state.own();
    let TryState { chosen, answer_shown, own, .. } = state;
    let (own, refused) = own.as_ref().expect("read just above");
    let mut asked = None;
    ui.small(t!("things-to-try-intro"));
    // The shipped experiments, then the teacher's own.
    for (k, e) in experiments::shipped().iter().chain(own).enumerate() {
        let words = e.words(lang);
        let is_chosen = *chosen == Some(k);
        if ui.selectable_label(is_chosen, format!("{}. {}", k + 1, words.title)).on_hover_text(&e.source).clicked() {
            *chosen = Some(k);
            *answer_shown = false;
            asked = Some(load(ui, e, lang));
        }
        if is_chosen {
            asked = chosen_ui(ui, answer_shown, e, ex, lang).or(asked);
        }
    }
    ui.separator();
    own_folder_ui(ui, refused);
    asked
}

/// What a click on `e` asks for: its scene under its title, and the control its words name
/// brought into view (the next time the controls draw it).
fn load(ui: &Ui, e: &Experiment, lang: Lang) -> TryAsked {
    let control = e.control_label();
    if let Some(label) = &control {
        crate::app::widgets::fields::bring_into_view(ui.ctx(), label);
    }
    TryAsked::Load(Box::new(e.doc.clone()), e.words(lang).title.clone(), control)
}

/// The experiment chosen: what to look for, the question, and the answer on request.
fn chosen_ui(ui: &mut Ui, shown: &mut bool, e: &Experiment, ex: &Explanation, lang: Lang) -> Option<TryAsked> {
    let words = e.words(lang);
    let mut asked = None;
    egui::Frame::group(ui.style()).show(ui, |ui| {
        ui.label(egui::RichText::new(t!("things-to-try-look")).small().strong());
        ui.label(&words.look);
        ui.label(egui::RichText::new(t!("things-to-try-question")).small().strong());
        ui.label(egui::RichText::new(&words.question).strong());
        match (*shown, answer(e, ex)) {
            (false, found) => {
                if ui.button(t!("things-to-try-show")).clicked() {
                    *shown = true;
                    asked = found.map(|(k, _)| TryAsked::Step(k));
                }
            }
            (true, Some((k, value))) => {
                let text = t!("things-to-try-answer", step = (k + 1).to_string(), value = value);
                ui.label(egui::RichText::new(text).monospace());
            }
            (true, None) => {
                ui.label(t!("things-to-try-no-step", step = e.answer.clone()));
            }
        }
    });
    asked
}

/// The shipped experiments offered in a band of the centre (under the picture and the plot):
/// a heading and as many as fit, whole rows only, each setting its experiment up and
/// opening the window on it. Nothing when not even the heading and one row fit.
pub fn suggestions_ui(ui: &mut Ui, state: &mut TryState, lang: Lang) -> Option<TryAsked> {
    let row = ui.spacing().interact_size.y + ui.spacing().item_spacing.y;
    let heading = ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
    let bottom = ui.max_rect().max.y;
    if ui.max_rect().height() < heading + row {
        return None;
    }
    ui.label(egui::RichText::new(t!("things-to-try-band")).strong());
    let mut asked = None;
    ui.horizontal_wrapped(|ui| {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        let right = ui.max_rect().max.x;
        for (k, e) in experiments::shipped().iter().enumerate() {
            // (Unnumbered: the window's list numbers them.)
            let title = e.words(lang).title.clone();
            let font = egui::TextStyle::Button.resolve(ui.style());
            let w = ui.fonts_mut(|f| f.layout_no_wrap(title.clone(), font, egui::Color32::WHITE).size().x)
                + 2.0 * ui.spacing().button_padding.x;
            // Where this button would stand: on this row, or the next; stop before a row
            // that does not fit whole.
            let top = if ui.cursor().min.x + w > right { ui.cursor().min.y + row } else { ui.cursor().min.y };
            if top + row > bottom + ui.spacing().item_spacing.y {
                break;
            }
            if ui.button(&title).on_hover_text(&e.words(lang).question).clicked() {
                state.open = true;
                state.chosen = Some(k);
                state.answer_shown = false;
                asked = Some(load(ui, e, lang));
            }
        }
    });
    asked
}

/// Where a teacher's own experiments go, and why any of theirs did not load.
fn own_folder_ui(ui: &mut Ui, refused: &[String]) {
    match crate::platform::storage::experiments_dir() {
        Some(dir) => {
            ui.small(t!("things-to-try-own", folder = dir.display().to_string()));
        }
        None => {
            ui.small(t!("things-to-try-own-none"));
        }
    }
    for why in refused {
        ui.small(egui::RichText::new(why).color(ui.visuals().warn_fg_color));
    }
}
