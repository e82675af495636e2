//! One result of a sweep: a (scene, method, design point) with its accuracy against the
//! float reference, its speed and its cost. Written one per line (JSON lines) and as CSV.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Where a figure comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Source {
    /// Measured: synthesized, placed and routed (README, "Units").
    Measured,
    /// Modelled: not synthesized at this point.
    Modelled,
}

/// A sweep's result at one (scene, method, design point).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// The scene's or trilist's file stem.
    pub scene: String,
    /// `scanline` or `vector`.
    pub method: String,
    /// The point's name: `default`, `<knob>=<value>` (sensitivity), `joint-<i>`.
    pub point: String,
    /// `default`, `sensitivity` or `joint` (see `crate::grid`).
    pub kind: String,
    /// For a sensitivity point, the knob swept (`xy.frac`, `lanes`, ...) and its value.
    pub knob: Option<String>,
    pub value: Option<u32>,
    /// Every quantity's format (`fx::Formats`, house notation).
    pub formats: BTreeMap<String, String>,
    /// The method's parameters: setup multipliers `K` and divider stages `L` (scanline),
    /// `lanes` (vector).
    pub params: BTreeMap<String, u32>,
    /// Accuracy against the float reference (`accuracy::Report`). PSNR is infinite when
    /// the images are identical: `null` in JSON.
    #[serde(with = "infinite_as_null")]
    pub psnr_db: f64,
    /// RMS colour error over the whole image in 8-bit LSBs (255 / 10^(PSNR / 20)): what the
    /// charts plot, as it sees coverage as well as shading.
    pub color_rms_lsb: f64,
    /// Colour max and mean error in 8-bit LSBs where the same triangle won in both.
    pub color_max_lsb: f64,
    pub color_mean_lsb: f64,
    pub color_over_1: u64,
    /// Depth max and mean error in LSBs of the point's depth format, and in LSBs of a
    /// 16-bit depth buffer (1/65536 of the range), which compares across depth formats.
    pub depth_max_lsb: f64,
    pub depth_mean_lsb: f64,
    pub depth_max_lsb16: f64,
    pub depth_mean_lsb16: f64,
    pub coverage_differs: u64,
    pub coverage_unexplained: u64,
    /// Pixels whose winning triangle differs from the reference's (depth-order inversions),
    /// and of those how many no documented tie explains.
    pub winner_differs: u64,
    pub winner_unexplained: u64,
    /// Triangles the fixed-point render could not draw (input out of range, overflow in
    /// analysis mode).
    pub problems: u64,
    /// Speed: cycles per frame (`model::cycles`) and pixels written per clock.
    pub cycles: u64,
    pub pixels_per_clock: f64,
    /// The clock in MHz where one is known for the method (`clock_source` says how), and
    /// the frame time at it in microseconds.
    pub clock_mhz: Option<f64>,
    pub clock_source: Option<Source>,
    pub frame_us: Option<f64>,
}

impl Row {
    /// The columns of the CSV, in order (every field; formats and params as
    /// `format.<quantity>` and `param.<name>`).
    pub fn csv_header(formats: &[String], params: &[String]) -> String {
        let mut cols: Vec<String> = ["scene", "method", "point", "kind", "knob", "value"].map(String::from).to_vec();
        cols.extend(formats.iter().map(|f| format!("format.{f}")));
        cols.extend(params.iter().map(|p| format!("param.{p}")));
        cols.extend(
            [
                "psnr_db",
                "color_rms_lsb",
                "color_max_lsb",
                "color_mean_lsb",
                "color_over_1",
                "depth_max_lsb",
                "depth_mean_lsb",
                "depth_max_lsb16",
                "depth_mean_lsb16",
                "coverage_differs",
                "coverage_unexplained",
                "winner_differs",
                "winner_unexplained",
                "problems",
                "cycles",
                "pixels_per_clock",
                "clock_mhz",
                "clock_source",
                "frame_us",
            ]
            .map(String::from),
        );
        cols.join(",")
    }

    /// This row as a CSV line under [`Row::csv_header`] with the same `formats` and `params`.
    pub fn csv_line(&self, formats: &[String], params: &[String]) -> String {
        let opt = |v: Option<String>| v.unwrap_or_default();
        let mut cells = vec![
            self.scene.clone(),
            self.method.clone(),
            self.point.clone(),
            self.kind.clone(),
            opt(self.knob.clone()),
            opt(self.value.map(|v| v.to_string())),
        ];
        cells.extend(formats.iter().map(|f| opt(self.formats.get(f).cloned())));
        cells.extend(params.iter().map(|p| opt(self.params.get(p).map(|v| v.to_string()))));
        cells.extend([
            self.psnr_db.to_string(),
            self.color_rms_lsb.to_string(),
            self.color_max_lsb.to_string(),
            self.color_mean_lsb.to_string(),
            self.color_over_1.to_string(),
            self.depth_max_lsb.to_string(),
            self.depth_mean_lsb.to_string(),
            self.depth_max_lsb16.to_string(),
            self.depth_mean_lsb16.to_string(),
            self.coverage_differs.to_string(),
            self.coverage_unexplained.to_string(),
            self.winner_differs.to_string(),
            self.winner_unexplained.to_string(),
            self.problems.to_string(),
            self.cycles.to_string(),
            self.pixels_per_clock.to_string(),
            opt(self.clock_mhz.map(|c| c.to_string())),
            opt(self.clock_source.map(|s| format!("{s:?}").to_lowercase())),
            opt(self.frame_us.map(|t| t.to_string())),
        ]);
        cells.iter().map(|c| csv_cell(c)).collect::<Vec<_>>().join(",")
    }
}

/// `c` quoted for CSV when it holds a comma, a quote or a space.
fn csv_cell(c: &str) -> String {
    if c.contains([',', '"', ' ']) {
        format!("\"{}\"", c.replace('"', "\"\""))
    } else {
        c.to_owned()
    }
}

/// An `f64` that may be +infinity, as JSON (which has no infinity) holds it: `null`.
mod infinite_as_null {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        if *v == f64::INFINITY {
            s.serialize_none()
        } else {
            s.serialize_f64(*v)
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::INFINITY))
    }
}
