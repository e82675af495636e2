//! A combinational signed multiplier of any widths: `p` = the low `P` bits of `a * b`,
//! `a` and `b` two's complement. rust-hdl multiplies only `Signed<16>` by `Signed<16>`,
//! so this block writes its own Verilog (`$signed(a) * $signed(b)`, both operands
//! sign-extended to the product's width, as the Verilog rules for a signed expression in a
//! `P`-bit context require) and computes the same in Rust for rust-hdl's simulator. The
//! dual-simulation tests of every unit that uses it guard that the two agree.
//!
//! Used by `cull_sort` (the back-face test) and `triangle_setup` (its reused multipliers,
//! 001 §II.2.라). On ECP5, Yosys maps it onto MULT18X18D blocks.

use rust_hdl::prelude::*;

/// `p = (a * b) mod 2^P`, `a` (`A` bits) and `b` (`B` bits) signed. Combinational.
#[derive(LogicBlock, Default)]
pub struct Mul<const A: usize, const B: usize, const P: usize> {
    pub a: Signal<In, Bits<A>>,
    pub b: Signal<In, Bits<B>>,
    pub p: Signal<Out, Bits<P>>,
}

/// `v`'s low `n` bits as a two's complement number.
fn signed(v: u128, n: usize) -> i128 {
    ((v << (128 - n)) as i128) >> (128 - n)
}

impl<const A: usize, const B: usize, const P: usize> Logic for Mul<A, B, P> {
    fn update(&mut self) {
        assert!(A + B <= 127 && P <= 128, "Mul<{A}, {B}, {P}>: the Rust model computes in i128");
        let prod = signed(self.a.val().to_u128(), A).wrapping_mul(signed(self.b.val().to_u128(), B)) as u128;
        let mask = if P == 128 { u128::MAX } else { (1u128 << P) - 1 };
        self.p.next = (prod & mask).to_bits();
    }

    fn connect(&mut self) {
        self.p.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "// p = low {P} bits of a * b, both signed: a signed {P}-bit context sign-extends\n\
             // both operands before multiplying.\n\
             always @(*) p = $signed(a) * $signed(b);\n"
        ))
    }
}

/// [`Mul`] between registers: its operands are registered from `a`, `b` and the product
/// from them, both while `en` is high, so `p` is the product of the operands of two
/// enabled cycles before (`model::triangle_setup::schedule::MULTIPLIER_STAGES`). Nothing
/// but the multiplier lies between its registers: on ECP5 its MULT18X18D blocks and the
/// adders of their partial products.
#[derive(LogicBlock, Default)]
pub struct PipelinedMul<const A: usize, const B: usize, const P: usize> {
    pub clock: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    pub a: Signal<In, Bits<A>>,
    pub b: Signal<In, Bits<B>>,
    pub p: Signal<Out, Bits<P>>,
    a_r: DFF<Bits<A>>,
    b_r: DFF<Bits<B>>,
    p_r: DFF<Bits<P>>,
    mul: Mul<A, B, P>,
}

impl<const A: usize, const B: usize, const P: usize> Logic for PipelinedMul<A, B, P> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, a_r, b_r, p_r);
        self.mul.a.next = self.a_r.q.val();
        self.mul.b.next = self.b_r.q.val();
        if self.en.val() {
            self.a_r.d.next = self.a.val();
            self.b_r.d.next = self.b.val();
            self.p_r.d.next = self.mul.p.val();
        }
        self.p.next = self.p_r.q.val();
    }
}
