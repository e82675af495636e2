//! Running a sweep: every (input, design point) through the bit-exact model and the float
//! reference (`accuracy::compare`), in parallel, each result cached.

use crate::area::{Design, Model};
use crate::clock;
use crate::grid::{Method, Point};
use crate::row::{Row, Source};
use accuracy::{compare, compare_se, Setup};
use model::cycles::Timing;
use model::render::Method as ModelMethod;
use rayon::prelude::*;
use scene::Trilist;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::path::PathBuf;

/// A scene or trilist to sweep.
pub struct Input {
    /// Its file stem (the rows' `scene`).
    pub name: String,
    /// A hash of its file's contents and size override: part of each result's cache key.
    pub key: u64,
    pub trilist: Trilist,
    pub background: [f64; 3],
    pub cull_back: bool,
}

impl Input {
    /// The scene file `path` at `width` x `height` (cache key 1); the error names the file.
    pub fn scene(path: &std::path::Path, width: u32, height: u32) -> Result<Input, String> {
        let name = path.file_stem().map_or_else(|| path.display().to_string(), |s| s.to_string_lossy().into_owned());
        let scene::Input::Scene(s) = scene::Input::load(path).map_err(|e| e.to_string())? else {
            return Err(format!("{}: a trilist, not a scene", path.display()));
        };
        let s = s.with_size(width, height).map_err(|e| format!("{}: {e}", path.display()))?;
        let trilist = s.to_trilist().map_err(|e| format!("{}: {e}", path.display()))?;
        if trilist.is_textured() {
            return Err(format!(
                "{}: the scene is textured: the sweep of the pipelines' formats takes untextured scenes \
                 (`sweep::texture` takes textured ones)",
                path.display()
            ));
        }
        Ok(Input { name, key: 1, trilist, background: s.background, cull_back: s.cull_back })
    }
}

/// How to run.
#[derive(Default)]
pub struct Options {
    /// Threads (0: one per core).
    pub jobs: usize,
    /// Run only tasks `i`, `i + n`, `i + 2n`, ... of the `n` shards (`--shard I/N`).
    pub shard: Option<(usize, usize)>,
    /// Where results are cached, one file per task (`<dir>/<key>.json`).
    pub cache: Option<PathBuf>,
    /// The area model (default: the committed calibration, `Model::calibrated`).
    pub area: Option<Model>,
}

/// One task: an input and a point, with the point's formats and parameters for it.
struct Task<'a> {
    input: &'a Input,
    point: &'a Point,
    formats: fx::Formats,
    params: std::collections::BTreeMap<String, u32>,
}

impl Task<'_> {
    /// The cache key: the input, the point and its resolved design, edgepaint's version.
    fn key(&self) -> u64 {
        let mut h = DefaultHasher::new();
        let design = serde_json::to_string(&(&self.point, &self.formats, &self.params)).expect("a point serialises");
        (self.input.key, &self.input.name, design, env!("CARGO_PKG_VERSION")).hash(&mut h);
        h.finish()
    }

    /// Renders and measures; the error names the point (an SE array the formats do not fit).
    fn measure(&self) -> Result<Row, String> {
        let (method, timing) = match self.point.method {
            Method::Scanline => (
                ModelMethod::Scanline,
                Timing { setup_multipliers: self.params["K"], divider_latency: self.params["L"], ..Timing::default() },
            ),
            Method::Vector => {
                (ModelMethod::Vector { lanes: self.params["lanes"], perspective: true }, Timing::default())
            }
            // The engines' own cycles count (`accuracy::compare_se`).
            Method::Se => (ModelMethod::Scanline, Timing::default()),
        };
        let setup = Setup {
            method,
            formats: self.formats,
            cull_back: self.input.cull_back,
            background: self.input.background,
            timing,
        };
        let r = match self.point.method {
            Method::Se => compare_se(&self.input.trilist, &setup)
                .map_err(|e| format!("{}: point {}: {e}", self.input.name, self.point.label()))?,
            _ => compare(&self.input.trilist, &setup),
        };
        let p = self.point;
        let to16 = (16.0 - self.formats.z.frac as f64).exp2();
        Ok(Row {
            scene: self.input.name.clone(),
            method: p.method.name().into(),
            point: p.name.clone(),
            kind: p.kind.clone(),
            knob: (p.kind == "sensitivity").then(|| p.set.keys().next().cloned()).flatten(),
            value: (p.kind == "sensitivity").then(|| p.set.values().next().copied()).flatten(),
            formats: self.formats.named().iter().map(|(k, f)| (k.to_string(), f.to_string())).collect(),
            params: self.params.clone(),
            psnr_db: r.errors.psnr_db,
            color_rms_lsb: 255.0 * 10f64.powf(-r.errors.psnr_db / 20.0),
            color_max_lsb: r.errors.color_max,
            color_mean_lsb: r.errors.color_mean,
            color_over_1: r.errors.color_over_1,
            depth_max_lsb: r.depth_max_lsb,
            depth_mean_lsb: r.depth_mean_lsb,
            depth_max_lsb16: r.depth_max_lsb * to16,
            depth_mean_lsb16: r.depth_mean_lsb * to16,
            coverage_differs: r.coverage_differs,
            coverage_unexplained: r.coverage_unexplained,
            winner_differs: r.winner_differs,
            winner_unexplained: r.winner_unexplained,
            problems: r.problems,
            cycles: r.cycles,
            pixels_per_clock: r.pixels_per_clock,
            clock_mhz: None,
            clock_source: None,
            frame_us: None,
            cost: None,
            cost_source: None,
        })
    }

    /// `row` with the design's clock, frame time and cost, for a method whose pipeline
    /// exists in RTL (scanline) at formats the RTL can be built at (`rtl::config::check`:
    /// not the wide formats of a format's sensitivity point): measured where the design was
    /// synthesized or routed, modelled elsewhere. Not cached: a recalibrated model reaches
    /// every row.
    fn priced(&self, mut row: Row, model: &Model) -> Row {
        let n = self.point.class(self.input.trilist.width, self.input.trilist.height);
        if self.point.method == Method::Vector {
            return self.priced_vector(row, n);
        }
        if self.point.method == Method::Se {
            return self.priced_se(row, n);
        }
        if self.point.method != Method::Scanline || rtl::config::check(n, &self.formats).is_err() {
            return row;
        }
        let design = Design { class: n, formats: self.formats, k: self.params["K"], l: self.params["L"] };
        let default = clock::measured_design();
        let source = |measured: bool| if measured { Source::Measured } else { Source::Modelled };
        let mhz = clock::pipeline_mhz(&design, &default);
        (row.clock_mhz, row.clock_source) = (Some(mhz), Some(source(design == default)));
        row.frame_us = Some(row.cycles as f64 / mhz);
        let measured = model.measured(&design);
        (row.cost, row.cost_source) =
            (Some(measured.unwrap_or_else(|| model.pipeline(&design))), Some(source(measured.is_some())));
        row
    }

    /// `row` (the vector method at size class `n`) with the clock, frame time and cost of
    /// its pipeline in RTL, `raster_top` with `METHOD = 1` (`rtl::vector`), at the formats it
    /// was built and measured at (`clock::measured_design`'s): the cost measured at one lane,
    /// modelled at 2, 4 and 8 (`area::vector_pipeline`), the clock routed at one and four
    /// (`clock::vector_pipeline_mhz`). Elsewhere none: no area model covers the vector unit
    /// at other formats yet.
    fn priced_vector(&self, mut row: Row, n: u32) -> Row {
        let d = clock::measured_design();
        let lanes = self.params["lanes"];
        let Some(cost) = crate::area::vector_pipeline(lanes).filter(|_| n == d.class && self.formats == d.formats)
        else {
            return row;
        };
        let source = if lanes == 1 { Source::Measured } else { Source::Modelled };
        let (mhz, clock_source) = clock::vector_pipeline_mhz(lanes).expect("lanes the area model prices");
        (row.clock_mhz, row.clock_source) = (Some(mhz), Some(clock_source));
        row.frame_us = Some(row.cycles as f64 / mhz);
        (row.cost, row.cost_source) = (Some(cost), Some(source));
        row
    }

    /// `row` (the SE method at size class `n`) with the clock, frame time and cost of its
    /// pipeline in RTL, `raster_top` with `METHOD = 2`, at the formats it was built at (the
    /// default ones) and the fewest engines that cover the screen (`area::se_pipeline`:
    /// measured at one and five engines, modelled at 16; the clock the one engine's, routed,
    /// measured there and modelled elsewhere: the engines run side by side on the span bus).
    fn priced_se(&self, mut row: Row, n: u32) -> Row {
        let d = clock::measured_design();
        let Some((cost, source)) =
            crate::area::se_pipeline(self.input.trilist.width).filter(|_| n == d.class && self.formats == d.formats)
        else {
            return row;
        };
        let engines = rtl::se_engines_for(self.input.trilist.width);
        let mhz = clock::SE_PIPELINE_MHZ;
        let clock_source = if engines == Some(1) { Source::Measured } else { Source::Modelled };
        (row.clock_mhz, row.clock_source) = (Some(mhz), Some(clock_source));
        row.frame_us = Some(row.cycles as f64 / mhz);
        (row.cost, row.cost_source) = (Some(cost), Some(source));
        row
    }
}

/// What a sweep gives: its rows, and the points a method cannot draw.
#[derive(Debug, PartialEq)]
pub struct Swept {
    /// In canonical order ([`crate::store::sort`]).
    pub rows: Vec<Row>,
    /// `<input>: point <method> <name>: <why>` for each (input, point) the method cannot
    /// draw though its formats are possible: the shading engines' words hold 32 bits at
    /// most (`model::se::array::array_params`).
    pub skipped: Vec<String>,
}

/// Runs every point on every input (the shard's tasks only, with `opts.shard`), reusing
/// cached results; `done` is called once per task finished. Errors: a point impossible for
/// an input (named), or a cache that cannot be written.
pub fn run(inputs: &[Input], points: &[Point], opts: &Options, done: &(dyn Fn() + Sync)) -> Result<Swept, String> {
    let (mut tasks, mut skipped) = (Vec::new(), Vec::new());
    for input in inputs {
        for point in points {
            let (formats, params) =
                point.resolve(input.trilist.width, input.trilist.height).map_err(|e| format!("{}: {e}", input.name))?;
            if point.method == Method::Se {
                if let Err(e) = model::se::array::array_params(input.trilist.width, &formats) {
                    skipped.push(format!("{}: point {}: {e}", input.name, point.label()));
                    continue;
                }
            }
            tasks.push(Task { input, point, formats, params });
        }
    }
    if let Some((i, n)) = opts.shard {
        if n == 0 || i >= n {
            return Err(format!("shard {i}/{n}: I must be below N"));
        }
        tasks = tasks.into_iter().enumerate().filter(|(k, _)| k % n == i).map(|(_, t)| t).collect();
    }
    if let Some(dir) = &opts.cache {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create the cache: {e}", dir.display()))?;
    }
    let pool = rayon::ThreadPoolBuilder::new().num_threads(opts.jobs).build().map_err(|e| e.to_string())?;
    let rows: Result<Vec<Row>, String> = pool.install(|| {
        tasks
            .par_iter()
            .map(|t| {
                let row = cached(t, opts)?;
                done();
                Ok(t.priced(row, opts.area.as_ref().unwrap_or_else(|| Model::calibrated())))
            })
            .collect()
    });
    let mut rows = rows?;
    crate::store::sort(&mut rows);
    Ok(Swept { rows, skipped })
}

/// `t`'s row from the cache, or measured and cached.
fn cached(t: &Task, opts: &Options) -> Result<Row, String> {
    let Some(dir) = &opts.cache else {
        return t.measure();
    };
    let path = dir.join(format!("{:016x}.json", t.key()));
    if let Some(row) = std::fs::read_to_string(&path).ok().and_then(|s| serde_json::from_str::<Row>(&s).ok()) {
        return Ok(row);
    }
    let row = t.measure()?;
    // Written whole, then renamed: an interrupted sweep leaves no half-written result.
    let tmp = path.with_extension(format!("tmp{}", std::process::id()));
    let json = serde_json::to_string(&row).expect("a row serialises");
    std::fs::write(&tmp, json)
        .and_then(|_| std::fs::rename(&tmp, &path))
        .map_err(|e| format!("{}: cannot write the cached result: {e}", path.display()))?;
    Ok(row)
}
