//! `fit::parts`: the optional parts of the fitted design follow the workload. Whether the
//! RTL without them still draws such workloads as the model does is
//! `testbenches/tests/raster_top.rs`, `raster_top_without_optional_parts_vs_model`.

use fit::parts::needed;
use rtl::switch::Parts;
use scene::{Trilist, Vertex};
use std::path::PathBuf;
use sweep::run::Input;

/// `scenes/<name>.json` at its own size.
fn shipped(name: &str) -> Input {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes")).join(format!("{name}.json"));
    let s = scene::Scene::load(&path).expect("a shipped scene loads");
    Input::scene(&path, s.width, s.height).expect("a shipped scene loads")
}

/// A workload of triangles given as (x, y, z) corners on a 64 x 48 screen.
fn triangles(cull_back: bool, tris: &[[(f64, f64, f64); 3]]) -> Input {
    let triangles = tris.iter().map(|t| t.map(|(x, y, z)| Vertex::new(x, y, z, [200.0, 100.0, 50.0]))).collect();
    Input {
        name: "t".into(),
        key: 0,
        trilist: Trilist { width: 64, height: 48, triangles, textures: Vec::new() },
        background: [0.0; 3],
        cull_back,
    }
}

const NONE: Parts = Parts { cull: false, clip_y: false, clip_x: false, clip_z: false, depth_test: false };

fn formats() -> fx::Formats {
    fx::Formats::for_n(10)
}

#[test]
fn a_workload_inside_the_screen_needs_no_clipping_culling_or_depth_test() {
    // Two triangles sharing an edge, counter-clockwise (front faces), inside the screen.
    let w = triangles(
        true,
        &[
            [(2.0, 2.0, 0.5), (2.0, 40.0, 0.5), (60.0, 2.0, 0.5)],
            [(60.0, 2.0, 0.5), (2.0, 40.0, 0.5), (60.0, 40.0, 0.5)],
        ],
    );
    let n = needed(&[w], &formats());
    assert_eq!(n.parts, NONE, "{n:?}");
    assert!(n.why.is_empty());
}

#[test]
fn each_part_is_kept_for_what_uses_it() {
    let f = formats();
    let on_screen = [(2.0, 2.0, 0.5), (2.0, 40.0, 0.5), (60.0, 2.0, 0.5)];
    let case = |cull_back: bool, t: [(f64, f64, f64); 3]| needed(&[triangles(cull_back, &[on_screen, t])], &f).parts;
    // A back face, culled.
    assert_eq!(case(true, [(10.0, 30.0, 0.5), (30.0, 20.0, 0.5), (10.0, 45.0, 0.5)]), Parts { cull: true, ..NONE });
    // Across the left edge, beyond the bottom, beyond the far plane.
    assert!(case(false, [(-5.0, 30.0, 0.5), (10.0, 45.0, 0.5), (20.0, 30.0, 0.5)]).clip_x);
    assert!(case(false, [(10.0, 30.0, 0.5), (10.0, 60.0, 0.5), (20.0, 30.0, 0.5)]).clip_y);
    assert!(case(false, [(10.0, 30.0, 0.5), (10.0, 45.0, 1.5), (20.0, 30.0, 0.5)]).clip_z);
    // Drawn over the first triangle: the depth test decides.
    assert!(case(false, [(4.0, 4.0, 0.3), (4.0, 20.0, 0.3), (20.0, 4.0, 0.3)]).depth_test);
}

/// The shipped scenes: `clip.json` crosses the screen and the near plane, the others stay
/// inside the screen and overlap.
#[test]
fn shipped_scenes_keep_what_they_use() {
    let clip = needed(&[shipped("clip")], &formats());
    assert!(clip.parts.clip_x && clip.parts.clip_y && clip.parts.clip_z && clip.parts.depth_test, "{clip:?}");
    let knot = needed(&[shipped("knot")], &formats());
    assert_eq!(knot.parts, Parts { depth_test: true, ..NONE }, "{knot:?}");
    assert_eq!(knot.why, vec![("DEPTH_TEST", "knot".to_string())]);
}
