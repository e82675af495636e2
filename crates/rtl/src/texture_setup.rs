//! `texture_setup`: the planes of s·q, t·q and q over a triangle, and their values at each
//! pixel (paper 001 §II-5: the texture coordinates are interpolated as attributes and divided
//! per pixel by its eq. (3)). Bit-exact to `model::texture_setup` at the size class 10
//! formats (`crate::n10::FORMATS`) and `fx::TexFormats::DEFAULT`: its module doc is the
//! specification.
//!
//! **Per triangle** (`start`, then `done`). The three vertices (`tri$x*`, `tri$y*` raw in
//! `xy`; `tri$sq*`, `tri$tq*` in `st`; `tri$q*` in `q`) and the reciprocal of twice the area,
//! `tri$mant` (`ooa`) and `tri$exp` ([`TexTri`]): `model::divider::reciprocal(|area2|)`, which triangle
//! setup's shared divider already computes for the same triangle (its OneOverArea), so it
//! is an input here, valid with `start`. The unit forms area2 itself, for its sign only.
//! One shared [`Mul`] (48 x 26 bits) does the 20 products in sequence, four steps a
//! gradient:
//!
//! | step | multiplier | accumulator, registers |
//! |---|---|---|
//! | 0, 1 | e1x·e2y, e2x·e1y | |
//! | 1, 2 | | acc = first; acc = acc - second = area2 |
//! | 3 | | neg = area2 < 0 |
//! | 4g, 4g + 1 (g = 1..6) | Cramer's two products of gradient g (d1·e2y, d2·e1y for d/dx; d2·e1x, d1·e2x for d/dy) | |
//! | 4g + 1, 4g + 2 | | acc = first; acc = ±(acc - second): the numerator, negated when area2 < 0 |
//! | 4g + 3 | acc · mant | |
//! | 4g + 4 | | the product rounded half up by 7 + exp bits: the plane gradient (wrapped) and the LOD gradient (rounded, saturated) written |
//!
//! Gradients g = 1..6 are d(s·q)/dx, d(s·q)/dy, d(t·q)/dx, d(t·q)/dy, dq/dx, dq/dy. `done`
//! rises [`SETUP_CYCLES`] cycles after `start` and stays high until the next `start`; the
//! LOD gradients (`dsq_*`, `dtq_*`, `dq_*`: the texture unit's `TexGrad`) are held from
//! then on, and so are the planes, which the pixel part reads. Pixels are valid only while
//! `done` is high: a `start` changes the planes under any pixel in flight, so it waits for
//! the pixel pipeline to drain. The sequence ignores `en`; a `start` while busy restarts it.
//!
//! **Per pixel** (`inp_valid`, `inp_x`, `inp_y` to `out_valid`, `out_sq`, `out_tq`, `out_q`),
//! a pixel a clock, any order, every register held while `en` is low:
//!
//! | stage | |
//! |---|---|
//! | 1 | X = 16 x + 8 - x0, Y likewise: the pixel centre's offsets from vertex 0 in sub-pixels |
//! | 2 | six products gradient · offset, modulo 2^47 (s·q, t·q) or 2^40 (q): 6 [`Mul`]s |
//! | 3 | a0·2^17 + gx·X + gy·Y + 2^16, bits 17 up (rounded half up to F), read with one more integer bit and clamped |
//!
//! Latency [`LATENCY`] enabled cycles. The sums are modulo the plane's wrap, as the model's
//! are, so the value is exact for any pixel (`TexturePlanes::at`).
//!
//! Emitted: `texture_setup` ([`emit_texture_setup`]). Yosys 0.23's `synth_ecp5`: 2878 LUT4,
//! 733 CCU2C, 1428 FF and 24 MULT18X18D (6 for the shared multiplier, 18 for the pixel's
//! six).

use crate::emit::{emit_unit, Emitted};
use crate::mul::Mul;
use crate::parts::{defaults, SignExtend};
use crate::Params;
use blank::Blank;
use fx::{Formats, TexFormats};
use model::texture_setup::{plane_fmt, plane_frac};
use rust_hdl::prelude::*;

const FMT: Formats = crate::n10::FORMATS;
const TF: TexFormats = TexFormats::DEFAULT;
/// Vertex positions (`xy`), and pixel coordinates on screen (x, y < 2^CLASS).
pub const XY: usize = FMT.xy.bits() as usize;
pub const SCREEN: usize = crate::n10::CLASS as usize;
/// s·q and t·q (`st`), q (`q`).
pub const ST: usize = TF.st.bits() as usize;
pub const QB: usize = TF.q.bits() as usize;
/// The LOD gradients: of s·q and t·q (`dst`), of q (`dq`).
pub const DST: usize = TF.dst.bits() as usize;
pub const DQ: usize = TF.dq.bits() as usize;
/// The reciprocal's mantissa (`ooa`) and exponent (the index of |area2|'s top bit).
pub const MANT: usize = FMT.ooa.bits() as usize;
pub const EXP: usize = 6;
/// Input to output of the pixel part, in enabled cycles.
pub const LATENCY: usize = 3;
/// `start` to `done`.
pub const SETUP_CYCLES: usize = 30;

/// An attribute's difference between two vertices.
const D: usize = ST + 1;
/// The shared multiplier's operands: numerators (a difference times an edge, XY + 1 bits,
/// summed) and the mantissa as a signed number.
const MA: usize = D + XY + 2;
const MB: usize = MANT + 1;
const MP: usize = MA + MB;
/// The planes' gradients: S(int + s + 1).P of s·q, t·q and of q.
const GS: usize = plane_fmt(&FMT, TF.st).bits() as usize;
const GQ: usize = plane_fmt(&FMT, TF.q).bits() as usize;
/// A pixel's offset from vertex 0 in sub-pixels.
const OFF: usize = XY + 2;
/// The per-pixel sum's fraction bits beyond F (P + s - F), and the value read above them
/// with one integer bit more than the format.
const RS: usize = (FMT.xy.int + 2 + FMT.xy.frac) as usize;
const WS: usize = ST + 1;
const WQ: usize = QB + 2;
/// The model's shift is -(SH0 + exp): SH0 = F + ooa.frac - s - P.
const SH0: usize = (TF.st.frac + FMT.ooa.frac - FMT.xy.frac - plane_frac(&FMT, TF.st.frac)) as usize;
/// The LOD gradients' rounding shifts from P bits.
const L_ST: usize = (plane_frac(&FMT, TF.st.frac) - TF.dst.frac) as usize;
const L_Q: usize = (plane_frac(&FMT, TF.q.frac) - TF.dq.frac) as usize;
const _: () = assert!(
    SH0 >= 1
        && XY < MB
        && GS == RS + WS
        && GQ == RS + WQ
        && plane_frac(&FMT, TF.q.frac) - TF.q.frac == plane_frac(&FMT, TF.st.frac) - TF.st.frac
        && !TF.q.signed
        && TF.st.signed
        && MP <= 127
        && 2 * XY + 1 < (1 << EXP)
);

fn word<const N: usize>(v: u128) -> Constant<Bits<N>> {
    Constant::new(v.to_bits())
}

fn at(i: usize) -> Constant<Bits<8>> {
    Constant::new(i.to_bits())
}

crate::bundle! {
    /// A triangle as texture setup takes it (`start`): the three vertices (x, y raw in `xy`;
    /// s·q, t·q in `st`; q in `q`) and the reciprocal of twice the area, `mant` (`ooa`) and
    /// `exp` (`model::divider::reciprocal(|area2|)`, which triangle setup's divider has);
    /// `texture_path` takes it with a triangle's first fragment.
    TexTri {
        In x0: Bits<XY>,
        In y0: Bits<XY>,
        In x1: Bits<XY>,
        In y1: Bits<XY>,
        In x2: Bits<XY>,
        In y2: Bits<XY>,
        In sq0: Bits<ST>,
        In sq1: Bits<ST>,
        In sq2: Bits<ST>,
        In tq0: Bits<ST>,
        In tq1: Bits<ST>,
        In tq2: Bits<ST>,
        In q0: Bits<QB>,
        In q1: Bits<QB>,
        In q2: Bits<QB>,
        In mant: Bits<MANT>,
        In exp: Bits<EXP>,
    }
}

/// The texture setup unit: the per-triangle planes and the per-pixel values.
#[derive(LogicBlock, Blank)]
pub struct TextureSetup {
    pub clock: Signal<In, Clock>,
    // Per triangle.
    pub start: Signal<In, Bit>,
    pub tri: TexTri,
    pub done: Signal<Out, Bit>,
    pub dsq_x: Signal<Out, Bits<DST>>,
    pub dsq_y: Signal<Out, Bits<DST>>,
    pub dtq_x: Signal<Out, Bits<DST>>,
    pub dtq_y: Signal<Out, Bits<DST>>,
    pub dq_x: Signal<Out, Bits<DQ>>,
    pub dq_y: Signal<Out, Bits<DQ>>,
    // Per pixel.
    pub en: Signal<In, Bit>,
    pub inp_valid: Signal<In, Bit>,
    pub inp_x: Signal<In, Bits<SCREEN>>,
    pub inp_y: Signal<In, Bits<SCREEN>>,
    pub out_valid: Signal<Out, Bit>,
    pub out_sq: Signal<Out, Bits<ST>>,
    pub out_tq: Signal<Out, Bits<ST>>,
    pub out_q: Signal<Out, Bits<QB>>,

    // The sequence: step, running, finished, area2 < 0.
    step: DFF<Bits<5>>,
    busy: DFF<Bit>,
    done_r: DFF<Bit>,
    neg: DFF<Bit>,
    /// Positions (x0, y0, x1, y1, x2, y2) to MB bits, s·q and t·q (sq0..2, tq0..2) to D.
    sx_pos: [SignExtend<XY, MB>; 6],
    sx_st: [SignExtend<ST, D>; 6],
    /// The edges from vertex 0 (MB bits), e1x and e2x again at MA bits.
    e1x: DFF<Bits<MB>>,
    e1y: DFF<Bits<MB>>,
    e2x: DFF<Bits<MB>>,
    e2y: DFF<Bits<MB>>,
    sx_e1x: SignExtend<MB, MA>,
    sx_e2x: SignExtend<MB, MA>,
    /// Per attribute, its differences from vertex 0: v1 - v0 and v2 - v0.
    d1: [DFF<Bits<D>>; 3],
    d2: [DFF<Bits<D>>; 3],
    /// The difference the step multiplies, to MA bits.
    sel_d: Signal<Local, Bits<D>>,
    sx_d: SignExtend<D, MA>,
    mant: DFF<Bits<MANT>>,
    exp: DFF<Bits<EXP>>,
    mul: Mul<MA, MB, MP>,
    mul_a: Signal<Local, Bits<MA>>,
    mul_b: Signal<Local, Bits<MB>>,
    prod: DFF<Bits<MP>>,
    acc: DFF<Bits<MP>>,
    // The scaled product rounded: shifted by SH0 - 1 + exp (arithmetic), then by 1 half up.
    k1: Signal<Local, Bits<7>>,
    zs: Signal<Local, Bits<MP>>,
    y1: Signal<Local, Bits<MP>>,
    exact: Signal<Local, Bits<MP>>,
    // The LOD gradients: rounded half up to `dst` (`dq`), saturated.
    t_st: Signal<Local, Bits<MP>>,
    u_st: Signal<Local, Bits<MP>>,
    ts_st: Signal<Local, Bits<MP>>,
    l_st: Signal<Local, Bits<DST>>,
    t_q: Signal<Local, Bits<MP>>,
    u_q: Signal<Local, Bits<MP>>,
    ts_q: Signal<Local, Bits<MP>>,
    l_q: Signal<Local, Bits<DQ>>,
    // The planes: origin (sub-pixels), values at vertex 0 (at the sums' widths), gradients
    // [d/dx, d/dy]; the LOD gradients.
    ox: DFF<Bits<OFF>>,
    oy: DFF<Bits<OFF>>,
    a0_sq: DFF<Bits<GS>>,
    a0_tq: DFF<Bits<GS>>,
    a0_q: DFF<Bits<GQ>>,
    g_sq: [DFF<Bits<GS>>; 2],
    g_tq: [DFF<Bits<GS>>; 2],
    g_q: [DFF<Bits<GQ>>; 2],
    lod_sq: [DFF<Bits<DST>>; 2],
    lod_tq: [DFF<Bits<DST>>; 2],
    lod_q: [DFF<Bits<DQ>>; 2],

    // Pixel stage 1: the offsets.
    s1_valid: DFF<Bit>,
    s1_x: DFF<Bits<OFF>>,
    s1_y: DFF<Bits<OFF>>,
    // Stage 2: the products, [x, y] each.
    mul_sq: [Mul<GS, OFF, GS>; 2],
    mul_tq: [Mul<GS, OFF, GS>; 2],
    mul_q: [Mul<GQ, OFF, GQ>; 2],
    s2_valid: DFF<Bit>,
    s2_sq: [DFF<Bits<GS>>; 2],
    s2_tq: [DFF<Bits<GS>>; 2],
    s2_q: [DFF<Bits<GQ>>; 2],
    // Stage 3: the sums, the values read above RS bits, clamped.
    sum_sq: Signal<Local, Bits<GS>>,
    sum_tq: Signal<Local, Bits<GS>>,
    sum_q: Signal<Local, Bits<GQ>>,
    w_sq: Signal<Local, Bits<WS>>,
    w_tq: Signal<Local, Bits<WS>>,
    w_q: Signal<Local, Bits<WQ>>,
    s3_valid: DFF<Bit>,
    s3_sq: DFF<Bits<ST>>,
    s3_tq: DFF<Bits<ST>>,
    s3_q: DFF<Bits<QB>>,

    /// SH0 - 1; the product's sign bit and its weight.
    pre: Constant<Bits<7>>,
    mp_msb: Constant<Bits<8>>,
    mp_top: Constant<Bits<MP>>,
    /// The LOD roundings: half an LSB, the shift, the bias and bound of the range check
    /// (t + 2^(DST - 1 + L) < 2^(DST + L): t >> L fits), the saturated values.
    half_st: Constant<Bits<MP>>,
    sh_st: Constant<Bits<8>>,
    bias_st: Constant<Bits<MP>>,
    lim_st: Constant<Bits<MP>>,
    max_st: Constant<Bits<DST>>,
    min_st: Constant<Bits<DST>>,
    half_q: Constant<Bits<MP>>,
    sh_q: Constant<Bits<8>>,
    bias_q: Constant<Bits<MP>>,
    lim_q: Constant<Bits<MP>>,
    max_q: Constant<Bits<DQ>>,
    min_q: Constant<Bits<DQ>>,
    /// s (the pixel's sub-pixel shift), half a pixel, RS and half an LSB of F at RS.
    sub: Constant<Bits<8>>,
    centre: Constant<Bits<OFF>>,
    rs: Constant<Bits<8>>,
    half_f: Constant<Bits<GS>>,
    /// The read values' sign and top integer bits, and the formats' ends.
    ws_msb: Constant<Bits<8>>,
    ws_top: Constant<Bits<8>>,
    wq_msb: Constant<Bits<8>>,
    wq_top: Constant<Bits<8>>,
    st_max: Constant<Bits<ST>>,
    st_min: Constant<Bits<ST>>,
    q_max: Constant<Bits<QB>>,
}

impl Default for TextureSetup {
    fn default() -> Self {
        let mask = |bits: usize| (1u128 << bits) - 1;
        Self {
            sx_pos: defaults(),
            sx_st: defaults(),
            d1: defaults(),
            d2: defaults(),
            g_sq: defaults(),
            g_tq: defaults(),
            g_q: defaults(),
            lod_sq: defaults(),
            lod_tq: defaults(),
            lod_q: defaults(),
            mul_sq: defaults(),
            mul_tq: defaults(),
            mul_q: defaults(),
            s2_sq: defaults(),
            s2_tq: defaults(),
            s2_q: defaults(),
            pre: word(SH0 as u128 - 1),
            mp_msb: at(MP - 1),
            mp_top: word(1 << (MP - 1)),
            half_st: word(1 << (L_ST - 1)),
            sh_st: at(L_ST),
            bias_st: word(1 << (DST - 1 + L_ST)),
            lim_st: word(1 << (DST + L_ST)),
            max_st: word(mask(DST - 1)),
            min_st: word(1 << (DST - 1)),
            half_q: word(1 << (L_Q - 1)),
            sh_q: at(L_Q),
            bias_q: word(1 << (DQ - 1 + L_Q)),
            lim_q: word(1 << (DQ + L_Q)),
            max_q: word(mask(DQ - 1)),
            min_q: word(1 << (DQ - 1)),
            sub: at(FMT.xy.frac as usize),
            centre: word(1 << (FMT.xy.frac - 1)),
            rs: at(RS),
            half_f: word(1 << (RS - 1)),
            ws_msb: at(WS - 1),
            ws_top: at(WS - 2),
            wq_msb: at(WQ - 1),
            wq_top: at(WQ - 2),
            st_max: word(TF.st.max_raw() as u128),
            st_min: word(TF.st.min_raw() as u128 & mask(ST)),
            q_max: word(TF.q.max_raw() as u128),
            ..Self::blank()
        }
    }
}

impl Logic for TextureSetup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, step, busy, done_r, neg, e1x, e1y, e2x, e2y, mant, exp, prod, acc, ox, oy, a0_sq, a0_tq, a0_q,
            s1_valid, s1_x, s1_y, s2_valid, s3_valid, s3_sq, s3_tq, s3_q
        );
        for i in 0..2 {
            self.g_sq[i].clock.next = self.clock.val();
            self.g_tq[i].clock.next = self.clock.val();
            self.g_q[i].clock.next = self.clock.val();
            self.lod_sq[i].clock.next = self.clock.val();
            self.lod_tq[i].clock.next = self.clock.val();
            self.lod_q[i].clock.next = self.clock.val();
            self.s2_sq[i].clock.next = self.clock.val();
            self.s2_tq[i].clock.next = self.clock.val();
            self.s2_q[i].clock.next = self.clock.val();
            self.g_sq[i].d.next = self.g_sq[i].q.val();
            self.g_tq[i].d.next = self.g_tq[i].q.val();
            self.g_q[i].d.next = self.g_q[i].q.val();
            self.lod_sq[i].d.next = self.lod_sq[i].q.val();
            self.lod_tq[i].d.next = self.lod_tq[i].q.val();
            self.lod_q[i].d.next = self.lod_q[i].q.val();
        }
        for i in 0..3 {
            self.d1[i].clock.next = self.clock.val();
            self.d2[i].clock.next = self.clock.val();
            self.d1[i].d.next = self.d1[i].q.val();
            self.d2[i].d.next = self.d2[i].q.val();
        }

        // ---- Per triangle. The inputs sign-extended.
        self.sx_pos[0].x.next = self.tri.x0.val();
        self.sx_pos[1].x.next = self.tri.y0.val();
        self.sx_pos[2].x.next = self.tri.x1.val();
        self.sx_pos[3].x.next = self.tri.y1.val();
        self.sx_pos[4].x.next = self.tri.x2.val();
        self.sx_pos[5].x.next = self.tri.y2.val();
        self.sx_st[0].x.next = self.tri.sq0.val();
        self.sx_st[1].x.next = self.tri.sq1.val();
        self.sx_st[2].x.next = self.tri.sq2.val();
        self.sx_st[3].x.next = self.tri.tq0.val();
        self.sx_st[4].x.next = self.tri.tq1.val();
        self.sx_st[5].x.next = self.tri.tq2.val();
        self.sx_e1x.x.next = self.e1x.q.val();
        self.sx_e2x.x.next = self.e2x.q.val();

        // The multiplier's operands by step (0 outside the products).
        self.sel_d.next = 0.into();
        self.mul_b.next = 0.into();
        // Gradient 2k + 1 (d/dx) of attribute k at steps 8k + 4, 8k + 5; 2k + 2 (d/dy) at 8k + 8,
        // 8k + 9.
        if self.step.q.val() == 4 {
            self.sel_d.next = self.d1[0].q.val();
            self.mul_b.next = self.e2y.q.val();
        }
        if self.step.q.val() == 5 {
            self.sel_d.next = self.d2[0].q.val();
            self.mul_b.next = self.e1y.q.val();
        }
        if self.step.q.val() == 8 {
            self.sel_d.next = self.d2[0].q.val();
            self.mul_b.next = self.e1x.q.val();
        }
        if self.step.q.val() == 9 {
            self.sel_d.next = self.d1[0].q.val();
            self.mul_b.next = self.e2x.q.val();
        }
        if self.step.q.val() == 12 {
            self.sel_d.next = self.d1[1].q.val();
            self.mul_b.next = self.e2y.q.val();
        }
        if self.step.q.val() == 13 {
            self.sel_d.next = self.d2[1].q.val();
            self.mul_b.next = self.e1y.q.val();
        }
        if self.step.q.val() == 16 {
            self.sel_d.next = self.d2[1].q.val();
            self.mul_b.next = self.e1x.q.val();
        }
        if self.step.q.val() == 17 {
            self.sel_d.next = self.d1[1].q.val();
            self.mul_b.next = self.e2x.q.val();
        }
        if self.step.q.val() == 20 {
            self.sel_d.next = self.d1[2].q.val();
            self.mul_b.next = self.e2y.q.val();
        }
        if self.step.q.val() == 21 {
            self.sel_d.next = self.d2[2].q.val();
            self.mul_b.next = self.e1y.q.val();
        }
        if self.step.q.val() == 24 {
            self.sel_d.next = self.d2[2].q.val();
            self.mul_b.next = self.e1x.q.val();
        }
        if self.step.q.val() == 25 {
            self.sel_d.next = self.d1[2].q.val();
            self.mul_b.next = self.e2x.q.val();
        }
        self.sx_d.x.next = self.sel_d.val();
        self.mul_a.next = self.sx_d.y.val();
        if self.step.q.val() == 0 {
            self.mul_a.next = self.sx_e1x.y.val();
            self.mul_b.next = self.e2y.q.val();
        }
        if self.step.q.val() == 1 {
            self.mul_a.next = self.sx_e2x.y.val();
            self.mul_b.next = self.e1y.q.val();
        }
        if self.step.q.val().get_bits::<2>(0) == 3 {
            self.mul_a.next = bit_cast::<MA, MP>(self.acc.q.val());
            self.mul_b.next = bit_cast::<MB, MANT>(self.mant.q.val());
        }
        self.mul.a.next = self.mul_a.val();
        self.mul.b.next = self.mul_b.val();
        self.prod.d.next = self.mul.p.val();

        // The scaled product, rounded half up by SH0 + exp bits.
        self.k1.next = bit_cast::<7, EXP>(self.exp.q.val()) + self.pre.val();
        self.zs.next = self.prod.q.val() >> self.k1.val();
        if self.prod.q.val().get_bit(self.mp_msb.val().index()) {
            self.zs.next = !((!self.prod.q.val()) >> self.k1.val());
        }
        self.y1.next = self.zs.val() + 1;
        self.exact.next = (self.y1.val() >> 1) | (self.y1.val() & self.mp_top.val());
        // Its LOD gradients, saturated when t >> L leaves the format.
        self.t_st.next = self.exact.val() + self.half_st.val();
        self.u_st.next = self.t_st.val() + self.bias_st.val();
        self.ts_st.next = self.t_st.val() >> self.sh_st.val();
        self.l_st.next = bit_cast::<DST, MP>(self.ts_st.val());
        if self.u_st.val() >= self.lim_st.val() {
            self.l_st.next = self.max_st.val();
            if self.t_st.val().get_bit(self.mp_msb.val().index()) {
                self.l_st.next = self.min_st.val();
            }
        }
        self.t_q.next = self.exact.val() + self.half_q.val();
        self.u_q.next = self.t_q.val() + self.bias_q.val();
        self.ts_q.next = self.t_q.val() >> self.sh_q.val();
        self.l_q.next = bit_cast::<DQ, MP>(self.ts_q.val());
        if self.u_q.val() >= self.lim_q.val() {
            self.l_q.next = self.max_q.val();
            if self.t_q.val().get_bit(self.mp_msb.val().index()) {
                self.l_q.next = self.min_q.val();
            }
        }

        if self.busy.q.val() {
            self.step.d.next = self.step.q.val() + 1;
            if self.step.q.val().get_bits::<2>(0) == 1 {
                self.acc.d.next = self.prod.q.val();
            }
            if self.step.q.val().get_bits::<2>(0) == 2 {
                self.acc.d.next = self.acc.q.val() - self.prod.q.val();
                if self.neg.q.val() {
                    self.acc.d.next = self.prod.q.val() - self.acc.q.val();
                }
            }
            if self.step.q.val() == 3 {
                self.neg.d.next = self.acc.q.val().get_bit(self.mp_msb.val().index());
            }
            if self.step.q.val() == 8 {
                self.g_sq[0].d.next = bit_cast::<GS, MP>(self.exact.val());
                self.lod_sq[0].d.next = self.l_st.val();
            }
            if self.step.q.val() == 12 {
                self.g_sq[1].d.next = bit_cast::<GS, MP>(self.exact.val());
                self.lod_sq[1].d.next = self.l_st.val();
            }
            if self.step.q.val() == 16 {
                self.g_tq[0].d.next = bit_cast::<GS, MP>(self.exact.val());
                self.lod_tq[0].d.next = self.l_st.val();
            }
            if self.step.q.val() == 20 {
                self.g_tq[1].d.next = bit_cast::<GS, MP>(self.exact.val());
                self.lod_tq[1].d.next = self.l_st.val();
            }
            if self.step.q.val() == 24 {
                self.g_q[0].d.next = bit_cast::<GQ, MP>(self.exact.val());
                self.lod_q[0].d.next = self.l_q.val();
            }
            if self.step.q.val() == 28 {
                self.g_q[1].d.next = bit_cast::<GQ, MP>(self.exact.val());
                self.lod_q[1].d.next = self.l_q.val();
            }
            if self.step.q.val() == 28 {
                self.busy.d.next = false;
                self.done_r.d.next = true;
            }
        }
        if self.start.val() {
            self.busy.d.next = true;
            self.done_r.d.next = false;
            self.step.d.next = 0.into();
            self.neg.d.next = false;
            self.e1x.d.next = self.sx_pos[2].y.val() - self.sx_pos[0].y.val();
            self.e1y.d.next = self.sx_pos[3].y.val() - self.sx_pos[1].y.val();
            self.e2x.d.next = self.sx_pos[4].y.val() - self.sx_pos[0].y.val();
            self.e2y.d.next = self.sx_pos[5].y.val() - self.sx_pos[1].y.val();
            self.d1[0].d.next = self.sx_st[1].y.val() - self.sx_st[0].y.val();
            self.d2[0].d.next = self.sx_st[2].y.val() - self.sx_st[0].y.val();
            self.d1[1].d.next = self.sx_st[4].y.val() - self.sx_st[3].y.val();
            self.d2[1].d.next = self.sx_st[5].y.val() - self.sx_st[3].y.val();
            self.d1[2].d.next = bit_cast::<D, QB>(self.tri.q1.val()) - bit_cast::<D, QB>(self.tri.q0.val());
            self.d2[2].d.next = bit_cast::<D, QB>(self.tri.q2.val()) - bit_cast::<D, QB>(self.tri.q0.val());
            self.mant.d.next = self.tri.mant.val();
            self.exp.d.next = self.tri.exp.val();
            self.ox.d.next = bit_cast::<OFF, MB>(self.sx_pos[0].y.val());
            self.oy.d.next = bit_cast::<OFF, MB>(self.sx_pos[1].y.val());
            self.a0_sq.d.next = bit_cast::<GS, D>(self.sx_st[0].y.val()) << self.rs.val();
            self.a0_tq.d.next = bit_cast::<GS, D>(self.sx_st[3].y.val()) << self.rs.val();
            self.a0_q.d.next = bit_cast::<GQ, QB>(self.tri.q0.val()) << self.rs.val();
        }
        self.done.next = self.done_r.q.val();
        self.dsq_x.next = self.lod_sq[0].q.val();
        self.dsq_y.next = self.lod_sq[1].q.val();
        self.dtq_x.next = self.lod_tq[0].q.val();
        self.dtq_y.next = self.lod_tq[1].q.val();
        self.dq_x.next = self.lod_q[0].q.val();
        self.dq_y.next = self.lod_q[1].q.val();

        // ---- Per pixel.
        for i in 0..2 {
            self.mul_sq[i].a.next = self.g_sq[i].q.val();
            self.mul_tq[i].a.next = self.g_tq[i].q.val();
            self.mul_q[i].a.next = self.g_q[i].q.val();
        }
        self.mul_sq[0].b.next = self.s1_x.q.val();
        self.mul_tq[0].b.next = self.s1_x.q.val();
        self.mul_q[0].b.next = self.s1_x.q.val();
        self.mul_sq[1].b.next = self.s1_y.q.val();
        self.mul_tq[1].b.next = self.s1_y.q.val();
        self.mul_q[1].b.next = self.s1_y.q.val();
        self.sum_sq.next = self.a0_sq.q.val() + self.s2_sq[0].q.val() + self.s2_sq[1].q.val() + self.half_f.val();
        self.sum_tq.next = self.a0_tq.q.val() + self.s2_tq[0].q.val() + self.s2_tq[1].q.val() + self.half_f.val();
        self.sum_q.next =
            self.a0_q.q.val() + self.s2_q[0].q.val() + self.s2_q[1].q.val() + bit_cast::<GQ, GS>(self.half_f.val());
        self.w_sq.next = bit_cast::<WS, GS>(self.sum_sq.val() >> self.rs.val());
        self.w_tq.next = bit_cast::<WS, GS>(self.sum_tq.val() >> self.rs.val());
        self.w_q.next = bit_cast::<WQ, GQ>(self.sum_q.val() >> self.rs.val());

        for i in 0..2 {
            self.s2_sq[i].d.next = self.s2_sq[i].q.val();
            self.s2_tq[i].d.next = self.s2_tq[i].q.val();
            self.s2_q[i].d.next = self.s2_q[i].q.val();
        }
        if self.en.val() {
            self.s1_valid.d.next = self.inp_valid.val();
            self.s1_x.d.next =
                (bit_cast::<OFF, SCREEN>(self.inp_x.val()) << self.sub.val()) + self.centre.val() - self.ox.q.val();
            self.s1_y.d.next =
                (bit_cast::<OFF, SCREEN>(self.inp_y.val()) << self.sub.val()) + self.centre.val() - self.oy.q.val();
            self.s2_valid.d.next = self.s1_valid.q.val();
            for i in 0..2 {
                self.s2_sq[i].d.next = self.mul_sq[i].p.val();
                self.s2_tq[i].d.next = self.mul_tq[i].p.val();
                self.s2_q[i].d.next = self.mul_q[i].p.val();
            }
            self.s3_valid.d.next = self.s2_valid.q.val();
            // Read with one integer bit more, then clamped to the format.
            self.s3_sq.d.next = bit_cast::<ST, WS>(self.w_sq.val());
            if !self.w_sq.val().get_bit(self.ws_msb.val().index()) & self.w_sq.val().get_bit(self.ws_top.val().index())
            {
                self.s3_sq.d.next = self.st_max.val();
            }
            if self.w_sq.val().get_bit(self.ws_msb.val().index()) & !self.w_sq.val().get_bit(self.ws_top.val().index())
            {
                self.s3_sq.d.next = self.st_min.val();
            }
            self.s3_tq.d.next = bit_cast::<ST, WS>(self.w_tq.val());
            if !self.w_tq.val().get_bit(self.ws_msb.val().index()) & self.w_tq.val().get_bit(self.ws_top.val().index())
            {
                self.s3_tq.d.next = self.st_max.val();
            }
            if self.w_tq.val().get_bit(self.ws_msb.val().index()) & !self.w_tq.val().get_bit(self.ws_top.val().index())
            {
                self.s3_tq.d.next = self.st_min.val();
            }
            self.s3_q.d.next = bit_cast::<QB, WQ>(self.w_q.val());
            if self.w_q.val().get_bit(self.wq_top.val().index()) {
                self.s3_q.d.next = self.q_max.val();
            }
            if self.w_q.val().get_bit(self.wq_msb.val().index()) {
                self.s3_q.d.next = 0.into();
            }
        }
        self.out_valid.next = self.s3_valid.q.val();
        self.out_sq.next = self.s3_sq.q.val();
        self.out_tq.next = self.s3_tq.q.val();
        self.out_q.next = self.s3_q.q.val();
    }
}

crate::pins!(TextureSetup {
    clock: clock,
    inputs: [start, en, inp_valid, inp_x, inp_y],
    outputs: [done, dsq_x, dsq_y, dtq_x, dtq_y, dq_x, dq_y, out_valid, out_sq, out_tq, out_q],
    links: [tri],
});

/// `UNITS` entry: the unit at the class 10 formats and `fx::TexFormats::DEFAULT`; no
/// parameters.
pub fn emit_texture_setup(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("texture_setup", TextureSetup::default(), params))
}
