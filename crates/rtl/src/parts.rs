//! Small combinational blocks the units share: sign tests, a rounding shift, its range
//! tests alone and bit concatenation; and [`defaults`], the arrays of signals, registers and blocks a unit's
//! constructor fills.
//!
//! The units keep signed quantities in plain `Bits<N>` (adds and subtracts wrap the same
//! either way, and rust-hdl simulates `Bits` fast), so the few places that need a sign use
//! [`Negative`] and [`SignedLess`]. Width-derived numbers (a sign bit's weight, a shift)
//! are `Constant`s here, because an `#[hdl_gen]` kernel cannot name a Rust constant.

use blank::Blank;
use rust_hdl::prelude::*;

/// `N` default values: an array of signals, registers or blocks as a unit starts.
pub fn defaults<T: Default, const N: usize>() -> [T; N] {
    std::array::from_fn(|_| T::default())
}

/// `neg` = `x < 0`, for an `N`-bit two's complement `x`.
#[derive(LogicBlock)]
pub struct Negative<const N: usize> {
    pub x: Signal<In, Bits<N>>,
    pub neg: Signal<Out, Bit>,
    /// 2^(N-1), the sign bit's weight.
    half: Constant<Bits<N>>,
}

impl<const N: usize> Default for Negative<N> {
    fn default() -> Self {
        Negative { x: Default::default(), neg: Default::default(), half: Constant::new(bits(1 << (N - 1))) }
    }
}

impl<const N: usize> Logic for Negative<N> {
    #[hdl_gen]
    fn update(&mut self) {
        self.neg.next = self.x.val() >= self.half.val();
    }
}

/// `lt` = `a < b`, for `N`-bit two's complement `a` and `b` (flipping both sign bits
/// turns the signed order into the unsigned one).
#[derive(LogicBlock, Blank)]
pub struct SignedLess<const N: usize> {
    pub a: Signal<In, Bits<N>>,
    pub b: Signal<In, Bits<N>>,
    pub lt: Signal<Out, Bit>,
    /// 2^(N-1), the sign bit's weight.
    half: Constant<Bits<N>>,
}

impl<const N: usize> Default for SignedLess<N> {
    fn default() -> Self {
        SignedLess { half: Constant::new(bits(1 << (N - 1))), ..SignedLess::blank() }
    }
}

impl<const N: usize> Logic for SignedLess<N> {
    #[hdl_gen]
    fn update(&mut self) {
        self.lt.next = (self.a.val() ^ self.half.val()) < (self.b.val() ^ self.half.val());
    }
}

/// `x` rounded half up from `S` fraction bits to none, for an `IN`-bit two's complement
/// `x`: `r = floor((x + 2^(S-1)) / 2^S)`, computed in `EXT = IN + 1` bits so that nothing
/// wraps (`fx::shr_half_up`). Outputs `neg` (r < 0), `over` (r >= 2^OUT) and the low `OUT`
/// bits of r, which are r itself when neither is set.
#[derive(LogicBlock, Blank)]
pub struct RoundShift<const IN: usize, const EXT: usize, const OUT: usize, const S: usize> {
    pub x: Signal<In, Bits<IN>>,
    pub neg: Signal<Out, Bit>,
    pub over: Signal<Out, Bit>,
    pub low: Signal<Out, Bits<OUT>>,
    x_neg: Negative<IN>,
    /// 2^IN: the sign extension bit, and the sign bit's weight in `EXT` bits.
    top: Constant<Bits<EXT>>,
    /// 2^(S-1): half of the result's LSB.
    half: Constant<Bits<EXT>>,
    shift: Constant<Bits<8>>,
    /// 2^OUT.
    limit: Constant<Bits<EXT>>,
    ext: Signal<Local, Bits<EXT>>,
    sum: Signal<Local, Bits<EXT>>,
    shifted: Signal<Local, Bits<EXT>>,
}

impl<const IN: usize, const EXT: usize, const OUT: usize, const S: usize> Default for RoundShift<IN, EXT, OUT, S> {
    fn default() -> Self {
        assert!(EXT == IN + 1 && S >= 1 && S + OUT < EXT && S < 256, "RoundShift<{IN}, {EXT}, {OUT}, {S}>");
        RoundShift {
            top: Constant::new(bits(1 << IN)),
            half: Constant::new(bits(1 << (S - 1))),
            shift: Constant::new(bits(S as u64)),
            limit: Constant::new(bits(1 << OUT)),
            ..RoundShift::blank()
        }
    }
}

impl<const IN: usize, const EXT: usize, const OUT: usize, const S: usize> Logic for RoundShift<IN, EXT, OUT, S> {
    #[hdl_gen]
    fn update(&mut self) {
        self.x_neg.x.next = self.x.val();
        self.ext.next = bit_cast::<EXT, IN>(self.x.val());
        if self.x_neg.neg.val() {
            self.ext.next = bit_cast::<EXT, IN>(self.x.val()) | self.top.val();
        }
        self.sum.next = self.ext.val() + self.half.val();
        self.neg.next = self.sum.val() >= self.top.val();
        self.shifted.next = self.sum.val() >> self.shift.val();
        self.over.next = !self.neg.val() & (self.shifted.val() >= self.limit.val());
        self.low.next = bit_cast::<OUT, EXT>(self.shifted.val());
    }
}

/// [`RoundShift`]'s range flags without its rounding: for r = `x` rounded half up from
/// `S` fraction bits (an `IN`-bit two's complement `x`), `neg` (r < 0) and `over`
/// (r >= 2^OUT). r < 0 exactly when x < -2^(S-1), and r >= 2^OUT exactly when
/// x >= 2^(S+OUT) - 2^(S-1): two comparisons of `x` with constants side by side, not an
/// addition and then a comparison. (`span` tests a command's end depths with it as it
/// takes the command: `raster_top`'s critical path at stop 59 ran through the rounding's
/// adder and then its comparison there.)
#[derive(LogicBlock, Blank)]
pub struct RoundRange<const IN: usize, const OUT: usize, const S: usize> {
    pub x: Signal<In, Bits<IN>>,
    pub neg: Signal<Out, Bit>,
    pub over: Signal<Out, Bit>,
    /// 2^(IN-1): flipping the sign bits turns the signed order into the unsigned one.
    flip: Constant<Bits<IN>>,
    /// -2^(S-1) and 2^(S+OUT) - 2^(S-1), their sign bits flipped; whether the second is
    /// below 2^(IN-1) (else no `x` rounds to 2^OUT or more).
    lo: Constant<Bits<IN>>,
    hi: Constant<Bits<IN>>,
    can_over: Constant<Bit>,
}

impl<const IN: usize, const OUT: usize, const S: usize> Default for RoundRange<IN, OUT, S> {
    fn default() -> Self {
        assert!(IN < 64 && S >= 1 && S + OUT <= IN, "RoundRange<{IN}, {OUT}, {S}>");
        let (flip, half, mask) = (1u64 << (IN - 1), 1u64 << (S - 1), (1u64 << IN) - 1);
        let hi = (1u64 << (S + OUT)) - half;
        RoundRange {
            flip: Constant::new(bits(flip)),
            lo: Constant::new(bits((half.wrapping_neg() & mask) ^ flip)),
            hi: Constant::new(bits((hi & mask) ^ flip)),
            can_over: Constant::new(hi < flip),
            ..RoundRange::blank()
        }
    }
}

impl<const IN: usize, const OUT: usize, const S: usize> Logic for RoundRange<IN, OUT, S> {
    #[hdl_gen]
    fn update(&mut self) {
        self.neg.next = (self.x.val() ^ self.flip.val()) < self.lo.val();
        self.over.next = self.can_over.val() & ((self.x.val() ^ self.flip.val()) >= self.hi.val());
    }
}

/// `out` = `{hi, lo}`: `hi` above the `LO` bits of `lo`, `W = HI + LO` bits.
#[derive(LogicBlock, Blank)]
pub struct Concat<const HI: usize, const LO: usize, const W: usize> {
    pub hi: Signal<In, Bits<HI>>,
    pub lo: Signal<In, Bits<LO>>,
    pub out: Signal<Out, Bits<W>>,
    shift: Constant<Bits<8>>,
}

impl<const HI: usize, const LO: usize, const W: usize> Default for Concat<HI, LO, W> {
    fn default() -> Self {
        assert!(W == HI + LO && LO < 256, "Concat<{HI}, {LO}, {W}>");
        Concat { shift: Constant::new(bits(LO as u64)), ..Concat::blank() }
    }
}

impl<const HI: usize, const LO: usize, const W: usize> Logic for Concat<HI, LO, W> {
    #[hdl_gen]
    fn update(&mut self) {
        self.out.next = (bit_cast::<W, HI>(self.hi.val()) << self.shift.val()) | bit_cast::<W, LO>(self.lo.val());
    }
}

/// `y` = `x` sign-extended from `IN` to `OUT` bits (`OUT > IN`): a kernel cannot `bit_cast`
/// an array element indexed by a loop's variable, so an array of these does it.
#[derive(LogicBlock, Blank)]
pub struct SignExtend<const IN: usize, const OUT: usize> {
    pub x: Signal<In, Bits<IN>>,
    pub y: Signal<Out, Bits<OUT>>,
    msb: Constant<Bits<8>>,
    /// Ones above the low `IN` bits.
    ext: Constant<Bits<OUT>>,
}

impl<const IN: usize, const OUT: usize> Default for SignExtend<IN, OUT> {
    fn default() -> Self {
        assert!(IN < OUT, "SignExtend<{IN}, {OUT}>: widens");
        SignExtend {
            msb: Constant::new((IN - 1).to_bits()),
            ext: Constant::new(!Bits::<OUT>::default() << (IN as u64)),
            ..SignExtend::blank()
        }
    }
}

impl<const IN: usize, const OUT: usize> Logic for SignExtend<IN, OUT> {
    #[hdl_gen]
    fn update(&mut self) {
        self.y.next = bit_cast::<OUT, IN>(self.x.val());
        if self.x.val().get_bit(self.msb.val().index()) {
            self.y.next = bit_cast::<OUT, IN>(self.x.val()) | self.ext.val();
        }
    }
}

/// `q` = `d` of `n` enabled cycles before (`en` high: every stage moves on; low: all hold):
/// a shift register of `n` `W`-bit stages, `n` >= 1 (`DelayLine::new`).
#[derive(LogicBlock, Blank)]
pub struct DelayLine<const W: usize> {
    pub clock: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    pub d: Signal<In, Bits<W>>,
    pub q: Signal<Out, Bits<W>>,
    stages: Vec<DFF<Bits<W>>>,
    _n: usize,
}

impl<const W: usize> DelayLine<W> {
    pub fn new(n: usize) -> Self {
        assert!(n >= 1, "DelayLine of {n} stages");
        DelayLine { stages: (0..n).map(|_| Default::default()).collect(), _n: n, ..DelayLine::blank() }
    }
}

impl<const W: usize> Logic for DelayLine<W> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..self._n {
            self.stages[i].clock.next = self.clock.val();
            self.stages[i].d.next = self.stages[i].q.val();
        }
        if self.en.val() {
            self.stages[0].d.next = self.d.val();
            for i in 1..self._n {
                self.stages[i].d.next = self.stages[i - 1].q.val();
            }
        }
        // The last stage, by a loop of one iteration (array indices from loop variables).
        for i in (self._n - 1)..self._n {
            self.q.next = self.stages[i].q.val();
        }
    }
}
