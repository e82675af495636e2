//! `edgepaint fit`: the narrowest scanline design that meets an accuracy target on a
//! workload (`fit` crate), emitted as Verilog, synthesized, and proven on the workload in
//! Verilator.
//!
//! Writes into DIR: `formats.json` (every quantity's format: `--formats` of `emit`,
//! `render`, `report`), `manifest.json` (the design, the target, every scene's measures,
//! the minimality trials), `hdl/raster_top.v` with its manifest (`edgepaint emit` at the
//! fitted build), `yosys/` (`edgepaint report --no-pnr` of the fitted raster_top),
//! `proof/<scene>.png` (each scene drawn by the fitted RTL in Verilator, checked equal to the
//! model, image and depth) and `report.md`.

use super::input::Size;
use anyhow::{anyhow, bail, Context, Result};
use fit::parts::Needed;
use fit::search::{cost, fit, Objective};
use fit::target::Target;
use std::path::{Path, PathBuf};
use std::process::Command;
use sweep::area::Model;
use sweep::row::Row;
use sweep::run::Options;

/// Arguments of `edgepaint fit`.
#[derive(clap::Args)]
pub struct Args {
    /// The workload: scene files or trilists (JSON).
    #[arg(required = true)]
    inputs: Vec<PathBuf>,
    /// The accuracy every scene must meet, e.g.
    /// `psnr>=45,colour_max_lsb<=2,depth_order=exact,coverage_unexplained=0` (README, "Fit").
    #[arg(long, value_name = "SPEC")]
    target: String,
    /// The method: `scanline` (001/003), the one whose pipeline exists in RTL; `auto`
    /// chooses among those (today scanline).
    #[arg(long, default_value = "auto", value_parser = ["auto", "scanline", "se", "vector"])]
    method: String,
    /// What setup's multipliers K and divider stages L are chosen for.
    #[arg(long, default_value = "area", value_parser = ["area", "cycles", "area*cycles"])]
    objective: String,
    /// Integer bits of headroom over the workload's ranges (`dz`, `dc`, `ooa_d`, `z_acc`,
    /// `c_acc`; each range x 2^BITS): for inputs near the workload, such as an animation's
    /// other frames. 0: the workload as given (a scene beyond it is reported by the analysis
    /// mode, not drawn wrong).
    #[arg(long, value_name = "BITS", default_value_t = 0, value_parser = clap::value_parser!(u32).range(0..=32))]
    margin: u32,
    /// Override the scenes' resolution, e.g. 320x240.
    #[arg(long)]
    size: Option<Size>,
    /// Threads (default: one per core).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// Skip Yosys on the fitted design (several minutes); the report then gives the area
    /// model's figures only.
    #[arg(long)]
    no_synth: bool,
    /// Skip the Verilator proof on the workload (a minute or more per scene).
    #[arg(long)]
    no_proof: bool,
    /// Output directory.
    #[arg(short, long)]
    out: PathBuf,
}

pub fn run(args: Args) -> Result<()> {
    if args.method == "se" || args.method == "vector" {
        bail!(
            "--method {}: fit searches the scanline pipeline's formats and parts only so far (the {} method's RTL is \
             built at the default formats); use scanline or auto",
            args.method,
            args.method
        );
    }
    let target = Target::parse(&args.target).map_err(|e| anyhow!(e))?;
    let objective = match args.objective.as_str() {
        "cycles" => Objective::Cycles,
        "area*cycles" => Objective::AreaCycles,
        _ => Objective::Area,
    };
    let inputs = args.inputs.iter().map(|p| super::sweep::load(p, args.size)).collect::<Result<Vec<_>>>()?;
    let opts = Options { jobs: args.jobs, shard: None, cache: Some(args.out.join("cache")), area: None };
    let start = std::time::Instant::now();
    eprintln!("fit: searching the formats ({} scenes)", inputs.len());
    let fitted = fit(&inputs, &target, objective, args.margin, &opts).map_err(|e| anyhow!(e))?;
    let search_s = start.elapsed().as_secs_f64();
    let d = fitted.design;
    let out = &args.out;
    std::fs::create_dir_all(out).with_context(|| format!("{}: cannot create", out.display()))?;
    let formats_path = out.join("formats.json");
    let formats_json = serde_json::to_string_pretty(&d.formats)? + "\n";
    super::input::write(&formats_path, "the fitted formats", formats_json.as_bytes())?;
    let side = 1u32 << d.class;
    let reread =
        fx::Formats::with_overrides(side, side, &serde_json::from_str(&formats_json)?).map_err(|e| anyhow!(e))?;
    anyhow::ensure!(reread == d.formats, "formats.json does not read back as the fitted formats: a bug in fit");
    let needed = fit::parts::needed(&inputs, &d.formats);
    let mut params = vec![("N", d.class as u64), ("K", d.k as u64), ("L", d.l as u64)];
    params.extend(needed.parts.params());
    let edgepaint = |what: &str, sub: &[&str], more: &[&str]| -> Result<()> {
        let mut cmd = Command::new(std::env::current_exe()?);
        cmd.args(sub).args(["--formats"]).arg(&formats_path);
        cmd.args(more);
        eprintln!("fit: {what}");
        let status = cmd.status().with_context(|| format!("running edgepaint for {what}"))?;
        anyhow::ensure!(status.success(), "{what} failed ({status})");
        Ok(())
    };
    let param_args: Vec<String> = params.iter().flat_map(|(k, v)| ["--param".into(), format!("{k}={v}")]).collect();
    let param_args: Vec<&str> = param_args.iter().map(String::as_str).collect();
    let hdl = out.join("hdl");
    let emit = [&["emit", "--unit", "raster_top"][..], &param_args].concat();
    edgepaint("emitting the fitted raster_top", &emit, &["-o", path(&hdl)?])?;
    let yosys = if args.no_synth {
        None
    } else {
        let dir = out.join("yosys");
        let report = [&["report", "--no-pnr", "--unit", "raster_top"][..], &param_args].concat();
        edgepaint("synthesizing it (Yosys, several minutes)", &report, &["-o", path(&dir)?])?;
        let text = std::fs::read_to_string(dir.join("report.json")).context("reading Yosys' report")?;
        Some(serde_json::from_str::<serde_json::Value>(&text)?["units"][0].clone())
    };
    let mut proven = Vec::new();
    if !args.no_proof {
        let dir = out.join("proof");
        std::fs::create_dir_all(&dir).with_context(|| format!("{}: cannot create", dir.display()))?;
        for (input, file) in inputs.iter().zip(&args.inputs) {
            let png = dir.join(format!("{}.png", input.name));
            let mut more = [&["--engine", "rtl", "--top", "raster_top", "-o", path(&png)?][..], &param_args].concat();
            let size = args.size.map(|s| format!("{}x{}", s.width, s.height));
            if let Some(s) = &size {
                more.extend(["--size", s]);
            }
            more.push(path(file)?);
            edgepaint(&format!("drawing {} with the fitted RTL in Verilator", input.name), &["render"], &more)?;
            proven.push(input.name.clone());
        }
    }
    let manifest = serde_json::json!({
        "class": d.class, "K": d.k, "L": d.l, "formats": d.formats, "target": args.target,
        "objective": args.objective, "scenes": fitted.rows, "default_scenes": fitted.default_rows,
        "narrower": fitted.narrower.iter().map(|(k, t)| serde_json::json!({"knob": k, "value": t.set[k], "misses": t.misses})).collect::<Vec<_>>(),
        "trials": fitted.trials, "proven_in_verilator": proven,
        "margin": fitted.margin,
        "ranges": fitted.ints.iter().map(|i| serde_json::json!({"quantity": i.quantity, "min": i.range.map(|r| r.0), "max": i.range.map(|r| r.1), "int_needed": i.needed, "int_floor": i.floor, "int_default": i.default, "int_fitted": i.fitted})).collect::<Vec<_>>(),
        "parts": needed.parts, "parts_needed_by": needed.why.iter().map(|(p, s)| serde_json::json!({"param": p, "scene": s})).collect::<Vec<_>>(),
    });
    super::input::write(
        &out.join("manifest.json"),
        "the fit's manifest",
        (serde_json::to_string_pretty(&manifest)? + "\n").as_bytes(),
    )?;
    let md = report(&fitted, &needed, &target, &args, yosys.as_ref(), &proven, search_s);
    super::input::write(&out.join("report.md"), "the fit's report", md.as_bytes())?;
    print!("{md}");
    println!("wrote {}", out.display());
    Ok(())
}

/// `p` as a string for a command line; an error for a path that is not UTF-8.
fn path(p: &Path) -> Result<&str> {
    p.to_str().ok_or_else(|| anyhow!("{}: not a UTF-8 path", p.display()))
}

/// The mean of `f` over `rows`.
fn mean(rows: &[Row], f: impl Fn(&Row) -> f64) -> f64 {
    rows.iter().map(f).sum::<f64>() / rows.len().max(1) as f64
}

/// The report: the fitted design beside the default one.
fn report(
    fitted: &fit::search::Fitted,
    needed: &Needed,
    target: &Target,
    args: &Args,
    yosys: Option<&serde_json::Value>,
    proven: &[String],
    secs: f64,
) -> String {
    let model = Model::calibrated();
    let d = &fitted.design;
    let default = &fitted.default;
    let (cf, cd) = (cost(d, model), cost(default, model));
    let mut md = format!("# edgepaint fit\n\nWorkload: {}. Target: `{}` (every scene; `problems=0` unless bounded). Method: scanline (001/003), the one method with a pipeline in RTL. Objective: {}. Search: {} designs run in {secs:.1} s.\n\n",
        fitted.rows.iter().map(|r| r.scene.as_str()).collect::<Vec<_>>().join(", "), args.target, args.objective, fitted.trials);
    md += "| | default | fitted |\n|---|---|---|\n";
    md += &format!("| size class | {} | {} |\n| K, L | 7, 5 | {}, {} |\n", default.class, d.class, d.k, d.l);
    let removed: Vec<&str> = needed.parts.params().iter().filter(|(_, on)| *on == 0).map(|(p, _)| *p).collect();
    md += &format!(
        "| optional parts removed | none | {} |\n",
        if removed.is_empty() { "none".into() } else { removed.join(", ") }
    );
    for ((q, fd), (_, ff)) in default.formats.named().iter().zip(d.formats.named()) {
        let mark = if *fd != ff { " **" } else { "" };
        md += &format!("| {q} | {fd} | {ff}{mark} |\n");
    }
    let pct = |a: f64, b: f64| format!("{:+.0}%", 100.0 * (b / a - 1.0));
    md += &format!("| GE (area model, every part present) | {:.0} | {:.0} ({}) |\n", cd.ge, cf.ge, pct(cd.ge, cf.ge));
    md += &format!(
        "| ECP5 LUT4 / FF / DSP (area model, every part present) | {:.0} / {:.0} / {:.0} | {:.0} / {:.0} / {:.0} |\n",
        cd.ecp5_lut4, cd.ecp5_ff, cd.ecp5_dsp, cf.ecp5_lut4, cf.ecp5_ff, cf.ecp5_dsp
    );
    md += &format!("| iCE40 LUT4 (area model, every part present) | {:.0} | {:.0} |\n", cd.ice40_lut4, cf.ice40_lut4);
    if let Some(y) = yosys {
        let measured = model.measured(default);
        let n = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
        let ge = n(&y["generic"]["gate_equivalents"]);
        md += &format!(
            "| GE (Yosys, emitted raster_top) | {} | {ge:.0}{} |\n| ECP5 LUT4 / FF / DSP (Yosys) | {} | {:.0} / {:.0} / {:.0} |\n| iCE40 LUT4 (Yosys) | {} | {:.0} |\n",
            measured.map_or("–".into(), |c| format!("{:.0}", c.ge)),
            measured.map_or(String::new(), |c| format!(" ({})", pct(c.ge, ge))),
            measured.map_or("–".into(), |c| format!("{:.0} / {:.0} / {:.0}", c.ecp5_lut4, c.ecp5_ff, c.ecp5_dsp)),
            n(&y["ecp5"]["luts"]), n(&y["ecp5"]["ffs"]), n(&y["ecp5"]["dsps"]),
            measured.map_or("–".into(), |c| format!("{:.0}", c.ice40_lut4)),
            n(&y["ice40"]["luts"]),
        );
    }
    md += &format!(
        "| cycles per frame (mean) | {:.0} | {:.0} |\n",
        mean(&fitted.default_rows, |r| r.cycles as f64),
        mean(&fitted.rows, |r| r.cycles as f64)
    );
    md += &format!(
        "| clock (modelled), MHz | {:.1} | {:.1} |\n",
        mean(&fitted.default_rows, |r| r.clock_mhz.unwrap_or(f64::NAN)),
        mean(&fitted.rows, |r| r.clock_mhz.unwrap_or(f64::NAN))
    );
    md += "\n## Units present\n\nThe optional parts of the units (`rtl::switch`), kept only where the workload uses them (`fit::parts`):\n\n| part | fitted | because |\n|---|---|---|\n";
    for (name, on) in needed.parts.params() {
        let doc = rtl::switch::Parts::PARAMS.iter().find(|(p, _)| *p == name).map_or("", |(_, d)| d);
        let because = needed
            .why
            .iter()
            .find(|(p, _)| *p == name)
            .map_or("nothing in the workload uses it".to_string(), |(_, s)| format!("{s} uses it"));
        md += &format!(
            "| `{name}` ({}) | {} | {because} |\n",
            doc.split(';').next().unwrap_or(doc).trim_start_matches("1: "),
            if on == 1 { "present" } else { "**removed**" }
        );
    }
    md += &format!("\n## Integer bits from the workload's ranges\n\nThe values the model's registers were given over the workload (analysis mode), the integer bits they need, plus the margin ({} bits), within the RTL's floor and the defaults' rules (`fit::search`):\n\n| quantity | range seen | needed | floor | default | fitted |\n|---|---|---:|---:|---:|---:|\n", fitted.margin);
    for i in &fitted.ints {
        let range = i.range.map_or("none".to_string(), |(lo, hi)| format!("[{lo:.4}, {hi:.4}]"));
        md += &format!("| {} | {range} | {} | {} | {} | {} |\n", i.quantity, i.needed, i.floor, i.default, i.fitted);
    }
    md += "\n## Each scene against the target\n\n| scene | design |";
    for t in &target.terms {
        md += &format!(" {t} |");
    }
    md += "\n|---|---|";
    md += &"---:|".repeat(target.terms.len());
    md += "\n";
    for (label, rows) in [("default", &fitted.default_rows), ("fitted", &fitted.rows)] {
        for r in rows {
            md += &format!("| {} | {label} |", r.scene);
            for t in &target.terms {
                let shown = fit::target::shown(t.measure.of(r));
                md += &format!(" {shown}{} |", if t.met(r) { "" } else { " (missed)" });
            }
            md += "\n";
        }
    }
    md += "\n## Minimal knob by knob\n\nEach knob one bit narrower, run on the workload:\n\n";
    for (knob, t) in &fitted.narrower {
        md += &format!("- {knob} = {}: {}\n", t.set[knob], t.misses.first().map_or("passes (?)", String::as_str));
    }
    md += &match proven.len() {
        0 => "\nNot proven in Verilator (`--no-proof`).\n".to_string(),
        _ => format!("\n**Proof.** The fitted raster_top (its formats, K and L, and the parts present), in Verilator, drew {} exactly as the model does at the fitted design: image and depth bit for bit, and the cycles `model::cycles` predicts (`render --engine rtl`). The guarantee is for this workload as given: a scene with larger ranges may need wider formats, and the models' analysis mode (`render --analysis`) reports the overflow.\n", proven.join(", ")),
    };
    md
}
