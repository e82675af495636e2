//! A sweep's results on disk: `results.jsonl` (one [`Row`] per line) and `results.csv`,
//! and merging the results of shards.

use crate::row::Row;
use std::path::Path;

/// The JSON lines file in a sweep's directory.
pub const JSONL: &str = "results.jsonl";
/// The CSV file in a sweep's directory.
pub const CSV: &str = "results.csv";

/// Canonical order: by scene, method, then the point's name (`default` first).
pub fn sort(rows: &mut [Row]) {
    rows.sort_by(|a, b| {
        let key = |r: &Row| (r.scene.clone(), r.method.clone(), r.kind != "default", r.point.clone());
        key(a).cmp(&key(b))
    });
}

/// Writes `rows` into `dir` as [`JSONL`] and [`CSV`].
pub fn write(dir: &Path, rows: &[Row]) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    let jsonl: String = rows.iter().map(|r| serde_json::to_string(r).expect("a row serialises") + "\n").collect();
    let mut formats: Vec<String> = rows.iter().flat_map(|r| r.formats.keys().cloned()).collect();
    let mut params: Vec<String> = rows.iter().flat_map(|r| r.params.keys().cloned()).collect();
    for v in [&mut formats, &mut params] {
        v.sort();
        v.dedup();
    }
    let mut csv = Row::csv_header(&formats, &params) + "\n";
    for r in rows {
        csv += &(r.csv_line(&formats, &params) + "\n");
    }
    for (name, text) in [(JSONL, jsonl), (CSV, csv)] {
        let path = dir.join(name);
        std::fs::write(&path, text).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    }
    Ok(())
}

/// Reads the rows of a sweep's directory ([`JSONL`]); the error names the file and line.
pub fn read(dir: &Path) -> Result<Vec<Row>, String> {
    let path = dir.join(JSONL);
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| {
            serde_json::from_str(l).map_err(|e| format!("{}:{}: not a sweep row: {e}", path.display(), i + 1))
        })
        .collect()
}

/// The rows of several sweeps (shards) as one, in canonical order; a (scene, method,
/// point) found twice with different results is an error.
pub fn merge(dirs: &[&Path]) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for d in dirs {
        rows.extend(read(d)?);
    }
    sort(&mut rows);
    let mut out: Vec<Row> = Vec::with_capacity(rows.len());
    for r in rows {
        match out.last() {
            Some(last) if (&last.scene, &last.method, &last.point) == (&r.scene, &r.method, &r.point) => {
                if *last != r {
                    return Err(format!("{} {} {}: two shards disagree", r.scene, r.method, r.point));
                }
            }
            _ => out.push(r),
        }
    }
    Ok(out)
}
