//! `raster_top`: the whole scanline rasterizer of papers 001 (Woo 2004) and 003 (Lee 2008)
//! as one design, from screen-space triangles to depth and colour writes.
//!
//! ```text
//!  triangles --> cull_sort --> triangle_setup --> edge_walk --> span FIFO --> span --> pixel_out <--> memory
//!  (inp_*,        003 Fig. 4   001 eq. 2, with     001/003       4 commands    003     depth test,   (rd_*, wr_*,
//!   inp_last)     1 cycle      the divider         Fig. 5        (bypass)      Fig. 6  2 cycles       mem_ready)
//! ```
//!
//! Every link is a valid/ready stream (a transfer on a rising edge with valid and ready
//! high) and each unit holds its work while the next one is not ready, so a stalled memory
//! (`mem_ready` low) stops the whole pipeline without losing anything. The links carry the
//! model's transactions field for field: `Sorted`, `SetupOut`, `SpanCmd`, `Pixel`.
//!
//! **A frame.** Clear the buffers (depth to z_max, colour to the background), set `width`,
//! `height` (1 to 2^N) and `cull_back`, send the triangles (the model's `Vtx`
//! words, `model::input::to_fixed`) with `inp_last` on the final one; `done` rises once
//! that triangle has gone through and every unit is empty, and stays high until the next
//! triangle is taken. `verdict_*` report each triangle `cull_sort` lets go (see
//! `rtl::cull_sort`).
//!
//! **Parameters.** `N`, the size class (10, 11 or 12; `crate::CLASSES`): screens up to
//! 2^N x 2^N and the number formats `Formats::for_n(N)` (`widths`), every port and
//! register as wide as that class needs; `model::raster_top::class_for` picks the class of
//! a screen as the model's default formats do. Resolution within the class: the `width`
//! and `height` ports. Units: all of the scanline pipeline; `K` and `L` choose setup's
//! multipliers and the divider's stages (`triangle_setup`). The span FIFO holds [`SPAN_FIFO`] commands, as
//! `model::cycles::Timing::span_fifo`.
//!
//! **Timing** (`model::cycles::scanline_frame` predicts it cycle for cycle when the memory
//! never stalls): cull_sort 1 cycle; setup `model::cycles::setup_latency`; the edge walk's
//! first command 2 cycles after it takes a triangle, then a scanline per cycle; the span
//! FIFO passes a command straight through when empty; span's first pixel 1 cycle after it
//! takes a command, then a pixel per cycle; the write 2 cycles after the pixel.
//! Model: `model::raster::render` with `Method::Scanline`. Emitted: `hdl-out/raster_top.v`.

use super::cull_sort::{CullSort, COLOR, INV_W, OUTCODE, XY, Z};
use super::edge_walk::EdgeWalk;
use crate::emit::{ports, verilog, Emitted};
use super::pixel_out::PixelOut;
use super::span::Span;
use super::triangle_setup::TriangleSetup;
use super::widths::{ADDR, C_ACC, DC, DEPTH, DIM, DZ, PIXEL, RGB, SCREEN, Z_ACC};
use crate::Params;
use rust_hdl::prelude::*;

/// Span commands the FIFO between the edge walk and span holds.
pub const SPAN_FIFO: usize = 4;

/// Whether a `D`-deep FIFO holding `count` entries is `full` or `empty`. (Alone in its
/// module, so that these outputs depend on the registered count only: Verilator orders a
/// module's logic as one block, and with the pushes and pops beside them the handshake
/// with the edge walk would look like a combinational loop.)
#[derive(LogicBlock)]
pub struct FifoLevel<const D: usize> {
    pub count: Signal<In, Bits<3>>,
    pub full: Signal<Out, Bit>,
    pub empty: Signal<Out, Bit>,
    depth: Constant<Bits<3>>,
}

impl<const D: usize> Default for FifoLevel<D> {
    fn default() -> Self {
        assert!((1..8).contains(&D), "FifoLevel<{D}>: 1 to 7 entries");
        FifoLevel {
            count: Default::default(),
            full: Default::default(),
            empty: Default::default(),
            depth: Constant::new(bits(D as u64)),
        }
    }
}

impl<const D: usize> Logic for FifoLevel<D> {
    #[hdl_gen]
    fn update(&mut self) {
        self.full.next = self.count.val() == self.depth.val();
        self.empty.next = self.count.val() == 0;
    }
}

/// One field of a `D`-deep FIFO: entries shift towards `head` on a pop; a push writes
/// entry `wr`.
#[derive(LogicBlock)]
pub struct FifoLane<const W: usize, const D: usize> {
    pub clock: Signal<In, Clock>,
    pub push: Signal<In, Bit>,
    pub pop: Signal<In, Bit>,
    pub wr: Signal<In, Bits<3>>,
    pub din: Signal<In, Bits<W>>,
    pub head: Signal<Out, Bits<W>>,
    e: [DFF<Bits<W>>; D],
}

impl<const W: usize, const D: usize> Default for FifoLane<W, D> {
    fn default() -> Self {
        FifoLane {
            clock: Default::default(),
            push: Default::default(),
            pop: Default::default(),
            wr: Default::default(),
            din: Default::default(),
            head: Default::default(),
            e: std::array::from_fn(|_| Default::default()),
        }
    }
}

impl<const W: usize, const D: usize> Logic for FifoLane<W, D> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..D {
            self.e[i].clock.next = self.clock.val();
            self.e[i].d.next = self.e[i].q.val();
        }
        if self.pop.val() {
            for i in 0..(D - 1) {
                self.e[i].d.next = self.e[i + 1].q.val();
            }
        }
        if self.push.val() {
            for i in 0..D {
                if self.wr.val().index() == i {
                    self.e[i].d.next = self.din.val();
                }
            }
        }
        self.head.next = self.e[0].q.val();
    }
}

/// The span command FIFO between the edge walk and span (`model::cycles`: "a 4-deep FIFO
/// before it"): `SpanCmd` on `inp_*` and `out_*`. Empty, it passes a command straight
/// through in the same cycle; `inp_ready` is low only when full.
#[derive(LogicBlock, Default)]
pub struct SpanFifo {
    pub clock: Signal<In, Clock>,
    pub inp_valid: Signal<In, Bit>,
    pub inp_ready: Signal<Out, Bit>,
    pub inp_y: Signal<In, Bits<SCREEN>>,
    pub inp_xl: Signal<In, Bits<PIXEL>>,
    pub inp_xr: Signal<In, Bits<PIXEL>>,
    pub inp_left_z: Signal<In, Bits<Z_ACC>>,
    pub inp_left_c0: Signal<In, Bits<C_ACC>>,
    pub inp_left_c1: Signal<In, Bits<C_ACC>>,
    pub inp_left_c2: Signal<In, Bits<C_ACC>>,
    pub inp_right_z: Signal<In, Bits<Z_ACC>>,
    pub inp_right_c0: Signal<In, Bits<C_ACC>>,
    pub inp_right_c1: Signal<In, Bits<C_ACC>>,
    pub inp_right_c2: Signal<In, Bits<C_ACC>>,
    pub inp_ddx_z: Signal<In, Bits<DZ>>,
    pub inp_ddx_c0: Signal<In, Bits<DC>>,
    pub inp_ddx_c1: Signal<In, Bits<DC>>,
    pub inp_ddx_c2: Signal<In, Bits<DC>>,
    pub out_valid: Signal<Out, Bit>,
    pub out_ready: Signal<In, Bit>,
    pub out_y: Signal<Out, Bits<SCREEN>>,
    pub out_xl: Signal<Out, Bits<PIXEL>>,
    pub out_xr: Signal<Out, Bits<PIXEL>>,
    pub out_left_z: Signal<Out, Bits<Z_ACC>>,
    pub out_left_c0: Signal<Out, Bits<C_ACC>>,
    pub out_left_c1: Signal<Out, Bits<C_ACC>>,
    pub out_left_c2: Signal<Out, Bits<C_ACC>>,
    pub out_right_z: Signal<Out, Bits<Z_ACC>>,
    pub out_right_c0: Signal<Out, Bits<C_ACC>>,
    pub out_right_c1: Signal<Out, Bits<C_ACC>>,
    pub out_right_c2: Signal<Out, Bits<C_ACC>>,
    pub out_ddx_z: Signal<Out, Bits<DZ>>,
    pub out_ddx_c0: Signal<Out, Bits<DC>>,
    pub out_ddx_c1: Signal<Out, Bits<DC>>,
    pub out_ddx_c2: Signal<Out, Bits<DC>>,
    /// No command held.
    pub empty: Signal<Out, Bit>,
    /// Entries held, and whether that is all or none.
    count: DFF<Bits<3>>,
    level: FifoLevel<SPAN_FIFO>,
    /// The entry a push writes, counted after this cycle's pop.
    wr: Signal<Local, Bits<3>>,
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
    push: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
}

/// `SpanFifo`'s kernel, with each lane `$f` wired from `$inp` to `$out`: its head, or the
/// input itself when the FIFO is empty. (A macro writes the fifteen lanes out before
/// `#[hdl_gen]` reads the kernel.)
macro_rules! span_fifo_logic {
    ($($f:ident: $inp:ident -> $out:ident),* $(,)?) => {
        impl Logic for SpanFifo {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, count);
                self.level.count.next = self.count.q.val();
                self.inp_ready.next = !self.level.full.val();
                self.out_valid.next = !self.level.empty.val() | self.inp_valid.val();
                self.empty.next = self.level.empty.val();
                // Empty and taken at once: the command passes straight through.
                self.push.next = self.inp_valid.val() & !self.level.full.val() & !(self.level.empty.val() & self.out_ready.val());
                self.pop.next = !self.level.empty.val() & self.out_ready.val();
                self.wr.next = self.count.q.val();
                if self.pop.val() {
                    self.wr.next = self.count.q.val() - 1;
                }
                if self.push.val() & !self.pop.val() {
                    self.count.d.next = self.count.q.val() + 1;
                }
                if self.pop.val() & !self.push.val() {
                    self.count.d.next = self.count.q.val() - 1;
                }
                $(
                    self.$f.clock.next = self.clock.val();
                    self.$f.push.next = self.push.val();
                    self.$f.pop.next = self.pop.val();
                    self.$f.wr.next = self.wr.val();
                    self.$f.din.next = self.$inp.val();
                    self.$out.next = self.$f.head.val();
                    if self.level.empty.val() {
                        self.$out.next = self.$inp.val();
                    }
                )*
            }
        }
    };
}

span_fifo_logic!(
    y: inp_y -> out_y,
    xl: inp_xl -> out_xl,
    xr: inp_xr -> out_xr,
    left_z: inp_left_z -> out_left_z,
    left_c0: inp_left_c0 -> out_left_c0,
    left_c1: inp_left_c1 -> out_left_c1,
    left_c2: inp_left_c2 -> out_left_c2,
    right_z: inp_right_z -> out_right_z,
    right_c0: inp_right_c0 -> out_right_c0,
    right_c1: inp_right_c1 -> out_right_c1,
    right_c2: inp_right_c2 -> out_right_c2,
    ddx_z: inp_ddx_z -> out_ddx_z,
    ddx_c0: inp_ddx_c0 -> out_ddx_c0,
    ddx_c1: inp_ddx_c1 -> out_ddx_c1,
    ddx_c2: inp_ddx_c2 -> out_ddx_c2,
);

/// The scanline rasterizer: see the module documentation. Ports: the triangle stream
/// `inp_*` (`model::input::Vtx` per vertex, `cull_sort`'s inputs), `cull_sort`'s verdicts,
/// `pixel_out`'s memory port, and `done`.
#[derive(LogicBlock)]
pub struct RasterTop {
    pub clock: Signal<In, Clock>,
    /// Screen size in pixels, 1 to 2^CLASS each (the size class); constant during a frame.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// Drop back faces (`model::cull_sort::Cull::Back`).
    pub cull_back: Signal<In, Bit>,
    pub inp_valid: Signal<In, Bit>,
    pub inp_ready: Signal<Out, Bit>,
    /// The frame's last triangle.
    pub inp_last: Signal<In, Bit>,
    pub inp_v0_x: Signal<In, Bits<XY>>,
    pub inp_v0_y: Signal<In, Bits<XY>>,
    pub inp_v0_z: Signal<In, Bits<Z>>,
    pub inp_v0_c0: Signal<In, Bits<COLOR>>,
    pub inp_v0_c1: Signal<In, Bits<COLOR>>,
    pub inp_v0_c2: Signal<In, Bits<COLOR>>,
    pub inp_v0_iw: Signal<In, Bits<INV_W>>,
    pub inp_v1_x: Signal<In, Bits<XY>>,
    pub inp_v1_y: Signal<In, Bits<XY>>,
    pub inp_v1_z: Signal<In, Bits<Z>>,
    pub inp_v1_c0: Signal<In, Bits<COLOR>>,
    pub inp_v1_c1: Signal<In, Bits<COLOR>>,
    pub inp_v1_c2: Signal<In, Bits<COLOR>>,
    pub inp_v1_iw: Signal<In, Bits<INV_W>>,
    pub inp_v2_x: Signal<In, Bits<XY>>,
    pub inp_v2_y: Signal<In, Bits<XY>>,
    pub inp_v2_z: Signal<In, Bits<Z>>,
    pub inp_v2_c0: Signal<In, Bits<COLOR>>,
    pub inp_v2_c1: Signal<In, Bits<COLOR>>,
    pub inp_v2_c2: Signal<In, Bits<COLOR>>,
    pub inp_v2_iw: Signal<In, Bits<INV_W>>,
    /// A triangle leaves `cull_sort` (passed or rejected), with why (`rtl::cull_sort`).
    pub verdict_valid: Signal<Out, Bit>,
    pub verdict_code: Signal<Out, Bits<2>>,
    pub verdict_outside: Signal<Out, Bits<OUTCODE>>,
    /// The memory port of `pixel_out` (see `rtl::pixel_out`).
    pub mem_ready: Signal<In, Bit>,
    pub rd_en: Signal<Out, Bit>,
    pub rd_addr: Signal<Out, Bits<ADDR>>,
    pub rd_z: Signal<In, Bits<DEPTH>>,
    pub wr_en: Signal<Out, Bit>,
    pub wr_addr: Signal<Out, Bits<ADDR>>,
    pub wr_z: Signal<Out, Bits<DEPTH>>,
    pub wr_rgb: Signal<Out, Bits<RGB>>,
    /// The frame is drawn: the `inp_last` triangle has been taken and every unit is empty.
    pub done: Signal<Out, Bit>,
    cull_sort: CullSort,
    triangle_setup: TriangleSetup,
    edge_walk: EdgeWalk,
    fifo: SpanFifo,
    span: Span,
    pixel_out: PixelOut,
    /// The last triangle taken had `inp_last`.
    last_in: DFF<Bit>,
    /// Setup holds a triangle (taken from cull_sort, not yet handed to the edge walk).
    in_setup: DFF<Bit>,
}

impl RasterTop {
    /// The rasterizer with `k` multipliers in setup and an `l`-stage divider.
    pub fn new(k: usize, l: usize) -> Result<RasterTop, String> {
        Ok(RasterTop {
            clock: Default::default(),
            width: Default::default(),
            height: Default::default(),
            cull_back: Default::default(),
            inp_valid: Default::default(),
            inp_ready: Default::default(),
            inp_last: Default::default(),
            inp_v0_x: Default::default(),
            inp_v0_y: Default::default(),
            inp_v0_z: Default::default(),
            inp_v0_c0: Default::default(),
            inp_v0_c1: Default::default(),
            inp_v0_c2: Default::default(),
            inp_v0_iw: Default::default(),
            inp_v1_x: Default::default(),
            inp_v1_y: Default::default(),
            inp_v1_z: Default::default(),
            inp_v1_c0: Default::default(),
            inp_v1_c1: Default::default(),
            inp_v1_c2: Default::default(),
            inp_v1_iw: Default::default(),
            inp_v2_x: Default::default(),
            inp_v2_y: Default::default(),
            inp_v2_z: Default::default(),
            inp_v2_c0: Default::default(),
            inp_v2_c1: Default::default(),
            inp_v2_c2: Default::default(),
            inp_v2_iw: Default::default(),
            verdict_valid: Default::default(),
            verdict_code: Default::default(),
            verdict_outside: Default::default(),
            mem_ready: Default::default(),
            rd_en: Default::default(),
            rd_addr: Default::default(),
            rd_z: Default::default(),
            wr_en: Default::default(),
            wr_addr: Default::default(),
            wr_z: Default::default(),
            wr_rgb: Default::default(),
            done: Default::default(),
            cull_sort: Default::default(),
            triangle_setup: TriangleSetup::new(k, l)?,
            edge_walk: Default::default(),
            fifo: Default::default(),
            span: Default::default(),
            pixel_out: Default::default(),
            last_in: Default::default(),
            in_setup: Default::default(),
        })
    }
}

impl Logic for RasterTop {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last_in, in_setup);
        clock!(self, clock, cull_sort, triangle_setup, edge_walk, fifo, span, pixel_out);

        // Triangles in: cull_sort.
        self.cull_sort.width.next = self.width.val();
        self.cull_sort.height.next = self.height.val();
        self.cull_sort.cull_back.next = self.cull_back.val();
        self.cull_sort.inp_valid.next = self.inp_valid.val();
        self.inp_ready.next = self.cull_sort.inp_ready.val();
        self.cull_sort.inp_v0_x.next = self.inp_v0_x.val();
        self.cull_sort.inp_v0_y.next = self.inp_v0_y.val();
        self.cull_sort.inp_v0_z.next = self.inp_v0_z.val();
        self.cull_sort.inp_v0_c0.next = self.inp_v0_c0.val();
        self.cull_sort.inp_v0_c1.next = self.inp_v0_c1.val();
        self.cull_sort.inp_v0_c2.next = self.inp_v0_c2.val();
        self.cull_sort.inp_v0_iw.next = self.inp_v0_iw.val();
        self.cull_sort.inp_v1_x.next = self.inp_v1_x.val();
        self.cull_sort.inp_v1_y.next = self.inp_v1_y.val();
        self.cull_sort.inp_v1_z.next = self.inp_v1_z.val();
        self.cull_sort.inp_v1_c0.next = self.inp_v1_c0.val();
        self.cull_sort.inp_v1_c1.next = self.inp_v1_c1.val();
        self.cull_sort.inp_v1_c2.next = self.inp_v1_c2.val();
        self.cull_sort.inp_v1_iw.next = self.inp_v1_iw.val();
        self.cull_sort.inp_v2_x.next = self.inp_v2_x.val();
        self.cull_sort.inp_v2_y.next = self.inp_v2_y.val();
        self.cull_sort.inp_v2_z.next = self.inp_v2_z.val();
        self.cull_sort.inp_v2_c0.next = self.inp_v2_c0.val();
        self.cull_sort.inp_v2_c1.next = self.inp_v2_c1.val();
        self.cull_sort.inp_v2_c2.next = self.inp_v2_c2.val();
        self.cull_sort.inp_v2_iw.next = self.inp_v2_iw.val();
        self.verdict_valid.next = self.cull_sort.verdict_valid.val();
        self.verdict_code.next = self.cull_sort.verdict_code.val();
        self.verdict_outside.next = self.cull_sort.verdict_outside.val();

        // cull_sort -> triangle_setup: the sorted triangle (`inv_w` is the vector method's).
        self.triangle_setup.inp_valid.next = self.cull_sort.out_valid.val();
        self.cull_sort.out_ready.next = self.triangle_setup.inp_ready.val();
        self.triangle_setup.inp_crosses.next = self.cull_sort.out_crosses.val();
        self.triangle_setup.inp_v0_x.next = self.cull_sort.out_v0_x.val();
        self.triangle_setup.inp_v0_y.next = self.cull_sort.out_v0_y.val();
        self.triangle_setup.inp_v0_z.next = self.cull_sort.out_v0_z.val();
        self.triangle_setup.inp_v0_c0.next = self.cull_sort.out_v0_c0.val();
        self.triangle_setup.inp_v0_c1.next = self.cull_sort.out_v0_c1.val();
        self.triangle_setup.inp_v0_c2.next = self.cull_sort.out_v0_c2.val();
        self.triangle_setup.inp_v1_x.next = self.cull_sort.out_v1_x.val();
        self.triangle_setup.inp_v1_y.next = self.cull_sort.out_v1_y.val();
        self.triangle_setup.inp_v1_z.next = self.cull_sort.out_v1_z.val();
        self.triangle_setup.inp_v1_c0.next = self.cull_sort.out_v1_c0.val();
        self.triangle_setup.inp_v1_c1.next = self.cull_sort.out_v1_c1.val();
        self.triangle_setup.inp_v1_c2.next = self.cull_sort.out_v1_c2.val();
        self.triangle_setup.inp_v2_x.next = self.cull_sort.out_v2_x.val();
        self.triangle_setup.inp_v2_y.next = self.cull_sort.out_v2_y.val();
        self.triangle_setup.inp_v2_z.next = self.cull_sort.out_v2_z.val();
        self.triangle_setup.inp_v2_c0.next = self.cull_sort.out_v2_c0.val();
        self.triangle_setup.inp_v2_c1.next = self.cull_sort.out_v2_c1.val();
        self.triangle_setup.inp_v2_c2.next = self.cull_sort.out_v2_c2.val();

        // triangle_setup -> edge_walk: `SetupOut`, one to one.
        self.edge_walk.height.next = self.height.val();
        self.edge_walk.inp_valid.next = self.triangle_setup.out_valid.val();
        self.triangle_setup.out_ready.next = self.edge_walk.inp_ready.val();
        self.edge_walk.inp_walk.next = self.triangle_setup.out_walk.val();
        self.edge_walk.inp_maj_left.next = self.triangle_setup.out_maj_left.val();
        self.edge_walk.inp_maj_j.next = self.triangle_setup.out_maj_j.val();
        self.edge_walk.inp_maj_count.next = self.triangle_setup.out_maj_count.val();
        self.edge_walk.inp_maj_x.next = self.triangle_setup.out_maj_x.val();
        self.edge_walk.inp_maj_r.next = self.triangle_setup.out_maj_r.val();
        self.edge_walk.inp_maj_q.next = self.triangle_setup.out_maj_q.val();
        self.edge_walk.inp_maj_rho.next = self.triangle_setup.out_maj_rho.val();
        self.edge_walk.inp_maj_d.next = self.triangle_setup.out_maj_d.val();
        self.edge_walk.inp_maj_at_z.next = self.triangle_setup.out_maj_at_z.val();
        self.edge_walk.inp_maj_at_c0.next = self.triangle_setup.out_maj_at_c0.val();
        self.edge_walk.inp_maj_at_c1.next = self.triangle_setup.out_maj_at_c1.val();
        self.edge_walk.inp_maj_at_c2.next = self.triangle_setup.out_maj_at_c2.val();
        self.edge_walk.inp_maj_inc0_z.next = self.triangle_setup.out_maj_inc0_z.val();
        self.edge_walk.inp_maj_inc0_c0.next = self.triangle_setup.out_maj_inc0_c0.val();
        self.edge_walk.inp_maj_inc0_c1.next = self.triangle_setup.out_maj_inc0_c1.val();
        self.edge_walk.inp_maj_inc0_c2.next = self.triangle_setup.out_maj_inc0_c2.val();
        self.edge_walk.inp_maj_inc1_z.next = self.triangle_setup.out_maj_inc1_z.val();
        self.edge_walk.inp_maj_inc1_c0.next = self.triangle_setup.out_maj_inc1_c0.val();
        self.edge_walk.inp_maj_inc1_c1.next = self.triangle_setup.out_maj_inc1_c1.val();
        self.edge_walk.inp_maj_inc1_c2.next = self.triangle_setup.out_maj_inc1_c2.val();
        self.edge_walk.inp_short0_j.next = self.triangle_setup.out_short0_j.val();
        self.edge_walk.inp_short0_count.next = self.triangle_setup.out_short0_count.val();
        self.edge_walk.inp_short0_x.next = self.triangle_setup.out_short0_x.val();
        self.edge_walk.inp_short0_r.next = self.triangle_setup.out_short0_r.val();
        self.edge_walk.inp_short0_q.next = self.triangle_setup.out_short0_q.val();
        self.edge_walk.inp_short0_rho.next = self.triangle_setup.out_short0_rho.val();
        self.edge_walk.inp_short0_d.next = self.triangle_setup.out_short0_d.val();
        self.edge_walk.inp_short0_at_z.next = self.triangle_setup.out_short0_at_z.val();
        self.edge_walk.inp_short0_at_c0.next = self.triangle_setup.out_short0_at_c0.val();
        self.edge_walk.inp_short0_at_c1.next = self.triangle_setup.out_short0_at_c1.val();
        self.edge_walk.inp_short0_at_c2.next = self.triangle_setup.out_short0_at_c2.val();
        self.edge_walk.inp_short0_inc0_z.next = self.triangle_setup.out_short0_inc0_z.val();
        self.edge_walk.inp_short0_inc0_c0.next = self.triangle_setup.out_short0_inc0_c0.val();
        self.edge_walk.inp_short0_inc0_c1.next = self.triangle_setup.out_short0_inc0_c1.val();
        self.edge_walk.inp_short0_inc0_c2.next = self.triangle_setup.out_short0_inc0_c2.val();
        self.edge_walk.inp_short0_inc1_z.next = self.triangle_setup.out_short0_inc1_z.val();
        self.edge_walk.inp_short0_inc1_c0.next = self.triangle_setup.out_short0_inc1_c0.val();
        self.edge_walk.inp_short0_inc1_c1.next = self.triangle_setup.out_short0_inc1_c1.val();
        self.edge_walk.inp_short0_inc1_c2.next = self.triangle_setup.out_short0_inc1_c2.val();
        self.edge_walk.inp_short1_j.next = self.triangle_setup.out_short1_j.val();
        self.edge_walk.inp_short1_count.next = self.triangle_setup.out_short1_count.val();
        self.edge_walk.inp_short1_x.next = self.triangle_setup.out_short1_x.val();
        self.edge_walk.inp_short1_r.next = self.triangle_setup.out_short1_r.val();
        self.edge_walk.inp_short1_q.next = self.triangle_setup.out_short1_q.val();
        self.edge_walk.inp_short1_rho.next = self.triangle_setup.out_short1_rho.val();
        self.edge_walk.inp_short1_d.next = self.triangle_setup.out_short1_d.val();
        self.edge_walk.inp_short1_at_z.next = self.triangle_setup.out_short1_at_z.val();
        self.edge_walk.inp_short1_at_c0.next = self.triangle_setup.out_short1_at_c0.val();
        self.edge_walk.inp_short1_at_c1.next = self.triangle_setup.out_short1_at_c1.val();
        self.edge_walk.inp_short1_at_c2.next = self.triangle_setup.out_short1_at_c2.val();
        self.edge_walk.inp_short1_inc0_z.next = self.triangle_setup.out_short1_inc0_z.val();
        self.edge_walk.inp_short1_inc0_c0.next = self.triangle_setup.out_short1_inc0_c0.val();
        self.edge_walk.inp_short1_inc0_c1.next = self.triangle_setup.out_short1_inc0_c1.val();
        self.edge_walk.inp_short1_inc0_c2.next = self.triangle_setup.out_short1_inc0_c2.val();
        self.edge_walk.inp_short1_inc1_z.next = self.triangle_setup.out_short1_inc1_z.val();
        self.edge_walk.inp_short1_inc1_c0.next = self.triangle_setup.out_short1_inc1_c0.val();
        self.edge_walk.inp_short1_inc1_c1.next = self.triangle_setup.out_short1_inc1_c1.val();
        self.edge_walk.inp_short1_inc1_c2.next = self.triangle_setup.out_short1_inc1_c2.val();
        self.edge_walk.inp_ddx_z.next = self.triangle_setup.out_ddx_z.val();
        self.edge_walk.inp_ddx_c0.next = self.triangle_setup.out_ddx_c0.val();
        self.edge_walk.inp_ddx_c1.next = self.triangle_setup.out_ddx_c1.val();
        self.edge_walk.inp_ddx_c2.next = self.triangle_setup.out_ddx_c2.val();

        // edge_walk -> span FIFO -> span: `SpanCmd`.
        self.fifo.inp_valid.next = self.edge_walk.out_valid.val();
        self.edge_walk.out_ready.next = self.fifo.inp_ready.val();
        self.span.width.next = self.width.val();
        self.span.inp_valid.next = self.fifo.out_valid.val();
        self.fifo.out_ready.next = self.span.inp_ready.val();
        self.fifo.inp_y.next = self.edge_walk.out_y.val();
        self.fifo.inp_xl.next = self.edge_walk.out_xl.val();
        self.fifo.inp_xr.next = self.edge_walk.out_xr.val();
        self.fifo.inp_left_z.next = self.edge_walk.out_left_z.val();
        self.fifo.inp_left_c0.next = self.edge_walk.out_left_c0.val();
        self.fifo.inp_left_c1.next = self.edge_walk.out_left_c1.val();
        self.fifo.inp_left_c2.next = self.edge_walk.out_left_c2.val();
        self.fifo.inp_right_z.next = self.edge_walk.out_right_z.val();
        self.fifo.inp_right_c0.next = self.edge_walk.out_right_c0.val();
        self.fifo.inp_right_c1.next = self.edge_walk.out_right_c1.val();
        self.fifo.inp_right_c2.next = self.edge_walk.out_right_c2.val();
        self.fifo.inp_ddx_z.next = self.edge_walk.out_ddx_z.val();
        self.fifo.inp_ddx_c0.next = self.edge_walk.out_ddx_c0.val();
        self.fifo.inp_ddx_c1.next = self.edge_walk.out_ddx_c1.val();
        self.fifo.inp_ddx_c2.next = self.edge_walk.out_ddx_c2.val();
        self.span.inp_y.next = self.fifo.out_y.val();
        self.span.inp_xl.next = self.fifo.out_xl.val();
        self.span.inp_xr.next = self.fifo.out_xr.val();
        self.span.inp_left_z.next = self.fifo.out_left_z.val();
        self.span.inp_left_c0.next = self.fifo.out_left_c0.val();
        self.span.inp_left_c1.next = self.fifo.out_left_c1.val();
        self.span.inp_left_c2.next = self.fifo.out_left_c2.val();
        self.span.inp_right_z.next = self.fifo.out_right_z.val();
        self.span.inp_right_c0.next = self.fifo.out_right_c0.val();
        self.span.inp_right_c1.next = self.fifo.out_right_c1.val();
        self.span.inp_right_c2.next = self.fifo.out_right_c2.val();
        self.span.inp_ddx_z.next = self.fifo.out_ddx_z.val();
        self.span.inp_ddx_c0.next = self.fifo.out_ddx_c0.val();
        self.span.inp_ddx_c1.next = self.fifo.out_ddx_c1.val();
        self.span.inp_ddx_c2.next = self.fifo.out_ddx_c2.val();

        // span -> pixel_out: `Pixel`; pixel_out <-> memory.
        self.pixel_out.inp_valid.next = self.span.out_valid.val();
        self.span.out_ready.next = self.pixel_out.inp_ready.val();
        self.pixel_out.inp_x.next = self.span.out_x.val();
        self.pixel_out.inp_y.next = self.span.out_y.val();
        self.pixel_out.inp_z.next = self.span.out_z.val();
        self.pixel_out.inp_rgb0.next = self.span.out_rgb0.val();
        self.pixel_out.inp_rgb1.next = self.span.out_rgb1.val();
        self.pixel_out.inp_rgb2.next = self.span.out_rgb2.val();
        self.pixel_out.mem_ready.next = self.mem_ready.val();
        self.pixel_out.rd_z.next = self.rd_z.val();
        self.rd_en.next = self.pixel_out.rd_en.val();
        self.rd_addr.next = self.pixel_out.rd_addr.val();
        self.wr_en.next = self.pixel_out.wr_en.val();
        self.wr_addr.next = self.pixel_out.wr_addr.val();
        self.wr_z.next = self.pixel_out.wr_z.val();
        self.wr_rgb.next = self.pixel_out.wr_rgb.val();

        // Frame done: after the last triangle, every unit empty.
        if self.inp_valid.val() & self.cull_sort.inp_ready.val() {
            self.last_in.d.next = self.inp_last.val();
        }
        if self.cull_sort.out_valid.val() & self.triangle_setup.inp_ready.val() {
            self.in_setup.d.next = true;
        } else if self.triangle_setup.out_valid.val() & self.edge_walk.inp_ready.val() {
            self.in_setup.d.next = false;
        }
        self.done.next = self.last_in.q.val()
            & !self.cull_sort.out_valid.val()
            & !self.in_setup.q.val()
            & self.edge_walk.inp_ready.val()
            & self.fifo.empty.val()
            & self.span.idle.val()
            & self.pixel_out.idle.val();
    }
}

crate::pins!(RasterTop {
    clock: clock,
    inputs: [
        width, height, cull_back, inp_valid, inp_last, inp_v0_x, inp_v0_y, inp_v0_z, inp_v0_c0, inp_v0_c1, inp_v0_c2,
        inp_v0_iw, inp_v1_x, inp_v1_y, inp_v1_z, inp_v1_c0, inp_v1_c1, inp_v1_c2, inp_v1_iw, inp_v2_x, inp_v2_y,
        inp_v2_z, inp_v2_c0, inp_v2_c1, inp_v2_c2, inp_v2_iw, mem_ready, rd_z
    ],
    outputs: [
        inp_ready,
        verdict_valid,
        verdict_code,
        verdict_outside,
        rd_en,
        rd_addr,
        wr_en,
        wr_addr,
        wr_z,
        wr_rgb,
        done
    ],
});

/// `UNITS` entry: the rasterizer with `params["K"]` setup multipliers and a
/// `params["L"]`-stage divider.
pub fn emit_raster_top(params: &Params) -> Result<Emitted, String> {
    let mut u = RasterTop::new(params["K"] as usize, params["L"] as usize)?;
    u.connect_all();
    Ok(Emitted { unit: "raster_top", params: params.clone(), ports: ports(&u), verilog: verilog("raster_top", &u) })
}
