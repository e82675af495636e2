//! `gpu_top`: edgepaint as a core for an FPGA design (001's processor, Fig. 1, without its
//! texture and blending): the register block on an AXI4-Lite slave (`gpu_regs`), the
//! command parser reading vertex buffers through an AXI4 read master (`command_parser`),
//! the triangle queue (`triangle_queue`), the scanline rasterizer (`cull_sort`, setup with the divider, the edge walk, span) and
//! the pixels into system memory on AXI4 (`pixel_bus`).
//!
//! **A frame.** Writing START (`CONTROL` bit 0) while idle starts the parser at `VB_ADDR`.
//! The parser refuses a header whose screen the buffers do not hold (`SCREEN`, and the
//! pitches at 4 bytes a pixel; fault `SCREEN`), so no buffer makes the core write outside
//! them. When the header has passed its checks, its screen, back-face flag and background become
//! the rasterizer's and `pixel_bus`'s, and `pixel_bus` starts (clearing the buffers first
//! when CLEAR is set; triangles wait meanwhile). The parser's triangles go to `cull_sort`
//! through `triangle_queue` (512 triangles in block RAM), so that the parser reads ahead
//! while large triangles are drawn and runs of culled ones do not wait for it. The frame
//! ends when the parser has ended (the buffer's last triangle, or an error) and the queue,
//! the rasterizer and `pixel_bus` are empty: `IRQ` bit 0 is set, and
//! `FRAME_CYCLES` and `TRIANGLES` hold the frame's cycles (from START's cycle on) and the
//! triangles handed over.
//!
//! **`STATUS`**: bit 0 busy; bit 1 the frame failed (a parser fault or a bus error); bits
//! 4-7 the parser's fault code (`model::vertex_buffer::Fault`, 0 none); bit 8 a pixel
//! transfer answered with an error; bits 9-11 the parser's state.
//!
//! Emitted: `hdl-out/gpu_top.v`.

use super::command_parser::CommandParser;
use super::cull_sort::CullSort;
use super::gpu_regs::GpuRegs;
use super::links::{
    LiteSlave, ParsedSource, PixelSource, ReadMaster, SortedSource, TriangleSink, TriangleSource, WordReadMaster,
    WordWriteMaster,
};
use super::pixel_bus::PixelBus;
use super::raster_top::RasterTopCore;
use super::triangle_queue::TriangleQueue;
use super::widths::DIM;
use crate::emit::{emit_unit, Emitted};
use crate::link::Shared;
use crate::parts::Concat;
use crate::switch::Parts;
use crate::Params;
use rust_hdl::prelude::*;

/// The core: see the module documentation.
#[derive(LogicBlock, Default)]
pub struct GpuTop {
    pub clock: Signal<In, Clock>,
    /// The host's registers (`gpu_regs`) and the frame-done interrupt.
    pub host: LiteSlave,
    pub irq: Signal<Out, Bit>,
    /// The vertex buffer's reads (`command_parser`'s AXI4 read master, 128-bit).
    pub vb: ReadMaster,
    /// The depth buffer's reads and writes, the colour buffer's writes (`pixel_bus`).
    pub zr: WordReadMaster,
    pub zw: WordWriteMaster,
    pub cw: WordWriteMaster,
    regs: GpuRegs,
    parser: CommandParser<9, 32>,
    queue: TriangleQueue<9>,
    cull_sort: CullSort,
    core: RasterTopCore,
    pixel_bus: PixelBus,
    /// A frame running; its header seen; its cycles and triangles so far.
    busy: DFF<Bit>,
    header: DFF<Bit>,
    /// The parser has ended the frame: its frame or buffer done (one-cycle pulses), or a
    /// fault.
    ended: DFF<Bit>,
    cycles: DFF<Bits<32>>,
    triangles: DFF<Bits<32>>,
    /// The header's screen and back-face flag, and its background as `{R, G, B}`.
    width: DFF<Bits<DIM>>,
    height: DFF<Bits<DIM>>,
    cull_back: DFF<Bit>,
    rg: Concat<8, 8, 16>,
    rgb: Concat<16, 8, 24>,
    background: DFF<Bits<24>>,
    /// The widest screen the buffers hold: `SCREEN`'s width, and each pitch's pixels.
    max_width: Signal<Local, Bits<16>>,
    color_row: Signal<Local, Bits<16>>,
    depth_row: Signal<Local, Bits<16>>,
    done: Signal<Local, Bit>,
    status: Signal<Local, Bits<32>>,
}

impl GpuTop {
    /// The core with `k` multipliers in setup and an `l`-stage divider, and the
    /// rasterizer's optional parts as `parts` says.
    pub fn new(k: usize, l: usize, parts: &Parts) -> Result<GpuTop, String> {
        Ok(GpuTop {
            parser: CommandParser::new(),
            cull_sort: CullSort::new(parts),
            core: RasterTopCore::new(k, l, parts)?,
            ..Default::default()
        })
    }
}

impl Logic for GpuTop {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, busy, header, ended, cycles, triangles, width, height, cull_back, background);
        clock!(self, clock, regs, parser, queue, cull_sort, core, pixel_bus);
        LiteSlave::link(&mut self.host, &mut self.regs.host);
        ReadMaster::link(&mut self.vb, &mut self.parser.bus);
        WordReadMaster::link(&mut self.zr, &mut self.pixel_bus.zr);
        WordWriteMaster::link(&mut self.zw, &mut self.pixel_bus.zw);
        WordWriteMaster::link(&mut self.cw, &mut self.pixel_bus.cw);
        self.irq.next = self.regs.irq.val();

        // The frame: START while idle starts the parser.
        self.parser.start.next = self.regs.start.val() & !self.busy.q.val();
        self.parser.address.next = self.regs.vb_addr.val();
        // The screen the buffers hold (`model::gpu_top::screen_limit`).
        self.color_row.next = bit_cast::<16, 14>(self.regs.color_pitch.val().get_bits::<14>(2));
        self.depth_row.next = bit_cast::<16, 14>(self.regs.depth_pitch.val().get_bits::<14>(2));
        self.max_width.next = self.regs.screen.val().get_bits::<16>(0);
        if self.color_row.val() < self.max_width.val() {
            self.max_width.next = self.color_row.val();
        }
        if self.depth_row.val() < self.max_width.val() {
            self.max_width.next = self.depth_row.val();
        }
        self.parser.max_width.next = self.max_width.val();
        self.parser.max_height.next = self.regs.screen.val().get_bits::<16>(16);
        if self.busy.q.val() {
            self.cycles.d.next = self.cycles.q.val() + 1;
        }
        if self.parser.start.val() {
            self.busy.d.next = true;
            self.header.d.next = false;
            self.ended.d.next = false;
            self.cycles.d.next = 1.into();
            self.triangles.d.next = 0.into();
        }

        // The header: the screen and the clear.
        self.rg.hi.next = self.parser.background.val().get_bits::<8>(0);
        self.rg.lo.next = self.parser.background.val().get_bits::<8>(8);
        self.rgb.hi.next = self.rg.out.val();
        self.rgb.lo.next = self.parser.background.val().get_bits::<8>(16);
        self.pixel_bus.start.next = false;
        if self.busy.q.val() & !self.header.q.val() & self.parser.render_valid.val() {
            self.header.d.next = true;
            self.width.d.next = self.parser.width.val().get_bits::<DIM>(0);
            self.height.d.next = self.parser.height.val().get_bits::<DIM>(0);
            self.cull_back.d.next = self.parser.cull_back.val();
            self.background.d.next = self.rgb.out.val();
            self.pixel_bus.start.next = true;
        }
        self.pixel_bus.clear.next = self.regs.clear.val();
        self.pixel_bus.width.next = self.parser.width.val().get_bits::<DIM>(0);
        self.pixel_bus.height.next = self.parser.height.val().get_bits::<DIM>(0);
        self.pixel_bus.background.next = self.rgb.out.val();
        if self.header.q.val() {
            self.pixel_bus.width.next = self.width.q.val();
            self.pixel_bus.height.next = self.height.q.val();
            self.pixel_bus.background.next = self.background.q.val();
        }
        self.pixel_bus.color_base.next = self.regs.color_base.val();
        self.pixel_bus.color_pitch.next = self.regs.color_pitch.val();
        self.pixel_bus.depth_base.next = self.regs.depth_base.val();
        self.pixel_bus.depth_pitch.next = self.regs.depth_pitch.val();

        // Triangles: parser -> the queue -> cull_sort -> the core -> pixel_bus.
        self.cull_sort.width.next = self.width.q.val();
        self.cull_sort.height.next = self.height.q.val();
        self.cull_sort.cull_back.next = self.cull_back.q.val();
        self.core.width.next = self.width.q.val();
        self.core.height.next = self.height.q.val();
        Shared::<ParsedSource, TriangleSink>::join(&mut self.parser.out, &mut self.queue.inp);
        TriangleSource::join(&mut self.queue.out, &mut self.cull_sort.inp);
        SortedSource::join(&mut self.cull_sort.out, &mut self.core.inp);
        self.core.inp_last.next = false;
        self.core.hold.next = false;
        PixelSource::join(&mut self.core.out, &mut self.pixel_bus.inp);
        if self.parser.out.valid.val() & self.queue.inp.ready.val() {
            self.triangles.d.next = self.triangles.q.val() + 1;
        }

        // The end: the parser done or stopped, nothing in flight.
        if self.busy.q.val()
            & (self.parser.frame_done.val() | self.parser.buffer_done.val() | self.parser.fault.val().any())
        {
            self.ended.d.next = true;
        }
        self.done.next = self.busy.q.val()
            & (self.header.q.val() | self.parser.fault.val().any())
            & self.ended.q.val()
            & !self.parser.out.valid.val()
            & self.queue.idle.val()
            & self.cull_sort.idle.val()
            & self.core.idle.val()
            & self.pixel_bus.idle.val();
        if self.done.val() {
            self.busy.d.next = false;
        }
        self.regs.done.next = self.done.val();
        self.regs.frame_cycles.next = self.cycles.q.val();
        self.regs.triangles.next = self.triangles.q.val();
        self.status.next = 0.into();
        self.status.next = self.status.val().replace_bit(0, self.busy.q.val());
        self.status.next = self.status.val().replace_bit(1, self.parser.fault.val().any() | self.pixel_bus.error.val());
        for k in 0..4 {
            self.status.next = self.status.val().replace_bit(4 + k, self.parser.fault.val().get_bit(k));
        }
        self.status.next = self.status.val().replace_bit(8, self.pixel_bus.error.val());
        for k in 0..3 {
            self.status.next = self.status.val().replace_bit(9 + k, self.parser.state.val().get_bit(k));
        }
        self.regs.status.next = self.status.val();
    }
}

crate::pins!(GpuTop { clock: clock, inputs: [], outputs: [irq], links: [host, vb, zr, zw, cw] });

/// `UNITS` entry: the core with `params["K"]` setup multipliers and a `params["L"]`-stage
/// divider, every optional part of the rasterizer present.
pub fn emit_gpu_top(params: &Params) -> Result<Emitted, String> {
    if let Some(why) = super::command_parser::unsupported() {
        return Err(why);
    }
    let (k, l) = (params["K"] as usize, params["L"] as usize);
    Ok(emit_unit("gpu_top", GpuTop::new(k, l, &Parts::of(params)?)?, params))
}
