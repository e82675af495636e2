//! Float measurements of a screen-space triangle at a point, for test oracles
//! and the accuracy harness (never for rasterizing).

use crate::Triangle;

/// Distance in pixels from (x, y) to the nearest point of the triangle's edges.
pub fn edge_distance(t: &Triangle, x: f64, y: f64) -> f64 {
    (0..3)
        .map(|k| {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let u = (((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
            ((a.x + u * dx - x).powi(2) + (a.y + u * dy - y).powi(2)).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

/// Whether (x, y) lies in the closed triangle, whatever its winding.
pub fn inside(t: &Triangle, x: f64, y: f64) -> bool {
    let e = |a: usize, b: usize| (t[b].x - t[a].x) * (y - t[a].y) - (t[b].y - t[a].y) * (x - t[a].x);
    let (e0, e1, e2) = (e(1, 2), e(2, 0), e(0, 1));
    (e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) || (e0 <= 0.0 && e1 <= 0.0 && e2 <= 0.0)
}

/// The triangle's screen-linear depth at (x, y) (the plane through its three
/// vertices, by Cramer's rule), or `None` for a zero-area triangle.
pub fn plane_z(t: &Triangle, x: f64, y: f64) -> Option<f64> {
    let [(x0, y0, z0), (x1, y1, z1), (x2, y2, z2)] = t.map(|v| (v.x, v.y, v.z));
    let det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if det == 0.0 {
        return None;
    }
    let a = ((z1 - z0) * (y2 - y0) - (z2 - z0) * (y1 - y0)) / det;
    let b = ((x1 - x0) * (z2 - z0) - (x2 - x0) * (z1 - z0)) / det;
    Some(z0 + a * (x - x0) + b * (y - y0))
}
