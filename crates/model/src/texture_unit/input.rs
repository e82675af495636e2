//! The texture unit's inputs from a screen-space triangle in f64: the planes of s·q, t·q
//! and q = w_min / w over the screen (q is 1/w scaled so that the triangle's nearest vertex
//! has 1), evaluated at pixel centres and quantized to the unit's formats. What triangle
//! setup and the interpolators will hand the unit; today the models' tests and the
//! accuracy measurements use it to drive the unit alone.

use super::{TexGrad, TexIn};
use fx::{Fmt, TexFormats};

/// One attribute's plane: a(x, y) = a0 + a_x (x - x0) + a_y (y - y0).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Plane {
    a0: f64,
    grad: [f64; 2],
}

/// The planes of s·q, t·q and q over a triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexPlanes {
    origin: [f64; 2],
    sq: Plane,
    tq: Plane,
    q: Plane,
}

impl TexPlanes {
    /// The planes through vertices at screen positions `xy` with texture coordinates `st`
    /// and 1/w `inv_w` (all 1 for screen-linear coordinates); `None` for a triangle of zero
    /// area or a non-positive or non-finite 1/w.
    pub fn new(xy: [[f64; 2]; 3], st: [[f64; 2]; 3], inv_w: [f64; 3]) -> Option<TexPlanes> {
        let max = inv_w.iter().copied().fold(0.0, f64::max);
        if !inv_w.iter().all(|w| w.is_finite() && *w > 0.0) {
            return None;
        }
        let q = inv_w.map(|w| w / max);
        let e = [[xy[1][0] - xy[0][0], xy[1][1] - xy[0][1]], [xy[2][0] - xy[0][0], xy[2][1] - xy[0][1]]];
        let det = e[0][0] * e[1][1] - e[1][0] * e[0][1];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let plane = |a: [f64; 3]| {
            let (d1, d2) = (a[1] - a[0], a[2] - a[0]);
            Plane { a0: a[0], grad: [(d1 * e[1][1] - d2 * e[0][1]) / det, (d2 * e[0][0] - d1 * e[1][0]) / det] }
        };
        Some(TexPlanes {
            origin: xy[0],
            sq: plane(std::array::from_fn(|k| st[k][0] * q[k])),
            tq: plane(std::array::from_fn(|k| st[k][1] * q[k])),
            q: plane(q),
        })
    }

    /// The triangle's gradients in the unit's formats (saturated where they do not fit).
    pub fn grad(&self, f: &TexFormats) -> TexGrad {
        TexGrad {
            dsq: self.sq.grad.map(|g| quantize(f.dst, g)),
            dtq: self.tq.grad.map(|g| quantize(f.dst, g)),
            dq: self.q.grad.map(|g| quantize(f.dq, g)),
        }
    }

    /// The inputs at point (x, y) (a pixel centre is (px + 1/2, py + 1/2)).
    pub fn at(&self, f: &TexFormats, x: f64, y: f64) -> TexIn {
        let (dx, dy) = (x - self.origin[0], y - self.origin[1]);
        let v = |p: &Plane| p.a0 + p.grad[0] * dx + p.grad[1] * dy;
        TexIn { sq: quantize(f.st, v(&self.sq)), tq: quantize(f.st, v(&self.tq)), q: quantize(f.q, v(&self.q)) }
    }
}

/// `v` in format `fmt`, rounded to nearest, saturated to its range (NaN as 0).
fn quantize(fmt: Fmt, v: f64) -> i64 {
    let scaled = (v * (fmt.frac as f64).exp2()).round();
    let scaled = if scaled.is_nan() { 0.0 } else { scaled };
    scaled.clamp(fmt.min_raw() as f64, fmt.max_raw() as f64) as i64
}
