//! `cull_sort` (paper 003): rust-hdl and Verilator in lockstep, every output compared on
//! every cycle, and each triangle's verdict and sorted vertices checked against
//! `model::cull_sort`; latency and initiation interval against its constants.

use model::cull_sort::{cull_sort, Cull, Reject, Sorted, II, LATENCY};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rtl::cull_sort::{verdict, CullSort, OUTCODE};
use rtl::switch::Parts;
use rtl::widths::{DIM, FORMATS};
use std::collections::VecDeque;
use testbenches::flow::Flow;
use testbenches::stimulus::{extremes, random_case, scene, Case};
use testbenches::streams::{as_pins, raw, sorted, triangle, PinValues};
use testbenches::{count, seed, verilated, verilated_with, Dual, Mismatch, Value};

/// A case on the input ports.
fn case_pins(c: &Case) -> PinValues {
    let mut out = vec![
        ("width".to_owned(), raw(DIM, c.clip.width as i128)),
        ("height".to_owned(), raw(DIM, c.clip.height as i128)),
        ("cull_back".to_owned(), Value::new(1, (c.cull == Cull::Back) as u128)),
    ];
    out.extend(triangle("inp", &c.v));
    out
}

/// A passing triangle on the output ports.
fn sorted_pins(s: &Sorted) -> PinValues {
    sorted("out", s)
}

/// The verdict ports' values for a model result.
fn verdict_of(r: &Result<Sorted, Reject>) -> (u64, u8) {
    match r {
        Ok(_) => (verdict::PASSED, 0),
        Err(Reject::Outside(planes)) => (verdict::OUTSIDE, *planes),
        Err(Reject::BackFace) => (verdict::BACK_FACE, 0),
        Err(Reject::ZeroArea) => (verdict::ZERO_AREA, 0),
    }
}

/// When each triangle was taken and when it left, in cycles.
#[derive(Clone, Copy, Debug, Default)]
struct Timing {
    taken: u64,
    left: u64,
}

/// Runs `cases` through both simulators (`flow` from `rng`), checks every verdict and
/// every passing triangle against the model, and returns each triangle's timing.
fn run(dual: &mut Dual<CullSort>, cases: &[Case], flow: Flow, rng: &mut ChaCha8Rng) -> Result<Vec<Timing>, Mismatch> {
    let expected: Vec<_> = cases.iter().map(|c| cull_sort(&c.v, c.clip, c.cull, &FORMATS)).collect();
    let mut timing = vec![Timing::default(); cases.len()];
    let (mut next, mut presenting, mut ready, mut done) = (0, false, true, 0);
    let mut in_flight: VecDeque<usize> = VecDeque::new();
    let limit = 20 * cases.len() as u64 + 100;
    while done < cases.len() {
        assert!(dual.cycles() < limit, "cull_sort: {done} of {} triangles out after {limit} cycles", cases.len());
        if next < cases.len() {
            presenting = flow.offer(presenting, rng);
        }
        let mut pins = case_pins(&cases[next.min(cases.len() - 1)]);
        pins.push(("inp$valid".into(), Value::new(1, presenting as u128)));
        pins.push(("out$ready".into(), Value::new(1, ready as u128)));
        let out = dual.cycle(&as_pins(&pins))?;
        let cycle = dual.cycles() - 1;
        let bit = |pin: &str| out.get(pin).bit(0);
        assert_eq!(
            bit("out$valid") && ready,
            bit("verdict$valid") && out.get("verdict$code") == &Value::new(2, verdict::PASSED as u128),
            "cycle {cycle}: a passing triangle leaves exactly when it is taken downstream"
        );
        if bit("verdict$valid") {
            let i = in_flight.pop_front().expect("a verdict for a triangle taken");
            let (code, planes) = verdict_of(&expected[i]);
            dual.expect(&out, "verdict$code", &Value::new(2, code as u128))?;
            dual.expect(&out, "verdict$outside", &raw(OUTCODE, planes as i128))?;
            if let Ok(s) = &expected[i] {
                for (pin, v) in sorted_pins(s) {
                    dual.expect(&out, &pin, &v)?;
                }
            }
            timing[i].left = cycle;
            done += 1;
        }
        if presenting && bit("inp$ready") {
            timing[next].taken = cycle;
            in_flight.push_back(next);
            next += 1;
            presenting = false;
        }
        ready = flow.next_ready(ready, rng);
    }
    Ok(timing)
}

/// Runs `cases` with `flow`; on a mismatch, panics with the seed and the case.
fn check(cases: &[Case], flow: Flow, seed: u64) -> Vec<Timing> {
    let vl = verilated("cull_sort");
    let mut dual = Dual::new(CullSort::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    run(&mut dual, cases, flow, &mut rng)
        .unwrap_or_else(|m| panic!("{m}\nseed {seed}; cases in flight: see the inputs"))
}

#[test]
fn cull_sort_random_vs_model() {
    let (seed, n) = (seed(), count());
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let cases: Vec<Case> = (0..n).map(|_| random_case(&mut rng)).collect();
    check(&cases, Flow::STALLING, seed);
}

#[test]
fn cull_sort_extremes_vs_model() {
    let cases: Vec<Case> = extremes().into_iter().map(|(_, c)| c).collect();
    // Every verdict occurs among them.
    let codes: Vec<u64> = cases.iter().map(|c| verdict_of(&cull_sort(&c.v, c.clip, c.cull, &FORMATS)).0).collect();
    for code in [verdict::PASSED, verdict::OUTSIDE, verdict::BACK_FACE, verdict::ZERO_AREA] {
        assert!(codes.contains(&code), "no extreme case gets verdict {code}");
    }
    check(&cases, Flow::BACK_TO_BACK, seed());
    check(&cases, Flow::STALLING, seed());
}

/// The shipped scenes through the geometry stage and `to_fixed`: realistic triangles, at
/// 640x480 with back faces culled and at 320x240 across the screen edges and near plane.
#[test]
fn cull_sort_scenes_vs_model() {
    let mut cases = scene("all", Cull::Back);
    cases.extend(scene("clip", Cull::None));
    check(&cases, Flow::STALLING, seed());
}

/// 003 Table 1: clipping (cull & sort) takes 1 cycle, a triangle per cycle; here three
/// pipeline stages (`rtl::cull_sort`). Back to back with the output always taken, one
/// triangle is taken per cycle and each leaves `LATENCY` cycles later.
#[test]
fn cull_sort_latency_and_ii_paper_003_table1() {
    assert_eq!((LATENCY, II), (3, 1));
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let cases: Vec<Case> = (0..200).map(|_| random_case(&mut rng)).collect();
    let t = check(&cases, Flow::BACK_TO_BACK, seed());
    for (i, w) in t.windows(2).enumerate() {
        assert_eq!(w[1].taken - w[0].taken, II as u64, "triangles {i} and {} taken back to back", i + 1);
    }
    for (i, t) in t.iter().enumerate() {
        assert_eq!(t.left - t.taken, LATENCY as u64, "triangle {i}: {t:?}");
    }
}

/// 003 Fig. 4: triangles across the clip boundary go on whole, so three of them send nine
/// vertices (clipping in geometry would send fifteen); one wholly outside sends none.
#[test]
fn cull_sort_paper_003_fig4_sends_nine_vertices() {
    let clip = model::cull_sort::Clip { width: 320, height: 240 };
    let (w, h) = (320 * 16, 240 * 16);
    let v = |x: i128, y: i128| model::input::Vtx { x, y, z: 30000, c: [200, 100, 50], iw: 32768 };
    let cases = [
        [v(-800, 400), v(1600, 800), v(-400, 1600)], // across the left edge
        [v(w - 400, h - 800), v(w + 900, h + 40), v(w - 1200, h + 600)], // across the bottom-right corner
        [v(1600, -300), v(2400, 600), v(900, 500)],  // across the top edge
        [v(w + 10, 100), v(w + 900, 900), v(w + 50, 2000)], // wholly right
    ]
    .map(|v| Case { v, clip, cull: Cull::None });
    let vl = verilated("cull_sort");
    let mut dual = Dual::new(CullSort::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut sent = Vec::new();
    for c in &cases {
        let mut pins = case_pins(c);
        pins.push(("inp$valid".into(), Value::new(1, 1)));
        pins.push(("out$ready".into(), Value::new(1, 1)));
        dual.cycle(&as_pins(&pins)).unwrap_or_else(|m| panic!("{m}"));
        let mut out = None;
        for _ in 0..LATENCY {
            out = Some(dual.cycle(&[("inp$valid", Value::new(1, 0))]).unwrap_or_else(|m| panic!("{m}")));
        }
        let out = out.expect("LATENCY >= 1");
        if out.get("out$valid").bit(0) {
            sent.extend((0..3).map(|i| out.get(&format!("out$v{i}_x")).clone()));
        }
    }
    assert_eq!(sent.len(), 9, "three crossing triangles, three vertices each, no new vertices");
    let model_sent: usize = cases.iter().filter_map(|c| cull_sort(&c.v, c.clip, c.cull, &FORMATS).ok()).count() * 3;
    assert_eq!(model_sent, 9);
}

/// Without rejecting and culling (`CULL = 0`, `rtl::switch`): the triangles that pass
/// the model's cull & sort (random ones, back faces not culled) are sorted as the model
/// sorts them, in both simulators; a back face with `cull_back` high passes, which the
/// model culls: the logic is gone.
#[test]
fn cull_sort_without_cull_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(3));
    let cases: Vec<Case> = (0..count())
        .map(|_| random_case(&mut rng))
        .filter(|c| cull_sort(&c.v, c.clip, c.cull, &FORMATS).is_ok())
        .collect();
    assert!(cases.len() > count() / 4, "enough triangles pass");
    let vl = verilated_with("cull_sort", [("CULL", 0)]);
    let unit = || CullSort::new(&Parts { cull: false, ..Parts::ALL });
    let mut dual = Dual::new(unit(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    run(&mut dual, &cases, Flow::STALLING, &mut rng).unwrap_or_else(|m| panic!("{m}\nseed {seed}"));
    let back = random_case_culled(&mut rng);
    let mut dual = Dual::new(unit(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let err = run(&mut dual, &[back], Flow::BACK_TO_BACK, &mut rng).expect_err("the back face passes");
    assert!(err.to_string().contains("verdict$code"), "{err}");
}

/// A random case the model culls as a back face.
fn random_case_culled(rng: &mut ChaCha8Rng) -> Case {
    loop {
        let c = Case { cull: Cull::Back, ..random_case(rng) };
        if cull_sort(&c.v, c.clip, c.cull, &FORMATS) == Err(Reject::BackFace) {
            return c;
        }
    }
}
