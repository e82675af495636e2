//! In-process simulation speed of the EPT and of whole frames through `raster_top` in each
//! simulator, in cycles per second.
//!
//! `cargo run --release -p testbenches --features classes-11-12,custom-formats --example
//! sim_speed [SECONDS]` (default 2 s per measurement; needs Verilator: scripts/setup-tools.sh;
//! without the features, classes 11 and 12 and `rtl::custom` are left out). EPT: one cycle = drive `xl`, `xr`,
//! settle, read `px`, as in the tests, with random (XL, XR) from a fixed seed. raster_top:
//! the cube scene at 64 x 48 in rust-hdl, and the whole shipped scene `all` at 640 x 480 in
//! Verilator at every build of the scanline units (`rtl::BUILDS`: size classes 10, 11 and
//! 12 at their default formats, and `rtl::custom`), frames drawn again and again for the
//! time given by `testbenches::frame::draw` with Rust memories, as `render --engine rtl`
//! does, each checked against the model's image.

use fx::Build;
use model::cull_sort::Cull;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::ept::{Ept, EptSize, Pixels};
use std::time::{Duration, Instant};
use testbenches::frame::{self, draw, Cycle, Frame, MemoryModel};
use testbenches::memory::ReadDuringWrite;
use testbenches::{HdlSim, Sim, Value};

/// Runs `sim` for about `budget`; returns cycles per second.
fn measure(sim: &mut dyn Sim, p: usize, budget: Duration) -> f64 {
    let b = p.trailing_zeros() as usize;
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let inputs: Vec<(Value, Value)> = (0..4096)
        .map(|_| (Value::new(b, rng.gen_range(0..p as u128)), Value::new(b, rng.gen_range(0..p as u128))))
        .collect();
    let (start, mut cycles) = (Instant::now(), 0usize);
    while start.elapsed() < budget {
        let (xl, xr) = &inputs[cycles % inputs.len()];
        sim.set("xl", xl);
        sim.set("xr", xr);
        sim.settle();
        std::hint::black_box(sim.get("px"));
        cycles += 1;
    }
    cycles as f64 / start.elapsed().as_secs_f64()
}

fn speeds<const P: usize>(budget: Duration)
where
    Pixels<P>: EptSize,
{
    let vl = testbenches::verilate(&testbenches::emitted("ept", [("P", P as u64)])).unwrap_or_else(|e| panic!("{e}"));
    let mut vl_sim = vl.model().unwrap_or_else(|e| panic!("{e}"));
    let mut hdl_sim = HdlSim::new(Ept::<P>::default());
    let hdl = measure(&mut hdl_sim, P, budget);
    let ver = measure(&mut vl_sim, P, budget);
    println!("| ept | P={P} | {hdl:.0} | {ver:.0} |");
}

/// Frames of scene `name` at `size` drawn on `dut`, at `build`, again and again for about
/// `budget` (at least once); returns the cycles of one frame and cycles per second.
fn frame_speed(dut: &mut dyn Cycle, build: Build, name: &str, size: (u32, u32), budget: Duration) -> (u64, f64) {
    let path = scene::shipped::path(name);
    let s = scene::Scene::load(&path).and_then(|s| s.with_size(size.0, size.1)).unwrap_or_else(|e| panic!("{e}"));
    let list = s.to_trilist().unwrap_or_else(|e| panic!("{e}"));
    let cull = if s.cull_back { Cull::Back } else { Cull::None };
    let prep = model::raster_top::raster_top(&build, &list, cull, [0; 3]).unwrap_or_else(|e| panic!("{e}"));
    let f = Frame {
        build: prep.build,
        width: list.width,
        height: list.height,
        cull,
        background: [0; 3],
        triangles: &prep.triangles,
        lanes: 1,
    };
    let (start, mut total, mut frame_cycles) = (Instant::now(), 0, 0);
    while total == 0 || start.elapsed() < budget {
        let memory = MemoryModel { read_during_write: ReadDuringWrite::Old, ready: &mut |_| true };
        let out = draw(dut, &f, memory, 100_000_000).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(out.memory.differs_from(&prep.render.fb), None, "{name}");
        (frame_cycles, total) = (out.cycles, total + out.cycles);
    }
    (frame_cycles, total as f64 / start.elapsed().as_secs_f64())
}

/// Stack of the thread the measurements run on: building the rust-hdl `raster_top` of the
/// larger size classes (to emit their Verilog) recurses deeper than a main thread's 8 MiB,
/// as in the CLI (`crates/cli/main.rs`).
const STACK: usize = 512 << 20;

fn main() {
    let secs: f64 = std::env::args().nth(1).map_or(2.0, |s| s.parse().expect("seconds"));
    let budget = Duration::from_secs_f64(secs);
    let run = std::thread::Builder::new().stack_size(STACK).spawn(move || measure_all(budget));
    run.expect("a thread to measure on").join().expect("the measurements ran");
}

/// Prints the table: the EPT at three sizes in both simulators, `raster_top` in rust-hdl and
/// at every build in Verilator.
fn measure_all(budget: Duration) {
    let defaults = rtl::Unit::named("raster_top").expect("raster_top is in UNITS").params([]).expect("defaults");
    let kl = format!("K={} L={}", defaults["K"], defaults["L"]);
    println!("| unit | parameters | rust-hdl cycles/s | Verilator cycles/s |\n|---|---|---:|---:|");
    speeds::<8>(budget);
    speeds::<64>(budget);
    speeds::<1024>(budget);
    let build = Build::default();
    let (cycles, hdl) = frame_speed(&mut HdlSim::new(frame::unit()), build, "cube", (64, 48), budget);
    println!("| raster_top | {kl}, class 10, cube 64x48 ({cycles} cycles) | {hdl:.0} | |");
    for &build in rtl::BUILDS {
        let custom = rtl::CUSTOM.map_or("other formats", |(_, source)| source);
        let formats = if build == Build::of_class(build.class) { "default formats" } else { custom };
        let mut dut = frame::verilator(&build).unwrap_or_else(|e| panic!("{e}"));
        let (cycles, vl) = frame_speed(&mut dut, build, "all", (640, 480), budget);
        println!("| raster_top | {kl}, class {}, {formats}, all 640x480 ({cycles} cycles) | | {vl:.0} |", build.class);
    }
}
