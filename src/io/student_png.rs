//! A student's picture read as hostile input: the file capped before it is read, a link
//! refused by the open itself ([`crate::io::input_file::read_submission`]), its size checked against the size expected
//! from the header alone, before any pixel is decoded, and the decoder's memory capped.

use std::path::Path;

use crate::t;

/// The largest picture file read: a 512 x 512 RGBA PNG without compression is 1 MiB.
pub const MAX_PICTURE_BYTES: u64 = 32 << 20;

/// The most the decoder may allocate: a 4096 x 4096 RGBA picture.
const MAX_DECODED_BYTES: usize = 64 << 20;

/// Reads the PNG at `path`, which must be `size` pixels square, as RGBA8 (rows top to
/// bottom); colour types, 16-bit channels and palettes are converted. The messages say
/// what is wrong in the user's language: not a PNG, damaged, or the wrong size (with the
/// size expected).
pub fn read(path: &Path, size: usize) -> Result<Vec<u8>, String> {
    let bytes = crate::io::input_file::read_submission(path, MAX_PICTURE_BYTES, &t!("file-kind-pictures"))?;
    decode(&bytes, path, size)
}

/// Decodes the PNG `bytes` of the file named `path` (read capped already: a drop), as
/// [`read`] does.
pub fn decode(bytes: &[u8], path: &Path, size: usize) -> Result<Vec<u8>, String> {
    let shown = crate::io::reasons::shown(path);
    let limits = png::Limits { bytes: MAX_DECODED_BYTES };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(bytes), limits);
    decoder.set_transformations(png::Transformations::normalize_to_color8() | png::Transformations::ALPHA);
    let bad = |reason: String| t!("diagnose-bad-png", path = shown.clone(), reason = reason);
    let mut reader = decoder.read_info().map_err(|e| bad(png_reason(bytes, &e)))?;
    let (w, h) = (reader.info().width as usize, reader.info().height as usize);
    if (w, h) != (size, size) {
        return Err(t!(
            "diagnose-wrong-size",
            path = shown.clone(),
            got = format!("{w}x{h}"),
            expected = format!("{size}x{size}")
        ));
    }
    let mut buf = vec![0; reader.output_buffer_size().ok_or_else(|| bad(t!("png-reason-too-large")))?];
    let info = reader.next_frame(&mut buf).map_err(|e| bad(png_reason(bytes, &e)))?;
    buf.truncate(info.buffer_size());
    let rgba = match info.color_type {
        png::ColorType::Rgba => buf,
        png::ColorType::GrayscaleAlpha => buf.chunks_exact(2).flat_map(|c| [c[0], c[0], c[0], c[1]]).collect(),
        other => return Err(bad(t!("png-reason-colours", kind = format!("{other:?}")))),
    };
    opaque(rgba, &shown)
}

/// `rgba` when every pixel is opaque, else why it is refused: a transparent or see-through
/// pixel shows whatever lies behind it (a page's white, a viewer's checkerboard), so no
/// verdict on its colour would be true of what the student saw. The file shown as `shown`.
fn opaque(rgba: Vec<u8>, shown: &str) -> Result<Vec<u8>, String> {
    let clear = rgba.chunks_exact(4).filter(|p| p[3] < 255).count();
    if clear == 0 {
        return Ok(rgba);
    }
    Err(t!("diagnose-transparent", path = shown.to_owned(), count = clear.to_string()))
}

/// Why the decoder refused `bytes`, in the catalogue's words (the decoder's own are
/// English): not a PNG at all, too large to decode, or a PNG damaged or cut short.
fn png_reason(bytes: &[u8], e: &png::DecodingError) -> String {
    const SIGNATURE: [u8; 8] = [137, 80, 78, 71, 13, 10, 26, 10];
    // JPEG's start of image: students hand in .jpg, however named.
    if bytes.starts_with(&[0xFF, 0xD8, 0xFF]) {
        t!("png-reason-jpeg")
    } else if !bytes.starts_with(&SIGNATURE) {
        t!("png-reason-not-png")
    } else if matches!(e, png::DecodingError::LimitsExceeded) {
        t!("png-reason-too-large")
    } else {
        t!("png-reason-damaged")
    }
}
