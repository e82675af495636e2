//! `edgepaint`: a Rust-embedded hardware generator for 3D rasterization hardware.
//!
//! This file is only the command-line interface; every algorithm lives in the
//! library crates under `crates/`. With no arguments it emits the default
//! design's Verilog into `hdl-out/`.

mod cmd;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// edgepaint describes rasterization hardware from five papers in Rust (rust-hdl),
/// emits it as Verilog, simulates it against bit-exact models and a float
/// reference, and reports speed, area and accuracy.
///
/// Run without a command to emit the default design into hdl-out/.
#[derive(Parser)]
#[command(name = "edgepaint", version, about, long_about)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene through the software geometry stage and write its screen-space triangle list (trilist v1).
    Trilist(cmd::trilist::Args),
    /// Pack a scene or trilist into the vertex buffer 001's command parser reads (indexed, fixed point).
    Pack(cmd::pack::Args),
    /// Print a vertex buffer: its header, triangle index list and vertex array.
    Inspect(cmd::inspect::Args),
    /// Render a scene, trilist or vertex buffer to a PNG, with the float reference or a fixed-point pipeline.
    Render(cmd::render::Args),
    /// Compare a fixed-point pipeline with the float reference: coverage, colour, depth, cycles.
    Accuracy(cmd::accuracy::Args),
    /// Emit Verilog for one unit (or, with no unit, the default design) into a directory.
    Emit(cmd::emit::Args),
    /// Synthesize emitted units and tabulate their area and speed (Markdown and JSON).
    Report(cmd::report::Args),
    /// Sweep methods and number formats over scenes: accuracy, speed and cost per design point, charted.
    Sweep(cmd::sweep::Args),
    /// Fit the narrowest scanline design that meets an accuracy target on a workload, emit it and prove it in Verilator.
    Fit(cmd::fit::Args),
    /// Where each method fails: families of generated triangles swept against the float reference, as heatmaps.
    Stability(cmd::stability::Args),
}

/// The stack of the thread that runs a command: rust-hdl builds, moves and walks a design's
/// blocks on the stack, and the largest (raster_top with 16 shading engines) overflow a
/// main thread's 8 MiB in an unoptimised build.
const STACK: usize = 512 << 20;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let run = std::thread::Builder::new().stack_size(STACK).spawn(move || run(cli));
    match run.map(|t| t.join()) {
        Ok(Ok(code)) => code,
        Ok(Err(_)) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("edgepaint: error: starting the command's thread: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> ExitCode {
    let result = match cli.command {
        None => cmd::emit::run_default(),
        Some(Command::Trilist(a)) => cmd::trilist::run(a),
        Some(Command::Pack(a)) => cmd::pack::run(a),
        Some(Command::Inspect(a)) => cmd::inspect::run(a),
        Some(Command::Render(a)) => cmd::render::run(a),
        Some(Command::Accuracy(a)) => cmd::accuracy::run(a),
        Some(Command::Emit(a)) => cmd::emit::run(a),
        Some(Command::Report(a)) => cmd::report::run(a),
        Some(Command::Sweep(a)) => cmd::sweep::run(a),
        Some(Command::Fit(a)) => cmd::fit::run(a),
        Some(Command::Stability(a)) => cmd::stability::run(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("edgepaint: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
