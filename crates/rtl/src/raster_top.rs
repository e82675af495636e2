//! `raster_top`: the whole scanline rasterizer of papers 001 (Woo 2004) and 003 (Lee 2008)
//! as one design, from screen-space triangles to depth and colour writes.
//!
//! ```text
//!  triangles --> cull_sort --> triangle_setup --> edge_walk --> span FIFO --> span --> pixel_out <--> memory
//!  (inp$*,        003 Fig. 4   001 eq. 2, with     001/003       4 commands    003     depth test,   (mem$*)
//!   inp_last)     3 cycles     the divider         Fig. 5        (bypass)      Fig. 6  2 cycles
//! ```
//!
//! Every link is a valid/ready stream (a transfer on a rising edge with valid and ready
//! high) and each unit holds its work while the next one is not ready, so a stalled memory
//! (`mem$ready` low) stops the whole pipeline without losing anything. The links carry the
//! model's transactions field for field: `Sorted`, `TriangleSetupOut`, `SpanCmd`, `Pixel`.
//!
//! **A frame.** Clear the buffers (depth to z_max, colour to the background), set `width`,
//! `height` (1 to 2^N) and `cull_back`, send the triangles (the model's `Vtx`
//! words, `model::input::to_fixed`) with `inp_last` on the final one; `done` rises once
//! that triangle has gone through and every unit is empty, and stays high until the next
//! triangle is taken. `verdict$*` report each triangle `cull_sort` lets go (see
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
//! **Units present.** The core, [`RasterTopCore`] (setup with the divider, edge walk, span
//! FIFO, span: sorted triangles in, fragments out), always; `CULL_SORT = 1` puts `cull_sort`
//! in front of it ([`RasterTopFragments`]: the host sends triangles as submitted, rather
//! than sorted with their clip crossings), `PIXEL_OUT = 1` puts `pixel_out` behind
//! ([`RasterTopSorted`]: the memory port `mem$*` rather than the fragment stream `out$*`
//! for a depth test and memory of the host's own), both give [`RasterTop`]. Each variant
//! is a block holding the smaller one, emitted as module `raster_top`;
//! `model::cycles::Timing` has the same two switches. `TEXTURE = 1` (size class 10) puts
//! `texture_path` and the blending `pixel_out` behind the core: `rtl::raster_top_textured`,
//! which holds the core's edge walk (`hold`) until `span` is empty at each triangle.
//!
//! **Timing** (`model::cycles::scanline_frame` predicts it cycle for cycle when the memory
//! never stalls): cull_sort 3 cycles; setup `model::cycles::setup_timing` (latency 28, a
//! triangle every 10 cycles at K = 7, L = 5, taken on that grid or when setup is empty);
//! the edge walk's first command 2 cycles after
//! it takes a triangle, then a scanline per cycle; the span FIFO passes a command straight
//! through when empty; span's first pixel 2 cycles after it takes a command, then a pixel
//! per cycle; the write 2 cycles after the pixel.
//! Model: `model::render::render` with `Method::Scanline`. Emitted: `hdl-out/raster_top.v`.

use super::cull_sort::CullSort;
use super::edge_walk::EdgeWalk;
use super::links::{
    ChunkPort, MemoryPort, PixelSource, SeMemory, SortedSink, SortedSource, SpanCmdSource, TriangleSetupSource,
    TriangleSink, Verdict,
};
use super::pixel_out::{ChunkOut, PixelOut};
use super::se_array::Bank;
use super::se_cmd::SeCmd;
use super::span::Span;
use super::span_fifo::SpanFifo;
use super::triangle_setup::{TriangleSetup, MANT};
use super::vector::Vector;
use super::widths::{ADDR, DEPTH, DIM, RGB, SCREEN};
use crate::emit::{emit_unit, Emitted};
use crate::parts::Concat;
use crate::switch::Parts;
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;

/// `raster_top` with neither `cull_sort` nor `pixel_out` (`CULL_SORT = 0`, `PIXEL_OUT = 0`),
/// the core every variant holds: `triangle_setup` (with the divider) -> `edge_walk` -> the
/// span FIFO -> `span`. Sorted triangles in (`model::cull_sort::Sorted`, with their clip
/// crossings, on the link `inp`), fragments out (`model::span::Pixel` on `out`).
#[derive(LogicBlock, Blank)]
pub struct RasterTopCore {
    pub clock: Signal<In, Clock>,
    /// Screen size in pixels, 1 to 2^CLASS each (the size class); constant during a frame.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// The sorted triangles in.
    pub inp: SortedSink,
    /// The frame's last triangle (with `inp.valid`).
    pub inp_last: Signal<In, Bit>,
    /// The fragments, before any depth test.
    pub out: PixelSource,
    /// No triangle, span command or pixel held.
    pub idle: Signal<Out, Bit>,
    /// The frame is drawn: the `inp_last` triangle has been taken and every unit is empty.
    pub done: Signal<Out, Bit>,
    /// The edge walk takes no triangle (the textured `raster_top`'s gate,
    /// `rtl::raster_top_textured`; low in every other build).
    pub hold: Signal<In, Bit>,
    /// The edge walk takes a triangle from setup this cycle, and that triangle's
    /// OneOverArea (`triangle_setup`'s `recip_mant`, `recip_exp`).
    pub handed: Signal<Out, Bit>,
    pub recip_mant: Signal<Out, Bits<MANT>>,
    pub recip_exp: Signal<Out, Bits<6>>,
    /// The edge walk, the span FIFO and span are empty: every fragment of the triangles
    /// handed over has left `span`.
    pub walk_idle: Signal<Out, Bit>,
    #[given]
    triangle_setup: TriangleSetup,
    edge_walk: EdgeWalk,
    fifo: SpanFifo,
    span: Span,
    /// The last triangle taken had `inp_last`.
    last_in: DFF<Bit>,
}

impl RasterTopCore {
    /// The core with `k` multipliers in setup, an `l`-stage divider, and the clipping
    /// `parts` says.
    pub fn new(k: usize, l: usize, parts: &Parts) -> Result<RasterTopCore, String> {
        Ok(RasterTopCore {
            edge_walk: EdgeWalk::new(parts),
            span: Span::new(parts),
            ..RasterTopCore::blank(RasterTopCoreGiven { triangle_setup: TriangleSetup::new(k, l)? })
        })
    }
}

/// The core at the units' default parameters (`UNITS`: 001's 7 multipliers and 5 divider
/// stages).
impl Default for RasterTopCore {
    fn default() -> Self {
        RasterTopCore::new(crate::K.default as usize, crate::L.default as usize, &Parts::ALL)
            .expect("the default K and L are supported")
    }
}

impl Logic for RasterTopCore {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last_in);
        clock!(self, clock, triangle_setup, edge_walk, fifo, span);
        // Sorted triangles in.
        SortedSink::link(&mut self.inp, &mut self.triangle_setup.inp);
        if self.inp.valid.val() & self.inp.ready.val() {
            self.last_in.d.next = self.inp_last.val();
        }

        // triangle_setup -> edge_walk: `TriangleSetupOut`.
        self.edge_walk.height.next = self.height.val();
        TriangleSetupSource::join(&mut self.triangle_setup.out, &mut self.edge_walk.inp);
        self.edge_walk.hold.next = self.hold.val();
        self.triangle_setup.out_free_next.next = self.edge_walk.free_next.val();
        self.triangle_setup.out_hold.next = self.hold.val();
        self.recip_mant.next = self.triangle_setup.recip_mant.val();
        self.recip_exp.next = self.triangle_setup.recip_exp.val();

        // edge_walk -> span FIFO -> span: `SpanCmd`.
        self.span.width.next = self.width.val();
        SpanCmdSource::join(&mut self.edge_walk.out, &mut self.fifo.inp);
        SpanCmdSource::join(&mut self.fifo.out, &mut self.span.inp);

        // Fragments out.
        PixelSource::link(&mut self.out, &mut self.span.out);

        self.handed.next = self.triangle_setup.out.valid.val() & self.edge_walk.inp.ready.val();
        self.walk_idle.next = self.edge_walk.idle.val() & self.fifo.empty.val() & self.span.idle.val();
        self.idle.next = self.triangle_setup.idle.val() & self.walk_idle.val();
        self.done.next = self.last_in.q.val() & self.idle.val();
    }
}

crate::pins!(RasterTopCore {
    clock: clock,
    inputs: [width, height, inp_last, hold],
    outputs: [idle, done, handed, recip_mant, recip_exp, walk_idle],
    links: [inp, out],
});

/// `raster_top` without `pixel_out` (`CULL_SORT = 1`, `PIXEL_OUT = 0`): `cull_sort` in
/// front of the core. Triangles in as submitted (`model::input::Vtx` per vertex), `cull_sort`'s
/// verdicts, and the fragment stream out (`out`) for a depth test and memory of the host's
/// own.
#[derive(LogicBlock, Default)]
pub struct RasterTopFragments {
    pub clock: Signal<In, Clock>,
    /// As [`RasterTopCore`]'s.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// The triangles, as submitted.
    pub inp: TriangleSink,
    pub inp_last: Signal<In, Bit>,
    /// Drop back faces (`model::cull_sort::Cull::Back`).
    pub cull_back: Signal<In, Bit>,
    /// Each triangle `cull_sort` lets go (passed or rejected), and why.
    pub verdict: Verdict,
    pub out: PixelSource,
    /// `inp_last`'s triangle taken (and perhaps culled), and every unit empty.
    pub done: Signal<Out, Bit>,
    cull_sort: CullSort,
    core: RasterTopCore,
    last_in: DFF<Bit>,
}

impl RasterTopFragments {
    /// `cull_sort` and the core with `k` multipliers in setup and an `l`-stage divider,
    /// with the parts `parts` says.
    pub fn new(k: usize, l: usize, parts: &Parts) -> Result<RasterTopFragments, String> {
        Ok(RasterTopFragments {
            cull_sort: CullSort::new(parts),
            core: RasterTopCore::new(k, l, parts)?,
            ..Default::default()
        })
    }
}

impl Logic for RasterTopFragments {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last_in);
        clock!(self, clock, cull_sort, core);
        self.cull_sort.width.next = self.width.val();
        self.cull_sort.height.next = self.height.val();
        self.cull_sort.cull_back.next = self.cull_back.val();
        self.core.width.next = self.width.val();
        self.core.height.next = self.height.val();
        // Triangles into cull_sort, the sorted ones on to the core, which does not see
        // the frame's end: a culled last triangle never reaches it.
        TriangleSink::link(&mut self.inp, &mut self.cull_sort.inp);
        Verdict::link(&mut self.verdict, &mut self.cull_sort.verdict);
        SortedSource::join(&mut self.cull_sort.out, &mut self.core.inp);
        self.core.inp_last.next = false;
        self.core.hold.next = false;
        PixelSource::link(&mut self.out, &mut self.core.out);
        if self.inp.valid.val() & self.inp.ready.val() {
            self.last_in.d.next = self.inp_last.val();
        }
        self.done.next = self.last_in.q.val() & self.cull_sort.idle.val() & self.core.idle.val();
    }
}

crate::pins!(RasterTopFragments {
    clock: clock,
    inputs: [width, height, inp_last, cull_back],
    outputs: [done],
    links: [inp, out, verdict],
});

/// `raster_top` without `cull_sort` (`CULL_SORT = 0`, `PIXEL_OUT = 1`): the core and
/// `pixel_out` behind it. The host culls and sorts, and sends the sorted triangles
/// (`model::cull_sort::Sorted`) with their clip crossings; depth and colour go to the
/// memory port `mem` (`rtl::pixel_out`).
#[derive(LogicBlock, Default)]
pub struct RasterTopSorted {
    pub clock: Signal<In, Clock>,
    /// As [`RasterTopCore`]'s.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    pub inp: SortedSink,
    pub inp_last: Signal<In, Bit>,
    /// The memory port of `pixel_out`.
    pub mem: MemoryPort,
    /// The core is done and `pixel_out` has written the last pixel.
    pub done: Signal<Out, Bit>,
    core: RasterTopCore,
    pixel_out: PixelOut,
}

impl RasterTopSorted {
    /// The core with `k` multipliers in setup and an `l`-stage divider, and `pixel_out`,
    /// with the parts `parts` says.
    pub fn new(k: usize, l: usize, parts: &Parts) -> Result<RasterTopSorted, String> {
        Ok(RasterTopSorted {
            core: RasterTopCore::new(k, l, parts)?,
            pixel_out: PixelOut::new(parts),
            ..Default::default()
        })
    }
}

impl Logic for RasterTopSorted {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, core, pixel_out);
        self.core.width.next = self.width.val();
        self.core.height.next = self.height.val();
        SortedSink::link(&mut self.inp, &mut self.core.inp);
        self.core.inp_last.next = self.inp_last.val();
        self.core.hold.next = false;
        PixelSource::join(&mut self.core.out, &mut self.pixel_out.inp);
        MemoryPort::link(&mut self.mem, &mut self.pixel_out.mem);
        self.done.next = self.core.done.val() & self.pixel_out.idle.val();
    }
}

crate::pins!(RasterTopSorted { clock: clock, inputs: [width, height, inp_last], outputs: [done], links: [inp, mem] });

/// The whole scanline rasterizer (`CULL_SORT = 1`, `PIXEL_OUT = 1`): [`RasterTopFragments`]
/// (`cull_sort` and the core) with `pixel_out` behind it. Triangles in as submitted,
/// `cull_sort`'s verdicts, the memory port, and `done`.
#[derive(LogicBlock, Default)]
pub struct RasterTop {
    pub clock: Signal<In, Clock>,
    /// As [`RasterTopFragments`]'s.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    pub inp: TriangleSink,
    pub inp_last: Signal<In, Bit>,
    pub cull_back: Signal<In, Bit>,
    pub verdict: Verdict,
    /// The memory port of `pixel_out`.
    pub mem: MemoryPort,
    /// `inp_last`'s triangle taken, every unit empty and the last pixel written.
    pub done: Signal<Out, Bit>,
    fragments: RasterTopFragments,
    pixel_out: PixelOut,
}

impl RasterTop {
    /// `cull_sort`, the core with `k` multipliers in setup and an `l`-stage divider, and
    /// `pixel_out`, with the parts `parts` says.
    pub fn new(k: usize, l: usize, parts: &Parts) -> Result<RasterTop, String> {
        Ok(RasterTop {
            fragments: RasterTopFragments::new(k, l, parts)?,
            pixel_out: PixelOut::new(parts),
            ..Default::default()
        })
    }
}

impl Logic for RasterTop {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, fragments, pixel_out);
        self.fragments.width.next = self.width.val();
        self.fragments.height.next = self.height.val();
        self.fragments.inp_last.next = self.inp_last.val();
        self.fragments.cull_back.next = self.cull_back.val();
        TriangleSink::link(&mut self.inp, &mut self.fragments.inp);
        Verdict::link(&mut self.verdict, &mut self.fragments.verdict);
        PixelSource::join(&mut self.fragments.out, &mut self.pixel_out.inp);
        MemoryPort::link(&mut self.mem, &mut self.pixel_out.mem);
        self.done.next = self.fragments.done.val() & self.pixel_out.idle.val();
    }
}

crate::pins!(RasterTop {
    clock: clock,
    inputs: [width, height, inp_last, cull_back],
    outputs: [done],
    links: [inp, mem, verdict],
});

/// The barycentric rasterizer (`METHOD = 1`, paper 004): `cull_sort`, [`Vector`] with
/// `LANES` lanes and [`ChunkOut`] (`pixel_out` a chunk a cycle), with [`RasterTop`]'s ports
/// but the memory port a word per chunk of `LANES` pixels (`links::ChunkPort`: address
/// `{y, x / LANES}`, `AW` = 2 N - log2 `LANES` bits; at one lane `links::MemoryPort`, as
/// the scanline `raster_top`'s). The vector unit takes a triangle when its setup is free
/// and sends a chunk a cycle (`rtl::vector`); `model::cycles::vector_frame` predicts the
/// frame cycle for cycle.
#[derive(LogicBlock, Blank)]
pub struct RasterTopVector<const LANES: usize, const ZW: usize, const CW: usize, const AW: usize> {
    pub clock: Signal<In, Clock>,
    /// As [`RasterTop`]'s.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    pub inp: TriangleSink,
    pub inp_last: Signal<In, Bit>,
    pub cull_back: Signal<In, Bit>,
    pub verdict: Verdict,
    pub mem: ChunkPort<LANES, AW, ZW, CW>,
    pub done: Signal<Out, Bit>,
    cull_sort: CullSort,
    vector: Vector<LANES, ZW, CW>,
    #[given]
    pixel_out: ChunkOut<LANES, AW, ZW, CW>,
    last_in: DFF<Bit>,
    /// A chunk's address: `y` shifted by the row's chunk bits, `x` by log2 `LANES`.
    row_at: Constant<Bits<8>>,
    lane_bits: Constant<Bits<8>>,
}

impl<const LANES: usize, const ZW: usize, const CW: usize, const AW: usize> RasterTopVector<LANES, ZW, CW, AW> {
    /// `cull_sort`, the vector unit with an `l`-stage divider and perspective-correct colours
    /// or not, and `pixel_out`, with the parts `parts` says (`CULL`, `DEPTH_TEST`).
    pub fn new(l: usize, perspective: bool, parts: &Parts) -> Result<Self, String> {
        let lane_bits = LANES.trailing_zeros() as usize;
        assert_eq!(AW, 2 * SCREEN - lane_bits, "RasterTopVector<{LANES}, {ZW}, {CW}, {AW}>");
        Ok(RasterTopVector {
            cull_sort: CullSort::new(parts),
            vector: Vector::new(l, perspective)?,
            row_at: Constant::new((SCREEN - lane_bits).to_bits()),
            lane_bits: Constant::new(lane_bits.to_bits()),
            ..RasterTopVector::blank(RasterTopVectorGiven { pixel_out: ChunkOut::new(parts) })
        })
    }
}

impl<const LANES: usize, const ZW: usize, const CW: usize, const AW: usize> Logic
    for RasterTopVector<LANES, ZW, CW, AW>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last_in);
        clock!(self, clock, cull_sort, vector, pixel_out);
        self.cull_sort.width.next = self.width.val();
        self.cull_sort.height.next = self.height.val();
        self.cull_sort.cull_back.next = self.cull_back.val();
        self.vector.width.next = self.width.val();
        self.vector.height.next = self.height.val();
        TriangleSink::link(&mut self.inp, &mut self.cull_sort.inp);
        Verdict::link(&mut self.verdict, &mut self.cull_sort.verdict);
        SortedSource::join(&mut self.cull_sort.out, &mut self.vector.inp);
        // The vector unit's chunk is a memory word's lanes as they are.
        self.pixel_out.in_valid.next = self.vector.out_valid.val();
        self.vector.out_ready.next = self.pixel_out.in_ready.val();
        self.pixel_out.in_mask.next = self.vector.out_mask.val();
        self.pixel_out.in_addr.next = (bit_cast::<AW, SCREEN>(self.vector.out_y.val()) << self.row_at.val())
            | bit_cast::<AW, SCREEN>(self.vector.out_x.val() >> self.lane_bits.val());
        self.pixel_out.in_z.next = self.vector.out_z.val();
        self.pixel_out.in_rgb.next = self.vector.out_rgb.val();
        ChunkPort::<LANES, AW, ZW, CW>::link(&mut self.mem, &mut self.pixel_out.mem);
        if self.inp.valid.val() & self.inp.ready.val() {
            self.last_in.d.next = self.inp_last.val();
        }
        self.done.next =
            self.last_in.q.val() & self.cull_sort.idle.val() & self.vector.idle.val() & self.pixel_out.idle.val();
    }
}

crate::pins!(impl[const LANES: usize, const ZW: usize, const CW: usize, const AW: usize] RasterTopVector<LANES, ZW, CW, AW> {
    clock: clock,
    inputs: [width, height, inp_last, cull_back],
    outputs: [done],
    links: [inp, mem, verdict],
});

/// The barycentric `raster_top` at one lane, on the scanline one's memory port.
pub type RasterTopVector1 = RasterTopVector<1, DEPTH, RGB, ADDR>;

/// The SE back end (`METHOD = 2`, paper 000 on the scanline front end of 001/003):
/// `cull_sort`, `triangle_setup`, `edge_walk` and the span FIFO as [`RasterTop`]'s, then
/// `se_cmd` and `E` shading engines on one span bus (`rtl::se_array`), with [`RasterTop`]'s
/// ports but the engines' banked memory port (`links::SeMemory`: `EL` = 4 `E` lanes, `ZW`
/// and `CW` bits of depths and colours); screens up to 64 `E` columns wide.
/// `model::cycles::se_frame` predicts the frame cycle for cycle.
#[derive(LogicBlock, Blank)]
pub struct RasterTopSe<const E: usize, const EL: usize, const ZW: usize, const CW: usize> {
    pub clock: Signal<In, Clock>,
    /// As [`RasterTop`]'s.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    pub inp: TriangleSink,
    pub inp_last: Signal<In, Bit>,
    pub cull_back: Signal<In, Bit>,
    pub verdict: Verdict,
    pub mem: SeMemory<EL, { SCREEN + 4 }, ZW, CW>,
    pub done: Signal<Out, Bit>,
    cull_sort: CullSort,
    #[given]
    triangle_setup: TriangleSetup,
    edge_walk: EdgeWalk,
    fifo: SpanFifo,
    se_cmd: SeCmd,
    banks: Vec<Bank<ZW, CW, EL>>,
    /// The banks' write words gathered.
    g_z: Vec<Signal<Local, Bits<ZW>>>,
    g_rgb: Vec<Signal<Local, Bits<CW>>>,
    g_en: Vec<Signal<Local, Bits<EL>>>,
    rd_addr: Concat<SCREEN, 4, { SCREEN + 4 }>,
    wr_addr: Concat<SCREEN, 4, { SCREEN + 4 }>,
    last_in: DFF<Bit>,
}

impl<const E: usize, const EL: usize, const ZW: usize, const CW: usize> RasterTopSe<E, EL, ZW, CW> {
    /// `cull_sort`, setup with `k` multipliers and an `l`-stage divider, the edge walk, the
    /// span FIFO, `se_cmd` and the `E` engines, with the parts `parts` says (`CULL`,
    /// `CLIP_Y`).
    pub fn new(k: usize, l: usize, parts: &Parts) -> Result<Self, String> {
        assert!(EL == 4 * E && ZW == EL * DEPTH && CW == EL * RGB, "RasterTopSe<{E}, {EL}, {ZW}, {CW}>");
        if !super::se_array::FITS {
            return Err("raster_top: METHOD = 2 (the SE back end) is built at size class 10's default formats, whose engines are rtl::se::SeWide".into());
        }
        Ok(RasterTopSe {
            cull_sort: CullSort::new(parts),
            edge_walk: EdgeWalk::new(parts),
            banks: (0..E).map(Bank::new).collect(),
            g_z: (0..=E).map(|_| Default::default()).collect(),
            g_rgb: (0..=E).map(|_| Default::default()).collect(),
            g_en: (0..=E).map(|_| Default::default()).collect(),
            ..RasterTopSe::blank(RasterTopSeGiven { triangle_setup: TriangleSetup::new(k, l)? })
        })
    }
}

impl<const E: usize, const EL: usize, const ZW: usize, const CW: usize> Logic for RasterTopSe<E, EL, ZW, CW> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last_in);
        clock!(self, clock, cull_sort, triangle_setup, edge_walk, fifo, se_cmd);
        for i in 0..E {
            self.banks[i].clock.next = self.clock.val();
        }
        self.cull_sort.width.next = self.width.val();
        self.cull_sort.height.next = self.height.val();
        self.cull_sort.cull_back.next = self.cull_back.val();
        self.edge_walk.height.next = self.height.val();
        self.se_cmd.width.next = self.width.val();
        // Triangles into cull_sort, on through setup and the edge walk into the span FIFO.
        TriangleSink::link(&mut self.inp, &mut self.cull_sort.inp);
        Verdict::link(&mut self.verdict, &mut self.cull_sort.verdict);
        SortedSource::join(&mut self.cull_sort.out, &mut self.triangle_setup.inp);
        TriangleSetupSource::join(&mut self.triangle_setup.out, &mut self.edge_walk.inp);
        self.edge_walk.hold.next = false;
        self.triangle_setup.out_free_next.next = self.edge_walk.free_next.val();
        self.triangle_setup.out_hold.next = false;
        SpanCmdSource::join(&mut self.edge_walk.out, &mut self.fifo.inp);
        SpanCmdSource::join(&mut self.fifo.out, &mut self.se_cmd.inp);

        // The span bus: every engine takes each command; all run in step.
        self.g_z[0].next = 0.into();
        self.g_rgb[0].next = 0.into();
        self.g_en[0].next = 0.into();
        for i in 0..E {
            self.banks[i].valid.next = self.se_cmd.out_valid.val();
            self.banks[i].xl.next = self.se_cmd.xl.val();
            self.banks[i].xr.next = self.se_cmd.xr.val();
            self.banks[i].za.next = self.se_cmd.za.val();
            self.banks[i].zb.next = self.se_cmd.zb.val();
            self.banks[i].ra.next = self.se_cmd.ra.val();
            self.banks[i].rb.next = self.se_cmd.rb.val();
            self.banks[i].ga.next = self.se_cmd.ga.val();
            self.banks[i].gb.next = self.se_cmd.gb.val();
            self.banks[i].ba.next = self.se_cmd.ba.val();
            self.banks[i].bb.next = self.se_cmd.bb.val();
            self.banks[i].rd_z.next = self.mem.rd_z.val();
            self.g_z[i + 1].next = self.g_z[i].val() | self.banks[i].wr_z.val();
            self.g_rgb[i + 1].next = self.g_rgb[i].val() | self.banks[i].wr_rgb.val();
            self.g_en[i + 1].next = self.g_en[i].val() | self.banks[i].wr_en.val();
        }
        for i in 0..1 {
            self.se_cmd.out_ready.next = self.banks[i].ready.val();
            self.mem.rd.next = self.banks[i].oz_rd.val();
            self.rd_addr.lo.next = self.banks[i].oz_addr.val();
            self.mem.wr.next = self.banks[i].wr.val();
            self.wr_addr.lo.next = self.banks[i].wr_addr.val();
        }
        for i in E..(E + 1) {
            self.mem.wr_z.next = self.g_z[i].val();
            self.mem.wr_rgb.next = self.g_rgb[i].val();
            self.mem.wr_en.next = self.g_en[i].val();
        }
        self.rd_addr.hi.next = self.se_cmd.rd_y.val();
        self.wr_addr.hi.next = self.se_cmd.wr_y.val();
        self.mem.rd_addr.next = self.rd_addr.out.val();
        self.mem.wr_addr.next = self.wr_addr.out.val();

        if self.inp.valid.val() & self.inp.ready.val() {
            self.last_in.d.next = self.inp_last.val();
        }
        self.done.next = self.last_in.q.val()
            & self.cull_sort.idle.val()
            & self.triangle_setup.idle.val()
            & self.edge_walk.inp.ready.val()
            & self.fifo.empty.val()
            & self.se_cmd.idle.val()
            & self.se_cmd.engines_idle.val();
    }
}

crate::pins!(impl[const E: usize, const EL: usize, const ZW: usize, const CW: usize] RasterTopSe<E, EL, ZW, CW> {
    clock: clock,
    inputs: [width, height, inp_last, cull_back],
    outputs: [done],
    links: [inp, mem, verdict],
});

/// `UNITS` entry: the rasterizer with `params["K"]` setup multipliers, a
/// `params["L"]`-stage divider, `cull_sort` and `pixel_out` present (1) or not (0) as
/// `params["CULL_SORT"]` and `params["PIXEL_OUT"]` say, and the optional parts of the units
/// present as `CULL`, `CLIP_Y`, `CLIP_X`, `CLIP_Z` and `DEPTH_TEST` say (`crate::switch`).
pub fn emit_raster_top(params: &Params) -> Result<Emitted, String> {
    let (k, l) = (params["K"] as usize, params["L"] as usize);
    let parts = Parts::of(params)?;
    let perspective = match params["PERSPECTIVE"] {
        0 => false,
        1 => true,
        v => return Err(format!("raster_top: PERSPECTIVE = {v}: 0 or 1")),
    };
    match params["METHOD"] {
        0 if params["LANES"] != 1 => {
            return Err(format!(
                "raster_top: LANES = {} is the vector unit's (METHOD = 1); the scanline method draws a pixel a cycle",
                params["LANES"]
            ))
        }
        0 => {}
        1 => {
            if (params["CULL_SORT"], params["PIXEL_OUT"]) != (1, 1) {
                return Err("raster_top: METHOD = 1 (vector) is built with cull_sort and pixel_out (CULL_SORT = 1, PIXEL_OUT = 1)".into());
            }
            if !(parts.clip_y && parts.clip_x && parts.clip_z) {
                return Err("raster_top: CLIP_Y, CLIP_X and CLIP_Z switch parts of edge_walk and span, which METHOD = 1 (vector) has not: its box walk clips to the screen".into());
            }
            let p = &parts;
            return Ok(match params["LANES"] {
                1 => emit_unit("raster_top", RasterTopVector1::new(l, perspective, p)?, params),
                2 => emit_unit(
                    "raster_top",
                    RasterTopVector::<2, { 2 * DEPTH }, { 2 * RGB }, { ADDR - 1 }>::new(l, perspective, p)?,
                    params,
                ),
                4 => emit_unit(
                    "raster_top",
                    RasterTopVector::<4, { 4 * DEPTH }, { 4 * RGB }, { ADDR - 2 }>::new(l, perspective, p)?,
                    params,
                ),
                8 => emit_unit(
                    "raster_top",
                    RasterTopVector::<8, { 8 * DEPTH }, { 8 * RGB }, { ADDR - 3 }>::new(l, perspective, p)?,
                    params,
                ),
                n => return Err(format!("raster_top: LANES = {n}: 1, 2, 4 or 8 (METHOD = 1)")),
            });
        }
        2 => {
            if (params["CULL_SORT"], params["PIXEL_OUT"]) != (1, 1)
                || !(parts.clip_x && parts.clip_z && parts.depth_test)
            {
                return Err("raster_top: METHOD = 2 (the SE back end) is built with cull_sort and its engines (CULL_SORT = 1, PIXEL_OUT = 1; CLIP_X, CLIP_Z and DEPTH_TEST are the engines' own: 1)".into());
            }
            if params["LANES"] != 1 {
                return Err("raster_top: LANES is the vector unit's (METHOD = 1); METHOD = 2 has ENGINES".into());
            }
            let p = &parts;
            return Ok(match params["ENGINES"] {
                1 => emit_unit("raster_top", RasterTopSe::<1, 4, { 4 * DEPTH }, { 4 * RGB }>::new(k, l, p)?, params),
                5 => emit_unit("raster_top", RasterTopSe::<5, 20, { 20 * DEPTH }, { 20 * RGB }>::new(k, l, p)?, params),
                16 => {
                    emit_unit("raster_top", RasterTopSe::<16, 64, { 64 * DEPTH }, { 64 * RGB }>::new(k, l, p)?, params)
                }
                n => {
                    return Err(format!(
                        "raster_top: ENGINES = {n}: 1, 5 or 16 (screens up to 64, 320 or 1024 columns)"
                    ))
                }
            });
        }
        m => return Err(format!("raster_top: METHOD = {m}: 0 (scanline), 1 (vector) or 2 (se)")),
    }
    if params["CULL_SORT"] == 0 && !parts.cull {
        return Err(
            "raster_top: CULL = 0 removes cull_sort's rejecting and culling, which CULL_SORT = 0 has no unit for"
                .into(),
        );
    }
    if params["PIXEL_OUT"] == 0 && !parts.depth_test {
        return Err(
            "raster_top: DEPTH_TEST = 0 removes pixel_out's depth test, which PIXEL_OUT = 0 has no unit for".into()
        );
    }
    let p = &parts;
    match (params["CULL_SORT"], params["PIXEL_OUT"], params["TEXTURE"]) {
        (_, _, 0) => {}
        (1, 1, 1) if super::widths::FORMATS == crate::n10::FORMATS => {
            return crate::raster_top_textured::emit(params, p)
        }
        (1, 1, 1) => {
            return Err(
                "raster_top: TEXTURE = 1 is built at size class 10's default formats (N = 10), as texture_path".into()
            )
        }
        (_, _, 1) => {
            return Err(
                "raster_top: TEXTURE = 1 is built with cull_sort and pixel_out (CULL_SORT = 1, PIXEL_OUT = 1)".into()
            )
        }
        (_, _, t) => return Err(format!("raster_top: TEXTURE = {t}: 0 or 1")),
    }
    match (params["CULL_SORT"], params["PIXEL_OUT"]) {
        (1, 1) => Ok(emit_unit("raster_top", RasterTop::new(k, l, p)?, params)),
        (1, 0) => Ok(emit_unit("raster_top", RasterTopFragments::new(k, l, p)?, params)),
        (0, 1) => Ok(emit_unit("raster_top", RasterTopSorted::new(k, l, p)?, params)),
        (0, 0) => Ok(emit_unit("raster_top", RasterTopCore::new(k, l, p)?, params)),
        (c, p) => Err(format!("raster_top: CULL_SORT and PIXEL_OUT are 1 (present) or 0 (absent), not {c} and {p}")),
    }
}
