//! One cell of a map: a family's trilists at one axis value, drawn by one method at one
//! formats point and compared with the float reference (`accuracy::compare`,
//! `accuracy::compare_se`), its measures summed over the trilists and judged by the
//! family's criterion ([`Family::failure`]).

use crate::family::Family;
use crate::geometry;
use accuracy::{compare, compare_se, Report, Setup};
use fx::Formats;
use model::cycles::Timing;
use model::render::Method as ModelMethod;
use scene::Trilist;
use serde::{Deserialize, Serialize};
use sweep::grid::Method;

/// A point of number formats: the defaults for each cell's screen, with a formats file's
/// quantities over them (`fx::Formats::with_overrides`, as `render --formats FILE` reads it).
#[derive(Clone, Debug, PartialEq)]
pub struct FormatsPoint {
    /// Its name in the cells and the files: `default`, or the formats file's stem.
    pub name: String,
    /// The file's JSON object; `None` for the defaults.
    pub overrides: Option<serde_json::Value>,
}

impl FormatsPoint {
    /// The default formats of each screen.
    pub fn default_point() -> FormatsPoint {
        FormatsPoint { name: "default".into(), overrides: None }
    }

    /// The formats for a `width` x `height` screen; the error says why they are impossible.
    pub fn resolve(&self, width: u32, height: u32) -> Result<Formats, String> {
        match &self.overrides {
            None => Ok(Formats::for_resolution(width, height)),
            Some(json) => Formats::with_overrides(width, height, json),
        }
    }
}

/// What a cell measured, summed over its trilists (errors: the largest).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Measure {
    /// Pixels the reference / the fixed-point engine covered.
    pub pixels_reference: u64,
    pub pixels_fixed: u64,
    /// Pixels covered by exactly one of the two, and of those how many no documented tie
    /// explains (`accuracy`'s module doc).
    pub coverage_differs: u64,
    pub coverage_unexplained: u64,
    /// Pixels the reference covers and the fixed-point engine does not.
    pub holes: u64,
    /// Depth-test passes beyond the first at a pixel: writes of a triangle over one drawn
    /// before it, which only the shared-edge family counts ([`Family::counts_double_hits`]:
    /// there each triangle is nearer than all before it, so an overlap always writes).
    pub double_hits: Option<u64>,
    /// Pixels both covered but another triangle won (order inversions), and of those how
    /// many no documented tie explains.
    pub inversions: u64,
    pub inversions_unexplained: u64,
    /// Largest colour error (8-bit LSBs) where the same triangle won, against the
    /// perspective-correct reference when the input carries w.
    pub color_max: f64,
    /// Largest depth error (LSBs of the depth buffer) where the same triangle won.
    pub depth_max_lsb: f64,
    /// Triangles the engine could not draw: input out of range, harmful overflow.
    pub problems: u64,
    /// Triangles it dropped as of zero area once snapped (a sliver under the subpixel grid).
    pub degenerate: u64,
}

impl Measure {
    /// The measure of one comparison.
    fn of(r: &Report, double_hits: bool) -> Measure {
        // |F \ R| - |R \ F| = pixels_fixed - pixels_reference, |F \ R| + |R \ F| = differs.
        let holes = (r.coverage_differs + r.pixels_reference - r.pixels_fixed) / 2;
        Measure {
            pixels_reference: r.pixels_reference,
            pixels_fixed: r.pixels_fixed,
            coverage_differs: r.coverage_differs,
            coverage_unexplained: r.coverage_unexplained,
            holes,
            double_hits: double_hits.then(|| r.pixels_written - r.pixels_fixed),
            inversions: r.winner_differs,
            inversions_unexplained: r.winner_unexplained,
            color_max: r.vs_perspective.as_ref().unwrap_or(&r.errors).color_max,
            depth_max_lsb: r.depth_max_lsb,
            problems: r.problems,
            degenerate: r.degenerate,
        }
    }

    /// Pixels the fixed-point engine covers and the reference does not.
    pub fn spills(&self) -> u64 {
        self.coverage_differs - self.holes
    }

    /// `self` and `o` together: counts added, errors the larger.
    fn add(&mut self, o: &Measure) {
        self.pixels_reference += o.pixels_reference;
        self.pixels_fixed += o.pixels_fixed;
        self.coverage_differs += o.coverage_differs;
        self.coverage_unexplained += o.coverage_unexplained;
        self.holes += o.holes;
        self.double_hits = self.double_hits.zip(o.double_hits).map(|(a, b)| a + b).or(o.double_hits);
        self.inversions += o.inversions;
        self.inversions_unexplained += o.inversions_unexplained;
        self.color_max = self.color_max.max(o.color_max);
        self.depth_max_lsb = self.depth_max_lsb.max(o.depth_max_lsb);
        self.problems += o.problems;
        self.degenerate += o.degenerate;
    }
}

/// One cell's record (a line of `cells.json`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cell {
    pub family: Family,
    pub method: Method,
    /// The formats point's name.
    pub formats: String,
    /// The subpixel and depth-buffer bits at that point (of the cell's first screen).
    pub xy_frac: u32,
    pub z_frac: u32,
    /// Its axis values (`y`: two-axis families only).
    pub x: f64,
    pub y: Option<f64>,
    /// The first trilist's screen, and the triangles over all its trilists.
    pub width: u32,
    pub height: u32,
    pub triangles: u64,
    /// What it measured; `None` when skipped.
    pub measure: Option<Measure>,
    /// Why it fails its family's criterion; `None` when it passes or was skipped.
    pub failure: Option<String>,
    /// Why it was not run: the method cannot draw at these formats (the shading engines'
    /// 32-bit words), or the formats are impossible for the cell's screen.
    pub skipped: Option<String>,
}

impl Cell {
    /// Whether it passes; `None` when skipped.
    pub fn passes(&self) -> Option<bool> {
        self.measure.as_ref().map(|_| self.failure.is_none())
    }
}

/// The model's method and timing for a sweep method (as `edgepaint sweep` runs it: the
/// vector method with 4 lanes, perspective-correct).
fn setup(method: Method, formats: Formats) -> Setup {
    let method = match method {
        Method::Vector => ModelMethod::Vector { lanes: 4, perspective: true },
        Method::Scanline | Method::Se => ModelMethod::Scanline,
    };
    Setup { method, formats, cull_back: false, background: [0.0; 3], timing: Timing::default() }
}

/// Draws `list` with `method` at `formats` and compares with the reference; double hits
/// counted when `double_hits` (see [`Measure::double_hits`]). Errs when the method cannot
/// draw at these formats (the shading engines).
pub fn measure(list: &Trilist, method: Method, formats: Formats, double_hits: bool) -> Result<Measure, String> {
    let r = match method {
        Method::Se => compare_se(list, &setup(method, formats))?,
        _ => compare(list, &setup(method, formats)),
    };
    Ok(Measure::of(&r, double_hits))
}

/// Runs the cell at (`x`, `y`) of `family` through `method` at `point`.
pub fn run(family: Family, method: Method, point: &FormatsPoint, x: f64, y: Option<f64>) -> Cell {
    let lists = geometry::cell(family, x, y.unwrap_or(0.0));
    let (width, height) = (lists[0].width, lists[0].height);
    let first = point.resolve(width, height);
    let mut cell = Cell {
        family,
        method,
        formats: point.name.clone(),
        xy_frac: first.as_ref().map_or(0, |f| f.xy.frac),
        z_frac: first.as_ref().map_or(0, |f| f.z.frac),
        x,
        y,
        width,
        height,
        triangles: lists.iter().map(|l| l.triangles.len() as u64).sum(),
        measure: None,
        failure: None,
        skipped: None,
    };
    let double_hits = family.counts_double_hits();
    let mut total = Measure { double_hits: double_hits.then_some(0), ..Measure::default() };
    for list in &lists {
        let measured = point
            .resolve(list.width, list.height)
            .map_err(|e| format!("formats impossible for {}x{}: {e}", list.width, list.height))
            .and_then(|f| measure(list, method, f, double_hits));
        match measured {
            Ok(m) => total.add(&m),
            Err(why) => {
                cell.skipped = Some(why);
                return cell;
            }
        }
    }
    cell.failure = family.failure(&total);
    cell.measure = Some(total);
    cell
}

/// A cell of `family` at (x, y) with nothing measured but its verdict: passing, failing or
/// (`None`) not run, for the tests of the maps and boundaries.
#[cfg(test)]
pub(crate) fn verdict(family: Family, x: f64, y: Option<f64>, passes: Option<bool>) -> Cell {
    Cell {
        family,
        method: Method::Scanline,
        formats: "default".into(),
        xy_frac: 4,
        z_frac: 16,
        x,
        y,
        width: 64,
        height: 64,
        triangles: 2,
        measure: passes.map(|_| Measure::default()),
        failure: (passes == Some(false)).then(|| "fails".into()),
        skipped: passes.is_none().then(|| format!("not at {x}")),
    }
}
