//! The exported PyOpenGL programs (`phonglab export --to pyopengl`), run by a real OpenGL
//! (Mesa 22.3.6, llvmpipe, with freeglut and GLU), draw what phonglab's renderer draws:
//! the same coverage and a mean difference within 3/255, for the shipped scenes, Red Book
//! teapots and generated exercises (levels 1 to 4, both rule sets), in Gouraud and Phong
//! shading, sphere, teapot and cylinder.
//!
//! Mesa's pictures are data (`tests/data/pyopengl_mesa/*.png`, 128x128, `--size 128`),
//! made once by `scripts/pyopengl_mesa.sh` from the programs the ignored test below
//! writes, so this test needs neither Python nor Mesa:
//!
//! ```text
//! PHONGLAB_PYOPENGL_OUT=/tmp/py cargo test --test all pyopengl_mesa::write_programs -- --ignored
//! scripts/pyopengl_mesa.sh /tmp/py tests/data/pyopengl_mesa
//! ```
//!
//! `programs.txt` beside the pictures records each program's CRC-32: a program that no
//! longer matches its picture fails here until the pictures are made again.

use std::path::{Path, PathBuf};

use phonglab::io::image::{Difference, read_png};
use phonglab_core::exercise::{Level, Spec, generate};
use phonglab_core::export::pyopengl::program;
use phonglab_core::render::Renderer;
use phonglab_core::{Document, ObjectKind, PowFn, Rules, Shading};

const SIZE: usize = 128;

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pyopengl_mesa")
}

fn scene_file(path: &str) -> Document {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    Document::from_toml_in(&std::fs::read_to_string(&p).unwrap(), p.parent()).unwrap()
}

/// The cases: a name and the document drawn.
fn cases() -> Vec<(String, Document)> {
    let mut out = Vec::new();
    let with = |mut d: Document, object: Option<ObjectKind>, shading: Option<Shading>| {
        if let Some(o) = object {
            d.view.object = o;
        }
        if let Some(s) = shading {
            d.view.shading = s;
        }
        d
    };
    for (file, object, shading) in [
        ("worksheet-mview5.toml", None, None),
        ("worksheet-mview5.toml", Some(ObjectKind::Sphere), Some(Shading::Phong)),
        ("worksheet-mview1.toml", None, Some(Shading::Phong)),
        ("worksheet-mview2.toml", None, None),
        ("worksheet-mview3.toml", Some(ObjectKind::Cylinder), None),
        ("worksheet-mview4.toml", None, Some(Shading::Phong)),
        ("spotlight.toml", None, None),
        ("spotlight.toml", None, Some(Shading::Gouraud)),
        ("three-lights.toml", None, None),
        ("three-lights.toml", Some(ObjectKind::Teapot), Some(Shading::Gouraud)),
        ("phong-demo.toml", None, Some(Shading::Gouraud)),
        ("phong-demo.toml", None, Some(Shading::Phong)),
        ("redbook-teapots/11-gold.toml", None, None),
        ("redbook-teapots/05-ruby.toml", None, Some(Shading::Phong)),
        ("redbook-teapots/20-cyan-rubber.toml", Some(ObjectKind::Cylinder), None),
    ] {
        let doc = with(scene_file(&format!("assets/scenes/{file}")), object, shading);
        let name = format!(
            "{}-{:?}-{:?}",
            file.trim_end_matches(".toml").replace('/', "-"),
            doc.view.object,
            doc.view.shading
        )
        .to_lowercase();
        out.push((name, doc));
    }
    for level in 1..=4u8 {
        for (rules, tag) in [(Rules::WORKSHEET, "worksheet"), (Rules::OPENGL, "opengl")] {
            let spec = Spec::level(Level::from_number(level).unwrap(), rules);
            let ex = generate(300 + level as u64, 1, &spec).unwrap().remove(0);
            let shading = if level % 2 == 0 { Shading::Phong } else { Shading::Gouraud };
            let object = [ObjectKind::Sphere, ObjectKind::Teapot, ObjectKind::Cylinder][level as usize % 3];
            let doc = with(ex.doc, Some(object), Some(shading));
            out.push((format!("exercise-{level}-{tag}"), doc));
        }
    }
    out
}

#[test]
#[ignore = "writes the programs for scripts/pyopengl_mesa.sh (set PHONGLAB_PYOPENGL_OUT)"]
fn write_programs() {
    let dir = PathBuf::from(std::env::var("PHONGLAB_PYOPENGL_OUT").expect("PHONGLAB_PYOPENGL_OUT"));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, doc) in cases() {
        std::fs::write(
            dir.join(format!("{name}.py")),
            program(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap(),
        )
        .unwrap();
    }
}

#[test]
fn the_pyopengl_programs_draw_under_mesa_what_phonglab_draws() {
    let recorded = std::fs::read_to_string(data().join("programs.txt")).unwrap();
    let crc_of: std::collections::BTreeMap<&str, &str> =
        recorded.lines().filter_map(|l| l.split_once(' ')).map(|(c, n)| (n.trim(), c)).collect();
    let cases = cases();
    assert!(cases.len() >= 20);
    for (name, doc) in &cases {
        let text = program(doc, &phonglab_core::export::shaded_key(doc)).unwrap();
        let crc = format!("{:08x}", crc32fast::hash(text.as_bytes()));
        assert_eq!(
            crc_of.get(format!("{name}.py").as_str()).copied(),
            Some(crc.as_str()),
            "{name}: the program changed since Mesa drew it: make the pictures again (this file's header)"
        );
        let (w, h, mesa) = read_png(&data().join(format!("{name}.png"))).unwrap();
        assert_eq!((w, h), (SIZE, SIZE));
        let setup = doc.shaded_setup(PowFn::Exact);
        let mesh = doc.view.mesh();
        let mut renderer = Renderer::new();
        let (ours, _) = renderer.render(&setup.job(&mesh), SIZE, SIZE).unwrap();
        let bg = doc.view.background.map(|c| (c * 255.0).round() as u8);
        let d = Difference::of(&ours.rgba, &mesa, bg);
        let mean = d.mad.iter().sum::<f64>() / 3.0;
        eprintln!(
            "{name}: {} px both cover, {} only ours, {} only Mesa's; mean difference {mean:.3}/255",
            d.both, d.only_first, d.only_second
        );
        assert!(d.both > 500, "{name}: only {} pixels covered", d.both);
        assert!(d.only_one() as f64 <= 0.005 * d.pixels as f64, "{name}: coverage differs: {d:?}");
        assert!(mean <= 3.0, "{name}: mean difference {mean}/255: {d:?}");
    }
}
