//! `phonglab bench`: figures measured on this machine, printed as plain columns.
//!
//! - `render`: DESIGN.md's benchmark scene (512x512, gluPerspective(40, 1, 0.5, 20), the
//!   object rotating 3 degrees a frame) for each object and shading:
//!   `object shading ms_per_frame triangles coverage`.
//! - `lighting`: the general engine against the specialised evaluator on the three scenes
//!   of issue 5: `scene general_ns_per_vertex specialised_ns_per_vertex speedup`.

use std::time::Instant;

use anyhow::Result;
use clap::{Args, Subcommand};
use phonglab_core::mesh::{Mesh, sphere, teapot};
use phonglab_core::presets::{BENCH_BACKGROUND, LightingBench, bench_projection, bench_scene, sphere_points};
use phonglab_core::render::{Job, Renderer};
use phonglab_core::specialised::Lighter;
use phonglab_core::{Engine, EvalOptions, Shading, Vertex};

/// `phonglab bench`.
#[derive(Subcommand, Debug)]
pub enum BenchCommand {
    /// ms per frame of the CPU renderer on the benchmark scene.
    Render(RenderBench),
    /// ns per vertex of the general and the specialised lighting.
    Lighting(LightingBenchArgs),
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
}

/// The benchmark's objects: gluSphere(1, 50, 50) and glutSolidTeapot(0.8).
pub fn bench_meshes() -> [(&'static str, Mesh); 2] {
    [("sphere", sphere::glu_sphere(1.0, 50, 50)), ("teapot", teapot::glut_teapot(0.8, 7))]
}

/// One figure of `bench render`.
pub struct RenderFigure {
    /// "sphere" or "teapot".
    pub object: &'static str,
    /// The shading.
    pub shading: Shading,
    /// Mean milliseconds per frame.
    pub ms_per_frame: f64,
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Share of pixels covered.
    pub coverage: f64,
}

/// Times the renderer on the benchmark scene.
pub fn render_figures(frames: u32, size: usize) -> Result<Vec<RenderFigure>> {
    let mut out = Vec::new();
    for (name, mesh) in bench_meshes() {
        for shading in Shading::ALL {
            let mut r = Renderer::new();
            let frame = |i: u32, r: &mut Renderer| -> Result<f64> {
                let scene = bench_scene(i);
                let job = Job {
                    scene: &scene,
                    mesh: &mesh,
                    clip_from_eye: bench_projection(),
                    shading,
                    background: BENCH_BACKGROUND,
                    cull_back: false,
                    options: EvalOptions::default(),
                };
                let (img, _) = r.render(&job, size, size)?;
                Ok(img.coverage())
            };
            for i in 0..5 {
                frame(i, &mut r)?;
            }
            let t = Instant::now();
            let mut coverage = 0.0;
            for i in 0..frames {
                coverage = frame(i, &mut r)?;
            }
            let ms = t.elapsed().as_secs_f64() * 1e3 / frames.max(1) as f64;
            out.push(RenderFigure {
                object: name,
                shading,
                ms_per_frame: ms,
                triangles: mesh.triangle_count(),
                coverage,
            });
        }
    }
    Ok(out)
}

fn render(a: &RenderBench) -> Result<()> {
    println!(
        "# phonglab bench render: {}x{} px, {} frames, {} threads",
        a.size,
        a.size,
        a.frames,
        rayon::current_num_threads()
    );
    println!("object shading ms_per_frame triangles coverage");
    for f in render_figures(a.frames, a.size)? {
        println!(
            "{} {} {:.3} {} {:.4}",
            f.object,
            f.shading.label().to_lowercase(),
            f.ms_per_frame,
            f.triangles,
            f.coverage
        );
    }
    Ok(())
}

/// One figure of `bench lighting`: ns per vertex, general and specialised.
pub fn lighting_figures(vertices: usize, repeats: u32) -> Result<Vec<(&'static str, f64, f64)>> {
    let (pos, nrm) = sphere_points(vertices);
    let verts: Vec<Vertex> = pos
        .iter()
        .zip(&nrm)
        .map(|(p, n)| Vertex { position: p.as_dvec3().extend(1.0), normal: n.as_dvec3() })
        .collect();
    let mut out_buf = vec![[0.0f32; 4]; vertices];
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
        let special = best(&mut || lighter.light_batch_sum(&pos, &nrm, &mut out_buf, None));
        std::hint::black_box(sink);
        figures.push((b.name(), general * 1e9 / vertices as f64, special * 1e9 / vertices as f64));
    }
    Ok(figures)
}

fn lighting(a: &LightingBenchArgs) -> Result<()> {
    println!("# phonglab bench lighting: {} vertices, best of {}, one thread, f32", a.vertices, a.repeats);
    println!("scene general_ns_per_vertex specialised_ns_per_vertex speedup");
    for (name, g, s) in lighting_figures(a.vertices, a.repeats)? {
        println!("{name} {g:.2} {s:.2} {:.1}", g / s);
    }
    Ok(())
}

/// Runs `phonglab bench ...`.
pub fn run(cmd: &BenchCommand) -> Result<()> {
    match cmd {
        BenchCommand::Render(a) => {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(a.threads.unwrap_or(0)).build()?;
            pool.install(|| render(a))
        }
        BenchCommand::Lighting(a) => lighting(a),
    }
}
