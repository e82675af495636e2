//! The area model: what a scanline design costs (gate equivalents, ECP5 LUT4s, flip-flops
//! and multipliers, iCE40 LUT4s) at formats and parameters that were never synthesized.
//!
//! Each unit's cost in each metric is a non-negative combination of a few bit counts of its
//! datapath ([`features`]), read off the width table the RTL itself is built from
//! (`rtl::config::Widths`): the bits of the links it registers, its multipliers' operand
//! products, its divider's array. The combination is fitted ([`fit`]) to Yosys runs of real
//! builds spread over the formats and parameters (`area/builds.json`; the results in
//! `area/yosys.json`, written by `edgepaint sweep --calibrate`). Builds marked `held_out`
//! are left out of the fit, and [`Model::validation`] gives the model's error on them.
//!
//! A pipeline (`raster_top`) is its units plus the span FIFO between the edge walk and
//! span, whose cost is fitted as a multiple of the FIFO's bits.

use crate::row::Source;
use fx::Formats;
use rtl::config::Widths;
// The span FIFO's depth in span commands, the same in every build.
use rtl::n10::span_fifo::SPAN_FIFO;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The units of the scanline pipeline, and `raster_top`, as the calibration names them.
pub const UNITS: [&str; 5] = ["cull_sort", "triangle_setup", "edge_walk", "span", "pixel_out"];
/// The whole pipeline: [`UNITS`] and the span FIFO.
pub const PIPELINE: &str = "raster_top";

/// The costs the model gives, as `edgepaint report` measures them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Cost {
    /// 2-input gate equivalents (Yosys `synth -flatten`, `stat -tech cmos`, flip-flops
    /// counted: `edgepaint report`).
    pub ge: f64,
    /// `synth_ecp5`: LUT4, TRELLIS_FF, MULT18X18D.
    pub ecp5_lut4: f64,
    pub ecp5_ff: f64,
    pub ecp5_dsp: f64,
    /// `synth_ice40`: SB_LUT4.
    pub ice40_lut4: f64,
}

/// The barycentric pipeline at the default design, as `edgepaint report --unit raster_top
/// --param METHOD=1` measured it (stop 40: `cull_sort`, `rtl::vector` at one lane with
/// perspective-correct colours, the scout and the walker, `pixel_out`): the vector method's
/// cost where the sweep prices it (`run`, [`vector_pipeline`]).
pub const VECTOR_PIPELINE: Cost =
    Cost { ge: 275_176.0, ecp5_lut4: 8_305.0, ecp5_ff: 10_707.0, ecp5_dsp: 42.0, ice40_lut4: 33_566.0 };

/// One more lane of it: `edgepaint report --unit vector` at `LANES=2` less `LANES=1` (stop
/// 40: a lane's coverage, its pixel pipeline with 16 multipliers and a divider, and the
/// lanes' gathering), and a `pixel_out` for the lane's bank (README, "Units": 1,701 GE, 151
/// LUT4, 142 FF); iCE40 LUT4s, not synthesized for the lane, in the pipeline's ratio of
/// iCE40 LUT4s to gate equivalents.
pub const VECTOR_LANE: Cost = Cost {
    ge: (417_995.0 - 252_322.0) + 1_701.0,
    ecp5_lut4: (9_923.0 - 7_935.0) + 151.0,
    ecp5_ff: (15_218.0 - 9_593.0) + 142.0,
    ecp5_dsp: 78.0 - 40.0,
    ice40_lut4: ((417_995.0 - 252_322.0) + 1_701.0) * VECTOR_PIPELINE.ice40_lut4 / VECTOR_PIPELINE.ge,
};

/// The SE back end (`raster_top` with `METHOD = 2`: the scanline front end, `se_cmd` and
/// five shading engines) at the default design, synthesized (`edgepaint report --unit
/// raster_top --param METHOD=2 --param ENGINES=5`, stop 41; README, "Units"): the generic
/// flow's gate equivalents count the engines' corner-turning RAMs as flip-flops, ECP5 maps
/// them to 605 LUT RAMs.
pub const SE_PIPELINE_5: Cost = se_measured(943_093.0, 47_771.0, 17_990.0);

/// The same at one engine (`--param ENGINES=1`, stop 42; 121 LUT RAMs), placed and routed
/// (`sweep::clock::SE_PIPELINE_MHZ`).
pub const SE_PIPELINE_1: Cost = se_measured(460_752.0, 26_554.0, 14_614.0);

/// The SE back end as synthesized: gate equivalents, ECP5 LUT4s and flip-flops, and
/// setup's 30 DSP blocks (the engines' multipliers are serial); iCE40 LUT4s, not
/// synthesized, in the vector pipeline's ratio of iCE40 to ECP5 LUT4s.
const fn se_measured(ge: f64, ecp5_lut4: f64, ecp5_ff: f64) -> Cost {
    let ice40_lut4 = ecp5_lut4 * VECTOR_PIPELINE.ice40_lut4 / VECTOR_PIPELINE.ecp5_lut4;
    Cost { ge, ecp5_lut4, ecp5_ff, ecp5_dsp: 30.0, ice40_lut4 }
}

/// An engine more: a quarter of [`SE_PIPELINE_5`] less [`SE_PIPELINE_1`] (a `Bank`: the
/// engine, its four ports' clamps, and its share of the gathered write word).
pub fn se_engine() -> Cost {
    let mut c = Cost::default();
    for m in 0..METRICS.len() {
        c.set(m, (SE_PIPELINE_5.get(m) - SE_PIPELINE_1.get(m)) / 4.0);
    }
    c
}

/// The SE back end for a screen `width` columns wide at the default design, with the fewest
/// engines built that cover it (`rtl::se_engines_for`: 1, 5 or 16), and where the figure
/// comes from: measured at 1 and 5 engines, modelled at 16 ([`SE_PIPELINE_5`] and 11
/// [`se_engine`]s: the engines beside one another on the span bus; `synth_ecp5` of
/// `raster_top` at 16 engines gave 106,907 LUT4s and 27,343 FF against the model's 106,118
/// and 27,274, stop 42); `None` beyond 1,024 columns.
pub fn se_pipeline(width: u32) -> Option<(Cost, Source)> {
    Some(match rtl::se_engines_for(width)? {
        1 => (SE_PIPELINE_1, Source::Measured),
        5 => (SE_PIPELINE_5, Source::Measured),
        e => {
            let mut c = SE_PIPELINE_5;
            for _ in 5..e {
                c = c.add(se_engine());
            }
            (c, Source::Modelled)
        }
    })
}

/// The barycentric pipeline at `lanes` lanes (1, 2, 4 or 8) at the default design: measured
/// at one ([`VECTOR_PIPELINE`]); beyond it a model, a [`VECTOR_LANE`] per lane more (the
/// lanes beside one another). Checked against `raster_top` at `LANES=4` synthesized (stop
/// 41, no place and route): 771,450 GE, 15,848 LUT4, 27,796 FF, 156 DSP against the model's
/// 777,298, 14,722, 28,008 and 156. `None` for other lane counts (`rtl::vector` is built
/// with 1, 2, 4 or 8).
pub fn vector_pipeline(lanes: u32) -> Option<Cost> {
    matches!(lanes, 1 | 2 | 4 | 8).then(|| {
        let mut c = VECTOR_PIPELINE;
        for _ in 1..lanes {
            c = c.add(VECTOR_LANE);
        }
        c
    })
}

/// The metrics of a [`Cost`], by name.
pub const METRICS: [&str; 5] = ["ge", "ecp5_lut4", "ecp5_ff", "ecp5_dsp", "ice40_lut4"];
/// The metric counted, not fitted: ECP5 multiplier blocks ([`multiplier_blocks`]).
const DSP: usize = 3;

impl Cost {
    fn get(&self, metric: usize) -> f64 {
        [self.ge, self.ecp5_lut4, self.ecp5_ff, self.ecp5_dsp, self.ice40_lut4][metric]
    }

    fn set(&mut self, metric: usize, v: f64) {
        *[&mut self.ge, &mut self.ecp5_lut4, &mut self.ecp5_ff, &mut self.ecp5_dsp, &mut self.ice40_lut4][metric] = v;
    }

    fn add(self, o: Cost) -> Cost {
        let mut c = self;
        for m in 0..METRICS.len() {
            c.set(m, self.get(m) + o.get(m));
        }
        c
    }
}

/// A scanline design: its build (size class, formats) and setup's parameters.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Design {
    pub class: u32,
    pub formats: Formats,
    /// Setup's multipliers and the divider's stages.
    #[serde(rename = "K")]
    pub k: u32,
    #[serde(rename = "L")]
    pub l: u32,
}

/// One Yosys run of a calibration build's unit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// The calibration build's name (`area/builds.json`).
    pub build: String,
    pub unit: String,
    pub design: Design,
    /// Left out of the fit, to measure the model's error.
    pub held_out: bool,
    pub cost: Cost,
}

/// A build the calibration synthesizes (`area/builds.json`): a size class, the formats
/// over its defaults (knobs only, `fx::Formats::with_overrides`), setup's parameters.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Build {
    pub name: String,
    pub class: u32,
    pub formats: serde_json::Map<String, serde_json::Value>,
    /// `K`, `L` where not the defaults (7 and `model::divider::LATENCY`).
    #[serde(default)]
    pub params: BTreeMap<String, u32>,
    /// The units synthesized: [`UNITS`], only these, or with these too.
    #[serde(default)]
    pub only: Option<Vec<String>>,
    #[serde(default)]
    pub also: Vec<String>,
    #[serde(default)]
    pub held_out: bool,
}

impl Build {
    /// Every calibration build.
    pub fn all() -> Vec<Build> {
        serde_json::from_str(include_str!("../area/builds.json")).expect("area/builds.json parses")
    }

    /// The units this build synthesizes.
    pub fn units(&self) -> Vec<String> {
        let mut u = self.only.clone().unwrap_or_else(|| UNITS.map(String::from).to_vec());
        u.extend(self.also.iter().cloned());
        u
    }

    /// Its design: the formats resolved for a screen of its class.
    pub fn design(&self) -> Result<Design, String> {
        let side = 1u32 << self.class.min(16);
        let formats = Formats::with_overrides(side, side, &serde_json::Value::Object(self.formats.clone()))
            .map_err(|e| format!("calibration build {}: {e}", self.name))?;
        let param = |k: &str, d: u32| self.params.get(k).copied().unwrap_or(d);
        Ok(Design { class: self.class, formats, k: param("K", 7), l: param("L", model::divider::LATENCY) })
    }

    /// The sample of `unit` from `edgepaint report`'s JSON (`report.json`).
    pub fn sample(&self, unit: &str, report: &serde_json::Value) -> Result<Sample, String> {
        let row = &report["units"][0];
        let num = |path: [&str; 2]| {
            row[path[0]][path[1]]
                .as_f64()
                .ok_or_else(|| format!("report of {unit} in {}: no {}.{}", self.name, path[0], path[1]))
        };
        Ok(Sample {
            build: self.name.clone(),
            unit: unit.into(),
            design: self.design()?,
            held_out: self.held_out,
            cost: Cost {
                ge: num(["generic", "gate_equivalents"])?,
                ecp5_lut4: num(["ecp5", "luts"])?,
                ecp5_ff: num(["ecp5", "ffs"])?,
                ecp5_dsp: num(["ecp5", "dsps"])?,
                ice40_lut4: num(["ice40", "luts"])?,
            },
        })
    }
}

/// The bit counts a unit's cost is fitted on, with their names; the first is 1 (fixed
/// control logic). [`PIPELINE`]'s are those of the span FIFO alone.
pub fn features(unit: &str, d: &Design) -> Vec<(&'static str, f64)> {
    let w = Widths::of(d.class, &d.formats);
    let (k, l) = (d.k as f64, d.l as f64);
    let f = |v: usize| v as f64;
    let mut out = vec![("1", 1.0)];
    out.extend(match unit {
        // Outcodes and the sort's multiplexers over the vertices; twice the area, two
        // products of edge deltas (xy + 1 bits each).
        "cull_sort" => vec![
            ("vertex bits", f(w.triangle_link())),
            ("area product bits", f((w.xy + 1) * (w.xy + 1))),
            ("area product blocks", f(multiplier_blocks(unit, d))),
        ],
        // The vertices in, the set-up triangle out, the products kept; K multipliers of
        // mul_a x mul_b (their bits, and their 18 x 18 blocks); the divider's restoring
        // array (quotient bits x divisor) cut into L stages of registers.
        "triangle_setup" => vec![
            ("link bits", f(w.triangle_link() + w.setup_link())),
            ("multiplier bits", k * f(w.mul_a * w.mul_b)),
            ("multiplier blocks", f(multiplier_blocks(unit, d))),
            ("divider array", f(w.div_q * w.div_d)),
            ("divider stage registers", l * f(w.div_n + w.div_d + w.div_q)),
        ],
        // Three edge walkers with their attributes; a span command out.
        "edge_walk" => vec![("link bits", f(w.setup_link())), ("span bits", f(w.span_cmd_link()))],
        // A span command held and stepped; a pixel out.
        "span" => vec![("span bits", f(w.span_cmd_link())), ("pixel bits", f(w.pixel_link()))],
        // The memory port: address, depth compare, colour.
        "pixel_out" => vec![("port bits", f(w.addr + 2 * w.depth))],
        _ => vec![("span FIFO bits", f(SPAN_FIFO * w.span_cmd_link()))],
    });
    if unit == PIPELINE {
        out.remove(0);
    }
    out
}

/// The 18 x 18 multiplier blocks (ECP5's MULT18X18D) Yosys maps the low `p` bits of an
/// `a` x `b` product to: each operand cut into 18-bit slices from its LSB, a slice under 2
/// bits left to logic, and a pair of slices kept when its weight, the sum of the slices'
/// offsets, falls below `p` (the product's bits above it are not computed). Matches every
/// calibration build's count.
fn tiles(a: usize, b: usize, p: usize) -> usize {
    let slices = |n: usize| (0..n).step_by(18).filter(move |&o| n - o >= 2);
    slices(a).map(|oa| slices(b).filter(|&ob| oa + ob < p).count()).sum()
}

/// The ECP5 multiplier blocks of `unit` in `d`, counted: cull_sort's two area products,
/// setup's K multipliers (none elsewhere; the span FIFO has none).
pub fn multiplier_blocks(unit: &str, d: &Design) -> usize {
    let w = Widths::of(d.class, &d.formats);
    match unit {
        "cull_sort" => 2 * tiles(w.xy + 1, w.xy + 1, 2 * (w.xy + 1)),
        "triangle_setup" => d.k as usize * tiles(w.mul_a, w.mul_b, w.mul_p),
        _ => 0,
    }
}

/// Per unit and metric, the fitted coefficients of [`features`] (none for the counted
/// multiplier blocks).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Model {
    pub coefficients: BTreeMap<String, Vec<Vec<f64>>>,
    /// The samples it was fitted on and validated with.
    pub samples: Vec<Sample>,
}

/// The model's error on one held-out sample.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Validation {
    pub build: String,
    pub unit: String,
    pub measured: Cost,
    pub modelled: Cost,
}

impl Validation {
    /// (modelled - measured) / measured per metric; `None` where both are 0 (no DSPs).
    pub fn relative(&self, metric: usize) -> Option<f64> {
        let (m, p) = (self.measured.get(metric), self.modelled.get(metric));
        (m != 0.0 || p != 0.0).then(|| (p - m) / m.max(1.0))
    }
}

/// Fits [`Model`] to `samples` not held out: per unit and metric, the non-negative least
/// squares fit of the cost to the unit's features. [`PIPELINE`] samples fit the span FIFO
/// to what the pipeline costs beyond its units' models. An error when a unit has no sample.
pub fn fit(samples: &[Sample]) -> Result<Model, String> {
    let mut model = Model { coefficients: BTreeMap::new(), samples: samples.to_vec() };
    for unit in UNITS.iter().chain([&PIPELINE]) {
        let train: Vec<&Sample> = samples.iter().filter(|s| s.unit == *unit && !s.held_out).collect();
        if train.is_empty() {
            return Err(format!("no calibration sample of {unit} to fit"));
        }
        let rows: Vec<Vec<f64>> =
            train.iter().map(|s| features(unit, &s.design).into_iter().map(|(_, v)| v).collect()).collect();
        let mut per_metric = Vec::new();
        for m in 0..METRICS.len() {
            if m == DSP {
                per_metric.push(Vec::new());
                continue;
            }
            let y: Vec<f64> = train
                .iter()
                .map(|s| s.cost.get(m) - if *unit == PIPELINE { model.units(&s.design).get(m) } else { 0.0 })
                .collect();
            per_metric.push(nnls(&rows, &y));
        }
        model.coefficients.insert(unit.to_string(), per_metric);
    }
    Ok(model)
}

impl Model {
    /// The committed calibration (`area/yosys.json`) fitted.
    pub fn calibrated() -> &'static Model {
        static MODEL: std::sync::OnceLock<Model> = std::sync::OnceLock::new();
        MODEL.get_or_init(|| {
            let samples: Vec<Sample> =
                serde_json::from_str(include_str!("../area/yosys.json")).expect("area/yosys.json parses");
            fit(&samples).expect("area/yosys.json has every unit")
        })
    }

    /// `unit`'s modelled cost in `d`.
    pub fn unit(&self, unit: &str, d: &Design) -> Cost {
        let x: Vec<f64> = features(unit, d).into_iter().map(|(_, v)| v).collect();
        let mut c = Cost::default();
        for (m, coef) in self.coefficients[unit].iter().enumerate() {
            c.set(m, coef.iter().zip(&x).map(|(a, b)| a * b).sum::<f64>().max(0.0));
        }
        c.set(DSP, multiplier_blocks(unit, d) as f64);
        c
    }

    /// The sum of [`UNITS`]' modelled costs.
    fn units(&self, d: &Design) -> Cost {
        UNITS.iter().map(|u| self.unit(u, d)).fold(Cost::default(), Cost::add)
    }

    /// The whole pipeline's modelled cost: its units and the span FIFO.
    pub fn pipeline(&self, d: &Design) -> Cost {
        self.units(d).add(self.unit(PIPELINE, d))
    }

    /// The measured cost of the pipeline in `d` when the calibration synthesized it.
    pub fn measured(&self, d: &Design) -> Option<Cost> {
        self.samples.iter().find(|s| s.unit == PIPELINE && s.design == *d).map(|s| s.cost)
    }

    /// The model against Yosys on every held-out sample.
    pub fn validation(&self) -> Vec<Validation> {
        self.samples
            .iter()
            .filter(|s| s.held_out)
            .map(|s| Validation {
                build: s.build.clone(),
                unit: s.unit.clone(),
                measured: s.cost,
                modelled: if s.unit == PIPELINE { self.pipeline(&s.design) } else { self.unit(&s.unit, &s.design) },
            })
            .collect()
    }
}

/// The validation as Markdown: per held-out build, the units it synthesized summed,
/// modelled against measured in every metric; then each unit; then the mean and largest
/// error per metric over the builds.
pub fn validation_report(model: &Model) -> String {
    use std::fmt::Write as _;
    let v = model.validation();
    let mut builds: BTreeMap<&str, (Cost, Cost, Vec<&str>)> = BTreeMap::new();
    for s in &v {
        let b = builds.entry(s.build.as_str()).or_default();
        (b.0, b.1) = (b.0.add(s.measured), b.1.add(s.modelled));
        b.2.push(&s.unit);
    }
    let header = |first: &str| {
        let cols: Vec<String> = METRICS.iter().map(|m| format!("{m} Yosys / model / error")).collect();
        format!("| {first} | {} |\n|---|{}\n", cols.join(" | "), "---:|".repeat(METRICS.len()))
    };
    let cells = |measured: &Cost, modelled: &Cost| {
        let v = Validation { build: String::new(), unit: String::new(), measured: *measured, modelled: *modelled };
        (0..METRICS.len())
            .map(|m| match v.relative(m) {
                Some(e) => format!("{:.0} / {:.0} / {:+.1}%", measured.get(m), modelled.get(m), 100.0 * e),
                None => "0 / 0 / –".into(),
            })
            .collect::<Vec<_>>()
            .join(" | ")
    };
    let mut md = String::from("## The area model against Yosys on builds it was not fitted on\n\n");
    md += &header("held-out build (units summed)");
    let mut errors = vec![Vec::new(); METRICS.len()];
    for (name, (measured, modelled, units)) in &builds {
        writeln!(md, "| {name} ({}) | {} |", units.join(", "), cells(measured, modelled)).expect("a String");
        let v = Validation { build: String::new(), unit: String::new(), measured: *measured, modelled: *modelled };
        for (m, e) in errors.iter_mut().enumerate() {
            e.extend(v.relative(m).map(f64::abs));
        }
    }
    md += "\n";
    md += &header("held-out build, unit");
    for s in &v {
        writeln!(md, "| {} {} | {} |", s.build, s.unit, cells(&s.measured, &s.modelled)).expect("a String");
    }
    md += "\n| metric | mean abs. error over held-out builds | largest |\n|---|---:|---:|\n";
    for (m, e) in errors.iter().enumerate() {
        let mean = e.iter().sum::<f64>() / e.len().max(1) as f64;
        let max = e.iter().cloned().fold(0.0, f64::max);
        writeln!(md, "| {} | {:.1}% | {:.1}% |", METRICS[m], 100.0 * mean, 100.0 * max).expect("a String");
    }
    let fitted: std::collections::BTreeSet<&str> =
        model.samples.iter().filter(|s| !s.held_out).map(|s| s.build.as_str()).collect();
    writeln!(
        md,
        "\nFitted on {} builds ({}); held out: {}.",
        fitted.len(),
        fitted.into_iter().collect::<Vec<_>>().join(", "),
        builds.keys().cloned().collect::<Vec<_>>().join(", ")
    )
    .expect("a String");
    md
}

/// Non-negative least squares, `min |A x - y|` over `x >= 0`, by its support: the
/// unconstrained least-squares solution on each subset of the columns, the best of those
/// that are non-negative (the features are few). Columns are scaled to a maximum of 1 for
/// the solve.
pub(crate) fn nnls(a: &[Vec<f64>], y: &[f64]) -> Vec<f64> {
    let n = a[0].len();
    let scale: Vec<f64> = (0..n)
        .map(|j| a.iter().map(|r| r[j].abs()).fold(0.0, f64::max))
        .map(|s| if s > 0.0 { s } else { 1.0 })
        .collect();
    let mut best = (residual(a, y, &vec![0.0; n]), vec![0.0; n]);
    for mask in 1u32..(1 << n) {
        let cols: Vec<usize> = (0..n).filter(|j| mask >> j & 1 == 1).collect();
        let Some(sol) = least_squares(a, y, &cols, &scale) else { continue };
        if sol.iter().all(|&v| v >= 0.0) {
            let mut x = vec![0.0; n];
            for (&j, v) in cols.iter().zip(sol) {
                x[j] = v / scale[j];
            }
            let r = residual(a, y, &x);
            if r < best.0 * (1.0 - 1e-12) {
                best = (r, x);
            }
        }
    }
    best.1
}

fn residual(a: &[Vec<f64>], y: &[f64], x: &[f64]) -> f64 {
    a.iter().zip(y).map(|(r, y)| (r.iter().zip(x).map(|(a, x)| a * x).sum::<f64>() - y).powi(2)).sum()
}

/// The least-squares solution on columns `cols` (scaled by `scale`), by the normal
/// equations and Gaussian elimination; `None` when they are singular.
fn least_squares(a: &[Vec<f64>], y: &[f64], cols: &[usize], scale: &[f64]) -> Option<Vec<f64>> {
    let k = cols.len();
    let x = |r: &Vec<f64>, j: usize| r[j] / scale[j];
    // The normal equations [A'A | A'y], a row per column.
    let mut m: Vec<Vec<f64>> = cols
        .iter()
        .map(|&i| {
            let mut row: Vec<f64> = cols.iter().map(|&j| a.iter().map(|r| x(r, i) * x(r, j)).sum()).collect();
            row.push(a.iter().zip(y).map(|(r, yv)| x(r, i) * yv).sum());
            row
        })
        .collect();
    for c in 0..k {
        let p = (c..k).max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))?;
        if m[p][c].abs() < 1e-9 {
            return None;
        }
        m.swap(c, p);
        let pivot = m[c].clone();
        for (_, row) in m.iter_mut().enumerate().filter(|(i, _)| *i != c) {
            let f = row[c] / pivot[c];
            for (v, pv) in row.iter_mut().zip(&pivot).skip(c) {
                *v -= f * pv;
            }
        }
    }
    Some(m.iter().enumerate().map(|(i, row)| row[k] / row[i]).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn design(z_frac: u32, k: u32) -> Design {
        let mut f = Formats::for_n(10);
        f.z.frac = z_frac;
        Design { class: 10, formats: f, k, l: 5 }
    }

    /// Yosys' MULT18X18D counts of the calibration builds: setup's K multipliers and
    /// cull_sort's two area products.
    #[test]
    fn tiles_count_yosys_multiplier_blocks() {
        assert_eq!([tiles(57, 19, 58), tiles(58, 20, 60), tiles(55, 19, 55), tiles(64, 27, 64)], [4, 7, 3, 7]);
        assert_eq!([tiles(17, 17, 34), tiles(20, 20, 40)], [1, 4]);
        for s in &Model::calibrated().samples {
            let n = match s.unit.as_str() {
                PIPELINE => UNITS.iter().map(|u| multiplier_blocks(u, &s.design)).sum(),
                u => multiplier_blocks(u, &s.design),
            };
            assert_eq!(n as f64, s.cost.ecp5_dsp, "{} {}", s.build, s.unit);
        }
    }

    #[test]
    fn nnls_recovers_a_non_negative_combination_and_clamps_a_negative_one() {
        let a: Vec<Vec<f64>> = (0..6).map(|i| vec![1.0, i as f64, (i * i) as f64]).collect();
        let y: Vec<f64> = a.iter().map(|r| 3.0 + 2.0 * r[1] + 0.5 * r[2]).collect();
        let x = nnls(&a, &y);
        for (got, want) in x.iter().zip([3.0, 2.0, 0.5]) {
            assert!((got - want).abs() < 1e-9, "{x:?}");
        }
        // y = 10 - i: the best non-negative fit drops the slope.
        let y: Vec<f64> = (0..6).map(|i| 10.0 - i as f64).collect();
        let x = nnls(&a, &y);
        assert!(x.iter().all(|&v| v >= 0.0) && x[1] == 0.0, "{x:?}");
    }

    /// The fit sees no held-out sample: changing one changes no coefficient, only the
    /// validation.
    #[test]
    fn held_out_samples_do_not_reach_the_fit() {
        let mut samples = Model::calibrated().samples.clone();
        let fitted = fit(&samples).unwrap();
        let i = samples.iter().position(|s| s.held_out).expect("a held-out sample");
        samples[i].cost.ge *= 3.0;
        let refit = fit(&samples).unwrap();
        assert_eq!(fitted.coefficients, refit.coefficients);
        assert_ne!(fitted.validation(), refit.validation());
    }

    /// More depth bits or more multipliers never make a design smaller.
    #[test]
    fn cost_grows_with_widths_and_multipliers() {
        let m = Model::calibrated();
        let (narrow, wide) = (m.pipeline(&design(16, 7)), m.pipeline(&design(24, 7)));
        for (i, metric) in METRICS.iter().enumerate() {
            assert!(wide.get(i) >= narrow.get(i), "{metric}: {} < {}", wide.get(i), narrow.get(i));
        }
        let (few, many) = (m.unit("triangle_setup", &design(16, 1)), m.unit("triangle_setup", &design(16, 7)));
        assert!(many.ecp5_dsp > few.ecp5_dsp && many.ge > few.ge, "{few:?} {many:?}");
    }
}
