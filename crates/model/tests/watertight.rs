//! Watertightness in fixed point, at default formats: every pixel of a union of
//! triangles that share edges is hit exactly once, for both methods.

use fx::Formats;
use model::cull_sort::{Clip, Cull};
use model::render::{triangle, Method, Options};
use scene::stress::{fan, random_mesh, split_rectangle};
use scene::Triangle;

const METHODS: [Method; 2] = [Method::Scanline, Method::Vector { lanes: 4, perspective: false }];

fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

/// Hits per pixel through the fixed-point pipeline at default formats.
fn hits(tris: &[Triangle], w: u32, h: u32, method: Method) -> Vec<u32> {
    let f = Formats::for_resolution(w, h);
    let opts = Options { method, cull: Cull::None, analysis: true, background: [0; 3] };
    let mut count = vec![0u32; (w * h) as usize];
    for t in tris {
        if let Ok(tr) = triangle(t, Clip { width: w, height: h }, &f, &opts).0 {
            for p in tr.pixels {
                count[(p.y * w + p.x) as usize] += 1;
            }
        }
    }
    count
}

#[test]
fn model_shared_edges_through_pixel_centres_paint_the_union_once() {
    for m in METHODS {
        for (a, b) in [((1.5, 1.5), (9.5, 9.5)), ((0.5, 2.5), (20.5, 12.5)), ((3.5, 1.5), (5.5, 17.5))] {
            for flip in [false, true] {
                let count = hits(&split_rectangle(a, b, flip), 32, 32, m);
                for (i, &c) in count.iter().enumerate() {
                    let (cx, cy) = ((i % 32) as f64 + 0.5, (i / 32) as f64 + 0.5);
                    let want = u32::from(cx >= a.0 && cx < b.0 && cy >= a.1 && cy < b.1);
                    assert_eq!(c, want, "{m:?} {a:?}-{b:?} flip={flip}: pixel ({cx}, {cy})");
                }
            }
        }
    }
}

#[test]
fn model_fan_of_32_thin_triangles_leaves_no_hole_and_no_double_hit() {
    for m in METHODS {
        for centre in [(32.5, 32.5), (31.3, 33.7)] {
            let (tris, ring) = fan(centre, 28.0, 32);
            let count = hits(&tris, 64, 64, m);
            for (i, &c) in count.iter().enumerate() {
                let s = ((i % 64) as f64 + 0.5, (i / 64) as f64 + 0.5);
                // The ring's vertices are on the 1/16 grid, so the fixed-point ring is
                // exact: a centre strictly inside is hit once, strictly outside never.
                let side = (0..ring.len())
                    .map(|k| {
                        let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                        (b.0 - a.0) * (s.1 - a.1) - (b.1 - a.1) * (s.0 - a.0)
                    })
                    .fold(f64::INFINITY, f64::min);
                assert!(c <= 1, "{m:?} centre {centre:?}: ({}, {}) hit {c} times", s.0, s.1);
                if side > 0.0 {
                    assert_eq!(c, 1, "{m:?} centre {centre:?}: hole at ({}, {})", s.0, s.1);
                } else if side < 0.0 {
                    assert_eq!(c, 0, "{m:?} centre {centre:?}: ({}, {}) outside painted", s.0, s.1);
                }
            }
        }
    }
}

#[test]
fn model_random_2x2_mesh_covers_the_screen_exactly_once() {
    for m in METHODS {
        for k in 0..10 {
            let count = hits(&random_mesh(seed() + k, 48, 32), 48, 32, m);
            for (i, &c) in count.iter().enumerate() {
                assert_eq!(c, 1, "{m:?} seed {}: pixel ({}, {}) hit {c} times", seed() + k, i % 48, i / 48);
            }
        }
    }
}
