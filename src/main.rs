//! phonglab: a desktop explorer for OpenGL's fixed-function vertex lighting, and a CLI.

mod cli;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let args = cli::Cli::parse();
    match args.command {
        Some(command) => cli::run(command),
        None => {
            eprintln!("phonglab: the explorer window is not built yet; try `phonglab --help`");
            ExitCode::from(2)
        }
    }
}
