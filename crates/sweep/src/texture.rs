//! The texture unit in the sweep (paper 001 section II-5; `model::texture_unit`): its
//! precision knobs against its error, area and speed, and its cache geometry against hit
//! rate and frame time.
//!
//! A [`TexGrid`] names the knobs' values (one knob at a time around the defaults, and a
//! joint grid) and the cache geometries. Every (scene, knob point) runs every textured
//! fragment through the bit-exact unit against the float reference
//! (`accuracy::texture::judge`, judged as the GL and Vulkan conformance tests judge
//! filtering); the unit's cache trace is then replayed at every geometry
//! (`accuracy::texture::cache_stats`), so a row is a (scene, knob point, geometry) with:
//! conformance failures, max and mean error (8-bit LSBs), PSNR, the unit's ECP5 area at
//! that point ([`crate::texture_area`]), the cache's hit rate, and a frame time in cycles:
//! one cache access a clock (a fragment between two levels takes two) plus, for each lane
//! that misses, the miss penalty of `model::texture_cache::Params::miss_penalty` at one
//! lane and the grid's memory latency. A request missing in m lanes costs m·line + L + 2
//! in the RTL, not m·(line + L + 2): the figure is an upper bound, exact where misses
//! come one lane at a time.
//!
//! [`charts`] draws the error against area, the hit rate and the frame time against the
//! cache's size, and each knob's sensitivity with Vulkan 1.0's minimums (4 sub-texel and
//! 4 level-of-detail bits, `VkPhysicalDeviceLimits::subTexelPrecisionBits` and
//! `mipmapPrecisionBits`) and Vulkan Roadmap 2022's (8 and 6) drawn as rules.

use crate::chart::{pareto, Chart, Pt, Series};
use crate::row::Source;
use crate::texture_area::{unit_cost, TexCost};
use accuracy::texture::{cache_stats, judge, TextureSetup};
use fx::{Fmt, TexFormats};
use model::texture_cache::Params as CacheParams;
use rayon::prelude::*;
use scene::Trilist;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use texture::LodRule;

/// A precision knob of the texture unit (`fx::TexFormats`' field of the same name).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Knob {
    /// Fraction bits of texel coordinates (Vulkan's `subTexelPrecisionBits`).
    Subtexel,
    /// Fraction bits of the level of detail (Vulkan's `mipmapPrecisionBits`).
    LodFrac,
    /// Fraction bits of the bilinear weights.
    Weight,
    /// Fraction bits of the reciprocal of q (001's eq. 3 divider).
    Recip,
}

impl Knob {
    pub const ALL: [Knob; 4] = [Knob::Subtexel, Knob::LodFrac, Knob::Weight, Knob::Recip];

    /// Its name in grids, rows and charts.
    pub fn name(self) -> &'static str {
        match self {
            Knob::Subtexel => "subtexel",
            Knob::LodFrac => "lod_frac",
            Knob::Weight => "weight",
            Knob::Recip => "recip",
        }
    }

    /// What an API requires of it: (bits, requirement), Vulkan 1.0's minimums and Vulkan
    /// Roadmap 2022's (`../shared/PRECISION.md`); none for the knobs no API names.
    pub fn requirements(self) -> &'static [(u32, &'static str)] {
        match self {
            Knob::Subtexel => &[(4, "Vulkan 1.0 minimum (4)"), (8, "Roadmap 2022 (8)")],
            Knob::LodFrac => &[(4, "Vulkan 1.0 minimum (4)"), (6, "Roadmap 2022 (6)")],
            Knob::Weight | Knob::Recip => &[],
        }
    }
}

/// The knobs' values at one point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Knobs {
    pub subtexel: u32,
    pub lod_frac: u32,
    pub weight: u32,
    pub recip: u32,
}

impl Knobs {
    /// The defaults' (`TexFormats::DEFAULT`).
    pub const DEFAULT: Knobs = Knobs::of(&TexFormats::DEFAULT);

    /// The knobs of `f`.
    pub const fn of(f: &TexFormats) -> Knobs {
        Knobs { subtexel: f.subtexel, lod_frac: f.lod_frac, weight: f.weight, recip: f.recip }
    }

    /// `knob`'s value.
    pub fn get(&self, knob: Knob) -> u32 {
        match knob {
            Knob::Subtexel => self.subtexel,
            Knob::LodFrac => self.lod_frac,
            Knob::Weight => self.weight,
            Knob::Recip => self.recip,
        }
    }

    /// `self` with `knob` at `v`.
    pub fn with(mut self, knob: Knob, v: u32) -> Knobs {
        *match knob {
            Knob::Subtexel => &mut self.subtexel,
            Knob::LodFrac => &mut self.lod_frac,
            Knob::Weight => &mut self.weight,
            Knob::Recip => &mut self.recip,
        } = v;
        self
    }

    /// The unit's formats at these knobs, the rest at the defaults; s and t (`st`) keep
    /// `subtexel` + 12 fraction bits, the texel coordinates of a 4096-texel level
    /// (`TexFormats::check`), and at least the default's 20.
    pub fn formats(&self) -> TexFormats {
        TexFormats {
            subtexel: self.subtexel,
            lod_frac: self.lod_frac,
            weight: self.weight,
            recip: self.recip,
            st: Fmt::s(8, (self.subtexel + fx::texture::MAX_SIZE_LOG2).max(TexFormats::DEFAULT.st.frac)).saturating(),
            ..TexFormats::DEFAULT
        }
    }

    /// A short name: `s8 l6 w8 r24`.
    pub fn label(&self) -> String {
        format!("s{} l{} w{} r{}", self.subtexel, self.lod_frac, self.weight, self.recip)
    }
}

/// The texture sweep's grid (JSON, every key optional):
///
/// ```json
/// {"sensitivity": {"subtexel": [2, 4, 6, 8, 10], "lod_frac": [2, 4, 6, 8]},
///  "joint": {"subtexel": [4, 8], "lod_frac": [4, 6], "weight": [8], "recip": [16, 24]},
///  "caches": [[64, 2, 4], [16, 1, 4]], "mem_latency": 8, "lod": "max"}
/// ```
///
/// `sensitivity` moves one knob with the others at their defaults; `joint` is the product
/// of its lists (a knob left out stays at its default); `caches` are (sets, ways, words per
/// line) of each bank (`model::texture_cache::Params`); `mem_latency` the texture memory's
/// latency in cycles (the frame time's miss penalty); `lod` the level-of-detail rule,
/// `max` (001's eq. 4, the design's) or `exact` (GL's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TexGrid {
    pub sensitivity: BTreeMap<Knob, Vec<u32>>,
    pub joint: BTreeMap<Knob, Vec<u32>>,
    pub caches: Vec<[u32; 3]>,
    pub mem_latency: u32,
    pub lod: LodRule,
}

impl Default for TexGrid {
    /// Each knob from below Vulkan 1.0's minimum to beyond the defaults; the joint grid
    /// around Vulkan 1.0's and Roadmap 2022's values; every cache geometry the RTL builds
    /// (`rtl::texture_cache::GEOMETRIES`); a memory latency of 8 cycles; 001's rule.
    fn default() -> TexGrid {
        TexGrid {
            sensitivity: [
                (Knob::Subtexel, (1..=10).collect()),
                (Knob::LodFrac, (1..=8).collect()),
                (Knob::Weight, (1..=10).collect()),
                (Knob::Recip, (8..=24).step_by(2).collect()),
            ]
            .into(),
            joint: [
                (Knob::Subtexel, vec![4, 6, 8]),
                (Knob::LodFrac, vec![4, 6]),
                (Knob::Weight, vec![4, 6, 8]),
                (Knob::Recip, vec![12, 16, 24]),
            ]
            .into(),
            caches: rtl::texture_cache::GEOMETRIES.iter().map(|&(s, w, l)| [s, w, l]).collect(),
            mem_latency: 8,
            lod: LodRule::Max,
        }
    }
}

/// A knob point of a grid.
#[derive(Clone, Debug, PartialEq)]
pub struct TexPoint {
    /// `default`, `<knob>=<bits>` or the joint point's [`Knobs::label`].
    pub name: String,
    /// `default`, `sensitivity` or `joint`.
    pub kind: &'static str,
    /// The knob a sensitivity point moves.
    pub knob: Option<Knob>,
    pub knobs: Knobs,
}

impl TexGrid {
    /// The grid in `text`; the error names the key and what is wrong.
    pub fn parse(text: &str) -> Result<TexGrid, String> {
        let g: TexGrid = serde_json::from_str(text).map_err(|e| format!("not a texture grid: {e}"))?;
        g.check()?;
        Ok(g)
    }

    /// Whether every point's formats and every cache geometry can be built.
    pub fn check(&self) -> Result<(), String> {
        for p in self.points() {
            p.knobs.formats().check().map_err(|e| format!("point {}: {e}", p.name))?;
        }
        if self.caches.is_empty() {
            return Err("caches: give at least one geometry [sets, ways, line]".into());
        }
        for c in self.cache_params() {
            c.check()?;
        }
        if !(1..=1024).contains(&self.mem_latency) {
            return Err(format!("mem_latency = {}: 1 to 1024 cycles", self.mem_latency));
        }
        Ok(())
    }

    /// The cache geometries.
    pub fn cache_params(&self) -> Vec<CacheParams> {
        self.caches.iter().map(|&[sets, ways, line]| CacheParams { sets, ways, line }).collect()
    }

    /// The default point, then the sensitivity points, then the joint ones; a point whose
    /// knobs an earlier one has is left out.
    pub fn points(&self) -> Vec<TexPoint> {
        let mut out = vec![TexPoint { name: "default".into(), kind: "default", knob: None, knobs: Knobs::DEFAULT }];
        for (&knob, values) in &self.sensitivity {
            for &v in values {
                let knobs = Knobs::DEFAULT.with(knob, v);
                out.push(TexPoint {
                    name: format!("{}={v}", knob.name()),
                    kind: "sensitivity",
                    knob: Some(knob),
                    knobs,
                });
            }
        }
        let mut joint = vec![Knobs::DEFAULT];
        for (&knob, values) in &self.joint {
            joint = joint.iter().flat_map(|k| values.iter().map(move |&v| k.with(knob, v))).collect();
        }
        if !self.joint.is_empty() {
            out.extend(joint.into_iter().map(|knobs| TexPoint {
                name: knobs.label(),
                kind: "joint",
                knob: None,
                knobs,
            }));
        }
        let mut seen = std::collections::HashSet::new();
        out.retain(|p| seen.insert(p.knobs));
        out
    }
}

/// A textured scene to sweep.
pub struct TexInput {
    pub name: String,
    pub list: Trilist,
}

/// One row: a (scene, knob point, cache geometry).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TexRow {
    pub scene: String,
    pub point: String,
    pub kind: String,
    pub knob: Option<Knob>,
    pub knobs: Knobs,
    pub sets: u32,
    pub ways: u32,
    pub line: u32,
    /// The cache's bytes: four banks of sets x ways x line 32-bit words.
    pub cache_bytes: u32,
    /// Textured fragments judged, and cache accesses (2x2 footprints, one per level read).
    pub fragments: u64,
    pub accesses: u64,
    /// Fragments outside the conformance tolerance of every allowed result.
    pub failures: u64,
    pub max_error_lsb: f64,
    pub mean_error_lsb: f64,
    /// `None`: no error at all.
    pub psnr_db: Option<f64>,
    pub hits: u64,
    pub misses: u64,
    pub hit_rate: f64,
    pub mem_latency: u32,
    /// Accesses plus each missing lane's penalty (the module doc: an upper bound).
    pub frame_cycles: u64,
    /// The texture unit's four units at this point ([`crate::texture_area::unit_cost`]).
    pub cost: TexCost,
    pub cost_source: Source,
}

impl TexRow {
    /// Failures per fragment.
    pub fn failure_rate(&self) -> f64 {
        self.failures as f64 / self.fragments.max(1) as f64
    }
}

/// Runs every (input, point) on `jobs` threads (0: one per core), each replayed at every
/// cache geometry; `done` after each (input, point). Rows in (scene, point, geometry)
/// order. Errors: a grid that cannot be built, an untextured input, a scene the unit
/// refuses (named).
pub fn run(inputs: &[TexInput], grid: &TexGrid, jobs: usize, done: &(dyn Fn() + Sync)) -> Result<Vec<TexRow>, String> {
    grid.check()?;
    for i in inputs {
        if !i.list.is_textured() {
            return Err(format!("{}: no textured triangle: nothing for the texture unit to sample", i.name));
        }
    }
    let points = grid.points();
    let tasks: Vec<(&TexInput, &TexPoint)> = inputs.iter().flat_map(|i| points.iter().map(move |p| (i, p))).collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(jobs).build().map_err(|e| e.to_string())?;
    let rows: Result<Vec<Vec<TexRow>>, String> = pool.install(|| {
        tasks
            .par_iter()
            .map(|&(input, point)| {
                let rows = measure(input, point, grid);
                done();
                rows
            })
            .collect()
    });
    Ok(rows?.into_iter().flatten().collect())
}

/// One (input, point) at every geometry of `grid`.
fn measure(input: &TexInput, point: &TexPoint, grid: &TexGrid) -> Result<Vec<TexRow>, String> {
    let formats = point.knobs.formats();
    let setup = TextureSetup { formats, lod: grid.lod, affine: false };
    let r = judge(&input.list, &setup).map_err(|e| format!("{}: point {}: {e}", input.name, point.name))?;
    Ok(grid
        .cache_params()
        .iter()
        .map(|p| {
            let c = cache_stats(p, &r.trace);
            let (cost, cost_source) = unit_cost(&formats, p);
            let penalty = p.miss_penalty(1, grid.mem_latency);
            TexRow {
                scene: input.name.clone(),
                point: point.name.clone(),
                kind: point.kind.into(),
                knob: point.knob,
                knobs: point.knobs,
                sets: p.sets,
                ways: p.ways,
                line: p.line,
                cache_bytes: model::texture_cache::LANES as u32 * p.bank_words() * 4,
                fragments: r.pixels,
                accesses: r.trace.len() as u64,
                failures: r.failures,
                max_error_lsb: r.max_error_lsb,
                mean_error_lsb: r.mean_error_lsb,
                psnr_db: r.psnr_db.is_finite().then_some(r.psnr_db),
                hits: c.hits,
                misses: c.misses,
                hit_rate: c.hit_rate,
                mem_latency: grid.mem_latency,
                frame_cycles: r.trace.len() as u64 + c.misses * penalty,
                cost,
                cost_source,
            }
        })
        .collect())
}

/// The default geometry's rows (`accuracy::texture::DEFAULT_CACHE`), or, when the grid
/// lacks it, the first geometry's.
fn at_one_geometry(rows: &[TexRow]) -> Vec<&TexRow> {
    let d = accuracy::texture::DEFAULT_CACHE;
    let has_default = rows.iter().any(|r| (r.sets, r.ways, r.line) == (d.sets, d.ways, d.line));
    let first = rows.first().map(|r| (r.sets, r.ways, r.line));
    let keep = if has_default { Some((d.sets, d.ways, d.line)) } else { first };
    rows.iter().filter(|r| Some((r.sets, r.ways, r.line)) == keep).collect()
}

/// Per point (at one geometry), summed over the scenes: (fragments, failures, worst max
/// error, worst PSNR, the cost), in the rows' order.
pub struct PointSum<'a> {
    pub point: &'a str,
    pub kind: &'a str,
    pub knob: Option<Knob>,
    pub knobs: Knobs,
    pub fragments: u64,
    pub failures: u64,
    pub max_error_lsb: f64,
    /// The worst scene's; `None` when every scene is exact.
    pub psnr_db: Option<f64>,
    pub cost: TexCost,
    pub cost_source: Source,
}

impl PointSum<'_> {
    /// Failures, in % of the fragments.
    pub fn failure_percent(&self) -> f64 {
        100.0 * self.failures as f64 / self.fragments.max(1) as f64
    }
}

/// Every point summed over the scenes (at the default geometry).
pub fn point_sums(rows: &[TexRow]) -> Vec<PointSum<'_>> {
    let mut out: Vec<PointSum> = Vec::new();
    for r in at_one_geometry(rows) {
        let s = match out.iter_mut().find(|s| s.point == r.point) {
            Some(s) => s,
            None => {
                out.push(PointSum {
                    point: &r.point,
                    kind: &r.kind,
                    knob: r.knob,
                    knobs: r.knobs,
                    fragments: 0,
                    failures: 0,
                    max_error_lsb: 0.0,
                    psnr_db: None,
                    cost: r.cost,
                    cost_source: r.cost_source,
                });
                out.last_mut().expect("just pushed")
            }
        };
        s.fragments += r.fragments;
        s.failures += r.failures;
        s.max_error_lsb = s.max_error_lsb.max(r.max_error_lsb);
        s.psnr_db = match (s.psnr_db, r.psnr_db) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
    }
    out
}

/// The texture sweep's charts: error against area, hit rate and frame time against the
/// cache's size, and one sensitivity chart per knob swept.
pub fn charts(rows: &[TexRow]) -> Vec<Chart> {
    let sums = point_sums(rows);
    let mut out = vec![error_vs_area(&sums)];
    out.extend(cache_charts(rows));
    for knob in Knob::ALL {
        if sums.iter().any(|s| s.knob == Some(knob)) {
            out.push(sensitivity(&sums, knob));
        }
    }
    out
}

/// % of fragments out of tolerance against the unit's ECP5 LUT4s, one series per kind of
/// point, the Pareto front, the default and Vulkan 1.0's minimums (4 sub-texel, 4 level
/// bits, the rest at the defaults) marked.
fn error_vs_area(sums: &[PointSum]) -> Chart {
    let mut series: BTreeMap<&str, Vec<Pt>> = BTreeMap::new();
    let mut marks = Vec::new();
    let vulkan = Knobs { subtexel: 4, lod_frac: 4, ..Knobs::DEFAULT };
    for s in sums {
        let p = Pt { x: s.cost.lut4, y: s.failure_percent(), label: s.point.to_string() };
        if s.kind == "default" {
            marks.push(Pt { label: "default (Roadmap 2022: 8 sub-texel, 6 level bits)".into(), ..p.clone() });
        } else if s.knobs == vulkan {
            marks.push(Pt { label: "Vulkan 1.0 minimums (4, 4)".into(), ..p.clone() });
        }
        series.entry(s.kind).or_default().push(p);
    }
    let all: Vec<&Pt> = series.values().flatten().collect();
    let front =
        pareto(&all.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>()).into_iter().map(|i| all[i].clone()).collect();
    Chart {
        stem: "texture_error_vs_area".into(),
        title: "Texture unit: conformance failures vs ECP5 area (all textured scenes)".into(),
        x_label: "ECP5 LUT4s of the texture unit (default cache; modelled off the defaults)".into(),
        y_label: format!("% of textured fragments out of tolerance (log; 0 drawn at {:e})", crate::chart::LOG_FLOOR),
        x_log: false,
        y_log: true,
        series: series.into_iter().map(|(name, points)| Series { name: name.into(), points }).collect(),
        front,
        marks,
        rules: Vec::new(),
    }
}

/// Hit rate and frame time against the cache's bytes at the default knobs, a series per
/// scene, the default geometry marked.
fn cache_charts(rows: &[TexRow]) -> Vec<Chart> {
    let d = accuracy::texture::DEFAULT_CACHE;
    let chart = |stem: &str, title: &str, y_label: &str, y: fn(&TexRow) -> f64, y_log: bool| {
        let mut series: BTreeMap<&str, Vec<Pt>> = BTreeMap::new();
        let mut marks = Vec::new();
        for r in rows.iter().filter(|r| r.kind == "default") {
            let p = Pt { x: f64::from(r.cache_bytes), y: y(r), label: format!("{}/{}/{}", r.sets, r.ways, r.line) };
            if (r.sets, r.ways, r.line) == (d.sets, d.ways, d.line) {
                marks.push(Pt { label: format!("{} default", r.scene), ..p.clone() });
            }
            series.entry(&r.scene).or_default().push(p);
        }
        Chart {
            stem: stem.into(),
            title: title.into(),
            x_label: "cache size (bytes, four banks; log)".into(),
            y_label: y_label.into(),
            x_log: true,
            y_log,
            series: series.into_iter().map(|(name, points)| Series { name: name.into(), points }).collect(),
            front: Vec::new(),
            marks,
            rules: Vec::new(),
        }
    };
    vec![
        chart(
            "texture_hit_rate_vs_cache",
            "Texture cache: hit rate vs size, every geometry (default formats)",
            "hit rate per lane lookup",
            |r| r.hit_rate,
            false,
        ),
        chart(
            "texture_frame_vs_cache",
            "Texture unit: frame time vs cache size (default formats)",
            "cycles per frame: accesses + missing lanes x miss penalty (log)",
            |r| r.frame_cycles as f64,
            true,
        ),
    ]
}

/// `knob`'s sensitivity: % out of tolerance against its bits, the other knobs at their
/// defaults, the default marked and the APIs' requirements drawn as rules.
fn sensitivity(sums: &[PointSum], knob: Knob) -> Chart {
    let d = Knobs::DEFAULT.get(knob);
    let mut points: Vec<Pt> = sums
        .iter()
        .filter(|s| s.knob == Some(knob) || s.kind == "default")
        .map(|s| Pt { x: f64::from(s.knobs.get(knob)), y: s.failure_percent(), label: s.point.to_string() })
        .collect();
    points.sort_by(|a, b| a.x.total_cmp(&b.x));
    let marks = points.iter().filter(|p| p.x == f64::from(d)).map(|p| Pt { label: "default".into(), ..p.clone() });
    Chart {
        stem: format!("texture_sensitivity_{}", knob.name()),
        title: format!("Texture unit: sensitivity to {} (other knobs at defaults, all textured scenes)", knob.name()),
        x_label: format!("{} (fraction bits)", knob.name()),
        y_label: format!("% of textured fragments out of tolerance (log; 0 drawn at {:e})", crate::chart::LOG_FLOOR),
        x_log: false,
        y_log: true,
        marks: marks.collect(),
        series: vec![Series { name: knob.name().into(), points }],
        front: Vec::new(),
        rules: rules(&[knob]),
    }
}

/// The APIs' requirements of `knobs` as chart rules: one per distinct bit count, naming
/// every requirement at it (`subtexel, lod_frac: Vulkan 1.0 minimum (4)`).
pub fn rules(knobs: &[Knob]) -> Vec<Pt> {
    let mut at: BTreeMap<u32, Vec<String>> = BTreeMap::new();
    for &k in knobs {
        for &(bits, what) in k.requirements() {
            at.entry(bits).or_default().push(format!("{} {what}", k.name()));
        }
    }
    at.into_iter().map(|(bits, what)| Pt { x: f64::from(bits), y: f64::NAN, label: what.join("; ") }).collect()
}

/// The texture sweep's Markdown: the knob points summed over the scenes, the cache
/// geometries at the default knobs, and the charts (SVG beside it).
pub fn report(rows: &[TexRow], charts: &[Chart]) -> String {
    let mut md = String::from("# edgepaint sweep: the texture unit\n\n");
    let scenes: std::collections::BTreeSet<&str> = rows.iter().map(|r| r.scene.as_str()).collect();
    md += &format!(
        "Scenes: {}. Every textured fragment through the bit-exact unit against the float reference, judged as the \
         conformance tests judge filtering (`accuracy::texture`); area: `sweep::texture_area` (Yosys where measured).\n\n",
        scenes.into_iter().collect::<Vec<_>>().join(", ")
    );
    md += "## Knob points (default cache), summed over the scenes\n\n| point | subtexel | lod_frac | weight | recip | \
           fragments out of tolerance | worst max error (LSB) | worst PSNR (dB) | LUT4 | FF | DSP | area |\n\
           |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for s in point_sums(rows) {
        let k = s.knobs;
        md += &format!(
            "| {} | {} | {} | {} | {} | {} ({:.3}%) | {:.2} | {} | {:.0} | {:.0} | {:.0} | {} |\n",
            s.point,
            k.subtexel,
            k.lod_frac,
            k.weight,
            k.recip,
            s.failures,
            s.failure_percent(),
            s.max_error_lsb,
            s.psnr_db.map_or("exact".into(), |p| format!("{p:.1}")),
            s.cost.lut4,
            s.cost.ff,
            s.cost.dsp,
            format!("{:?}", s.cost_source).to_lowercase()
        );
    }
    md += "\n## Cache geometries (default knobs)\n\n| scene | sets | ways | words | bytes | hit rate | misses | \
           frame cycles | cache LUT4 + unit | DP16KD |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for r in rows.iter().filter(|r| r.kind == "default") {
        md += &format!(
            "| {} | {} | {} | {} | {} | {:.4} | {} | {} | {:.0} | {:.0} |\n",
            r.scene,
            r.sets,
            r.ways,
            r.line,
            r.cache_bytes,
            r.hit_rate,
            r.misses,
            r.frame_cycles,
            r.cost.lut4,
            r.cost.bram
        );
    }
    for c in charts {
        md += &format!("\n## {}\n\n![{}]({}.svg)\n", c.title, c.title, c.stem);
    }
    let cal = crate::texture_area::Calibration::committed();
    md += &format!(
        "\n## The cache's area model\n\nFitted to {} Yosys `synth_ecp5` runs of `texture_cache` (`crates/sweep/area/texture.json`), \
         block RAMs counted; its error on the runs held out of the fit:\n\n{}",
        cal.cache.iter().filter(|s| !s.held_out).count(),
        crate::texture_area::validation(crate::texture_area::CacheModel::calibrated(), &cal.cache)
    );
    md
}

/// Writes `rows` as `texture.jsonl` and `texture.csv` into `dir`.
pub fn write(dir: &std::path::Path, rows: &[TexRow]) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    let jsonl: String = rows.iter().map(|r| serde_json::to_string(r).expect("a row serialises") + "\n").collect();
    let mut csv = String::from(
        "scene,point,kind,subtexel,lod_frac,weight,recip,sets,ways,line,cache_bytes,fragments,accesses,failures,\
         max_error_lsb,mean_error_lsb,psnr_db,hits,misses,hit_rate,mem_latency,frame_cycles,lut4,ff,dsp,bram,lut_ram,cost_source\n",
    );
    for r in rows {
        let k = r.knobs;
        csv += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            r.scene,
            r.point,
            r.kind,
            k.subtexel,
            k.lod_frac,
            k.weight,
            k.recip,
            r.sets,
            r.ways,
            r.line,
            r.cache_bytes,
            r.fragments,
            r.accesses,
            r.failures,
            r.max_error_lsb,
            r.mean_error_lsb,
            r.psnr_db.map_or(String::new(), |p| p.to_string()),
            r.hits,
            r.misses,
            r.hit_rate,
            r.mem_latency,
            r.frame_cycles,
            r.cost.lut4,
            r.cost.ff,
            r.cost.dsp,
            r.cost.bram,
            r.cost.lut_ram,
            format!("{:?}", r.cost_source).to_lowercase()
        );
    }
    for (name, text) in [("texture.jsonl", jsonl), ("texture.csv", csv)] {
        let path = dir.join(name);
        std::fs::write(&path, text).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    }
    Ok(())
}
