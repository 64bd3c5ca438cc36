//! The generated WGSL, run by wgpu on the machine's adapter (the software one here, as the
//! UI snapshot tests use) through the app's own GPU path (`phonglab::paint::gpu`), draws the
//! benchmark scene, the shipped scenes and the Phong demo (lit in object space, its normal
//! not renormalised) as the CPU renderer does: coverage identical but for at most 1 % of
//! the silhouette, and a mean difference over the covered pixels within 1/255 per channel,
//! Gouraud and Phong.

use phonglab::io::image::Difference;
use phonglab_core::mesh::sphere;
use phonglab_core::render::{Job, Renderer};
use phonglab_core::shader::ShaderShading;
use phonglab_core::{Shading, presets};

const SIZE: u32 = 256;

/// The CPU renderer's image of `doc`'s shaded view, and the GPU's with the generated WGSL.
fn images_of(doc: &phonglab_core::Document, shading: ShaderShading) -> (Vec<u8>, Vec<u8>, [u8; 3]) {
    let mut doc = doc.clone();
    doc.view.shading = if shading == ShaderShading::Phong { Shading::Phong } else { Shading::Gouraud };
    let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let mesh = doc.view.mesh();
    let job = setup.job(&mesh);
    gpu_image(&job)
}

fn bench_images(shading: ShaderShading) -> (Vec<u8>, Vec<u8>, [u8; 3]) {
    let scene = presets::bench_scene(10);
    let mesh = sphere::glu_sphere(1.0, 50, 50);
    let cpu_shading = if shading == ShaderShading::Phong { Shading::Phong } else { Shading::Gouraud };
    let job = phonglab_core::shaded::bench_job(&scene, &mesh, cpu_shading);
    gpu_image(&job)
}

/// The GPU's picture of `job` (the app's path: `phonglab::paint::gpu`), the CPU renderer's, and
/// the background.
fn gpu_image(job: &Job<'_>) -> (Vec<u8>, Vec<u8>, [u8; 3]) {
    let mut r = Renderer::new();
    let cpu = r.render(job, SIZE as usize, SIZE as usize).unwrap().0.rgba.clone();
    let bg = job.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    let rs = egui_kittest::wgpu::create_render_state(egui_kittest::wgpu::default_wgpu_setup(), Default::default());
    let gpu = phonglab::paint::gpu::render(&rs.device, &rs.queue, job, SIZE).unwrap();
    (gpu, cpu, bg)
}

fn compare(what: &str, shading: ShaderShading, (gpu, cpu, bg): (Vec<u8>, Vec<u8>, [u8; 3])) {
    let d = Difference::of(&gpu, &cpu, bg);
    println!("{what} {shading:?}: {d}");
    assert!(d.both > 2_000, "{what}: {d}");
    assert!(d.only_one() as f64 <= 0.01 * d.both as f64, "{what}: coverage differs: {d}");
    assert!(d.mad.iter().all(|m| *m <= 1.0), "{what} {shading:?}: mean difference > 1/255: {d}");
}

#[test]
fn the_generated_wgsl_draws_what_the_cpu_renderer_draws() {
    for shading in [ShaderShading::Gouraud, ShaderShading::Phong] {
        compare("benchmark", shading, bench_images(shading));
    }
}

#[test]
fn so_it_does_for_the_shipped_scenes() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut docs = Vec::new();
    for f in [
        "spotlight.toml",
        "three-lights.toml",
        "worksheet-mview5.toml",
        "worksheet-mview2.toml",
        "redbook-teapots/11-gold.toml",
    ] {
        let doc = phonglab_core::Document::from_toml(&std::fs::read_to_string(root.join(f)).unwrap()).unwrap();
        docs.push((f.to_string(), doc));
    }
    // Energy-conserving Blinn-Phong (the normalised factor in the WGSL) on the spotlight.
    let mut normalised = docs[0].1.clone();
    normalised.scene.rules.specular = phonglab_core::SpecularModel::BlinnPhongNormalised;
    docs.push(("spotlight, normalised Blinn-Phong".into(), normalised));
    // Two-sided lighting on the open cylinder, whose inside shows.
    let mut two = docs[0].1.clone();
    two.scene.light_model.two_sided = true;
    two.view.object = phonglab_core::ObjectKind::Cylinder;
    docs.push(("spotlight, two-sided, cylinder".into(), two));
    // The Phong demo as its program draws it: clip-space picture, lit in object space, the
    // interpolated normal not renormalised, its rules (the reflection vector, clamped).
    let demo = phonglab_core::library::documents()
        .into_iter()
        .find(|(name, _)| name.contains("demo"))
        .expect("the Phong demo is a preset");
    docs.push(demo);
    for (what, doc) in &docs {
        for shading in [ShaderShading::Gouraud, ShaderShading::Phong] {
            compare(what, shading, images_of(doc, shading));
        }
    }
}

/// The probe on the GPU path: the app's probe reads the CPU renderer's frame of the same
/// view, and at pixels both pictures cover its bytes are the GPU's within two levels (the
/// rasterisers differ in their last bits), at every pixel the two cover of the spotlight's
/// teapot and the three lights' sphere, Gouraud and Phong.
#[test]
fn the_probe_tells_the_gpu_pictures_pixels() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let (mut probed, mut off_by_more) = (0, 0);
    for f in ["spotlight.toml", "three-lights.toml"] {
        let mut doc = phonglab_core::Document::from_toml(&std::fs::read_to_string(root.join(f)).unwrap()).unwrap();
        for shading in [Shading::Gouraud, Shading::Phong] {
            doc.view.shading = shading;
            let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
            let mesh = doc.view.mesh();
            let job = setup.job(&mesh);
            let (gpu, _, bg) = gpu_image(&job);
            let mut r = Renderer::new();
            r.keep_visibility(true);
            r.render(&job, SIZE as usize, SIZE as usize).unwrap();
            for y in (0..SIZE as usize).step_by(3) {
                for x in (0..SIZE as usize).step_by(3) {
                    let g = &gpu[(y * SIZE as usize + x) * 4..][..3];
                    let Some(p) = phonglab_core::probe::probe(&r, &job, x, y).unwrap() else { continue };
                    if g == bg {
                        continue;
                    }
                    probed += 1;
                    let most = (0..3).map(|c| p.rgba8[c].abs_diff(g[c])).max().unwrap();
                    off_by_more += (most > 2) as usize;
                }
            }
        }
    }
    eprintln!("{probed} pixels probed on the GPU's pictures, {off_by_more} more than 2 levels off");
    assert!(probed > 2_000, "{probed}");
    // Along silhouettes and shared edges the two may draw different triangles.
    assert!(off_by_more * 100 <= probed, "{off_by_more} of {probed}");
}
