#![allow(dead_code)] // each test binary uses part of this module
//! Helpers shared by the model's integration tests: one triangle through a
//! fixed-point method compared with the float reference.

use fx::Formats;
use model::cull_sort::{Clip, Cull};
use model::render::{triangle, Dropped, Method, Options};
use scene::measure::{edge_distance, plane_z};
use scene::Triangle;
use std::collections::HashMap;

pub fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

pub fn count() -> usize {
    std::env::var("EDGEPAINT_N").ok().and_then(|s| s.parse().ok()).unwrap_or(1000)
}

pub const METHODS: [Method; 2] = [Method::Scanline, Method::Vector { lanes: 4, perspective: true }];

/// Depth at a pixel centre of the plane through the triangle's vertices after
/// snapping to the input formats: what the hardware can at best produce (depth
/// LSBs). Computed here, independently of the models.
fn snapped_depth(t: &Triangle, f: &Formats, x: u32, y: u32) -> f64 {
    let q = |fm: fx::Fmt, v: f64| fm.to_f64(fm.from_f64(v).unwrap());
    let snapped = t.map(|v| scene::Vertex { x: q(f.xy, v.x), y: q(f.xy, v.y), z: q(f.z, v.z), ..v });
    plane_z(&snapped, x as f64 + 0.5, y as f64 + 0.5).expect("non-degenerate") * (f.z.frac as f64).exp2()
}

/// How far a fixed-point triangle may stray from the reference.
#[derive(Clone, Copy)]
pub struct Tol {
    /// Coverage may differ only for centres this close to an edge (px).
    pub tie: f64,
    /// Colour LSBs from the reference's.
    pub color: f64,
    /// Depth LSBs from the plane through the snapped vertices.
    pub depth: f64,
}

/// One triangle through a fixed-point method and through the reference, both on
/// a `size` screen.
pub struct Case<'a> {
    pub t: &'a Triangle,
    pub size: (u32, u32),
    pub f: &'a Formats,
    pub method: Method,
}

/// Checks a case under `tol`: coverage equal to the reference's (clipped the
/// same way) except at documented ties, colour within `tol.color` of the
/// reference's, depth within `tol.depth` of the plane through the snapped
/// vertices. The ties: a centre within `tol.tie` of an edge (snapping moved the
/// edge), a pixel whose float and snapped depths lie on different sides of a z
/// boundary (z clipping follows the snapped vertices), and depths between the
/// largest buffer value and 1 (the far-plane tie).
pub fn agree(c: &Case, tol: &Tol) -> Result<(), String> {
    let (w, h) = c.size;
    let opts = Options { method: c.method, cull: Cull::None, analysis: true, background: [0; 3] };
    let perspective = matches!(c.method, Method::Vector { perspective: true, .. }) && c.t.iter().any(|v| v.w.is_some());
    let mut want = HashMap::new();
    let ropts = reference::Options { ignore_w: !perspective, ..Default::default() };
    reference::fragments(c.t, w, h, &ropts, |f| {
        want.insert((f.x, f.y), (f.z, f.rgb));
    });
    let got = match triangle(c.t, Clip { width: w, height: h }, c.f, &opts).0 {
        Ok(tr) => tr.pixels,
        Err(Dropped::Rejected(_)) => Vec::new(),
        Err(e) => return Err(format!("dropped: {e:?}")),
    };
    let zmax = (c.f.z.frac as f64).exp2() - 1.0;
    let near_edge = |x: u32, y: u32| edge_distance(c.t, x as f64 + 0.5, y as f64 + 0.5) <= tol.tie;
    let in_range = |z: f64| (0.0..=zmax).contains(&z);
    let z_tie = |x: u32, y: u32, float_z: f64| {
        let z = snapped_depth(c.t, c.f, x, y);
        in_range(z.round()) != (0.0..=1.0).contains(&float_z) || float_z * (zmax + 1.0) > zmax - tol.depth
    };
    for p in &got {
        match want.get(&(p.x, p.y)) {
            Some(&(z, rgb)) if (0.0..=1.0).contains(&z) => {
                for (i, (&g, r)) in p.rgb.iter().zip(rgb).enumerate() {
                    if (g as f64 - r).abs() > tol.color {
                        return Err(format!("pixel {:?} channel {i}: {g} vs {r:.4}", (p.x, p.y)));
                    }
                }
                let z = snapped_depth(c.t, c.f, p.x, p.y);
                if (p.z as f64 - z).abs() > tol.depth {
                    return Err(format!("pixel {:?}: depth {} vs {z:.3} LSB", (p.x, p.y), p.z));
                }
            }
            Some(&(z, _)) if z_tie(p.x, p.y, z) => {}
            _ if near_edge(p.x, p.y) => {}
            _ => return Err(format!("pixel {:?} drawn, not in the reference", (p.x, p.y))),
        }
    }
    for (&(x, y), &(z, _)) in &want {
        let drawn = got.iter().any(|p| (p.x, p.y) == (x, y));
        if (0.0..=1.0).contains(&z) && !drawn && !near_edge(x, y) && !z_tie(x, y, z) {
            return Err(format!("pixel {:?} missing", (x, y)));
        }
    }
    Ok(())
}

/// Snapping moves each vertex by at most half an LSB in x and y, so an edge
/// moves by at most sqrt(2)/2 LSB: only centres that close may change sides.
pub fn wide_tolerance(f: &Formats) -> Tol {
    Tol { tie: (-(f.xy.frac as f64)).exp2(), color: 1.0, depth: 1.0 }
}
