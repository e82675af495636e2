//! Heatmaps: one per (family, method, formats point), as PNG and SVG (`plotters`, with the
//! sweep's embedded font, `sweep::chart::font`). A cell is green where it passes its
//! family's criterion, red where it fails, grey where it was not run, and prints the figure
//! the criterion looks at ([`Family::note`]); a thick black line runs between passing and
//! failing neighbours: the failure boundary. A one-axis family is a one-row map.

use crate::cell::Cell;
use crate::family::{Axis, Family};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;
use sweep::grid::Method;

/// The cells of one map.
#[derive(Clone, Debug)]
pub struct Map<'a> {
    pub family: Family,
    pub method: Method,
    pub formats: String,
    pub cells: Vec<&'a Cell>,
}

impl Map<'_> {
    /// The files' name without extension: `<family>_<method>_<formats>`.
    pub fn stem(&self) -> String {
        format!("{}_{}_{}", self.family.name(), self.method.name(), self.formats)
    }

    /// The caption: family, method, formats with their subpixel and depth bits.
    pub fn title(&self) -> String {
        let bits = self.cells.iter().find(|c| c.xy_frac > 0);
        let bits = bits.map_or(String::new(), |c| format!(" ({} subpixel bits, {}-bit depth)", c.xy_frac, c.z_frac));
        format!("{}: {} at {} formats{bits}", self.family.name(), self.method.name(), self.formats)
    }

    /// The cell at (x index, row index), if any.
    fn at(&self, xs: &Axis, rows: &[Option<f64>], i: usize, j: usize) -> Option<&Cell> {
        self.cells.iter().copied().find(|c| c.x == xs.values[i] && c.y == rows[j])
    }
}

/// The maps of `cells`, in the order their first cells come.
pub fn maps(cells: &[Cell]) -> Vec<Map<'_>> {
    let mut out: Vec<Map> = Vec::new();
    for c in cells {
        match out.iter_mut().find(|m| (m.family, m.method, m.formats.as_str()) == (c.family, c.method, &c.formats)) {
            Some(m) => m.cells.push(c),
            None => out.push(Map { family: c.family, method: c.method, formats: c.formats.clone(), cells: vec![c] }),
        }
    }
    out
}

const PASS: RGBColor = RGBColor(134, 205, 134);
const FAIL: RGBColor = RGBColor(235, 120, 108);
const SKIPPED: RGBColor = RGBColor(205, 205, 205);

/// The map's rows: the y axis' values, or one row.
fn rows(family: Family) -> Vec<Option<f64>> {
    family.y().map_or(vec![None], |a| a.values.into_iter().map(Some).collect())
}

/// The drawing's size: 960 px wide, 70 px per row.
fn size(family: Family) -> (u32, u32) {
    (960, 170 + 70 * rows(family).len() as u32)
}

/// Draws `map` as `<dir>/<stem>.png` and `<dir>/<stem>.svg`.
pub fn draw(map: &Map, dir: &Path) -> Result<(), String> {
    sweep::chart::font()?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    let png = dir.join(format!("{}.png", map.stem()));
    plot(&BitMapBackend::new(&png, size(map.family)).into_drawing_area(), map)
        .map_err(|e| format!("{}: {e}", png.display()))?;
    let svg = dir.join(format!("{}.svg", map.stem()));
    plot(&SVGBackend::new(&svg, size(map.family)).into_drawing_area(), map)
        .map_err(|e| format!("{}: {e}", svg.display()))?;
    Ok(())
}

/// Draws `map` on `root`.
fn plot<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, map: &Map) -> Result<(), String> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let (xs, rows) = (map.family.x(), rows(map.family));
    let y_axis = map.family.y();
    let (nx, ny) = (xs.values.len() as i32, rows.len() as i32);
    root.fill(&WHITE).map_err(err)?;
    let mut c = ChartBuilder::on(root)
        .caption(map.title(), ("sans-serif", 18))
        .margin(16)
        .x_label_area_size(56)
        .y_label_area_size(if y_axis.is_some() { 96 } else { 24 })
        .build_cartesian_2d((0..nx - 1).into_segmented(), 0.0..f64::from(ny))
        .map_err(err)?;
    // x: one segment per value, labelled at its centre. y: rows j..j + 1 of a plain axis
    // (a segmented axis of one row has no extent), labelled at j + 1/2, ticks every 1/2.
    let x_label = |v: &SegmentValue<i32>| match v {
        SegmentValue::CenterOf(i) => xs.labels.get(*i as usize).cloned().unwrap_or_default(),
        _ => String::new(),
    };
    let y_labels = y_axis.as_ref().map_or(vec![], |a| a.labels.clone());
    let y_label = |v: &f64| match (v - 0.5).fract() == 0.0 {
        true => y_labels.get((v - 0.5) as usize).cloned().unwrap_or_default(),
        false => String::new(),
    };
    let x_desc =
        format!("{} -> harder   (green passes, red fails, grey not run; cells: {})", xs.name, map.family.note_legend());
    c.configure_mesh()
        .disable_mesh()
        .x_desc(x_desc)
        .y_desc(y_axis.as_ref().map_or("", |a| a.name))
        .x_labels(nx as usize)
        .y_labels(2 * ny as usize + 1)
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .label_style(("sans-serif", 12))
        .axis_desc_style(("sans-serif", 13))
        .draw()
        .map_err(err)?;
    let corner = |i: i32, j: i32| (SegmentValue::Exact(i), f64::from(j));
    let centred = TextStyle::from(("sans-serif", 12).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
    for j in 0..ny {
        for i in 0..nx {
            let cell = map.at(&xs, &rows, i as usize, j as usize);
            let (fill, note) = match cell.and_then(|c| c.measure.as_ref().map(|m| (c, m))) {
                Some((c, m)) => (if c.failure.is_none() { PASS } else { FAIL }, map.family.note(m)),
                None => (SKIPPED, "-".to_string()),
            };
            let mut rect = Rectangle::new([corner(i, j), corner(i + 1, j + 1)], fill.filled());
            rect.set_margin(1, 1, 1, 1);
            c.draw_series([rect]).map_err(err)?;
            c.draw_series([Text::new(note, (SegmentValue::CenterOf(i), f64::from(j) + 0.5), centred.clone())])
                .map_err(err)?;
        }
    }
    let passes = |i: i32, j: i32| map.at(&xs, &rows, i as usize, j as usize).and_then(Cell::passes);
    let differ = |a: Option<bool>, b: Option<bool>| matches!((a, b), (Some(a), Some(b)) if a != b);
    let mut lines = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            if i + 1 < nx && differ(passes(i, j), passes(i + 1, j)) {
                lines.push([corner(i + 1, j), corner(i + 1, j + 1)]);
            }
            if j + 1 < ny && differ(passes(i, j), passes(i, j + 1)) {
                lines.push([corner(i, j + 1), corner(i + 1, j + 1)]);
            }
        }
    }
    c.draw_series(lines.into_iter().map(|l| PathElement::new(l.to_vec(), BLACK.stroke_width(4)))).map_err(err)?;
    root.present().map_err(err)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cell::verdict as cell;

    /// A cell of `family` at (x, y): passing, failing or (None) not run.
    #[test]
    fn a_map_is_drawn_with_a_line_per_boundary_edge() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path();
        let (x, y) = (Family::Depth.x().values, Family::Depth.y().unwrap().values);
        // Row 0 fails from x[2]; row 1 from x[3], and its last cell is not run: boundary
        // edges (x[1] | x[2]) and (x[2] | x[3]) across, and under x[2] between the rows.
        let mut cells = Vec::new();
        for (j, row_fails) in [(0, 2), (1, 3)] {
            for (i, &v) in x.iter().enumerate() {
                let verdict = if j == 1 && i == x.len() - 1 { None } else { Some(i < row_fails) };
                cells.push(cell(Family::Depth, v, Some(y[j]), verdict));
            }
        }
        let all = maps(&cells);
        assert_eq!(all.len(), 1);
        assert_eq!(all[0].stem(), "depth_scanline_default");
        draw(&all[0], dir).unwrap();
        let svg = std::fs::read_to_string(dir.join("depth_scanline_default.svg")).unwrap();
        assert!(svg.contains(&all[0].title()), "the caption");
        assert_eq!(svg.matches("stroke-width=\"4\"").count(), 3, "three boundary edges");
        assert!(svg.contains("near 1") && svg.contains("2^-4"), "the axes' labels");
        assert!(dir.join("depth_scanline_default.png").is_file());
    }
}
