//! `render --engine rtl`: a whole frame through the RTL of the scanline pipeline
//! (`raster_top`) under Verilator, with the depth and colour buffers in Rust
//! (`sim::frame`). The `raster_top` of the screen's size class draws it
//! (`fx::Build::for_screen`: class 10 up to 1024 x 1024, 11 and 12 above) at the
//! formats asked for (`--formats`; formats edgepaint is not built at are compiled first,
//! `super::rebuild`). The Verilated model is built the first time, cached under
//! `target/verilator/` (Verilator from `scripts/setup-tools.sh`). The image is checked against the scanline model's, bit for
//! bit. The summary gives the frame's time at the design's clock (`sweep::clock::raster_top_mhz`):
//! `raster_top`'s routed ECP5 Fmax at the default design, the clock model's elsewhere (other
//! formats, K or L, or an optional part left out, which the model does not see).

use super::engine::FixedArgs;
use super::input::Loaded;
use super::render::{depth16, Image};
use anyhow::{anyhow, bail, ensure, Result};
use fx::Build;
use model::cull_sort::Cull;
use model::cycles::Timing;
use sim::frame::{self, Frame, MemoryModel, Report};
use sim::memory::ReadDuringWrite;
use std::time::Instant;
use sweep::area::Design;
use sweep::row::Source;

/// Draws `loaded` (its formats: `FixedArgs::formats_of`) through `raster_top`; returns the image and the summary line with its
/// fragment count, or `None` when an edgepaint compiled at the formats asked for drew it.
pub fn render(
    loaded: &Loaded,
    cull_back: bool,
    fixed: &FixedArgs,
    analysis: bool,
    params: &[(String, u64)],
) -> Result<Option<(Image, (String, u64))>> {
    ensure!(!analysis, "--analysis checks the models' arithmetic; it does not apply to --engine rtl");
    let list = &loaded.trilist;
    let mut timing = Timing::default();
    let mut class = loaded.build.unwrap_or(Build::for_screen(list.width, list.height)).class;
    let mut parts = Vec::new();
    for (name, v) in params {
        let v32 = u32::try_from(*v).unwrap_or(u32::MAX);
        match name.as_str() {
            "K" => timing.setup_multipliers = v32,
            "L" => timing.divider_latency = v32,
            "N" => class = v32,
            _ if rtl::switch::Parts::PARAMS.iter().any(|(p, _)| p == name) => parts.push((name.as_str(), *v)),
            _ => bail!(
                "--param {name}: --engine rtl takes N (the size class), K (setup's multipliers), L (the divider's \
                 stages) and the switches of optional parts ({})",
                rtl::switch::Parts::PARAMS.map(|(p, _)| p).join(", ")
            ),
        }
    }
    let (k, l) = (timing.setup_multipliers as u64, timing.divider_latency as u64);
    let mut unit_params = vec![("K", k), ("L", l)];
    unit_params.extend(parts.iter().copied());
    let formats = fixed.formats_of(loaded)?;
    let build = Build { class, formats };
    if !rtl::built(&build) {
        let source = if loaded.build.is_some() { "the vertex buffer's" } else { fixed.formats.as_str() };
        rtl::config::check(class, &formats).map_err(|e| anyhow!("--engine rtl, formats \"{source}\": {e}"))?;
        let why = if build == Build::of_class(class) {
            format!("size class {class}")
        } else {
            format!("the formats of {source}")
        };
        if super::rebuild::ensure(&build, &why)? {
            return Ok(None);
        }
    }
    let cull = if cull_back { Cull::Back } else { Cull::None };
    let background = loaded.background.map(|c| c.round().clamp(0.0, 255.0) as u8);
    let prep =
        model::raster_top::raster_top(&build, list, cull, background).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    for (i, e) in prep.skipped.iter().take(5) {
        eprintln!("warning: triangle {i} not drawn: {e}");
    }
    ensure!(!prep.triangles.is_empty(), "--engine rtl: no triangle to draw");
    let f = Frame { build, width: list.width, height: list.height, cull, background, triangles: &prep.triangles };
    let memory = MemoryModel { read_during_write: ReadDuringWrite::Old, ready: &mut |_| true };
    let max_cycles = 2 * prep.cycles() + 100_000;
    let mut dut = frame::verilator_with(&build, &unit_params).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let start = Instant::now();
    let out = frame::draw(&mut dut, &f, memory, max_cycles).map_err(|e| anyhow!(e))?;
    let secs = start.elapsed().as_secs_f64();
    let r = Report { predicted: prep.cycles_with(&timing), ..Report::of(&out, &prep) };
    if let Some(first) = out.memory.differs_from(&prep.render.fb) {
        bail!("the RTL's image differs from the scanline model's ({first}): a bug in the RTL or the model");
    }
    ensure!(
        r.cycles == r.predicted,
        "the RTL took {} cycles, model::cycles predicts {}: a bug in the RTL or the cycle model",
        r.cycles,
        r.predicted
    );
    let latency = r.latency.map_or("none".into(), |(lo, mid, hi)| format!("{lo}/{mid}/{hi}"));
    let design =
        Design { class: build.class, formats: build.formats, k: timing.setup_multipliers, l: timing.divider_latency };
    let (mhz, source) = sweep::clock::raster_top_mhz(&design);
    let every_part = parts.iter().all(|&(_, v)| v == 1);
    let clock = match (source, every_part) {
        (Source::Measured, true) => "routed, ECP5",
        (_, true) => "modelled, ECP5",
        (_, false) => "modelled, ECP5, not counting the parts left out",
    };
    let summary = format!(
        "rtl (raster_top of size class {}{}, K = {k}, L = {l}, in Verilator): {} triangles in, {} drawn, {} culled; {} fragments, {} pixels written; \
         {} cycles (model::cycles: {}), frame time {:.3} ms at {mhz:.1} MHz ({clock}), {:.3} pixels per clock; per triangle: latency to its first pixel \
         {latency} cycles (min/median/max), {:.1} cycles between triangles (max {}); {:.0} cycles/s simulated ({secs:.2} s); \
         image, depth and cycles equal to the scanline model's",
        build.class,
        if build == Build::of_class(class) { "" } else { ", formats of --formats" },
        list.triangles.len(),
        r.drawn,
        r.triangles - r.drawn,
        r.fragments,
        r.written,
        r.cycles,
        r.predicted,
        r.cycles as f64 / (mhz * 1000.0),
        r.pixels_per_clock(),
        r.interval.0,
        r.interval.1,
        r.cycles as f64 / secs,
    );
    let m = out.memory;
    let image = Image {
        width: m.width,
        height: m.height,
        depth16: m.depth.iter().map(|&d| depth16(d, formats.z.frac)).collect(),
        rgb: m.rgb,
        written: m.written,
    };
    Ok(Some((image, (summary, r.fragments))))
}
