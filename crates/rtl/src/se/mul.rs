//! The serial multiplier of paper 000, Fig. 7, with the rounding of its result.
//! Model: `model::se::mul`.

use rust_hdl::prelude::*;

/// Bits of X: 000 Fig. 7's 11 stages, screens up to 1024 wide (the RTL's size class + 1).
pub const X_BITS: usize = fx::RTL_CLASS as usize + 1;

/// One of the SE's L and R serial multipliers (000 Fig. 7): y = A X + B, A and B serial
/// LSB first, X in parallel, one stage per bit of X (11). Each stage is a full adder of
/// the partial product a & x_j, its stage's sum and its carry, in carry-save form: the
/// sums move one stage down per clock and stage 0 emits a product bit; a serial adder adds
/// B. y_k is registered, one clock after a_k, b_k (000's pipeline of Lyon's design passes A
/// through the stages too and takes 11 clocks more; here A is broadcast to the 11 AND
/// gates). `first` (with bit 0) clears the carries, so the multiplier takes one attribute
/// after another with no gap.
///
/// Rounding: a serial incrementer turns y into round(y / 2^F) half up, `e`: `rnd` is high
/// in the clock `y` holds bit F - 1, whose value it loads as the carry; from the next clock
/// e_k = y_(F+k) XOR carry. Model: `model::se::mul::endpoint`.
#[derive(LogicBlock, Default)]
pub struct SerialMul {
    pub clock: Signal<In, Clock>,
    /// X: the column the line is evaluated at (XL_i or XR_i), unsigned.
    pub x: Signal<In, Bits<X_BITS>>,
    /// Bit k of A (two's complement; the low bits only matter modulo the stream length).
    pub a: Signal<In, Bit>,
    /// Bit k of B.
    pub b: Signal<In, Bit>,
    /// High with bit 0 of A and B: a new product starts.
    pub first: Signal<In, Bit>,
    /// High in the clock `y` holds bit F - 1: load the rounding carry.
    pub rnd: Signal<In, Bit>,
    /// Bit k of round(A X + B): bit F + k of A X + B (one clock after a_(F+k), b_(F+k))
    /// with the rounding carry added.
    pub e: Signal<Out, Bit>,
    /// Stage sums (stage j's sum moves to stage j - 1).
    s: DFF<Bits<X_BITS>>,
    /// Stage carries.
    c: DFF<Bits<X_BITS>>,
    /// Carry of the serial adder for B.
    cb: DFF<Bit>,
    /// Bit k of y = A X + B, one clock after a_k, b_k.
    yq: DFF<Bit>,
    /// The rounding incrementer's carry.
    cr: DFF<Bit>,
    /// a & X: this clock's partial product.
    pp: Signal<Local, Bits<X_BITS>>,
    /// Stage sums and carries as the adders see them (zero in a `first` clock).
    sin: Signal<Local, Bits<X_BITS>>,
    cin: Signal<Local, Bits<X_BITS>>,
    sum: Signal<Local, Bits<X_BITS>>,
    /// The product bit of this clock (stage 0's sum) and B's adder's carry in.
    p: Signal<Local, Bit>,
    cbin: Signal<Local, Bit>,
}

impl Logic for SerialMul {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s, c, cb, yq, cr);
        self.pp.next = 0.into();
        if self.a.val() {
            self.pp.next = self.x.val();
        }
        self.sin.next = self.s.q.val();
        self.cin.next = self.c.q.val();
        self.cbin.next = self.cb.q.val();
        if self.first.val() {
            self.sin.next = 0.into();
            self.cin.next = 0.into();
            self.cbin.next = false;
        }
        // One full adder per stage (carry-save), then shift the sums down a stage.
        self.sum.next = self.pp.val() ^ self.sin.val() ^ self.cin.val();
        self.c.d.next =
            (self.pp.val() & self.sin.val()) | (self.pp.val() & self.cin.val()) | (self.sin.val() & self.cin.val());
        self.s.d.next = self.sum.val() >> 1;
        self.p.next = self.sum.val().get_bit(0);
        // Serial adder: + B.
        self.yq.d.next = self.p.val() ^ self.b.val() ^ self.cbin.val();
        self.cb.d.next =
            (self.p.val() & self.b.val()) | (self.p.val() & self.cbin.val()) | (self.b.val() & self.cbin.val());
        // Rounding incrementer: carry := bit F-1, then e = y + carry, bit by bit.
        self.e.next = self.yq.q.val() ^ self.cr.q.val();
        self.cr.d.next = self.yq.q.val() & self.cr.q.val();
        if self.rnd.val() {
            self.cr.d.next = self.yq.q.val();
        }
    }
}
