//! A fit's accuracy target, `--target SPEC`: every scene of the workload must meet every
//! term.
//!
//! **Grammar.** `SPEC = TERM ("," TERM)*`, `TERM = MEASURE OP NUMBER | "depth_order=exact"
//! | "coverage=exact"`, `OP = ">=" | "<=" | "="`, spaces allowed around the parts. The
//! measures are a sweep row's (`sweep::row::Row`, against the float reference):
//!
//! | measure | meaning | ops |
//! |---|---|---|
//! | `psnr` | PSNR of the 8-bit image, dB (infinite when identical) | `>=` |
//! | `colour_max_lsb`, `colour_mean_lsb`, `colour_rms_lsb` | colour error, 8-bit LSBs | `<=` |
//! | `colour_over_1` | pixels more than 1 LSB off | `<=`, `=` |
//! | `depth_max_lsb16`, `depth_mean_lsb16` | depth error, LSBs of a 16-bit buffer | `<=` |
//! | `coverage_differs`, `coverage_unexplained` | pixels covered in one render only (all, or no documented tie explains) | `<=`, `=` |
//! | `winner_differs`, `winner_unexplained` | pixels another triangle won (all, unexplained) | `<=`, `=` |
//! | `problems` | triangles not drawn (input out of range, overflow) | `<=`, `=` |
//!
//! `depth_order=exact` is `winner_unexplained=0`, `coverage=exact` is
//! `coverage_unexplained=0`; `colour` may be spelt `color`. Unless the SPEC bounds
//! `problems` itself, `problems=0` is part of every target: a design that drops triangles
//! does not draw the workload.

use sweep::row::Row;

/// A measure a target bounds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Measure {
    Psnr,
    ColourMax,
    ColourMean,
    ColourRms,
    ColourOver1,
    DepthMax16,
    DepthMean16,
    CoverageDiffers,
    CoverageUnexplained,
    WinnerDiffers,
    WinnerUnexplained,
    Problems,
}

/// The measures, by their SPEC names.
const NAMES: [(&str, Measure); 12] = [
    ("psnr", Measure::Psnr),
    ("colour_max_lsb", Measure::ColourMax),
    ("colour_mean_lsb", Measure::ColourMean),
    ("colour_rms_lsb", Measure::ColourRms),
    ("colour_over_1", Measure::ColourOver1),
    ("depth_max_lsb16", Measure::DepthMax16),
    ("depth_mean_lsb16", Measure::DepthMean16),
    ("coverage_differs", Measure::CoverageDiffers),
    ("coverage_unexplained", Measure::CoverageUnexplained),
    ("winner_differs", Measure::WinnerDiffers),
    ("winner_unexplained", Measure::WinnerUnexplained),
    ("problems", Measure::Problems),
];

impl Measure {
    /// Its SPEC name.
    pub fn name(self) -> &'static str {
        NAMES.iter().find(|(_, m)| *m == self).expect("every measure is named").0
    }

    /// Its value in `row`.
    pub fn of(self, r: &Row) -> f64 {
        match self {
            Measure::Psnr => r.psnr_db,
            Measure::ColourMax => r.color_max_lsb,
            Measure::ColourMean => r.color_mean_lsb,
            Measure::ColourRms => r.color_rms_lsb,
            Measure::ColourOver1 => r.color_over_1 as f64,
            Measure::DepthMax16 => r.depth_max_lsb16,
            Measure::DepthMean16 => r.depth_mean_lsb16,
            Measure::CoverageDiffers => r.coverage_differs as f64,
            Measure::CoverageUnexplained => r.coverage_unexplained as f64,
            Measure::WinnerDiffers => r.winner_differs as f64,
            Measure::WinnerUnexplained => r.winner_unexplained as f64,
            Measure::Problems => r.problems as f64,
        }
    }

    /// Whether larger is better (PSNR) rather than smaller (the errors and counts).
    fn larger_is_better(self) -> bool {
        self == Measure::Psnr
    }
}

/// A comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    Ge,
    Le,
    Eq,
}

/// One term: `measure op value`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Term {
    pub measure: Measure,
    pub op: Op,
    pub value: f64,
}

impl Term {
    /// Whether `row` meets it.
    pub fn met(&self, r: &Row) -> bool {
        let v = self.measure.of(r);
        match self.op {
            Op::Ge => v >= self.value,
            Op::Le => v <= self.value,
            Op::Eq => v == self.value,
        }
    }
}

impl std::fmt::Display for Term {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let op = match self.op {
            Op::Ge => ">=",
            Op::Le => "<=",
            Op::Eq => "=",
        };
        write!(f, "{}{op}{}", self.measure.name(), self.value)
    }
}

/// A parsed SPEC: see the module documentation.
#[derive(Clone, Debug, PartialEq)]
pub struct Target {
    pub terms: Vec<Term>,
}

impl Target {
    /// Parses a SPEC; the error names the term and what is wrong with it.
    pub fn parse(spec: &str) -> Result<Target, String> {
        let mut terms = Vec::new();
        for raw in spec.split(',') {
            let t = raw.trim();
            if t.is_empty() {
                return Err(format!("target \"{spec}\": an empty term (two commas, or one at an end)"));
            }
            terms.push(term(t).map_err(|e| format!("target term \"{t}\": {e}"))?);
        }
        if !terms.iter().any(|t| t.measure == Measure::Problems) {
            terms.push(Term { measure: Measure::Problems, op: Op::Eq, value: 0.0 });
        }
        Ok(Target { terms })
    }

    /// The terms `row` does not meet, each with the row's value: empty when it meets all.
    pub fn misses(&self, r: &Row) -> Vec<String> {
        self.terms
            .iter()
            .filter(|t| !t.met(r))
            .map(|t| format!("{} is {} (needs {t})", t.measure.name(), shown(t.measure.of(r))))
            .collect()
    }
}

/// A measure's value for a person: whole numbers as they are, others to 3 decimals.
pub fn shown(v: f64) -> String {
    if v.fract() == 0.0 || !v.is_finite() {
        format!("{v}")
    } else {
        format!("{v:.3}")
    }
}

fn term(t: &str) -> Result<Term, String> {
    let t = t.replace("color", "colour");
    match t.replace(' ', "").as_str() {
        "depth_order=exact" => return Ok(Term { measure: Measure::WinnerUnexplained, op: Op::Eq, value: 0.0 }),
        "coverage=exact" => return Ok(Term { measure: Measure::CoverageUnexplained, op: Op::Eq, value: 0.0 }),
        _ => {}
    }
    let (at, op, len) = [(">=", Op::Ge), ("<=", Op::Le), ("=", Op::Eq)]
        .iter()
        .find_map(|(s, op)| t.find(s).map(|at| (at, *op, s.len())))
        .ok_or("no comparison: write MEASURE>=N, MEASURE<=N or MEASURE=N")?;
    let (name, value) = (t[..at].trim(), t[at + len..].trim());
    if name == "depth_order" || name == "coverage" {
        return Err(format!("{name} takes only \"=exact\""));
    }
    let known: Vec<&str> = NAMES.iter().map(|(n, _)| *n).collect();
    let measure =
        NAMES.iter().find(|(n, _)| *n == name).map(|(_, m)| *m).ok_or_else(|| {
            format!("unknown measure \"{name}\" (measures: {}, depth_order, coverage)", known.join(", "))
        })?;
    let value: f64 = value.parse().map_err(|_| format!("\"{value}\" is not a number"))?;
    if !value.is_finite() || value < 0.0 {
        return Err(format!("{value} is not a finite, non-negative bound"));
    }
    let bound_side = if measure.larger_is_better() { Op::Ge } else { Op::Le };
    if op != bound_side && op != Op::Eq {
        return Err(format!(
            "{name} is {} is better: bound it with {}",
            if measure.larger_is_better() { "larger" } else { "smaller" },
            if measure.larger_is_better() { ">=" } else { "<=" }
        ));
    }
    Ok(Term { measure, op, value })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_readme_example_parses_with_problems_added() {
        let t = Target::parse("psnr>=45, colour_max_lsb<=2,depth_order=exact,coverage_unexplained=0").unwrap();
        let shown: Vec<String> = t.terms.iter().map(|t| t.to_string()).collect();
        assert_eq!(
            shown,
            ["psnr>=45", "colour_max_lsb<=2", "winner_unexplained=0", "coverage_unexplained=0", "problems=0"]
        );
        let t = Target::parse("color_rms_lsb <= 0.5, problems<=3").unwrap();
        assert_eq!(
            t.terms,
            [
                Term { measure: Measure::ColourRms, op: Op::Le, value: 0.5 },
                Term { measure: Measure::Problems, op: Op::Le, value: 3.0 }
            ]
        );
    }

    #[test]
    fn a_bad_spec_names_its_term_and_the_fault() {
        let e = |s: &str| Target::parse(s).unwrap_err();
        assert!(e("psnr>=45,,problems=0").contains("empty term"), "{}", e("psnr>=45,,problems=0"));
        assert!(e("psnr~45").contains("\"psnr~45\": no comparison"));
        assert!(e("sharpness>=3").contains("unknown measure \"sharpness\""));
        assert!(e("psnr>=fast").contains("\"fast\" is not a number"));
        assert!(e("psnr<=45").contains("larger is better: bound it with >="));
        assert!(e("colour_max_lsb>=2").contains("smaller is better"));
        assert!(e("colour_max_lsb<=-1").contains("not a finite, non-negative bound"));
        assert!(e("depth_order=close").contains("depth_order takes only \"=exact\""));
    }

    #[test]
    fn values_are_shown_whole_or_to_three_decimals() {
        assert_eq!(shown(54.534885922130556), "54.535");
        assert_eq!(shown(0.0), "0");
        assert_eq!(shown(12.0), "12");
        assert_eq!(shown(f64::INFINITY), "inf");
    }
}
