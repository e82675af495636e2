//! The whole rasterizer (`raster_top`): frames drawn in Verilator (one Verilated model for
//! every test of this module) and, for a small frame, in rust-hdl and Verilator in
//! lockstep; every image bit for bit the model's (`model::render::render`, scanline, at
//! the RTL's formats), every frame's cycle count the cycle model's.

use fx::Build;
use model::cull_sort::Cull;
use model::cycles::Timing;
use model::input::Vtx;
use model::raster_top::{self as top, raster_top, raster_top_by, raster_top_se};
use model::render::Method;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::switch::Parts;
use rust_hdl::prelude::Block;
use scene::stress::{fan, random_mesh, split_rectangle};
use scene::{Triangle, Trilist, Vertex};
use std::path::Path;
use std::process::Command;
use testbenches::frame::{self, draw, Cycle, Frame, FrameOut, MemoryModel, Report};
use testbenches::memory::{Memory, ReadDuringWrite, Request};
use testbenches::se_frame;
use testbenches::streams::{as_pins, pixel_of, unsigned};
use testbenches::{seed, Dual, Pins, Value};

/// The default `raster_top` under Verilator (the committed `hdl-out/raster_top.v`; the
/// model is built once, cached under the target directory).
fn model() -> frame::RasterTopVl {
    frame::verilator(&Build::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// `list` through the model and through `dut`; the image, depth and cycles compared.
fn check(
    what: &str,
    dut: &mut dyn Cycle,
    list: &Trilist,
    cull: Cull,
    mem: MemoryModel,
) -> (top::RasterTopOut, FrameOut) {
    check_by(Build::for_screen(list.width, list.height), Method::Scanline, what, dut, list, cull, mem)
}

/// [`check`] with `dut` the `raster_top` of build `build` and `method`.
fn check_by(
    build: Build,
    method: Method,
    what: &str,
    dut: &mut dyn Cycle,
    list: &Trilist,
    cull: Cull,
    mem: MemoryModel,
) -> (top::RasterTopOut, FrameOut) {
    let prep = raster_top_by(&build, list, cull, [20, 24, 32], method).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(prep.skipped.is_empty(), "{what}: triangles that do not fit the input formats");
    let f = Frame {
        build: prep.build,
        width: list.width,
        height: list.height,
        cull,
        background: [20, 24, 32],
        triangles: &prep.triangles,
        lanes: match method {
            Method::Vector { lanes, .. } => lanes,
            Method::Scanline => 1,
        },
    };
    let out = draw(dut, &f, mem, 50_000_000).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(out.memory.differs_from(&prep.render.fb), None, "{what}");
    assert_eq!(out.memory.writes, prep.render.stats.pixels_written, "{what}: pixels written");
    assert_eq!(out.reads.len() as u64, prep.render.stats.fragments, "{what}: fragments");
    (prep, out)
}

/// Always-ready memory, reads returning the old word.
fn ready_memory(always: &mut dyn FnMut(u64) -> bool) -> MemoryModel<'_> {
    MemoryModel { read_during_write: ReadDuringWrite::Old, ready: always }
}

fn scene(name: &str, size: Option<(u32, u32)>) -> (Trilist, Cull) {
    let path = scene::shipped::path(name);
    let mut s = scene::Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    if let Some((w, h)) = size {
        s = s.with_size(w, h).unwrap_or_else(|e| panic!("{e}"));
    }
    (s.to_trilist().unwrap_or_else(|e| panic!("{e}")), if s.cull_back { Cull::Back } else { Cull::None })
}

/// Every shipped scene at 64 x 48: the image and the cycle count equal the model's.
#[test]
fn raster_top_scenes_small_vs_model() {
    for name in ["cube", "sphere", "cone", "torus", "pawn", "house", "all", "clip"] {
        let (list, cull) = scene(name, Some((64, 48)));
        let mut dut = model();
        let (prep, out) = check(name, &mut dut, &list, cull, ready_memory(&mut |_| true));
        let r = Report::of(&out, &prep);
        assert_eq!(r.cycles, r.predicted, "{name}: cycles, RTL against model::cycles");
    }
}

/// Two scenes at 320 x 240 (003's screen), image and cycles as the model's.
#[test]
fn raster_top_scenes_320x240_vs_model() {
    for name in ["torus", "clip"] {
        let (list, cull) = scene(name, Some((320, 240)));
        let mut dut = model();
        let (prep, out) = check(name, &mut dut, &list, cull, ready_memory(&mut |_| true));
        let r = Report::of(&out, &prep);
        assert_eq!(r.cycles, r.predicted, "{name}: cycles, RTL against model::cycles");
        assert!(r.written > 1000, "{name}: {r:?}");
    }
}

/// `raster_top` with the barycentric method (`METHOD = 1`: `cull_sort`, `rtl::vector`,
/// `pixel_out`) with `lanes` lanes, perspective-correct colours, under Verilator.
fn vector_model(lanes: u32) -> frame::RasterTopVl {
    frame::verilator_with(&Build::default(), &[("METHOD", 1), ("LANES", lanes as u64)])
        .unwrap_or_else(|e| panic!("{e}"))
}

/// Every shipped scene at 64 x 48 and two at 320 x 240 drawn by the barycentric
/// `raster_top` (004) with `lanes` lanes: image, depth and cycle count the model's
/// (`Method::Vector`, `model::cycles::vector_frame`); the memory stalling too.
fn vector_scenes(lanes: u32) {
    let method = Method::Vector { lanes, perspective: true };
    let mut dut = vector_model(lanes);
    assert_eq!(dut.lanes(), lanes, "the memory port's lanes");
    let scenes = ["cube", "sphere", "cone", "torus", "pawn", "house", "all", "clip"].map(|n| (n, (64, 48)));
    for (name, size) in scenes.into_iter().chain([("torus", (320, 240)), ("clip", (320, 240))]) {
        let (list, cull) = scene(name, Some(size));
        let what = format!("{name} at {size:?}, {lanes} lanes");
        let (prep, out) = check_by(Build::default(), method, &what, &mut dut, &list, cull, ready_memory(&mut |_| true));
        let r = Report::of(&out, &prep);
        assert_eq!(r.cycles, r.predicted, "{what}: cycles, RTL against model::cycles::vector_frame");
        assert!(r.written > 0, "{what}: {r:?}");
    }
    let (list, cull) = scene("all", Some((64, 48)));
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut stalls = |_| rng.gen_bool(0.7);
    check_by(Build::default(), method, "all, stalling", &mut dut, &list, cull, ready_memory(&mut stalls));
}

/// The barycentric `raster_top` at one lane (`--engine rtl --method vector --lanes 1`; the
/// soak's: the test command draws these frames at four lanes, and a one-lane `raster_top` at
/// fitted formats proves `fit --method vector`'s choice, `cli_fit_chooses_the_barycentric_back_end_and_proves_it`).
#[test]
#[ignore = "soak: scripts/soak.sh"]
fn raster_top_vector_scenes_vs_model() {
    vector_scenes(1);
}

/// At four lanes (the default of `--lanes`): a memory word per chunk of four pixels.
#[test]
fn raster_top_vector_4_lanes_scenes_vs_model() {
    vector_scenes(4);
}

/// At two and eight lanes (`scripts/soak.sh`: two more Verilated models of the whole
/// rasterizer).
#[test]
#[ignore = "soak: scripts/soak.sh"]
fn raster_top_vector_2_and_8_lanes_scenes_vs_model() {
    vector_scenes(2);
    vector_scenes(8);
}

/// Every shipped scene at 64 x 48 and torus and clip at 320 x 240 drawn by `raster_top`'s
/// SE back end (`METHOD = 2`: 000's shading engines behind the scanline front end and
/// `se_cmd`, five engines) under Verilator: image, depth, pixels written and cycles the
/// model's (`model::raster_top::raster_top_se`: `se::array::render`, `cycles::se_frame`).
#[test]
#[ignore = "long: scripts/soak.sh runs it (the SE back end's Verilated model)"]
fn raster_top_se_scenes_vs_model() {
    let mut dut = se_frame::verilator(5).unwrap_or_else(|e| panic!("{e}"));
    let scenes = ["cube", "sphere", "cone", "torus", "pawn", "house", "all", "clip"].map(|n| (n, (64, 48)));
    for (name, size) in scenes.into_iter().chain([("torus", (320, 240)), ("clip", (320, 240))]) {
        let (list, cull) = scene(name, Some(size));
        let what = format!("{name} at {size:?}, SE back end");
        let prep =
            raster_top_se(&Build::default(), &list, cull, [20, 24, 32]).unwrap_or_else(|e| panic!("{what}: {e}"));
        let f = Frame {
            build: Build::default(),
            width: list.width,
            height: list.height,
            cull,
            background: [20, 24, 32],
            triangles: &prep.front.triangles,
            lanes: 1,
        };
        let out = se_frame::draw(&mut dut, &f, 50_000_000).unwrap_or_else(|e| panic!("{what}: {e}"));
        assert_eq!(out.memory.differs_from(&prep.fb), None, "{what}");
        assert_eq!(out.memory.writes, prep.pixels_written, "{what}: pixels written");
        assert_eq!(out.cycles, prep.cycles, "{what}: cycles, RTL against model::cycles::se_frame");
        assert!(out.memory.writes > 0, "{what}");
    }
}

/// The SE back end with its default 16 engines (`scripts/soak.sh`: its Verilated model
/// takes minutes to build): torus at 1024 x 768 and all at 1000 x 700, image, depth, pixels
/// written and cycles the model's.
#[test]
#[ignore = "soak: scripts/soak.sh"]
fn raster_top_se_16_engines_vs_model() {
    let mut dut = se_frame::verilator(16).unwrap_or_else(|e| panic!("{e}"));
    for (name, size) in [("torus", (1024, 768)), ("all", (1000, 700))] {
        let (list, cull) = scene(name, Some(size));
        let prep = raster_top_se(&Build::default(), &list, cull, [0; 3]).unwrap_or_else(|e| panic!("{name}: {e}"));
        let f = Frame {
            build: Build::default(),
            width: list.width,
            height: list.height,
            cull,
            background: [0; 3],
            triangles: &prep.front.triangles,
            lanes: 1,
        };
        let out = se_frame::draw(&mut dut, &f, 100_000_000).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(out.memory.differs_from(&prep.fb), None, "{name}");
        assert_eq!((out.memory.writes, out.cycles), (prep.pixels_written, prep.cycles), "{name}: writes, cycles");
    }
}

fn list(width: u32, height: u32, triangles: Vec<Triangle>) -> Trilist {
    Trilist { width, height, triangles, textures: Vec::new() }
}

/// The model's fill-rule cases (`scene::stress`, as `crates/model/tests/watertight.rs`):
/// split rectangles, fans of thin triangles, random meshes; and its clipping cases
/// (`crates/model/tests/clipping.rs`): triangles across each boundary, pairs of them, and
/// the z range.
#[test]
fn raster_top_fill_rule_and_clipping_vs_model() {
    let mut tris = Vec::new();
    for (a, b) in [((1.5, 1.5), (9.5, 9.5)), ((0.5, 2.5), (20.5, 12.5)), ((3.5, 1.5), (5.5, 17.5))] {
        for flip in [false, true] {
            tris.extend(split_rectangle(a, b, flip));
        }
    }
    let mut cases = vec![("split rectangles", list(32, 32, tris))];
    for centre in [(32.5, 32.5), (31.3, 33.7)] {
        cases.push(("fan", list(64, 64, fan(centre, 28.0, 32).0)));
    }
    cases.push(("random mesh", list(48, 40, random_mesh(seed(), 48, 40))));
    let c = [[250.0, 10.0, 40.0], [20.0, 240.0, 90.0], [60.0, 70.0, 230.0]];
    let tri = |p: [(f64, f64, f64); 3]| -> Triangle { [0, 1, 2].map(|k| Vertex::new(p[k].0, p[k].1, p[k].2, c[k])) };
    let crossing = vec![
        tri([(-20.3, 10.2, 0.3), (30.7, 5.1, 0.5), (10.1, 50.6, 0.7)]),
        tri([(60.3, 10.2, 0.3), (101.7, 25.1, 0.5), (50.1, 50.6, 0.7)]),
        tri([(20.3, -25.2, 0.3), (60.7, 15.1, 0.5), (10.1, 40.6, 0.7)]),
        tri([(20.3, 25.2, 0.3), (70.7, 45.1, 0.5), (10.1, 83.6, 0.7)]),
        tri([(-30.3, 20.2, 0.3), (111.7, 25.1, 0.5), (40.1, 50.6, 0.7)]),
        tri([(20.3, -30.2, 0.3), (60.7, 25.1, 0.5), (30.1, 90.6, 0.7)]),
        tri([(-40.3, -30.2, 0.3), (130.7, -10.1, 0.5), (30.1, 120.6, 0.7)]),
        tri([(5.3, 5.2, -0.4), (75.7, 15.1, 0.5), (20.1, 55.6, 0.6)]),
        tri([(5.3, 5.2, 0.4), (75.7, 15.1, 1.4), (20.1, 55.6, 0.6)]),
        tri([(5.3, 5.2, -0.45), (75.7, 15.1, 1.45), (20.1, 55.6, 0.6)]),
        // Wholly outside one plane: culled.
        tri([(-20.3, 10.2, 0.3), (-30.7, 5.1, 0.5), (-10.1, 50.6, 0.7)]),
    ];
    cases.push(("clipping", list(80, 60, crossing)));
    // Beyond the vertex format (vertices 10,000 px away) and behind the eye (w = -1): the
    // host sends the front end's pieces (`model::guard_band`).
    let mut behind = tri([(8.0, 6.0, 0.4), (58.0, 12.0, 0.6), (20.0, 70.0, 0.5)]);
    for (v, w) in behind.iter_mut().zip([1.0, 2.0, -1.0]) {
        v.w = Some(w);
    }
    let far = tri([(-10000.0, 10000.0, 0.7), (10000.0, 10000.0, 0.7), (40.0, -10000.0, 0.7)]);
    cases.push(("beyond the vertex format", list(80, 60, vec![far, behind])));
    for (what, l) in &cases {
        for cull in [Cull::None, Cull::Back] {
            let mut dut = model();
            let (prep, out) = check(what, &mut dut, l, cull, ready_memory(&mut |_| true));
            let r = Report::of(&out, &prep);
            assert_eq!(r.cycles, r.predicted, "{what}, {cull:?}: cycles");
        }
    }
}

/// Without every optional part (`CULL = CLIP_Y = CLIP_X = CLIP_Z = DEPTH_TEST = 0`,
/// `rtl::switch`), in Verilator: frames that need none of them (a random mesh covering
/// the screen edge to edge, a fan within it, split rectangles: nothing culled or crossing
/// the screen, no pixel drawn twice) come out as the model's, image, depth and cycles, with
/// no depth read; a triangle reaching beyond the far plane, which needs Z clipping, does
/// not.
#[test]
fn raster_top_without_optional_parts_vs_model() {
    let none = rtl::switch::Parts { cull: false, clip_y: false, clip_x: false, clip_z: false, depth_test: false };
    let mut dut = frame::verilator_with(&Build::default(), &none.params()).unwrap_or_else(|e| panic!("{e}"));
    let mut rects = Vec::new();
    for (a, b, flip) in
        [((1.5, 1.5), (9.5, 9.5), false), ((12.5, 2.5), (30.5, 12.5), true), ((3.5, 14.5), (5.5, 30.5), false)]
    {
        rects.extend(split_rectangle(a, b, flip));
    }
    let frames = [
        ("random mesh", list(48, 40, random_mesh(seed(), 48, 40))),
        ("fan", list(64, 64, fan((32.5, 32.5), 28.0, 32).0)),
        ("split rectangles", list(32, 32, rects)),
    ];
    for (what, l) in &frames {
        let prep = raster_top(&Build::default(), l, Cull::None, [20, 24, 32]).unwrap_or_else(|e| panic!("{what}: {e}"));
        let st = &prep.render.stats;
        assert_eq!(
            (st.culled_outside + st.culled_back + st.degenerate, st.crosses, st.overdraw, st.z_clipped),
            (0, 0, 0, 0),
            "{what}"
        );
        let f = Frame {
            build: prep.build,
            width: l.width,
            height: l.height,
            cull: Cull::None,
            background: [20, 24, 32],
            triangles: &prep.triangles,
            lanes: 1,
        };
        let out = draw(&mut dut, &f, ready_memory(&mut |_| true), 10_000_000).unwrap_or_else(|e| panic!("{what}: {e}"));
        assert_eq!(out.memory.differs_from(&prep.render.fb), None, "{what}");
        assert_eq!((out.memory.writes, out.reads.len()), (st.pixels_written, 0), "{what}: writes, and no depth read");
        assert_eq!(Report::of(&out, &prep).cycles, Report::of(&out, &prep).predicted, "{what}: cycles");
    }
    let cull = Cull::None;
    let beyond_far = [(5.3, 5.2, 0.4), (75.7, 15.1, 1.4), (20.1, 55.6, 0.6)];
    let clipping = list(80, 60, vec![beyond_far.map(|(x, y, z)| Vertex::new(x, y, z, [200.0, 90.0, 30.0]))]);
    let prep = raster_top(&Build::default(), &clipping, cull, [20, 24, 32]).unwrap_or_else(|e| panic!("{e}"));
    let f = Frame {
        build: prep.build,
        width: 80,
        height: 60,
        cull,
        background: [20, 24, 32],
        triangles: &prep.triangles,
        lanes: 1,
    };
    let out = draw(&mut dut, &f, ready_memory(&mut |_| true), 1_000_000);
    assert!(
        out.map_or(true, |o| o.memory.depth != prep.render.fb.depth),
        "without Z clipping, a triangle beyond the far plane is drawn wrongly"
    );
}

/// Triangles back to back: 300 one-pixel triangles, then 300 that draw nothing (a pixel
/// wide, between centres), then large overlapping ones. Setup takes one every II cycles
/// (`model::cycles::setup_timing`); the image and the cycles are the model's.
#[test]
fn raster_top_back_to_back_vs_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut tris = Vec::new();
    let col = |rng: &mut ChaCha8Rng| [rng.gen_range(0.0..255.0), rng.gen_range(0.0..255.0), rng.gen_range(0.0..255.0)];
    for i in 0..300 {
        let (x, y, z) = ((i % 30) as f64 * 2.0 + 1.0, (i / 30) as f64 * 3.0 + 1.0, rng.gen_range(0.1..0.9));
        let c = col(&mut rng);
        tris.push([Vertex::new(x, y, z, c), Vertex::new(x + 1.0, y + 0.2, z, c), Vertex::new(x + 0.1, y + 1.0, z, c)]);
    }
    for i in 0..300 {
        let (x, y) = ((i % 30) as f64 * 2.0 + 0.6, (i / 30) as f64 * 3.0 + 0.6);
        let c = col(&mut rng);
        tris.push([Vertex::new(x, y, 0.5, c), Vertex::new(x + 0.3, y, 0.5, c), Vertex::new(x, y + 0.3, 0.5, c)]);
    }
    for _ in 0..20 {
        let p = |rng: &mut ChaCha8Rng| {
            Vertex::new(rng.gen_range(-10.0..70.0), rng.gen_range(-10.0..40.0), rng.gen_range(0.0..1.0), col(rng))
        };
        tris.push([p(&mut rng), p(&mut rng), p(&mut rng)]);
    }
    let l = list(64, 32, tris);
    let mut dut = model();
    let (prep, out) = check("back to back", &mut dut, &l, Cull::None, ready_memory(&mut |_| true));
    let r = Report::of(&out, &prep);
    assert_eq!(r.cycles, r.predicted, "cycles");
    let ii = model::cycles::setup_timing(&Default::default()).interval as u64;
    // The first LATENCY + 1 are taken back to back (into setup and cull_sort's stages).
    let gaps: Vec<u64> = out.taken[..300].windows(2).map(|w| w[1] - w[0]).collect();
    let fill = model::cull_sort::LATENCY as usize;
    assert!(gaps[..fill].iter().all(|&g| g == 1), "cull_sort's stages filled back to back: {gaps:?}");
    assert!(gaps[fill..].iter().all(|&g| g == ii), "one-pixel triangles taken every {ii} cycles: {gaps:?}");
}

/// A memory ready in 80% of the cycles, with bursts of 1 to 19 stalled cycles: which
/// cycles are ready, for the first `n`.
fn stall_pattern(rng: &mut ChaCha8Rng, n: usize) -> Vec<bool> {
    let mut burst = 0;
    (0..n)
        .map(|_| {
            if burst > 0 {
                burst -= 1;
                return false;
            }
            if rng.gen_bool(0.02) {
                burst = rng.gen_range(1..20);
            }
            rng.gen_bool(0.8)
        })
        .collect()
}

/// The memory port stalled (`mem$ready` low 30% of the time, in bursts), reads returning
/// the old or the new word: the same image, nothing lost or written twice, and the frame's
/// cycles those `model::cycles::scanline_frame_stalled` predicts for the same stalls.
#[test]
fn raster_top_memory_stalled_vs_model() {
    let (l, cull) = scene("all", Some((96, 64)));
    for rdw in [ReadDuringWrite::Old, ReadDuringWrite::New] {
        let pattern = stall_pattern(&mut ChaCha8Rng::seed_from_u64(seed()), 1 << 20);
        let ready = |c: u64| pattern.get(c as usize).copied().unwrap_or(true);
        let mut dut = model();
        let (prep, out) =
            check("all, stalled", &mut dut, &l, cull, MemoryModel { read_during_write: rdw, ready: &mut |c| ready(c) });
        assert!(out.stalls > out.cycles / 5, "{} stalled cycles of {}", out.stalls, out.cycles);
        let predicted = prep.cycles_stalled(&Timing::default(), &ready).unwrap();
        assert_eq!(out.cycles, predicted, "all, stalled: cycles, RTL against model::cycles");
        // Most stalls fall where the pipeline waits for setup anyway: they cost some cycles,
        // far fewer than stalled.
        assert!(predicted > prep.cycles(), "the stalls cost cycles: {predicted} against {}", prep.cycles());
    }
    // Pixel-bound frames behind a memory ready one cycle in two at random: span, the span
    // FIFO, the edge walk and setup all wait on it, and the cycle model follows.
    let mut rng = ChaCha8Rng::seed_from_u64(seed() ^ 0x5a11);
    let half: Vec<bool> = (0..1 << 21).map(|_| rng.gen_bool(0.5)).collect();
    let ready = |c: u64| half.get(c as usize).copied().unwrap_or(true);
    for name in ["torus", "clip"] {
        let (l, cull) = scene(name, Some((160, 120)));
        let mut dut = model();
        let (prep, out) = check(name, &mut dut, &l, cull, ready_memory(&mut |c| ready(c)));
        let predicted = prep.cycles_stalled(&Timing::default(), &ready).unwrap();
        assert_eq!(out.cycles, predicted, "{name}, half stalled: cycles, RTL against model::cycles");
        assert!(
            predicted > prep.cycles() + prep.render.stats.fragments / 2,
            "{name}: {predicted} against {}",
            prep.cycles()
        );
    }
}

/// A small frame in rust-hdl and Verilator in lockstep, every output of `raster_top`
/// compared every cycle (rust-hdl steps the whole design directly), the image the model's.
#[test]
fn raster_top_hdl_vs_verilator_lockstep() {
    let (l, cull) = scene("cube", Some((24, 16)));
    let vl = testbenches::verilated("raster_top");
    let mut dual = Dual::new(frame::unit(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let ready = |c: u64| c % 7 != 6;
    let (prep, out) = check("cube, lockstep", &mut dual, &l, cull, ready_memory(&mut |c| ready(c)));
    assert_eq!(out.cycles, prep.cycles_stalled(&Timing::default(), &ready).unwrap(), "cube, lockstep: cycles");
}

/// Every shipped scene at 128 x 96 in rust-hdl and Verilator in lockstep, every output of
/// `raster_top` compared every cycle, the memory stalling one cycle in five
/// (`scripts/soak.sh`: rust-hdl steps `raster_top` at about 1,700 cycles/s).
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn raster_top_hdl_vs_verilator_lockstep_long() {
    let vl = testbenches::verilated("raster_top");
    for name in ["cube", "sphere", "cone", "torus", "pawn", "house", "all", "clip"] {
        let (l, cull) = scene(name, Some((128, 96)));
        let mut dual = Dual::new(frame::unit(), vl.model().unwrap_or_else(|e| panic!("{e}")));
        let (prep, out) = check(&format!("{name}, lockstep"), &mut dual, &l, cull, ready_memory(&mut |c| c % 5 != 2));
        assert_eq!(out.cycles, prep.cycles_stalled(&Timing::default(), &|c| c % 5 != 2).unwrap(), "{name}: cycles");
    }
}

/// The divider stages of the lockstep builds that test something else (size classes, units
/// present): 001's 5, as rust-hdl's simulation of the default 25 stages is most of what they
/// would cost. The default runs in lockstep at class 10 and at `rtl::custom`'s formats, and
/// in Verilator against the model at every class.
const LOCKSTEP_L: usize = 5;

/// The larger size classes in rust-hdl and Verilator in lockstep: a small screen with the
/// cube and a triangle whose vertices lie beyond class 10's coordinate range (|x|, |y| >=
/// 2048, which class 10 takes only clipped), every output compared every cycle, the image the
/// model's at the class's formats (`Formats::for_n(class)`). The far triangle reaches past
/// the left and top edges only (337 cycles at class 11): reaching past the right edge too,
/// its spans would walk thousands of off-screen pixels each (003 allows it), 27,952 cycles
/// at rust-hdl's speed. Spans across both edges are in `crossing_40x30` (in lockstep below)
/// and in the clipping frames in Verilator.
#[test]
#[cfg(feature = "classes-11-12")]
#[ignore = "soak: two more Verilator models of raster_top in rust-hdl's lockstep"]
fn raster_top_size_classes_11_and_12_lockstep() {
    fn lockstep<U: Block + Pins>(class: u32, unit: U) {
        let (mut l, cull) = scene("cube", Some((24, 16)));
        let far = [(-3000.0, 3.0, 0.3), (20.0, -2500.0, 0.5), (20.0, 14.0, 0.9)];
        l.triangles.push(far.map(|(x, y, z)| Vertex::new(x, y, z, [90.0, 160.0, 230.0])));
        // Class 10's S11.4 cannot hold the far triangle: the front end sends its pieces
        // (`model::guard_band`). Classes 11 and 12 take it whole.
        let class10 = raster_top(&Build::for_screen(l.width, l.height), &l, cull, [0; 3]).expect("a 24 x 16 frame");
        assert!(class10.skipped.is_empty() && class10.triangles.len() > l.triangles.len(), "class 10 clips it");
        let vl = testbenches::verilated_with("raster_top", [("N", class as u64), ("L", LOCKSTEP_L as u64)]);
        let mut dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
        let what = format!("class {class}, lockstep");
        let (prep, _) = check_by(
            Build::of_class(class),
            Method::Scanline,
            &what,
            &mut dual,
            &l,
            cull,
            ready_memory(&mut |c| c % 5 != 3),
        );
        assert_eq!(prep.triangles.len(), l.triangles.len(), "{what}: the far triangle is sent whole");
        assert!(prep.fragments.last().is_some_and(|&n| n > 0), "{what}: the far triangle draws");
    }
    let (k, l) = (7, LOCKSTEP_L);
    lockstep(11, rtl::n11::raster_top::RasterTop::new(k, l, &Parts::ALL).expect("K = 7, default L"));
    lockstep(12, rtl::n12::raster_top::RasterTop::new(k, l, &Parts::ALL).expect("K = 7, default L"));
}

/// A screen larger than class 10's through the `raster_top` the CLI picks for it (class
/// 11), in Verilator: image and cycles the model's.
#[test]
#[cfg(feature = "classes-11-12")]
fn raster_top_class_11_scene_vs_model() {
    let (l, cull) = scene("sphere", Some((1280, 960)));
    assert_eq!(Build::for_screen(l.width, l.height).class, 11);
    let mut dut = frame::verilator(&Build::of_class(11)).unwrap_or_else(|e| panic!("{e}"));
    let (prep, out) = check("sphere at 1280x960", &mut dut, &l, cull, ready_memory(&mut |_| true));
    assert_eq!(out.cycles, prep.cycles(), "cycles");
}

/// One triangle alone: the latency from taking it to its first pixel's read, and to its
/// write, against 003 Table 1 (31 cycles in all) and 001 (68 extra cycles per triangle).
#[test]
fn raster_top_latency_of_one_triangle() {
    let t = [
        Vertex::new(2.0, 2.0, 0.5, [255.0; 3]),
        Vertex::new(9.0, 2.0, 0.5, [255.0; 3]),
        Vertex::new(2.0, 9.0, 0.5, [255.0; 3]),
    ];
    let l = list(16, 16, vec![t]);
    let mut dut = model();
    let (prep, out) = check("one triangle", &mut dut, &l, Cull::None, ready_memory(&mut |_| true));
    let r = Report::of(&out, &prep);
    // cull_sort + setup + edge walk + the span FIFO + span: the first pixel enters pixel_out.
    let setup = model::cycles::setup_latency(&Default::default()) as u64;
    let first =
        [model::cull_sort::LATENCY, model::edge_walk::LATENCY, model::cycles::SPAN_FIFO_LATENCY, model::span::LATENCY]
            .iter()
            .map(|&c| c as u64)
            .sum::<u64>()
            + setup;
    assert_eq!(r.latency, Some((first, first, first)), "{r:?}");
    assert_eq!(r.cycles, r.predicted);
}

/// Icarus Verilog, a simulator outside Rust, replays two frames from vector files the
/// model writes (under the target directory): the bench `testbenches/iverilog/
/// raster_top_tb.v` sends the triangles to `raster_top` (the emitted Verilog) and checks
/// every memory write against the model's, in order; the second frame with the memory
/// stalling one cycle in seven. A vector file with one expected write changed must fail.
///
/// Icarus runs the emitted file after Yosys's `proc` pass (processes rewritten as muxes
/// and flip-flops, nothing optimised; Yosys reads the file as synthesis does): on the file
/// as rust-hdl writes it, one large `always @(*)` per module re-run on every change of a
/// submodule's output, Icarus manages under 10 cycles/s; after `proc`, about 1,500.
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn raster_top_iverilog_replay() {
    iverilog_replay("replay", &[("cube", (48, 32), false), ("clip", (64, 48), true)]);
}

/// [`raster_top_iverilog_replay`] on long frames (`scripts/soak.sh`): every shipped scene
/// at 160 x 120, half of them with the memory stalling.
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn raster_top_iverilog_replay_long() {
    let scenes = ["cube", "sphere", "cone", "torus", "pawn", "house", "all", "clip"];
    let frames: Vec<_> = scenes.iter().enumerate().map(|(i, name)| (*name, (160, 120), i % 2 == 1)).collect();
    iverilog_replay("replay-long", &frames);
}

/// Replays each (scene, size, stall) in Icarus (see [`raster_top_iverilog_replay`]), in
/// `<target>/<dir>/`.
fn iverilog_replay(dir: &str, frames: &[(&str, (u32, u32), bool)]) {
    let dir = testbenches::target_dir().join(dir);
    std::fs::create_dir_all(&dir).expect("the replay directory");
    let top = sim::verilog_file(&testbenches::emitted("raster_top", [])).unwrap_or_else(|e| panic!("{e}"));
    let processed = dir.join("raster_top_proc.v");
    let script = format!(
        "read_verilog {}; hierarchy -check -top raster_top; proc; opt_clean; write_verilog -noattr {}",
        top.display(),
        processed.display()
    );
    let out = Command::new("yosys")
        .args(["-q", "-p", &script])
        .output()
        .unwrap_or_else(|e| panic!("yosys is not installed ({e}): run scripts/setup-tools.sh"));
    assert!(out.status.success(), "yosys: {}", String::from_utf8_lossy(&out.stderr));
    let bench = dir.join("raster_top_tb.vvp");
    let tb = Path::new(env!("CARGO_MANIFEST_DIR")).join("iverilog/raster_top_tb.v");
    let hint = "run scripts/setup-tools.sh (Icarus Verilog comes from Debian)";
    let out = Command::new("iverilog")
        .args(["-g2012", "-o"])
        .args([&bench, &tb, &processed])
        .output()
        .unwrap_or_else(|e| panic!("iverilog is not installed ({e}): {hint}"));
    assert!(out.status.success(), "iverilog: {}", String::from_utf8_lossy(&out.stderr));
    let replay = |vectors: &Path, stall: bool| {
        let mut vvp = Command::new("vvp");
        vvp.arg("-n").arg(&bench).arg(format!("+vectors={}", vectors.display()));
        if stall {
            vvp.arg("+stall");
        }
        let out = vvp.output().unwrap_or_else(|e| panic!("vvp is not installed ({e}): {hint}"));
        (
            out.status.success(),
            format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)),
        )
    };
    for &(name, size, stall) in frames {
        let (l, cull) = scene(name, Some(size));
        let prep =
            raster_top(&Build::for_screen(l.width, l.height), &l, cull, [0; 3]).unwrap_or_else(|e| panic!("{e}"));
        assert!(prep.writes.len() > 100, "{name}: {} writes", prep.writes.len());
        let f = Frame {
            build: prep.build,
            width: l.width,
            height: l.height,
            cull,
            background: [0; 3],
            triangles: &prep.triangles,
            lanes: 1,
        };
        let vectors = dir.join(format!("{name}.vec"));
        frame::write_vectors(&vectors, &f, &prep.writes).expect("the vector file");
        let (ok, log) = replay(&vectors, stall);
        assert!(ok && log.contains(&format!("PASS {} writes", prep.writes.len())), "{name}: {log}");
        if !stall {
            // One expected colour off by one a tenth of the way through the frame (well past
            // its first writes; the bench stops at the first mismatch): it must say so.
            let mut wrong = prep.writes.clone();
            let k = wrong.len() / 10;
            wrong[k].rgb[1] ^= 1;
            let bad = dir.join(format!("{name}-wrong.vec"));
            frame::write_vectors(&bad, &f, &wrong).expect("the vector file");
            let (ok, log) = replay(&bad, false);
            assert!(!ok && log.contains("FAIL: cycle") && log.contains(&format!("write {k} is")), "{name}: {log}");
        }
    }
}

/// One frame through a `raster_top` with some units left out (`CULL_SORT`, `PIXEL_OUT`),
/// in rust-hdl and Verilator in lockstep (every output compared every cycle): without
/// `cull_sort` the host's triangles are the model's sorted ones (`Frame::sorted`), without
/// `pixel_out` the fragment stream must be the model's (`Frame::pixels`), taken with
/// `out_ready` low when `stall` says; with it, the memory must hold the model's image. When
/// nothing stalls, the cycles are `model::cycles`' for these units.
fn units_frame<U: Block + Pins>(
    dual: &mut Dual<U>,
    units: Timing,
    what: &str,
    list: &Trilist,
    cull: Cull,
    stall: &mut dyn FnMut(u64) -> bool,
) {
    let prep = raster_top(&Build::for_screen(list.width, list.height), list, cull, [20, 24, 32])
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    // The triangles as the host sends them, with their crossings when it culls.
    let sent: Vec<([Vtx; 3], u8)> = if units.cull_sort {
        prep.triangles.iter().map(|t| (*t, 0)).collect()
    } else {
        prep.sorted.iter().map(|s| (s.v, s.crosses)).collect()
    };
    assert!(!sent.is_empty(), "{what}: a triangle to carry inp_last");
    let build = prep.build;
    let class = build.class;
    let zmax = model::cull_sort::z_max(&build.formats) as u32;
    let mut memory = Memory::new(class, 1, (list.width, list.height), zmax, [20, 24, 32], ReadDuringWrite::Old);
    let (mut taken, mut fragments, mut stalled) = (0, Vec::new(), false);
    let dim = |v: u32| Value::new(class as usize + 1, v as u128);
    for cycle in 0..5_000_000u64 {
        let ready = !stall(cycle);
        stalled |= !ready;
        let mut pins = vec![("width".to_owned(), dim(list.width)), ("height".to_owned(), dim(list.height))];
        let offer = sent.get(taken);
        pins.push(("inp$valid".into(), Value::new(1, offer.is_some() as u128)));
        pins.push(("inp_last".into(), Value::new(1, (taken + 1 == sent.len()) as u128)));
        let (tri, crosses) = offer.copied().unwrap_or(sent[0]);
        pins.extend(frame::triangle_pins(&build, &tri));
        if units.cull_sort {
            pins.push(("cull_back".into(), Value::new(1, (cull == Cull::Back) as u128)));
        } else {
            pins.push(("inp$crosses".into(), Value::new(rtl::cull_sort::OUTCODE, crosses as u128)));
        }
        if units.pixel_out {
            pins.push(("mem$ready".into(), Value::new(1, ready as u128)));
            pins.push(("mem$rd_z".into(), memory.rd_z_value(rtl::widths::DEPTH)));
        } else {
            pins.push(("out$ready".into(), Value::new(1, ready as u128)));
        }
        let o = dual.cycle(&as_pins(&pins)).unwrap_or_else(|m| panic!("{what}: {m}"));
        let high = |p: &str| unsigned(o.get(p)) == 1;
        if high("done") && offer.is_none() {
            if units.pixel_out {
                assert_eq!(memory.differs_from(&prep.render.fb), None, "{what}");
                assert_eq!(memory.writes, prep.writes.len() as u64, "{what}: pixels written");
            } else {
                assert_eq!(fragments.len(), prep.pixels.len(), "{what}: fragments");
                if let Some(i) = fragments.iter().zip(&prep.pixels).position(|(a, b)| a != b) {
                    panic!("{what}: fragment {i} is {:?}, the model's {:?}", fragments[i], prep.pixels[i]);
                }
            }
            if !stalled {
                assert_eq!(cycle, prep.cycles_with(&units), "{what}: cycles, RTL against model::cycles");
            }
            return;
        }
        taken += (offer.is_some() && high("inp$ready")) as usize;
        if units.pixel_out {
            memory.edge(ready, &Request::of(&o));
        } else if ready && high("out$valid") {
            fragments.push(pixel_of(&o, "out"));
        }
    }
    panic!("{what}: no done ({taken} of {} triangles taken)", sent.len());
}

/// Triangles across every clip plane and the near and far planes on a 40 x 30 screen, one
/// wholly outside the left edge and one back-facing.
fn crossing_40x30() -> Trilist {
    let c = [[250.0, 10.0, 40.0], [20.0, 240.0, 90.0], [60.0, 70.0, 230.0]];
    let tri = |p: [(f64, f64, f64); 3]| -> Triangle { [0, 1, 2].map(|k| Vertex::new(p[k].0, p[k].1, p[k].2, c[k])) };
    list(
        40,
        30,
        vec![
            tri([(-10.3, 5.2, 0.3), (15.7, 2.1, 0.5), (5.1, 25.6, 0.7)]),
            tri([(30.3, 5.2, 0.3), (51.7, 12.1, 0.5), (25.1, 25.6, 0.7)]),
            tri([(10.3, -12.2, 0.3), (30.7, 7.1, 0.5), (5.1, 20.6, 0.7)]),
            tri([(-20.3, -15.2, 0.3), (65.7, -5.1, 0.5), (15.1, 60.6, 0.7)]),
            tri([(2.3, 2.2, -0.4), (37.7, 7.1, 1.5), (10.1, 27.6, 0.6)]),
            tri([(-10.3, 5.2, 0.3), (-15.7, 2.1, 0.5), (-5.1, 25.6, 0.7)]),
            tri([(3.3, 3.2, 0.2), (5.1, 27.6, 0.2), (36.7, 4.1, 0.2)]),
        ],
    )
}

/// Units present: `raster_top` without `pixel_out` (fragments out), emitted, Verilated and
/// run beside its rust-hdl self on the cube with nothing stalling (cycles =
/// `model::cycles`) and on triangles across every clip plane with the output stalled at
/// random. The other builds, and each frame both ways, run in
/// [`raster_top_units_present_lockstep_long`].
#[test]
fn raster_top_units_present_lockstep() {
    let (k, l) = (7, LOCKSTEP_L);
    units_present(|| rtl::raster_top::RasterTopFragments::new(k, l, &Parts::ALL).expect("K = 7"), true, false, false);
}

/// [`raster_top_units_present_lockstep`] with each frame both unstalled and stalled, and so
/// also without `cull_sort` (sorted triangles in) and without both (`scripts/soak.sh`: two
/// more Verilated builds of raster_top, 34 s of CPU; `gpu_top` holds the core without
/// either, and its tests run it in the test command).
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn raster_top_units_present_lockstep_long() {
    let (k, l) = (7, LOCKSTEP_L);
    units_present(|| rtl::raster_top::RasterTopFragments::new(k, l, &Parts::ALL).expect("K = 7"), true, false, true);
    units_present(|| rtl::raster_top::RasterTopSorted::new(k, l, &Parts::ALL).expect("K = 7"), false, true, true);
    units_present(|| rtl::raster_top::RasterTopCore::new(k, l, &Parts::ALL).expect("K = 7"), false, false, true);
}

/// One build of [`raster_top_units_present_lockstep`]: `unit` makes the rust-hdl block with
/// `cull_sort` and `pixel_out` present or not; the cube unstalled and the clipping frame
/// stalled, and with `both_ways` each frame both ways.
fn units_present<U: Block + Pins>(unit: impl Fn() -> U, cull_sort: bool, pixel_out: bool, both_ways: bool) {
    let units = Timing { cull_sort, pixel_out, divider_latency: LOCKSTEP_L as u32, ..Timing::default() };
    let vl = testbenches::verilated_with(
        "raster_top",
        [("CULL_SORT", cull_sort as u64), ("PIXEL_OUT", pixel_out as u64), ("L", LOCKSTEP_L as u64)],
    );
    let (cube, cube_cull) = scene("cube", Some((24, 16)));
    let crossing = crossing_40x30();
    let name = format!("CULL_SORT={} PIXEL_OUT={}", cull_sort as u8, pixel_out as u8);
    for (what, l, cull) in [("cube", &cube, cube_cull), ("clipping", &crossing, Cull::Back)] {
        if what == "cube" || both_ways {
            let mut dual = Dual::new(unit(), vl.model().unwrap_or_else(|e| panic!("{e}")));
            units_frame(&mut dual, units, &format!("{name}, {what}"), l, cull, &mut |_| false);
        }
        if what == "clipping" || both_ways {
            let mut rng = ChaCha8Rng::seed_from_u64(seed());
            let mut dual = Dual::new(unit(), vl.model().unwrap_or_else(|e| panic!("{e}")));
            units_frame(&mut dual, units, &format!("{name}, {what}, stalled"), l, cull, &mut |_| rng.gen_bool(0.3));
        }
    }
}

/// `raster_top` built at formats other than its class's defaults (`rtl::custom`; by default
/// `crates/rtl/custom-formats.json`: a 24-bit depth buffer, 3 subpixel bits, colours with 2
/// fraction bits, narrower reciprocal, wider gradients), emitted at those formats and
/// Verilated, beside its rust-hdl self in lockstep (every output every cycle): the cube
/// with nothing stalling (cycles = `model::cycles`) and the clipping cases with the memory
/// stalling, image and depth buffer the model's at those formats, which differ from the
/// model's at the class's defaults. (The soak's: the test command builds without
/// `rtl::custom`, the feature `custom-formats`.)
#[test]
#[cfg(feature = "custom-formats")]
fn raster_top_custom_formats_lockstep() {
    let build = Build { class: rtl::custom::CLASS, formats: rtl::custom::FORMATS };
    assert_ne!(
        build,
        Build::of_class(build.class),
        "rtl::custom is built at its class's defaults: nothing new to test"
    );
    let unit = rtl::Unit::named("raster_top").expect("raster_top is in UNITS");
    let params = unit.params([("N".to_owned(), build.class as u64)]).expect("known parameters");
    let e = unit.emit_at(&params, &build.formats).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        e.ports.iter().any(|p| p.name == "mem$wr_z" && p.width == build.formats.z.frac as usize),
        "mem$wr_z is z.frac wide"
    );
    let vl = testbenches::verilate(&e).unwrap_or_else(|e| panic!("{e}"));
    let (cube, cube_cull) = scene("cube", Some((24, 16)));
    let crossing = crossing_40x30();
    // The clipping cases with the memory not ready one cycle in five.
    for (what, l, cull, stalling) in [("cube", &cube, cube_cull, false), ("clipping", &crossing, Cull::Back, true)] {
        let unit = rtl::custom::raster_top::RasterTop::new(7, model::divider::LATENCY as usize, &Parts::ALL)
            .expect("K = 7, default L");
        let mut dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
        let what = format!("{} formats, {what}", rtl::custom::SOURCE);
        let (prep, out) = check_by(
            build,
            Method::Scanline,
            &what,
            &mut dual,
            l,
            cull,
            ready_memory(&mut |c| !stalling || c % 5 != 3),
        );
        if out.stalls == 0 {
            assert_eq!(out.cycles, prep.cycles(), "{what}: cycles, RTL against model::cycles");
        }
        let defaults =
            raster_top(&Build::of_class(build.class), l, cull, [20, 24, 32]).expect("the class's default formats");
        assert!(defaults.render.fb.depth != prep.render.fb.depth, "{what}: the formats change the depth buffer");
    }
}

/// The model's frame of hardware words `tris` on `clip`: its framebuffer, pixels written,
/// fragments and predicted cycles (`model::render::trace` per triangle, as `render` does
/// after `to_fixed`).
fn model_frame(
    tris: &[[Vtx; 3]],
    clip: model::cull_sort::Clip,
    cull: Cull,
) -> (model::pixel_out::Framebuffer, u64, u64, u64) {
    use model::render::{trace, Method, Options};
    let f = rtl::widths::FORMATS;
    let opts = Options { method: Method::Scanline, cull, analysis: false, background: [20, 24, 32] };
    let mut fb =
        model::pixel_out::Framebuffer::new(clip.width, clip.height, model::cull_sort::z_max(&f) as u32, [20, 24, 32]);
    let (mut writes, mut fragments, mut work) = (0, 0, Vec::new());
    for (i, v) in tris.iter().enumerate() {
        match trace(v, clip, &opts, &mut model::ctx::Ctx::new(f)) {
            Ok(t) => {
                fragments += t.pixels.len() as u64;
                writes += t.pixels.iter().filter(|p| fb.pixel_out(p, i as u32)).count() as u64;
                work.push(t.work);
            }
            Err(_) => work.push(model::render::Work::default()),
        }
    }
    let cycles = model::cycles::scanline_frame(&work, &Timing::default()).total;
    (fb, writes, fragments, cycles)
}

/// Issue 15's soak: 100,000 random triangles (`stimulus::random_triangle`: degenerate,
/// collinear, coincident, tiny and huge ones, on the clip planes and at the limits of `xy`;
/// `EDGEPAINT_TRIANGLES` to change the count) through `raster_top` in Verilator and the
/// model, in frames of 500 on the 64 x 48 and 320 x 240 screens with both cullings: every
/// pixel's colour and depth, the writes, the fragments and the frame's cycles equal.
#[test]
#[ignore = "soak: 100,000 triangles, about 6 minutes; scripts/soak.sh"]
fn raster_top_100k_random_triangles_vs_model() {
    let n: usize = std::env::var("EDGEPAINT_TRIANGLES").ok().and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut dut = model();
    let mut drawn = 0;
    for frame_no in 0..n.div_ceil(500) {
        let clip = testbenches::stimulus::SCREENS[rng.gen_range(0..2)];
        let cull = if rng.gen_bool(0.5) { Cull::Back } else { Cull::None };
        let tris: Vec<[Vtx; 3]> = (0..500).map(|_| testbenches::stimulus::random_triangle(&mut rng, clip)).collect();
        let (fb, writes, fragments, cycles) = model_frame(&tris, clip, cull);
        let f = Frame {
            build: Build::default(),
            width: clip.width,
            height: clip.height,
            cull,
            background: [20, 24, 32],
            triangles: &tris,
            lanes: 1,
        };
        let out = draw(&mut dut, &f, ready_memory(&mut |_| true), 100_000_000)
            .unwrap_or_else(|e| panic!("frame {frame_no}: {e}"));
        let what = format!("frame {frame_no} ({}x{}, {cull:?})", clip.width, clip.height);
        assert_eq!(out.memory.differs_from(&fb), None, "{what}");
        assert_eq!((out.memory.writes, out.reads.len() as u64), (writes, fragments), "{what}: writes, fragments");
        assert_eq!(out.cycles, cycles, "{what}: cycles");
        drawn += out.verdicts.iter().filter(|&&v| v as u64 == rtl::cull_sort::verdict::PASSED).count();
    }
    assert!(drawn > n / 10, "{drawn} of {n} triangles drawn: the mix must draw many");
}
