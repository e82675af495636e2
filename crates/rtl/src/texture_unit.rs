//! `texture_unit`: paper 001's texture unit (Woo, Jang and Lee 2004, section II-5) as one
//! pipeline, a textured pixel a clock while the texture cache hits: `texture_coords` (the
//! perspective division of eq. 3 and the level of detail of eq. 4) -> `texture_address`
//! (levels, footprint and wrap, OpenGL 4.6 sections 8.14.2, 8.14.3 and 8.15) ->
//! `texture_cache` (four banks, one memory read port) -> `texture_filter` (decode, bilinear
//! with 001's Fig. 6 weights, the blend between levels, the texture environment of OpenGL
//! 2.1 section 3.13). Cycle for cycle `model::texture_unit::pipeline`; every colour is
//! `model::texture_unit::TextureUnit::sample`'s.
//!
//! ```text
//!  inp ──> texture_coords ──> texture_address ──> texture_cache ──> pick ──> texture_filter ──> out
//!   │      21 stages, en_c    3 stages, en_a       valid/ready      words    5 stages, en_f
//!   │                 second ──┘                   side: attrs      └─> pair (a pixel's 1st level)
//!   └─ cf, tag ──> two 64-entry RAMs: cf read as the pixel enters the filter, tag at out
//! ```
//!
//! # Stalls
//!
//! Three global enables and the cache's handshakes, no skid buffer:
//!
//! * `en_f = out_ready | !out_valid`: the filter (and the output, its last register) moves
//!   on unless its pixel waits to be taken. The cache's `out_ready` is `en_f`: a cache
//!   result goes into the filter, or into the pair register, only when the filter moves.
//! * `en_a = !address.out_valid | cache.inp_ready`: `texture_address` moves on when its
//!   last stage is empty or the cache takes its access, so it stalls exactly while the
//!   cache refuses (a miss being filled, a Clear, a full output) and its last stage's
//!   bubbles are squeezed out.
//! * `en_c = !coords.out_valid | (en_a & (!two | second))`: coords moves on when its last
//!   stage is empty or `texture_address` takes its pixel's last access (`two`:
//!   `texture_address`' combinational `inp_two_levels` of coords' pixel). `inp_ready = en_c
//!   & !st_load` (so it depends on `out_ready`, `inp_flush` and `st_load` in the same cycle,
//!   never on `inp_valid`, as the cache's).
//! * A pixel between two levels (GL's `*_MIPMAP_LINEAR` with a nonzero fraction) makes two
//!   accesses: the first level's into `texture_address` in the cycle it moves while coords
//!   shows the pixel (`second` low), the second's in the next one it moves (`second` high,
//!   carried to `out_second`); coords holds the pixel until then, so `inp_ready` is low for
//!   that one cycle. The two accesses pass `texture_address` and the cache one after the
//!   other. The first's words (picked into footprint order) wait in the pair register; the
//!   filter takes the pixel once, with the second's words.
//!
//! The cache's side payload carries each access's attributes (bit 0 second, 1 two levels,
//! 7..2 the level fraction, 15..8 the footprint's banks, 23..16 alpha, 31..24 beta; 63..32
//! zero). A pixel's lit colour `inp_cf` and tag `inp_tag` go into two RAMs of 64 words at
//! its taking (`wp`): `cf` is read as the pixel enters the filter (`rc`), `tag` while it is
//! at the output (`rt`); both RAMs read synchronously at the pointer's next value every
//! cycle, and a word is written at least 26 cycles before it is read (21 + 3 + 2: coords,
//! `texture_address`, the cache), so it is always read after its write. At most 21 + 3 +
//! 2 + 1 + 5 = 32 pixels are in flight ([`IN_FLIGHT`]: coords' stages, `texture_address`'
//! stages, the cache's S1 and output register, the pair register, the filter's stages: each
//! pixel in flight holds at least one of these places), so 64 words never overflow and `wp
//! == rt` (`idle`) means that none is. (32 words held at most 31: enough for the 19 stages
//! coords had before B and C were split, not for 21.)
//!
//! # Cycles
//!
//! A pixel of one level taken in cycle t, every stage free and the cache hitting:
//!
//! ```text
//!  cycle   what
//!  t       inp_valid & inp_ready: into texture_coords (cf, tag into the RAMs)
//!  t+21    coords.out_valid: the access into texture_address (stage A: the level)
//!  t+22    stage B: the footprint's indices and fractions, the level's first word
//!  t+23    stage C: wrap, each bank's word
//!  t+24    address.out_valid: the cache takes the access
//!  t+25    cache S1: every lane hits
//!  t+26    cache out_valid: the words picked into footprint order, into the filter (cf read)
//!  t+31    out_valid, out_rgba, out_tag: [`LATENCY`] = 31
//! ```
//!
//! Between two levels: the first access goes into texture_address in t+21 (`inp_ready`
//! low in t+21), the second in t+22; the cache takes them in t+24 and t+25; the first's
//! words go into the pair register in t+26, the second's with them into the filter in
//! t+27; out in t+32. One such pixel costs one cycle more than a one-level pixel. A miss
//! of m lanes holds the cache (`texture_cache`'s table: m·LINE + L + 2 cycles more than a
//! hit at memory latency L), and with it `texture_address`, coords and the input;
//! `out_ready` low holds the filter and the cache's output register, and then the rest.
//!
//! # State
//!
//! The texture's state is registers (`st$*`, [`TextureState`]), loaded by `st_load` (the cycle it is high,
//! `inp_ready` is low), read by every stage as its pixel passes: load it only while `idle`
//! (no pixel in flight), once a texture, not per pixel. The level-of-detail rule is the
//! parameter `EXACT`, as `texture_coords` has it. The triangle's gradients come with each
//! pixel (`inp_d*`): `texture_coords` carries them past its divider in its delay line
//! anyway, so registers for them here would only add flip-flops; holding them per triangle
//! (a triangle's gradients in one of two register sets, a set bit down the delay line
//! instead of 176 bits) would save that delay line and is not done yet. `inp_flush` (a
//! pulse) is the cache's: it invalidates every line once the access in the cache's S1 is
//! done; accesses after it (the pixels then in coords and texture_address, too) read
//! memory afresh.
//!
//! Area (Yosys 0.23 `synth_ecp5`, the default design's parameters): 9,251 LUT4, 8,028 FF,
//! 55 MULT18X18D, 11 DP16KD and 200 DPR16X4: the four units and the state, pair and
//! pointer registers and the cf and tag RAMs of 64 words (tag in a DP16KD, cf in
//! DPR16X4s). 41.0 MHz between registers on an LFE5U-45F (nextpnr-ecp5 router2), its
//! critical path now in `texture_filter`: a decoded texel (`s4_cs`) through the texture
//! environment's multiplier, its bias and rounding into `s5_rgba` (24.4 ns, 15.8 of them
//! routing). Before `texture_coords`' B and C had a register after their multipliers
//! (19 stages, 32-word RAMs): 9,876 LUT4, 7,263 FF, 10 DP16KD, 204 DPR16X4, 31.5 MHz, the
//! critical path in its stage C (s · dq/dx through the multiplier, the numerator, its
//! magnitude and the shift by the size: 31.8 ns, 21.6 of them routing); 13.6 MHz while
//! `texture_address` was combinational.
//! Throughput on the shipped textured scenes (every textured fragment in raster order,
//! memory latency 10, the default cache; `model::texture_unit::pipeline::cycles`): 0.87
//! pixels a clock on `checker.json` (hit rate 0.997), 0.20 to 0.24 on `crate.json`,
//! `env-modes.json` and `mip-levels.json` (0.94 to 0.75): the cache blocks on a miss, so
//! each missing lane's line costs the whole pipeline LINE + L + 2 cycles.
//!
//! Model: `model::texture_unit::pipeline`.
//! Tests: `testbenches/tests/texture_unit.rs`. Emitted: `edgepaint emit --unit
//! texture_unit --param SETS=.. --param WAYS=.. --param LINE=.. --param EXACT=0|1`.

use crate::emit::{emit_unit, Emitted};
use crate::texture_address::TextureAddress;
use crate::texture_cache::{CacheCounters, TexMemory, TextureCache, ADDR};
use crate::texture_coords::{TextureCoords, DQ, DST, QB, ST};
use crate::texture_filter::TextureFilter;
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::RAM;

crate::bundle! {
    /// A texture's state (`model::texture_unit::TexState` in the unit's codes), as
    /// `texture_unit` loads it (`st`), `texture_path` takes it with each triangle (`state`) and
    /// the textured `raster_top` with each triangle sent (`tex_state`): log2 of its sides,
    /// its levels (1 to 13), its base word address, `texture_address`'s codes (filters 1
    /// linear; mip 0 none, 1 nearest, 2 linear; wrap 0 repeat, 1 mirrored repeat, 2 clamp to
    /// edge), `texture_filter`'s (format, Gaussian weights, environment).
    TextureState {
        In ws: Bits<4>,
        In hs: Bits<4>,
        In levels: Bits<4>,
        In base: Bits<ADDR>,
        In min_linear: Bit,
        In mag_linear: Bit,
        In mip: Bits<2>,
        In wrap_s: Bits<2>,
        In wrap_t: Bits<2>,
        In format: Bits<3>,
        In gaussian: Bit,
        In env: Bits<3>,
    }
}

/// Input to output of a one-level pixel when nothing stalls: coords, texture_address, the
/// cache's hit latency, the filter.
pub const LATENCY: usize = crate::texture_coords::LATENCY
    + crate::texture_address::LATENCY
    + model::texture_cache::HIT_LATENCY as usize
    + crate::texture_filter::LATENCY;
/// Pixels in flight at most: coords' and texture_address' stages, the cache's S1 and output
/// register, the pair register, the filter's stages (32).
pub const IN_FLIGHT: usize = crate::texture_coords::LATENCY
    + crate::texture_address::LATENCY
    + model::texture_cache::HIT_LATENCY as usize
    + 1
    + crate::texture_filter::LATENCY;
/// log2 of the cf and tag RAMs' words: room for every pixel in flight, with `wp == rt` left
/// to mean none.
const FB: usize = 6;
const _: () = assert!(IN_FLIGHT < 1 << FB);
const _: () = assert!(
    crate::texture_coords::LATENCY == model::texture_unit::pipeline::COORDS_STAGES
        && LATENCY as u64 == model::texture_unit::pipeline::LATENCY
);

/// One of the four cache words, by its bank code: the footprint texel's word.
#[derive(LogicBlock, Default)]
pub struct Pick {
    pub data0: Signal<In, Bits<32>>,
    pub data1: Signal<In, Bits<32>>,
    pub data2: Signal<In, Bits<32>>,
    pub data3: Signal<In, Bits<32>>,
    pub bank: Signal<In, Bits<2>>,
    pub word: Signal<Out, Bits<32>>,
}

impl Logic for Pick {
    #[hdl_gen]
    fn update(&mut self) {
        self.word.next = self.data0.val();
        if self.bank.val() == 1 {
            self.word.next = self.data1.val();
        }
        if self.bank.val() == 2 {
            self.word.next = self.data2.val();
        }
        if self.bank.val() == 3 {
            self.word.next = self.data3.val();
        }
    }
}

/// The texture unit over a cache of `1 << SB` sets, `W` ways, `1 << (DA - SB)` words a line
/// (`texture_cache`'s widths; name it by geometry with [`TextureUnitOf`]).
#[derive(LogicBlock, Blank)]
pub struct TextureUnit<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> {
    pub clock: Signal<In, Clock>,
    /// A pixel is offered: s·q, t·q (`st`), q (`q`), its triangle's gradients (`dst`, `dq`),
    /// its lit colour (R 23..16, G 15..8, B 7..0) and a tag carried to `out_tag`.
    pub inp_valid: Signal<In, Bit>,
    /// The pixel is taken this cycle (with `inp_valid`).
    pub inp_ready: Signal<Out, Bit>,
    pub inp_sq: Signal<In, Bits<ST>>,
    pub inp_tq: Signal<In, Bits<ST>>,
    pub inp_q: Signal<In, Bits<QB>>,
    pub inp_dsq_x: Signal<In, Bits<DST>>,
    pub inp_dsq_y: Signal<In, Bits<DST>>,
    pub inp_dtq_x: Signal<In, Bits<DST>>,
    pub inp_dtq_y: Signal<In, Bits<DST>>,
    pub inp_dq_x: Signal<In, Bits<DQ>>,
    pub inp_dq_y: Signal<In, Bits<DQ>>,
    pub inp_cf: Signal<In, Bits<24>>,
    pub inp_tag: Signal<In, Bits<32>>,
    /// High for a cycle: the state registers take `st` (only while `idle`).
    pub st_load: Signal<In, Bit>,
    /// The texture's state.
    pub st: TextureState,
    /// A pulse: the cache invalidates every line.
    pub inp_flush: Signal<In, Bit>,
    /// A textured pixel: its colour (R 31..24, G 23..16, B 15..8, A 7..0) and tag, held
    /// until taken (`out_ready`).
    pub out_valid: Signal<Out, Bit>,
    pub out_ready: Signal<In, Bit>,
    pub out_rgba: Signal<Out, Bits<32>>,
    pub out_tag: Signal<Out, Bits<32>>,
    /// The cache's memory read port and its counters.
    pub mem: TexMemory,
    pub counters: CacheCounters,
    /// No pixel in flight: the state may be loaded.
    pub idle: Signal<Out, Bit>,

    coords: TextureCoords,
    address: TextureAddress,
    cache: TextureCache<SB, DA, W, TAG, TV>,
    pick: [Pick; 4],
    filter: TextureFilter,
    cf_ram: RAM<Bits<24>, FB>,
    tag_ram: RAM<Bits<32>, FB>,
    r_ws: DFF<Bits<4>>,
    r_hs: DFF<Bits<4>>,
    r_levels: DFF<Bits<4>>,
    r_base: DFF<Bits<ADDR>>,
    r_min_linear: DFF<Bit>,
    r_mag_linear: DFF<Bit>,
    r_mip: DFF<Bits<2>>,
    r_wrap_s: DFF<Bits<2>>,
    r_wrap_t: DFF<Bits<2>>,
    r_format: DFF<Bits<3>>,
    r_gaussian: DFF<Bit>,
    r_env: DFF<Bits<3>>,
    /// The access coords' pixel makes next (into texture_address) is of its second level.
    second: DFF<Bit>,
    /// The RAMs' pointers: the next pixel's word; the pixel entering the filter's; the
    /// pixel at the output's.
    wp: DFF<Bits<FB>>,
    rc: DFF<Bits<FB>>,
    rt: DFF<Bits<FB>>,
    /// A two-level pixel's first level: its words in footprint order, alpha, beta.
    pair_words: [DFF<Bits<32>>; 4],
    pair_alpha: DFF<Bits<8>>,
    pair_beta: DFF<Bits<8>>,
    en_f: Signal<Local, Bit>,
    en_a: Signal<Local, Bit>,
    en_c: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    accept: Signal<Local, Bit>,
    attr: Signal<Local, Bits<32>>,
    /// The cache's result: its attributes (the side's low half), a pixel's first level,
    /// a whole pixel for the filter.
    res: Signal<Local, Bits<32>>,
    first: Signal<Local, Bit>,
    whole: Signal<Local, Bit>,
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize>
    TextureUnit<SB, DA, W, TAG, TV>
{
    /// The unit, with GL's exact rho when `exact` (else 001's eq. 4).
    pub fn new(exact: bool) -> Self {
        Self { coords: TextureCoords::new(exact), ..Self::blank() }
    }
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> Default
    for TextureUnit<SB, DA, W, TAG, TV>
{
    fn default() -> Self {
        Self::new(false)
    }
}

impl<const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize> Logic
    for TextureUnit<SB, DA, W, TAG, TV>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            r_ws,
            r_hs,
            r_levels,
            r_base,
            r_min_linear,
            r_mag_linear,
            r_mip,
            r_wrap_s,
            r_wrap_t,
            r_format,
            r_gaussian,
            r_env,
            second,
            wp,
            rc,
            rt,
            pair_alpha,
            pair_beta
        );
        for k in 0..4 {
            self.pair_words[k].clock.next = self.clock.val();
            self.pair_words[k].d.next = self.pair_words[k].q.val();
        }
        if self.st_load.val() {
            self.r_ws.d.next = self.st.ws.val();
            self.r_hs.d.next = self.st.hs.val();
            self.r_levels.d.next = self.st.levels.val();
            self.r_base.d.next = self.st.base.val();
            self.r_min_linear.d.next = self.st.min_linear.val();
            self.r_mag_linear.d.next = self.st.mag_linear.val();
            self.r_mip.d.next = self.st.mip.val();
            self.r_wrap_s.d.next = self.st.wrap_s.val();
            self.r_wrap_t.d.next = self.st.wrap_t.val();
            self.r_format.d.next = self.st.format.val();
            self.r_gaussian.d.next = self.st.gaussian.val();
            self.r_env.d.next = self.st.env.val();
        }

        // The filter moves on unless its pixel waits at the output.
        self.en_f.next = self.out_ready.val() | !self.filter.out_valid.val();

        // texture_address moves on when its last stage is empty or the cache takes its
        // access.
        self.en_a.next = !self.address.out_valid.val() | self.cache.inp_ready.val();

        // Coords' pixel into texture_address: its access (the second level's when `second`),
        // at the cache LATENCY enabled clocks later.
        self.address.clock.next = self.clock.val();
        self.address.en.next = self.en_a.val();
        self.address.inp_valid.next = self.coords.out_valid.val();
        self.address.s.next = self.coords.out_s.val();
        self.address.t.next = self.coords.out_t.val();
        self.address.lambda.next = self.coords.out_lambda.val();
        self.address.second.next = self.second.q.val();
        self.address.ws.next = self.r_ws.q.val();
        self.address.hs.next = self.r_hs.q.val();
        self.address.levels.next = self.r_levels.q.val();
        self.address.base.next = self.r_base.q.val();
        self.address.min_linear.next = self.r_min_linear.q.val();
        self.address.mag_linear.next = self.r_mag_linear.q.val();
        self.address.mip.next = self.r_mip.q.val();
        self.address.wrap_s.next = self.r_wrap_s.q.val();
        self.address.wrap_t.next = self.r_wrap_t.q.val();
        self.attr.next = (bit_cast::<32, 8>(self.address.beta.val()) << 24)
            | (bit_cast::<32, 8>(self.address.alpha.val()) << 16)
            | (bit_cast::<32, 8>(self.address.banks.val()) << 8)
            | (bit_cast::<32, 6>(self.address.frac.val()) << 2);
        if self.address.two_levels.val() {
            self.attr.next = self.attr.val().replace_bit(1, true);
        }
        if self.address.out_second.val() {
            self.attr.next = self.attr.val().replace_bit(0, true);
        }
        self.cache.clock.next = self.clock.val();
        self.cache.inp_valid.next = self.address.out_valid.val();
        self.cache.inp_en.next = self.address.lanes.val();
        self.cache.inp_addr0.next = self.address.addr0.val();
        self.cache.inp_addr1.next = self.address.addr1.val();
        self.cache.inp_addr2.next = self.address.addr2.val();
        self.cache.inp_addr3.next = self.address.addr3.val();
        self.cache.inp_side.next = bit_cast::<64, 32>(self.attr.val());
        self.cache.inp_flush.next = self.inp_flush.val();
        self.cache.out_ready.next = self.en_f.val();
        TexMemory::link(&mut self.mem, &mut self.cache.mem);
        CacheCounters::link(&mut self.counters, &mut self.cache.counters);

        // Coords moves on when its last stage is empty or texture_address takes its pixel's
        // last access.
        self.take.next = self.coords.out_valid.val() & self.en_a.val();
        self.en_c.next = !self.coords.out_valid.val()
            | (self.en_a.val() & (!self.address.inp_two_levels.val() | self.second.q.val()));
        if self.take.val() {
            self.second.d.next = self.address.inp_two_levels.val() & !self.second.q.val();
        }
        self.inp_ready.next = self.en_c.val() & !self.st_load.val();
        self.accept.next = self.inp_valid.val() & self.inp_ready.val();
        self.coords.clock.next = self.clock.val();
        self.coords.en.next = self.en_c.val();
        self.coords.inp_valid.next = self.inp_valid.val() & !self.st_load.val();
        self.coords.inp_sq.next = self.inp_sq.val();
        self.coords.inp_tq.next = self.inp_tq.val();
        self.coords.inp_q.next = self.inp_q.val();
        self.coords.inp_dsq_x.next = self.inp_dsq_x.val();
        self.coords.inp_dsq_y.next = self.inp_dsq_y.val();
        self.coords.inp_dtq_x.next = self.inp_dtq_x.val();
        self.coords.inp_dtq_y.next = self.inp_dtq_y.val();
        self.coords.inp_dq_x.next = self.inp_dq_x.val();
        self.coords.inp_dq_y.next = self.inp_dq_y.val();
        self.coords.inp_ws.next = self.r_ws.q.val();
        self.coords.inp_hs.next = self.r_hs.q.val();

        // The pixel's colour and tag, in order, one RAM word a pixel.
        self.cf_ram.write_clock.next = self.clock.val();
        self.cf_ram.read_clock.next = self.clock.val();
        self.tag_ram.write_clock.next = self.clock.val();
        self.tag_ram.read_clock.next = self.clock.val();
        self.cf_ram.write_enable.next = self.accept.val();
        self.tag_ram.write_enable.next = self.accept.val();
        self.cf_ram.write_address.next = self.wp.q.val();
        self.tag_ram.write_address.next = self.wp.q.val();
        self.cf_ram.write_data.next = self.inp_cf.val();
        self.tag_ram.write_data.next = self.inp_tag.val();
        if self.accept.val() {
            self.wp.d.next = self.wp.q.val() + 1;
        }

        // The cache's result: a first level waits in the pair register, a whole pixel
        // (one level, or the second of two) goes into the filter.
        self.res.next = self.cache.out_side.val().get_bits::<32>(0);
        for k in 0..4 {
            self.pick[k].data0.next = self.cache.out_data0.val();
            self.pick[k].data1.next = self.cache.out_data1.val();
            self.pick[k].data2.next = self.cache.out_data2.val();
            self.pick[k].data3.next = self.cache.out_data3.val();
        }
        self.pick[0].bank.next = self.res.val().get_bits::<2>(8);
        self.pick[1].bank.next = self.res.val().get_bits::<2>(10);
        self.pick[2].bank.next = self.res.val().get_bits::<2>(12);
        self.pick[3].bank.next = self.res.val().get_bits::<2>(14);
        self.first.next = self.res.val().get_bit(1) & !self.res.val().get_bit(0);
        self.whole.next = self.cache.out_valid.val() & !self.first.val();
        if self.cache.out_valid.val() & self.first.val() & self.en_f.val() {
            for k in 0..4 {
                self.pair_words[k].d.next = self.pick[k].word.val();
            }
            self.pair_alpha.d.next = self.res.val().get_bits::<8>(16);
            self.pair_beta.d.next = self.res.val().get_bits::<8>(24);
        }
        self.filter.clock.next = self.clock.val();
        self.filter.en.next = self.en_f.val();
        self.filter.inp_valid.next = self.whole.val();
        self.filter.inp_words0_0.next = self.pick[0].word.val();
        self.filter.inp_words0_1.next = self.pick[1].word.val();
        self.filter.inp_words0_2.next = self.pick[2].word.val();
        self.filter.inp_words0_3.next = self.pick[3].word.val();
        self.filter.inp_alpha0.next = self.res.val().get_bits::<8>(16);
        self.filter.inp_beta0.next = self.res.val().get_bits::<8>(24);
        if self.res.val().get_bit(1) {
            self.filter.inp_words0_0.next = self.pair_words[0].q.val();
            self.filter.inp_words0_1.next = self.pair_words[1].q.val();
            self.filter.inp_words0_2.next = self.pair_words[2].q.val();
            self.filter.inp_words0_3.next = self.pair_words[3].q.val();
            self.filter.inp_alpha0.next = self.pair_alpha.q.val();
            self.filter.inp_beta0.next = self.pair_beta.q.val();
        }
        self.filter.inp_words1_0.next = self.pick[0].word.val();
        self.filter.inp_words1_1.next = self.pick[1].word.val();
        self.filter.inp_words1_2.next = self.pick[2].word.val();
        self.filter.inp_words1_3.next = self.pick[3].word.val();
        self.filter.inp_alpha1.next = self.res.val().get_bits::<8>(16);
        self.filter.inp_beta1.next = self.res.val().get_bits::<8>(24);
        self.filter.inp_frac.next = self.res.val().get_bits::<6>(2);
        self.filter.inp_two_levels.next = self.res.val().get_bit(1);
        self.filter.inp_format.next = self.r_format.q.val();
        self.filter.inp_gaussian.next = self.r_gaussian.q.val();
        self.filter.inp_env.next = self.r_env.q.val();
        self.filter.inp_cf.next = self.cf_ram.read_data.val();
        self.cf_ram.read_address.next = self.rc.q.val();
        if self.whole.val() & self.en_f.val() {
            self.rc.d.next = self.rc.q.val() + 1;
            self.cf_ram.read_address.next = self.rc.q.val() + 1;
        }

        // The output: the filter's last stage, the tag of its pixel.
        self.out_valid.next = self.filter.out_valid.val();
        self.out_rgba.next = self.filter.out_rgba.val();
        self.out_tag.next = self.tag_ram.read_data.val();
        self.tag_ram.read_address.next = self.rt.q.val();
        if self.filter.out_valid.val() & self.out_ready.val() {
            self.rt.d.next = self.rt.q.val() + 1;
            self.tag_ram.read_address.next = self.rt.q.val() + 1;
        }
        self.idle.next = self.wp.q.val() == self.rt.q.val();
    }
}

crate::pins!(impl[const SB: usize, const DA: usize, const W: usize, const TAG: usize, const TV: usize]
    TextureUnit<SB, DA, W, TAG, TV> {
    clock: clock,
    inputs: [
        inp_valid, inp_sq, inp_tq, inp_q, inp_dsq_x, inp_dsq_y, inp_dtq_x, inp_dtq_y, inp_dq_x, inp_dq_y, inp_cf,
        inp_tag, st_load, inp_flush, out_ready,
    ],
    outputs: [inp_ready, out_valid, out_rgba, out_tag, idle],
    links: [st, mem, counters],
});

/// The cache geometries the unit is built for: (SETS, WAYS, LINE) and its type.
macro_rules! unit_geometries {
    ($(($s:literal $w:literal $l:literal) => $unit:ty,)*) => {
        /// The cache geometries (SETS, WAYS, LINE) `texture_unit` is built for: the default
        /// design's and the tests' small direct-mapped one. (Each is a copy of the cache and
        /// the unit in this crate; `texture_cache` alone is built at more.)
        pub const GEOMETRIES: &[(u32, u32, u32)] = &[$(($s, $w, $l)),*];

        /// `emit_unit` of geometry `g`, when built.
        fn emit_built(g: (u32, u32, u32), exact: bool, params: &Params) -> Option<Emitted> {
            $(
                if g == ($s, $w, $l) {
                    return Some(emit_unit("texture_unit", <$unit>::new(exact), params));
                }
            )*
            None
        }
    };
}

/// The unit over the default cache: 64 sets, 2 ways, 4 words.
pub type TextureUnit6424 = TextureUnit<6, 8, 2, 18, 19>;
/// The unit over a cache of 4 sets, 1 way, 1 word (every new word a miss): the tests'.
pub type TextureUnit411 = TextureUnit<2, 2, 1, 24, 25>;

unit_geometries! {
    (64 2 4) => TextureUnit6424,
    (4 1 1) => TextureUnit411,
}

/// `UNITS` entry: the unit over the cache `params["SETS"]`, `["WAYS"]`, `["LINE"]` (one of
/// [`GEOMETRIES`]), the level-of-detail rule `params["EXACT"]`.
pub fn emit_texture_unit(params: &Params) -> Result<Emitted, String> {
    let exact = crate::exact_rule("texture_unit", params)?;
    let get = |k: &str| u32::try_from(params[k]).map_err(|_| format!("texture_unit: {k} = {} is too large", params[k]));
    let p = model::texture_cache::Params { sets: get("SETS")?, ways: get("WAYS")?, line: get("LINE")? };
    p.check()?;
    emit_built((p.sets, p.ways, p.line), exact, params).ok_or_else(|| {
        let built: Vec<String> = GEOMETRIES.iter().map(|(s, w, l)| format!("{s}/{w}/{l}")).collect();
        format!(
            "texture_unit: SETS = {}, WAYS = {}, LINE = {} is not built; the geometries built (SETS/WAYS/LINE, \
             rtl::texture_unit::GEOMETRIES): {}",
            p.sets,
            p.ways,
            p.line,
            built.join(", ")
        )
    })
}
