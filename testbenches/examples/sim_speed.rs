//! In-process simulation speed of the EPT in each simulator, in cycles per second.
//!
//! `cargo run --release -p testbenches --example sim_speed [SECONDS]` (default 2 s per
//! measurement; needs Verilator: scripts/setup-tools.sh). One cycle = drive `xl`, `xr`,
//! settle, read `px`, as in the tests, with random (XL, XR) from a fixed seed.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::ept::{Ept, EptSize, Pixels};
use std::time::{Duration, Instant};
use testbenches::{HdlSim, Sim, Value, Verilated};

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
    let unit = rtl::Unit::named("ept").expect("ept");
    let e = unit.emit(&unit.params([("P".to_owned(), P as u64)]).expect("P")).expect("supported P");
    let vl = Verilated::emitted(&e).unwrap_or_else(|e| panic!("{e}"));
    let mut vl_sim = vl.model().unwrap_or_else(|e| panic!("{e}"));
    let mut hdl_sim = HdlSim::new(Ept::<P>::default());
    let hdl = measure(&mut hdl_sim, P, budget);
    let ver = measure(&mut vl_sim, P, budget);
    println!("| ept | P={P} | {hdl:.0} | {ver:.0} |");
}

fn main() {
    let secs: f64 = std::env::args().nth(1).map_or(2.0, |s| s.parse().expect("seconds"));
    let budget = Duration::from_secs_f64(secs);
    println!("| unit | parameters | rust-hdl cycles/s | Verilator cycles/s |\n|---|---|---:|---:|");
    speeds::<8>(budget);
    speeds::<64>(budget);
    speeds::<1024>(budget);
}
