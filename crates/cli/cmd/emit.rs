//! `edgepaint emit`: Verilog for one unit, or for the default design, plus `manifest.json`.

use anyhow::{anyhow, bail, Context, Result};
use rtl::emit::Emitted;
use rtl::Unit;
use std::path::{Path, PathBuf};

/// Arguments of `edgepaint emit`.
#[derive(clap::Args)]
pub struct Args {
    /// The unit to emit (ept); without it, every unit of the default design.
    #[arg(long, value_name = "NAME")]
    unit: Option<String>,
    /// A parameter of the unit, e.g. `--param P=128`; repeatable. Unset ones take their default.
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = parse_param)]
    params: Vec<(String, u64)>,
    /// Number formats of a scanline unit: a JSON file of formats by quantity over the
    /// defaults of its size class N (e.g. {"z": "S1.24 half-up"} for a 24-bit depth
    /// buffer). Formats edgepaint is not built at are compiled first (cargo, target/formats).
    #[arg(long, value_name = "FILE")]
    formats: Option<PathBuf>,
    /// Directory to write `<unit>.v` and `manifest.json` into.
    #[arg(short, long, value_name = "DIR", default_value = "hdl-out")]
    out: PathBuf,
}

/// `NAME=VALUE` of `--param`.
pub fn parse_param(s: &str) -> std::result::Result<(String, u64), String> {
    let (k, v) = s.split_once('=').ok_or_else(|| format!("\"{s}\" is not NAME=VALUE, e.g. P=128"))?;
    let v = v.trim().parse().map_err(|_| format!("\"{v}\" in \"{s}\" is not a whole number"))?;
    Ok((k.trim().to_owned(), v))
}

pub fn run(args: Args) -> Result<()> {
    let Some(name) = args.unit else {
        if !args.params.is_empty() || args.formats.is_some() {
            bail!("--param and --formats need --unit: the default design's parameters are fixed");
        }
        return emit_default(&args.out);
    };
    match emit_with(&name, args.params, args.formats.as_deref())? {
        Some(emitted) => write(&args.out, &[emitted]),
        None => Ok(()), // an edgepaint compiled at those formats emitted it
    }
}

/// Emits unit `name` with `params` over its defaults, at the formats file `formats` over
/// its size class's defaults when given (a scanline unit). `None` when this edgepaint does
/// not hold that build (the formats, or a size class it is compiled without) and one
/// compiled at it ran the command instead (`super::rebuild`).
pub fn emit_with(name: &str, params: Vec<(String, u64)>, formats: Option<&Path>) -> Result<Option<Emitted>> {
    let unit = unit_named(name)?;
    let params = unit.params(params).map_err(|e| anyhow!(e))?;
    let Some(&class) = params.get("N") else {
        if formats.is_some() {
            bail!("{name} has no number formats to set (--formats is for the scanline units)");
        }
        return unit.emit(&params).map(Some).map_err(|e| anyhow!(e));
    };
    let (build, why) = super::rebuild::build_at(u32::try_from(class).unwrap_or(u32::MAX), formats)?;
    if super::rebuild::ensure(&build, &why)? {
        return Ok(None);
    }
    unit.emit_at(&params, &build.formats).map(Some).map_err(|e| anyhow!(e))
}

fn unit_named(name: &str) -> Result<&'static Unit> {
    Unit::named(name).ok_or_else(|| anyhow!("no unit named {name} (units: {})", rtl::emit::unit_names()))
}

/// `edgepaint` with no arguments: the default design into `hdl-out/`.
pub fn run_default() -> Result<()> {
    emit_default(Path::new("hdl-out"))
}

/// Writes the default design into `dir` and deletes any other `.v` there and in its
/// subdirectories (a subdirectory left empty too), so the directory holds exactly the design.
fn emit_default(dir: &Path) -> Result<()> {
    let design = rtl::emit::default_design();
    write(dir, &design)?;
    remove_stale(dir, dir, &design)
}

/// Deletes the `.v` files under `at` (a directory of `root` or `root` itself) that are not
/// files of `design`, and `at` itself when that leaves it empty.
fn remove_stale(root: &Path, at: &Path, design: &[Emitted]) -> Result<()> {
    for entry in std::fs::read_dir(at).with_context(|| format!("listing {}", at.display()))? {
        let path = entry?.path();
        if path.is_dir() {
            remove_stale(root, &path, design)?;
            continue;
        }
        let name = path.strip_prefix(root).expect("under root").to_string_lossy().into_owned();
        if name.ends_with(".v") && !design.iter().any(|e| e.file() == name) {
            std::fs::remove_file(&path).with_context(|| format!("removing stale {}", path.display()))?;
            println!("removed {} (not in the default design)", path.display());
        }
    }
    if at != root && std::fs::read_dir(at)?.next().is_none() {
        std::fs::remove_dir(at).with_context(|| format!("removing {}", at.display()))?;
    }
    Ok(())
}

fn write(dir: &Path, units: &[Emitted]) -> Result<()> {
    let paths = rtl::emit::write(dir, units).with_context(|| format!("writing into {}", dir.display()))?;
    for (e, path) in units.iter().zip(&paths) {
        let params: Vec<String> = e.params.iter().map(|(k, v)| format!("{k}={v}")).collect();
        let ports: Vec<String> =
            e.ports.iter().map(|p| format!("{} {}[{}]", p.dir.verilog(), p.name, p.width)).collect();
        println!("wrote {} (module {}, {}; {})", path.display(), e.unit, params.join(" "), ports.join(", "));
    }
    println!("wrote {}", paths.last().expect("the manifest is always written").display());
    Ok(())
}
