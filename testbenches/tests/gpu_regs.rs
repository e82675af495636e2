//! `gpu_regs`: rust-hdl and Verilator in lockstep with `model::gpu_regs`, every output
//! compared every cycle, under a random AXI4-Lite host: writes and reads of every address
//! (inside and outside the map) with random strobes, each offered until taken, responses
//! taken at random, and `gpu_top`'s side (status, counts, frame ends) changing at random.

use model::gpu_regs::{GpuRegs as Model, Inputs, Outputs as ModelOutputs, Reg, SLVERR};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::gpu_regs::GpuRegs;
use rtl::widths::CLASS;
use testbenches::{count, seed, verilated_with, Dual, Outputs, Value};

/// Every input as pins.
fn input_pins(i: &Inputs) -> Vec<(&'static str, Value)> {
    let bit = |b: bool| Value::new(1, b as u128);
    let (w_data, w_strb) = i.w.unwrap_or((0, 0));
    vec![
        ("host$aw_valid", bit(i.aw.is_some())),
        ("host$aw_addr", Value::new(6, i.aw.unwrap_or(0).into())),
        ("host$w_valid", bit(i.w.is_some())),
        ("host$w_data", Value::new(32, w_data.into())),
        ("host$w_strb", Value::new(4, w_strb.into())),
        ("host$b_ready", bit(i.b_ready)),
        ("host$ar_valid", bit(i.ar.is_some())),
        ("host$ar_addr", Value::new(6, i.ar.unwrap_or(0).into())),
        ("host$r_ready", bit(i.r_ready)),
        ("status", Value::new(32, i.status.into())),
        ("frame_cycles", Value::new(32, i.frame_cycles.into())),
        ("triangles", Value::new(32, i.triangles.into())),
        ("done", bit(i.done)),
    ]
}

/// Every output against the model's (data and responses where they are valid).
fn compare(got: &Outputs, o: &ModelOutputs) -> Result<(), String> {
    let bit = |b: bool| Value::new(1, b as u128);
    let mut want = vec![
        ("host$aw_ready", bit(o.w_ready)),
        ("host$w_ready", bit(o.w_ready)),
        ("host$ar_ready", bit(o.ar_ready)),
        ("host$b_valid", bit(o.b.is_some())),
        ("host$r_valid", bit(o.r.is_some())),
        ("start", bit(o.start)),
        ("clear", bit(o.clear)),
        ("irq", bit(o.irq)),
        ("vb_addr", Value::new(32, o.vb_addr.into())),
        ("color_base", Value::new(32, o.color_base.into())),
        ("color_pitch", Value::new(16, o.color_pitch.into())),
        ("depth_base", Value::new(32, o.depth_base.into())),
        ("depth_pitch", Value::new(16, o.depth_pitch.into())),
        ("screen", Value::new(32, o.screen.into())),
    ];
    if let Some(resp) = o.b {
        want.push(("host$b_resp", Value::new(2, resp.into())));
    }
    if let Some((data, resp)) = o.r {
        want.push(("host$r_data", Value::new(32, data.into())));
        want.push(("host$r_resp", Value::new(2, resp.into())));
    }
    match want.iter().find(|(pin, v)| got.get(pin) != v) {
        Some((pin, v)) => Err(format!("{pin}: RTL {}, model {v}", got.get(pin))),
        None => Ok(()),
    }
}

/// A random byte address: mostly a register's (or just past the map), sometimes any.
fn address(rng: &mut ChaCha8Rng) -> u32 {
    if rng.gen_bool(0.8) {
        Reg::ALL[rng.gen_range(0..Reg::ALL.len())] as u32 | rng.gen_range(0..4)
    } else {
        rng.gen_range(0..64)
    }
}

/// `EDGEPAINT_N` x 20 cycles of random traffic; every response is counted by kind.
#[test]
fn gpu_regs_random_host_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let vl = verilated_with("gpu_regs", []);
    let mut dual = Dual::new(GpuRegs::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut model = Model::new(CLASS);
    let mut i = Inputs::default();
    let (mut starts, mut irqs, mut errors, mut reads) = (0, 0, 0, 0);
    for cycle in 0..count() * 20 {
        // An offer stays until taken (AXI): new ones only where none is waiting.
        if i.aw.is_none() && rng.gen_bool(0.3) {
            i.aw = Some(address(&mut rng));
        }
        if i.w.is_none() && rng.gen_bool(0.3) {
            let data = if rng.gen_bool(0.5) { rng.gen() } else { rng.gen_range(0..8) };
            i.w = Some((data, rng.gen_range(0..16)));
        }
        if i.ar.is_none() && rng.gen_bool(0.3) {
            i.ar = Some(address(&mut rng));
        }
        i.b_ready = rng.gen_bool(0.7);
        i.r_ready = rng.gen_bool(0.7);
        if rng.gen_bool(0.05) {
            (i.status, i.frame_cycles, i.triangles) = (rng.gen(), rng.gen(), rng.gen());
        }
        i.done = rng.gen_bool(0.02);
        let o = model.outputs(&i);
        let pins = input_pins(&i);
        let got = dual.cycle(&pins).unwrap_or_else(|m| panic!("{m}"));
        compare(&got, &o).unwrap_or_else(|e| panic!("seed {seed}, cycle {cycle}: {e}"));
        starts += o.start as u32;
        irqs += o.irq as u32;
        if let (Some((_, resp)), true) = (o.r, i.r_ready) {
            reads += 1;
            errors += (resp == SLVERR) as u32;
        }
        model.clock(&i);
        if o.w_ready {
            (i.aw, i.w) = (None, None);
        }
        if o.ar_ready {
            i.ar = None;
        }
    }
    // The traffic reached every behaviour: starts, interrupts, good and bad reads.
    assert!(starts > 0 && irqs > 0 && errors > 0 && reads > errors, "{starts} {irqs} {errors} {reads}");
}
