//! The host's clipping front end: what a trilist triangle becomes before its vertices are
//! converted to the hardware's words (`input::to_fixed`), for every fixed-point engine.
//!
//! The hardware takes screen-space vertices in the `xy` format, whose range is the guard
//! band around the screen (S11.4 holds [-2048, 2048) for screens up to 1024 x 1024). A
//! trilist, the exchange format, may carry triangles beyond it (a full-screen triangle
//! with far-away vertices is the most common triangle of real frames) and vertices behind
//! the eye (w <= 0). As a GPU's clipper does, the front end
//!
//! 1. clips a triangle with a vertex at w <= 0 in homogeneous space, (x w, y w, z w, w) with
//!    the colours linear there, against w >= [`W_NEAR`] x its largest |w|, and projects the
//!    polygon back (a vertex at w = 0 exactly has no position: the triangle is dropped);
//! 2. clips what lies beyond the `xy` range in x or y, or beyond the `z` range in z (the
//!    near plane's vertices have z/w far beyond it), against the range's edges in 2-D
//!    (z is screen-linear, so z = c is a line on screen): z screen-linear, the colours
//!    screen-linear or perspective-correct (with w's reciprocal linear) as the method
//!    interpolates them; nothing visible is lost, as only z in [0, 1] is drawn;
//! 3. fans the polygon out into triangles, each drawn as its own (the hardware sets up
//!    each).
//!
//! A triangle inside the range with w > 0 passes unchanged. The float reference, which
//! needs no guard band, clips the same way in its own code (`reference`, "Vertices behind
//! the eye"); the pieces cover what the whole triangle covers there, up to the snapping of
//! the new vertices to `xy`.

use fx::Formats;
use scene::{Tex, Triangle, Trilist, Vertex};

/// The near plane of the homogeneous clip, as a fraction of the triangle's largest |w|.
pub const W_NEAR: f64 = 1.0 / (1u64 << 30) as f64;

/// The triangles the fixed-point engines draw for a trilist.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Pieces {
    /// Each input triangle as it is when it needs no clipping, else its pieces, in order.
    pub triangles: Vec<Triangle>,
    /// For each piece, the index of the input triangle it comes from.
    pub source: Vec<usize>,
    /// Input triangles clipped (into pieces, or away entirely).
    pub clipped: u64,
}

/// A polygon vertex: position, depth, colour, w's reciprocal (1 without w) and texture
/// coordinates (0 when untextured).
#[derive(Clone, Copy, Debug)]
struct P {
    x: f64,
    y: f64,
    z: f64,
    rgb: [f64; 3],
    inv_w: f64,
    st: [f64; 2],
}

/// The pieces of every triangle of `list` for formats `f`; `perspective`: the method
/// interpolates colour perspective-correctly (step 2).
pub fn pieces(list: &Trilist, f: &Formats, perspective: bool) -> Pieces {
    let mut out = Pieces::default();
    for (i, tri) in list.triangles.iter().enumerate() {
        match clip(tri, f, perspective) {
            None => {
                out.triangles.push(*tri);
                out.source.push(i);
            }
            Some(parts) => {
                out.clipped += 1;
                out.source.extend(std::iter::repeat_n(i, parts.len()));
                out.triangles.extend(parts);
            }
        }
    }
    out
}

/// `tri`'s pieces, or `None` when it needs no clipping.
fn clip(tri: &Triangle, f: &Formats, perspective: bool) -> Option<Vec<Triangle>> {
    let range = |fm: fx::Fmt| (fm.to_f64(fm.min_raw()), fm.to_f64(fm.max_raw()));
    let ((lo, hi), (z_lo, z_hi)) = (range(f.xy), range(f.z));
    let has_w = tri.iter().any(|v| v.w.is_some());
    let behind = tri.iter().any(|v| v.w_or_one() <= 0.0);
    let outside =
        tri.iter().any(|v| !(lo..=hi).contains(&v.x) || !(lo..=hi).contains(&v.y) || !(z_lo..=z_hi).contains(&v.z));
    if !behind && !outside {
        return None;
    }
    let mut poly = if behind { near(tri)? } else { tri.map(screen).to_vec() };
    let planes = [(0, lo, false), (0, hi, true), (1, lo, false), (1, hi, true), (2, z_lo, false), (2, z_hi, true)];
    for (axis, bound, keep_below) in planes {
        poly = clip_axis(&poly, axis, bound, keep_below, perspective);
    }
    let texture = tri[0].tex.map(|t| t.texture);
    let vertex = |p: &P| Vertex {
        w: has_w.then_some(1.0 / p.inv_w),
        tex: texture.map(|texture| Tex { s: p.st[0], t: p.st[1], texture }),
        blend: tri[0].blend,
        ..Vertex::new(p.x, p.y, p.z, p.rgb)
    };
    Some(
        (1..poly.len().saturating_sub(1)).map(|k| [vertex(&poly[0]), vertex(&poly[k]), vertex(&poly[k + 1])]).collect(),
    )
}

/// A trilist vertex as a polygon vertex.
fn screen(v: Vertex) -> P {
    P { x: v.x, y: v.y, z: v.z, rgb: v.rgb(), inv_w: 1.0 / v.w_or_one(), st: st_of(&v) }
}

/// Step 1: the polygon in front of the near plane, projected; `None` when a vertex lies at
/// w = 0 exactly (no position to clip from).
fn near(tri: &Triangle) -> Option<Vec<P>> {
    let w = tri.map(|v| v.w_or_one());
    if w.contains(&0.0) {
        return None;
    }
    let w_near = W_NEAR * w.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    // Homogeneous: (x w, y w, z w, w), the colours and texture coordinates, all linear
    // along an edge.
    let h: Vec<[f64; 9]> = tri
        .iter()
        .zip(w)
        .map(|(v, w)| {
            let st = st_of(v);
            [v.x * w, v.y * w, v.z * w, w, v.r, v.g, v.b, st[0], st[1]]
        })
        .collect();
    let d = |p: &[f64; 9]| p[3] - w_near;
    let mut poly = Vec::new();
    for k in 0..h.len() {
        let (a, b) = (&h[k], &h[(k + 1) % h.len()]);
        if d(a) >= 0.0 {
            poly.push(*a);
        }
        if (d(a) >= 0.0) != (d(b) >= 0.0) {
            let t = d(a) / (d(a) - d(b));
            let mut p: [f64; 9] = std::array::from_fn(|c| a[c] + t * (b[c] - a[c]));
            p[3] = w_near;
            poly.push(p);
        }
    }
    Some(
        poly.iter()
            .map(|p| P {
                x: p[0] / p[3],
                y: p[1] / p[3],
                z: p[2] / p[3],
                rgb: [p[4], p[5], p[6]],
                inv_w: 1.0 / p[3],
                st: [p[7], p[8]],
            })
            .collect(),
    )
}

/// Step 2 for one edge of the `xy` or `z` range: the part of `poly` with coordinate `axis`
/// (0: x, 1: y, 2: z) at most (`keep_below`) or at least `bound`.
fn clip_axis(poly: &[P], axis: usize, bound: f64, keep_below: bool, perspective: bool) -> Vec<P> {
    let coord = |p: &P| [p.x, p.y, p.z][axis];
    let inside = |p: &P| if keep_below { coord(p) <= bound } else { coord(p) >= bound };
    let mut out = Vec::new();
    for k in 0..poly.len() {
        let (a, b) = (&poly[k], &poly[(k + 1) % poly.len()]);
        if inside(a) {
            out.push(*a);
        }
        if inside(a) != inside(b) {
            let t = (bound - coord(a)) / (coord(b) - coord(a));
            let mut p = between(a, b, t, perspective);
            // On the edge exactly, whatever the rounding of t.
            *[&mut p.x, &mut p.y, &mut p.z][axis] = bound;
            out.push(p);
        }
    }
    out
}

/// The point at screen-space parameter `t` from `a` to `b`: position and depth linear,
/// colour linear or (`perspective`) linear in clip space, w's reciprocal linear, texture
/// coordinates linear in clip space (the texture path divides by q whatever the method).
fn between(a: &P, b: &P, t: f64, perspective: bool) -> P {
    let lerp = |u: f64, v: f64| u + t * (v - u);
    let inv_w = lerp(a.inv_w, b.inv_w);
    let rgb = std::array::from_fn(|c| {
        if perspective {
            lerp(a.rgb[c] * a.inv_w, b.rgb[c] * b.inv_w) / inv_w
        } else {
            lerp(a.rgb[c], b.rgb[c])
        }
    });
    let st = std::array::from_fn(|c| lerp(a.st[c] * a.inv_w, b.st[c] * b.inv_w) / inv_w);
    P { x: lerp(a.x, b.x), y: lerp(a.y, b.y), z: lerp(a.z, b.z), rgb, inv_w, st }
}

/// A vertex's texture coordinates, 0 when it has none.
fn st_of(v: &Vertex) -> [f64; 2] {
    v.tex.map_or([0.0; 2], |t| [t.s, t.t])
}
