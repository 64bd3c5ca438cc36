//! The class's causes counted as a bar chart (`report.png` beside `phonglab check folder
//! --report report.md`), painted as the window paints: a row a cause, its words right-aligned
//! against its bar and wrapped onto more lines rather than cut, the picture as tall as its
//! rows.

use egui::{Align, Color32, Rect, Sense, TextStyle, Ui, pos2, vec2};

use crate::t;

/// The picture's width, points.
const WIDTH: f32 = 900.0;
/// The widest a cause's words may be before they wrap, points.
const LABEL_WIDTH: f32 = 460.0;
/// The gap between the words and their bar, points.
const GAP: f32 = 12.0;
/// The longest bar (the commonest cause), points.
const BAR_WIDTH: f32 = 320.0;
/// A bar's height, points.
const BAR_HEIGHT: f32 = 18.0;
/// The space under the last row, points.
const MARGIN: f32 = 12.0;

/// Where one row went: its words (the text's rect) and whether any of them were cut, and
/// its bar.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChartRow {
    /// The painted words' rect.
    pub label: Rect,
    /// Whether the words were cut (never: they wrap).
    pub cut: bool,
    /// The bar's rect.
    pub bar: Rect,
}

/// The chart painted: its size in pixels, its pixels (RGBA8) and where each row went.
pub struct Chart {
    /// Width, pixels.
    pub width: usize,
    /// Height, pixels.
    pub height: usize,
    /// The pixels, RGBA8.
    pub rgba: Vec<u8>,
    /// A row a cause, in the order given.
    pub rows: Vec<ChartRow>,
}

/// The causes `counts` (words, how many works) of `total` works, painted as a chart as tall
/// as its rows: laid out once on a tall page to measure them, then painted to that height.
pub fn chart(counts: &[(String, usize)], total: usize) -> Chart {
    let tall = 80.0 + 80.0 * counts.len().max(1) as f32;
    let mut bottom = 0.0f32;
    crate::paint::egui_cpu::paint_ui(WIDTH, tall, 1.0, |ui| {
        egui::CentralPanel::default().show(ui, |ui| {
            chart_ui(ui, counts, total);
            // (Where the next row would go: the panel's own rect fills the page.)
            bottom = ui.cursor().top();
        });
    });
    let height = (bottom + MARGIN).ceil();
    let mut rows = Vec::new();
    let canvas = crate::paint::egui_cpu::paint_ui(WIDTH, height, 1.0, |ui| {
        egui::CentralPanel::default().show(ui, |ui| rows = chart_ui(ui, counts, total));
    });
    Chart { width: canvas.width, height: canvas.height, rgba: canvas.rgba8(), rows }
}

/// The title, then a row a cause: its words right-aligned against its bar (wrapped at
/// [`LABEL_WIDTH`]), the bar, the count.
fn chart_ui(ui: &mut Ui, counts: &[(String, usize)], total: usize) -> Vec<ChartRow> {
    ui.strong(t!("check-chart-title", count = total));
    let most = counts.iter().map(|c| c.1).max().unwrap_or(1).max(1) as f32;
    let font = TextStyle::Body.resolve(ui.style());
    let ink = ui.visuals().text_color();
    let mut rows = Vec::new();
    for (words, n) in counts {
        let mut job = egui::text::LayoutJob::simple(words.clone(), font.clone(), ink, LABEL_WIDTH);
        job.halign = Align::RIGHT;
        let galley = ui.painter().layout_job(job);
        let height = galley.rect.height().max(BAR_HEIGHT + 2.0);
        let (row, _) = ui.allocate_exact_size(vec2(ui.available_width(), height), Sense::hover());
        let right = row.left() + LABEL_WIDTH;
        let label = galley.rect.translate(vec2(right, row.center().y - galley.rect.height() / 2.0));
        let bar_left = right + GAP;
        let bar = Rect::from_min_size(
            pos2(bar_left, row.center().y - BAR_HEIGHT / 2.0),
            vec2((BAR_WIDTH * *n as f32 / most).max(2.0), BAR_HEIGHT),
        );
        let cut = galley.elided;
        // (Right-aligned, the galley's rect ends at x = 0: painted from the right edge.)
        ui.painter().galley(pos2(right, label.top()), galley, ink);
        ui.painter().rect_filled(bar, 2.0, Color32::from_rgb(70, 130, 200));
        let count = pos2(bar.right() + GAP / 2.0, row.center().y);
        ui.painter().text(count, egui::Align2::LEFT_CENTER, n.to_string(), font.clone(), ink);
        rows.push(ChartRow { label, cut, bar });
    }
    rows
}
