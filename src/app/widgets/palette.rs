//! The colours of the symbols, shared by the vector plot and the worked calculation.

use egui::Color32;
use phonglab_core::explain::StepKind;

// The symbols' colours are Okabe and Ito's set for colour-blind viewers ("Color Universal
// Design", 2002): told apart under protanopia, deuteranopia and tritanopia. Each is drawn
// with a contrast of at least 3:1 against the theme's background ([`ink`] darkens or
// lightens it where it falls short), and each also has a letter at its tip, and H a dashed
// line, so no symbol depends on its colour alone.

/// N, the normal (Okabe-Ito blue).
pub const N: Color32 = Color32::from_rgb(0x00, 0x72, 0xB2);
/// L, towards the light (Okabe-Ito vermillion).
pub const L: Color32 = Color32::from_rgb(0xD5, 0x5E, 0x00);
/// V, towards the viewer (Okabe-Ito bluish green).
pub const V: Color32 = Color32::from_rgb(0x00, 0x9E, 0x73);
/// H, the halfway vector (Okabe-Ito reddish purple; drawn dashed).
pub const H: Color32 = Color32::from_rgb(0xCC, 0x79, 0xA7);
/// R, the reflection of L: it takes H's place under Phong's model, so H's colour (dashed).
pub const R: Color32 = H;
/// M n, the normal moved as a point would be, beside the true N (Okabe-Ito sky blue, a
/// lighter N; drawn dotted).
pub const NAIVE_NORMAL: Color32 = Color32::from_rgb(0x56, 0xB4, 0xE9);
/// S, the spot axis (Okabe-Ito orange; drawn dotted).
pub const SPOT: Color32 = Color32::from_rgb(0xE6, 0x9F, 0x00);
/// Notes where the engine took a limit.
pub const NOTE: Color32 = Color32::from_rgb(0xE6, 0x9F, 0x00);
/// Error messages.
pub const ERROR: Color32 = Color32::from_rgb(0xff, 0x60, 0x60);

/// The least contrast a symbol keeps against its background.
pub const MIN_CONTRAST: f32 = 3.0;

/// WCAG's relative luminance of an sRGB colour.
pub fn luminance(c: Color32) -> f32 {
    let lin = |x: u8| {
        let x = x as f32 / 255.0;
        if x <= 0.04045 { x / 12.92 } else { ((x + 0.055) / 1.055).powf(2.4) }
    };
    0.2126 * lin(c.r()) + 0.7152 * lin(c.g()) + 0.0722 * lin(c.b())
}

/// The relative luminance of a linear rgb (GL's values, as lit): Rec. 709's weights.
pub fn linear_luminance([r, g, b]: [f64; 3]) -> f64 {
    0.2126 * r + 0.7152 * g + 0.0722 * b
}

/// WCAG's contrast ratio of two colours (1 to 21).
pub fn contrast(a: Color32, b: Color32) -> f32 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// The least contrast a letter keeps against what it is written on (WCAG's for text).
pub const TEXT_CONTRAST: f32 = 4.5;

/// `c` as drawn on `background`: as it is where its contrast is at least [`MIN_CONTRAST`],
/// otherwise darkened (on a light background) or lightened (on a dark one) until it is.
pub fn ink_on(c: Color32, background: Color32) -> Color32 {
    ink_with_contrast(c, background, MIN_CONTRAST)
}

/// [`ink_on`] to the contrast `least` (a symbol's letter: [`TEXT_CONTRAST`]).
pub fn ink_with_contrast(c: Color32, background: Color32, least: f32) -> Color32 {
    let light_bg = luminance(background) > 0.18;
    let mut out = c;
    for k in 1..=20 {
        if contrast(out, background) >= least {
            break;
        }
        let t = k as f32 / 20.0;
        let towards = if light_bg { 0.0 } else { 255.0 };
        let mix = |x: u8| (x as f32 + (towards - x as f32) * t).round() as u8;
        out = Color32::from_rgb(mix(c.r()), mix(c.g()), mix(c.b()));
    }
    out
}

/// `c` as drawn in `ui`: [`ink_on`] the panel's background.
pub fn ink(ui: &egui::Ui, c: Color32) -> Color32 {
    ink_on(c, ui.visuals().panel_fill)
}

/// `c` at 55 % of its brightness.
pub fn darker(c: Color32) -> Color32 {
    let k = |x: u8| (x as f32 * 0.55).round() as u8;
    Color32::from_rgb(k(c.r()), k(c.g()), k(c.b()))
}

/// The colour a step's value is drawn in (`None`: the default text colour).
pub fn step(kind: StepKind) -> Option<Color32> {
    match kind {
        StepKind::Normal => Some(N),
        StepKind::L => Some(L),
        StepKind::V => Some(V),
        StepKind::H => Some(H),
        StepKind::R => Some(R),
        StepKind::Spot => Some(SPOT),
        _ => None,
    }
}

/// A GL colour (unclamped floats) as it would be displayed: clamped to [0, 1], sRGB-encoded
/// as OpenGL writes it to an 8-bit framebuffer (no conversion: OpenGL's fixed function
/// writes the value straight to the framebuffer).
pub fn gl_to_color32(rgb: [f64; 3]) -> Color32 {
    let c = |x: f64| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    Color32::from_rgb(c(rgb[0]), c(rgb[1]), c(rgb[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_symbol_keeps_3_to_1_on_both_themes_backgrounds() {
        for theme in [crate::app::shell::layout::Theme::Light, crate::app::shell::layout::Theme::Dark] {
            let v = theme.visuals();
            for bg in [v.panel_fill, v.extreme_bg_color, v.faint_bg_color] {
                for (name, c) in [("N", N), ("L", L), ("V", V), ("H", H), ("S", SPOT), ("note", NOTE)] {
                    let k = contrast(ink_on(c, bg), bg);
                    assert!(k >= MIN_CONTRAST, "{theme:?} {name} on {bg:?}: {k:.2}");
                }
            }
        }
        // Okabe-Ito's own values already pass on black and white for N, L and V.
        assert_eq!(ink_on(N, Color32::WHITE), N);
        assert_eq!(ink_on(L, Color32::BLACK), L);
        assert!((contrast(Color32::BLACK, Color32::WHITE) - 21.0).abs() < 1e-3);
    }

    #[test]
    fn the_four_symbols_are_distinct_colours() {
        let all = [N, L, V, H];
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                let d = (a.r() as i32 - b.r() as i32).abs()
                    + (a.g() as i32 - b.g() as i32).abs()
                    + (a.b() as i32 - b.b() as i32).abs();
                assert!(d > 100, "{a:?} {b:?}");
            }
        }
    }

    #[test]
    fn letters_read_at_a_texts_contrast_on_any_picture() {
        // The Phong demo's black picture, the start's dark blue one, a white one, mid grey.
        let backgrounds = [Color32::BLACK, Color32::from_rgb(20, 24, 40), Color32::WHITE, Color32::from_gray(128)];
        for bg in backgrounds {
            for (name, c) in [("N", N), ("L", L), ("V", V), ("H", H), ("M n", NAIVE_NORMAL)] {
                let k = contrast(ink_with_contrast(c, bg, TEXT_CONTRAST), bg);
                assert!(k >= TEXT_CONTRAST, "{name} on {bg:?}: {k:.2}");
            }
        }
        // N's own blue on black is under it (3.2:1): the letter is lightened.
        assert!(contrast(N, Color32::BLACK) < TEXT_CONTRAST);
        assert_ne!(ink_with_contrast(N, Color32::BLACK, TEXT_CONTRAST), N);
    }
}
