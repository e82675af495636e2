//! `edgepaint trilist`: scene -> geometry stage -> trilist v1 JSON.

use super::input::{self, Size};
use anyhow::Result;
use std::path::PathBuf;

/// Arguments of `edgepaint trilist`.
#[derive(clap::Args)]
pub struct Args {
    /// Scene file (JSON).
    scene: PathBuf,
    /// Where to write the trilist; standard output when omitted.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Override the scene's resolution, e.g. 320x240.
    #[arg(long)]
    size: Option<Size>,
}

pub fn run(args: Args) -> Result<()> {
    let loaded = input::load(&args.scene, args.size)?;
    let json = loaded.trilist.to_json();
    match &args.output {
        Some(path) => {
            input::write(path, "the trilist", json.as_bytes())?;
            eprintln!(
                "trilist: {} triangles, {}x{} -> {}",
                loaded.trilist.triangles.len(),
                loaded.trilist.width,
                loaded.trilist.height,
                path.display()
            );
        }
        None => println!("{json}"),
    }
    Ok(())
}
