//! `phonglab render`: the shaded view (sphere, teapot, cylinder or a mesh) to a PNG.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};
use glam::DMat4;
use phonglab_core::channels::{self, Channel, ColourMap};
use phonglab_core::mesh::Mesh;
use phonglab_core::render::{Job, Renderer};
use phonglab_core::{EvalOptions, ObjectKind, PowFn, Scene, Shading, ShadingMode, library, presets};

use super::scene_file;
use crate::t;

/// What to draw, shared by `render` and `probe`: a scene (file, preset or the benchmark's
/// frame), its object and shading, the picture's size.
#[derive(Args, Debug)]
pub struct ShadedInput {
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

/// `phonglab render`.
#[derive(Args, Debug)]
pub struct RenderArgs {
    /// What to draw.
    #[command(flatten)]
    pub input: ShadedInput,
    /// The PNG to write.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Draw one term of the lighting equation in false colour instead of the picture.
    #[arg(long, value_enum, value_name = "NAME")]
    pub channel: Option<Channel>,
    /// The channel's light, by its place among the enabled lights (0 the first); the
    /// colour terms sum every light when it is left out.
    #[arg(long, value_name = "I", requires = "channel")]
    pub light: Option<usize>,
    /// The false colour's map.
    #[arg(long, value_enum, default_value = "viridis", requires = "channel")]
    pub colour_map: ColourMap,
    /// Also write the channel's values, unclamped, as a portable float map (PFM).
    #[arg(long, value_name = "FILE.pfm", requires = "channel")]
    pub raw: Option<PathBuf>,
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
fn within_budget(job: &Job<'_>, size: u32) -> Result<()> {
    let (vertices, triangles) = (job.mesh.positions.len() as u64, job.mesh.triangle_count() as u64);
    let what = t!(
        "budget-what-render",
        width = size,
        height = size,
        count = triangles as i64,
        triangles = crate::locale::grouped(triangles)
    );
    let size = u64::from(size);
    crate::io::budget::check(&what, crate::io::budget::render_bytes(size, size, vertices, triangles))
        .map_err(anyhow::Error::msg)
}

/// A scene and mesh ready to draw ([`ShadedInput::load`]): owns what a [`Job`] borrows.
pub struct Loaded {
    scene: Scene,
    mesh: Mesh,
    clip_from_object: DMat4,
    mode: ShadingMode,
    background: [f32; 3],
    cull_back: bool,
    options: EvalOptions,
    /// Notes on the mesh read (an OBJ's repairs).
    pub notes: Vec<String>,
    /// The mesh as GLU draws it inside out, where the object is a GLU quadric (for
    /// `diagnose`'s `quadric-inside`).
    pub inside: Option<Mesh>,
}

impl Loaded {
    /// The job that draws it.
    pub fn job(&self) -> Job<'_> {
        Job {
            scene: &self.scene,
            mesh: &self.mesh,
            clip_from_object: self.clip_from_object,
            mode: self.mode,
            background: self.background,
            cull_back: self.cull_back,
            depth_test: true,
            options: self.options,
        }
    }
}

impl ShadedInput {
    /// Every input file named (the scene, the OBJ), for refusing an output onto one.
    pub fn inputs(&self) -> Vec<(&Path, crate::io::same_file::Input)> {
        use crate::io::same_file::Input;
        let scene = self.scene.iter().map(|p| (p.as_path(), Input::Scene));
        scene.chain(self.obj.iter().map(|p| (p.as_path(), Input::Mesh))).collect()
    }

    /// Reads the scene and builds its mesh; refuses `outputs` that are the scene's own mesh
    /// and a picture past the memory budget.
    pub fn load(&self, outputs: &[&Path]) -> Result<Loaded> {
        let loaded = self.load_unbudgeted(outputs)?;
        within_budget(&loaded.job(), self.size)?;
        Ok(loaded)
    }

    /// [`ShadedInput::load`] without the render's memory budget: for a command that draws
    /// more than one picture and checks its whole need itself, once (`diagnose`), so that
    /// its refusal says all it needs rather than the first picture's share.
    pub fn load_unbudgeted(&self, outputs: &[&Path]) -> Result<Loaded> {
        use phonglab_core::mesh::{sphere, teapot};
        use phonglab_core::{Document, ObjectKind, Shading};
        let (object, shading) = (self.object, self.shading);
        let loaded = if let Some(frame) = self.bench_frame {
            let object = object.unwrap_or(ObjectKind::Sphere);
            let mesh = match object {
                ObjectKind::Sphere => sphere::glu_sphere(1.0, 50, 50),
                ObjectKind::Teapot => teapot::glut_teapot(0.8, 7),
                ObjectKind::Cylinder => (phonglab_core::View { object, ..Default::default() }).mesh(),
                ObjectKind::Obj => {
                    bail!(t!("err-bench-frame-obj"))
                }
            };
            let scene = presets::bench_scene(frame);
            let job = phonglab_core::shaded::bench_job(&scene, &mesh, shading.unwrap_or(Shading::Gouraud));
            let (clip_from_object, mode, background) = (job.clip_from_object, job.mode, job.background);
            let options = EvalOptions::with_pow(self.pow);
            Loaded {
                scene,
                mesh,
                clip_from_object,
                mode,
                background,
                cull_back: self.cull,
                options,
                notes: Vec::new(),
                inside: None,
            }
        } else {
            let mut doc = match (&self.scene, self.preset.as_deref()) {
                (Some(p), _) => scene_file(p)?,
                (None, Some("phong-demo")) => library::phong_demo_document(),
                (None, Some("worksheet") | None) => Document::default(),
                (None, Some(other)) => {
                    bail!(t!("err-unknown-preset", value = format!("{other:?}"), names = "worksheet, phong-demo"))
                }
            };
            if let Some(o) = object {
                doc.view.object = o;
            }
            if let Some(obj) = &self.obj {
                doc.view.object = ObjectKind::Obj;
                doc.view.obj = Some(obj.display().to_string());
            }
            if let Some(s) = shading {
                doc.view.shading = s;
            }
            if let Some(f) = self.frame {
                doc.view.spin_degrees = 0.5 * f as f64;
            }
            for c in &self.correct {
                for d in c.departures() {
                    d.correct(&mut doc);
                }
            }
            doc.validate().context(t!("err-scene-to-render"))?;
            let mut notes = Vec::new();
            if doc.view.object == ObjectKind::Obj {
                // The scene's own mesh is an input too.
                let mesh = doc.view.obj.as_deref().map(|m| (Path::new(m), crate::io::same_file::Input::Mesh));
                crate::io::same_file::refuse_onto(outputs, mesh.as_slice()).map_err(anyhow::Error::msg)?;
                notes.clone_from(&doc.view.obj_mesh()?.notes);
            }
            let mesh = doc.view.mesh();
            let setup = doc.shaded_setup(self.pow);
            let job = setup.job(&mesh);
            let (clip_from_object, mode, background, options) =
                (job.clip_from_object, job.mode, job.background, job.options);
            Loaded {
                scene: setup.scene,
                mesh,
                clip_from_object,
                mode,
                background,
                cull_back: self.cull,
                options,
                notes,
                inside: doc.view.mesh_inside(),
            }
        };
        Ok(loaded)
    }
}

/// Refuses `--light light` on a scene of `count` lights (numbered from 0): a light that is
/// not there would give an empty channel and a picture that says nothing.
fn refuse_missing_light(light: usize, count: usize) -> Result<()> {
    if light >= count {
        bail!(t!("err-no-such-light", light = light, count = count, last = count.saturating_sub(1)));
    }
    Ok(())
}

/// Runs `phonglab render`.
pub fn run(a: &RenderArgs) -> Result<()> {
    let outputs: Vec<&Path> = std::iter::once(a.output.as_path()).chain(a.raw.as_deref()).collect();
    // Onto an input, or the PFM onto the PNG: refused before anything is read.
    crate::io::same_file::refuse_onto(&outputs, &a.input.inputs()).map_err(anyhow::Error::msg)?;
    for o in &outputs {
        crate::io::atomic_write::check_file_destination(o)?;
    }
    let loaded = a.input.load(&outputs)?;
    if let Some(light) = a.light {
        refuse_missing_light(light, loaded.scene.lights.len())?;
    }
    let job = loaded.job();
    let size = a.input.size as usize;
    let mut r = Renderer::new();
    r.keep_visibility(a.channel.is_some());
    let t = std::time::Instant::now();
    let (img, stats) = r.render(&job, size, size)?;
    let ms = t.elapsed().as_secs_f64() * 1e3;
    let (width, height, coverage) = (img.width, img.height, img.coverage());
    match a.channel {
        None => crate::io::image::write_png(&a.output, width, height, &img.rgba)?,
        Some(channel) => {
            let image = channels::channel_image(&r, &job, channel, a.light)?;
            let bg = job.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
            crate::io::image::write_png(&a.output, width, height, &image.false_colour(a.colour_map, bg))?;
            if let Some(raw) = &a.raw {
                crate::io::atomic_write::write(raw, &channels::pfm(&image))?;
            }
            let (lo, hi) = image.range();
            let number = |x: f64| crate::locale::num(x, 4);
            super::say(&t!(
                "render-channel-summary",
                channel = crate::locale::tr(image.message_id),
                map = format!("{:?}", a.colour_map).to_lowercase(),
                low = number(lo),
                high = number(hi)
            ));
        }
    }
    super::say(&t!(
        "render-summary",
        path = crate::io::reasons::shown(&a.output),
        size = format!("{width}x{height}"),
        triangles = stats.triangles,
        covered = crate::locale::decimal(&format!("{:.1}", 100.0 * coverage)),
        evaluations = stats.evaluations,
        ms = crate::locale::decimal(&format!("{ms:.1}"))
    ));
    for note in &loaded.notes {
        super::say(&t!("note-line", note = note));
    }
    Ok(())
}
