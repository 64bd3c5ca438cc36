//! A link as a QR code (the `qrcode` crate finds the modules), written as PNG or SVG: dark
//! modules on white, a quiet zone of four modules, large enough to scan from the back of a
//! room when projected (8 pixels a module in the PNG).

use std::path::Path;

use anyhow::{Context, Result};

/// Pixels a module in the PNG.
const MODULE_PX: usize = 8;
/// The quiet zone around the code, in modules (the standard's four).
const QUIET: usize = 4;

/// The QR code of `text` as RGBA8 pixels, 8 a module, and its side.
pub fn qr_rgba(text: &str) -> Result<(usize, Vec<u8>)> {
    qr_rgba_at(text, MODULE_PX, qrcode::EcLevel::M)
}

/// The QR code of `text` as RGBA8 pixels, `module_px` pixels a module (the window draws
/// it one pixel a module, scaled up without smoothing), with the quiet zone, at the error
/// correction level `ec` (M, 15 % recoverable, for print; L, 7 %, for a screen), and its side.
pub fn qr_rgba_at(text: &str, module_px: usize, ec: qrcode::EcLevel) -> Result<(usize, Vec<u8>)> {
    let module_px = module_px.max(1);
    let code = qrcode::QrCode::with_error_correction_level(text.as_bytes(), ec)
        .with_context(|| crate::t!("share-qr-too-long"))?;
    let n = code.width();
    let colours = code.to_colors();
    let side = (n + 2 * QUIET) * module_px;
    let mut rgba = vec![255u8; side * side * 4];
    for (i, c) in colours.iter().enumerate() {
        if *c != qrcode::Color::Dark {
            continue;
        }
        let (mx, my) = (i % n + QUIET, i / n + QUIET);
        for y in my * module_px..(my + 1) * module_px {
            for x in mx * module_px..(mx + 1) * module_px {
                rgba[(y * side + x) * 4..][..3].copy_from_slice(&[0, 0, 0]);
            }
        }
    }
    Ok((side, rgba))
}

/// Writes the QR code of `text` to `path`: SVG when its name ends in `.svg`, else PNG.
pub fn write(path: &Path, text: &str) -> Result<()> {
    if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("svg")) {
        let code = qrcode::QrCode::new(text.as_bytes()).with_context(|| crate::t!("share-qr-too-long"))?;
        let svg = code.render::<qrcode::render::svg::Color<'_>>().min_dimensions(400, 400).quiet_zone(true).build();
        super::atomic_write::write(path, svg.as_bytes())?;
        return Ok(());
    }
    let (side, rgba) = qr_rgba(text)?;
    super::image::write_png(path, side, side, &rgba)
}
