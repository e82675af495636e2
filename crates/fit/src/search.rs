//! The search: the narrowest formats of the scanline pipeline with which every scene of a
//! workload meets a [`Target`], then setup's parameters for an [`Objective`].
//!
//! A candidate design is a sweep point (`sweep::grid::Point`, kind `joint`: the knobs set,
//! every other quantity following by the defaults' rules, `fx::Formats::follow`) at the
//! workload's size class (its largest screen's), run on every scene through the bit-exact
//! model and the float reference by `sweep::run` (in parallel, cached in the sweep's
//! cache). It *passes* when the RTL can be built at it (`rtl::config::check`) and every
//! scene meets every term of the target.
//!
//! Fraction bits are fitted one knob at a time by bisection between a floor and the
//! knob's passing value: first the quantities the vertices carry (`xy`, `z`, `color`,
//! `ooa`), their accumulators following, then the internal ones (`ooa_d`, `z_acc`, `c_acc`),
//! which start where the rules put them. Rounds repeat until none moves a knob. Then each
//! knob one bit narrower is run again: it must fail (the design is minimal knob by knob),
//! and if one passes after all (the error is not monotonic in the bits) the descent goes
//! on from there. The default design is the start; when it misses the target the start is
//! every knob at its ceiling, and a target that misses there is an error.
//!
//! **The size class** is the smallest that holds the workload's largest screen
//! (`fx::smallest_class`: a 320 x 240 workload gets class 9, 512 x 512 counters and
//! addresses; 200 x 150 class 8; never below `fx::SMALLEST_CLASS`, 8, the smallest the
//! RTL's tests prove), not the default formats' class 10.
//!
//! **Integer bits from the workload's ranges** ([`Search::ints`]), once the fraction bits
//! are fitted: every scene is drawn by the model in analysis mode at the fitted formats,
//! which records the smallest and largest value each register quantity was given
//! (`model::ctx::Ranges`), and `z_acc`, `c_acc`, `dc`, `dz` and `ooa_d` get the fewest
//! integer bits that hold them plus `margin` ([`IntFit`]), never more than the defaults'
//! rules give and never fewer than the RTL's rules allow (`rtl::config::violation`): `dz`
//! and `dc` keep the modular minimum (`z_acc.int + s`, `c_acc.int + s`: below it setup's
//! start values, computed in `dz`-wide lanes from the unwrapped gradients, differ from the
//! model's, `rtl::config::violation` says how), `dz` at least as wide as
//! `dc`, and setup's gradient registers are `ooa_d` wide with the accumulators' start values
//! their slices (`ooa_d.int` >= `z.frac + z_acc.int + s` and `color.frac + c_acc.int + s`).
//! So today the ranges move `c_acc` (S9 to S8 when the colours stay in [-256, 256)) and, with
//! it, `dc` and possibly `ooa_d`; `dz`'s and `dc`'s own ranges (a gently shaded workload
//! needs S1 and S4 where the defaults carry S5 and S13) become usable once the RTL is
//! proven below the modular minimum. `z_acc` holds z's guard band [-0.5, 1.5] (S1) and `c_acc` 0..255 (S8 at
//! least, `fx::Formats::check`). The other quantities are fixed by the API and the RTL: `xy`
//! holds the class's guard band, `z` is S1 (its fraction bits the depth buffer), `color`
//! U8, `inv_w` U1, and `ooa` is a reciprocal's mantissa, U1 with a shift (1/area's range
//! goes into the shift, not the format). Fewer integer bits than the defaults' rules give
//! are safe for the workload because nothing wraps on it (the ranges), and beyond it
//! because the models' analysis mode reports every triangle in which a quantity narrower
//! than those rules wrapped (`fx::Formats::narrowed`, `model::render::Dropped::Overflow`).
//! `margin` (`--margin BITS`, default 0) widens each range by 2^margin for inputs near the
//! workload (an animation's other frames); 0 because the fit's guarantee, like its
//! fraction bits, is for the workload as given, and a scene beyond it is reported, not
//! drawn wrong. The pixels at the fitted integer bits are those at the defaults' (nothing
//! that fits is changed), which the search checks by running the design once more.
//!
//! Setup's multipliers `K` and the divider's stages `L` change cycles and area, not pixels:
//! they are chosen last, over K 1 to 7 and L 1 to 8, by the objective (the area model's
//! gate equivalents, the workload's mean cycles or time per frame, or a product of area and
//! one of them).

use crate::target::Target;
use model::ctx::{Ranges, Q};
use std::collections::BTreeMap;
use sweep::area::{Cost, Design, Model};
use sweep::grid::{Method, Point};
use sweep::row::Row;
use sweep::run::{run, Input, Options};

/// A design as the search names it: knobs and parameters with their values (a sweep
/// point's `set`).
pub type Set = BTreeMap<String, u32>;

/// For each knob above its floor, the trial one bit narrower.
pub type Narrower = Vec<(String, Trial)>;

/// What K and L, and the method (`fit::method`), are chosen for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Objective {
    /// Fewest gate equivalents (area model).
    Area,
    /// Fewest cycles per frame, mean over the workload.
    Cycles,
    /// Shortest frame, mean over the workload, at the design's clock (routed where
    /// measured, `sweep::clock` elsewhere).
    Time,
    /// Least gate equivalents x mean cycles.
    AreaCycles,
    /// Least gate equivalents x mean frame time.
    AreaTime,
}

impl Objective {
    /// The objectives by the names `--objective` takes.
    pub const NAMES: [(&'static str, Objective); 5] = [
        ("area", Objective::Area),
        ("cycles", Objective::Cycles),
        ("time", Objective::Time),
        ("area*cycles", Objective::AreaCycles),
        ("area*time", Objective::AreaTime),
    ];

    /// The score of a design of `ge` gate equivalents taking `cycles` per frame and
    /// `frame_us` microseconds (means over the workload): the smaller the better; a tie on
    /// the objective goes to area or, for area, to cycles.
    pub fn score(self, ge: f64, cycles: f64, frame_us: f64) -> f64 {
        match self {
            Objective::Area => ge + cycles * 1e-9,
            Objective::Cycles => cycles + ge * 1e-9,
            Objective::Time => frame_us + ge * 1e-12,
            Objective::AreaCycles => ge * cycles,
            Objective::AreaTime => ge * frame_us,
        }
    }
}

/// The knobs fitted, in the order fitted, with the floor and ceiling of their fraction
/// bits: the floors are the least a format can hold (the RTL's rules, `rtl::config`, refuse
/// what it cannot build above them), the ceilings the sweep's widest.
pub const KNOBS: [(&str, u32, u32); 7] = [
    ("xy.frac", 0, 8),
    ("z.frac", 1, 32),
    ("color.frac", 0, 8),
    ("ooa.frac", 1, 32),
    ("ooa_d.frac", 1, 48),
    ("z_acc.frac", 1, 56),
    ("c_acc.frac", 0, 40),
];

/// Knob `knob`'s fraction bits in `f`.
fn frac(f: &fx::Formats, knob: &str) -> u32 {
    match knob {
        "xy.frac" => f.xy.frac,
        "z.frac" => f.z.frac,
        "color.frac" => f.color.frac,
        "ooa.frac" => f.ooa.frac,
        "ooa_d.frac" => f.ooa_d.frac,
        "z_acc.frac" => f.z_acc.frac,
        _ => f.c_acc.frac,
    }
}

/// A design tried, and how it did.
#[derive(Clone, Debug)]
pub struct Trial {
    pub set: Set,
    /// One row per scene (empty when the RTL cannot be built at the formats).
    pub rows: Vec<Row>,
    /// Why it fails: the RTL's rule it breaks, or `<scene>: <term missed>`; empty when it
    /// passes.
    pub misses: Vec<String>,
}

impl Trial {
    pub fn passes(&self) -> bool {
        self.misses.is_empty()
    }
}

/// The fitted design.
#[derive(Clone, Debug)]
pub struct Fitted {
    /// The knobs and K, L (a sweep point's set).
    pub set: Set,
    pub design: Design,
    /// Its rows, one per scene.
    pub rows: Vec<Row>,
    /// The default design edgepaint ships for the workload's screens (size class 10 up to
    /// 1024 x 1024, its formats, K = 7, L = `model::divider::LATENCY`), and its rows.
    pub default: Design,
    pub default_rows: Vec<Row>,
    /// For each knob above its floor: the trial one bit narrower, which fails.
    pub narrower: Narrower,
    /// Designs evaluated (each a run over the workload; cached ones included).
    pub trials: usize,
    /// The integer bits fitted to the workload's ranges, and the margin they were given.
    pub ints: Vec<IntFit>,
    pub margin: u32,
}

/// One quantity's integer bits fitted to the workload's ranges ([`Search::ints`]).
#[derive(Clone, Debug, PartialEq)]
pub struct IntFit {
    /// The quantity (`fx::Formats` field).
    pub quantity: &'static str,
    /// The smallest and largest value its registers were given over the workload, in its
    /// units (`None`: no triangle reached it).
    pub range: Option<(f64, f64)>,
    /// The fewest integer bits that hold the range.
    pub needed: u32,
    /// The fewest the rules allow, and what the defaults' rules give.
    pub floor: u32,
    pub default: u32,
    /// `needed + margin`, within [floor, default].
    pub fitted: u32,
}

/// The quantities whose integer bits are fitted, in the order fitted (an accumulator
/// before its gradient, the gradients before `ooa_d`: the floors depend on them).
pub const INT_QUANTITIES: [Q; 5] = [Q::ZAcc, Q::CAcc, Q::Dc, Q::Dz, Q::OoaD];

/// The search's state: the workload, the target, how to run.
pub struct Search<'a> {
    pub inputs: &'a [Input],
    pub target: &'a Target,
    pub opts: &'a Options,
    /// The design's size class: the largest screen's.
    pub class: u32,
    pub trials: usize,
}

impl<'a> Search<'a> {
    pub fn new(inputs: &'a [Input], target: &'a Target, opts: &'a Options) -> Search<'a> {
        let class =
            inputs.iter().map(|i| fx::smallest_class(i.trilist.width, i.trilist.height)).max().unwrap_or(fx::RTL_CLASS);
        Search { inputs, target, opts, class, trials: 0 }
    }

    /// The point of `set` at the workload's class.
    fn point(&self, set: &Set) -> Point {
        let name: Vec<String> = set.iter().map(|(k, v)| format!("{k}={v}")).collect();
        Point {
            method: Method::Scanline,
            name: format!("fit {}", name.join(" ")),
            kind: "joint".into(),
            set: set.clone(),
            class: Some(self.class),
        }
    }

    /// The design of `set`: the formats it resolves to at the workload's class, K and L.
    pub fn design(&self, set: &Set) -> Result<Design, String> {
        let side = 1u32 << self.class.min(16);
        let (formats, params) = self.point(set).resolve(side, side)?;
        Ok(Design { class: self.class, formats, k: params["K"], l: params["L"] })
    }

    /// Runs `set` on the workload.
    pub fn trial(&mut self, set: &Set) -> Result<Trial, String> {
        self.trials += 1;
        let design = match self.design(set) {
            Ok(d) => d,
            Err(e) => return Ok(Trial { set: set.clone(), rows: Vec::new(), misses: vec![e] }),
        };
        if let Err(e) = rtl::config::check(design.class, &design.formats) {
            return Ok(Trial { set: set.clone(), rows: Vec::new(), misses: vec![e] });
        }
        let rows = run(self.inputs, &[self.point(set)], self.opts, &|| {})?.rows;
        let misses = rows
            .iter()
            .flat_map(|r| self.target.misses(r).into_iter().map(move |m| format!("{}: {m}", r.scene)))
            .collect();
        Ok(Trial { set: set.clone(), rows, misses })
    }

    /// The smallest value of `knob` in [lo, hi] with which `set` passes, `hi` passing.
    fn bisect(&mut self, set: &mut Set, knob: &str, mut lo: u32, mut hi: u32) -> Result<(), String> {
        while lo < hi {
            let mid = (lo + hi) / 2;
            set.insert(knob.into(), mid);
            if self.trial(set)?.passes() {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        set.insert(knob.into(), hi);
        Ok(())
    }

    /// The fitted formats' knobs (K and L at their defaults): see the module documentation.
    pub fn formats(&mut self) -> Result<(Set, Narrower), String> {
        let mut set = Set::new();
        if !self.trial(&set)?.passes() {
            set = KNOBS.iter().map(|(k, _, hi)| (k.to_string(), *hi)).collect();
            let wide = self.trial(&set)?;
            if !wide.passes() {
                return Err(format!(
                    "the target is not met even with every knob at its ceiling ({}): {}",
                    KNOBS.iter().map(|(k, _, hi)| format!("{k}={hi}")).collect::<Vec<_>>().join(", "),
                    wide.misses.join("; ")
                ));
            }
        }
        loop {
            let before = set.clone();
            for (knob, floor, _) in KNOBS {
                let current = frac(&self.design(&set)?.formats, knob);
                set.insert(knob.into(), current);
                self.bisect(&mut set, knob, floor.min(current), current)?;
            }
            let mut narrower = Vec::new();
            let mut moved = false;
            for (knob, floor, _) in KNOBS {
                let v = set[knob];
                if v <= floor {
                    continue;
                }
                let mut less = set.clone();
                less.insert(knob.into(), v - 1);
                let t = self.trial(&less)?;
                if t.passes() {
                    set = less;
                    moved = true;
                    break;
                }
                narrower.push((knob.to_string(), t));
            }
            if !moved && set == before {
                return Ok((set, narrower));
            }
        }
    }

    /// Every scene of the workload drawn by the model at `formats` in analysis mode: the
    /// values each quantity's registers were given.
    pub fn ranges(&self, formats: &fx::Formats) -> Ranges {
        let mut all = Ranges::default();
        for inp in self.inputs {
            let opts = model::render::Options {
                method: model::render::Method::Scanline,
                cull: if inp.cull_back { model::cull_sort::Cull::Back } else { model::cull_sort::Cull::None },
                analysis: true,
                background: inp.background.map(|c| c.round().clamp(0.0, 255.0) as u8),
            };
            all.merge(&model::render::render(&inp.trilist, formats, &opts, &mut |_| {}).ranges);
        }
        all
    }

    /// The integer bits of `z_acc`, `c_acc`, `dc`, `dz` and `ooa_d` fitted to the ranges
    /// the workload gives at `set`'s formats, plus `margin` (module documentation): `set`
    /// with a `<quantity>.int` knob for each below its default, and the fit of each. An
    /// error if the RTL cannot be built there or the design no longer meets the target (a
    /// bug: what fits is unchanged).
    pub fn ints(&mut self, set: &Set, margin: u32) -> Result<(Set, Vec<IntFit>), String> {
        let f = self.design(set)?.formats;
        let ranges = self.ranges(&f);
        let mut g = f;
        let s = f.xy.frac;
        let mut fits = Vec::new();
        for q in INT_QUANTITIES {
            let floor = match q {
                Q::ZAcc => 1,
                Q::CAcc => 8,
                Q::Dc => g.c_acc.int + s,
                Q::Dz => (g.z_acc.int + s).max((g.dc.bits() - 1).saturating_sub(g.dz.frac)),
                _ => (g.z.frac + g.z_acc.int + s).max(g.color.frac + g.c_acc.int + s),
            };
            let default = q.of(&f).int;
            let needed = ranges.int_bits(q, &f).unwrap_or(0);
            let fitted = needed.saturating_add(margin).max(floor).min(default);
            let range = ranges.get(q).map(|(lo, hi)| {
                let unit = (-(q.of(&f).frac as f64)).exp2();
                (lo as f64 * unit, hi as f64 * unit)
            });
            match q {
                Q::ZAcc => g.z_acc.int = fitted,
                Q::CAcc => g.c_acc.int = fitted,
                Q::Dc => g.dc.int = fitted,
                Q::Dz => g.dz.int = fitted,
                _ => g.ooa_d.int = fitted,
            }
            fits.push(IntFit { quantity: q.name(), range, needed, floor, default, fitted });
        }
        let mut out = set.clone();
        for fit in &fits {
            if fit.fitted < fit.default {
                out.insert(format!("{}.int", fit.quantity), fit.fitted);
            }
        }
        let t = self.trial(&out)?;
        if !t.passes() {
            return Err(format!(
                "the integer bits fitted to the workload's ranges miss the target: {}",
                t.misses.join("; ")
            ));
        }
        Ok((out, fits))
    }

    /// K and L for `objective` at the fitted knobs `set`: the design, its rows.
    pub fn params(&mut self, set: &Set, objective: Objective, model: &Model) -> Result<(Set, Vec<Row>), String> {
        let mut best: Option<(f64, Set, Vec<Row>)> = None;
        for k in 1..=7 {
            for l in 1..=8 {
                let mut s = set.clone();
                s.extend([("K".to_string(), k), ("L".to_string(), l)]);
                let t = self.trial(&s)?;
                if !t.passes() {
                    continue;
                }
                let ge = model.pipeline(&self.design(&s)?).ge;
                let mean = |f: &dyn Fn(&Row) -> f64| t.rows.iter().map(f).sum::<f64>() / t.rows.len().max(1) as f64;
                let frame = mean(&|r| r.frame_us.unwrap_or(f64::INFINITY));
                let score = objective.score(ge, mean(&|r| r.cycles as f64), frame);
                if best.as_ref().is_none_or(|(b, ..)| score < *b) {
                    best = Some((score, s, t.rows));
                }
            }
        }
        best.map(|(_, s, rows)| (s, rows)).ok_or_else(|| "no K and L pass at the fitted formats".to_string())
    }
}

/// Fits the workload: fraction bits, integer bits from its ranges plus `margin`, then K and
/// L; the default design's rows beside.
pub fn fit(
    inputs: &[Input],
    target: &Target,
    objective: Objective,
    margin: u32,
    opts: &Options,
) -> Result<Fitted, String> {
    let model = opts.area.as_ref().unwrap_or_else(|| Model::calibrated());
    let mut s = Search::new(inputs, target, opts);
    let (knobs, narrower) = s.formats()?;
    let (knobs, ints) = s.ints(&knobs, margin)?;
    let (set, rows) = s.params(&knobs, objective, model)?;
    let (default, default_rows) = shipped(inputs, target, opts)?;
    Ok(Fitted {
        design: s.design(&set)?,
        set,
        rows,
        default,
        default_rows,
        narrower,
        trials: s.trials + 1,
        ints,
        margin,
    })
}

/// The default design edgepaint ships for the workload's screens (size class 10 up to
/// 1024 x 1024, its formats, K = 7, L = `model::divider::LATENCY`) and its rows: what a fit
/// is measured against.
pub fn shipped(inputs: &[Input], target: &Target, opts: &Options) -> Result<(Design, Vec<Row>), String> {
    let class = inputs.iter().map(|i| fx::resolution_bits(i.trilist.width, i.trilist.height)).max();
    let mut s = Search { class: class.unwrap_or(fx::RTL_CLASS), ..Search::new(inputs, target, opts) };
    Ok((s.design(&Set::new())?, s.trial(&Set::new())?.rows))
}

/// The modelled cost of `d` (the calibration's measurement where it has one).
pub fn cost(d: &Design, model: &Model) -> Cost {
    model.measured(d).unwrap_or_else(|| model.pipeline(d))
}
