//! Issue 57's measured cases of `phonglab diagnose` (scripts/diagnose-table.sh): a light's or
//! a material's colour a few levels off is said as that colour, not as an attenuation (the
//! Phong demo has none); a shininess 10 % off is that shininess, not a square painted over.

use phonglab_core::teach::diagnose::{Diagnosis, Drawing, Shape, Verdict, diagnose};

const SIZE: usize = 256;

/// A shipped scene (`assets/scenes/NAME.toml`) drawn as `phonglab diagnose` draws it.
fn shipped(name: &str) -> Drawing {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/scenes/");
    let text = std::fs::read_to_string(format!("{path}{name}.toml")).expect("a shipped scene");
    let doc = phonglab_core::Document::from_toml(&text).expect("a scene");
    let mesh = doc.view.mesh();
    let mut d = Drawing::of(&doc.shaded_setup(phonglab_core::PowFn::Exact).job(&mesh));
    d.inside = doc.view.mesh_inside();
    d
}

/// The causes with their scores, for a failure's message.
fn said(d: &Diagnosis) -> String {
    let causes: Vec<_> = d.causes.iter().map(|t| (t.label(), t.matched.map(|m| m.score))).collect();
    format!("{:?} {causes:?} shape {:?}", d.verdict, d.shape)
}

/// A scene's name and a change made to it.
type Case = (&'static str, &'static dyn Fn(&mut Drawing));

/// `right` with `change` made, diagnosed against `right`.
fn changed(right: &Drawing, change: impl Fn(&mut Drawing)) -> Diagnosis {
    let mut wrong = right.clone();
    change(&mut wrong);
    diagnose(right, &wrong.draw(SIZE).expect("drawn").1, SIZE).expect("diagnosed")
}

#[test]
fn a_colour_a_few_levels_off_is_that_colour_not_an_attenuation() {
    // Each was named an attenuation with confidence: linear (on a scene with none), constant
    // 1.03, quadratic.
    let cases: [Case; 3] = [
        ("phong-demo", &|d| d.scene.material.diffuse.x = 0.388),
        ("three-lights", &|d| d.scene.lights[1].diffuse.y = 0.87),
        ("spotlight", &|d| d.scene.lights[0].diffuse -= glam::DVec4::new(6.0, 6.0, 6.0, 0.0) / 255.0),
    ];
    for (name, change) in cases {
        let d = changed(&shipped(name), change);
        assert_eq!(d.verdict, Verdict::Wrong, "{name}: {}", said(&d));
        assert_eq!(d.causes[0].id(), "colours-differ", "{name}: {}", said(&d));
        assert!(d.causes.iter().all(|t| !t.id().starts_with("attenuation-")), "{name}: {}", said(&d));
    }
}

#[test]
fn a_shininess_ten_percent_off_is_the_shininess_not_a_square_painted_over() {
    // Three lights with 66 or 54 for 60: was "256 pixels ... evenly lighter", unexplained.
    let right = shipped("three-lights");
    for shininess in [66.0, 54.0] {
        let d = changed(&right, |d| d.scene.material.shininess = shininess);
        assert_eq!(d.verdict, Verdict::Wrong, "{shininess}: {}", said(&d));
        assert_eq!(d.causes[0].id(), "shininess-differs", "{shininess}: {}", said(&d));
    }
}

#[test]
fn a_right_picture_blurred_is_right_as_saved_lossily_and_moved_half_a_pixel_is_no_marks() {
    // Each pixel the mean of itself and its neighbour to the right (moved half a pixel), or
    // of its 3 x 3 weighted 1-2-1 (a blur): was unexplained, then "thin marks".
    let right = shipped("spotlight");
    let rgba = right.draw(SIZE).expect("drawn").1;
    let at = |x: usize, y: usize, c: usize| u32::from(rgba[(y.min(SIZE - 1) * SIZE + x.min(SIZE - 1)) * 4 + c]);
    let half: Vec<u8> = (0..SIZE * SIZE * 4)
        .map(|i| {
            let (p, c) = (i / 4, i % 4);
            if c == 3 { 255 } else { (at(p % SIZE, p / SIZE, c) + at(p % SIZE + 1, p / SIZE, c)).div_ceil(2) as u8 }
        })
        .collect();
    let blurred: Vec<u8> = (0..SIZE * SIZE * 4)
        .map(|i| {
            let (p, c) = (i / 4, i % 4);
            let (x, y) = (p % SIZE, p / SIZE);
            let w = [1, 2, 1];
            let near = |k: usize| at((x + k % 3).saturating_sub(1), (y + k / 3).saturating_sub(1), c);
            let sum: u32 = (0..9).map(|k| w[k % 3] * w[k / 3] * near(k)).sum();
            if c == 3 { 255 } else { ((sum + 8) / 16) as u8 }
        })
        .collect();
    let d = diagnose(&right, &blurred, SIZE).expect("diagnosed");
    assert_eq!(d.verdict, Verdict::Right, "blurred: {}", said(&d));
    assert!(d.lossy.is_some(), "blurred: {}", said(&d));
    // Moved half a pixel: right as saved lossily, or, where a square across the terminator
    // moves by half its gradient, unexplained by that square (the offset test keeps the
    // attenuation a little off saved lossily from being called right): never thin marks,
    // never a mistake.
    let d = diagnose(&right, &half, SIZE).expect("diagnosed");
    assert_ne!(d.verdict, Verdict::Wrong, "half a pixel: {}", said(&d));
    assert!(!matches!(d.shape, Some(Shape::Marks(_) | Shape::Region(_))), "half a pixel: {}", said(&d));
}

/// Mitchell–Netravali's cubic (B = C = 1/3): ImageMagick's default filter for a picture with
/// an alpha channel (a PNG phonglab or a viewer saved), down and up alike.
fn mitchell(x: f64) -> f64 {
    let x = x.abs();
    if x < 1.0 {
        (7.0 * x.powi(3) - 12.0 * x.powi(2) + 16.0 / 3.0) / 6.0
    } else if x < 2.0 {
        (-7.0 / 3.0 * x.powi(3) + 12.0 * x.powi(2) - 20.0 * x + 32.0 / 3.0) / 6.0
    } else {
        0.0
    }
}

/// The rows of `rgba` (`from` pixels wide, `rows` high) resampled to `to` pixels wide with
/// [`mitchell`] (widened by the scale when shrinking, as ImageMagick does), edges clamped.
fn resampled_rows(rgba: &[u8], from: usize, rows: usize, to: usize) -> Vec<u8> {
    let scale = from as f64 / to as f64;
    let support = 2.0 * scale.max(1.0);
    let mut out = vec![255u8; to * rows * 4];
    for x in 0..to {
        let centre = (x as f64 + 0.5) * scale - 0.5;
        let taps: Vec<(usize, f64)> = ((centre - support).floor() as i64..=(centre + support).ceil() as i64)
            .map(|j| (j.clamp(0, from as i64 - 1) as usize, mitchell((j as f64 - centre) / scale.max(1.0))))
            .collect();
        let total: f64 = taps.iter().map(|t| t.1).sum();
        for y in 0..rows {
            for c in 0..3 {
                let v: f64 = taps.iter().map(|&(j, w)| w * f64::from(rgba[(y * from + j) * 4 + c])).sum();
                out[(y * to + x) * 4 + c] = (v / total).round().clamp(0.0, 255.0) as u8;
            }
        }
    }
    out
}

/// `rgba` (`w` x `h`) transposed (`h` x `w`).
fn transposed(rgba: &[u8], w: usize, h: usize) -> Vec<u8> {
    (0..w * h).flat_map(|p| rgba[((p % h) * w + p / h) * 4..][..4].to_vec()).collect()
}

/// `rgba` (`size` square) resized to `to` square, as `convert -resize` does with Mitchell's
/// filter: the rows, then the columns.
fn resized(rgba: &[u8], size: usize, to: usize) -> Vec<u8> {
    let rows = resampled_rows(rgba, size, size, to);
    transposed(&resampled_rows(&transposed(&rows, to, size), size, to, to), to, to)
}

#[test]
fn a_right_picture_resized_down_and_up_is_right_and_marks_over_it_are_still_marks() {
    // The spotlight scene's right PNG through `convert -resize 50% -resize 200%` (Mitchell's
    // filter, for a picture with an alpha channel): was "thin marks of 114 pixels" on the
    // lid's rim, where the blur lowers the rim's thin highlight below anything near it.
    let size = 512;
    let right = shipped("spotlight");
    let (_, rgba, covered) = right.draw(size).expect("drawn");
    let half_and_back = resized(&resized(&rgba, size, size / 2), size / 2, size);
    let d = diagnose(&right, &half_and_back, size).expect("diagnosed");
    assert_eq!(d.verdict, Verdict::Right, "{}", said(&d));
    assert!(d.lossy.is_some(), "{}", said(&d));
    // Said as resized too, not as a JPEG only.
    let words = d.lossy_words().expect("words");
    assert!(words.starts_with("Right, with losses:"), "{words}");
    // A line of one pixel, 60 levels darker, drawn across it afterwards is still marks.
    let mut lined = half_and_back.clone();
    let object: Vec<usize> = (0..size * size).filter(|&p| covered[p]).collect();
    let cx = object.iter().map(|p| p % size).sum::<usize>() / object.len();
    let cy = object.iter().map(|p| p / size).sum::<usize>() / object.len();
    for x in cx - 40..cx + 40 {
        for c in 0..3 {
            let at = (cy * size + x) * 4 + c;
            lined[at] = lined[at].saturating_sub(60);
        }
    }
    let d = diagnose(&right, &lined, size).expect("diagnosed");
    assert!(matches!(d.shape, Some(Shape::Marks(_))), "{}", said(&d));
}
