//! `render --engine rtl`: a whole frame through the RTL under Verilator, by one of two tops
//! (`--top`).
//!
//! **`gpu_top`** (the default where it applies: the default build, no `--param`): the
//! frame as a system draws it. The input is packed into a vertex buffer (a `.vb` input is
//! used as it is), put in a memory behind `gpu_top`'s AXI4 read master, the depth and
//! colour buffers in memories behind its other masters, and a host drives the registers
//! through the README's sequence (`sim::soc`): START with CLEAR, to the interrupt, then
//! `STATUS`, `FRAME_CYCLES` and `TRIANGLES`. The image is read out of the colour memory and
//! checked against `model::gpu_top`'s frame, bit for bit, as is `STATUS`.
//!
//! **`raster_top`**: triangles on the rasterizer's ports, with the depth and colour
//! buffers in Rust (`sim::frame`); its method the scanline pipeline's (001, 003) or, with
//! `--method vector`, 004's per-pixel barycentric unit (`METHOD = 1`) with `--lanes` lanes (1, 2, 4
//! or 8; default 4, as the vector model's), its memory a word per chunk of lanes; with
//! `--method se`, 000's shading engines behind the scanline front end (`METHOD = 2`,
//! `sim::se_frame`). The `raster_top` of the screen's size class draws it
//! (`fx::Build::for_screen`: class 10 up to 1024 x 1024, 11 and 12 above) at the
//! formats asked for (`--formats`; formats edgepaint is not built at are compiled first,
//! `super::rebuild`). The Verilated model is built the first time, cached under
//! `target/verilator/` (Verilator from `scripts/setup-tools.sh`). The image is checked against the method's model, bit for
//! bit, and the cycles against `model::cycles`. The summary gives the frame's time at the design's clock (`sweep::clock::raster_top_mhz`):
//! `raster_top`'s routed ECP5 Fmax at the default design, the clock model's elsewhere (other
//! formats, K or L, or an optional part left out, which the model does not see).

use super::engine::FixedArgs;
use super::input::Loaded;
use super::render::{depth16, Image};
use anyhow::{anyhow, bail, ensure, Result};
use fx::Build;
use model::cull_sort::Cull;
use model::cycles::textured::textured_frame;
use model::cycles::Timing;
use model::pixel_bus::color_word;
use model::render::Method;
use sim::frame::{self, Frame, MemoryModel, Report};
use sim::memory::ReadDuringWrite;
use sim::soc::{Pace, Soc, VB_BASE};
use std::time::Instant;
use sweep::area::Design;
use sweep::row::Source;

/// The top `render --engine rtl` draws through.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Top {
    /// The core from a vertex buffer in memory, through its bus ports and registers.
    #[value(name = "gpu_top")]
    GpuTop,
    /// The scanline pipeline, triangles on its ports.
    #[value(name = "raster_top")]
    RasterTop,
}

/// `raster_top`'s method (its parameter `METHOD`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RtlMethod {
    /// Setup, edge walk and span (001, 003).
    Scanline,
    /// The per-pixel barycentric unit (004), `--lanes` pixels a cycle.
    Vector,
    /// 000's shading engines behind the scanline front end (`METHOD = 2`).
    Se,
}

/// What draws: the method, its colours, `raster_top`'s parameters and the top.
pub struct How<'a> {
    pub method: RtlMethod,
    /// The vector method's colours perspective-correct.
    pub perspective: bool,
    pub params: &'a [(String, u64)],
    pub top: Option<Top>,
    /// The scene's file, for errors.
    pub input: &'a std::path::Path,
}

/// Draws `loaded` (its formats: `FixedArgs::formats_of`) as `how` says (top None: `gpu_top`
/// where it applies, else `raster_top`; a textured or blended scene: the textured
/// `raster_top`); returns the image and the summary line with its
/// fragment count, or `None` when an edgepaint compiled at the formats asked for drew it.
pub fn render(
    loaded: &Loaded,
    cull_back: bool,
    fixed: &FixedArgs,
    analysis: bool,
    how: &How,
) -> Result<Option<(Image, (String, u64))>> {
    ensure!(!analysis, "--analysis checks the models' arithmetic; it does not apply to --engine rtl");
    if loaded.trilist.is_textured() || loaded.trilist.is_blended() {
        return textured(loaded, cull_back, fixed, how).map(Some);
    }
    if how.method == RtlMethod::Se {
        return se_back_end(loaded, cull_back, fixed, how).map(Some);
    }
    let (params, top, vector) = (how.params, how.top, how.method == RtlMethod::Vector);
    ensure!(
        vector || fixed.lanes.is_none(),
        "--engine rtl --lanes: the lanes are the vector unit's (--method vector); the scanline method draws a pixel a cycle"
    );
    let lanes = if vector { fixed.lanes.unwrap_or(super::engine::DEFAULT_LANES) } else { 1 };
    ensure!(
        model::raster_top::LANES.contains(&lanes),
        "--engine rtl --method vector --lanes {lanes}: raster_top's vector unit is built with 1, 2, 4 or 8 lanes"
    );
    let list = &loaded.trilist;
    let default_build = loaded.build.unwrap_or(Build::for_screen(list.width, list.height)) == Build::default()
        && fixed.formats_of(loaded)? == Build::default().formats;
    let gpu_top_why_not = match (params.first(), default_build) {
        _ if vector => Some("gpu_top holds the scanline method (--method scanline)".to_owned()),
        (Some((name, _)), _) => Some(format!("--param {name} sets raster_top's parameters")),
        (None, false) => {
            Some(format!("gpu_top is built at size class {} and its default formats only", Build::default().class))
        }
        (None, true) => None,
    };
    match (top, gpu_top_why_not) {
        (Some(Top::GpuTop) | None, None) => return gpu_top(loaded, cull_back).map(Some),
        (Some(Top::GpuTop), Some(why)) => bail!("--top gpu_top: {why}; draw with --top raster_top"),
        _ => {}
    }
    let mut timing = Timing::default();
    let mut class = loaded.build.unwrap_or(Build::for_screen(list.width, list.height)).class;
    let mut parts = Vec::new();
    for (name, v) in params {
        let v32 = u32::try_from(*v).unwrap_or(u32::MAX);
        match name.as_str() {
            "K" if vector => bail!("--param K: triangle_setup's multipliers; --method vector has no triangle_setup (no setup unit: the vector unit sets up each triangle itself)"),
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
    ensure!(
        !vector || l == model::divider::LATENCY as u64,
        "--method vector: --param L sets the divider's stages, and the vector model's cycles are those of the default {}",
        model::divider::LATENCY
    );
    let mut unit_params = vec![
        ("K", k),
        ("L", l),
        ("METHOD", vector as u64),
        ("PERSPECTIVE", how.perspective as u64),
        ("LANES", lanes as u64),
    ];
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
    let method = match vector {
        false => Method::Scanline,
        true => Method::Vector { lanes, perspective: how.perspective },
    };
    let prep = model::raster_top::raster_top_by(&build, list, cull, background, method)
        .map_err(|e| anyhow!("--engine rtl: {e}"))?;
    for (i, e) in prep.skipped.iter().take(5) {
        eprintln!("warning: triangle {i} not drawn: {e}");
    }
    ensure!(!prep.triangles.is_empty(), "--engine rtl: no triangle to draw");
    let f =
        Frame { build, width: list.width, height: list.height, cull, background, triangles: &prep.triangles, lanes };
    let memory = MemoryModel { read_during_write: ReadDuringWrite::Old, ready: &mut |_| true };
    let max_cycles = 2 * prep.cycles() + 100_000;
    let mut dut = frame::verilator_with(&build, &unit_params).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let start = Instant::now();
    let out = frame::draw(&mut dut, &f, memory, max_cycles).map_err(|e| anyhow!(e))?;
    let secs = start.elapsed().as_secs_f64();
    let r = Report { predicted: prep.cycles_with(&timing), ..Report::of(&out, &prep) };
    let name = accuracy::method_name(method);
    if let Some(first) = out.memory.differs_from(&prep.render.fb) {
        bail!("the RTL's image differs from the {name} model's ({first}): a bug in the RTL or the model");
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
    let vector_clock = sweep::clock::vector_pipeline_mhz(lanes).expect("lanes raster_top is built with");
    let (mhz, clock) = match (vector, source, every_part) {
        (true, _, true) if build == Build::default() => match vector_clock {
            (mhz, Source::Measured) => (mhz, "routed, ECP5"),
            (mhz, Source::Modelled) => (mhz, "modelled from one lane's and four's routed clocks, ECP5"),
        },
        (true, _, _) => (vector_clock.0, "the default design's at these lanes, ECP5; not at these formats or parts"),
        (false, Source::Measured, true) => (mhz, "routed, ECP5"),
        (false, _, true) => (mhz, "modelled, ECP5"),
        (false, _, false) => (mhz, "modelled, ECP5, not counting the parts left out"),
    };
    let units = if vector {
        format!(
            "METHOD = 1: cull_sort, vector with {lanes} lanes, pixel_out; L = {l}, colours {}",
            if how.perspective { "perspective-correct" } else { "linear" }
        )
    } else {
        format!("K = {k}, L = {l}")
    };
    let summary = format!(
        "rtl (raster_top of size class {}{}, {units}, in Verilator): {} triangles in, {} drawn, {} culled; {} fragments, {} pixels written; \
         {} cycles (model::cycles: {}), frame time {:.3} ms at {mhz:.1} MHz ({clock}), {:.3} pixels per clock; per triangle: latency to its first pixel \
         {latency} cycles (min/median/max), {:.1} cycles between triangles (max {}); {:.0} cycles/s simulated ({secs:.2} s); \
         image, depth and cycles equal to the {name} model's",
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
    let image = image_of(out.memory, formats.z.frac);
    Ok(Some((image, (summary, r.fragments))))
}

/// A textured or blended scene: `loaded` drawn by the textured `raster_top` (`TEXTURE = 1`:
/// the scanline method, `texture_path` and the blending `pixel_out`) at the default build,
/// in Verilator (`sim::textured`), behind a texture memory of latency 10; image and depth
/// checked against the textured scanline render (`model::render::render_with`), the
/// cache's counters against its accesses.
fn textured(loaded: &Loaded, cull_back: bool, fixed: &FixedArgs, how: &How) -> Result<(Image, (String, u64))> {
    let list = &loaded.trilist;
    let build = sim::textured::BUILD;
    let what = format!(
        "{}: the scene is textured or blends, and the textured raster_top (TEXTURE = 1) that draws it",
        how.input.display()
    );
    ensure!(how.method == RtlMethod::Scanline, "{what} has the scanline method only (no --method vector or se)");
    ensure!(how.top != Some(Top::GpuTop), "{what} is raster_top's: --top gpu_top has no texture path yet");
    ensure!(how.params.is_empty(), "{what} is built at raster_top's default parameters (no --param)");
    ensure!(
        fixed.formats_of(loaded)? == build.formats
            && loaded.build.is_none_or(|b| b == build)
            && fixed.texture_formats()? == fx::TexFormats::DEFAULT,
        "{what} is built at size class {} and its default formats only (screens up to {}x{}, no --formats)",
        build.class,
        1 << build.class,
        1 << build.class
    );
    let side = 1u32 << build.class;
    ensure!(
        list.width <= side && list.height <= side,
        "{what} draws screens up to {side}x{side}, not {}x{}",
        list.width,
        list.height
    );
    let f = build.formats;
    let texturing = fixed.texturing(list, !how.perspective, how.input)?;
    let background = loaded.background.map(|c| c.round().clamp(0.0, 255.0) as u8);
    let cull = if cull_back { Cull::Back } else { Cull::None };
    let opts = model::render::Options { method: Method::Scanline, cull, analysis: false, background };
    let work = model::texture_path::sent_work(list, &f, &opts, texturing.as_ref());
    let tris: Vec<_> = work.iter().map(|w| w.sent).collect();
    ensure!(!tris.is_empty(), "{}: --engine rtl: no triangle to draw", how.input.display());
    let want = model::render::render_with(list, &f, &opts, texturing.as_ref(), &mut |_| {});
    let exact = fixed.lod_rule() == texture::LodRule::Exact;
    let mut vl = sim::textured::TexturedVl::new(exact).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let words = texturing.as_ref().map_or(Vec::new(), |t| t.memory.words.clone());
    let mut tex = model::texture_memory::ReadPort::new(words.clone(), 10);
    let start = Instant::now();
    let size = (list.width, list.height);
    let max_cycles = 100 * (want.stats.fragments + 1000 * tris.len() as u64);
    let out = sim::textured::draw(
        &mut |p| vl.cycle(p),
        &tris,
        size,
        background,
        cull_back,
        &mut tex,
        &mut |_| true,
        max_cycles,
    )
    .map_err(|e| anyhow!(e))?;
    let secs = start.elapsed().as_secs_f64();
    if let Some(first) = out.memory.differs_from(&want.fb) {
        bail!("the RTL's image differs from the textured scanline model's ({first}): a bug in the RTL or the model");
    }
    let c = model::texture_cache::hit_rate_of_trace(&accuracy::texture::DEFAULT_CACHE, &want.fetches);
    ensure!(
        out.counters == [c.hits, c.misses, c.fills],
        "the RTL's texture cache counted {:?} hits, misses and fills, the model's accesses give {:?}: a bug in the RTL or the model",
        out.counters,
        [c.hits, c.misses, c.fills]
    );
    let cache = accuracy::texture::DEFAULT_CACHE;
    let path = model::texture_path::TexturePath::new(f, fx::TexFormats::DEFAULT, cache, fixed.lod_rule())
        .map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let mut tex = model::texture_memory::ReadPort::new(words, 10);
    let predicted = textured_frame(&work, &Timing::default(), path, &mut tex, &mut |_| true, &|_| true);
    ensure!(
        predicted.frame.total == out.cycles,
        "the RTL took {} cycles, model::cycles::textured predicts {}: a bug in the RTL or the cycle model",
        out.cycles,
        predicted.frame.total
    );
    let st = &want.stats;
    let summary = format!(
        "rtl (raster_top of size class {} with TEXTURE = 1: cull_sort, setup, edge walk, span, texture_path with a 64-set \
         2-way cache of 4-word lines, blending pixel_out; in Verilator, a texture memory of latency 10): {} triangles in, \
         {} drawn; {} fragments, {} pixels written; {} cycles ({:.3} fragments per clock, as model::cycles::textured \
         predicts), texture cache hit rate {:.4} ({} misses); {:.0} cycles/s simulated ({secs:.2} s); image and depth \
         equal to the textured scanline model's",
        build.class,
        list.triangles.len(),
        st.drawn,
        st.fragments,
        st.pixels_written,
        out.cycles,
        st.fragments as f64 / out.cycles.max(1) as f64,
        c.hits as f64 / (c.hits + c.misses).max(1) as f64,
        c.misses,
        out.cycles as f64 / secs,
    );
    let image = image_of(out.memory, f.z.frac);
    Ok((image, (summary, st.fragments)))
}

/// The image of the buffers `m`, depth in `z_frac` fraction bits.
fn image_of(m: sim::memory::Memory, z_frac: u32) -> Image {
    let depth16 = m.depth.iter().map(|&d| depth16(d, z_frac)).collect();
    Image { width: m.width, height: m.height, depth16, rgb: m.rgb, written: m.written }
}

/// `--method se`: `loaded` drawn by `raster_top` with `METHOD = 2` (the scanline front end,
/// `se_cmd` and the fewest engines built that cover the screen, or `--param ENGINES=N`) at
/// the default build, in Verilator (`sim::se_frame`); image, depth, pixels written and
/// cycles checked against `model::raster_top::raster_top_se`.
fn se_back_end(loaded: &Loaded, cull_back: bool, fixed: &FixedArgs, how: &How) -> Result<(Image, (String, u64))> {
    let list = &loaded.trilist;
    let build = Build::default();
    ensure!(
        fixed.formats_of(loaded)? == build.formats && loaded.build.is_none_or(|b| b == build),
        "--method se: the SE back end is built at size class {} and its default formats only (screens up to {}x{}, \
         no --formats); this is a {}x{} screen",
        build.class,
        1 << build.class,
        1 << build.class,
        list.width,
        list.height
    );
    ensure!(fixed.lanes.is_none(), "--method se: --lanes is the vector unit's (--method vector)");
    ensure!(how.top != Some(Top::GpuTop), "--method se: gpu_top holds the scanline method (--method scanline)");
    let mut engines = rtl::se_engines_for(list.width).unwrap_or(u32::MAX);
    for (name, v) in how.params {
        match name.as_str() {
            "ENGINES" => engines = u32::try_from(*v).unwrap_or(u32::MAX),
            _ => bail!("--param {name}: --method se takes ENGINES (its shading engines: 1, 5 or 16)"),
        }
    }
    ensure!(
        rtl::SE_ENGINES.contains(&engines) && 64 * engines >= list.width,
        "--method se: {} engines for a screen {} columns wide: raster_top's SE back end is built with 1, 5 or 16 \
         engines of 64 columns each",
        if engines == u32::MAX { "no number of".to_owned() } else { engines.to_string() },
        list.width
    );
    let cull = if cull_back { Cull::Back } else { Cull::None };
    let background = loaded.background.map(|c| c.round().clamp(0.0, 255.0) as u8);
    let prep = model::raster_top::raster_top_se(&build, list, cull, background)
        .map_err(|e| anyhow!("--engine rtl --method se: {e}"))?;
    ensure!(!prep.front.triangles.is_empty(), "--engine rtl: no triangle to draw");
    let f = Frame {
        build,
        width: list.width,
        height: list.height,
        cull,
        background,
        triangles: &prep.front.triangles,
        lanes: 1,
    };
    let mut dut = sim::se_frame::verilator(engines).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let start = Instant::now();
    let out = sim::se_frame::draw(&mut dut, &f, 2 * prep.cycles + 100_000).map_err(|e| anyhow!(e))?;
    let secs = start.elapsed().as_secs_f64();
    if let Some(first) = out.memory.differs_from(&prep.fb) {
        bail!("the RTL's image differs from the se model's ({first}): a bug in the RTL or the model");
    }
    ensure!(
        out.cycles == prep.cycles && out.memory.writes == prep.pixels_written,
        "the RTL took {} cycles and wrote {} pixels, the model {} and {}: a bug in the RTL or the model",
        out.cycles,
        out.memory.writes,
        prep.cycles,
        prep.pixels_written
    );
    let drawn = out.verdicts.iter().filter(|&&v| v as u64 == rtl::cull_sort::verdict::PASSED).count();
    let mhz = sweep::clock::SE_PIPELINE_MHZ;
    let clock = if engines == 1 { "routed, ECP5" } else { "one engine's, routed, ECP5" };
    let summary = format!(
        "rtl (raster_top of size class {}, METHOD = 2: the scanline front end, se_cmd and {engines} shading engines of \
         64 pixels, in Verilator): {} triangles in, {drawn} drawn; {} spans issued, {} pixels written; {} cycles \
         (model::cycles::se_frame: {}), frame time {:.3} ms at {mhz:.1} MHz ({clock}), {:.3} pixels per clock; \
         {:.0} cycles/s simulated ({secs:.2} s); image, depth and cycles equal to the se model's",
        build.class,
        list.triangles.len(),
        out.reads / 16,
        out.memory.writes,
        out.cycles,
        prep.cycles,
        out.cycles as f64 / (mhz * 1000.0),
        out.memory.writes as f64 / out.cycles.max(1) as f64,
        out.cycles as f64 / secs,
    );
    let writes = out.memory.writes;
    Ok((image_of(out.memory, build.formats.z.frac), (summary, writes)))
}

/// `--top gpu_top`: `loaded` packed into a vertex buffer (a vertex buffer's own bytes when
/// its back-face flag is the one asked for) and drawn by `gpu_top` in Verilator as a host
/// drives it (`sim::soc`), on buffers of the screen's size; `STATUS`, `TRIANGLES` and both
/// buffers checked against `model::gpu_top::run`.
fn gpu_top(loaded: &Loaded, cull_back: bool) -> Result<(Image, (String, u64))> {
    let list = &loaded.trilist;
    let build = Build::default();
    let background = loaded.background.map(|c| c.round().clamp(0.0, 255.0) as u8);
    let bytes = match (&loaded.bytes, loaded.cull_back == cull_back) {
        (Some(bytes), true) => bytes.clone(),
        _ => {
            let (vb, skipped) = model::vertex_buffer::pack(list, &build, cull_back, background)
                .map_err(|e| anyhow!("--engine rtl: packing the vertex buffer: {e}"))?;
            for (i, e) in skipped.iter().take(5) {
                eprintln!("warning: triangle {i} not drawn: {e}");
            }
            vb.encode()
        }
    };
    let (width, height) = (list.width, list.height);
    let cull = if cull_back { Cull::Back } else { Cull::None };
    let prep =
        model::raster_top::raster_top(&build, list, cull, background).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    // Generous: every cycle of the unbuffered frame, the clear, and the parser's reads.
    let limit = 4 * prep.cycles() + 4 * u64::from(width * height) + 100 * bytes.len() as u64 + 100_000;
    let model =
        model::gpu_top::run(&bytes, VB_BASE, [width, height], limit).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let core = sim::soc::verilator().map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let mut soc = Soc::new(core, &bytes, (width, height), Pace::at_once());
    let start = Instant::now();
    let end = soc.frame(true, limit).map_err(|e| anyhow!("--engine rtl: {e}"))?;
    let secs = start.elapsed().as_secs_f64();
    ensure!(
        end.status & 0x1ff == model.status && end.triangles == model.triangles,
        "gpu_top ended with STATUS {:#x} after {} triangles, its model with {:#x} after {}: a bug in the RTL or the model",
        end.status,
        end.triangles,
        model.status,
        model.triangles
    );
    ensure!(end.status & 0x1ff == 0, "gpu_top stopped the frame: STATUS {:#x} (README, \"gpu_top\")", end.status);
    let frame = model.drawn.map(|d| d.2).ok_or_else(|| anyhow!("gpu_top: the header was not taken"))?;
    if let Some(i) =
        (0..frame.color.len()).find(|&i| (soc.color.words[i], soc.depth.words[i]) != (frame.color[i], frame.depth[i]))
    {
        bail!(
            "gpu_top's buffers differ from its model's at pixel ({}, {}): a bug in the RTL or the model",
            i as u32 % width,
            i as u32 / width
        );
    }
    let fb = &prep.render.fb;
    debug_assert!(fb.rgb.iter().map(|&c| color_word(c)).eq(frame.color.iter().copied()));
    let rgb = soc.color.words.iter().map(|&w| [(w >> 16) as u8, (w >> 8) as u8, w as u8]).collect();
    let z = build.formats.z.frac;
    let depth16 = soc.depth.words.iter().map(|&d| depth16(d, z)).collect();
    let image = Image { width, height, rgb, depth16, written: fb.written.clone() };
    let direct = prep.cycles();
    let mhz = sweep::clock::GPU_TOP_MHZ;
    let fetches = soc.vb.requests.len();
    let summary = format!(
        "rtl (gpu_top of size class {}, in Verilator, from a vertex buffer of {} bytes in memory, driven through its \
         registers): {} triangles read, {} drawn; {} bursts read from the vertex buffer; {} depth and {} colour \
         writes (the clear's {} each among them); {} cycles from START to the interrupt ({} for \
         raster_top fed the triangles directly, without the clear), frame time {:.3} ms at {mhz:.1} MHz (gpu_top \
         routed, ECP5); {:.0} cycles/s simulated ({secs:.2} s); STATUS, \
         TRIANGLES, image and depth equal to model::gpu_top's",
        build.class,
        bytes.len(),
        end.triangles,
        prep.sorted.len(),
        fetches,
        soc.depth.written.len(),
        soc.color.written.len(),
        width * height,
        end.cycles,
        direct,
        f64::from(end.cycles) / (mhz * 1000.0),
        soc.cycle as f64 / secs,
    );
    Ok((image, (summary, prep.fragments.iter().sum::<usize>() as u64)))
}
