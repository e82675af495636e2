//! `edgepaint inspect`: a vertex buffer, for a person (README, "Vertex buffer").

use super::input;
use anyhow::Result;
use model::vertex_buffer::{VertexBuffer, HEADER_BYTES, RECORD_BYTES};
use std::path::PathBuf;

/// Arguments of `edgepaint inspect`.
#[derive(clap::Args)]
pub struct Args {
    /// The vertex buffer (`edgepaint pack`).
    input: PathBuf,
    /// Records of each array to print (the first ones); `--all` prints every one.
    #[arg(long, default_value_t = 8)]
    records: usize,
    #[arg(long)]
    all: bool,
}

pub fn run(args: Args) -> Result<()> {
    let vb = input::vertex_buffer(&args.input)?;
    let shown = if args.all { usize::MAX } else { args.records };
    print!("{}", describe(&vb, shown));
    Ok(())
}

/// The buffer in words: the header, then up to `shown` records of each array.
fn describe(vb: &VertexBuffer, shown: usize) -> String {
    let f = &vb.build.formats;
    let mut out = format!(
        "vertex buffer v{}: {}x{} screen, size class {}, cull {}, background {:?}\n",
        model::vertex_buffer::VERSION,
        vb.width,
        vb.height,
        vb.build.class,
        if vb.cull_back { "back faces" } else { "none" },
        vb.background
    );
    let formats: Vec<String> = f.named().iter().map(|(k, f)| format!("{k} {f}")).collect();
    out += &format!("formats: {}\n", formats.join(", "));
    let bytes = vb.vertex_offset() + RECORD_BYTES * vb.vertices.len();
    out += &format!(
        "header {HEADER_BYTES} bytes; {} triangles from byte {}; {} vertices from byte {} ({:.2} per triangle); {bytes} bytes\n",
        vb.triangles.len(),
        vb.index_offset(),
        vb.vertices.len(),
        vb.vertex_offset(),
        vb.vertices.len() as f64 / vb.triangles.len().max(1) as f64
    );
    out += "triangle index list (V0 V1 V2, flags, inv_w per vertex):\n";
    for (i, t) in vb.triangles.iter().enumerate().take(shown) {
        let flags = [(t.end_of_buffer, "end of buffer"), (t.end_of_frame, "end of frame")];
        let flags: Vec<&str> = flags.iter().filter(|(on, _)| *on).map(|(_, n)| *n).collect();
        let iw: Vec<String> = t.iw.iter().map(|&w| format!("{}", f.inv_w.to_f64(w))).collect();
        out += &format!(
            "  {i:>7}: {:>7} {:>7} {:>7}  [{}]  inv_w {}\n",
            t.v[0],
            t.v[1],
            t.v[2],
            flags.join(", "),
            iw.join(" ")
        );
    }
    if vb.triangles.len() > shown {
        out += &format!("  ... {} more (--all)\n", vb.triangles.len() - shown);
    }
    out += "vertex information array (x y z, R G B):\n";
    for (i, v) in vb.vertices.iter().enumerate().take(shown) {
        let c: Vec<String> = v.c.iter().map(|&c| format!("{}", f.color.to_f64(c))).collect();
        out += &format!("  {i:>7}: {} {} {}  {}\n", f.xy.to_f64(v.x), f.xy.to_f64(v.y), f.z.to_f64(v.z), c.join(" "));
    }
    if vb.vertices.len() > shown {
        out += &format!("  ... {} more (--all)\n", vb.vertices.len() - shown);
    }
    out
}
