//! `edgepaint stability`: families of generated triangles through the methods at points of
//! number formats against the float reference; heatmaps with the failure boundary, every
//! cell in JSON, a report (`stability` crate).

use anyhow::{anyhow, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use stability::cell::FormatsPoint;
use stability::family::Family;
use std::path::{Path, PathBuf};
use std::time::Instant;
use sweep::grid::Method;

/// Arguments of `edgepaint stability`.
#[derive(clap::Args)]
pub struct Args {
    /// Families to run (default: all): sliver-h, sliver-v, sliver-d, tiny, span, offscreen,
    /// depth, perspective, screen, shared.
    #[arg(long, num_args = 1.., value_delimiter = ',')]
    family: Vec<String>,
    /// Methods (default: all three): scanline, vector, se.
    #[arg(long, num_args = 1.., value_delimiter = ',')]
    method: Vec<String>,
    /// A formats file (JSON of formats by quantity over each screen's defaults, as
    /// `render --formats FILE`), run besides the default formats; repeat for more points.
    #[arg(long)]
    formats: Vec<PathBuf>,
    /// Threads (default: one per core).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// Output directory: cells.json, a heatmap per family, method and formats (PNG, SVG),
    /// report.md.
    #[arg(short, long)]
    out: PathBuf,
}

/// The method `name` (as the sweep's grid names them); the error lists the known ones.
fn method(name: &str) -> Result<Method> {
    serde_json::from_value(serde_json::Value::String(name.trim().into()))
        .map_err(|e| anyhow!("--method \"{name}\": {e}"))
}

/// A formats file as a formats point named by its stem.
fn point(path: &Path) -> Result<FormatsPoint> {
    let name = path.display();
    let json = super::engine::formats_json(path)?;
    let stem = path.file_stem().map_or_else(|| name.to_string(), |s| s.to_string_lossy().into_owned());
    let p = FormatsPoint { name: stem, overrides: Some(json) };
    stability::run::check_points(std::slice::from_ref(&p)).map_err(|e| anyhow!("{name}: {e}"))?;
    Ok(p)
}

pub fn run(args: Args) -> Result<()> {
    let families = if args.family.is_empty() {
        Family::ALL.to_vec()
    } else {
        args.family
            .iter()
            .map(|n| Family::parse(n.trim()).map_err(|e| anyhow!("--family: {e}")))
            .collect::<Result<_>>()?
    };
    let methods: Vec<Method> = if args.method.is_empty() {
        Method::ALL.to_vec()
    } else {
        args.method.iter().map(|m| method(m)).collect::<Result<_>>()?
    };
    let mut points = vec![FormatsPoint::default_point()];
    for path in &args.formats {
        let p = point(path)?;
        anyhow::ensure!(
            points.iter().all(|q| q.name != p.name),
            "{}: a formats point named \"{}\" is already run (name the files apart)",
            path.display(),
            p.name
        );
        points.push(p);
    }
    let tasks = stability::run::tasks(&families, &methods, points.len());
    let bar = ProgressBar::new(tasks.len() as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} cells, {elapsed} elapsed, {eta} to go")
            .expect("a valid template"),
    );
    let start = Instant::now();
    let cells = stability::run::run(&tasks, &points, args.jobs, &|| bar.inc(1)).map_err(|e| anyhow!(e))?;
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();
    let out = &args.out;
    std::fs::create_dir_all(out).with_context(|| format!("{}: cannot create", out.display()))?;
    stability::report::write_cells(out, &cells).map_err(|e| anyhow!(e))?;
    let maps = stability::map::maps(&cells);
    for m in &maps {
        stability::map::draw(m, out).map_err(|e| anyhow!(e))?;
    }
    let command = std::env::args().skip(1).collect::<Vec<_>>().join(" ");
    let run = stability::report::Run { command: format!("edgepaint {command}"), seconds };
    stability::report::write_report(out, &maps, &run).map_err(|e| anyhow!(e))?;
    let failing = cells.iter().filter(|c| c.passes() == Some(false)).count();
    let skipped = cells.iter().filter(|c| c.passes().is_none()).count();
    println!("{} cells ({failing} fail, {skipped} not run) in {seconds:.1} s; wrote {}", cells.len(), out.display());
    Ok(())
}
