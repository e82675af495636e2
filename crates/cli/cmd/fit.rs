//! `edgepaint fit`: the smallest design that meets an accuracy target on a workload (`fit`
//! crate): the narrowest scanline design, or with `--method auto` (the default) whichever
//! of it and the barycentric and SE back ends at their built formats best meets the
//! objective (`fit::method`), emitted as Verilog, synthesized, and proven on the workload
//! in Verilator.
//!
//! Writes into DIR: `formats.json` (every quantity's format: `--formats` of `emit`,
//! `render`, `report`), `manifest.json` (the design, the target, every scene's measures,
//! the methods compared, the minimality trials), `hdl/raster_top.v` with its manifest
//! (`edgepaint emit` at the chosen design), `yosys/` (`edgepaint report --no-pnr` of the
//! chosen raster_top), `proof/<scene>.png` (each scene drawn by the chosen RTL in
//! Verilator, checked equal to the model: image, depth and cycles) and `report.md`.
//!
//! A textured scene's geometry and lit colours are fitted as the rest (its textures
//! stripped: texture coordinates go through `texture_setup`'s planes, not the pipeline's
//! formats), and the texture unit (paper 001 section II-5) is fitted on its textured
//! fragments (`fit::texture`): the narrowest knobs meeting the conformance check and the
//! target's PSNR, written into `formats.json`'s `"texture"` object, and the texture units
//! emitted beside raster_top, each into `hdl/<unit>/` (at their built formats, the cache at
//! the default geometry). An untextured workload gets no texture unit.

use super::input::Size;
use anyhow::{anyhow, bail, Context, Result};
use fit::method::Candidate;
use fit::parts::Needed;
use fit::search::{cost, fit, Fitted, Objective};
use fit::target::Target;
use std::path::{Path, PathBuf};
use std::process::Command;
use sweep::area::{Design, Model};
use sweep::grid::Method;
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
    /// The method: `scanline` (001/003: its formats, K, L and parts fitted), `vector`
    /// (004's barycentric back end at its built formats: the lanes chosen), `se` (000's
    /// shading engines at their built formats: the fewest engines that cover the screen), or
    /// `auto`: each of them, and the one that best meets the objective.
    #[arg(long, default_value = "auto", value_parser = ["auto", "scanline", "se", "vector"])]
    method: String,
    /// What the method, setup's multipliers K and divider stages L, and the lanes are
    /// chosen for: the area model's gate equivalents (`area`), the mean cycles per frame
    /// (`cycles`), the mean frame time at the design's clock (`time`), or a product.
    #[arg(long, default_value = "area", value_parser = Objective::NAMES.map(|(n, _)| n))]
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

/// The design chosen, and what it is measured against.
struct Chosen {
    candidate: Candidate,
    /// The scanline search's outcome, when the scanline method is chosen.
    fitted: Option<Fitted>,
    /// Its size class and formats.
    class: u32,
    formats: fx::Formats,
    /// The default design and its rows.
    default: Design,
    default_rows: Vec<Row>,
    /// Every candidate compared, the chosen one among them.
    candidates: Vec<Candidate>,
    /// Designs run.
    trials: usize,
}

/// The candidates of `--method` on the workload, and the one chosen for the objective.
fn choose(args: &Args, inputs: &[sweep::run::Input], target: &Target, opts: &Options) -> Result<Chosen> {
    let objective = objective(args);
    let model = Model::calibrated();
    let all = args.method == "auto";
    let mut candidates = Vec::new();
    let mut fitted = None;
    let mut trials = 0;
    if all || args.method == "scanline" {
        eprintln!("fit: searching the scanline pipeline's formats ({} scenes)", inputs.len());
        let f = fit(inputs, target, objective, args.margin, opts);
        if let (Err(e), false) = (&f, all) {
            bail!("{e}");
        }
        candidates.push(fit::method::scanline(&f, model));
        trials += f.as_ref().map_or(0, |f| f.trials);
        fitted = f.ok();
    }
    if all || args.method == "vector" {
        eprintln!("fit: the barycentric back end at 1, 2, 4 and 8 lanes");
        candidates.extend(fit::method::vector(inputs, target, opts).map_err(|e| anyhow!(e))?);
        trials += model::raster_top::LANES.len();
    }
    if all || args.method == "se" {
        eprintln!("fit: the SE back end");
        candidates.push(fit::method::se(inputs, target, opts).map_err(|e| anyhow!(e))?);
        trials += 1;
    }
    let Some(chosen) = fit::method::choose(&candidates, objective).cloned() else {
        let why: Vec<String> = candidates
            .iter()
            .map(|c| format!("{}: {}", c.label(), c.misses.first().map_or("?", String::as_str)))
            .collect();
        bail!("no design of --method {} meets the target: {}", args.method, why.join("; "));
    };
    let (default, default_rows) = match &fitted {
        Some(f) => (f.default, f.default_rows.clone()),
        None => {
            trials += 1;
            fit::search::shipped(inputs, target, opts).map_err(|e| anyhow!(e))?
        }
    };
    let (class, formats, fitted) = match chosen.method {
        Method::Scanline => {
            let f = fitted.context("the scanline design chosen without a fit: a bug in fit")?;
            (f.design.class, f.design.formats, Some(f))
        }
        _ => (fx::Build::default().class, fx::Build::default().formats, None),
    };
    Ok(Chosen { candidate: chosen, fitted, class, formats, default, default_rows, candidates, trials })
}

fn objective(args: &Args) -> Objective {
    Objective::NAMES.iter().find(|(n, _)| *n == args.objective).map_or(Objective::Area, |(_, o)| *o)
}

/// A parameter of the chosen candidate (lanes, engines).
fn param(c: &Candidate, name: &str) -> u64 {
    c.params.get(name).copied().unwrap_or_default() as u64
}

pub fn run(args: Args) -> Result<()> {
    let target = Target::parse(&args.target).map_err(|e| anyhow!(e))?;
    let mut inputs = Vec::new();
    let mut textured = Vec::new();
    for p in &args.inputs {
        let (input, tex) = load(p, args.size)?;
        inputs.push(input);
        textured.extend(tex);
    }
    let tex = fit_texture(&textured, &target)?;
    let opts = Options { jobs: args.jobs, shard: None, cache: Some(args.out.join("cache")), area: None };
    let start = std::time::Instant::now();
    let chosen = choose(&args, &inputs, &target, &opts)?;
    let search_s = start.elapsed().as_secs_f64();
    let c = &chosen.candidate;
    let scanline = c.method == Method::Scanline;
    eprintln!("fit: chose {}", c.label());
    let out = &args.out;
    std::fs::create_dir_all(out).with_context(|| format!("{}: cannot create", out.display()))?;
    let formats_path = out.join("formats.json");
    let mut formats_value = serde_json::to_value(chosen.formats)?;
    if let Some(t) = &tex {
        formats_value["texture"] = serde_json::to_value(t.fit.formats)?;
    }
    let formats_json = serde_json::to_string_pretty(&formats_value)? + "\n";
    super::input::write(&formats_path, "the fitted formats", formats_json.as_bytes())?;
    let side = 1u32 << chosen.class;
    let reread =
        fx::Formats::with_overrides(side, side, &serde_json::from_str(&formats_json)?).map_err(|e| anyhow!(e))?;
    anyhow::ensure!(reread == chosen.formats, "formats.json does not read back as the fitted formats: a bug in fit");
    let reread_tex =
        fx::TexFormats::from_formats_file(&serde_json::from_str(&formats_json)?).map_err(|e| anyhow!(e))?;
    anyhow::ensure!(
        tex.as_ref().is_none_or(|t| t.fit.formats == reread_tex),
        "formats.json does not read back as the fitted texture formats: a bug in fit"
    );
    let needed = fit::parts::needed(&inputs, &chosen.formats);
    // raster_top's parameters (`emit`, `report`) and how `render --engine rtl` draws with it.
    let (params, render_how): (Vec<(&str, u64)>, Vec<String>) = match c.method {
        Method::Scanline => {
            let mut p = vec![("N", chosen.class as u64), ("K", param(c, "K")), ("L", param(c, "L"))];
            p.extend(needed.parts.params());
            let how = p.iter().flat_map(|(k, v)| ["--param".into(), format!("{k}={v}")]).collect();
            (p, how)
        }
        Method::Vector => {
            let lanes = param(c, "lanes");
            (
                vec![("METHOD", 1), ("LANES", lanes)],
                ["--method", "vector", "--lanes"].map(String::from).into_iter().chain([lanes.to_string()]).collect(),
            )
        }
        Method::Se => {
            let engines = param(c, "engines");
            (
                vec![("METHOD", 2), ("ENGINES", engines)],
                vec!["--method".into(), "se".into(), "--param".into(), format!("ENGINES={engines}")],
            )
        }
    };
    // The scanline design is built at its fitted formats; the others at the defaults.
    let formats_arg: Vec<&str> = if scanline { vec!["--formats", path(&formats_path)?] } else { Vec::new() };
    let edgepaint = |what: &str, sub: &[&str], more: &[&str]| -> Result<()> {
        let mut cmd = Command::new(std::env::current_exe()?);
        cmd.args(sub).args(&formats_arg).args(more);
        eprintln!("fit: {what}");
        let status = cmd.status().with_context(|| format!("running edgepaint for {what}"))?;
        anyhow::ensure!(status.success(), "{what} failed ({status})");
        Ok(())
    };
    let param_args: Vec<String> = params.iter().flat_map(|(k, v)| ["--param".into(), format!("{k}={v}")]).collect();
    let param_args: Vec<&str> = param_args.iter().map(String::as_str).collect();
    let hdl = out.join("hdl");
    let emit = [&["emit", "--unit", "raster_top"][..], &param_args].concat();
    edgepaint("emitting the chosen raster_top", &emit, &["-o", path(&hdl)?])?;
    if tex.is_some() {
        // The texture units exist in RTL at their default formats (and the cache at every
        // geometry of `rtl::texture_cache::GEOMETRIES`): emitted as built, each into its own
        // directory (`hdl/<unit>/`: `emit` writes one unit's `manifest.json`).
        for unit in TEXTURE_UNITS {
            eprintln!("fit: emitting {unit}");
            let status = Command::new(std::env::current_exe()?)
                .args(["emit", "--unit", unit, "-o", path(&hdl.join(unit))?])
                .status()
                .with_context(|| format!("running edgepaint to emit {unit}"))?;
            anyhow::ensure!(status.success(), "emitting {unit} failed ({status})");
        }
    }
    let yosys = if args.no_synth {
        None
    } else {
        let dir = out.join("yosys");
        let mut report = [&["report", "--no-pnr", "--unit", "raster_top"][..], &param_args].concat();
        if c.method == Method::Se {
            // The generic flow makes flip-flops of the engines' memories.
            report.extend(["--flow", "ecp5"]);
        }
        edgepaint("synthesizing it (Yosys, several minutes)", &report, &["-o", path(&dir)?])?;
        let text = std::fs::read_to_string(dir.join("report.json")).context("reading Yosys' report")?;
        Some(serde_json::from_str::<serde_json::Value>(&text)?["units"][0].clone())
    };
    let mut proven = Vec::new();
    if !args.no_proof {
        let dir = out.join("proof");
        std::fs::create_dir_all(&dir).with_context(|| format!("{}: cannot create", dir.display()))?;
        let how: Vec<&str> = render_how.iter().map(String::as_str).collect();
        for (input, file) in inputs.iter().zip(&args.inputs) {
            if textured.iter().any(|t| t.name == input.name) {
                // The textured raster_top is built at the default formats only, not the fitted ones.
                continue;
            }
            let png = dir.join(format!("{}.png", input.name));
            let mut more = [&["--engine", "rtl", "--top", "raster_top", "-o", path(&png)?][..], &how].concat();
            let size = args.size.map(|s| format!("{}x{}", s.width, s.height));
            if let Some(s) = &size {
                more.extend(["--size", s]);
            }
            more.push(path(file)?);
            edgepaint(&format!("drawing {} with the chosen RTL in Verilator", input.name), &["render"], &more)?;
            proven.push(input.name.clone());
        }
    }
    let f = chosen.fitted.as_ref();
    let compared: Vec<serde_json::Value> = chosen
        .candidates
        .iter()
        .map(|k| {
            serde_json::json!({"method": k.method.name(), "params": k.params, "passes": k.passes(),
                "misses": k.misses, "cost": k.cost.map(|c| c.0), "cost_source": k.cost.map(|c| c.1),
                "clock_mhz": k.clock.map(|c| c.0), "clock_source": k.clock.map(|c| c.1),
                "mean_cycles": k.cycles(), "score": k.score(objective(&args))})
        })
        .collect();
    let manifest = serde_json::json!({
        "method": c.method.name(), "params": c.params, "methods_compared": compared,
        "class": chosen.class, "formats": chosen.formats, "target": args.target,
        "objective": args.objective, "scenes": c.rows, "default_scenes": chosen.default_rows,
        "narrower": f.map_or(Vec::new(), |f| f.narrower.iter().map(|(k, t)| serde_json::json!({"knob": k, "value": t.set[k], "misses": t.misses})).collect()),
        "trials": chosen.trials, "proven_in_verilator": proven,
        "margin": args.margin,
        "ranges": f.map_or(Vec::new(), |f| f.ints.iter().map(|i| serde_json::json!({"quantity": i.quantity, "min": i.range.map(|r| r.0), "max": i.range.map(|r| r.1), "int_needed": i.needed, "int_floor": i.floor, "int_default": i.default, "int_fitted": i.fitted})).collect()),
        "parts": scanline.then_some(&needed.parts),
        "texture": tex.as_ref().map(|t| t.manifest()),
        "parts_needed_by": needed.why.iter().filter(|_| scanline).map(|(p, s)| serde_json::json!({"param": p, "scene": s})).collect::<Vec<_>>(),
    });
    super::input::write(
        &out.join("manifest.json"),
        "the fit's manifest",
        (serde_json::to_string_pretty(&manifest)? + "\n").as_bytes(),
    )?;
    let mut md = report(&chosen, &needed, &target, &args, yosys.as_ref(), &proven, search_s);
    md += &match &tex {
        Some(t) => t.report(),
        None => "\n## Texture unit\n\nNo scene is textured: the design has no texture unit (no `texture_*` unit emitted, no `\"texture\"` formats).\n".into(),
    };
    super::input::write(&out.join("report.md"), "the fit's report", md.as_bytes())?;
    print!("{md}");
    println!("wrote {}", out.display());
    Ok(())
}

/// The texture units a textured workload's design keeps (`rtl`'s names), in pipeline order.
const TEXTURE_UNITS: [&str; 4] = ["texture_coords", "texture_address", "texture_cache", "texture_filter"];

/// A workload input: the raster pipeline's (its textures stripped, when it has any) and
/// its textured scene for the texture unit's fit.
fn load(p: &Path, size: Option<Size>) -> Result<(sweep::run::Input, Option<fit::texture::TexScene>)> {
    let mut loaded = super::input::load(p, size)?;
    let tex = loaded.trilist.is_textured().then(|| fit::texture::TexScene {
        name: p.file_stem().map_or_else(|| p.display().to_string(), |s| s.to_string_lossy().into_owned()),
        list: loaded.trilist.clone(),
    });
    loaded.trilist.textures.clear();
    for v in loaded.trilist.triangles.iter_mut().flatten() {
        v.tex = None;
    }
    Ok((super::sweep::input_of(p, size, loaded)?, tex))
}

/// The texture unit's fit on the textured scenes, and what they need of it.
struct TexFitted {
    needs: fit::texture::TexNeeds,
    fit: fit::texture::TexFit,
}

/// The texture unit fitted to `scenes` for `target`'s PSNR (its `psnr>=` term) and the
/// conformance check; `None` when no scene is textured.
fn fit_texture(scenes: &[fit::texture::TexScene], target: &Target) -> Result<Option<TexFitted>> {
    if scenes.is_empty() {
        return Ok(None);
    }
    let psnr = target.terms.iter().find(|t| t.measure == fit::target::Measure::Psnr).map(|t| t.value);
    eprintln!("fit: the texture unit's knobs ({} textured scenes)", scenes.len());
    let fit = fit::texture::fit_formats(scenes, &fit::texture::TexTarget { psnr_db: psnr }).map_err(|e| anyhow!(e))?;
    Ok(Some(TexFitted { needs: fit::texture::needs(scenes), fit }))
}

impl TexFitted {
    fn manifest(&self) -> serde_json::Value {
        let n = &self.needs;
        serde_json::json!({
            "formats": self.fit.formats, "units": TEXTURE_UNITS,
            "needs": {"unit": n.unit, "filter": n.filter, "mip": n.mip},
            "scenes": self.fit.scenes.iter().map(|(s, f, x, p)| serde_json::json!({"scene": s, "fragments": f, "failures": x, "psnr_db": p})).collect::<Vec<_>>(),
            "narrower": self.fit.narrower.iter().map(|(k, t)| serde_json::json!({"knob": k.name(), "value": t.knobs.get(*k), "misses": t.miss})).collect::<Vec<_>>(),
            "trials": self.fit.trials,
        })
    }

    fn report(&self) -> String {
        let (d, k) = (sweep::texture::Knobs::DEFAULT, sweep::texture::Knobs::of(&self.fit.formats));
        let n = &self.needs;
        let why = |s: &Option<String>, what: &str| {
            s.as_ref().map_or(format!("not needed: {what}"), |s| format!("needed ({s})"))
        };
        let mut md = format!(
            "\n## Texture unit\n\nThe textured scenes' fragments through the bit-exact texture unit against the float reference \
             (`fit::texture`, the conformance check; {} designs judged). Emitted into `hdl/<unit>/`: {} (the cache at the \
             default geometry; the units at their built formats: the fitted knobs are in `formats.json`'s `\"texture\"`). Textured scenes are \
             not drawn in the Verilator proof: the textured `raster_top` (`TEXTURE=1`) is built at the default formats only, not at the fitted ones.\n\n| | default | fitted |\n|---|---:|---:|\n",
            self.fit.trials,
            TEXTURE_UNITS.join(", ")
        );
        for knob in sweep::texture::Knob::ALL {
            md += &format!("| {} | {} | {} |\n", knob.name(), d.get(knob), k.get(knob));
        }
        md += &format!(
            "\n- the texture unit: {}\n- the bilinear filter: {}\n- the mip chain: {}\n\n| scene | fragments | out of tolerance | PSNR (dB) |\n|---|---:|---:|---:|\n",
            why(&n.unit, "no textured triangle"),
            why(&n.filter, "every sampler is nearest"),
            why(&n.mip, "no minified fragment under a mip mode"),
        );
        for (s, f, x, p) in &self.fit.scenes {
            md += &format!("| {s} | {f} | {x} | {} |\n", p.map_or("exact".into(), |p| format!("{p:.1}")));
        }
        md += "\nEach knob one bit narrower:\n\n";
        for (knob, t) in &self.fit.narrower {
            md +=
                &format!("- {} = {}: {}\n", knob.name(), t.knobs.get(*knob), t.miss.as_deref().unwrap_or("passes (?)"));
        }
        md
    }
}

/// `p` as a string for a command line; an error for a path that is not UTF-8.
fn path(p: &Path) -> Result<&str> {
    p.to_str().ok_or_else(|| anyhow!("{}: not a UTF-8 path", p.display()))
}

/// The mean of `f` over `rows`.
fn mean(rows: &[Row], f: impl Fn(&Row) -> f64) -> f64 {
    rows.iter().map(f).sum::<f64>() / rows.len().max(1) as f64
}

/// The report: the chosen design beside the default one, and the methods compared.
fn report(
    chosen: &Chosen,
    needed: &Needed,
    target: &Target,
    args: &Args,
    yosys: Option<&serde_json::Value>,
    proven: &[String],
    secs: f64,
) -> String {
    let model = Model::calibrated();
    let c = &chosen.candidate;
    let fitted = chosen.fitted.as_ref();
    let default = &chosen.default;
    let cd = cost(default, model);
    let (cf, cf_source) = c.cost.unwrap_or((cd, sweep::row::Source::Modelled));
    let why = match args.method.as_str() {
        "auto" => format!(
            "`auto`: the least {} of the {} designs compared that meet the target",
            args.objective,
            chosen.candidates.len()
        ),
        m => format!("`{m}`"),
    };
    let mut md = format!(
        "# edgepaint fit\n\nWorkload: {}. Target: `{}` (every scene; `problems=0` unless bounded). Method: {why}, \
         **{}**. Objective: {}. Search: {} designs run in {secs:.1} s.\n\n",
        c.rows.iter().map(|r| r.scene.as_str()).collect::<Vec<_>>().join(", "),
        args.target,
        c.label(),
        args.objective,
        chosen.trials
    );
    md += "| | default | chosen |\n|---|---|---|\n";
    md += &format!("| method | scanline K={} L={} | {} |\n", default.k, default.l, c.label());
    md += &format!("| size class | {} | {} |\n", default.class, chosen.class);
    let removed: Vec<&str> = needed.parts.params().iter().filter(|(_, on)| *on == 0).map(|(p, _)| *p).collect();
    md += &format!(
        "| optional parts removed | none | {} |\n",
        match (fitted, removed.is_empty()) {
            (None, _) => "none (fitted for the scanline method)".to_string(),
            (Some(_), true) => "none".into(),
            (Some(_), false) => removed.join(", "),
        }
    );
    for ((q, fd), (_, ff)) in default.formats.named().iter().zip(chosen.formats.named()) {
        let mark = if *fd != ff { " **" } else { "" };
        md += &format!("| {q} | {fd} | {ff}{mark} |\n");
    }
    let pct = |a: f64, b: f64| format!("{:+.0}%", 100.0 * (b / a - 1.0));
    let how = match (c.method, cf_source) {
        (Method::Scanline, _) => "area model, every part present",
        (_, sweep::row::Source::Measured) => "Yosys, the calibration's run of this design",
        _ => "area model",
    };
    md += &format!("| GE ({how}) | {:.0} | {:.0} ({}) |\n", cd.ge, cf.ge, pct(cd.ge, cf.ge));
    md += &format!(
        "| ECP5 LUT4 / FF / DSP ({how}) | {:.0} / {:.0} / {:.0} | {:.0} / {:.0} / {:.0} |\n",
        cd.ecp5_lut4, cd.ecp5_ff, cd.ecp5_dsp, cf.ecp5_lut4, cf.ecp5_ff, cf.ecp5_dsp
    );
    md += &format!("| iCE40 LUT4 ({how}) | {:.0} | {:.0} |\n", cd.ice40_lut4, cf.ice40_lut4);
    if let Some(y) = yosys {
        let measured = model.measured(default);
        let n = |v: &serde_json::Value| v.as_f64().map_or("–".to_string(), |x| format!("{x:.0}"));
        let ge = y["generic"]["gate_equivalents"].as_f64();
        md += &format!(
            "| GE (Yosys, emitted raster_top) | {} | {}{} |\n| ECP5 LUT4 / FF / DSP (Yosys) | {} | {} / {} / {} |\n| iCE40 LUT4 (Yosys) | {} | {} |\n",
            measured.map_or("–".into(), |c| format!("{:.0}", c.ge)),
            n(&y["generic"]["gate_equivalents"]),
            measured.zip(ge).map_or(String::new(), |(c, ge)| format!(" ({})", pct(c.ge, ge))),
            measured.map_or("–".into(), |c| format!("{:.0} / {:.0} / {:.0}", c.ecp5_lut4, c.ecp5_ff, c.ecp5_dsp)),
            n(&y["ecp5"]["luts"]), n(&y["ecp5"]["ffs"]), n(&y["ecp5"]["dsps"]),
            measured.map_or("–".into(), |c| format!("{:.0}", c.ice40_lut4)),
            n(&y["ice40"]["luts"]),
        );
    }
    let default_cycles = mean(&chosen.default_rows, |r| r.cycles as f64);
    md += &format!("| cycles per frame (mean) | {default_cycles:.0} | {:.0} |\n", c.cycles());
    let default_mhz = mean(&chosen.default_rows, |r| r.clock_mhz.unwrap_or(f64::NAN));
    let mhz = c.clock.map_or(f64::NAN, |k| k.0);
    md += &format!("| clock, MHz | {default_mhz:.1} | {mhz:.1} |\n");
    md += &format!(
        "| frame time (mean), µs | {:.1} | {:.1} |\n",
        mean(&chosen.default_rows, |r| r.frame_us.unwrap_or(f64::NAN)),
        c.frame_us().unwrap_or(f64::NAN)
    );
    md += "\n## Methods compared\n\nEach design run on the workload through its bit-exact model against the float reference (`fit::method`). The barycentric and SE back ends exist in RTL at the default formats of size class 10 only, so they compete there; the scanline design is the one fitted. Area: the calibration's Yosys run of the design where there is one, the area model elsewhere; clock: routed where measured, modelled elsewhere.\n\n| design | meets the target | GE | ECP5 LUT4 / FF / DSP | cycles (mean) | clock, MHz | frame (mean), µs |\n|---|---|---:|---|---:|---:|---:|\n";
    for k in &chosen.candidates {
        let mark = if k.label() == c.label() { " (chosen)" } else { "" };
        let met = if k.passes() {
            "yes".to_string()
        } else {
            format!("no: {}", k.misses.first().map_or("?", String::as_str))
        };
        let src = |s: sweep::row::Source| if s == sweep::row::Source::Measured { "measured" } else { "modelled" };
        let (ge, cells) = k.cost.map_or(("–".into(), "–".into()), |(c, s)| {
            (format!("{:.0} ({})", c.ge, src(s)), format!("{:.0} / {:.0} / {:.0}", c.ecp5_lut4, c.ecp5_ff, c.ecp5_dsp))
        });
        let clock = k.clock.map_or("–".into(), |(m, s)| format!("{m:.1} ({})", src(s)));
        let frame = k.frame_us().map_or("–".into(), |t| format!("{t:.1}"));
        md += &format!("| {}{mark} | {met} | {ge} | {cells} | {:.0} | {clock} | {frame} |\n", k.label(), k.cycles());
    }
    if let Some(fitted) = fitted {
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
            md +=
                &format!("| {} | {range} | {} | {} | {} | {} |\n", i.quantity, i.needed, i.floor, i.default, i.fitted);
        }
    }
    md += "\n## Each scene against the target\n\n| scene | design |";
    for t in &target.terms {
        md += &format!(" {t} |");
    }
    md += "\n|---|---|";
    md += &"---:|".repeat(target.terms.len());
    md += "\n";
    for (label, rows) in [("default", &chosen.default_rows), ("chosen", &c.rows)] {
        for r in rows {
            md += &format!("| {} | {label} |", r.scene);
            for t in &target.terms {
                let shown = fit::target::shown(t.measure.of(r));
                md += &format!(" {shown}{} |", if t.met(r) { "" } else { " (missed)" });
            }
            md += "\n";
        }
    }
    match fitted {
        Some(fitted) => {
            md += "\n## Minimal knob by knob\n\nEach knob one bit narrower, run on the workload:\n\n";
            for (knob, t) in &fitted.narrower {
                md +=
                    &format!("- {knob} = {}: {}\n", t.set[knob], t.misses.first().map_or("passes (?)", String::as_str));
            }
        }
        None => md += "\nThe chosen back end's formats are the defaults it is built at: not fitted.\n",
    }
    md += &match proven.len() {
        0 => "\nNot proven in Verilator (`--no-proof`).\n".to_string(),
        _ => format!("\n**Proof.** The chosen raster_top ({}), in Verilator, drew {} exactly as the model does at that design: image and depth bit for bit, and the cycles `model::cycles` predicts (`render --engine rtl`). The guarantee is for this workload as given: a scene with larger ranges may need wider formats, and the models' analysis mode (`render --analysis`) reports the overflow.\n", c.label(), proven.join(", ")),
    };
    md
}
