//! The one number field: every number the user types goes through it.
//!
//! - At rest it shows the value to 6 significant digits (the exact value on hover), and
//!   dragging it changes the value.
//! - Clicked (or reached with Tab) it holds the exact value as text, all of it selected.
//! - What is typed is read only when the field is left: Enter, Tab or a click elsewhere.
//!   Never per keystroke, so `1e400` is read as `1e400`, not as 1, then 1e4...
//! - It reads a decimal point or a decimal comma (`0.5`, `0,5`, `1,5e-3`;
//!   [`phonglab_core::typed_number::parse_number`]).
//! - A refused text (not a number, beyond single precision, a whole number expected, or a
//!   value the scene's validator refuses) stays in the field, in red, with the reason beside
//!   it, until it is corrected or Esc puts the value back.

use egui::{Color32, Id, Key, Response, Sense, TextEdit, Ui, WidgetInfo};
use phonglab_core::explain::fmt_sig;
use phonglab_core::typed_number::parse_number;

use crate::app::widgets::palette;

/// How many significant digits a field shows at rest.
pub const SHOWN_DIGITS: usize = 6;

/// What a field accepts besides any finite number single precision holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Accepts {
    /// Any such number (the scene's validator may still refuse it).
    Any,
    /// A whole number in `min..=max`.
    Whole {
        /// The smallest allowed.
        min: i64,
        /// The largest allowed.
        max: i64,
    },
}

/// What a field keeps between frames: the text being edited, or refused.
#[derive(Clone, Debug, Default)]
struct Draft {
    text: String,
    /// The field had the keyboard last frame.
    editing: bool,
    /// Why the text was refused (shown beside the field).
    refused: Option<String>,
}

/// The last number committed by any field: when the scene's validator refuses the edit it
/// made, the field shows the refusal ([`refuse_last_commit`]).
#[derive(Clone, Debug)]
struct LastCommit {
    field: Id,
    text: String,
}

fn last_commit_id() -> Id {
    Id::unique("phonglab number field: last commit")
}

/// The text a value shows at rest: 6 significant digits.
pub fn shown_text(v: f64) -> String {
    crate::locale::decimal(&fmt_sig(v, SHOWN_DIGITS))
}

/// A number as the shortest decimal that reads back as the same `f64` (exponent form
/// outside [1e-4, 1e15)): what a field holds while it is edited, so a field that is only
/// clicked and left keeps its value exactly.
pub fn exact_text(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e15).contains(&a) { format!("{v:e}") } else { format!("{v}") }
}

/// Reads what was typed in a field that accepts `accepts`, or says why not.
pub fn read(text: &str, accepts: Accepts) -> Result<f64, String> {
    let x = parse_number(text).map_err(|e| e.to_string())?;
    match accepts {
        Accepts::Any => Ok(x),
        Accepts::Whole { min, max } => {
            if x.fract() != 0.0 {
                Err(crate::t!("not-whole", text = text.trim()))
            } else if x < min as f64 || x > max as f64 {
                Err(crate::t!("outside-range", text = text.trim(), min = min.to_string(), max = max.to_string()))
            } else {
                Ok(x)
            }
        }
    }
}

/// What a field did this frame.
pub struct Shown {
    /// `changed()` when the value changed (a committed text or a drag).
    pub response: Response,
    /// A whole row was typed into it.
    pub row: Option<Vec<f64>>,
    /// Why its text is refused, to show after the row.
    pub refused: Option<String>,
}

/// Why a field's text was refused, in red, on a row of its own.
pub fn refusal_ui(ui: &mut Ui, why: &str) {
    let red = palette::ink(ui, palette::ERROR);
    ui.colored_label(red, why);
}

/// What was typed in one of a row's fields.
#[derive(Clone, Debug, PartialEq)]
pub enum Typed {
    /// One number, for this field.
    One(f64),
    /// A number for every field of the row.
    Row(Vec<f64>),
}

/// Reads what was typed in one of a row of `n` fields: one number, or `n` of them
/// separated by semicolons, spaces or commas
/// ([`phonglab_core::typed_number::parse_numbers`]).
pub fn read_row(text: &str, accepts: Accepts, n: usize) -> Result<Typed, String> {
    use phonglab_core::typed_number::parse_numbers;
    let parts = parse_numbers(text).map_err(|e| e.to_string())?;
    match parts.len() {
        0 | 1 => read(text, accepts).map(Typed::One),
        k if k == n => {
            let text_of = |x: &f64| exact_text(*x);
            parts.iter().map(|x| read(&text_of(x), accepts)).collect::<Result<Vec<_>, _>>().map(Typed::Row)
        }
        k if n == 1 => Err(crate::t!("numbers-type-one", count = k)),
        k => Err(crate::t!("numbers-type-row", count = k, fields = n)),
    }
}

/// A number field for `value`, named `name` for assistive technology (and tests).
pub struct NumberField<'a> {
    value: &'a mut f64,
    name: String,
    speed: f64,
    accepts: Accepts,
    width: f32,
}

impl<'a> NumberField<'a> {
    /// A field that accepts any number, dragged at 0.01 a point, 64 points wide.
    pub fn new(value: &'a mut f64, name: impl Into<String>) -> Self {
        Self { value, name: name.into(), speed: 0.01, accepts: Accepts::Any, width: 64.0 }
    }

    /// How much a point of dragging changes the value.
    pub fn speed(mut self, speed: f64) -> Self {
        self.speed = speed;
        self
    }

    /// What it accepts.
    pub fn accepts(mut self, accepts: Accepts) -> Self {
        self.accepts = accepts;
        self
    }

    /// Its width in points.
    pub fn width(mut self, width: f32) -> Self {
        self.width = width;
        self
    }

    /// Draws the field (and the reason, when its text was refused); the response is
    /// `changed()` when the value changed: a committed text or a drag.
    pub fn show_ui(self, ui: &mut Ui) -> Response {
        let shown = self.show_in_row_ui(ui, 1);
        if let Some(why) = &shown.refused {
            refusal_ui(ui, why);
        }
        shown.response
    }

    /// The field alone, for one of a row of `n` components (a vector, a colour, a matrix
    /// row, or `n` = 1 with a label after it): `n` numbers typed into any of them
    /// (`0,5; 0,3; 0,1` or `0.5, 0.3, 0.1`) are returned for the whole row, which the
    /// caller sets; the caller shows the reason of a refusal ([`refusal_ui`]) after the row.
    pub fn show_in_row_ui(self, ui: &mut Ui, n: usize) -> Shown {
        let NumberField { value, name, speed, accepts, width } = self;
        let mut row = None;
        let id = ui.make_persistent_id(("number field", &name));
        let mut draft: Option<Draft> = ui.data(|d| d.get_temp(id));
        let editing = ui.memory(|m| m.has_focus(id));
        let escape = ui.input(|i| i.key_pressed(Key::Escape));
        if !editing && escape && ui.memory(|m| m.focused().is_none()) {
            draft = None;
        }
        let size = egui::vec2(width, ui.spacing().interact_size.y);
        let error = palette::ink(ui, palette::ERROR);
        let mut changed = false;
        // The field lost the keyboard to a click elsewhere, which egui reports the frame
        // after: what was typed is read now.
        if !editing && let Some(d) = draft.take_if(|d| d.editing) {
            draft = if escape { None } else { finish(ui, id, d, accepts, n, value, &mut row, &mut changed) };
        }
        let mut response = if editing {
            let mut d = draft
                .take()
                .unwrap_or_else(|| Draft { text: crate::locale::decimal(&exact_text(*value)), ..Draft::default() });
            let gained = !d.editing;
            d.editing = true;
            if gained {
                // Before the text edit reads its events: a key typed in this very frame
                // replaces the value, as it does in any number field.
                select_all(ui, id, &d.text);
            }
            let mut edit = TextEdit::singleline(&mut d.text).id(id).min_size(size).desired_width(width);
            if d.refused.is_some() {
                edit = edit.text_color(error);
            }
            let mut response = ui.add(edit);
            if response.changed() {
                // Typing is not a change of the value (only leaving the field is); the red
                // goes once the refused text is edited.
                d.refused = None;
                response.flags.remove(egui::response::Flags::CHANGED);
            }
            if response.lost_focus() {
                draft = if escape { None } else { finish(ui, id, d, accepts, n, value, &mut row, &mut changed) };
            } else {
                draft = Some(d);
            }
            response
        } else {
            rest_ui(ui, id, value, draft.as_ref(), width, error)
        };
        if !editing && draft.is_none() {
            if response.clicked() {
                ui.memory_mut(|m| m.request_focus(id));
            } else if response.dragged() {
                // The drag's exact position is kept apart from the value, which is rounded
                // to what the field shows: a slow drag still moves the last digit.
                let precise_id = id.with("drag");
                let start = if response.drag_started() { None } else { ui.data(|d| d.get_temp::<f64>(precise_id)) };
                let delta = response.drag_delta();
                let precise = start.unwrap_or(*value) + f64::from(delta.x - delta.y) * speed;
                ui.data_mut(|d| d.insert_temp(precise_id, precise));
                let moved = dragged(precise, accepts);
                if moved != *value {
                    *value = moved;
                    changed = true;
                }
            }
        } else if !editing && response.clicked() {
            ui.memory_mut(|m| m.request_focus(id));
        }
        match &draft {
            Some(d) => {
                ui.data_mut(|data| data.insert_temp(id, d.clone()));
            }
            None => ui.data_mut(|data| data.remove::<Draft>(id)),
        }
        let refused = draft
            .as_ref()
            .and_then(|d| d.refused.as_ref())
            .map(|why| crate::t!("refused-esc", why = why, value = shown_text(*value)));
        if changed {
            response.mark_changed();
        }
        let text = match &draft {
            Some(d) => d.text.clone(),
            None => shown_text(*value),
        };
        let v = *value;
        response.widget_info(|| WidgetInfo::drag_value(true, v));
        ui.ctx().accesskit_node_builder(id, |b| {
            b.clear_label();
            b.set_label(name.clone());
            b.set_value(text.clone());
        });
        Shown { response, row, refused }
    }
}

/// The field at rest: the value to 6 significant digits (or the refused text, in red, in
/// a red frame), in a button-like frame that can be clicked or dragged.
fn rest_ui(ui: &mut Ui, id: Id, value: &f64, draft: Option<&Draft>, width: f32, error: Color32) -> Response {
    let refused = draft.is_some_and(|d| d.refused.is_some());
    let text = match draft {
        Some(d) if refused => d.text.clone(),
        _ => shown_text(*value),
    };
    let galley = egui::WidgetText::from(text).into_galley(
        ui,
        Some(egui::TextWrapMode::Extend),
        f32::INFINITY,
        egui::TextStyle::Button,
    );
    let pad = ui.spacing().button_padding;
    let desired = egui::vec2(width.max(galley.size().x + 2.0 * pad.x), ui.spacing().interact_size.y);
    let (_, rect) = ui.allocate_space(desired);
    let mut response = ui.interact(rect, id, Sense::click_and_drag());
    if ui.is_rect_visible(rect) {
        let visuals = ui.style().interact(&response);
        let stroke = if refused { egui::Stroke::new(1.5, error) } else { visuals.bg_stroke };
        ui.painter().rect(
            rect.expand(visuals.expansion),
            visuals.corner_radius,
            visuals.weak_bg_fill,
            stroke,
            egui::StrokeKind::Inside,
        );
        let colour = if refused { error } else { visuals.text_color() };
        let at = egui::pos2(rect.min.x + pad.x, rect.center().y - galley.size().y / 2.0);
        ui.painter().galley(at, galley, colour);
    }
    response = response.on_hover_cursor(egui::CursorIcon::ResizeHorizontal);
    if !refused && shown_text(*value) != exact_text(*value) {
        response = response.on_hover_text(crate::locale::decimal(&exact_text(*value)));
    }
    response
}

/// Reads the text of a field that was left: the value (or the whole row) is set and the
/// draft goes, or the draft stays, refused, with the reason.
#[allow(clippy::too_many_arguments)]
fn finish(
    ui: &Ui,
    id: Id,
    d: Draft,
    accepts: Accepts,
    n: usize,
    value: &mut f64,
    row: &mut Option<Vec<f64>>,
    changed: &mut bool,
) -> Option<Draft> {
    let remember = || {
        let commit = LastCommit { field: id, text: d.text.trim().to_string() };
        ui.data_mut(|data| data.insert_temp(last_commit_id(), commit));
    };
    match read_row(&d.text, accepts, n) {
        Ok(Typed::Row(all)) => {
            remember();
            *row = Some(all);
            *changed = true;
            None
        }
        Ok(Typed::One(x)) => {
            if x.to_bits() != value.to_bits() {
                *value = x;
                *changed = true;
                remember();
            }
            None
        }
        Err(why) => Some(Draft { refused: Some(why), editing: false, ..d }),
    }
}

/// A dragged value, rounded to 6 significant digits (a drag has no more precision than
/// that), whole when the field takes whole numbers, and kept inside their range.
fn dragged(x: f64, accepts: Accepts) -> f64 {
    let rounded: f64 = fmt_sig(x, SHOWN_DIGITS).parse().unwrap_or(x);
    match accepts {
        Accepts::Any => rounded,
        Accepts::Whole { min, max } => rounded.round().clamp(min as f64, max as f64),
    }
}

fn select_all(ui: &Ui, id: Id, text: &str) {
    let mut state = TextEdit::load_state(ui.ctx(), id).unwrap_or_default();
    state.cursor.set_char_range(Some(egui::text::CCursorRange::select_all_str(text)));
    state.store(ui.ctx(), id);
}

/// The scene's validator refused the last edit: the field that made it (when a number
/// field did, this frame) shows the text again, in red, with `why`.
pub fn refuse_last_commit(ctx: &egui::Context, why: &str) {
    let Some(commit) = ctx.data_mut(|d| {
        let c = d.get_temp::<LastCommit>(last_commit_id());
        d.remove::<LastCommit>(last_commit_id());
        c
    }) else {
        return;
    };
    ctx.data_mut(|d| {
        d.insert_temp(commit.field, Draft { text: commit.text, refused: Some(why.to_string()), editing: false })
    });
}

/// Forgets the last commit (the edit it made was kept).
pub fn accept_last_commit(ctx: &egui::Context) {
    ctx.data_mut(|d| d.remove::<LastCommit>(last_commit_id()));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_text_reads_back_as_the_same_number() {
        for v in [0.0, -0.0, 0.2125, 121.76225070590814, 1e300, -1e-300, 5e-324, 1e15, 99999.5, 0.44721359549995804] {
            let t = exact_text(v);
            assert_eq!(t.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{v} -> {t}");
            assert!(t.len() <= 24, "{t}");
        }
        assert_eq!(exact_text(0.2125), "0.2125");
        assert_eq!(exact_text(1e300), "1e300");
        assert_eq!(exact_text(-665.1075), "-665.1075");
    }

    #[test]
    fn a_field_at_rest_shows_six_significant_digits() {
        assert_eq!(shown_text(0.44721359549995804), "0.447214");
        // -665.1075 is held as -665.10749999999996: it rounds down.
        assert_eq!(shown_text(-665.1075), "-665.107");
        assert_eq!(shown_text(-512.0), "-512");
        assert_eq!(shown_text(25.6), "25.6");
        assert_eq!(shown_text(1.5e-7), "1.5e-7");
    }

    #[test]
    fn typed_text_is_read_or_refused_with_a_reason() {
        assert_eq!(read("12,5", Accepts::Any), Ok(12.5));
        assert_eq!(read("1,5e-3", Accepts::Any), Ok(0.0015));
        assert_eq!(read(" -5 ", Accepts::Any), Ok(-5.0));
        assert!(read("1e400", Accepts::Any).unwrap_err().contains("single precision"));
        assert!(read("1e-400", Accepts::Any).unwrap_err().contains("would be 0"));
        assert!(read("abc", Accepts::Any).unwrap_err().contains("not a number"));
        assert!(read("NaN", Accepts::Any).unwrap_err().contains("not a finite number"));
        let slices = Accepts::Whole { min: 3, max: 256 };
        assert_eq!(read("12", slices), Ok(12.0));
        assert!(read("4,5", slices).unwrap_err().contains("not a whole number"));
        assert!(read("2", slices).unwrap_err().contains("outside 3 to 256"));
        assert_eq!(dragged(7.6, slices), 8.0);
        assert_eq!(dragged(1.0, slices), 3.0);
        assert_eq!(dragged(0.1 + 0.2, Accepts::Any), 0.3);
    }
}
