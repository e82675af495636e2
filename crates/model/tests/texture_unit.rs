//! The texture unit's bit-exact model (`model::texture_unit`, paper 001 section II-5)
//! against values worked out by hand and against the float reference's rules one stage at
//! a time: wrap, level choice, the divide and the level of detail. Its error over whole
//! scenes, judged as the conformance tests judge texture filtering, is
//! `crates/accuracy/tests/texture.rs`'s.

mod common;

use fx::{Fmt, TexFormats};
use model::texture_address::{levels, taps, wrap_index, Levels};
use model::texture_unit::{TexGrad, TexIn, TexState, TextureUnit};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use texture::{EnvMode, Filter, LevelChoice, LodRule, MipMode, Sampler, TexelFormat, Wrap};

fn unit() -> TextureUnit {
    TextureUnit::new(TexFormats::default()).unwrap()
}

fn state(ws: u32, hs: u32, sampler: Sampler) -> TexState {
    TexState {
        size_log2: [ws, hs],
        levels: ws.max(hs) + 1,
        base: 0,
        format: TexelFormat::Rgba8888,
        sampler,
        env: EnvMode::Replace,
        lod: LodRule::Max,
    }
}

/// Raw value of `v` in `fmt` (exact for the binary fractions used here).
fn raw(fmt: Fmt, v: f64) -> i64 {
    fmt.from_f64(v).unwrap() as i64
}

#[test]
fn the_divide_and_texel_selection_give_the_worked_values() {
    let u = unit();
    let f = u.formats;
    let st = state(2, 2, Sampler::default());
    // q = 1/2, s·q = 0.15625: s = 0.3125, u = 4 s = 1.25 on a 4-wide level; bilinear reads
    // texels 0 and 1 with alpha = 0.75 (192 of 256), as texture's own axis test.
    let p = TexIn { sq: raw(f.st, 0.15625), tq: raw(f.st, 0.5), q: raw(f.q, 0.5) };
    let c = u.coords(&st, &p, &TexGrad::default());
    assert_eq!((c.s, c.t), (raw(f.st, 0.3125), raw(f.st, 1.0)));
    let taps = taps(&f, &st, &c, 0, Filter::Linear);
    assert_eq!((taps.i, taps.alpha), ([0, 1], 192));
    // t = 1: v - 1/2 = 3.5, texels 3 and 4 -> 0 (repeat), beta 1/2.
    assert_eq!((taps.j, taps.beta), ([3, 0], 128));
    // Nearest: floor(1.25) = 1, floor(4) = 4 -> 0.
    let near = model::texture_address::taps(&f, &st, &c, 0, Filter::Nearest);
    assert_eq!((near.i, near.j), ([1, 1], [0, 0]));
    // No derivatives: magnified.
    assert_eq!(levels(&f, &st, c.lambda), Levels::Magnify);
}

#[test]
fn the_level_of_detail_gives_the_worked_values() {
    let u = unit();
    let f = u.formats;
    let one = 1 << f.lod_frac;
    // A 256 x 256 texture, q = 1 and constant: ds/dx = 2/256 is 2 texels per pixel: lambda 1.
    let mut st = state(8, 8, Sampler::default());
    let p = TexIn { sq: raw(f.st, 0.25), tq: raw(f.st, 0.25), q: raw(f.q, 1.0) };
    let g = TexGrad { dsq: [raw(f.dst, 2.0 / 256.0), 0], dtq: [0, raw(f.dst, 2.0 / 256.0)], dq: [0, 0] };
    assert_eq!(u.coords(&st, &p, &g).lambda, one);
    // Both along x: 001's max is still 2 texels, GL's exact rho is 2 sqrt(2): lambda 1.5.
    let g = TexGrad { dsq: [raw(f.dst, 2.0 / 256.0), 0], dtq: [raw(f.dst, 2.0 / 256.0), 0], dq: [0, 0] };
    assert_eq!(u.coords(&st, &p, &g).lambda, one);
    st.lod = LodRule::Exact;
    assert_eq!(u.coords(&st, &p, &g).lambda, one * 3 / 2);
    // The same pixel at q = 1/4 with the gradients of s·q a quarter: s and the derivatives
    // of s unchanged (the quotient rule with dq = 0).
    let p4 = TexIn { sq: raw(f.st, 0.0625), tq: raw(f.st, 0.0625), q: raw(f.q, 0.25) };
    let g4 = TexGrad { dsq: [raw(f.dst, 0.5 / 256.0), 0], dtq: [raw(f.dst, 0.5 / 256.0), 0], dq: [0, 0] };
    let c = u.coords(&st, &p4, &g4);
    assert_eq!((c.s, c.lambda), (raw(f.st, 0.25), one * 3 / 2));
    // With dq/dx = -1/8 at s = 1/4: ds/dx = (d(s·q)/dx - s dq/dx) / q = (1/512 + 1/32) / (1/4).
    let g = TexGrad { dsq: [raw(f.dst, 1.0 / 512.0), 0], dtq: [0, 0], dq: [raw(f.dq, -0.125), 0] };
    let want = ((1.0 / 512.0 + 1.0 / 32.0) * 4.0 * 256.0_f64).log2();
    st.lod = LodRule::Max;
    let got = u.coords(&st, &p4, &g).lambda as f64 / one as f64;
    assert!((got - want).abs() <= 1.0 / one as f64, "lambda {got}, want {want}");
}

#[test]
fn wrap_matches_the_float_reference_on_every_index() {
    for wrap in [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge] {
        for size_log2 in 0..5 {
            for i in -70..70 {
                assert_eq!(
                    wrap_index(wrap, i, size_log2),
                    wrap.index(i, 1 << size_log2),
                    "{wrap:?} {i} of 2^{size_log2}"
                );
            }
        }
    }
}

#[test]
fn levels_follow_gl_level_choice() {
    let f = TexFormats::default();
    let one = 1i64 << f.lod_frac;
    for mip in [MipMode::None, MipMode::Nearest, MipMode::Linear] {
        let st = state(4, 3, Sampler { mip, ..Sampler::default() });
        for lambda in -one..8 * one {
            let want = texture::level_choice(lambda as f64 / one as f64, mip, 5);
            let got = match levels(&f, &st, lambda) {
                Levels::Magnify => LevelChoice::Magnify,
                Levels::One(d) => LevelChoice::Level(d as usize),
                Levels::Two { d1, frac } => LevelChoice::Blend { d1: d1 as usize, frac: f64::from(frac) / one as f64 },
            };
            assert_eq!(got, want, "{mip:?} lambda {lambda}/{one}");
        }
    }
}

#[test]
fn coordinates_and_level_agree_with_f64_within_their_precision() {
    let mut rng = ChaCha8Rng::seed_from_u64(common::seed());
    let u = unit();
    let f = u.formats;
    let one = f64::from(1u32 << f.lod_frac);
    let (mut worst_s, mut worst_lambda) = (0.0f64, 0.0f64);
    for _ in 0..20_000 {
        let rule = if rng.gen() { LodRule::Max } else { LodRule::Exact };
        let st = TexState { lod: rule, ..state(rng.gen_range(0..=12), rng.gen_range(0..=12), Sampler::default()) };
        let q = rng.gen_range(0.004..=1.0);
        let s = rng.gen_range(-60.0..60.0);
        let p =
            TexIn { sq: raw(f.st.half_up(), s * q), tq: raw(f.st.half_up(), -s * q / 3.0), q: raw(f.q.half_up(), q) };
        let g = TexGrad {
            dsq: [rng.gen_range(-0.02..0.02), rng.gen_range(-0.02..0.02)].map(|v| raw(f.dst.half_up(), v)),
            dtq: [rng.gen_range(-0.02..0.02), rng.gen_range(-0.02..0.02)].map(|v| raw(f.dst.half_up(), v)),
            dq: [rng.gen_range(-0.004..0.004), rng.gen_range(-0.004..0.004)].map(|v| raw(f.dq.half_up(), v)),
        };
        let c = u.coords(&st, &p, &g);
        // The same computation in f64 from the quantized inputs.
        let val = |fmt: Fmt, r: i64| fmt.to_f64(i128::from(r));
        let (qv, sv, tv) = (val(f.q, p.q), val(f.st, p.sq) / val(f.q, p.q), val(f.st, p.tq) / val(f.q, p.q));
        // The reciprocal's mantissa is within 2^-recip relative, then s is floored.
        let err_s = (val(f.st, c.s) - sv).abs() / f.st.lsb();
        let bound = 1.0 + sv.abs() * f64::from(f.st.frac as i32 - f.recip as i32).exp2();
        worst_s = worst_s.max(err_s / bound);
        assert!(err_s <= bound, "s {} against {sv}: {err_s} LSB", val(f.st, c.s));
        let d = |k: usize, x: f64, dxq: i64| (val(f.dst, dxq) - x * val(f.dq, g.dq[k])) / qv;
        let [ws, hs] = st.size_log2.map(|b| f64::from(1u32 << b));
        let (ux, vx, uy, vy) =
            (d(0, sv, g.dsq[0]) * ws, d(0, tv, g.dtq[0]) * hs, d(1, sv, g.dsq[1]) * ws, d(1, tv, g.dtq[1]) * hs);
        let want = rule.rho(ux, vx, uy, vy).log2();
        if want.is_finite() && want > -20.0 {
            let err = (c.lambda as f64 / one - want).abs();
            worst_lambda = worst_lambda.max(err);
            // Rounding to lod_frac bits (1/2 LSB), two table entries (their intervals and
            // rounding, under 0.1 LSB each) and the numerators' floor (relative 2^-20 or so).
            assert!(err <= 0.75 / one, "{rule:?} lambda {} against {want}: {err}", c.lambda as f64 / one);
        }
    }
    println!(
        "worst s error {worst_s:.3} of its bound, worst lambda error {:.3} LSB of {} bits",
        worst_lambda * one,
        f.lod_frac
    );
}
