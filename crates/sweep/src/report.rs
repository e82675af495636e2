//! A sweep's report, `report.md`: what was swept, every chart (as SVG, next to the report)
//! and the Pareto fronts of colour error against cycles and against area as tables.

use crate::chart::Chart;
use crate::row::Row;
use std::collections::BTreeSet;
use std::path::Path;

/// The report's file name in a sweep's directory.
pub const FILE: &str = "report.md";

/// The chart whose front the report's table lists.
const FRONT_CHART: &str = "error_vs_cycles";

/// Writes `<dir>/report.md` for `rows` and their `charts` (drawn into `dir` by
/// [`crate::chart::draw`]); the error names a file that cannot be written.
pub fn write(dir: &Path, rows: &[Row], charts: &[Chart]) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    let path = dir.join(FILE);
    std::fs::write(&path, text(rows, charts)).map_err(|e| format!("{}: cannot write: {e}", path.display()))
}

/// The report's Markdown.
fn text(rows: &[Row], charts: &[Chart]) -> String {
    let mut md = String::from("# edgepaint sweep: speed against accuracy\n\n");
    md += &counts(rows);
    for c in charts {
        md += &format!("\n## {}\n\n![{}]({}.svg)\n", c.title, c.title, c.stem);
    }
    if let Some(c) = charts.iter().find(|c| c.stem == FRONT_CHART) {
        md += &front_table(rows, c);
    }
    if let Some(c) = charts.iter().find(|c| c.stem == AREA_CHART) {
        md += &area_table(rows, c);
    }
    md
}

/// The chart of error against area, whose front the report also tabulates with costs.
const AREA_CHART: &str = "error_vs_area";

/// The front of error against area, each point's cost (the first scene's row: the cost is
/// a function of the design, and the scenes share a size class or the first is shown),
/// and what the front saves at the scanline default's error.
fn area_table(rows: &[Row], chart: &Chart) -> String {
    let mut md = String::from("\n## Pareto front: colour error against area\n\n");
    md += "Cost: the area model (`sweep::area`, fitted to Yosys runs), or Yosys itself where the design \
           was synthesized (source). Clock: modelled from the units' routed Fmax at the default.\n\n";
    md += "| method | point | mean RMS colour error (LSB) | GE | ECP5 LUT4 | ECP5 FF | ECP5 DSP | iCE40 LUT4 | cost | clock MHz | formats (vs default) | params |\n";
    md += "|---|---|---:|---:|---:|---:|---:|---:|---|---:|---|---|\n";
    for p in &chart.front {
        let (method, point) = p.label.split_once(' ').unwrap_or((p.label.as_str(), ""));
        let Some(r) = rows.iter().find(|r| r.method == method && r.point == point) else { continue };
        let Some(c) = r.cost else { continue };
        let (formats, params) = design(rows, method, point);
        let source = r.cost_source.map_or("?".into(), |s| format!("{s:?}").to_lowercase());
        md += &format!(
            "| {method} | {point} | {:.4} | {:.0} | {:.0} | {:.0} | {:.0} | {:.0} | {source} | {:.1} | {formats} | {params} |\n",
            p.y,
            c.ge,
            c.ecp5_lut4,
            c.ecp5_ff,
            c.ecp5_dsp,
            c.ice40_lut4,
            r.clock_mhz.unwrap_or(f64::NAN)
        );
    }
    let default = chart.marks.iter().find(|m| m.label.starts_with("scanline default"));
    let cheaper = default.and_then(|d| chart.front.iter().find(|p| p.y <= d.y).map(|p| (d, p)));
    if let Some((d, p)) = cheaper {
        md += &format!(
            "\nAt the scanline default's error ({:.4} LSB RMS, {:.0} ECP5 LUT4s), the cheapest design on the front \
             with no more error is {} at {:.0} LUT4s: {:.0}% less.\n",
            d.y,
            d.x,
            p.label,
            p.x,
            100.0 * (1.0 - p.x / d.x)
        );
    }
    md
}

/// One line per count: design points, scenes, methods.
fn counts(rows: &[Row]) -> String {
    let points: BTreeSet<(&str, &str)> = rows.iter().map(|r| (r.method.as_str(), r.point.as_str())).collect();
    let scenes: BTreeSet<&str> = rows.iter().map(|r| r.scene.as_str()).collect();
    let methods: BTreeSet<&str> = rows.iter().map(|r| r.method.as_str()).collect();
    let list = |s: &BTreeSet<&str>| s.iter().copied().collect::<Vec<_>>().join(", ");
    format!(
        "- Design points: {} ({} rows)\n- Scenes: {} ({})\n- Methods: {} ({})\n",
        points.len(),
        rows.len(),
        scenes.len(),
        list(&scenes),
        methods.len(),
        list(&methods)
    )
}

/// The front of `chart` as a table: one row per point, with its design.
fn front_table(rows: &[Row], chart: &Chart) -> String {
    let mut md = String::from("\n## Pareto front: colour error against cycles\n\n");
    md += "Means over scenes. Formats: those that differ from the method's default design \
           (first scene's).\n\n";
    md += "| method | point | mean cycles | mean RMS colour error (LSB) | formats (vs default) | params |\n";
    md += "|---|---|---:|---:|---|---|\n";
    for p in &chart.front {
        let (method, point) = p.label.split_once(' ').unwrap_or((p.label.as_str(), ""));
        let (formats, params) = design(rows, method, point);
        md += &format!("| {method} | {point} | {:.0} | {:.4} | {formats} | {params} |\n", p.x, p.y);
    }
    md
}

/// A point's formats that differ from its method's default row (of the same scene), and
/// its parameters, as table cells (the first scene's).
fn design(rows: &[Row], method: &str, point: &str) -> (String, String) {
    let Some(r) = rows.iter().find(|r| r.method == method && r.point == point) else {
        return ("?".into(), "?".into());
    };
    let default = rows.iter().find(|d| d.method == method && d.scene == r.scene && d.kind == "default");
    let differ: Vec<String> = r
        .formats
        .iter()
        .filter(|(q, f)| default.is_some_and(|d| d.formats.get(*q) != Some(f)))
        .map(|(q, f)| format!("{q} {f}"))
        .collect();
    let formats = match (default, differ.is_empty()) {
        (None, _) => "(no default row)".into(),
        (Some(_), true) => "(as default)".into(),
        (Some(_), false) => differ.join("; "),
    };
    let params: Vec<String> = r.params.iter().map(|(k, v)| format!("{k}={v}")).collect();
    (formats, params.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::tests::rows;

    #[test]
    fn the_report_embeds_every_chart_and_tabulates_the_front() {
        let rows = rows();
        let charts = crate::chart::charts(&rows);
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path();
        write(dir, &rows, &charts).unwrap();
        let md = std::fs::read_to_string(dir.join(FILE)).unwrap();
        for stem in ["error_vs_cycles", "error_vs_frame_time", "error_vs_area", "sensitivity_xy_frac"] {
            assert!(md.contains(&format!("({stem}.svg)")), "{stem} missing:\n{md}");
        }
        assert!(md.contains("- Design points: 8 (16 rows)\n- Scenes: 2 (a, b)\n- Methods: 2 (scanline, vector)\n"));
        let table: Vec<&str> =
            md.lines().filter(|l| l.starts_with("| scanline") || l.starts_with("| vector")).collect();
        let area_front = charts.iter().find(|c| c.stem == AREA_CHART).unwrap().front.len();
        assert_eq!(table.len(), charts[0].front.len() + area_front);
        assert_eq!(table[0], "| vector | default | 600 | 4.0000 | (as default) | lanes=4 |");
        assert_eq!(table[1], "| scanline | default | 2000 | 2.0000 | (as default) | K=7, L=5 |");
        // Only the scanline default is a design with a cost: the area front is it alone.
        assert_eq!(area_front, 1);
        assert!(table[2].starts_with("| scanline | default | 2.0000 | 0 | 20000 |"), "{}", table[2]);
        assert!(
            md.contains("cheapest design on the front with no more error is scanline default at 20000 LUT4s: 0% less")
        );
    }
}
