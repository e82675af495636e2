//! The families of generated triangles (issue 15, item 1): what each sweeps, along which
//! axes, and the documented criterion a cell of it passes by.
//!
//! Every family's x axis runs from the easy end to the hard end (difficulty grows to the
//! right of a map), so that the failure boundary of a row is where it first fails
//! ([`crate::boundary`]). The geometry of each family is in [`crate::geometry`].

use crate::cell::Measure;
use serde::{Deserialize, Serialize};

/// A family of generated triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Family {
    /// Needles of thickness t and length L, horizontal, their axis along a row of pixel centres.
    SliverH,
    /// The same, vertical, along a column of pixel centres.
    SliverV,
    /// The same at 45 degrees, along a diagonal of pixel centres.
    SliverD,
    /// Triangles of a given area, each over a pixel centre at a random subpixel offset.
    Tiny,
    /// One triangle whose longest span is L pixels, steep colour and depth gradients across it.
    Span,
    /// Triangles with vertices d pixels beyond the left and the top edge.
    Offscreen,
    /// Two overlapping triangles of constant depth, the farther drawn first, dz apart.
    Depth,
    /// A triangle whose vertices' w differ by a ratio.
    Perspective,
    /// Thin and small triangles reaching the far corners of a square screen of a size.
    Screen,
    /// Random fans and grids sharing edges at arbitrary subpixel positions: an invariant.
    Shared,
}

/// An axis of a family's map: its values in order of difficulty, and their labels.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// What it measures, with its unit.
    pub name: &'static str,
    pub values: Vec<f64>,
    pub labels: Vec<String>,
}

impl Axis {
    /// `2^from`, `2^(from + step)`, ... up to `2^to` (`step` negative for a falling axis).
    fn pow2(name: &'static str, from: i32, to: i32, step: i32) -> Axis {
        let n = (to - from) / step + 1;
        let values: Vec<f64> = (0..n).map(|k| f64::from(from + k * step).exp2()).collect();
        Axis { name, labels: values.iter().map(|v| label(*v)).collect(), values }
    }

    /// Named rows (values 0, 1, ...).
    fn named(name: &'static str, labels: &[&str]) -> Axis {
        Axis {
            name,
            values: (0..labels.len()).map(|k| k as f64).collect(),
            labels: labels.iter().map(|s| s.to_string()).collect(),
        }
    }

    /// The label of `v`, one of the axis' values.
    pub fn label_of(&self, v: f64) -> String {
        self.values.iter().position(|&a| a == v).map_or_else(|| label(v), |i| self.labels[i].clone())
    }
}

/// A value's label: a power of two below 1 or above 2^12 as `2^k`, a whole number as it is.
pub fn label(v: f64) -> String {
    let k = v.log2();
    if v > 0.0 && k == k.round() && !(0.0..=12.0).contains(&k) {
        format!("2^{k}")
    } else if v == v.round() {
        format!("{v}")
    } else {
        format!("{v:.3}")
    }
}

/// Whether a colour error (8-bit LSBs, against the unrounded reference) is acceptable: the
/// output's own rounding is half of it.
pub const COLOR_TOLERANCE: f64 = 1.0;
/// The same for depth, in LSBs of the depth buffer.
pub const DEPTH_TOLERANCE: f64 = 1.0;

impl Family {
    pub const ALL: [Family; 10] = [
        Family::SliverH,
        Family::SliverV,
        Family::SliverD,
        Family::Tiny,
        Family::Span,
        Family::Offscreen,
        Family::Depth,
        Family::Perspective,
        Family::Screen,
        Family::Shared,
    ];

    /// The name the CLI, the files and the cells use.
    pub fn name(self) -> &'static str {
        match self {
            Family::SliverH => "sliver-h",
            Family::SliverV => "sliver-v",
            Family::SliverD => "sliver-d",
            Family::Tiny => "tiny",
            Family::Span => "span",
            Family::Offscreen => "offscreen",
            Family::Depth => "depth",
            Family::Perspective => "perspective",
            Family::Screen => "screen",
            Family::Shared => "shared",
        }
    }

    /// The family named `name`; the error lists the known names.
    pub fn parse(name: &str) -> Result<Family, String> {
        Family::ALL.into_iter().find(|f| f.name() == name).ok_or_else(|| {
            let known: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
            format!("unknown family \"{name}\" (known: {})", known.join(", "))
        })
    }

    /// What the family draws, for the report.
    pub fn what(self) -> &'static str {
        match self {
            Family::SliverH => "a needle from a base of thickness t to a tip L px to the right, its axis along a row of pixel centres",
            Family::SliverV => "the horizontal needle turned to run down a column of pixel centres",
            Family::SliverD => "the needle at 45 degrees, its axis through a diagonal of pixel centres",
            Family::Tiny => "4 seeds x 64 triangles of the area, each over a pixel centre at a random subpixel offset, random shapes (no angle below 43 degrees)",
            Family::Span => "a triangle L px wide and 8 px tall on whole-pixel vertices: colour across the full 0..255 range and depth across 2^-12..1-2^-12, both along the span and down its 8 rows",
            Family::Offscreen => "two overlapping triangles on a 256 x 256 screen, one with a vertex d px beyond the left edge (X clipping), one with two vertices d px above the top edge (Y clipping)",
            Family::Depth => "two overlapping triangles of constant depth on a 64 x 64 screen, the farther drawn first, dz apart: the nearer at z = 2^-10 (near 0) or the farther at 1 - 2^-10 (near 1)",
            Family::Perspective => "a 120 x 120 px triangle with w = 1, r, sqrt(r) at its vertices and a primary colour at each; error against the perspective-correct reference",
            Family::Screen => "on a square screen of the size: a band 1.4 px wide from corner to corner, a full-width thin triangle along the bottom row and a small triangle with steep gradients in the far corner",
            Family::Shared => "4 seeds of a random fan (ring on the 1/4-px grid, centre anywhere) or grid (border on whole pixels, interior vertices anywhere) of about n triangles on 128 x 128 px, each triangle nearer than all drawn before it",
        }
    }

    /// The x axis, from easy to hard.
    pub fn x(self) -> Axis {
        match self {
            Family::SliverH | Family::SliverV | Family::SliverD => Axis::pow2("thickness t (px)", 1, -8, -1),
            Family::Tiny => Axis::pow2("area (px^2)", 4, -10, -1),
            Family::Span => Axis::pow2("span length L (px)", 4, 12, 1),
            Family::Offscreen => {
                let values: Vec<f64> = std::iter::once(0.0).chain((0..=16).map(|k| f64::from(k).exp2())).collect();
                Axis {
                    name: "distance d beyond the edge (px)",
                    labels: values.iter().map(|v| label(*v)).collect(),
                    values,
                }
            }
            Family::Depth => Axis::pow2("depth separation dz", -4, -26, -1),
            Family::Perspective => Axis::pow2("w ratio r across the triangle", 0, 20, 1),
            Family::Screen => Axis::pow2("screen size (px, square)", 6, 12, 1),
            Family::Shared => Axis::pow2("triangles per mesh n", 3, 9, 1),
        }
    }

    /// The y axis of a two-axis family.
    pub fn y(self) -> Option<Axis> {
        match self {
            Family::SliverH | Family::SliverV | Family::SliverD => Some(Axis::pow2("length L (px)", 2, 12, 1)),
            Family::Depth => Some(Axis::named("depth", &["near 0", "near 1"])),
            Family::Shared => Some(Axis::named("mesh", &["fan", "grid"])),
            _ => None,
        }
    }

    /// Whether the family draws each triangle nearer than every one before it, so that
    /// every fragment passes the depth test and writes beyond one per pixel are double hits.
    pub fn counts_double_hits(self) -> bool {
        self == Family::Shared
    }

    /// The documented criterion a cell passes by (besides drawing every triangle).
    pub fn criterion(self) -> &'static str {
        match self {
            Family::SliverH | Family::SliverV | Family::SliverD => {
                "the fixed-point engine covers at least half of the pixels the reference covers"
            }
            Family::Tiny => "at most 1 in 10 of the pixels the reference covers differs (lost or gained)",
            Family::Span | Family::Screen => {
                "colour within 1 LSB and depth within 1 LSB of the reference where the same triangle won; no coverage or depth-order difference a documented tie does not explain"
            }
            Family::Offscreen => {
                "colour within 1 LSB of the reference where the same triangle won; no coverage or depth-order difference a documented tie does not explain"
            }
            Family::Depth => "no pixel won by the other triangle than in the reference (no order inversion, ties included)",
            Family::Perspective => "colour within 1 LSB of the perspective-correct reference where the same triangle won",
            Family::Shared => "no hole, no double hit, no pixel covered outside the mesh (the invariant)",
        }
    }

    /// Why a cell's measure fails the family's criterion, or `None` when it passes.
    pub fn failure(self, m: &Measure) -> Option<String> {
        if m.problems > 0 {
            return Some(format!("{} triangles not drawn (input out of range or overflow)", m.problems));
        }
        let color = (m.color_max > COLOR_TOLERANCE).then(|| format!("colour off by {:.2} LSB", m.color_max));
        let depth = (m.depth_max_lsb > DEPTH_TOLERANCE).then(|| format!("depth off by {:.2} LSB", m.depth_max_lsb));
        let unexplained = (m.coverage_unexplained + m.inversions_unexplained > 0).then(|| {
            format!(
                "{} coverage and {} depth-order differences no tie explains",
                m.coverage_unexplained, m.inversions_unexplained
            )
        });
        match self {
            Family::SliverH | Family::SliverV | Family::SliverD => (2 * m.holes > m.pixels_reference)
                .then(|| format!("lost {} of the reference's {} pixels", m.holes, m.pixels_reference)),
            Family::Tiny => (10 * m.coverage_differs > m.pixels_reference)
                .then(|| format!("{} of the reference's {} pixels differ", m.coverage_differs, m.pixels_reference)),
            Family::Span | Family::Screen => unexplained.or(color).or(depth),
            Family::Offscreen => unexplained.or(color),
            Family::Depth => (m.inversions > 0).then(|| format!("{} pixels in the wrong depth order", m.inversions)),
            Family::Perspective => color,
            Family::Shared => (m.holes + m.double_hits.unwrap_or(0) + m.spills() > 0).then(|| {
                format!("{} holes, {} double hits, {} pixels outside", m.holes, m.double_hits.unwrap_or(0), m.spills())
            }),
        }
    }

    /// The short text a map prints in a cell: the figure its criterion looks at.
    pub fn note(self, m: &Measure) -> String {
        match self {
            Family::SliverH | Family::SliverV | Family::SliverD => format!("{}/{}", m.pixels_fixed, m.pixels_reference),
            Family::Tiny => format!("{}/{}", m.coverage_differs, m.pixels_reference),
            Family::Depth => m.inversions.to_string(),
            Family::Shared => format!("{}/{}", m.holes + m.spills(), m.double_hits.unwrap_or(0)),
            Family::Span | Family::Screen => format!("{:.2}/{:.2}", m.color_max, m.depth_max_lsb),
            Family::Offscreen | Family::Perspective => format!("{:.2}", m.color_max),
        }
    }

    /// What [`Family::note`] shows, for the map's caption.
    pub fn note_legend(self) -> &'static str {
        match self {
            Family::SliverH | Family::SliverV | Family::SliverD => "pixels fixed/reference",
            Family::Tiny => "pixels differing/reference",
            Family::Depth => "pixels in the wrong order",
            Family::Shared => "holes+outside/double hits",
            Family::Span | Family::Screen => "max colour/depth error (LSB)",
            Family::Offscreen | Family::Perspective => "max colour error (LSB)",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn families_parse_by_name_and_an_unknown_one_lists_them() {
        for f in Family::ALL {
            assert_eq!(Family::parse(f.name()), Ok(f));
        }
        let e = Family::parse("slivers").unwrap_err();
        assert!(e.contains("\"slivers\"") && e.contains("sliver-h, sliver-v, sliver-d, tiny"), "{e}");
    }

    #[test]
    fn labels_write_small_and_huge_powers_of_two_as_powers() {
        let got: Vec<String> = [0.0, 0.0625, 1.0, 4096.0, 8192.0, 1.5].iter().map(|&v| label(v)).collect();
        assert_eq!(got, ["0", "2^-4", "1", "4096", "2^13", "1.500"]);
        let depth = Family::Depth.y().unwrap();
        assert_eq!((depth.label_of(0.0), depth.label_of(1.0)), ("near 0".into(), "near 1".into()));
    }

    #[test]
    fn criteria_judge_the_measure_their_family_is_about() {
        let sliver =
            Measure { pixels_reference: 100, pixels_fixed: 49, coverage_differs: 51, holes: 51, ..Measure::default() };
        assert!(Family::SliverD.failure(&sliver).is_some_and(|w| w.contains("lost 51")));
        assert_eq!(Family::SliverD.failure(&Measure { holes: 50, ..sliver.clone() }), None);
        let colour = Measure { color_max: 1.01, ..Measure::default() };
        assert!(Family::Perspective.failure(&colour).is_some() && Family::Depth.failure(&colour).is_none());
        let shared = Measure { double_hits: Some(1), ..Measure::default() };
        assert!(Family::Shared.failure(&shared).is_some_and(|w| w.contains("1 double hits")));
        let problem = Measure { problems: 2, ..Measure::default() };
        assert!(Family::ALL.iter().all(|f| f.failure(&problem).is_some_and(|w| w.contains("2 triangles not drawn"))));
    }
}
