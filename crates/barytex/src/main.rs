//! The `barytex` command.
//!
//! - `barytex` (what `cargo run --release` runs): a demo of the seed's worked examples, checked
//!   against exact arithmetic, until the renderer exists.
//! - `barytex report [--out DIR] [--quick]`: the speed-vs-error report of the interpolation
//!   methods, written as Markdown (`DIR/README.md`, `DIR/interp.md`; default `docs/report`).
//! - `barytex uv-layout --mesh sphere|equal-area-sphere|torus|cylinder|cube|plane [--size N]
//!   [--out FILE.png]`: a parametric mesh's uv layout (default `docs/uv-layout/<mesh>.png`).

mod demo;
mod report;
mod timing;
mod uv_layout;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

/// barytex: interpolation math, exact where a sign decides topology.
///
/// Without a subcommand, prints a demo of the seed's worked examples.
#[derive(Debug, Parser)]
#[command(name = "barytex", version, about, long_about = None)]
struct Cli {
    /// What to do; the demo when absent.
    #[command(subcommand)]
    command: Option<Command>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
enum Command {
    /// Measure every method's speed and error on the same inputs and write the Markdown report.
    Report(ReportArgs),
    /// Draw a parametric mesh's uv layout (wireframe over a checker, seams in red) to a PNG.
    UvLayout(UvLayoutArgs),
}

/// Options of `barytex uv-layout`.
#[derive(Debug, Args)]
struct UvLayoutArgs {
    /// Which mesh.
    #[arg(long, value_enum)]
    mesh: uv_layout::MeshKind,
    /// Picture side in pixels (1 to 8192).
    #[arg(long, default_value_t = 512)]
    size: u32,
    /// The PNG to write (default `docs/uv-layout/<mesh>.png`).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Options of `barytex report`.
#[derive(Debug, Args)]
struct ReportArgs {
    /// Directory for README.md and interp.md (created if missing).
    #[arg(long, default_value = "docs/report")]
    out: PathBuf,
    /// Few inputs and short timing: a fast, rough run (for tests).
    #[arg(long)]
    quick: bool,
}

/// The command line as typed, with the program's path shortened to `barytex`.
fn command_line() -> String {
    std::iter::once("barytex".to_owned())
        .chain(std::env::args().skip(1))
        .collect::<Vec<_>>()
        .join(" ")
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => demo::run(),
        Some(Command::Report(args)) => report::run(&report::Options {
            out: args.out,
            quick: args.quick,
            command: command_line(),
        }),
        Some(Command::UvLayout(args)) => uv_layout::run(&uv_layout::Options {
            mesh: args.mesh,
            size: args.size,
            out: args.out,
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("barytex: {error}");
            ExitCode::FAILURE
        }
    }
}
