//! The lit colour: a large swatch and the rgba numbers, clamped and unclamped.

use egui::{RichText, Ui};

use super::palette::{self, gl_to_color32};
use super::state::{Evaluated, Message, SideColors};

fn fmt4(c: &[f64; 4]) -> String {
    let s: Vec<String> = c.iter().map(|x| phonglab_core::explain::fmt_sig(*x, 8)).collect();
    format!("[{}]", s.join("  "))
}

fn side_ui(ui: &mut Ui, title: &str, c: &SideColors, separate: bool) {
    ui.vertical(|ui| {
        ui.label(RichText::new(title).strong());
        let (rect, _) = ui.allocate_exact_size(egui::vec2(160.0, 96.0), egui::Sense::hover());
        ui.painter().rect_filled(rect, 6.0, gl_to_color32([c.shown[0], c.shown[1], c.shown[2]]));
        ui.painter().rect_stroke(
            rect,
            6.0,
            egui::Stroke::new(1.0, ui.visuals().weak_text_color()),
            egui::StrokeKind::Outside,
        );
        egui::Grid::new(format!("{title} numbers")).num_columns(2).show(ui, |ui| {
            ui.label("rgba (unclamped)");
            ui.monospace(fmt4(&c.primary)).on_hover_text("The primary colour as the equation gives it.");
            ui.end_row();
            ui.label("rgba (clamped)");
            ui.monospace(fmt4(&c.shown))
                .on_hover_text("Primary + secondary rgb, clamped to [0, 1]: what a fragment gets.");
            ui.end_row();
            if separate {
                ui.label("secondary");
                ui.monospace(fmt4(&c.secondary));
                ui.end_row();
            }
        });
    });
}

/// The swatch(es) and numbers, and the last message.
pub fn result_ui(ui: &mut Ui, eval: &Evaluated, separate_specular: bool, message: &Option<Message>) {
    ui.horizontal(|ui| {
        side_ui(ui, if eval.back.is_some() { "Front face" } else { "Vertex colour" }, &eval.front, separate_specular);
        if let Some(b) = &eval.back {
            ui.add_space(16.0);
            side_ui(ui, "Back face", b, separate_specular);
        }
    });
    match message {
        Some(Message::Refused(m)) => {
            ui.colored_label(palette::ERROR, m);
        }
        Some(Message::Info(m)) => {
            ui.label(m);
        }
        None => {}
    }
}
