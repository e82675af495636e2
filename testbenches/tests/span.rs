//! The span unit (001 §II.2, 003 Fig. 6): rust-hdl and Verilator in lockstep, every cycle,
//! against `model::span`: each pixel, and when it comes (the model's `LATENCY`, one
//! pixel or skipped pixel walked per cycle, a dropped span in one cycle, pixels held, and
//! the walk behind them, while `out$ready` is low).

use model::ctx::Ctx;
use model::cull_sort::{cull_sort, z_max, Clip, Cull};
use model::edge_walk::{edge_walk, SpanCmd};
use model::span::{span, Pixel, II, LATENCY};
use model::triangle_setup::{triangle_setup, Attrs};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::span::Span;
use rtl::switch::Parts;
use rtl::widths::{DIM, FORMATS};
use testbenches::stimulus::random_triangle;
use testbenches::streams::{as_pins, pixel_of, span_cmd, PinValues};
use testbenches::{count, seed, verilated, verilated_with, Dual, Value};

/// One span command on a screen `width` wide, with the model's pixels laid out in the
/// cycles the walk spends: `slots[i]` is the pixel sent in the i-th cycle, if any.
struct Job {
    cmd: SpanCmd,
    width: u32,
    slots: Vec<Option<Pixel>>,
    pins: PinValues,
}

fn job(cmd: SpanCmd, clip: Clip) -> Job {
    let out = span(&cmd, clip, &mut Ctx::new(FORMATS));
    // The walk order (003): right to left from xr when xl < 0, else left to right from xl.
    let slot = |p: &Pixel| if cmd.xl < 0 { cmd.xr - p.x as i128 } else { p.x as i128 - cmd.xl } as usize;
    let mut slots = vec![None; out.cycles as usize];
    for p in &out.pixels {
        slots[slot(p)] = Some(*p);
    }
    Job { pins: span_cmd("inp", &cmd), cmd, width: clip.width, slots }
}

/// The span commands of random triangles on `clip`, through the model's front end.
fn triangle_jobs(rng: &mut ChaCha8Rng, clip: Clip, n: usize) -> Vec<Job> {
    let mut out = Vec::new();
    while out.len() < n {
        let Ok(sorted) = cull_sort(&random_triangle(rng, clip), clip, Cull::None, &FORMATS) else { continue };
        let mut ctx = Ctx::new(FORMATS);
        let setup = triangle_setup(&sorted, &mut ctx);
        out.extend(edge_walk(&setup, clip, &mut ctx).spans().map(|c| job(*c, clip)));
    }
    out
}

/// Synthetic commands skewed toward the clipping cases: ends off either side of the
/// screen or both, depths beyond 0 or z_max at one or both ends, steps that walk out of
/// the depth range mid-span, colours that leave [0, 255].
fn synthetic_jobs(rng: &mut ChaCha8Rng, clip: Clip, n: usize) -> Vec<Job> {
    let w = clip.width as i128;
    let (zf, cf) = (FORMATS.z_acc.frac, FORMATS.c_acc.frac);
    let one_z = 1i128 << zf;
    let (za, ca) = (FORMATS.z_acc, FORMATS.c_acc);
    (0..n)
        .map(|_| {
            let xl = rng.gen_range(-2 * w - 3..2 * w + 3);
            let xr = xl + rng.gen_range(0..2 * w + 3);
            let z = |rng: &mut ChaCha8Rng| match rng.gen_range(0..4) {
                0 => rng.gen_range(-one_z / 4..0),
                1 => rng.gen_range(one_z - one_z / 4..one_z + one_z / 4),
                2 => rng.gen_range(za.min_raw()..=za.max_raw()),
                _ => rng.gen_range(0..one_z),
            };
            let c = |rng: &mut ChaCha8Rng| match rng.gen_range(0..3) {
                0 => rng.gen_range(ca.min_raw()..=ca.max_raw()),
                _ => rng.gen_range(-(8i128 << cf)..(264i128 << cf)),
            };
            let a = |rng: &mut ChaCha8Rng| Attrs { z: z(rng), c: [c(rng), c(rng), c(rng)] };
            let step = |rng: &mut ChaCha8Rng, f: fx::Fmt, scale: u32| match rng.gen_range(0..4) {
                0 => rng.gen_range(f.min_raw()..=f.max_raw()),
                _ => rng.gen_range(-(1i128 << (f.frac - scale))..(1i128 << (f.frac - scale))),
            };
            let ddx = Attrs { z: step(rng, FORMATS.dz, 4), c: std::array::from_fn(|_| step(rng, FORMATS.dc, 0)) };
            let y = rng.gen_range(0..clip.height) as i32;
            job(SpanCmd { y, xl, xr, left: a(rng), right: a(rng), ddx }, clip)
        })
        .collect()
}

/// What the walk does this cycle, by the timing contract.
#[derive(Clone, Copy, Debug)]
enum State {
    Idle,
    /// In cycle `k` of job `i`'s walk.
    Walk {
        i: usize,
        k: usize,
    },
}

/// Runs `jobs` back to back (one on another screen waits until the walk is idle) with
/// `out$ready` from `ready`; checks every cycle `inp$ready`, `out$valid` and the pixel
/// against the model's slots: the walk takes a slot per cycle while the pixel register is
/// empty or being taken, and a sent slot's pixel is in the pixel register (on `out$*`) the
/// cycle after. Returns (cycles, stalls): the cycles in all, and those in which the pixel
/// register held a pixel not taken while the walk had a slot to move on from or nothing
/// more to do.
fn run(
    dual: &mut Dual<Span>,
    jobs: &[Job],
    mut ready: impl FnMut(&mut ChaCha8Rng) -> bool,
) -> Result<(u64, u64), String> {
    assert_eq!(
        (LATENCY, II),
        (2, 1),
        "this bench walks a command from the cycle after it is taken, then registers each pixel"
    );
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let (mut state, mut next, mut width, mut stalls) = (State::Idle, 0, 0, 0);
    // The pixel register: the pixel on `out$*`, and the command it came from.
    let mut held: Option<(Pixel, usize)> = None;
    while next < jobs.len() || !matches!(state, State::Idle) || held.is_some() {
        let out_ready = ready(&mut rng);
        let due = match state {
            State::Walk { i, k } => jobs[i].slots[k],
            State::Idle => None,
        };
        let free = held.is_none() || out_ready;
        let leaving = match state {
            State::Walk { i, k } => k + 1 == jobs[i].slots.len() && free,
            State::Idle => true,
        };
        let offer = next < jobs.len() && (jobs[next].width == width || matches!(state, State::Idle));
        if offer && matches!(state, State::Idle) {
            width = jobs[next].width;
        }
        let mut pins = vec![
            ("width", Value::new(DIM, width as u128)),
            ("inp$valid", Value::new(1, offer as u128)),
            ("out$ready", Value::new(1, out_ready as u128)),
        ];
        if offer {
            pins.extend(as_pins(&jobs[next].pins));
        }
        let out = dual.cycle(&pins).map_err(|m| m.to_string())?;
        let cycle = dual.cycles() - 1;
        let at = |i: usize| format!("{:?}, pixel of command {i}: {:?}", state, jobs[i].cmd);
        if (out.get("inp$ready") == &Value::new(1, 1)) != leaving {
            return Err(format!("cycle {cycle}: inp$ready should be {leaving} in {state:?}"));
        }
        let valid = out.get("out$valid") == &Value::new(1, 1);
        match held {
            Some((p, i)) => {
                let got = pixel_of(&out, "out");
                if !valid || got != p {
                    return Err(format!("cycle {cycle}: got valid {valid} {got:?}, model {p:?}; {}", at(i)));
                }
            }
            None if valid => return Err(format!("cycle {cycle}: out$valid high in {state:?}, no pixel due")),
            None => {}
        }
        let walking = matches!(state, State::Walk { .. });
        stalls += (!free && (walking || !offer)) as u64;
        if out_ready {
            held = None;
        }
        if let (State::Walk { i, .. }, true) = (state, free) {
            held = due.map(|p| (p, i));
        }
        state = match state {
            _ if leaving && offer => {
                next += 1;
                State::Walk { i: next - 1, k: 0 }
            }
            _ if leaving => State::Idle,
            State::Walk { i, k } if free => State::Walk { i, k: k + 1 },
            s => s,
        };
    }
    Ok((dual.cycles(), stalls))
}

/// 1 when the last job's walk ends on a pixel sent: the pixel register then takes a cycle
/// more to empty.
fn drain(jobs: &[Job]) -> usize {
    jobs.last().and_then(|j| j.slots.last()).is_some_and(Option::is_some) as usize
}

fn dual(vl: &testbenches::Verilated) -> Dual<Span> {
    Dual::new(Span::default(), vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// The spans of random triangles and synthetic clipping cases on small screens, back to
/// back with `out_ready` high: each command takes exactly the model's cycles, pixels
/// follow each other without a gap.
#[test]
fn span_random_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let n = count();
    let mut jobs = Vec::new();
    for clip in [Clip { width: 1, height: 1 }, Clip { width: 7, height: 5 }, Clip { width: 64, height: 48 }] {
        jobs.extend(triangle_jobs(&mut rng, clip, n / 3));
        jobs.extend(synthetic_jobs(&mut rng, clip, n / 3));
    }
    let vl = verilated("span");
    let (cycles, _) = run(&mut dual(&vl), &jobs, |_| true).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    // Back to back, the first command is taken in cycle 0 and each walks its model
    // cycles; a new screen width waits one idle cycle; the last pixel leaves the pixel
    // register after the walk.
    let model: usize = jobs.iter().map(|j| j.slots.len()).sum();
    let switches = jobs.windows(2).filter(|p| p[0].width != p[1].width).count();
    assert_eq!(cycles, (model + LATENCY as usize - 1 + drain(&jobs) + switches) as u64, "seed {seed}");
    assert!(jobs.iter().any(|j| j.slots.len() == 1 && j.slots[0].is_none()), "some spans were dropped");
    assert!(jobs.iter().any(|j| j.cmd.xl < 0 && j.slots.iter().any(Option::is_some)), "some walked right to left");
}

/// The same with `out_ready` low 40% of the time: a pixel waits until taken, holding the
/// walk behind it, nothing else stalls.
#[test]
fn span_back_pressure_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(1));
    let clip = Clip { width: 64, height: 48 };
    let mut jobs = triangle_jobs(&mut rng, clip, count() / 2);
    jobs.extend(synthetic_jobs(&mut rng, clip, count() / 2));
    let vl = verilated("span");
    let (cycles, stalls) =
        run(&mut dual(&vl), &jobs, |r| r.gen_bool(0.6)).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    let model: usize = jobs.iter().map(|j| j.slots.len()).sum();
    assert_eq!(cycles, (model + LATENCY as usize - 1 + drain(&jobs)) as u64 + stalls, "seed {seed}");
}

/// 003 Table 1: span latency 1 cycle, one pixel per cycle; here 2, the pixel register's
/// cycle added. A span of 3 pixels on screen, taken in cycle 0: walked in cycles 1, 2 and
/// 3, pixels out in cycles 2, 3 and 4, a second command taken in cycle 3.
#[test]
fn span_latency_003_table1() {
    let clip = Clip { width: 64, height: 48 };
    let z = Attrs { z: z_max(&FORMATS) << (FORMATS.z_acc.frac - FORMATS.z.frac - 1), c: [0; 3] };
    let cmd = SpanCmd { y: 4, xl: 10, xr: 12, left: z, right: z, ddx: Attrs::default() };
    let j = job(cmd, clip);
    assert_eq!(j.slots.iter().flatten().count(), 3);
    let vl = verilated("span");
    let mut d = dual(&vl);
    let mut pins =
        vec![("width", Value::new(DIM, 64)), ("inp$valid", Value::new(1, 1)), ("out$ready", Value::new(1, 1))];
    pins.extend(as_pins(&j.pins));
    let (mut valid, mut ready) = (Vec::new(), Vec::new());
    for _ in 0..5 {
        let out = d.cycle(&pins).unwrap_or_else(|m| panic!("{m}"));
        valid.push(out.get("out$valid") == &Value::new(1, 1));
        ready.push(out.get("inp$ready") == &Value::new(1, 1));
    }
    assert_eq!(valid, [false, false, true, true, true], "out$valid in cycles 0 to 4");
    assert_eq!(ready, [true, false, false, true, false], "inp$ready in cycles 0 to 4");
}

/// Without X and Z clipping (`CLIP_X = CLIP_Z = 0`, `rtl::switch`): the spans of random
/// triangles that need neither (every pixel from xl to xr on screen and in the depth
/// range) come out as the model's, in both simulators and with back-pressure; a span
/// starting left of the screen does not: the logic is gone.
#[test]
fn span_without_clipping_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(2));
    let clip = Clip { width: 64, height: 48 };
    let mut jobs = Vec::new();
    while jobs.len() < count() {
        let inside = |j: &Job| {
            j.cmd.xl >= 0
                && j.cmd.xr < clip.width as i128
                && j.slots.iter().flatten().count() as i128 == j.cmd.xr - j.cmd.xl + 1
        };
        jobs.extend(triangle_jobs(&mut rng, clip, 1).into_iter().filter(inside));
    }
    let vl = verilated_with("span", [("CLIP_X", 0), ("CLIP_Z", 0)]);
    let parts = Parts { clip_x: false, clip_z: false, ..Parts::ALL };
    let dual = || Dual::new(Span::new(&parts), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let (cycles, stalls) = run(&mut dual(), &jobs, |r| r.gen_bool(0.7)).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    let model: usize = jobs.iter().map(|j| j.slots.len()).sum();
    assert_eq!(cycles, (model + LATENCY as usize - 1 + drain(&jobs)) as u64 + stalls, "seed {seed}");
    let z = Attrs { z: 1 << (FORMATS.z_acc.frac - 1), c: [0; 3] };
    let left_of_screen = job(SpanCmd { y: 4, xl: -3, xr: 2, left: z, right: z, ddx: Attrs::default() }, clip);
    assert!(
        run(&mut dual(), &[left_of_screen], |_| true).is_err(),
        "without X clipping, a span from x = -3 is drawn wrongly"
    );
}
