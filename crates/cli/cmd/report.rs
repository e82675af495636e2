//! `edgepaint report`: synthesize units with Yosys, place and route them with nextpnr, and
//! tabulate area and speed as Markdown and JSON.
//!
//! Per unit and parameter set:
//! * generic: Yosys `synth -flatten`; cells, and 2-input gate equivalents (GE) defined as
//!   transistors / 4 (a CMOS NAND2 is 4 transistors): `stat -tech cmos` for the gates, which
//!   leaves flip-flops out, plus [`ff_transistors`] for each flip-flop;
//! * iCE40: `synth_ice40` of the unit alone: SB_LUT4, SB_DFF*, SB_CARRY, SB_MAC16;
//! * ECP5: `synth_ecp5` of the unit alone: LUT4, TRELLIS_FF, CCU2C, MULT18X18D;
//! * Fmax: the unit inside `rtl::emit::pnr_wrapper` (registered inputs and outputs, four
//!   pins), `nextpnr-ice40` on an iCE40 HX8K (ct256) and `nextpnr-ecp5` on the smallest
//!   LFE5U (25F, 45F, 85F; CABGA381) the synthesized unit fits in, seed 1; the achieved
//!   clock in nextpnr's JSON report. A unit too large for every part has no Fmax.
//! * Hit rate (`--scene`): for the units that hold the texture cache (`texture_cache`,
//!   `texture_unit`, `texture_path`, `raster_top` with `TEXTURE = 1`), the cache at the row's
//!   geometry on each scene's textured fragments in drawing order, per lane lookup
//!   (`accuracy::texture::cache_stats` over the trace `accuracy::texture::judge` records, at
//!   the row's level-of-detail rule).

use super::emit::emit_with;
use accuracy::texture::{cache_stats, judge, CacheStats, TextureSetup, DEFAULT_CACHE};
use anyhow::{anyhow, bail, Context, Result};
use fx::TexFormats;
use model::texture_cache::Params as CacheParams;
use model::texture_unit::Fetch;
use rtl::emit::Emitted;
use scene::Trilist;
use serde::Serialize;
use std::collections::hash_map::{Entry, HashMap};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use texture::LodRule;

/// Arguments of `edgepaint report`.
#[derive(clap::Args)]
pub struct Args {
    /// The unit to report (ept); without it, every unit of the default design.
    #[arg(long, value_name = "NAME")]
    unit: Option<String>,
    /// A parameter of the unit, e.g. `--param P=1024`; give one name several times for one
    /// row per value (`--param P=64 --param P=1024`).
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = super::emit::parse_param)]
    params: Vec<(String, u64)>,
    /// Number formats of a scanline unit (`emit --formats`): a JSON file over the defaults
    /// of its size class N.
    #[arg(long, value_name = "FILE")]
    formats: Option<PathBuf>,
    /// Skip place and route (no Fmax): synthesis only, much faster.
    #[arg(long)]
    no_pnr: bool,
    /// The flows to run: generic, ice40, ecp5 (give it several times; all three without
    /// it). `--flow ecp5` reports a unit that fits no iCE40 (gpu_top) in an hour less.
    #[arg(long = "flow", value_enum, value_name = "FLOW")]
    flows: Vec<Flow>,
    /// nextpnr's router: router1 (its default) or router2, which routes large designs
    /// (triangle_setup, raster_top) in minutes where router1 had not finished in 20.
    #[arg(long, default_value = "router1", value_parser = ["router1", "router2"])]
    router: String,
    /// A textured scene (or trilist) to give the texture cache's hit rate on, for each unit
    /// that holds the cache; repeatable.
    #[arg(long = "scene", value_name = "FILE")]
    scenes: Vec<PathBuf>,
    /// Directory for report.md, report.json and the tools' work files.
    #[arg(short, long, value_name = "DIR", default_value = "target/report")]
    out: PathBuf,
}

/// A synthesis flow of `edgepaint report`.
#[derive(clap::ValueEnum, Clone, Copy, PartialEq, Eq)]
enum Flow {
    /// Yosys `synth -flatten`: generic cells and gate equivalents.
    Generic,
    /// `synth_ice40`, and place and route on an iCE40 HX8K.
    Ice40,
    /// `synth_ecp5`, and place and route on the smallest LFE5U with room.
    Ecp5,
}

/// An FPGA part for place and route: its name, nextpnr's flags for it, its LUT4s,
/// multiplier blocks and block RAMs.
struct Part {
    name: &'static str,
    flags: &'static [&'static str],
    luts: u64,
    dsps: u64,
    brams: u64,
}

/// iCE40 part for place and route: the largest HX part (no DSP blocks; `synth_ice40`
/// infers none).
const ICE40: &[Part] =
    &[Part { name: "iCE40HX8K-CT256", flags: &["--hx8k", "--package", "ct256"], luts: 7_680, dsps: 0, brams: 32 }];
/// ECP5 parts, smallest first.
const ECP5: &[Part] = &[
    Part { name: "LFE5U-25F-CABGA381", flags: &["--25k", "--package", "CABGA381"], luts: 24_288, dsps: 28, brams: 56 },
    Part { name: "LFE5U-45F-CABGA381", flags: &["--45k", "--package", "CABGA381"], luts: 43_848, dsps: 72, brams: 108 },
    Part {
        name: "LFE5U-85F-CABGA381",
        flags: &["--85k", "--package", "CABGA381"],
        luts: 83_640,
        dsps: 156,
        brams: 208,
    },
];

/// The smallest of `parts` with room for `luts`, `dsps` and `brams` (iCE40 SB_RAM40_4K,
/// ECP5 DP16KD), a quarter of its LUTs left for the wrapper and for routing: nextpnr-ecp5
/// took over 20 minutes and had not routed triangle_setup at 91% of an LFE5U-25F's LUTs.
/// (`triangle_queue`'s 138,240 RAM bits fit an HX8K's LUTs and not its 32 block RAMs.)
fn part_for(parts: &'static [Part], luts: u64, dsps: u64, brams: u64) -> Option<&'static Part> {
    parts.iter().find(|p| luts * 4 <= p.luts * 3 && dsps <= p.dsps && brams <= p.brams)
}

/// An FPGA family's flow: its Yosys mapping, the cells that mapping makes, its parts and
/// its place and route.
struct Family {
    /// The flow's name, and the prefix of its work files.
    name: &'static str,
    /// Yosys' mapping pass.
    synth: &'static str,
    /// The cell types of LUTs, carry cells, multipliers, block RAMs and LUT RAMs, and the
    /// prefix of its flip-flops' types.
    lut: &'static str,
    ff_prefix: &'static str,
    carry: &'static str,
    dsp: &'static str,
    bram: &'static str,
    lut_ram: Option<&'static str>,
    /// The LUT sites a netlist occupies, from its cell counts.
    lut_sites: fn(&BTreeMap<String, u64>) -> u64,
    parts: &'static [Part],
    nextpnr: &'static str,
    /// Target clock for timing-driven placement, in MHz; the achieved Fmax is reported
    /// whether or not it meets it.
    target_mhz: &'static str,
    /// The pin constraints (file name, text) written beside the netlist, and nextpnr's
    /// flags for them.
    pins: Option<(&'static str, &'static str)>,
    pin_flags: &'static [&'static str],
}

const ICE40_FAMILY: Family = Family {
    name: "ice40",
    synth: "synth_ice40",
    lut: "SB_LUT4",
    ff_prefix: "SB_DFF",
    carry: "SB_CARRY",
    dsp: "SB_MAC16",
    bram: "SB_RAM40_4K",
    lut_ram: None,
    lut_sites: |cells| count(cells, |k| k == "SB_LUT4"),
    parts: ICE40,
    nextpnr: "nextpnr-ice40",
    target_mhz: "100",
    pins: None,
    pin_flags: &["--pcf-allow-unconstrained"],
};

const ECP5_FAMILY: Family = Family {
    name: "ecp5",
    synth: "synth_ecp5",
    lut: "LUT4",
    ff_prefix: "TRELLIS_FF",
    carry: "CCU2C",
    dsp: "MULT18X18D",
    bram: "DP16KD",
    lut_ram: Some("TRELLIS_DPR16X4"),
    lut_sites: ecp5_lut_sites,
    parts: ECP5,
    nextpnr: "nextpnr-ecp5",
    target_mhz: "200",
    pins: Some(ECP5_LPF),
    pin_flags: &["--lpf", ECP5_LPF.0, "--lpf-allow-unconstrained"],
};

#[derive(Serialize)]
struct Row {
    unit: String,
    parameters: BTreeMap<String, u64>,
    /// The formats file the unit was built at (`--formats`), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    formats: Option<String>,
    /// Each flow's figures; `None` for a flow left out (`--flow`).
    #[serde(skip_serializing_if = "Option::is_none")]
    generic: Option<Generic>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ice40: Option<Fpga>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ecp5: Option<Fpga>,
    /// The texture cache's hit rate on each `--scene`, for a unit that holds the cache.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    hit_rates: Vec<SceneHitRate>,
}

impl Row {
    /// The row's parameters and formats file, as the tables print them.
    fn parameters_text(&self) -> String {
        let params = self.parameters.iter().map(|(k, v)| format!("{k}={v}"));
        params.chain(self.formats.iter().map(|f| format!("formats={f}"))).collect::<Vec<_>>().join(" ")
    }
}

/// The texture cache at a row's geometry on one scene's textured fragments.
#[derive(Serialize)]
struct SceneHitRate {
    scene: String,
    #[serde(flatten)]
    cache: CacheStats,
}

#[derive(Serialize)]
struct Generic {
    /// Yosys generic cells after `synth -flatten`.
    cells: u64,
    /// `stat -tech cmos` estimate of the gates (flip-flops not counted).
    transistors: u64,
    /// Flip-flops, and their transistors by [`ff_transistors`].
    flip_flops: u64,
    ff_transistors: u64,
    /// (transistors + ff_transistors) / 4.
    gate_equivalents: f64,
}

#[derive(Serialize)]
struct Fpga {
    /// The part placed and routed on; `None` when the unit fits none (no Fmax then).
    device: Option<&'static str>,
    luts: u64,
    ffs: u64,
    /// iCE40 SB_CARRY or ECP5 CCU2C (two-bit carry cells).
    carry: u64,
    /// iCE40 SB_MAC16 or ECP5 MULT18X18D.
    dsps: u64,
    /// iCE40 SB_RAM40_4K or ECP5 DP16KD block RAMs.
    block_ram: u64,
    /// ECP5 TRELLIS_DPR16X4, 16 x 4 distributed (LUT) RAM with one write and one
    /// asynchronous read port (the shading engine's corner-turning memories); iCE40 has
    /// none (Yosys builds such memories from flip-flops there).
    lut_ram: u64,
    /// Achieved clock of the wrapped unit after place and route; `None` with `--no-pnr` or
    /// when it fits no part.
    fmax_mhz: Option<f64>,
}

pub fn run(args: Args) -> Result<()> {
    // The scenes first: a bad one is reported before minutes of synthesis.
    let files = args
        .scenes
        .iter()
        .map(|path| {
            let loaded = super::input::load(path, None)?;
            anyhow::ensure!(loaded.trilist.is_textured(), "{}: not textured: no texture cache access", path.display());
            Ok((path.clone(), loaded.trilist))
        })
        .collect::<Result<Vec<_>>>()?;
    let mut scenes = Scenes { files, traces: HashMap::new() };
    let designs: Vec<Emitted> = match &args.unit {
        None if !args.params.is_empty() || args.formats.is_some() => {
            bail!("--param and --formats need --unit: the default design's parameters are fixed")
        }
        None => rtl::emit::default_design(),
        Some(name) => {
            let mut designs = Vec::new();
            for p in sweep(&args.params) {
                match emit_with(name, p, args.formats.as_deref())? {
                    Some(e) => designs.push(e),
                    None => return Ok(()), // an edgepaint compiled at those formats reported
                }
            }
            designs
        }
    };
    let flows = if args.flows.is_empty() { vec![Flow::Generic, Flow::Ice40, Flow::Ecp5] } else { args.flows.clone() };
    let mut tools = vec!["yosys"];
    if !args.no_pnr {
        tools.extend(flows.iter().filter_map(|f| match f {
            Flow::Generic => None,
            Flow::Ice40 => Some("nextpnr-ice40"),
            Flow::Ecp5 => Some("nextpnr-ecp5"),
        }));
    }
    for tool in tools {
        if Command::new(tool).arg("--version").output().is_err() {
            bail!("{tool} is not on PATH: run scripts/setup-tools.sh, then `source scripts/tools-env.sh`");
        }
    }
    let mut rows = Vec::new();
    for e in &designs {
        let mut tag: String = e.params.iter().map(|(k, v)| format!("-{k}{v}")).collect();
        if let Some(stem) = args.formats.as_deref().and_then(Path::file_stem) {
            tag.push_str(&format!("-{}", stem.to_string_lossy()));
        }
        let dir = args.out.join(format!("{}{tag}", e.unit));
        eprintln!("report: {}{tag} in {}", e.unit, dir.display());
        let mut row = report(e, &dir, &flows, (!args.no_pnr).then_some(args.router.as_str()))?;
        row.formats = args.formats.as_ref().map(|f| f.display().to_string());
        row.hit_rates = hit_rates(e.unit, &e.params, &mut scenes)?;
        rows.push(row);
    }
    let md = markdown(&rows);
    let json = serde_json::to_string_pretty(&serde_json::json!({ "units": rows }))? + "\n";
    std::fs::create_dir_all(&args.out)?;
    let (md_path, json_path) = (args.out.join("report.md"), args.out.join("report.json"));
    std::fs::write(&md_path, &md).with_context(|| format!("writing {}", md_path.display()))?;
    std::fs::write(&json_path, &json).with_context(|| format!("writing {}", json_path.display()))?;
    print!("{md}");
    println!("\nwrote {} and {}", md_path.display(), json_path.display());
    Ok(())
}

/// One parameter set per value of a repeated name (a cartesian product over names).
fn sweep(params: &[(String, u64)]) -> Vec<Vec<(String, u64)>> {
    let mut by_name: BTreeMap<&str, Vec<u64>> = BTreeMap::new();
    for (k, v) in params {
        by_name.entry(k).or_default().push(*v);
    }
    by_name.into_iter().fold(vec![vec![]], |sets, (k, values)| {
        sets.iter()
            .flat_map(|set| values.iter().map(move |v| set.iter().cloned().chain([(k.to_owned(), *v)]).collect()))
            .collect()
    })
}

fn report(e: &Emitted, dir: &Path, flows: &[Flow], router: Option<&str>) -> Result<Row> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let unit_v = dir.join(e.file());
    let wrap_v = dir.join(format!("{}_pnr.v", e.unit));
    std::fs::write(&unit_v, &e.verilog)?;
    std::fs::write(&wrap_v, rtl::emit::pnr_wrapper(e))?;
    let top = e.unit;
    let read = format!("read_verilog {}", unit_v.display());
    let generic = if flows.contains(&Flow::Generic) { Some(generic(dir, &read, top)?) } else { None };
    let family = |flow, family| -> Result<Option<Fpga>> {
        if !flows.contains(&flow) {
            return Ok(None);
        }
        fpga(dir, family, &read, &format!("{read}; read_verilog {}", wrap_v.display()), top, router).map(Some)
    };
    let ice40 = family(Flow::Ice40, &ICE40_FAMILY)?;
    let ecp5 = family(Flow::Ecp5, &ECP5_FAMILY)?;
    Ok(Row {
        unit: e.unit.to_owned(),
        parameters: e.params.clone(),
        formats: None,
        generic,
        ice40,
        ecp5,
        hit_rates: Vec::new(),
    })
}

/// The texture cache's geometry and level-of-detail rule in `unit` at `params`, if it holds
/// the cache: `texture_cache` and `texture_unit` at their `SETS`, `WAYS` and `LINE`;
/// `texture_path` and the textured `raster_top` at the unit's default geometry.
fn texture_cache_of(unit: &str, params: &rtl::Params) -> Option<(CacheParams, LodRule)> {
    let p = |name: &str| params.get(name).copied();
    let holds = match unit {
        "texture_cache" | "texture_unit" | "texture_path" => true,
        "raster_top" => p("TEXTURE") == Some(1),
        _ => false,
    };
    let geometry = |name, default: u32| p(name).map_or(default, |v| v as u32);
    let cache = CacheParams {
        sets: geometry("SETS", DEFAULT_CACHE.sets),
        ways: geometry("WAYS", DEFAULT_CACHE.ways),
        line: geometry("LINE", DEFAULT_CACHE.line),
    };
    let lod = if p("EXACT") == Some(1) { LodRule::Exact } else { LodRule::Max };
    holds.then_some((cache, lod))
}

/// The `--scene` files, and each one's trace of texture fetches per level-of-detail rule,
/// drawn once (`accuracy::texture::judge`) however many rows ask for it.
struct Scenes {
    files: Vec<(PathBuf, Trilist)>,
    traces: HashMap<(usize, LodRule), Vec<Fetch>>,
}

/// The hit rate of `unit`'s texture cache at `params` on each of `scenes` (none when it
/// holds no cache).
fn hit_rates(unit: &str, params: &rtl::Params, scenes: &mut Scenes) -> Result<Vec<SceneHitRate>> {
    let Some((cache, lod)) = texture_cache_of(unit, params) else { return Ok(Vec::new()) };
    let mut rates = Vec::new();
    for (i, (path, list)) in scenes.files.iter().enumerate() {
        let trace = match scenes.traces.entry((i, lod)) {
            Entry::Occupied(e) => e.into_mut(),
            Entry::Vacant(e) => {
                let setup = TextureSetup { formats: TexFormats::DEFAULT, lod, affine: false };
                e.insert(judge(list, &setup).map_err(|e| anyhow!("{}: {e}", path.display()))?.trace)
            }
        };
        rates.push(SceneHitRate { scene: path.display().to_string(), cache: cache_stats(&cache, trace) });
    }
    Ok(rates)
}

/// An FPGA flow: the unit alone through `family`'s mapping (`read`: the command reading
/// its Verilog; `top`: its module), and, with a `router`, the unit inside its wrapper
/// (`read_both` reads both) placed and routed on the smallest part with room for it.
fn fpga(dir: &Path, family: &Family, read: &str, read_both: &str, top: &str, router: Option<&str>) -> Result<Fpga> {
    let f = family;
    let script = format!("{read}; {} -top {top}", f.synth);
    let alone = cells(&yosys_stat(dir, f.name, &script, "")?);
    let mut fpga = Fpga {
        device: None,
        luts: count(&alone, |k| k == f.lut),
        ffs: count(&alone, |k| k.starts_with(f.ff_prefix)),
        carry: count(&alone, |k| k == f.carry),
        dsps: count(&alone, |k| k == f.dsp),
        block_ram: count(&alone, |k| k == f.bram),
        lut_ram: count(&alone, |k| Some(k) == f.lut_ram),
        fmax_mhz: None,
    };
    fpga.device = part_for(f.parts, (f.lut_sites)(&alone), fpga.dsps, fpga.block_ram).map(|p| p.name);
    let Some(router) = router.filter(|_| fpga.device.is_some()) else { return Ok(fpga) };
    // The part is chosen for the wrapped unit: the wrapper's shift registers and output
    // multiplexers add a LUT and a flip-flop per port bit.
    let net = format!("{}_pnr.json", f.name);
    let script = format!("{read_both}; {} -top {top}_pnr -json {}", f.synth, dir.join(&net).display());
    let wrapped = cells(&yosys_stat(dir, &format!("{}_pnr", f.name), &script, "")?);
    let part = part_for(f.parts, (f.lut_sites)(&wrapped), count(&wrapped, |k| k == f.dsp), fpga.block_ram);
    fpga.device = part.map(|p| p.name);
    if let Some(part) = part {
        if let Some((file, text)) = f.pins {
            std::fs::write(dir.join(file), text).with_context(|| format!("writing {}", dir.join(file).display()))?;
        }
        fpga.fmax_mhz = Some(nextpnr(dir, f.nextpnr, (part.flags, &net, f.target_mhz, f.pin_flags), router)?);
    }
    Ok(fpga)
}

/// The generic flow: Yosys `synth -flatten` of the unit alone (`read`: the command reading
/// its Verilog; `top`: its module) and `stat -tech cmos`.
fn generic(dir: &Path, read: &str, top: &str) -> Result<Generic> {
    let generic = yosys_stat(dir, "generic", &format!("{read}; synth -flatten -top {top}"), "-tech cmos")?;
    // "N+" when some cells (the flip-flops) have no estimate.
    let transistors: u64 = generic["estimated_num_transistors"]
        .as_str()
        .and_then(|s| s.trim_end_matches('+').parse().ok())
        .ok_or_else(|| anyhow!("no transistor estimate in Yosys' stat"))?;
    let flops = cells(&generic).into_iter().filter_map(|(k, n)| ff_transistors(&k).map(|t| (n, n * t)));
    let (flip_flops, ff_transistors) = flops.fold((0, 0), |(a, b), (n, t)| (a + n, b + t));
    Ok(Generic {
        cells: generic["num_cells"].as_u64().ok_or_else(|| anyhow!("no cell count in Yosys' stat"))?,
        transistors,
        flip_flops,
        ff_transistors,
        gate_equivalents: (transistors + ff_transistors) as f64 / 4.0,
    })
}

/// The cells of `cells` whose type passes `f`.
fn count(cells: &BTreeMap<String, u64>, f: impl Fn(&str) -> bool) -> u64 {
    cells.iter().filter(|(k, _)| f(k)).map(|(_, n)| n).sum()
}

/// The LUT4 sites an ECP5 netlist (`synth_ecp5` cell counts) occupies: a CCU2C (two bits
/// of carry) takes the two LUT4s of a slice, a TRELLIS_DPR16X4 three slices (two hold the
/// 16 x 4 bits, one its write port).
fn ecp5_lut_sites(cells: &BTreeMap<String, u64>) -> u64 {
    let n = |name: &str| cells.get(name).copied().unwrap_or(0);
    n("LUT4") + 2 * n("CCU2C") + 6 * n("TRELLIS_DPR16X4")
}

/// Transistors of a Yosys generic flip-flop cell (`$_DFF_P_`, `$_DFFE_PP_`,
/// `$_SDFFCE_PP0P_`, ...), which `stat -tech cmos` does not count; `None` for other cells.
/// A static master-slave D flip-flop is 24 transistors (two latches of two transmission gates
/// and two inverters, and the clock inverters); an enable adds a 2:1 mux (12, Yosys' cost of
/// `$_MUX_`), a synchronous set or reset a gate (4), an asynchronous one 4 more.
fn ff_transistors(cell: &str) -> Option<u64> {
    let kind = cell.strip_prefix("$_")?;
    let (name, _) = kind.split_once('_')?;
    let base = match name {
        "DFF" | "DFFE" | "SDFF" | "SDFFE" | "SDFFCE" | "DFFSR" | "DFFSRE" | "ALDFF" | "ALDFFE" => 24,
        _ => return None,
    };
    let enable = if name.ends_with('E') { 12 } else { 0 };
    let reset = if name.starts_with("SDFF") || name.starts_with("ALDFF") { 4 } else { 0 };
    let async_reset =
        if name.starts_with("DFF") && kind.split('_').nth(1).is_some_and(|p| p.len() >= 3) { 4 } else { 0 };
    Some(base + enable + reset + async_reset)
}

/// Runs Yosys script `script` (log: `dir/<step>.log`).
fn yosys(dir: &Path, step: &str, script: &str) -> Result<()> {
    let log = dir.join(format!("{step}.log"));
    let out =
        Command::new("yosys").arg("-q").arg("-l").arg(&log).arg("-p").arg(script).output().context("running yosys")?;
    if !out.status.success() {
        bail!("yosys ({step}) failed; log: {}\n{}", log.display(), String::from_utf8_lossy(&out.stderr));
    }
    Ok(())
}

/// Runs `script` then `stat -json <stat_args>`; returns the whole design's statistics.
fn yosys_stat(dir: &Path, step: &str, script: &str, stat_args: &str) -> Result<serde_json::Value> {
    let stat = dir.join(format!("{step}.stat.json"));
    yosys(dir, step, &format!("{script}; tee -q -o {} stat -json {stat_args}", stat.display()))?;
    let text = std::fs::read_to_string(&stat).with_context(|| format!("reading {}", stat.display()))?;
    let json: serde_json::Value = serde_json::from_str(&text).with_context(|| format!("parsing {}", stat.display()))?;
    let design =
        json.get("design").cloned().or_else(|| json["modules"].as_object().and_then(|m| m.values().next().cloned()));
    design.ok_or_else(|| anyhow!("{}: no design statistics", stat.display()))
}

/// Cell counts by type from a `stat -json` design entry.
fn cells(design: &serde_json::Value) -> BTreeMap<String, u64> {
    design["num_cells_by_type"]
        .as_object()
        .map(|m| m.iter().map(|(k, v)| (k.clone(), v.as_u64().unwrap_or(0))).collect())
        .unwrap_or_default()
}

/// The ECP5 pin constraints (file name, text): the wrapper's clock on pin G2 of the
/// CABGA381 package, a primary clock input (PCLKT6_0, the ULX3S board's 25 MHz clock).
/// Left to nextpnr, the clock may land on a plain I/O that cannot reach the global clock
/// network: router2 failed on triangle_setup so ("Failed to route arc 0.0 of net
/// 'clk$TRELLIS_IO_IN' ... to G_CLKI_TDCC0").
const ECP5_LPF: (&str, &str) = ("ecp5.lpf", "LOCATE COMP \"clk\" SITE \"G2\";\nIOBUF PORT \"clk\" IO_TYPE=LVCMOS33;\n");

/// Places and routes netlist `dir/net`; returns the achieved Fmax in MHz of its one clock.
/// Runs in `dir` with relative paths: the YoWASP build of nextpnr-ecp5 sees only the
/// current directory.
/// `args`: the part's flags, the netlist, the target clock in MHz, the pin constraints'
/// flags; `router`: nextpnr's `--router`.
fn nextpnr(dir: &Path, tool: &str, args: (&[&str], &str, &str, &[&str]), router: &str) -> Result<f64> {
    let (part, net, target_mhz, pins) = args;
    let (report, log) = (format!("{tool}.report.json"), format!("{tool}.log"));
    let out = Command::new(tool)
        .current_dir(dir)
        .args(part)
        .args(["--json", net, "--timing-allow-fail", "--seed", "1", "--freq", target_mhz])
        .args(pins)
        .args(["--router", router])
        .args(["--report", &report, "--log", &log])
        .output()
        .with_context(|| format!("running {tool}"))?;
    if !out.status.success() {
        bail!("{tool} failed; log: {}\n{}", dir.join(log).display(), String::from_utf8_lossy(&out.stderr));
    }
    let report = dir.join(report);
    let text = std::fs::read_to_string(&report).with_context(|| format!("reading {}", report.display()))?;
    let json: serde_json::Value =
        serde_json::from_str(&text).with_context(|| format!("parsing {}", report.display()))?;
    let clocks = json["fmax"].as_object().ok_or_else(|| anyhow!("{}: no fmax", report.display()))?;
    clocks
        .values()
        .filter_map(|c| c["achieved"].as_f64())
        .reduce(f64::min)
        .ok_or_else(|| anyhow!("{}: no achieved clock", report.display()))
}

fn markdown(rows: &[Row]) -> String {
    const SKIPPED: &str = "–";
    let mhz = |f: &Fpga| match (f.fmax_mhz, f.device) {
        (Some(mhz), Some(part)) => format!("{mhz:.1} ({})", part.split('-').take(2).collect::<Vec<_>>().join("-")),
        (_, None) => "does not fit".to_owned(),
        (None, Some(_)) => SKIPPED.to_owned(),
    };
    // A flow left out (`--flow`) leaves its columns "–".
    let columns = |f: Option<&Fpga>, n: usize, cols: &dyn Fn(&Fpga) -> Vec<String>| {
        f.map_or_else(|| vec![SKIPPED.to_owned(); n], cols)
    };
    let mut md = String::from(
        "| unit | parameters | generic cells | GE (2-input) | iCE40 LUT | iCE40 FF | iCE40 carry | iCE40 DSP | iCE40 BRAM | iCE40 Fmax MHz | ECP5 LUT | ECP5 FF | ECP5 LUT RAM | ECP5 carry | ECP5 DSP | ECP5 BRAM | ECP5 Fmax MHz |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let mut cells = vec![r.unit.clone(), r.parameters_text()];
        cells.extend(match &r.generic {
            Some(g) => vec![g.cells.to_string(), format!("{:.0}", g.gate_equivalents)],
            None => vec![SKIPPED.to_owned(); 2],
        });
        cells.extend(columns(r.ice40.as_ref(), 6, &|i| {
            let n = [i.luts, i.ffs, i.carry, i.dsps, i.block_ram];
            n.iter().map(u64::to_string).chain([mhz(i)]).collect()
        }));
        cells.extend(columns(r.ecp5.as_ref(), 7, &|e| {
            let n = [e.luts, e.ffs, e.lut_ram, e.carry, e.dsps, e.block_ram];
            n.iter().map(u64::to_string).chain([mhz(e)]).collect()
        }));
        writeln!(md, "| {} |", cells.join(" | ")).expect("writing to a String");
    }
    md.push_str(&format!(
        "\nGE: transistors / 4, Yosys `stat -tech cmos` for the gates plus 24 per flip-flop (36 with an enable). LUT, FF, carry, DSP, BRAM (SB_RAM40_4K / DP16KD): the unit alone through \
         `synth_ice40` / `synth_ecp5`. Fmax: the unit between registers (`rtl::emit::pnr_wrapper`), nextpnr on {} and the \
         smallest of {} with room for it (LUTs at most 75% of the part's; its multipliers and block RAMs).\n",
        ICE40[0].name,
        ECP5.iter().map(|p| p.name).collect::<Vec<_>>().join(", ")
    ));
    if rows.iter().any(|r| !r.hit_rates.is_empty()) {
        md.push_str(
            "\nThe texture cache on each scene's textured fragments, in drawing order (per lane lookup):\n\n\
             | unit | parameters | scene | sets, ways, words a line | lookups | hits | misses | hit rate |\n\
             |---|---|---|---|---:|---:|---:|---:|\n",
        );
        for r in rows {
            for h in &r.hit_rates {
                let c = &h.cache;
                writeln!(
                    md,
                    "| {} | {} | {} | {}, {}, {} | {} | {} | {} | {:.4} |",
                    r.unit,
                    r.parameters_text(),
                    h.scene,
                    c.sets,
                    c.ways,
                    c.line,
                    c.hits + c.misses,
                    c.hits,
                    c.misses,
                    c.hit_rate
                )
                .expect("writing to a String");
            }
        }
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_sweep_gives_one_set_per_value() {
        let p = |k: &str, v| (k.to_owned(), v);
        assert_eq!(sweep(&[p("P", 64), p("P", 1024)]), vec![vec![p("P", 64)], vec![p("P", 1024)]]);
        assert_eq!(sweep(&[]), vec![Vec::<(String, u64)>::new()]);
        assert_eq!(sweep(&[p("A", 1), p("B", 2), p("A", 3)]).len(), 2);
    }

    #[test]
    fn report_places_on_the_smallest_part_with_room() {
        let name = |p: Option<&Part>| p.map(|p| p.name);
        assert_eq!(name(part_for(ECP5, 1_000, 4, 0)), Some("LFE5U-25F-CABGA381"));
        // 75% of 24,288 LUTs is 18,216: one more goes to the 45F; so do 29 multipliers.
        assert_eq!(name(part_for(ECP5, 18_216, 0, 0)), Some("LFE5U-25F-CABGA381"));
        assert_eq!(name(part_for(ECP5, 18_217, 0, 0)), Some("LFE5U-45F-CABGA381"));
        assert_eq!(name(part_for(ECP5, 1_000, 29, 0)), Some("LFE5U-45F-CABGA381"));
        assert_eq!(name(part_for(ECP5, 70_000, 0, 0)), None);
        // Block RAMs: 56 on the 25F, 108 on the 45F, 208 on the 85F; 32 on an HX8K.
        assert_eq!(name(part_for(ECP5, 1_000, 0, 57)), Some("LFE5U-45F-CABGA381"));
        assert_eq!(name(part_for(ECP5, 1_000, 0, 209)), None);
        assert_eq!(name(part_for(ICE40, 1_000, 0, 33)), None);
        assert_eq!(name(part_for(ICE40, 6_000, 0, 0)), None);
        assert_eq!(name(part_for(ICE40, 5_760, 0, 0)), Some("iCE40HX8K-CT256"));
    }

    #[test]
    fn report_leaves_the_columns_of_a_flow_left_out_empty() {
        let ecp5 = Fpga {
            device: Some("LFE5U-85F-CABGA381"),
            luts: 26_565,
            ffs: 18_784,
            carry: 4_269,
            dsps: 32,
            block_ram: 13,
            lut_ram: 0,
            fmax_mhz: Some(30.4),
        };
        let row = Row {
            unit: "gpu_top".to_owned(),
            parameters: BTreeMap::from([("N".to_owned(), 10)]),
            formats: None,
            generic: None,
            ice40: None,
            ecp5: Some(ecp5),
            hit_rates: Vec::new(),
        };
        let md = markdown(&[row]);
        let line = md.lines().nth(2).expect("a row under the header");
        assert_eq!(
            line,
            "| gpu_top | N=10 | – | – | – | – | – | – | – | – | 26565 | 18784 | 0 | 4269 | 32 | 13 | 30.4 (LFE5U-85F) |"
        );
        assert_eq!(line.matches('|').count(), md.lines().next().unwrap().matches('|').count(), "one cell per column");
    }

    /// `scenes/textured/checker.json` at 128 x 96.
    fn checker() -> (PathBuf, Trilist) {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/textured/checker.json");
        let loaded = super::super::input::load(&path, Some(super::super::input::Size { width: 128, height: 96 }))
            .expect("the shipped checker scene");
        (path, loaded.trilist)
    }

    fn params(p: &[(&str, u64)]) -> rtl::Params {
        p.iter().map(|(k, v)| (k.to_string(), *v)).collect()
    }

    #[test]
    fn report_gives_the_texture_cache_hit_rate_of_each_unit_that_holds_it() {
        let mut scenes = Scenes { files: vec![checker()], traces: HashMap::new() };
        let mut rate = |unit: &str, p: &[(&str, u64)]| {
            let mut r = hit_rates(unit, &params(p), &mut scenes).expect("a textured scene");
            assert!(r.len() <= 1, "one scene, one rate");
            r.pop().map(|h| h.cache)
        };
        // No cache, no rate.
        assert!(rate("edge_walk", &[]).is_none());
        assert!(rate("raster_top", &[("TEXTURE", 0)]).is_none());
        let small = rate("texture_cache", &[("SETS", 16), ("WAYS", 1), ("LINE", 4)]).expect("the cache itself");
        let default = rate("texture_unit", &[("SETS", 64), ("WAYS", 2), ("LINE", 4), ("EXACT", 0)]).expect("the unit");
        let big = rate("texture_cache", &[("SETS", 256), ("WAYS", 4), ("LINE", 16)]).expect("the cache itself");
        assert_eq!((small.sets, small.ways, small.line), (16, 1, 4));
        assert_eq!((big.sets, big.ways, big.line), (256, 4, 16));
        // Every lane the unit enables is one lookup, at any geometry.
        let setup = TextureSetup { formats: TexFormats::DEFAULT, lod: LodRule::Max, affine: false };
        let trace = judge(&checker().1, &setup).expect("the checker scene").trace;
        let lanes: u64 = trace.iter().map(|f| f.iter().flatten().count() as u64).sum();
        assert!(lanes > 1000, "the scene textures {lanes} lanes");
        for c in [&small, &default, &big] {
            assert_eq!(c.hits + c.misses, lanes, "{} sets: lookups", c.sets);
            assert!((c.hit_rate - c.hits as f64 / lanes as f64).abs() < 1e-12);
        }
        // A larger cache misses less on the checker.
        assert!(small.hit_rate < default.hit_rate && default.hit_rate < big.hit_rate, "{small:?} {default:?} {big:?}");
        // The path and the textured raster_top hold the unit at its default geometry.
        for (unit, p) in [("texture_path", &[("EXACT", 0)][..]), ("raster_top", &[("TEXTURE", 1), ("EXACT", 0)][..])] {
            let c = rate(unit, p).expect("holds the cache");
            assert_eq!((c.sets, c.ways, c.line, c.hits, c.misses), (64, 2, 4, default.hits, default.misses), "{unit}");
        }
        // GL's exact rule picks other levels, so other texels.
        assert_eq!(texture_cache_of("texture_path", &params(&[("EXACT", 1)])).map(|c| c.1), Some(LodRule::Exact));
    }

    #[test]
    fn report_refuses_a_scene_without_texture_before_synthesis() {
        let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cube.json");
        let args = Args {
            unit: Some("texture_cache".into()),
            params: Vec::new(),
            formats: None,
            no_pnr: true,
            flows: vec![Flow::Generic],
            router: "router1".into(),
            scenes: vec![cube],
            out: std::env::temp_dir().join("edgepaint-report-untextured"),
        };
        let e = run(args).expect_err("an untextured scene").to_string();
        assert!(e.contains("cube.json") && e.contains("not textured"), "{e}");
    }

    #[test]
    fn report_counts_flip_flop_transistors() {
        assert_eq!(ff_transistors("$_DFF_P_"), Some(24));
        assert_eq!(ff_transistors("$_DFFE_PP_"), Some(36));
        assert_eq!(ff_transistors("$_DFF_PP0_"), Some(28));
        assert_eq!(ff_transistors("$_SDFFCE_PP0P_"), Some(40));
        assert_eq!(ff_transistors("$_SDFF_PP1_"), Some(28));
        assert_eq!(ff_transistors("$_MUX_"), None);
        assert_eq!(ff_transistors("$_XOR_"), None);
    }
}
