//! A sweep's charts: first as data ([`charts`] builds [`Chart`]s from the rows), then
//! drawn ([`draw`] writes each as PNG and SVG).
//!
//! Every figure is a mean over scenes: the rows of one (method, point) are averaged, a row
//! whose plotted metric is not finite (NaN, infinite) left out. A log axis cannot show 0:
//! a value at or below [`LOG_FLOOR`] is drawn at [`LOG_FLOOR`] (the chart's data keep the
//! true value; the axis label says so).

use crate::row::Row;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;
use std::path::Path;

/// Where a log axis draws values at or below it (a zero error, say).
pub const LOG_FLOOR: f64 = 1e-4;

/// The drawings' size in pixels (PNG; the SVG's view box).
pub const SIZE: (u32, u32) = (960, 640);

/// One point of a chart.
#[derive(Clone, Debug, PartialEq)]
pub struct Pt {
    /// Where it is, in the axes' units (the true value: a log axis floors it only when
    /// drawing).
    pub x: f64,
    pub y: f64,
    /// The point's name: a series' point name (`default`, `xy.frac=4`, `joint-3`), a front
    /// point's `<method> <point>`, a mark's text.
    pub label: String,
}

/// The points of one method.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The method, as the legend names it.
    pub name: String,
    /// Its points: a scatter's in (method, point) order, a sensitivity's sorted by x.
    pub points: Vec<Pt>,
}

/// A chart, as data.
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    /// The file name without its extension.
    pub stem: String,
    /// The caption, and the report's heading and image text.
    pub title: String,
    /// The axes' descriptions.
    pub x_label: String,
    pub y_label: String,
    /// Whether an axis is logarithmic (values at or below [`LOG_FLOOR`] drawn at it).
    pub x_log: bool,
    pub y_log: bool,
    /// One per method, scattered.
    pub series: Vec<Series>,
    /// The Pareto front, drawn as a line, its points labelled (`<method> <point>`).
    pub front: Vec<Pt>,
    /// Points singled out (the default design), drawn as a distinct marker with their label.
    pub marks: Vec<Pt>,
    /// Vertical reference lines: what an API requires of the x axis' quantity (Vulkan 1.0's
    /// minimum sub-texel bits, say), each drawn as a grey line at its `x` with its `label`
    /// near the top (`y` unused).
    pub rules: Vec<Pt>,
}

/// The indices of the points no other point dominates when both x and y are minimised,
/// sorted by x. Of equal points one is kept; a point with a coordinate not finite is never
/// on the front.
pub fn pareto(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> =
        (0..points.len()).filter(|&i| points[i].0.is_finite() && points[i].1.is_finite()).collect();
    order.sort_by(|&a, &b| points[a].partial_cmp(&points[b]).expect("finite").then(a.cmp(&b)));
    let mut best = f64::INFINITY;
    let mut front = Vec::new();
    for i in order {
        if points[i].1 < best {
            best = points[i].1;
            front.push(i);
        }
    }
    front
}

/// Every chart of a sweep's rows: colour error against cycles per frame, against frame
/// time and against area (where some method has a clock and a cost: a pipeline in RTL),
/// and one per sensitivity knob.
pub fn charts(rows: &[Row]) -> Vec<Chart> {
    let mut out = vec![scatter(
        rows,
        "error_vs_cycles",
        "Colour error vs cycles per frame, mean over scenes".into(),
        "mean cycles per frame",
        |r| Some(r.cycles as f64),
    )];
    if rows.iter().any(|r| r.frame_us.is_some()) {
        let title = format!("Colour error vs frame time{}", missing(rows, |r| r.frame_us.is_some()));
        out.push(scatter(
            rows,
            "error_vs_frame_time",
            title,
            "mean frame time (µs), at the routed or modelled clock",
            |r| r.frame_us,
        ));
    }
    if rows.iter().any(|r| r.cost.is_some()) {
        let title = format!("Colour error vs area{}", missing(rows, |r| r.cost.is_some()));
        let x_label = "ECP5 LUT4s, area model (measured where synthesized)";
        out.push(scatter(rows, "error_vs_area", title, x_label, |r| r.cost.map(|c| c.ecp5_lut4)));
    }
    let knobs: BTreeSet<&str> = sensitivity_rows(rows).filter_map(|r| r.knob.as_deref()).collect();
    out.extend(knobs.into_iter().map(|k| sensitivity(rows, k)));
    out
}

/// The rows of (method, point), keyed in that order.
fn groups(rows: &[Row]) -> BTreeMap<(&str, &str), Vec<&Row>> {
    let mut g: BTreeMap<(&str, &str), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        g.entry((r.method.as_str(), r.point.as_str())).or_default().push(r);
    }
    g
}

/// The mean of `(x, y)` over `rows`, leaving out a row whose x or y is missing or not
/// finite; `None` when no row is left.
fn mean(rows: &[&Row], xy: impl Fn(&Row) -> Option<(f64, f64)>) -> Option<(f64, f64)> {
    let kept: Vec<(f64, f64)> =
        rows.iter().filter_map(|r| xy(r)).filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
    let n = kept.len() as f64;
    (!kept.is_empty()).then(|| (kept.iter().map(|p| p.0).sum::<f64>() / n, kept.iter().map(|p| p.1).sum::<f64>() / n))
}

/// RMS colour error (8-bit LSBs, whole image) against `x`, one series per method, the
/// Pareto front over every method's designs one would build ([`is_design`]), each method's
/// default marked. Log x.
fn scatter(rows: &[Row], stem: &str, title: String, x_label: &str, x: fn(&Row) -> Option<f64>) -> Chart {
    let mut series: BTreeMap<&str, Vec<Pt>> = BTreeMap::new();
    let mut marks = Vec::new();
    let mut designs = Vec::new();
    for ((method, point), g) in groups(rows) {
        let Some((mx, my)) = mean(&g, |r| Some((x(r)?, r.color_rms_lsb))) else { continue };
        let p = Pt { x: mx, y: my, label: point.into() };
        if g[0].kind == "default" {
            marks.push(Pt { label: default_label(g[0]), ..p.clone() });
        }
        if is_design(g[0]) {
            designs.push(Pt { label: format!("{method} {point}"), ..p.clone() });
        }
        series.entry(method).or_default().push(p);
    }
    let front = pareto(&designs.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>())
        .into_iter()
        .map(|i| designs[i].clone())
        .collect();
    Chart {
        stem: stem.into(),
        title,
        x_label: format!("{x_label} (log)"),
        y_label: "RMS colour error (8-bit LSBs, whole image, vs the float reference)".into(),
        x_log: true,
        y_log: false,
        series: series.into_iter().map(|(name, points)| Series { name: name.into(), points }).collect(),
        front,
        marks,
        rules: Vec::new(),
    }
}

/// Whether a row is a design one would build, and so a candidate for the Pareto front:
/// the default, a joint point, a parameter's sensitivity point (at the default formats);
/// not a format's sensitivity point, whose other quantities are wide to isolate it.
fn is_design(r: &Row) -> bool {
    r.kind != "sensitivity" || r.knob.as_deref().is_some_and(|k| !k.ends_with(".frac"))
}

/// A default row's mark, naming the paper whose design it is: `scanline default (001 K=7
/// L=25)`, 001's 7 multipliers and 16-bit depth buffer with a divider of one quotient step a
/// stage (001's has 5 stages); `se default
/// (000, 64-pixel engines)` (000's 24-bit z words do not fit the engines' 32-bit words at 4
/// subpixel bits: `skipped.txt`); `vector default (004, <n> lanes)`.
fn default_label(r: &Row) -> String {
    match (r.method.as_str(), r.params.get("K"), r.params.get("L"), r.params.get("lanes")) {
        ("scanline", Some(k), Some(l), _) => format!("scanline default (001 K={k} L={l})"),
        ("se", ..) => "se default (000, 64-pixel engines)".into(),
        ("vector", .., Some(n)) => format!("vector default (004, {n} lanes)"),
        (m, ..) => format!("{m} default"),
    }
}

/// A title's note naming the methods without the figure (`has`): ` (vector, se: not
/// measured in RTL yet, not shown)`, empty when every method has it.
fn missing(rows: &[Row], has: fn(&Row) -> bool) -> String {
    let mut methods: BTreeMap<&str, bool> = BTreeMap::new();
    for r in rows {
        *methods.entry(r.method.as_str()).or_default() |= has(r);
    }
    let without: Vec<&str> = methods.into_iter().filter(|(_, has)| !has).map(|(m, _)| m).collect();
    match without.is_empty() {
        true => String::new(),
        false => format!(" ({}: not measured in RTL yet, not shown)", without.join(", ")),
    }
}

/// The rows of sensitivity points.
fn sensitivity_rows(rows: &[Row]) -> impl Iterator<Item = &Row> {
    rows.iter().filter(|r| r.kind == "sensitivity")
}

/// What a knob's sensitivity chart plots: depth error for the depth knobs, colour error
/// otherwise; the metric and its axis label.
fn knob_metric(knob: &str) -> (fn(&Row) -> f64, &'static str) {
    match knob {
        "z.frac" | "z_acc.frac" => (|r| r.depth_mean_lsb16, "mean depth error (LSBs of a 16-bit depth buffer)"),
        _ => (|r| r.color_rms_lsb, "RMS colour error (8-bit LSBs)"),
    }
}

/// A knob's axis label.
fn knob_label(knob: &str) -> String {
    match knob {
        "K" => "K (setup multipliers)".into(),
        "L" => "L (divider stages)".into(),
        "lanes" => "lanes (vector lanes)".into(),
        _ => format!("{knob} (fraction bits)"),
    }
}

/// One knob's sensitivity: its error against its value, one series per method that has
/// it, each method's default value marked (where the sweep has a point at it). Log y.
fn sensitivity(rows: &[Row], knob: &str) -> Chart {
    let (metric, y_label) = knob_metric(knob);
    let mut by: BTreeMap<&str, BTreeMap<u32, Vec<&Row>>> = BTreeMap::new();
    for r in sensitivity_rows(rows).filter(|r| r.knob.as_deref() == Some(knob)) {
        if let Some(v) = r.value {
            by.entry(&r.method).or_default().entry(v).or_default().push(r);
        }
    }
    let series: Vec<Series> = by
        .into_iter()
        .map(|(method, values)| Series {
            name: method.into(),
            points: values
                .into_iter()
                .filter_map(|(v, g)| {
                    let (x, y) = mean(&g, |r| Some((f64::from(v), metric(r))))?;
                    Some(Pt { x, y, label: format!("{knob}={v}") })
                })
                .collect(),
        })
        .collect();
    let marks = series.iter().flat_map(|s| default_marks(rows, knob, s)).collect();
    Chart {
        stem: format!("sensitivity_{}", knob.replace('.', "_")),
        title: format!("Sensitivity to {knob}, mean over scenes (other quantities wide)"),
        x_label: knob_label(knob),
        y_label: format!("{y_label} (log; 0 drawn at {LOG_FLOOR:e})"),
        x_log: false,
        y_log: true,
        series,
        front: Vec::new(),
        marks,
        rules: Vec::new(),
    }
}

/// The marks of a method's default value of `knob` on its series `s`: one per distinct
/// default over the scenes, where the series has a point at that value.
fn default_marks(rows: &[Row], knob: &str, s: &Series) -> Vec<Pt> {
    let mut values: Vec<u32> =
        rows.iter().filter(|r| r.method == s.name && r.kind == "default").filter_map(|r| knob_value(r, knob)).collect();
    values.sort();
    values.dedup();
    values
        .into_iter()
        .filter_map(|v| s.points.iter().find(|p| p.x == f64::from(v)))
        .map(|p| Pt { label: format!("{} default", s.name), ..p.clone() })
        .collect()
}

/// `knob`'s value in row `r`: a parameter's (`K`, `L`, `lanes`) or a quantity's fraction
/// bits (`<quantity>.frac`, read from its format, `S11.4 [16] half-up`).
fn knob_value(r: &Row, knob: &str) -> Option<u32> {
    match knob.strip_suffix(".frac") {
        Some(q) => r.formats.get(q)?.parse::<fx::Fmt>().ok().map(|f| f.frac),
        None => r.params.get(knob).copied(),
    }
}

/// The series' colours, in order (then again).
const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
];

/// The marks' colour.
const MARK: RGBColor = RGBColor(255, 127, 14);

/// The reference lines' colour.
const RULE: RGBColor = RGBColor(90, 90, 90);

/// The embedded font, registered once as plotters' `sans-serif` (no system font is read);
/// the error if it does not parse. Public for the other charts drawn with it (`stability`).
pub fn font() -> Result<(), String> {
    static REGISTERED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        let bytes = include_bytes!("../fonts/DejaVuSansMono.ttf");
        plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).is_ok()
    });
    ok.then_some(()).ok_or_else(|| "the embedded font DejaVuSansMono.ttf does not parse".into())
}

/// Draws `chart` as `<dir>/<stem>.png` and `<dir>/<stem>.svg` ([`SIZE`]); an error for a
/// chart with no finite point, or a file that cannot be written.
pub fn draw(chart: &Chart, dir: &Path) -> Result<(), String> {
    font()?;
    // Before any file is created: a backend left undrawn still writes its blank image.
    let axes = axes(chart)?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    let png = dir.join(format!("{}.png", chart.stem));
    render(&BitMapBackend::new(&png, SIZE).into_drawing_area(), chart, &axes)
        .map_err(|e| format!("{}: {e}", png.display()))?;
    let svg = dir.join(format!("{}.svg", chart.stem));
    render(&SVGBackend::new(&svg, SIZE).into_drawing_area(), chart, &axes)
        .map_err(|e| format!("{}: {e}", svg.display()))?;
    Ok(())
}

/// A chart's x and y ranges.
type Axes = (Range<f64>, Range<f64>);

/// The ranges that show every point of `chart`; an error when it has no finite point.
fn axes(chart: &Chart) -> Result<Axes, String> {
    let no_points = || format!("chart {}: no point to draw", chart.stem);
    let x = range(all_points(chart).map(|p| p.x), chart.x_log).ok_or_else(no_points)?;
    let y = range(all_points(chart).map(|p| p.y), chart.y_log).ok_or_else(no_points)?;
    Ok((x, y))
}

/// Where a value is drawn on an axis: at least [`LOG_FLOOR`] on a log axis.
fn shown(v: f64, log: bool) -> f64 {
    if log {
        v.max(LOG_FLOOR)
    } else {
        v
    }
}

/// An axis' range over `values` (drawn as [`shown`]), with a margin; `None` when no value
/// is finite.
fn range(values: impl Iterator<Item = f64>, log: bool) -> Option<Range<f64>> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .map(|v| shown(v, log))
        .fold(None, |acc: Option<(f64, f64)>, v| Some(acc.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v)))))?;
    if log {
        return Some(lo / 2.0..hi * 2.0);
    }
    let pad = if hi > lo { (hi - lo) * 0.08 } else { lo.abs().max(1.0) * 0.1 };
    let start = if lo >= 0.0 { (lo - pad).max(0.0) } else { lo - pad };
    Some(start..hi + pad)
}

/// Every point of `chart` (series, front, marks); a rule counts by its x alone (its y is
/// that of the chart's first point, so that it widens no y range).
fn all_points(chart: &Chart) -> impl Iterator<Item = Pt> + '_ {
    let points = || chart.series.iter().flat_map(|s| &s.points).chain(&chart.front).chain(&chart.marks);
    let y = points().map(|p| p.y).find(|y| y.is_finite()).unwrap_or(f64::NAN);
    points().cloned().chain(chart.rules.iter().map(move |r| Pt { y, ..r.clone() }))
}

/// Draws `chart` on `root` over `axes`, linear or log as the chart says.
fn render<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, chart: &Chart, axes: &Axes) -> Result<(), String> {
    let (x, y) = axes.clone();
    let right = |p: &Pt| label_left(p, &axes.0, chart.x_log);
    match (chart.x_log, chart.y_log) {
        (false, false) => plot(root, chart, x, y, &right),
        (true, false) => plot(root, chart, x.log_scale(), y, &right),
        (false, true) => plot(root, chart, x, y.log_scale(), &right),
        (true, true) => plot(root, chart, x.log_scale(), y.log_scale(), &right),
    }
}

/// Whether `p`'s label goes to its left: past 60% of the x axis `x` (log or linear), where
/// a label to the right would run off the plot.
fn label_left(p: &Pt, x: &Range<f64>, log: bool) -> bool {
    let f = |v: f64| if log { v.ln() } else { v };
    let v = shown(p.x, log);
    (f(v) - f(x.start)) > 0.6 * (f(x.end) - f(x.start))
}

/// A tick label: plain for moderate magnitudes (whole from 10,000 to a million), scientific
/// otherwise.
fn tick(v: &f64) -> String {
    let a = v.abs();
    if a == 0.0 || (0.01..10_000.0).contains(&a) {
        format!("{}", (v * 1000.0).round() / 1000.0)
    } else if (10_000.0..1e6).contains(&a) {
        // Whole numbers: 13500, not 1.4e4 (two ticks 1,000 apart would read alike).
        format!("{v:.0}")
    } else {
        format!("{v:.1e}")
    }
}

/// How many x ticks to ask for: one per value on a linear axis of few values (a knob's
/// values are whole numbers), up to 12.
fn x_ticks(chart: &Chart) -> usize {
    if chart.x_log {
        return 10;
    }
    let mut xs: Vec<f64> = all_points(chart).map(|p| p.x).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    xs.len().clamp(2, 12)
}

/// A front point's text: its label, none where a mark sits (the mark's label says it).
fn front_label(chart: &Chart, p: &Pt) -> String {
    let marked = chart.marks.iter().any(|m| (m.x, m.y) == (p.x, p.y));
    if marked {
        String::new()
    } else {
        p.label.clone()
    }
}

/// The title's font size: 22 px, smaller for a title too long for the width.
fn title_size(title: &str) -> f64 {
    // DejaVu Sans Mono advances 0.6 em per character.
    (f64::from(SIZE.0 - 40) / (0.6 * title.chars().count() as f64)).min(22.0)
}

/// Draws `chart` on `root` over axes `x` and `y`, a point's label to its left where `left`
/// says so.
fn plot<DB, X, Y>(
    root: &DrawingArea<DB, Shift>,
    chart: &Chart,
    x: X,
    y: Y,
    left: &dyn Fn(&Pt) -> bool,
) -> Result<(), String>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(err)?;
    let mut c = ChartBuilder::on(root)
        .caption(&chart.title, ("sans-serif", title_size(&chart.title)))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d(x, y)
        .map_err(err)?;
    c.configure_mesh()
        .x_desc(chart.x_label.as_str())
        .y_desc(chart.y_label.as_str())
        .x_labels(x_ticks(chart))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .light_line_style(TRANSPARENT)
        .label_style(("sans-serif", 12))
        .axis_desc_style(("sans-serif", 14))
        .draw()
        .map_err(err)?;
    let at = |p: &Pt| (shown(p.x, chart.x_log), shown(p.y, chart.y_log));
    let label_font = ("sans-serif", 11).into_font();
    // A label beside a point (`dx`, `dy` from it to the right), or as far to its left.
    let label = |text: String, p: &Pt, (dx, dy): (i32, i32)| {
        let style = TextStyle::from(label_font.clone());
        match left(p) {
            true => Text::new(text, (-dx, dy), style.pos(Pos::new(HPos::Right, VPos::Top))),
            false => Text::new(text, (dx, dy), style),
        }
    };
    for (i, s) in chart.series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        c.draw_series(s.points.iter().map(|p| Circle::new(at(p), 3, colour.filled())))
            .map_err(err)?
            .label(&s.name)
            .legend(move |(x, y)| Circle::new((x, y), 4, colour.filled()));
    }
    if !chart.front.is_empty() {
        c.draw_series(LineSeries::new(chart.front.iter().map(at), BLACK.stroke_width(1)))
            .map_err(err)?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new([(x - 8, y), (x + 8, y)], BLACK.stroke_width(1)));
        c.draw_series(chart.front.iter().map(|p| {
            EmptyElement::at(at(p))
                + Circle::new((0, 0), 4, BLACK.stroke_width(1))
                + label(front_label(chart, p), p, (5, 4))
        }))
        .map_err(err)?;
    }
    if !chart.marks.is_empty() {
        c.draw_series(chart.marks.iter().map(|p| {
            EmptyElement::at(at(p))
                + TriangleMarker::new((0, 0), 9, MARK.filled())
                + label(p.label.clone(), p, (8, -16))
        }))
        .map_err(err)?
        .label("default design")
        .legend(|(x, y)| TriangleMarker::new((x, y), 6, MARK.filled()));
    }
    let y_range = c.plotting_area().get_y_range();
    for (k, r) in chart.rules.iter().enumerate() {
        let x = shown(r.x, chart.x_log);
        c.draw_series(LineSeries::new([(x, y_range.start), (x, y_range.end)], RULE.stroke_width(1))).map_err(err)?;
        // Labels stacked down from the top, one line each, so that rules close together stay legible.
        let at = (x, y_range.end);
        let text = Text::new(r.label.clone(), (4, 4 + 13 * k as i32), label_font.clone().color(&RULE));
        c.draw_series(std::iter::once(EmptyElement::at(at) + text)).map_err(err)?;
    }
    c.configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font(("sans-serif", 12))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A synthetic row: `point` is `default` or `xy.frac=<v>` (a sensitivity point, its
    /// other quantities wide); scanline has a clock, vector none.
    fn row(scene: &str, method: &str, point: &str, cycles: u64, color: f64) -> Row {
        let value: Option<u32> = point.strip_prefix("xy.frac=").map(|v| v.parse().unwrap());
        let formats = match value {
            None => [("xy", "S11.4 [16] half-up".to_string()), ("z", "U16.0 [16]".into())],
            Some(v) => [("xy", format!("S11.{v} [{}] half-up", 12 + v)), ("z", "U24.0 [24]".into())],
        };
        let params = match method {
            "scanline" => [("K".to_string(), 7), ("L".into(), 5)].into(),
            _ => [("lanes".to_string(), 4)].into(),
        };
        let clock = (method == "scanline").then_some(18.7);
        let cost = (method == "scanline").then_some(crate::area::Cost { ecp5_lut4: 20_000.0, ..Default::default() });
        Row {
            scene: scene.into(),
            method: method.into(),
            point: point.into(),
            kind: if value.is_some() { "sensitivity" } else { "default" }.into(),
            knob: value.map(|_| "xy.frac".into()),
            value,
            formats: formats.into_iter().map(|(q, f)| (q.to_string(), f)).collect(),
            params,
            psnr_db: 40.0,
            color_rms_lsb: color,
            color_max_lsb: color * 2.0,
            color_mean_lsb: color,
            color_over_1: 0,
            depth_max_lsb: 1.0,
            depth_mean_lsb: 0.5,
            depth_max_lsb16: 1.0,
            depth_mean_lsb16: 0.5,
            coverage_differs: 0,
            coverage_unexplained: 0,
            winner_differs: 0,
            winner_unexplained: 0,
            problems: 0,
            cycles,
            pixels_per_clock: 1.0,
            clock_mhz: clock,
            clock_source: None,
            frame_us: clock.map(|c| cycles as f64 / c),
            cost,
            cost_source: None,
        }
    }

    /// Two methods, each a default and `xy.frac` at 5, 3 and 4, over scenes `a` and `b`.
    /// Means over the scenes, (cycles, colour error): scanline default (2000, 2),
    /// xy.frac=3 (1500, 7), =4 (2000, 2.25), =5 (4000, 0.5); vector default (600, 4),
    /// xy.frac=3 (600, 9: scene b's error is NaN, left out), =4 (700, 3), =5 (800, 1).
    pub(crate) fn rows() -> Vec<Row> {
        let table: [(&str, &str, [u64; 2], [f64; 2]); 8] = [
            ("scanline", "default", [1000, 3000], [1.0, 3.0]),
            ("scanline", "xy.frac=5", [4000, 4000], [0.5, 0.5]),
            ("scanline", "xy.frac=3", [1500, 1500], [6.0, 8.0]),
            ("scanline", "xy.frac=4", [2000, 2000], [2.0, 2.5]),
            ("vector", "default", [500, 700], [4.0, 4.0]),
            ("vector", "xy.frac=5", [800, 800], [1.0, 1.0]),
            ("vector", "xy.frac=3", [600, 900], [9.0, f64::NAN]),
            ("vector", "xy.frac=4", [700, 700], [3.0, 3.0]),
        ];
        let mut rows = Vec::new();
        for (i, scene) in ["a", "b"].into_iter().enumerate() {
            rows.extend(table.iter().map(|(m, p, c, e)| row(scene, m, p, c[i], e[i])));
        }
        rows
    }

    fn find<'a>(charts: &'a [Chart], stem: &str) -> &'a Chart {
        charts.iter().find(|c| c.stem == stem).unwrap_or_else(|| panic!("no chart {stem}"))
    }

    fn xy(points: &[Pt]) -> Vec<(f64, f64)> {
        points.iter().map(|p| (p.x, p.y)).collect()
    }

    #[test]
    fn pareto_keeps_the_non_dominated_sorted_by_x() {
        let points = [
            (1.0, 5.0),
            (2.0, 3.0),
            (3.0, 4.0),
            (2.0, 3.0),
            (4.0, 1.0),
            (5.0, 1.0),
            (0.5, 9.0),
            (3.0, 2.0),
            (f64::NAN, 0.0),
            (2.0, 6.0),
        ];
        assert_eq!(pareto(&points), [6, 0, 1, 7, 4]);
        assert!(pareto(&[]).is_empty());
    }

    #[test]
    fn charts_average_over_scenes_one_series_per_method() {
        let charts = charts(&rows());
        let stems: Vec<&str> = charts.iter().map(|c| c.stem.as_str()).collect();
        assert_eq!(stems, ["error_vs_cycles", "error_vs_frame_time", "error_vs_area", "sensitivity_xy_frac"]);
        let c = find(&charts, "error_vs_cycles");
        assert!(c.x_log && !c.y_log);
        let names: Vec<&str> = c.series.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["scanline", "vector"]);
        let labels: Vec<&str> = c.series[0].points.iter().map(|p| p.label.as_str()).collect();
        assert_eq!(labels, ["default", "xy.frac=3", "xy.frac=4", "xy.frac=5"]);
        assert_eq!(xy(&c.series[0].points), [(2000.0, 2.0), (1500.0, 7.0), (2000.0, 2.25), (4000.0, 0.5)]);
        assert_eq!(xy(&c.series[1].points), [(600.0, 4.0), (600.0, 9.0), (700.0, 3.0), (800.0, 1.0)]);
        let marks: Vec<(&str, f64, f64)> = c.marks.iter().map(|p| (p.label.as_str(), p.x, p.y)).collect();
        assert_eq!(
            marks,
            [("scanline default (001 K=7 L=5)", 2000.0, 2.0), ("vector default (004, 4 lanes)", 600.0, 4.0)]
        );
    }

    #[test]
    fn the_front_is_the_non_dominated_designs_of_every_method() {
        let rows = rows();
        let charts = charts(&rows);
        let c = find(&charts, "error_vs_cycles");
        let labels: Vec<&str> = c.front.iter().map(|p| p.label.as_str()).collect();
        // The xy.frac points are sensitivity points (their other formats wide): shown, but
        // no design one would build, so not on the front though scanline xy.frac=5
        // (4000, 0.5) would be.
        assert_eq!(labels, ["vector default", "scanline default"]);
        assert!(rows.iter().all(|r| is_design(r) == (r.kind == "default")));
        let designs: Vec<&Pt> = c.marks.iter().collect();
        for f in &c.front {
            let dominated = designs.iter().any(|p| p.x <= f.x && p.y <= f.y && (p.x < f.x || p.y < f.y));
            assert!(!dominated, "{} is dominated", f.label);
        }
        assert!(c.front.windows(2).all(|w| w[0].x < w[1].x && w[0].y > w[1].y));
    }

    #[test]
    fn frame_time_and_area_show_only_methods_with_a_pipeline_in_rtl() {
        let charts = charts(&rows());
        for (stem, x) in [("error_vs_frame_time", 2000.0 / 18.7), ("error_vs_area", 20_000.0)] {
            let c = find(&charts, stem);
            assert_eq!(c.series.len(), 1, "{stem}");
            assert_eq!(c.series[0].name, "scanline");
            assert!((c.series[0].points[0].x - x).abs() < 1e-9, "{stem}");
            assert!(c.title.ends_with(" (vector: not measured in RTL yet, not shown)"), "{}", c.title);
        }
        let no_rtl: Vec<Row> = rows().into_iter().filter(|r| r.method == "vector").collect();
        assert!(charts_stems(&no_rtl).iter().all(|s| s != "error_vs_frame_time" && s != "error_vs_area"));
    }

    #[test]
    fn the_defaults_are_marked_with_their_papers() {
        let mut rows = rows();
        for r in rows.iter_mut().filter(|r| r.method == "vector") {
            r.method = "se".into();
        }
        let marks: Vec<String> =
            find(&charts(&rows), "error_vs_cycles").marks.iter().map(|p| p.label.clone()).collect();
        assert_eq!(marks, ["scanline default (001 K=7 L=5)", "se default (000, 64-pixel engines)"]);
    }

    #[test]
    fn labels_past_three_fifths_of_the_x_axis_go_left() {
        let at = |x: f64| Pt { x, y: 1.0, label: String::new() };
        assert!(!label_left(&at(50.0), &(0.0..100.0), false));
        assert!(label_left(&at(70.0), &(0.0..100.0), false));
        // On a log axis from 10 to 10,000, 3/5 of the way is 10^2.8, about 631.
        assert!(!label_left(&at(600.0), &(10.0..10_000.0), true));
        assert!(label_left(&at(700.0), &(10.0..10_000.0), true));
    }

    fn charts_stems(rows: &[Row]) -> Vec<String> {
        charts(rows).into_iter().map(|c| c.stem).collect()
    }

    #[test]
    fn sensitivity_is_sorted_by_value_with_the_default_marked() {
        let charts = charts(&rows());
        let c = find(&charts, "sensitivity_xy_frac");
        assert!(c.front.is_empty() && c.y_log && c.y_label.contains("colour"));
        assert_eq!(xy(&c.series[0].points), [(3.0, 7.0), (4.0, 2.25), (5.0, 0.5)]);
        assert_eq!(xy(&c.series[1].points), [(3.0, 9.0), (4.0, 3.0), (5.0, 1.0)]);
        let marks: Vec<(&str, f64, f64)> = c.marks.iter().map(|p| (p.label.as_str(), p.x, p.y)).collect();
        assert_eq!(marks, [("scanline default", 4.0, 2.25), ("vector default", 4.0, 3.0)]);
        assert!(knob_metric("z_acc.frac").1.contains("depth"));
    }

    #[test]
    fn draw_writes_a_png_and_an_svg() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path();
        for c in charts(&rows()) {
            draw(&c, dir).unwrap();
            let png = image::open(dir.join(format!("{}.png", c.stem))).unwrap();
            assert_eq!((png.width(), png.height()), SIZE);
            let svg = std::fs::read_to_string(dir.join(format!("{}.svg", c.stem))).unwrap();
            assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"), "{}", &svg[..40]);
            assert!(svg.contains(&c.title), "{} lacks its title", c.stem);
        }
        let empty = Chart {
            stem: "empty".into(),
            series: vec![Series { name: "scanline".into(), points: Vec::new() }],
            front: Vec::new(),
            marks: Vec::new(),
            rules: Vec::new(),
            ..charts(&rows())[0].clone()
        };
        assert!(draw(&empty, dir).unwrap_err().contains("no point"));
        assert!(!dir.join("empty.png").exists() && !dir.join("empty.svg").exists());
    }
}
