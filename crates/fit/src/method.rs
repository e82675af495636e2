//! The method (`--method auto|scanline|vector|se`): the designs of each method that can draw
//! the workload, and the one that best meets the objective.
//!
//! - **scanline** (001/003): the design [`crate::search::fit`] fits (formats, integer bits,
//!   K and L, the parts present).
//! - **vector** (004, `raster_top` with `METHOD = 1`): built at the default formats of size
//!   class 10 only, so its candidates are those formats at 1, 2, 4 and 8 lanes
//!   (`model::raster_top::LANES`); the lanes are chosen for the objective. Priced by
//!   `sweep::area::vector_pipeline` (Yosys at one lane, modelled beyond) and clocked by
//!   `sweep::clock::vector_pipeline_mhz` (routed at one and four lanes).
//! - **se** (000's shading engines behind the scanline front end, `METHOD = 2`): built at the
//!   same formats, with the fewest engines that cover the workload's widest screen
//!   (`rtl::se_engines_for`: 1, 5 or 16); priced by `sweep::area::se_pipeline`.
//!
//! Each candidate runs on every scene through its bit-exact model and the float reference
//! (`sweep::run`, cached and parallel) and passes when every scene meets the target. Of the
//! passing ones, `auto` takes the least [`Objective::score`]: the area model's gate
//! equivalents (measured where the design was synthesized), the mean cycles or time per
//! frame (at the clock routed where measured, modelled elsewhere), or a product of area and
//! one of them. The vector and SE back ends' formats are not fitted (their RTL exists at
//! the default formats only), so they compete at those.

use crate::search::{cost, Fitted, Objective, Set};
use crate::target::Target;
use sweep::area::{Cost, Model};
use sweep::grid::{Method, Point};
use sweep::row::{Row, Source};
use sweep::run::{run, Input, Options};

/// A design of one method, run on the workload.
#[derive(Clone, Debug)]
pub struct Candidate {
    pub method: Method,
    /// Its parameters: `K` and `L` (scanline), `lanes` (vector), `engines` (se).
    pub params: Set,
    /// One row per scene (empty when the method cannot draw the workload).
    pub rows: Vec<Row>,
    /// Its area and where the figure comes from; `None` where no RTL is built.
    pub cost: Option<(Cost, Source)>,
    /// Its clock in MHz (routed where measured) and where the figure comes from.
    pub clock: Option<(f64, Source)>,
    /// Why it fails (`<scene>: <term missed>`, or why the method cannot draw the workload);
    /// empty when it passes.
    pub misses: Vec<String>,
}

impl Candidate {
    pub fn passes(&self) -> bool {
        self.misses.is_empty()
    }

    /// Its mean cycles per frame over the workload.
    pub fn cycles(&self) -> f64 {
        self.rows.iter().map(|r| r.cycles as f64).sum::<f64>() / self.rows.len().max(1) as f64
    }

    /// Its mean frame time over the workload in microseconds, at its clock.
    pub fn frame_us(&self) -> Option<f64> {
        self.clock.map(|(mhz, _)| self.cycles() / mhz)
    }

    /// Its score for `objective` (smaller is better); `None` when it fails or is not priced.
    pub fn score(&self, objective: Objective) -> Option<f64> {
        let (c, _) = self.cost.filter(|_| self.passes())?;
        Some(objective.score(c.ge, self.cycles(), self.frame_us().unwrap_or(f64::INFINITY)))
    }

    /// `method` with its parameters, e.g. `vector lanes=4`.
    pub fn label(&self) -> String {
        let params: Vec<String> = self.params.iter().map(|(k, v)| format!("{k}={v}")).collect();
        format!("{} {}", self.method.name(), params.join(" ")).trim_end().to_string()
    }
}

/// The scanline design `fitted` as a candidate (its cost measured where the calibration
/// synthesized it, modelled elsewhere), or the reason the search found none.
pub fn scanline(fitted: &Result<Fitted, String>, model: &Model) -> Candidate {
    let f = match fitted {
        Ok(f) => f,
        Err(why) => {
            let (params, rows, misses) = (Set::new(), Vec::new(), vec![why.clone()]);
            return Candidate { method: Method::Scanline, params, rows, cost: None, clock: None, misses };
        }
    };
    let source = if model.measured(&f.design).is_some() { Source::Measured } else { Source::Modelled };
    let clock = f.rows.first().and_then(|r| Some((r.clock_mhz?, r.clock_source?)));
    Candidate {
        method: Method::Scanline,
        params: Set::from([("K".into(), f.design.k), ("L".into(), f.design.l)]),
        rows: f.rows.clone(),
        cost: Some((cost(&f.design, model), source)),
        clock,
        misses: Vec::new(),
    }
}

/// The vector back end at the default formats, one candidate per lane count built.
pub fn vector(inputs: &[Input], target: &Target, opts: &Options) -> Result<Vec<Candidate>, String> {
    model::raster_top::LANES
        .iter()
        .map(|&lanes| {
            let cost = sweep::area::vector_pipeline(lanes).map(|c| (c, source(lanes == 1)));
            let clock = sweep::clock::vector_pipeline_mhz(lanes);
            at_defaults(inputs, target, opts, Method::Vector, Set::from([("lanes".into(), lanes)]), cost, clock)
        })
        .collect()
}

/// The SE back end at the default formats with the fewest engines that cover the
/// workload's widest screen.
pub fn se(inputs: &[Input], target: &Target, opts: &Options) -> Result<Candidate, String> {
    let width = inputs.iter().map(|i| i.trilist.width).max().unwrap_or(0);
    let Some(engines) = rtl::se_engines_for(width) else {
        return Ok(Candidate {
            method: Method::Se,
            params: Set::new(),
            rows: Vec::new(),
            cost: None,
            clock: None,
            misses: vec![format!(
                "the SE back end is built with {:?} engines of 64 columns: none covers a screen {width} columns wide",
                rtl::SE_ENGINES
            )],
        });
    };
    let cost = sweep::area::se_pipeline(width);
    let clock = Some((sweep::clock::SE_PIPELINE_MHZ, source(engines == 1)));
    at_defaults(inputs, target, opts, Method::Se, Set::new(), cost, clock)
        .map(|c| Candidate { params: Set::from([("engines".into(), engines)]), ..c })
}

fn source(measured: bool) -> Source {
    if measured {
        Source::Measured
    } else {
        Source::Modelled
    }
}

/// `method` at the default formats with parameters `params`, run on the workload: it fails
/// where a scene misses the target, where the method cannot draw a scene, and where a
/// scene needs a size class above the one its RTL is built at (10).
fn at_defaults(
    inputs: &[Input],
    target: &Target,
    opts: &Options,
    method: Method,
    params: Set,
    cost: Option<(Cost, Source)>,
    clock: Option<(f64, Source)>,
) -> Result<Candidate, String> {
    let point = Point { method, name: "fit".into(), kind: "default".into(), set: params.clone(), class: None };
    let swept = run(inputs, &[point], opts, &|| {})?;
    let mut misses = swept.skipped;
    for r in &swept.rows {
        if r.cost.is_none() {
            misses.push(format!(
                "{}: the {} back end is built at size class {} (screens up to 1024 x 1024) only",
                r.scene,
                method.name(),
                fx::RTL_CLASS
            ));
        }
        misses.extend(target.misses(r).into_iter().map(|m| format!("{}: {m}", r.scene)));
    }
    Ok(Candidate { method, params, rows: swept.rows, cost, clock, misses })
}

/// The passing candidate with the least score for `objective`.
pub fn choose(candidates: &[Candidate], objective: Objective) -> Option<&Candidate> {
    candidates.iter().filter_map(|c| Some((c.score(objective)?, c))).min_by(|a, b| a.0.total_cmp(&b.0)).map(|(_, c)| c)
}
