//! The edge walk (001 §II.2, 003 Fig. 5): rust-hdl and Verilator in lockstep, every cycle,
//! against `model::edge_walk`: each scanline's span command, and when it comes (the
//! model's `LATENCY` and `II`, and a walk that holds while `out$ready` is low).

use model::ctx::Ctx;
use model::cull_sort::outcode::{BOTTOM, TOP};
use model::cull_sort::{cull_sort, outcode, Clip, Cull};
use model::edge_walk::{edge_walk, SpanCmd, II, LATENCY};
use model::input::Vtx;
use model::triangle_setup::{triangle_setup, TriangleSetupOut, Walk};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::edge_walk::EdgeWalk;
use rtl::switch::Parts;
use rtl::widths::{DIM, FORMATS};
use testbenches::stimulus::{extremes, random_triangle};
use testbenches::streams::{as_pins, span_cmd_of, triangle_setup_out, PinValues};
use testbenches::{count, seed, verilated, verilated_with, Dual, Value};

/// One triangle for the walk: its setup, screen height and the model's scanlines.
struct Job {
    setup: TriangleSetupOut,
    height: u32,
    scanlines: Vec<Option<SpanCmd>>,
    pins: PinValues,
}

/// The triangle `v` on `clip` through the model's cull_sort, setup and edge walk (None
/// when culled).
fn job(v: &[Vtx; 3], clip: Clip) -> Option<Job> {
    let sorted = cull_sort(v, clip, Cull::None, &FORMATS).ok()?;
    let mut ctx = Ctx::new(FORMATS);
    let setup = triangle_setup(&sorted, &mut ctx);
    let scanlines = edge_walk(&setup, clip, &mut ctx).scanlines;
    Some(Job { pins: triangle_setup_out("inp", &setup), setup, height: clip.height, scanlines })
}

/// Small screens, where random triangles cross every boundary often and walks are short.
const SCREENS: [Clip; 4] = [
    Clip { width: 1, height: 1 },
    Clip { width: 7, height: 5 },
    Clip { width: 64, height: 48 },
    Clip { width: 320, height: 240 },
];

fn random_jobs(seed: u64, n: usize) -> Vec<Job> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out = Vec::new();
    while out.len() < n {
        let clip = SCREENS[rng.gen_range(0..SCREENS.len())];
        out.extend(job(&random_triangle(&mut rng, clip), clip));
    }
    out
}

/// What the walk does this cycle, by the timing contract.
#[derive(Clone, Copy, Debug)]
enum State {
    Idle,
    /// `left` cycles until the first scanline of job `i`.
    Setup {
        i: usize,
        left: u32,
    },
    /// Presenting scanline `k` of job `i`.
    Walk {
        i: usize,
        k: usize,
    },
}

/// Counts from one run.
#[derive(Debug, Default)]
struct Run {
    cycles: u64,
    commands: u64,
    stalls: u64,
}

/// Runs `jobs` back to back (a job on another screen waits for the walk to finish) with
/// `out$ready` from `ready`; checks every cycle: `inp$ready` high exactly when the
/// contract says the walk is idle, and `out$valid` and the command exactly as the model's
/// scanline due that cycle. Returns the counts, or the first difference.
fn run(dual: &mut Dual<EdgeWalk>, jobs: &[Job], mut ready: impl FnMut(&mut ChaCha8Rng) -> bool) -> Result<Run, String> {
    assert_eq!(II, 1, "this bench steps one scanline per cycle");
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let (mut state, mut next, mut height, mut r) = (State::Idle, 0, 0, Run::default());
    let where_ = |i: usize| format!("triangle {i}: {:?}", jobs[i].setup);
    while next < jobs.len() || !matches!(state, State::Idle) {
        let idle = matches!(state, State::Idle);
        // A new screen height only while the walk is idle.
        let offer = next < jobs.len() && (jobs[next].height == height || idle);
        if offer {
            height = jobs[next].height;
        }
        let out_ready = ready(&mut rng);
        let mut pins = vec![
            ("height", Value::new(DIM, height as u128)),
            ("inp$valid", Value::new(1, offer as u128)),
            ("out$ready", Value::new(1, out_ready as u128)),
        ];
        if offer {
            pins.extend(as_pins(&jobs[next].pins));
        }
        let out = dual.cycle(&pins).map_err(|m| m.to_string())?;
        let cycle = dual.cycles() - 1;
        let got_ready = out.get("inp$ready") == &Value::new(1, 1);
        if got_ready != idle {
            return Err(format!("cycle {cycle}: inp$ready {got_ready}, expected {idle} in {state:?}"));
        }
        let due = match state {
            State::Walk { i, k } => jobs[i].scanlines[k].map(|c| (i, c)),
            _ => None,
        };
        let valid = out.get("out$valid") == &Value::new(1, 1);
        match due {
            Some((i, cmd)) => {
                let got = span_cmd_of(&out, "out");
                if !valid || got != cmd {
                    return Err(format!(
                        "cycle {cycle}: {state:?}: got valid {valid} {got:?}, model {cmd:?}; {}",
                        where_(i)
                    ));
                }
            }
            None if valid => return Err(format!("cycle {cycle}: out$valid high in {state:?}")),
            None => {}
        }
        state = match state {
            State::Idle if offer => {
                next += 1;
                State::Setup { i: next - 1, left: LATENCY - 1 }
            }
            State::Idle => State::Idle,
            State::Setup { i, left } if left > 1 => State::Setup { i, left: left - 1 },
            State::Setup { i, .. } if jobs[i].scanlines.is_empty() => State::Idle,
            State::Setup { i, .. } => State::Walk { i, k: 0 },
            State::Walk { i, k } if due.is_some() && !out_ready => {
                r.stalls += 1;
                State::Walk { i, k }
            }
            State::Walk { i, k } => {
                r.commands += due.is_some() as u64;
                if k + 1 == jobs[i].scanlines.len() {
                    State::Idle
                } else {
                    State::Walk { i, k: k + 1 }
                }
            }
        };
    }
    r.cycles = dual.cycles();
    Ok(r)
}

fn dual(vl: &testbenches::Verilated) -> Dual<EdgeWalk> {
    Dual::new(EdgeWalk::default(), vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// Random triangles on small screens, `out$ready` always high: every command at the
/// model's cycle (first `LATENCY` cycles after the triangle is taken, then one scanline per
/// cycle, the next triangle taken the cycle after the last scanline).
#[test]
fn edge_walk_random_vs_model() {
    let seed = seed();
    let jobs = random_jobs(seed, count());
    let vl = verilated("edge_walk");
    let mut d = dual(&vl);
    let r = run(&mut d, &jobs, |_| true).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    let scanlines: usize = jobs.iter().map(|j| j.scanlines.len()).sum();
    // Back to back: each triangle costs LATENCY cycles plus one per scanline.
    assert_eq!(r.cycles, (jobs.len() * LATENCY as usize + scanlines) as u64, "seed {seed}");
    assert!(r.commands > 0 && r.stalls == 0);
}

/// The same with `out$ready` low 40% of the time: the walk holds a command until it is
/// taken and loses no cycle otherwise.
#[test]
fn edge_walk_back_pressure_vs_model() {
    let seed = seed();
    let jobs = random_jobs(seed.wrapping_add(1), count() / 2);
    let vl = verilated("edge_walk");
    let mut d = dual(&vl);
    let r = run(&mut d, &jobs, |rng| rng.gen_bool(0.6)).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    let scanlines: usize = jobs.iter().map(|j| j.scanlines.len()).sum();
    assert_eq!(r.cycles, (jobs.len() * LATENCY as usize + scanlines) as u64 + r.stalls, "seed {seed}");
    assert!(r.stalls > 0);
}

/// The synthetic triangles at the limits of the formats (`stimulus::extremes`) on the
/// 1024 x 1024 screen, and the Y clipping cases on a 64 x 48 screen: walking up from a
/// triangle crossing row 0 only (stops after row 0), down across both boundaries (cycles
/// above the screen, none below it), flat tops and bottoms (a short edge with no
/// scanline), a start exactly on the boundary (no scanline left: no walk).
#[test]
fn edge_walk_edge_cases_vs_model() {
    let px = 1i128 << FORMATS.xy.frac;
    let clip = Clip { width: 64, height: 48 };
    let v = |x: f64, y: f64| Vtx {
        x: (x * px as f64) as i128,
        y: (y * px as f64) as i128,
        z: 30000,
        c: [10, 200, 90],
        iw: 0,
    };
    let (down, up) = (Walk::Down, Walk::Up);
    let one = Clip { width: 1, height: 1 };
    // (what, vertices, screen, walk direction, no scanline at all)
    let cases: Vec<(&str, [Vtx; 3], Clip, Walk, bool)> = vec![
        ("crosses row 0 only", [v(3.0, -20.0), v(40.0, 10.0), v(10.0, 30.0)], clip, up, false),
        ("crosses both", [v(3.0, -20.0), v(40.0, 60.0), v(10.0, 30.0)], clip, down, false),
        ("flat top", [v(3.0, 4.5), v(40.0, 4.5), v(10.0, 30.0)], clip, down, false),
        ("flat bottom", [v(20.0, 4.0), v(40.0, 30.5), v(1.0, 30.5)], clip, down, false),
        ("flat top, crossing row 0", [v(-5.0, -3.5), v(40.0, -3.5), v(10.0, 30.0)], clip, up, false),
        ("flat bottom, crossing row 0", [v(20.0, -9.0), v(40.0, 30.5), v(1.0, 30.5)], clip, up, false),
        ("top vertex on the bottom edge of the screen", [v(3.0, 48.0), v(40.0, 50.0), v(10.0, 60.0)], clip, down, true),
        ("bottom vertex on row 0's centre", [v(3.0, -9.0), v(40.0, 0.5), v(10.0, -3.0)], clip, up, true),
        ("one scanline", [v(3.0, 10.4), v(40.0, 10.6), v(10.0, 10.55)], clip, down, false),
        ("across the left edge", [v(-30.0, 4.0), v(2.0, 20.0), v(-10.0, 30.0)], clip, down, false),
        ("covering a 1 x 1 screen", [v(-3.0, -3.0), v(9.0, 0.0), v(0.0, 9.0)], one, down, false),
    ];
    let mut jobs: Vec<Job> = Vec::new();
    for (what, v, clip, walk, empty) in &cases {
        let j = job(v, *clip).unwrap_or_else(|| panic!("{what}: culled"));
        assert_eq!((j.setup.walk, j.scanlines.is_empty()), (*walk, *empty), "{what}");
        jobs.push(j);
    }
    for (_, c) in extremes().into_iter().filter(|(_, c)| c.cull == Cull::None) {
        jobs.extend(job(&c.v, c.clip));
    }
    let vl = verilated("edge_walk");
    let mut d = dual(&vl);
    run(&mut d, &jobs, |_| true).unwrap_or_else(|e| panic!("{e}"));
    let mut d = dual(&vl);
    run(&mut d, &jobs, |rng| rng.gen_bool(0.5)).unwrap_or_else(|e| panic!("with back-pressure: {e}"));
}

/// 003 Table 1: the edge walk's latency is 2 cycles. One triangle, `out$ready` high: taken
/// in cycle 0, its first scanline in cycle 2, the next one in cycle 3.
#[test]
fn edge_walk_latency_003_table1() {
    assert_eq!((LATENCY, II), (2, 1));
    let px = 1i128 << FORMATS.xy.frac;
    let v = |x: i128, y: i128| Vtx { x: x * px, y: y * px, z: 1000, c: [1, 2, 3], iw: 0 };
    let j = job(&[v(1, 1), v(30, 2), v(5, 20)], Clip { width: 64, height: 48 }).expect("on screen");
    assert!(j.scanlines[0].is_some() && j.scanlines[1].is_some());
    let vl = verilated("edge_walk");
    let mut d = dual(&vl);
    let mut pins =
        vec![("height", Value::new(DIM, 48)), ("inp$valid", Value::new(1, 1)), ("out$ready", Value::new(1, 1))];
    pins.extend(as_pins(&j.pins));
    let mut valid = Vec::new();
    for t in 0..4 {
        let idle = [("inp$valid", Value::new(1, 0))];
        let out = d.cycle(if t == 0 { &pins } else { &idle }).unwrap_or_else(|m| panic!("{m}"));
        if t == 0 {
            assert_eq!(out.get("inp$ready"), &Value::new(1, 1), "taken in cycle 0");
        }
        valid.push(out.get("out$valid") == &Value::new(1, 1));
    }
    assert_eq!(valid, [false, false, true, true], "out$valid in cycles 0 to 3");
}

/// Without Y clipping (`CLIP_Y = 0`, `rtl::switch`): random triangles within the screen's
/// rows, which need none, walk as the model walks them, in both simulators and with
/// back-pressure; a triangle crossing row 0 does not: the logic is gone.
#[test]
fn edge_walk_without_clip_y_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(5));
    let mut jobs = Vec::new();
    while jobs.len() < count() / 2 {
        let clip = SCREENS[rng.gen_range(0..SCREENS.len())];
        let v = random_triangle(&mut rng, clip);
        if v.iter().all(|p| outcode(p, clip, &FORMATS) & (TOP | BOTTOM) == 0) {
            jobs.extend(job(&v, clip));
        }
    }
    let vl = verilated_with("edge_walk", [("CLIP_Y", 0)]);
    let dual = || {
        Dual::new(EdgeWalk::new(&Parts { clip_y: false, ..Parts::ALL }), vl.model().unwrap_or_else(|e| panic!("{e}")))
    };
    let r = run(&mut dual(), &jobs, |rng| rng.gen_bool(0.7)).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    assert!(r.commands > 0 && r.stalls > 0);
    let px = 1i128 << FORMATS.xy.frac;
    let v = |x: i128, y: i128| Vtx { x: x * px, y: y * px, z: 1000, c: [1, 2, 3], iw: 0 };
    let crossing = job(&[v(3, -20), v(40, 10), v(10, 30)], Clip { width: 64, height: 48 }).expect("on screen");
    assert!(
        run(&mut dual(), &[crossing], |_| true).is_err(),
        "without Y clipping, a triangle across row 0 is walked wrongly"
    );
}
