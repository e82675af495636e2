//! `edgepaint stability`: families of generated triangles through the methods at points of
//! number formats against the float reference; heatmaps with the failure boundary, every
//! cell in JSON, a report (`stability` crate); and the texture unit's stress families
//! through the bit-exact unit, judged by the conformance check (`stability::texture`).

use anyhow::{anyhow, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use stability::cell::FormatsPoint;
use stability::family::Family;
use stability::texture::TexFamily;
use std::path::{Path, PathBuf};
use std::time::Instant;
use sweep::grid::Method;

/// Arguments of `edgepaint stability`.
#[derive(clap::Args)]
pub struct Args {
    /// Families to run (default: all): sliver-h, sliver-v, sliver-d, tiny, span, offscreen,
    /// depth, perspective, screen, shared; the texture unit's tex-grazing, tex-minify,
    /// tex-magnify, tex-near-w0, tex-wrap, tex-1x1, tex-1024.
    #[arg(long, num_args = 1.., value_delimiter = ',')]
    family: Vec<String>,
    /// Methods (default: all three): scanline, vector, se.
    #[arg(long, num_args = 1.., value_delimiter = ',')]
    method: Vec<String>,
    /// A formats file (JSON of formats by quantity over each screen's defaults, as
    /// `render --formats FILE`; its "texture" object for the texture families), run besides
    /// the default formats; repeat for more points.
    #[arg(long)]
    formats: Vec<PathBuf>,
    /// Threads (default: one per core).
    #[arg(long, default_value_t = 0)]
    jobs: usize,
    /// Output directory: cells.json, a heatmap per family, method and formats (PNG, SVG),
    /// report.md; for the texture families texture_cells.json and texture.md.
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
    let (mut families, mut textures) = (Vec::new(), Vec::new());
    for n in &args.family {
        match TexFamily::parse(n.trim()) {
            Some(t) => textures.push(t),
            None => families.push(Family::parse(n.trim()).map_err(|e| {
                anyhow!("--family: {e} (or a texture family: {})", TexFamily::ALL.map(TexFamily::name).join(", "))
            })?),
        }
    }
    if args.family.is_empty() {
        (families, textures) = (Family::ALL.to_vec(), TexFamily::ALL.to_vec());
    }
    // Every argument checked before anything is written.
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
    let texture_points = texture_points(&args.formats)?;
    std::fs::create_dir_all(&args.out).with_context(|| format!("{}: cannot create", args.out.display()))?;
    if !textures.is_empty() {
        texture(&args, &textures, &texture_points)?;
    }
    if families.is_empty() {
        return Ok(());
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

/// The texture formats points: the defaults and each formats file's "texture" object.
fn texture_points(formats: &[PathBuf]) -> Result<Vec<(String, fx::TexFormats)>> {
    let mut points = vec![("default".to_string(), fx::TexFormats::default())];
    for path in formats {
        let json = super::engine::formats_json(path)?;
        let f = fx::TexFormats::from_formats_file(&json).map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let stem = path.file_stem().map_or_else(|| path.display().to_string(), |s| s.to_string_lossy().into_owned());
        points.push((stem, f));
    }
    Ok(points)
}

/// The texture families at `points` (`texture_points`): `texture_cells.json` and
/// `texture.md` in the output directory.
fn texture(args: &Args, families: &[TexFamily], points: &[(String, fx::TexFormats)]) -> Result<()> {
    let total: usize = families.iter().map(|f| f.axis().1.len()).sum::<usize>() * points.len();
    let bar = ProgressBar::new(total as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} texture cells, {elapsed} elapsed, {eta} to go")
            .expect("a valid template"),
    );
    let start = Instant::now();
    let cells = stability::texture::run(families, points, args.jobs, &|| bar.inc(1)).map_err(|e| anyhow!(e))?;
    bar.finish_and_clear();
    let lines: Vec<String> = cells.iter().map(serde_json::to_string).collect::<Result<_, _>>()?;
    let json = format!("[\n{}\n]\n", lines.join(",\n"));
    super::input::write(&args.out.join("texture_cells.json"), "the texture cells", json.as_bytes())?;
    let md = stability::texture::report(&cells);
    super::input::write(&args.out.join("texture.md"), "the texture report", md.as_bytes())?;
    let failing = cells.iter().filter(|c| c.passes() == Some(false)).count();
    let refused = cells.iter().filter(|c| c.passes().is_none()).count();
    println!(
        "{} texture cells ({failing} fail, {refused} refused) in {:.1} s; wrote {}",
        cells.len(),
        start.elapsed().as_secs_f64(),
        args.out.join("texture.md").display()
    );
    Ok(())
}
