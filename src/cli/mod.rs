//! The command line: `phonglab <subcommand>` works headless and never opens a window.
//!
//! The doc comments below describe the arguments to readers of the code; what a user reads
//! in `--help` comes from the message catalogue, in their language ([`crate::cli::help`]).

pub mod bench;
pub mod cost;
pub mod exercise;
pub mod export;
pub mod help;
pub mod screenshot;

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result, bail};
use clap::{Args, Parser, Subcommand, ValueEnum};
use phonglab_core::explain::{Side, explain};
use phonglab_core::glref::{self, CaseColors};
use phonglab_core::{Engine, EvalOptions, PowFn, Real, Scene, library, presets, t};

/// phonglab: OpenGL's fixed-function vertex lighting, step by step. Without a subcommand it
/// opens the explorer window on the worksheet's scene.
#[derive(Parser, Debug)]
#[command(name = "phonglab", version, about)]
pub struct Cli {
    /// What to do; omit to open the app.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// A scene file (TOML) to open the app on; one that cannot be read opens the worksheet
    /// and says why.
    pub file: Option<PathBuf>,
    /// Who draws the app's shaded view: auto (the GPU when the adapter is a real one), cpu
    /// (the reference renderer) or gpu (the scene's generated WGSL, even on a software
    /// adapter).
    #[arg(long, value_enum, default_value_t = RendererArg::Auto)]
    pub renderer: RendererArg,
    /// The language of what phonglab says: en, pt-PT or pt-BR (default: the system's, from
    /// LC_ALL, LC_MESSAGES or LANG). JSON, CSV and scene files keep English keys.
    #[arg(long, global = true, value_parser = parse_lang)]
    pub lang: Option<phonglab_core::locale::Lang>,
    /// How numbers meant for people are written: point (0.5) or comma (0,5); default: the
    /// language's (a comma in Portuguese). Typed numbers are read with either.
    #[arg(long, global = true, value_parser = parse_decimal)]
    pub decimal: Option<phonglab_core::locale::DecimalMark>,
    /// The memory a command may take for what it is asked (a picture's size, a mesh):
    /// 512M, 8G, ...; default: half of what the system has available. Past it, a command
    /// says how much it needs and does not start.
    #[arg(long, global = true, value_name = "SIZE", value_parser = crate::io::budget::parse_size)]
    pub memory_budget: Option<u64>,
}

fn parse_lang(s: &str) -> Result<phonglab_core::locale::Lang, String> {
    phonglab_core::locale::Lang::parse(s).ok_or_else(|| t!("err-lang", value = format!("{s:?}")))
}

fn parse_decimal(s: &str) -> Result<phonglab_core::locale::DecimalMark, String> {
    phonglab_core::locale::DecimalMark::parse(s).ok_or_else(|| t!("err-decimal", value = format!("{s:?}")))
}

impl Cli {
    /// Parses the command line with its help in the language asked for (`--lang`, before
    /// parsing, or the system's): every text of `--help` comes from the catalogue
    /// ([`crate::cli::help`]).
    pub fn parse_localised() -> Cli {
        use clap::{CommandFactory, FromArgMatches};
        let args: Vec<String> = std::env::args().collect();
        let asked = args
            .iter()
            .enumerate()
            .find_map(|(i, a)| match a.strip_prefix("--lang=") {
                Some(v) => Some(v.to_string()),
                None => (a == "--lang").then(|| args.get(i + 1).cloned()).flatten(),
            })
            .and_then(|v| phonglab_core::locale::Lang::parse(&v));
        let lang = asked.unwrap_or_else(phonglab_core::locale::Lang::from_env);
        phonglab_core::locale::set_default(phonglab_core::locale::Locale::of(lang));
        let mut cmd = crate::cli::help::localised(Cli::command());
        let matches = cmd.get_matches_mut();
        if let Some(("help", asked)) = matches.subcommand() {
            let names = asked.get_many::<String>("command").into_iter().flatten();
            crate::cli::help::print_help_of(&mut cmd, names);
            std::process::exit(0);
        }
        Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
    }

    /// The locale the command line asks for: `--lang` over the system's, `--decimal` over
    /// the language's own mark.
    pub fn locale(&self) -> phonglab_core::locale::Locale {
        use phonglab_core::locale::{Lang, Locale};
        let lang = self.lang.unwrap_or_else(Lang::from_env);
        Locale { lang, decimal: self.decimal.unwrap_or(lang.decimal_mark()) }
    }
}

/// `--renderer`'s values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RendererArg {
    /// The GPU when the adapter is a real one, else the CPU renderer.
    Auto,
    /// The CPU renderer (the reference).
    Cpu,
    /// The GPU, even a software adapter.
    Gpu,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Evaluate glref cases (JSON) and print the lit colours as JSON.
    Eval(EvalArgs),
    /// Print the worked calculation of a vertex, step by step, in the worksheet's order.
    Explain(ExplainArgs),
    /// Render the shaded view (sphere, teapot or cylinder) to a PNG.
    Render(RenderArgs),
    /// Write exercise sheets in the worksheet's style, with scene files and answer keys.
    Exercise(crate::cli::exercise::ExerciseArgs),
    /// Print the shader (GLSL 3.30 or WGSL) that draws a scene's shaded view: only the stages it needs.
    Shader(ShaderArgs),
    /// Write scene files as glref cases (JSON), to check them against a real OpenGL with
    /// the Mesa harness (`glref.py CASES.json OUT.json`) or with `phonglab eval`.
    Case(CaseArgs),
    /// What accuracy costs: each shading and tessellation, f32 against f64 and the usual
    /// approximations, timed and compared with a per-pixel f64 reference; writes
    /// cost.csv and cost.png.
    Cost(CostArgs),
    /// Measure: the renderer, the lighting.
    #[command(subcommand)]
    Bench(crate::cli::bench::BenchCommand),
    /// Draw the whole window headless (no display, no GPU) to a PNG: for slides, handouts
    /// and the tests.
    Screenshot(crate::cli::screenshot::ScreenshotArgs),
    /// Write a scene as the student's own code: the worksheet's notebook, a PyOpenGL
    /// program, an openFrameworks app, or the GLSL.
    Export(crate::cli::export::ExportArgs),
    /// Read a worksheet-style notebook (.ipynb) or Python script (.py) into a scene file.
    Import(crate::cli::export::ImportArgs),
}

/// Floating-point precision of the engine.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum Precision {
    /// Single precision, as OpenGL computes.
    F32,
    /// Double precision.
    F64,
}

/// The power function of the specular and spot terms.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum PowArg {
    /// The exact library pow (default).
    Exact,
    /// Mesa llvmpipe's exp2(e log2 x) approximation, bit-exact with Mesa 22.3.
    Llvmpipe,
    /// Schlick's rational approximation.
    Schlick,
}

impl From<PowArg> for PowFn {
    fn from(p: PowArg) -> Self {
        match p {
            PowArg::Exact => PowFn::Exact,
            PowArg::Llvmpipe => PowFn::Llvmpipe,
            PowArg::Schlick => PowFn::Schlick,
        }
    }
}

/// `phonglab eval`.
#[derive(Args, Debug)]
pub struct EvalArgs {
    /// A JSON file of cases (a list, or {"cases": [...]}), as in docs/lighting.md.
    pub cases: PathBuf,
    /// Engine precision.
    #[arg(long, value_enum, default_value = "f32")]
    pub precision: Precision,
    /// Clamp the colours to [0, 1] as OpenGL does by default (otherwise unclamped).
    #[arg(long)]
    pub clamp: bool,
    /// Power function for the specular and spot terms.
    #[arg(long, value_enum, default_value = "exact")]
    pub pow: PowArg,
}

/// An object of the shaded view.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum ObjectArg {
    /// gluSphere.
    Sphere,
    /// The Utah teapot.
    Teapot,
    /// gluCylinder.
    Cylinder,
}

impl From<ObjectArg> for phonglab_core::ObjectKind {
    fn from(o: ObjectArg) -> Self {
        match o {
            ObjectArg::Sphere => Self::Sphere,
            ObjectArg::Teapot => Self::Teapot,
            ObjectArg::Cylinder => Self::Cylinder,
        }
    }
}

/// A shading.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum ShadingArg {
    /// Per-vertex lighting, colours interpolated.
    Gouraud,
    /// Per-pixel lighting.
    Phong,
    /// One evaluation per face.
    Flat,
}

/// `phonglab shader`.
#[derive(Args, Debug)]
pub struct ShaderArgs {
    /// A scene file (default: the worksheet's, mview5).
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// glsl (3.30 core: a vertex and a fragment shader) or wgsl (one module). (`--lang`
    /// is the language phonglab speaks, on every command.)
    #[arg(long, default_value = "glsl")]
    pub target: String,
    /// gouraud (lit per vertex) or phong (lit per fragment).
    #[arg(long, default_value = "gouraud")]
    pub shading: String,
}

fn shader_cmd(a: &ShaderArgs) -> Result<()> {
    use phonglab_core::shader::{Lang, ShaderShading};
    let doc = match &a.scene {
        Some(p) => load_scene_file(p)?,
        None => phonglab_core::Document::default(),
    };
    let lang = match a.target.as_str() {
        "glsl" => Lang::Glsl,
        "wgsl" => Lang::Wgsl,
        other => bail!(t!("err-target", value = format!("{other:?}"))),
    };
    let shading = match a.shading.as_str() {
        "gouraud" => ShaderShading::Gouraud,
        "phong" => ShaderShading::Phong,
        other => bail!(t!("err-shading", value = format!("{other:?}"))),
    };
    // A scene that does not evaluate is refused with the engine's reason.
    let shader = phonglab_core::shader::for_view(&doc, lang, shading)?;
    print!("{}", shader.text(lang));
    Ok(())
}

/// `phonglab render`.
#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The object (default: the scene's).
    #[arg(long, value_enum)]
    pub object: Option<ObjectArg>,
    /// Shade this Wavefront OBJ mesh instead of the scene's object (fitted to radius 0.5).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["object", "bench_frame"])]
    pub obj: Option<PathBuf>,
    /// The shading (default: the scene's).
    #[arg(long, value_enum)]
    pub shading: Option<ShadingArg>,
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
    pub pow: PowArg,
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

/// `phonglab explain`.
#[derive(Args, Debug)]
pub struct ExplainArgs {
    /// A scene file (TOML), as the app saves it.
    #[arg(conflicts_with_all = ["worksheet", "preset"])]
    pub scene: Option<PathBuf>,
    /// The worksheet's scene with modelview N (1-5). The default when no scene is given: 5.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(1..=5))]
    pub worksheet: Option<u8>,
    /// A ready-made scene instead: "phong-demo".
    #[arg(long, conflicts_with = "worksheet")]
    pub preset: Option<String>,
    /// Engine precision.
    #[arg(long, value_enum, default_value = "f64")]
    pub precision: Precision,
    /// Explain the back side (two-sided lighting).
    #[arg(long)]
    pub back: bool,
    /// Print a Markdown table instead of text.
    #[arg(long)]
    pub markdown: bool,
    /// Significant digits.
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
}

/// `phonglab cost`.
#[derive(Args, Debug)]
pub struct CostArgs {
    /// The object to study (default: all three).
    #[arg(long, value_enum)]
    pub object: Option<ObjectArg>,
    /// Where to write cost.csv, cost.png and the heat maps.
    #[arg(long, default_value = ".")]
    pub out: PathBuf,
    /// Image width and height in pixels.
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
    pub size: u32,
    /// A scene file (TOML) for the lighting and the view; default: the worksheet's scene.
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// Turn the object this many degrees about y (the cylinder shows its side at 30).
    #[arg(long, default_value_t = 30.0)]
    pub spin: f64,
    /// Threads for rendering (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Quick timings (3 frames or 0.1 s per variant) instead of careful ones.
    #[arg(long)]
    pub quick: bool,
}

/// `phonglab case`.
#[derive(Args, Debug)]
pub struct CaseArgs {
    /// Scene files (TOML); each becomes one case, its id the file's stem.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
}

/// Runs a subcommand; the exit code is 0 on success, 2 on input that cannot be used, 1
/// when `eval` evaluated a file some of whose cases failed.
pub fn run(command: Command) -> ExitCode {
    let r = match command {
        Command::Eval(a) => {
            return eval(&a).unwrap_or_else(|e| {
                eprintln!("phonglab: {}", phonglab_core::escape::terminal::lines(&format!("{e:#}")));
                ExitCode::from(2)
            });
        }
        Command::Explain(a) => explain_cmd(&a),
        Command::Exercise(a) => crate::cli::exercise::run(&a),
        Command::Shader(a) => shader_cmd(&a),
        Command::Bench(b) => crate::cli::bench::run(&b),
        Command::Render(a) => render(&a),
        Command::Case(a) => case(&a),
        Command::Cost(a) => cost(&a),
        // The binary hands it to the window (`crate::app`), which it draws.
        Command::Screenshot(_) => Err(anyhow::anyhow!(t!("err-needs-window"))),
        Command::Export(a) => crate::cli::export::export(&a),
        Command::Import(a) => crate::cli::export::import(&a),
    };
    finish(r)
}

/// A command's exit code: 0 when it did what it was asked, else 2 after saying why on the
/// standard error (its control characters written visibly).
pub fn finish(r: Result<()>) -> ExitCode {
    match r {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("phonglab: {}", phonglab_core::escape::terminal::lines(&format!("{e:#}")));
            ExitCode::from(2)
        }
    }
}

fn evaluate(scene: &Scene, precision: Precision, options: EvalOptions, clamp: bool) -> Result<CaseColors, String> {
    let r = match precision {
        Precision::F32 => glref::evaluate::<f32>(scene, options, clamp),
        Precision::F64 => glref::evaluate::<f64>(scene, options, clamp),
    };
    r.map_err(|e| e.to_string())
}

/// `eval`: the results on stdout; exit 1 (after printing them) when any case failed.
fn eval(a: &EvalArgs) -> Result<ExitCode> {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let (all, failed) = eval_stream(&a.cases, a.precision, EvalOptions::with_pow(a.pow.into()), a.clamp, &mut out)?;
    out.flush()?;
    if failed > 0 {
        eprintln!("phonglab: {}", t!("err-cases-failed", failed = failed, all = all));
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// Evaluates the case file at `path` into `out` as `{"results": [...]}` (what `eval`
/// prints): the number of cases and of failed ones.
///
/// The file is read as a stream twice, never whole: once to check that it is a case file
/// (so a broken one writes nothing), then case by case, each result written as it is
/// lit. The memory is one case's (and the ids', to refuse a repeated one), whatever the
/// number of cases.
pub fn eval_stream(
    path: &Path,
    precision: Precision,
    options: EvalOptions,
    clamp: bool,
    out: &mut impl std::io::Write,
) -> Result<(usize, usize)> {
    let open = || -> Result<std::fs::File> {
        // The size cap and the file's kind, checked on the handle; the bytes stream.
        let file = crate::platform::os::open_to_read(path).map_err(|e| {
            anyhow::anyhow!(t!(
                "read-cannot",
                path = path.display().to_string(),
                reason = crate::io::reasons::io_reason(&e)
            ))
        })?;
        let meta = file.metadata()?;
        if !meta.is_file() {
            bail!(t!("read-not-a-file", path = path.display().to_string()));
        }
        let (shown, kind) = (path.display().to_string(), t!("file-kind-cases"));
        crate::io::input_file::within_cap(&shown, meta.len(), crate::io::input_file::MAX_CASE_BYTES, &kind)
            .map_err(anyhow::Error::msg)?;
        Ok(file)
    };
    let not_cases = || format!("{}: {}", path.display(), t!("err-not-case-file"));
    glref::count_cases(open()?).context(not_cases())?;
    let (mut all, mut failed) = (0usize, 0usize);
    let mut write_error = None;
    out.write_all(b"{\n  \"results\": [")?;
    glref::for_each_case(open()?, |id, case| {
        let r = case.map_err(|e| e.to_string()).and_then(|c| evaluate(&c.scene, precision, options, clamp));
        failed += usize::from(r.is_err());
        // serde_json's pretty form of the whole, one result at a time.
        let result = serde_json::to_string_pretty(&glref::result_json(&id, &r)).unwrap_or_default();
        let sep = if all == 0 { "\n" } else { ",\n" };
        all += 1;
        let indented = result.lines().map(|l| format!("    {l}")).collect::<Vec<_>>().join("\n");
        if let Err(e) = write!(out, "{sep}{indented}") {
            write_error.get_or_insert(e);
        }
    })
    .context(not_cases())?;
    if let Some(e) = write_error {
        return Err(e.into());
    }
    out.write_all(if all == 0 { b"]\n}\n" } else { b"\n  ]\n}\n" })?;
    Ok((all, failed))
}

/// Reads and checks a scene file.
pub fn load_scene_file(path: &Path) -> Result<phonglab_core::Document> {
    crate::io::input_file::load_scene(path).map_err(anyhow::Error::msg)
}

/// The scene `explain` works on.
fn explain_scene(a: &ExplainArgs) -> Result<(Scene, String)> {
    if let Some(p) = &a.scene {
        let doc = load_scene_file(p)?;
        let name = if doc.name.is_empty() {
            p.display().to_string()
        } else {
            phonglab_core::library::localised_name(&doc.name)
        };
        return Ok((doc.scene, name));
    }
    if let Some(p) = &a.preset {
        return match p.as_str() {
            "phong-demo" => Ok((presets::phong_demo(), t!("preset-phong-demo"))),
            other => bail!(t!("err-unknown-preset", value = format!("{other:?}"), names = "phong-demo")),
        };
    }
    let n = a.worksheet.unwrap_or(5) as usize;
    Ok((presets::worksheet(n), phonglab_core::t!("doc-worksheet", k = n.to_string())))
}

fn explain_text<S: Real>(scene: &Scene, what: &str, a: &ExplainArgs) -> Result<String> {
    let lit = Engine::<S>::light_scene_vertex(scene)?;
    let ex = explain(scene, &lit, if a.back { Side::Back } else { Side::Front });
    let digits = a.digits as usize;
    Ok(if a.markdown {
        let name = phonglab_core::escape::markdown::text(what);
        format!("# {}\n\n{}", phonglab_core::t!("worked-calculation-of", name = name), ex.to_markdown(digits))
    } else {
        let name = phonglab_core::escape::terminal::text(what);
        format!("{}\n{}", phonglab_core::t!("worked-calculation-of", name = name), ex.to_text(digits))
    })
}

fn explain_cmd(a: &ExplainArgs) -> Result<()> {
    let (scene, what) = explain_scene(a)?;
    let text = match a.precision {
        Precision::F32 => explain_text::<f32>(&scene, &what, a)?,
        Precision::F64 => explain_text::<f64>(&scene, &what, a)?,
    };
    print!("{text}");
    Ok(())
}

/// The scene files as `{"cases": [...]}`.
pub fn cases_json(paths: &[PathBuf]) -> Result<serde_json::Value> {
    let mut cases = Vec::new();
    for p in paths {
        let doc = load_scene_file(p)?;
        if doc.scene.rules != phonglab_core::Rules::OPENGL {
            eprintln!(
                "phonglab: {}",
                phonglab_core::t!(
                    "case-rules-note",
                    path = p.display().to_string(),
                    rules = doc.scene.rules.set.label()
                )
            );
        }
        let id = p.file_stem().map_or_else(|| format!("case{}", cases.len()), |s| s.to_string_lossy().into_owned());
        cases.push(glref::case_json(&id, &doc.scene));
    }
    Ok(serde_json::json!({ "cases": cases }))
}

fn case(a: &CaseArgs) -> Result<()> {
    println!("{}", serde_json::to_string_pretty(&cases_json(&a.scenes)?)?);
    Ok(())
}

fn cost(a: &CostArgs) -> Result<()> {
    if let Some(scene) = &a.scene {
        // The report replaces every file of an earlier report in the folder.
        let mut names: Vec<String> = ["cost.csv", "cost.md", "cost.png"].map(String::from).to_vec();
        let earlier = std::fs::read_dir(&a.out).into_iter().flatten().flatten();
        names.extend(
            earlier
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| crate::cli::cost::belongs_to_a_report(n)),
        );
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        crate::io::same_file::refuse_outputs_in_folder(&a.out, &names, &[scene]).map_err(anyhow::Error::msg)?;
    }
    let doc = match &a.scene {
        Some(p) => load_scene_file(p)?,
        None => phonglab_core::Document::default(),
    };
    crate::cli::cost::run(&crate::cli::cost::CostRun {
        objects: a.object.map_or(phonglab_core::ObjectKind::ALL.to_vec(), |o| vec![o.into()]),
        doc,
        out: a.out.clone(),
        size: a.size as usize,
        spin: a.spin,
        threads: a.threads.unwrap_or(0),
        timing: if a.quick { phonglab_core::cost::Timing::QUICK } else { phonglab_core::cost::Timing::CAREFUL },
    })
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

fn render(a: &RenderArgs) -> Result<()> {
    use phonglab_core::mesh::{sphere, teapot};
    use phonglab_core::render::Renderer;
    use phonglab_core::{Document, ObjectKind, Shading};
    let object = a.object.map(ObjectKind::from);
    let shading = a.shading.map(|s| match s {
        ShadingArg::Gouraud => Shading::Gouraud,
        ShadingArg::Phong => Shading::Phong,
        ShadingArg::Flat => Shading::Flat,
    });
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
        job.options = EvalOptions::with_pow(a.pow.into());
        job
    } else {
        let mut doc = match (&a.scene, a.preset.as_deref()) {
            (Some(p), _) => load_scene_file(p)?,
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
        setup = doc.shaded_setup(a.pow.into());
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
