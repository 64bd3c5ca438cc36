//! The colours of the symbols, shared by the vector plot and the worked calculation.

use egui::Color32;
use phonglab_core::explain::StepKind;

/// N, the normal.
pub const N: Color32 = Color32::from_rgb(0x4c, 0x9a, 0xff);
/// L, towards the light.
pub const L: Color32 = Color32::from_rgb(0xff, 0xb0, 0x20);
/// V, towards the viewer.
pub const V: Color32 = Color32::from_rgb(0x3c, 0xc8, 0x7a);
/// H, the halfway vector.
pub const H: Color32 = Color32::from_rgb(0xe0, 0x5a, 0xd8);
/// R, the reflection of L.
pub const R: Color32 = Color32::from_rgb(0xee, 0x55, 0x55);
/// S, the spot axis.
pub const SPOT: Color32 = Color32::from_rgb(0xb8, 0xb8, 0x40);
/// Notes where the engine took a limit.
pub const NOTE: Color32 = Color32::from_rgb(0xff, 0x9a, 0x3c);
/// Error messages.
pub const ERROR: Color32 = Color32::from_rgb(0xff, 0x60, 0x60);

/// `c` as drawn on the current background: as is on a dark one, darkened on a light one
/// so that it keeps its contrast (the light theme is for bright rooms).
pub fn ink(ui: &egui::Ui, c: Color32) -> Color32 {
    if ui.visuals().dark_mode { c } else { darker(c) }
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
