//! The texture unit's addresses (paper 001 section II-5, OpenGL 4.6 section 8.14):
//! rust-hdl and Verilator in lockstep on random pixels and texture states, every cache
//! access checked against `model::texture_address::request`, and worked values.

use fx::TexFormats;
use model::texture_address::{request, Request};
use model::texture_coords::{Coords, MAGNIFIED};
use model::texture_memory::{address, chain_words, ADDR_BITS};
use model::texture_unit::TexState;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_address::{TextureAddress, ADDR, LAMBDA, ST};
use testbenches::{count, seed, verilated, Dual, Value};
use texture::{Filter, LodRule, MipMode, Sampler, Wrap};

const F: TexFormats = TexFormats::DEFAULT;
const WRAPS: [Wrap; 3] = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
const MIPS: [MipMode; 3] = [MipMode::None, MipMode::Nearest, MipMode::Linear];

fn raw(bits: usize, v: i64) -> Value {
    Value::new(bits, (v as u128) & ((1u128 << bits) - 1))
}

fn pins(st: &TexState, c: &Coords, second: bool) -> Vec<(&'static str, Value)> {
    let code = |w: Wrap| WRAPS.iter().position(|x| *x == w).unwrap() as u128;
    vec![
        ("s", raw(ST, c.s)),
        ("t", raw(ST, c.t)),
        ("lambda", raw(LAMBDA, c.lambda)),
        ("second", Value::new(1, second.into())),
        ("ws", Value::new(4, st.size_log2[0].into())),
        ("hs", Value::new(4, st.size_log2[1].into())),
        ("levels", Value::new(4, st.levels.into())),
        ("base", Value::new(ADDR, st.base.into())),
        ("min_linear", Value::new(1, (st.sampler.min == Filter::Linear).into())),
        ("mag_linear", Value::new(1, (st.sampler.mag == Filter::Linear).into())),
        ("mip", Value::new(2, MIPS.iter().position(|m| *m == st.sampler.mip).unwrap() as u128)),
        ("wrap_s", Value::new(2, code(st.sampler.wrap_s))),
        ("wrap_t", Value::new(2, code(st.sampler.wrap_t))),
    ]
}

/// Every output against the model's access.
fn check(dual: &mut Dual<TextureAddress>, st: &TexState, c: &Coords, second: bool) -> Request {
    let r = request(&F, st, c, second);
    let out = dual.cycle(&pins(st, c, second)).unwrap_or_else(|m| panic!("{m}"));
    let lanes = (0..4).filter(|&b| r.fetch[b].is_some()).map(|b| 1u128 << b).sum();
    let banks = (0..4).map(|k| (r.banks[k] as u128) << (2 * k)).sum();
    let mut want = vec![
        ("lanes", Value::new(4, lanes)),
        ("banks", Value::new(8, banks)),
        ("alpha", Value::new(8, r.alpha.into())),
        ("beta", Value::new(8, r.beta.into())),
        ("two_levels", Value::new(1, r.two_levels.into())),
        ("frac", Value::new(6, r.frac.into())),
    ];
    for (b, pin) in ["addr0", "addr1", "addr2", "addr3"].into_iter().enumerate() {
        want.push((pin, Value::new(ADDR, r.fetch[b].unwrap_or(0).into())));
    }
    for (pin, v) in want {
        dual.expect(&out, pin, &v).unwrap_or_else(|m| panic!("{m}\n{st:?}\n{c:?} second {second}"));
    }
    r
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
    let vl = verilated("texture_address");
    let mut dual = Dual::new(TextureAddress::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let (mut two, mut shared) = (0, 0);
    for _ in 0..20 * count() {
        let st = random_state(&mut rng);
        let c = random_coords(&mut rng);
        let r = check(&mut dual, &st, &c, false);
        if r.two_levels {
            two += 1;
            check(&mut dual, &st, &c, true);
        }
        shared += usize::from(r.fetch.iter().filter(|f| f.is_some()).count() < 4);
    }
    // Both kinds of access were tried: two-level pixels, and footprints of fewer than four
    // distinct texels (nearest, clamped edges, 1-wide levels).
    assert!(two > 1000 && shared > 1000, "{two} two-level pixels, {shared} shared footprints");
}

#[test]
fn texture_address_gives_the_worked_footprint() {
    // A 4 x 4 texture at base 1000, bilinear, repeat: s = 0.3125 (u = 1.25, texels 0 and
    // 1, alpha 3/4), t = 1 (v - 1/2 = 3.5: rows 3 and 0, beta 1/2); level 0's planes are
    // 2 x 2, texel (i, j) word 1000 + 4 · bank(i, j) + 2 (j >> 1) + (i >> 1).
    let vl = verilated("texture_address");
    let mut dual = Dual::new(TextureAddress::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
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
    let r = check(&mut dual, &st, &c, false);
    assert_eq!((r.alpha, r.beta, r.two_levels), (192, 128, false));
    // T(0, 3): bank 2, word 1000 + 8 + 2 + 0; T(1, 3): bank 3; T(0, 0): bank 0; T(1, 0): bank 1.
    assert_eq!(r.banks, [2, 3, 0, 1]);
    assert_eq!(r.fetch, [Some(1000), Some(1004), Some(1010), Some(1014)]);
    for (i, j) in [(0, 3), (1, 3), (0, 0), (1, 0)] {
        assert!(r.fetch.contains(&Some(address(1000, 2, 2, 0, i, j))));
    }
}
