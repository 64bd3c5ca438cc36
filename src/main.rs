//! phonglab: a desktop explorer for OpenGL's fixed-function vertex lighting, and a CLI;
//! built for the browser (`scripts/web`), the same explorer on a web page.
// Windows: a GUI program, so no console window opens beside the explorer when a student
// double-clicks it; a command typed in a terminal attaches to that terminal to print
// (`platform::os::attach_to_terminal`).
#![cfg_attr(windows, windows_subsystem = "windows")]

#[cfg(not(target_arch = "wasm32"))]
use std::process::ExitCode;

#[cfg(not(target_arch = "wasm32"))]
use phonglab::app::panels::shaded::gpu::RendererChoice;
#[cfg(not(target_arch = "wasm32"))]
use phonglab::cli::{self, RendererArg};

/// In the browser: the app on the page's canvas (see `phonglab::web`).
#[cfg(target_arch = "wasm32")]
fn main() {
    phonglab::app::shell::web::start();
}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    phonglab::platform::os::attach_to_terminal();
    // eframe's and wgpu's warnings reach stderr (RUST_LOG=info or debug for more).
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let args = cli::Cli::parse_localised();
    phonglab::locale::set_default(args.locale());
    if let Err(e) = phonglab::io::budget::set(args.memory_budget) {
        return cli::finish(Err(anyhow::Error::msg(e)));
    }
    match args.command {
        // The two commands that draw the window: the command line reads their arguments,
        // the window draws them (the two layers never name each other; this file joins them).
        Some(cli::Command::Screenshot(a)) => cli::finish(phonglab::app::shell::screenshot::run(&shot(a))),
        Some(cli::Command::Bench(cli::bench::BenchCommand::Ui(a))) => {
            cli::finish(phonglab::app::shell::bench_ui::run(&phonglab::app::shell::bench_ui::UiBench {
                frames: a.frames,
                width: a.width,
                height: a.height,
                present: a.present,
            }))
        }
        Some(command) => {
            phonglab::platform::os::end_quietly_on_closed_pipe();
            cli::say_when_stopped();
            cli::run(command)
        }
        None => match phonglab::app::run(
            args.file,
            match args.renderer {
                RendererArg::Auto => RendererChoice::Auto,
                RendererArg::Cpu => RendererChoice::Cpu,
                RendererArg::Gpu => RendererChoice::Gpu,
            },
        ) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                let error = e.to_string();
                eprintln!(
                    "phonglab: {}",
                    phonglab_core::escape::terminal::lines(&phonglab::locale::tr_args(
                        "app-cannot-open-window",
                        &[("error", error.into())]
                    ))
                );
                ExitCode::from(1)
            }
        },
    }
}

/// `phonglab screenshot`'s arguments as the window's picture request.
#[cfg(not(target_arch = "wasm32"))]
fn shot(a: cli::screenshot::ScreenshotArgs) -> phonglab::app::shell::screenshot::Shot {
    phonglab::app::shell::screenshot::Shot {
        size: a.size,
        scale: a.scale,
        present: a.present,
        light: a.light,
        scene: a.scene,
        open: a.open,
        output: a.output,
    }
}
