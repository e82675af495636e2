//! Fill-rule tests in the manner of dEQP's fill_rules: draw triangles that share
//! edges, count hits per pixel (additive blending), and require every pixel of
//! the union exactly once.

use reference::{fragments, Options};
use scene::stress::{fan, random_mesh, split_rectangle};
use scene::Triangle;

/// Hits per pixel over a set of triangles, ignoring depth (additive blending).
fn hits(tris: &[Triangle], w: u32, h: u32) -> Vec<u32> {
    let mut count = vec![0u32; (w * h) as usize];
    for t in tris {
        fragments(t, w, h, &Options::default(), |f| count[(f.y * w + f.x) as usize] += 1);
    }
    count
}

fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

#[test]
fn reference_shared_edge_through_pixel_centres_paints_union_once() {
    // Squares split along diagonals that run through pixel centres, with
    // outer edges on pixel centres too: every tie the rule has to break.
    for (a, b) in [((1.5, 1.5), (9.5, 9.5)), ((0.5, 2.5), (20.5, 12.5)), ((3.5, 1.5), (5.5, 17.5))] {
        let (x0, y0, x1, y1) = (a.0, a.1, b.0, b.1);
        for flip in [false, true] {
            let count = hits(&split_rectangle(a, b, flip), 32, 32);
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
        let (tris, ring) = fan(centre, 28.0, n);
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

#[test]
fn reference_random_2x2_mesh_covers_screen_exactly_once() {
    for k in 0..20 {
        let tris = random_mesh(seed() + k, 48, 32);
        let count = hits(&tris, 48, 32);
        for (i, &c) in count.iter().enumerate() {
            assert_eq!(c, 1, "seed {}: pixel ({}, {}) hit {c} times", seed() + k, i % 48, i / 48);
        }
    }
}
