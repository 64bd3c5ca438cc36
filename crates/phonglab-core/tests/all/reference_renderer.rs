//! The fast renderer against the plain one (`raster::reference`, a student's top-to-bottom
//! reading of the algorithm): for every object, shading and two-sided case, and an OBJ
//! mesh, the same pixels covered and every colour within 1/255 per channel.

use phonglab_core::document::Document;
use phonglab_core::raster::reference;
use phonglab_core::render::Renderer;
use phonglab_core::{ObjectKind, Shading};

const SIZE: usize = 128;

fn compare(what: &str, doc: &Document) -> (usize, u8) {
    let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let mesh = doc.view.mesh();
    let job = setup.job(&mesh);
    let mut renderer = Renderer::new();
    let (fast, _) = renderer.render(&job, SIZE, SIZE).unwrap();
    let plain = reference::render(&job, SIZE, SIZE).unwrap();
    let bg = doc.view.background.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8);
    let (mut covered, mut worst) = (0, 0u8);
    for (i, (f, p)) in fast.rgba.chunks(4).zip(plain.rgba.chunks(4)).enumerate() {
        let (fc, pc) = (f[..3] != bg, p[..3] != bg);
        assert_eq!(
            fc,
            pc,
            "{what}: pixel ({}, {}) covered by one renderer only: fast {f:?}, plain {p:?}",
            i % SIZE,
            i / SIZE
        );
        if fc {
            covered += 1;
            let d = f.iter().zip(p).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
            worst = worst.max(d);
        }
    }
    assert!(covered > 500, "{what}: {covered} pixels covered");
    assert!(worst <= 1, "{what}: colours differ by up to {worst}/255");
    (covered, worst)
}

#[test]
fn the_fast_renderer_draws_what_the_plain_one_draws() {
    let mut n = 0;
    for two_sided in [false, true] {
        for object in [ObjectKind::Sphere, ObjectKind::Teapot, ObjectKind::Cylinder] {
            for shading in [Shading::Gouraud, Shading::Phong, Shading::Flat] {
                let mut doc = Document::from_toml(include_str!("../../../../assets/scenes/spotlight.toml")).unwrap();
                doc.view.object = object;
                doc.view.shading = shading;
                doc.scene.light_model.two_sided = two_sided;
                // The open cylinder shows its inside: the back material is another colour.
                doc.scene.back_material = Some(phonglab_core::materials::by_name("jade").unwrap().clone());
                compare(&format!("{object:?} {shading:?} two-sided {two_sided}"), &doc);
                n += 1;
            }
        }
    }
    // The worksheet's rules, and the Phong demo's (object-space lighting, clip-space framing).
    for (name, mut doc) in
        [("worksheet", Document::default()), ("phong demo", phonglab_core::library::phong_demo_document())]
    {
        for shading in [Shading::Gouraud, Shading::Phong, Shading::Flat] {
            doc.view.shading = shading;
            compare(&format!("{name} {shading:?}"), &doc);
            n += 1;
        }
    }
    assert_eq!(n, 24);
}

#[test]
fn an_obj_mesh_too() {
    let dir = std::env::temp_dir().join(format!("phonglab-reference-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // An octahedron with a face normal per corner (flat facets) and one without normals.
    let obj = "v 0 0 1\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n\
               f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\nf 6 3 2\nf 6 4 3\nf 6 5 4\nf 6 2 5\n";
    let path = dir.join("octahedron.obj");
    std::fs::write(&path, obj).unwrap();
    for shading in [Shading::Gouraud, Shading::Phong, Shading::Flat] {
        let mut doc = Document::default();
        doc.view.object = ObjectKind::Obj;
        doc.view.obj = Some(path.display().to_string());
        doc.view.shading = shading;
        compare(&format!("OBJ {shading:?}"), &doc);
    }
    std::fs::remove_dir_all(&dir).ok();
}
