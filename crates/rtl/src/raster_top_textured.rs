//! The textured `raster_top` (`TEXTURE = 1`, size class 10): the scanline rasterizer of
//! papers 001 and 003 with 001's texture path (§II-5) between `span` and a blending
//! `pixel_out`, from submitted triangles with their texture words to blended depth and
//! colour writes.
//!
//! ```text
//!  inp$*, tex$*, tex_state$* ──> cull_sort ──> RasterTopCore (setup, edge walk, span FIFO, span) ──┬─> texture_path ──┬─> pixel_out (blending) <──> mem$*
//!    │                            │ verdict        │ handed, recip_mant/exp          fragments  │  (textured)      │   (mode, alpha)
//!    │                            ▼                ▼                                            └─> alpha 255 ─────┘
//!    └─> slot RAM ──> queue of passed slots ──> cur (the triangle being walked) ──> texture_path's tri$*, state$*
//! ```
//!
//! **Texture words.** With each triangle (`inp`) comes its texture words (`tex$*`):
//! `textured`, the vertices' s·q, t·q and q (`model::texture_setup::TexVtx::a`) and the
//! blend mode (`rtl::blend`'s code), and the texture's state (`tex_state$*`). They go into a slot of a
//! 16-word RAM with the vertices' x and y, and stay there until the next triangle is handed
//! to the edge walk. `cull_sort`'s verdicts come in order: a passed triangle's slot joins
//! the queue of triangles in setup; the edge walk's taking of a triangle (the core's
//! `handed`) makes the queue's head the current slot (`cur`), whose words, with the
//! OneOverArea that setup's divider computed for it (the core's `recip_mant`,
//! `recip_exp`), are `texture_path`'s triangle (`tri$*`, `tri_mode`, `state$*`). The slots in use run from the
//! current one (while its fragments flow), or else the queue's head, or else the next
//! verdict's, to the next free one; a triangle is taken only while one slot is free beyond.
//!
//! **One triangle behind setup at a time.** The edge walk takes a triangle only once every
//! fragment of the one before has left `span` (`walk_idle`), and an untextured one only
//! once `texture_path` is idle too (the core's `hold`): a triangle's fragments are
//! `texture_path`'s (the first with `inp_new`) or, untextured, go straight to `pixel_out`
//! with alpha 255, and `pixel_out` sees them in drawing order. Setup still works ahead.
//! `texture_path` sets each textured triangle up on its first fragment (30 cycles).
//!
//! Model: `model::render::render_with` (scanline, textured); the frames are
//! `testbenches/tests/raster_top.rs`'s. Emitted: `edgepaint emit --unit raster_top --param
//! TEXTURE=1` (`hdl-out/raster_top-TEXTURE=1/`).

use crate::emit::{emit_unit, Emitted};
use crate::n10::cull_sort::CullSort;
use crate::n10::links::{BlendMemoryPort, SortedSource, TriangleSink, Verdict};
use crate::n10::pixel_out::PixelOutBlend;
use crate::n10::raster_top::RasterTopCore;
use crate::n10::widths::DIM;
use crate::switch::Parts;
use crate::texture_cache::{CacheCounters, TexMemory, ADDR as TADDR};
use crate::texture_path::{TexturePath, SW};
use crate::texture_setup::{QB, ST, XY};
use crate::texture_unit::TextureState;
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::RAM;

/// log2 of the slots.
const SB: usize = 4;
/// log2 of the queue of passed slots: at most one per copy of setup's registers
/// (`triangle_setup::COPIES_MAX`) wait there.
const QB_LOG: usize = 3;
const _: () = assert!(crate::n10::triangle_setup::COPIES_MAX < 1 << QB_LOG);
const _: () = assert!(XY == crate::n10::cull_sort::XY, "texture_setup takes the input's x and y");
/// A slot's word: x0, y0, x1, y1, x2, y2; s·q of the three vertices, then t·q; q; the
/// state's fields (`SW` bits, `texture_path`'s order of `state$ws` to `state$env`); the mode.
const PW: usize = 6 * XY + 6 * ST + 3 * QB + SW + 3;
/// Where each field of a slot word starts ([`AT`]'s order).
const FIELDS: usize = 28;
/// Field widths in the slot word, from bit 0 up.
const WIDTHS: [usize; FIELDS] =
    [XY, XY, XY, XY, XY, XY, ST, ST, ST, ST, ST, ST, QB, QB, QB, 4, 4, 4, TADDR, 1, 1, 2, 2, 2, 3, 1, 3, 3];
const _: () = {
    let mut sum = 0;
    let mut k = 0;
    while k < FIELDS {
        sum += WIDTHS[k];
        k += 1;
    }
    assert!(sum == PW);
};

crate::bundle! {
    /// A triangle's texture words, with `inp.valid` (`model::texture_path::TexTriangle`
    /// without the vertices' x and y, which are `inp`'s, and the blend mode of every
    /// triangle).
    TexWords {
        /// The triangle is textured; the others' fragments are drawn with alpha 255.
        In textured: Bit,
        In sq0: Bits<ST>,
        In sq1: Bits<ST>,
        In sq2: Bits<ST>,
        In tq0: Bits<ST>,
        In tq1: Bits<ST>,
        In tq2: Bits<ST>,
        In q0: Bits<QB>,
        In q1: Bits<QB>,
        In q2: Bits<QB>,
        /// The blend mode (`rtl::blend`'s code), textured or not.
        In mode: Bits<3>,
    }
}

/// The textured rasterizer: see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct RasterTopTextured {
    pub clock: Signal<In, Clock>,
    /// As `RasterTop`'s.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    pub inp: TriangleSink,
    /// The triangle's texture words, with `inp`.
    pub tex: TexWords,
    /// The triangle's texture state, with `inp` (`texture_unit`'s codes).
    pub tex_state: TextureState,
    pub inp_last: Signal<In, Bit>,
    pub cull_back: Signal<In, Bit>,
    pub verdict: Verdict,
    /// A pulse: the texture cache invalidates every line (`texture_path`'s).
    pub inp_flush: Signal<In, Bit>,
    /// The blending `pixel_out`'s memory port.
    pub mem: BlendMemoryPort,
    /// The texture memory's read port and the cache's counters (`texture_path`'s).
    pub tex_mem: TexMemory,
    pub counters: CacheCounters,
    /// `inp_last`'s triangle taken, every unit empty and the last pixel written.
    pub done: Signal<Out, Bit>,

    cull_sort: CullSort,
    core: RasterTopCore,
    #[given]
    path: TexturePath,
    pixel_out: PixelOutBlend,
    slots: RAM<Bits<PW>, SB>,
    /// The next slot written, and the slot of the next verdict.
    wi: DFF<Bits<SB>>,
    vi: DFF<Bits<SB>>,
    /// The textured flag of each slot.
    tex_bits: DFF<Bits<16>>,
    /// The passed slots in setup, in order: head `qh`, count `qn`.
    queue: [DFF<Bits<SB>>; 8],
    qh: DFF<Bits<QB_LOG>>,
    qn: DFF<Bits<4>>,
    head: Signal<Local, Bits<SB>>,
    head_tex: Signal<Local, Bit>,
    /// Where the next passed slot goes, and whether one comes this cycle.
    tail: Signal<Local, Bits<QB_LOG>>,
    push: Signal<Local, Bit>,
    /// The current triangle: its slot, whether its fragments may still come, whether it is
    /// textured, whether its first fragment is still to come, its OneOverArea.
    cur: DFF<Bits<SB>>,
    cur_live: DFF<Bit>,
    cur_tex: DFF<Bit>,
    first: DFF<Bit>,
    cur_mant: DFF<Bits<{ crate::texture_setup::MANT }>>,
    cur_exp: DFF<Bits<{ crate::texture_setup::EXP }>>,
    /// The oldest slot in use (or `wi` when none is); the slot after `wi`, and whether it is
    /// not the oldest in use (a triangle may be taken).
    base: Signal<Local, Bits<SB>>,
    wi_next: Signal<Local, Bits<SB>>,
    slot_free: Signal<Local, Bit>,
    word_in: Signal<Local, Bits<PW>>,
    word: Signal<Local, Bits<PW>>,
    last_in: DFF<Bit>,
    /// Where each field starts in a slot word.
    at: [Constant<Bits<16>>; FIELDS],
}

impl RasterTopTextured {
    /// `cull_sort`, the core with `k` multipliers in setup and an `l`-stage divider, the
    /// texture path (the level of detail by GL's exact rho when `exact`) and the blending
    /// `pixel_out`, with the parts `parts` says.
    pub fn new(k: usize, l: usize, parts: &Parts, exact: bool) -> Result<RasterTopTextured, String> {
        let mut at = [0usize; FIELDS];
        for f in 1..FIELDS {
            at[f] = at[f - 1] + WIDTHS[f - 1];
        }
        Ok(RasterTopTextured {
            cull_sort: CullSort::new(parts),
            core: RasterTopCore::new(k, l, parts)?,
            pixel_out: PixelOutBlend::new(parts),
            at: at.map(|a| Constant::new(a.to_bits())),
            ..RasterTopTextured::blank(RasterTopTexturedGiven { path: TexturePath::new(exact) })
        })
    }
}

impl Logic for RasterTopTextured {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wi, vi, tex_bits, qh, qn, cur, cur_live, cur_tex, first, cur_mant, cur_exp, last_in);
        for k in 0..8 {
            self.queue[k].clock.next = self.clock.val();
            self.queue[k].d.next = self.queue[k].q.val();
        }
        clock!(self, clock, cull_sort, core, path, pixel_out);
        self.cull_sort.width.next = self.width.val();
        self.cull_sort.height.next = self.height.val();
        self.cull_sort.cull_back.next = self.cull_back.val();
        self.core.width.next = self.width.val();
        self.core.height.next = self.height.val();

        // The slots in use: from the current one while its fragments may come, else the
        // queue's head, else the next verdict's; a triangle is taken while one is free
        // beyond the next.
        self.head.next = self.queue[0].q.val();
        for k in 1..8 {
            if self.qh.q.val().index() == k {
                self.head.next = self.queue[k].q.val();
            }
        }
        self.head_tex.next = self.tex_bits.q.val().get_bit(self.head.val().index());
        self.base.next = self.vi.q.val();
        if self.qn.q.val() != 0 {
            self.base.next = self.head.val();
        }
        if self.cur_live.q.val() {
            self.base.next = self.cur.q.val();
        }
        // (Field by field: a linked port has no name of its own inside to gate.)
        self.cull_sort.inp.v0_x.next = self.inp.v0_x.val();
        self.cull_sort.inp.v0_y.next = self.inp.v0_y.val();
        self.cull_sort.inp.v0_z.next = self.inp.v0_z.val();
        self.cull_sort.inp.v0_c0.next = self.inp.v0_c0.val();
        self.cull_sort.inp.v0_c1.next = self.inp.v0_c1.val();
        self.cull_sort.inp.v0_c2.next = self.inp.v0_c2.val();
        self.cull_sort.inp.v0_iw.next = self.inp.v0_iw.val();
        self.cull_sort.inp.v1_x.next = self.inp.v1_x.val();
        self.cull_sort.inp.v1_y.next = self.inp.v1_y.val();
        self.cull_sort.inp.v1_z.next = self.inp.v1_z.val();
        self.cull_sort.inp.v1_c0.next = self.inp.v1_c0.val();
        self.cull_sort.inp.v1_c1.next = self.inp.v1_c1.val();
        self.cull_sort.inp.v1_c2.next = self.inp.v1_c2.val();
        self.cull_sort.inp.v1_iw.next = self.inp.v1_iw.val();
        self.cull_sort.inp.v2_x.next = self.inp.v2_x.val();
        self.cull_sort.inp.v2_y.next = self.inp.v2_y.val();
        self.cull_sort.inp.v2_z.next = self.inp.v2_z.val();
        self.cull_sort.inp.v2_c0.next = self.inp.v2_c0.val();
        self.cull_sort.inp.v2_c1.next = self.inp.v2_c1.val();
        self.cull_sort.inp.v2_c2.next = self.inp.v2_c2.val();
        self.cull_sort.inp.v2_iw.next = self.inp.v2_iw.val();
        // (wi + 1 in a signal of its own: compared as an expression, Verilog would widen the
        // sum to 32 bits and never wrap it.)
        self.wi_next.next = self.wi.q.val() + 1;
        self.slot_free.next = self.wi_next.val() != self.base.val();
        self.cull_sort.inp.valid.next = self.inp.valid.val() & self.slot_free.val();
        self.inp.ready.next = self.cull_sort.inp.ready.val() & self.slot_free.val();
        Verdict::link(&mut self.verdict, &mut self.cull_sort.verdict);
        SortedSource::join(&mut self.cull_sort.out, &mut self.core.inp);
        self.core.inp_last.next = false;
        if self.inp.valid.val() & self.inp.ready.val() {
            self.last_in.d.next = self.inp_last.val();
        }

        // A triangle taken: its words into the slot `wi`.
        self.word_in.next = (bit_cast::<PW, XY>(self.inp.v0_x.val()) << self.at[0].val())
            | (bit_cast::<PW, XY>(self.inp.v0_y.val()) << self.at[1].val())
            | (bit_cast::<PW, XY>(self.inp.v1_x.val()) << self.at[2].val())
            | (bit_cast::<PW, XY>(self.inp.v1_y.val()) << self.at[3].val())
            | (bit_cast::<PW, XY>(self.inp.v2_x.val()) << self.at[4].val())
            | (bit_cast::<PW, XY>(self.inp.v2_y.val()) << self.at[5].val())
            | (bit_cast::<PW, ST>(self.tex.sq0.val()) << self.at[6].val())
            | (bit_cast::<PW, ST>(self.tex.sq1.val()) << self.at[7].val())
            | (bit_cast::<PW, ST>(self.tex.sq2.val()) << self.at[8].val())
            | (bit_cast::<PW, ST>(self.tex.tq0.val()) << self.at[9].val())
            | (bit_cast::<PW, ST>(self.tex.tq1.val()) << self.at[10].val())
            | (bit_cast::<PW, ST>(self.tex.tq2.val()) << self.at[11].val())
            | (bit_cast::<PW, QB>(self.tex.q0.val()) << self.at[12].val())
            | (bit_cast::<PW, QB>(self.tex.q1.val()) << self.at[13].val())
            | (bit_cast::<PW, QB>(self.tex.q2.val()) << self.at[14].val())
            | (bit_cast::<PW, 4>(self.tex_state.ws.val()) << self.at[15].val())
            | (bit_cast::<PW, 4>(self.tex_state.hs.val()) << self.at[16].val())
            | (bit_cast::<PW, 4>(self.tex_state.levels.val()) << self.at[17].val())
            | (bit_cast::<PW, TADDR>(self.tex_state.base.val()) << self.at[18].val())
            | (bit_cast::<PW, 2>(self.tex_state.mip.val()) << self.at[21].val())
            | (bit_cast::<PW, 2>(self.tex_state.wrap_s.val()) << self.at[22].val())
            | (bit_cast::<PW, 2>(self.tex_state.wrap_t.val()) << self.at[23].val())
            | (bit_cast::<PW, 3>(self.tex_state.format.val()) << self.at[24].val())
            | (bit_cast::<PW, 3>(self.tex_state.env.val()) << self.at[26].val())
            | (bit_cast::<PW, 3>(self.tex.mode.val()) << self.at[27].val());
        if self.tex_state.min_linear.val() {
            self.word_in.next = self.word_in.val().replace_bit(self.at[19].val().index(), true);
        }
        if self.tex_state.mag_linear.val() {
            self.word_in.next = self.word_in.val().replace_bit(self.at[20].val().index(), true);
        }
        if self.tex_state.gaussian.val() {
            self.word_in.next = self.word_in.val().replace_bit(self.at[25].val().index(), true);
        }
        self.slots.write_clock.next = self.clock.val();
        self.slots.read_clock.next = self.clock.val();
        self.slots.write_enable.next = self.inp.valid.val() & self.inp.ready.val();
        self.slots.write_address.next = self.wi.q.val();
        self.slots.write_data.next = self.word_in.val();
        if self.inp.valid.val() & self.inp.ready.val() {
            self.wi.d.next = self.wi.q.val() + 1;
            self.tex_bits.d.next = self.tex_bits.q.val().replace_bit(self.wi.q.val().index(), self.tex.textured.val());
        }

        // Verdicts in order: a passed triangle's slot joins the queue.
        if self.verdict.valid.val() {
            self.vi.d.next = self.vi.q.val() + 1;
        }
        self.push.next = self.verdict.valid.val() & (self.verdict.code.val() == 0);
        self.tail.next = self.qh.q.val() + bit_cast::<QB_LOG, 4>(self.qn.q.val());
        for k in 0..8 {
            if self.push.val() & (self.tail.val().index() == k) {
                self.queue[k].d.next = self.vi.q.val();
            }
        }

        // The edge walk takes a triangle once the one before has left span, an untextured
        // one once the texture path is idle too; the queue's head becomes the current one.
        self.core.hold.next = !self.core.walk_idle.val() | (!self.head_tex.val() & !self.path.idle.val());
        if self.push.val() & !self.core.handed.val() {
            self.qn.d.next = self.qn.q.val() + 1;
        }
        if !self.push.val() & self.core.handed.val() {
            self.qn.d.next = self.qn.q.val() - 1;
        }
        self.slots.read_address.next = self.cur.q.val();
        if self.core.handed.val() {
            self.qh.d.next = self.qh.q.val() + 1;
            self.cur.d.next = self.head.val();
            self.cur_live.d.next = true;
            self.cur_tex.d.next = self.head_tex.val();
            self.first.d.next = self.head_tex.val();
            self.cur_mant.d.next = self.core.recip_mant.val();
            self.cur_exp.d.next = self.core.recip_exp.val();
            self.slots.read_address.next = self.head.val();
        }
        if self.cur_live.q.val() & self.core.walk_idle.val() & !self.core.handed.val() {
            self.cur_live.d.next = false;
        }
        self.word.next = self.slots.read_data.val();

        // The current triangle as texture_path takes it.
        self.path.tri.x0.next = self.word.val().get_bits::<XY>(self.at[0].val().index());
        self.path.tri.y0.next = self.word.val().get_bits::<XY>(self.at[1].val().index());
        self.path.tri.x1.next = self.word.val().get_bits::<XY>(self.at[2].val().index());
        self.path.tri.y1.next = self.word.val().get_bits::<XY>(self.at[3].val().index());
        self.path.tri.x2.next = self.word.val().get_bits::<XY>(self.at[4].val().index());
        self.path.tri.y2.next = self.word.val().get_bits::<XY>(self.at[5].val().index());
        self.path.tri.sq0.next = self.word.val().get_bits::<ST>(self.at[6].val().index());
        self.path.tri.sq1.next = self.word.val().get_bits::<ST>(self.at[7].val().index());
        self.path.tri.sq2.next = self.word.val().get_bits::<ST>(self.at[8].val().index());
        self.path.tri.tq0.next = self.word.val().get_bits::<ST>(self.at[9].val().index());
        self.path.tri.tq1.next = self.word.val().get_bits::<ST>(self.at[10].val().index());
        self.path.tri.tq2.next = self.word.val().get_bits::<ST>(self.at[11].val().index());
        self.path.tri.q0.next = self.word.val().get_bits::<QB>(self.at[12].val().index());
        self.path.tri.q1.next = self.word.val().get_bits::<QB>(self.at[13].val().index());
        self.path.tri.q2.next = self.word.val().get_bits::<QB>(self.at[14].val().index());
        self.path.tri.mant.next = self.cur_mant.q.val();
        self.path.tri.exp.next = self.cur_exp.q.val();
        self.path.state.ws.next = self.word.val().get_bits::<4>(self.at[15].val().index());
        self.path.state.hs.next = self.word.val().get_bits::<4>(self.at[16].val().index());
        self.path.state.levels.next = self.word.val().get_bits::<4>(self.at[17].val().index());
        self.path.state.base.next = self.word.val().get_bits::<TADDR>(self.at[18].val().index());
        self.path.state.min_linear.next = self.word.val().get_bit(self.at[19].val().index());
        self.path.state.mag_linear.next = self.word.val().get_bit(self.at[20].val().index());
        self.path.state.mip.next = self.word.val().get_bits::<2>(self.at[21].val().index());
        self.path.state.wrap_s.next = self.word.val().get_bits::<2>(self.at[22].val().index());
        self.path.state.wrap_t.next = self.word.val().get_bits::<2>(self.at[23].val().index());
        self.path.state.format.next = self.word.val().get_bits::<3>(self.at[24].val().index());
        self.path.state.gaussian.next = self.word.val().get_bit(self.at[25].val().index());
        self.path.state.env.next = self.word.val().get_bits::<3>(self.at[26].val().index());
        self.path.tri_mode.next = self.word.val().get_bits::<3>(self.at[27].val().index());

        // Fragments: a textured triangle's through texture_path (its first with inp_new),
        // an untextured one's straight to pixel_out with alpha 255.
        self.path.inp.x.next = self.core.out.x.val();
        self.path.inp.y.next = self.core.out.y.val();
        self.path.inp.z.next = self.core.out.z.val();
        self.path.inp.rgb0.next = self.core.out.rgb0.val();
        self.path.inp.rgb1.next = self.core.out.rgb1.val();
        self.path.inp.rgb2.next = self.core.out.rgb2.val();
        self.path.inp.valid.next = self.core.out.valid.val() & self.cur_tex.q.val();
        self.path.inp_new.next = self.first.q.val();
        self.path.inp_flush.next = self.inp_flush.val();
        if self.path.inp.valid.val() & self.path.inp.ready.val() {
            self.first.d.next = false;
        }
        self.path.out.ready.next = self.pixel_out.inp.ready.val() & self.cur_tex.q.val();
        if self.cur_tex.q.val() {
            self.core.out.ready.next = self.path.inp.ready.val();
            self.pixel_out.inp.valid.next = self.path.out.valid.val();
            self.pixel_out.inp.x.next = self.path.out.x.val();
            self.pixel_out.inp.y.next = self.path.out.y.val();
            self.pixel_out.inp.z.next = self.path.out.z.val();
            self.pixel_out.inp.rgb0.next = self.path.out.rgb0.val();
            self.pixel_out.inp.rgb1.next = self.path.out.rgb1.val();
            self.pixel_out.inp.rgb2.next = self.path.out.rgb2.val();
            self.pixel_out.inp.alpha.next = self.path.out.alpha.val();
            self.pixel_out.inp.mode.next = self.path.out.mode.val();
        } else {
            self.core.out.ready.next = self.pixel_out.inp.ready.val();
            self.pixel_out.inp.valid.next = self.core.out.valid.val();
            self.pixel_out.inp.x.next = self.core.out.x.val();
            self.pixel_out.inp.y.next = self.core.out.y.val();
            self.pixel_out.inp.z.next = self.core.out.z.val();
            self.pixel_out.inp.rgb0.next = self.core.out.rgb0.val();
            self.pixel_out.inp.rgb1.next = self.core.out.rgb1.val();
            self.pixel_out.inp.rgb2.next = self.core.out.rgb2.val();
            self.pixel_out.inp.alpha.next = 255.into();
            self.pixel_out.inp.mode.next = self.word.val().get_bits::<3>(self.at[27].val().index());
        }
        BlendMemoryPort::link(&mut self.mem, &mut self.pixel_out.mem);
        TexMemory::link(&mut self.tex_mem, &mut self.path.mem);
        CacheCounters::link(&mut self.counters, &mut self.path.counters);
        self.done.next = self.last_in.q.val()
            & self.cull_sort.idle.val()
            & self.core.idle.val()
            & self.path.idle.val()
            & self.pixel_out.idle.val();
    }
}

crate::pins!(RasterTopTextured {
    clock: clock,
    inputs: [width, height, inp_last, cull_back, inp_flush],
    outputs: [done],
    links: [inp, tex, tex_state, mem, verdict, tex_mem, counters],
});

/// `raster_top` with `TEXTURE = 1`: the textured rasterizer with `params["K"]` setup
/// multipliers, a `params["L"]`-stage divider, the parts `parts` and the level-of-detail
/// rule `params["EXACT"]`.
pub fn emit(params: &Params, parts: &Parts) -> Result<Emitted, String> {
    let exact = crate::exact_rule("raster_top", params)?;
    let top = RasterTopTextured::new(params["K"] as usize, params["L"] as usize, parts, exact)?;
    Ok(emit_unit("raster_top", top, params))
}
