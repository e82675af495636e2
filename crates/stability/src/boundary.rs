//! The failure boundary of a map: along each row, from the easy end of the x axis, the last
//! value that passes and the first that fails ([`Family::x`] runs from easy to hard).

use crate::cell::Cell;
use crate::family::Family;
use std::collections::BTreeMap;

/// Where one row of a map starts failing.
#[derive(Clone, Debug, PartialEq)]
pub struct Boundary {
    /// The row's y value (`None` in a one-axis family).
    pub row: Option<f64>,
    /// The last x value that passes before the first failure (`None`: the first fails).
    pub last_pass: Option<f64>,
    /// The first x value that fails (`None`: none fails).
    pub first_fail: Option<f64>,
    /// Cells beyond the first failure that pass again (a row that is not monotone).
    pub passes_after: usize,
    /// Cells not run, and why (the first reason).
    pub skipped: usize,
    pub skipped_why: Option<String>,
}

/// The boundary of one row: `cells` in the order of the x axis.
pub fn row(row: Option<f64>, cells: &[&Cell]) -> Boundary {
    let mut b = Boundary { row, last_pass: None, first_fail: None, passes_after: 0, skipped: 0, skipped_why: None };
    for c in cells {
        match c.passes() {
            None => {
                b.skipped += 1;
                b.skipped_why = b.skipped_why.take().or_else(|| c.skipped.clone());
            }
            Some(true) if b.first_fail.is_none() => b.last_pass = Some(c.x),
            Some(true) => b.passes_after += 1,
            Some(false) if b.first_fail.is_none() => b.first_fail = Some(c.x),
            Some(false) => {}
        }
    }
    b
}

/// The boundaries of a map's rows, in the y axis' order; `cells` are one (family, method,
/// formats)'s.
pub fn boundaries(family: Family, cells: &[&Cell]) -> Vec<Boundary> {
    let xs = family.x().values;
    let ys: Vec<Option<f64>> = family.y().map_or(vec![None], |a| a.values.into_iter().map(Some).collect());
    ys.into_iter()
        .map(|y| {
            let mut r: Vec<&Cell> = cells.iter().copied().filter(|c| c.y == y).collect();
            r.sort_by_key(|c| xs.iter().position(|&v| v == c.x));
            row(y, &r)
        })
        .collect()
}

/// One row's boundary in words, with the family's x labels (a row not run: `not run`).
fn words(family: Family, b: &Boundary) -> String {
    let x = family.x();
    let text = match (b.last_pass, b.first_fail) {
        (Some(p), None) => format!("passes everywhere (to {})", x.label_of(p)),
        (None, Some(f)) => format!("fails everywhere (from {})", x.label_of(f)),
        (Some(p), Some(f)) => format!("passes at {}, fails from {}", x.label_of(p), x.label_of(f)),
        (None, None) => return "not run".into(),
    };
    let again =
        if b.passes_after > 0 { format!(" ({} cells beyond pass again)", b.passes_after) } else { String::new() };
    let skipped = if b.skipped > 0 { format!(" ({} cells not run)", b.skipped) } else { String::new() };
    format!("{text}{again}{skipped}")
}

/// A map's boundaries in words: one phrase per distinct row outcome, prefixed by the rows
/// it holds for in a two-axis family (`length L (px) 4, 16: passes at 2^-4, fails from
/// 2^-5`), then the first reason a cell was not run, if any (`why not run: ...`).
pub fn describe(family: Family, boundaries: &[Boundary]) -> String {
    let why = boundaries
        .iter()
        .find_map(|b| b.skipped_why.as_deref())
        .map_or(String::new(), |w| format!("; why not run: {w}"));
    let Some(y) = family.y() else {
        let rows: Vec<String> = boundaries.iter().map(|b| words(family, b)).collect();
        return format!("{}{why}", rows.join("; "));
    };
    let mut groups: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut order = Vec::new();
    for b in boundaries {
        let w = words(family, b);
        if !groups.contains_key(&w) {
            order.push(w.clone());
        }
        groups.entry(w).or_default().push(b.row.map_or_else(String::new, |r| y.label_of(r)));
    }
    let text = if order.len() == 1 {
        format!("every {}: {}", y.name, order[0])
    } else {
        order.iter().map(|w| format!("{} {}: {w}", y.name, groups[w].join(", "))).collect::<Vec<_>>().join("; ")
    };
    format!("{text}{why}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cell::verdict as cell;

    #[test]
    fn a_row_fails_where_it_first_fails_from_the_easy_end() {
        let verdicts = [Some(true), None, Some(true), Some(false), Some(true), Some(false)];
        let cells: Vec<Cell> =
            verdicts.iter().enumerate().map(|(i, &v)| cell(Family::Span, i as f64, None, v)).collect();
        let refs: Vec<&Cell> = cells.iter().collect();
        let b = row(None, &refs);
        assert_eq!((b.last_pass, b.first_fail, b.passes_after, b.skipped), (Some(2.0), Some(3.0), 1, 1));
        assert_eq!(b.skipped_why.as_deref(), Some("not at 1"));
        let all_pass = row(None, &refs[..3]);
        assert_eq!((all_pass.last_pass, all_pass.first_fail), (Some(2.0), None));
    }

    #[test]
    fn rows_with_one_outcome_are_described_once() {
        let (x, y) = (Family::SliverH.x().values, Family::SliverH.y().unwrap().values);
        // Every length passes the first four thicknesses (2 to 2^-2) and fails from 2^-3,
        // but the longest, which is not run at all.
        let mut cells = Vec::new();
        for (j, &l) in y.iter().enumerate() {
            for (i, &t) in x.iter().enumerate() {
                let v = if j == y.len() - 1 { None } else { Some(i < 4) };
                cells.push(cell(Family::SliverH, t, Some(l), v));
            }
        }
        let refs: Vec<&Cell> = cells.iter().collect();
        let text = describe(Family::SliverH, &boundaries(Family::SliverH, &refs));
        assert_eq!(
            text,
            "length L (px) 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048: passes at 2^-2, fails from 2^-3; \
             length L (px) 4096: not run; why not run: not at 2"
        );
        let short: Vec<&Cell> = refs.iter().copied().filter(|c| c.y != Some(4096.0)).collect();
        let b = boundaries(Family::SliverH, &short);
        assert_eq!(b.len(), y.len());
        let text = describe(Family::SliverH, &b[..b.len() - 1]);
        assert_eq!(text, "every length L (px): passes at 2^-2, fails from 2^-3");
    }
}
