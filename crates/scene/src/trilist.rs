//! trilist v1: the screen-space triangle list every rasterizer in edgepaint reads.
//!
//! ```json
//! {"width": W, "height": H,
//!  "triangles": [ [[x,y,z,r,g,b],[x,y,z,r,g,b],[x,y,z,r,g,b]], ... ]}
//! ```
//!
//! * `x`, `y`: pixels, origin at the top-left corner, y down. Pixel (i, j) covers
//!   [i, i+1) x [j, j+1) and is sampled at its centre (i + 0.5, j + 0.5).
//! * `z`: depth, 0 nearest, 1 farthest. Values outside [0, 1] are legal: the
//!   rasterizers clip them per pixel.
//! * `r`, `g`, `b`: colour in [0, 255].
//! * an optional 7th value, `w`: the vertex's clip-space w. With it colours are
//!   interpolated perspective-correctly; without it w = 1 (screen-linear).
//!   `w <= 0` is legal (a vertex behind the eye): see `reference` for how it is drawn.
//!
//! Reading validates everything and reports the file, the triangle, the vertex
//! and the value at fault; nothing here panics on bad input.

use serde::Serialize;
use std::fmt;
use std::path::Path;

use crate::error::{Error, Result};

/// Largest width or height edgepaint accepts. The fixed-point formats derive
/// their integer bits from the resolution; 4096 keeps every default format
/// within the widths the RTL is built for.
pub const MAX_RESOLUTION: u32 = 4096;

/// One vertex as the rasterizer sees it (screen space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub r: f64,
    pub g: f64,
    pub b: f64,
    /// Clip-space w when the producer knew it (7th value); `None` means w = 1.
    pub w: Option<f64>,
}

impl Vertex {
    /// A vertex without w (screen-linear interpolation).
    pub const fn new(x: f64, y: f64, z: f64, rgb: [f64; 3]) -> Self {
        Vertex { x, y, z, r: rgb[0], g: rgb[1], b: rgb[2], w: None }
    }

    /// The colour as an array.
    pub fn rgb(&self) -> [f64; 3] {
        [self.r, self.g, self.b]
    }

    /// w, defaulting to 1 when the vertex carries none.
    pub fn w_or_one(&self) -> f64 {
        self.w.unwrap_or(1.0)
    }
}

/// Three vertices in submission order (winding matters for back-face culling).
pub type Triangle = [Vertex; 3];

/// A frame's worth of screen-space triangles.
#[derive(Clone, Debug, PartialEq)]
pub struct Trilist {
    pub width: u32,
    pub height: u32,
    pub triangles: Vec<Triangle>,
}

/// Which vertex field a validation error refers to.
const FIELD_NAMES: [&str; 7] = ["x", "y", "z", "r", "g", "b", "w"];

impl Trilist {
    /// An empty list for a `width` x `height` screen (checked).
    pub fn new(width: u32, height: u32) -> Result<Self> {
        check_resolution(width, height)?;
        Ok(Trilist { width, height, triangles: Vec::new() })
    }

    /// Reads and validates a trilist v1 file.
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        Self::from_json(&text).map_err(|e| e.in_file(path))
    }

    /// Parses and validates trilist v1 JSON text.
    pub fn from_json(text: &str) -> Result<Self> {
        let raw: serde_json::Value = crate::error::parse_json(text)?;
        Self::from_value(&raw)
    }

    /// Validates an already parsed JSON value (also used to sniff input kinds).
    pub fn from_value(raw: &serde_json::Value) -> Result<Self> {
        let obj = raw
            .as_object()
            .ok_or_else(|| Error::invalid("a trilist must be a JSON object with width, height and triangles"))?;
        for key in obj.keys() {
            if !matches!(key.as_str(), "width" | "height" | "triangles") {
                return Err(Error::invalid(format!("unknown key \"{key}\" (trilist v1 has width, height, triangles)")));
            }
        }
        let dim = |name: &str| -> Result<u32> {
            let v = obj.get(name).ok_or_else(|| Error::invalid(format!("missing \"{name}\"")))?;
            let n = v
                .as_u64()
                .ok_or_else(|| Error::invalid(format!("\"{name}\" must be a whole number of pixels, got {v}")))?;
            u32::try_from(n).map_err(|_| Error::invalid(format!("\"{name}\" = {n} is out of range")))
        };
        let (width, height) = (dim("width")?, dim("height")?);
        check_resolution(width, height)?;
        let tris = obj
            .get("triangles")
            .ok_or_else(|| Error::invalid("missing \"triangles\""))?
            .as_array()
            .ok_or_else(|| Error::invalid("\"triangles\" must be an array of triangles"))?;
        let mut triangles = Vec::with_capacity(tris.len());
        for (t, tri) in tris.iter().enumerate() {
            let verts = tri
                .as_array()
                .ok_or_else(|| Error::invalid(format!("triangle {t}: must be an array of 3 vertices")))?;
            if verts.len() != 3 {
                return Err(Error::invalid(format!("triangle {t}: has {} vertices, a triangle needs 3", verts.len())));
            }
            let mut out = [Vertex::new(0.0, 0.0, 0.0, [0.0; 3]); 3];
            for (k, v) in verts.iter().enumerate() {
                out[k] = parse_vertex(v).map_err(|msg| Error::invalid(format!("triangle {t} vertex {k}: {msg}")))?;
            }
            triangles.push(out);
        }
        Ok(Trilist { width, height, triangles })
    }

    /// Writes trilist v1 JSON. A vertex carries the 7th value exactly when it has w.
    pub fn to_json(&self) -> String {
        #[derive(Serialize)]
        struct Out<'a> {
            width: u32,
            height: u32,
            triangles: Vec<[Vec<f64>; 3]>,
            #[serde(skip)]
            _p: std::marker::PhantomData<&'a ()>,
        }
        let triangles = self
            .triangles
            .iter()
            .map(|t| {
                t.map(|v| {
                    let mut a = vec![v.x, v.y, v.z, v.r, v.g, v.b];
                    a.extend(v.w);
                    a
                })
            })
            .collect();
        serde_json::to_string(&Out { width: self.width, height: self.height, triangles, _p: Default::default() })
            .expect("finite floats always serialise")
    }

    /// Writes the list to `path` as trilist v1 JSON.
    pub fn save(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_json()).map_err(|e| Error::io(path, e))
    }
}

/// Rejects zero and absurd resolutions.
pub fn check_resolution(width: u32, height: u32) -> Result<()> {
    for (name, v) in [("width", width), ("height", height)] {
        if v == 0 || v > MAX_RESOLUTION {
            return Err(Error::invalid(format!(
                "{name} {v} is out of range: edgepaint renders 1 to {MAX_RESOLUTION} pixels"
            )));
        }
    }
    Ok(())
}

fn parse_vertex(v: &serde_json::Value) -> std::result::Result<Vertex, String> {
    let a = v.as_array().ok_or("must be an array [x,y,z,r,g,b] or [x,y,z,r,g,b,w]")?;
    if a.len() != 6 && a.len() != 7 {
        return Err(format!("has {} values, a vertex needs 6 (x,y,z,r,g,b) or 7 (with w)", a.len()));
    }
    let mut f = [0.0f64; 7];
    for (i, x) in a.iter().enumerate() {
        f[i] = x.as_f64().ok_or_else(|| format!("{} must be a number, got {x}", FIELD_NAMES[i]))?;
        if !f[i].is_finite() {
            return Err(format!("{} is not finite ({})", FIELD_NAMES[i], f[i]));
        }
    }
    for (i, c) in f.iter().enumerate().take(6).skip(3) {
        if !(0.0..=255.0).contains(c) {
            return Err(format!("colour {} = {c} is outside [0, 255]", FIELD_NAMES[i]));
        }
    }
    Ok(Vertex { x: f[0], y: f[1], z: f[2], r: f[3], g: f[4], b: f[5], w: (a.len() == 7).then_some(f[6]) })
}

impl fmt::Display for Vertex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {}, z {}, rgb {} {} {}", self.x, self.y, self.z, self.r, self.g, self.b)?;
        if let Some(w) = self.w {
            write!(f, ", w {w}")?;
        }
        write!(f, ")")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trilist_round_trips_with_and_without_w() {
        let mut t = Trilist::new(64, 48).unwrap();
        t.triangles.push([
            Vertex::new(1.5, 2.25, 0.5, [1.0, 2.0, 3.0]),
            Vertex { w: Some(2.5), ..Vertex::new(10.0, 2.0, 0.25, [255.0, 0.0, 0.0]) },
            Vertex::new(3.0, 40.0, 1.0, [0.0, 0.0, 255.0]),
        ]);
        let back = Trilist::from_json(&t.to_json()).unwrap();
        assert_eq!(back, t);
    }

    #[test]
    fn trilist_rejects_wrong_arity_and_bad_values() {
        let cases = [
            (r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0,0],[1,0,0,0,0,0]]]}"#, "triangle 0: has 2 vertices"),
            (
                r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]]]}"#,
                "vertex 0: has 5 values",
            ),
            (r#"{"width":0,"height":4,"triangles":[]}"#, "width 0 is out of range"),
            (r#"{"width":100000,"height":4,"triangles":[]}"#, "width 100000 is out of range"),
            (r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0,300],[1,0,0,0,0,0],[0,1,0,0,0,0]]]}"#, "colour b = 300"),
            (
                r#"{"width":4,"height":4,"triangles":[[[0,"a",0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]]]}"#,
                "y must be a number",
            ),
            (r#"{"width":4,"height":4}"#, "missing \"triangles\""),
            (r#"{"width":4,"height":4,"triangles":[],"tris":1}"#, "unknown key \"tris\""),
        ];
        for (json, want) in cases {
            let err = Trilist::from_json(json).unwrap_err().to_string();
            assert!(err.contains(want), "{json}: got {err:?}, want {want:?}");
        }
    }
}
