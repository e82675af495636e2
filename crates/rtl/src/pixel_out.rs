//! `pixel_out`: the depth test (LESS) and the writes to the depth and colour buffers,
//! behind `span`, through one synchronous memory port, one pixel per cycle.
//!
//! **The memory port** (so the design can sit on FPGA block RAM or external memory): a
//! word per pixel at address `{y, x}` (a row pitch of 2^SCREEN words), holding a depth
//! (`DEPTH` bits) and a colour (`RGB` bits), on the bundle `mem` (`links::MemoryPort`). In
//! each cycle with `mem$ready` high the memory performs, at the rising edge, the read asked
//! for (`mem$rd_en`, `mem$rd_addr`), returning the depth on `mem$rd_z` from the next cycle
//! until its next read, and the write asked for (`mem$wr_en`, `mem$wr_addr`, `mem$wr_z`,
//! `mem$wr_rgb`). With `mem$ready` low it does neither and the unit holds every register:
//! `mem$ready` is the memory's stall. Whether a read and a write
//! of one address at one edge return the old or the new word does not matter (see below).
//!
//! **Pipeline** (`model::pixel_out::{LATENCY, II}` = 2, 1):
//!
//! ```text
//!   cycle t          t + 1                              t + 2
//!   pixel in     ->  s1: old depth = rd_z, or the     ->  s2: write depth and colour
//!   read depth;      newer one s2 is writing now, or      (when the test passed)
//!   address vs       the one s3 wrote in cycle t;
//!   s1's and s2's    test z < old
//! ```
//!
//! Read-after-write hazards: the depth read for a pixel happens before the writes of the
//! two pixels ahead of it (the one in s2 as it is read, the one in s1 next cycle), so a
//! pixel whose address matches one of them takes that pixel's depth instead of `rd_z`
//! (the newer first). Its address is compared with theirs in cycle t, as it comes in
//! (`hit2`, `hit3`, registered with it), so that in cycle t + 1 only a choice of three
//! depths and the test lie between the registers (for the clock). Model:
//! `model::pixel_out::Framebuffer::pixel_out`. Emitted: `hdl-out/pixel_out.v`.

use crate::emit::{emit_unit, Emitted};
use crate::parts::Concat;
use crate::switch::{Parts, Switch};
use super::links::{MemoryPort, PixelSink};
use super::widths::{ADDR, CHANNEL, DEPTH, RGB, SCREEN};
use crate::Params;
use rust_hdl::prelude::*;

/// The pixel output unit: see the module documentation.
#[derive(LogicBlock, Default)]
pub struct PixelOut {
    pub clock: Signal<In, Clock>,
    /// The pixels; `inp.ready` is `mem.ready`: a pixel is taken whenever the memory is.
    pub inp: PixelSink,
    /// The memory port (see the module documentation).
    pub mem: MemoryPort,
    /// No pixel in the pipeline (for `raster_top`'s frame-done): empty 3 cycles after the
    /// last pixel came in, whether it was written or not.
    pub idle: Signal<Out, Bit>,
    /// The depth test present (`DEPTH_TEST`, `crate::switch`); without it no depth is read
    /// and every pixel is written: no two pixels of a frame may share an address.
    depth_test: Switch,
    /// s1: the pixel whose depth is being read (`mem.rd_z` holds it this cycle).
    s1_valid: DFF<Bit>,
    s1_addr: DFF<Bits<ADDR>>,
    s1_z: DFF<Bits<DEPTH>>,
    s1_rgb: DFF<Bits<RGB>>,
    /// s2: the pixel after its test; written when it passed (`s2_write`).
    s2_valid: DFF<Bit>,
    s2_write: DFF<Bit>,
    s2_addr: DFF<Bits<ADDR>>,
    s2_z: DFF<Bits<DEPTH>>,
    s2_rgb: DFF<Bits<RGB>>,
    /// s3: the write done in the last cycle the memory was ready (its address is compared
    /// while it is in s2: `hit3`).
    s3_valid: DFF<Bit>,
    s3_z: DFF<Bits<DEPTH>>,
    /// s1's address equals s2's (`hit2`) and s3's (`hit3`): compared as s1's pixel came in,
    /// against the pixels then in s1 and s2, which moved on to s2 and s3 with it.
    hit2: DFF<Bit>,
    hit3: DFF<Bit>,
    /// `{y, x}` and `{R, G, B}` of the pixel coming in.
    addr: Concat<SCREEN, SCREEN, ADDR>,
    rg: Concat<CHANNEL, CHANNEL, { 2 * CHANNEL }>,
    rgb: Concat<{ 2 * CHANNEL }, CHANNEL, RGB>,
    /// The depth s1's pixel is tested against, and the test.
    old_z: Signal<Local, Bits<DEPTH>>,
    pass: Signal<Local, Bit>,
}

impl Logic for PixelOut {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_valid, s1_addr, s1_z, s1_rgb, s2_valid, s2_write, s2_addr, s2_z, s2_rgb, s3_valid, s3_z,
            hit2, hit3
        );
        self.addr.hi.next = self.inp.y.val();
        self.addr.lo.next = self.inp.x.val();
        self.rg.hi.next = self.inp.rgb0.val();
        self.rg.lo.next = self.inp.rgb1.val();
        self.rgb.hi.next = self.rg.out.val();
        self.rgb.lo.next = self.inp.rgb2.val();

        // Cycle t: the pixel comes in and its depth is read.
        self.inp.ready.next = self.mem.ready.val();
        self.mem.rd_en.next = self.inp.valid.val() & self.depth_test.on.val();
        self.mem.rd_addr.next = self.addr.out.val();

        // Cycle t + 1: depth test against the newest depth of the address (the address
        // compares made in cycle t).
        self.old_z.next = self.mem.rd_z.val();
        if self.s3_valid.q.val() & self.hit3.q.val() {
            self.old_z.next = self.s3_z.q.val();
        }
        if self.s2_write.q.val() & self.hit2.q.val() {
            self.old_z.next = self.s2_z.q.val();
        }
        self.pass.next = self.s1_valid.q.val();
        if self.depth_test.on.val() & (self.s1_z.q.val() >= self.old_z.val()) {
            self.pass.next = false;
        }

        // Cycle t + 2: the write.
        self.mem.wr_en.next = self.s2_write.q.val();
        self.mem.wr_addr.next = self.s2_addr.q.val();
        self.mem.wr_z.next = self.s2_z.q.val();
        self.mem.wr_rgb.next = self.s2_rgb.q.val();
        self.idle.next = !self.s1_valid.q.val() & !self.s2_valid.q.val();

        if self.mem.ready.val() {
            self.s1_valid.d.next = self.inp.valid.val();
            self.s1_addr.d.next = self.addr.out.val();
            self.s1_z.d.next = self.inp.z.val();
            self.s1_rgb.d.next = self.rgb.out.val();
            self.hit2.d.next = self.s1_addr.q.val() == self.addr.out.val();
            self.hit3.d.next = self.s2_addr.q.val() == self.addr.out.val();
            self.s2_valid.d.next = self.s1_valid.q.val();
            self.s2_write.d.next = self.pass.val();
            self.s2_addr.d.next = self.s1_addr.q.val();
            self.s2_z.d.next = self.s1_z.q.val();
            self.s2_rgb.d.next = self.s1_rgb.q.val();
            self.s3_valid.d.next = self.s2_write.q.val();
            self.s3_z.d.next = self.s2_z.q.val();
        }
    }
}

crate::pins!(PixelOut {
    clock: clock,
    inputs: [],
    outputs: [idle],
    links: [inp, mem],
});

impl PixelOut {
    /// The pixel output unit with the depth test present or not (`parts.depth_test`).
    pub fn new(parts: &Parts) -> PixelOut {
        PixelOut { depth_test: Switch::new(parts.depth_test), ..Default::default() }
    }
}

/// `UNITS` entry: the pixel output unit, with the depth test as `params["DEPTH_TEST"]`
/// says (widths from `crate::widths`).
pub fn emit_pixel_out(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("pixel_out", PixelOut::new(&Parts::of(params)?), params))
}
