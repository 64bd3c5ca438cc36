//! The pixel probe's window: why the pixel under the pointer (or the one clicked) is the
//! colour it is, as `phonglab probe` reports it, line by line under the worksheet's names.
//! The shaded view finds the pixel and fills [`ProbeState`]; this draws it.

use egui::{Context, RichText};
use phonglab_core::probe_report::ReportLine;

use crate::t;

/// The probe's switch, the pixel it shows and its report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ProbeState {
    /// The probe follows the pointer over the picture (and its window is open).
    pub on: bool,
    /// The pixel shown (x, y from the top-left of the picture's pixels) and the picture's
    /// side in pixels.
    pub at: Option<([usize; 2], usize)>,
    /// A click pinned it: the pointer no longer moves it.
    pub pinned: bool,
    /// What the report was made for: the pixel, the picture's side and the picture's
    /// generation (a new picture is probed again).
    pub made_for: Option<([usize; 2], usize, u64)>,
    /// The report; empty where the pixel shows the background.
    pub lines: Vec<ReportLine>,
}

impl ProbeState {
    /// Does the report need making again for the picture `generation`?
    pub fn stale(&self, generation: u64) -> bool {
        match self.at {
            Some((p, px)) => self.made_for != Some((p, px, generation)),
            None => false,
        }
    }
}

/// What the probe's window asks: a mesh vertex whose worked calculation to open.
#[derive(Debug, Default, PartialEq)]
pub struct ProbeAsked {
    /// Open this vertex's calculation.
    pub vertex: Option<usize>,
}

/// The probe's window, while the probe is on.
pub fn probe_window_ui(ctx: &Context, probe: &mut ProbeState) -> ProbeAsked {
    let mut asked = ProbeAsked::default();
    if !probe.on {
        return asked;
    }
    let mut open = true;
    // At the right, over the worked calculation, clear of the picture.
    let screen = ctx.content_rect();
    let width = (screen.width() * 0.42).clamp(320.0, 560.0);
    egui::Window::new(t!("probe-window"))
        .open(&mut open)
        .default_pos(egui::pos2(screen.right() - width - 16.0, screen.top() + 40.0))
        .default_width(width)
        .max_width(width.max(screen.width() * 0.5))
        .resizable(true)
        .show(ctx, |ui| {
            ui.small(crate::locale::tr(if probe.pinned { "probe-pinned" } else { "probe-follows" }));
            if probe.pinned && ui.button(t!("probe-unpin")).clicked() {
                probe.pinned = false;
            }
            ui.separator();
            match (probe.at, probe.lines.is_empty()) {
                (None, _) => {
                    ui.label(t!("probe-hover-the-picture"));
                }
                (Some(([x, y], _)), true) => {
                    ui.label(t!("probe-uncovered", x = x as i64, y = y as i64));
                }
                (Some(_), false) => {
                    egui::ScrollArea::vertical().max_height(ui.ctx().content_rect().height() * 0.6).show(ui, |ui| {
                        report_ui(ui, &probe.lines, &mut asked);
                    });
                }
            }
        });
    if !open {
        probe.on = false;
    }
    asked
}

/// The report: a line without a value is a heading, wrapped across the window; the lines
/// under it a grid of two columns, the label with the worksheet's name, and the value. A
/// vertex's line opens its calculation.
fn report_ui(ui: &mut egui::Ui, lines: &[ReportLine], asked: &mut ProbeAsked) {
    let mut rest = lines;
    let mut grid = 0;
    while let Some(first) = rest.first() {
        if first.value.is_empty() {
            let text = RichText::new(&first.label);
            ui.label(if first.depth == 0 { text.strong() } else { text });
            rest = &rest[1..];
            continue;
        }
        let n = rest.iter().position(|l| l.value.is_empty()).unwrap_or(rest.len());
        egui::Grid::new(("probe-report", grid)).num_columns(2).striped(true).show(ui, |ui| {
            for l in &rest[..n] {
                line_ui(ui, l, asked);
                ui.end_row();
            }
        });
        (rest, grid) = (&rest[n..], grid + 1);
    }
}

/// One line of the report: its label (a link for a vertex) and name, then its value.
fn line_ui(ui: &mut egui::Ui, l: &ReportLine, asked: &mut ProbeAsked) {
    ui.horizontal(|ui| {
        ui.add_space(12.0 * l.depth as f32);
        let text = if l.depth == 0 { RichText::new(&l.label).strong() } else { RichText::new(&l.label) };
        match l.vertex {
            Some(v) => {
                if ui.link(text).on_hover_text(t!("probe-open-vertex", vertex = v as i64)).clicked() {
                    asked.vertex = Some(v);
                }
            }
            None => {
                ui.label(text);
            }
        }
        if !l.name.is_empty() {
            ui.label(RichText::new(&l.name).monospace().small().weak());
        }
    });
    ui.label(RichText::new(&l.value).monospace());
}
