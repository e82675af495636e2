//! `edgepaint inspect`: a vertex buffer, for a person (README, "Vertex buffer").

use super::input;
use anyhow::{anyhow, ensure, Result};
use model::command_parser::{self, Bench, Outcome, Params};
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
    /// Entries of the command parser's vertex cache for its fetch count (a power of two,
    /// 1 to 1024).
    #[arg(long, default_value_t = Params::default().cache)]
    cache: u32,
    /// Bytes per beat of the command parser's read bus (4, 8, 16 or 32).
    #[arg(long, default_value_t = Params::default().beat_bytes)]
    bus_bytes: u32,
    /// Cycles before each burst's first beat, for the parser's cycle count.
    #[arg(long, default_value_t = 0)]
    latency: u32,
}

pub fn run(args: Args) -> Result<()> {
    let vb = input::vertex_buffer(&args.input)?;
    let params = Params { cache: args.cache, beat_bytes: args.bus_bytes };
    params.check().map_err(|e| anyhow!("--cache / --bus-bytes: {e}"))?;
    let shown = if args.all { usize::MAX } else { args.records };
    print!("{}", describe(&vb, shown));
    // Each of the 4 T + 3 bursts (header, index records, vertices missed) takes at most its
    // latency, 24 beats and a few cycles of address, check and lookup.
    let max_cycles = (4 * vb.triangles.len() as u64 + 3) * (u64::from(args.latency) + 30);
    let bench = Bench { latency: args.latency, max_cycles, ..Bench::default() };
    let r = command_parser::run(params, vb.build, &vb.encode(), bench).map_err(|e| anyhow!(e))?;
    ensure!(
        r.outcome == Outcome::FrameDone,
        "{}: the command parser's model ended in {:?}",
        args.input.display(),
        r.outcome
    );
    let s = r.stats;
    println!(
        "command parser (model::command_parser: {}-bit bus, {}-entry vertex cache, latency {}): {:.2} vertex fetches \
         per triangle ({} fetched, {} from the cache), {} cycles ({:.1} per triangle)",
        8 * params.beat_bytes,
        params.cache,
        args.latency,
        s.fetches_per_triangle(),
        s.vertex_bursts,
        s.cache_hits,
        r.cycles,
        r.cycles as f64 / s.triangles.max(1) as f64
    );
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
