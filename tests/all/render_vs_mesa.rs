//! The shaded view against Mesa llvmpipe's own images of docs/lighting.md's benchmark scene
//! (tests/data/mesa_bench): Gouraud against the fixed-function pipeline, Phong against the
//! harness's per-pixel GLSL. Over the pixels both cover, the mean absolute difference is
//! at most 1/255 per channel; the covered areas agree within 0.5 % of the image.

use phonglab::io::image::Difference;
use phonglab_core::Shading;
use phonglab_core::mesh::{Mesh, sphere, teapot};
use phonglab_core::presets::bench_scene;
use phonglab_core::render::Renderer;

/// Ours (first) against Mesa's image `name` (second).
fn compare(mesh: &Mesh, shading: Shading, name: &str) -> Difference {
    let path = format!("{}/tests/data/mesa_bench/{name}.png", env!("CARGO_MANIFEST_DIR"));
    let (w, h, theirs) = phonglab::io::image::read_png(std::path::Path::new(&path)).unwrap();
    let scene = bench_scene(199);
    let job = phonglab_core::shaded::bench_job(&scene, mesh, shading);
    let mut r = Renderer::new();
    let (img, _) = r.render(&job, w, h).unwrap();
    // Covered: differs from the background (Mesa's corner pixel), as the harness counts it.
    Difference::of(&img.rgba, &theirs, [theirs[0], theirs[1], theirs[2]])
}

fn check(c: &Difference, what: &str) {
    eprintln!("{what}: {c}; coverage ours {:.4}, Mesa {:.4}", c.coverage_first(), c.coverage_second());
    assert!(c.mad.iter().all(|m| *m <= 1.0), "{what}: mean absolute difference {:?} > 1/255", c.mad);
    assert!(
        (c.coverage_first() - c.coverage_second()).abs() <= 0.005,
        "{what}: coverage {} vs {}",
        c.coverage_first(),
        c.coverage_second()
    );
    assert!(c.coverage_second() > 0.1, "{what}: the reference shows the object");
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
