//! The texture cache of paper 001's texture unit (section II-5, printed §II.2.마 "Texture
//! Mapping": "to fetch the texture map's data efficiently we implemented a texture cache"),
//! four banks so that the 2x2 footprint of a bilinear sample is fetched in one clock;
//! `model::texture_cache`, cycle for cycle.
//!
//! # Banking
//!
//! The texture unit stores each mip level as four parity planes (`model::texture_memory`:
//! texel (i, j) in plane (j & 1)·2 + (i & 1)), so the four texels of a footprint lie in
//! four different planes; lane b of a request asks for a word of plane b and is looked up
//! in bank b only. Each bank is an independent set-associative cache of 32-bit words over
//! the whole texture memory (26-bit word addresses, `model::texture_memory::ADDR_BITS`): `SETS` sets of `WAYS` lines of `LINE`
//! words, round-robin replacement per set. The four banks share one memory read port.
//!
//! ```text
//!  word address [25:0] = | tag: 26 - S - L bits | set: S bits | word: L bits |   S = log2 SETS, L = log2 LINE
//!
//!  bank b (lane b):  tags[w]: RAM, SETS words of {tag, valid}   (one per way w < WAYS)
//!                    words[w]: RAM, SETS·LINE words of 32 bits, address {set, word}
//!                    victim: RAM, SETS words of 2 bits (the way the set's next fill takes)
//! ```
//!
//! Every RAM reads synchronously (rust-hdl's `RAM`; `synth_ecp5` makes the data RAMs block
//! RAM, the small tag and pointer RAMs distributed RAM with a register), so every way is read
//! at once and the way is chosen after the tag compare, in the cycle after the read.
//!
//! # Cycles
//!
//! A request taken in cycle t (`inp_valid & inp_ready`) is looked up in t+1 (stage S1) and,
//! if every enabled lane hits, is in the output register in t+2: hit latency 2, one
//! request a cycle. A miss of m lanes, with a memory that takes each word at once
//! (`mem$ack` high) and answers a word taken in cycle c in cycle c + L:
//!
//! ```text
//!  cycle         st     what
//!  t             Run    request taken (inp_valid & inp_ready); RAMs read its addresses
//!  t+1           Run    S1: a lane misses (hits, misses counted); inp_ready low
//!  t+2 ..        Fill   mem$valid: the missing lanes' lines, word by word, in lane order
//!  t+1+m·LINE    Fill   the last word asked
//!  t+1+m·LINE+L  Fill   the last word in (mem$rvalid): its line's tag written valid
//!  t+2+m·LINE+L  Wait   the RAMs read S1's addresses again
//!  t+3+m·LINE+L  Run    S1: every lane hits (not counted); inp_ready high again
//!  t+4+m·LINE+L  Run    out_valid
//! ```
//!
//! Miss penalty over a hit: m·LINE + L + 2 cycles (`model::texture_cache::Params::miss_penalty`).
//! The words asked run ahead of those received (the next lane's line is asked while the
//! previous lane's comes in); responses come in the order asked.
//!
//! States (`st`): 0 Clear, 1 Run, 2 Fill, 3 Wait (`model::texture_cache::State`).
//! Clear invalidates one set of every way of every bank a cycle (its tags written 0, its
//! victim pointer 0), SETS cycles, with `inp_ready` low. There is no reset pin, as nowhere
//! in edgepaint: every register starts at 0, so the unit powers up in Clear at set 0 and
//! takes its first request in cycle SETS. `inp_flush` (a pulse) asks for a Clear: from that
//! cycle `inp_ready` is low; a request in S1 completes first (its fill too), then Clear
//! runs; a flush asked during a Clear makes another after it.
//!
//! The handshakes: a transfer when valid and ready are high in the same cycle. S1 moves
//! on to the output register when every enabled lane hits and the register is empty or
//! taken this cycle; `inp_ready` = Run & no flush asked & (S1 empty, or moving on), so it
//! depends on `out_ready` and `inp_flush` in the same cycle (never on `inp_valid`).
//! `out_valid`, `out_data*`, `out_side` are the output register's: they hold until taken.
//!
//! Ports (no reset pin; every field's `///` says more):
//!
//! | port | dir | bits | |
//! |---|---|---:|---|
//! | `clock` | in | 1 | |
//! | `inp_valid`, `inp_ready` | in, out | 1 | the request stream |
//! | `inp_en` | in | 4 | lane b enabled |
//! | `inp_addr0` .. `inp_addr3` | in | 20 | lane b's word address (bank b) |
//! | `inp_side` | in | 64 | carried to `out_side` |
//! | `inp_flush` | in | 1 | a pulse: invalidate every line |
//! | `out_valid`, `out_ready` | out, in | 1 | the result stream |
//! | `out_data0` .. `out_data3` | out | 32 | lane b's word, 0 if disabled |
//! | `out_side` | out | 64 | the request's `inp_side` |
//! | `mem$valid`, `mem$addr` | out | 1, 20 | a word asked, held until `mem$ack` ([`TexMemory`]) |
//! | `mem$ack` | in | 1 | the word asked is taken this cycle |
//! | `mem$rvalid`, `mem$rdata` | in | 1, 32 | a word answered, in the order asked (ignored outside Fill) |
//! | `counters$hits`, `counters$misses`, `counters$fills` | out | 32 | counters, wrapping ([`CacheCounters`]) |
//!
//! Widths are compile-time in rust-hdl, and a RAM's size is its address width, so the unit
//! is generic over them: `TextureCache<SB, DA, W, TAG, TV>` with SB = log2 SETS, DA = SB +
//! log2 LINE (a way's data RAM address), W = WAYS, TAG = 26 - DA, TV = TAG + 1 (stable Rust
//! cannot write those sums as widths; `default` checks them). [`TextureCacheOf`] names the
//! unit for (SETS, WAYS, LINE), one of the geometries built, [`GEOMETRIES`] (26 of the 105
//! the model takes: each copy costs the build time).
//!
//! Model: `model::texture_cache`. Tests: `testbenches/tests/texture_cache.rs`.
//! Emitted: `edgepaint emit --unit texture_cache --param SETS=.. --param WAYS=.. --param LINE=..`.

use crate::emit::{emit_unit, Emitted};
use crate::Params;
use blank::Blank;
use model::texture_cache as m;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::RAM;

/// Bits of a word address.
pub const ADDR: usize = m::ADDR_BITS as usize;

crate::bundle! {
    /// The cache's memory read port, as each texture block above it passes it on
    /// (`texture_unit`, `texture_path`, and the textured `raster_top` as `tex_mem`): a word
    /// asked (`valid`, `addr`), held until `ack`; the words asked come back in order
    /// (`rvalid`, `rdata`; ignored outside Fill).
    TexMemory {
        Out valid: Bit,
        Out addr: Bits<ADDR>,
        In ack: Bit,
        In rvalid: Bit,
        In rdata: Bits<32>,
    }
}

crate::bundle! {
    /// The cache's counters, 32 bits each, wrapping: lane lookups that hit and that missed,
    /// and lines fetched (`model::texture_cache::Out`'s `hits`, `misses`, `fills`).
    CacheCounters {
        Out hits: Bits<32>,
        Out misses: Bits<32>,
        Out fills: Bits<32>,
    }
}
/// Bits of the side payload.
pub const SIDE: usize = m::SIDE_BITS as usize;

/// One bank: the RAMs of lane b and its lookup (tag compare, way select) and writes (a
/// fill's words and tag, a Clear's set). See the module documentation for its RAMs.
#[derive(LogicBlock, Blank)]
pub struct Bank<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> {
    pub clock: Signal<In, Clock>,
    /// The address's set and word read at this clock edge (the request taken, else S1's).
    pub rd_addr: Signal<In, Bits<DA>>,
    /// S1's address: looked up this cycle against what the RAMs read at the last edge.
    pub addr: Signal<In, Bits<ADDR>>,
    /// A word of this bank's line comes in: write `wdata` to word `word` of the line of
    /// `addr` in the victim way.
    pub fill: Signal<In, Bit>,
    pub word: Signal<In, Bits<DA>>,
    pub wdata: Signal<In, Bits<32>>,
    /// It is the line's last word: its tag is written valid, the set's pointer advances.
    pub last: Signal<In, Bit>,
    /// Clear set `clear_set`: every way's tag invalid, the pointer 0.
    pub clear: Signal<In, Bit>,
    pub clear_set: Signal<In, Bits<SB>>,
    /// S1's address is in a valid way.
    pub hit: Signal<Out, Bit>,
    /// Its word (0 on a miss).
    pub data: Signal<Out, Bits<32>>,
    tags: [RAM<Bits<TV>, SB>; W],
    words: [RAM<Bits<32>, DA>; W],
    victim: RAM<Bits<2>, SB>,
    /// The set's first bit (log2 LINE), the tag's (DA).
    set_at: Constant<Bits<8>>,
    tag_at: Constant<Bits<8>>,
    /// LINE - 1; WAYS - 1; a valid tag word's valid bit.
    word_mask: Constant<Bits<DA>>,
    way_mask: Constant<Bits<2>>,
    valid_bit: Constant<Bits<TV>>,
    set: Signal<Local, Bits<SB>>,
    tag: Signal<Local, Bits<TAG>>,
    way: Signal<Local, Bits<2>>,
    tag_word: Signal<Local, Bits<TV>>,
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> Default
    for Bank<SB, DA, W, TAG, TV>
{
    fn default() -> Self {
        assert!(
            DA >= SB && TAG == ADDR - DA && TV == TAG + 1 && [1, 2, 4].contains(&W),
            "Bank<{SB}, {DA}, {W}, {TAG}, {TV}>: DA = SB + log2 LINE, TAG = {ADDR} - DA, TV = TAG + 1, W = 1, 2 or 4"
        );
        Bank {
            set_at: Constant::new((DA - SB).to_bits()),
            tag_at: Constant::new(DA.to_bits()),
            word_mask: Constant::new(((1u64 << (DA - SB)) - 1).to_bits()),
            way_mask: Constant::new(((W - 1) as u64).to_bits()),
            valid_bit: Constant::new(1u64.to_bits()),
            ..Bank::blank()
        }
    }
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> Logic
    for Bank<SB, DA, W, TAG, TV>
{
    #[hdl_gen]
    fn update(&mut self) {
        self.victim.read_clock.next = self.clock.val();
        self.victim.write_clock.next = self.clock.val();
        self.victim.read_address.next = self.rd_addr.val().get_bits::<SB>(self.set_at.val().index());
        for w in 0..W {
            self.tags[w].read_clock.next = self.clock.val();
            self.tags[w].write_clock.next = self.clock.val();
            self.words[w].read_clock.next = self.clock.val();
            self.words[w].write_clock.next = self.clock.val();
            self.tags[w].read_address.next = self.rd_addr.val().get_bits::<SB>(self.set_at.val().index());
            self.words[w].read_address.next = self.rd_addr.val();
        }

        // The lookup: a valid way whose tag is S1's.
        self.set.next = self.addr.val().get_bits::<SB>(self.set_at.val().index());
        self.tag.next = self.addr.val().get_bits::<TAG>(self.tag_at.val().index());
        self.hit.next = false;
        self.data.next = 0.into();
        for w in 0..W {
            if self.tags[w].read_data.val().get_bit(0)
                & (self.tags[w].read_data.val().get_bits::<TAG>(1) == self.tag.val())
            {
                self.hit.next = true;
                self.data.next = self.words[w].read_data.val();
            }
        }

        // The writes: a fill's word into the victim way (the pointer as read: it changes
        // only with the line's last word), and with the last word the tag and the pointer;
        // or a Clear's set.
        self.way.next = self.victim.read_data.val();
        self.tag_word.next = (bit_cast::<TV, TAG>(self.tag.val()) << 1) | self.valid_bit.val();
        self.victim.write_enable.next = self.clear.val() | (self.fill.val() & self.last.val());
        self.victim.write_address.next = self.set.val();
        self.victim.write_data.next = (self.way.val() + 1) & self.way_mask.val();
        if self.clear.val() {
            self.victim.write_address.next = self.clear_set.val();
            self.victim.write_data.next = 0.into();
        }
        for w in 0..W {
            self.words[w].write_enable.next = false;
            self.tags[w].write_enable.next = self.clear.val();
            if self.fill.val() & (self.way.val().index() == w) {
                self.words[w].write_enable.next = true;
                self.tags[w].write_enable.next = self.last.val();
            }
            self.words[w].write_address.next =
                (self.addr.val().get_bits::<DA>(0) & !self.word_mask.val()) | self.word.val();
            self.words[w].write_data.next = self.wdata.val();
            self.tags[w].write_address.next = self.set.val();
            self.tags[w].write_data.next = self.tag_word.val();
            if self.clear.val() {
                self.tags[w].write_address.next = self.clear_set.val();
                self.tags[w].write_data.next = 0.into();
            }
        }
    }
}

/// The texture cache: see the module documentation. Generic over its widths; name it by
/// its geometry with [`TextureCacheOf`].
#[derive(LogicBlock, Blank)]
pub struct TextureCache<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> {
    pub clock: Signal<In, Clock>,
    /// A request is offered: lanes `inp_en`, addresses `inp_addr0..3`, payload `inp_side`.
    pub inp_valid: Signal<In, Bit>,
    /// The request is taken this cycle (with `inp_valid`).
    pub inp_ready: Signal<Out, Bit>,
    /// Bit b: lane b enabled (looked up in bank b; a disabled lane's word is 0).
    pub inp_en: Signal<In, Bits<4>>,
    /// Lane b's word address, in texture memory (bank b caches it).
    pub inp_addr0: Signal<In, Bits<ADDR>>,
    pub inp_addr1: Signal<In, Bits<ADDR>>,
    pub inp_addr2: Signal<In, Bits<ADDR>>,
    pub inp_addr3: Signal<In, Bits<ADDR>>,
    /// Carried unchanged to the output with the request.
    pub inp_side: Signal<In, Bits<SIDE>>,
    /// A pulse: invalidate every line (Clear), after the request in S1.
    pub inp_flush: Signal<In, Bit>,
    /// A result is offered; it holds until taken.
    pub out_valid: Signal<Out, Bit>,
    pub out_ready: Signal<In, Bit>,
    /// The word at lane b's address, 0 for a disabled lane.
    pub out_data0: Signal<Out, Bits<32>>,
    pub out_data1: Signal<Out, Bits<32>>,
    pub out_data2: Signal<Out, Bits<32>>,
    pub out_data3: Signal<Out, Bits<32>>,
    /// The request's `inp_side`.
    pub out_side: Signal<Out, Bits<SIDE>>,
    /// The memory read port.
    pub mem: TexMemory,
    /// Lookups of enabled lanes that hit, and that missed, counted once per request (in S1's
    /// first cycle); lines fetched.
    pub counters: CacheCounters,
    banks: [Bank<SB, DA, W, TAG, TV>; 4],
    /// The state: 0 Clear, 1 Run, 2 Fill, 3 Wait; the set Clear writes; a flush asked.
    st: DFF<Bits<2>>,
    clr: DFF<Bits<SB>>,
    flush_pend: DFF<Bit>,
    /// Stage 1: the request looked up; in its first cycle (counted).
    s1_valid: DFF<Bit>,
    s1_fresh: DFF<Bit>,
    s1_en: DFF<Bits<4>>,
    s1_addr: [DFF<Bits<ADDR>>; 4],
    s1_side: DFF<Bits<SIDE>>,
    /// The output register.
    o_valid: DFF<Bit>,
    o_data: [DFF<Bits<32>>; 4],
    o_side: DFF<Bits<SIDE>>,
    /// Fill: the lanes whose words are still to ask, and to receive; each's next word.
    iss_mask: DFF<Bits<4>>,
    iss_word: DFF<Bits<DA>>,
    rcv_mask: DFF<Bits<4>>,
    rcv_word: DFF<Bits<DA>>,
    hits_r: DFF<Bits<32>>,
    misses_r: DFF<Bits<32>>,
    fills_r: DFF<Bits<32>>,
    /// LINE - 1 (a line's last word); the address bits of a line's first word.
    word_last: Constant<Bits<DA>>,
    line_base: Constant<Bits<ADDR>>,
    run: Signal<Local, Bit>,
    all_hit: Signal<Local, Bit>,
    miss_mask: Signal<Local, Bits<4>>,
    n_hit: Signal<Local, Bits<32>>,
    n_miss: Signal<Local, Bits<32>>,
    o_free: Signal<Local, Bit>,
    s1_go: Signal<Local, Bit>,
    pending: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    iss_lane: Signal<Local, Bits<2>>,
    iss_addr: Signal<Local, Bits<ADDR>>,
    rcv_lane: Signal<Local, Bits<2>>,
    rcv: Signal<Local, Bit>,
    rcv_last: Signal<Local, Bit>,
    rcv_rest: Signal<Local, Bits<4>>,
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> Default
    for TextureCache<SB, DA, W, TAG, TV>
{
    fn default() -> Self {
        let p = m::Params { sets: 1 << SB, ways: W as u32, line: 1 << (DA - SB) };
        p.check().unwrap_or_else(|e| panic!("TextureCache<{SB}, {DA}, {W}, {TAG}, {TV}>: {e}"));
        TextureCache {
            word_last: Constant::new(((p.line - 1) as u64).to_bits()),
            line_base: Constant::new((((1u64 << ADDR) - 1) & !((p.line - 1) as u64)).to_bits()),
            ..TextureCache::blank()
        }
    }
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> Logic
    for TextureCache<SB, DA, W, TAG, TV>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, st, clr, flush_pend, s1_valid, s1_fresh, s1_en, s1_side, o_valid, o_side, iss_mask, iss_word,
            rcv_mask, rcv_word, hits_r, misses_r, fills_r
        );
        for b in 0..4 {
            self.s1_addr[b].clock.next = self.clock.val();
            self.s1_addr[b].d.next = self.s1_addr[b].q.val();
            self.o_data[b].clock.next = self.clock.val();
            self.o_data[b].d.next = self.o_data[b].q.val();
            self.banks[b].clock.next = self.clock.val();
            self.banks[b].addr.next = self.s1_addr[b].q.val();
        }
        self.run.next = self.st.q.val() == 1;

        // S1's lookup: the enabled lanes that miss.
        self.all_hit.next = true;
        self.miss_mask.next = 0.into();
        self.n_hit.next = 0.into();
        self.n_miss.next = 0.into();
        for b in 0..4 {
            if self.s1_en.q.val().get_bit(b) {
                if self.banks[b].hit.val() {
                    self.n_hit.next = self.n_hit.val() + 1;
                } else {
                    self.n_miss.next = self.n_miss.val() + 1;
                    self.all_hit.next = false;
                    self.miss_mask.next = self.miss_mask.val().replace_bit(b, true);
                }
            }
        }

        // The handshakes.
        self.o_free.next = !self.o_valid.q.val() | self.out_ready.val();
        self.s1_go.next = self.run.val() & self.s1_valid.q.val() & self.all_hit.val() & self.o_free.val();
        self.pending.next = self.flush_pend.q.val() | self.inp_flush.val();
        self.inp_ready.next = self.run.val() & !self.pending.val() & (!self.s1_valid.q.val() | self.s1_go.val());
        self.take.next = self.inp_valid.val() & self.inp_ready.val();

        // The RAMs read the request taken, else S1's addresses again.
        self.banks[0].rd_addr.next = self.s1_addr[0].q.val().get_bits::<DA>(0);
        self.banks[1].rd_addr.next = self.s1_addr[1].q.val().get_bits::<DA>(0);
        self.banks[2].rd_addr.next = self.s1_addr[2].q.val().get_bits::<DA>(0);
        self.banks[3].rd_addr.next = self.s1_addr[3].q.val().get_bits::<DA>(0);
        self.s1_fresh.d.next = self.take.val();
        if self.take.val() {
            self.banks[0].rd_addr.next = self.inp_addr0.val().get_bits::<DA>(0);
            self.banks[1].rd_addr.next = self.inp_addr1.val().get_bits::<DA>(0);
            self.banks[2].rd_addr.next = self.inp_addr2.val().get_bits::<DA>(0);
            self.banks[3].rd_addr.next = self.inp_addr3.val().get_bits::<DA>(0);
            self.s1_valid.d.next = true;
            self.s1_en.d.next = self.inp_en.val();
            self.s1_addr[0].d.next = self.inp_addr0.val();
            self.s1_addr[1].d.next = self.inp_addr1.val();
            self.s1_addr[2].d.next = self.inp_addr2.val();
            self.s1_addr[3].d.next = self.inp_addr3.val();
            self.s1_side.d.next = self.inp_side.val();
        } else if self.s1_go.val() {
            self.s1_valid.d.next = false;
        }

        // The output register.
        self.out_valid.next = self.o_valid.q.val();
        self.out_data0.next = self.o_data[0].q.val();
        self.out_data1.next = self.o_data[1].q.val();
        self.out_data2.next = self.o_data[2].q.val();
        self.out_data3.next = self.o_data[3].q.val();
        self.out_side.next = self.o_side.q.val();
        if self.s1_go.val() {
            self.o_valid.d.next = true;
            self.o_side.d.next = self.s1_side.q.val();
            for b in 0..4 {
                self.o_data[b].d.next = 0.into();
                if self.s1_en.q.val().get_bit(b) {
                    self.o_data[b].d.next = self.banks[b].data.val();
                }
            }
        } else if self.out_ready.val() {
            self.o_valid.d.next = false;
        }

        // The counters: S1's first cycle.
        self.counters.hits.next = self.hits_r.q.val();
        self.counters.misses.next = self.misses_r.q.val();
        self.counters.fills.next = self.fills_r.q.val();
        if self.run.val() & self.s1_valid.q.val() & self.s1_fresh.q.val() {
            self.hits_r.d.next = self.hits_r.q.val() + self.n_hit.val();
            self.misses_r.d.next = self.misses_r.q.val() + self.n_miss.val();
        }

        // Clear: one set a cycle, in every bank.
        self.flush_pend.d.next = self.pending.val();
        for b in 0..4 {
            self.banks[b].clear.next = self.st.q.val() == 0;
            self.banks[b].clear_set.next = self.clr.q.val();
        }
        if self.st.q.val() == 0 {
            self.clr.d.next = self.clr.q.val() + 1;
            if self.clr.q.val().all() {
                self.st.d.next = 1.into();
            }
        }

        // Run: a miss starts a fill; else a flush asked, with S1 empty or moving on, a Clear.
        if self.run.val() {
            if self.s1_valid.q.val() & !self.all_hit.val() {
                self.st.d.next = 2.into();
                self.iss_mask.d.next = self.miss_mask.val();
                self.rcv_mask.d.next = self.miss_mask.val();
                self.iss_word.d.next = 0.into();
                self.rcv_word.d.next = 0.into();
            } else if self.pending.val() & (!self.s1_valid.q.val() | self.s1_go.val()) {
                self.st.d.next = 0.into();
                self.clr.d.next = 0.into();
                self.flush_pend.d.next = false;
            }
        }
        if self.st.q.val() == 3 {
            self.st.d.next = 1.into();
        }

        // Fill, asking: the lowest lane still to ask, its line's next word.
        self.iss_lane.next = 3.into();
        if self.iss_mask.q.val().get_bit(2) {
            self.iss_lane.next = 2.into();
        }
        if self.iss_mask.q.val().get_bit(1) {
            self.iss_lane.next = 1.into();
        }
        if self.iss_mask.q.val().get_bit(0) {
            self.iss_lane.next = 0.into();
        }
        self.iss_addr.next = self.s1_addr[0].q.val();
        for b in 1..4 {
            if self.iss_lane.val().index() == b {
                self.iss_addr.next = self.s1_addr[b].q.val();
            }
        }
        self.mem.valid.next = (self.st.q.val() == 2) & self.iss_mask.q.val().any();
        self.mem.addr.next = (self.iss_addr.val() & self.line_base.val()) | bit_cast::<ADDR, DA>(self.iss_word.q.val());
        if self.mem.valid.val() & self.mem.ack.val() {
            self.iss_word.d.next = self.iss_word.q.val() + 1;
            if self.iss_word.q.val() == self.word_last.val() {
                self.iss_word.d.next = 0.into();
                self.iss_mask.d.next = self.iss_mask.q.val() & (self.iss_mask.q.val() - 1);
            }
        }

        // Fill, receiving: the word in goes to the lowest lane still to receive.
        self.rcv_lane.next = 3.into();
        if self.rcv_mask.q.val().get_bit(2) {
            self.rcv_lane.next = 2.into();
        }
        if self.rcv_mask.q.val().get_bit(1) {
            self.rcv_lane.next = 1.into();
        }
        if self.rcv_mask.q.val().get_bit(0) {
            self.rcv_lane.next = 0.into();
        }
        self.rcv.next = (self.st.q.val() == 2) & self.rcv_mask.q.val().any() & self.mem.rvalid.val();
        self.rcv_last.next = self.rcv_word.q.val() == self.word_last.val();
        self.rcv_rest.next = self.rcv_mask.q.val() & (self.rcv_mask.q.val() - 1);
        for b in 0..4 {
            self.banks[b].fill.next = false;
            if self.rcv.val() & (self.rcv_lane.val().index() == b) {
                self.banks[b].fill.next = true;
            }
            self.banks[b].word.next = self.rcv_word.q.val();
            self.banks[b].wdata.next = self.mem.rdata.val();
            self.banks[b].last.next = self.rcv_last.val();
        }
        if self.rcv.val() {
            self.rcv_word.d.next = self.rcv_word.q.val() + 1;
            if self.rcv_last.val() {
                self.rcv_word.d.next = 0.into();
                self.rcv_mask.d.next = self.rcv_rest.val();
                self.fills_r.d.next = self.fills_r.q.val() + 1;
                if !self.rcv_rest.val().any() {
                    self.st.d.next = 3.into();
                }
            }
        }
    }
}

crate::pins!(impl[const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize]
    TextureCache<SB, DA, W, TAG, TV> {
    clock: clock,
    inputs: [
        inp_valid, inp_en, inp_addr0, inp_addr1, inp_addr2, inp_addr3, inp_side, inp_flush, out_ready,
    ],
    outputs: [inp_ready, out_valid, out_data0, out_data1, out_data2, out_data3, out_side],
    links: [mem, counters],
});

/// A geometry (SETS, WAYS, LINE), as a type: [`TextureCacheOf`] is its unit.
pub struct Geometry<const SETS: usize, const WAYS: usize, const LINE: usize>;

/// The unit of one geometry built.
pub trait CacheGeometry {
    /// `TextureCache<log2 SETS, log2 SETS + log2 LINE, WAYS, 20 - that, 21 - that>`.
    type Unit: Block + crate::sim::Pins + Default;
}

/// The texture cache with `SETS` sets of `WAYS` lines of `LINE` words per bank (one of
/// [`GEOMETRIES`]).
pub type TextureCacheOf<const SETS: usize, const WAYS: usize, const LINE: usize> =
    <Geometry<SETS, WAYS, LINE> as CacheGeometry>::Unit;

/// log2 of a power of two, for the widths of [`geometries!`].
const fn lg(x: usize) -> usize {
    x.trailing_zeros() as usize
}

/// The geometries built: for each `(SETS WAYS LINE)`, `impl CacheGeometry`, an entry of
/// [`GEOMETRIES`] and a case of `emit_built`.
macro_rules! geometries {
    ($(($s:literal $w:literal $l:literal))*) => {
        $(
            impl CacheGeometry for Geometry<$s, $w, $l> {
                type Unit = TextureCache<
                    { lg($s) },
                    { lg($s) + lg($l) },
                    $w,
                    { ADDR - lg($s) - lg($l) },
                    { ADDR + 1 - lg($s) - lg($l) },
                >;
            }
        )*

        /// The geometries (SETS, WAYS, LINE) the RTL is built for (each is a copy of the
        /// unit in this crate: about 0.7 s of the optimised build's CPU each, so not all
        /// 105 that `model::texture_cache::Params::check` takes): SETS 4 to 256 at the
        /// default WAYS 2, LINE 4; every WAYS and LINE at the default SETS 64; the tests'
        /// (4, 1, 1) and (8, 4, 8); the corners (4, 4, 16), (256, 1, 1), (256, 4, 16).
        /// Another is one line in the list of `geometries!`.
        pub const GEOMETRIES: &[(u32, u32, u32)] = &[$(($s, $w, $l)),*];

        /// `emit_unit` of geometry `g`, when built.
        fn emit_built(g: (u32, u32, u32), params: &Params) -> Option<Emitted> {
            $(
                if g == ($s, $w, $l) {
                    return Some(emit_unit("texture_cache", TextureCacheOf::<$s, $w, $l>::default(), params));
                }
            )*
            None
        }
    };
}

geometries! {
    (4 2 4) (8 2 4) (16 2 4) (32 2 4) (64 2 4) (128 2 4) (256 2 4)
    (64 1 1) (64 1 2) (64 1 4) (64 1 8) (64 1 16)
    (64 2 1) (64 2 2) (64 2 8) (64 2 16)
    (64 4 1) (64 4 2) (64 4 4) (64 4 8) (64 4 16)
    (4 1 1) (8 4 8)
    (4 4 16) (256 1 1) (256 4 16)
}

/// `UNITS` entry: the cache with `params["SETS"]`, `["WAYS"]`, `["LINE"]`; `Err` for a
/// geometry the model refuses (`model::texture_cache::Params::check`) or one not built
/// ([`GEOMETRIES`]).
pub fn emit_texture_cache(params: &Params) -> Result<Emitted, String> {
    let get =
        |k: &str| u32::try_from(params[k]).map_err(|_| format!("texture_cache: {k} = {} is too large", params[k]));
    let p = m::Params { sets: get("SETS")?, ways: get("WAYS")?, line: get("LINE")? };
    p.check()?;
    let g = (p.sets, p.ways, p.line);
    emit_built(g, params).ok_or_else(|| {
        let built: Vec<String> = GEOMETRIES.iter().map(|(s, w, l)| format!("{s}/{w}/{l}")).collect();
        format!(
            "texture_cache: SETS = {}, WAYS = {}, LINE = {} is not built; the geometries built (SETS/WAYS/LINE, \
             rtl::texture_cache::GEOMETRIES): {}",
            p.sets,
            p.ways,
            p.line,
            built.join(", ")
        )
    })
}
