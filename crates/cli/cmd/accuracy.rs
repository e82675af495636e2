//! `edgepaint accuracy`: a fixed-point pipeline against the float reference.

use super::engine::{Engine, FixedArgs};
use super::input::{self, Size};
use accuracy::{compare, compare_se, Setup};
use anyhow::{bail, Result};
use model::cycles::Timing;
use model::render::Method;
use std::path::PathBuf;

/// Arguments of `edgepaint accuracy`.
#[derive(clap::Args)]
pub struct Args {
    /// Scene file or trilist (JSON), or vertex buffer (measured at the formats in its header).
    input: PathBuf,
    /// Fixed-point pipeline(s) to measure.
    #[arg(long, value_enum, default_value = "scanline", num_args = 1.., value_delimiter = ',')]
    engine: Vec<Engine>,
    #[command(flatten)]
    fixed: FixedArgs,
    /// Also write the reports as JSON to this file.
    #[arg(long)]
    json: Option<PathBuf>,
    /// Override a scene's resolution, e.g. 320x240.
    #[arg(long)]
    size: Option<Size>,
}

pub fn run(args: Args) -> Result<()> {
    let loaded = input::load(&args.input, args.size)?;
    loaded.untextured(&args.input, "the fixed-point models")?;
    let list = &loaded.trilist;
    let formats = args.fixed.formats_of(&loaded)?;
    let mut reports = Vec::new();
    for &engine in &args.engine {
        let setup = |method| Setup {
            method,
            formats,
            cull_back: loaded.cull_back,
            background: loaded.background,
            timing: Timing::default(),
        };
        let r = match engine {
            Engine::Se => compare_se(list, &setup(Method::Scanline))
                .map_err(|e| anyhow::anyhow!("{}: {e}", args.input.display()))?,
            _ => {
                let Some(method) = args.fixed.method(engine, true)? else {
                    bail!("--engine float is the reference itself; measure scanline, vector or se against it");
                };
                compare(list, &setup(method))
            }
        };
        println!("{} ({} triangles)\n{}", args.input.display(), list.triangles.len(), r.table());
        reports.push(r);
    }
    if let Some(path) = &args.json {
        let json = serde_json::to_string_pretty(&reports)?;
        input::write(path, "the accuracy report", json.as_bytes())?;
    }
    Ok(())
}
