//! In-process simulation speed of the EPT and of whole frames through `raster_top` in each
//! simulator, in cycles per second.
//!
//! `cargo run --release -p testbenches --example sim_speed [SECONDS]` (default 2 s per EPT
//! measurement; needs Verilator: scripts/setup-tools.sh). EPT: one cycle = drive `xl`, `xr`,
//! settle, read `px`, as in the tests, with random (XL, XR) from a fixed seed. raster_top:
//! the cube scene at 64 x 48 (rust-hdl) and the whole shipped scene `all` at 320 x 240
//! (Verilator), drawn by `testbenches::frame::draw` with Rust memories, as
//! `render --engine rtl` does.

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

/// A frame of scene `name` at `size` drawn on `dut`; returns cycles per second.
fn frame_speed(dut: &mut dyn Cycle, name: &str, size: (u32, u32)) -> (u64, f64) {
    let path = scene::shipped::path(name);
    let s = scene::Scene::load(&path).and_then(|s| s.with_size(size.0, size.1)).unwrap_or_else(|e| panic!("{e}"));
    let list = s.to_trilist().unwrap_or_else(|e| panic!("{e}"));
    let cull = if s.cull_back { Cull::Back } else { Cull::None };
    let prep = model::raster_top::raster_top(&fx::Build::for_screen(list.width, list.height), &list, cull, [0; 3])
        .unwrap_or_else(|e| panic!("{e}"));
    let f = Frame {
        build: prep.build,
        width: list.width,
        height: list.height,
        cull,
        background: [0; 3],
        triangles: &prep.triangles,
    };
    let memory = MemoryModel { read_during_write: ReadDuringWrite::Old, ready: &mut |_| true };
    let start = Instant::now();
    let out = draw(dut, &f, memory, 100_000_000).unwrap_or_else(|e| panic!("{e}"));
    let speed = out.cycles as f64 / start.elapsed().as_secs_f64();
    assert!(out.memory.rgb == prep.render.fb.rgb, "{name}: the RTL's image differs from the model's");
    (out.cycles, speed)
}

fn main() {
    let secs: f64 = std::env::args().nth(1).map_or(2.0, |s| s.parse().expect("seconds"));
    let budget = Duration::from_secs_f64(secs);
    println!("| unit | parameters | rust-hdl cycles/s | Verilator cycles/s |\n|---|---|---:|---:|");
    speeds::<8>(budget);
    speeds::<64>(budget);
    speeds::<1024>(budget);
    let (cycles, hdl) = frame_speed(&mut HdlSim::new(frame::unit()), "cube", (64, 48));
    println!("| raster_top | K=7 L=5, cube 64x48 ({cycles} cycles) | {hdl:.0} | |");
    let mut dut = frame::verilator(&Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let (cycles, vl) = frame_speed(&mut dut, "all", (320, 240));
    println!("| raster_top | K=7 L=5, all 320x240 ({cycles} cycles) | | {vl:.0} |");
}
