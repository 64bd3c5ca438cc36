//! A link as a QR code (the `qrcode` crate finds the modules), written as PNG or SVG: dark
//! modules on white, a quiet zone of four modules, large enough to scan from the back of a
//! room when projected (8 pixels a module in the PNG).

use std::path::Path;

use anyhow::{Context, Result};

/// Pixels a module in the PNG.
const MODULE_PX: usize = 8;
/// The quiet zone around the code, in modules (the standard's four).
const QUIET: usize = 4;

/// The QR code of `text` as RGBA8 pixels, and its side.
pub fn qr_rgba(text: &str) -> Result<(usize, Vec<u8>)> {
    let code = qrcode::QrCode::new(text.as_bytes()).context("the link is too long for a QR code")?;
    let n = code.width();
    let colours = code.to_colors();
    let side = (n + 2 * QUIET) * MODULE_PX;
    let mut rgba = vec![255u8; side * side * 4];
    for (i, c) in colours.iter().enumerate() {
        if *c != qrcode::Color::Dark {
            continue;
        }
        let (mx, my) = (i % n + QUIET, i / n + QUIET);
        for y in my * MODULE_PX..(my + 1) * MODULE_PX {
            for x in mx * MODULE_PX..(mx + 1) * MODULE_PX {
                rgba[(y * side + x) * 4..][..3].copy_from_slice(&[0, 0, 0]);
            }
        }
    }
    Ok((side, rgba))
}

/// Writes the QR code of `text` to `path`: SVG when its name ends in `.svg`, else PNG.
pub fn write(path: &Path, text: &str) -> Result<()> {
    if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("svg")) {
        let code = qrcode::QrCode::new(text.as_bytes()).context("the link is too long for a QR code")?;
        let svg = code.render::<qrcode::render::svg::Color<'_>>().min_dimensions(400, 400).quiet_zone(true).build();
        super::atomic_write::write(path, svg.as_bytes())?;
        return Ok(());
    }
    let (side, rgba) = qr_rgba(text)?;
    super::image::write_png(path, side, side, &rgba)
}
