//! `phonglab render`: the shaded view (sphere, teapot, cylinder or a mesh) to a PNG.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};
use phonglab_core::{EvalOptions, ObjectKind, PowFn, Shading, library, presets, t};

use super::scene_file;

/// `phonglab render`.
#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The object (default: the scene's).
    #[arg(long, value_enum)]
    pub object: Option<ObjectKind>,
    /// Shade this Wavefront OBJ mesh instead of the scene's object (fitted to radius 0.5).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["object", "bench_frame"])]
    pub obj: Option<PathBuf>,
    /// The shading (default: the scene's).
    #[arg(long, value_enum)]
    pub shading: Option<Shading>,
    /// Image width and height in pixels.
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(1..=8192))]
    pub size: u32,
    /// The PNG to write.
    #[arg(short, long)]
    pub output: PathBuf,
    /// A scene file (TOML); default: the worksheet's scene.
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// A ready-made scene instead: "worksheet" or "phong-demo".
    #[arg(long, conflicts_with = "scene")]
    pub preset: Option<String>,
    /// docs/lighting.md's benchmark scene at this frame instead (sphere r 1 50x50, teapot 0.8,
    /// gluPerspective(40, 1, 0.5, 20)): the image Mesa's harness draws.
    #[arg(long, conflicts_with_all = ["scene", "preset"])]
    pub bench_frame: Option<u32>,
    /// Power function for the specular and spot terms.
    #[arg(long, value_enum, default_value = "exact")]
    pub pow: PowFn,
    /// Cull back faces.
    #[arg(long)]
    pub cull: bool,
    /// Frame N of the scene's spin: N steps of 0.5 degrees (the Phong demo's first frame
    /// drawn is 1). Default: the scene's own spin.
    #[arg(long, value_name = "N", conflicts_with = "bench_frame")]
    pub frame: Option<u32>,
    /// Correct the Phong demo's departures from OpenGL's lighting (comma-separated):
    /// light (fixed in the world), normals (the surface's true ones), highlight (in the
    /// light's colour), or all.
    #[arg(long, value_delimiter = ',', value_enum, conflicts_with = "bench_frame")]
    pub correct: Vec<CorrectArg>,
}

/// A correction of the Phong demo (`render --correct`).
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum CorrectArg {
    /// The light fixed in the world.
    Light,
    /// The surface's true normals.
    Normals,
    /// The highlight in the light's colour.
    Highlight,
    /// All three.
    All,
}

impl CorrectArg {
    /// The departures this argument corrects.
    pub fn departures(self) -> Vec<library::DemoDeparture> {
        use library::DemoDeparture as D;
        match self {
            CorrectArg::Light => vec![D::LightTurnsWithObject],
            CorrectArg::Normals => vec![D::PositionNormals],
            CorrectArg::Highlight => vec![D::HighlightInObjectColour],
            CorrectArg::All => D::ALL.to_vec(),
        }
    }
}

/// Refuses a render of `job` into a `size` x `size` picture past the memory budget.
fn within_budget(job: &phonglab_core::render::Job<'_>, size: u32) -> Result<()> {
    let (vertices, triangles) = (job.mesh.positions.len() as u64, job.mesh.triangle_count() as u64);
    let what = t!(
        "budget-what-render",
        width = size,
        height = size,
        count = triangles as i64,
        triangles = phonglab_core::locale::grouped(triangles)
    );
    let size = u64::from(size);
    crate::io::budget::check(&what, crate::io::budget::render_bytes(size, size, vertices, triangles))
        .map_err(anyhow::Error::msg)
}

/// Runs `phonglab render`.
pub fn run(a: &RenderArgs) -> Result<()> {
    use phonglab_core::mesh::{sphere, teapot};
    use phonglab_core::render::Renderer;
    use phonglab_core::{Document, ObjectKind, Shading};
    let (object, shading) = (a.object, a.shading);
    let size = a.size as usize;
    let inputs: Vec<&Path> = a.scene.iter().chain(&a.obj).map(PathBuf::as_path).collect();
    crate::io::same_file::refuse_output_onto_input(&[&a.output], &inputs).map_err(anyhow::Error::msg)?;
    crate::io::atomic_write::check_file_destination(&a.output)?;
    let mut notes = Vec::new();
    let bench_scene;
    let bench_mesh;
    let setup;
    let doc_mesh;
    let job = if let Some(frame) = a.bench_frame {
        let object = object.unwrap_or(ObjectKind::Sphere);
        bench_mesh = match object {
            ObjectKind::Sphere => sphere::glu_sphere(1.0, 50, 50),
            ObjectKind::Teapot => teapot::glut_teapot(0.8, 7),
            ObjectKind::Cylinder => (phonglab_core::View { object, ..Default::default() }).mesh(),
            ObjectKind::Obj => {
                bail!(t!("err-bench-frame-obj"))
            }
        };
        bench_scene = presets::bench_scene(frame);
        let mut job = phonglab_core::shaded::bench_job(&bench_scene, &bench_mesh, shading.unwrap_or(Shading::Gouraud));
        job.cull_back = a.cull;
        job.options = EvalOptions::with_pow(a.pow);
        job
    } else {
        let mut doc = match (&a.scene, a.preset.as_deref()) {
            (Some(p), _) => scene_file(p)?,
            (None, Some("phong-demo")) => library::phong_demo_document(),
            (None, Some("worksheet")) | (None, None) => Document::default(),
            (None, Some(other)) => {
                bail!(t!("err-unknown-preset", value = format!("{other:?}"), names = "worksheet, phong-demo"))
            }
        };
        if let Some(o) = object {
            doc.view.object = o;
        }
        if let Some(obj) = &a.obj {
            doc.view.object = ObjectKind::Obj;
            doc.view.obj = Some(obj.display().to_string());
        }
        if let Some(s) = shading {
            doc.view.shading = s;
        }
        if let Some(f) = a.frame {
            doc.view.spin_degrees = 0.5 * f as f64;
        }
        for c in &a.correct {
            for d in c.departures() {
                d.correct(&mut doc);
            }
        }
        doc.validate().context(t!("err-scene-to-render"))?;
        if doc.view.object == ObjectKind::Obj {
            // The scene's own mesh is an input too.
            let mesh = doc.view.obj.as_deref().map(Path::new);
            crate::io::same_file::refuse_output_onto_input(&[&a.output], mesh.as_slice())
                .map_err(anyhow::Error::msg)?;
            notes = doc.view.obj_mesh()?.notes.clone();
        }
        doc_mesh = doc.view.mesh();
        setup = doc.shaded_setup(a.pow);
        let mut job = setup.job(&doc_mesh);
        job.cull_back = a.cull;
        job
    };
    within_budget(&job, a.size)?;
    let mut r = Renderer::new();
    let t = std::time::Instant::now();
    let (img, stats) = r.render(&job, size, size)?;
    let ms = t.elapsed().as_secs_f64() * 1e3;
    crate::io::image::write_png(&a.output, img.width, img.height, &img.rgba)?;
    eprintln!(
        "{}",
        phonglab_core::t!(
            "render-summary",
            path = a.output.display().to_string(),
            size = format!("{}x{}", img.width, img.height),
            triangles = stats.triangles,
            covered = phonglab_core::locale::decimal(&format!("{:.1}", 100.0 * img.coverage())),
            evaluations = stats.evaluations,
            ms = phonglab_core::locale::decimal(&format!("{ms:.1}"))
        )
    );
    for note in notes {
        eprintln!("{}", phonglab_core::t!("note-line", note = note));
    }
    Ok(())
}
