//! The texture unit's addresses (paper 001 section II-5, OpenGL 4.6 section 8.14):
//! rust-hdl and Verilator in lockstep on random pixels and texture states with random
//! stalls (`en`) and bubbles, every cycle's outputs checked against a pipeline of
//! `model::texture_address::request` [`LATENCY`] enabled clocks deep, and worked values.

use fx::TexFormats;
use model::texture_address::{request, Request};
use model::texture_coords::{Coords, MAGNIFIED};
use model::texture_memory::{address, chain_words, ADDR_BITS};
use model::texture_unit::TexState;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_address::{TextureAddress, ADDR, LAMBDA, LATENCY, ST};
use testbenches::{count, seed, verilated, Dual, Value};
use texture::{Filter, LodRule, MipMode, Sampler, Wrap};

const F: TexFormats = TexFormats::DEFAULT;
const WRAPS: [Wrap; 3] = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
const MIPS: [MipMode; 3] = [MipMode::None, MipMode::Nearest, MipMode::Linear];

fn raw(bits: usize, v: i64) -> Value {
    Value::new(bits, (v as u128) & ((1u128 << bits) - 1))
}

fn bit(b: bool) -> Value {
    Value::new(1, b.into())
}

fn pins(st: &TexState, c: &Coords, second: bool) -> Vec<(&'static str, Value)> {
    let code = |w: Wrap| WRAPS.iter().position(|x| *x == w).unwrap() as u128;
    vec![
        ("s", raw(ST, c.s)),
        ("t", raw(ST, c.t)),
        ("lambda", raw(LAMBDA, c.lambda)),
        ("second", bit(second)),
        ("ws", Value::new(4, st.size_log2[0].into())),
        ("hs", Value::new(4, st.size_log2[1].into())),
        ("levels", Value::new(4, st.levels.into())),
        ("base", Value::new(ADDR, st.base.into())),
        ("min_linear", bit(st.sampler.min == Filter::Linear)),
        ("mag_linear", bit(st.sampler.mag == Filter::Linear)),
        ("mip", Value::new(2, MIPS.iter().position(|m| *m == st.sampler.mip).unwrap() as u128)),
        ("wrap_s", Value::new(2, code(st.sampler.wrap_s))),
        ("wrap_t", Value::new(2, code(st.sampler.wrap_t))),
    ]
}

/// The outputs of an access the model gives.
fn access(r: &Request, second: bool) -> Vec<(&'static str, Value)> {
    let lanes = (0..4).filter(|&b| r.fetch[b].is_some()).map(|b| 1u128 << b).sum();
    let banks = (0..4).map(|k| (r.banks[k] as u128) << (2 * k)).sum();
    let mut want = vec![
        ("out_second", bit(second)),
        ("lanes", Value::new(4, lanes)),
        ("banks", Value::new(8, banks)),
        ("alpha", Value::new(8, r.alpha.into())),
        ("beta", Value::new(8, r.beta.into())),
        ("two_levels", bit(r.two_levels)),
        ("frac", Value::new(6, r.frac.into())),
    ];
    for (b, pin) in ["addr0", "addr1", "addr2", "addr3"].into_iter().enumerate() {
        want.push((pin, Value::new(ADDR, r.fetch[b].unwrap_or(0).into())));
    }
    want
}

/// The unit in both simulators beside the model's pipeline: each stage's access (the
/// model's request, whether of a second level, and the inputs for a failure's message).
struct Bench {
    dual: Dual<TextureAddress>,
    stages: [Option<(Request, bool, TexState, Coords)>; LATENCY],
}

impl Bench {
    fn new() -> Bench {
        let vl = verilated("texture_address");
        Bench {
            dual: Dual::new(TextureAddress::default(), vl.model().unwrap_or_else(|e| panic!("{e}"))),
            stages: [None; LATENCY],
        }
    }

    /// One clock: `en`, the pixel at `c` (an access when `valid`, of its second level when
    /// `second`) with state `st`; every output checked (`inp_two_levels` against the
    /// model's for the inputs, the access out against the one that went in LATENCY enabled
    /// clocks before). Returns the access out this cycle and the model's for the inputs.
    fn cycle(&mut self, en: bool, valid: bool, st: &TexState, c: &Coords, second: bool) -> (Option<Request>, Request) {
        let r = request(&F, st, c, second);
        let mut inputs = pins(st, c, second);
        inputs.push(("en", bit(en)));
        inputs.push(("inp_valid", bit(valid)));
        let out = self.dual.cycle(&inputs).unwrap_or_else(|m| panic!("{m}"));
        let head = self.stages[LATENCY - 1];
        let mut want = vec![("inp_two_levels", bit(r.two_levels)), ("out_valid", bit(head.is_some()))];
        if let Some((h, second, ..)) = head {
            want.extend(access(&h, second));
        }
        for (pin, v) in want {
            self.dual.expect(&out, pin, &v).unwrap_or_else(|m| {
                let at = head.map(|(_, s, st, c)| format!("{st:?}\n{c:?} second {s}"));
                panic!("{m}\nout: {}\nin: {st:?}\n{c:?} second {second} (seed {})", at.unwrap_or_default(), seed())
            });
        }
        if en {
            self.stages.copy_within(0..LATENCY - 1, 1);
            self.stages[0] = valid.then_some((r, second, *st, *c));
        }
        (head.map(|(h, ..)| h), r)
    }

    /// Enabled clocks without an access until the pipeline is empty (the state may change
    /// then).
    fn drain(&mut self, st: &TexState) {
        while self.stages.iter().any(Option::is_some) {
            self.cycle(true, false, st, &Coords { s: 0, t: 0, lambda: 0 }, false);
        }
    }
}

fn random_state(rng: &mut ChaCha8Rng) -> TexState {
    let (ws, hs) = (rng.gen_range(0..=12), rng.gen_range(0..=12));
    let levels = rng.gen_range(1..=ws.max(hs) + 1);
    let filter = |rng: &mut ChaCha8Rng| if rng.gen() { Filter::Linear } else { Filter::Nearest };
    let sampler = Sampler {
        min: filter(rng),
        mag: filter(rng),
        mip: MIPS[rng.gen_range(0..3)],
        wrap_s: WRAPS[rng.gen_range(0..3)],
        wrap_t: WRAPS[rng.gen_range(0..3)],
        ..Sampler::default()
    };
    let room = (1u32 << ADDR_BITS) - chain_words(ws, hs, levels);
    TexState {
        size_log2: [ws, hs],
        levels,
        base: rng.gen_range(0..=room),
        format: Default::default(),
        sampler,
        env: Default::default(),
        lod: LodRule::Max,
    }
}

fn random_coords(rng: &mut ChaCha8Rng) -> Coords {
    let st = |rng: &mut ChaCha8Rng| match rng.gen_range(0..4) {
        0 => [F.st.min_raw() as i64, F.st.max_raw() as i64, 0, -1][rng.gen_range(0..4)],
        1 => rng.gen_range(F.st.min_raw() as i64..=F.st.max_raw() as i64),
        _ => rng.gen_range(-3i64 << F.st.frac..3i64 << F.st.frac),
    };
    let lambda = match rng.gen_range(0..5) {
        0 => [MAGNIFIED, 0, 1, i64::from(i32::MAX)][rng.gen_range(0..4)],
        1 => rng.gen_range(-200..200),
        _ => rng.gen_range(0..14 << F.lod_frac),
    };
    Coords { s: st(rng), t: st(rng), lambda }
}

#[test]
fn texture_address_random_accesses_in_both_simulators_match_the_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut bench = Bench::new();
    let (mut two, mut shared, mut held, mut n) = (0, 0, 0, 0);
    while n < 20 * count() {
        // A state held over a few pixels (the unit reads it as each access passes), each
        // pixel one access or two (`second`), with bubbles and stalls between.
        let st = random_state(&mut rng);
        for _ in 0..rng.gen_range(1..=8) {
            let c = random_coords(&mut rng);
            let mut second = false;
            loop {
                let en = rng.gen_range(0..4) != 0;
                let valid = rng.gen_range(0..5) != 0;
                let (_, r) = bench.cycle(en, valid, &st, &c, second);
                held += usize::from(!en && bench.stages.iter().any(Option::is_some));
                if !(valid && en) {
                    continue;
                }
                n += 1;
                shared += usize::from(r.fetch.iter().filter(|f| f.is_some()).count() < 4);
                if !r.two_levels || second {
                    break;
                }
                two += 1;
                second = true;
            }
        }
        bench.drain(&st);
    }
    // Both kinds of access were tried: two-level pixels, and footprints of fewer than four
    // distinct texels (nearest, clamped edges, 1-wide levels); and accesses were held.
    assert!(
        two > 1000 && shared > 1000 && held > 1000,
        "{two} two-level pixels, {shared} shared footprints, {held} held"
    );
}

#[test]
fn texture_address_gives_the_worked_footprint() {
    // A 4 x 4 texture at base 1000, bilinear, repeat: s = 0.3125 (u = 1.25, texels 0 and
    // 1, alpha 3/4), t = 1 (v - 1/2 = 3.5: rows 3 and 0, beta 1/2); level 0's planes are
    // 2 x 2, texel (i, j) word 1000 + 4 · bank(i, j) + 2 (j >> 1) + (i >> 1). It comes out
    // LATENCY = 3 clocks after it goes in.
    let mut bench = Bench::new();
    let st = TexState {
        size_log2: [2, 2],
        levels: 3,
        base: 1000,
        format: Default::default(),
        sampler: Sampler::default(),
        env: Default::default(),
        lod: LodRule::Max,
    };
    let c = Coords { s: 5 << (F.st.frac - 4), t: 1 << F.st.frac, lambda: MAGNIFIED };
    let (_, r) = bench.cycle(true, true, &st, &c, false);
    let mut out = Vec::new();
    for k in 1..=LATENCY {
        let (o, _) = bench.cycle(true, false, &st, &c, false);
        out.extend(o.map(|o| (k, o)));
    }
    assert_eq!(out, [(LATENCY, r)]);
    assert_eq!((r.alpha, r.beta, r.two_levels), (192, 128, false));
    // T(0, 3): bank 2, word 1000 + 8 + 2 + 0; T(1, 3): bank 3; T(0, 0): bank 0; T(1, 0): bank 1.
    assert_eq!(r.banks, [2, 3, 0, 1]);
    assert_eq!(r.fetch, [Some(1000), Some(1004), Some(1010), Some(1014)]);
    for (i, j) in [(0, 3), (1, 3), (0, 0), (1, 0)] {
        assert!(r.fetch.contains(&Some(address(1000, 2, 2, 0, i, j))));
    }
}
