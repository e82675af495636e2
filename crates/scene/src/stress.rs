//! Triangle sets that stress a rasterizer's fill rule: shared edges through
//! pixel centres, a fan of thin triangles, and a random mesh of small triangles
//! covering the screen. Every rasterizer in edgepaint must paint each pixel of
//! such a union exactly once (the dEQP fill_rules idea: count hits per pixel).

use crate::{Triangle, Vertex};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn v(x: f64, y: f64, rgb: [f64; 3]) -> Vertex {
    Vertex::new(x, y, 0.5, rgb)
}

/// Two triangles splitting the rectangle `a`-`b` along its diagonal, one with
/// its winding flipped when `flip`. Choose corners on pixel centres so that
/// all four sides and the shared diagonal run through centres.
pub fn split_rectangle(a: (f64, f64), b: (f64, f64), flip: bool) -> [Triangle; 2] {
    let (x0, y0, x1, y1) = (a.0, a.1, b.0, b.1);
    let mut t1 = [v(x0, y0, [200.0, 0.0, 0.0]), v(x1, y1, [0.0, 200.0, 0.0]), v(x0, y1, [0.0, 0.0, 200.0])];
    let t2 = [v(x0, y0, [200.0, 0.0, 0.0]), v(x1, y0, [90.0, 90.0, 0.0]), v(x1, y1, [0.0, 200.0, 0.0])];
    if flip {
        t1.swap(1, 2);
    }
    [t1, t2]
}

/// `n` thin triangles around `centre`, out to `radius`, ring vertices snapped to
/// 1/16 pixel so that many edges pass exactly through pixel centres. Returns the
/// triangles and the ring (a convex polygon, in order).
pub fn fan(centre: (f64, f64), radius: f64, n: usize) -> (Vec<Triangle>, Vec<(f64, f64)>) {
    let snap = |t: f64| (t * 16.0).round() / 16.0;
    let ring: Vec<(f64, f64)> = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            (snap(centre.0 + radius * a.cos()), snap(centre.1 + radius * a.sin()))
        })
        .collect();
    let tris = (0..n)
        .map(|k| {
            let (p, q) = (ring[k], ring[(k + 1) % n]);
            let c = 255.0 * k as f64 / n as f64;
            [v(centre.0, centre.1, [c, 0.0, 255.0 - c]), v(p.0, p.1, [0.0, c, 0.0]), v(q.0, q.1, [255.0, c, 0.0])]
        })
        .collect();
    (tris, ring)
}

/// A mesh of roughly 2x2-pixel triangles covering the whole `w` x `h` screen
/// (w and h even). Interior vertices are jittered by multiples of 1/4 px, so
/// edges and vertices land on pixel centres often; border vertices stay on the
/// border. Each quad is split along a random diagonal and each triangle gets a
/// random winding and random colours.
pub fn random_mesh(seed: u64, w: u32, h: u32) -> Vec<Triangle> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
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
                let mut col = || rng.gen_range(0.0..=255.0);
                tris.push(t.map(|q| v(q.0, q.1, [col(), col(), col()])));
            }
        }
    }
    tris
}
