//! The Shader window: the GLSL or WGSL program the scene's plan compiles to
//! ([`phonglab_core::shader`]), coloured, with Copy. When an edit changes the program (a
//! spotlight switched on, the local viewer, attenuation back to (1, 0, 0)) the lines it
//! added are highlighted and the lines it removed are listed.

use egui::text::LayoutJob;
use egui::{Color32, FontId, RichText, TextFormat, Ui};
use phonglab_core::shader::{ShaderShading, ShadingLanguage, for_view};
use phonglab_core::{Document, Shading};

use crate::t;

/// The window's state.
#[derive(Clone, Debug, Default)]
pub struct ShaderState {
    /// The window is open.
    pub open: bool,
    /// WGSL rather than GLSL.
    pub wgsl: bool,
    /// The program last shown, and the one before it changed (for the diff).
    pub shown: String,
    /// Lines added by the last change.
    pub added: Vec<String>,
    /// Lines removed by the last change.
    pub removed: Vec<String>,
}

/// The lines of `new` not in `old` and of `old` not in `new`, by a longest common
/// subsequence of lines (programs are tens of lines).
pub fn line_diff(old: &str, new: &str) -> (Vec<String>, Vec<String>) {
    let (a, b): (Vec<&str>, Vec<&str>) = (old.lines().collect(), new.lines().collect());
    let (n, m) = (a.len(), b.len());
    let mut lcs = vec![vec![0u32; m + 1]; n + 1];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            lcs[i][j] = if a[i] == b[j] { lcs[i + 1][j + 1] + 1 } else { lcs[i + 1][j].max(lcs[i][j + 1]) };
        }
    }
    let (mut i, mut j) = (0, 0);
    let (mut added, mut removed) = (Vec::new(), Vec::new());
    while i < n || j < m {
        if i < n && j < m && a[i] == b[j] {
            i += 1;
            j += 1;
        } else if j < m && (i == n || lcs[i][j + 1] >= lcs[i + 1][j]) {
            added.push(b[j].to_string());
            j += 1;
        } else {
            removed.push(a[i].to_string());
            i += 1;
        }
    }
    (added, removed)
}

/// The program that draws `doc`'s shaded view (its shading: Phong per fragment,
/// otherwise per vertex), as the GPU view runs it ([`phonglab_core::shader::for_view`]).
pub fn program_text(doc: &Document, wgsl: bool) -> String {
    let lang = if wgsl { ShadingLanguage::Wgsl } else { ShadingLanguage::Glsl };
    let shading = if doc.view.shading == Shading::Phong { ShaderShading::Phong } else { ShaderShading::Gouraud };
    for_view(doc, lang, shading).map(|s| s.text(lang)).unwrap_or_default()
}

const KEYWORDS: &[&str] = &[
    "void",
    "float",
    "bool",
    "vec3",
    "vec4",
    "mat3",
    "mat4",
    "uniform",
    "in",
    "out",
    "layout",
    "return",
    "var",
    "let",
    "fn",
    "struct",
    "true",
    "false",
    "main",
    "f32",
    "vec3<f32>",
    "vec4<f32>",
    "@vertex",
    "@fragment",
];

/// The colour of a symbol the calculation and the plot draw in colour: `N`, `L`, `V`, `H`,
/// `R` or `S`, alone or with a light's number (`L0`, `H2`).
pub fn symbol_color(word: &str) -> Option<Color32> {
    let mut chars = word.chars();
    let first = chars.next()?;
    if !chars.all(|c| c.is_ascii_digit()) {
        return None;
    }
    use crate::app::widgets::palette as p;
    Some(match first {
        'N' => p::N,
        'L' => p::L,
        'V' => p::V,
        'H' | 'R' => p::H,
        'S' => p::SPOT,
        _ => return None,
    })
}

/// The colour a line is drawn on: its own background, or the panel's where it has none.
fn background_of(ui: &Ui, background: Color32) -> Color32 {
    if background == Color32::TRANSPARENT { ui.visuals().panel_fill } else { background }
}

/// One line, coloured: comments, keywords, numbers, and the symbols in their colours.
fn line_job(line: &str, ui: &Ui, background: Color32) -> LayoutJob {
    let dark = ui.visuals().dark_mode;
    let (text, comment, keyword, number) = if dark {
        (
            Color32::from_gray(230),
            Color32::from_gray(140),
            Color32::from_rgb(175, 155, 255),
            Color32::from_rgb(240, 190, 110),
        )
    } else {
        (Color32::BLACK, Color32::from_gray(90), Color32::from_rgb(95, 55, 170), Color32::from_rgb(150, 80, 0))
    };
    let font = FontId::monospace(ui.text_style_height(&egui::TextStyle::Monospace) * 0.85);
    let mut job = LayoutJob::default();
    let fmt = |c: Color32| TextFormat { font_id: font.clone(), color: c, background, ..Default::default() };
    let (code, rest) = match line.find("//") {
        Some(i) => (&line[..i], &line[i..]),
        None => (line, ""),
    };
    let mut word = String::new();
    let flush = |job: &mut LayoutJob, word: &mut String| {
        if word.is_empty() {
            return;
        }
        let c = if let Some(c) = symbol_color(word) {
            // N, L, V, H, R and S (L0, H1, ... with several lights) in the plot's colours.
            crate::app::widgets::palette::ink_on(c, background_of(ui, background))
        } else if KEYWORDS.contains(&word.as_str()) {
            keyword
        } else if word.chars().next().is_some_and(|c| c.is_ascii_digit()) {
            number
        } else {
            text
        };
        job.append(word, 0.0, fmt(c));
        word.clear();
    };
    for ch in code.chars() {
        if ch.is_alphanumeric() || ch == '_' || ch == '.' || ch == '@' {
            word.push(ch);
        } else {
            flush(&mut job, &mut word);
            job.append(&ch.to_string(), 0.0, fmt(text));
        }
    }
    flush(&mut job, &mut word);
    if !rest.is_empty() {
        job.append(rest, 0.0, fmt(comment));
    }
    job
}

/// The Shader window.
pub fn shader_window_ui(ctx: &egui::Context, state: &mut ShaderState, doc: &Document) {
    if !state.open {
        return;
    }
    let text = program_text(doc, state.wgsl);
    if text != state.shown {
        if !state.shown.is_empty() {
            (state.added, state.removed) = line_diff(&state.shown, &text);
        }
        state.shown.clone_from(&text);
    }
    let mut open = state.open;
    // Over the centre and the calculation, leaving the controls free to toggle effects.
    let at = ctx.content_rect().right_top() + egui::vec2(-640.0, 70.0);
    egui::Window::new(crate::t!("shader")).open(&mut open).default_size([620.0, 560.0]).default_pos(at).show(
        ctx,
        |ui| {
            ui.horizontal_wrapped(|ui| {
                let before = state.wgsl;
                ui.radio_value(&mut state.wgsl, false, "GLSL 3.30");
                ui.radio_value(&mut state.wgsl, true, "WGSL");
                if state.wgsl != before {
                    // Another language is not a change of the program.
                    state.shown.clear();
                    state.added.clear();
                    state.removed.clear();
                }
                if ui.button(t!("copy")).on_hover_text(t!("copy-program-hover")).clicked() {
                    ui.ctx().copy_text(text.clone());
                }
                ui.small(if doc.view.shading == Shading::Phong {
                    t!("shader-stages-phong")
                } else {
                    t!("shader-stages-vertex")
                });
            });
            if !state.added.is_empty() || !state.removed.is_empty() {
                ui.small(t!("shader-last-change", added = state.added.len(), removed = state.removed.len()));
            }
            egui::ScrollArea::both().auto_shrink(false).show(ui, |ui| {
                let hi = if ui.visuals().dark_mode {
                    Color32::from_rgb(20, 70, 30)
                } else {
                    Color32::from_rgb(200, 245, 205)
                };
                for line in text.lines() {
                    let bg = if state.added.iter().any(|a| a == line) { hi } else { Color32::TRANSPARENT };
                    ui.add(egui::Label::new(line_job(line, ui, bg)).wrap_mode(egui::TextWrapMode::Extend));
                }
                if !state.removed.is_empty() {
                    ui.separator();
                    ui.label(RichText::new(t!("shader-removed")).small());
                    for line in &state.removed {
                        ui.label(RichText::new(format!("- {line}")).monospace().small().strikethrough());
                    }
                }
            });
        },
    );
    state.open = open;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_diff_finds_added_and_removed_lines() {
        let (a, r) = line_diff("a\nb\nc\nd\n", "a\nx\nc\nd\ny\n");
        assert_eq!(a, ["x", "y"]);
        assert_eq!(r, ["b"]);
        assert_eq!(line_diff("a\nb\n", "a\nb\n"), (vec![], vec![]));
    }
}

#[cfg(test)]
mod symbol_tests {
    use super::symbol_color;

    #[test]
    fn the_symbols_have_the_plots_colours() {
        use crate::app::widgets::palette as p;
        assert_eq!(symbol_color("N"), Some(p::N));
        assert_eq!(symbol_color("L2"), Some(p::L));
        assert_eq!(symbol_color("H0"), Some(p::H));
        assert_eq!(symbol_color("V"), Some(p::V));
        assert_eq!(symbol_color("NdotL"), None);
        assert_eq!(symbol_color("vec3"), None);
        assert_eq!(symbol_color("P"), None);
    }
}
