//! Framebuffer blending (paper 001 section II-5's six blend modes, OpenGL 4.6 section
//! 17.3.6): rust-hdl and Verilator in lockstep on random colours in every mode, the colour
//! checked against `model::blend::blend`, and worked values.

use model::blend::{blend, MODES};
use model::texture_filter::Rgba8;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::blend::{emit_blend, Blend};
use testbenches::{count, seed, verilate, Dual, Value, Verilated};
use texture::BlendMode;

fn pack(c: Rgba8) -> Value {
    Value::new(32, u32::from_le_bytes(c).into())
}

fn verilated() -> Verilated {
    verilate(&emit_blend(&rtl::Params::new()).unwrap_or_else(|e| panic!("{e}"))).unwrap_or_else(|e| panic!("{e}"))
}

/// Both simulators' colour for `src` onto `dst` in `mode`, checked against the model's.
fn check(dual: &mut Dual<Blend>, mode: BlendMode, src: Rgba8, dst: Rgba8) -> Rgba8 {
    let code = MODES.iter().position(|m| *m == mode).unwrap() as u128;
    let out = dual
        .cycle(&[("src", pack(src)), ("dst", pack(dst)), ("mode", Value::new(3, code))])
        .unwrap_or_else(|m| panic!("{m}"));
    let want = blend(mode, src, dst);
    dual.expect(&out, "color", &pack(want)).unwrap_or_else(|m| panic!("{m}\n{mode:?} {src:?} onto {dst:?}"));
    want
}

#[test]
fn blend_random_colours_in_both_simulators_match_the_model_in_every_mode() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let vl = verilated();
    let mut dual = Dual::new(Blend::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let channel = |rng: &mut ChaCha8Rng| match rng.gen_range(0..4) {
        0 => [0, 1, 127, 128, 254, 255][rng.gen_range(0..6)],
        _ => rng.gen(),
    };
    let mut saturated = 0;
    for _ in 0..10 * count() {
        let src: Rgba8 = std::array::from_fn(|_| channel(&mut rng));
        let dst: Rgba8 = std::array::from_fn(|_| channel(&mut rng));
        for mode in MODES {
            let got = check(&mut dual, mode, src, dst);
            saturated += usize::from(mode == BlendMode::Additive && got.contains(&255));
        }
    }
    assert!(saturated > count(), "the saturating add was tried: {saturated} additive colours with a channel at 255");
}

#[test]
fn blend_gives_the_worked_values() {
    let vl = verilated();
    let mut dual = Dual::new(Blend::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let (src, dst) = model::blend::WORKED_SRC_DST;
    for (mode, want) in model::blend::WORKED {
        assert_eq!(check(&mut dual, mode, src, dst), want, "{mode:?}");
    }
    // Codes 6 and 7 are opaque.
    for code in [6, 7] {
        let out = dual
            .cycle(&[("src", pack(src)), ("dst", pack(dst)), ("mode", Value::new(3, code))])
            .unwrap_or_else(|m| panic!("{m}"));
        dual.expect(&out, "color", &pack(src)).unwrap_or_else(|m| panic!("{m}"));
    }
}
