//! How two pictures of one object differ, pixel by pixel: what Compare's difference view
//! shows (`|A - B|`, amplified, with a legend that says how much), and how the start
//! scene's Gouraud and Phong are held apart.

/// The gain of the difference picture: a difference of `256 / GAIN` levels or more is
/// white.
pub const GAIN: u32 = 8;

/// The difference, in levels of 255, past which a pixel counts as visibly different (about
/// 10 %: what a class sees at the back of the room).
pub const VISIBLE: u8 = 24;

/// Two pictures compared.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// `|A - B|` channel by channel, times [`GAIN`] and clamped, RGBA8 (alpha 255).
    pub rgba: Vec<u8>,
    /// Pixels where either picture shows the object (not the background).
    pub object: usize,
    /// Those whose largest channel difference passes [`VISIBLE`].
    pub visible: usize,
    /// The largest channel difference anywhere, in levels of 255.
    pub largest: u8,
}

impl Difference {
    /// The share of the object's pixels that differ visibly, in percent (0 with no object).
    pub fn visible_percent(&self) -> f64 {
        if self.object == 0 { 0.0 } else { 100.0 * self.visible as f64 / self.object as f64 }
    }
}

/// Compares two RGBA8 pictures of the same size, drawn on the background `background`
/// (rgb): the object is every pixel where either is not the background.
pub fn difference(a: &[u8], b: &[u8], background: [u8; 3]) -> Difference {
    let n = a.len().min(b.len()) / 4;
    let mut out = Difference { rgba: vec![0; n * 4], object: 0, visible: 0, largest: 0 };
    for i in 0..n {
        let (pa, pb) = (&a[4 * i..4 * i + 3], &b[4 * i..4 * i + 3]);
        let d: [u8; 3] = std::array::from_fn(|c| pa[c].abs_diff(pb[c]));
        let worst = d[0].max(d[1]).max(d[2]);
        out.largest = out.largest.max(worst);
        if pa != background || pb != background {
            out.object += 1;
            if worst > VISIBLE {
                out.visible += 1;
            }
        }
        for (o, &dc) in out.rgba[4 * i..4 * i + 3].iter_mut().zip(&d) {
            *o = (u32::from(dc) * GAIN).min(255) as u8;
        }
        out.rgba[4 * i + 3] = 255;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::formats::document::Document;
    use crate::model::view::Shading;
    use crate::numerics::pow::PowFn;
    use crate::raster::render::Renderer;

    /// The picture of `doc` in `shading`, `px` square.
    fn picture(doc: &Document, shading: Shading, px: usize) -> (Vec<u8>, [u8; 3]) {
        let mut doc = doc.clone();
        doc.view.shading = shading;
        let setup = doc.shaded_setup(PowFn::Exact);
        let mesh = doc.view.mesh();
        let mut renderer = Renderer::new();
        let (img, _) = renderer.render(&setup.job(&mesh), px, px).unwrap();
        let bg = doc.view.background.map(|c| (c * 255.0).round() as u8);
        (img.rgba.clone(), bg)
    }

    #[test]
    fn differences_are_counted_on_the_object_and_amplified() {
        let bg = [10, 20, 30];
        let a = [10, 20, 30, 255, 100, 100, 100, 255, 100, 100, 100, 255, 10, 20, 30, 255];
        let b = [10, 20, 30, 255, 100, 130, 100, 255, 110, 100, 100, 255, 40, 20, 30, 255];
        let d = difference(&a, &b, bg);
        assert_eq!((d.object, d.visible, d.largest), (3, 2, 30));
        assert_eq!(&d.rgba[4..8], &[0, 240, 0, 255]);
        assert_eq!(&d.rgba[8..12], &[80, 0, 0, 255]);
        assert_eq!(&d.rgba[0..4], &[0, 0, 0, 255]);
    }

    /// The start scene shows how Gouraud and Phong spread the light differently: at 512
    /// pixels, more than 5 % of the teapot's pixels differ by more than 24/255 (with
    /// glutSolidTeapot's own tessellation, 7, only 1.1 % did).
    #[test]
    fn the_start_scene_shows_gouraud_and_phong_apart() {
        let doc = Document::default();
        let (g, bg) = picture(&doc, Shading::Gouraud, 512);
        let (p, _) = picture(&doc, Shading::Phong, 512);
        let d = difference(&g, &p, bg);
        assert!(d.object > 40_000, "the teapot covers {} pixels", d.object);
        assert!(d.visible_percent() >= 5.0, "{:.2} % differ visibly", d.visible_percent());
        assert!(d.largest > 60, "largest difference {}", d.largest);
        let mut fine = doc.clone();
        fine.view.teapot_grid = 7;
        let (g7, _) = picture(&fine, Shading::Gouraud, 512);
        let (p7, _) = picture(&fine, Shading::Phong, 512);
        assert!(difference(&g7, &p7, bg).visible_percent() < 2.0, "the fine teapot hides the difference");
    }
}
