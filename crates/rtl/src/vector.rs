//! `vector`: per-pixel barycentric rasterization of paper 004 (Lee et al. 2009, eq. 1-6),
//! one pixel per clock, bit-exact and cycle-exact to `model::vector::vector` at `lanes` = 1.
//!
//! It takes a sorted triangle (the link `inp`, `links::SortedSink`, the vertices' `inv_w`
//! included) when its setup is free, walks the triangle's bounding box of pixel centres
//! (clipped to the screen) row by row, and sends each pixel inside whose depth lies in
//! [0, z_max] on the link `out` (`links::PixelSource`, as `span` does to `pixel_out`).
//! Setup works on the next triangle while the walk and the pixel pipeline work on this
//! one.
//!
//! **Setup** (cycle 0 takes the triangle; `model::vector::setup` cycles, 21 with the
//! default divider):
//!
//! ```text
//!  cycle 1      bounding box: min and max of x and y (registers)
//!               area products (v1 - v0) x (v2 - v0), two multipliers
//!  cycle 2      the box to pixel centres, clipped to the screen
//!  cycle 3      empty box?
//!  cycle 3      twice the area (exact)
//!  cycle 4      its sign: v1 and v2 swapped for a negative area (clockwise on screen); |area|
//!  cycle 5      edge deltas of the (swapped) edges v1->v2, v2->v0, v0->v1; attribute
//!               differences v1 - v0, v2 - v0; |area|'s leading one (exp)
//!  cycle 6      1/area's divisor (`model::divider::recip_operands`) into a register; setup's
//!               own divider (LA = `model::vector::area_divider_latency` stages, 13 at the
//!               default L = 25) takes it in cycle 7 and returns it LA later
//!  cycles 6-8   each edge function at the box's first pixel centre: two products
//!  cycle 7+LA   1/area's mantissa; handed to the walk this cycle (or at cycle 11, LA < 4)
//!               or later: when the walk before is in its last pixel or done, and the set
//!               of constants the triangle goes into is free (below); its walk starts the
//!               cycle after, and setup may take the next triangle
//! ```
//!
//! **Walk.** A pixel a cycle; the edge functions step exactly by -2^s dy along a row and
//! 2^s dx down a column, so every pixel's are exact. Coverage: all three positive, or zero
//! on an edge the triangle owns (top-left rule), as the model.
//!
//! **Pixel pipeline** (cycle t: the pixel's edge functions in the walk registers; `L` the
//! divider's stages; `model::vector::pixel_latency` = 16 + L):
//!
//! ```text
//!  t+0..2    a = w1/area, b = w2/area (eq. 3): w x 1/area's mantissa, shifted by exp    (2 multipliers)
//!  t+3..5    z = z0 + (z1 - z0) a + (z2 - z0) b (eq. 4, screen-linear)                  (2)
//!            q_k = l_k iw_k, l = (1 - a - b, a, b) (eq. 5)                              (3)
//!  t+6       depth rounded and tested against [0, z_max]; sum = q0 + q1 + q2
//!  t+7       the sum's leading one
//!  t+8       1/sum's divisor into a register; t+9 into the pixels' divider, back at t+9+L
//!  t+9+L..   a' = q1/sum, b' = q2/sum (eq. 6): q x 1/sum's mantissa, shifted             (2)
//!  t+12+L..  colours c0 + (c1 - c0) a' + (c2 - c0) b' (eq. 4; a, b without
//!            perspective correction), rounded and clamped                                (6)
//!  t+16+L    the pixel on `out`
//! ```
//!
//! The arithmetic is the model's, every wrap a register's width and every floor a bit slice
//! ([`Rescale`]): a and b wrap to `bary`, the depth accumulator to `z_acc`, the colours to
//! `c_acc`; depth and colour round as `span` rounds them (`span::DepthOf`, `span::ColorOf`).
//!
//! **Triangles in flight.** The pipeline's stages read their triangle's constants (1/area's
//! mantissa and exponent at t+0 and t+2; z's and eq. 5's at t+3 and t+5; the colours' at
//! t+12+L and t+14+L) from one of two sets, the pixel's set found in a shift register of
//! the walk's (`ph`): the walk after next may load a set only when the last pixel using it
//! has passed t+14+L (`model::vector::constants_read`). `model::cycles::VectorUnit` is this
//! timing. While a pixel waits on `out` the whole unit waits (`run` low: every register
//! holds, the multipliers' and the dividers' too).
//!
//! **Parameters.** `N`, the size class (widths from `crate::widths`); `L`, the divider's
//! stages; `PERSPECTIVE` (1: colours by eq. 5-6; 0: by a and b, and the synthesis removes
//! eq. 5-6's multipliers and the divider's second use).
//!
//! Model: `model::vector::vector`. Emitted: `hdl-out/vector.v`.

use super::cull_sort::{COLOR, INV_W, XY, Z};
use super::divider::{DividerRtl, DIV_D, DIV_N, LATENCY_MAX};
use super::links::{PixelSource, SortedSink};
use super::span::{ColorOf, DepthOf};
use super::widths::{CHANNEL, C_ACC, DEPTH, DERIVED, DIM, FORMATS, PIXEL, SCREEN, Z_ACC};
use crate::emit::{emit_unit, Emitted};
use crate::mul::PipelinedMul;
use crate::parts::{defaults, DelayLine, Negative, SignExtend};
use crate::switch::Switch;
use crate::Params;
use rust_hdl::prelude::*;

/// A vertex difference and a pixel centre's offset from a vertex: `delta_bits`.
const D1: usize = XY + 1;
/// An edge function at a pixel centre in the box, exact: two `D1` x `D1` products' difference.
const EFN: usize = 2 * D1 + 1;
/// Twice the area, exact, and its magnitude (`area_bits`).
const AREA: usize = DERIVED.area_bits as usize;
/// The reciprocal's normalised divisor has its top bit here (`recip_operands`).
const TOP: usize = DERIVED.area_bits as usize - 2;
/// a, b, their perspective-corrected forms and the weights q (`bary`).
const BARY: usize = FORMATS.bary.bits() as usize;
/// A reciprocal's mantissa (`ooa`), and zero-extended as a signed operand.
const MANT: usize = FORMATS.ooa.bits() as usize;
const MANT1: usize = MANT + 1;
/// The sum of three weights.
const SUMW: usize = BARY + 2;
/// Differences of z and of a colour channel.
const Z1: usize = Z + 1;
const C1: usize = COLOR + 1;
const IW1: usize = INV_W + 1;

/// Products: w x mantissa, z difference x a (two summed), l x iw, q x mantissa, colour
/// difference x a (two summed).
const PAB: usize = EFN + MANT1;
const PZ: usize = Z1 + BARY + 1;
const PL: usize = BARY + IW1;
const PR: usize = BARY + MANT1;
const PC: usize = C1 + BARY + 1;

/// `n` if non-negative, else 0.
const fn pos(n: i64) -> usize {
    if n > 0 {
        n as usize
    } else {
        0
    }
}
const fn max(a: usize, b: usize) -> usize {
    if a > b {
        a
    } else {
        b
    }
}

/// `ratio` (model): the product is in `ooa.frac + exp` fraction bits, `bary` wants
/// `bary.frac`: shifted left by RL, then right by RR + exp.
const RL: usize = pos(FORMATS.bary.frac as i64 - FORMATS.ooa.frac as i64);
const RR: usize = pos(FORMATS.ooa.frac as i64 - FORMATS.bary.frac as i64);
/// The depth's sum of products: from `z.frac + bary.frac` to `z_acc.frac` fraction bits.
const ZL: usize = pos(FORMATS.z_acc.frac as i64 - (FORMATS.z.frac + FORMATS.bary.frac) as i64);
const ZR: usize = pos((FORMATS.z.frac + FORMATS.bary.frac) as i64 - FORMATS.z_acc.frac as i64);
/// z0 into `z_acc` (config: `z_acc.frac > z.frac`).
const Z0L: usize = (FORMATS.z_acc.frac - FORMATS.z.frac) as usize;
/// A colour's sum of products: from `color.frac + bary.frac` to `c_acc.frac`.
const CL: usize = pos(FORMATS.c_acc.frac as i64 - (FORMATS.color.frac + FORMATS.bary.frac) as i64);
const CR: usize = pos((FORMATS.color.frac + FORMATS.bary.frac) as i64 - FORMATS.c_acc.frac as i64);
/// c0 into `c_acc` (config: `c_acc.frac >= color.frac`).
const C0L: usize = (FORMATS.c_acc.frac - FORMATS.color.frac) as usize;
/// l x iw: from `bary.frac + inv_w.frac` to `bary.frac`.
const QR: usize = FORMATS.inv_w.frac as usize;

/// Widths the shifts work in: every bit a slice takes lies below them (a/b's and a'/b''s
/// right shift is at most the divisor's top bit, or the sum's width, plus RR).
const AB_WIDE: usize = max(PAB, TOP + RR + BARY);
const R_WIDE: usize = max(PR, SUMW + RR + BARY);
const Z_WIDE: usize = max(PZ, ZR + Z_ACC);
const C_WIDE: usize = max(PC, CR + C_ACC);
const Q_WIDE: usize = max(PL, QR + BARY);
const Z0_WIDE: usize = max(Z1, Z_ACC);
const C0_WIDE: usize = max(C1, C_ACC);

/// The walk's tag of a pixel: inside, x, y (`{y, x, inside}`); the depth's: in range, depth.
const TAG: usize = 2 * SCREEN + 1;
const DTAG: usize = DEPTH + 1;

/// `y` = the low `OUT` bits of floor(x 2^lsh / 2^(rsh + by)), `x` an `IN`-bit two's
/// complement number: the model's `rescale` (floor) and its wrap into a register, as a bit
/// slice. `WIDE` >= `IN` and >= rsh + max(by) + `OUT`: every bit the slice takes lies
/// below it (bits shifted left past it are above the slice).
#[derive(LogicBlock)]
pub struct Rescale<const IN: usize, const WIDE: usize, const OUT: usize> {
    pub x: Signal<In, Bits<IN>>,
    /// A further right shift (a reciprocal's exponent), 0 for a fixed rescale.
    pub by: Signal<In, Bits<8>>,
    pub y: Signal<Out, Bits<OUT>>,
    lsh: Constant<Bits<8>>,
    rsh: Constant<Bits<8>>,
    msb: Constant<Bits<8>>,
    /// Ones above the low `IN` bits.
    ext: Constant<Bits<WIDE>>,
    wide: Signal<Local, Bits<WIDE>>,
    shifted: Signal<Local, Bits<WIDE>>,
}

impl<const IN: usize, const WIDE: usize, const OUT: usize> Rescale<IN, WIDE, OUT> {
    pub fn new(lsh: usize, rsh: usize) -> Self {
        assert!(WIDE >= IN && WIDE >= OUT + rsh, "Rescale<{IN}, {WIDE}, {OUT}> by {lsh}, {rsh}");
        Rescale {
            x: Default::default(),
            by: Default::default(),
            y: Default::default(),
            lsh: Constant::new(lsh.to_bits()),
            rsh: Constant::new(rsh.to_bits()),
            msb: Constant::new((IN - 1).to_bits()),
            ext: Constant::new(if IN < WIDE { !Bits::<WIDE>::default() << (IN as u64) } else { Bits::default() }),
            wide: Default::default(),
            shifted: Default::default(),
        }
    }
}

impl<const IN: usize, const WIDE: usize, const OUT: usize> Logic for Rescale<IN, WIDE, OUT> {
    #[hdl_gen]
    fn update(&mut self) {
        self.wide.next = bit_cast::<WIDE, IN>(self.x.val());
        if self.x.val().get_bit(self.msb.val().index()) {
            self.wide.next = bit_cast::<WIDE, IN>(self.x.val()) | self.ext.val();
        }
        self.shifted.next = ((self.wide.val() << self.lsh.val()) >> self.rsh.val()) >> self.by.val();
        self.y.next = bit_cast::<OUT, WIDE>(self.shifted.val());
    }
}

/// `pos` = the position of the leading one of `x` (0 for `x` = 0): `127 - leading_zeros`.
#[derive(LogicBlock)]
pub struct LeadingOne<const N: usize> {
    pub x: Signal<In, Bits<N>>,
    pub pos: Signal<Out, Bits<8>>,
    index: Vec<Constant<Bits<8>>>,
}

impl<const N: usize> Default for LeadingOne<N> {
    fn default() -> Self {
        LeadingOne { x: Default::default(), pos: Default::default(), index: (0..N).map(|i| Constant::new(i.to_bits())).collect() }
    }
}

impl<const N: usize> Logic for LeadingOne<N> {
    #[hdl_gen]
    fn update(&mut self) {
        self.pos.next = 0.into();
        for i in 0..N {
            if self.x.val().get_bit(i) {
                self.pos.next = self.index[i].val();
            }
        }
    }
}

/// The divider's divisor for 1/x (`model::divider::recip_operands`): `x` (`N` bits, >= 1)
/// with its leading one `exp` moved to bit `TOP`, its low bits dropped when it is wider.
#[derive(LogicBlock)]
pub struct Normalise<const N: usize, const W: usize> {
    pub x: Signal<In, Bits<N>>,
    pub exp: Signal<In, Bits<8>>,
    pub d: Signal<Out, Bits<DIV_D>>,
    top: Constant<Bits<8>>,
    /// The left shift (exp <= TOP) or the right shift (exp > TOP); the other is 0.
    lsh: Signal<Local, Bits<8>>,
    rsh: Signal<Local, Bits<8>>,
    wide: Signal<Local, Bits<W>>,
}

impl<const N: usize, const W: usize> Default for Normalise<N, W> {
    fn default() -> Self {
        assert!(W >= N && W >= DIV_D && W > TOP, "Normalise<{N}, {W}>");
        Normalise {
            x: Default::default(),
            exp: Default::default(),
            d: Default::default(),
            top: Constant::new(TOP.to_bits()),
            lsh: Default::default(),
            rsh: Default::default(),
            wide: Default::default(),
        }
    }
}

impl<const N: usize, const W: usize> Logic for Normalise<N, W> {
    #[hdl_gen]
    fn update(&mut self) {
        self.lsh.next = self.top.val() - self.exp.val();
        self.rsh.next = 0.into();
        if self.exp.val() > self.top.val() {
            self.lsh.next = 0.into();
            self.rsh.next = self.exp.val() - self.top.val();
        }
        self.wide.next = (bit_cast::<W, N>(self.x.val()) << self.lsh.val()) >> self.rsh.val();
        self.d.next = bit_cast::<DIV_D, W>(self.wide.val());
    }
}

/// The barycentric unit; see the module documentation.
#[derive(LogicBlock)]
pub struct Vector {
    pub clock: Signal<In, Clock>,
    /// Screen size in pixels, 1 to 2^CLASS each; constant during a frame.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// The sorted triangle in (`inp.crosses` is not read), taken when the unit is empty.
    pub inp: SortedSink,
    /// The pixels, each held until `out.ready`.
    pub out: PixelSource,
    /// No triangle in the unit.
    pub idle: Signal<Out, Bit>,

    persp: Switch,
    /// The pixels' divider (1/sum, a division every cycle) and 1/area's, for the triangle
    /// in setup while the one before walks.
    div: DividerRtl,
    div_a: DividerRtl,
    /// Setup's two multipliers: the area, then each edge function at the first pixel.
    mul_s: [PipelinedMul<D1, D1, EFN>; 2],
    mul_a: PipelinedMul<EFN, MANT1, PAB>,
    mul_b: PipelinedMul<EFN, MANT1, PAB>,
    mul_z1: PipelinedMul<Z1, BARY, PZ>,
    mul_z2: PipelinedMul<Z1, BARY, PZ>,
    mul_l: [PipelinedMul<BARY, IW1, PL>; 3],
    mul_ra: PipelinedMul<BARY, MANT1, PR>,
    mul_rb: PipelinedMul<BARY, MANT1, PR>,
    mul_c1: [PipelinedMul<C1, BARY, PC>; 3],
    mul_c2: [PipelinedMul<C1, BARY, PC>; 3],

    // Control.
    /// A triangle is in setup (taken, not yet handed to the walk); the unit runs (no pixel
    /// waits on `out`).
    sbusy: DFF<Bit>,
    run: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    /// Setup's cycle (1 up to `at_walk`, where it waits for the handover; 0: none) and, from
    /// the walk's last cycle, the cycles until its last pixel has left.
    sc: DFF<Bits<8>>,
    dc: DFF<Bits<8>>,
    at_mant: Constant<Bits<8>>,
    at_walk: Constant<Bits<8>>,
    drain: Constant<Bits<8>>,
    /// The walk is in its last pixel or done; the set the next walk loads is free; the
    /// triangle in setup goes to the walk (or, with an empty box, away) this cycle.
    at_last: Signal<Local, Bit>,
    walk_ok: Signal<Local, Bit>,
    set_ok: Signal<Local, Bit>,
    hand: Signal<Local, Bit>,
    /// Per set of constants, the cycles they are still read (`model::vector::constants_read`
    /// from the walk's last cycle, less one).
    hold: [DFF<Bits<8>>; 2],
    held_m1: Constant<Bits<8>>,
    /// The walking triangle's set, and the sets of the pixels behind the walk: bit j that
    /// of the pixel at t+j+1. Taps: the stages that read a constant.
    wp: DFF<Bit>,
    ph: DFF<Bits<64>>,
    tap_exp: Constant<Bits<8>>,
    tap_z: Constant<Bits<8>>,
    tap_z0: Constant<Bits<8>>,
    tap_c: Constant<Bits<8>>,
    tap_c0: Constant<Bits<8>>,

    // The triangle: vertices (swapped for a negative area in cycle 4).
    vx: [DFF<Bits<XY>>; 3],
    vy: [DFF<Bits<XY>>; 3],
    vz: [DFF<Bits<Z>>; 3],
    vc: [DFF<Bits<COLOR>>; 9],
    viw: [DFF<Bits<INV_W>>; 3],
    ex: [SignExtend<XY, D1>; 3],
    ey: [SignExtend<XY, D1>; 3],
    ez: [SignExtend<Z, Z1>; 3],
    /// Sign bits flipped: x and y in unsigned order.
    ux: [Signal<Local, Bits<XY>>; 3],
    uy: [Signal<Local, Bits<XY>>; 3],
    half_xy: Constant<Bits<XY>>,
    min_x: Signal<Local, Bits<XY>>,
    max_x: Signal<Local, Bits<XY>>,
    min_y: Signal<Local, Bits<XY>>,
    max_y: Signal<Local, Bits<XY>>,
    /// The vertices' extremes (sign bits flipped back), registered in cycle 1.
    min_xr: DFF<Bits<XY>>,
    max_xr: DFF<Bits<XY>>,
    min_yr: DFF<Bits<XY>>,
    max_yr: DFF<Bits<XY>>,
    /// The box's corners before clamping: min + (px/2 - 1), max - px/2 (D1 bits).
    lo_x: Signal<Local, Bits<D1>>,
    lo_y: Signal<Local, Bits<D1>>,
    hi_x: Signal<Local, Bits<D1>>,
    hi_y: Signal<Local, Bits<D1>>,
    neg_lo_x: Negative<D1>,
    neg_lo_y: Negative<D1>,
    neg_hi_x: Negative<D1>,
    neg_hi_y: Negative<D1>,
    ext_min_x: SignExtend<XY, D1>,
    ext_min_y: SignExtend<XY, D1>,
    ext_max_x: SignExtend<XY, D1>,
    ext_max_y: SignExtend<XY, D1>,
    px_half_m1: Constant<Bits<D1>>,
    px_half: Constant<Bits<D1>>,
    frac: Constant<Bits<8>>,
    /// The box (pixels, non-negative), whether its bottom or right lies left of or above
    /// the screen, and whether it is empty.
    bx0: DFF<Bits<PIXEL>>,
    bx1: DFF<Bits<PIXEL>>,
    by0: DFF<Bits<PIXEL>>,
    by1: DFF<Bits<PIXEL>>,
    hi_x_c: Signal<Local, Bits<PIXEL>>,
    hi_y_c: Signal<Local, Bits<PIXEL>>,
    bneg: DFF<Bit>,
    empty: DFF<Bit>,
    /// The box's first pixel centre, in `xy` units.
    cx0: Signal<Local, Bits<D1>>,
    cy0: Signal<Local, Bits<D1>>,

    area: DFF<Bits<EFN>>,
    area_neg: Negative<EFN>,
    area_abs: DFF<Bits<AREA>>,
    lead_a: LeadingOne<AREA>,
    exp_a: DFF<Bits<8>>,
    norm_a: Normalise<AREA, { max(AREA, DIV_D) + 1 }>,
    norm_s: Normalise<SUMW, { max(SUMW, max(DIV_D, TOP + 1)) }>,
    recip_n: Constant<Bits<DIV_N>>,
    /// 1/area's mantissa: from its divider in cycle 7 + LA (the handover may come in it),
    /// from `mant` after.
    mant_c: Signal<Local, Bits<MANT>>,
    /// The dividers' divisors, registered: 1/area's in cycle 6, each pixel's 1/sum's.
    div_da: DFF<Bits<DIV_D>>,
    div_d: DFF<Bits<DIV_D>>,
    mant: DFF<Bits<MANT>>,

    /// Per edge (v1->v2, v2->v0, v0->v1): dx, dy; whether it owns its samples; the edge
    /// function at the first pixel, at the row's first pixel and at the walk's pixel.
    dx: [DFF<Bits<D1>>; 3],
    dy: [DFF<Bits<D1>>; 3],
    dx_neg: [Negative<D1>; 3],
    dy_neg: [Negative<D1>; 3],
    owns: [Signal<Local, Bit>; 3],
    edx: [SignExtend<D1, EFN>; 3],
    edy: [SignExtend<D1, EFN>; 3],
    w0: [DFF<Bits<EFN>>; 3],
    wrow: [DFF<Bits<EFN>>; 3],
    w: [DFF<Bits<EFN>>; 3],
    w_neg: [Negative<EFN>; 3],
    covered: Signal<Local, Bit>,
    /// Attribute differences v1 - v0, v2 - v0 (after the swap).
    d1z: DFF<Bits<Z1>>,
    d2z: DFF<Bits<Z1>>,
    d1c: [DFF<Bits<C1>>; 3],
    d2c: [DFF<Bits<C1>>; 3],

    // The walk: its pixel, its box and edges (setup's, handed over).
    tv: DFF<Bit>,
    tx: DFF<Bits<SCREEN>>,
    ty: DFF<Bits<SCREEN>>,
    wx0: DFF<Bits<SCREEN>>,
    wx1: DFF<Bits<SCREEN>>,
    wy1: DFF<Bits<SCREEN>>,
    wdx: [DFF<Bits<D1>>; 3],
    wdy: [DFF<Bits<D1>>; 3],
    /// Two sets of a triangle's constants for the pixels (set s at index s, or 3s + k for
    /// vertex or channel k), and those of the pixel at each stage that reads one.
    k_mant: [DFF<Bits<MANT>>; 2],
    k_exp: [DFF<Bits<8>>; 2],
    k_d1z: [DFF<Bits<Z1>>; 2],
    k_d2z: [DFF<Bits<Z1>>; 2],
    k_z0: [DFF<Bits<Z>>; 2],
    k_iw: [DFF<Bits<INV_W>>; 6],
    k_d1c: [DFF<Bits<C1>>; 6],
    k_d2c: [DFF<Bits<C1>>; 6],
    k_c0: [DFF<Bits<COLOR>>; 6],
    c_mant: Signal<Local, Bits<MANT>>,
    c_exp: Signal<Local, Bits<8>>,
    c_d1z: Signal<Local, Bits<Z1>>,
    c_d2z: Signal<Local, Bits<Z1>>,
    c_z0: Signal<Local, Bits<Z>>,
    ez0: SignExtend<Z, Z1>,
    c_iw: [Signal<Local, Bits<INV_W>>; 3],
    c_d1c: [Signal<Local, Bits<C1>>; 3],
    c_d2c: [Signal<Local, Bits<C1>>; 3],
    c_c0: [Signal<Local, Bits<COLOR>>; 3],
    tag: Signal<Local, Bits<TAG>>,
    tag_dl: DelayLine<TAG>,
    tag_out: Signal<Local, Bits<TAG>>,
    x_shift: Constant<Bits<8>>,
    y_shift: Constant<Bits<8>>,

    // The pixel pipeline.
    rs_a: Rescale<PAB, AB_WIDE, BARY>,
    rs_b: Rescale<PAB, AB_WIDE, BARY>,
    a3: DFF<Bits<BARY>>,
    b3: DFF<Bits<BARY>>,
    one: Constant<Bits<BARY>>,
    rs_z: Rescale<PZ, Z_WIDE, Z_ACC>,
    rs_z0: Rescale<Z1, Z0_WIDE, Z_ACC>,
    z6: DFF<Bits<Z_ACC>>,
    depth_of: DepthOf,
    dtag: Signal<Local, Bits<DTAG>>,
    dtag_dl: DelayLine<DTAG>,
    dtag_out: Signal<Local, Bits<DTAG>>,
    rs_q: [Rescale<PL, Q_WIDE, BARY>; 3],
    q6: [DFF<Bits<BARY>>; 3],
    eq: [SignExtend<BARY, SUMW>; 3],
    sum_c: Signal<Local, Bits<SUMW>>,
    sum7: DFF<Bits<SUMW>>,
    lead_s: LeadingOne<SUMW>,
    sum8: DFF<Bits<SUMW>>,
    exp8: DFF<Bits<8>>,
    q_pair: Signal<Local, Bits<{ 2 * BARY }>>,
    q_dl: DelayLine<{ 2 * BARY }>,
    exp_dl: DelayLine<8>,
    ab_pair: Signal<Local, Bits<{ 2 * BARY }>>,
    ab_dl: DelayLine<{ 2 * BARY }>,
    half_pair: Constant<Bits<8>>,
    rs_ra: Rescale<PR, R_WIDE, BARY>,
    rs_rb: Rescale<PR, R_WIDE, BARY>,
    ca11: DFF<Bits<BARY>>,
    cb11: DFF<Bits<BARY>>,
    ca: Signal<Local, Bits<BARY>>,
    cb: Signal<Local, Bits<BARY>>,
    rs_c: [Rescale<PC, C_WIDE, C_ACC>; 3],
    rs_c0: [Rescale<C1, C0_WIDE, C_ACC>; 3],
    c14: [DFF<Bits<C_ACC>>; 3],
    color_of: [ColorOf; 3],
    full: Constant<Bits<CHANNEL>>,

    // The output register.
    o_valid: DFF<Bit>,
    o_x: DFF<Bits<SCREEN>>,
    o_y: DFF<Bits<SCREEN>>,
    o_z: DFF<Bits<DEPTH>>,
    o_rgb: [DFF<Bits<CHANNEL>>; 3],
}

impl Vector {
    /// The unit with an `l`-stage divider, colours perspective-corrected or not.
    pub fn new(l: usize, perspective: bool) -> Result<Vector, String> {
        if !(1..=LATENCY_MAX).contains(&l) {
            return Err(format!("vector: L = {l} divider stages is not supported: 1 to {LATENCY_MAX}"));
        }
        let (setup, pixel) =
            (model::vector::setup(l as u32) as usize, model::vector::pixel_latency(l as u32) as usize);
        let la = model::vector::area_divider_latency(l as u32) as usize;
        let px = 1usize << FORMATS.xy.frac;
        Ok(Vector {
            clock: Default::default(),
            width: Default::default(),
            height: Default::default(),
            inp: Default::default(),
            out: Default::default(),
            idle: Default::default(),
            persp: Switch::new(perspective),
            div: DividerRtl::new(l),
            div_a: DividerRtl::new(la),
            mul_s: defaults(),
            mul_a: Default::default(),
            mul_b: Default::default(),
            mul_z1: Default::default(),
            mul_z2: Default::default(),
            mul_l: defaults(),
            mul_ra: Default::default(),
            mul_rb: Default::default(),
            mul_c1: defaults(),
            mul_c2: defaults(),
            sbusy: Default::default(),
            run: Default::default(),
            take: Default::default(),
            sc: Default::default(),
            dc: Default::default(),
            at_mant: Constant::new((7 + la).to_bits()),
            at_walk: Constant::new((setup - 1).to_bits()),
            drain: Constant::new(pixel.to_bits()),
            at_last: Default::default(),
            walk_ok: Default::default(),
            set_ok: Default::default(),
            hand: Default::default(),
            hold: defaults(),
            held_m1: Constant::new((model::vector::constants_read(l as u32) as usize - 1).to_bits()),
            wp: Default::default(),
            ph: Default::default(),
            tap_exp: Constant::new(1usize.to_bits()),
            tap_z: Constant::new(2usize.to_bits()),
            tap_z0: Constant::new(4usize.to_bits()),
            tap_c: Constant::new((11 + l).to_bits()),
            tap_c0: Constant::new((13 + l).to_bits()),
            vx: defaults(),
            vy: defaults(),
            vz: defaults(),
            vc: defaults(),
            viw: defaults(),
            ex: defaults(),
            ey: defaults(),
            ez: defaults(),
            ux: defaults(),
            uy: defaults(),
            half_xy: Constant::new((1u64 << (XY - 1)).to_bits()),
            min_x: Default::default(),
            max_x: Default::default(),
            min_y: Default::default(),
            max_y: Default::default(),
            min_xr: Default::default(),
            max_xr: Default::default(),
            min_yr: Default::default(),
            max_yr: Default::default(),
            lo_x: Default::default(),
            lo_y: Default::default(),
            hi_x: Default::default(),
            hi_y: Default::default(),
            neg_lo_x: Default::default(),
            neg_lo_y: Default::default(),
            neg_hi_x: Default::default(),
            neg_hi_y: Default::default(),
            ext_min_x: Default::default(),
            ext_min_y: Default::default(),
            ext_max_x: Default::default(),
            ext_max_y: Default::default(),
            px_half_m1: Constant::new((px / 2 - 1).to_bits()),
            px_half: Constant::new((px / 2).to_bits()),
            frac: Constant::new((FORMATS.xy.frac as usize).to_bits()),
            bx0: Default::default(),
            bx1: Default::default(),
            by0: Default::default(),
            by1: Default::default(),
            hi_x_c: Default::default(),
            hi_y_c: Default::default(),
            bneg: Default::default(),
            empty: Default::default(),
            cx0: Default::default(),
            cy0: Default::default(),
            area: Default::default(),
            area_neg: Default::default(),
            area_abs: Default::default(),
            lead_a: Default::default(),
            exp_a: Default::default(),
            norm_a: Default::default(),
            norm_s: Default::default(),
            recip_n: Constant::new((1u128 << (TOP as u32 + FORMATS.ooa.frac)).to_bits()),
            mant_c: Default::default(),
            div_da: Default::default(),
            div_d: Default::default(),
            mant: Default::default(),
            dx: defaults(),
            dy: defaults(),
            dx_neg: defaults(),
            dy_neg: defaults(),
            owns: defaults(),
            edx: defaults(),
            edy: defaults(),
            w0: defaults(),
            wrow: defaults(),
            w: defaults(),
            w_neg: defaults(),
            covered: Default::default(),
            d1z: Default::default(),
            d2z: Default::default(),
            d1c: defaults(),
            d2c: defaults(),
            tv: Default::default(),
            tx: Default::default(),
            ty: Default::default(),
            wx0: Default::default(),
            wx1: Default::default(),
            wy1: Default::default(),
            wdx: defaults(),
            wdy: defaults(),
            k_mant: defaults(),
            k_exp: defaults(),
            k_d1z: defaults(),
            k_d2z: defaults(),
            k_z0: defaults(),
            k_iw: defaults(),
            k_d1c: defaults(),
            k_d2c: defaults(),
            k_c0: defaults(),
            c_mant: Default::default(),
            c_exp: Default::default(),
            c_d1z: Default::default(),
            c_d2z: Default::default(),
            c_z0: Default::default(),
            ez0: Default::default(),
            c_iw: defaults(),
            c_d1c: defaults(),
            c_d2c: defaults(),
            c_c0: defaults(),
            tag: Default::default(),
            tag_dl: DelayLine::new(pixel - 1),
            tag_out: Default::default(),
            x_shift: Constant::new(1usize.to_bits()),
            y_shift: Constant::new((SCREEN + 1).to_bits()),
            rs_a: Rescale::new(RL, RR),
            rs_b: Rescale::new(RL, RR),
            a3: Default::default(),
            b3: Default::default(),
            one: Constant::new((1u64 << FORMATS.bary.frac).to_bits()),
            rs_z: Rescale::new(ZL, ZR),
            rs_z0: Rescale::new(Z0L, 0),
            z6: Default::default(),
            depth_of: Default::default(),
            dtag: Default::default(),
            dtag_dl: DelayLine::new(pixel - 7),
            dtag_out: Default::default(),
            rs_q: std::array::from_fn(|_| Rescale::new(0, QR)),
            q6: defaults(),
            eq: defaults(),
            sum_c: Default::default(),
            sum7: Default::default(),
            lead_s: Default::default(),
            sum8: Default::default(),
            exp8: Default::default(),
            q_pair: Default::default(),
            q_dl: DelayLine::new(l + 3),
            exp_dl: DelayLine::new(l + 3),
            ab_pair: Default::default(),
            ab_dl: DelayLine::new(pixel - 7),
            half_pair: Constant::new(BARY.to_bits()),
            rs_ra: Rescale::new(RL, RR),
            rs_rb: Rescale::new(RL, RR),
            ca11: Default::default(),
            cb11: Default::default(),
            ca: Default::default(),
            cb: Default::default(),
            rs_c: std::array::from_fn(|_| Rescale::new(CL, CR)),
            rs_c0: std::array::from_fn(|_| Rescale::new(C0L, 0)),
            c14: defaults(),
            color_of: defaults(),
            full: Constant::new(255usize.to_bits()),
            o_valid: Default::default(),
            o_x: Default::default(),
            o_y: Default::default(),
            o_z: Default::default(),
            o_rgb: defaults(),
        })
    }
}

/// The default unit (`UNITS`): the default divider, perspective-correct colours.
impl Default for Vector {
    fn default() -> Self {
        Vector::new(crate::L.default as usize, true).expect("the default L is supported")
    }
}

impl Logic for Vector {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- Clocks; every register holds unless written, and is written only while the
        // unit runs.
        dff_setup!(self, clock, sbusy, sc, dc, bx0, bx1, by0, by1, bneg, empty, area, area_abs, exp_a, div_da, div_d, mant);
        dff_setup!(self, clock, wp, ph, wx0, wx1, wy1);
        dff_setup!(self, clock, d1z, d2z, tv, tx, ty, a3, b3, z6, sum7, sum8, exp8, ca11, cb11);
        dff_setup!(self, clock, min_xr, max_xr, min_yr, max_yr);
        dff_setup!(self, clock, o_valid, o_x, o_y, o_z);
        clock!(self, clock, div, div_a, mul_a, mul_b, mul_z1, mul_z2, mul_ra, mul_rb, tag_dl, dtag_dl, q_dl, exp_dl, ab_dl);
        for k in 0..3 {
            self.vx[k].clock.next = self.clock.val();
            self.vx[k].d.next = self.vx[k].q.val();
            self.vy[k].clock.next = self.clock.val();
            self.vy[k].d.next = self.vy[k].q.val();
            self.vz[k].clock.next = self.clock.val();
            self.vz[k].d.next = self.vz[k].q.val();
            self.viw[k].clock.next = self.clock.val();
            self.viw[k].d.next = self.viw[k].q.val();
            self.dx[k].clock.next = self.clock.val();
            self.dx[k].d.next = self.dx[k].q.val();
            self.dy[k].clock.next = self.clock.val();
            self.dy[k].d.next = self.dy[k].q.val();
            self.w0[k].clock.next = self.clock.val();
            self.w0[k].d.next = self.w0[k].q.val();
            self.wrow[k].clock.next = self.clock.val();
            self.wrow[k].d.next = self.wrow[k].q.val();
            self.w[k].clock.next = self.clock.val();
            self.w[k].d.next = self.w[k].q.val();
            self.d1c[k].clock.next = self.clock.val();
            self.d1c[k].d.next = self.d1c[k].q.val();
            self.d2c[k].clock.next = self.clock.val();
            self.d2c[k].d.next = self.d2c[k].q.val();
            self.q6[k].clock.next = self.clock.val();
            self.q6[k].d.next = self.q6[k].q.val();
            self.c14[k].clock.next = self.clock.val();
            self.c14[k].d.next = self.c14[k].q.val();
            self.o_rgb[k].clock.next = self.clock.val();
            self.o_rgb[k].d.next = self.o_rgb[k].q.val();
            self.mul_l[k].clock.next = self.clock.val();
            self.mul_c1[k].clock.next = self.clock.val();
            self.mul_c2[k].clock.next = self.clock.val();
            self.wdx[k].clock.next = self.clock.val();
            self.wdx[k].d.next = self.wdx[k].q.val();
            self.wdy[k].clock.next = self.clock.val();
            self.wdy[k].d.next = self.wdy[k].q.val();
        }
        for k in 0..6 {
            self.k_iw[k].clock.next = self.clock.val();
            self.k_iw[k].d.next = self.k_iw[k].q.val();
            self.k_d1c[k].clock.next = self.clock.val();
            self.k_d1c[k].d.next = self.k_d1c[k].q.val();
            self.k_d2c[k].clock.next = self.clock.val();
            self.k_d2c[k].d.next = self.k_d2c[k].q.val();
            self.k_c0[k].clock.next = self.clock.val();
            self.k_c0[k].d.next = self.k_c0[k].q.val();
        }
        for k in 0..9 {
            self.vc[k].clock.next = self.clock.val();
            self.vc[k].d.next = self.vc[k].q.val();
        }
        for k in 0..2 {
            self.mul_s[k].clock.next = self.clock.val();
            self.hold[k].clock.next = self.clock.val();
            self.hold[k].d.next = self.hold[k].q.val();
            self.k_mant[k].clock.next = self.clock.val();
            self.k_mant[k].d.next = self.k_mant[k].q.val();
            self.k_exp[k].clock.next = self.clock.val();
            self.k_exp[k].d.next = self.k_exp[k].q.val();
            self.k_d1z[k].clock.next = self.clock.val();
            self.k_d1z[k].d.next = self.k_d1z[k].q.val();
            self.k_d2z[k].clock.next = self.clock.val();
            self.k_d2z[k].d.next = self.k_d2z[k].q.val();
            self.k_z0[k].clock.next = self.clock.val();
            self.k_z0[k].d.next = self.k_z0[k].q.val();
        }

        // ---- Control: the unit runs unless a pixel waits on `out`. Setup takes a triangle
        // when it holds none and the unit runs, and hands it to the walk in its last cycle
        // (`at_walk`) or later: when the walk is in its last pixel or done and the set of
        // constants the walk loads (the other than the walking triangle's) is read no more;
        // an empty box at once.
        self.run.next = !(self.o_valid.q.val() & !self.out.ready.val());
        self.inp.ready.next = !self.sbusy.q.val() & self.run.val();
        self.take.next = self.inp.valid.val() & self.inp.ready.val();
        self.idle.next = !self.sbusy.q.val() & !self.tv.q.val() & (self.dc.q.val() == 0);
        self.at_last.next = (self.tx.q.val() == self.wx1.q.val()) & (self.ty.q.val() == self.wy1.q.val());
        self.walk_ok.next = !self.tv.q.val() | self.at_last.val();
        self.set_ok.next = self.hold[1].q.val() == 0;
        if self.wp.q.val() {
            self.set_ok.next = self.hold[0].q.val() == 0;
        }
        self.hand.next = self.sbusy.q.val()
            & (self.sc.q.val() == self.at_walk.val())
            & (self.empty.q.val() | (self.walk_ok.val() & self.set_ok.val()));
        self.div.hold.next = !self.run.val();
        self.div.out_ready.next = true;
        self.div.inp_valid.next = true;
        self.div.inp_n.next = self.recip_n.val();
        self.div_a.hold.next = !self.run.val();
        self.div_a.out_ready.next = true;
        self.div_a.inp_valid.next = true;
        self.div_a.inp_n.next = self.recip_n.val();
        self.div_a.inp_d.next = self.div_da.q.val();
        self.mant_c.next = self.mant.q.val();
        if self.sc.q.val() == self.at_mant.val() {
            self.mant_c.next = self.div_a.out_q.val().get_bits::<MANT>(0);
        }
        self.mul_a.en.next = self.run.val();
        self.mul_b.en.next = self.run.val();
        self.mul_z1.en.next = self.run.val();
        self.mul_z2.en.next = self.run.val();
        self.mul_ra.en.next = self.run.val();
        self.mul_rb.en.next = self.run.val();
        self.tag_dl.en.next = self.run.val();
        self.dtag_dl.en.next = self.run.val();
        self.q_dl.en.next = self.run.val();
        self.exp_dl.en.next = self.run.val();
        self.ab_dl.en.next = self.run.val();
        for k in 0..3 {
            self.mul_l[k].en.next = self.run.val();
            self.mul_c1[k].en.next = self.run.val();
            self.mul_c2[k].en.next = self.run.val();
        }
        for k in 0..2 {
            self.mul_s[k].en.next = self.run.val();
        }

        // ---- The triangle's geometry, combinationally from its registers.
        for k in 0..3 {
            self.ex[k].x.next = self.vx[k].q.val();
            self.ey[k].x.next = self.vy[k].q.val();
            self.ez[k].x.next = self.vz[k].q.val();
            self.ux[k].next = self.vx[k].q.val() ^ self.half_xy.val();
            self.uy[k].next = self.vy[k].q.val() ^ self.half_xy.val();
            self.dx_neg[k].x.next = self.wdx[k].q.val();
            self.dy_neg[k].x.next = self.wdy[k].q.val();
            // Top edges run in +x, left edges in -y (clockwise on screen, y down).
            self.owns[k].next = self.dy_neg[k].neg.val()
                | ((self.wdy[k].q.val() == 0) & !self.dx_neg[k].neg.val() & (self.wdx[k].q.val() != 0));
            self.edx[k].x.next = self.wdx[k].q.val();
            self.edy[k].x.next = self.wdy[k].q.val();
        }
        // The bounding box of the vertices, in unsigned order, then of pixel centres.
        self.min_x.next = self.ux[0].val();
        self.max_x.next = self.ux[0].val();
        self.min_y.next = self.uy[0].val();
        self.max_y.next = self.uy[0].val();
        for k in 1..3 {
            if self.ux[k].val() < self.min_x.val() {
                self.min_x.next = self.ux[k].val();
            }
            if self.ux[k].val() > self.max_x.val() {
                self.max_x.next = self.ux[k].val();
            }
            if self.uy[k].val() < self.min_y.val() {
                self.min_y.next = self.uy[k].val();
            }
            if self.uy[k].val() > self.max_y.val() {
                self.max_y.next = self.uy[k].val();
            }
        }
        self.ext_min_x.x.next = self.min_xr.q.val();
        self.ext_max_x.x.next = self.max_xr.q.val();
        self.ext_min_y.x.next = self.min_yr.q.val();
        self.ext_max_y.x.next = self.max_yr.q.val();
        self.lo_x.next = self.ext_min_x.y.val() + self.px_half_m1.val();
        self.lo_y.next = self.ext_min_y.y.val() + self.px_half_m1.val();
        self.hi_x.next = self.ext_max_x.y.val() - self.px_half.val();
        self.hi_y.next = self.ext_max_y.y.val() - self.px_half.val();
        self.neg_lo_x.x.next = self.lo_x.val();
        self.neg_lo_y.x.next = self.lo_y.val();
        self.neg_hi_x.x.next = self.hi_x.val();
        self.neg_hi_y.x.next = self.hi_y.val();
        self.hi_x_c.next = bit_cast::<PIXEL, D1>(self.hi_x.val() >> self.frac.val());
        if self.hi_x_c.val() >= bit_cast::<PIXEL, DIM>(self.width.val()) {
            self.hi_x_c.next = bit_cast::<PIXEL, DIM>(self.width.val()) - 1;
        }
        self.hi_y_c.next = bit_cast::<PIXEL, D1>(self.hi_y.val() >> self.frac.val());
        if self.hi_y_c.val() >= bit_cast::<PIXEL, DIM>(self.height.val()) {
            self.hi_y_c.next = bit_cast::<PIXEL, DIM>(self.height.val()) - 1;
        }
        self.cx0.next = (bit_cast::<D1, PIXEL>(self.bx0.q.val()) << self.frac.val()) + self.px_half.val();
        self.cy0.next = (bit_cast::<D1, PIXEL>(self.by0.q.val()) << self.frac.val()) + self.px_half.val();
        self.area_neg.x.next = self.area.q.val();
        self.lead_a.x.next = self.area_abs.q.val();
        self.norm_a.x.next = self.area_abs.q.val();
        self.norm_a.exp.next = self.exp_a.q.val();

        // Setup's multipliers: the area in cycle 1, edge k's function at the first pixel
        // centre in cycle 6 + k (from its start vertex v1, v2, v0).
        self.mul_s[0].a.next = self.ex[1].y.val() - self.ex[0].y.val();
        self.mul_s[0].b.next = self.ey[2].y.val() - self.ey[0].y.val();
        self.mul_s[1].a.next = self.ey[1].y.val() - self.ey[0].y.val();
        self.mul_s[1].b.next = self.ex[2].y.val() - self.ex[0].y.val();
        if self.sc.q.val() == 6 {
            self.mul_s[0].a.next = self.dx[0].q.val();
            self.mul_s[0].b.next = self.cy0.val() - self.ey[1].y.val();
            self.mul_s[1].a.next = self.dy[0].q.val();
            self.mul_s[1].b.next = self.cx0.val() - self.ex[1].y.val();
        }
        if self.sc.q.val() == 7 {
            self.mul_s[0].a.next = self.dx[1].q.val();
            self.mul_s[0].b.next = self.cy0.val() - self.ey[2].y.val();
            self.mul_s[1].a.next = self.dy[1].q.val();
            self.mul_s[1].b.next = self.cx0.val() - self.ex[2].y.val();
        }
        if self.sc.q.val() == 8 {
            self.mul_s[0].a.next = self.dx[2].q.val();
            self.mul_s[0].b.next = self.cy0.val() - self.ey[0].y.val();
            self.mul_s[1].a.next = self.dy[2].q.val();
            self.mul_s[1].b.next = self.cx0.val() - self.ex[0].y.val();
        }
        // The dividers: 1/area's divisor registered in cycle 6 (above), the pixel's 1/sum's at t+8.
        self.norm_s.x.next = self.sum8.q.val();
        self.norm_s.exp.next = self.exp8.q.val();
        self.div.inp_d.next = self.div_d.q.val();

        // ---- The walk's pixel: inside (coverage, top-left rule), and its tag.
        self.covered.next = self.tv.q.val();
        for k in 0..3 {
            self.w_neg[k].x.next = self.w[k].q.val();
            if self.w_neg[k].neg.val() | ((self.w[k].q.val() == 0) & !self.owns[k].val()) {
                self.covered.next = false;
            }
        }
        self.tag.next = (bit_cast::<TAG, SCREEN>(self.ty.q.val()) << self.y_shift.val())
            | (bit_cast::<TAG, SCREEN>(self.tx.q.val()) << self.x_shift.val());
        if self.covered.val() {
            self.tag.next = (bit_cast::<TAG, SCREEN>(self.ty.q.val()) << self.y_shift.val())
                | (bit_cast::<TAG, SCREEN>(self.tx.q.val()) << self.x_shift.val())
                | 1u64;
        }
        self.tag_dl.d.next = self.tag.val();
        self.tag_out.next = self.tag_dl.q.val();

        // ---- Each stage's constants: of the set of the pixel there.
        self.c_mant.next = self.k_mant[0].q.val();
        if self.wp.q.val() {
            self.c_mant.next = self.k_mant[1].q.val();
        }
        self.c_exp.next = self.k_exp[0].q.val();
        if self.ph.q.val().get_bit(self.tap_exp.val().index()) {
            self.c_exp.next = self.k_exp[1].q.val();
        }
        self.c_d1z.next = self.k_d1z[0].q.val();
        self.c_d2z.next = self.k_d2z[0].q.val();
        for k in 0..3 {
            self.c_iw[k].next = self.k_iw[k].q.val();
        }
        if self.ph.q.val().get_bit(self.tap_z.val().index()) {
            self.c_d1z.next = self.k_d1z[1].q.val();
            self.c_d2z.next = self.k_d2z[1].q.val();
            for k in 0..3 {
                self.c_iw[k].next = self.k_iw[3 + k].q.val();
            }
        }
        self.c_z0.next = self.k_z0[0].q.val();
        if self.ph.q.val().get_bit(self.tap_z0.val().index()) {
            self.c_z0.next = self.k_z0[1].q.val();
        }
        for k in 0..3 {
            self.c_d1c[k].next = self.k_d1c[k].q.val();
            self.c_d2c[k].next = self.k_d2c[k].q.val();
            if self.ph.q.val().get_bit(self.tap_c.val().index()) {
                self.c_d1c[k].next = self.k_d1c[3 + k].q.val();
                self.c_d2c[k].next = self.k_d2c[3 + k].q.val();
            }
            self.c_c0[k].next = self.k_c0[k].q.val();
            if self.ph.q.val().get_bit(self.tap_c0.val().index()) {
                self.c_c0[k].next = self.k_c0[3 + k].q.val();
            }
        }

        // ---- The pixel pipeline. t+0: a, b's products.
        self.mul_a.a.next = self.w[1].q.val();
        self.mul_a.b.next = bit_cast::<MANT1, MANT>(self.c_mant.val());
        self.mul_b.a.next = self.w[2].q.val();
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
        self.dtag.next = bit_cast::<DTAG, DEPTH>(self.depth_of.low.val()) << self.x_shift.val();
        if !self.depth_of.neg.val() & !self.depth_of.over.val() {
            self.dtag.next = (bit_cast::<DTAG, DEPTH>(self.depth_of.low.val()) << self.x_shift.val()) | 1u64;
        }
        self.dtag_dl.d.next = self.dtag.val();
        self.dtag_out.next = self.dtag_dl.q.val();
        self.sum_c.next = self.eq[0].y.val() + self.eq[1].y.val() + self.eq[2].y.val();
        if self.sum_c.val() == 0 {
            self.sum_c.next = 1.into();
        }
        self.q_pair.next = (bit_cast::<{ 2 * BARY }, BARY>(self.q6[1].q.val()) << self.half_pair.val())
            | bit_cast::<{ 2 * BARY }, BARY>(self.q6[2].q.val());
        self.q_dl.d.next = self.q_pair.val();
        // t+7: the sum's leading one; t+8: the divisor's register (below); t+9: the divider.
        self.lead_s.x.next = self.sum7.q.val();
        self.exp_dl.d.next = self.exp8.q.val();
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
            // Setup's counter, the drain's, and the end of the unit's work on a triangle.
            if (self.sc.q.val() != 0) & (self.sc.q.val() != self.at_walk.val()) {
                self.sc.d.next = self.sc.q.val() + 1;
            }
            if self.dc.q.val() != 0 {
                self.dc.d.next = self.dc.q.val() - 1;
            }
            for k in 0..2 {
                if self.hold[k].q.val() != 0 {
                    self.hold[k].d.next = self.hold[k].q.val() - 1;
                }
            }
            self.ph.d.next = self.ph.q.val() << self.x_shift.val();
            if self.wp.q.val() {
                self.ph.d.next = (self.ph.q.val() << self.x_shift.val()) | 1u64;
            }
            if self.take.val() {
                self.sbusy.d.next = true;
                self.sc.d.next = 1.into();
                self.vx[0].d.next = self.inp.v0_x.val();
                self.vx[1].d.next = self.inp.v1_x.val();
                self.vx[2].d.next = self.inp.v2_x.val();
                self.vy[0].d.next = self.inp.v0_y.val();
                self.vy[1].d.next = self.inp.v1_y.val();
                self.vy[2].d.next = self.inp.v2_y.val();
                self.vz[0].d.next = self.inp.v0_z.val();
                self.vz[1].d.next = self.inp.v1_z.val();
                self.vz[2].d.next = self.inp.v2_z.val();
                self.vc[0].d.next = self.inp.v0_c0.val();
                self.vc[1].d.next = self.inp.v0_c1.val();
                self.vc[2].d.next = self.inp.v0_c2.val();
                self.vc[3].d.next = self.inp.v1_c0.val();
                self.vc[4].d.next = self.inp.v1_c1.val();
                self.vc[5].d.next = self.inp.v1_c2.val();
                self.vc[6].d.next = self.inp.v2_c0.val();
                self.vc[7].d.next = self.inp.v2_c1.val();
                self.vc[8].d.next = self.inp.v2_c2.val();
                self.viw[0].d.next = self.inp.v0_iw.val();
                self.viw[1].d.next = self.inp.v1_iw.val();
                self.viw[2].d.next = self.inp.v2_iw.val();
            }
            // Cycle 1: the vertices' extremes; cycle 2: the box.
            if self.sc.q.val() == 1 {
                self.min_xr.d.next = self.min_x.val() ^ self.half_xy.val();
                self.max_xr.d.next = self.max_x.val() ^ self.half_xy.val();
                self.min_yr.d.next = self.min_y.val() ^ self.half_xy.val();
                self.max_yr.d.next = self.max_y.val() ^ self.half_xy.val();
            }
            if self.sc.q.val() == 2 {
                self.bx0.d.next = bit_cast::<PIXEL, D1>(self.lo_x.val() >> self.frac.val());
                if self.neg_lo_x.neg.val() {
                    self.bx0.d.next = 0.into();
                }
                self.by0.d.next = bit_cast::<PIXEL, D1>(self.lo_y.val() >> self.frac.val());
                if self.neg_lo_y.neg.val() {
                    self.by0.d.next = 0.into();
                }
                self.bx1.d.next = self.hi_x_c.val();
                self.by1.d.next = self.hi_y_c.val();
                self.bneg.d.next = self.neg_hi_x.neg.val() | self.neg_hi_y.neg.val();
            }
            // Cycle 3: empty?
            if self.sc.q.val() == 3 {
                self.empty.d.next =
                    self.bneg.q.val() | (self.bx0.q.val() > self.bx1.q.val()) | (self.by0.q.val() > self.by1.q.val());
            }
            // Cycle 3: twice the area.
            if self.sc.q.val() == 3 {
                self.area.d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            // Cycle 4: clockwise (v1, v2 swapped for a negative area); |area|.
            if self.sc.q.val() == 4 {
                self.area_abs.d.next = bit_cast::<AREA, EFN>(self.area.q.val());
                if self.area_neg.neg.val() {
                    self.area_abs.d.next = bit_cast::<AREA, EFN>(!self.area.q.val() + 1);
                    self.vx[1].d.next = self.vx[2].q.val();
                    self.vx[2].d.next = self.vx[1].q.val();
                    self.vy[1].d.next = self.vy[2].q.val();
                    self.vy[2].d.next = self.vy[1].q.val();
                    self.vz[1].d.next = self.vz[2].q.val();
                    self.vz[2].d.next = self.vz[1].q.val();
                    self.viw[1].d.next = self.viw[2].q.val();
                    self.viw[2].d.next = self.viw[1].q.val();
                    for k in 0..3 {
                        self.vc[3 + k].d.next = self.vc[6 + k].q.val();
                        self.vc[6 + k].d.next = self.vc[3 + k].q.val();
                    }
                }
            }
            // Cycle 5: edges, attribute differences, |area|'s leading one.
            if self.sc.q.val() == 5 {
                self.dx[0].d.next = self.ex[2].y.val() - self.ex[1].y.val();
                self.dy[0].d.next = self.ey[2].y.val() - self.ey[1].y.val();
                self.dx[1].d.next = self.ex[0].y.val() - self.ex[2].y.val();
                self.dy[1].d.next = self.ey[0].y.val() - self.ey[2].y.val();
                self.dx[2].d.next = self.ex[1].y.val() - self.ex[0].y.val();
                self.dy[2].d.next = self.ey[1].y.val() - self.ey[0].y.val();
                self.d1z.d.next = self.ez[1].y.val() - self.ez[0].y.val();
                self.d2z.d.next = self.ez[2].y.val() - self.ez[0].y.val();
                self.d1c[0].d.next = bit_cast::<C1, COLOR>(self.vc[3].q.val()) - bit_cast::<C1, COLOR>(self.vc[0].q.val());
                self.d1c[1].d.next = bit_cast::<C1, COLOR>(self.vc[4].q.val()) - bit_cast::<C1, COLOR>(self.vc[1].q.val());
                self.d1c[2].d.next = bit_cast::<C1, COLOR>(self.vc[5].q.val()) - bit_cast::<C1, COLOR>(self.vc[2].q.val());
                self.d2c[0].d.next = bit_cast::<C1, COLOR>(self.vc[6].q.val()) - bit_cast::<C1, COLOR>(self.vc[0].q.val());
                self.d2c[1].d.next = bit_cast::<C1, COLOR>(self.vc[7].q.val()) - bit_cast::<C1, COLOR>(self.vc[1].q.val());
                self.d2c[2].d.next = bit_cast::<C1, COLOR>(self.vc[8].q.val()) - bit_cast::<C1, COLOR>(self.vc[2].q.val());
                self.exp_a.d.next = self.lead_a.pos.val();
            }
            // Cycles 8-10: the edge functions at the first pixel centre.
            if self.sc.q.val() == 8 {
                self.w0[0].d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            if self.sc.q.val() == 9 {
                self.w0[1].d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            if self.sc.q.val() == 10 {
                self.w0[2].d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            // Cycle 7 + LA: 1/area's mantissa.
            if self.sc.q.val() == self.at_mant.val() {
                self.mant.d.next = self.mant_c.val();
            }
            // The walk: a pixel a cycle, row by row; in its last, the set its triangle's
            // constants are in is held for the pixels behind.
            if self.tv.q.val() {
                if self.at_last.val() {
                    self.tv.d.next = false;
                    self.dc.d.next = self.drain.val();
                    if self.wp.q.val() {
                        self.hold[1].d.next = self.held_m1.val();
                    } else {
                        self.hold[0].d.next = self.held_m1.val();
                    }
                } else if self.tx.q.val() == self.wx1.q.val() {
                    self.tx.d.next = self.wx0.q.val();
                    self.ty.d.next = self.ty.q.val() + 1;
                    for k in 0..3 {
                        self.wrow[k].d.next = self.wrow[k].q.val() + (self.edx[k].y.val() << self.frac.val());
                        self.w[k].d.next = self.wrow[k].q.val() + (self.edx[k].y.val() << self.frac.val());
                    }
                } else {
                    self.tx.d.next = self.tx.q.val() + 1;
                    for k in 0..3 {
                        self.w[k].d.next = self.w[k].q.val() - (self.edy[k].y.val() << self.frac.val());
                    }
                }
            }
            // The handover: setup is free from the next cycle; a non-empty box's walk starts
            // with its first pixel, its constants in the other set.
            if self.hand.val() {
                self.sbusy.d.next = false;
                self.sc.d.next = 0.into();
                if !self.empty.q.val() {
                    self.tv.d.next = true;
                    self.wp.d.next = !self.wp.q.val();
                    self.tx.d.next = bit_cast::<SCREEN, PIXEL>(self.bx0.q.val());
                    self.ty.d.next = bit_cast::<SCREEN, PIXEL>(self.by0.q.val());
                    self.wx0.d.next = bit_cast::<SCREEN, PIXEL>(self.bx0.q.val());
                    self.wx1.d.next = bit_cast::<SCREEN, PIXEL>(self.bx1.q.val());
                    self.wy1.d.next = bit_cast::<SCREEN, PIXEL>(self.by1.q.val());
                    for k in 0..3 {
                        self.w[k].d.next = self.w0[k].q.val();
                        self.wrow[k].d.next = self.w0[k].q.val();
                        self.wdx[k].d.next = self.dx[k].q.val();
                        self.wdy[k].d.next = self.dy[k].q.val();
                    }
                    if self.wp.q.val() {
                        self.k_mant[0].d.next = self.mant_c.val();
                        self.k_exp[0].d.next = self.exp_a.q.val();
                        self.k_d1z[0].d.next = self.d1z.q.val();
                        self.k_d2z[0].d.next = self.d2z.q.val();
                        self.k_z0[0].d.next = self.vz[0].q.val();
                        for k in 0..3 {
                            self.k_iw[k].d.next = self.viw[k].q.val();
                            self.k_d1c[k].d.next = self.d1c[k].q.val();
                            self.k_d2c[k].d.next = self.d2c[k].q.val();
                            self.k_c0[k].d.next = self.vc[k].q.val();
                        }
                    } else {
                        self.k_mant[1].d.next = self.mant_c.val();
                        self.k_exp[1].d.next = self.exp_a.q.val();
                        self.k_d1z[1].d.next = self.d1z.q.val();
                        self.k_d2z[1].d.next = self.d2z.q.val();
                        self.k_z0[1].d.next = self.vz[0].q.val();
                        for k in 0..3 {
                            self.k_iw[3 + k].d.next = self.viw[k].q.val();
                            self.k_d1c[3 + k].d.next = self.d1c[k].q.val();
                            self.k_d2c[3 + k].d.next = self.d2c[k].q.val();
                            self.k_c0[3 + k].d.next = self.vc[k].q.val();
                        }
                    }
                }
            }
            // The pixel pipeline's registers.
            self.a3.d.next = self.rs_a.y.val();
            self.b3.d.next = self.rs_b.y.val();
            self.z6.d.next = self.rs_z.y.val() + self.rs_z0.y.val();
            for k in 0..3 {
                self.q6[k].d.next = self.rs_q[k].y.val();
                self.c14[k].d.next = self.rs_c[k].y.val() + self.rs_c0[k].y.val();
                self.o_rgb[k].d.next = self.color_of[k].low.val();
                if self.color_of[k].over.val() {
                    self.o_rgb[k].d.next = self.full.val();
                }
                if self.color_of[k].neg.val() {
                    self.o_rgb[k].d.next = 0.into();
                }
            }
            self.div_d.d.next = self.norm_s.d.val();
            if self.sc.q.val() == 6 {
                self.div_da.d.next = self.norm_a.d.val();
            }
            self.sum7.d.next = self.sum_c.val();
            self.sum8.d.next = self.sum7.q.val();
            self.exp8.d.next = self.lead_s.pos.val();
            self.ca11.d.next = self.rs_ra.y.val();
            self.cb11.d.next = self.rs_rb.y.val();
            self.o_valid.d.next = self.tag_out.val().get_bit(0) & self.dtag_out.val().get_bit(0);
            self.o_x.d.next = bit_cast::<SCREEN, TAG>(self.tag_out.val() >> self.x_shift.val());
            self.o_y.d.next = bit_cast::<SCREEN, TAG>(self.tag_out.val() >> self.y_shift.val());
            self.o_z.d.next = bit_cast::<DEPTH, DTAG>(self.dtag_out.val() >> self.x_shift.val());
        }
        self.out.valid.next = self.o_valid.q.val();
        self.out.x.next = self.o_x.q.val();
        self.out.y.next = self.o_y.q.val();
        self.out.z.next = self.o_z.q.val();
        self.out.rgb0.next = self.o_rgb[0].q.val();
        self.out.rgb1.next = self.o_rgb[1].q.val();
        self.out.rgb2.next = self.o_rgb[2].q.val();
    }
}

crate::pins!(Vector {
    clock: clock,
    inputs: [width, height],
    outputs: [idle],
    links: [inp, out],
});

/// `UNITS` entry: the barycentric unit with an `L`-stage divider, perspective-correct
/// colours as `params["PERSPECTIVE"]` says.
pub fn emit_vector(params: &Params) -> Result<Emitted, String> {
    let perspective = match params["PERSPECTIVE"] {
        0 => false,
        1 => true,
        v => return Err(format!("vector: PERSPECTIVE = {v}: 0 or 1")),
    };
    Ok(emit_unit("vector", Vector::new(params["L"] as usize, perspective)?, params))
}

