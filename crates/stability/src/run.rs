//! Running the cells of a stability map: every (family, method, formats point, axis
//! value) in parallel with rayon, as `sweep::run` runs design points.

use crate::cell::{self, Cell, FormatsPoint};
use crate::family::Family;
use rayon::prelude::*;
use sweep::grid::Method;

/// One cell to run.
#[derive(Clone, Debug, PartialEq)]
pub struct Task {
    pub family: Family,
    pub method: Method,
    /// Index into the formats points.
    pub point: usize,
    pub x: f64,
    pub y: Option<f64>,
}

/// Every cell of `families` x `methods` x `points` (the points by index), in that order,
/// each family's rows (y) outer and its x values inner.
pub fn tasks(families: &[Family], methods: &[Method], points: usize) -> Vec<Task> {
    let mut out = Vec::new();
    for &family in families {
        let ys: Vec<Option<f64>> = family.y().map_or(vec![None], |a| a.values.into_iter().map(Some).collect());
        for &method in methods {
            for point in 0..points {
                for &y in &ys {
                    for &x in &family.x().values {
                        out.push(Task { family, method, point, x, y });
                    }
                }
            }
        }
    }
    out
}

/// Checks that every formats point is possible on the smallest screen a family uses
/// (64 x 64), so that a malformed or impossible formats file is an error before anything
/// runs; cells on screens a point cannot hold are skipped later, with the reason.
pub fn check_points(points: &[FormatsPoint]) -> Result<(), String> {
    for p in points {
        p.resolve(64, 64).map_err(|e| format!("formats \"{}\": {e}", p.name))?;
    }
    Ok(())
}

/// Runs `tasks` on `jobs` threads (0: one per core), calling `done` after each; the cells
/// come back in the tasks' order.
pub fn run(
    tasks: &[Task],
    points: &[FormatsPoint],
    jobs: usize,
    done: &(dyn Fn() + Sync),
) -> Result<Vec<Cell>, String> {
    check_points(points)?;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(jobs).build().map_err(|e| e.to_string())?;
    Ok(pool.install(|| {
        tasks
            .par_iter()
            .map(|t| {
                let c = cell::run(t.family, t.method, &points[t.point], t.x, t.y);
                done();
                c
            })
            .collect()
    }))
}
