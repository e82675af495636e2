//! `rtl::mul::SplitMul`, setup's multiplier: rust-hdl and Verilator in lockstep on random
//! operands over their whole range (and the extremes), with the enable toggling, each
//! product checked against `i128` arithmetic three enabled cycles after its operands.
//! The widths cover every shape of its Verilog: setup's at class 10 (b's top two bits by
//! a masked subtraction), b of 18 bits or fewer (one top bit), b's top bits on a
//! multiplier, a single chunk of `a`, and products wider than `P` (chunks cut off).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::mul::{emit_split_mul, SplitMul};
use testbenches::{count, seed, verilate, Dual, Pins, Value};

/// `n`-bit two's complement `v`, as the low `n` bits.
fn raw(n: usize, v: i128) -> u128 {
    (v as u128) & ((1u128 << n) - 1)
}

/// A random `n`-bit signed operand: uniform, or an extreme (most negative, -1, 0, 1, most
/// positive), or a small one.
fn operand(rng: &mut ChaCha8Rng, n: usize) -> i128 {
    let lim = 1i128 << (n - 1);
    match rng.gen_range(0..8) {
        0 => [-lim, -1, 0, 1, lim - 1][rng.gen_range(0..5)],
        1 => rng.gen_range(-256..256).clamp(-lim, lim - 1),
        _ => rng.gen_range(-lim..lim),
    }
}

fn lockstep<const A: usize, const B: usize, const P: usize>()
where
    SplitMul<A, B, P>: Pins,
{
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let vl = verilate(&emit_split_mul::<A, B, P>()).unwrap_or_else(|e| panic!("{e}"));
    let mut dual = Dual::new(SplitMul::<A, B, P>::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    // The products of the operands taken at each enabled edge, in order.
    let mut taken: Vec<u128> = Vec::new();
    let mut checked = 0;
    for _ in 0..count() * 10 {
        let (a, b, en) = (operand(&mut rng, A), operand(&mut rng, B), rng.gen_bool(0.8));
        let pins =
            [("en", Value::new(1, en as u128)), ("a", Value::new(A, raw(A, a))), ("b", Value::new(B, raw(B, b)))];
        let out = dual.cycle(&pins).unwrap_or_else(|m| panic!("SplitMul<{A}, {B}, {P}>: {m}\nseed {seed}"));
        // Before this edge: the product of three enabled edges ago, 0 until there is one.
        let want = if taken.len() >= 3 { taken[taken.len() - 3] } else { 0 };
        dual.expect(&out, "p", &Value::new(P, want))
            .unwrap_or_else(|m| panic!("SplitMul<{A}, {B}, {P}>: {m}\nseed {seed}"));
        checked += usize::from(taken.len() >= 3);
        if en {
            taken.push(raw(P, a * b));
        }
    }
    assert!(checked > count() * 5, "SplitMul<{A}, {B}, {P}>: {checked} products checked");
}

#[test]
fn split_mul_matches_its_product_in_both_simulators() {
    // Setup at class 10: 57 x 19 into 58 bits (four chunks of a; b's top two bits).
    lockstep::<57, 19, 58>();
    // b of 16 bits (one top bit, its sign), a 30-bit product of a 30-bit a: cut off.
    lockstep::<30, 16, 30>();
    // b's top 6 bits on a multiplier; a chunk of a entirely above P.
    lockstep::<60, 23, 50>();
    // a in one chunk (signed), b's top 3 bits.
    lockstep::<12, 20, 32>();
}
