//! One screen-space triangle to fragments, in f64.
//!
//! Coverage is sampled at pixel centres with edge functions. Each edge function
//! is evaluated in a *canonical* vertex order (the endpoint with the smaller
//! (y, x) first) and negated as the triangle's winding requires, so two triangles
//! sharing an edge compute bit-identical values for it and the fill rule below
//! gives every sample on a shared edge to exactly one of them.
//!
//! Fill rule (top-left, as Direct3D and OpenGL implementations use): a centre
//! strictly inside belongs to the triangle; a centre exactly on an edge belongs
//! to it only when that edge is a *top* edge (horizontal, interior below it;
//! y points down) or a *left* edge (interior to its right).

use crate::Interpolation;

/// A screen-space vertex ready for rasterization.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterVertex {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// 1/w (1 when the input had no w).
    pub inv_w: f64,
    pub rgb: [f64; 3],
    /// Texture coordinates (s, t); 0 where the input has none.
    pub st: [f64; 2],
}

/// A covered sample: pixel (x, y) with interpolated depth, colour and texture
/// coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    pub x: u32,
    pub y: u32,
    pub z: f64,
    pub rgb: [f64; 3],
    /// Texture coordinates (s, t) at the centre, interpolated as the colour is.
    pub st: [f64; 2],
    /// Their derivatives per pixel: `[[ds/dx, dt/dx], [ds/dy, dt/dy]]`, exact for the
    /// interpolation used (perspective: 001's eq. (3), the quotient rule on
    /// (s/w) / (1/w)).
    pub dst: [[f64; 2]; 2],
}

/// Edge function of the directed edge a -> b at sample s, evaluated in canonical
/// endpoint order so that (a, b) and (b, a) give exact negatives of each other.
fn edge(a: (f64, f64), b: (f64, f64), s: (f64, f64)) -> f64 {
    let swap = (b.1, b.0) < (a.1, a.0);
    let (p, q) = if swap { (b, a) } else { (a, b) };
    let e = (q.0 - p.0) * (s.1 - p.1) - (q.1 - p.1) * (s.0 - p.0);
    if swap {
        -e
    } else {
        e
    }
}

/// The attribute with values `a` at the three vertices, at the point whose weights of
/// vertices 1 and 2 are `b1`, `b2`: `a0 + b1 (a1 - a0) + b2 (a2 - a0)`. Written from the
/// differences, not as `b0 a0 + b1 a1 + b2 a2`, so that an attribute equal at the three
/// vertices comes out exactly (the three weights need not sum to exactly 1 in floating
/// point): a triangle at z = 1 never passes LESS against the 1.0 clear.
fn lerp(a: [f64; 3], b1: f64, b2: f64) -> f64 {
    a[0] + b1 * (a[1] - a[0]) + b2 * (a[2] - a[0])
}

/// Twice the signed area in screen coordinates (y down). Positive means the
/// triangle runs clockwise as seen on screen; negative, counter-clockwise.
pub fn signed_area2(v: &[RasterVertex; 3]) -> f64 {
    (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y)
}

/// Calls `emit` for every pixel centre of the `width` x `height` screen that the
/// triangle covers under the top-left rule, with depth, colour and texture coordinates
/// interpolated at the centre. Depth is screen-linear (it is z/w already); colour and
/// texture coordinates follow `interp`. Returns the number of covered samples. A
/// zero-area triangle covers nothing.
pub fn rasterize(
    tri: &[RasterVertex; 3],
    width: u32,
    height: u32,
    interp: Interpolation,
    mut emit: impl FnMut(Fragment),
) -> u64 {
    let area2 = signed_area2(tri);
    if area2 == 0.0 || !area2.is_finite() {
        return 0;
    }
    // Orient clockwise-on-screen (area2 > 0) so that inside means every edge > 0.
    let v = if area2 > 0.0 { *tri } else { [tri[0], tri[2], tri[1]] };
    let area2 = area2.abs();
    let p = v.map(|v| (v.x, v.y));
    // Edge k runs from vertex k+1 to vertex k+2: it is opposite vertex k, so its
    // value over area2 is vertex k's barycentric weight.
    let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
    // In this orientation (y down) a top edge runs in +x, a left edge in -y.
    let owns_ties = edges.map(|(a, b)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        dy < 0.0 || (dy == 0.0 && dx > 0.0)
    });
    // The barycentric weights' derivatives along x and y (the edge functions' over area2).
    let db = [edges.map(|(a, b)| -(b.1 - a.1) / area2), edges.map(|(a, b)| (b.0 - a.0) / area2)];
    // Texture coordinates are N / Q with N = sum b_k st_k q_k and Q = sum b_k q_k (q the
    // vertices' 1/w, or 1 screen-linearly).
    let q = match interp {
        Interpolation::Linear => [1.0; 3],
        Interpolation::Perspective => v.map(|v| v.inv_w),
    };

    let min_x = p.iter().map(|q| q.0).fold(f64::INFINITY, f64::min);
    let max_x = p.iter().map(|q| q.0).fold(f64::NEG_INFINITY, f64::max);
    let min_y = p.iter().map(|q| q.1).fold(f64::INFINITY, f64::min);
    let max_y = p.iter().map(|q| q.1).fold(f64::NEG_INFINITY, f64::max);
    // Pixels whose centres can lie in [min, max]; clamped to the screen.
    let span = |lo: f64, hi: f64, n: u32| -> Option<(u32, u32)> {
        let a = (lo - 0.5).ceil().max(0.0);
        let b = (hi - 0.5).floor().min(n as f64 - 1.0);
        (a <= b).then_some((a as u32, b as u32))
    };
    let (Some((x0, x1)), Some((y0, y1))) = (span(min_x, max_x, width), span(min_y, max_y, height)) else {
        return 0;
    };

    let mut covered = 0;
    for py in y0..=y1 {
        let sy = py as f64 + 0.5;
        for px in x0..=x1 {
            let s = (px as f64 + 0.5, sy);
            let mut e = [0.0; 3];
            let mut inside = true;
            for k in 0..3 {
                e[k] = edge(edges[k].0, edges[k].1, s);
                if !(e[k] > 0.0 || (e[k] == 0.0 && owns_ties[k])) {
                    inside = false;
                    break;
                }
            }
            if !inside {
                continue;
            }
            let b = e.map(|ek| ek / area2);
            let z = lerp(v.map(|v| v.z), b[1], b[2]);
            let rgb = match interp {
                Interpolation::Linear => std::array::from_fn(|c| lerp(v.map(|v| v.rgb[c]), b[1], b[2])),
                Interpolation::Perspective => {
                    let q: [f64; 3] = std::array::from_fn(|k| b[k] * v[k].inv_w);
                    let sum = q[0] + q[1] + q[2];
                    std::array::from_fn(|c| lerp(v.map(|v| v.rgb[c]), q[1] / sum, q[2] / sum))
                }
            };
            let sum = |w: [f64; 3], a: &dyn Fn(usize) -> f64| (0..3).map(|k| w[k] * q[k] * a(k)).sum::<f64>();
            let den = sum(b, &|_| 1.0);
            let st: [f64; 2] = std::array::from_fn(|c| sum(b, &|k| v[k].st[c]) / den);
            let dst = db.map(|d| {
                let dden = sum(d, &|_| 1.0);
                std::array::from_fn(|c| (sum(d, &|k| v[k].st[c]) - st[c] * dden) / den)
            });
            covered += 1;
            emit(Fragment { x: px, y: py, z, rgb, st, dst });
        }
    }
    covered
}
