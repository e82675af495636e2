//! The files of a stability run: `cells.json` (every cell) and `report.md` (per family what
//! it draws, its criterion, the table "where each method fails" and its maps).

use crate::boundary::{boundaries, describe};
use crate::cell::Cell;
use crate::family::Family;
use crate::map::Map;
use std::fmt::Write as _;
use std::path::Path;
use sweep::grid::Method;

/// How the run was made, for the report's head.
pub struct Run {
    /// The command line.
    pub command: String,
    pub seconds: f64,
}

/// One map's boundary in words (the report's table row).
pub fn where_it_fails(map: &Map) -> String {
    describe(map.family, &boundaries(map.family, &map.cells))
}

fn write(path: &Path, what: &str, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: cannot write {what}: {e}", path.display()))
}

/// Writes `cells.json`, one cell per line.
pub fn write_cells(dir: &Path, cells: &[Cell]) -> Result<(), String> {
    let lines: Vec<String> = cells.iter().map(|c| serde_json::to_string(c).expect("a cell serialises")).collect();
    write(&dir.join("cells.json"), "the cells", &format!("[\n{}\n]\n", lines.join(",\n")))
}

/// Reads a `cells.json`.
pub fn read_cells(path: &Path) -> Result<Vec<Cell>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: not a cells file: {e}", path.display()))
}

/// The table of every family against every method at the default formats, when they ran.
fn summary(s: &mut String, maps: &[Map]) {
    let defaults: Vec<&Map> = maps.iter().filter(|m| m.formats == "default").collect();
    let mut methods: Vec<Method> = defaults.iter().map(|m| m.method).collect();
    methods.sort();
    methods.dedup();
    if methods.is_empty() {
        return;
    }
    let names: Vec<&str> = methods.iter().map(|m| m.name()).collect();
    let _ = writeln!(
        s,
        "## At the default formats\n\n| family | {} |\n|---|{}",
        names.join(" | "),
        "---|".repeat(names.len())
    );
    for family in Family::ALL.into_iter().filter(|f| defaults.iter().any(|m| m.family == *f)) {
        let row: Vec<String> = methods
            .iter()
            .map(|&method| {
                defaults
                    .iter()
                    .find(|m| (m.family, m.method) == (family, method))
                    .map_or("-".into(), |m| where_it_fails(m))
            })
            .collect();
        let _ = writeln!(s, "| {} | {} |", family.name(), row.join(" | "));
    }
    s.push('\n');
}

/// Writes `report.md` over `maps` (whose images are `<stem>.svg` beside it).
pub fn write_report(dir: &Path, maps: &[Map], run: &Run) -> Result<(), String> {
    let mut s = String::new();
    let cells: usize = maps.iter().map(|m| m.cells.len()).sum();
    let _ = writeln!(s, "# Where each method fails: the stability map\n");
    let _ = writeln!(
        s,
        "`{}`: {cells} cells in {:.1} s. Every cell draws a family's triangles with a method at a formats \
         point and compares the image with the float reference (`accuracy`); its verdict follows the \
         family's criterion below (and every family fails a cell with a triangle not drawn). Axes run \
         from easy to hard; a map's black line is the boundary between passing and failing cells.\n",
        run.command, run.seconds
    );
    summary(&mut s, maps);
    for family in Family::ALL {
        let mine: Vec<&Map> = maps.iter().filter(|m| m.family == family).collect();
        if mine.is_empty() {
            continue;
        }
        let _ = writeln!(s, "## {}\n\n{}.\n\nPasses when {}.\n", family.name(), family.what(), family.criterion());
        let _ = writeln!(s, "| method | formats | where it fails ({}) |\n|---|---|---|", family.x().name);
        for m in &mine {
            let _ = writeln!(s, "| {} | {} | {} |", m.method.name(), m.formats, where_it_fails(m));
        }
        s.push('\n');
        for m in &mine {
            let _ = writeln!(s, "![{}]({}.svg)\n", m.title(), m.stem());
        }
    }
    write(&dir.join("report.md"), "the report", &s)
}
