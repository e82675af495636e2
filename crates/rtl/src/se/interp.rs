//! The bit-serial midpoint-subdivision interpolator of paper 000, Figs. 8 and 9.
//! Model: `model::se::interp`.
//!
//! Streams, one bit per clock, LSB first, stream clock s = 0, 1, ...:
//!
//! ```text
//!   s        0      1 .. n       n+1 .. n+K     K+1 .. K+n
//!   ends     half   e bits 0..n-1  MSB again     -
//!   px       -      -            -              bit s-K-1 of every pixel's round(f(x))
//! ```
//!
//! **Aligned points.** Point x of level L carries V_x = 2^L (2 f(x) + 1), bit i at stream
//! clock i: the ends carry 2 e + 1 (the half first), and the sum of a point's parents,
//! each brought to scale 2^(L-1) by delaying it (one clock = times 2), is V_x exactly:
//! halving costs no bit (000: "no truncation error"). A_L is every point of levels <= L,
//! each delayed to level-L scale (point x delayed L - level(x) clocks); level L + 1 takes
//! both parents from A_L, so one register per level and bit (A_L delayed a clock) makes
//! all the delays. A_K aligns all pixels: bit K + 1 + k of V_x / 2^level(x), i.e. bit k of
//! floor(f(x) + 1/2) = round(f(x)), at clock K + 1 + k for every x.
//!
//! **Fig. 9, sign extension.** From s = n + 1 each end repeats its MSB, for the K clocks
//! the deepest level still adds.

use crate::parts::defaults;
use blank::Blank;
use rust_hdl::prelude::*;

/// The adders of one level L of the subdivision tree: the points x = (2k+1) P / 2^L, each
/// the serial sum of its neighbours x -+ P / 2^L in A_(L-1) (point P, the right end, comes
/// on `e1`, already delayed to scale). A full adder and a carry per point, in parallel.
#[derive(LogicBlock, Blank)]
pub struct Level<const P: usize> {
    pub clock: Signal<In, Clock>,
    /// A_(L-1): the streams of the points of levels < L, aligned to scale 2^(L-1).
    pub pts: Signal<In, Bits<P>>,
    /// The right end's stream, aligned to scale 2^(L-1).
    pub e1: Signal<In, Bit>,
    /// Stream clock 0: the carries start from 0.
    pub first: Signal<In, Bit>,
    /// The new points' streams (bits of this level's points; 0 elsewhere).
    pub n: Signal<Out, Bits<P>>,
    /// This level's points.
    lm: Constant<Bits<P>>,
    /// The distance to the neighbours, P / 2^L.
    sh: Constant<Bits<16>>,
    /// The point whose right neighbour is the right end, P - P / 2^L.
    top: Constant<Bits<P>>,
    /// Left and right neighbour of each point, and the carries in.
    lt: Signal<Local, Bits<P>>,
    rt: Signal<Local, Bits<P>>,
    cin: Signal<Local, Bits<P>>,
    c: DFF<Bits<P>>,
}

impl<const P: usize> Level<P> {
    /// Level `l` (1 ..= log2 P).
    pub fn new(l: usize) -> Self {
        let s = P >> l;
        let mut lm = Bits::<P>::default();
        for x in (s..P).step_by(2 * s) {
            lm = lm.replace_bit(x, true);
        }
        Self {
            lm: Constant::new(lm),
            sh: Constant::new((s as u64).into()),
            top: Constant::new(Bits::<P>::default().replace_bit(P - s, true)),
            ..Self::blank()
        }
    }
}

impl<const P: usize> Logic for Level<P> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, c);
        self.lt.next = (self.pts.val() << self.sh.val()) & self.lm.val();
        self.rt.next = (self.pts.val() >> self.sh.val()) & self.lm.val();
        if self.e1.val() {
            self.rt.next = ((self.pts.val() >> self.sh.val()) & self.lm.val()) | self.top.val();
        }
        self.cin.next = self.c.q.val();
        if self.first.val() {
            self.cin.next = 0.into();
        }
        self.n.next = self.lt.val() ^ self.rt.val() ^ self.cin.val();
        self.c.d.next =
            (self.lt.val() & self.rt.val()) | (self.lt.val() & self.cin.val()) | (self.rt.val() & self.cin.val());
    }
}

/// The interpolator for P pixels, K = log2 P levels (000 Fig. 8 for 9 points, here P + 1):
/// ends `e0` = f(XL_i) and `e1` = f(XR_i) in, every pixel's round(f(x)) out, all serial.
#[derive(LogicBlock, Blank)]
pub struct Interp<const P: usize, const K: usize> {
    pub clock: Signal<In, Clock>,
    /// Bit of f(XL_i) (rounded), from the L multiplier.
    pub e0: Signal<In, Bit>,
    /// Bit of f(XR_i) (rounded), from the R multiplier.
    pub e1: Signal<In, Bit>,
    /// Stream clock 0: both ends carry the half (1); every adder starts from carry 0.
    pub half: Signal<In, Bit>,
    /// Past the ends' MSB: repeat it (Fig. 9).
    pub ext: Signal<In, Bit>,
    /// Bit x: pixel x's stream, aligned (bit k of round(f(x)) at stream clock K + 1 + k).
    pub px: Signal<Out, Bits<P>>,
    /// Each end as it enters, after the half and the sign extension.
    in0: Signal<Local, Bit>,
    in1: Signal<Local, Bit>,
    /// Fig. 9: each end's last bit before the extension.
    msb0: DFF<Bit>,
    msb1: DFF<Bit>,
    /// The right end delayed: bit d - 1 = d clocks ago (0 before the stream began).
    e1d: DFF<Bits<K>>,
    /// A_0: the left end, at bit 0.
    a0: Signal<Local, Bits<P>>,
    /// A_1 .. A_K (index L - 1).
    a: [Signal<Local, Bits<P>>; K],
    /// A_0 .. A_(K-1) delayed a clock (index L - 1 holds A_(L-1)).
    d: [DFF<Bits<P>>; K],
    /// A_0 .. A_(K-1) delayed, zero in stream clock 0 (the previous stream's tail).
    dm: [Signal<Local, Bits<P>>; K],
    /// Levels 1 .. K (index L - 1).
    #[given]
    lv: [Level<P>; K],
}

impl<const P: usize, const K: usize> Default for Interp<P, K> {
    fn default() -> Self {
        assert_eq!(1 << K, P, "K = log2 P");
        Self {
            a: defaults(),
            d: defaults(),
            dm: defaults(),
            ..Self::blank(InterpGiven { lv: std::array::from_fn(|l| Level::new(l + 1)) })
        }
    }
}

impl<const P: usize, const K: usize> Logic for Interp<P, K> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, msb0, msb1, e1d);
        for l in 0..K {
            self.d[l].clock.next = self.clock.val();
            self.lv[l].clock.next = self.clock.val();
            self.lv[l].first.next = self.half.val();
            self.dm[l].next = self.d[l].q.val();
            if self.half.val() {
                self.dm[l].next = 0.into();
            }
        }
        // The ends: the half first, then the bits, then (Fig. 9) the MSB again.
        self.in0.next = self.e0.val();
        self.in1.next = self.e1.val();
        if self.ext.val() {
            self.in0.next = self.msb0.q.val();
            self.in1.next = self.msb1.q.val();
        }
        if self.half.val() {
            self.in0.next = true;
            self.in1.next = true;
        }
        self.msb0.d.next = self.in0.val();
        self.msb1.d.next = self.in1.val();
        self.e1d.d.next = self.e1d.q.val() << 1;
        if self.in1.val() {
            self.e1d.d.next = (self.e1d.q.val() << 1) | 1;
        }
        if self.half.val() {
            // A new stream: only its half (1) goes in; the older bits were the last one's.
            self.e1d.d.next = 1.into();
        }
        self.a0.next = 0.into();
        if self.in0.val() {
            self.a0.next = 1.into();
        }
        // Level 1: the midpoint of the ends, both undelayed.
        self.lv[0].pts.next = self.a0.val();
        self.lv[0].e1.next = self.in1.val();
        self.d[0].d.next = self.a0.val();
        self.a[0].next = self.dm[0].val() | self.lv[0].n.val();
        // Level L = l + 1 from A_l; the right end delayed l clocks.
        for l in 1..K {
            self.lv[l].pts.next = self.a[l - 1].val();
            self.lv[l].e1.next = self.e1d.q.val().get_bit(l - 1) & !self.half.val();
            self.d[l].d.next = self.a[l - 1].val();
            self.a[l].next = self.dm[l].val() | self.lv[l].n.val();
        }
        // A_K (an index may name only loop variables: rust-hdl evaluates it per unrolled loop).
        for l in (K - 1)..K {
            self.px.next = self.a[l].val();
        }
    }
}
