//! The window's arrangement: which panels are open, presentation mode, the theme, the
//! highlighted step, and what the centre shows beside the shaded view. Kept across
//! restarts (the panels' widths are kept by egui's own memory).
//!
//! Sizes are chosen from the window so that the four projector sizes (1024×768, 1280×720,
//! 1440×900, 1920×1080) fit without clipping; `tests/all/ui_layout.rs` checks it.

use serde::{Deserialize, Serialize};

/// Light or dark, both high-contrast (for bright rooms and for dark ones).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Theme {
    /// White panels, black text.
    Light,
    /// Black panels, white text.
    #[default]
    Dark,
}

impl Theme {
    /// The visuals: egui's, with text, strokes and panels pushed to full contrast.
    pub fn visuals(self) -> egui::Visuals {
        use egui::Color32;
        let (mut v, text, fill, faint) = match self {
            Theme::Light => (egui::Visuals::light(), Color32::BLACK, Color32::WHITE, Color32::from_gray(236)),
            Theme::Dark => (egui::Visuals::dark(), Color32::WHITE, Color32::BLACK, Color32::from_gray(24)),
        };
        v.panel_fill = fill;
        v.window_fill = fill;
        v.extreme_bg_color = faint;
        v.faint_bg_color = faint;
        v.widgets.noninteractive.fg_stroke.color = text;
        v.widgets.inactive.fg_stroke.color = text;
        v.widgets.hovered.fg_stroke.color = text;
        v.widgets.active.fg_stroke.color = text;
        v.widgets.noninteractive.bg_stroke.color = text.gamma_multiply(0.5);
        v
    }

    /// The other one.
    pub fn toggled(self) -> Theme {
        match self {
            Theme::Light => Theme::Dark,
            Theme::Dark => Theme::Light,
        }
    }

    /// "light" or "dark".
    pub fn label(self) -> String {
        match self {
            Theme::Light => crate::t!("theme-light"),
            Theme::Dark => crate::t!("theme-dark"),
        }
    }
}

/// What the centre shows below or beside the shaded view.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Beside {
    /// The vectors at the vertex.
    #[default]
    Vectors,
    /// The reflected intensity against angle.
    Lobe,
}

/// The arrangement of the window.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Layout {
    /// The controls panel (left) is open.
    pub controls_open: bool,
    /// The worked calculation (right) is open.
    pub calculation_open: bool,
    /// Presentation mode: large type, the controls in a drawer.
    pub presenting: bool,
    /// In presentation mode, the controls drawer is out.
    pub drawer_open: bool,
    /// The theme.
    pub theme: Theme,
    /// The step of the calculation the teacher is on (arrow keys), counted from 0.
    pub step: Option<usize>,
    /// The plot beside the shaded view.
    pub beside: Beside,
    /// Where the divider between the pictures and the plot was dragged.
    pub dividers: crate::app::shell::centre_layout::Dividers,
    /// The language chosen in the menu (`en`, `pt-PT`, `pt-BR`); `None`: the command
    /// line's or the system's.
    pub language: Option<String>,
    /// The decimal mark chosen in the menu (`point`, `comma`); `None`: the language's.
    pub decimal: Option<String>,
}

impl Default for Layout {
    fn default() -> Self {
        Self {
            controls_open: true,
            calculation_open: true,
            presenting: false,
            drawer_open: false,
            theme: Theme::Dark,
            step: None,
            beside: Beside::Vectors,
            dividers: Default::default(),
            language: None,
            decimal: None,
        }
    }
}

/// The key the arrangement is kept under in eframe's storage.
pub const LAYOUT_KEY: &str = "phonglab.layout.ron";

/// Presenting, the narrowest window in which the drawer stands beside the calculation.
pub const DRAWER_BESIDE_CALCULATION: f32 = 1200.0;

/// Type is this much larger in presentation mode.
pub const PRESENTATION_TEXT_SCALE: f32 = 1.45;

impl Layout {
    /// The arrangement as stored.
    pub fn to_ron(&self) -> String {
        ron::to_string(self).unwrap_or_default()
    }

    /// The stored arrangement, or the default when there is none or it does not read
    /// (an arrangement is not worth a message).
    pub fn from_ron(text: Option<&str>) -> Layout {
        text.and_then(|t| ron::from_str(t).ok()).unwrap_or_default()
    }

    /// The locale the window speaks: the menu's choices over the process's default.
    pub fn locale(&self) -> crate::locale::Locale {
        use crate::locale::{DecimalMark, Lang, Locale, default_locale};
        let lang = self.language.as_deref().and_then(Lang::parse).unwrap_or(default_locale().lang);
        let decimal = self.decimal.as_deref().and_then(DecimalMark::parse).unwrap_or_else(|| {
            // The process's mark when the language is the process's; else the language's own.
            if self.language.is_none() { default_locale().decimal } else { lang.decimal_mark() }
        });
        Locale { lang, decimal }
    }

    /// The controls panel's starting width for a window `width` points wide.
    pub fn controls_width(width: f32) -> f32 {
        (width * 0.26).clamp(290.0, 400.0)
    }

    /// The calculation panel's starting width for a window `width` points wide.
    pub fn calculation_width(width: f32) -> f32 {
        (width * 0.27).clamp(270.0, 460.0)
    }

    /// The least width the centre (the picture and the plot) keeps in a window `width`
    /// points wide, whatever the side panels' contents or a dragged edge ask: the side
    /// panels narrow (their text wraps) rather than cover it. Presenting, the pictures are
    /// what a class looks at (the centre keeps most of the window), unless the drawer is
    /// out, when the centre, the drawer and the calculation share it.
    pub fn centre_floor(&self, width: f32) -> f32 {
        match (self.presenting, self.drawer_open) {
            (true, false) => 0.64 * width,
            (true, true) if self.drawer_pushes_calculation(width) => 0.6 * width,
            _ => 0.42 * width,
        }
    }

    /// Presenting in a window narrower than [`DRAWER_BESIDE_CALCULATION`], the drawer out
    /// pushes the calculation aside (it comes back when the drawer goes in): three columns
    /// of large type left the picture 145 points at 1024x600.
    pub fn drawer_pushes_calculation(&self, width: f32) -> bool {
        self.presenting && self.drawer_open && width < DRAWER_BESIDE_CALCULATION
    }

    /// Moves the highlighted step by `delta` among `count` steps (starting at the first).
    pub fn step_by(&mut self, delta: isize, count: usize) {
        if count == 0 {
            self.step = None;
            return;
        }
        let next = match self.step {
            None if delta >= 0 => 0,
            None => count - 1,
            Some(s) => (s as isize + delta).clamp(0, count as isize - 1) as usize,
        };
        self.step = Some(next);
    }
}

/// Sets `style`'s text and control sizes to egui's own times `k` (1: egui's; presenting,
/// [`PRESENTATION_TEXT_SCALE`]). From egui's sizes, not `style`'s, so applying it twice
/// changes nothing.
pub fn set_text_scale(style: &mut egui::Style, k: f32) {
    let base = egui::Style::default();
    style.text_styles = base.text_styles;
    for font in style.text_styles.values_mut() {
        font.size *= k;
    }
    style.spacing.interact_size = base.spacing.interact_size * k;
    style.spacing.icon_width = base.spacing.icon_width * k;
    style.spacing.icon_width_inner = base.spacing.icon_width_inner * k;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_arrangement_round_trips_and_bad_text_gives_the_default() {
        let l = Layout { presenting: true, theme: Theme::Light, step: Some(3), ..Default::default() };
        assert_eq!(Layout::from_ron(Some(&l.to_ron())), l);
        assert_eq!(Layout::from_ron(Some("(presenting: maybe")), Layout::default());
        assert_eq!(Layout::from_ron(None), Layout::default());
    }

    #[test]
    fn steps_move_within_the_list() {
        let mut l = Layout::default();
        l.step_by(1, 5);
        assert_eq!(l.step, Some(0));
        l.step_by(10, 5);
        assert_eq!(l.step, Some(4));
        l.step_by(-1, 5);
        assert_eq!(l.step, Some(3));
        l.step_by(-9, 5);
        assert_eq!(l.step, Some(0));
        l.step_by(1, 0);
        assert_eq!(l.step, None);
    }

    #[test]
    fn both_themes_are_high_contrast() {
        for t in [Theme::Light, Theme::Dark] {
            let v = t.visuals();
            let text = v.widgets.noninteractive.fg_stroke.color;
            let lum = |c: egui::Color32| (c.r() as f32 + c.g() as f32 + c.b() as f32) / 3.0;
            assert!((lum(text) - lum(v.panel_fill)).abs() > 250.0, "{t:?}");
        }
    }
}
