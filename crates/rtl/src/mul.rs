//! A combinational signed multiplier of any widths: `p` = the low `P` bits of `a * b`,
//! `a` and `b` two's complement. rust-hdl multiplies only `Signed<16>` by `Signed<16>`,
//! so this block writes its own Verilog (`$signed(a) * $signed(b)`, both operands
//! sign-extended to the product's width, as the Verilog rules for a signed expression in a
//! `P`-bit context require) and computes the same in Rust for rust-hdl's simulator. The
//! dual-simulation tests of every unit that uses it guard that the two agree.
//!
//! Used by `cull_sort` (the back-face test) and, pipelined, by `triangle_setup` (its reused
//! multipliers, 001 §II.2.라: [`SplitMul`]) and the vector unit ([`PipelinedMul`]). On ECP5,
//! Yosys maps it onto MULT18X18D blocks.

use crate::emit::{ports, verilog, Emitted};
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

/// Bits of an unsigned operand chunk: with a zero above it, it fills an 18-bit signed port
/// of a DSP block (ECP5's MULT18X18D, and most FPGAs' 18 x 18 or wider).
const CHUNK: usize = 17;

/// A signed multiplier split into DSP-sized partial products, with a register between the
/// DSP blocks and the adders that sum them: `p` is the low `P` bits of the product of the
/// `a` and `b` of three enabled cycles before (`model::triangle_setup::schedule::
/// MULTIPLIER_STAGES`). Yosys maps a `$signed(a) * $signed(b)` wider than one block onto
/// several blocks and a tree of adders behind them in one path; here
///
/// 1. `a` and `b` are registered;
/// 2. `a` is cut into 17-bit unsigned chunks (the top one signed, up to 18 bits), each
///    multiplied by `b`'s low 17 bits (one DSP block each), and `a` times `b`'s top bits
///    (`b` sign-extended to 18 bits or more; with one or two top bits a masked subtraction
///    in logic, with more a multiplier); each partial product is registered;
/// 3. the chunks' products, at even and odd chunk positions, tile two rows (concatenated,
///    not added), and the two rows and `a` times `b`'s top bits are summed into `p`.
///
/// The Rust model computes the whole product (`Mul`'s arithmetic); the dual-simulation
/// tests (`testbenches/tests/mul.rs`, and those of setup) guard that the emitted partial
/// products sum to it.
#[derive(LogicBlock, Default)]
pub struct SplitMul<const A: usize, const B: usize, const P: usize> {
    pub clock: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    pub a: Signal<In, Bits<A>>,
    pub b: Signal<In, Bits<B>>,
    pub p: Signal<Out, Bits<P>>,
    /// The registered operands and the product of the operands before them (the partial
    /// products' sum, in one number).
    _a: u128,
    _b: u128,
    _ab: u128,
}

/// `a`'s chunks, low first: (lowest bit, width, signed).
fn chunks(width: usize) -> Vec<(usize, usize, bool)> {
    let n = if width <= CHUNK + 1 { 1 } else { 1 + (width - CHUNK - 1).div_ceil(CHUNK) };
    (0..n).map(|i| (CHUNK * i, if i + 1 == n { width - CHUNK * i } else { CHUNK }, i + 1 == n)).collect()
}

/// A `p`-bit concatenation of partial products `parts` (name, lowest bit, width, signed),
/// which do not overlap; only the highest may be signed (sign-extended to the top).
fn row(p: usize, parts: &[(String, usize, usize, bool)]) -> String {
    let (mut pieces, mut top) = (Vec::new(), p);
    for (name, lo, w, signed) in parts.iter().rev().filter(|part| part.1 < p) {
        let end = lo + w;
        if end < top {
            pieces.push(if *signed {
                format!("{{{}{{{name}[{}]}}}}", top - end, w - 1)
            } else {
                format!("{}'d0", top - end)
            });
        }
        pieces.push(format!("{name}[{}:0]", top.min(end) - lo - 1));
        top = *lo;
    }
    if top > 0 {
        pieces.push(format!("{top}'d0"));
    }
    format!("{{{}}}", pieces.join(", "))
}

impl<const A: usize, const B: usize, const P: usize> Logic for SplitMul<A, B, P> {
    fn update(&mut self) {
        assert!(A + B <= 127 && P <= 128 && P > CHUNK + 1, "SplitMul<{A}, {B}, {P}>: the Rust model computes in i128");
        if self.clock.pos_edge() && self.en.val() {
            let mask = if P == 128 { u128::MAX } else { (1u128 << P) - 1 };
            self.p.next = self._ab.to_bits();
            self._ab = (signed(self._a, A).wrapping_mul(signed(self._b, B)) as u128) & mask;
            self._a = self.a.val().to_u128();
            self._b = self.b.val().to_u128();
        }
    }

    fn connect(&mut self) {
        self.p.connect();
    }

    fn hdl(&self) -> Verilog {
        // b sign-extended to at least 18 bits: 17 low bits (unsigned) and t top bits.
        let bx = B.max(CHUNK + 1);
        let t = bx - CHUNK;
        let mut v = format!(
            "// p = low {P} bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):\n\
             // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP\n\
             // block each, and a times b's top {t} bits); their sum.\n\
             reg [{}:0] a_r;\nreg [{}:0] b_r;\ninitial a_r = 0;\ninitial b_r = 0;\n\
             wire [{}:0] bx = {};\n",
            A - 1,
            B - 1,
            bx - 1,
            if bx > B { format!("{{{{{}{{b_r[{}]}}}}, b_r}}", bx - B, B - 1) } else { "b_r".into() },
        );
        let mut regs = vec![];
        let mut parts = [vec![], vec![]];
        for (i, (lo, w, top)) in chunks(A).into_iter().enumerate().filter(|c| c.1 .0 < P) {
            // A chunk times b's low bits: unsigned by unsigned, or (the top chunk) signed by unsigned.
            let (pw, expr) = if top {
                (w + CHUNK + 1, format!("$signed(a_r[{}:{lo}]) * $signed({{1'b0, bx[{}:0]}})", lo + w - 1, CHUNK - 1))
            } else {
                (w + CHUNK, format!("a_r[{}:{lo}] * bx[{}:0]", lo + w - 1, CHUNK - 1))
            };
            // Bits at P and above are not kept.
            let pw = pw.min(P - lo);
            v += &format!("reg [{}:0] pp{i};\ninitial pp{i} = 0;\n", pw - 1);
            regs.push(format!("pp{i} <= {expr};"));
            parts[i % 2].push((format!("pp{i}"), lo, pw, top));
        }
        // a times b's top bits, into the bits above b's low ones (P - 17 of them).
        let h = P - CHUNK;
        v += &format!("reg [{}:0] ph;\ninitial ph = 0;\n", h - 1);
        if t <= 2 {
            let ax =
                if A >= h { format!("a_r[{}:0]", h - 1) } else { format!("{{{{{}{{a_r[{}]}}}}, a_r}}", h - A, A - 1) };
            v += &format!("wire [{}:0] ax = {ax};\n", h - 1);
        }
        let top = |k: usize| format!("bx[{}]", CHUNK + k);
        regs.push(match t {
            1 => format!("ph <= {h}'d0 - ({{{h}{{{}}}}} & ax);", top(0)),
            2 => format!("ph <= ({{{h}{{{}}}}} & ax) - ({{{h}{{{}}}}} & {{ax[{}:0], 1'b0}});", top(0), top(1), h - 2),
            _ => format!("ph <= $signed(a_r) * $signed(bx[{}:{CHUNK}]);", bx - 1),
        });
        v += "always @(posedge clock) if (en) begin\n    a_r <= a;\n    b_r <= b;\n";
        for r in regs {
            v += &format!("    {r}\n");
        }
        let mut sum = vec![row(P, &parts[0])];
        if !parts[1].is_empty() {
            sum.push(row(P, &parts[1]));
        }
        sum.push(format!("{{ph, {CHUNK}'d0}}"));
        v += &format!("    p <= {};\nend\ninitial p = 0;\n", sum.join(" + "));
        Verilog::Custom(v)
    }
}

crate::pins!(impl[const A: usize, const B: usize, const P: usize] SplitMul<A, B, P> {
    clock: clock,
    inputs: [en, a, b],
    outputs: [p],
});

/// A [`SplitMul`] alone, as unit `split_mul` (for its dual-simulation tests).
pub fn emit_split_mul<const A: usize, const B: usize, const P: usize>() -> Emitted {
    let mut u = SplitMul::<A, B, P>::default();
    u.connect_all();
    let params = [("A".to_owned(), A as u64), ("B".to_owned(), B as u64), ("P".to_owned(), P as u64)].into();
    Emitted { unit: "split_mul", params, formats: None, ports: ports(&u), verilog: verilog("split_mul", &u), dir: None }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_mul_chunks_cover_the_operand() {
        assert_eq!(chunks(57), vec![(0, 17, false), (17, 17, false), (34, 17, false), (51, 6, true)]);
        assert_eq!(chunks(18), vec![(0, 18, true)]);
        assert_eq!(chunks(19), vec![(0, 17, false), (17, 2, true)]);
        assert_eq!(chunks(35), vec![(0, 17, false), (17, 18, true)]);
    }
}
