//! The triangles of one cell of each family ([`crate::family`]): one or more trilists
//! (seeds, meshes), each on a screen just large enough for its geometry, so that a cell
//! costs the pixels its triangles cover rather than a large frame.
//!
//! Vertices sit on whole pixels or the 1/4-px grid wherever the family does not sweep
//! position itself, so that every format with 2 or more subpixel bits holds them exactly
//! and what a cell measures is the swept quantity alone.

use crate::family::Family;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use scene::{Triangle, Trilist, Vertex, MAX_RESOLUTION};
use std::f64::consts::TAU;

/// Random seeds per cell of the random families (tiny, shared).
pub const SEEDS: u64 = 4;

/// The trilists of the cell at (`x`, `y`) of `family` (`y` ignored by one-axis families).
pub fn cell(family: Family, x: f64, y: f64) -> Vec<Trilist> {
    match family {
        Family::SliverH => vec![sliver(x, y, Orientation::Horizontal)],
        Family::SliverV => vec![sliver(x, y, Orientation::Vertical)],
        Family::SliverD => vec![sliver(x, y, Orientation::Diagonal)],
        Family::Tiny => (1..=SEEDS).map(|s| tiny(x, s)).collect(),
        Family::Span => vec![span(x)],
        Family::Offscreen => vec![offscreen(x)],
        Family::Depth => vec![depth(x, y == 1.0)],
        Family::Perspective => vec![perspective(x)],
        Family::Screen => vec![screen(x as u32)],
        Family::Shared => {
            (1..=SEEDS).map(|s| if y == 0.0 { fan(x as usize, s) } else { grid(x as usize, s) }).collect()
        }
    }
}

fn v(x: f64, y: f64, z: f64, rgb: [f64; 3]) -> Vertex {
    Vertex::new(x, y, z, rgb)
}

fn list(width: u32, height: u32, triangles: Vec<Triangle>) -> Trilist {
    Trilist { width: width.min(MAX_RESOLUTION), height: height.min(MAX_RESOLUTION), triangles, textures: Vec::new() }
}

/// How a needle runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Orientation {
    Horizontal,
    Vertical,
    Diagonal,
}

/// A needle of base thickness `t` and length `l`: its base's midpoint on the pixel centre
/// (2.5, 4.5) (diagonal: (2.5, 2.5)), its tip `l` px along the axis (diagonal: on the
/// pixel centre nearest to it), the axis through a line of pixel centres. A tip beyond
/// 4096 px leaves the screen and is clipped.
pub fn sliver(t: f64, l: f64, o: Orientation) -> Trilist {
    let (rgb, z) = ([200.0, 120.0, 40.0], 0.5);
    let h = t / 2.0;
    match o {
        Orientation::Horizontal => {
            let tri = [v(2.5, 4.5 - h, z, rgb), v(2.5, 4.5 + h, z, rgb), v(2.5 + l, 4.5, z, rgb)];
            list(l as u32 + 6, 9, vec![tri])
        }
        Orientation::Vertical => {
            let tri = [v(4.5 - h, 2.5, z, rgb), v(4.5 + h, 2.5, z, rgb), v(4.5, 2.5 + l, z, rgb)];
            list(9, l as u32 + 6, vec![tri])
        }
        Orientation::Diagonal => {
            let k = (l / 2f64.sqrt()).round();
            let d = h / 2f64.sqrt();
            let tri = [v(2.5 - d, 2.5 + d, z, rgb), v(2.5 + d, 2.5 - d, z, rgb), v(2.5 + k, 2.5 + k, z, rgb)];
            list(k as u32 + 6, k as u32 + 6, vec![tri])
        }
    }
}

/// 64 triangles of area `area` (seed `seed`), one per 8 x 8 px tile of a 64 x 64 screen:
/// a random shape (three points on a circle, about 120 degrees apart, each turned by up to
/// 0.3 rad) placed so that a uniformly random point inside it lies on the tile's central
/// pixel centre. Constant colour and depth.
pub fn tiny(area: f64, seed: u64) -> Trilist {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut tris = Vec::new();
    for tile in 0..64 {
        let (cx, cy) = ((tile % 8 * 8) as f64 + 4.5, (tile / 8 * 8) as f64 + 4.5);
        let a0 = rng.gen_range(0.0..TAU);
        let p: [(f64, f64); 3] = std::array::from_fn(|k| {
            let a = a0 + k as f64 * TAU / 3.0 + rng.gen_range(-0.3..0.3);
            (a.cos(), a.sin())
        });
        let unit = ((p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)).abs() / 2.0;
        let s = (area / unit).sqrt();
        // A uniform point inside: barycentrics from two uniforms, folded.
        let (mut u, mut w) = (rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0));
        if u + w > 1.0 {
            (u, w) = (1.0 - u, 1.0 - w);
        }
        let inner = (
            p[0].0 + u * (p[1].0 - p[0].0) + w * (p[2].0 - p[0].0),
            p[0].1 + u * (p[1].1 - p[0].1) + w * (p[2].1 - p[0].1),
        );
        let rgb = [rng.gen_range(0..=255) as f64, 128.0, 255.0 - tile as f64];
        tris.push(p.map(|(x, y)| v(cx + s * (x - inner.0), cy + s * (y - inner.1), 0.5, rgb)));
    }
    list(64, 64, tris)
}

/// A triangle `l` px wide and 8 px tall on whole pixels: (0, 2), (l, 6), (0, 10), red
/// rising along the span, green and blue steep down the rows, depth from 2^-12 at the left
/// to 1 - 2^-12 at the tip and 1/2 down the rows.
pub fn span(l: f64) -> Trilist {
    let e = (-12f64).exp2();
    let tri = [
        v(0.0, 2.0, e, [0.0, 255.0, 30.0]),
        v(l, 6.0, 1.0 - e, [255.0, 0.0, 220.0]),
        v(0.0, 10.0, 0.5, [40.0, 10.0, 255.0]),
    ];
    list((l as u32).max(16), 12, vec![tri])
}

/// On 256 x 256 px: a triangle with a vertex `d` px beyond the left edge, and one with two
/// vertices `d` px above the top edge, overlapping, the first nearer; vertices on the
/// 1/4-px grid.
pub fn offscreen(d: f64) -> Trilist {
    let left = [
        v(-d, 100.25, 0.25, [255.0, 0.0, 0.0]),
        v(200.5, 20.75, 0.3, [0.0, 255.0, 0.0]),
        v(210.25, 180.5, 0.35, [0.0, 0.0, 255.0]),
    ];
    let top = [
        v(30.25, -d, 0.6, [250.0, 250.0, 0.0]),
        v(230.75, -d - 3.5, 0.7, [0.0, 250.0, 250.0]),
        v(128.5, 240.25, 0.8, [250.0, 0.0, 250.0]),
    ];
    list(256, 256, vec![left, top])
}

/// Where the two triangles of the depth family lie (64 x 64 screen, whole pixels): the
/// farther (drawn first) and the nearer. Every edge has one even and one odd extent (after
/// taking out a common power of two), so no pixel centre lies on an edge.
const DEPTH_FAR: [(f64, f64); 3] = [(4.0, 4.0), (60.0, 9.0), (10.0, 60.0)];
const DEPTH_NEAR: [(f64, f64); 3] = [(7.0, 6.0), (58.0, 30.0), (21.0, 58.0)];

/// The depths of the depth family's two triangles `dz` apart: near 0, the nearer at 2^-10;
/// near 1, the farther at 1 - 2^-10. Returns (farther, nearer).
pub fn depth_pair(dz: f64, near_one: bool) -> (f64, f64) {
    let e = (-10f64).exp2();
    if near_one {
        (1.0 - e, 1.0 - e - dz)
    } else {
        (e + dz, e)
    }
}

/// Two overlapping triangles of constant depth `dz` apart ([`depth_pair`]), the farther
/// drawn first.
pub fn depth(dz: f64, near_one: bool) -> Trilist {
    let (zf, zn) = depth_pair(dz, near_one);
    let far = DEPTH_FAR.map(|(x, y)| v(x, y, zf, [200.0, 40.0, 40.0]));
    let near = DEPTH_NEAR.map(|(x, y)| v(x, y, zn, [40.0, 40.0, 200.0]));
    list(64, 64, vec![far, near])
}

/// A triangle (4, 4), (124, 20), (30, 124) with w = 1, `r`, sqrt(`r`) and red, green, blue.
pub fn perspective(r: f64) -> Trilist {
    let ws = [1.0, r, r.sqrt()];
    let mut tri = [
        v(4.0, 4.0, 0.2, [255.0, 0.0, 0.0]),
        v(124.0, 20.0, 0.8, [0.0, 255.0, 0.0]),
        v(30.0, 124.0, 0.5, [0.0, 0.0, 255.0]),
    ];
    for (vx, w) in tri.iter_mut().zip(ws) {
        vx.w = Some(w);
    }
    list(128, 128, vec![tri])
}

/// On a `s` x `s` screen: a band 2^0.5 px wide from corner to corner (two triangles), a thin
/// triangle along the bottom row across the whole width, and a small triangle with steep
/// gradients in the far corner; vertices on the 1/4-px grid, depths on multiples of 2^-12.
pub fn screen(s: u32) -> Trilist {
    let f = s as f64;
    let q = |z: f64| (z * 4096.0).round() / 4096.0;
    let (a, b) = ([255.0, 30.0, 0.0], [0.0, 200.0, 255.0]);
    // A rectangle 2^0.5 px wide along the diagonal, split along its long diagonal.
    let (n0, n1) = (v(0.25, 1.25, q(0.1), a), v(1.25, 0.25, q(0.1), a));
    let (f0, f1) = (v(f - 0.25, f - 1.25, q(0.9), b), v(f - 1.25, f - 0.25, q(0.9), b));
    let band = [[n0, n1, f0], [n0, f0, f1]];
    let bottom = [v(0.0, f - 3.0, q(0.3), a), v(f, f - 2.5, q(0.7), b), v(0.0, f - 1.5, q(0.5), [90.0, 90.0, 90.0])];
    let corner = [
        v(f - 20.5, f - 19.75, q(0.05), [0.0, 0.0, 0.0]),
        v(f - 2.25, f - 15.5, q(0.95), [255.0, 255.0, 0.0]),
        v(f - 12.75, f - 4.25, q(0.5), [0.0, 255.0, 255.0]),
    ];
    list(s, s, vec![band[0], band[1], bottom, corner])
}

/// The depth of the `i`-th triangle of a mesh: nearer than every one before it by 2^-12,
/// so that all its fragments pass the depth test (at 12 or more depth bits).
fn mesh_z(i: usize) -> f64 {
    0.75 - i as f64 * (-12f64).exp2()
}

fn random_rgb(rng: &mut ChaCha8Rng) -> [f64; 3] {
    [0, 1, 2].map(|_| rng.gen_range(0..=255) as f64)
}

/// A fan of about `n` triangles (seed `seed`) on 128 x 128 px: the centre anywhere within
/// 8 px of (64, 64); the ring at radius 40 to 60 on the 1/4-px grid, in angular order,
/// points closer than 10^-3 rad in angle to the one before left out. So the fan's outline is
/// exact in every format of 2 or more subpixel bits and snapping moves only the centre, too
/// little to fold a triangle: the union covers the same pixels in every method.
pub fn fan(n: usize, seed: u64) -> Trilist {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let c = (64.0 + rng.gen_range(-8.0..8.0), 64.0 + rng.gen_range(-8.0..8.0));
    let quarter = |t: f64| (t * 4.0).round() / 4.0;
    let mut ring: Vec<(f64, (f64, f64))> = (0..n)
        .map(|k| {
            let a = TAU * (k as f64 + rng.gen_range(-0.4..0.4)) / n as f64;
            let r = rng.gen_range(40.0..60.0);
            let p = (quarter(c.0 + r * a.cos()), quarter(c.1 + r * a.sin()));
            ((p.1 - c.1).atan2(p.0 - c.0), p)
        })
        .collect();
    ring.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut kept: Vec<(f64, (f64, f64))> = Vec::new();
    for p in ring {
        if kept.last().is_none_or(|q| p.0 - q.0 >= 1e-3) {
            kept.push(p);
        }
    }
    if kept.len() > 1 && kept[0].0 + TAU - kept[kept.len() - 1].0 < 1e-3 {
        kept.pop();
    }
    let tris = (0..kept.len())
        .map(|k| {
            let (p, q) = (kept[k].1, kept[(k + 1) % kept.len()].1);
            let rgb = random_rgb(&mut rng);
            let z = mesh_z(k);
            let mut t = [v(c.0, c.1, z, rgb), v(p.0, p.1, z, rgb), v(q.0, q.1, z, rgb)];
            if rng.gen_bool(0.5) {
                t.swap(1, 2);
            }
            t
        })
        .collect();
    list(128, 128, tris)
}

/// A grid of about `n` triangles (seed `seed`): k x k quads, k = round(sqrt(n / 2)), so
/// 2k^2 triangles, over [8, 120]^2 on a 128 x 128 screen, the border's
/// vertices on whole pixels, the interior's moved anywhere by up to a quarter of the
/// spacing in x and y (quads stay convex, even after snapping at 2 subpixel bits from a
/// spacing of 2 px); each quad split along a random diagonal, each triangle wound at random.
pub fn grid(n: usize, seed: u64) -> Trilist {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let k = ((n as f64 / 2.0).sqrt().round() as usize).max(1);
    let s = 112.0 / k as f64;
    let border = |i: usize| i == 0 || i == k;
    let mut p = vec![(0.0, 0.0); (k + 1) * (k + 1)];
    for j in 0..=k {
        for i in 0..=k {
            let (x, y) = (8.0 + i as f64 * s, 8.0 + j as f64 * s);
            p[j * (k + 1) + i] = if border(i) || border(j) {
                (x.round(), y.round())
            } else {
                (x + rng.gen_range(-s / 4.0..s / 4.0), y + rng.gen_range(-s / 4.0..s / 4.0))
            };
        }
    }
    let mut tris = Vec::new();
    for j in 0..k {
        for i in 0..k {
            let at = |di: usize, dj: usize| p[(j + dj) * (k + 1) + i + di];
            let (a, b, c, d) = (at(0, 0), at(1, 0), at(1, 1), at(0, 1));
            let halves = if rng.gen_bool(0.5) { [[a, b, c], [a, c, d]] } else { [[a, b, d], [b, c, d]] };
            for h in halves {
                let (z, rgb) = (mesh_z(tris.len()), random_rgb(&mut rng));
                let mut t = h.map(|(x, y)| v(x, y, z, rgb));
                if rng.gen_bool(0.5) {
                    t.swap(1, 2);
                }
                tris.push(t);
            }
        }
    }
    list(128, 128, tris)
}
