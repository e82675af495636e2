//! From a trilist triangle to the screen-space triangles that are rasterized.
//!
//! A triangle whose vertices all have w > 0 (or no w) is passed through as is.
//! A vertex with w < 0 lies behind the eye: its screen position is the image of
//! a point through the projection centre, and drawing the triangle from those
//! positions would paint garbage. Such triangles are rebuilt in homogeneous
//! space, (x*w, y*w, z*w, w), clipped against the plane w = [`W_EPSILON`] times
//! the largest |w| of the triangle (Sutherland-Hodgman), divided again and
//! fan-triangulated. What is left in front of the eye is then drawn; the per-pixel
//! z test in [0, 1] does the near and far clipping, exactly as it does for
//! triangles that never needed this step. A vertex with w = 0 exactly has no
//! recoverable position (x and y would be infinite), so its triangle is rejected.

use crate::raster::RasterVertex;
use scene::Triangle;

/// Relative distance in front of the eye at which behind-the-eye triangles are cut.
pub const W_EPSILON: f64 = 1e-9;

/// Why a triangle produced nothing to rasterize.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rejected {
    /// A vertex has w = 0.
    WZero,
    /// Every vertex is behind the eye.
    BehindEye,
}

/// The screen-space triangles (one, or a fan after clipping) that draw `tri`.
pub fn to_screen(tri: &Triangle) -> Result<Vec<[RasterVertex; 3]>, Rejected> {
    let w = tri.map(|v| v.w_or_one());
    if w.contains(&0.0) {
        return Err(Rejected::WZero);
    }
    if w.iter().all(|&w| w > 0.0) {
        return Ok(vec![tri.map(|v| RasterVertex {
            x: v.x,
            y: v.y,
            z: v.z,
            inv_w: 1.0 / v.w_or_one(),
            rgb: v.rgb(),
            st: st(&v),
        })]);
    }
    // Homogeneous vertices: position * w, w, the colour and the texture coordinates
    // (linear in clip space).
    let hom: Vec<[f64; 9]> = tri
        .iter()
        .zip(w)
        .map(|(v, w)| {
            let [s, t] = st(v);
            [v.x * w, v.y * w, v.z * w, w, v.r, v.g, v.b, s, t]
        })
        .collect();
    let eps = W_EPSILON * w.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let mut poly = Vec::with_capacity(4);
    for i in 0..3 {
        let (a, b) = (hom[i], hom[(i + 1) % 3]);
        let (da, db) = (a[3] - eps, b[3] - eps);
        if da >= 0.0 {
            poly.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            poly.push(std::array::from_fn(|k| a[k] + t * (b[k] - a[k])));
        }
    }
    if poly.len() < 3 {
        return Err(Rejected::BehindEye);
    }
    let screen: Vec<RasterVertex> = poly
        .iter()
        .map(|h| RasterVertex {
            x: h[0] / h[3],
            y: h[1] / h[3],
            z: h[2] / h[3],
            inv_w: 1.0 / h[3],
            rgb: [h[4], h[5], h[6]],
            st: [h[7], h[8]],
        })
        .collect();
    Ok((1..screen.len() - 1).map(|i| [screen[0], screen[i], screen[i + 1]]).collect())
}

/// A vertex's texture coordinates, 0 when it has none.
fn st(v: &scene::Vertex) -> [f64; 2] {
    v.tex.map_or([0.0; 2], |x| [x.s, x.t])
}

#[cfg(test)]
mod tests {
    use super::*;
    use scene::Vertex;

    fn v(x: f64, y: f64, w: f64) -> Vertex {
        Vertex { w: Some(w), ..Vertex::new(x, y, 0.5, [10.0, 20.0, 30.0]) }
    }

    #[test]
    fn clip_passes_triangles_in_front_of_the_eye_unchanged() {
        let out = to_screen(&[v(1.0, 2.0, 1.0), v(5.0, 2.0, 2.0), v(1.0, 9.0, 4.0)]).unwrap();
        assert_eq!(out.len(), 1);
        assert_eq!(out[0][1].x, 5.0);
        assert_eq!(out[0][1].inv_w, 0.5);
    }

    #[test]
    fn clip_cuts_a_vertex_behind_the_eye_into_a_fan_in_front() {
        // One vertex behind the eye: the cut leaves a quad, drawn as two triangles,
        // and every remaining vertex has w > 0.
        let out = to_screen(&[v(1.0, 2.0, 1.0), v(5.0, 2.0, 1.0), v(3.0, 9.0, -1.0)]).unwrap();
        assert_eq!(out.len(), 2);
        assert!(out.iter().flatten().all(|r| r.inv_w > 0.0));
        // The kept vertices are exactly the inputs.
        assert_eq!((out[0][0].x, out[0][0].y), (1.0, 2.0));
    }

    #[test]
    fn clip_rejects_w_zero_and_all_behind() {
        assert_eq!(to_screen(&[v(1.0, 2.0, 0.0), v(5.0, 2.0, 1.0), v(3.0, 9.0, 1.0)]), Err(Rejected::WZero));
        assert_eq!(to_screen(&[v(1.0, 2.0, -1.0), v(5.0, 2.0, -2.0), v(3.0, 9.0, -1.0)]), Err(Rejected::BehindEye));
    }
}
