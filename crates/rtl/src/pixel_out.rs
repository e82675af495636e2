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
//!
//! **Blending** (parameter `BLEND` = 1, [`PixelOutBlend`], one lane): framebuffer blending,
//! paper 001 section II-5's six blend modes as OpenGL 4.6 section 17.3.6 blends (blend
//! equation FUNC_ADD, one glBlendFunc pair a mode: `rtl::blend`'s table). Each pixel brings
//! an alpha and a mode (`inp$alpha`, `inp$mode`: `rtl::blend`'s code, `model::blend::MODES`'
//! order, 6 and 7 opaque; the link `links::BlendPixelSink`), and the memory's read returns
//! the word's colour with its depth (`mem$rd_rgb`, `links::BlendMemoryPort`); every pixel's
//! word is read, with the depth test or without it. The depth test and its forwarding are
//! [`ChunkOut`]'s, unchanged; beside the test, in s1, the pixel's colour is blended onto the
//! newest colour of its address, chosen as its depth is (s2's blended colour when s2 writes
//! that address, else s3's likewise, else `rd_rgb`), by three of `rtl::blend`'s channels
//! (the buffer holds no alpha: the destination's is 255, which the colour channels do not
//! read), and s2 writes the blend with the depth ([`BlendLane`]):
//!
//! ```text
//!   cycle t          t + 1                                   t + 2
//!   pixel in,    ->  s1: test as above; dst = rd_rgb, or  ->  s2: write depth and the
//!   alpha, mode;     s2's colour, or s3's (as the depth);     blended colour (when the
//!   read depth       blend(rgb, alpha, mode onto dst)         test passed)
//!   and colour
//! ```
//!
//! So pixels on one address back to back, or one or two apart, blend one onto the other in
//! order, as `model::pixel_out::Framebuffer::pixel_out_blended` does them one after the
//! other: bit-exact, image, depth and every write, at the same latency 2 and a pixel a cycle
//! (`model::pixel_out::{LATENCY, II}`). A stage more would not shorten the clock: a pixel's
//! blend needs the blend of the pixel right ahead of it on its address, made the cycle
//! before, and its multiply takes that colour, so the colour choice and the blend are a loop
//! of one cycle however the pipeline is cut (at a pixel a cycle). Area at class 10 (Yosys
//! 0.23 `synth_ecp5`): 445 LUT4, 116 CCU2C, 177 FF and 3 MULT18X18D, against the unit
//! without blending's 169 LUT4, 8 CCU2C, 142 FF; Fmax 39.4 MHz on an LFE5U-25F (nextpnr
//! router2, `edgepaint report --unit pixel_out --param BLEND=1`; 121.3 MHz without), the
//! blend's arithmetic the path (`blend` alone: 45.7 MHz). Tests:
//! `testbenches/tests/pixel_out_blend.rs`. Emitted by `edgepaint emit --unit pixel_out
//! --param BLEND=1` (linted by `scripts/lint.sh`). With `BLEND` = 0 the unit and its Verilog
//! are as they were: the colour path is a list of none ([`ChunkOut::new`]).

use super::links::{BlendMemoryPort, BlendPixelSink, ChunkPort, MemoryPort, PixelSink};
use super::widths::{ADDR, CHANNEL, DEPTH, RGB, SCREEN};
use crate::blend::BlendChannel;
use crate::emit::{emit_unit, Emitted};
use crate::parts::Concat;
use crate::switch::{Parts, Switch};
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;

/// The pixel output unit at one lane, behind the pixel link: see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct PixelOut {
    pub clock: Signal<In, Clock>,
    /// The pixels; `inp.ready` is `mem.ready`: a pixel is taken whenever the memory is.
    pub inp: PixelSink,
    /// The memory port (see the module documentation).
    pub mem: MemoryPort,
    /// No pixel in the pipeline (for `raster_top`'s frame-done): empty 3 cycles after the
    /// last pixel came in, whether it was written or not.
    pub idle: Signal<Out, Bit>,
    #[given]
    chunk: ChunkOut<1, ADDR, DEPTH, RGB>,
    /// `{y, x}` and `{R, G, B}` of the pixel coming in.
    addr: Concat<SCREEN, SCREEN, ADDR>,
    rg: Concat<CHANNEL, CHANNEL, { 2 * CHANNEL }>,
    rgb: Concat<{ 2 * CHANNEL }, CHANNEL, RGB>,
    /// The one lane's enable.
    one: Constant<Bits<1>>,
}

/// The kernel of a one-lane unit ([`PixelOut`], [`PixelOutBlend`]): the pixel coming in
/// onto the chunk's one lane (its `{y, x}`, `{R, G, B}` and the lane's enable) and
/// `inp.ready` from the chunk, then the unit's own statements (its memory port's wiring,
/// and the blending unit's colour path), then `idle`. A macro writes the kernels out before
/// `#[hdl_gen]` reads them. Each unit writes its part as a kernel, `#[hdl_gen] fn
/// update(&mut self) { ... }`: the attribute and `self` are then the unit's tokens, not the
/// macro's, so that (by macro hygiene) its statements' `self` is the kernel's argument, in
/// the kernel and in the code `#[hdl_gen]` makes of it.
macro_rules! one_lane_kernel {
    ($unit:ident, $pound:tt $hdl_gen:tt fn update(&mut $s:ident) { $($own:tt)* }) => {
        impl Logic for $unit {
            $pound $hdl_gen
            fn update(&mut $s) {
                clock!($s, clock, chunk);
                $s.addr.hi.next = $s.inp.y.val();
                $s.addr.lo.next = $s.inp.x.val();
                $s.rg.hi.next = $s.inp.rgb0.val();
                $s.rg.lo.next = $s.inp.rgb1.val();
                $s.rgb.hi.next = $s.rg.out.val();
                $s.rgb.lo.next = $s.inp.rgb2.val();
                $s.chunk.in_valid.next = $s.inp.valid.val();
                $s.chunk.in_mask.next = $s.one.val();
                $s.chunk.in_addr.next = $s.addr.out.val();
                $s.chunk.in_z.next = $s.inp.z.val();
                $s.chunk.in_rgb.next = $s.rgb.out.val();
                $s.inp.ready.next = $s.chunk.in_ready.val();
                $($own)*
                $s.idle.next = $s.chunk.idle.val();
            }
        }
    };
}

one_lane_kernel! {
    PixelOut,
    #[hdl_gen]
    fn update(&mut self) {
        MemoryPort::link(&mut self.mem, &mut self.chunk.mem);
    }
}

crate::pins!(impl[const LANES: usize, const AW: usize, const ZW: usize, const CW: usize] ChunkOut<LANES, AW, ZW, CW> {
    clock: clock,
    inputs: [in_valid, in_mask, in_addr, in_z, in_rgb],
    outputs: [in_ready, idle],
    links: [mem],
});

crate::pins!(PixelOut { clock: clock, inputs: [], outputs: [idle], links: [inp, mem] });

impl PixelOut {
    /// The pixel output unit with the depth test present or not (`parts.depth_test`).
    pub fn new(parts: &Parts) -> PixelOut {
        PixelOut { one: Constant::new(1.into()), ..PixelOut::blank(PixelOutGiven { chunk: ChunkOut::new(parts) }) }
    }
}

/// The unit with the depth test (`raster_top`'s variants hold one).
impl Default for PixelOut {
    fn default() -> Self {
        PixelOut::new(&Parts::ALL)
    }
}

/// The blending pixel output unit (`BLEND` = 1) at one lane: [`PixelOut`] with each pixel's
/// alpha and blend mode on its link and the colour read with the depth: see the module
/// documentation.
#[derive(LogicBlock, Blank)]
pub struct PixelOutBlend {
    pub clock: Signal<In, Clock>,
    /// The pixels; `inp.ready` is `mem.ready`.
    pub inp: BlendPixelSink,
    /// The memory port: [`MemoryPort`] and the colour read (`mem.rd_rgb`).
    pub mem: BlendMemoryPort,
    /// No pixel in the pipeline, as [`PixelOut`]'s.
    pub idle: Signal<Out, Bit>,
    #[given]
    chunk: ChunkOut<1, ADDR, DEPTH, RGB>,
    /// `{y, x}` and `{R, G, B}` of the pixel coming in.
    addr: Concat<SCREEN, SCREEN, ADDR>,
    rg: Concat<CHANNEL, CHANNEL, { 2 * CHANNEL }>,
    rgb: Concat<{ 2 * CHANNEL }, CHANNEL, RGB>,
    /// The one lane's enable.
    one: Constant<Bits<1>>,
}

one_lane_kernel! {
    PixelOutBlend,
    #[hdl_gen]
    fn update(&mut self) {
        self.chunk.mem.ready.next = self.mem.ready.val();
        self.mem.rd_en.next = self.chunk.mem.rd_en.val();
        self.mem.rd_addr.next = self.chunk.mem.rd_addr.val();
        self.chunk.mem.rd_z.next = self.mem.rd_z.val();
        self.mem.wr_en.next = self.chunk.mem.wr_en.val();
        self.mem.wr_addr.next = self.chunk.mem.wr_addr.val();
        self.mem.wr_z.next = self.chunk.mem.wr_z.val();
        self.mem.wr_rgb.next = self.chunk.mem.wr_rgb.val();
        // The chunk's blending ports, its lists of one (a loop of one iteration indexes them).
        for b in 0..1 {
            self.chunk.in_alpha[b].next = self.inp.alpha.val();
            self.chunk.in_mode[b].next = self.inp.mode.val();
            self.chunk.rd_rgb[b].next = self.mem.rd_rgb.val();
        }
    }
}

crate::pins!(PixelOutBlend { clock: clock, inputs: [], outputs: [idle], links: [inp, mem] });

impl PixelOutBlend {
    /// The blending unit with the depth test present or not (`parts.depth_test`; without
    /// it every pixel is written, blended).
    pub fn new(parts: &Parts) -> PixelOutBlend {
        PixelOutBlend {
            one: Constant::new(1.into()),
            ..PixelOutBlend::blank(PixelOutBlendGiven { chunk: ChunkOut::blending(parts) })
        }
    }
}

/// The unit with the depth test.
impl Default for PixelOutBlend {
    fn default() -> Self {
        PixelOutBlend::new(&Parts::ALL)
    }
}

/// The pixel output unit for chunks of `LANES` pixels (`AW` address bits, `ZW` = `LANES`
/// x `DEPTH`, `CW` = `LANES` x `RGB`): see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct ChunkOut<const LANES: usize, const AW: usize, const ZW: usize, const CW: usize> {
    pub clock: Signal<In, Clock>,
    /// A chunk in: its lanes with a pixel (`in_mask`), its address, the lanes' depths and
    /// colours as the memory words hold them. Taken whenever the memory is ready.
    pub in_valid: Signal<In, Bit>,
    pub in_ready: Signal<Out, Bit>,
    pub in_mask: Signal<In, Bits<LANES>>,
    pub in_addr: Signal<In, Bits<AW>>,
    pub in_z: Signal<In, Bits<ZW>>,
    pub in_rgb: Signal<In, Bits<CW>>,
    /// Blending ([`ChunkOut::blending`], one lane): the pixel's alpha and blend mode as it
    /// comes in, and the colour read (from the cycle after the read, as `mem.rd_z`), one
    /// each (ports `in_alpha$0`, `in_mode$0`, `rd_rgb$0`); without blending, none.
    pub in_alpha: Vec<Signal<In, Bits<8>>>,
    pub in_mode: Vec<Signal<In, Bits<3>>>,
    pub rd_rgb: Vec<Signal<In, Bits<CW>>>,
    /// The memory port (see the module documentation).
    pub mem: ChunkPort<LANES, AW, ZW, CW>,
    /// No chunk in the pipeline: empty 3 cycles after the last one came in.
    pub idle: Signal<Out, Bit>,
    /// The depth test present (`DEPTH_TEST`, `crate::switch`); without it no depth is read
    /// and every pixel is written: no two pixels of a frame may share an address.
    depth_test: Switch,
    /// s1: the chunk whose depths are being read (`mem.rd_z` holds them this cycle).
    s1_valid: DFF<Bit>,
    s1_mask: DFF<Bits<LANES>>,
    s1_addr: DFF<Bits<AW>>,
    s1_z: DFF<Bits<ZW>>,
    s1_rgb: DFF<Bits<CW>>,
    /// s2: the chunk after its test; its lanes that passed are written (`s2_write`).
    s2_valid: DFF<Bit>,
    s2_write: DFF<Bits<LANES>>,
    s2_addr: DFF<Bits<AW>>,
    s2_z: DFF<Bits<ZW>>,
    s2_rgb: DFF<Bits<CW>>,
    /// s3: the lanes written in the last cycle the memory was ready (its address is
    /// compared while it is in s2: `hit3`).
    s3_write: DFF<Bits<LANES>>,
    s3_z: DFF<Bits<ZW>>,
    /// s1's address equals s2's (`hit2`) and s3's (`hit3`): compared as s1's chunk came in,
    /// against the chunks then in s1 and s2, which moved on to s2 and s3 with it.
    hit2: DFF<Bit>,
    hit3: DFF<Bit>,
    /// Each lane's test, and the lanes that pass gathered (`pass`).
    lanes: Vec<LaneTest<LANES, ZW>>,
    g_pass: Vec<Signal<Local, Bits<LANES>>>,
    pass: Signal<Local, Bits<LANES>>,
    /// Blending: the colour path ([`BlendLane`], one), whose blended colour s2 holds and
    /// writes in place of the pixel's; without blending, none (and no Verilog of it).
    blend: Vec<BlendLane<CW>>,
    /// `blend.len()`, for the kernel's loops.
    _blend: usize,
}

impl<const LANES: usize, const AW: usize, const ZW: usize, const CW: usize> ChunkOut<LANES, AW, ZW, CW> {
    /// The unit with the depth test present or not (`parts.depth_test`).
    pub fn new(parts: &Parts) -> Self {
        Self::with_blend(parts, 0)
    }

    /// The unit that blends (one lane, for [`PixelOutBlend`]), with the depth test present
    /// or not.
    pub fn blending(parts: &Parts) -> Self {
        assert!(LANES == 1, "ChunkOut<{LANES}, ..> blends at one lane only");
        Self::with_blend(parts, 1)
    }

    fn with_blend(parts: &Parts, blend: usize) -> Self {
        assert!(ZW == LANES * DEPTH && CW == LANES * RGB, "ChunkOut<{LANES}, {AW}, {ZW}, {CW}>");
        ChunkOut {
            in_alpha: (0..blend).map(|_| Default::default()).collect(),
            in_mode: (0..blend).map(|_| Default::default()).collect(),
            rd_rgb: (0..blend).map(|_| Default::default()).collect(),
            depth_test: Switch::new(parts.depth_test),
            lanes: (0..LANES).map(LaneTest::new).collect(),
            g_pass: (0..=LANES).map(|_| Default::default()).collect(),
            blend: (0..blend).map(|_| Default::default()).collect(),
            _blend: blend,
            ..ChunkOut::blank()
        }
    }
}

impl<const LANES: usize, const AW: usize, const ZW: usize, const CW: usize> Logic for ChunkOut<LANES, AW, ZW, CW> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, s1_valid, s1_mask, s1_addr, s1_z, s1_rgb, s2_valid, s2_write, s2_addr, s2_z, s2_rgb, s3_write,
            s3_z, hit2, hit3
        );

        // Cycle t: the chunk comes in and its lanes' depths are read.
        self.in_ready.next = self.mem.ready.val();
        self.mem.rd_en.next = 0.into();
        if self.in_valid.val() & self.depth_test.on.val() {
            self.mem.rd_en.next = self.in_mask.val();
        }
        self.mem.rd_addr.next = self.in_addr.val();

        // Cycle t + 1: each lane's test against the newest depth of its pixel (the address
        // compares made in cycle t).
        self.g_pass[0].next = 0.into();
        for i in 0..LANES {
            self.lanes[i].rd_z.next = self.mem.rd_z.val();
            self.lanes[i].s1_z.next = self.s1_z.q.val();
            self.lanes[i].s2_z.next = self.s2_z.q.val();
            self.lanes[i].s3_z.next = self.s3_z.q.val();
            self.lanes[i].s1_mask.next = self.s1_mask.q.val();
            self.lanes[i].s2_write.next = self.s2_write.q.val();
            self.lanes[i].s3_write.next = self.s3_write.q.val();
            self.lanes[i].hit2.next = self.hit2.q.val();
            self.lanes[i].hit3.next = self.hit3.q.val();
            self.lanes[i].on.next = self.depth_test.on.val();
            self.g_pass[i + 1].next = self.g_pass[i].val() | self.lanes[i].pass.val();
        }
        for i in LANES..(LANES + 1) {
            self.pass.next = self.g_pass[i].val();
        }

        // Cycle t + 2: the write.
        self.mem.wr_en.next = self.s2_write.q.val();
        self.mem.wr_addr.next = self.s2_addr.q.val();
        self.mem.wr_z.next = self.s2_z.q.val();
        self.mem.wr_rgb.next = self.s2_rgb.q.val();
        self.idle.next = !self.s1_valid.q.val() & !self.s2_valid.q.val();

        if self.mem.ready.val() {
            self.s1_valid.d.next = self.in_valid.val();
            self.s1_mask.d.next = 0.into();
            if self.in_valid.val() {
                self.s1_mask.d.next = self.in_mask.val();
            }
            self.s1_addr.d.next = self.in_addr.val();
            self.s1_z.d.next = self.in_z.val();
            self.s1_rgb.d.next = self.in_rgb.val();
            self.hit2.d.next = self.s1_addr.q.val() == self.in_addr.val();
            self.hit3.d.next = self.s2_addr.q.val() == self.in_addr.val();
            self.s2_valid.d.next = self.s1_valid.q.val();
            self.s2_write.d.next = self.pass.val();
            self.s2_addr.d.next = self.s1_addr.q.val();
            self.s2_z.d.next = self.s1_z.q.val();
            self.s2_rgb.d.next = self.s1_rgb.q.val();
            self.s3_write.d.next = self.s2_write.q.val();
            self.s3_z.d.next = self.s2_z.q.val();
        }

        // Blending: the colour is read with the depth, with the test or without it; in
        // cycle t + 1 the colour path blends s1's pixel onto its address's newest colour,
        // chosen as its depth is (s2's if s2 writes that address, else s3's likewise, else
        // the one read), and s2 takes the blend in place of the pixel's colour.
        for b in 0..self._blend {
            if self.in_valid.val() {
                self.mem.rd_en.next = self.in_mask.val();
            }
            self.blend[b].clock.next = self.clock.val();
            self.blend[b].ready.next = self.mem.ready.val();
            self.blend[b].in_alpha.next = self.in_alpha[b].val();
            self.blend[b].in_mode.next = self.in_mode[b].val();
            self.blend[b].rd_rgb.next = self.rd_rgb[b].val();
            self.blend[b].src.next = self.s1_rgb.q.val();
            self.blend[b].s2_rgb.next = self.s2_rgb.q.val();
            self.blend[b].fwd2.next = (self.s2_write.q.val() != 0) & self.hit2.q.val();
            self.blend[b].fwd3.next = (self.s3_write.q.val() != 0) & self.hit3.q.val();
            if self.mem.ready.val() {
                self.s2_rgb.d.next = self.blend[b].color.val();
            }
        }
    }
}

/// The colour path of the blending [`ChunkOut`] at one lane (`CW` = 24 bits, `{R, G, B}`):
/// the pixel's alpha and mode taken into s1 with it, the destination colour chosen in s1
/// (`fwd2`: s2 writes s1's address, its colour; else `fwd3`: s3 did, its colour; else the
/// one read), and the blend of s1's colour onto it (`color`, into s2) by three of
/// `rtl::blend`'s channels (the destination's alpha is 255: the colour channels do not
/// read it); s3's colour kept for the forwarding.
#[derive(LogicBlock, Default)]
pub struct BlendLane<const CW: usize> {
    pub clock: Signal<In, Clock>,
    /// The memory is ready: the registers move.
    pub ready: Signal<In, Bit>,
    /// Cycle t: the alpha and the mode of the pixel coming in.
    pub in_alpha: Signal<In, Bits<8>>,
    pub in_mode: Signal<In, Bits<3>>,
    /// Cycle t + 1: the colour read, s1's colour (the source), and s2's (the colour it
    /// writes when it writes).
    pub rd_rgb: Signal<In, Bits<CW>>,
    pub src: Signal<In, Bits<CW>>,
    pub s2_rgb: Signal<In, Bits<CW>>,
    /// s2, and s3, write s1's address (`ChunkOut`'s write masks and `hit2`, `hit3`).
    pub fwd2: Signal<In, Bit>,
    pub fwd3: Signal<In, Bit>,
    /// s1's colour blended onto the destination.
    pub color: Signal<Out, Bits<CW>>,
    s1_alpha: DFF<Bits<8>>,
    s1_mode: DFF<Bits<3>>,
    /// The colour s3 wrote (when it wrote).
    s3_rgb: DFF<Bits<CW>>,
    dst: Signal<Local, Bits<CW>>,
    /// R, G, B.
    ch: [BlendChannel; 3],
}

impl<const CW: usize> Logic for BlendLane<CW> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1_alpha, s1_mode, s3_rgb);
        if self.ready.val() {
            self.s1_alpha.d.next = self.in_alpha.val();
            self.s1_mode.d.next = self.in_mode.val();
            self.s3_rgb.d.next = self.s2_rgb.val();
        }
        self.dst.next = self.rd_rgb.val();
        if self.fwd3.val() {
            self.dst.next = self.s3_rgb.q.val();
        }
        if self.fwd2.val() {
            self.dst.next = self.s2_rgb.val();
        }
        self.ch[0].cs.next = self.src.val().get_bits::<8>(16);
        self.ch[1].cs.next = self.src.val().get_bits::<8>(8);
        self.ch[2].cs.next = self.src.val().get_bits::<8>(0);
        self.ch[0].cd.next = self.dst.val().get_bits::<8>(16);
        self.ch[1].cd.next = self.dst.val().get_bits::<8>(8);
        self.ch[2].cd.next = self.dst.val().get_bits::<8>(0);
        for k in 0..3 {
            self.ch[k].a_s.next = self.s1_alpha.q.val();
            self.ch[k].mode.next = self.s1_mode.q.val();
        }
        self.color.next = (bit_cast::<CW, 8>(self.ch[0].out.val()) << 16)
            | (bit_cast::<CW, 8>(self.ch[1].out.val()) << 8)
            | bit_cast::<CW, 8>(self.ch[2].out.val());
    }
}

/// One lane's depth test in [`ChunkOut`]: lane `i`'s depth out of each chunk word, the
/// newest depth of its pixel (s2's if s2 writes this lane of the same chunk, else s3's
/// likewise, else the one read), and `pass`: the lane's bit when its pixel is present and
/// nearer (LESS), or present and the test absent.
#[derive(LogicBlock, Blank)]
pub struct LaneTest<const LANES: usize, const ZW: usize> {
    pub rd_z: Signal<In, Bits<ZW>>,
    pub s1_z: Signal<In, Bits<ZW>>,
    pub s2_z: Signal<In, Bits<ZW>>,
    pub s3_z: Signal<In, Bits<ZW>>,
    pub s1_mask: Signal<In, Bits<LANES>>,
    pub s2_write: Signal<In, Bits<LANES>>,
    pub s3_write: Signal<In, Bits<LANES>>,
    pub hit2: Signal<In, Bit>,
    pub hit3: Signal<In, Bit>,
    /// The depth test present.
    pub on: Signal<In, Bit>,
    pub pass: Signal<Out, Bits<LANES>>,
    /// The lane's first depth bit and its bit in the masks.
    at: Constant<Bits<16>>,
    lane_bit: Constant<Bits<LANES>>,
    z: Signal<Local, Bits<DEPTH>>,
    old_z: Signal<Local, Bits<DEPTH>>,
}

impl<const LANES: usize, const ZW: usize> LaneTest<LANES, ZW> {
    fn new(i: usize) -> Self {
        LaneTest {
            at: Constant::new((i * DEPTH).to_bits()),
            lane_bit: Constant::new((1usize << i).to_bits()),
            ..LaneTest::blank()
        }
    }
}

impl<const LANES: usize, const ZW: usize> Logic for LaneTest<LANES, ZW> {
    #[hdl_gen]
    fn update(&mut self) {
        self.old_z.next = bit_cast::<DEPTH, ZW>(self.rd_z.val() >> self.at.val());
        if ((self.s3_write.val() & self.lane_bit.val()) != 0) & self.hit3.val() {
            self.old_z.next = bit_cast::<DEPTH, ZW>(self.s3_z.val() >> self.at.val());
        }
        if ((self.s2_write.val() & self.lane_bit.val()) != 0) & self.hit2.val() {
            self.old_z.next = bit_cast::<DEPTH, ZW>(self.s2_z.val() >> self.at.val());
        }
        self.z.next = bit_cast::<DEPTH, ZW>(self.s1_z.val() >> self.at.val());
        self.pass.next = self.s1_mask.val() & self.lane_bit.val();
        if self.on.val() & (self.z.val() >= self.old_z.val()) {
            self.pass.next = 0.into();
        }
    }
}

/// `UNITS` entry: the pixel output unit, with the depth test as `params["DEPTH_TEST"]`
/// says (widths from `crate::widths`): [`PixelOut`] at `LANES` = 1, [`ChunkOut`] at 2, 4
/// or 8; with `params["BLEND"]` = 1 (absent: 0), [`PixelOutBlend`] (`LANES` = 1).
pub fn emit_pixel_out(params: &Params) -> Result<Emitted, String> {
    let parts = Parts::of(params)?;
    match (params.get("BLEND").copied().unwrap_or(0), params["LANES"]) {
        (0, _) => {}
        (1, 1) => return Ok(emit_unit("pixel_out", PixelOutBlend::new(&parts), params)),
        (1, n) => return Err(format!("pixel_out: BLEND = 1 at LANES = {n}: blending is built at one lane")),
        (b, _) => return Err(format!("pixel_out: BLEND = {b}: 0 or 1")),
    }
    Ok(match params["LANES"] {
        1 => emit_unit("pixel_out", PixelOut::new(&parts), params),
        2 => emit_unit("pixel_out", ChunkOut::<2, { ADDR - 1 }, { 2 * DEPTH }, { 2 * RGB }>::new(&parts), params),
        4 => emit_unit("pixel_out", ChunkOut::<4, { ADDR - 2 }, { 4 * DEPTH }, { 4 * RGB }>::new(&parts), params),
        8 => emit_unit("pixel_out", ChunkOut::<8, { ADDR - 3 }, { 8 * DEPTH }, { 8 * RGB }>::new(&parts), params),
        n => return Err(format!("pixel_out: LANES = {n}: 1, 2, 4 or 8")),
    })
}
