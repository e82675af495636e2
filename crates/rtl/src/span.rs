//! `span`: span processing of paper 001 (Woo 2004, §II.2) with the X and Z clipping of
//! paper 003 (Lee 2008, §II.1.다.(3), Fig. 6), one pixel per cycle.
//!
//! It takes span commands (`model::edge_walk::SpanCmd`, on the link `inp`) and sends
//! pixels (`model::span::Pixel`, on the link `out`: `links::PixelSource`, ports `out$*`), both
//! on valid/ready streams:
//!
//! * X clipping (003): a span wholly left or right of the screen is dropped; one that
//!   starts left of the screen is walked right to left from its last pixel and stops at
//!   column 0; any other left to right from its first pixel, stopping at the last column
//!   or its end. Pixels right of the screen met walking left take their cycle unsent.
//! * Z clipping (003): a span whose two ends lie beyond the same z boundary is dropped;
//!   otherwise each pixel's depth is checked against [0, z_max] and a pixel outside takes
//!   its cycle unsent.
//! * Each pixel: depth `z_acc` rounded half up to the depth buffer's bits, colour `c_acc`
//!   rounded half up to an integer and clamped to [0, 255] (`model::span::{depth_of,
//!   color_of}`).
//!
//! ```text
//!   xl >= 0:       xl -> -> -> min(xr, W-1)        (stops at the last column)
//!   xl <  0:  0 <- <- <- xr                        (stops at column 0)
//!            |<------ screen ------>|
//! ```
//!
//! Timing (`model::span::{LATENCY, II}` = 2, 1): a command taken in cycle t starts its
//! walk in cycle t + 1, a pixel (sent or not) per cycle; each pixel walked goes into the
//! pixel register, which drives `out$*`, so the first pixel is presented in cycle t + 2
//! and one pixel per cycle after that (003 Table 1 has span at 1 cycle: the register
//! keeps the depth's and colours' rounding and the clip tests off the handshake's path,
//! for the clock). The walk moves on while the pixel register is empty or its pixel is
//! being taken, so a pixel held while `out$ready` is low holds the walk. The next command
//! is taken in the walk's last cycle, so pixels follow each other without a gap. A dropped
//! span takes one cycle.
//!
//! ```text
//!   cycle     t          t + 1             t + 2          ...
//!   command   taken      walk: x, z, c     walk: x+1 ...
//!   pixel                                  register: x -> out$*
//! ```
//!
//! Model: `model::span::span`. Emitted: `hdl-out/span.v`.

use super::links::{PixelSource, SpanCmdSink};
use super::widths::{CHANNEL, C_ACC, DC, DEPTH, DIM, DZ, FORMATS, PIXEL, SCREEN, Z_ACC};
use crate::emit::{emit_unit, Emitted};
use crate::parts::{Negative, RoundRange, RoundShift, SignedLess};
use crate::switch::{Parts, Switch};
use crate::Params;
use rust_hdl::prelude::*;

/// Bits the depth loses from the z accumulator: `z_acc.frac - z.frac`.
const Z_SHIFT: usize = (FORMATS.z_acc.frac - FORMATS.z.frac) as usize;
/// Bits a colour loses from its accumulator, down to an integer: `c_acc.frac`.
const C_SHIFT: usize = FORMATS.c_acc.frac as usize;

/// `model::span::depth_of`: a z accumulator rounded half up to the depth buffer's bits;
/// `neg` and `over` flag depths below 0 and above z_max = 2^DEPTH - 1.
pub type DepthOf = RoundShift<Z_ACC, { Z_ACC + 1 }, DEPTH, Z_SHIFT>;
/// [`DepthOf`]'s `neg` and `over` alone, for a command's end depths (only their range
/// decides the z drop, 003).
pub type DepthRange = RoundRange<Z_ACC, DEPTH, Z_SHIFT>;
/// `model::span::color_of` before its clamp: a colour accumulator rounded half up to an
/// integer; `neg` and `over` flag values below 0 and above 255.
pub type ColorOf = RoundShift<C_ACC, { C_ACC + 1 }, CHANNEL, C_SHIFT>;

/// The span unit: see the module documentation.
#[derive(LogicBlock, Default)]
pub struct Span {
    pub clock: Signal<In, Clock>,
    /// Screen width in pixels, 1 to 2^SCREEN.
    pub width: Signal<In, Bits<DIM>>,
    /// Span commands; `inp.ready` high when idle or in the last pixel of a span (as it leaves).
    pub inp: SpanCmdSink,
    /// A pixel on screen with its depth in [0, z_max].
    pub out: PixelSource,
    /// No span in progress (for `raster_top`'s frame-done).
    pub idle: Signal<Out, Bit>,
    /// X and Z clipping present (`CLIP_X`, `CLIP_Z`, `crate::switch`). Without X clipping
    /// every span is walked left to right from xl to xr and the screen's columns are not
    /// checked; without Z clipping no depth is checked.
    clip_x: Switch,
    clip_z: Switch,
    /// A span is in progress; `drop` marks the one cycle of a dropped span.
    busy: DFF<Bit>,
    drop: DFF<Bit>,
    /// Walking right to left.
    left: DFF<Bit>,
    /// The pixel presented and the last one of the walk.
    x: DFF<Bits<PIXEL>>,
    last: DFF<Bits<PIXEL>>,
    /// `x == last`, kept as a register (set with the command, then from the next pixel's
    /// position) so that the handshake with the span FIFO does not start with that
    /// comparison (raster_top's critical path at stop 61: `x` through the comparison and
    /// `drop` into the FIFO's head registers, 13.0 ns). The walk's last cycle is `drop` or
    /// this.
    at_last: DFF<Bit>,
    /// The walk's next pixel, `x - 1` walking left, else `x + 1`.
    x_next: Signal<Local, Bits<PIXEL>>,
    /// The command's first and last pixels, as `x` and `last` take them, and whether they
    /// are one: `xr == 0` walking left; walking right `xl == xr` with xr on the screen, or
    /// `xl == W - 1` with it beyond (side by side rather than comparing the two
    /// multiplexers' outputs: raster_top's critical path at stop 62 ran through them,
    /// 12.5 ns).
    x_first: Signal<Local, Bits<PIXEL>>,
    x_last: Signal<Local, Bits<PIXEL>>,
    one_pixel: Signal<Local, Bit>,
    /// xr beyond the screen's last column (with X clipping), and that column, W - 1.
    xr_off: Signal<Local, Bit>,
    last_column: Signal<Local, Bits<PIXEL>>,
    /// The command is dropped, as `drop` takes it.
    dropped: Signal<Local, Bit>,
    /// The walk's last cycle: `drop` or `at_last`.
    ends: Signal<Local, Bit>,
    y: DFF<Bits<SCREEN>>,
    /// Attributes at pixel x.
    a_z: DFF<Bits<Z_ACC>>,
    a_c0: DFF<Bits<C_ACC>>,
    a_c1: DFF<Bits<C_ACC>>,
    a_c2: DFF<Bits<C_ACC>>,
    /// Per-pixel steps, cut to the accumulators' widths (only those bits reach them).
    d_z: DFF<Bits<Z_ACC>>,
    d_c0: DFF<Bits<C_ACC>>,
    d_c1: DFF<Bits<C_ACC>>,
    d_c2: DFF<Bits<C_ACC>>,
    /// The command's end depths (for the z drop) and the signs of its ends.
    zl: DepthRange,
    zr: DepthRange,
    xl_neg: Negative<PIXEL>,
    xr_neg: Negative<PIXEL>,
    /// The pixel's depth and colour.
    zp: DepthOf,
    c0: ColorOf,
    c1: ColorOf,
    c2: ColorOf,
    /// xl <= W - 1, i.e. xl < W (signed).
    xl_on: SignedLess<PIXEL>,
    width_x: Signal<Local, Bits<PIXEL>>,
    /// The walk's pixel is sent (on screen, in the depth range), and its colour clamped.
    valid: Signal<Local, Bit>,
    rgb0: Signal<Local, Bits<CHANNEL>>,
    rgb1: Signal<Local, Bits<CHANNEL>>,
    rgb2: Signal<Local, Bits<CHANNEL>>,
    /// The pixel register: the walk's last pixel, rounded and clamped, while `out$valid`.
    o_valid: DFF<Bit>,
    o_x: DFF<Bits<SCREEN>>,
    o_y: DFF<Bits<SCREEN>>,
    o_z: DFF<Bits<DEPTH>>,
    o_rgb0: DFF<Bits<CHANNEL>>,
    o_rgb1: DFF<Bits<CHANNEL>>,
    o_rgb2: DFF<Bits<CHANNEL>>,
    advance: Signal<Local, Bit>,
    ready: Signal<Local, Bit>,
    accept: Signal<Local, Bit>,
}

impl Logic for Span {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, busy, drop, left, x, last, at_last, y, a_z, a_c0, a_c1, a_c2, d_z, d_c0, d_c1, d_c2, o_valid,
            o_x, o_y, o_z, o_rgb0, o_rgb1, o_rgb2
        );

        // The walk's pixel: sent or not, its depth and colour.
        self.width_x.next = bit_cast::<PIXEL, DIM>(self.width.val());
        self.zp.x.next = self.a_z.q.val();
        self.c0.x.next = self.a_c0.q.val();
        self.c1.x.next = self.a_c1.q.val();
        self.c2.x.next = self.a_c2.q.val();
        self.valid.next = self.busy.q.val() & !self.drop.q.val();
        if self.clip_x.on.val() & (self.x.q.val() >= self.width_x.val()) {
            self.valid.next = false;
        }
        if self.clip_z.on.val() & (self.zp.neg.val() | self.zp.over.val()) {
            self.valid.next = false;
        }
        self.rgb0.next = self.c0.low.val();
        if self.c0.over.val() {
            self.rgb0.next = 255.into();
        }
        if self.c0.neg.val() {
            self.rgb0.next = 0.into();
        }
        self.rgb1.next = self.c1.low.val();
        if self.c1.over.val() {
            self.rgb1.next = 255.into();
        }
        if self.c1.neg.val() {
            self.rgb1.next = 0.into();
        }
        self.rgb2.next = self.c2.low.val();
        if self.c2.over.val() {
            self.rgb2.next = 255.into();
        }
        if self.c2.neg.val() {
            self.rgb2.next = 0.into();
        }

        // The pixel register drives the output.
        self.out.valid.next = self.o_valid.q.val();
        self.out.x.next = self.o_x.q.val();
        self.out.y.next = self.o_y.q.val();
        self.out.z.next = self.o_z.q.val();
        self.out.rgb0.next = self.o_rgb0.q.val();
        self.out.rgb1.next = self.o_rgb1.q.val();
        self.out.rgb2.next = self.o_rgb2.q.val();
        self.idle.next = !self.busy.q.val() & !self.o_valid.q.val();

        self.x_next.next = self.x.q.val() + 1;
        if self.left.q.val() {
            self.x_next.next = self.x.q.val() - 1;
        }

        // Handshakes: the walk moves on while the pixel register is empty or its pixel is
        // being taken (whether the walk's pixel is sent or not: that is not on this path);
        // a command is taken when idle or in the walk's last cycle.
        self.advance.next = self.busy.q.val() & (!self.o_valid.q.val() | self.out.ready.val());
        self.ends.next = self.drop.q.val() | self.at_last.q.val();
        self.ready.next = !self.busy.q.val() | (self.ends.val() & self.advance.val());
        self.inp.ready.next = self.ready.val();
        self.accept.next = self.inp.valid.val() & self.ready.val();
        if self.out.ready.val() {
            self.o_valid.d.next = false;
        }
        if self.advance.val() {
            self.o_valid.d.next = self.valid.val();
            self.o_x.d.next = bit_cast::<SCREEN, PIXEL>(self.x.q.val());
            self.o_y.d.next = self.y.q.val();
            self.o_z.d.next = self.zp.low.val();
            self.o_rgb0.d.next = self.rgb0.val();
            self.o_rgb1.d.next = self.rgb1.val();
            self.o_rgb2.d.next = self.rgb2.val();
            if self.ends.val() {
                self.busy.d.next = false;
            } else {
                self.x.d.next = self.x_next.val();
                self.at_last.d.next = self.x_next.val() == self.last.q.val();
                if self.left.q.val() {
                    self.a_z.d.next = self.a_z.q.val() - self.d_z.q.val();
                    self.a_c0.d.next = self.a_c0.q.val() - self.d_c0.q.val();
                    self.a_c1.d.next = self.a_c1.q.val() - self.d_c1.q.val();
                    self.a_c2.d.next = self.a_c2.q.val() - self.d_c2.q.val();
                } else {
                    self.a_z.d.next = self.a_z.q.val() + self.d_z.q.val();
                    self.a_c0.d.next = self.a_c0.q.val() + self.d_c0.q.val();
                    self.a_c1.d.next = self.a_c1.q.val() + self.d_c1.q.val();
                    self.a_c2.d.next = self.a_c2.q.val() + self.d_c2.q.val();
                }
            }
        }

        // The command: dropped when wholly off screen in x (xl > W - 1 or xr < 0) or with
        // both ends beyond the same z boundary; walked from xr leftwards when xl < 0.
        self.zl.x.next = self.inp.left_z.val();
        self.zr.x.next = self.inp.right_z.val();
        self.xl_neg.x.next = self.inp.xl.val();
        self.xr_neg.x.next = self.inp.xr.val();
        self.xl_on.a.next = self.inp.xl.val();
        self.xl_on.b.next = self.width_x.val();
        self.dropped.next = false;
        if self.clip_x.on.val() & (!self.xl_on.lt.val() | self.xr_neg.neg.val()) {
            self.dropped.next = true;
        }
        if self.clip_z.on.val() & ((self.zl.neg.val() & self.zr.neg.val()) | (self.zl.over.val() & self.zr.over.val()))
        {
            self.dropped.next = true;
        }
        self.last_column.next = self.width_x.val() - 1;
        self.xr_off.next = self.clip_x.on.val() & (self.inp.xr.val() >= self.width_x.val());
        if self.xl_neg.neg.val() & self.clip_x.on.val() {
            self.x_first.next = self.inp.xr.val();
            self.x_last.next = 0.into();
            self.one_pixel.next = self.inp.xr.val() == 0;
        } else {
            self.x_first.next = self.inp.xl.val();
            self.x_last.next = self.inp.xr.val();
            self.one_pixel.next = self.inp.xl.val() == self.inp.xr.val();
            if self.xr_off.val() {
                self.x_last.next = self.last_column.val();
                self.one_pixel.next = self.inp.xl.val() == self.last_column.val();
            }
        }
        if self.accept.val() {
            self.busy.d.next = true;
            self.drop.d.next = self.dropped.val();
            self.x.d.next = self.x_first.val();
            self.last.d.next = self.x_last.val();
            self.at_last.d.next = self.one_pixel.val();
            self.y.d.next = self.inp.y.val();
            self.d_z.d.next = bit_cast::<Z_ACC, DZ>(self.inp.ddx_z.val());
            self.d_c0.d.next = bit_cast::<C_ACC, DC>(self.inp.ddx_c0.val());
            self.d_c1.d.next = bit_cast::<C_ACC, DC>(self.inp.ddx_c1.val());
            self.d_c2.d.next = bit_cast::<C_ACC, DC>(self.inp.ddx_c2.val());
            self.left.d.next = self.xl_neg.neg.val() & self.clip_x.on.val();
            if self.xl_neg.neg.val() & self.clip_x.on.val() {
                self.a_z.d.next = self.inp.right_z.val();
                self.a_c0.d.next = self.inp.right_c0.val();
                self.a_c1.d.next = self.inp.right_c1.val();
                self.a_c2.d.next = self.inp.right_c2.val();
            } else {
                self.a_z.d.next = self.inp.left_z.val();
                self.a_c0.d.next = self.inp.left_c0.val();
                self.a_c1.d.next = self.inp.left_c1.val();
                self.a_c2.d.next = self.inp.left_c2.val();
            }
        }
    }
}

crate::pins!(Span { clock: clock, inputs: [width,], outputs: [idle], links: [inp, out] });

impl Span {
    /// The span unit with X and Z clipping present or not (`parts.clip_x`, `parts.clip_z`).
    pub fn new(parts: &Parts) -> Span {
        Span { clip_x: Switch::new(parts.clip_x), clip_z: Switch::new(parts.clip_z), ..Default::default() }
    }
}

/// `UNITS` entry: the span unit, with X and Z clipping as `params["CLIP_X"]` and
/// `params["CLIP_Z"]` say (widths from `crate::widths`).
pub fn emit_span(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("span", Span::new(&Parts::of(params)?), params))
}
