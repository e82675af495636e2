//! `edgepaint sweep`: every scene through every design point of a grid, charted
//! (`sweep` crate); `edgepaint sweep merge`: the shards of a sweep as one; `edgepaint sweep
//! --texture`: textured scenes through the texture unit's knobs and cache geometries
//! (`sweep::texture`).

use super::input::{self, Size};
use anyhow::{anyhow, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::time::Instant;
use sweep::grid::{Grid, Method};
use sweep::run::{Input, Options};

/// The file in a sweep's directory listing the points skipped, one per line.
const SKIPPED: &str = "skipped.txt";

/// Arguments of `edgepaint sweep`.
#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true)]
pub struct Args {
    #[command(subcommand)]
    merge: Option<Merge>,
    /// Scene files or trilists (JSON).
    inputs: Vec<PathBuf>,
    /// Methods to sweep (default: the grid's).
    #[arg(long, value_enum, num_args = 1.., value_delimiter = ',')]
    method: Vec<MethodArg>,
    /// The grid of design points (JSON; see the README, "Sweep"); default: the built-in grid.
    #[arg(long)]
    grid: Option<PathBuf>,
    /// Threads (default: one per core).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// Run only shard I of N (0-based), e.g. 2/8; `edgepaint sweep merge` joins them.
    #[arg(long)]
    shard: Option<Shard>,
    /// Override the scenes' resolution, e.g. 320x240.
    #[arg(long)]
    size: Option<Size>,
    /// Output directory: results.jsonl, results.csv, the charts (PNG, SVG), report.md, and
    /// the cache of results (cache/) from which an interrupted sweep resumes.
    #[arg(short, long)]
    out: Option<PathBuf>,
    /// Instead of sweeping: synthesize the area model's calibration builds with Yosys
    /// (crates/sweep/area/builds.json; minutes each, an interrupted run resumes), fit the
    /// model and report its error on the builds held out of the fit, into -o DIR
    /// (yosys.json, area.md).
    #[arg(long, conflicts_with_all = ["inputs", "method", "grid", "shard", "size", "area"])]
    calibrate: bool,
    /// Fit the area model to these calibration samples (a `--calibrate` run's yosys.json)
    /// instead of those edgepaint was built with.
    #[arg(long, value_name = "FILE")]
    area: Option<PathBuf>,
    /// Sweep the texture unit instead (paper 001 section II-5): textured scenes through its
    /// precision knobs (subtexel, lod_frac, weight, recip) and cache geometries, `--grid` a
    /// texture grid (README, "Sweep"); writes texture.jsonl, texture.csv, the charts and
    /// texture.md.
    #[arg(long, conflicts_with_all = ["method", "shard", "calibrate", "area"])]
    texture: bool,
}

#[derive(clap::Subcommand)]
enum Merge {
    /// Join the results of shards (`--shard I/N` runs) into one sweep, with its charts and report.
    Merge {
        /// The shards' output directories.
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        /// Output directory.
        #[arg(short, long)]
        out: PathBuf,
    },
}

/// A method as the command line names it.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
enum MethodArg {
    Scanline,
    Vector,
    Se,
}

/// `I/N`.
#[derive(Clone, Copy, Debug)]
struct Shard(usize, usize);

impl std::str::FromStr for Shard {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Shard, String> {
        let bad = || format!("\"{s}\" is not a shard I/N with 0 <= I < N, e.g. 0/4");
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let (i, n) = (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if i >= n {
            return Err(bad());
        }
        Ok(Shard(i, n))
    }
}

pub fn run(args: Args) -> Result<()> {
    if let Some(Merge::Merge { dirs, out }) = args.merge {
        let dirs: Vec<&Path> = dirs.iter().map(PathBuf::as_path).collect();
        let rows = sweep::store::merge(&dirs).map_err(|e| anyhow!(e))?;
        return finish(&out, &rows, true);
    }
    let out = args.out.clone().context("give the output directory with -o DIR")?;
    if args.calibrate {
        return super::calibrate::run(&out);
    }
    anyhow::ensure!(!args.inputs.is_empty(), "give at least one scene or trilist to sweep");
    if args.texture {
        return texture(&args, &out);
    }
    let area = args.area.as_deref().map(area_model).transpose()?;
    let mut grid = match &args.grid {
        Some(path) => {
            let text =
                std::fs::read_to_string(path).with_context(|| format!("{}: cannot read the grid", path.display()))?;
            Grid::parse(&text).map_err(|e| anyhow!("{}: {e}", path.display()))?
        }
        None => Grid::default(),
    };
    if !args.method.is_empty() {
        grid.methods = args
            .method
            .iter()
            .map(|m| match m {
                MethodArg::Scanline => Method::Scanline,
                MethodArg::Vector => Method::Vector,
                MethodArg::Se => Method::Se,
            })
            .collect();
    }
    let inputs = args.inputs.iter().map(|p| load(p, args.size)).collect::<Result<Vec<_>>>()?;
    let points = grid.points();
    let tasks = inputs.len() * points.len();
    let shard = args.shard.map(|Shard(i, n)| (i, n));
    let mine = shard.map_or(tasks, |(i, n)| (tasks + n - 1 - i) / n);
    let bar = ProgressBar::new(mine as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} points, {elapsed} elapsed, {eta} to go")
            .expect("a valid template"),
    );
    let opts = Options { jobs: args.jobs, shard, cache: Some(out.join("cache")), area };
    let start = Instant::now();
    let swept = sweep::run::run(&inputs, &points, &opts, &|| bar.inc(1)).map_err(|e| anyhow!(e))?;
    bar.finish_and_clear();
    let rows = swept.rows;
    if let Some(first) = swept.skipped.first() {
        println!(
            "{} points skipped, the method cannot draw them (listed in {}), e.g. {first}",
            swept.skipped.len(),
            SKIPPED
        );
    }
    let skipped: String = swept.skipped.iter().map(|s| s.clone() + "\n").collect();
    std::fs::create_dir_all(&out).with_context(|| format!("{}: cannot create", out.display()))?;
    input::write(&out.join(SKIPPED), "the skipped points", skipped.as_bytes())?;
    println!(
        "{} points ({} inputs x {} design points{}) in {:.1} s",
        rows.len(),
        inputs.len(),
        points.len(),
        shard.map_or(String::new(), |(i, n)| format!(", shard {i}/{n}")),
        start.elapsed().as_secs_f64()
    );
    finish(&out, &rows, shard.is_none())
}

/// Writes `rows` into `out`, with the charts and the report when `charts`.
fn finish(out: &Path, rows: &[sweep::row::Row], charts: bool) -> Result<()> {
    sweep::store::write(out, rows).map_err(|e| anyhow!(e))?;
    if charts {
        let charts = sweep::chart::charts(rows);
        for c in &charts {
            sweep::chart::draw(c, out).map_err(|e| anyhow!(e))?;
        }
        sweep::report::write(out, rows, &charts).map_err(|e| anyhow!(e))?;
    }
    println!("wrote {}", out.display());
    Ok(())
}

/// `edgepaint sweep --texture`: the texture unit's grid on the textured inputs, its rows,
/// charts and report into `out`.
fn texture(args: &Args, out: &Path) -> Result<()> {
    use sweep::texture::{TexGrid, TexInput};
    let grid = match &args.grid {
        Some(path) => {
            let text =
                std::fs::read_to_string(path).with_context(|| format!("{}: cannot read the grid", path.display()))?;
            TexGrid::parse(&text).map_err(|e| anyhow!("{}: {e}", path.display()))?
        }
        None => TexGrid::default(),
    };
    let inputs = args
        .inputs
        .iter()
        .map(|p| {
            let name = p.file_stem().map_or_else(|| p.display().to_string(), |s| s.to_string_lossy().into_owned());
            Ok(TexInput { name, list: input::load(p, args.size)?.trilist })
        })
        .collect::<Result<Vec<_>>>()?;
    let points = grid.points().len();
    let bar = ProgressBar::new((inputs.len() * points) as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} (scene, knob point)s, {elapsed} elapsed, {eta} to go")
            .expect("a valid template"),
    );
    let start = Instant::now();
    let rows = sweep::texture::run(&inputs, &grid, args.jobs, &|| bar.inc(1)).map_err(|e| anyhow!(e))?;
    bar.finish_and_clear();
    println!(
        "{} rows ({} scenes x {points} knob points x {} cache geometries) in {:.1} s",
        rows.len(),
        inputs.len(),
        grid.caches.len(),
        start.elapsed().as_secs_f64()
    );
    sweep::texture::write(out, &rows).map_err(|e| anyhow!(e))?;
    let charts = sweep::texture::charts(&rows);
    for c in &charts {
        sweep::chart::draw(c, out).map_err(|e| anyhow!(e))?;
    }
    input::write(&out.join("texture.md"), "the texture report", sweep::texture::report(&rows, &charts).as_bytes())?;
    println!("wrote {}", out.display());
    Ok(())
}

/// The area model fitted to the calibration samples in `path`.
fn area_model(path: &Path) -> Result<sweep::area::Model> {
    let text = std::fs::read_to_string(path).with_context(|| format!("{}: cannot read", path.display()))?;
    let samples: Vec<sweep::area::Sample> =
        serde_json::from_str(&text).with_context(|| format!("{}: not calibration samples", path.display()))?;
    sweep::area::fit(&samples).map_err(|e| anyhow!("{}: {e}", path.display()))
}

/// An input of the sweep, its cache key from its file's bytes and the size asked for.
pub fn load(path: &Path, size: Option<Size>) -> Result<Input> {
    let loaded = input::load(path, size)?;
    loaded.untextured(
        path,
        "the sweep of the pipelines' formats takes untextured, unblended scenes (sweep --texture takes textured ones)",
    )?;
    input_of(path, size, loaded)
}

/// The sweep's input of `loaded`, read from `path` at `size`: named by its file's stem,
/// keyed by its bytes and the size.
pub fn input_of(path: &Path, size: Option<Size>, loaded: input::Loaded) -> Result<Input> {
    let bytes = std::fs::read(path).with_context(|| format!("{}: cannot read", path.display()))?;
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (bytes, size.map(|s| (s.width, s.height))).hash(&mut h);
    Ok(Input {
        name: path.file_stem().map_or_else(|| path.display().to_string(), |s| s.to_string_lossy().into_owned()),
        key: h.finish(),
        trilist: loaded.trilist,
        background: loaded.background,
        cull_back: loaded.cull_back,
    })
}
