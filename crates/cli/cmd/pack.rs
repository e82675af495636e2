//! `edgepaint pack`: scene or trilist -> the vertex buffer 001's command parser reads
//! (`model::vertex_buffer`; README, "Vertex buffer").

use super::engine::FixedArgs;
use super::input::{self, Size};
use anyhow::{anyhow, ensure, Result};
use fx::Build;
use model::vertex_buffer;
use std::path::PathBuf;

/// Arguments of `edgepaint pack`.
#[derive(clap::Args)]
pub struct Args {
    /// Scene file or trilist (JSON).
    input: PathBuf,
    /// Where to write the vertex buffer (`.vb`).
    #[arg(short, long)]
    output: PathBuf,
    /// Override a scene's resolution, e.g. 320x240.
    #[arg(long)]
    size: Option<Size>,
    /// Number formats of the words: "default" (derived from the resolution), "wide", or a
    /// JSON file of formats by quantity (as `render --formats`); the header records them.
    #[arg(long, default_value = "default")]
    formats: String,
}

pub fn run(args: Args) -> Result<()> {
    let loaded = input::load(&args.input, args.size)?;
    loaded.untextured(
        &args.input,
        "the vertex buffer carries no texture words or blend modes: gpu_top's command parser has no texture path \
         (render --engine rtl draws it through the textured raster_top)",
    )?;
    ensure!(loaded.build.is_none(), "{}: already a vertex buffer", args.input.display());
    let list = &loaded.trilist;
    let fixed = FixedArgs { formats: args.formats.clone(), lanes: None, lod: super::engine::Lod::Max };
    let build =
        Build { formats: fixed.formats(list.width, list.height)?, ..Build::for_screen(list.width, list.height) };
    let background = loaded.background.map(|c| c.round().clamp(0.0, 255.0) as u8);
    let (vb, skipped) = vertex_buffer::pack(list, &build, loaded.cull_back, background)
        .map_err(|e| anyhow!("{}: {e}", args.input.display()))?;
    for (i, e) in skipped.iter().take(5) {
        eprintln!("warning: triangle {i} left out: {e}");
    }
    if skipped.len() > 5 {
        eprintln!("warning: ... {} triangles in all left out", skipped.len());
    }
    ensure!(!vb.triangles.is_empty(), "{}: no triangle to pack", args.input.display());
    let bytes = vb.encode();
    input::write(&args.output, "the vertex buffer", &bytes)?;
    println!(
        "pack: {} triangles in, {} packed ({} vertices, {:.2} per triangle), {} bytes, size class {} -> {}",
        list.triangles.len(),
        vb.triangles.len(),
        vb.vertices.len(),
        vb.vertices.len() as f64 / vb.triangles.len() as f64,
        bytes.len(),
        build.class,
        args.output.display()
    );
    Ok(())
}
