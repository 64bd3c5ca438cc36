//! `phonglab eval`: glref cases (JSON) lit by the engine, the colours printed as JSON.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result, bail};
use clap::Args;
use phonglab_core::glref::{self, CaseColors};
use phonglab_core::{EvalOptions, PowFn, Precision, Scene};

use crate::t;

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
    pub pow: PowFn,
}

fn evaluate(scene: &Scene, precision: Precision, options: EvalOptions, clamp: bool) -> Result<CaseColors, String> {
    let r = match precision {
        Precision::F32 => glref::evaluate::<f32>(scene, options, clamp),
        Precision::F64 => glref::evaluate::<f64>(scene, options, clamp),
    };
    r.map_err(|e| e.to_string())
}

/// `eval`: the results on stdout; exit 1 (after printing them) when any case failed.
pub fn run(a: &EvalArgs) -> Result<ExitCode> {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let (all, failed) = eval_stream(&a.cases, a.precision, EvalOptions::with_pow(a.pow), a.clamp, &mut out)?;
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
/// (so a broken one writes nothing) and to measure its largest case, which is refused past
/// the memory budget ([`crate::io::budget::eval_bytes`]); then case by case, each result
/// written as it is lit. The memory is one case's (and the ids', to refuse a repeated
/// one), whatever the number of cases.
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
                path = crate::io::reasons::shown(path),
                reason = crate::io::reasons::io_reason(&e)
            ))
        })?;
        let Some(meta) = crate::platform::os::regular_file_metadata(&file)? else {
            bail!(t!("read-not-a-file", path = crate::io::reasons::shown(path)));
        };
        let (shown, kind) = (crate::io::reasons::shown(path), t!("file-kind-cases"));
        crate::io::input_file::within_cap(&shown, meta.len(), crate::io::input_file::MAX_CASE_BYTES, &kind)
            .map_err(anyhow::Error::msg)?;
        Ok(file)
    };
    let not_cases = || format!("{}: {}", crate::io::reasons::shown(path), t!("err-not-case-file"));
    // The first pass reads past each case without building it, measuring the largest:
    // the second holds one case at a time, so that one is what must fit the budget.
    let (count, largest) = glref::measure_cases(open()?).context(not_cases())?;
    let what =
        t!("budget-what-eval", count = count as i64, largest = phonglab_core::mesh::obj::describe_bytes(largest));
    crate::io::budget::check(&what, crate::io::budget::eval_bytes(largest)).map_err(anyhow::Error::msg)?;
    let (mut all, mut failed) = (0usize, 0usize);
    let mut write_error = None;
    out.write_all(b"{\n  \"results\": [")?;
    glref::for_each_case(open()?, |id, case| {
        let r = case.map_err(|e| e.to_string()).and_then(|c| evaluate(&c.scene, precision, options, clamp));
        failed += usize::from(r.is_err());
        // serde_json's pretty form of the whole, one result at a time.
        let result = serde_json::to_string_pretty(&glref::result_json(&id, &r)).unwrap_or_default();
        let result = phonglab_core::escape::json::text(&result);
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
