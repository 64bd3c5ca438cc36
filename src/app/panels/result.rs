//! The lit colour: a large swatch and the rgba numbers, clamped and unclamped.

use egui::{Color32, RichText, Ui};

use crate::app::editing::evaluated::{Evaluated, SideColors};
use crate::app::editing::message::Message;
use crate::app::widgets::palette::{self, gl_to_color32};
use crate::t;

fn fmt4(c: &[f64; 4], digits: usize) -> String {
    let s: Vec<String> = c.iter().map(|x| crate::locale::num(*x, digits)).collect();
    format!("[{}]", s.join("  "))
}

/// The significant digits the rows of numbers are written with: 8 (as the worked
/// calculation), or fewer where the centre is too narrow for them (the calculation keeps
/// all 8): a row is never cut.
const DIGITS: [usize; 3] = [8, 6, 4];

/// How bright a colour is to the eye, 0 to 1: its relative luminance (Rec. 709 weights,
/// on the clamped values).
pub fn luminance(c: &[f64; 4]) -> f64 {
    palette::linear_luminance([c[0], c[1], c[2]].map(|x| x.clamp(0.0, 1.0)))
}

/// Below this luminance the colour is called dark (a nearly black swatch beside a lit
/// object reads as a mistake unless it is said).
pub const DARK: f64 = 0.08;

/// The clamped colour in large type (two decimals), beside the title: read from the back
/// of the room, where the swatch alone (a dark one especially) says little.
fn large_value_ui(ui: &mut Ui, shown: &[f64; 4]) {
    let text: Vec<String> =
        shown[..3].iter().map(|x| crate::locale::decimal(&format!("{:.2}", x.clamp(0.0, 1.0)))).collect();
    let size = ui.text_style_height(&egui::TextStyle::Heading);
    ui.label(RichText::new(text.join("  ")).font(egui::FontId::monospace(size)).strong())
        .on_hover_text(t!("large-value-hover"));
}

fn side_ui(ui: &mut Ui, title: &str, c: &SideColors, separate: bool, dark: Option<Dark>) {
    // The widest row of numbers with `digits`, to choose how many fit and where the swatch goes.
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let rows = |digits: usize| {
        let mut v = vec![&c.primary, &c.shown];
        if separate {
            v.push(&c.secondary);
        }
        v.into_iter().map(|x| fmt4(x, digits)).collect::<Vec<_>>()
    };
    let width_of = |ui: &Ui, digits: usize| {
        rows(digits)
            .into_iter()
            .map(|t| ui.ctx().fonts_mut(|f| f.layout_no_wrap(t, font.clone(), Color32::WHITE).size().x))
            .fold(0.0, f32::max)
    };
    // The rows' names (small), as wide as the widest.
    let small = egui::TextStyle::Small.resolve(ui.style());
    let names = [t!("unclamped"), t!("clamped"), t!("secondary")];
    let labels_w = names
        .iter()
        .map(|n| ui.ctx().fonts_mut(|f| f.layout_no_wrap(n.clone(), small.clone(), Color32::WHITE).size().x))
        .fold(0.0, f32::max)
        + 6.0
        + ui.spacing().item_spacing.x;
    // The swatch wide enough for its note in the small type.
    let note_w = dark.as_ref().map_or(0.0, |d| {
        ui.ctx().fonts_mut(|f| f.layout_no_wrap(d.short.clone(), small.clone(), Color32::WHITE).size().x)
    });
    let swatch_w = (note_w + 16.0).max(88.0);
    let avail = ui.available_width();
    let beside = |ui: &Ui, d: usize| avail >= swatch_w + 16.0 + labels_w + width_of(ui, d);
    let under = |ui: &Ui, d: usize| avail >= labels_w + width_of(ui, d);
    let (wide, digits) = match DIGITS.iter().find(|d| beside(ui, **d)) {
        Some(d) => (true, *d),
        None => (false, DIGITS.iter().copied().find(|d| under(ui, *d)).unwrap_or(4)),
    };
    let swatch = |ui: &mut Ui, size: egui::Vec2| {
        let (rect, resp) = ui.allocate_exact_size(size, egui::Sense::hover());
        let said = dark.as_ref().map_or_else(|| format!("{title} swatch"), |d| format!("{title} swatch: {}", d.said));
        resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::ColorWell, true, said.clone()));
        if let Some(d) = &dark {
            resp.on_hover_text(&d.said);
        }
        ui.painter().rect_filled(rect, 6.0, gl_to_color32([c.shown[0], c.shown[1], c.shown[2]]));
        ui.painter().rect_stroke(
            rect,
            6.0,
            egui::Stroke::new(1.0, ui.visuals().weak_text_color()),
            egui::StrokeKind::Outside,
        );
        // A dark colour says so on its swatch, in light ink (the whole sentence on hover).
        if let Some(d) = dark.as_ref().filter(|_| size.y >= 40.0) {
            let font = egui::FontId::proportional(ui.text_style_height(&egui::TextStyle::Small));
            let ink = Color32::from_gray(235);
            ui.painter().text(rect.center(), egui::Align2::CENTER_CENTER, &d.short, font, ink);
        }
    };
    let numbers = |ui: &mut Ui| {
        let texts = rows(digits);
        let hovers = [t!("unclamped-hover"), t!("clamped-hover"), t!("secondary-hover")];
        egui::Grid::new(format!("{title} numbers")).num_columns(2).spacing([6.0, 2.0]).show(ui, |ui| {
            for ((name, value), why) in names.iter().zip(texts).zip(hovers) {
                ui.small(name);
                ui.monospace(value).on_hover_text(why);
                ui.end_row();
            }
        });
    };
    if wide {
        ui.horizontal_top(|ui| {
            swatch(ui, egui::vec2(swatch_w, 64.0));
            ui.vertical(|ui| {
                // (No wider than the rows below, which fit.)
                ui.horizontal(|ui| {
                    ui.label(RichText::new(title).strong());
                    large_value_ui(ui, &c.shown);
                });
                numbers(ui);
            });
        });
    } else {
        // Narrow: the swatch beside the title, the rows (named) below it, unclamped first,
        // and a dark colour's note on a line of its own (its swatch is too small for it).
        ui.vertical(|ui| {
            ui.horizontal_wrapped(|ui| {
                swatch(ui, egui::vec2(40.0, 18.0));
                ui.label(RichText::new(title).strong());
                large_value_ui(ui, &c.shown);
            });
            if let Some(d) = &dark {
                ui.small(d.short.replace('\n', " ")).on_hover_text(&d.said);
            }
            numbers(ui);
        });
    }
}

/// The swatch(es) and numbers, and the last message; while a quiz hides the answers
/// (`hidden`), a line saying so in their place.
pub fn result_ui(ui: &mut Ui, eval: &Evaluated, separate_specular: bool, message: &Option<Message>, hidden: bool) {
    if hidden {
        ui.label(RichText::new(t!("vertex-colour")).strong());
        ui.label(t!("colour-hidden"));
        ui.small(t!("colour-hidden-teacher"));
        message_ui(ui, message);
        return;
    }
    ui.horizontal_wrapped(|ui| {
        side_ui(
            ui,
            &if eval.back.is_some() { t!("front-face") } else { t!("vertex-colour") },
            &eval.front,
            separate_specular,
            dark_note(eval, &eval.front),
        );
        if let Some(b) = &eval.back {
            ui.add_space(16.0);
            side_ui(ui, &t!("back-face"), b, separate_specular, dark_note(eval, b));
        }
    });
    message_ui(ui, message);
}

/// What a dark colour's swatch says: a short note on it, the whole sentence in its hover.
struct Dark {
    /// On the swatch: "dark vertex", then how bright and the light's angle.
    short: String,
    /// The sentence.
    said: String,
}

/// For a dark colour, saying so: how bright it is, and with one light the angle at which
/// the light meets the surface (past 90 degrees it does not light it).
fn dark_note(eval: &Evaluated, c: &SideColors) -> Option<Dark> {
    let y = luminance(&c.shown);
    if y >= DARK {
        return None;
    }
    let percent = format!("{:.0}", 100.0 * y);
    Some(match eval.lights.as_slice() {
        [one] => {
            let cos = eval.n.normalize_or_zero().dot(one.l.normalize_or_zero()).clamp(-1.0, 1.0);
            let angle = format!("{:.0}", cos.acos().to_degrees());
            Dark {
                short: format!("{}\n{percent}\u{a0}% · θ {angle}°", t!("dark-vertex-short")),
                said: t!("dark-vertex-angle", percent = percent, angle = angle),
            }
        }
        _ => Dark {
            short: format!("{}\n{percent}\u{a0}%", t!("dark-vertex-short")),
            said: t!("dark-vertex", percent = percent),
        },
    })
}

/// The last message, in two lines reserved for it whether there is one or not, so that
/// nothing below moves when one appears (a longer one is cut, and shown whole on hover).
fn message_ui(ui: &mut Ui, message: &Option<Message>) {
    let h = 2.0 * ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
    let w = ui.available_width();
    let (rect, _) = ui.allocate_exact_size(egui::vec2(w, h), egui::Sense::hover());
    let (text, color) = match message {
        Some(Message::Refused(m)) => (m, palette::ink(ui, palette::ERROR)),
        Some(Message::Info(m)) => (m, ui.visuals().text_color()),
        None => return,
    };
    let font = egui::TextStyle::Body.resolve(ui.style());
    let mut job = egui::text::LayoutJob::simple(text.clone(), font, color, rect.width());
    job.wrap.max_rows = 2;
    job.wrap.overflow_character = Some('…');
    ui.scope_builder(egui::UiBuilder::new().max_rect(rect), |ui| {
        ui.add(egui::Label::new(job)).on_hover_text(text);
    });
}
