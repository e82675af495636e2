//! Float trilist vertices to the fixed-point words the rasterizer hardware takes.
//!
//! This is the boundary between the software geometry stage and the hardware
//! (001 Fig. 1: the CPU writes fixed-point vertices into the vertex buffer). It
//! is not a hardware unit. A value that does not fit its format is an error
//! here, in every mode: wrapping a vertex would draw garbage.

use fx::{Fmt, Formats};
use scene::Triangle;
use std::fmt;

/// A vertex as the hardware receives it: raw values in the formats named.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Vtx {
    /// x, y: `xy`.
    pub x: i128,
    pub y: i128,
    /// z: `z`.
    pub z: i128,
    /// R, G, B: `color`.
    pub c: [i128; 3],
    /// w_min / w over the triangle: `inv_w` (1.0 for the nearest vertex; 1.0
    /// everywhere when the input has no w). Used by `vector` only.
    pub iw: i128,
}

/// Why a triangle could not enter the fixed-point pipeline.
#[derive(Clone, Debug, PartialEq)]
pub struct InputError {
    pub vertex: usize,
    pub quantity: &'static str,
    pub value: f64,
    /// The format it did not fit (`None` for w <= 0).
    pub fmt: Option<Fmt>,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.fmt {
            Some(fm) => write!(f, "vertex {}: {} = {} does not fit {fm}", self.vertex, self.quantity, self.value),
            None => write!(
                f,
                "vertex {}: w = {} lies behind the eye; the fixed-point pipelines take screen-space triangles only",
                self.vertex, self.value
            ),
        }
    }
}

/// Converts one trilist triangle to hardware vertices under `f`.
pub fn to_fixed(tri: &Triangle, f: &Formats) -> Result<[Vtx; 3], InputError> {
    let w = tri.map(|v| v.w_or_one());
    if let Some(k) = w.iter().position(|&w| w <= 0.0) {
        return Err(InputError { vertex: k, quantity: "w", value: w[k], fmt: None });
    }
    let w_min = w.iter().copied().fold(f64::INFINITY, f64::min);
    let mut out = [Vtx::default(); 3];
    for (k, v) in tri.iter().enumerate() {
        let get = |q: &'static str, fm: Fmt, x: f64| {
            fm.from_f64(x).ok_or(InputError { vertex: k, quantity: q, value: x, fmt: Some(fm) })
        };
        out[k] = Vtx {
            x: get("x", f.xy, v.x)?,
            y: get("y", f.xy, v.y)?,
            z: get("z", f.z, v.z)?,
            c: [get("r", f.color, v.r)?, get("g", f.color, v.g)?, get("b", f.color, v.b)?],
            iw: get("w_min/w", f.inv_w, w_min / w[k])?,
        };
    }
    Ok(out)
}
