//! One result of a sweep: a (scene, method, design point) with its accuracy against the
//! float reference, its speed and its cost. Written one per line (JSON lines) and as CSV.

use crate::area::Cost;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Where a figure comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Source {
    /// Measured: synthesized (area) or placed and routed (clock) at this very design.
    Measured,
    /// Modelled: `crate::area` or `crate::clock` at a design not synthesized.
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
    /// The clock in MHz where one is known for the method (`clock_source` says how:
    /// measured at the default design, `crate::clock`'s model elsewhere), and the frame
    /// time at it in microseconds.
    pub clock_mhz: Option<f64>,
    pub clock_source: Option<Source>,
    pub frame_us: Option<f64>,
    /// What the design costs (`crate::area`), for a method whose pipeline exists in RTL;
    /// `cost_source` says whether Yosys measured it (a calibration build) or the model gave it.
    pub cost: Option<Cost>,
    pub cost_source: Option<Source>,
}

/// A CSV column: its name and how a row prints it.
type Column = (&'static str, fn(&Row) -> String);

/// The CSV's columns after the design's.
const MEASURES: &[Column] = &[
    ("psnr_db", |r| r.psnr_db.to_string()),
    ("color_rms_lsb", |r| r.color_rms_lsb.to_string()),
    ("color_max_lsb", |r| r.color_max_lsb.to_string()),
    ("color_mean_lsb", |r| r.color_mean_lsb.to_string()),
    ("color_over_1", |r| r.color_over_1.to_string()),
    ("depth_max_lsb", |r| r.depth_max_lsb.to_string()),
    ("depth_mean_lsb", |r| r.depth_mean_lsb.to_string()),
    ("depth_max_lsb16", |r| r.depth_max_lsb16.to_string()),
    ("depth_mean_lsb16", |r| r.depth_mean_lsb16.to_string()),
    ("coverage_differs", |r| r.coverage_differs.to_string()),
    ("coverage_unexplained", |r| r.coverage_unexplained.to_string()),
    ("winner_differs", |r| r.winner_differs.to_string()),
    ("winner_unexplained", |r| r.winner_unexplained.to_string()),
    ("problems", |r| r.problems.to_string()),
    ("cycles", |r| r.cycles.to_string()),
    ("pixels_per_clock", |r| r.pixels_per_clock.to_string()),
    ("clock_mhz", |r| r.clock_mhz.map_or(String::new(), |c| c.to_string())),
    ("clock_source", |r| r.clock_source.map_or(String::new(), |s| format!("{s:?}").to_lowercase())),
    ("frame_us", |r| r.frame_us.map_or(String::new(), |t| t.to_string())),
    ("ge", |r| r.cost.map_or(String::new(), |c| format!("{:.0}", c.ge))),
    ("ecp5_lut4", |r| r.cost.map_or(String::new(), |c| format!("{:.0}", c.ecp5_lut4))),
    ("ecp5_ff", |r| r.cost.map_or(String::new(), |c| format!("{:.0}", c.ecp5_ff))),
    ("ecp5_dsp", |r| r.cost.map_or(String::new(), |c| format!("{:.0}", c.ecp5_dsp))),
    ("ice40_lut4", |r| r.cost.map_or(String::new(), |c| format!("{:.0}", c.ice40_lut4))),
    ("cost_source", |r| r.cost_source.map_or(String::new(), |s| format!("{s:?}").to_lowercase())),
];

impl Row {
    /// The columns of the CSV, in order: the point, its formats and parameters (as
    /// `format.<quantity>` and `param.<name>`), then every measure.
    pub fn csv_header(formats: &[String], params: &[String]) -> String {
        let mut cols: Vec<String> = ["scene", "method", "point", "kind", "knob", "value"].map(String::from).to_vec();
        cols.extend(formats.iter().map(|f| format!("format.{f}")));
        cols.extend(params.iter().map(|p| format!("param.{p}")));
        cols.extend(MEASURES.iter().map(|(name, _)| name.to_string()));
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
        cells.extend(MEASURES.iter().map(|(_, cell)| cell(self)));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every line has the header's columns, a cell with a comma or space quoted, and each
    /// measure lands under its own name.
    #[test]
    fn csv_lines_match_the_header() {
        let row = Row {
            scene: "a, b".into(),
            method: "scanline".into(),
            point: "default".into(),
            kind: "default".into(),
            knob: None,
            value: None,
            formats: [("xy".to_string(), "S11.4 [16] half-up".to_string())].into(),
            params: [("K".to_string(), 7)].into(),
            psnr_db: 40.5,
            color_rms_lsb: 0.9,
            color_max_lsb: 2.0,
            color_mean_lsb: 0.3,
            color_over_1: 4,
            depth_max_lsb: 5.0,
            depth_mean_lsb: 1.5,
            depth_max_lsb16: 5.0,
            depth_mean_lsb16: 1.5,
            coverage_differs: 6,
            coverage_unexplained: 0,
            winner_differs: 7,
            winner_unexplained: 1,
            problems: 0,
            cycles: 1234,
            pixels_per_clock: 0.5,
            clock_mhz: Some(18.7),
            clock_source: Some(Source::Measured),
            frame_us: Some(66.0),
            cost: Some(Cost { ge: 1e5, ecp5_lut4: 2e4, ecp5_ff: 9e3, ecp5_dsp: 14.0, ice40_lut4: 3e4 }),
            cost_source: Some(Source::Modelled),
        };
        let (formats, params) = (vec!["xy".to_string()], vec!["K".to_string()]);
        let header: Vec<String> = Row::csv_header(&formats, &params).split(',').map(String::from).collect();
        let line = row.csv_line(&formats, &params);
        assert!(line.starts_with("\"a, b\",scanline,default,default,,,\"S11.4 [16] half-up\",7,40.5,0.9,"), "{line}");
        // Unquoted, the line has the header's cells.
        let unquoted = line.replace("\"a, b\"", "ab").replace("\"S11.4 [16] half-up\"", "xy");
        let cells: Vec<&str> = unquoted.split(',').collect();
        assert_eq!(cells.len(), header.len());
        let at = |name: &str| cells[header.iter().position(|h| h == name).unwrap()];
        assert_eq!((at("cycles"), at("clock_source"), at("winner_unexplained")), ("1234", "measured", "1"));
        assert_eq!((at("ecp5_lut4"), at("ecp5_dsp"), at("cost_source")), ("20000", "14", "modelled"));
    }
}
