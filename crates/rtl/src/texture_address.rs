//! `texture_address`: the second stage of paper 001's texture unit (section II-5), between
//! `texture_coords` and the texture cache: from a pixel's s, t and lambda, the level it
//! reads (OpenGL 4.6 sections 8.14.3 and 8.15: magnified, one level, or the first or second
//! of two), the 2x2 footprint's texels in it with their fractions (section 8.14.2), each
//! index wrapped on its own, and each texel's word in `model::texture_memory`'s parity
//! planes: one cache access, a word per bank. Three stages, a global enable `en`; bit-exact
//! to `model::texture_unit::request` at `fx::TexFormats::DEFAULT`.
//!
//! ```text
//!  A  lambda ─> level d (magnify: 0; nearest: clamp((lambda + 31) >> 6, 0, q); linear: lambda >> 6
//!     (+1 second)); the level's sides sw = max(ws - d, 0), sh; its planes' pw = max(sw - 1, 0), ph
//!  B  s, t ──> u = s >> (12 - sw) (8 sub-texel bits); linear: i0 = (u - 1/2) >> 8, alpha = its low
//!     8 bits, i1 = (u + 1/2) >> 8 = i0 + 1; nearest: i0 = i1 = u >> 8
//!     offset(d) = base + the words of levels 0 .. d - 1 (a bit pattern and 4 words a 1 x 1 level)
//!  C  wrap each index (repeat: a mask; mirrored: a mask and a reflection; clamp: a clamp);
//!     each bank's texel by the indices' parities; its word
//!     offset(d) + bank · plane(d) + (j >> 1) · pitch(d) + (i >> 1)
//!  (plane(d) = 2^(pw + ph), pitch(d) = 2^pw: the three terms are disjoint bit fields, one sum)
//! ```
//!
//! The levels before d, each 4 planes of 2^(max(ws - k - 1, 0) + max(hs - k - 1, 0)) words,
//! make offset(d) without an adder per level (summed level by level, 13 adders behind each
//! other, they were the critical path of the unit when it was combinational: 13.4 MHz on
//! ECP5): with a = max(ws, hs), b = min(ws, hs), S = ws + hs, m = min(d, b), e = min(d, a),
//! levels k < m add 2^(S - 2k) (bits S, S - 2, ..., S - 2m + 2), levels b <= k < e add
//! 2^(a - k + 1) (bits a + 1 - b down to a + 2 - e, below the first run), and the levels
//! k >= a 4 words each: offset(d) = base + (the two runs) + 4 max(d - a, 0).
//!
//! Latency [`LATENCY`] = 3 enabled clocks: an access presented in cycle c with `en` high is
//! on the outputs in cycle c + 3 when `en` is high in cycles c .. c + 2; `en` low holds every
//! register. `inp_valid` and `second` travel with the access to `out_valid` and
//! `out_second`. `inp_two_levels` is combinational: whether the pixel at the input reads
//! two levels (the texture unit then presents it twice, `second` low then high). The state
//! (size, levels, filters, mipmapping, wrap, base) is the texture's, read by each stage as
//! the access passes (A the level rule and sizes, B the sizes and base, C the wrap modes):
//! hold it while accesses are in flight, as the texture unit does while a triangle is
//! drawn. Tests: `testbenches/tests/texture_address.rs`.
//!
//! Area (Yosys 0.23 `synth_ecp5`): 3,069 LUT4 and 381 FF (7,734 LUT4 when it was
//! combinational); 51.4 MHz between registers on an LFE5U-25F (nextpnr-ecp5 router2), its
//! critical path the state's sides through the first runs' bit pattern into stage B's
//! first word.

use crate::emit::{emit_unit, Emitted};
use crate::Params;
use blank::Blank;
use fx::TexFormats;
use rust_hdl::prelude::*;

const F: TexFormats = TexFormats::DEFAULT;
/// s and t (`st`).
pub const ST: usize = F.st.bits() as usize;
/// lambda, as `texture_coords` gives it.
pub const LAMBDA: usize = crate::texture_coords::LAMBDA;
/// Word addresses of texture memory (`model::texture_memory::ADDR_BITS`).
pub const ADDR: usize = model::texture_memory::ADDR_BITS as usize;
/// Sub-texel bits and level-of-detail fraction bits.
pub const SUB: usize = F.subtexel as usize;
pub const LF: usize = F.lod_frac as usize;
/// Enabled clocks from an access in to its words out.
pub const LATENCY: usize = 3;
/// A coordinate in a level's sub-texel bits (signed, with room for the half texel), texel
/// indices before wrapping (signed, with room for i0 + 1) and after.
const U: usize = ST + 1;
const I: usize = U - SUB;
const IW: usize = fx::texture::MAX_SIZE_LOG2 as usize + 1;
/// Bits of the offset's exponents and level counts (sums of sizes and levels, at most 49).
const E: usize = 6;
// rust-hdl's `hdl_gen` reads a Rust constant in an expression as a Verilog name, so bit
// positions and rounding terms are literals below: ST - 1 = 28, U - 1 = 29, I - 1 = 21, LAMBDA - 1 =
// 31, sub-texel bits 8 (1/2 is 128), 2^(LF - 1) - 1 = 31 and LF = 6, 12 = st.frac - SUB,
// 0x3f_ffff = 2^I - 1.
const _: () = assert!(
    F.st.frac as usize == SUB + fx::texture::MAX_SIZE_LOG2 as usize
        && ST == 29
        && I == 22
        && LAMBDA == 32
        && SUB == 8
        && LF == 6
        && fx::texture::MAX_SIZE_LOG2 == 12
        && 2 * (fx::texture::MAX_SIZE_LOG2 as usize) < ADDR
        && ADDR + 2 * (fx::texture::MAX_SIZE_LOG2 as usize) < 1 << E
);

/// Stage B of one axis: the coordinate in the level's sub-texel bits, the footprint's two
/// indices (before wrapping) and fraction.
#[derive(LogicBlock, Default)]
pub struct Axis {
    /// The coordinate (`st`), log2 of the level's size along the axis, whether the filter
    /// is linear.
    pub coord: Signal<In, Bits<ST>>,
    pub size_log2: Signal<In, Bits<4>>,
    pub linear: Signal<In, Bit>,
    pub i0: Signal<Out, Bits<I>>,
    pub i1: Signal<Out, Bits<I>>,
    pub frac: Signal<Out, Bits<SUB>>,
    wide: Signal<Local, Bits<U>>,
    u: Signal<Local, Bits<U>>,
    top: Signal<Local, Bits<I>>,
}

impl Logic for Axis {
    #[hdl_gen]
    fn update(&mut self) {
        // u = coord >> (12 - size_log2), arithmetic, in one bit more than coord (room for
        // the half texel a linear filter moves by): sub-texel bits of the level.
        self.wide.next = bit_cast::<U, ST>(self.coord.val());
        if self.coord.val().get_bit(28) {
            self.wide.next = bit_cast::<U, ST>(self.coord.val()) | bits::<U>(0x2000_0000);
        }
        self.u.next = self.wide.val() >> (bits::<U>(12) - bit_cast::<U, 4>(self.size_log2.val()));
        if self.coord.val().get_bit(28) {
            self.u.next = (self.wide.val() >> (bits::<U>(12) - bit_cast::<U, 4>(self.size_log2.val())))
                | !(bits::<U>(0x3fff_ffff) >> (bits::<U>(12) - bit_cast::<U, 4>(self.size_log2.val())));
        }
        // i0 = (u - 1/2) >> 8 and i1 = (u + 1/2) >> 8 = i0 + 1: u >> 8 (the top I bits, the
        // sign among them) and one more, or one less and u >> 8, by u's bit 7; alpha = the
        // low 8 bits of u - 1/2.
        self.top.next = self.u.val().get_bits::<I>(8);
        self.i0.next = self.top.val();
        self.i1.next = self.top.val();
        self.frac.next = 0.into();
        if self.linear.val() {
            self.i1.next = self.top.val() + 1;
            if !self.u.val().get_bit(7) {
                self.i0.next = self.top.val() - 1;
                self.i1.next = self.top.val();
            }
            self.frac.next = self.u.val().get_bits::<SUB>(0) ^ bits::<SUB>(128);
        }
    }
}

/// A texel index wrapped into 0..2^size_log2 (`model::texture_address::wrap_index`), by
/// masks: REPEAT keeps the bits below size_log2; MIRRORED_REPEAT also inverts them when the
/// bit at size_log2 is set (2n - 1 - p for n <= p < 2n); CLAMP_TO_EDGE gives 0 below 0 and
/// n - 1 when a bit at or above size_log2 is set.
#[derive(LogicBlock, Default)]
pub struct Wrap {
    pub i: Signal<In, Bits<I>>,
    pub size_log2: Signal<In, Bits<4>>,
    pub mode: Signal<In, Bits<2>>,
    pub wrapped: Signal<Out, Bits<IW>>,
    /// n = 2^size_log2, n - 1, the index's bits below size_log2 and at or above it.
    n: Signal<Local, Bits<I>>,
    mask: Signal<Local, Bits<I>>,
    low: Signal<Local, Bits<I>>,
    high: Signal<Local, Bits<I>>,
}

impl Logic for Wrap {
    #[hdl_gen]
    fn update(&mut self) {
        self.n.next = bits::<I>(1) << bit_cast::<I, 4>(self.size_log2.val());
        self.mask.next = !(bits::<I>(0x3f_ffff) << bit_cast::<I, 4>(self.size_log2.val()));
        self.low.next = self.i.val() & self.mask.val();
        self.high.next = self.i.val() & !self.mask.val();
        // Repeat (and the default for mode 3).
        self.wrapped.next = bit_cast::<IW, I>(self.low.val());
        if (self.mode.val() == 1) & (self.i.val() & self.n.val()).any() {
            self.wrapped.next = bit_cast::<IW, I>(!self.i.val() & self.mask.val());
        }
        if self.mode.val() == 2 {
            if self.i.val().get_bit(21) {
                self.wrapped.next = 0.into();
            } else if self.high.val().any() {
                self.wrapped.next = bit_cast::<IW, I>(self.mask.val());
            }
        }
    }
}

/// One bank's word: offset + bank · 2^(pw + ph) + (j >> 1) · 2^pw + (i >> 1), the three
/// terms disjoint bit fields (i >> 1 < 2^pw, j >> 1 < 2^ph), so one sum.
#[derive(LogicBlock, Default)]
pub struct Word {
    pub i: Signal<In, Bits<IW>>,
    pub j: Signal<In, Bits<IW>>,
    /// The bank, the level's first word (base + offset(d)), log2 of its planes' width and
    /// of their words (pw + ph).
    pub bank: Signal<In, Bits<2>>,
    pub first: Signal<In, Bits<ADDR>>,
    pub pw: Signal<In, Bits<4>>,
    pub pwh: Signal<In, Bits<5>>,
    pub addr: Signal<Out, Bits<ADDR>>,
    field: Signal<Local, Bits<ADDR>>,
}

impl Logic for Word {
    #[hdl_gen]
    fn update(&mut self) {
        self.field.next = (bit_cast::<ADDR, 2>(self.bank.val()) << bit_cast::<ADDR, 5>(self.pwh.val()))
            | (bit_cast::<ADDR, IW>(self.j.val() >> 1) << bit_cast::<ADDR, 4>(self.pw.val()))
            | bit_cast::<ADDR, IW>(self.i.val() >> 1);
        self.addr.next = self.first.val() + self.field.val();
    }
}

/// The texture address unit: stages A, B and C (see the module documentation).
#[derive(LogicBlock, Blank)]
pub struct TextureAddress {
    pub clock: Signal<In, Clock>,
    /// Every register moves on when high.
    pub en: Signal<In, Bit>,
    /// An access is presented: the pixel's s, t, lambda, and whether it is of the second of
    /// its two levels.
    pub inp_valid: Signal<In, Bit>,
    pub s: Signal<In, Bits<ST>>,
    pub t: Signal<In, Bits<ST>>,
    pub lambda: Signal<In, Bits<LAMBDA>>,
    pub second: Signal<In, Bit>,
    /// The texture's state: log2 of its sides, its levels (1 to 13), its base address, the
    /// filters (1: linear), mipmapping (0 none, 1 nearest, 2 linear), wrap per axis (0
    /// repeat, 1 mirrored repeat, 2 clamp to edge).
    pub ws: Signal<In, Bits<4>>,
    pub hs: Signal<In, Bits<4>>,
    pub levels: Signal<In, Bits<4>>,
    pub base: Signal<In, Bits<ADDR>>,
    pub min_linear: Signal<In, Bit>,
    pub mag_linear: Signal<In, Bit>,
    pub mip: Signal<In, Bits<2>>,
    pub wrap_s: Signal<In, Bits<2>>,
    pub wrap_t: Signal<In, Bits<2>>,
    /// Combinational: the pixel at the input reads two levels.
    pub inp_two_levels: Signal<Out, Bit>,
    /// The access, [`LATENCY`] enabled clocks later: valid, of a second level, each bank's
    /// enable and word address, the bank of each footprint texel (2 bits each, T(i0, j0)
    /// lowest), the fractions, and the pixel's levels.
    pub out_valid: Signal<Out, Bit>,
    pub out_second: Signal<Out, Bit>,
    pub lanes: Signal<Out, Bits<4>>,
    pub addr0: Signal<Out, Bits<ADDR>>,
    pub addr1: Signal<Out, Bits<ADDR>>,
    pub addr2: Signal<Out, Bits<ADDR>>,
    pub addr3: Signal<Out, Bits<ADDR>>,
    pub banks: Signal<Out, Bits<8>>,
    pub alpha: Signal<Out, Bits<SUB>>,
    pub beta: Signal<Out, Bits<SUB>>,
    pub two_levels: Signal<Out, Bit>,
    pub frac: Signal<Out, Bits<LF>>,

    // Stage A: the level.
    magnify: Signal<Local, Bit>,
    q: Signal<Local, Bits<LAMBDA>>,
    d: Signal<Local, Bits<LAMBDA>>,
    level: Signal<Local, Bits<4>>,
    sw: Signal<Local, Bits<4>>,
    sh: Signal<Local, Bits<4>>,
    a_valid: DFF<Bit>,
    a_second: DFF<Bit>,
    a_s: DFF<Bits<ST>>,
    a_t: DFF<Bits<ST>>,
    a_two: DFF<Bit>,
    a_frac: DFF<Bits<LF>>,
    a_linear: DFF<Bit>,
    a_level: DFF<Bits<4>>,
    a_sw: DFF<Bits<4>>,
    a_sh: DFF<Bits<4>>,
    a_pw: DFF<Bits<4>>,
    a_ph: DFF<Bits<4>>,

    // Stage B: the indices and fractions, the level's first word.
    across: Axis,
    up: Axis,
    /// ws, hs and the level in E bits; max, min and sum of the sides (a, b, S); min(d, b),
    /// 2 min(d, b), min(d, a); S - p and a + 1 - p for each bit p; the two runs of the levels
    /// before d, and the 1 x 1 levels' words.
    ws_e: Signal<Local, Bits<E>>,
    hs_e: Signal<Local, Bits<E>>,
    d_e: Signal<Local, Bits<E>>,
    side_max: Signal<Local, Bits<E>>,
    side_min: Signal<Local, Bits<E>>,
    side_sum: Signal<Local, Bits<E>>,
    m_lv: Signal<Local, Bits<E>>,
    m_2: Signal<Local, Bits<E>>,
    e_lv: Signal<Local, Bits<E>>,
    from_sum: [Signal<Local, Bits<E>>; ADDR],
    from_max: [Signal<Local, Bits<E>>; ADDR],
    runs: Signal<Local, Bits<ADDR>>,
    ones: Signal<Local, Bits<ADDR>>,
    b_valid: DFF<Bit>,
    b_second: DFF<Bit>,
    b_two: DFF<Bit>,
    b_frac: DFF<Bits<LF>>,
    b_sw: DFF<Bits<4>>,
    b_sh: DFF<Bits<4>>,
    b_pw: DFF<Bits<4>>,
    b_pwh: DFF<Bits<5>>,
    b_i0: DFF<Bits<I>>,
    b_i1: DFF<Bits<I>>,
    b_j0: DFF<Bits<I>>,
    b_j1: DFF<Bits<I>>,
    b_alpha: DFF<Bits<SUB>>,
    b_beta: DFF<Bits<SUB>>,
    b_first: DFF<Bits<ADDR>>,

    // Stage C: wrap, each bank's texel and word.
    wrap: [Wrap; 4],
    /// The wrapped indices' parities; the even and odd index along each axis (either one
    /// when both have that parity or neither does).
    i_even: Signal<Local, Bits<IW>>,
    i_odd: Signal<Local, Bits<IW>>,
    j_even: Signal<Local, Bits<IW>>,
    j_odd: Signal<Local, Bits<IW>>,
    has_i_even: Signal<Local, Bit>,
    has_i_odd: Signal<Local, Bit>,
    has_j_even: Signal<Local, Bit>,
    has_j_odd: Signal<Local, Bit>,
    /// The banks read.
    lane: Signal<Local, Bits<4>>,
    word: [Word; 4],
    c_valid: DFF<Bit>,
    c_second: DFF<Bit>,
    c_two: DFF<Bit>,
    c_frac: DFF<Bits<LF>>,
    c_alpha: DFF<Bits<SUB>>,
    c_beta: DFF<Bits<SUB>>,
    c_lanes: DFF<Bits<4>>,
    c_banks: DFF<Bits<8>>,
    c_addr: [DFF<Bits<ADDR>>; 4],

    bank_id: [Constant<Bits<2>>; 4],
    lane_bit: [Constant<Bits<4>>; 4],
    /// Bit p of an address: its position p, 2^p.
    pos: [Constant<Bits<E>>; ADDR],
    pos_bit: [Constant<Bits<ADDR>>; ADDR],
}

impl Default for TextureAddress {
    fn default() -> Self {
        Self {
            bank_id: std::array::from_fn(|b| Constant::new(b.to_bits())),
            lane_bit: std::array::from_fn(|b| Constant::new((1usize << b).to_bits())),
            pos: std::array::from_fn(|p| Constant::new(p.to_bits())),
            pos_bit: std::array::from_fn(|p| Constant::new((1usize << p).to_bits())),
            ..Self::blank()
        }
    }
}

impl Logic for TextureAddress {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, a_valid, a_second, a_s, a_t, a_two, a_frac, a_linear, a_level, a_sw, a_sh, a_pw, a_ph,
            b_valid, b_second, b_two, b_frac, b_sw, b_sh, b_pw, b_pwh, b_i0, b_i1, b_j0, b_j1, b_alpha, b_beta,
            b_first, c_valid, c_second, c_two, c_frac, c_alpha, c_beta, c_lanes, c_banks
        );
        for b in 0..4 {
            self.c_addr[b].clock.next = self.clock.val();
            self.c_addr[b].d.next = self.c_addr[b].q.val();
        }

        // A: the level (section 8.14.3): q = levels - 1; lambda <= 0 magnifies.
        self.q.next = bit_cast::<LAMBDA, 4>(self.levels.val()) - 1;
        self.magnify.next = self.lambda.val().get_bit(31) | !self.lambda.val().any();
        self.inp_two_levels.next = false;
        self.d.next = 0.into();
        if !self.magnify.val() {
            if self.mip.val() == 1 {
                // ceil(lambda + 1/2) - 1 = (lambda + 2^(LF-1) - 1) >> LF, at most q.
                self.d.next = (self.lambda.val() + 31) >> 6;
                if self.d.val() > self.q.val() {
                    self.d.next = self.q.val();
                }
            }
            if self.mip.val() == 2 {
                self.d.next = self.lambda.val() >> 6;
                if self.d.val() >= self.q.val() {
                    self.d.next = self.q.val();
                } else {
                    self.inp_two_levels.next = true;
                    if self.second.val() {
                        self.d.next = self.d.val() + 1;
                    }
                }
            }
        }
        self.level.next = self.d.val().get_bits::<4>(0);
        // The level's sides: max(ws - d, 0), max(hs - d, 0).
        self.sw.next = 0.into();
        if self.ws.val() > self.level.val() {
            self.sw.next = self.ws.val() - self.level.val();
        }
        self.sh.next = 0.into();
        if self.hs.val() > self.level.val() {
            self.sh.next = self.hs.val() - self.level.val();
        }
        if self.en.val() {
            self.a_valid.d.next = self.inp_valid.val();
            self.a_second.d.next = self.second.val();
            self.a_s.d.next = self.s.val();
            self.a_t.d.next = self.t.val();
            self.a_two.d.next = self.inp_two_levels.val();
            self.a_frac.d.next = 0.into();
            if self.inp_two_levels.val() {
                self.a_frac.d.next = self.lambda.val().get_bits::<LF>(0);
            }
            self.a_linear.d.next = self.min_linear.val();
            if self.magnify.val() {
                self.a_linear.d.next = self.mag_linear.val();
            }
            self.a_level.d.next = self.level.val();
            self.a_sw.d.next = self.sw.val();
            self.a_sh.d.next = self.sh.val();
            // A plane's sides: one less than the level's (a 1-wide level's are 1 wide).
            self.a_pw.d.next = 0.into();
            if self.sw.val().any() {
                self.a_pw.d.next = self.sw.val() - 1;
            }
            self.a_ph.d.next = 0.into();
            if self.sh.val().any() {
                self.a_ph.d.next = self.sh.val() - 1;
            }
        }

        // B: the footprint (section 8.14.2), before wrapping.
        self.across.coord.next = self.a_s.q.val();
        self.across.size_log2.next = self.a_sw.q.val();
        self.across.linear.next = self.a_linear.q.val();
        self.up.coord.next = self.a_t.q.val();
        self.up.size_log2.next = self.a_sh.q.val();
        self.up.linear.next = self.a_linear.q.val();
        // B: the level's first word: base, the two runs of the levels k < min(d, a) (bits
        // S, S - 2, ..., S - 2m + 2; then a + 1 - b down to a + 2 - e), 4 words a 1 x 1 level.
        self.ws_e.next = bit_cast::<E, 4>(self.ws.val());
        self.hs_e.next = bit_cast::<E, 4>(self.hs.val());
        self.d_e.next = bit_cast::<E, 4>(self.a_level.q.val());
        self.side_max.next = self.ws_e.val();
        self.side_min.next = self.hs_e.val();
        if self.hs_e.val() > self.ws_e.val() {
            self.side_max.next = self.hs_e.val();
            self.side_min.next = self.ws_e.val();
        }
        self.side_sum.next = self.ws_e.val() + self.hs_e.val();
        self.m_lv.next = self.d_e.val();
        if self.d_e.val() > self.side_min.val() {
            self.m_lv.next = self.side_min.val();
        }
        self.m_2.next = self.m_lv.val() << 1;
        self.e_lv.next = self.d_e.val();
        if self.d_e.val() > self.side_max.val() {
            self.e_lv.next = self.side_max.val();
        }
        self.runs.next = 0.into();
        for p in 0..ADDR {
            // Bit p is in the first run when S - p is even and below 2m (S - p wraps past
            // 2m for p > S), in the second when b <= a + 1 - p < e (likewise).
            self.from_sum[p].next = self.side_sum.val() - self.pos[p].val();
            self.from_max[p].next = self.side_max.val() + 1 - self.pos[p].val();
            if !self.from_sum[p].val().get_bit(0) & (self.from_sum[p].val() < self.m_2.val()) {
                self.runs.next = self.runs.val() | self.pos_bit[p].val();
            }
            if (self.from_max[p].val() >= self.side_min.val()) & (self.from_max[p].val() < self.e_lv.val()) {
                self.runs.next = self.runs.val() | self.pos_bit[p].val();
            }
        }
        self.ones.next = 0.into();
        if self.d_e.val() > self.side_max.val() {
            self.ones.next = bit_cast::<ADDR, E>(self.d_e.val() - self.side_max.val()) << 2;
        }
        if self.en.val() {
            self.b_valid.d.next = self.a_valid.q.val();
            self.b_second.d.next = self.a_second.q.val();
            self.b_two.d.next = self.a_two.q.val();
            self.b_frac.d.next = self.a_frac.q.val();
            self.b_sw.d.next = self.a_sw.q.val();
            self.b_sh.d.next = self.a_sh.q.val();
            self.b_pw.d.next = self.a_pw.q.val();
            self.b_pwh.d.next = bit_cast::<5, 4>(self.a_pw.q.val()) + bit_cast::<5, 4>(self.a_ph.q.val());
            self.b_i0.d.next = self.across.i0.val();
            self.b_i1.d.next = self.across.i1.val();
            self.b_j0.d.next = self.up.i0.val();
            self.b_j1.d.next = self.up.i1.val();
            self.b_alpha.d.next = self.across.frac.val();
            self.b_beta.d.next = self.up.frac.val();
            self.b_first.d.next = self.base.val() + self.runs.val() + self.ones.val();
        }

        // C: wrap; each bank (j & 1)·2 + (i & 1) reads the texel of those parities (two
        // footprint texels of one parity along an axis are one texel: a 1-wide level, or a
        // clamped or mirrored edge).
        self.wrap[0].i.next = self.b_i0.q.val();
        self.wrap[1].i.next = self.b_i1.q.val();
        self.wrap[2].i.next = self.b_j0.q.val();
        self.wrap[3].i.next = self.b_j1.q.val();
        self.wrap[0].size_log2.next = self.b_sw.q.val();
        self.wrap[1].size_log2.next = self.b_sw.q.val();
        self.wrap[2].size_log2.next = self.b_sh.q.val();
        self.wrap[3].size_log2.next = self.b_sh.q.val();
        self.wrap[0].mode.next = self.wrap_s.val();
        self.wrap[1].mode.next = self.wrap_s.val();
        self.wrap[2].mode.next = self.wrap_t.val();
        self.wrap[3].mode.next = self.wrap_t.val();
        self.i_even.next = self.wrap[1].wrapped.val();
        self.i_odd.next = self.wrap[0].wrapped.val();
        if !self.wrap[0].wrapped.val().get_bit(0) {
            self.i_even.next = self.wrap[0].wrapped.val();
            self.i_odd.next = self.wrap[1].wrapped.val();
        }
        self.j_even.next = self.wrap[3].wrapped.val();
        self.j_odd.next = self.wrap[2].wrapped.val();
        if !self.wrap[2].wrapped.val().get_bit(0) {
            self.j_even.next = self.wrap[2].wrapped.val();
            self.j_odd.next = self.wrap[3].wrapped.val();
        }
        self.has_i_even.next = !self.wrap[0].wrapped.val().get_bit(0) | !self.wrap[1].wrapped.val().get_bit(0);
        self.has_i_odd.next = self.wrap[0].wrapped.val().get_bit(0) | self.wrap[1].wrapped.val().get_bit(0);
        self.has_j_even.next = !self.wrap[2].wrapped.val().get_bit(0) | !self.wrap[3].wrapped.val().get_bit(0);
        self.has_j_odd.next = self.wrap[2].wrapped.val().get_bit(0) | self.wrap[3].wrapped.val().get_bit(0);
        self.word[0].i.next = self.i_even.val();
        self.word[1].i.next = self.i_odd.val();
        self.word[2].i.next = self.i_even.val();
        self.word[3].i.next = self.i_odd.val();
        self.word[0].j.next = self.j_even.val();
        self.word[1].j.next = self.j_even.val();
        self.word[2].j.next = self.j_odd.val();
        self.word[3].j.next = self.j_odd.val();
        self.lane.next = 0.into();
        if self.has_i_even.val() & self.has_j_even.val() {
            self.lane.next = self.lane.val() | self.lane_bit[0].val();
        }
        if self.has_i_odd.val() & self.has_j_even.val() {
            self.lane.next = self.lane.val() | self.lane_bit[1].val();
        }
        if self.has_i_even.val() & self.has_j_odd.val() {
            self.lane.next = self.lane.val() | self.lane_bit[2].val();
        }
        if self.has_i_odd.val() & self.has_j_odd.val() {
            self.lane.next = self.lane.val() | self.lane_bit[3].val();
        }
        for b in 0..4 {
            self.word[b].bank.next = self.bank_id[b].val();
            self.word[b].first.next = self.b_first.q.val();
            self.word[b].pw.next = self.b_pw.q.val();
            self.word[b].pwh.next = self.b_pwh.q.val();
        }
        if self.en.val() {
            self.c_valid.d.next = self.b_valid.q.val();
            self.c_second.d.next = self.b_second.q.val();
            self.c_two.d.next = self.b_two.q.val();
            self.c_frac.d.next = self.b_frac.q.val();
            self.c_alpha.d.next = self.b_alpha.q.val();
            self.c_beta.d.next = self.b_beta.q.val();
            // Each footprint texel's bank: T(i0, j0), T(i1, j0), T(i0, j1), T(i1, j1).
            self.c_banks.d.next = bit_cast::<8, 1>(self.wrap[0].wrapped.val().get_bits::<1>(0))
                | (bit_cast::<8, 1>(self.wrap[2].wrapped.val().get_bits::<1>(0)) << 1)
                | (bit_cast::<8, 1>(self.wrap[1].wrapped.val().get_bits::<1>(0)) << 2)
                | (bit_cast::<8, 1>(self.wrap[2].wrapped.val().get_bits::<1>(0)) << 3)
                | (bit_cast::<8, 1>(self.wrap[0].wrapped.val().get_bits::<1>(0)) << 4)
                | (bit_cast::<8, 1>(self.wrap[3].wrapped.val().get_bits::<1>(0)) << 5)
                | (bit_cast::<8, 1>(self.wrap[1].wrapped.val().get_bits::<1>(0)) << 6)
                | (bit_cast::<8, 1>(self.wrap[3].wrapped.val().get_bits::<1>(0)) << 7);
            self.c_lanes.d.next = self.lane.val();
            for b in 0..4 {
                self.c_addr[b].d.next = 0.into();
                if (self.lane.val() & self.lane_bit[b].val()).any() {
                    self.c_addr[b].d.next = self.word[b].addr.val();
                }
            }
        }
        self.out_valid.next = self.c_valid.q.val();
        self.out_second.next = self.c_second.q.val();
        self.two_levels.next = self.c_two.q.val();
        self.frac.next = self.c_frac.q.val();
        self.alpha.next = self.c_alpha.q.val();
        self.beta.next = self.c_beta.q.val();
        self.lanes.next = self.c_lanes.q.val();
        self.banks.next = self.c_banks.q.val();
        self.addr0.next = self.c_addr[0].q.val();
        self.addr1.next = self.c_addr[1].q.val();
        self.addr2.next = self.c_addr[2].q.val();
        self.addr3.next = self.c_addr[3].q.val();
    }
}

crate::pins!(TextureAddress {
    clock: clock,
    inputs: [en, inp_valid, s, t, lambda, second, ws, hs, levels, base, min_linear, mag_linear, mip, wrap_s, wrap_t],
    outputs: [
        inp_two_levels,
        out_valid,
        out_second,
        lanes,
        addr0,
        addr1,
        addr2,
        addr3,
        banks,
        alpha,
        beta,
        two_levels,
        frac
    ],
});

/// `UNITS` entry: the unit at `fx::TexFormats::DEFAULT`.
pub fn emit_texture_address(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("texture_address", TextureAddress::default(), params))
}
