//! `texture_coords`: the first stage of paper 001's texture unit (section II-5), one pixel
//! per clock: the perspective division of its eq. (3), s = (s·q) / q and t = (t·q) / q, and
//! the level of detail of its eq. (4), lambda = log2 max(|ds/dx|, |dt/dx|, |ds/dy|,
//! |dt/dy|) in texels, or OpenGL's exact rho (`EXACT = 1`). Bit-exact to
//! `model::texture_coords` at `fx::TexFormats::DEFAULT`.
//!
//! ```text
//!  q ──leading one──> M = q << lz ──> divider: r = floor(2^45 / M)    (DIV_STAGES stages,
//!  s·q, t·q, gradients, ws, hs ──────> delay line ─────────────┐       the shared divider
//!                                                              v       of 001, reused)
//!  B1 the products s·q · r, t·q · r, registered                2 multipliers 29 x 27
//!  B2 s = sat(s·q · r >> (25 - lz)), t likewise
//!  C1 the products s · dq/dx (x4), registered from bit 24 up    4 multipliers 29 x 30
//!  C2 g = d(s·q)/dx - (s · dq/dx) >> 24 (x4), |g| << ws or hs
//!  D  m = max of the four (EXACT = 0: two levels of maxima), or of the two sums of squares
//!     (EXACT = 1: 4 squares)
//!  E1 the leading ones of m and r, the 10 bits below each: indices of two 1024-entry log2
//!     tables (`model::texture_coords::log2_table`)
//!  E2 the tables read: synchronous ROMs (block RAM), addressed by the indices entering E2,
//!     or by E2's own while the pipeline stalls, so that entry and pixel stay together
//!  E3 lambda = round(log2 m + log2 r + (lz - 49) · 2^10, 4 bits); MAGNIFIED for m = 0
//! ```
//!
//! Latency [`LATENCY`] = `DIV_STAGES` + 8 cycles (21); a global enable `en` holds every
//! register (the texture unit stalls on a cache miss). `inp_valid` travels to `out_valid`.
//! Each multiplier of B and C has a register after it (B1, C1): in one stage, a product
//! and what follows it (B's shift and saturation, C's difference, magnitude and shift by
//! the size) were the unit's critical path, and `texture_unit`'s (31.8 ns on ECP5, C).
//!
//! Area and clock (Yosys 0.23 `synth_ecp5`, nextpnr-ecp5 router2 on an LFE5U-25F, 001's
//! rule): 3,141 LUT4, 5,817 FF, 24 MULT18X18D, 2 DP16KD, 48.0 MHz between registers (3,104
//! LUT4, 5,095 FF and 34.7 MHz with 19 stages). The critical path is now E1: m's leading
//! one (a priority chain over `d_m`) and the normalising shift into the table index
//! `e1_idx` (20.8 ns, 11.8 of them routing).
//!
//! Model: `model::texture_unit::TextureUnit::coords`. Emitted: `texture_coords`
//! (`--param EXACT=0|1`).

use crate::divider::Divider;
use crate::emit::{emit_unit, Emitted};
use crate::mul::Mul;
use crate::Params;
use blank::Blank;
use fx::TexFormats;
use model::texture_coords::{log2_table, MAGNIFIED};
use rust_hdl::prelude::*;

const F: TexFormats = TexFormats::DEFAULT;
/// s·q, t·q, s and t (`st`).
pub const ST: usize = F.st.bits() as usize;
/// q (`q`).
pub const QB: usize = F.q.bits() as usize;
/// The gradients of s·q and t·q (`dst`).
pub const DST: usize = F.dst.bits() as usize;
/// The gradients of q (`dq`).
pub const DQ: usize = F.dq.bits() as usize;
/// The level of detail's output width: lambda in `lod_frac` bits, two's complement.
pub const LAMBDA: usize = 32;
const R: usize = F.recip as usize;
/// The reciprocal 2^(recip + QB) / M: its quotient magnitude (recip + 2 bits), signed
/// quotient, dividend and divisor widths.
const DIV_QM: usize = R + 2;
const DIV_Q: usize = R + 3;
const DIV_N: usize = R + QB + 2;
const DIV_D: usize = QB;
/// Divider stages: two restoring steps each.
pub const DIV_STAGES: usize = DIV_QM / 2;
/// Input to output, in enabled cycles.
pub const LATENCY: usize = DIV_STAGES + 8;
/// s·q · r.
const PS: usize = ST + DIV_Q;
/// s · dq/dx, and its shift to `dst`'s fraction bits.
const PG: usize = ST + DQ;
const G_SHIFT: usize = (F.st.frac + F.dq.frac - F.dst.frac) as usize;
/// The product's bits from the shift up, the numerator, and its magnitude.
const PGS: usize = PG - G_SHIFT;
const G: usize = PGS + 1;
const GA: usize = G - 1;
/// |g| in texels of level 0 (shifted by up to 12), and the exact rule's squares and sum.
const U: usize = GA + fx::texture::MAX_SIZE_LOG2 as usize;
const U1: usize = U + 1;
const SQ: usize = 2 * U1;
const M: usize = 2 * U + 1;
/// The log2 tables' index and entry bits; the level of detail's sum (frac + 1 bits).
const T: usize = (F.lod_frac + 4) as usize;
/// The bits of s·q · r from ST - 1 up: all equal when s fits.
const SAT: usize = PS - ST + 1;
const TE: usize = 12;
const SUM: usize = 24;
const _: () = assert!(G_SHIFT < PG && DIV_QM.is_multiple_of(2) && M <= 127 && SQ <= 127);

/// A constant bit index or shift amount (rust-hdl's `hdl_gen` reads a Rust constant in an
/// expression as a Verilog name, so each one used there is a `Constant` field).
fn at(i: usize) -> Constant<Bits<8>> {
    Constant::new(i.to_bits())
}

/// A constant of `N` bits.
fn word<const N: usize>(v: u128) -> Constant<Bits<N>> {
    Constant::new(v.to_bits())
}

/// One numerator of the quotient rule in texels of level 0: |d(x·q) - floor(x · dq >>
/// G_SHIFT)| << size_log2, for x = s or t and d = d/dx or d/dy (`model::texture_coords`'s
/// `numerator`), from the product x · dq's bits from G_SHIFT up (`p`, its top bit the
/// product's sign; the product is stage C1's, registered). Combinational.
#[derive(LogicBlock, Blank)]
pub struct Numerator {
    pub dxq: Signal<In, Bits<DST>>,
    pub p: Signal<In, Bits<PGS>>,
    pub size_log2: Signal<In, Bits<4>>,
    pub u: Signal<Out, Bits<U>>,
    g: Signal<Local, Bits<G>>,
    g_abs: Signal<Local, Bits<GA>>,
    /// The sign bits DST - 1, PGS - 1, G - 1, and the masks that sign-extend the gradient
    /// and the product's slice to G bits.
    dst_msb: Constant<Bits<8>>,
    pgs_msb: Constant<Bits<8>>,
    g_msb: Constant<Bits<8>>,
    ext_dst: Constant<Bits<G>>,
    ext_pgs: Constant<Bits<G>>,
}

impl Default for Numerator {
    fn default() -> Self {
        let mask = |bits: usize| (1u128 << bits) - 1;
        Self {
            dst_msb: at(DST - 1),
            pgs_msb: at(PGS - 1),
            g_msb: at(G - 1),
            ext_dst: word(mask(G) ^ mask(DST)),
            ext_pgs: word(mask(G) ^ mask(PGS)),
            ..Self::blank()
        }
    }
}

impl Logic for Numerator {
    #[hdl_gen]
    fn update(&mut self) {
        // The gradient sign-extended, less the product's slice sign-extended.
        self.g.next = bit_cast::<G, DST>(self.dxq.val()) - bit_cast::<G, PGS>(self.p.val());
        if self.dxq.val().get_bit(self.dst_msb.val().index()) {
            self.g.next = self.g.val() + self.ext_dst.val();
        }
        if self.p.val().get_bit(self.pgs_msb.val().index()) {
            self.g.next = self.g.val() - self.ext_pgs.val();
        }
        self.g_abs.next = self.g.val().get_bits::<GA>(0);
        if self.g.val().get_bit(self.g_msb.val().index()) {
            self.g_abs.next = !self.g_abs.val() + 1;
        }
        self.u.next = bit_cast::<U, GA>(self.g_abs.val()) << bit_cast::<U, 4>(self.size_log2.val());
    }
}

/// The texture coordinates unit; `exact` chooses GL's exact rho over 001's eq. (4).
#[derive(LogicBlock, Blank)]
pub struct TextureCoords {
    pub clock: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    pub inp_valid: Signal<In, Bit>,
    pub inp_sq: Signal<In, Bits<ST>>,
    pub inp_tq: Signal<In, Bits<ST>>,
    pub inp_q: Signal<In, Bits<QB>>,
    pub inp_dsq_x: Signal<In, Bits<DST>>,
    pub inp_dsq_y: Signal<In, Bits<DST>>,
    pub inp_dtq_x: Signal<In, Bits<DST>>,
    pub inp_dtq_y: Signal<In, Bits<DST>>,
    pub inp_dq_x: Signal<In, Bits<DQ>>,
    pub inp_dq_y: Signal<In, Bits<DQ>>,
    /// log2 of the texture's width and height (0 to 12).
    pub inp_ws: Signal<In, Bits<4>>,
    pub inp_hs: Signal<In, Bits<4>>,
    pub out_valid: Signal<Out, Bit>,
    pub out_s: Signal<Out, Bits<ST>>,
    pub out_t: Signal<Out, Bits<ST>>,
    pub out_lambda: Signal<Out, Bits<LAMBDA>>,

    // Normalise q and divide; the rest waits in delay lines.
    qn: Signal<Local, Bits<QB>>,
    lz: Signal<Local, Bits<8>>,
    #[given]
    recip: Divider<DIV_N, DIV_D, { DIV_D + 1 }, DIV_Q, DIV_QM>,
    dl_sq: Vec<DFF<Bits<ST>>>,
    dl_tq: Vec<DFF<Bits<ST>>>,
    dl_dsq_x: Vec<DFF<Bits<DST>>>,
    dl_dsq_y: Vec<DFF<Bits<DST>>>,
    dl_dtq_x: Vec<DFF<Bits<DST>>>,
    dl_dtq_y: Vec<DFF<Bits<DST>>>,
    dl_dq_x: Vec<DFF<Bits<DQ>>>,
    dl_dq_y: Vec<DFF<Bits<DQ>>>,
    dl_lz: Vec<DFF<Bits<8>>>,
    dl_ws: Vec<DFF<Bits<4>>>,
    dl_hs: Vec<DFF<Bits<4>>>,
    // B1: the divide's products s·q · r and t·q · r, and the shift.
    mul_s: Mul<ST, DIV_Q, PS>,
    mul_t: Mul<ST, DIV_Q, PS>,
    sh: Signal<Local, Bits<8>>,
    b1_valid: DFF<Bit>,
    b1_p: [DFF<Bits<PS>>; 2],
    b1_sh: DFF<Bits<8>>,
    b1_dxq: [DFF<Bits<DST>>; 4],
    b1_dq: [DFF<Bits<DQ>>; 2],
    b1_lz: DFF<Bits<8>>,
    b1_ws: DFF<Bits<4>>,
    b1_hs: DFF<Bits<4>>,
    b1_r: DFF<Bits<DIV_Q>>,
    // B2: the products shifted and saturated.
    wide: [Signal<Local, Bits<PS>>; 2],
    st_c: [Signal<Local, Bits<ST>>; 2],
    b_valid: DFF<Bit>,
    b_st: [DFF<Bits<ST>>; 2],
    b_dxq: [DFF<Bits<DST>>; 4],
    b_dq: [DFF<Bits<DQ>>; 2],
    b_lz: DFF<Bits<8>>,
    b_ws: DFF<Bits<4>>,
    b_hs: DFF<Bits<4>>,
    b_r: DFF<Bits<DIV_Q>>,
    // C1: the products s · dq/dx, s · dq/dy, t · dq/dx, t · dq/dy (their bits from G_SHIFT
    // up); C2: the numerators, (s, x), (s, y), (t, x), (t, y).
    mul_g: [Mul<ST, DQ, PG>; 4],
    c1_valid: DFF<Bit>,
    c1_st: [DFF<Bits<ST>>; 2],
    c1_p: [DFF<Bits<PGS>>; 4],
    c1_dxq: [DFF<Bits<DST>>; 4],
    c1_lz: DFF<Bits<8>>,
    c1_ws: DFF<Bits<4>>,
    c1_hs: DFF<Bits<4>>,
    c1_r: DFF<Bits<DIV_Q>>,
    num: [Numerator; 4],
    c_valid: DFF<Bit>,
    c_st: [DFF<Bits<ST>>; 2],
    c_u: [DFF<Bits<U>>; 4],
    c_lz: DFF<Bits<8>>,
    c_r: DFF<Bits<DIV_Q>>,
    // D: the scale factor (squared for the exact rule); 001's as a tree of maxima.
    mul_sq: [Mul<U1, U1, SQ>; 4],
    m_01: Signal<Local, Bits<U>>,
    m_23: Signal<Local, Bits<U>>,
    m_max: Signal<Local, Bits<U>>,
    m_x: Signal<Local, Bits<M>>,
    m_y: Signal<Local, Bits<M>>,
    d_valid: DFF<Bit>,
    d_st: [DFF<Bits<ST>>; 2],
    d_m: DFF<Bits<M>>,
    d_lz: DFF<Bits<8>>,
    d_r: DFF<Bits<DIV_Q>>,
    // E1: the leading ones and the table indices; E2: the tables read (a synchronous ROM
    // each, at the index moving into E2, or E2's own while stalled); E3: lambda.
    p_m: Signal<Local, Bits<8>>,
    p_r: Signal<Local, Bits<8>>,
    norm_m: Signal<Local, Bits<M>>,
    norm_r: Signal<Local, Bits<DIV_Q>>,
    e1_valid: DFF<Bit>,
    e1_zero: DFF<Bit>,
    e1_st: [DFF<Bits<ST>>; 2],
    e1_p: [DFF<Bits<8>>; 2],
    e1_idx: [DFF<Bits<T>>; 2],
    e1_lz: DFF<Bits<8>>,
    e2_valid: DFF<Bit>,
    e2_zero: DFF<Bit>,
    e2_st: [DFF<Bits<ST>>; 2],
    e2_p: [DFF<Bits<8>>; 2],
    e2_idx: [DFF<Bits<T>>; 2],
    e2_lz: DFF<Bits<8>>,
    #[given]
    log_m: SyncROM<Bits<TE>, T>,
    #[given]
    log_r: SyncROM<Bits<TE>, T>,
    sum: Signal<Local, Bits<SUM>>,
    rounded: Signal<Local, Bits<SUM>>,
    lambda24: Signal<Local, Bits<SUM>>,
    e_valid: DFF<Bit>,
    e_st: [DFF<Bits<ST>>; 2],
    e_lambda: DFF<Bits<LAMBDA>>,

    exact: Constant<Bit>,
    /// 2^45, the reciprocal's dividend.
    dividend: Constant<Bits<DIV_N>>,
    /// i, for the leading ones.
    index: Vec<Constant<Bits<8>>>,
    /// Bit positions and shifts: QB - 1, recip + 1, ST - 1, PS - 1, G_SHIFT (the slice of
    /// x · dq), M - 1, the log index slices (M - 1 - T, DIV_Q - 1 - T), DIV_Q - 1, T, T - 1,
    /// SUM - 1.
    qb_top: Constant<Bits<8>>,
    recip_1: Constant<Bits<8>>,
    st_msb: Constant<Bits<8>>,
    ps_msb: Constant<Bits<8>>,
    g_shift: Constant<Bits<8>>,
    m_top: Constant<Bits<8>>,
    m_index: Constant<Bits<8>>,
    r_top: Constant<Bits<8>>,
    r_index: Constant<Bits<8>>,
    t_bits: Constant<Bits<8>>,
    t_less_1: Constant<Bits<8>>,
    sum_msb: Constant<Bits<8>>,
    /// The most negative and positive `st` values, for the divide's saturation.
    st_min: Constant<Bits<ST>>,
    st_max: Constant<Bits<ST>>,
    /// Masks of the sign extensions: PS bits, 24 to 32 bits.
    ones_ps: Constant<Bits<PS>>,
    ones_sum: Constant<Bits<SUM>>,
    ext_lambda: Constant<Bits<LAMBDA>>,
    /// lambda's exponent offset qf - QB - dst.frac - recip (lz is added), in T fraction bits.
    offset: Constant<Bits<SUM>>,
    magnified: Constant<Bits<LAMBDA>>,
}

impl TextureCoords {
    /// The unit, with the exact rule when `exact`.
    pub fn new(exact: bool) -> Self {
        let table = log2_table(&F);
        let rom = || SyncROM::<Bits<TE>, T>::from(table.iter().map(|&v| (v as u64).to_bits::<TE>()));
        let offset = (i64::from(F.q.frac) - QB as i64 - i64::from(F.dst.frac) - R as i64) << T;
        let mask = |bits: usize| (1u128 << bits) - 1;
        Self {
            dl_sq: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_tq: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_dsq_x: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_dsq_y: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_dtq_x: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_dtq_y: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_dq_x: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_dq_y: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_lz: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_ws: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            dl_hs: (0..DIV_STAGES).map(|_| Default::default()).collect(),
            exact: Constant::new(exact),
            dividend: word(1 << (R + QB)),
            index: (0..M).map(at).collect(),
            qb_top: at(QB - 1),
            recip_1: at(R + 1),
            st_msb: at(ST - 1),
            ps_msb: at(PS - 1),
            g_shift: at(G_SHIFT),
            m_top: at(M - 1),
            m_index: at(M - 1 - T),
            r_top: at(DIV_Q - 1),
            r_index: at(DIV_Q - 1 - T),
            t_bits: at(T),
            t_less_1: at(T - 1),
            sum_msb: at(SUM - 1),
            st_min: word(1 << (ST - 1)),
            st_max: word(mask(ST - 1)),
            ones_ps: word(mask(PS)),
            ones_sum: word(mask(SUM)),
            ext_lambda: word(mask(LAMBDA) ^ mask(SUM)),
            offset: word(offset as i128 as u128 & mask(SUM)),
            magnified: word(MAGNIFIED as i128 as u128 & mask(LAMBDA)),
            ..Self::blank(TextureCoordsGiven { recip: Divider::new(DIV_STAGES), log_m: rom(), log_r: rom() })
        }
    }
}

impl Default for TextureCoords {
    fn default() -> Self {
        TextureCoords::new(false)
    }
}

impl Logic for TextureCoords {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, b1_valid, b1_sh, b1_lz, b1_ws, b1_hs, b1_r, b_valid, b_lz, b_ws, b_hs, b_r, c1_valid, c1_lz,
            c1_ws, c1_hs, c1_r, c_valid, c_lz, c_r, d_valid, d_m, d_lz, d_r, e1_valid, e1_zero, e1_lz, e2_valid,
            e2_zero, e2_lz, e_valid, e_lambda
        );
        for k in 0..2 {
            self.b1_p[k].clock.next = self.clock.val();
            self.b1_p[k].d.next = self.b1_p[k].q.val();
            self.b1_dq[k].clock.next = self.clock.val();
            self.b1_dq[k].d.next = self.b1_dq[k].q.val();
            self.c1_st[k].clock.next = self.clock.val();
            self.c1_st[k].d.next = self.c1_st[k].q.val();
            self.b_st[k].clock.next = self.clock.val();
            self.b_st[k].d.next = self.b_st[k].q.val();
            self.b_dq[k].clock.next = self.clock.val();
            self.b_dq[k].d.next = self.b_dq[k].q.val();
            self.c_st[k].clock.next = self.clock.val();
            self.c_st[k].d.next = self.c_st[k].q.val();
            self.d_st[k].clock.next = self.clock.val();
            self.d_st[k].d.next = self.d_st[k].q.val();
            self.e_st[k].clock.next = self.clock.val();
            self.e_st[k].d.next = self.e_st[k].q.val();
            self.e1_st[k].clock.next = self.clock.val();
            self.e1_st[k].d.next = self.e1_st[k].q.val();
            self.e2_st[k].clock.next = self.clock.val();
            self.e2_st[k].d.next = self.e2_st[k].q.val();
            self.e1_p[k].clock.next = self.clock.val();
            self.e1_p[k].d.next = self.e1_p[k].q.val();
            self.e2_p[k].clock.next = self.clock.val();
            self.e2_p[k].d.next = self.e2_p[k].q.val();
            self.e1_idx[k].clock.next = self.clock.val();
            self.e1_idx[k].d.next = self.e1_idx[k].q.val();
            self.e2_idx[k].clock.next = self.clock.val();
            self.e2_idx[k].d.next = self.e2_idx[k].q.val();
        }
        for k in 0..4 {
            self.b1_dxq[k].clock.next = self.clock.val();
            self.b1_dxq[k].d.next = self.b1_dxq[k].q.val();
            self.c1_p[k].clock.next = self.clock.val();
            self.c1_p[k].d.next = self.c1_p[k].q.val();
            self.c1_dxq[k].clock.next = self.clock.val();
            self.c1_dxq[k].d.next = self.c1_dxq[k].q.val();
            self.b_dxq[k].clock.next = self.clock.val();
            self.b_dxq[k].d.next = self.b_dxq[k].q.val();
            self.c_u[k].clock.next = self.clock.val();
            self.c_u[k].d.next = self.c_u[k].q.val();
        }
        for i in 0..DIV_STAGES {
            self.dl_sq[i].clock.next = self.clock.val();
            self.dl_sq[i].d.next = self.dl_sq[i].q.val();
            self.dl_tq[i].clock.next = self.clock.val();
            self.dl_tq[i].d.next = self.dl_tq[i].q.val();
            self.dl_lz[i].clock.next = self.clock.val();
            self.dl_lz[i].d.next = self.dl_lz[i].q.val();
            self.dl_ws[i].clock.next = self.clock.val();
            self.dl_ws[i].d.next = self.dl_ws[i].q.val();
            self.dl_hs[i].clock.next = self.clock.val();
            self.dl_hs[i].d.next = self.dl_hs[i].q.val();
            self.dl_dsq_x[i].clock.next = self.clock.val();
            self.dl_dsq_x[i].d.next = self.dl_dsq_x[i].q.val();
            self.dl_dsq_y[i].clock.next = self.clock.val();
            self.dl_dsq_y[i].d.next = self.dl_dsq_y[i].q.val();
            self.dl_dtq_x[i].clock.next = self.clock.val();
            self.dl_dtq_x[i].d.next = self.dl_dtq_x[i].q.val();
            self.dl_dtq_y[i].clock.next = self.clock.val();
            self.dl_dtq_y[i].d.next = self.dl_dtq_y[i].q.val();
            self.dl_dq_x[i].clock.next = self.clock.val();
            self.dl_dq_x[i].d.next = self.dl_dq_x[i].q.val();
            self.dl_dq_y[i].clock.next = self.clock.val();
            self.dl_dq_y[i].d.next = self.dl_dq_y[i].q.val();
        }

        // Normalise q (0 as 1): its leading one to the top, into the divider.
        self.qn.next = self.inp_q.val();
        if !self.inp_q.val().any() {
            self.qn.next = 1.into();
        }
        self.lz.next = 0.into();
        for i in 0..QB {
            if self.qn.val().get_bit(i) {
                self.lz.next = self.qb_top.val() - self.index[i].val();
            }
        }
        self.recip.clock.next = self.clock.val();
        self.recip.hold.next = !self.en.val();
        self.recip.out_ready.next = true;
        self.recip.inp_valid.next = self.inp_valid.val();
        self.recip.inp_n.next = self.dividend.val();
        self.recip.inp_d.next = self.qn.val() << bit_cast::<QB, 8>(self.lz.val());
        if self.en.val() {
            self.dl_sq[0].d.next = self.inp_sq.val();
            self.dl_tq[0].d.next = self.inp_tq.val();
            self.dl_dsq_x[0].d.next = self.inp_dsq_x.val();
            self.dl_dsq_y[0].d.next = self.inp_dsq_y.val();
            self.dl_dtq_x[0].d.next = self.inp_dtq_x.val();
            self.dl_dtq_y[0].d.next = self.inp_dtq_y.val();
            self.dl_dq_x[0].d.next = self.inp_dq_x.val();
            self.dl_dq_y[0].d.next = self.inp_dq_y.val();
            self.dl_lz[0].d.next = self.lz.val();
            self.dl_ws[0].d.next = self.inp_ws.val();
            self.dl_hs[0].d.next = self.inp_hs.val();
            for i in 1..DIV_STAGES {
                self.dl_sq[i].d.next = self.dl_sq[i - 1].q.val();
                self.dl_tq[i].d.next = self.dl_tq[i - 1].q.val();
                self.dl_lz[i].d.next = self.dl_lz[i - 1].q.val();
                self.dl_ws[i].d.next = self.dl_ws[i - 1].q.val();
                self.dl_hs[i].d.next = self.dl_hs[i - 1].q.val();
                self.dl_dsq_x[i].d.next = self.dl_dsq_x[i - 1].q.val();
                self.dl_dsq_y[i].d.next = self.dl_dsq_y[i - 1].q.val();
                self.dl_dtq_x[i].d.next = self.dl_dtq_x[i - 1].q.val();
                self.dl_dtq_y[i].d.next = self.dl_dtq_y[i - 1].q.val();
                self.dl_dq_x[i].d.next = self.dl_dq_x[i - 1].q.val();
                self.dl_dq_y[i].d.next = self.dl_dq_y[i - 1].q.val();
            }
        }

        // B1: the products s·q · r and t·q · r, and the shift recip + 1 - lz.
        for i in (DIV_STAGES - 1)..DIV_STAGES {
            self.mul_s.a.next = self.dl_sq[i].q.val();
            self.mul_t.a.next = self.dl_tq[i].q.val();
            self.sh.next = self.recip_1.val() - self.dl_lz[i].q.val();
        }
        self.mul_s.b.next = self.recip.out_q.val();
        self.mul_t.b.next = self.recip.out_q.val();
        if self.en.val() {
            self.b1_valid.d.next = self.recip.out_valid.val();
            self.b1_r.d.next = self.recip.out_q.val();
            self.b1_p[0].d.next = self.mul_s.p.val();
            self.b1_p[1].d.next = self.mul_t.p.val();
            self.b1_sh.d.next = self.sh.val();
            for i in (DIV_STAGES - 1)..DIV_STAGES {
                self.b1_dxq[0].d.next = self.dl_dsq_x[i].q.val();
                self.b1_dxq[1].d.next = self.dl_dsq_y[i].q.val();
                self.b1_dxq[2].d.next = self.dl_dtq_x[i].q.val();
                self.b1_dxq[3].d.next = self.dl_dtq_y[i].q.val();
                self.b1_dq[0].d.next = self.dl_dq_x[i].q.val();
                self.b1_dq[1].d.next = self.dl_dq_y[i].q.val();
                self.b1_lz.d.next = self.dl_lz[i].q.val();
                self.b1_ws.d.next = self.dl_ws[i].q.val();
                self.b1_hs.d.next = self.dl_hs[i].q.val();
            }
        }

        // B2: s = sat(product >> sh), likewise t.
        for k in 0..2 {
            self.wide[k].next = self.b1_p[k].q.val() >> self.b1_sh.q.val();
            if self.b1_p[k].q.val().get_bit(self.ps_msb.val().index()) {
                self.wide[k].next =
                    (self.b1_p[k].q.val() >> self.b1_sh.q.val()) | !(self.ones_ps.val() >> self.b1_sh.q.val());
            }
        }
        for k in 0..2 {
            // Fits when its bits from ST - 1 up are all equal.
            self.st_c[k].next = self.wide[k].val().get_bits::<ST>(0);
            if (self.wide[k].val() >> self.st_msb.val()).any()
                & !(self.wide[k].val().get_bits::<SAT>(self.st_msb.val().index()).all())
            {
                self.st_c[k].next = self.st_max.val();
                if self.wide[k].val().get_bit(self.ps_msb.val().index()) {
                    self.st_c[k].next = self.st_min.val();
                }
            }
        }
        if self.en.val() {
            self.b_valid.d.next = self.b1_valid.q.val();
            self.b_r.d.next = self.b1_r.q.val();
            for k in 0..2 {
                self.b_st[k].d.next = self.st_c[k].val();
                self.b_dq[k].d.next = self.b1_dq[k].q.val();
            }
            for k in 0..4 {
                self.b_dxq[k].d.next = self.b1_dxq[k].q.val();
            }
            self.b_lz.d.next = self.b1_lz.q.val();
            self.b_ws.d.next = self.b1_ws.q.val();
            self.b_hs.d.next = self.b1_hs.q.val();
        }

        // C1: x · dq for (s, x), (s, y), (t, x), (t, y), its bits from G_SHIFT up.
        self.mul_g[0].a.next = self.b_st[0].q.val();
        self.mul_g[0].b.next = self.b_dq[0].q.val();
        self.mul_g[1].a.next = self.b_st[0].q.val();
        self.mul_g[1].b.next = self.b_dq[1].q.val();
        self.mul_g[2].a.next = self.b_st[1].q.val();
        self.mul_g[2].b.next = self.b_dq[0].q.val();
        self.mul_g[3].a.next = self.b_st[1].q.val();
        self.mul_g[3].b.next = self.b_dq[1].q.val();
        if self.en.val() {
            self.c1_valid.d.next = self.b_valid.q.val();
            for k in 0..2 {
                self.c1_st[k].d.next = self.b_st[k].q.val();
            }
            for k in 0..4 {
                self.c1_p[k].d.next = self.mul_g[k].p.val().get_bits::<PGS>(self.g_shift.val().index());
                self.c1_dxq[k].d.next = self.b_dxq[k].q.val();
            }
            self.c1_lz.d.next = self.b_lz.q.val();
            self.c1_ws.d.next = self.b_ws.q.val();
            self.c1_hs.d.next = self.b_hs.q.val();
            self.c1_r.d.next = self.b_r.q.val();
        }

        // C2: g = d(x·q) - floor(x · dq >> G_SHIFT); |g| in texels of level 0 (u along s by
        // ws, v along t by hs).
        self.num[0].size_log2.next = self.c1_ws.q.val();
        self.num[1].size_log2.next = self.c1_ws.q.val();
        self.num[2].size_log2.next = self.c1_hs.q.val();
        self.num[3].size_log2.next = self.c1_hs.q.val();
        for k in 0..4 {
            self.num[k].dxq.next = self.c1_dxq[k].q.val();
            self.num[k].p.next = self.c1_p[k].q.val();
        }
        if self.en.val() {
            self.c_valid.d.next = self.c1_valid.q.val();
            for k in 0..2 {
                self.c_st[k].d.next = self.c1_st[k].q.val();
            }
            for k in 0..4 {
                self.c_u[k].d.next = self.num[k].u.val();
            }
            self.c_lz.d.next = self.c1_lz.q.val();
            self.c_r.d.next = self.c1_r.q.val();
        }

        // D: 001's max of the four, or GL's max of |(u, v)_x|² and |(u, v)_y|².
        self.m_01.next = self.c_u[0].q.val();
        if self.c_u[1].q.val() > self.c_u[0].q.val() {
            self.m_01.next = self.c_u[1].q.val();
        }
        self.m_23.next = self.c_u[2].q.val();
        if self.c_u[3].q.val() > self.c_u[2].q.val() {
            self.m_23.next = self.c_u[3].q.val();
        }
        self.m_max.next = self.m_01.val();
        if self.m_23.val() > self.m_01.val() {
            self.m_max.next = self.m_23.val();
        }
        self.mul_sq[0].a.next = bit_cast::<U1, U>(self.c_u[0].q.val());
        self.mul_sq[0].b.next = bit_cast::<U1, U>(self.c_u[0].q.val());
        self.mul_sq[1].a.next = bit_cast::<U1, U>(self.c_u[1].q.val());
        self.mul_sq[1].b.next = bit_cast::<U1, U>(self.c_u[1].q.val());
        self.mul_sq[2].a.next = bit_cast::<U1, U>(self.c_u[2].q.val());
        self.mul_sq[2].b.next = bit_cast::<U1, U>(self.c_u[2].q.val());
        self.mul_sq[3].a.next = bit_cast::<U1, U>(self.c_u[3].q.val());
        self.mul_sq[3].b.next = bit_cast::<U1, U>(self.c_u[3].q.val());
        self.m_x.next = bit_cast::<M, SQ>(self.mul_sq[0].p.val()) + bit_cast::<M, SQ>(self.mul_sq[2].p.val());
        self.m_y.next = bit_cast::<M, SQ>(self.mul_sq[1].p.val()) + bit_cast::<M, SQ>(self.mul_sq[3].p.val());
        if self.en.val() {
            self.d_valid.d.next = self.c_valid.q.val();
            for k in 0..2 {
                self.d_st[k].d.next = self.c_st[k].q.val();
            }
            self.d_m.d.next = bit_cast::<M, U>(self.m_max.val());
            if self.exact.val() {
                self.d_m.d.next = self.m_x.val();
                if self.m_y.val() > self.m_x.val() {
                    self.d_m.d.next = self.m_y.val();
                }
            }
            self.d_lz.d.next = self.c_lz.q.val();
            self.d_r.d.next = self.c_r.q.val();
        }

        // E1: the leading ones of m and r and the table indices: the T bits below them.
        self.p_m.next = 0.into();
        for i in 0..M {
            if self.d_m.q.val().get_bit(i) {
                self.p_m.next = self.index[i].val();
            }
        }
        self.p_r.next = 0.into();
        for i in 0..DIV_Q {
            if self.d_r.q.val().get_bit(i) {
                self.p_r.next = self.index[i].val();
            }
        }
        self.norm_m.next = self.d_m.q.val() << (self.m_top.val() - self.p_m.val());
        self.norm_r.next = self.d_r.q.val() << (self.r_top.val() - self.p_r.val());
        if self.en.val() {
            self.e1_valid.d.next = self.d_valid.q.val();
            self.e1_zero.d.next = !self.d_m.q.val().any();
            self.e1_p[0].d.next = self.p_m.val();
            self.e1_p[1].d.next = self.p_r.val();
            self.e1_idx[0].d.next = self.norm_m.val().get_bits::<T>(self.m_index.val().index());
            self.e1_idx[1].d.next = self.norm_r.val().get_bits::<T>(self.r_index.val().index());
            self.e1_lz.d.next = self.d_lz.q.val();
            self.e2_valid.d.next = self.e1_valid.q.val();
            self.e2_zero.d.next = self.e1_zero.q.val();
            self.e2_lz.d.next = self.e1_lz.q.val();
            for k in 0..2 {
                self.e1_st[k].d.next = self.d_st[k].q.val();
                self.e2_st[k].d.next = self.e1_st[k].q.val();
                self.e2_p[k].d.next = self.e1_p[k].q.val();
                self.e2_idx[k].d.next = self.e1_idx[k].q.val();
            }
        }
        // E2: the tables hold the entries of E2's indices after every edge.
        self.log_m.clock.next = self.clock.val();
        self.log_r.clock.next = self.clock.val();
        self.log_m.address.next = self.e2_idx[0].q.val();
        self.log_r.address.next = self.e2_idx[1].q.val();
        if self.en.val() {
            self.log_m.address.next = self.e1_idx[0].q.val();
            self.log_r.address.next = self.e1_idx[1].q.val();
        }

        // E3: lambda = log2 m (halved for the exact rule) + log2 r + offset + lz, in T
        // fraction bits, rounded half up to lod_frac (T - 4).
        self.sum.next = (bit_cast::<SUM, 8>(self.e2_p[0].q.val()) << self.t_bits.val())
            + (bit_cast::<SUM, TE>(self.log_m.data.val()) << 1);
        if self.exact.val() {
            self.sum.next = (bit_cast::<SUM, 8>(self.e2_p[0].q.val()) << self.t_less_1.val())
                + bit_cast::<SUM, TE>(self.log_m.data.val());
        }
        self.rounded.next = self.sum.val()
            + (bit_cast::<SUM, 8>(self.e2_p[1].q.val()) << self.t_bits.val())
            + (bit_cast::<SUM, TE>(self.log_r.data.val()) << 1)
            + self.offset.val()
            + (bit_cast::<SUM, 8>(self.e2_lz.q.val()) << self.t_bits.val())
            + 8;
        self.lambda24.next = self.rounded.val() >> 4;
        if self.rounded.val().get_bit(self.sum_msb.val().index()) {
            self.lambda24.next = (self.rounded.val() >> 4) | !(self.ones_sum.val() >> 4);
        }
        if self.en.val() {
            self.e_valid.d.next = self.e2_valid.q.val();
            for k in 0..2 {
                self.e_st[k].d.next = self.e2_st[k].q.val();
            }
            self.e_lambda.d.next = bit_cast::<LAMBDA, SUM>(self.lambda24.val());
            if self.lambda24.val().get_bit(self.sum_msb.val().index()) {
                self.e_lambda.d.next = bit_cast::<LAMBDA, SUM>(self.lambda24.val()) | self.ext_lambda.val();
            }
            if self.e2_zero.q.val() {
                self.e_lambda.d.next = self.magnified.val();
            }
        }
        self.out_valid.next = self.e_valid.q.val();
        self.out_s.next = self.e_st[0].q.val();
        self.out_t.next = self.e_st[1].q.val();
        self.out_lambda.next = self.e_lambda.q.val();
    }
}

crate::pins!(TextureCoords {
    clock: clock,
    inputs: [
        en, inp_valid, inp_sq, inp_tq, inp_q, inp_dsq_x, inp_dsq_y, inp_dtq_x, inp_dtq_y, inp_dq_x, inp_dq_y, inp_ws,
        inp_hs
    ],
    outputs: [out_valid, out_s, out_t, out_lambda],
});

/// `UNITS` entry: the unit at `fx::TexFormats::DEFAULT`, `params["EXACT"]` choosing the rule.
pub fn emit_texture_coords(params: &Params) -> Result<Emitted, String> {
    let exact = crate::exact_rule("texture_coords", params)?;
    Ok(emit_unit("texture_coords", TextureCoords::new(exact), params))
}
