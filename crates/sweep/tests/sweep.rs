//! The sweep end to end on a shipped scene: shards merge to the unsharded run, and a
//! cached result is read back rather than recomputed.

use std::path::PathBuf;
use sweep::grid::Grid;
use sweep::run::{run, Input, Options};

/// `scenes/<name>.json` at `w` x `h`.
fn input(name: &str, w: u32, h: u32) -> Input {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes")).join(format!("{name}.json"));
    Input::scene(&path, w, h).expect("a shipped scene loads")
}

/// A small grid: both methods, two knobs, a joint sample.
fn grid() -> Grid {
    Grid::parse(r#"{"sensitivity": {"xy.frac": [2, 6], "K": [1], "lanes": [1]}, "joint": {"samples": 2, "seed": 3}}"#)
        .expect("a valid grid")
}

#[test]
fn sweep_shards_merge_to_the_unsharded_run() {
    let inputs = [input("cube", 48, 32), input("cone", 40, 30)];
    let points = grid().points();
    let whole = run(&inputs, &points, &Options::default(), &|| {}).unwrap().rows;
    assert_eq!(whole.len(), inputs.len() * points.len());
    let dirs: Vec<tempfile::TempDir> = (0..3)
        .map(|i| {
            let d = tempfile::tempdir().unwrap();
            let rows =
                run(&inputs, &points, &Options { shard: Some((i, 3)), ..Options::default() }, &|| {}).unwrap().rows;
            assert!(rows.len() < whole.len());
            sweep::store::write(d.path(), &rows).unwrap();
            d
        })
        .collect();
    let merged = sweep::store::merge(&dirs.iter().map(tempfile::TempDir::path).collect::<Vec<_>>()).unwrap();
    assert_eq!(merged, whole);
    // Coarser subpixels cost accuracy: the sweep sees what the formats do.
    let err =
        |point: &str| whole.iter().find(|r| r.scene == "cube" && r.method == "scanline" && r.point == point).unwrap();
    let (coarse, fine) = (err("xy.frac=2"), err("xy.frac=6"));
    assert!(coarse.psnr_db < fine.psnr_db && coarse.coverage_differs > fine.coverage_differs);
    // One multiplier in setup: slower, as accurate.
    let (k1, d) = (err("K=1"), err("default"));
    assert!(k1.cycles > d.cycles && k1.psnr_db == d.psnr_db);
}

#[test]
fn sweep_reads_a_cached_result_back() {
    let inputs = [input("cube", 32, 24)];
    let points = &grid().points()[..3];
    let cache = tempfile::tempdir().unwrap();
    let opts = Options { cache: Some(cache.path().to_path_buf()), ..Options::default() };
    let first = run(&inputs, points, &opts, &|| {}).unwrap().rows;
    // Mark every cached result: a second run returns the marks, so it measured nothing.
    for f in std::fs::read_dir(cache.path()).unwrap() {
        let path = f.unwrap().path();
        let mut row: sweep::row::Row = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        row.psnr_db = -1.0;
        std::fs::write(&path, serde_json::to_string(&row).unwrap()).unwrap();
    }
    let second = run(&inputs, points, &opts, &|| {}).unwrap().rows;
    assert_eq!(second.len(), first.len());
    assert!(second.iter().all(|r| r.psnr_db == -1.0));
    assert!(first.iter().all(|r| r.psnr_db > 0.0));
}

#[test]
fn sweep_skips_what_the_shading_engines_cannot_draw() {
    let g = Grid::parse(r#"{"methods": ["se"], "sensitivity": {"z.frac": [16, 24]}}"#).unwrap();
    let swept = run(&[input("cube", 48, 32)], &g.points(), &Options::default(), &|| {}).unwrap();
    let points: Vec<&str> = swept.rows.iter().map(|r| r.point.as_str()).collect();
    assert_eq!(points, ["default", "z.frac=16"]);
    assert_eq!(swept.skipped.len(), 1);
    let s = &swept.skipped[0];
    assert!(s.starts_with("cube: point se z.frac=24") && s.contains("2 to 32 bits"), "{s}");
    // The engines draw what the scanline pipeline draws, to within their rounding.
    assert!(swept.rows.iter().all(|r| r.problems == 0 && r.psnr_db > 30.0));
}

/// Cost and clock: measured at the default design (Yosys' raster_top among the calibration
/// samples, the routed clock), modelled at a design never built; the vector method's at one
/// lane and the default formats (its pipeline in RTL, measured), modelled at 2, 4 and 8
/// lanes there, absent at other vector points (no area model covers the vector unit at other
/// formats).
#[test]
fn sweep_rows_carry_cost_and_clock_measured_or_modelled() {
    use sweep::area::{Model, PIPELINE};
    use sweep::row::Source;
    let swept = run(&[input("cube", 48, 32)], &grid().points(), &Options::default(), &|| {}).unwrap();
    let row = |method: &str, point: &str| {
        swept.rows.iter().find(|r| r.method == method && r.point == point).unwrap_or_else(|| panic!("{method} {point}"))
    };
    let default = row("scanline", "default");
    let n10 = Model::calibrated().samples.iter().find(|s| s.build == "n10" && s.unit == PIPELINE).unwrap();
    assert_eq!((default.cost, default.cost_source), (Some(n10.cost), Some(Source::Measured)));
    assert_eq!((default.clock_mhz, default.clock_source), (Some(sweep::clock::PIPELINE_MHZ), Some(Source::Measured)));
    assert_eq!(default.frame_us, Some(default.cycles as f64 / sweep::clock::PIPELINE_MHZ));
    // One multiplier instead of 7: fewer DSP blocks, modelled; the same widths, the same clock.
    let k1 = row("scanline", "K=1");
    let (c1, c7) = (k1.cost.unwrap(), default.cost.unwrap());
    assert_eq!(k1.cost_source, Some(Source::Modelled));
    assert!(c1.ecp5_dsp < c7.ecp5_dsp && c1.ge < c7.ge, "{c1:?} {c7:?}");
    assert_eq!((k1.clock_mhz, k1.clock_source), (Some(sweep::clock::PIPELINE_MHZ), Some(Source::Modelled)));
    // 6 subpixel bits with every other quantity wide: a larger, slower design.
    let wide = row("scanline", "xy.frac=6");
    assert!(wide.cost.unwrap().ge > c7.ge && wide.clock_mhz.unwrap() < sweep::clock::PIPELINE_MHZ);
    let one_lane = row("vector", "lanes=1");
    assert_eq!((one_lane.cost, one_lane.cost_source), (Some(sweep::area::VECTOR_PIPELINE), Some(Source::Measured)));
    let mhz = sweep::clock::VECTOR_PIPELINE_MHZ;
    assert_eq!((one_lane.clock_mhz, one_lane.frame_us), (Some(mhz), Some(one_lane.cycles as f64 / mhz)));
    // More lanes at the default formats (the vector default: 4): a lane and a pixel_out bank
    // more each, modelled, at the clock routed at four lanes or modelled at two and eight;
    // lanes the RTL is not built with, and other formats, unpriced.
    let four = row("vector", "default");
    assert_eq!((four.params["lanes"], four.cost_source), (4, Some(Source::Modelled)));
    let lane = sweep::area::VECTOR_LANE;
    for r in swept.rows.iter().filter(|r| r.method == "vector" && r.point != "lanes=1") {
        let l = r.params["lanes"];
        if [2, 4, 8].contains(&l) && r.formats == four.formats {
            let c = sweep::area::vector_pipeline(l).unwrap();
            let clock = sweep::clock::vector_pipeline_mhz(l).unwrap();
            assert_eq!((r.cost, r.cost_source), (Some(c), Some(Source::Modelled)));
            assert_eq!((r.clock_mhz, r.clock_source), (Some(clock.0), Some(clock.1)));
            assert_eq!(clock.1 == Source::Measured, l == 4, "lanes {l}");
            assert_eq!(c.ecp5_dsp, sweep::area::VECTOR_PIPELINE.ecp5_dsp + (l - 1) as f64 * lane.ecp5_dsp);
        } else {
            assert_eq!((r.cost, r.clock_mhz, r.frame_us), (None, None, None), "{} {}", r.method, r.point);
        }
    }
}

/// The SE method is priced with the fewest engines that cover the screen: synthesized at
/// one engine (up to 64 columns; its clock routed) and five (65 to 320), modelled at 16 (up
/// to 1,024), at the default formats. Its cycles are the whole SE back end's
/// (`model::cycles::se_frame`).
#[test]
fn sweep_prices_the_se_back_end_by_its_engines() {
    use sweep::area::{se_engine, SE_PIPELINE_1, SE_PIPELINE_5};
    use sweep::clock::SE_PIPELINE_MHZ;
    use sweep::grid::Method;
    use sweep::row::Source;
    let points: Vec<_> =
        grid().points().into_iter().filter(|p| p.method == Method::Se && p.name == "default").collect();
    assert_eq!(points.len(), 1);
    let m = Some(Source::Measured);
    let sixteen = SE_PIPELINE_5.ecp5_lut4 + 11.0 * se_engine().ecp5_lut4;
    for (w, h, cost, cost_source, clock_source) in [
        (48, 32, SE_PIPELINE_1.ecp5_lut4, m, m),
        (64, 48, SE_PIPELINE_1.ecp5_lut4, m, m),
        (65, 48, SE_PIPELINE_5.ecp5_lut4, m, Some(Source::Modelled)),
        (320, 240, SE_PIPELINE_5.ecp5_lut4, m, Some(Source::Modelled)),
        (640, 32, sixteen, Some(Source::Modelled), Some(Source::Modelled)),
    ] {
        let swept = run(&[input("cube", w, h)], &points, &Options::default(), &|| {}).unwrap();
        let r = &swept.rows[0];
        assert_eq!(r.cost.map(|c| c.ecp5_lut4), Some(cost), "{w}x{h}");
        assert_eq!((r.cost_source, r.clock_source), (cost_source, clock_source), "{w}x{h}");
        assert_eq!(r.frame_us, Some(r.cycles as f64 / SE_PIPELINE_MHZ), "{w}x{h}");
        assert!(r.cycles > 136 * 10, "{w}x{h}: {} cycles", r.cycles);
    }
    // An engine more costs logic, flip-flops and no multiplier (the engines' are serial).
    let e = se_engine();
    assert!(e.ecp5_lut4 > 1_000.0 && e.ecp5_ff > 0.0 && e.ecp5_dsp == 0.0, "{e:?}");
}
