//! The "Phong demo" preset against the demo's own program: its three GLSL programs run by
//! Mesa llvmpipe exactly as the Python source draws them (`seed_demo.py` of the glref
//! harness: no projection, `mvMatrix = rotY(0.5 deg)^frame` uploaded untransposed,
//! light and eye at (-4, 0, -8) in object space, 512x512, black, depth test LESS), kept as
//! `tests/data/seed_demo/seed_<frame>_<object>_<shading>.png`.
//!
//! For every object x shading at each kept frame: the covered pixels agree with an IoU of
//! at least 0.97 and the mean absolute difference over pixels both cover is at most 3/255
//! per channel; where an object covers under 1 % of the image (the cylinder seen end-on)
//! the numbers of covered pixels agree within 15 % instead.

use phonglab::io::image::Difference;
use phonglab_core::render::Renderer;
use phonglab_core::{ObjectKind, Shading, library};

/// The frames kept (1: the first frame the program draws; 250: 125 degrees on).
const FRAMES: [u32; 2] = [1, 250];

/// Mesa's picture: width, height, RGBA8.
fn mesa_rgba(frame: u32, object: ObjectKind, shading: Shading) -> (usize, usize, Vec<u8>) {
    let path = format!(
        "{}/tests/data/seed_demo/seed_{frame}_{}_{}.png",
        env!("CARGO_MANIFEST_DIR"),
        object.label().to_lowercase(),
        shading.label().to_lowercase()
    );
    phonglab::io::image::read_png(std::path::Path::new(&path)).unwrap()
}

fn mesa(frame: u32, object: ObjectKind, shading: Shading) -> (usize, usize, Vec<[u8; 3]>) {
    let (w, h, rgba) = mesa_rgba(frame, object, shading);
    (w, h, rgba.chunks(4).map(|c| [c[0], c[1], c[2]]).collect())
}

/// Ours (first) against Mesa's (second).
fn compare(frame: u32, object: ObjectKind, shading: Shading) -> Difference {
    let (w, h, theirs) = mesa_rgba(frame, object, shading);
    let mut doc = library::phong_demo_document();
    doc.view.object = object;
    doc.view.shading = shading;
    doc.view.spin_degrees = 0.5 * frame as f64;
    let mesh = doc.view.mesh();
    let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let mut r = Renderer::new();
    let (img, _) = r.render(&setup.job(&mesh), w, h).unwrap();
    // Covered, as the harness counts it: not black. (The demo's ambient alone is 0.2 red,
    // so a covered pixel is never black.)
    Difference::of(&img.rgba, &theirs, [0; 3])
}

fn check(frame: u32, object: ObjectKind, shading: Shading) {
    let c = compare(frame, object, shading);
    let what = format!("frame {frame} {} {}", object.label(), shading.label());
    let (ours, theirs) = (c.both + c.only_first, c.both + c.only_second);
    eprintln!("{what}: IoU {:.4}, {c}; covered ours {ours} Mesa {theirs}", c.iou());
    if c.coverage_second() < 0.01 {
        // Edge-on (no pixel at all) both ways, or within 15 %.
        let ratio = if theirs == 0 { if ours == 0 { 1.0 } else { f64::INFINITY } } else { ours as f64 / theirs as f64 };
        assert!((0.85..=1.15).contains(&ratio), "{what}: covered {ours} vs Mesa's {theirs}");
    } else {
        assert!(c.iou() >= 0.97, "{what}: IoU {}", c.iou());
        assert!(c.mad.iter().all(|m| *m <= 3.0), "{what}: mean absolute difference {:?}", c.mad);
    }
}

#[test]
fn sphere_as_the_demo_draws_it() {
    for f in FRAMES {
        for s in Shading::ALL {
            check(f, ObjectKind::Sphere, s);
        }
    }
}

#[test]
fn teapot_as_the_demo_draws_it() {
    for f in FRAMES {
        for s in Shading::ALL {
            check(f, ObjectKind::Teapot, s);
        }
    }
}

#[test]
fn cylinder_as_the_demo_draws_it() {
    for f in FRAMES {
        for s in Shading::ALL {
            check(f, ObjectKind::Cylinder, s);
        }
    }
}

#[test]
fn the_highlight_is_red_and_on_the_left() {
    // Frame 1, sphere, Gouraud: the brightest pixel is pure red and left of centre, as in
    // the program's own picture.
    let (w, h, theirs) = mesa(1, ObjectKind::Sphere, Shading::Gouraud);
    let mut doc = library::phong_demo_document();
    doc.view.spin_degrees = 0.5;
    let mesh = doc.view.mesh();
    let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let mut r = Renderer::new();
    let (img, _) = r.render(&setup.job(&mesh), w, h).unwrap();
    for (name, px) in [("ours", (0..w * h).map(|i| img.rgb(i % w, i / w)).collect::<Vec<_>>()), ("Mesa", theirs)] {
        let (i, best) = px.iter().enumerate().max_by_key(|(_, p)| p[0]).unwrap();
        assert_eq!((best[1], best[2]), (0, 0), "{name}: the highlight is red");
        assert!(best[0] > 200, "{name}: the highlight is bright ({best:?})");
        assert!(i % w < w / 2 - 20, "{name}: the highlight is on the left (x = {})", i % w);
    }
}
