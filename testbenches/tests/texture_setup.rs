//! Texture setup (paper 001 §II-5, `model::texture_setup`): rust-hdl and Verilator in
//! lockstep, every output compared every cycle, on random perspective triangles (slivers,
//! guard-band giants, q near 0, s and t near ±256) and random pixels inside and outside
//! them, with random stalls: the LOD gradients and every pixel's s·q, t·q and q checked
//! against the model, `done` at its cycle.

use fx::{Formats, TexFormats};
use model::divider::reciprocal;
use model::input::to_fixed;
use model::texture_setup::{area2, tex_vertices, texture_setup, TexVtx, TexturePlanes};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_setup::{TextureSetup, DQ, DST, EXP, LATENCY, MANT, QB, SCREEN, SETUP_CYCLES, ST, XY};
use scene::{Tex, Triangle, Vertex};
use std::collections::VecDeque;
use testbenches::{count, seed, verilate, Dual, Value};

const F: Formats = rtl::n10::FORMATS;
const TF: TexFormats = TexFormats::DEFAULT;

/// `v`'s low `bits` bits, as a port value.
fn raw(bits: usize, v: i128) -> Value {
    Value::new(bits, (v as u128) & ((1u128 << bits) - 1))
}

fn bit(b: bool) -> Value {
    Value::new(1, b.into())
}

/// A random perspective triangle of one of several kinds.
pub(crate) fn triangle(rng: &mut ChaCha8Rng) -> Triangle {
    let kind = rng.gen_range(0..5);
    // Positions: on screen, across the guard band, or a sliver (a third vertex near the
    // line through the first two).
    let mut p: [[f64; 2]; 3] = std::array::from_fn(|_| match kind {
        1 => [rng.gen_range(-2047.0..2047.0), rng.gen_range(-2047.0..2047.0)],
        2 => [rng.gen_range(-100.0..1124.0), rng.gen_range(-100.0..1124.0)],
        _ => [rng.gen_range(0.0..1024.0), rng.gen_range(0.0..1024.0)],
    });
    if kind == 3 {
        let u = rng.gen_range(-0.5..1.5);
        p[2] = std::array::from_fn(|d| p[0][d] + u * (p[1][d] - p[0][d]) + rng.gen_range(-0.3..0.3));
    }
    if kind == 4 {
        // A small triangle.
        let c = [rng.gen_range(0.0..1024.0), rng.gen_range(0.0..1024.0)];
        for v in &mut p {
            *v = [c[0] + rng.gen_range(-4.0..4.0), c[1] + rng.gen_range(-4.0..4.0)];
        }
    }
    // w over ratios up to 1e4 (q near 0 at the far vertices); s and t up to ±256.
    let range = [2.0, 16.0, 255.9][rng.gen_range(0..3)];
    let w_max: f64 = [2.0, 100.0, 1e4][rng.gen_range(0..3)];
    std::array::from_fn(|k| Vertex {
        w: Some(w_max.powf(rng.gen_range(0.0..1.0))),
        tex: Some(Tex { s: rng.gen_range(-range..range), t: rng.gen_range(-range..range), texture: 0 }),
        ..Vertex::new(p[k][0], p[k][1], 0.5, [0.0; 3])
    })
}

/// A triangle's texture vertices, its planes and the reciprocal of twice its area, or
/// `None` when out of range or of zero area.
pub(crate) fn setup(tri: &Triangle) -> Option<([TexVtx; 3], TexturePlanes, model::divider::Recip)> {
    let v = to_fixed(tri, &F).ok()?;
    let tv = tex_vertices(tri, &v, &TF, false).ok()??;
    let planes = texture_setup(&tv, &F, &TF)?;
    Some((tv, planes, reciprocal(area2(&tv).abs(), &F)))
}

pub(crate) fn start_pins(tv: &[TexVtx; 3], r: &model::divider::Recip) -> Vec<(&'static str, Value)> {
    const NAMES: [[&str; 5]; 3] = [
        ["tri$x0", "tri$y0", "tri$sq0", "tri$tq0", "tri$q0"],
        ["tri$x1", "tri$y1", "tri$sq1", "tri$tq1", "tri$q1"],
        ["tri$x2", "tri$y2", "tri$sq2", "tri$tq2", "tri$q2"],
    ];
    let mut pins = vec![("start", bit(true)), ("tri$mant", raw(MANT, r.mant)), ("tri$exp", raw(EXP, r.exp.into()))];
    for (v, n) in tv.iter().zip(NAMES) {
        pins.extend([
            (n[0], raw(XY, v.x)),
            (n[1], raw(XY, v.y)),
            (n[2], raw(ST, v.a[0])),
            (n[3], raw(ST, v.a[1])),
            (n[4], raw(QB, v.a[2])),
        ]);
    }
    pins
}

/// A pixel: in the triangle's bounding box (mostly inside or near it) or anywhere.
pub(crate) fn pixel(rng: &mut ChaCha8Rng, tv: &[TexVtx; 3]) -> (u32, u32) {
    let max = (1i128 << SCREEN) - 1;
    if rng.gen_bool(0.3) {
        return (rng.gen_range(0..=max as u32), rng.gen_range(0..=max as u32));
    }
    let px = |c: i128| (c >> F.xy.frac).clamp(0, max);
    let lo = [0, 1].map(|d| px(tv.iter().map(|v| [v.x, v.y][d]).min().unwrap()));
    let hi = [0, 1].map(|d| px(tv.iter().map(|v| [v.x, v.y][d]).max().unwrap()));
    (rng.gen_range(lo[0]..=hi[0]) as u32, rng.gen_range(lo[1]..=hi[1]) as u32)
}

/// Sets up `tri` and runs `pixels` random pixels through, en low one cycle in `stall` of 8,
/// checking everything against the model. Returns the pixels' latencies in enabled cycles.
fn run_triangle(
    dual: &mut Dual<TextureSetup>,
    rng: &mut ChaCha8Rng,
    tv: &[TexVtx; 3],
    planes: &TexturePlanes,
    r: &model::divider::Recip,
    pixels: usize,
    stall: u32,
) -> Vec<u64> {
    let idle = |rng: &mut ChaCha8Rng, en: bool| {
        vec![
            ("start", bit(false)),
            ("en", bit(en)),
            ("inp_valid", bit(false)),
            ("inp_x", raw(SCREEN, rng.gen_range(0..1 << SCREEN))),
            ("inp_y", raw(SCREEN, rng.gen_range(0..1 << SCREEN))),
        ]
    };
    let mut pins = start_pins(tv, r);
    pins.push(("en", bit(rng.gen_range(0..8) >= stall)));
    let out = dual.cycle(&pins).unwrap_or_else(|m| panic!("{m}"));
    assert!(!out.get("out_valid").bit(0), "a pixel out of an empty pipeline");
    // Setup: `done` low until SETUP_CYCLES cycles after `start`, whatever the stalls.
    for c in 1..=SETUP_CYCLES {
        let en = rng.gen_range(0..8) >= stall;
        let out = dual.cycle(&idle(rng, en)).unwrap_or_else(|m| panic!("{m}"));
        assert_eq!(out.get("done").bit(0), c == SETUP_CYCLES, "done at cycle {c} after start");
        assert!(!out.get("out_valid").bit(0), "a pixel out during setup");
    }
    let g = planes.grad();
    let out = dual.cycle(&idle(rng, false)).unwrap_or_else(|m| panic!("{m}"));
    for (pin, bits, want) in [
        ("dsq_x", DST, g.dsq[0]),
        ("dsq_y", DST, g.dsq[1]),
        ("dtq_x", DST, g.dtq[0]),
        ("dtq_y", DST, g.dtq[1]),
        ("dq_x", DQ, g.dq[0]),
        ("dq_y", DQ, g.dq[1]),
    ] {
        dual.expect(&out, pin, &raw(bits, want.into())).unwrap_or_else(|m| panic!("{m}\n{tv:?}"));
    }
    // Pixels.
    let (mut next, mut done, mut enabled) = (0, 0, 0u64);
    let mut in_flight: VecDeque<((u32, u32), u64)> = VecDeque::new();
    let mut latency = Vec::new();
    let first = dual.cycles();
    while done < pixels {
        assert!(dual.cycles() - first < 8 * pixels as u64 + 100, "{done} of {pixels} pixels out");
        let en = rng.gen_range(0..8) >= stall;
        let valid = next < pixels && rng.gen_range(0..4) != 0;
        let (x, y) = pixel(rng, tv);
        let pins = [
            ("start", bit(false)),
            ("en", bit(en)),
            ("inp_valid", bit(valid)),
            ("inp_x", raw(SCREEN, x.into())),
            ("inp_y", raw(SCREEN, y.into())),
        ];
        let out = dual.cycle(&pins).unwrap_or_else(|m| panic!("{m}"));
        assert!(out.get("done").bit(0), "done dropped with no start");
        if en {
            if out.get("out_valid").bit(0) {
                let ((px, py), t) = in_flight.pop_front().expect("an output with no pixel in flight");
                let want = planes.at(px, py);
                for (pin, bits, w) in [("out_sq", ST, want.sq), ("out_tq", ST, want.tq), ("out_q", QB, want.q)] {
                    dual.expect(&out, pin, &raw(bits, w.into()))
                        .unwrap_or_else(|m| panic!("{m}\npixel ({px}, {py}) of {tv:?}"));
                }
                latency.push(enabled - t);
                done += 1;
            }
            if valid {
                in_flight.push_back(((x, y), enabled));
                next += 1;
            }
            enabled += 1;
        }
    }
    latency
}

#[test]
fn texture_setup_random_triangles_in_both_simulators_match_the_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let emitted = rtl::texture_setup::emit_texture_setup(&Default::default()).unwrap();
    let vl = verilate(&emitted).unwrap_or_else(|e| panic!("{e}"));
    let mut dual = Dual::new(TextureSetup::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let (mut tested, mut saturated, mut clamped) = (0, 0, 0);
    while tested < count() {
        let tri = triangle(&mut rng);
        let Some((tv, planes, r)) = setup(&tri) else { continue };
        let g = planes.grad();
        let lods = [g.dsq[0], g.dsq[1], g.dtq[0], g.dtq[1]];
        saturated += lods.iter().any(|&v| v == TF.dst.max_raw() as i64 || v == TF.dst.min_raw() as i64) as usize;
        let latency = run_triangle(&mut dual, &mut rng, &tv, &planes, &r, 24, 2);
        assert!(latency.iter().all(|&l| l == LATENCY as u64), "latencies {latency:?}");
        // How often a pixel's value is clamped (outside the triangle): both kinds are tested.
        clamped += (0..8)
            .map(|_| pixel(&mut rng, &tv))
            .filter(|&(x, y)| {
                let v = planes.at(x, y);
                v.q == 0
                    || v.q == TF.q.max_raw() as i64
                    || v.sq == TF.st.max_raw() as i64
                    || v.sq == TF.st.min_raw() as i64
            })
            .count();
        tested += 1;
    }
    eprintln!(
        "seed {}: {tested} triangles, {saturated} with a saturated LOD gradient, {clamped} clamped pixels",
        seed()
    );
    assert!(tested < 20 || (saturated > 0 && clamped > 0), "the stimulus reaches saturation and clamping");
}

#[test]
fn texture_setup_back_to_back_without_stalls_holds_its_timing() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed() ^ 0x5e7);
    let emitted = rtl::texture_setup::emit_texture_setup(&Default::default()).unwrap();
    let vl = verilate(&emitted).unwrap_or_else(|e| panic!("{e}"));
    let mut dual = Dual::new(TextureSetup::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut tested = 0;
    while tested < 8 {
        let Some((tv, planes, r)) = setup(&triangle(&mut rng)) else { continue };
        let latency = run_triangle(&mut dual, &mut rng, &tv, &planes, &r, 64, 0);
        assert_eq!(latency, vec![LATENCY as u64; 64]);
        tested += 1;
    }
}
