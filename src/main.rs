//! phonglab: a desktop explorer for OpenGL's fixed-function vertex lighting, and a CLI;
//! built for the browser (`scripts/web`), the same explorer on a web page.

#[cfg(not(target_arch = "wasm32"))]
use std::process::ExitCode;

#[cfg(not(target_arch = "wasm32"))]
use phonglab::app::gpu_view::RendererChoice;
#[cfg(not(target_arch = "wasm32"))]
use phonglab::cli::{self, RendererArg};

/// In the browser: the app on the page's canvas (see `phonglab::web`).
#[cfg(target_arch = "wasm32")]
fn main() {
    phonglab::web::start();
}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    // eframe's and wgpu's warnings reach stderr (RUST_LOG=info or debug for more).
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let args = cli::Cli::parse_localised();
    phonglab_core::locale::set_default(args.locale());
    phonglab::io::budget::set(args.memory_budget);
    match args.command {
        Some(command) => cli::run(command),
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
                    phonglab_core::locale::tr_args("app-cannot-open-window", &[("error", error.into())])
                );
                ExitCode::from(1)
            }
        },
    }
}
