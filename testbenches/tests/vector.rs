//! The barycentric unit (paper 004): rust-hdl and Verilator in lockstep, every output
//! compared on every cycle, against `model::vector` at one lane: each pixel in walk order,
//! and, back to back, the cycle each triangle is taken and each pixel leaves
//! (`model::cycles::VectorUnit`: setup overlapping the walk before).

use model::ctx::Ctx;
use model::cull_sort::{cull_sort, Clip, Cull, Sorted};
use model::cycles::VectorUnit;
use model::span::Pixel;
use model::vector::{pixel_latency, vector, VectorOut};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rtl::vector::Vector;
use rtl::widths::{DIM, FORMATS};
use testbenches::flow::Flow;
use testbenches::stimulus::{extremes, random_triangle};
use testbenches::streams::{as_pins, pixel_of, raw, sorted};
use testbenches::{count, seed, verilated_with, Dual, Value};

/// The screen the tests draw on: small, so that a triangle's box is at most 3,072 pixels
/// (triangles may reach far beyond it).
const CLIP: Clip = Clip { width: 64, height: 48 };

/// A triangle for the unit, and what the model makes of it.
struct Job {
    sorted: Sorted,
    out: VectorOut,
}

fn job(sorted: Sorted, perspective: bool) -> Job {
    let out = vector(&sorted, CLIP, 1, perspective, &mut Ctx::new(FORMATS));
    Job { sorted, out }
}

/// The triangles among `v` that cull & sort lets through (back faces kept), as jobs.
fn jobs(v: impl IntoIterator<Item = [model::input::Vtx; 3]>, perspective: bool) -> Vec<Job> {
    v.into_iter().filter_map(|v| cull_sort(&v, CLIP, Cull::None, &FORMATS).ok()).map(|s| job(s, perspective)).collect()
}

/// The unit in both simulators, with or without perspective-correct colours.
fn dual(perspective: bool) -> Dual<Vector> {
    dual_with(perspective, model::divider::LATENCY)
}

/// [`dual`] with `l` divider stages.
fn dual_with(perspective: bool, l: u32) -> Dual<Vector> {
    let vl = verilated_with("vector", [("PERSPECTIVE", perspective as u64), ("L", l as u64)]);
    let unit = Vector::new(l as usize, perspective).unwrap_or_else(|e| panic!("{e}"));
    Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// Runs `jobs` through `dual` with `flow` and checks every pixel against the model, in
/// order; returns the cycle each triangle was taken and each pixel left, per triangle.
fn run(dual: &mut Dual<Vector>, jobs: &[Job], flow: Flow, seed: u64) -> Vec<(u64, Vec<u64>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let expected: Vec<(usize, Pixel)> =
        jobs.iter().enumerate().flat_map(|(j, job)| job.out.pixels.iter().map(move |p| (j, *p))).collect();
    let mut times: Vec<(u64, Vec<u64>)> = Vec::new();
    let (mut next, mut presenting, mut ready, mut got, mut idle) = (0, false, true, 0, false);
    let work: u64 = jobs.iter().map(|j| j.out.walk_cycles as u64 + 100).sum();
    let limit = 4 * work + 1000;
    let fail = |m: testbenches::Mismatch| panic!("{m}\nseed {seed}");
    while got < expected.len() || next < jobs.len() || !idle {
        assert!(dual.cycles() < limit, "vector: {got} of {} pixels after {limit} cycles", expected.len());
        if next < jobs.len() {
            presenting = flow.offer(presenting, &mut rng);
        }
        let mut pins = sorted("inp", &jobs[next.min(jobs.len() - 1)].sorted);
        pins.push(("width".into(), raw(DIM, CLIP.width as i128)));
        pins.push(("height".into(), raw(DIM, CLIP.height as i128)));
        pins.push(("inp$valid".into(), Value::new(1, presenting as u128)));
        pins.push(("out$ready".into(), Value::new(1, ready as u128)));
        let out = dual.cycle(&as_pins(&pins)).unwrap_or_else(fail);
        let cycle = dual.cycles() - 1;
        idle = out.get("idle").bit(0);
        if out.get("out$valid").bit(0) && ready {
            let (j, want) = expected.get(got).unwrap_or_else(|| panic!("cycle {cycle}: a pixel past the model's"));
            assert_eq!(pixel_of(&out, "out"), *want, "cycle {cycle}: pixel {got} (triangle {j}), seed {seed}");
            times[*j].1.push(cycle);
            got += 1;
        }
        if presenting && out.get("inp$ready").bit(0) {
            times.push((cycle, Vec::new()));
            next += 1;
            presenting = false;
        }
        ready = flow.next_ready(ready, &mut rng);
    }
    times
}

/// Back to back (each triangle offered from the cycle after the one before was taken), the
/// cycle each is taken and each of its pixels leaves (`pixel_latency` after its walk
/// cycle) are `model::cycles::VectorUnit`'s, exactly.
fn check_timing(jobs: &[Job], times: &[(u64, Vec<u64>)]) {
    check_timing_with(jobs, times, model::divider::LATENCY);
}

/// [`check_timing`] with `l` divider stages.
fn check_timing_with(jobs: &[Job], times: &[(u64, Vec<u64>)], l: u32) {
    assert_eq!(times.len(), jobs.len());
    let mut unit = VectorUnit::new(l);
    let mut offered = 0;
    for (j, (job, (taken, left))) in jobs.iter().zip(times).enumerate() {
        let t = unit.triangle(offered, job.out.walk_cycles);
        assert_eq!(*taken, t.taken, "triangle {j}: the cycle it was taken");
        offered = t.taken + 1;
        let want: Vec<u64> = match t.start {
            Some(start) => job.out.walk.iter().map(|&i| start + (i + pixel_latency(l)) as u64).collect(),
            None => Vec::new(),
        };
        assert_eq!(*left, want, "triangle {j}: the cycles its pixels left");
    }
}

fn random_jobs(n: usize, seed: u64, perspective: bool) -> Vec<Job> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    jobs((0..n).map(|_| random_triangle(&mut rng, CLIP)), perspective)
}

#[test]
fn vector_random_vs_model() {
    let seed = seed();
    for perspective in [true, false] {
        let jobs = random_jobs(count() / 40, seed, perspective);
        assert!(jobs.iter().map(|j| j.out.pixels.len()).sum::<usize>() > 1000, "the triangles draw pixels");
        let mut d = dual(perspective);
        let t = run(&mut d, &jobs, Flow::BACK_TO_BACK, seed);
        check_timing(&jobs, &t);
        run(&mut d, &jobs, Flow::STALLING, seed);
    }
}

/// With 001's 5-stage divider (setup 13 cycles, each pixel out 21 cycles after its walk
/// cycle), as the model's timing for it says.
#[test]
fn vector_with_a_5_stage_divider_vs_model() {
    let jobs = random_jobs(count() / 100, seed(), true);
    let mut d = dual_with(true, 5);
    let t = run(&mut d, &jobs, Flow::BACK_TO_BACK, seed());
    check_timing_with(&jobs, &t, 5);
    assert_eq!((model::vector::setup(5), model::vector::pixel_latency(5)), (13, 21));
}

/// The triangles at the limits of `xy`, z and colour (`stimulus::extremes`) on the small
/// screen: the widest edge functions and areas, unit areas, every winding, w_min / w = 0.
#[test]
fn vector_extremes_vs_model() {
    let jobs = jobs(extremes().into_iter().map(|(_, c)| c.v), true);
    let mut d = dual(true);
    let t = run(&mut d, &jobs, Flow::BACK_TO_BACK, seed());
    check_timing(&jobs, &t);
}

/// 004's per-pixel unit draws a pixel a cycle: a triangle covering the whole screen walks
/// its box in as many cycles, and its pixels leave one a cycle; its colours are
/// perspective-correct (eq. 5-6), its depth screen-linear.
#[test]
fn vector_one_pixel_per_cycle_paper_004() {
    let (w, h) = (CLIP.width as i128 * 16, CLIP.height as i128 * 16);
    let v = |x, y, z, c, iw| model::input::Vtx { x, y, z, c, iw };
    let cover = [
        v(-w, -h, 30000, [255, 0, 0], 32768),
        v(3 * w, -h, 20000, [0, 255, 0], 16384),
        v(-w, 3 * h, 10000, [0, 0, 255], 8192),
    ];
    let jobs = jobs([cover], true);
    assert_eq!(jobs[0].out.pixels.len() as u32, CLIP.width * CLIP.height);
    let flat = vector(&jobs[0].sorted, CLIP, 1, false, &mut Ctx::new(FORMATS));
    let moved = jobs[0].out.pixels.iter().zip(&flat.pixels).filter(|(p, q)| p.rgb != q.rgb && p.z == q.z).count();
    assert!(moved > 1000, "perspective moves the colours, not the depth: {moved} pixels");
    assert_eq!(jobs[0].out.walk_cycles, CLIP.width * CLIP.height);
    let t = run(&mut dual(true), &jobs, Flow::BACK_TO_BACK, seed());
    check_timing(&jobs, &t);
    assert!(t[0].1.windows(2).all(|p| p[1] == p[0] + 1), "a pixel every cycle");
}
