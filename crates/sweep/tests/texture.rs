//! The texture sweep (`sweep::texture`) end to end on a shipped textured scene: a knob
//! below Vulkan 1.0's minimum fails where the default passes, a larger cache hits more
//! often and takes fewer cycles, the charts carry Vulkan's and Roadmap 2022's rules, and a
//! bad grid is an error naming what is wrong.

use scene::Scene;
use std::path::Path;
use sweep::row::Source;
use sweep::texture::{charts, run, Knob, TexGrid, TexInput};

fn crate_scene() -> TexInput {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/textured/crate.json");
    TexInput { name: "crate".into(), list: Scene::load(&p).unwrap().to_trilist().unwrap() }
}

#[test]
fn the_texture_sweep_measures_error_area_hit_rate_and_frame_time() {
    let grid = TexGrid::parse(
        r#"{"sensitivity": {"subtexel": [2, 4], "lod_frac": [4]}, "joint": {},
            "caches": [[16, 1, 4], [64, 2, 4], [256, 4, 16]], "mem_latency": 8}"#,
    )
    .unwrap();
    let rows = run(&[crate_scene()], &grid, 0, &|| {}).unwrap();
    assert_eq!(rows.len(), 4 * 3, "default + 3 sensitivity points, 3 geometries");
    let at = |point: &str, sets: u32| rows.iter().find(|r| r.point == point && r.sets == sets).unwrap();
    let (d, coarse) = (at("default", 64), at("subtexel=2", 64));
    assert_eq!(d.failures, 0);
    assert!(coarse.failures > 0 && coarse.psnr_db < d.psnr_db, "{coarse:?}");
    // The default design at a synthesized geometry is all Yosys; fewer sub-texel bits are
    // modelled, and cost less.
    assert_eq!(d.cost_source, Source::Measured);
    assert!(coarse.cost_source == Source::Modelled && coarse.cost.lut4 < d.cost.lut4);
    // The cache: larger hits more, and the frame takes fewer cycles; every access is a cycle.
    let (small, large) = (at("default", 16), at("default", 256));
    assert!(small.hit_rate < d.hit_rate && d.hit_rate < large.hit_rate);
    assert!(small.frame_cycles > d.frame_cycles && d.frame_cycles > large.frame_cycles);
    assert!(large.frame_cycles > large.accesses && large.accesses >= large.fragments);
    // A missing lane: its line of 4 words, the latency of 8 and 2 (`Params::miss_penalty`).
    assert_eq!(d.frame_cycles, d.accesses + d.misses * (4 + 8 + 2));

    let charts = charts(&rows);
    let stems: Vec<&str> = charts.iter().map(|c| c.stem.as_str()).collect();
    assert_eq!(
        stems,
        [
            "texture_error_vs_area",
            "texture_hit_rate_vs_cache",
            "texture_frame_vs_cache",
            "texture_sensitivity_subtexel",
            "texture_sensitivity_lod_frac"
        ]
    );
    let sub = &charts[3];
    let rules: Vec<(f64, &str)> = sub.rules.iter().map(|r| (r.x, r.label.as_str())).collect();
    assert_eq!(rules, [(4.0, "subtexel Vulkan 1.0 minimum (4)"), (8.0, "subtexel Roadmap 2022 (8)")]);
    assert_eq!(Knob::LodFrac.requirements(), [(4, "Vulkan 1.0 minimum (4)"), (6, "Roadmap 2022 (6)")]);
    let tmp = tempfile::tempdir().unwrap();
    for c in &charts {
        sweep::chart::draw(c, tmp.path()).unwrap();
        assert!(
            tmp.path().join(format!("{}.png", c.stem)).exists() && tmp.path().join(format!("{}.svg", c.stem)).exists()
        );
    }
    let md = sweep::texture::report(&rows, &charts);
    assert!(md.contains("| default |") && md.contains("mean absolute error"), "{md}");
}

#[test]
fn a_bad_texture_grid_or_an_untextured_scene_is_an_error_naming_it() {
    let e = TexGrid::parse(r#"{"sensitivity": {"subtexel": [0]}}"#).unwrap_err();
    assert!(e.contains("point subtexel=0") && e.contains("subtexel = 0"), "{e}");
    let e = TexGrid::parse(r#"{"caches": [[48, 2, 4]]}"#).unwrap_err();
    assert!(e.contains("SETS = 48"), "{e}");
    assert!(TexGrid::parse(r#"{"knobs": []}"#).unwrap_err().contains("unknown field"));
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/cube.json");
    let plain = TexInput { name: "cube".into(), list: Scene::load(&cube).unwrap().to_trilist().unwrap() };
    let e = run(&[plain], &TexGrid::default(), 0, &|| {}).unwrap_err();
    assert!(e.contains("cube: no textured triangle"), "{e}");
}
