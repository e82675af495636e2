//! One lane of `rtl::vector`: the coverage of pixel `idx` of the walker's chunk and its pixel
//! pipeline (paper 004 eq. 3-6), `model::vector::pixel_latency` cycles from the walk cycle to
//! its output registers. The unit's module documentation gives the pipeline's stages.

use super::super::cull_sort::{COLOR, INV_W, Z};
use super::super::divider::{DividerRtl, DIV_D, DIV_N};
use super::super::span::{ColorOf, DepthOf};
use super::super::widths::{CHANNEL, C_ACC, DEPTH, FORMATS, SCREEN, Z_ACC};
use super::{
    LeadingOne, Normalise, Rejects, Rescale, AB_WIDE, BARY, C0L, C0_WIDE, C1, CL, CR, C_WIDE, EFN, IW1, MANT, MANT1,
    PAB, PC, PL, PR, PZ, QR, Q_WIDE, RL, RR, R_WIDE, SUMW, Z0L, Z0_WIDE, Z1, ZL, ZR, Z_WIDE,
};
use crate::mul::PipelinedMul;
use crate::parts::{defaults, DelayLine, SignExtend};
use crate::switch::Switch;
use blank::Blank;
use rust_hdl::prelude::*;

/// The depth's tag through the pipeline: in range, depth.
const DTAG: usize = DEPTH + 1;

/// Lane `idx`: its pixel is the chunk's `idx`-th, x = `x` + `idx`.
#[derive(LogicBlock, Blank)]
pub struct Lane {
    pub clock: Signal<In, Clock>,
    /// The unit runs (no pixel waits on `out`): every register holds while it is low.
    pub run: Signal<In, Bit>,
    /// The walker takes a row: the lane's edge offsets `idx` x `g` are loaded.
    pub load: Signal<In, Bit>,
    /// The scout's per-pixel step of each edge function (dy 2^s), for `load`.
    pub g_0: Signal<In, Bits<EFN>>,
    pub g_1: Signal<In, Bits<EFN>>,
    pub g_2: Signal<In, Bits<EFN>>,
    /// The walker: a chunk (valid), its first x, the box's x extent, each edge function at
    /// its first pixel and whether the edge owns its samples.
    pub valid: Signal<In, Bit>,
    pub x: Signal<In, Bits<SCREEN>>,
    pub x0: Signal<In, Bits<SCREEN>>,
    pub x1: Signal<In, Bits<SCREEN>>,
    pub w_0: Signal<In, Bits<EFN>>,
    pub w_1: Signal<In, Bits<EFN>>,
    pub w_2: Signal<In, Bits<EFN>>,
    pub owns_0: Signal<In, Bit>,
    pub owns_1: Signal<In, Bit>,
    pub owns_2: Signal<In, Bit>,
    /// The triangle's constants at the stages that read them (the unit picks the set).
    pub c_mant: Signal<In, Bits<MANT>>,
    pub c_exp: Signal<In, Bits<8>>,
    pub c_d1z: Signal<In, Bits<Z1>>,
    pub c_d2z: Signal<In, Bits<Z1>>,
    pub c_z0: Signal<In, Bits<Z>>,
    pub c_iw_0: Signal<In, Bits<INV_W>>,
    pub c_iw_1: Signal<In, Bits<INV_W>>,
    pub c_iw_2: Signal<In, Bits<INV_W>>,
    pub c_d1c_0: Signal<In, Bits<C1>>,
    pub c_d1c_1: Signal<In, Bits<C1>>,
    pub c_d1c_2: Signal<In, Bits<C1>>,
    pub c_d2c_0: Signal<In, Bits<C1>>,
    pub c_d2c_1: Signal<In, Bits<C1>>,
    pub c_d2c_2: Signal<In, Bits<C1>>,
    pub c_c0_0: Signal<In, Bits<COLOR>>,
    pub c_c0_1: Signal<In, Bits<COLOR>>,
    pub c_c0_2: Signal<In, Bits<COLOR>>,
    /// The output registers: a pixel inside with its depth in range, its depth and colour.
    pub o_valid: Signal<Out, Bit>,
    pub o_z: Signal<Out, Bits<DEPTH>>,
    /// `{R, G, B}`, R on top.
    pub o_rgb: Signal<Out, Bits<{ 3 * CHANNEL }>>,

    /// The per-edge and per-channel inputs as arrays.
    g: [Signal<Local, Bits<EFN>>; 3],
    w: [Signal<Local, Bits<EFN>>; 3],
    owns: [Signal<Local, Bit>; 3],
    c_iw: [Signal<Local, Bits<INV_W>>; 3],
    c_d1c: [Signal<Local, Bits<C1>>; 3],
    c_d2c: [Signal<Local, Bits<C1>>; 3],
    c_c0: [Signal<Local, Bits<COLOR>>; 3],
    persp: Switch,
    idx: Constant<Bits<SCREEN>>,
    /// `idx`'s bits as masks: all ones where bit b of `idx` is set.
    m1: Constant<Bits<EFN>>,
    m2: Constant<Bits<EFN>>,
    m4: Constant<Bits<EFN>>,
    one_s: Constant<Bits<8>>,
    ch1: Constant<Bits<8>>,
    ch2: Constant<Bits<8>>,
    two_s: Constant<Bits<8>>,
    off: [DFF<Bits<EFN>>; 3],
    e: [Signal<Local, Bits<EFN>>; 3],
    rej: [Rejects; 3],
    px: Signal<Local, Bits<SCREEN>>,
    covered: Signal<Local, Bit>,
    hit: Signal<Local, Bits<1>>,
    #[given]
    hit_dl: DelayLine<1>,

    #[given]
    div: DividerRtl,
    mul_a: PipelinedMul<EFN, MANT1, PAB>,
    mul_b: PipelinedMul<EFN, MANT1, PAB>,
    mul_z1: PipelinedMul<Z1, BARY, PZ>,
    mul_z2: PipelinedMul<Z1, BARY, PZ>,
    mul_l: [PipelinedMul<BARY, IW1, PL>; 3],
    mul_ra: PipelinedMul<BARY, MANT1, PR>,
    mul_rb: PipelinedMul<BARY, MANT1, PR>,
    mul_c1: [PipelinedMul<C1, BARY, PC>; 3],
    mul_c2: [PipelinedMul<C1, BARY, PC>; 3],
    recip_n: Constant<Bits<DIV_N>>,
    norm_s: Normalise<SUMW, { super::max(SUMW, super::max(DIV_D, super::TOP + 1)) }>,
    div_d: DFF<Bits<DIV_D>>,
    #[given]
    rs_a: Rescale<PAB, AB_WIDE, BARY>,
    #[given]
    rs_b: Rescale<PAB, AB_WIDE, BARY>,
    a3: DFF<Bits<BARY>>,
    b3: DFF<Bits<BARY>>,
    one: Constant<Bits<BARY>>,
    #[given]
    rs_z: Rescale<PZ, Z_WIDE, Z_ACC>,
    #[given]
    rs_z0: Rescale<Z1, Z0_WIDE, Z_ACC>,
    ez0: SignExtend<Z, Z1>,
    z6: DFF<Bits<Z_ACC>>,
    depth_of: DepthOf,
    dtag: Signal<Local, Bits<DTAG>>,
    #[given]
    dtag_dl: DelayLine<DTAG>,
    #[given]
    rs_q: [Rescale<PL, Q_WIDE, BARY>; 3],
    q6: [DFF<Bits<BARY>>; 3],
    eq: [SignExtend<BARY, SUMW>; 3],
    sum_c: Signal<Local, Bits<SUMW>>,
    sum7: DFF<Bits<SUMW>>,
    lead_s: LeadingOne<SUMW>,
    sum8: DFF<Bits<SUMW>>,
    exp8: DFF<Bits<8>>,
    q_pair: Signal<Local, Bits<{ 2 * BARY }>>,
    #[given]
    q_dl: DelayLine<{ 2 * BARY }>,
    #[given]
    exp_dl: DelayLine<8>,
    ab_pair: Signal<Local, Bits<{ 2 * BARY }>>,
    #[given]
    ab_dl: DelayLine<{ 2 * BARY }>,
    half_pair: Constant<Bits<8>>,
    #[given]
    rs_ra: Rescale<PR, R_WIDE, BARY>,
    #[given]
    rs_rb: Rescale<PR, R_WIDE, BARY>,
    ca11: DFF<Bits<BARY>>,
    cb11: DFF<Bits<BARY>>,
    ca: Signal<Local, Bits<BARY>>,
    cb: Signal<Local, Bits<BARY>>,
    #[given]
    rs_c: [Rescale<PC, C_WIDE, C_ACC>; 3],
    #[given]
    rs_c0: [Rescale<C1, C0_WIDE, C_ACC>; 3],
    c14: [DFF<Bits<C_ACC>>; 3],
    color_of: [ColorOf; 3],
    full: Constant<Bits<CHANNEL>>,
    ov: DFF<Bit>,
    oz: DFF<Bits<DEPTH>>,
    orgb: [DFF<Bits<CHANNEL>>; 3],
}

impl Lane {
    /// Lane `idx` (0 to 7) with an `l`-stage divider, colours perspective-corrected or not.
    pub fn new(idx: usize, l: usize, perspective: bool) -> Lane {
        assert!(idx < 8, "lane {idx}");
        let pixel = model::vector::pixel_latency(l as u32) as usize;
        let mask = |b: usize| Constant::new(if idx >> b & 1 == 1 { !Bits::<EFN>::default() } else { Bits::default() });
        let given = LaneGiven {
            hit_dl: DelayLine::new(pixel - 1),
            div: DividerRtl::new(l),
            rs_a: Rescale::new(RL, RR),
            rs_b: Rescale::new(RL, RR),
            rs_z: Rescale::new(ZL, ZR),
            rs_z0: Rescale::new(Z0L, 0),
            dtag_dl: DelayLine::new(pixel - 7),
            rs_q: std::array::from_fn(|_| Rescale::new(0, QR)),
            q_dl: DelayLine::new(l + 3),
            exp_dl: DelayLine::new(l + 3),
            ab_dl: DelayLine::new(pixel - 7),
            rs_ra: Rescale::new(RL, RR),
            rs_rb: Rescale::new(RL, RR),
            rs_c: std::array::from_fn(|_| Rescale::new(CL, CR)),
            rs_c0: std::array::from_fn(|_| Rescale::new(C0L, 0)),
        };
        Lane {
            g: defaults(),
            w: defaults(),
            owns: defaults(),
            c_iw: defaults(),
            c_d1c: defaults(),
            c_d2c: defaults(),
            c_c0: defaults(),
            persp: Switch::new(perspective),
            idx: Constant::new(idx.to_bits()),
            m1: mask(0),
            m2: mask(1),
            m4: mask(2),
            one_s: Constant::new(1usize.to_bits()),
            ch1: Constant::new(CHANNEL.to_bits()),
            ch2: Constant::new((2 * CHANNEL).to_bits()),
            two_s: Constant::new(2usize.to_bits()),
            off: defaults(),
            e: defaults(),
            rej: defaults(),
            mul_l: defaults(),
            mul_c1: defaults(),
            mul_c2: defaults(),
            recip_n: Constant::new((1u128 << (super::TOP as u32 + FORMATS.ooa.frac)).to_bits()),
            one: Constant::new((1u64 << FORMATS.bary.frac).to_bits()),
            q6: defaults(),
            eq: defaults(),
            half_pair: Constant::new(BARY.to_bits()),
            c14: defaults(),
            color_of: defaults(),
            full: Constant::new(255usize.to_bits()),
            orgb: defaults(),
            ..Lane::blank(given)
        }
    }
}

impl Logic for Lane {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, div_d, a3, b3, z6, sum7, sum8, exp8, ca11, cb11, ov, oz);
        clock!(self, clock, div, mul_a, mul_b, mul_z1, mul_z2, mul_ra, mul_rb, hit_dl, dtag_dl, q_dl, exp_dl, ab_dl);
        for k in 0..3 {
            self.off[k].clock.next = self.clock.val();
            self.off[k].d.next = self.off[k].q.val();
            self.q6[k].clock.next = self.clock.val();
            self.q6[k].d.next = self.q6[k].q.val();
            self.c14[k].clock.next = self.clock.val();
            self.c14[k].d.next = self.c14[k].q.val();
            self.orgb[k].clock.next = self.clock.val();
            self.orgb[k].d.next = self.orgb[k].q.val();
            self.mul_l[k].clock.next = self.clock.val();
            self.mul_c1[k].clock.next = self.clock.val();
            self.mul_c2[k].clock.next = self.clock.val();
            self.mul_l[k].en.next = self.run.val();
            self.mul_c1[k].en.next = self.run.val();
            self.mul_c2[k].en.next = self.run.val();
        }
        self.mul_a.en.next = self.run.val();
        self.mul_b.en.next = self.run.val();
        self.mul_z1.en.next = self.run.val();
        self.mul_z2.en.next = self.run.val();
        self.mul_ra.en.next = self.run.val();
        self.mul_rb.en.next = self.run.val();
        self.hit_dl.en.next = self.run.val();
        self.dtag_dl.en.next = self.run.val();
        self.q_dl.en.next = self.run.val();
        self.exp_dl.en.next = self.run.val();
        self.ab_dl.en.next = self.run.val();
        self.div.hold.next = !self.run.val();
        self.div.out_ready.next = true;
        self.div.inp_valid.next = true;
        self.div.inp_n.next = self.recip_n.val();

        // The per-edge and per-channel inputs as arrays.
        self.g[0].next = self.g_0.val();
        self.g[1].next = self.g_1.val();
        self.g[2].next = self.g_2.val();
        self.w[0].next = self.w_0.val();
        self.w[1].next = self.w_1.val();
        self.w[2].next = self.w_2.val();
        self.owns[0].next = self.owns_0.val();
        self.owns[1].next = self.owns_1.val();
        self.owns[2].next = self.owns_2.val();
        self.c_iw[0].next = self.c_iw_0.val();
        self.c_iw[1].next = self.c_iw_1.val();
        self.c_iw[2].next = self.c_iw_2.val();
        self.c_d1c[0].next = self.c_d1c_0.val();
        self.c_d1c[1].next = self.c_d1c_1.val();
        self.c_d1c[2].next = self.c_d1c_2.val();
        self.c_d2c[0].next = self.c_d2c_0.val();
        self.c_d2c[1].next = self.c_d2c_1.val();
        self.c_d2c[2].next = self.c_d2c_2.val();
        self.c_c0[0].next = self.c_c0_0.val();
        self.c_c0[1].next = self.c_c0_1.val();
        self.c_c0[2].next = self.c_c0_2.val();
        // ---- The lane's pixel: its edge functions (the chunk's less idx x g), inside the
        // box and the triangle (top-left rule)?
        self.px.next = self.x.val() + self.idx.val();
        self.covered.next = self.valid.val() & (self.px.val() >= self.x0.val()) & (self.px.val() <= self.x1.val());
        for k in 0..3 {
            self.e[k].next = self.w[k].val() - self.off[k].q.val();
            self.rej[k].e.next = self.e[k].val();
            self.rej[k].owns.next = self.owns[k].val();
            if self.rej[k].rejects.val() {
                self.covered.next = false;
            }
        }
        self.hit.next = 0.into();
        if self.covered.val() {
            self.hit.next = 1.into();
        }
        self.hit_dl.d.next = self.hit.val();

        // ---- t+0: a, b's products.
        self.mul_a.a.next = self.e[1].val();
        self.mul_a.b.next = bit_cast::<MANT1, MANT>(self.c_mant.val());
        self.mul_b.a.next = self.e[2].val();
        self.mul_b.b.next = bit_cast::<MANT1, MANT>(self.c_mant.val());
        // t+2: shifted by the area's exponent.
        self.rs_a.x.next = self.mul_a.p.val();
        self.rs_a.by.next = self.c_exp.val();
        self.rs_b.x.next = self.mul_b.p.val();
        self.rs_b.by.next = self.c_exp.val();
        // t+3: depth's and eq. 5's products.
        self.mul_z1.a.next = self.c_d1z.val();
        self.mul_z1.b.next = self.a3.q.val();
        self.mul_z2.a.next = self.c_d2z.val();
        self.mul_z2.b.next = self.b3.q.val();
        self.mul_l[0].a.next = self.one.val() - self.a3.q.val() - self.b3.q.val();
        self.mul_l[0].b.next = bit_cast::<IW1, INV_W>(self.c_iw[0].val());
        self.mul_l[1].a.next = self.a3.q.val();
        self.mul_l[1].b.next = bit_cast::<IW1, INV_W>(self.c_iw[1].val());
        self.mul_l[2].a.next = self.b3.q.val();
        self.mul_l[2].b.next = bit_cast::<IW1, INV_W>(self.c_iw[2].val());
        self.ab_pair.next = (bit_cast::<{ 2 * BARY }, BARY>(self.a3.q.val()) << self.half_pair.val())
            | bit_cast::<{ 2 * BARY }, BARY>(self.b3.q.val());
        self.ab_dl.d.next = self.ab_pair.val();
        // t+5: the depth accumulator; the weights q.
        self.rs_z.x.next = self.mul_z1.p.val() + self.mul_z2.p.val();
        self.rs_z.by.next = 0.into();
        self.ez0.x.next = self.c_z0.val();
        self.rs_z0.x.next = self.ez0.y.val();
        self.rs_z0.by.next = 0.into();
        for k in 0..3 {
            self.rs_q[k].x.next = self.mul_l[k].p.val();
            self.rs_q[k].by.next = 0.into();
            self.eq[k].x.next = self.q6[k].q.val();
        }
        // t+6: the depth, rounded, and whether it lies in [0, z_max]; the weights' sum.
        self.depth_of.x.next = self.z6.q.val();
        self.dtag.next = bit_cast::<DTAG, DEPTH>(self.depth_of.low.val()) << self.one_s.val();
        if !self.depth_of.neg.val() & !self.depth_of.over.val() {
            self.dtag.next = (bit_cast::<DTAG, DEPTH>(self.depth_of.low.val()) << self.one_s.val()) | 1u64;
        }
        self.dtag_dl.d.next = self.dtag.val();
        self.sum_c.next = self.eq[0].y.val() + self.eq[1].y.val() + self.eq[2].y.val();
        if self.sum_c.val() == 0 {
            self.sum_c.next = 1.into();
        }
        self.q_pair.next = (bit_cast::<{ 2 * BARY }, BARY>(self.q6[1].q.val()) << self.half_pair.val())
            | bit_cast::<{ 2 * BARY }, BARY>(self.q6[2].q.val());
        self.q_dl.d.next = self.q_pair.val();
        // t+7: the sum's leading one; t+8: the divisor's register; t+9: the divider.
        self.lead_s.x.next = self.sum7.q.val();
        self.exp_dl.d.next = self.exp8.q.val();
        self.norm_s.x.next = self.sum8.q.val();
        self.norm_s.exp.next = self.exp8.q.val();
        self.div.inp_d.next = self.div_d.q.val();
        // t+9+L: eq. 6's products with 1/sum's mantissa; t+11+L: shifted.
        self.mul_ra.a.next = bit_cast::<BARY, { 2 * BARY }>(self.q_dl.q.val() >> self.half_pair.val());
        self.mul_ra.b.next = bit_cast::<MANT1, MANT>(self.div.out_q.val().get_bits::<MANT>(0));
        self.mul_rb.a.next = bit_cast::<BARY, { 2 * BARY }>(self.q_dl.q.val());
        self.mul_rb.b.next = bit_cast::<MANT1, MANT>(self.div.out_q.val().get_bits::<MANT>(0));
        self.rs_ra.x.next = self.mul_ra.p.val();
        self.rs_ra.by.next = self.exp_dl.q.val();
        self.rs_rb.x.next = self.mul_rb.p.val();
        self.rs_rb.by.next = self.exp_dl.q.val();
        // t+12+L: the colours' weights, corrected or not; their products.
        self.ca.next = bit_cast::<BARY, { 2 * BARY }>(self.ab_dl.q.val() >> self.half_pair.val());
        self.cb.next = bit_cast::<BARY, { 2 * BARY }>(self.ab_dl.q.val());
        if self.persp.on.val() {
            self.ca.next = self.ca11.q.val();
            self.cb.next = self.cb11.q.val();
        }
        self.rs_c0[0].x.next = bit_cast::<C1, COLOR>(self.c_c0[0].val());
        self.rs_c0[1].x.next = bit_cast::<C1, COLOR>(self.c_c0[1].val());
        self.rs_c0[2].x.next = bit_cast::<C1, COLOR>(self.c_c0[2].val());
        for k in 0..3 {
            self.mul_c1[k].a.next = self.c_d1c[k].val();
            self.mul_c2[k].a.next = self.c_d2c[k].val();
            self.mul_c1[k].b.next = self.ca.val();
            self.mul_c2[k].b.next = self.cb.val();
            // t+14+L: each colour accumulator; t+15+L: rounded and clamped.
            self.rs_c[k].x.next = self.mul_c1[k].p.val() + self.mul_c2[k].p.val();
            self.rs_c[k].by.next = 0.into();
            self.rs_c0[k].by.next = 0.into();
            self.color_of[k].x.next = self.c14[k].q.val();
        }

        // ---- Registers, while the unit runs.
        if self.run.val() {
            if self.load.val() {
                for k in 0..3 {
                    self.off[k].d.next = (self.g[k].val() & self.m1.val())
                        + ((self.g[k].val() << self.one_s.val()) & self.m2.val())
                        + ((self.g[k].val() << self.two_s.val()) & self.m4.val());
                }
            }
            self.a3.d.next = self.rs_a.y.val();
            self.b3.d.next = self.rs_b.y.val();
            self.z6.d.next = self.rs_z.y.val() + self.rs_z0.y.val();
            for k in 0..3 {
                self.q6[k].d.next = self.rs_q[k].y.val();
                self.c14[k].d.next = self.rs_c[k].y.val() + self.rs_c0[k].y.val();
                self.orgb[k].d.next = self.color_of[k].low.val();
                if self.color_of[k].over.val() {
                    self.orgb[k].d.next = self.full.val();
                }
                if self.color_of[k].neg.val() {
                    self.orgb[k].d.next = 0.into();
                }
            }
            self.div_d.d.next = self.norm_s.d.val();
            self.sum7.d.next = self.sum_c.val();
            self.sum8.d.next = self.sum7.q.val();
            self.exp8.d.next = self.lead_s.pos.val();
            self.ca11.d.next = self.rs_ra.y.val();
            self.cb11.d.next = self.rs_rb.y.val();
            self.ov.d.next = (self.hit_dl.q.val() != 0) & self.dtag_dl.q.val().get_bit(0);
            self.oz.d.next = bit_cast::<DEPTH, DTAG>(self.dtag_dl.q.val() >> self.one_s.val());
        }
        self.o_valid.next = self.ov.q.val();
        self.o_z.next = self.oz.q.val();
        self.o_rgb.next = (bit_cast::<{ 3 * CHANNEL }, CHANNEL>(self.orgb[0].q.val()) << self.ch2.val())
            | (bit_cast::<{ 3 * CHANNEL }, CHANNEL>(self.orgb[1].q.val()) << self.ch1.val())
            | bit_cast::<{ 3 * CHANNEL }, CHANNEL>(self.orgb[2].q.val());
    }
}
