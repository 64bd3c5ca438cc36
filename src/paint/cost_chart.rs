//! The cost study drawn: its chart (time across, error up, every point labelled), its table
//! and its lessons in words, for the window's Cost of accuracy and for `phonglab cost`'s
//! `cost.png`; and the colours its pictures are drawn with.

use egui::{Color32, Ui};
use egui_plot::{Legend, Line, LineStyle, MarkerShape, Plot, PlotPoint, PlotPoints, Points, Text};
use phonglab_core::Shading;
use phonglab_core::cost::{self, Question, Study};

use crate::{locale, t};

/// The background colour of the study's images (the shaded view's).
pub const BACKGROUND: [f32; 3] = [0.1, 0.1, 0.15];

/// The heat map's white point, in 1/255.
pub const HEAT_FULL_SCALE: f32 = 16.0;

/// Colours of the three shadings and of the other questions, in the chart and the table.
/// The series' colours: Okabe and Ito's, so colour-blind readers tell them apart, and none
/// of them the grey of the 8-bit floor.
fn series_color(q: Question, s: Shading) -> Color32 {
    match (q, s) {
        (Question::Shading, Shading::Flat) => Color32::from_rgb(0xE6, 0x9F, 0x00),
        (Question::Shading, Shading::Gouraud) => Color32::from_rgb(0x00, 0x72, 0xB2),
        (Question::Shading, Shading::Phong) => Color32::from_rgb(0x00, 0x9E, 0x73),
        (Question::Precision, _) => Color32::from_rgb(0xCC, 0x79, 0xA7),
        (Question::Approximation, _) => Color32::from_rgb(0xD5, 0x5E, 0x00),
    }
}

/// Each approximation's marker, so the legend tells them apart without labels on the plot
/// (two approximations of nearly one cost and error used to print their names on top of
/// each other).
fn approximation_marker(k: usize) -> MarkerShape {
    [MarkerShape::Diamond, MarkerShape::Square, MarkerShape::Cross, MarkerShape::Up, MarkerShape::Down][k % 5]
}

/// `10^v` for a log-scale axis, with few digits, in the language's decimal mark.
fn pow10_label(v: f64) -> String {
    let x = 10f64.powf(v);
    let text = if x >= 10.0 {
        format!("{x:.0}")
    } else if x >= 1.0 {
        format!("{x:.1}")
    } else {
        format!("{x:.2}")
    };
    locale::decimal(&text)
}

/// The chart: ms per frame (median; the best of the rounds) across, mean error (1/255) up, both logarithmic; the
/// three shadings as lines through their tessellations, each point labelled with its
/// level; the approximations and Phong in f32 as labelled markers; the 8-bit floor dashed.
pub fn cost_chart_ui(ui: &mut Ui, study: &Study, height: f32) {
    let log = |x: f64| x.max(1e-3).log10();
    let xs: Vec<f64> = study.points.iter().map(|p| log(p.ms)).collect();
    let (x_min, x_max) = xs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(*x), b.max(*x)));
    // The floor in the text's own colour: no series is grey, so none is taken for it.
    let ui_text = ui.visuals().text_color();
    Plot::new(format!("cost chart {:?}", study.object))
        .height(height)
        .legend(Legend::default().position(egui_plot::Corner::LeftTop))
        .x_axis_label(t!("cost-axis-ms"))
        .y_axis_label(t!("cost-axis-error"))
        .x_axis_formatter(|m, _| pow10_label(m.value))
        .y_axis_formatter(|m, _| pow10_label(m.value))
        .allow_scroll(false)
        .show(ui, |p| {
            for shading in Shading::ALL {
                let pts: Vec<&cost::CostPoint> = study
                    .points
                    .iter()
                    .filter(|q| q.variant.question == Question::Shading && q.variant.shading == shading)
                    .collect();
                let xy: Vec<[f64; 2]> = pts.iter().map(|q| [log(q.ms), log(q.error.mean)]).collect();
                let c = series_color(Question::Shading, shading);
                p.line(Line::new(shading.label(), PlotPoints::from(xy.clone())).color(c).width(2.0));
                p.points(Points::new(shading.label(), PlotPoints::from(xy.clone())).color(c).radius(4.0));
                for (q, at) in pts.iter().zip(&xy) {
                    p.text(
                        Text::new(shading.label(), PlotPoint::new(at[0], at[1]), format!(" {}", q.variant.level))
                            .color(c)
                            .anchor(egui::Align2::LEFT_BOTTOM),
                    );
                }
            }
            for (k, q) in study.points.iter().filter(|q| q.variant.question != Question::Shading).enumerate() {
                let c = series_color(q.variant.question, q.variant.shading);
                let at = [log(q.ms), log(q.error.mean)];
                let shape = match q.variant.question {
                    Question::Precision => MarkerShape::Asterisk,
                    _ => approximation_marker(k),
                };
                // Named in the legend (outside the data, below the plot), not on the plot.
                let name = q.variant.name();
                p.points(Points::new(name, PlotPoints::from(vec![at])).color(c).radius(6.0).shape(shape).filled(true));
            }
            // 8-bit rounding alone leaves a mean error of about 1/4 of a step.
            let floor = log(0.25);
            p.line(
                Line::new(t!("cost-rounding"), PlotPoints::from(vec![[x_min - 0.1, floor], [x_max + 0.3, floor]]))
                    .color(ui_text)
                    .style(LineStyle::dashed_loose()),
            );
        });
}

/// The table under the chart.
pub fn cost_table_ui(ui: &mut Ui, study: &Study) {
    egui::Grid::new(format!("cost table {:?}", study.object)).striped(true).num_columns(6).show(ui, |ui| {
        for h in
            [t!("cost-variant"), t!("cost-triangles"), t!("cost-ms"), t!("cost-mean"), t!("cost-max"), "> 1/255".into()]
        {
            ui.strong(h);
        }
        ui.end_row();
        for p in &study.points {
            ui.colored_label(series_color(p.variant.question, p.variant.shading), p.variant.name());
            ui.monospace(p.triangles.to_string());
            ui.monospace(locale::decimal(&format!("{:.2}", p.ms)));
            ui.monospace(locale::decimal(&format!("{:.2}", p.error.mean)));
            ui.monospace(locale::decimal(&format!("{:.1}", p.error.max)));
            ui.monospace(locale::percent(p.error.share_over_one, 1));
            ui.end_row();
        }
    });
}

/// The lessons the numbers support, in words.
pub fn takeaways(study: &Study) -> Vec<String> {
    let mut out = Vec::new();
    let good = |q: &&cost::CostPoint| q.variant.question == Question::Shading && q.error.share_over_one < 0.01;
    if let Some(best) = study.points.iter().filter(good).min_by(|a, b| a.ms.total_cmp(&b.ms)) {
        out.push(t!(
            "cost-cheapest",
            variant = best.variant.name(),
            triangles = best.triangles,
            ms = locale::decimal(&format!("{:.2}", best.ms))
        ));
    } else {
        out.push(t!("cost-none-within"));
    }
    let p = &study.precision;
    out.push(t!(
        "cost-precision",
        vertices = p.vertices,
        apart = locale::decimal(&format!("{:.1e}", p.max_error)),
        shown = locale::decimal(&format!("{:.4}", p.max_error_shown_255)),
        f32 = format!("{:.0}", p.general_f32_ns),
        f64 = format!("{:.0}", p.general_f64_ns),
        specialised = format!("{:.0}", p.specialised_f32_ns)
    ));
    out
}
