//! The command parser of 001 (§II.1, Fig. 4): `model::command_parser`, cycle for cycle. It
//! waits for `start` (INIT), reads and checks a vertex buffer's header (Header), then for
//! each triangle reads and checks its index record (Tri Index), looks its three vertices up
//! in the post-transform vertex cache and fetches the ones it misses (vertex fetch), and
//! hands the triangle to the rasterizer when the output register is free (CP Ready), until
//! the record that ends the buffer. Every rule a buffer breaks stops it in Error with the
//! model's code (`model::vertex_buffer::Fault`).
//!
//! Memory is read through an AXI4 read master (`links::ReadMaster`: 128-bit data, INCR bursts,
//! one outstanding, every beat taken). A burst shifts into [`WORDS`] 32-bit registers from
//! the top, four words a beat, so that once its last beat is in a header's word `i` is
//! register `i` and a record's word `i` register [`RECORD_AT`] + `i`; [`HeaderCheck`],
//! [`IndexCheck`] and [`VertexCheck`] check them the cycle after, as
//! `vertex_buffer::read_header`, `read_index_record` and `read_vertex_record` do. The
//! header's screen must fit `max_width` x `max_height` (the buffers of `gpu_top`'s host).
//!
//! Index record t + 1 is read ahead while triangle t is assembled (the model's timing):
//! asked for when record t is checked or taken from ahead, checked as it comes in (as
//! triangle t + 1's: [`IndexCheck`]'s `t` is one more outside Tri Index), and held with its
//! error code in the `ahead_*` registers until triangle t is handed over.
//!
//! The vertex cache is `2^CB` entries of block RAM, direct-mapped by the vertex index: a
//! RAM of tags (the index an entry holds) beside a RAM of vertices (the six words at their
//! formats). Their reads are synchronous, so the read address is the vertex the parser
//! will look up in the next cycle (vertex `k` of the record, as `k` and the record will
//! be); an entry written in the cycle before a lookup is taken from a bypass register.
//! Which entries hold a vertex of the current buffer is `G` registers of 16 bits, cleared
//! when a buffer starts.

use super::cull_sort::{COLOR, INV_W, XY, Z};
use super::links::{ParsedSource, ReadMaster};
use super::widths::{CLASS, FORMATS};
use crate::emit::{emit_unit, Emitted};
use crate::parts::defaults;
use crate::Params;
use blank::Blank;
use model::vertex_buffer::{format_word, HEADER_BYTES, MAGIC, NO_TEXTURE, RECORD_BYTES, VERSION};
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::RAM;

/// Bytes per beat of the read bus: `model::command_parser::Params::beat_bytes` of the RTL.
pub const BEAT_BYTES: u32 = 16;
/// The burst registers: a header's words.
pub const WORDS: usize = HEADER_BYTES / 4;
/// A record's words.
const RECORD: usize = RECORD_BYTES / 4;
/// The register a record's first word is in once its last beat is.
pub const RECORD_AT: usize = WORDS - RECORD;
// A kernel's array indices are numbers (rust-hdl evaluates them without Rust's
// constants): the kernel writes RECORD_AT as 16, the four top registers as 20 to 23, a
// record's last beat as 1 and a header's as 5.
const _: () = assert!(WORDS == 24 && RECORD == 8 && RECORD_AT == 16 && BEAT_BYTES == 16);
/// A vertex as the cache and the output register hold it: x, y, z, R, G, B from bit 0 up.
const VTX: usize = 2 * XY + Z + 3 * COLOR;
/// Entries a register of the cache's valid flags covers.
const VALID_GROUP: usize = 16;

/// The vertex cache sizes the RTL is built for (`CACHE`).
pub const CACHE_SIZES: [u32; 5] = [16, 64, 256, 512, 1024];

/// Fig. 4's states (`model::command_parser::State`, in its order: the `state` port's code).
#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum ParserState {
    Init,
    Header,
    TriIndex,
    VertexFetch,
    CpReady,
    End,
    Error,
}

/// What the burst being received is.
#[derive(Copy, Clone, PartialEq, Eq, Debug, LogicState)]
pub enum BurstKind {
    Header,
    Index,
    Vertex,
}

/// `ok` = the 32-bit field `w` holds a word of an `N`-bit format, sign- or zero-extended
/// (`vertex_buffer::unfield`): the bits from `shift` up (`N` - 1 for a signed format, `N`
/// for an unsigned one) are 0, or, signed, all 1.
#[derive(LogicBlock, Blank)]
pub struct FieldFits {
    pub w: Signal<In, Bits<32>>,
    pub ok: Signal<Out, Bit>,
    shift: Constant<Bits<8>>,
    /// The bits from `shift` up all 1, shifted down.
    ones: Constant<Bits<32>>,
    sign_ext: Constant<Bit>,
    /// A 32-bit unsigned format: every word.
    every: Constant<Bit>,
    high: Signal<Local, Bits<32>>,
}

impl FieldFits {
    /// A field of `n` bits, signed or not.
    pub fn new(n: usize, signed: bool) -> FieldFits {
        assert!((1..=32).contains(&n), "a field of {n} bits");
        let shift = if signed { n - 1 } else { n };
        FieldFits {
            shift: Constant::new((shift.min(31) as u64).to_bits()),
            ones: Constant::new(bits((u32::MAX >> shift.min(31)) as u64)),
            sign_ext: Constant::new(signed),
            every: Constant::new(shift == 32),
            ..FieldFits::blank()
        }
    }
}

impl Logic for FieldFits {
    #[hdl_gen]
    fn update(&mut self) {
        self.high.next = self.w.val() >> self.shift.val();
        self.ok.next =
            self.every.val() | !self.high.val().any() | (self.sign_ext.val() & (self.high.val() == self.ones.val()));
    }
}

/// `eq` = `w` is the constant word given.
#[derive(LogicBlock)]
pub struct WordIs {
    pub w: Signal<In, Bits<32>>,
    pub eq: Signal<Out, Bit>,
    word: Constant<Bits<32>>,
}

impl WordIs {
    pub fn new(word: u32) -> WordIs {
        WordIs { w: Default::default(), eq: Default::default(), word: Constant::new(bits(word.into())) }
    }
}

impl Logic for WordIs {
    #[hdl_gen]
    fn update(&mut self) {
        self.eq.next = self.w.val() == self.word.val();
    }
}

/// The header's rules (`vertex_buffer::read_header` for this hardware, then the parser's
/// own: its bytes from `base` stay below 2^32, its screen inside `max_width` x
/// `max_height`): `fault` is the first broken rule's `Fault` code, 0 for none.
#[derive(LogicBlock, Blank)]
pub struct HeaderCheck {
    /// The header's words.
    pub h: [Signal<In, Bits<32>>; WORDS],
    pub base: Signal<In, Bits<32>>,
    pub max_width: Signal<In, Bits<16>>,
    pub max_height: Signal<In, Bits<16>>,
    pub fault: Signal<Out, Bits<4>>,
    #[given]
    magic: WordIs,
    #[given]
    size_class: WordIs,
    /// Words 10-20: the hardware's format words (`Formats::named` order).
    #[given]
    formats: [WordIs; 11],
    version: Constant<Bits<16>>,
    /// The largest screen side: 2^CLASS, at most `scene::trilist::MAX_RESOLUTION`.
    side: Constant<Bits<16>>,
    header_bytes: Constant<Bits<38>>,
    five: Constant<Bits<8>>,
    two_32: Constant<Bits<33>>,
    width: Signal<Local, Bits<16>>,
    height: Signal<Local, Bits<16>>,
    build_bad: Signal<Local, Bit>,
    /// The index list's and the vertex array's first and end bytes, and the length, in 38
    /// bits.
    index_at: Signal<Local, Bits<38>>,
    index_end: Signal<Local, Bits<38>>,
    vertex_at: Signal<Local, Bits<38>>,
    vertex_end: Signal<Local, Bits<38>>,
    length: Signal<Local, Bits<38>>,
    layout_bad: Signal<Local, Bit>,
}

impl Default for HeaderCheck {
    fn default() -> Self {
        let side = (1u64 << CLASS).min(u64::from(scene::trilist::MAX_RESOLUTION));
        let named = FORMATS.named();
        let given = HeaderCheckGiven {
            magic: WordIs::new(u32::from_le_bytes(MAGIC)),
            size_class: WordIs::new(CLASS),
            formats: std::array::from_fn(|i| WordIs::new(format_word(named[i].1))),
        };
        HeaderCheck {
            h: defaults(),
            version: Constant::new(bits(u64::from(VERSION))),
            side: Constant::new(bits(side)),
            header_bytes: Constant::new(bits(HEADER_BYTES as u64)),
            five: Constant::new(bits(5)),
            two_32: Constant::new(bits(1 << 32)),
            ..HeaderCheck::blank(given)
        }
    }
}

impl Logic for HeaderCheck {
    #[hdl_gen]
    fn update(&mut self) {
        // Word 2: the screen; 3: the size class; 10-20: the formats.
        self.magic.w.next = self.h[0].val();
        self.size_class.w.next = self.h[3].val();
        for i in 0..11 {
            self.formats[i].w.next = self.h[i + 10].val();
        }
        self.width.next = self.h[2].val().get_bits::<16>(0);
        self.height.next = self.h[2].val().get_bits::<16>(16);
        self.build_bad.next = !(self.size_class.eq.val()
            & self.formats[0].eq.val()
            & self.formats[1].eq.val()
            & self.formats[2].eq.val()
            & self.formats[3].eq.val()
            & self.formats[4].eq.val()
            & self.formats[5].eq.val()
            & self.formats[6].eq.val()
            & self.formats[7].eq.val()
            & self.formats[8].eq.val()
            & self.formats[9].eq.val()
            & self.formats[10].eq.val())
            | !self.width.val().any()
            | !self.height.val().any()
            | (self.width.val() > self.side.val())
            | (self.height.val() > self.side.val());
        // Words 4-8: T, V, the arrays' offsets, the length. Each array starts past the
        // header on a record boundary and ends inside the length; they do not overlap; the
        // buffer ends at or below 2^32.
        self.index_at.next = bit_cast::<38, 32>(self.h[6].val());
        self.vertex_at.next = bit_cast::<38, 32>(self.h[7].val());
        self.length.next = bit_cast::<38, 32>(self.h[8].val());
        self.index_end.next = self.index_at.val() + (bit_cast::<38, 32>(self.h[4].val()) << self.five.val());
        self.vertex_end.next = self.vertex_at.val() + (bit_cast::<38, 32>(self.h[5].val()) << self.five.val());
        self.layout_bad.next = self.h[6].val().get_bits::<5>(0).any()
            | (self.index_at.val() < self.header_bytes.val())
            | (self.index_end.val() > self.length.val())
            | self.h[7].val().get_bits::<5>(0).any()
            | (self.vertex_at.val() < self.header_bytes.val())
            | (self.vertex_end.val() > self.length.val())
            | (self.h[4].val().any()
                & self.h[5].val().any()
                & (self.index_at.val() < self.vertex_end.val())
                & (self.vertex_at.val() < self.index_end.val()))
            | ((bit_cast::<33, 32>(self.base.val()) + bit_cast::<33, 32>(self.h[8].val())) > self.two_32.val());
        // The first rule broken wins: magic, version, flags and reserved bytes, build,
        // layout, the screen on the host's buffers.
        self.fault.next = 0.into();
        if (self.width.val() > self.max_width.val()) | (self.height.val() > self.max_height.val()) {
            self.fault.next = 12.into();
        }
        if self.layout_bad.val() {
            self.fault.next = 5.into();
        }
        if self.build_bad.val() {
            self.fault.next = 4.into();
        }
        if self.h[1].val().get_bits::<15>(17).any()
            | self.h[9].val().get_bits::<8>(24).any()
            | self.h[21].val().any()
            | self.h[22].val().any()
            | self.h[23].val().any()
        {
            self.fault.next = 3.into();
        }
        if self.h[1].val().get_bits::<16>(0) != self.version.val() {
            self.fault.next = 2.into();
        }
        if !self.magic.eq.val() {
            self.fault.next = 1.into();
        }
    }
}

/// An index record's rules (`vertex_buffer::read_index_record`) for triangle `t` of a
/// buffer of `triangles` and `vertices`: `fault` is the first broken rule's code, 0 for
/// none.
#[derive(LogicBlock, Blank)]
pub struct IndexCheck {
    /// The record's words.
    pub r: [Signal<In, Bits<32>>; RECORD],
    pub t: Signal<In, Bits<32>>,
    pub triangles: Signal<In, Bits<32>>,
    pub vertices: Signal<In, Bits<32>>,
    pub fault: Signal<Out, Bits<4>>,
    /// Each `inv_w` word: a non-negative word of the format (`INV_W` bits, less the sign).
    #[given]
    iw: [FieldFits; 3],
    no_texture: Constant<Bits<16>>,
    /// 1 in the `inv_w` format.
    one: Constant<Bits<32>>,
    last: Signal<Local, Bit>,
    eob: Signal<Local, Bit>,
    eof: Signal<Local, Bit>,
    ti_bad: Signal<Local, Bit>,
    iw_bad: Signal<Local, Bit>,
}

impl Default for IndexCheck {
    fn default() -> Self {
        let f = FORMATS.inv_w;
        let given = IndexCheckGiven { iw: std::array::from_fn(|_| FieldFits::new(INV_W - f.signed as usize, false)) };
        IndexCheck {
            r: defaults(),
            no_texture: Constant::new(bits(u64::from(NO_TEXTURE))),
            one: Constant::new(bits(1 << f.frac)),
            ..IndexCheck::blank(given)
        }
    }
}

impl Logic for IndexCheck {
    #[hdl_gen]
    fn update(&mut self) {
        // Word 3, TI: no texture, bits 18-31 clear, end of buffer on the last triangle
        // only, end of frame on it only.
        self.last.next = (self.t.val() + 1) == self.triangles.val();
        self.eob.next = self.r[3].val().get_bit(16);
        self.eof.next = self.r[3].val().get_bit(17);
        self.ti_bad.next = (self.r[3].val().get_bits::<16>(0) != self.no_texture.val())
            | self.r[3].val().get_bits::<14>(18).any()
            | (self.eob.val() ^ self.last.val())
            | (self.eof.val() & !self.last.val());
        // Words 4-6, inv_w: non-negative words of the format, the largest 1.
        for k in 0..3 {
            self.iw[k].w.next = self.r[k + 4].val();
        }
        self.iw_bad.next = !self.iw[0].ok.val()
            | !self.iw[1].ok.val()
            | !self.iw[2].ok.val()
            | (self.r[4].val() > self.one.val())
            | (self.r[5].val() > self.one.val())
            | (self.r[6].val() > self.one.val())
            | !((self.r[4].val() == self.one.val())
                | (self.r[5].val() == self.one.val())
                | (self.r[6].val() == self.one.val()));
        // The first rule broken wins: V0-V2 inside the vertex array, TI, inv_w, word 7 clear.
        self.fault.next = 0.into();
        if self.r[7].val().any() {
            self.fault.next = 3.into();
        }
        if self.iw_bad.val() {
            self.fault.next = 8.into();
        }
        if self.ti_bad.val() {
            self.fault.next = 7.into();
        }
        if (self.r[0].val() >= self.vertices.val())
            | (self.r[1].val() >= self.vertices.val())
            | (self.r[2].val() >= self.vertices.val())
        {
            self.fault.next = 6.into();
        }
    }
}

/// A vertex record's rules (`vertex_buffer::read_vertex_record`): `fault` is the first
/// broken rule's code, 0 for none.
#[derive(LogicBlock, Blank)]
pub struct VertexCheck {
    /// The record's words.
    pub r: [Signal<In, Bits<32>>; RECORD],
    pub fault: Signal<Out, Bits<4>>,
    /// Words 0-5 in their formats: x, y (`xy`), z, R, G, B (`color`).
    #[given]
    fits: [FieldFits; 6],
}

impl Default for VertexCheck {
    fn default() -> Self {
        let f = &FORMATS;
        let fmt = [f.xy, f.xy, f.z, f.color, f.color, f.color];
        let width = [XY, XY, Z, COLOR, COLOR, COLOR];
        let given = VertexCheckGiven { fits: std::array::from_fn(|i| FieldFits::new(width[i], fmt[i].signed)) };
        VertexCheck { r: defaults(), ..VertexCheck::blank(given) }
    }
}

impl Logic for VertexCheck {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..6 {
            self.fits[i].w.next = self.r[i].val();
        }
        // The first rule broken wins: the six words in their formats, words 6-7 clear.
        self.fault.next = 0.into();
        if self.r[6].val().any() | self.r[7].val().any() {
            self.fault.next = 3.into();
        }
        if !(self.fits[0].ok.val()
            & self.fits[1].ok.val()
            & self.fits[2].ok.val()
            & self.fits[3].ok.val()
            & self.fits[4].ok.val()
            & self.fits[5].ok.val())
        {
            self.fault.next = 9.into();
        }
    }
}

/// The command parser with a vertex cache of `2^CB` entries, `G` = 2^CB / 16 registers of
/// their valid flags (see the module's documentation; `model::command_parser::CommandParser`
/// with `beat_bytes` 8 and `cache` 2^CB).
#[derive(LogicBlock, Blank)]
pub struct CommandParser<const CB: usize, const G: usize> {
    pub clock: Signal<In, Clock>,
    /// Start reading the buffer at `address` (taken in INIT and Error).
    pub start: Signal<In, Bit>,
    pub address: Signal<In, Bits<32>>,
    /// The largest screen the host's colour and depth buffers hold: a header asking for
    /// more stops the parser (`Fault::Screen`).
    pub max_width: Signal<In, Bits<16>>,
    pub max_height: Signal<In, Bits<16>>,
    pub bus: ReadMaster,
    /// The triangles, to the rasterizer.
    pub out: ParsedSource,
    /// The header's render state, from the cycle after the header is checked until the
    /// next start.
    pub render_valid: Signal<Out, Bit>,
    pub width: Signal<Out, Bits<16>>,
    pub height: Signal<Out, Bits<16>>,
    pub cull_back: Signal<Out, Bit>,
    /// The background colour: R in bits 0-7, G, B.
    pub background: Signal<Out, Bits<24>>,
    /// `ParserState`'s code.
    pub state: Signal<Out, Bits<3>>,
    /// The error code in Error (`vertex_buffer::Fault`), else 0.
    pub fault: Signal<Out, Bits<4>>,
    /// One cycle each: the frame's (buffer's) last triangle was taken, or a buffer of none
    /// was read.
    pub frame_done: Signal<Out, Bit>,
    pub buffer_done: Signal<Out, Bit>,
    st: DFF<ParserState>,
    fault_r: DFF<Bits<4>>,
    base: DFF<Bits<32>>,
    render_r: DFF<Bit>,
    width_r: DFF<Bits<16>>,
    height_r: DFF<Bits<16>>,
    cull_r: DFF<Bit>,
    background_r: DFF<Bits<24>>,
    triangles: DFF<Bits<32>>,
    vertices: DFF<Bits<32>>,
    /// The next index record's address, and the vertex array's.
    index_addr: DFF<Bits<32>>,
    vertex_base: DFF<Bits<32>>,
    /// The read offered; the burst asked for and being received (its beats so far); a
    /// burst received whole, checked this cycle; an error answered in it.
    ar_valid: DFF<Bit>,
    ar_addr: DFF<Bits<32>>,
    ar_len: DFF<Bits<8>>,
    burst: DFF<Bit>,
    kind: DFF<BurstKind>,
    beat: DFF<Bits<4>>,
    complete: DFF<Bit>,
    bus_error: DFF<Bit>,
    w: [DFF<Bits<32>>; WORDS],
    /// Triangle `t`: its index record's V0-V2, inv_w words and end flags, and its vertices
    /// assembled (`k` so far).
    t: DFF<Bits<32>>,
    rec_v: [DFF<Bits<32>>; 3],
    rec_iw: [DFF<Bits<INV_W>>; 3],
    rec_eob: DFF<Bit>,
    rec_eof: DFF<Bit>,
    /// Record `t + 1`, read ahead while triangle `t` is assembled: held, its error code (0
    /// none), its V0-V2, inv_w words and end flags.
    ahead_valid: DFF<Bit>,
    ahead_fault: DFF<Bits<4>>,
    ahead_v: [DFF<Bits<32>>; 3],
    ahead_iw: [DFF<Bits<INV_W>>; 3],
    ahead_eob: DFF<Bit>,
    ahead_eof: DFF<Bit>,
    k: DFF<Bits<2>>,
    asm: [DFF<Bits<VTX>>; 3],
    /// The vertex cache: entries holding a vertex of this buffer (entry `16 g + i` is bit
    /// `i` of `valid[g]`), the block RAMs of tags and vertices, and the entry written last
    /// cycle.
    valid: [DFF<Bits<VALID_GROUP>>; G],
    tag_ram: RAM<Bits<32>, CB>,
    vtx_ram: RAM<Bits<VTX>, CB>,
    byp_valid: DFF<Bit>,
    byp_tag: DFF<Bits<32>>,
    byp_vtx: DFF<Bits<VTX>>,
    /// The output register.
    out_valid: DFF<Bit>,
    out_vtx: [DFF<Bits<VTX>>; 3],
    out_iw: [DFF<Bits<INV_W>>; 3],
    out_eob: DFF<Bit>,
    out_eof: DFF<Bit>,
    frame_r: DFF<Bit>,
    buffer_r: DFF<Bit>,
    header_check: HeaderCheck,
    index_check: IndexCheck,
    vertex_check: VertexCheck,
    /// Shifts: a record (5), a valid flags' register (4), the fields in a vertex.
    five: Constant<Bits<16>>,
    four: Constant<Bits<16>>,
    at_y: Constant<Bits<16>>,
    at_z: Constant<Bits<16>>,
    at_c0: Constant<Bits<16>>,
    at_c1: Constant<Bits<16>>,
    at_c2: Constant<Bits<16>>,
    out_free: Signal<Local, Bit>,
    beat_in: Signal<Local, Bit>,
    last_beat: Signal<Local, Bits<4>>,
    go: Signal<Local, Bit>,
    check: Signal<Local, Bit>,
    look: Signal<Local, Bit>,
    hand: Signal<Local, Bit>,
    vertex_in: Signal<Local, Bit>,
    load_rec: Signal<Local, Bit>,
    /// The record that came in is `t + 1`'s, read ahead (not in Tri Index); the current
    /// record is taken from ahead this cycle.
    is_ahead: Signal<Local, Bit>,
    load_ahead: Signal<Local, Bit>,
    /// A read decided on this cycle: its address and what it reads.
    ask: Signal<Local, Bit>,
    ask_addr: Signal<Local, Bits<32>>,
    ask_kind: Signal<Local, BurstKind>,
    kn: Signal<Local, Bits<2>>,
    v_cur: Signal<Local, Bits<32>>,
    slot: Signal<Local, Bits<CB>>,
    /// The slot's valid flag: register `group`, bit `lane`.
    group: Signal<Local, Bits<CB>>,
    lane: Signal<Local, Bits<4>>,
    held: Signal<Local, Bit>,
    tag: Signal<Local, Bits<32>>,
    vtx: Signal<Local, Bits<VTX>>,
    hit: Signal<Local, Bit>,
    fetched: Signal<Local, Bits<VTX>>,
    cur: Signal<Local, Bits<VTX>>,
    /// The slots of V0-V2 and of vertex k, as they will be next cycle.
    rvn: [Signal<Local, Bits<CB>>; 3],
    v_next: Signal<Local, Bits<CB>>,
}

impl<const CB: usize, const G: usize> CommandParser<CB, G> {
    pub fn new() -> Self {
        assert!(
            G * VALID_GROUP == 1 << CB && CACHE_SIZES.contains(&(1 << CB)),
            "CommandParser<{CB}, {G}>: 2^CB entries, G = 2^CB / {VALID_GROUP}"
        );
        let shift = |n: usize| Constant::new(bits(n as u64));
        CommandParser {
            w: defaults(),
            rec_v: defaults(),
            rec_iw: defaults(),
            asm: defaults(),
            valid: defaults(),
            out_vtx: defaults(),
            out_iw: defaults(),
            five: shift(5),
            four: shift(4),
            at_y: shift(XY),
            at_z: shift(2 * XY),
            at_c0: shift(2 * XY + Z),
            at_c1: shift(2 * XY + Z + COLOR),
            at_c2: shift(2 * XY + Z + 2 * COLOR),
            rvn: defaults(),
            ..CommandParser::blank()
        }
    }
}

impl<const CB: usize, const G: usize> Default for CommandParser<CB, G> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const CB: usize, const G: usize> Logic for CommandParser<CB, G> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            st,
            fault_r,
            base,
            render_r,
            width_r,
            height_r,
            cull_r,
            background_r,
            triangles,
            vertices,
            index_addr,
            vertex_base,
            ar_valid,
            ar_addr,
            ar_len,
            burst,
            kind,
            beat,
            complete,
            bus_error,
            t,
            rec_eob,
            rec_eof,
            ahead_valid,
            ahead_fault,
            ahead_eob,
            ahead_eof,
            k,
            byp_valid,
            byp_tag,
            byp_vtx,
            out_valid,
            out_eob,
            out_eof,
            frame_r,
            buffer_r
        );
        for i in 0..3 {
            self.rec_v[i].clock.next = self.clock.val();
            self.rec_v[i].d.next = self.rec_v[i].q.val();
            self.rec_iw[i].clock.next = self.clock.val();
            self.rec_iw[i].d.next = self.rec_iw[i].q.val();
            self.ahead_v[i].clock.next = self.clock.val();
            self.ahead_v[i].d.next = self.ahead_v[i].q.val();
            self.ahead_iw[i].clock.next = self.clock.val();
            self.ahead_iw[i].d.next = self.ahead_iw[i].q.val();
            self.asm[i].clock.next = self.clock.val();
            self.asm[i].d.next = self.asm[i].q.val();
            self.out_vtx[i].clock.next = self.clock.val();
            self.out_vtx[i].d.next = self.out_vtx[i].q.val();
            self.out_iw[i].clock.next = self.clock.val();
            self.out_iw[i].d.next = self.out_iw[i].q.val();
        }
        for i in 0..WORDS {
            self.w[i].clock.next = self.clock.val();
            self.w[i].d.next = self.w[i].q.val();
        }
        for g in 0..G {
            self.valid[g].clock.next = self.clock.val();
            self.valid[g].d.next = self.valid[g].q.val();
        }
        self.tag_ram.read_clock.next = self.clock.val();
        self.tag_ram.write_clock.next = self.clock.val();
        self.vtx_ram.read_clock.next = self.clock.val();
        self.vtx_ram.write_clock.next = self.clock.val();
        self.kn.next = self.k.q.val();
        self.load_rec.next = false;
        self.load_ahead.next = false;
        self.ask.next = false;
        self.ask_addr.next = 0.into();
        self.ask_kind.next = BurstKind::Index;
        self.vertex_in.next = false;
        self.byp_valid.d.next = false;

        // The checks read the burst registers: a header from word 0, a record from RECORD_AT.
        for i in 0..WORDS {
            self.header_check.h[i].next = self.w[i].q.val();
        }
        self.header_check.base.next = self.base.q.val();
        self.header_check.max_width.next = self.max_width.val();
        self.header_check.max_height.next = self.max_height.val();
        for i in 0..RECORD {
            self.index_check.r[i].next = self.w[i + 16].q.val();
            self.vertex_check.r[i].next = self.w[i + 16].q.val();
        }
        // A record read ahead is triangle t + 1's.
        self.is_ahead.next = self.st.q.val() != ParserState::TriIndex;
        self.index_check.t.next = self.t.q.val();
        if self.is_ahead.val() {
            self.index_check.t.next = self.t.q.val() + 1;
        }
        self.index_check.triangles.next = self.triangles.q.val();
        self.index_check.vertices.next = self.vertices.q.val();

        // Vertex k of the triangle: its index, its cache entry (the block RAMs', or the one
        // written last cycle) and whether that holds it; the vertex record just read.
        self.v_cur.next = self.rec_v[0].q.val();
        for i in 1..3 {
            if self.k.q.val().index() == i {
                self.v_cur.next = self.rec_v[i].q.val();
            }
        }
        self.slot.next = self.v_cur.val().get_bits::<CB>(0);
        self.group.next = self.slot.val() >> self.four.val();
        self.lane.next = self.v_cur.val().get_bits::<4>(0);
        self.held.next = false;
        for g in 0..G {
            if self.group.val().index() == g {
                self.held.next = self.valid[g].q.val().get_bit(self.lane.val().index());
            }
        }
        self.tag.next = self.tag_ram.read_data.val();
        self.vtx.next = self.vtx_ram.read_data.val();
        if self.byp_valid.q.val() & (self.byp_tag.q.val().get_bits::<CB>(0) == self.slot.val()) {
            self.tag.next = self.byp_tag.q.val();
            self.vtx.next = self.byp_vtx.q.val();
        }
        self.hit.next = self.held.val() & (self.tag.val() == self.v_cur.val());
        self.fetched.next = bit_cast::<VTX, XY>(self.w[16].q.val().get_bits::<XY>(0))
            | (bit_cast::<VTX, XY>(self.w[17].q.val().get_bits::<XY>(0)) << self.at_y.val())
            | (bit_cast::<VTX, Z>(self.w[18].q.val().get_bits::<Z>(0)) << self.at_z.val())
            | (bit_cast::<VTX, COLOR>(self.w[19].q.val().get_bits::<COLOR>(0)) << self.at_c0.val())
            | (bit_cast::<VTX, COLOR>(self.w[20].q.val().get_bits::<COLOR>(0)) << self.at_c1.val())
            | (bit_cast::<VTX, COLOR>(self.w[21].q.val().get_bits::<COLOR>(0)) << self.at_c2.val());
        self.tag_ram.write_enable.next = false;
        self.tag_ram.write_address.next = self.slot.val();
        self.tag_ram.write_data.next = self.v_cur.val();
        self.vtx_ram.write_enable.next = false;
        self.vtx_ram.write_address.next = self.slot.val();
        self.vtx_ram.write_data.next = self.fetched.val();

        // The output register: taken this cycle (its end flags pulse), or free.
        self.frame_r.d.next = false;
        self.buffer_r.d.next = false;
        self.out_free.next = !self.out_valid.q.val() | self.out.ready.val();
        if self.out_valid.q.val() & self.out.ready.val() {
            self.out_valid.d.next = false;
            self.frame_r.d.next = self.out_eof.q.val();
            self.buffer_r.d.next = self.out_eob.q.val();
        }

        // The bus: the address taken; a beat shifted in from the top, the burst's last
        // making it complete.
        self.complete.d.next = false;
        if self.ar_valid.q.val() & self.bus.ar_ready.val() {
            self.ar_valid.d.next = false;
        }
        self.beat_in.next =
            self.burst.q.val() & self.bus.r_valid.val() & !(self.ar_valid.q.val() & !self.bus.ar_ready.val());
        self.last_beat.next = 1.into();
        if self.kind.q.val() == BurstKind::Header {
            self.last_beat.next = 5.into();
        }
        if self.beat_in.val() {
            for i in 0..(WORDS - 4) {
                self.w[i].d.next = self.w[i + 4].q.val();
            }
            self.w[20].d.next = self.bus.r_data.val().get_bits::<32>(0);
            self.w[21].d.next = self.bus.r_data.val().get_bits::<32>(32);
            self.w[22].d.next = self.bus.r_data.val().get_bits::<32>(64);
            self.w[23].d.next = self.bus.r_data.val().get_bits::<32>(96);
            self.bus_error.d.next = self.bus_error.q.val() | self.bus.r_resp.val().any();
            self.beat.d.next = self.beat.q.val() + 1;
            if self.beat.q.val() == self.last_beat.val() {
                self.burst.d.next = false;
                self.complete.d.next = true;
            }
        }

        // Fig. 4: what each state does this cycle.
        self.go.next = false;
        self.check.next = false;
        self.look.next = false;
        self.hand.next = false;
        match self.st.q.val() {
            ParserState::Init => {
                self.go.next = self.start.val();
            }
            ParserState::Error => {
                self.go.next = self.start.val();
            }
            ParserState::Header => {
                self.check.next = self.complete.q.val();
            }
            ParserState::TriIndex => {
                self.check.next = self.complete.q.val();
            }
            ParserState::VertexFetch => {
                // A lookup waits for the burst of a miss to come in whole and be checked;
                // record t + 1's burst, read ahead, holds back only a miss.
                self.check.next = self.complete.q.val();
                self.look.next =
                    !self.complete.q.val() & !(self.burst.q.val() & (self.kind.q.val() == BurstKind::Vertex));
            }
            ParserState::CpReady => {
                // Record t + 1, read ahead, is checked this cycle: the hand-over waits.
                self.check.next = self.complete.q.val();
                self.hand.next = self.out_free.val() & !self.complete.q.val();
            }
            ParserState::End => {
                if self.out_free.val() {
                    self.st.d.next = ParserState::Init;
                }
            }
        }

        // A burst received whole: checked, then the next step. Record t + 1, read ahead,
        // is kept with its verdict until triangle t is handed over.
        if self.check.val() & (self.kind.q.val() == BurstKind::Index) & self.is_ahead.val() {
            self.bus_error.d.next = false;
            self.ahead_valid.d.next = true;
            self.ahead_fault.d.next = self.index_check.fault.val();
            if self.bus_error.q.val() {
                self.ahead_fault.d.next = 10.into();
            }
            for i in 0..3 {
                self.ahead_v[i].d.next = self.w[i + 16].q.val();
                self.ahead_iw[i].d.next = self.w[i + 20].q.val().get_bits::<INV_W>(0);
            }
            self.ahead_eob.d.next = self.w[19].q.val().get_bit(16);
            self.ahead_eof.d.next = self.w[19].q.val().get_bit(17);
        } else if self.check.val() {
            if self.bus_error.q.val() {
                self.bus_error.d.next = false;
                self.st.d.next = ParserState::Error;
                self.fault_r.d.next = 10.into();
            } else {
                match self.kind.q.val() {
                    BurstKind::Header => {
                        if self.header_check.fault.val().any() {
                            self.st.d.next = ParserState::Error;
                            self.fault_r.d.next = self.header_check.fault.val();
                        } else {
                            self.render_r.d.next = true;
                            self.width_r.d.next = self.w[2].q.val().get_bits::<16>(0);
                            self.height_r.d.next = self.w[2].q.val().get_bits::<16>(16);
                            self.cull_r.d.next = self.w[1].q.val().get_bit(16);
                            self.background_r.d.next = self.w[9].q.val().get_bits::<24>(0);
                            self.triangles.d.next = self.w[4].q.val();
                            self.vertices.d.next = self.w[5].q.val();
                            self.index_addr.d.next = self.base.q.val() + self.w[6].q.val();
                            self.vertex_base.d.next = self.base.q.val() + self.w[7].q.val();
                            if self.w[4].q.val().any() {
                                self.st.d.next = ParserState::TriIndex;
                                self.ask.next = true;
                                self.ask_addr.next = self.base.q.val() + self.w[6].q.val();
                            } else {
                                // A buffer of no triangles: nothing to draw, and the frame ends.
                                self.frame_r.d.next = true;
                                self.buffer_r.d.next = true;
                                self.st.d.next = ParserState::Init;
                            }
                        }
                    }
                    BurstKind::Index => {
                        if self.index_check.fault.val().any() {
                            self.st.d.next = ParserState::Error;
                            self.fault_r.d.next = self.index_check.fault.val();
                        } else {
                            self.load_rec.next = true;
                            for i in 0..3 {
                                self.rec_v[i].d.next = self.w[i + 16].q.val();
                                self.rec_iw[i].d.next = self.w[i + 20].q.val().get_bits::<INV_W>(0);
                            }
                            self.rec_eob.d.next = self.w[19].q.val().get_bit(16);
                            self.rec_eof.d.next = self.w[19].q.val().get_bit(17);
                            self.kn.next = 0.into();
                            self.st.d.next = ParserState::VertexFetch;
                            // Record t + 1 asked for ahead, unless t ends the buffer.
                            if !self.w[19].q.val().get_bit(16) {
                                self.ask.next = true;
                                self.ask_addr.next = self.index_addr.q.val() + 32;
                            }
                        }
                    }
                    BurstKind::Vertex => {
                        if self.vertex_check.fault.val().any() {
                            self.st.d.next = ParserState::Error;
                            self.fault_r.d.next = self.vertex_check.fault.val();
                        } else {
                            // Into the cache (and the bypass), and vertex k is in.
                            self.tag_ram.write_enable.next = true;
                            self.vtx_ram.write_enable.next = true;
                            for g in 0..G {
                                if self.group.val().index() == g {
                                    self.valid[g].d.next =
                                        self.valid[g].q.val().replace_bit(self.lane.val().index(), true);
                                }
                            }
                            self.byp_valid.d.next = true;
                            self.byp_tag.d.next = self.v_cur.val();
                            self.byp_vtx.d.next = self.fetched.val();
                            self.vertex_in.next = true;
                        }
                    }
                }
            }
        }

        // A lookup: a hit is vertex k, a miss reads its record.
        self.cur.next = self.fetched.val();
        if self.look.val() {
            if self.hit.val() {
                self.cur.next = self.vtx.val();
                self.vertex_in.next = true;
            } else if !self.burst.q.val() {
                self.ask.next = true;
                self.ask_addr.next = self.vertex_base.q.val() + (self.v_cur.val() << self.five.val());
                self.ask_kind.next = BurstKind::Vertex;
            }
        }

        // Vertex k assembled; after the third, the triangle handed over or waiting.
        if self.vertex_in.val() {
            for i in 0..3 {
                if self.k.q.val().index() == i {
                    self.asm[i].d.next = self.cur.val();
                }
            }
            self.kn.next = self.k.q.val() + 1;
            if self.k.q.val() == 2 {
                if self.out_free.val() {
                    self.hand.next = true;
                } else {
                    self.st.d.next = ParserState::CpReady;
                }
            }
        }

        // The triangle into the output register, the next index record asked for.
        if self.hand.val() {
            self.out_valid.d.next = true;
            for i in 0..3 {
                self.out_vtx[i].d.next = self.asm[i].q.val();
                self.out_iw[i].d.next = self.rec_iw[i].q.val();
            }
            if self.vertex_in.val() {
                self.out_vtx[2].d.next = self.cur.val();
            }
            self.out_eob.d.next = self.rec_eob.q.val();
            self.out_eof.d.next = self.rec_eof.q.val();
            if self.rec_eob.q.val() {
                self.st.d.next = ParserState::End;
            } else {
                self.t.d.next = self.t.q.val() + 1;
                self.index_addr.d.next = self.index_addr.q.val() + 32;
                // Record t + 1: read ahead (its error stops the parser now), or still
                // coming (awaited in Tri Index).
                self.st.d.next = ParserState::TriIndex;
                if self.ahead_valid.q.val() {
                    self.ahead_valid.d.next = false;
                    if self.ahead_fault.q.val().any() {
                        self.st.d.next = ParserState::Error;
                        self.fault_r.d.next = self.ahead_fault.q.val();
                    } else {
                        self.load_ahead.next = true;
                        for i in 0..3 {
                            self.rec_v[i].d.next = self.ahead_v[i].q.val();
                            self.rec_iw[i].d.next = self.ahead_iw[i].q.val();
                        }
                        self.rec_eob.d.next = self.ahead_eob.q.val();
                        self.rec_eof.d.next = self.ahead_eof.q.val();
                        self.kn.next = 0.into();
                        self.st.d.next = ParserState::VertexFetch;
                        // And record t + 2 asked for, unless t + 1 ends the buffer.
                        if !self.ahead_eob.q.val() {
                            self.ask.next = true;
                            self.ask_addr.next = self.index_addr.q.val() + 64;
                        }
                    }
                }
            }
        }

        // A new buffer: the cache emptied, the header asked for (or the address refused).
        if self.go.val() {
            self.fault_r.d.next = 0.into();
            self.render_r.d.next = false;
            self.frame_r.d.next = false;
            self.buffer_r.d.next = false;
            self.bus_error.d.next = false;
            self.t.d.next = 0.into();
            self.kn.next = 0.into();
            self.ahead_valid.d.next = false;
            for g in 0..G {
                self.valid[g].d.next = 0.into();
            }
            if self.address.val().get_bits::<5>(0).any() {
                self.st.d.next = ParserState::Error;
                self.fault_r.d.next = 11.into();
            } else {
                self.base.d.next = self.address.val();
                self.st.d.next = ParserState::Header;
                self.ask.next = true;
                self.ask_addr.next = self.address.val();
                self.ask_kind.next = BurstKind::Header;
            }
        }

        // The read decided on this cycle, offered from the next: a header's 6 beats or a
        // record's 2.
        if self.ask.val() {
            self.ar_valid.d.next = true;
            self.ar_addr.d.next = self.ask_addr.val();
            self.ar_len.d.next = 1.into();
            if self.ask_kind.val() == BurstKind::Header {
                self.ar_len.d.next = 5.into();
            }
            self.burst.d.next = true;
            self.kind.d.next = self.ask_kind.val();
            self.beat.d.next = 0.into();
        }
        self.k.d.next = self.kn.val();

        // The cache's read address: vertex k of the record, as both will be next cycle.
        for i in 0..3 {
            self.rvn[i].next = self.rec_v[i].q.val().get_bits::<CB>(0);
        }
        if self.load_rec.val() {
            for i in 0..3 {
                self.rvn[i].next = self.w[i + 16].q.val().get_bits::<CB>(0);
            }
        }
        if self.load_ahead.val() {
            for i in 0..3 {
                self.rvn[i].next = self.ahead_v[i].q.val().get_bits::<CB>(0);
            }
        }
        self.v_next.next = self.rvn[0].val();
        for i in 1..3 {
            if self.kn.val().index() == i {
                self.v_next.next = self.rvn[i].val();
            }
        }
        self.tag_ram.read_address.next = self.v_next.val();
        self.vtx_ram.read_address.next = self.v_next.val();

        // The ports, from registers.
        self.bus.ar_valid.next = self.ar_valid.q.val();
        self.bus.ar_addr.next = self.ar_addr.q.val();
        self.bus.ar_len.next = self.ar_len.q.val();
        self.bus.ar_size.next = 4.into();
        self.bus.ar_burst.next = 1.into();
        self.bus.r_ready.next = true;
        self.out.valid.next = self.out_valid.q.val();
        self.out.v0_x.next = self.out_vtx[0].q.val().get_bits::<XY>(0);
        self.out.v0_y.next = self.out_vtx[0].q.val().get_bits::<XY>(self.at_y.val().index());
        self.out.v0_z.next = self.out_vtx[0].q.val().get_bits::<Z>(self.at_z.val().index());
        self.out.v0_c0.next = self.out_vtx[0].q.val().get_bits::<COLOR>(self.at_c0.val().index());
        self.out.v0_c1.next = self.out_vtx[0].q.val().get_bits::<COLOR>(self.at_c1.val().index());
        self.out.v0_c2.next = self.out_vtx[0].q.val().get_bits::<COLOR>(self.at_c2.val().index());
        self.out.v0_iw.next = self.out_iw[0].q.val();
        self.out.v1_x.next = self.out_vtx[1].q.val().get_bits::<XY>(0);
        self.out.v1_y.next = self.out_vtx[1].q.val().get_bits::<XY>(self.at_y.val().index());
        self.out.v1_z.next = self.out_vtx[1].q.val().get_bits::<Z>(self.at_z.val().index());
        self.out.v1_c0.next = self.out_vtx[1].q.val().get_bits::<COLOR>(self.at_c0.val().index());
        self.out.v1_c1.next = self.out_vtx[1].q.val().get_bits::<COLOR>(self.at_c1.val().index());
        self.out.v1_c2.next = self.out_vtx[1].q.val().get_bits::<COLOR>(self.at_c2.val().index());
        self.out.v1_iw.next = self.out_iw[1].q.val();
        self.out.v2_x.next = self.out_vtx[2].q.val().get_bits::<XY>(0);
        self.out.v2_y.next = self.out_vtx[2].q.val().get_bits::<XY>(self.at_y.val().index());
        self.out.v2_z.next = self.out_vtx[2].q.val().get_bits::<Z>(self.at_z.val().index());
        self.out.v2_c0.next = self.out_vtx[2].q.val().get_bits::<COLOR>(self.at_c0.val().index());
        self.out.v2_c1.next = self.out_vtx[2].q.val().get_bits::<COLOR>(self.at_c1.val().index());
        self.out.v2_c2.next = self.out_vtx[2].q.val().get_bits::<COLOR>(self.at_c2.val().index());
        self.out.v2_iw.next = self.out_iw[2].q.val();
        self.out.end_of_buffer.next = self.out_eob.q.val();
        self.out.end_of_frame.next = self.out_eof.q.val();
        self.render_valid.next = self.render_r.q.val();
        self.width.next = self.width_r.q.val();
        self.height.next = self.height_r.q.val();
        self.cull_back.next = self.cull_r.q.val();
        self.background.next = self.background_r.q.val();
        self.fault.next = self.fault_r.q.val();
        self.frame_done.next = self.frame_r.q.val();
        self.buffer_done.next = self.buffer_r.q.val();
        // (Assigned first: a case without a default would hold the output in a latch for
        // the register's one code that is no state.)
        self.state.next = 0.into();
        match self.st.q.val() {
            ParserState::Init => {
                self.state.next = 0.into();
            }
            ParserState::Header => {
                self.state.next = 1.into();
            }
            ParserState::TriIndex => {
                self.state.next = 2.into();
            }
            ParserState::VertexFetch => {
                self.state.next = 3.into();
            }
            ParserState::CpReady => {
                self.state.next = 4.into();
            }
            ParserState::End => {
                self.state.next = 5.into();
            }
            ParserState::Error => {
                self.state.next = 6.into();
            }
        }
    }
}

crate::pins!(impl[const CB: usize, const G: usize] CommandParser<CB, G> {
    clock: clock,
    inputs: [start, address, max_width, max_height],
    outputs: [render_valid, width, height, cull_back, background, state, fault, frame_done, buffer_done],
    links: [bus, out],
});

/// Why this build has no command parser, if it has none: a vertex buffer's fields are
/// 32-bit words.
pub fn unsupported() -> Option<String> {
    let f = &FORMATS;
    [("xy", f.xy), ("z", f.z), ("color", f.color), ("inv_w", f.inv_w)]
        .into_iter()
        .find(|(_, f)| f.bits() > 32)
        .map(|(name, f)| format!("command_parser: a vertex buffer's fields are at most 32 bits: {name} is {f}"))
}

/// `UNITS` entry: the command parser with `params["CACHE"]` vertex cache entries.
pub fn emit_command_parser(params: &Params) -> Result<Emitted, String> {
    if let Some(why) = unsupported() {
        return Err(why);
    }
    let unit = "command_parser";
    Ok(match params["CACHE"] {
        16 => emit_unit(unit, CommandParser::<4, 1>::new(), params),
        64 => emit_unit(unit, CommandParser::<6, 4>::new(), params),
        256 => emit_unit(unit, CommandParser::<8, 16>::new(), params),
        512 => emit_unit(unit, CommandParser::<9, 32>::new(), params),
        1024 => emit_unit(unit, CommandParser::<10, 64>::new(), params),
        c => return Err(format!("{unit}: CACHE = {c} is not supported: {CACHE_SIZES:?} entries")),
    })
}
