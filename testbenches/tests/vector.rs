//! The barycentric unit (paper 004): rust-hdl and Verilator in lockstep, every output
//! compared on every cycle, against `model::vector` at 1, 2, 4 and 8 lanes: each chunk's
//! pixels in walk order, and, back to back, the cycle each triangle is taken and each pixel
//! leaves (`model::cycles::VectorUnit`: setup overlapping the scout and the walker).

use model::ctx::Ctx;
use model::cull_sort::{cull_sort, Clip, Cull, Sorted};
use model::cycles::VectorUnit;
use model::span::Pixel;
use model::vector::{pixel_latency, vector, VectorOut};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rtl::vector::Vector;
use rtl::widths::{CHANNEL, DEPTH, DIM, FORMATS};
use testbenches::flow::Flow;
use testbenches::stimulus::{extremes, random_triangle};
use testbenches::streams::{as_pins, raw, sorted};
use testbenches::{count, seed, verilated_with, Dual, Value};

/// The screen the tests draw on: small, so that a triangle's box is at most 3,072 pixels
/// (triangles may reach far beyond it).
const CLIP: Clip = Clip { width: 64, height: 48 };

/// A triangle for the unit, and what the model makes of it at the unit's lanes.
struct Job {
    sorted: Sorted,
    out: VectorOut,
}

/// The triangles among `v` that cull & sort lets through (back faces kept), as jobs.
fn jobs(v: impl IntoIterator<Item = [model::input::Vtx; 3]>, lanes: u32, perspective: bool) -> Vec<Job> {
    v.into_iter()
        .filter_map(|v| cull_sort(&v, CLIP, Cull::None, &FORMATS).ok())
        .map(|sorted| Job { out: vector(&sorted, CLIP, lanes, perspective, &mut Ctx::new(FORMATS)), sorted })
        .collect()
}

/// The unit with `LANES` lanes and `l` divider stages in both simulators.
fn dual<const LANES: usize, const ZW: usize, const CW: usize>(
    perspective: bool,
    l: u32,
) -> Dual<Vector<LANES, ZW, CW>> {
    let params = [("PERSPECTIVE", perspective as u64), ("L", l as u64), ("LANES", LANES as u64)];
    let unit = Vector::new(l as usize, perspective).unwrap_or_else(|e| panic!("{e}"));
    Dual::new(unit, verilated_with("vector", params).model().unwrap_or_else(|e| panic!("{e}")))
}

/// `n` bits of `v` from bit `lo`.
fn field(v: &Value, lo: usize, n: usize) -> u32 {
    (0..n).map(|b| (v.bit(lo + b) as u32) << b).sum()
}

/// The pixels of the chunk on `out`, lane by lane.
fn chunk_pixels(out: &testbenches::Outputs, lanes: usize) -> Vec<Pixel> {
    let (mask, z, rgb) = (out.get("out_mask"), out.get("out_z"), out.get("out_rgb"));
    let (x, y) =
        (field(out.get("out_x"), 0, out.get("out_x").width()), field(out.get("out_y"), 0, out.get("out_y").width()));
    (0..lanes)
        .filter(|&i| mask.bit(i))
        .map(|i| Pixel {
            x: x + i as u32,
            y,
            z: field(z, i * DEPTH, DEPTH),
            rgb: std::array::from_fn(|k| field(rgb, (3 * i + 2 - k) * CHANNEL, CHANNEL) as u8),
        })
        .collect()
}

/// Runs `jobs` through `dual` with `flow` and checks every pixel against the model, in
/// order; returns the cycle each triangle was taken and each pixel left, per triangle.
fn run<const LANES: usize, const ZW: usize, const CW: usize>(
    dual: &mut Dual<Vector<LANES, ZW, CW>>,
    jobs: &[Job],
    flow: Flow,
    seed: u64,
) -> Vec<(u64, Vec<u64>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let expected: Vec<(usize, Pixel)> =
        jobs.iter().enumerate().flat_map(|(j, job)| job.out.pixels.iter().map(move |p| (j, *p))).collect();
    let mut times: Vec<(u64, Vec<u64>)> = Vec::new();
    let (mut next, mut presenting, mut ready, mut got, mut idle) = (0, false, true, 0, false);
    let work: u64 =
        jobs.iter().map(|j| j.out.rows.iter().map(|r| (r.search + r.chunks) as u64).sum::<u64>() + 100).sum();
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
        pins.push(("out_ready".into(), Value::new(1, ready as u128)));
        let out = dual.cycle(&as_pins(&pins)).unwrap_or_else(fail);
        let cycle = dual.cycles() - 1;
        idle = out.get("idle").bit(0);
        assert_eq!(
            out.get("out_valid").bit(0),
            out.get("out_mask").words()[0] != 0,
            "cycle {cycle}: valid is a lane's"
        );
        if out.get("out_valid").bit(0) && ready {
            for p in chunk_pixels(&out, LANES) {
                let (j, want) = expected.get(got).unwrap_or_else(|| panic!("cycle {cycle}: a pixel past the model's"));
                assert_eq!(p, *want, "cycle {cycle}: pixel {got} (triangle {j}), {LANES} lanes, seed {seed}");
                times[*j].1.push(cycle);
                got += 1;
            }
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
/// cycle each is taken and each of its pixels leaves (`pixel_latency` after its chunk's walk
/// cycle) are `model::cycles::VectorUnit`'s, exactly.
fn check_timing(jobs: &[Job], times: &[(u64, Vec<u64>)], l: u32) {
    assert_eq!(times.len(), jobs.len());
    let mut unit = VectorUnit::new(l);
    let mut offered = 0;
    for (j, (job, (taken, left))) in jobs.iter().zip(times).enumerate() {
        let t = unit.triangle(offered, &job.out.rows);
        assert_eq!(*taken, t.taken, "triangle {j}: the cycle it was taken");
        offered = t.taken + 1;
        let want: Vec<u64> = job.out.at.iter().map(|&at| t.chunk(at) + pixel_latency(l) as u64).collect();
        assert_eq!(*left, want, "triangle {j}: the cycles its pixels left");
    }
}

/// `n` random triangles (as cull & sort passes them) at `LANES` lanes through both
/// simulators, back to back (timing checked) and stalling.
fn random_vs_model<const LANES: usize, const ZW: usize, const CW: usize>(n: usize, perspective: bool, l: u32) {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let jobs = jobs((0..n).map(|_| random_triangle(&mut rng, CLIP)), LANES as u32, perspective);
    assert!(jobs.iter().map(|j| j.out.pixels.len()).sum::<usize>() > 10 * n, "the triangles draw pixels");
    let mut d = dual::<LANES, ZW, CW>(perspective, l);
    let t = run(&mut d, &jobs, Flow::BACK_TO_BACK, seed);
    check_timing(&jobs, &t, l);
    run(&mut d, &jobs, Flow::STALLING, seed);
}

const L: u32 = model::divider::LATENCY;

#[test]
fn vector_random_vs_model() {
    random_vs_model::<1, DEPTH, { 3 * CHANNEL }>(count() / 40, true, L);
}

/// [`vector_random_vs_model`] without perspective (the soak's: the test command runs the unit
/// without perspective at two lanes with 001's 5-stage divider,
/// [`vector_with_a_5_stage_divider_vs_model`], one Verilated build fewer).
#[test]
#[ignore = "soak: scripts/soak.sh"]
fn vector_random_linear_vs_model() {
    random_vs_model::<1, DEPTH, { 3 * CHANNEL }>(count() / 40, false, L);
}

/// Two lanes at the default divider (the soak's: the test command runs two lanes with 001's
/// 5-stage divider, [`vector_with_a_5_stage_divider_vs_model`], one Verilated build fewer).
#[test]
#[ignore = "soak: scripts/soak.sh"]
fn vector_two_lanes_random_vs_model() {
    random_vs_model::<2, { 2 * DEPTH }, { 6 * CHANNEL }>(count() / 40, true, L);
}

#[test]
fn vector_four_lanes_random_vs_model() {
    random_vs_model::<4, { 4 * DEPTH }, { 12 * CHANNEL }>(count() / 40, true, L);
}

#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn vector_eight_lanes_random_vs_model() {
    random_vs_model::<8, { 8 * DEPTH }, { 24 * CHANNEL }>(count() / 40, true, L);
}

/// With 001's 5-stage divider (setup 13 cycles, each pixel out 21 cycles after its walk
/// cycle), as the model's timing for it says; two lanes, without perspective (screen-linear
/// colours).
#[test]
fn vector_with_a_5_stage_divider_vs_model() {
    random_vs_model::<2, { 2 * DEPTH }, { 6 * CHANNEL }>(count() / 100, false, 5);
    assert_eq!((model::vector::setup(5), model::vector::pixel_latency(5)), (13, 21));
}

/// The triangles at the limits of `xy`, z and colour (`stimulus::extremes`) on the small
/// screen: the widest edge functions and areas, unit areas, every winding, w_min / w = 0.
#[test]
fn vector_extremes_vs_model() {
    let v: Vec<_> = extremes().into_iter().map(|(_, c)| c.v).collect();
    let one = jobs(v, 1, true);
    let t = run(&mut dual::<1, DEPTH, { 3 * CHANNEL }>(true, L), &one, Flow::BACK_TO_BACK, seed());
    check_timing(&one, &t, L);
}

/// [`vector_extremes_vs_model`] at eight lanes (its Verilated model is the soak's).
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn vector_extremes_eight_lanes_vs_model() {
    let v: Vec<_> = extremes().into_iter().map(|(_, c)| c.v).collect();
    let eight = jobs(v, 8, true);
    let t = run(&mut dual::<8, { 8 * DEPTH }, { 24 * CHANNEL }>(true, L), &eight, Flow::BACK_TO_BACK, seed());
    check_timing(&eight, &t, L);
}

/// 004's per-pixel unit draws `lanes` pixels a cycle: a triangle covering the whole screen
/// walks each row in width / lanes cycles, one after another, and its pixels leave a chunk
/// a cycle; its colours are perspective-correct (eq. 5-6), its depth screen-linear.
#[test]
fn vector_lanes_pixels_per_cycle_paper_004() {
    let (w, h) = (CLIP.width as i128 * 16, CLIP.height as i128 * 16);
    let v = |x, y, z, c, iw| model::input::Vtx { x, y, z, c, iw };
    let cover = [
        v(-w, -h, 30000, [255, 0, 0], 32768),
        v(3 * w, -h, 20000, [0, 255, 0], 16384),
        v(-w, 3 * h, 10000, [0, 0, 255], 8192),
    ];
    let one = jobs([cover], 1, true);
    assert_eq!(one[0].out.pixels.len() as u32, CLIP.width * CLIP.height);
    let flat = vector(&one[0].sorted, CLIP, 1, false, &mut Ctx::new(FORMATS));
    let moved = one[0].out.pixels.iter().zip(&flat.pixels).filter(|(p, q)| p.rgb != q.rgb && p.z == q.z).count();
    assert!(moved > 1000, "perspective moves the colours, not the depth: {moved} pixels");
    let four = jobs([cover], 4, true);
    assert_eq!(four[0].out.pixels, one[0].out.pixels, "the lanes draw the same pixels");
    assert!(four[0].out.rows.iter().all(|r| r.chunks == CLIP.width / 4), "each row in width / 4 chunks");
    let t = run(&mut dual::<4, { 4 * DEPTH }, { 12 * CHANNEL }>(true, L), &four, Flow::BACK_TO_BACK, seed());
    check_timing(&four, &t, L);
    let chunks: Vec<u64> = t[0].1.chunks(4).map(|c| c[0]).collect();
    assert!(t[0].1.chunks(4).all(|c| c.iter().all(|&x| x == c[0])), "four pixels a cycle");
    assert!(chunks.windows(2).all(|p| p[1] == p[0] + 1), "a chunk every cycle");
}

/// Pixels per clock of the walk on large triangles (random vertices on a 320 x 240 screen,
/// at least `min` pixels each), back to back through `VectorUnit`: pixels over the cycles
/// from the first chunk's walk cycle to the last's.
fn pixels_per_clock(lanes: u32, min: usize, n: usize, seed: u64) -> f64 {
    let clip = Clip { width: 320, height: 240 };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (mut unit, mut pixels, mut first, mut last) = (VectorUnit::new(L), 0usize, None, 0u64);
    let mut offered = 0;
    let mut drawn = 0;
    while drawn < n {
        let v: [model::input::Vtx; 3] = std::array::from_fn(|_| {
            use rand::Rng;
            model::input::Vtx {
                x: rng.gen_range(0..320 * 16),
                y: rng.gen_range(0..240 * 16),
                z: rng.gen_range(0..60000),
                c: [0; 3],
                iw: 32768,
            }
        });
        let Ok(sorted) = cull_sort(&v, clip, Cull::None, &FORMATS) else { continue };
        let out = vector(&sorted, clip, lanes, true, &mut Ctx::new(FORMATS));
        if out.pixels.len() < min {
            continue;
        }
        drawn += 1;
        let t = unit.triangle(offered, &out.rows);
        offered = t.taken + 1;
        let chunks: Vec<u64> = (0..out.rows.len())
            .filter(|&r| out.rows[r].chunks > 0)
            .flat_map(|r| [t.chunk((r as u32, 0)), t.chunk((r as u32, out.rows[r].chunks - 1))])
            .collect();
        first.get_or_insert(chunks[0]);
        last = *chunks.last().unwrap();
        pixels += out.pixels.len() + out.z_clipped as usize;
    }
    pixels as f64 / (last + 1 - first.unwrap()) as f64
}

/// Issue 18's aim: at least 0.8 x lanes pixels per clock on large triangles (2,000 pixels
/// or more on 320 x 240) at 1, 2, 4 and 8 lanes: the scout keeps the walker in each row's
/// chunks that may hold a pixel, so the walk wastes only the chunks a row's ends cut and
/// the scout's stalls (a box walk would spend half its cycles outside the triangle). The
/// model's timing is the RTL's (the tests above).
#[test]
fn vector_lanes_pixels_per_clock_on_large_triangles() {
    for lanes in [1, 2, 4, 8] {
        let rate = pixels_per_clock(lanes, 2000, 100, seed());
        assert!(rate >= 0.8 * lanes as f64, "{lanes} lanes: {rate:.3} pixels per clock");
    }
}
