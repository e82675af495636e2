//! `se_cmd`: the SE back end's span command unit (paper 000, Fig. 5), between the span FIFO
//! and the engines: each scanline span made into the lines f(X) = A X + B of z, R, G and B
//! that every shading engine (`rtl::se`) takes, and issued onto the span bus they share.
//! Model: `model::se_cmd` (the command and its timing), `model::cycles::se_frame`.
//!
//! ```text
//!   cycle t           t + 1 .. t + PIXEL              t + PIXEL + 1 ..
//!   span taken   ->   x0 A: one bit of x0 a cycle,  ->  command offered when the engines'
//!   (off screen:      four attributes side by side     gap since the last issue has
//!   dropped)          (`Attr`)                          passed; issued to all at once
//! ```
//!
//! A = the span's step, B = v0 - x0 A, from the end `span` walks from (xl, or xr when xl is
//! left of the screen), each at `SE_F` fraction bits in SE word LSBs, rounded half up
//! ([`Line`]). The gap: the engines' II after a span on another row, their latency after
//! one on the same row. `rd_y` and `wr_y` are the rows the engines read old z of (the last
//! span issued) and write (that span once its writes have begun, else the one before):
//! with a gap of at least the II, at most two spans are in the engines.

use super::links::SpanCmdSink;
use super::widths::{C_ACC, DC, DIM, DZ, FORMATS, PIXEL, SCREEN, SE, SE_CA, SE_F, SE_ZA, Z_ACC};
use crate::emit::{emit_unit, Emitted};
use crate::parts::{Negative, SignExtend};
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;

/// Bits of x0 A and of B before its rounding: a `PIXEL`-bit x0 times a step, and the start
/// value less it.
const PZ: usize = PIXEL + DZ + 1;
const PC: usize = PIXEL + DC + 1;
// `k` counts x0's bits in 5; the start values fit beside the products.
const _: () = assert!(PIXEL < 32 && Z_ACC < PZ && C_ACC < PC);
/// Fraction bits of the accumulators below an SE word's LSB.
const BELOW_Z: usize = (FORMATS.z_acc.frac - FORMATS.z.frac) as usize;
const BELOW_C: usize = FORMATS.c_acc.frac as usize;

/// `y` = the low `OUT` bits of x 2^F / 2^S rounded half up (`model::se_cmd`'s `to_frac`),
/// for an `IN`-bit two's complement x, in `W` bits (more than `IN`, at least S + `OUT`:
/// the bits read are exact modulo 2^W).
#[derive(LogicBlock, Blank)]
pub struct Line<const IN: usize, const W: usize, const OUT: usize> {
    pub x: Signal<In, Bits<IN>>,
    pub y: Signal<Out, Bits<OUT>>,
    widen: SignExtend<IN, W>,
    frac: Constant<Bits<8>>,
    half: Constant<Bits<W>>,
    s: Constant<Bits<8>>,
}

impl<const IN: usize, const W: usize, const OUT: usize> Line<IN, W, OUT> {
    fn new(s: usize) -> Self {
        assert!(W > IN && W >= s + OUT && s < 64, "Line<{IN}, {W}, {OUT}> from {s} fraction bits");
        Line {
            frac: Constant::new(SE_F.to_bits()),
            half: Constant::new(if s == 0 { 0u64 } else { 1u64 << (s - 1) }.to_bits()),
            s: Constant::new(s.to_bits()),
            ..Line::blank()
        }
    }
}

impl<const IN: usize, const W: usize, const OUT: usize> Logic for Line<IN, W, OUT> {
    #[hdl_gen]
    fn update(&mut self) {
        self.widen.x.next = self.x.val();
        self.y.next = bit_cast::<OUT, W>(((self.widen.y.val() << self.frac.val()) + self.half.val()) >> self.s.val());
    }
}

/// One attribute: its start value `V` and step `S` bits wide, x0 times the step formed a
/// bit of x0 a cycle in `P` bits (`run`: add the step shifted by the bits done when `bit`,
/// subtract it for x0's sign bit, `last`), and its A and B (`OUT` bits, from `below`
/// fraction bits below a word LSB; `WA` and `WB` the [`Line`]s' widths).
#[derive(LogicBlock, Blank)]
pub struct Attr<const V: usize, const S: usize, const P: usize, const OUT: usize, const WA: usize, const WB: usize> {
    pub clock: Signal<In, Clock>,
    /// Load `v0` and `step` (and clear the product).
    pub load: Signal<In, Bit>,
    pub v0: Signal<In, Bits<V>>,
    pub step: Signal<In, Bits<S>>,
    pub run: Signal<In, Bit>,
    pub x0_bit: Signal<In, Bit>,
    pub last: Signal<In, Bit>,
    pub a: Signal<Out, Bits<OUT>>,
    pub b: Signal<Out, Bits<OUT>>,
    v0_q: DFF<Bits<V>>,
    step_q: DFF<Bits<S>>,
    sh: DFF<Bits<P>>,
    acc: DFF<Bits<P>>,
    ext_step: SignExtend<S, P>,
    ext_v0: SignExtend<V, P>,
    #[given]
    line_a: Line<S, WA, OUT>,
    #[given]
    line_b: Line<P, WB, OUT>,
}

impl<const V: usize, const S: usize, const P: usize, const OUT: usize, const WA: usize, const WB: usize>
    Attr<V, S, P, OUT, WA, WB>
{
    fn new(below: usize) -> Self {
        Attr { ..Attr::blank(AttrGiven { line_a: Line::new(below), line_b: Line::new(below) }) }
    }
}

impl<const V: usize, const S: usize, const P: usize, const OUT: usize, const WA: usize, const WB: usize> Logic
    for Attr<V, S, P, OUT, WA, WB>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, v0_q, step_q, sh, acc);
        self.ext_step.x.next = self.step.val();
        self.ext_v0.x.next = self.v0_q.q.val();
        if self.load.val() {
            self.v0_q.d.next = self.v0.val();
            self.step_q.d.next = self.step.val();
            self.sh.d.next = self.ext_step.y.val();
            self.acc.d.next = 0.into();
        }
        if self.run.val() {
            self.sh.d.next = self.sh.q.val() << 1;
            if self.x0_bit.val() & self.last.val() {
                self.acc.d.next = self.acc.q.val() - self.sh.q.val();
            }
            if self.x0_bit.val() & !self.last.val() {
                self.acc.d.next = self.acc.q.val() + self.sh.q.val();
            }
        }
        self.line_a.x.next = self.step_q.q.val();
        self.line_b.x.next = self.ext_v0.y.val() - self.acc.q.val();
        self.a.next = self.line_a.y.val();
        self.b.next = self.line_b.y.val();
    }
}

/// z's and a colour's attribute.
type AttrZ = Attr<Z_ACC, DZ, PZ, SE_ZA, { DZ + SE_F + SE_ZA }, { PZ + SE_F + SE_ZA }>;
type AttrC = Attr<C_ACC, DC, PC, SE_CA, { DC + SE_F + SE_CA }, { PC + SE_F + SE_CA }>;

/// The span command unit: see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct SeCmd {
    pub clock: Signal<In, Clock>,
    /// Screen width (1 to 2^N): spans from it rightward are dropped, as those left of 0.
    pub width: Signal<In, Bits<DIM>>,
    /// The span commands (`model::edge_walk::SpanCmd`), from the span FIFO.
    pub inp: SpanCmdSink,
    /// The SE command, on the engines' port names, offered to all of them at once and
    /// taken with their `ready` (`out_ready`).
    pub out_valid: Signal<Out, Bit>,
    pub out_ready: Signal<In, Bit>,
    pub xl: Signal<Out, Bits<PIXEL>>,
    pub xr: Signal<Out, Bits<PIXEL>>,
    pub za: Signal<Out, Bits<SE_ZA>>,
    pub zb: Signal<Out, Bits<SE_ZA>>,
    pub ra: Signal<Out, Bits<SE_CA>>,
    pub rb: Signal<Out, Bits<SE_CA>>,
    pub ga: Signal<Out, Bits<SE_CA>>,
    pub gb: Signal<Out, Bits<SE_CA>>,
    pub ba: Signal<Out, Bits<SE_CA>>,
    pub bb: Signal<Out, Bits<SE_CA>>,
    /// The row of the engines' old-z reads and that of their writes.
    pub rd_y: Signal<Out, Bits<SCREEN>>,
    pub wr_y: Signal<Out, Bits<SCREEN>>,
    /// No span held.
    pub idle: Signal<Out, Bit>,
    /// The engines are done with every span issued: none was, or the last was issued their
    /// latency ago (its last write was in the cycle before).
    pub engines_idle: Signal<Out, Bit>,
    #[given]
    attr_z: AttrZ,
    #[given]
    attr_r: AttrC,
    #[given]
    attr_g: AttrC,
    #[given]
    attr_b: AttrC,
    /// A span held (its product being formed, or its command offered).
    busy: DFF<Bit>,
    /// Bits of x0 done, and x0 shifted right by them.
    k: DFF<Bits<5>>,
    x0s: DFF<Bits<PIXEL>>,
    y: DFF<Bits<SCREEN>>,
    cxl: DFF<Bits<PIXEL>>,
    cxr: DFF<Bits<PIXEL>>,
    /// A span has been issued; cycles since the last issue (saturating); its row and the
    /// row of the one before.
    started: DFF<Bit>,
    since: DFF<Bits<8>>,
    last_y: DFF<Bits<SCREEN>>,
    prev_y: DFF<Bits<SCREEN>>,
    xl_neg: Negative<PIXEL>,
    xr_neg: Negative<PIXEL>,
    /// `PIXEL`; the engines' II and latency, and the cycle their writes begin after an issue.
    pixel: Constant<Bits<5>>,
    ii: Constant<Bits<8>>,
    latency: Constant<Bits<8>>,
    writes: Constant<Bits<8>>,
    load: Signal<Local, Bit>,
    run: Signal<Local, Bit>,
    gap: Signal<Local, Bits<8>>,
    issue: Signal<Local, Bit>,
}

impl Default for SeCmd {
    fn default() -> Self {
        let latency = SE.latency() as usize;
        assert!(latency < 255, "the engines' latency {latency} fits `since`");
        let given = SeCmdGiven {
            attr_z: Attr::new(BELOW_Z),
            attr_r: Attr::new(BELOW_C),
            attr_g: Attr::new(BELOW_C),
            attr_b: Attr::new(BELOW_C),
        };
        SeCmd {
            pixel: Constant::new(PIXEL.to_bits()),
            ii: Constant::new((SE.ii() as usize).to_bits()),
            latency: Constant::new(latency.to_bits()),
            writes: Constant::new((latency - SE.p as usize / 4).to_bits()),
            ..SeCmd::blank(given)
        }
    }
}

impl Logic for SeCmd {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, busy, k, x0s, y, cxl, cxr, started, since, last_y, prev_y);
        clock!(self, clock, attr_z, attr_r, attr_g, attr_b);

        // Cycle t: a span taken when none is held; one off screen is dropped.
        self.xl_neg.x.next = self.inp.xl.val();
        self.xr_neg.x.next = self.inp.xr.val();
        self.inp.ready.next = !self.busy.q.val();
        self.load.next = self.inp.valid.val()
            & !self.busy.q.val()
            & !self.xr_neg.neg.val()
            & (self.xl_neg.neg.val() | (self.inp.xl.val() < bit_cast::<PIXEL, DIM>(self.width.val())));
        self.attr_z.v0.next = self.inp.left_z.val();
        self.attr_r.v0.next = self.inp.left_c0.val();
        self.attr_g.v0.next = self.inp.left_c1.val();
        self.attr_b.v0.next = self.inp.left_c2.val();
        if self.load.val() {
            self.x0s.d.next = self.inp.xl.val();
        }
        if self.xl_neg.neg.val() {
            self.attr_z.v0.next = self.inp.right_z.val();
            self.attr_r.v0.next = self.inp.right_c0.val();
            self.attr_g.v0.next = self.inp.right_c1.val();
            self.attr_b.v0.next = self.inp.right_c2.val();
            if self.load.val() {
                self.x0s.d.next = self.inp.xr.val();
            }
        }
        self.attr_z.step.next = self.inp.ddx_z.val();
        self.attr_r.step.next = self.inp.ddx_c0.val();
        self.attr_g.step.next = self.inp.ddx_c1.val();
        self.attr_b.step.next = self.inp.ddx_c2.val();
        if self.load.val() {
            self.busy.d.next = true;
            self.k.d.next = 0.into();
            self.y.d.next = self.inp.y.val();
            self.cxl.d.next = self.inp.xl.val();
            self.cxr.d.next = self.inp.xr.val();
        }

        // Cycles t + 1 .. t + PIXEL: x0 A, a bit of x0 a cycle (its sign bit last).
        self.run.next = self.busy.q.val() & (self.k.q.val() != self.pixel.val());
        if self.run.val() {
            self.k.d.next = self.k.q.val() + 1;
            self.x0s.d.next = self.x0s.q.val() >> 1;
        }
        self.attr_z.load.next = self.load.val();
        self.attr_z.run.next = self.run.val();
        self.attr_z.x0_bit.next = self.x0s.q.val().get_bit(0);
        self.attr_z.last.next = self.k.q.val() == (self.pixel.val() - 1);
        self.attr_r.load.next = self.load.val();
        self.attr_r.run.next = self.run.val();
        self.attr_r.x0_bit.next = self.x0s.q.val().get_bit(0);
        self.attr_r.last.next = self.k.q.val() == (self.pixel.val() - 1);
        self.attr_g.load.next = self.load.val();
        self.attr_g.run.next = self.run.val();
        self.attr_g.x0_bit.next = self.x0s.q.val().get_bit(0);
        self.attr_g.last.next = self.k.q.val() == (self.pixel.val() - 1);
        self.attr_b.load.next = self.load.val();
        self.attr_b.run.next = self.run.val();
        self.attr_b.x0_bit.next = self.x0s.q.val().get_bit(0);
        self.attr_b.last.next = self.k.q.val() == (self.pixel.val() - 1);

        // From t + PIXEL + 1: offered once the gap since the last issue has passed.
        self.gap.next = self.ii.val();
        if self.y.q.val() == self.last_y.q.val() {
            self.gap.next = self.latency.val();
        }
        self.out_valid.next = self.busy.q.val()
            & (self.k.q.val() == self.pixel.val())
            & (!self.started.q.val() | (self.since.q.val() >= self.gap.val()));
        self.xl.next = self.cxl.q.val();
        self.xr.next = self.cxr.q.val();
        self.za.next = self.attr_z.a.val();
        self.zb.next = self.attr_z.b.val();
        self.ra.next = self.attr_r.a.val();
        self.rb.next = self.attr_r.b.val();
        self.ga.next = self.attr_g.a.val();
        self.gb.next = self.attr_g.b.val();
        self.ba.next = self.attr_b.a.val();
        self.bb.next = self.attr_b.b.val();
        self.issue.next = self.out_valid.val() & self.out_ready.val();
        if self.since.q.val() != 255 {
            self.since.d.next = self.since.q.val() + 1;
        }
        if self.issue.val() {
            self.busy.d.next = false;
            self.started.d.next = true;
            self.since.d.next = 1.into();
            self.last_y.d.next = self.y.q.val();
            self.prev_y.d.next = self.last_y.q.val();
        }
        self.rd_y.next = self.last_y.q.val();
        self.wr_y.next = self.prev_y.q.val();
        if self.since.q.val() >= self.writes.val() {
            self.wr_y.next = self.last_y.q.val();
        }
        self.idle.next = !self.busy.q.val();
        self.engines_idle.next = !self.started.q.val() | (self.since.q.val() >= self.latency.val());
    }
}

crate::pins!(SeCmd {
    clock: clock,
    inputs: [width, out_ready],
    outputs: [out_valid, xl, xr, za, zb, ra, rb, ga, gb, ba, bb, rd_y, wr_y, idle, engines_idle],
    links: [inp],
});

/// `UNITS` entry: the span command unit of this build (widths from `crate::widths`).
pub fn emit_se_cmd(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("se_cmd", SeCmd::default(), params))
}
