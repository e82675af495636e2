//! Fill-rule tests in the manner of dEQP's fill_rules: draw triangles that share
//! edges, count hits per pixel (additive blending), and require every pixel of
//! the union exactly once.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use reference::{fragments, Options};
use scene::{Triangle, Vertex};

fn v(x: f64, y: f64) -> Vertex {
    Vertex::new(x, y, 0.5, [0.0, 0.0, 0.0])
}

/// Hits per pixel over a set of triangles, ignoring depth (additive blending).
fn hits(tris: &[Triangle], w: u32, h: u32) -> Vec<u32> {
    let mut count = vec![0u32; (w * h) as usize];
    for t in tris {
        fragments(t, w, h, &Options::default(), |f| count[(f.y * w + f.x) as usize] += 1);
    }
    count
}

pub fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

#[test]
fn reference_shared_edge_through_pixel_centres_paints_union_once() {
    // Squares split along diagonals that run through pixel centres, with
    // outer edges on pixel centres too: every tie the rule has to break.
    for (a, b) in [((1.5, 1.5), (9.5, 9.5)), ((0.5, 2.5), (20.5, 12.5)), ((3.5, 1.5), (5.5, 17.5))] {
        let (x0, y0, x1, y1) = (a.0, a.1, b.0, b.1);
        for flip in [false, true] {
            let mut t1 = [v(x0, y0), v(x1, y1), v(x0, y1)];
            let t2 = [v(x0, y0), v(x1, y0), v(x1, y1)];
            if flip {
                t1.swap(1, 2); // winding must not matter
            }
            let count = hits(&[t1, t2], 32, 32);
            for py in 0..32u32 {
                for px in 0..32u32 {
                    let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
                    // The union is the rectangle, closed on its left and top, open on its right and bottom.
                    let want = u32::from(cx >= x0 && cx < x1 && cy >= y0 && cy < y1);
                    assert_eq!(
                        count[(py * 32 + px) as usize],
                        want,
                        "square {a:?}-{b:?} flip={flip}: pixel ({px},{py})"
                    );
                }
            }
        }
    }
}

#[test]
fn reference_fan_of_32_thin_triangles_leaves_no_hole_and_no_double_hit() {
    // Centres on a pixel centre and off it; vertices snapped to 1/16 px so that
    // many edges pass exactly through pixel centres.
    for centre in [(32.5, 32.5), (31.3, 33.7)] {
        let n = 32;
        let ring: Vec<(f64, f64)> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                let snap = |t: f64| (t * 16.0).round() / 16.0;
                (snap(centre.0 + 28.0 * a.cos()), snap(centre.1 + 28.0 * a.sin()))
            })
            .collect();
        let tris: Vec<Triangle> = (0..n)
            .map(|k| [v(centre.0, centre.1), v(ring[k].0, ring[k].1), v(ring[(k + 1) % n].0, ring[(k + 1) % n].1)])
            .collect();
        let count = hits(&tris, 64, 64);
        assert!(count.iter().all(|&c| c <= 1), "centre {centre:?}: a pixel was hit twice");
        // Independent oracle: a centre strictly inside the convex polygon (by more
        // than rounding) must be hit once; one outside must not be hit.
        for py in 0..64u32 {
            for px in 0..64u32 {
                let s = (px as f64 + 0.5, py as f64 + 0.5);
                let side = (0..n)
                    .map(|k| {
                        let (a, b) = (ring[k], ring[(k + 1) % n]);
                        let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
                        ((b.0 - a.0) * (s.1 - a.1) - (b.1 - a.1) * (s.0 - a.0)) / len
                    })
                    .fold(f64::INFINITY, f64::min);
                let c = count[(py * 64 + px) as usize];
                if side > 1e-9 {
                    assert_eq!(c, 1, "centre {centre:?}: hole at ({px},{py})");
                } else if side < -1e-9 {
                    assert_eq!(c, 0, "centre {centre:?}: ({px},{py}) outside the fan was painted");
                }
            }
        }
    }
}

/// A mesh of roughly 2x2-pixel triangles covering the whole `w` x `h` screen.
/// Interior vertices are jittered by multiples of 1/4 px (so edges and vertices
/// land on pixel centres often); border vertices slide only along the border.
/// Each quad is split along a random diagonal and each triangle gets a random winding.
pub fn random_mesh(rng: &mut ChaCha8Rng, w: u32, h: u32) -> Vec<Triangle> {
    let (nx, ny) = (w / 2, h / 2);
    let mut p = vec![(0.0, 0.0); ((nx + 1) * (ny + 1)) as usize];
    for j in 0..=ny {
        for i in 0..=nx {
            let mut jitter = || rng.gen_range(-2i32..=2) as f64 * 0.25;
            let x = if i == 0 || i == nx { (2 * i) as f64 } else { (2 * i) as f64 + jitter() };
            let y = if j == 0 || j == ny { (2 * j) as f64 } else { (2 * j) as f64 + jitter() };
            p[(j * (nx + 1) + i) as usize] = (x, y);
        }
    }
    let mut tris = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let at = |a: u32, b: u32| p[(b * (nx + 1) + a) as usize];
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            let halves = if rng.gen() { [[a, b, c], [a, c, d]] } else { [[a, b, d], [b, c, d]] };
            for mut t in halves {
                if rng.gen() {
                    t.swap(1, 2);
                }
                tris.push(t.map(|q| v(q.0, q.1)));
            }
        }
    }
    tris
}

#[test]
fn reference_random_2x2_mesh_covers_screen_exactly_once() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    for _ in 0..20 {
        let tris = random_mesh(&mut rng, 48, 32);
        let count = hits(&tris, 48, 32);
        for (i, &c) in count.iter().enumerate() {
            assert_eq!(c, 1, "seed {}: pixel ({}, {}) hit {c} times", seed(), i % 48, i / 48);
        }
    }
}
