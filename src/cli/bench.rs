//! `phonglab bench`: figures measured on this machine, printed as plain columns.
//!
//! - `render`: docs/lighting.md's benchmark scene (512x512, gluPerspective(40, 1, 0.5, 20), the
//!   object rotating 3 degrees a frame) for each object and shading:
//!   `object shading ms_per_frame triangles coverage` and each stage's ms; `--moving
//!   light` circles the light round the standing object instead.
//! - `lighting`: the general engine against the specialised evaluator on the three scenes
//!   of issue 5: `scene general_ns_per_vertex specialised_ns_per_vertex speedup`.
//! - `ui`: the whole window headless with every panel open, CPU milliseconds per frame for
//!   egui's layout (which includes evaluating the scene and re-rendering the shaded view
//!   when it changed) and for tessellation: `case ui_median ui_p95 tessellate_median
//!   tessellate_p95 total_median`. Painting is the GPU's and is not included.

use crate::platform::clock::Instant;

use anyhow::Result;
use clap::{Args, Subcommand};
use phonglab_core::bench::{Moving, bench_meshes, bench_meshes_with, render_figures_of};
use phonglab_core::lighter::Lighter;
use phonglab_core::presets::{LightingBench, sphere_points};
use phonglab_core::{Engine, EvalOptions, Shading, Vertex};

/// `phonglab bench`.
#[derive(Subcommand, Debug)]
pub enum BenchCommand {
    /// ms per frame of the CPU renderer on the benchmark scene.
    Render(RenderBench),
    /// ns per vertex of the general and the specialised lighting.
    Lighting(LightingBenchArgs),
    /// CPU time per frame of the whole UI, headless, with every panel open.
    Ui(UiBenchArgs),
}

/// `phonglab bench ui`.
#[derive(Args, Debug)]
pub struct UiBenchArgs {
    /// Frames timed per case.
    #[arg(long, default_value_t = 200)]
    pub frames: u32,
    /// Window width in points.
    #[arg(long, default_value_t = 1440.0)]
    pub width: f32,
    /// Window height in points.
    #[arg(long, default_value_t = 900.0)]
    pub height: f32,
    /// Presentation mode (large type, the controls drawer out) at 1920x1080 unless a size
    /// is given: the light is dragged with Gouraud and then with Phong shading.
    #[arg(long)]
    pub present: bool,
}

/// `phonglab bench render`.
#[derive(Args, Debug)]
pub struct RenderBench {
    /// Frames timed per object and shading (after 5 warm-up frames).
    #[arg(long, default_value_t = 200)]
    pub frames: u32,
    /// Image size in pixels (square).
    #[arg(long, default_value_t = 512)]
    pub size: usize,
    /// Worker threads (default: one per core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Only this object: sphere or teapot (default: both).
    #[arg(long)]
    pub object: Option<String>,
    /// Only this shading: gouraud, phong or flat (default: all three).
    #[arg(long)]
    pub shading: Option<String>,
    /// The sphere's slices and stacks, 3 to 2048 (the benchmark's is 50): the cost against
    /// the triangle count.
    #[arg(long, visible_alias = "sphere", default_value_t = 50)]
    pub slices: u32,
    /// Time this OBJ mesh (fitted to the view) instead of the sphere and the teapot.
    #[arg(long, value_name = "FILE", conflicts_with = "scan")]
    pub mesh: Option<std::path::PathBuf>,
    /// Time the scan-like mesh of 20 x 4^LEVEL triangles (a bumpy, irregular subdivided
    /// icosahedron; 8 gives 1 310 720) instead of the sphere and the teapot.
    #[arg(long, value_name = "LEVEL")]
    pub scan: Option<u32>,
    /// Write the mesh that would be timed (`--mesh`, `--scan` or the sphere of `--slices`,
    /// as placed in the benchmark's view) as an OBJ file, and time nothing: the very vertex
    /// arrays for Mesa's harness (`benches/compare_llvmpipe.py`).
    #[arg(long, value_name = "FILE.obj")]
    pub write_mesh: Option<std::path::PathBuf>,
    /// What changes from frame to frame: `object` (it turns 3 degrees a frame, every frame
    /// drawn whole) or `light` (it circles the standing object, as when a student drags
    /// it: the visibility is kept and only lighting and shading run again).
    #[arg(long, value_name = "WHAT", default_value = "object", value_parser = ["object", "light"])]
    pub moving: String,
    /// Time the coarse copy of about this many triangles instead of the mesh itself: what
    /// the app draws while the camera turns over a very large mesh (it says how long the
    /// copy took to make).
    #[arg(long, value_name = "TRIANGLES")]
    pub coarse: Option<usize>,
}

/// A mesh fitted to the view (radius 0.5) made as large as the benchmark's sphere (radius
/// 1), so that it covers about as many pixels.
fn as_large_as_the_sphere(mut mesh: phonglab_core::mesh::Mesh) -> phonglab_core::mesh::Mesh {
    for p in &mut mesh.positions {
        *p *= 2.0;
    }
    mesh
}

/// `phonglab bench lighting`.
#[derive(Args, Debug)]
pub struct LightingBenchArgs {
    /// Vertices per scene.
    #[arg(long, default_value_t = 1_000_000)]
    pub vertices: usize,
    /// Timed repetitions (the best is reported).
    #[arg(long, default_value_t = 5)]
    pub repeats: u32,
    /// Also say where the specialised lighting's time goes: ns per vertex for loading,
    /// each stage of the scene's program, and writing.
    #[arg(long)]
    pub stages: bool,
}

fn render(a: &RenderBench) -> Result<()> {
    for name in a.object.iter().filter(|_| a.mesh.is_none() && a.scan.is_none()) {
        if !bench_meshes().iter().any(|(n, _)| n == name) {
            anyhow::bail!(crate::t!("err-bench-object", value = name));
        }
    }
    if let Some(name) = &a.shading
        && !Shading::ALL.iter().any(|s| s.label().eq_ignore_ascii_case(name))
    {
        anyhow::bail!(crate::t!("err-bench-shading", value = name));
    }
    if !(3..=2048).contains(&a.slices) {
        anyhow::bail!(crate::t!("err-bench-slices", value = a.slices.to_string()));
    }
    let chosen = a.mesh.is_some() || a.scan.is_some();
    let object_chosen = |object: &str| chosen || a.object.as_deref().is_none_or(|o| o == object);
    let only = |object: &str, shading: Shading| {
        object_chosen(object) && a.shading.as_deref().is_none_or(|s| shading.label().eq_ignore_ascii_case(s))
    };
    if let Some(out) = &a.write_mesh {
        use crate::io::same_file::{Input, refuse_onto};
        let inputs: Vec<(&std::path::Path, Input)> = a.mesh.iter().map(|p| (p.as_path(), Input::Mesh)).collect();
        refuse_onto(&[out], &inputs).map_err(anyhow::Error::msg)?;
        crate::io::atomic_write::check_file_destination(out)?;
    }
    let meshes: Vec<(&'static str, phonglab_core::mesh::Mesh)> = if let Some(path) = &a.mesh {
        vec![(
            "mesh",
            as_large_as_the_sphere(phonglab_core::mesh::obj::load_obj(path).map_err(anyhow::Error::msg)?.mesh),
        )]
    } else if let Some(level) = a.scan {
        if level > 9 {
            anyhow::bail!(crate::t!("err-bench-scan", value = level.to_string()));
        }
        vec![("scan", as_large_as_the_sphere(phonglab_core::mesh::bumpy_sphere::bumpy_sphere(level, 1)))]
    } else {
        bench_meshes_with(a.slices).into()
    };
    let meshes = match a.coarse {
        Some(target) => meshes
            .into_iter()
            .filter(|(name, _)| object_chosen(name))
            .map(|(name, mesh)| {
                let t = Instant::now();
                let copy = phonglab_core::mesh::coarse::clustered(&mesh, target);
                println!(
                    "# {}",
                    crate::t!(
                        "bench-coarse-made",
                        object = name,
                        triangles = copy.triangle_count().to_string(),
                        all = mesh.triangle_count().to_string(),
                        ms = format!("{:.1}", t.elapsed().as_secs_f64() * 1e3)
                    )
                );
                (name, copy)
            })
            .collect(),
        None => meshes,
    };
    if let Some(out) = &a.write_mesh {
        return write_mesh(out, &meshes[0].1);
    }
    println!(
        "# {}",
        crate::t!(
            "bench-render-header",
            size = a.size.to_string(),
            frames = a.frames.to_string(),
            threads = rayon::current_num_threads().to_string()
        )
    );
    println!(
        "object shading ms_per_frame triangles coverage vertices_ms setup_ms raster_ms resolve_ms moving frames_kept"
    );
    let moving = if a.moving == "light" { Moving::Light } else { Moving::Object };
    for f in render_figures_of(meshes, a.frames, a.size, moving, only)? {
        let [v, s, r, res] = f.stage_ms;
        println!(
            "{} {} {:.3} {} {:.4} {v:.3} {s:.3} {r:.3} {res:.3} {} {}",
            f.object,
            f.shading.label().to_lowercase(),
            f.ms_per_frame,
            f.triangles,
            f.coverage,
            a.moving,
            f.frames_kept
        );
    }
    Ok(())
}

/// `bench render --write-mesh`: the timed mesh as OBJ text, written whole or not at all.
/// (Checked not to be the input before anything was read.)
fn write_mesh(out: &std::path::Path, mesh: &phonglab_core::mesh::Mesh) -> Result<()> {
    crate::io::atomic_write::write(out, phonglab_core::mesh::obj_text::obj_text(mesh).as_bytes())?;
    println!(
        "{}",
        crate::t!(
            "bench-mesh-written",
            path = crate::io::reasons::shown(out),
            triangles = mesh.triangle_count().to_string(),
            vertices = mesh.positions.len().to_string()
        )
    );
    Ok(())
}

/// The arrays `bench lighting` lights: `vertices` points of the unit sphere with their
/// normals, and room for their colours.
struct LightingArrays {
    pos: Vec<glam::Vec3>,
    nrm: Vec<glam::Vec3>,
    out: Vec<[f32; 4]>,
}

impl LightingArrays {
    fn new(vertices: usize) -> Self {
        let (pos, nrm) = sphere_points(vertices);
        LightingArrays { pos, nrm, out: vec![[0.0f32; 4]; vertices] }
    }
}

/// One figure of `bench lighting`: ns per vertex, general and specialised.
pub fn lighting_figures(vertices: usize, repeats: u32) -> Result<Vec<(&'static str, f64, f64)>> {
    scene_figures(&mut LightingArrays::new(vertices), repeats)
}

fn scene_figures(arrays: &mut LightingArrays, repeats: u32) -> Result<Vec<(&'static str, f64, f64)>> {
    let LightingArrays { pos, nrm, out: out_buf } = arrays;
    let vertices = pos.len();
    let verts: Vec<Vertex> = pos.iter().zip(nrm.iter()).map(|(p, n)| Vertex::from_f32(*p, *n)).collect();
    let best = |f: &mut dyn FnMut()| {
        (0..repeats.max(1))
            .map(|_| {
                let t = Instant::now();
                f();
                t.elapsed().as_secs_f64()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let mut figures = Vec::new();
    for b in LightingBench::ALL {
        let scene = b.scene();
        let engine = Engine::<f32>::new(&scene)?;
        let lighter = Lighter::new(&scene, EvalOptions::default())?;
        let mut sink = 0.0f32;
        let general = best(&mut || {
            for v in &verts {
                sink += engine.light(v).front.primary[0];
            }
        });
        let special = best(&mut || lighter.light_batch_sum(pos, nrm, out_buf, None));
        std::hint::black_box(sink);
        figures.push((b.name(), general * 1e9 / vertices as f64, special * 1e9 / vertices as f64));
    }
    Ok(figures)
}

fn lighting(a: &LightingBenchArgs) -> Result<()> {
    println!(
        "# {}",
        crate::t!("bench-lighting-header", vertices = a.vertices.to_string(), repeats = a.repeats.to_string())
    );
    println!("scene general_ns_per_vertex specialised_ns_per_vertex speedup");
    let mut arrays = LightingArrays::new(a.vertices);
    for (name, g, s) in scene_figures(&mut arrays, a.repeats)? {
        println!("{name} {g:.2} {s:.2} {:.1}", g / s);
    }
    let (ns, gbs) = memory_floor(&mut arrays, a.repeats);
    println!(
        "# {}",
        crate::t!(
            "bench-memory-floor",
            ns = crate::locale::decimal(&format!("{ns:.2}")),
            gbs = crate::locale::decimal(&format!("{gbs:.1}")),
            bytes = MOVED.to_string()
        )
    );
    if a.stages {
        stage_figures(&mut arrays, a.repeats)?;
    }
    Ok(())
}

/// Bytes a vertex moves through memory in `bench lighting`: its position and normal in
/// (2 x 12, f32) and its colour out (16).
const MOVED: usize = 40;

/// The memory floor of `bench lighting`: the time to read the same positions and normals
/// and write the same colour array with no lighting at all (one add per component), in ns
/// per vertex, and the bandwidth that is (the best of `repeats`). Lighting cannot go below
/// it; how far above it a scene is says how much is arithmetic.
fn memory_floor(arrays: &mut LightingArrays, repeats: u32) -> (f64, f64) {
    let LightingArrays { pos, nrm, out } = arrays;
    let best = (0..repeats.max(1))
        .map(|_| {
            let t = Instant::now();
            for ((o, p), n) in out.iter_mut().zip(pos.iter()).zip(nrm.iter()) {
                *o = [p.x + n.x, p.y + n.y, p.z + n.z, 1.0];
            }
            std::hint::black_box(&mut *out);
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min);
    let ns = best * 1e9 / pos.len() as f64;
    (ns, MOVED as f64 / ns)
}

/// Where the specialised lighting's time goes, per scene: ns per vertex of each step of its
/// program (the run with the least total of `repeats`).
fn stage_figures(arrays: &mut LightingArrays, repeats: u32) -> Result<()> {
    let LightingArrays { pos, nrm, out: out_buf } = arrays;
    let vertices = pos.len();
    println!("# {}", crate::t!("bench-stages-header"));
    println!("scene step ns_per_vertex");
    for b in LightingBench::ALL {
        let lighter = Lighter::new(&b.scene(), EvalOptions::default())?;
        let total = |t: &phonglab_core::lighter::StageTimes| {
            t.load + t.write + t.stages.iter().map(|(_, d)| *d).sum::<std::time::Duration>()
        };
        let best = (0..repeats.max(1))
            .map(|_| lighter.light_batch_timed(pos, nrm, out_buf))
            .min_by_key(total)
            .expect("at least one run");
        let ns = |d: std::time::Duration| d.as_secs_f64() * 1e9 / vertices as f64;
        println!("{} load {:.2}", b.name(), ns(best.load));
        for (stage, d) in &best.stages {
            println!("{} {stage} {:.2}", b.name(), ns(*d));
        }
        println!("{} write {:.2}", b.name(), ns(best.write));
        println!("{} total {:.2}", b.name(), ns(total(&best)));
    }
    Ok(())
}

/// Runs `phonglab bench ...`.
pub fn run(cmd: &BenchCommand) -> Result<()> {
    match cmd {
        BenchCommand::Render(a) => {
            let threads = crate::platform::threads::asked(a.threads).map_err(anyhow::Error::msg)?;
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build()?;
            pool.install(|| render(a))
        }
        BenchCommand::Lighting(a) => lighting(a),
        // The binary hands it to the window (`crate::app`), which it draws.
        BenchCommand::Ui(_) => anyhow::bail!(crate::t!("err-needs-window")),
    }
}
