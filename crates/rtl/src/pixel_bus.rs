//! `pixel_bus`: `pixel_out`'s depth test (LESS) and buffer writes with the depth and colour
//! buffers in system memory, on AXI4: what `gpu_top` puts behind the rasterizer. The
//! buffers' layout, the frame (`start`, the clear), the queue of pixels in flight and its
//! hazard check are `model::pixel_bus`'s, which this unit follows on every cycle.
//!
//! **Buses** (single-beat INCR bursts of 4-byte words, every byte strobed; `r_ready` and
//! `b_ready` always high; every transfer offered from a register):
//! * `zr$` (`links::WordReadMaster`): depth reads; `zw$` (`links::WordWriteMaster`): depth
//!   writes. Both are the depth buffer's: one AXI4 master's read and write channels.
//! * `cw$` (`links::WordWriteMaster`): colour writes, a write-only AXI4 master.
//!
//! **Registers:** two input registers (`model::pixel_bus::INPUT`: pixels taken, with their
//! two word addresses, before they enter the queue, so that `inp$ready` comes from
//! registers and the address arithmetic ends in one), [`ENTRIES`] queue entries (each a
//! pixel's two word addresses, its depth, colour, whether it passed, and whether it is in
//! the queue), four ring pointers, the read address, the two buffers' write address and
//! data, the clear's pixel, and counts of the writes unanswered. Two multipliers make `y *
//! pitch` for the pixel coming in (or the clear's): on ECP5, MULT18X18D blocks.
//!
//! Emitted: `hdl-out/pixel_bus.v`.

use super::links::{PixelSink, WordReadMaster, WordWriteMaster};
use super::widths::{CHANNEL, DEPTH, DIM, RGB, SCREEN};
use crate::emit::{emit_unit, Emitted};
use crate::mul::Mul;
use crate::parts::{defaults, Concat};
use crate::Params;
use model::pixel_bus::INPUT;
use rust_hdl::prelude::*;

/// Pixels in flight (`model::pixel_bus::Params::entries`).
pub const ENTRIES: usize = 16;
/// Bits of the ring pointers, which count to twice [`ENTRIES`] so that full and empty
/// differ.
const POINTER: usize = 5;
/// Bits of the input registers' ring pointers, which count to twice
/// `model::pixel_bus::INPUT` (2).
const IN_POINTER: usize = 2;
const _: () = assert!(INPUT == 2 && 2 * INPUT == 1 << IN_POINTER, "the kernel picks an input by one pointer bit");
const _: () = assert!(ENTRIES == 16 && 2 * ENTRIES == 1 << POINTER, "the kernel takes 4 bits of a pointer");
/// `y` and `x` as the address arithmetic takes them: a clear counts to the screen's size.
const YW: usize = DIM + 1;
const X4: usize = DIM + 2;

/// The pixel-output unit on AXI4: see the module documentation.
#[derive(LogicBlock, Default)]
pub struct PixelBus {
    pub clock: Signal<In, Clock>,
    /// Taken while `idle`: clear `error` and, with `clear`, write every pixel of the
    /// `width` x `height` screen with the far depth and `background`.
    pub start: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    /// The screen and the buffers (`model::pixel_bus::Config`), held while busy.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// `{R, G, B}`, R in the top byte.
    pub background: Signal<In, Bits<RGB>>,
    pub color_base: Signal<In, Bits<32>>,
    /// Bytes per row.
    pub color_pitch: Signal<In, Bits<16>>,
    pub depth_base: Signal<In, Bits<32>>,
    pub depth_pitch: Signal<In, Bits<16>>,
    /// The pixels.
    pub inp: PixelSink,
    pub zr: WordReadMaster,
    pub zw: WordWriteMaster,
    pub cw: WordWriteMaster,
    /// No clear, no pixel in flight, every write answered.
    pub idle: Signal<Out, Bit>,
    /// A read or write answered with an error since `start`.
    pub error: Signal<Out, Bit>,
    /// 0 drawing, 1 clearing, 2 waiting for the clear's responses.
    phase: DFF<Bits<2>>,
    /// The clear's next pixel.
    cx: DFF<Bits<DIM>>,
    cy: DFF<Bits<DIM>>,
    /// The input registers, a ring: the oldest at `in_head`, the next free at `in_tail`.
    in_zaddr: [DFF<Bits<32>>; INPUT],
    in_caddr: [DFF<Bits<32>>; INPUT],
    in_z: [DFF<Bits<DEPTH>>; INPUT],
    in_rgb: [DFF<Bits<RGB>>; INPUT],
    in_head: DFF<Bits<IN_POINTER>>,
    in_tail: DFF<Bits<IN_POINTER>>,
    /// The queue's entries.
    e_zaddr: [DFF<Bits<32>>; ENTRIES],
    e_caddr: [DFF<Bits<32>>; ENTRIES],
    e_z: [DFF<Bits<DEPTH>>; ENTRIES],
    e_rgb: [DFF<Bits<RGB>>; ENTRIES],
    e_pass: [DFF<Bit>; ENTRIES],
    e_live: [DFF<Bit>; ENTRIES],
    /// The oldest entry, the next to write, the next to get its read data, the next free.
    head: DFF<Bits<POINTER>>,
    written: DFF<Bits<POINTER>>,
    tested: DFF<Bits<POINTER>>,
    tail: DFF<Bits<POINTER>>,
    /// The read address offered; each buffer's write address and data offered.
    ar_valid: DFF<Bit>,
    ar_addr: DFF<Bits<32>>,
    zaw_valid: DFF<Bit>,
    zaw_addr: DFF<Bits<32>>,
    zw_valid: DFF<Bit>,
    zw_data: DFF<Bits<32>>,
    caw_valid: DFF<Bit>,
    caw_addr: DFF<Bits<32>>,
    cw_valid: DFF<Bit>,
    cw_data: DFF<Bits<32>>,
    /// Writes unanswered, each buffer; depth-write responses not yet matched with an entry.
    z_pending: DFF<Bits<8>>,
    c_pending: DFF<Bits<8>>,
    credit: DFF<Bits<POINTER>>,
    err: DFF<Bit>,
    /// The pixel's (or the clear's) `y * pitch` and `4 x`.
    zmul: Mul<YW, 17, 32>,
    cmul: Mul<YW, 17, 32>,
    x4: Concat<DIM, 2, X4>,
    y_sel: Signal<Local, Bits<DIM>>,
    zaddr: Signal<Local, Bits<32>>,
    caddr: Signal<Local, Bits<32>>,
    rg: Concat<CHANNEL, CHANNEL, { 2 * CHANNEL }>,
    rgb: Concat<{ 2 * CHANNEL }, CHANNEL, RGB>,
    /// The far depth, all ones (from `zero`: a kernel has no all-ones literal of a width).
    zero: Signal<Local, Bits<DEPTH>>,
    far: Signal<Local, Bits<DEPTH>>,
    /// The pointers' entries.
    w_i: Signal<Local, Bits<4>>,
    h_i: Signal<Local, Bits<4>>,
    t_i: Signal<Local, Bits<4>>,
    tail_i: Signal<Local, Bits<4>>,
    clearing: Signal<Local, Bit>,
    drawing: Signal<Local, Bit>,
    idle_now: Signal<Local, Bit>,
    hazard: Signal<Local, Bit>,
    count: Signal<Local, Bits<POINTER>>,
    /// Inputs held, and the oldest one's fields.
    in_count: Signal<Local, Bits<IN_POINTER>>,
    oldest_zaddr: Signal<Local, Bits<32>>,
    oldest_caddr: Signal<Local, Bits<32>>,
    oldest_z: Signal<Local, Bits<DEPTH>>,
    oldest_rgb: Signal<Local, Bits<RGB>>,
    /// A pixel taken into the input registers; the oldest input entering the queue.
    take: Signal<Local, Bit>,
    enter: Signal<Local, Bit>,
    can_write: Signal<Local, Bit>,
    load: Signal<Local, Bit>,
    /// The entries at `written`, `head` and `tested`.
    w_zaddr: Signal<Local, Bits<32>>,
    w_caddr: Signal<Local, Bits<32>>,
    w_z: Signal<Local, Bits<DEPTH>>,
    w_rgb: Signal<Local, Bits<RGB>>,
    w_pass: Signal<Local, Bit>,
    h_pass: Signal<Local, Bit>,
    t_z: Signal<Local, Bits<DEPTH>>,
    old_z: Signal<Local, Bits<DEPTH>>,
    credit_in: Signal<Local, Bits<POINTER>>,
    retire: Signal<Local, Bit>,
    consume: Signal<Local, Bit>,
    cx_next: Signal<Local, Bits<DIM>>,
    cy_next: Signal<Local, Bits<DIM>>,
}

impl PixelBus {
    pub fn new() -> PixelBus {
        PixelBus {
            in_zaddr: defaults(),
            in_caddr: defaults(),
            in_z: defaults(),
            in_rgb: defaults(),
            e_zaddr: defaults(),
            e_caddr: defaults(),
            e_z: defaults(),
            e_rgb: defaults(),
            e_pass: defaults(),
            e_live: defaults(),
            ..Default::default()
        }
    }
}

impl Logic for PixelBus {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, phase, cx, cy, in_head, in_tail, head, written, tested, tail, ar_valid, ar_addr, zaw_valid,
            zaw_addr, zw_valid, zw_data, caw_valid, caw_addr, cw_valid, cw_data, z_pending, c_pending, credit, err
        );
        for i in 0..INPUT {
            self.in_zaddr[i].clock.next = self.clock.val();
            self.in_zaddr[i].d.next = self.in_zaddr[i].q.val();
            self.in_caddr[i].clock.next = self.clock.val();
            self.in_caddr[i].d.next = self.in_caddr[i].q.val();
            self.in_z[i].clock.next = self.clock.val();
            self.in_z[i].d.next = self.in_z[i].q.val();
            self.in_rgb[i].clock.next = self.clock.val();
            self.in_rgb[i].d.next = self.in_rgb[i].q.val();
        }
        for i in 0..ENTRIES {
            self.e_zaddr[i].clock.next = self.clock.val();
            self.e_zaddr[i].d.next = self.e_zaddr[i].q.val();
            self.e_caddr[i].clock.next = self.clock.val();
            self.e_caddr[i].d.next = self.e_caddr[i].q.val();
            self.e_z[i].clock.next = self.clock.val();
            self.e_z[i].d.next = self.e_z[i].q.val();
            self.e_rgb[i].clock.next = self.clock.val();
            self.e_rgb[i].d.next = self.e_rgb[i].q.val();
            self.e_pass[i].clock.next = self.clock.val();
            self.e_pass[i].d.next = self.e_pass[i].q.val();
            self.e_live[i].clock.next = self.clock.val();
            self.e_live[i].d.next = self.e_live[i].q.val();
        }
        self.clearing.next = self.phase.q.val() == 1;
        self.drawing.next = self.phase.q.val() == 0;
        self.idle_now.next = self.drawing.val()
            & (self.in_head.q.val() == self.in_tail.q.val())
            & (self.head.q.val() == self.tail.q.val())
            & (self.z_pending.q.val() == 0)
            & (self.c_pending.q.val() == 0);
        self.idle.next = self.idle_now.val();
        self.error.next = self.err.q.val();

        // The two addresses of the pixel coming in, or of the clear's.
        self.y_sel.next = bit_cast::<DIM, SCREEN>(self.inp.y.val());
        self.x4.hi.next = bit_cast::<DIM, SCREEN>(self.inp.x.val());
        if self.clearing.val() {
            self.y_sel.next = self.cy.q.val();
            self.x4.hi.next = self.cx.q.val();
        }
        self.x4.lo.next = 0.into();
        self.zmul.a.next = bit_cast::<YW, DIM>(self.y_sel.val());
        self.zmul.b.next = bit_cast::<17, 16>(self.depth_pitch.val());
        self.cmul.a.next = bit_cast::<YW, DIM>(self.y_sel.val());
        self.cmul.b.next = bit_cast::<17, 16>(self.color_pitch.val());
        self.zaddr.next = self.depth_base.val() + self.zmul.p.val() + bit_cast::<32, X4>(self.x4.out.val());
        self.caddr.next = self.color_base.val() + self.cmul.p.val() + bit_cast::<32, X4>(self.x4.out.val());
        self.rg.hi.next = self.inp.rgb0.val();
        self.rg.lo.next = self.inp.rgb1.val();
        self.rgb.hi.next = self.rg.out.val();
        self.rgb.lo.next = self.inp.rgb2.val();
        self.zero.next = 0.into();
        self.far.next = !self.zero.val();
        self.w_i.next = self.written.q.val().get_bits::<4>(0);
        self.h_i.next = self.head.q.val().get_bits::<4>(0);
        self.t_i.next = self.tested.q.val().get_bits::<4>(0);
        self.tail_i.next = self.tail.q.val().get_bits::<4>(0);

        // In: a free input register while drawing.
        self.in_count.next = self.in_tail.q.val() - self.in_head.q.val();
        self.inp.ready.next = self.drawing.val() & !self.in_count.val().get_bit(1);
        self.take.next = self.inp.valid.val() & self.inp.ready.val();
        for i in 0..INPUT {
            if self.take.val() & (self.in_tail.q.val().get_bits::<1>(0).index() == i) {
                self.in_zaddr[i].d.next = self.zaddr.val();
                self.in_caddr[i].d.next = self.caddr.val();
                self.in_z[i].d.next = self.inp.z.val();
                self.in_rgb[i].d.next = self.rgb.out.val();
            }
        }
        if self.take.val() {
            self.in_tail.d.next = self.in_tail.q.val() + 1;
        }
        self.oldest_zaddr.next = self.in_zaddr[0].q.val();
        self.oldest_caddr.next = self.in_caddr[0].q.val();
        self.oldest_z.next = self.in_z[0].q.val();
        self.oldest_rgb.next = self.in_rgb[0].q.val();
        if self.in_head.q.val().get_bit(0) {
            self.oldest_zaddr.next = self.in_zaddr[1].q.val();
            self.oldest_caddr.next = self.in_caddr[1].q.val();
            self.oldest_z.next = self.in_z[1].q.val();
            self.oldest_rgb.next = self.in_rgb[1].q.val();
        }

        // Into the queue: the oldest input, with a free entry, the read address register
        // free, and no pixel of the same word in the queue.
        self.hazard.next = false;
        for i in 0..ENTRIES {
            if self.e_live[i].q.val() & (self.e_zaddr[i].q.val() == self.oldest_zaddr.val()) {
                self.hazard.next = true;
            }
        }
        self.count.next = self.tail.q.val() - self.head.q.val();
        self.enter.next = self.drawing.val()
            & self.in_count.val().any()
            & !self.count.val().get_bit(4)
            & (!self.ar_valid.q.val() | self.zr.ar_ready.val())
            & !self.hazard.val();
        if self.enter.val() {
            self.in_head.d.next = self.in_head.q.val() + 1;
        }

        // The entries at the pointers.
        self.w_zaddr.next = self.e_zaddr[0].q.val();
        self.w_caddr.next = self.e_caddr[0].q.val();
        self.w_z.next = self.e_z[0].q.val();
        self.w_rgb.next = self.e_rgb[0].q.val();
        self.w_pass.next = self.e_pass[0].q.val();
        self.h_pass.next = self.e_pass[0].q.val();
        self.t_z.next = self.e_z[0].q.val();
        for i in 1..ENTRIES {
            if self.w_i.val().index() == i {
                self.w_zaddr.next = self.e_zaddr[i].q.val();
                self.w_caddr.next = self.e_caddr[i].q.val();
                self.w_z.next = self.e_z[i].q.val();
                self.w_rgb.next = self.e_rgb[i].q.val();
                self.w_pass.next = self.e_pass[i].q.val();
            }
            if self.h_i.val().index() == i {
                self.h_pass.next = self.e_pass[i].q.val();
            }
            if self.t_i.val().index() == i {
                self.t_z.next = self.e_z[i].q.val();
            }
        }

        // Write: the clear's pixel, or the oldest tested entry's (when it passed).
        self.can_write.next = (!self.zaw_valid.q.val() | self.zw.aw_ready.val())
            & (!self.zw_valid.q.val() | self.zw.w_ready.val())
            & (!self.caw_valid.q.val() | self.cw.aw_ready.val())
            & (!self.cw_valid.q.val() | self.cw.w_ready.val())
            & !self.z_pending.q.val().get_bit(7)
            & !self.c_pending.q.val().get_bit(7);
        self.load.next = false;
        if self.zw.aw_ready.val() {
            self.zaw_valid.d.next = false;
        }
        if self.zw.w_ready.val() {
            self.zw_valid.d.next = false;
        }
        if self.cw.aw_ready.val() {
            self.caw_valid.d.next = false;
        }
        if self.cw.w_ready.val() {
            self.cw_valid.d.next = false;
        }
        if self.clearing.val() & self.can_write.val() {
            self.load.next = true;
            self.zaw_addr.d.next = self.zaddr.val();
            self.zw_data.d.next = bit_cast::<32, DEPTH>(self.far.val());
            self.caw_addr.d.next = self.caddr.val();
            self.cw_data.d.next = bit_cast::<32, RGB>(self.background.val());
        } else if self.written.q.val() != self.tested.q.val() {
            if !self.w_pass.val() | self.can_write.val() {
                self.written.d.next = self.written.q.val() + 1;
            }
            if self.w_pass.val() & self.can_write.val() {
                self.load.next = true;
                self.zaw_addr.d.next = self.w_zaddr.val();
                self.zw_data.d.next = bit_cast::<32, DEPTH>(self.w_z.val());
                self.caw_addr.d.next = self.w_caddr.val();
                self.cw_data.d.next = bit_cast::<32, RGB>(self.w_rgb.val());
            }
        }
        if self.load.val() {
            self.zaw_valid.d.next = true;
            self.zw_valid.d.next = true;
            self.caw_valid.d.next = true;
            self.cw_valid.d.next = true;
        }

        // Out: the oldest entry, when it did not pass or with a depth-write response.
        self.credit_in.next = self.credit.q.val();
        if self.drawing.val() & self.zw.b_valid.val() {
            self.credit_in.next = self.credit.q.val() + 1;
        }
        self.retire.next = false;
        self.consume.next = false;
        if self.head.q.val() != self.written.q.val() {
            if !self.h_pass.val() {
                self.retire.next = true;
            } else if self.credit_in.val() != 0 {
                self.retire.next = true;
                self.consume.next = true;
            }
        }
        self.credit.d.next = self.credit_in.val();
        if self.consume.val() {
            self.credit.d.next = self.credit_in.val() - 1;
        }
        if self.retire.val() {
            self.head.d.next = self.head.q.val() + 1;
        }

        // Test: the read data into the oldest entry waiting for them.
        self.old_z.next = self.zr.r_data.val().get_bits::<DEPTH>(0);
        for i in 0..ENTRIES {
            if self.retire.val() & (self.h_i.val().index() == i) {
                self.e_live[i].d.next = false;
            }
            if self.zr.r_valid.val() & (self.tested.q.val() != self.tail.q.val()) & (self.t_i.val().index() == i) {
                self.e_pass[i].d.next = (self.zr.r_resp.val() == 0) & (self.t_z.val() < self.old_z.val());
            }
            if self.enter.val() & (self.tail_i.val().index() == i) {
                self.e_zaddr[i].d.next = self.oldest_zaddr.val();
                self.e_caddr[i].d.next = self.oldest_caddr.val();
                self.e_z[i].d.next = self.oldest_z.val();
                self.e_rgb[i].d.next = self.oldest_rgb.val();
                self.e_pass[i].d.next = false;
                self.e_live[i].d.next = true;
            }
        }
        if self.zr.r_valid.val() & (self.tested.q.val() != self.tail.q.val()) {
            self.tested.d.next = self.tested.q.val() + 1;
        }

        // The read address of the pixel entering the queue.
        if self.zr.ar_ready.val() {
            self.ar_valid.d.next = false;
        }
        if self.enter.val() {
            self.tail.d.next = self.tail.q.val() + 1;
            self.ar_valid.d.next = true;
            self.ar_addr.d.next = self.oldest_zaddr.val();
        }

        // Writes unanswered.
        if self.load.val() & !self.zw.b_valid.val() {
            self.z_pending.d.next = self.z_pending.q.val() + 1;
        }
        if !self.load.val() & self.zw.b_valid.val() {
            self.z_pending.d.next = self.z_pending.q.val() - 1;
        }
        if self.load.val() & !self.cw.b_valid.val() {
            self.c_pending.d.next = self.c_pending.q.val() + 1;
        }
        if !self.load.val() & self.cw.b_valid.val() {
            self.c_pending.d.next = self.c_pending.q.val() - 1;
        }

        // The frame: the clear's pixels, its responses, then drawing; start when idle.
        self.err.d.next = self.err.q.val()
            | (self.zr.r_valid.val() & (self.zr.r_resp.val() != 0))
            | (self.zw.b_valid.val() & (self.zw.b_resp.val() != 0))
            | (self.cw.b_valid.val() & (self.cw.b_resp.val() != 0));
        self.cx_next.next = self.cx.q.val() + 1;
        self.cy_next.next = self.cy.q.val() + 1;
        if self.clearing.val() & self.load.val() {
            if self.cx_next.val() < self.width.val() {
                self.cx.d.next = self.cx_next.val();
            } else {
                self.cx.d.next = 0.into();
                self.cy.d.next = self.cy_next.val();
                if self.cy_next.val() == self.height.val() {
                    self.phase.d.next = 2.into();
                }
            }
        }
        if (self.phase.q.val() == 2) & (self.z_pending.q.val() == 0) & (self.c_pending.q.val() == 0) {
            self.phase.d.next = 0.into();
        }
        if self.start.val() & self.idle_now.val() {
            self.err.d.next = false;
            self.cx.d.next = 0.into();
            self.cy.d.next = 0.into();
            if self.clear.val() & self.width.val().any() & self.height.val().any() {
                self.phase.d.next = 1.into();
            }
        }

        // The buses.
        self.zr.ar_valid.next = self.ar_valid.q.val();
        self.zr.ar_addr.next = self.ar_addr.q.val();
        self.zr.ar_len.next = 0.into();
        self.zr.ar_size.next = 2.into();
        self.zr.ar_burst.next = 1.into();
        self.zr.r_ready.next = true;
        self.zw.aw_valid.next = self.zaw_valid.q.val();
        self.zw.aw_addr.next = self.zaw_addr.q.val();
        self.zw.w_valid.next = self.zw_valid.q.val();
        self.zw.w_data.next = self.zw_data.q.val();
        self.cw.aw_valid.next = self.caw_valid.q.val();
        self.cw.aw_addr.next = self.caw_addr.q.val();
        self.cw.w_valid.next = self.cw_valid.q.val();
        self.cw.w_data.next = self.cw_data.q.val();
        self.zw.aw_len.next = 0.into();
        self.zw.aw_size.next = 2.into();
        self.zw.aw_burst.next = 1.into();
        self.zw.w_strb.next = 15.into();
        self.zw.w_last.next = true;
        self.zw.b_ready.next = true;
        self.cw.aw_len.next = 0.into();
        self.cw.aw_size.next = 2.into();
        self.cw.aw_burst.next = 1.into();
        self.cw.w_strb.next = 15.into();
        self.cw.w_last.next = true;
        self.cw.b_ready.next = true;
    }
}

crate::pins!(PixelBus {
    clock: clock,
    inputs: [start, clear, width, height, background, color_base, color_pitch, depth_base, depth_pitch],
    outputs: [idle, error],
    links: [inp, zr, zw, cw],
});

/// `UNITS` entry: the pixel-output unit on AXI4 (widths from `crate::widths`).
pub fn emit_pixel_bus(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("pixel_bus", PixelBus::new(), params))
}
