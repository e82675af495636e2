//! `raster_top`: the whole scanline rasterizer of papers 001 (Woo 2004) and 003 (Lee 2008)
//! as one design, from screen-space triangles to depth and colour writes.
//!
//! ```text
//!  triangles --> cull_sort --> triangle_setup --> edge_walk --> span FIFO --> span --> pixel_out <--> memory
//!  (inp$*,        003 Fig. 4   001 eq. 2, with     001/003       4 commands    003     depth test,   (rd_*, wr_*,
//!   inp_last)     1 cycle      the divider         Fig. 5        (bypass)      Fig. 6  2 cycles       mem_ready)
//! ```
//!
//! Every link is a valid/ready stream (a transfer on a rising edge with valid and ready
//! high) and each unit holds its work while the next one is not ready, so a stalled memory
//! (`mem_ready` low) stops the whole pipeline without losing anything. The links carry the
//! model's transactions field for field: `Sorted`, `TriangleSetupOut`, `SpanCmd`, `Pixel`.
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
//! register as wide as that class needs; `fx::Build::for_screen` picks the class of
//! a screen as the model's default formats do. Resolution within the class: the `width`
//! and `height` ports. `K` and `L` choose setup's multipliers and the divider's stages
//! (`triangle_setup`). The span FIFO holds `span_fifo::SPAN_FIFO` commands, as
//! `model::cycles::Timing::span_fifo`.
//!
//! **Units present.** [`RasterCore`] (setup with the divider, edge walk, span FIFO, span)
//! always; `CULL_SORT = 0` leaves out `cull_sort` (the host culls and sorts: sorted
//! triangles with their clip crossings in, [`RasterTopSorted`]), `PIXEL_OUT = 0` leaves
//! out `pixel_out` (the fragment stream leaves on `out$*` for the host's own depth test and
//! memory, [`RasterTopFragments`]), both give [`RasterTopCore`]. Every variant is emitted
//! as module `raster_top`; `model::cycles::Timing` has the same two switches.
//!
//! **Timing** (`model::cycles::scanline_frame` predicts it cycle for cycle when the memory
//! never stalls): cull_sort 1 cycle; setup `model::cycles::setup_latency`; the edge walk's
//! first command 2 cycles after it takes a triangle, then a scanline per cycle; the span
//! FIFO passes a command straight through when empty; span's first pixel 1 cycle after it
//! takes a command, then a pixel per cycle; the write 2 cycles after the pixel.
//! Model: `model::render::render` with `Method::Scanline`. Emitted: `hdl-out/raster_top.v`.

use super::cull_sort::{CullSort, OUTCODE};
use super::edge_walk::EdgeWalk;
use super::links::{PixelSource, SortedSink, SortedSource, SpanCmdSource, TriangleSetupSource, TriangleSink};
use super::pixel_out::PixelOut;
use super::span::Span;
use super::span_fifo::SpanFifo;
use super::triangle_setup::TriangleSetup;
use super::widths::{ADDR, DEPTH, DIM, RGB};
use crate::emit::{ports, verilog, Emitted};
use crate::Params;
use rust_hdl::prelude::*;

/// The part of `raster_top` that is always present: `triangle_setup` (with the divider)
/// -> `edge_walk` -> the span FIFO -> `span`. Sorted triangles in (`model::cull_sort::Sorted`
/// on the link `inp`), fragments out (`model::span::Pixel` on `span`'s
/// `out$*` ports); `idle` when it holds no work.
#[derive(LogicBlock)]
pub struct RasterCore {
    pub clock: Signal<In, Clock>,
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// The sorted triangles in.
    pub inp: SortedSink,
    /// The fragments.
    pub out: PixelSource,
    /// No triangle, span command or pixel held.
    pub idle: Signal<Out, Bit>,
    triangle_setup: TriangleSetup,
    edge_walk: EdgeWalk,
    fifo: SpanFifo,
    span: Span,
    /// Setup holds a triangle (taken, not yet handed to the edge walk).
    in_setup: DFF<Bit>,
}

impl RasterCore {
    /// The core with `k` multipliers in setup and an `l`-stage divider.
    pub fn new(k: usize, l: usize) -> Result<RasterCore, String> {
        Ok(RasterCore {
            clock: Default::default(),
            width: Default::default(),
            height: Default::default(),
            inp: Default::default(),
            out: Default::default(),
            idle: Default::default(),
            triangle_setup: TriangleSetup::new(k, l)?,
            edge_walk: Default::default(),
            fifo: Default::default(),
            span: Default::default(),
            in_setup: Default::default(),
        })
    }
}

impl Logic for RasterCore {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, in_setup);
        clock!(self, clock, triangle_setup, edge_walk, fifo, span);
        // Sorted triangles in.
        SortedSink::link(&mut self.inp, &mut self.triangle_setup.inp);

        // triangle_setup -> edge_walk: `TriangleSetupOut`.
        self.edge_walk.height.next = self.height.val();
        TriangleSetupSource::join(&mut self.triangle_setup.out, &mut self.edge_walk.inp);

        // edge_walk -> span FIFO -> span: `SpanCmd`.
        self.span.width.next = self.width.val();
        SpanCmdSource::join(&mut self.edge_walk.out, &mut self.fifo.inp);
        SpanCmdSource::join(&mut self.fifo.out, &mut self.span.inp);

        // Fragments out.
        PixelSource::link(&mut self.out, &mut self.span.out);

        if self.inp.valid.val() & self.inp.ready.val() {
            self.in_setup.d.next = true;
        } else if self.triangle_setup.out.valid.val() & self.edge_walk.inp.ready.val() {
            self.in_setup.d.next = false;
        }
        self.idle.next = !self.in_setup.q.val()
            & self.edge_walk.inp.ready.val()
            & self.fifo.empty.val()
            & self.span.idle.val();
    }
}

/// Declares one `raster_top` of the units the parameters choose: the [`RasterCore`] with
/// `cull_sort` in front of it (`cull_sort: <its field>`: triangles in on the link `inp`) or
/// not (`sorted: <the link's field>`: the host sends sorted triangles with their clip
/// crossings), and `pixel_out` behind it (`pixel_out: <its field>`) or not (`fragments:
/// <the link's field>`: the fragments leave on `out$*`); `inputs` and `outputs` name the
/// ports these add, for the simulators' pins. Each choice is an optional group of fields,
/// constructor and kernel statements, driven by the name given. (A macro, as rust-hdl's
/// `LogicBlock` takes its ports from the struct's fields; one arm, so that every `self` is
/// the kernel's.)
macro_rules! raster_top_variant {
    ($(#[$m:meta])* $name:ident {
        $(cull_sort: $cs:ident,)?
        $(sorted: $ic:ident,)?
        $(pixel_out: $po:ident,)?
        $(fragments: $ov:ident,)?
        inputs: [$($i:ident),* $(,)?],
        outputs: [$($o:ident),* $(,)?] $(,)?
    }) => {
        $(#[$m])*
        #[derive(LogicBlock)]
        pub struct $name {
            pub clock: Signal<In, Clock>,
            /// Screen size in pixels, 1 to 2^CLASS each (the size class); constant during a frame.
            pub width: Signal<In, Bits<DIM>>,
            pub height: Signal<In, Bits<DIM>>,
            /// The frame's last triangle (with `inp.valid`).
            pub inp_last: Signal<In, Bit>,
            $(
                /// The triangles, as submitted (`model::input::Vtx` per vertex).
                pub inp: TriangleSink,
                /// Drop back faces (`model::cull_sort::Cull::Back`).
                pub cull_back: Signal<In, Bit>,
                /// A triangle leaves `cull_sort` (passed or rejected), with why (`rtl::cull_sort`).
                pub verdict_valid: Signal<Out, Bit>,
                pub verdict_code: Signal<Out, Bits<2>>,
                pub verdict_outside: Signal<Out, Bits<OUTCODE>>,
                $cs: CullSort,
            )?
            $(
                /// The sorted triangles with the clip planes they cross (`model::cull_sort::Sorted`).
                pub $ic: SortedSink,
            )?
            $(
                /// The memory port of `pixel_out` (see `rtl::pixel_out`).
                pub mem_ready: Signal<In, Bit>,
                pub rd_en: Signal<Out, Bit>,
                pub rd_addr: Signal<Out, Bits<ADDR>>,
                pub rd_z: Signal<In, Bits<DEPTH>>,
                pub wr_en: Signal<Out, Bit>,
                pub wr_addr: Signal<Out, Bits<ADDR>>,
                pub wr_z: Signal<Out, Bits<DEPTH>>,
                pub wr_rgb: Signal<Out, Bits<RGB>>,
                $po: PixelOut,
            )?
            $(
                /// The fragments (`model::span::Pixel`), before any depth test, as a stream.
                pub $ov: PixelSource,
            )?
            /// The frame is drawn: the `inp_last` triangle has been taken and every unit is empty.
            pub done: Signal<Out, Bit>,
            core: RasterCore,
            /// The last triangle taken had `inp_last`.
            last_in: DFF<Bit>,
        }

        impl $name {
            /// The rasterizer with `k` multipliers in setup and an `l`-stage divider.
            pub fn new(k: usize, l: usize) -> Result<$name, String> {
                Ok($name {
                    clock: Default::default(),
                    width: Default::default(),
                    height: Default::default(),
                    inp_last: Default::default(),
                    $(
                        inp: Default::default(),
                        cull_back: Default::default(),
                        verdict_valid: Default::default(),
                        verdict_code: Default::default(),
                        verdict_outside: Default::default(),
                        $cs: Default::default(),
                    )?
                    $( $ic: Default::default(), )?
                    $(
                        mem_ready: Default::default(),
                        rd_en: Default::default(),
                        rd_addr: Default::default(),
                        rd_z: Default::default(),
                        wr_en: Default::default(),
                        wr_addr: Default::default(),
                        wr_z: Default::default(),
                        wr_rgb: Default::default(),
                        $po: Default::default(),
                    )?
                    $( $ov: Default::default(), )?
                    done: Default::default(),
                    core: RasterCore::new(k, l)?,
                    last_in: Default::default(),
                })
            }
        }

        impl Logic for $name {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, last_in);
                clock!(self, clock, core);
                self.core.width.next = self.width.val();
                self.core.height.next = self.height.val();
                // Frame done: after the last triangle, every unit empty.
                self.done.next = self.last_in.q.val() & self.core.idle.val();
                $(
                    // Triangles in: cull_sort, then the sorted triangle to the core.
                    self.$cs.clock.next = self.clock.val();
                    self.$cs.width.next = self.width.val();
                    self.$cs.height.next = self.height.val();
                    self.$cs.cull_back.next = self.cull_back.val();
                    TriangleSink::link(&mut self.inp, &mut self.$cs.inp);
                    self.verdict_valid.next = self.$cs.verdict_valid.val();
                    self.verdict_code.next = self.$cs.verdict_code.val();
                    self.verdict_outside.next = self.$cs.verdict_outside.val();
                    if self.inp.valid.val() & self.inp.ready.val() {
                        self.last_in.d.next = self.inp_last.val();
                    }
                    SortedSource::join(&mut self.$cs.out, &mut self.core.inp);
                    if self.$cs.out.valid.val() {
                        self.done.next = false;
                    }
                )?
                $(
                    // Sorted triangles in, straight to the core.
                    SortedSink::link(&mut self.$ic, &mut self.core.inp);
                    if self.$ic.valid.val() & self.$ic.ready.val() {
                        self.last_in.d.next = self.inp_last.val();
                    }
                )?
                $(
                    // The core -> pixel_out: `Pixel`; pixel_out <-> memory.
                    self.$po.clock.next = self.clock.val();
                    PixelSource::join(&mut self.core.out, &mut self.$po.inp);
                    self.$po.mem_ready.next = self.mem_ready.val();
                    self.$po.rd_z.next = self.rd_z.val();
                    self.rd_en.next = self.$po.rd_en.val();
                    self.rd_addr.next = self.$po.rd_addr.val();
                    self.wr_en.next = self.$po.wr_en.val();
                    self.wr_addr.next = self.$po.wr_addr.val();
                    self.wr_z.next = self.$po.wr_z.val();
                    self.wr_rgb.next = self.$po.wr_rgb.val();
                    if !self.$po.idle.val() {
                        self.done.next = false;
                    }
                )?
                $(
                    // Fragments out.
                    PixelSource::link(&mut self.$ov, &mut self.core.out);
                )?
            }
        }

        crate::pins!($name {
            clock: clock,
            inputs: [width, height, inp_last, $($i,)*],
            outputs: [done, $($o,)*],
            links: [inp, $($ov)?],
        });
    };
}

raster_top_variant!(
    /// The whole scanline rasterizer (`CULL_SORT = 1`, `PIXEL_OUT = 1`): triangles in
    /// (`model::input::Vtx` per vertex, `cull_sort`'s inputs), `cull_sort`'s verdicts,
    /// `pixel_out`'s memory port, and `done`.
    RasterTop {
        cull_sort: cull_sort,
        pixel_out: pixel_out,
        inputs: [cull_back, mem_ready, rd_z],
        outputs: [verdict_valid, verdict_code, verdict_outside, rd_en, rd_addr, wr_en, wr_addr, wr_z, wr_rgb],
    }
);
raster_top_variant!(
    /// `raster_top` without `pixel_out` (`PIXEL_OUT = 0`): triangles in, the fragment
    /// stream out (`out$*`) for a depth test and memory of the host's own.
    RasterTopFragments {
        cull_sort: cull_sort,
        fragments: out,
        inputs: [cull_back],
        outputs: [verdict_valid, verdict_code, verdict_outside],
    }
);
raster_top_variant!(
    /// `raster_top` without `cull_sort` (`CULL_SORT = 0`): the host culls and sorts, and
    /// sends the sorted triangles (`model::cull_sort::Sorted`) with their clip crossings.
    RasterTopSorted {
        sorted: inp,
        pixel_out: pixel_out,
        inputs: [mem_ready, rd_z],
        outputs: [rd_en, rd_addr, wr_en, wr_addr, wr_z, wr_rgb],
    }
);
raster_top_variant!(
    /// `raster_top` with neither (`CULL_SORT = 0`, `PIXEL_OUT = 0`): sorted triangles in,
    /// fragments out.
    RasterTopCore {
        sorted: inp,
        fragments: out,
        inputs: [],
        outputs: [],
    }
);

/// `unit`, connected and emitted as `raster_top` with `params`.
fn emitted<U: Block>(mut unit: U, params: &Params) -> Emitted {
    unit.connect_all();
    Emitted { unit: "raster_top", params: params.clone(), formats: None, ports: ports(&unit), verilog: verilog("raster_top", &unit) }
}

/// `UNITS` entry: the rasterizer with `params["K"]` setup multipliers, a
/// `params["L"]`-stage divider, and `cull_sort` and `pixel_out` present (1) or not (0) as
/// `params["CULL_SORT"]` and `params["PIXEL_OUT"]` say.
pub fn emit_raster_top(params: &Params) -> Result<Emitted, String> {
    let (k, l) = (params["K"] as usize, params["L"] as usize);
    match (params["CULL_SORT"], params["PIXEL_OUT"]) {
        (1, 1) => Ok(emitted(RasterTop::new(k, l)?, params)),
        (1, 0) => Ok(emitted(RasterTopFragments::new(k, l)?, params)),
        (0, 1) => Ok(emitted(RasterTopSorted::new(k, l)?, params)),
        (0, 0) => Ok(emitted(RasterTopCore::new(k, l)?, params)),
        (c, p) => Err(format!("raster_top: CULL_SORT and PIXEL_OUT are 1 (present) or 0 (absent), not {c} and {p}")),
    }
}
