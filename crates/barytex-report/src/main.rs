//! `barytex-report`: the speed-vs-error report of barytex's methods against exact and f64
//! references and against peer crates, written as Markdown with SVG charts (`docs/report/` by
//! default: `README.md`, `interp.md`, `texture.md`, `raster.md`, `shading.md`).
//!
//! From the repository root: `cargo run --release -p barytex-report` (add `-- --quick` for a
//! fast, rough run, `-- --out DIR` for another folder). It is a workspace tool, not part of the
//! `barytex` command: it measures against `barytex-testkit`'s references and against peer
//! crates (geo, nalgebra, robust) that the command need not carry.

mod report;
mod timing;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;

/// Measure every method's speed and error on the same inputs and write the Markdown report.
///
/// Writes into OUT: README.md (the index), interp.md (interpolation math), texture.md (texture
/// filters, with texture-filters-grazing.png), raster.md (rasterization), shading.md (shading
/// frequencies), and one speed-vs-error chart (SVG) per table.
#[derive(Debug, Parser)]
#[command(name = "barytex-report", version, about, long_about)]
struct Cli {
    /// Directory for README.md and the report pages (created if missing).
    #[arg(long, default_value = "docs/report")]
    out: PathBuf,
    /// Few inputs and short timing: a fast, rough run (for tests).
    #[arg(long)]
    quick: bool,
}

/// The command line as typed, with the program's path shortened to `barytex-report`.
fn command_line() -> String {
    std::iter::once("barytex-report".to_owned())
        .chain(std::env::args().skip(1))
        .collect::<Vec<_>>()
        .join(" ")
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = report::run(&report::Options {
        out: cli.out,
        quick: cli.quick,
        command: command_line(),
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("barytex-report: {error}");
            ExitCode::FAILURE
        }
    }
}
