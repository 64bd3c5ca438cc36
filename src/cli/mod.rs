//! The command line: `phonglab <subcommand>` works headless and never opens a window.
//!
//! The doc comments below describe the arguments to readers of the code; what a user reads
//! in `--help` comes from the message catalogue, in their language ([`crate::cli::help`]).

pub mod arg_errors;
pub mod bench;
pub mod case;
pub mod check;
pub mod check_class;
pub mod class_chart;
pub mod cost;
pub mod diagnose;
pub mod eval;
pub mod exercise;
pub mod explain;
pub mod export;
pub mod help;
pub mod probe;
pub mod render;
pub mod screenshot;
pub mod shader;
pub mod share;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand};

use crate::t;

/// What `phonglab --version` prints after the name: the crate's version and the commit it
/// was built from (`git rev-parse --short HEAD` at build time; "unknown" without git).
pub const VERSION: &str = concat!(env!("CARGO_PKG_VERSION"), " (", env!("PHONGLAB_COMMIT"), ")");

/// phonglab: OpenGL's fixed-function vertex lighting, step by step. Without a subcommand it
/// opens the explorer window on the worksheet's scene.
#[derive(Parser, Debug)]
#[command(name = "phonglab", version = VERSION, about)]
pub struct Cli {
    /// What to do; omit to open the app.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// A scene file (TOML), or a shared scene's link (https://…#v1.…), to open the app on;
    /// one that cannot be read opens the worksheet and says why (a word without a dot that
    /// names no file is taken for a mistyped command).
    pub file: Option<PathBuf>,
    /// Who draws the app's shaded view: auto (the GPU when the adapter is a real one), cpu
    /// (the reference renderer) or gpu (the scene's generated WGSL, even on a software
    /// adapter).
    #[arg(long, value_enum, default_value_t = RendererArg::Auto)]
    pub renderer: RendererArg,
    /// The language of what phonglab says: en, pt-PT or pt-BR (default: the system's:
    /// LC_ALL, LC_MESSAGES or LANG where one is set, else on Windows the user's display
    /// language and on macOS their preferred language). JSON, CSV and scene files keep
    /// English keys.
    #[arg(long, global = true, value_parser = parse_lang)]
    pub lang: Option<crate::locale::Lang>,
    /// How numbers meant for people are written: point (0.5) or comma (0,5); default: the
    /// language's (a comma in Portuguese). Typed numbers are read with either.
    #[arg(long, global = true, value_parser = parse_decimal)]
    pub decimal: Option<crate::locale::DecimalMark>,
    /// The memory a command may take for what it is asked (a picture's size, a mesh):
    /// 512M, 8G, ...; default: half of what the system has available. Past it, a command
    /// says how much it needs and does not start.
    #[arg(long, global = true, value_name = "SIZE", allow_hyphen_values = true, value_parser = crate::io::budget::parse_asked)]
    pub memory_budget: Option<crate::io::budget::Asked>,
}

fn parse_lang(s: &str) -> Result<crate::locale::Lang, String> {
    crate::locale::Lang::parse(s).ok_or_else(|| t!("err-lang", value = format!("{s:?}")))
}

fn parse_decimal(s: &str) -> Result<crate::locale::DecimalMark, String> {
    crate::locale::DecimalMark::parse(s).ok_or_else(|| t!("err-decimal", value = format!("{s:?}")))
}

impl Cli {
    /// Parses the command line with its help in the language asked for (`--lang`, before
    /// parsing, or the system's): every text of `--help` comes from the catalogue
    /// ([`crate::cli::help`]).
    pub fn parse_localised() -> Cli {
        use clap::{CommandFactory, FromArgMatches};
        // Not `std::env::args`, which stops the program on an argument that is not UTF-8.
        let args: Vec<String> = std::env::args_os().map(|a| a.to_string_lossy().into_owned()).collect();
        let asked = args
            .iter()
            .enumerate()
            .find_map(|(i, a)| match a.strip_prefix("--lang=") {
                Some(v) => Some(v.to_string()),
                None => (a == "--lang").then(|| args.get(i + 1).cloned()).flatten(),
            })
            .and_then(|v| crate::locale::Lang::parse(&v));
        let lang = asked.unwrap_or_else(crate::platform::language::system);
        crate::locale::set_default(crate::locale::Locale::of(lang));
        let mut cmd = crate::cli::help::localised(Cli::command());
        // The command the line names, for where its help is.
        let command = args.iter().skip(1).find(|a| cmd.get_subcommands().any(|s| s.get_name() == a.as_str())).cloned();
        let command = command.as_deref();
        let matches = cmd.try_get_matches_from_mut(std::env::args_os()).unwrap_or_else(|e| exit_escaped(&e, command));
        if let Some(("help", asked)) = matches.subcommand() {
            let names: Vec<&String> = asked.get_many::<String>("command").into_iter().flatten().collect();
            // `phonglab help exercises` (or `help bench rendr`): no such command, said as
            // `phonglab exercises --x` is, with the closest of the command before it.
            let mut parent = cmd.clone();
            for name in &names {
                match parent.find_subcommand(name.as_str()) {
                    Some(sub) => parent = sub.clone(),
                    None => {
                        exit_escaped(&arg_errors::unknown_command(&mut parent, name, "arg-error-unknown-command"), None)
                    }
                }
            }
            crate::cli::help::print_help_of(&mut cmd, names.into_iter());
            std::process::exit(0);
        }
        let mut cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| exit_escaped(&e, command));
        // `phonglab exercicios`: a word that is no file is a mistyped command, not a scene to
        // open the window on (which said why only in the window).
        if let (None, Some(word)) = (&cli.command, cli.file.as_ref().and_then(|f| mistyped_command(f))) {
            exit_escaped(&arg_errors::unknown_command(&mut cmd, &word, "arg-error-unknown-command-or-file"), None);
        }
        if let (Some(Command::Exercise(a)), Some(("exercise", m))) = (&mut cli.command, matches.subcommand()) {
            a.count_given = m.value_source("count") == Some(clap::parser::ValueSource::CommandLine);
        }
        cli
    }

    /// The locale the command line asks for: `--lang` over the system's, `--decimal` over
    /// the language's own mark.
    pub fn locale(&self) -> crate::locale::Locale {
        use crate::locale::Locale;
        let lang = self.lang.unwrap_or_else(crate::platform::language::system);
        Locale { lang, decimal: self.decimal.unwrap_or(lang.decimal_mark()) }
    }
}

/// Ends the program on clap's error `e` as clap would (its exit code, help and version on
/// the standard output), but said in the catalogue's words where its kind is a common one
/// ([`arg_errors`]), and otherwise with what it echoes of the command line (a bad value,
/// an unknown option) written visibly where it holds control characters.
/// `file`, given where a scene file goes, as the command it mistypes: a bare word (no
/// folder, no extension, not a link) that names nothing. A scene file always has a `.`
/// (`scene.toml`) and a link a `:`; a word like `exercicios` opened the window on the
/// worksheet with the error only there.
fn mistyped_command(file: &std::path::Path) -> Option<String> {
    let word = file.to_str()?;
    let bare = !word.is_empty() && !word.contains(['.', ':', '/', '\\']);
    (bare && std::fs::symlink_metadata(file).is_err()).then(|| word.to_string())
}

fn exit_escaped(e: &clap::Error, command: Option<&str>) -> ! {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        e.exit()
    }
    match arg_errors::message(e, command) {
        Some(said) => eprint!("{said}"),
        None => eprint!("{}", phonglab_core::escape::terminal::lines(&e.render().to_string())),
    }
    std::process::exit(e.exit_code())
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
    Eval(eval::EvalArgs),
    /// Print the worked calculation of a vertex, step by step, in the worksheet's order.
    Explain(explain::ExplainArgs),
    /// Render the shaded view (sphere, teapot or cylinder) to a PNG.
    Render(render::RenderArgs),
    /// Why one pixel of the shaded view is its colour: its triangle, weights, vertices or
    /// fragment, every term, the clamp and the 8-bit rounding.
    Probe(probe::ProbeArgs),
    /// Write exercise sheets in the worksheet's style, with scene files and answer keys.
    Exercise(exercise::ExerciseArgs),
    /// Print the shader (GLSL 3.30 or WGSL) that draws a scene's shaded view: only the stages it needs.
    Shader(shader::ShaderArgs),
    /// Write scene files as glref cases (JSON), to check them against a real OpenGL with
    /// the Mesa harness (`glref.py CASES.json OUT.json`) or with `phonglab eval`.
    Case(case::CaseArgs),
    /// What accuracy costs: each shading and tessellation, f32 against f64 and the usual
    /// approximations, timed and compared with a per-pixel f64 reference; writes
    /// cost.csv and cost.png.
    Cost(cost::CostArgs),
    /// A student's picture of a scene, checked: right, which mistake made it, or none
    /// phonglab knows; a difference image and the probe where it differs most.
    Diagnose(diagnose::DiagnoseArgs),
    /// Measure: the renderer, the lighting.
    #[command(subcommand)]
    Bench(bench::BenchCommand),
    /// Draw the whole window headless (no display, no GPU) to a PNG: for slides, handouts
    /// and the tests.
    Screenshot(screenshot::ScreenshotArgs),
    /// Write a scene as the student's own code: the worksheet's notebook, a PyOpenGL
    /// program, an openFrameworks app, or the GLSL.
    Export(export::ExportArgs),
    /// Read a worksheet-style notebook (.ipynb) or Python script (.py) into a scene file.
    Import(export::ImportArgs),
    /// Check a student's work: each printed step against the key, the first wrong step and
    /// its likely causes; a folder: the whole class.
    Check(check::CheckArgs),
    /// A scene as a link to the browser build (the scene in the link itself), and as a QR
    /// code for a class.
    Share(share::ShareArgs),
}

/// Runs a subcommand; the exit code is 0 on success, 2 on input that cannot be used, 1
/// when `eval` evaluated a file some of whose cases failed, and when `check` or `diagnose`
/// found the work wrong ([`judged`]).
pub fn run(command: Command) -> ExitCode {
    let r = match command {
        Command::Eval(a) => {
            return eval::run(&a).unwrap_or_else(|e| {
                eprintln!("phonglab: {}", phonglab_core::escape::terminal::lines(&format!("{e:#}")));
                ExitCode::from(2)
            });
        }
        Command::Explain(a) => explain::run(&a),
        Command::Exercise(a) => exercise::run(&a),
        Command::Shader(a) => shader::run(&a),
        Command::Bench(b) => bench::run(&b),
        Command::Render(a) => render::run(&a),
        Command::Probe(a) => probe::run(&a),
        Command::Diagnose(a) => return judged(diagnose::run(&a)),
        Command::Case(a) => case::run(&a),
        Command::Cost(a) => cost::run_args(&a),
        // The binary hands it to the window (`crate::app`), which it draws.
        Command::Screenshot(_) => Err(anyhow::anyhow!(t!("err-needs-window"))),
        Command::Export(a) => export::export(&a),
        Command::Import(a) => export::import(&a),
        Command::Check(a) => return judged(check::run(&a)),
        Command::Share(a) => share::run(&a),
    };
    finish(r)
}

/// A command stopped by Ctrl+C, or by the system asking it to end (a logout, `kill`), says
/// so on the standard error in the user's language before it ends with the code a shell
/// expects (130 for Ctrl+C: [`crate::platform::os::stopped_by`]), instead of vanishing
/// without a word. What it says holds because every file is written whole or not at all
/// (`io::atomic_write`; a set of files is finished or put back by the next run's journal).
/// Called once, before the command starts; the window has its own handler (it saves the
/// session).
pub fn say_when_stopped() {
    let (ctrl_c, asked) = (t!("cli-stopped", how = "ctrl-c"), t!("cli-stopped", how = "asked"));
    let installed = crate::platform::os::on_termination(move |event| {
        let (by_ctrl_c, code) = crate::platform::os::stopped_by(event);
        say(&format!("phonglab: {}", if by_ctrl_c { &ctrl_c } else { &asked }));
        std::process::exit(code);
    });
    match installed {
        Ok(()) => log::debug!("a command stopped by Ctrl+C says so"),
        Err(e) => log::debug!("a command stopped by Ctrl+C ends without a word: {e}"),
    }
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

/// The exit code of a command that judges a student's work (`check`, `diagnose`), for
/// scripts and autograders: 0 when it is right (or a class's report was written), 1 when
/// it is wrong, unchecked or unexplained, 2 on a usage or input error ([`finish`]).
pub fn judged(r: Result<bool>) -> ExitCode {
    match r {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => finish(Err(e)),
    }
}

/// Says `text` on the standard error, as every line a command says for a person: its
/// control characters written visibly (a file's name, a quoted line), its own line breaks
/// kept.
pub fn say(text: &str) {
    eprintln!("{}", phonglab_core::escape::terminal::lines(text));
}

/// Reads and checks a scene file (what several commands read).
fn scene_file(path: &Path) -> Result<phonglab_core::Document> {
    crate::io::input_file::load_scene(path).map_err(anyhow::Error::msg)
}
