//! The fixed-point pipelines against the float reference, triangle by triangle.

mod common;

use common::{agree, count, seed, wide_tolerance, Case, METHODS};
use fx::Formats;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use scene::{Triangle, Vertex};

fn random_triangle(rng: &mut ChaCha8Rng, w: u32, h: u32, with_w: bool) -> Triangle {
    let mut v = || {
        let mut v = Vertex::new(
            rng.gen_range(-0.3 * w as f64..1.3 * w as f64),
            rng.gen_range(-0.3 * h as f64..1.3 * h as f64),
            rng.gen_range(-0.2..1.2),
            [rng.gen_range(0.0..=255.0), rng.gen_range(0.0..=255.0), rng.gen_range(0.0..=255.0)],
        );
        if with_w {
            v.w = Some(rng.gen_range(0.5..4.0));
        }
        v
    };
    [v(), v(), v()]
}

#[test]
fn model_wide_formats_match_the_reference_on_random_triangles() {
    let size = (96, 64);
    let f = Formats::wide(size.0, size.1);
    let tol = wide_tolerance(&f);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    for i in 0..count() / 4 {
        let t = random_triangle(&mut rng, size.0, size.1, i % 2 == 1);
        for method in METHODS {
            agree(&Case { t: &t, size, f: &f, method }, &tol)
                .unwrap_or_else(|e| panic!("seed {} case {i} {method:?}: {e}\n{t:?}", seed()));
        }
    }
}
