//! The span command FIFO between `edge_walk` and `span` in `raster_top` (papers 001 and
//! 003): [`SPAN_FIFO`] `SpanCmd`s, as `model::cycles::Timing::span_fifo`. Its output is
//! always its head register: a command pushed into an empty FIFO is offered the cycle
//! after (no pass-through: raster_top's critical path at stop 62 ran from the
//! pass-through's select across its fifteen fields into span's tests of the command,
//! 12.5 ns). Part of `raster_top` (its model is the cycle model's FIFO).

use super::links::{SpanCmdSink, SpanCmdSource};
use super::widths::{C_ACC, DC, DZ, PIXEL, SCREEN, Z_ACC};
use crate::parts::defaults;
use blank::Blank;
use rust_hdl::prelude::*;

/// Span commands the FIFO between the edge walk and span holds.
pub const SPAN_FIFO: usize = 4;
/// Bits of the FIFO's ring pointers, which wrap by themselves: [`SPAN_FIFO`] is 2^POINTER.
const POINTER: usize = 2;
const _: () = assert!(SPAN_FIFO == 1 << POINTER, "the span FIFO's pointers wrap at 2^POINTER entries");

/// One field of a `D`-deep FIFO held as a ring: entry `wr` is written while `we` is high,
/// and `head` is entry `rd`, held in a register of its own. The entries' write enables
/// come from the FIFO's input side and its registered pointer only, never from the
/// output's handshake (on ECP5 that handshake spread to every entry's load enable was
/// raster_top's critical path: span's accept, then one 17 ns net across the die); the head
/// register is loaded from the input (`take_din`) or from entry `rd + 1` (`take_next`), so
/// that the FIFO's output is a register and not the ring's multiplexer on the read pointer
/// (raster_top's critical path at stop 56: that pointer, the multiplexer, then span's
/// accumulators, 14.6 ns).
#[derive(LogicBlock, Blank)]
pub struct FifoLane<const W: usize, const D: usize> {
    pub clock: Signal<In, Clock>,
    pub we: Signal<In, Bit>,
    pub wr: Signal<In, Bits<POINTER>>,
    pub rd: Signal<In, Bits<POINTER>>,
    /// The head becomes the input: the FIFO empty, or its one entry leaving.
    pub take_din: Signal<In, Bit>,
    /// The head becomes entry `rd + 1`: the head leaving, entries behind it.
    pub take_next: Signal<In, Bit>,
    pub din: Signal<In, Bits<W>>,
    pub head: Signal<Out, Bits<W>>,
    e: [DFF<Bits<W>>; D],
    h: DFF<Bits<W>>,
    /// `rd + 1`, wrapping.
    behind: Signal<Local, Bits<POINTER>>,
}

impl<const W: usize, const D: usize> Default for FifoLane<W, D> {
    fn default() -> Self {
        FifoLane { e: defaults(), ..FifoLane::blank() }
    }
}

impl<const W: usize, const D: usize> Logic for FifoLane<W, D> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..D {
            self.e[i].clock.next = self.clock.val();
            self.e[i].d.next = self.e[i].q.val();
            if (self.wr.val().index() == i) & self.we.val() {
                self.e[i].d.next = self.din.val();
            }
        }
        self.behind.next = self.rd.val() + 1;
        self.h.clock.next = self.clock.val();
        self.h.d.next = self.h.q.val();
        if self.take_next.val() {
            self.h.d.next = self.e[0].q.val();
            for i in 1..D {
                if self.behind.val().index() == i {
                    self.h.d.next = self.e[i].q.val();
                }
            }
        }
        if self.take_din.val() {
            self.h.d.next = self.din.val();
        }
        self.head.next = self.h.q.val();
    }
}

/// The span command FIFO between the edge walk and span (`model::cycles`: "a 4-deep FIFO
/// before it"): `SpanCmd` on the links `inp` and `out`. A command pushed in cycle t is
/// offered from cycle t + 1, from the head register; `inp.ready` is low only when full.
#[derive(LogicBlock, Blank)]
pub struct SpanFifo {
    pub clock: Signal<In, Clock>,
    /// The commands in; `inp.ready` low only when full.
    pub inp: SpanCmdSink,
    /// The commands out: the head register.
    pub out: SpanCmdSource,
    /// No command held.
    pub empty: Signal<Out, Bit>,
    /// Entries held, and whether that is all, some or one: the flags are registers of
    /// their own, set from the count's next value, so that the output's multiplexer and the
    /// handshakes start at a register and not at a comparison of the count (raster_top's
    /// critical path at stop 62: the count's comparison with 0 into the multiplexer, then
    /// span's tests of the command, 12.5 ns).
    count: DFF<Bits<3>>,
    full: DFF<Bit>,
    held: DFF<Bit>,
    one: DFF<Bit>,
    count_next: Signal<Local, Bits<3>>,
    /// [`SPAN_FIFO`], for `full`.
    depth: Constant<Bits<3>>,
    /// The entry the next push writes, and the head's: [`POINTER`] bits, wrapping.
    wr: DFF<Bits<POINTER>>,
    rd: DFF<Bits<POINTER>>,
    y: FifoLane<SCREEN, SPAN_FIFO>,
    xl: FifoLane<PIXEL, SPAN_FIFO>,
    xr: FifoLane<PIXEL, SPAN_FIFO>,
    left_z: FifoLane<Z_ACC, SPAN_FIFO>,
    left_c0: FifoLane<C_ACC, SPAN_FIFO>,
    left_c1: FifoLane<C_ACC, SPAN_FIFO>,
    left_c2: FifoLane<C_ACC, SPAN_FIFO>,
    right_z: FifoLane<Z_ACC, SPAN_FIFO>,
    right_c0: FifoLane<C_ACC, SPAN_FIFO>,
    right_c1: FifoLane<C_ACC, SPAN_FIFO>,
    right_c2: FifoLane<C_ACC, SPAN_FIFO>,
    ddx_z: FifoLane<DZ, SPAN_FIFO>,
    ddx_c0: FifoLane<DC, SPAN_FIFO>,
    ddx_c1: FifoLane<DC, SPAN_FIFO>,
    ddx_c2: FifoLane<DC, SPAN_FIFO>,
    /// Entry `wr` is written: the input offered and room for it.
    push: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    take_din: Signal<Local, Bit>,
    take_next: Signal<Local, Bit>,
}

impl Default for SpanFifo {
    fn default() -> Self {
        SpanFifo { depth: Constant::new(bits(SPAN_FIFO as u64)), ..SpanFifo::blank() }
    }
}

/// `SpanFifo`'s kernel, with lane `$f` holding field `$f` of the span command (each field
/// of `links::SpanCmdSink`): out goes its head. (A macro writes the fifteen lanes out
/// before `#[hdl_gen]` reads the kernel.)
macro_rules! span_fifo_logic {
    ($($f:ident),* $(,)?) => {
        impl Logic for SpanFifo {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, count, full, held, one, wr, rd);
                self.inp.ready.next = !self.full.q.val();
                self.out.valid.next = self.held.q.val();
                self.empty.next = !self.held.q.val();
                self.push.next = self.inp.valid.val() & !self.full.q.val();
                self.pop.next = self.held.q.val() & self.out.ready.val();
                // The head register: the input while empty or as the one entry leaves (the
                // input is then the entry behind it, if any), else entry `rd + 1` as the
                // head leaves.
                self.take_din.next = !self.held.q.val() | (self.one.q.val() & self.out.ready.val());
                self.take_next.next = self.pop.val() & !self.one.q.val();
                if self.push.val() {
                    self.wr.d.next = self.wr.q.val() + 1;
                }
                if self.pop.val() {
                    self.rd.d.next = self.rd.q.val() + 1;
                }
                self.count_next.next = self.count.q.val();
                if self.push.val() & !self.pop.val() {
                    self.count_next.next = self.count.q.val() + 1;
                }
                if self.pop.val() & !self.push.val() {
                    self.count_next.next = self.count.q.val() - 1;
                }
                self.count.d.next = self.count_next.val();
                self.full.d.next = self.count_next.val() == self.depth.val();
                self.held.d.next = self.count_next.val() != 0;
                self.one.d.next = self.count_next.val() == 1;
                $(
                    self.$f.clock.next = self.clock.val();
                    self.$f.we.next = self.push.val();
                    self.$f.wr.next = self.wr.q.val();
                    self.$f.rd.next = self.rd.q.val();
                    self.$f.take_din.next = self.take_din.val();
                    self.$f.take_next.next = self.take_next.val();
                    self.$f.din.next = self.inp.$f.val();
                    self.out.$f.next = self.$f.head.val();
                )*
            }
        }
    };
}

span_fifo_logic!(
    y, xl, xr, left_z, left_c0, left_c1, left_c2, right_z, right_c0, right_c1, right_c2, ddx_z, ddx_c0, ddx_c1, ddx_c2,
);
