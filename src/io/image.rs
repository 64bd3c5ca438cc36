//! PNG files: writing renders, reading reference images.

use std::path::Path;

use anyhow::{Context, Result};

use crate::t;

/// The keyword of the text chunk that says which program wrote a PNG (PNG's own
/// registered keyword for it).
pub const PNG_SIGNATURE_KEYWORD: &str = "Software";

/// Encodes RGBA8 pixels (rows top to bottom) as the bytes of a PNG file, every chunk
/// written and the encoder finished with its errors checked (dropping it would ignore them).
pub fn encode_png(width: usize, height: usize, rgba: &[u8]) -> Result<Vec<u8>> {
    encode_png_signed(width, height, rgba, None)
}

/// [`encode_png`] with a `Software` text chunk saying which output of phonglab it is
/// (`signed`, ASCII), by which phonglab knows its own earlier output again
/// ([`crate::io::work_output`]).
pub fn encode_png_signed(width: usize, height: usize, rgba: &[u8], signed: Option<&str>) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    let mut enc = png::Encoder::new(&mut bytes, width as u32, height as u32);
    enc.set_color(png::ColorType::Rgba);
    enc.set_depth(png::BitDepth::Eight);
    if let Some(text) = signed {
        enc.add_text_chunk(PNG_SIGNATURE_KEYWORD.to_string(), text.to_string()).context(t!("png-cannot-encode"))?;
    }
    let mut w = enc.write_header().context(t!("png-cannot-encode"))?;
    w.write_image_data(rgba).context(t!("png-cannot-encode"))?;
    w.finish().context(t!("png-cannot-encode"))?;
    Ok(bytes)
}

/// Writes RGBA8 pixels (rows top to bottom) as a PNG, whole or not at all
/// ([`crate::io::atomic_write::write`]).
pub fn write_png(path: &Path, width: usize, height: usize, rgba: &[u8]) -> Result<()> {
    let bytes = encode_png(width, height, rgba)?;
    crate::io::atomic_write::write(path, &bytes)?;
    Ok(())
}

/// Reads a PNG as RGBA8 (rows top to bottom): width, height, pixels.
pub fn read_png(path: &Path) -> Result<(usize, usize, Vec<u8>)> {
    let file = std::fs::File::open(path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::ALPHA);
    let mut reader = decoder.read_info().with_context(|| format!("{} is not a PNG", path.display()))?;
    let mut buf = vec![0; reader.output_buffer_size().context(t!("png-too-large"))?];
    let info = reader.next_frame(&mut buf).with_context(|| format!("{}: cannot decode", path.display()))?;
    let (w, h) = (info.width as usize, info.height as usize);
    buf.truncate(info.buffer_size());
    let rgba = match info.color_type {
        png::ColorType::Rgba => buf,
        png::ColorType::GrayscaleAlpha => buf.chunks(2).flat_map(|c| [c[0], c[0], c[0], c[1]]).collect(),
        other => {
            anyhow::bail!(t!("png-colour-type", path = crate::io::reasons::shown(path), kind = format!("{other:?}")))
        }
    };
    Ok((w, h, rgba))
}

/// How two pictures of one size differ, as the tests against Mesa and the GPU count it: a
/// pixel is covered where it differs from the background; colours are compared where both
/// cover it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Difference {
    /// Pixels covered in both pictures.
    pub both: usize,
    /// Pixels covered in the first picture only.
    pub only_first: usize,
    /// Pixels covered in the second picture only.
    pub only_second: usize,
    /// The mean absolute difference per channel (of 255) over the pixels both cover.
    pub mad: [f64; 3],
    /// All pixels.
    pub pixels: usize,
}

impl Difference {
    /// Compares two RGBA8 pictures of one size against the background `bg`.
    pub fn of(first: &[u8], second: &[u8], bg: [u8; 3]) -> Self {
        assert_eq!(first.len(), second.len(), "pictures of one size");
        let mut d = Difference { both: 0, only_first: 0, only_second: 0, mad: [0.0; 3], pixels: first.len() / 4 };
        for (a, b) in first.chunks_exact(4).zip(second.chunks_exact(4)) {
            match (a[..3] != bg, b[..3] != bg) {
                (true, true) => {
                    d.both += 1;
                    for k in 0..3 {
                        d.mad[k] += (a[k] as f64 - b[k] as f64).abs();
                    }
                }
                (true, false) => d.only_first += 1,
                (false, true) => d.only_second += 1,
                (false, false) => {}
            }
        }
        let n = d.both.max(1) as f64;
        d.mad = d.mad.map(|s| s / n);
        d
    }

    /// Pixels covered in one picture only.
    pub fn only_one(&self) -> usize {
        self.only_first + self.only_second
    }

    /// Intersection over union of the covered areas (1 when neither covers anything).
    pub fn iou(&self) -> f64 {
        let union = self.both + self.only_one();
        if union == 0 { 1.0 } else { self.both as f64 / union as f64 }
    }

    /// The fraction of the picture the first covers.
    pub fn coverage_first(&self) -> f64 {
        (self.both + self.only_first) as f64 / self.pixels.max(1) as f64
    }

    /// The fraction of the picture the second covers.
    pub fn coverage_second(&self) -> f64 {
        (self.both + self.only_second) as f64 / self.pixels.max(1) as f64
    }
}

impl std::fmt::Display for Difference {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} pixels covered in both, {} in one only; mean difference per channel {:.4} {:.4} {:.4} (of 255)",
            self.both,
            self.only_one(),
            self.mad[0],
            self.mad[1],
            self.mad[2]
        )
    }
}

#[cfg(test)]
mod tests {
    use super::Difference;

    #[test]
    fn counts_coverage_and_the_mean_difference_where_both_cover() {
        let bg = [10, 10, 10];
        let px = |c: [u8; 3]| [c[0], c[1], c[2], 255];
        let a: Vec<u8> = [px(bg), px([100, 0, 0]), px([50, 50, 50]), px([7, 8, 9])].concat();
        let b: Vec<u8> = [px(bg), px([104, 0, 2]), px(bg), px([7, 8, 9])].concat();
        let d = Difference::of(&a, &b, bg);
        assert_eq!((d.both, d.only_first, d.only_second, d.pixels), (2, 1, 0, 4));
        assert_eq!(d.mad, [2.0, 0.0, 1.0]);
        assert!((d.iou() - 2.0 / 3.0).abs() < 1e-12);
        assert_eq!((d.coverage_first(), d.coverage_second()), (0.75, 0.5));
    }
}
