//! Triangle setup (paper 001): rust-hdl and Verilator in lockstep, every output compared on
//! every cycle, and each result (`out_*`, `TriangleSetupOut` flattened, and OneOverArea on
//! `recip_mant`, `recip_exp`) checked against
//! `model::triangle_setup`; latency and initiation interval against
//! `model::cycles::setup_timing`. Its inputs are the triangles `model::cull_sort` passes.

use model::ctx::Ctx;
use model::cull_sort::{cull_sort, Cull, Sorted};
use model::cycles::{setup_latency, setup_timing, SetupTiming, Timing};
use model::triangle_setup::{triangle_setup, TriangleSetupOut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::divider::LATENCY_MAX;
use rtl::triangle_setup::{Schedule, TriangleSetup, MULTIPLIERS_MAX};
use rtl::widths::FORMATS;
use scene::Vertex;
use std::collections::VecDeque;
use testbenches::flow::{hdl_cycle, outputs, Cycle, Flow};
use testbenches::stimulus::{extremes, random_case, scene, Case};
use testbenches::streams::{self, as_pins, triangle_setup_out, PinValues};
use testbenches::{count, seed, verilated, Dual, HdlSim, Value};

/// The default design's configuration: 001's 7 multipliers, and a divider of one quotient
/// step a stage (25 stages; 001's has 5).
const K: usize = 7;
const L: usize = model::divider::LATENCY as usize;

/// The triangles of `cases` that `cull_sort` passes.
fn sorted(cases: &[Case]) -> Vec<Sorted> {
    cases.iter().filter_map(|c| cull_sort(&c.v, c.clip, c.cull, &FORMATS).ok()).collect()
}

/// A sorted triangle on the input ports.
fn sorted_pins(s: &Sorted) -> PinValues {
    streams::sorted("inp", s)
}

/// The model's result.
fn model(s: &Sorted) -> TriangleSetupOut {
    triangle_setup(s, &mut Ctx::new(FORMATS))
}

/// The cycle each triangle was taken, its result first valid, and the result taken.
#[derive(Clone, Copy, Debug, Default)]
struct Taken {
    taken: u64,
    valid: u64,
    handed: u64,
}

/// Drives `tris` through `cycle` (one clock of one or both simulators) and checks each
/// result against the model. The edge walk's side as `raster_top` has it: free or not
/// (`flow`), said a cycle ahead on `out_free_next`, and at times held (`out_hold`, with
/// `out.ready` low) while free.
fn run(cycle: &mut Cycle, tris: &[Sorted], flow: Flow, rng: &mut ChaCha8Rng) -> Result<Vec<Taken>, String> {
    let mut timing = vec![Taken::default(); tris.len()];
    let (mut next, mut presenting, mut done, mut now) = (0, false, 0, 0u64);
    let (mut free, mut free_next) = (true, flow.next_ready(true, rng));
    let mut in_flight: VecDeque<usize> = VecDeque::new();
    let mut was_valid = false;
    while done < tris.len() {
        if now > 200 * tris.len() as u64 + 200 {
            return Err(format!("{done} of {} triangles out after {now} cycles", tris.len()));
        }
        if next < tris.len() {
            presenting = flow.offer(presenting, rng);
        }
        let mut pins = sorted_pins(&tris[next.min(tris.len() - 1)]);
        pins.push(("inp$valid".into(), Value::new(1, presenting as u128)));
        let hold = rng.gen_bool(flow.stall / 2.0);
        let ready = free && !hold;
        pins.push(("out$ready".into(), Value::new(1, ready as u128)));
        pins.push(("out_free_next".into(), Value::new(1, free_next as u128)));
        pins.push(("out_hold".into(), Value::new(1, hold as u128)));
        let out = cycle(&as_pins(&pins))?;
        let valid = out.get("out$valid").bit(0);
        if valid {
            let &i = in_flight.front().ok_or(format!("cycle {now}: out$valid with no triangle taken"))?;
            if !was_valid {
                timing[i].valid = now;
            }
            let m = model(&tris[i]);
            let recip = [
                ("recip_mant", Value::new(rtl::triangle_setup::MANT, m.recip.mant as u128)),
                ("recip_exp", Value::new(6, m.recip.exp as u128)),
            ];
            for (pin, want) in triangle_setup_out("out", &m).into_iter().chain(recip.map(|(p, v)| (p.to_string(), v))) {
                if out.get(&pin) != &want {
                    return Err(format!(
                        "cycle {now}: {pin} = {} but the model says {want} for triangle {i}:\n{:?}",
                        out.get(&pin),
                        tris[i]
                    ));
                }
            }
        }
        was_valid = valid && !ready;
        if valid && ready {
            timing[in_flight[0]].handed = now;
            in_flight.pop_front();
            done += 1;
        }
        if presenting && out.get("inp$ready").bit(0) {
            timing[next].taken = now;
            in_flight.push_back(next);
            next += 1;
            presenting = false;
        }
        (free, free_next) = (free_next, flow.next_ready(free_next, rng));
        now += 1;
    }
    Ok(timing)
}

/// `tris` through rust-hdl and Verilator (the default K and L) in lockstep.
fn dual(tris: &[Sorted], flow: Flow) -> Vec<Taken> {
    let seed = seed();
    let vl = verilated("triangle_setup");
    let mut dual = Dual::new(TriangleSetup::new(K, L).expect("K, L"), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    run(&mut |p| dual.cycle(p).map_err(|m| m.to_string()), tris, flow, &mut rng)
        .unwrap_or_else(|e| panic!("{e}\nseed {seed}"))
}

/// `tris` through rust-hdl's simulator alone, with `k` multipliers and an `l`-stage divider.
fn hdl_only(k: usize, l: usize, tris: &[Sorted], flow: Flow) -> Vec<Taken> {
    let mut sim = HdlSim::new(TriangleSetup::new(k, l).expect("K, L"));
    let outs = outputs(&sim.unit);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut cycle = |pins: &[(&str, Value)]| Ok(hdl_cycle(&mut sim, &outs, pins));
    run(&mut cycle, tris, flow, &mut rng).unwrap_or_else(|e| panic!("{e}\nseed {} (K = {k}, L = {l})", seed()))
}

/// `n` random triangles that pass `cull_sort` (skewed toward the degenerate ones).
fn random(rng: &mut ChaCha8Rng, n: usize) -> Vec<Sorted> {
    let mut tris = Vec::with_capacity(n);
    while tris.len() < n {
        tris.extend(sorted(&[random_case(rng)]));
    }
    tris
}

#[test]
fn triangle_setup_random_vs_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    dual(&random(&mut rng, count()), Flow::STALLING);
}

/// The synthetic extremes that pass `cull_sort` (the largest and the unit area, slivers
/// with the steepest edges, flat tops and bottoms, vertices on the clip planes, z and
/// colours at their limits), back to back and with stalls.
#[test]
fn triangle_setup_extremes_vs_model() {
    let tris = sorted(&extremes().into_iter().map(|(_, c)| c).collect::<Vec<_>>());
    assert!(tris.len() >= 15, "only {} extreme triangles pass cull_sort", tris.len());
    dual(&tris, Flow::BACK_TO_BACK);
    dual(&tris, Flow::STALLING);
}

/// The shipped scenes through the geometry stage, `to_fixed` and `cull_sort`: realistic
/// triangles (all five models at 640x480, and the scene across the screen edges and the
/// near plane at 320x240).
#[test]
fn triangle_setup_scenes_vs_model() {
    let mut cases = scene("all", Cull::Back);
    cases.extend(scene("clip", Cull::None));
    dual(&sorted(&cases), Flow::STALLING);
}

/// 001 eq. (2) on its own worst case: an 800-pixel base and a colour step of 255 at
/// 800x600, where eq. (1)'s first product overflows a gradient register (see the model's
/// `triangle_setup_paper_001_eq2_fits_where_eq1_overflows`); the RTL computes the
/// model's values, and no register of the model wrapped.
#[test]
fn triangle_setup_paper_001_eq2_worst_case() {
    let t = [
        Vertex::new(0.0, 0.0, 0.5, [0.0; 3]),
        Vertex::new(0.0, 599.0, 0.5, [255.0; 3]),
        Vertex::new(800.0, 600.0, 0.5, [0.0; 3]),
    ];
    let clip = model::cull_sort::Clip { width: 800, height: 600 };
    let v = model::input::to_fixed(&t, &FORMATS).expect("fits");
    let tris = sorted(&[Case { v, clip, cull: Cull::None }]);
    let mut ctx = Ctx::new(FORMATS);
    triangle_setup(&tris[0], &mut ctx);
    assert_eq!(ctx.overflowed(), vec![], "no register of setup wraps");
    dual(&tris, Flow::BACK_TO_BACK);
}

/// 001 Table 3 gives setup 34 cycles (7 multipliers, one 5-stage divider); this setup's
/// schedule takes `model::cycles::setup_latency` = 52 with the default 25-stage divider (32
/// with 001's 5 stages: its pipelined multipliers' three registers on each of the four
/// dependent products of the longest path; derived in `model::triangle_setup::schedule`'s
/// tests) and takes a triangle every 10 cycles (`SetupTiming::interval`), six in flight.
/// Back to back with the output always taken,
/// each triangle's result is valid that many cycles after it is taken, and the next
/// triangle is taken 10 cycles after the one before.
#[test]
fn triangle_setup_latency_and_ii_paper_001_table3() {
    let t = Timing { setup_multipliers: K as u32, divider_latency: L as u32, ..Timing::default() };
    let SetupTiming { latency, interval } = setup_timing(&t);
    assert_eq!((latency, interval), (52, 10));
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let timing = dual(&random(&mut rng, 40), Flow::BACK_TO_BACK);
    // Offered from the first cycle after reset, the first triangle is taken in it.
    assert_eq!(timing[0].taken, 0, "{:?}", timing[0]);
    for (i, t) in timing.iter().enumerate() {
        assert_eq!(t.valid - t.taken, latency as u64, "triangle {i}: {t:?}");
    }
    for (i, w) in timing.windows(2).enumerate() {
        assert_eq!(w[1].taken - w[0].taken, interval as u64, "triangles {i} and {}: II", i + 1);
    }
}

/// While a result waits for the edge walk, setup holds every triangle behind it (six are
/// in flight): with the output rarely taken, each result is valid exactly 52 cycles of
/// running after its triangle was taken, the waits of the results ahead of it that began
/// after it was taken added.
#[test]
fn triangle_setup_waits_as_one_while_a_result_is_not_taken() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let tris = random(&mut rng, 12);
    let timing = dual(&tris, Flow { idle: 0.0, stall: 0.5, resume: 0.05 });
    assert_eq!(Schedule::new(K, L).expect("K, L").copies, 6);
    let mut overlapped = 0;
    for (i, b) in timing.iter().enumerate() {
        let ahead = timing[..i].iter().filter(|a| a.valid > b.taken);
        let wait: u64 = ahead.clone().map(|a| a.handed - a.valid).sum();
        overlapped += (ahead.count() > 1) as usize;
        assert_eq!(b.valid - b.taken, 52 + wait, "triangle {i}: {b:?} after {:?}", &timing[..i]);
        if i > 0 {
            assert!(b.taken >= timing[i - 1].taken + 10, "triangles {} and {i}: II", i - 1);
        }
    }
    // Some triangle waited for two results ahead of it, not only the one before.
    assert!(overlapped > 0, "{timing:?}");
}

/// Setup builds for every supported K and L (a copy's part of the schedule, II cycles,
/// fits its token's 64 bits), and says which are not supported.
#[test]
fn triangle_setup_builds_for_every_k_and_l() {
    for k in 1..=MULTIPLIERS_MAX {
        for l in 1..=LATENCY_MAX {
            let s = Schedule::new(k, l).expect("supported");
            assert!(s.interval <= 64, "K = {k}, L = {l}: {s:?}");
            assert!(TriangleSetup::new(k, l).is_ok(), "K = {k}, L = {l}");
        }
    }
    for (k, l) in [(0, 5), (MULTIPLIERS_MAX + 1, 5), (7, 0), (7, LATENCY_MAX + 1)] {
        assert!(TriangleSetup::new(k, l).is_err(), "K = {k}, L = {l}");
    }
}

/// Other multiplier counts and divider depths, in rust-hdl's simulator (each would be a
/// Verilator build of its own): bit-exact, with the model's latency and II.
#[test]
fn triangle_setup_other_k_and_l_rust_hdl() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let tris = random(&mut rng, 60);
    // (7, 5) and (7, 13), 001's divider and two steps a stage: four and five copies of the
    // registers (latency 32 and 42), II still 10.
    for (k, l) in [(1, 5), (3, 2), (4, 9), (7, 1), (7, 5), (7, 13)] {
        let t = Timing { setup_multipliers: k as u32, divider_latency: l as u32, ..Timing::default() };
        let timing = hdl_only(k, l, &tris, Flow::STALLING);
        let back_to_back = hdl_only(k, l, &tris[..5], Flow::BACK_TO_BACK);
        for t2 in back_to_back.iter().chain(&timing[..1]) {
            assert_eq!(t2.valid - t2.taken, setup_latency(&t) as u64, "K = {k}, L = {l}: {t2:?}");
        }
        for w in back_to_back.windows(2) {
            assert_eq!(w[1].taken - w[0].taken, setup_timing(&t).interval as u64, "K = {k}, L = {l}: II");
        }
    }
    let (s5, s13) = (Schedule::new(7, 5).unwrap(), Schedule::new(7, 13).unwrap());
    assert_eq!((s5.copies, s5.interval, s13.copies, s13.interval), (4, 10, 5, 10));
}
