//! The texture unit's coordinates (paper 001 eq. (3) and (4)): rust-hdl and Verilator in
//! lockstep on random pixels with random stalls, every s, t and lambda checked against
//! `model::texture_unit::TextureUnit::coords`, at both level-of-detail rules; the latency
//! and the worked values of the model's tests.

use fx::{Fmt, TexFormats};
use model::texture_unit::{TexGrad, TexIn, TexState, TextureUnit};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_coords::{TextureCoords, LAMBDA, LATENCY, ST};
use std::collections::VecDeque;
use testbenches::texture::coord_pins;
use testbenches::{count, seed, verilated_with, Dual, Value};
use texture::{LodRule, Sampler};

const F: TexFormats = TexFormats::DEFAULT;

/// One pixel's inputs: the pixel, the triangle's gradients and log2 of the texture's sides.
#[derive(Clone, Copy, Debug)]
struct Pixel {
    p: TexIn,
    g: TexGrad,
    size_log2: [u32; 2],
}

fn state(size_log2: [u32; 2], lod: LodRule) -> TexState {
    TexState {
        size_log2,
        levels: 1,
        base: 0,
        format: Default::default(),
        sampler: Sampler::default(),
        env: Default::default(),
        lod,
    }
}

/// `v`'s low `bits` bits, as a port value.
fn raw(bits: usize, v: i64) -> Value {
    Value::new(bits, (v as u128) & ((1u128 << bits) - 1))
}

fn pins(x: &Pixel, valid: bool, en: bool) -> Vec<(&'static str, Value)> {
    let mut pins = vec![("en", Value::new(1, en.into())), ("inp_valid", Value::new(1, valid.into()))];
    pins.extend(coord_pins(&x.p, &x.g));
    pins.extend([("inp_ws", Value::new(4, x.size_log2[0].into())), ("inp_hs", Value::new(4, x.size_log2[1].into()))]);
    pins
}

/// A random raw value of `fmt`: anywhere in its range, or small (a few LSB), or at its ends.
fn any(rng: &mut ChaCha8Rng, fmt: Fmt) -> i64 {
    let (lo, hi) = (fmt.min_raw() as i64, fmt.max_raw() as i64);
    match rng.gen_range(0..8) {
        0 => [lo, hi, 0][rng.gen_range(0..3)],
        1 => rng.gen_range(-300..300i64).clamp(lo, hi),
        2..=4 => rng.gen_range(lo..=hi),
        _ => {
            // A value of a random magnitude: most pixels are neither huge nor tiny.
            let bits = rng.gen_range(1..fmt.bits());
            rng.gen_range(-(1i64 << (bits - 1))..(1i64 << (bits - 1))).clamp(lo, hi)
        }
    }
}

fn random_pixel(rng: &mut ChaCha8Rng) -> Pixel {
    let q = match rng.gen_range(0..6) {
        0 => [0, 1, F.q.max_raw() as i64, 1 << F.q.frac][rng.gen_range(0..4)],
        1 => rng.gen_range(0..=F.q.max_raw() as i64),
        _ => {
            let bits = rng.gen_range(1..=F.q.frac);
            rng.gen_range(1i64 << (bits - 1)..1i64 << bits)
        }
    };
    Pixel {
        p: TexIn { sq: any(rng, F.st), tq: any(rng, F.st), q },
        g: TexGrad {
            dsq: [any(rng, F.dst), any(rng, F.dst)],
            dtq: [any(rng, F.dst), any(rng, F.dst)],
            dq: [any(rng, F.dq), any(rng, F.dq)],
        },
        size_log2: [rng.gen_range(0..=12), rng.gen_range(0..=12)],
    }
}

/// Runs `pixels` through the unit (EXACT = `exact`) with stalls (`en` low) one cycle in
/// `stall` of 8, checking every output against the model. Returns the cycles each pixel
/// took from input to output (enabled cycles only).
fn run(exact: bool, pixels: &[Pixel], stall: u32, rng: &mut ChaCha8Rng) -> Vec<u64> {
    let lod = if exact { LodRule::Exact } else { LodRule::Max };
    let model = TextureUnit::new(F).unwrap();
    let vl = verilated_with("texture_coords", [("EXACT", exact.into())]);
    let mut dual = Dual::new(TextureCoords::new(exact), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let (mut next, mut done, mut enabled) = (0, 0, 0u64);
    let mut in_flight: VecDeque<(usize, u64)> = VecDeque::new();
    let mut latency = Vec::new();
    let idle = Pixel { p: TexIn::default(), g: TexGrad::default(), size_log2: [0, 0] };
    while done < pixels.len() {
        assert!(dual.cycles() < 4 * pixels.len() as u64 + 100, "{done} of {} pixels out", pixels.len());
        let en = rng.gen_range(0..8) >= stall;
        let valid = next < pixels.len() && rng.gen_range(0..4) != 0;
        let x = if valid { pixels[next] } else { idle };
        let out = dual.cycle(&pins(&x, valid, en)).unwrap_or_else(|m| panic!("{m}"));
        if en {
            if out.get("out_valid").bit(0) {
                let (k, t) = in_flight.pop_front().expect("an output with no pixel in flight");
                let px = &pixels[k];
                let c = model.coords(&state(px.size_log2, lod), &px.p, &px.g);
                for (pin, bits, want) in [("out_s", ST, c.s), ("out_t", ST, c.t), ("out_lambda", LAMBDA, c.lambda)] {
                    dual.expect(&out, pin, &raw(bits, want)).unwrap_or_else(|m| panic!("{m}\npixel {k}: {px:?}"));
                }
                latency.push(enabled - t);
                done += 1;
            }
            if valid {
                in_flight.push_back((next, enabled));
                next += 1;
            }
            enabled += 1;
        }
    }
    latency
}

#[test]
fn texture_coords_random_pixels_in_both_simulators_match_the_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    for exact in [false, true] {
        let pixels: Vec<Pixel> = (0..4 * count()).map(|_| random_pixel(&mut rng)).collect();
        let latency = run(exact, &pixels, 2, &mut rng);
        assert!(latency.iter().all(|&l| l == LATENCY as u64), "EXACT = {exact}: latencies {latency:?}");
    }
}

#[test]
fn texture_coords_gives_the_worked_level_of_detail() {
    // A 256 x 256 texture, q = 1: ds/dx = dt/dx = 2/256, 2 texels a pixel along each axis:
    // eq. (4) gives lambda 1, GL's exact rho (2 sqrt 2) 1.5; in lod_frac = 6 bits 64 and 96.
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let step = F.dst.from_f64(2.0 / 256.0).unwrap() as i64;
    let px = Pixel {
        p: TexIn { sq: 1 << (F.st.frac - 2), tq: 1 << (F.st.frac - 2), q: 1 << F.q.frac },
        g: TexGrad { dsq: [step, 0], dtq: [step, 0], dq: [0, 0] },
        size_log2: [8, 8],
    };
    let model = TextureUnit::new(F).unwrap();
    assert_eq!(model.coords(&state([8, 8], LodRule::Max), &px.p, &px.g).lambda, 64);
    assert_eq!(model.coords(&state([8, 8], LodRule::Exact), &px.p, &px.g).lambda, 96);
    // The RTL against the model on it, with no stalls: one pixel in, out LATENCY later.
    for exact in [false, true] {
        assert_eq!(run(exact, &[px], 0, &mut rng), [LATENCY as u64]);
    }
}
