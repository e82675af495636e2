//! The shared-edge invariant as properties: random fans and grids at arbitrary subpixel
//! positions (`stability::geometry::{fan, grid}`), drawn by every method at the default
//! formats and at 2 subpixel bits, paint every pixel of their union exactly once: no hole,
//! no double hit, no pixel outside. Each triangle of a mesh is nearer than all before it,
//! so every fragment passes the depth test and a pixel drawn twice is written twice.
//! Scanline and vector draw every mesh at both formats; the shading engines, ten times
//! slower (cycle by cycle), a quarter of them at the default formats (their spans are the
//! scanline pipeline's). As every random test of edgepaint, the cases come from
//! `EDGEPAINT_SEED` (default 1) and `EDGEPAINT_N` (default 1000: 100 fans of 8 to 255
//! triangles and 100 grids of 8 to 512, about 900 renders; the soak's 10,000 make ten
//! times as many).

use fx::Formats;
use proptest::prelude::*;
use scene::Trilist;
use stability::cell::measure;
use stability::geometry::{fan, grid};
use sweep::grid::Method;

/// The default formats of a 128 x 128 screen, and the same at 2 subpixel bits.
fn formats() -> [Formats; 2] {
    let narrow = Formats::with_overrides(128, 128, &serde_json::json!({"xy": "S11.2 half-up"}));
    [Formats::for_resolution(128, 128), narrow.expect("2 subpixel bits hold a 128 x 128 screen")]
}

/// Scanline and vector at both formats, the shading engines at the default formats when
/// `se`: the mesh's union painted once, as the reference paints it.
fn painted_once(list: &Trilist, se: bool) -> Result<(), TestCaseError> {
    let [default, narrow] = formats();
    let runs =
        [(Method::Scanline, default), (Method::Vector, default), (Method::Scanline, narrow), (Method::Vector, narrow)];
    for (m, f) in runs.into_iter().chain(se.then_some((Method::Se, default))) {
        let r = measure(list, m, f, true).map_err(TestCaseError::fail)?;
        let what = format!("{m:?} at {}: {r:?}", f.xy);
        prop_assert!(r.pixels_reference > 2000, "{}", what);
        prop_assert_eq!((r.holes, r.double_hits, r.spills(), r.problems), (0, Some(0), 0, 0), "{}", what);
    }
    Ok(())
}

/// `EDGEPAINT_N` / 10 cases per property from seed `EDGEPAINT_SEED`, nothing persisted.
fn config() -> ProptestConfig {
    let var = |name: &str, default: u64| std::env::var(name).ok().and_then(|s| s.parse().ok()).unwrap_or(default);
    ProptestConfig {
        cases: (var("EDGEPAINT_N", 1000) / 10) as u32,
        rng_seed: proptest::test_runner::RngSeed::Fixed(var("EDGEPAINT_SEED", 1)),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn random_fans_paint_their_union_once(n in 8usize..256, seed in any::<u64>()) {
        let list = fan(n, seed);
        prop_assert!(list.triangles.len() >= 8);
        painted_once(&list, seed % 4 == 0)?;
    }

    #[test]
    fn random_grids_paint_their_union_once(n in 8usize..512, seed in any::<u64>()) {
        painted_once(&grid(n, seed), seed % 4 == 0)?;
    }
}

/// The counting can fail: a fan with its first triangle drawn again, nearer than the rest,
/// has as many double hits as that triangle covers pixel centres (those within one `xy` LSB,
/// 1/16 px, of its edges go either way: snapping moves its centre vertex), and no hole.
#[test]
fn a_triangle_drawn_twice_is_counted_as_double_hits() {
    use scene::measure::{edge_distance, inside};
    let mut list = fan(16, 7);
    let mut again = list.triangles[0];
    for v in &mut again {
        v.z = 0.1;
    }
    list.triangles.push(again);
    let centres = (0..128 * 128).map(|i| ((i % 128) as f64 + 0.5, (i / 128) as f64 + 0.5));
    let strictly =
        centres.clone().filter(|&(x, y)| inside(&again, x, y) && edge_distance(&again, x, y) > 1.0 / 16.0).count();
    let at_most = centres.filter(|&(x, y)| inside(&again, x, y) || edge_distance(&again, x, y) <= 1.0 / 16.0).count();
    assert!(strictly > 50, "{strictly}");
    for m in Method::ALL {
        let r = measure(&list, m, Formats::for_resolution(128, 128), true).unwrap();
        let hits = r.double_hits.unwrap() as usize;
        assert!(
            (strictly..=at_most).contains(&hits) && r.holes == 0,
            "{m:?}: {hits} not in {strictly}..={at_most}: {r:?}"
        );
    }
}
