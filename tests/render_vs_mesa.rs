//! The shaded view against Mesa llvmpipe's own images of docs/lighting.md's benchmark scene
//! (tests/data/mesa_bench): Gouraud against the fixed-function pipeline, Phong against the
//! harness's per-pixel GLSL. Over the pixels both cover, the mean absolute difference is
//! at most 1/255 per channel; the covered areas agree within 0.5 % of the image.

use phonglab_core::Shading;
use phonglab_core::mesh::{Mesh, sphere, teapot};
use phonglab_core::presets::bench_scene;
use phonglab_core::render::Renderer;

fn mesa(name: &str) -> (usize, usize, Vec<[u8; 3]>) {
    let path = format!("{}/tests/data/mesa_bench/{name}.png", env!("CARGO_MANIFEST_DIR"));
    let (w, h, rgba) = phonglab::image_io::read_png(std::path::Path::new(&path)).unwrap();
    (w, h, rgba.chunks(4).map(|c| [c[0], c[1], c[2]]).collect())
}

struct Comparison {
    mad: [f64; 3],
    coverage_ours: f64,
    coverage_mesa: f64,
    both: usize,
}

fn compare(mesh: &Mesh, shading: Shading, reference: &str) -> Comparison {
    let (w, h, theirs) = mesa(reference);
    let scene = bench_scene(199);
    let job = phonglab_core::library::bench_job(&scene, mesh, shading);
    let mut r = Renderer::new();
    let (img, _) = r.render(&job, w, h).unwrap();
    // Covered: differs from the background, as the harness counts it.
    let bg = theirs[0];
    let (mut sum, mut both, mut ours_n, mut theirs_n) = ([0.0f64; 3], 0usize, 0usize, 0usize);
    for y in 0..h {
        for x in 0..w {
            let o = img.rgb(x, y);
            let t = theirs[y * w + x];
            let (co, ct) = (o != bg, t != bg);
            ours_n += co as usize;
            theirs_n += ct as usize;
            if co && ct {
                both += 1;
                for c in 0..3 {
                    sum[c] += (o[c] as f64 - t[c] as f64).abs();
                }
            }
        }
    }
    let n = (w * h) as f64;
    Comparison {
        mad: sum.map(|s| s / both.max(1) as f64),
        coverage_ours: ours_n as f64 / n,
        coverage_mesa: theirs_n as f64 / n,
        both,
    }
}

fn check(c: &Comparison, what: &str) {
    eprintln!(
        "{what}: MAD per channel {:.3} {:.3} {:.3} (of 255) over {} pixels; coverage ours {:.4}, Mesa {:.4}",
        c.mad[0], c.mad[1], c.mad[2], c.both, c.coverage_ours, c.coverage_mesa
    );
    assert!(c.mad.iter().all(|m| *m <= 1.0), "{what}: mean absolute difference {:?} > 1/255", c.mad);
    assert!(
        (c.coverage_ours - c.coverage_mesa).abs() <= 0.005,
        "{what}: coverage {} vs {}",
        c.coverage_ours,
        c.coverage_mesa
    );
    assert!(c.coverage_mesa > 0.1, "{what}: the reference shows the object");
}

#[test]
fn gouraud_sphere_matches_mesa_fixed_function() {
    check(&compare(&sphere::glu_sphere(1.0, 50, 50), Shading::Gouraud, "sphere_50x50_ff_gouraud"), "sphere Gouraud");
}

#[test]
fn gouraud_teapot_matches_mesa_fixed_function() {
    check(&compare(&teapot::glut_teapot(0.8, 7), Shading::Gouraud, "glut_teapot_ff_gouraud"), "teapot Gouraud");
}

#[test]
fn phong_sphere_matches_mesa_per_pixel_glsl() {
    check(&compare(&sphere::glu_sphere(1.0, 50, 50), Shading::Phong, "sphere_50x50_glsl_phong"), "sphere Phong");
}

#[test]
fn phong_teapot_matches_mesa_per_pixel_glsl() {
    check(&compare(&teapot::glut_teapot(0.8, 7), Shading::Phong, "glut_teapot_glsl_phong"), "teapot Phong");
}
