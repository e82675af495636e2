//! `vector`: per-pixel barycentric rasterization of paper 004 (Lee et al. 2009, eq. 1-6),
//! `LANES` pixels per clock (1, 2, 4 or 8), bit-exact and cycle-exact to
//! `model::vector::vector` and `model::cycles::VectorUnit`.
//!
//! It takes a sorted triangle (the link `inp`, `links::SortedSink`, the vertices' `inv_w`
//! included) when its setup is free; a scout finds, row by row of the triangle's bounding
//! box of pixel centres (clipped to the screen), the chunks of `LANES` pixels that may hold
//! a pixel inside; the walker walks them, a chunk a cycle, and the lanes ([`lane::Lane`])
//! test and shade their pixel of the chunk. Each chunk with a pixel inside whose depth lies
//! in [0, z_max] leaves on `out_*`: the chunk's first x and its row, a mask of the lanes
//! with a pixel, their depths and colours. Setup works on the next triangle while the scout
//! and the walker work on the ones before.
//!
//! **Setup** (cycle 0 takes the triangle; `model::vector::setup` cycles, 21 with the
//! default divider):
//!
//! ```text
//!  cycle 1      bounding box: min and max of x and y (registers); the x of the first
//!               vertex of least y; area products (v1 - v0) x (v2 - v0), two multipliers
//!  cycle 2      the box to pixel centres, clipped to the screen
//!  cycle 3      empty box?; twice the area (exact); the start chunk: the top vertex's
//!               pixel clamped to the box, rounded down to a multiple of LANES
//!  cycle 4      the area's sign: v1 and v2 swapped for a negative area (clockwise on
//!               screen); |area|
//!  cycle 5      edge deltas of the (swapped) edges v1->v2, v2->v0, v0->v1; attribute
//!               differences v1 - v0, v2 - v0; |area|'s leading one (exp)
//!  cycle 6      1/area's divisor (`model::divider::recip_operands`) into a register; setup's
//!               own divider (LA = `model::vector::area_divider_latency` stages, 13 at the
//!               default L = 25) takes it in cycle 7 and returns it LA later
//!  cycles 6-8   each edge function at the start chunk's first pixel centre in the box's
//!               first row: two products
//!  cycle 7+LA   1/area's mantissa; handed to the scout this cycle (or at cycle 11, LA < 4)
//!               or later: when the scout is free and the set of constants the triangle
//!               goes into is free (below); setup may take the next triangle the cycle after
//! ```
//!
//! **Scout** (`model::vector::vector` gives the rule, `WalkRow` its cycles). Two probes,
//! each a chunk and the three edge functions at its first pixel, start on the first row at
//! the start chunk and on each next row where they ended (the functions step exactly:
//! -2^s dy a pixel right, 2^s dx a row down). An edge rising to the right (dy < 0) bounds a
//! row on the left: the left probe moves right while that edge rejects its chunk's last
//! pixel, left while no such edge rejects the pixel left of its chunk; the right probe
//! mirrors it with the edges falling to the right at its chunk's first pixel and the next
//! chunk's. A probe moves a chunk a cycle, within the box. A flat edge rejecting the row
//! ends it empty at once. When neither probe moves the row is found: empty (a probe still
//! out, or crossed) and left, or held until the walker takes it.
//!
//! **Walker.** It takes a found row in its last chunk of the row before (or idle): the
//! chunk, the row's last chunk, the left probe's edge functions, its triangle's edges and
//! set; then a chunk a cycle. Lane i tests pixel x + i with the chunk's functions less
//! i x 2^s dy (loaded when the walker takes a row): inside the box, and all three positive
//! or zero on an edge the triangle owns (top-left rule), as the model.
//!
//! **Pixel pipeline**, in every lane (cycle t: the chunk in the walker's registers; `L` the
//! divider's stages; `model::vector::pixel_latency` = 16 + L):
//!
//! ```text
//!  t+0..2    a = w1/area, b = w2/area (eq. 3): w x 1/area's mantissa, shifted by exp    (2 multipliers)
//!  t+3..5    z = z0 + (z1 - z0) a + (z2 - z0) b (eq. 4, screen-linear)                  (2)
//!            q_k = l_k iw_k, l = (1 - a - b, a, b) (eq. 5)                              (3)
//!  t+6       depth rounded and tested against [0, z_max]; sum = q0 + q1 + q2
//!  t+7       the sum's leading one
//!  t+8       1/sum's divisor into a register; t+9 into the lane's divider, back at t+9+L
//!  t+9+L..   a' = q1/sum, b' = q2/sum (eq. 6): q x 1/sum's mantissa, shifted             (2)
//!  t+12+L..  colours c0 + (c1 - c0) a' + (c2 - c0) b' (eq. 4; a, b without
//!            perspective correction), rounded and clamped                                (6)
//!  t+16+L    the chunk on `out`
//! ```
//!
//! The arithmetic is the model's, every wrap a register's width and every floor a bit slice
//! ([`Rescale`]): a and b wrap to `bary`, the depth accumulator to `z_acc`, the colours to
//! `c_acc`; depth and colour round as `span` rounds them (`span::DepthOf`, `span::ColorOf`).
//!
//! **Triangles in flight.** The pipeline's stages read their triangle's constants (1/area's
//! mantissa and exponent at t+0 and t+2; z's and eq. 5's at t+3 and t+5; the colours' at
//! t+12+L and t+14+L) from one of two sets, the chunk's set found in a shift register of
//! the walker's (`ph`): a triangle may load a set at its handover only when the last chunk
//! using it has passed t+14+L (`model::vector::constants_read`). While a chunk waits on
//! `out` the whole unit waits (`run` low: every register holds, the multipliers' and the
//! dividers' too).
//!
//! **Parameters.** `N`, the size class (widths from `crate::widths`); `L`, the divider's
//! stages; `PERSPECTIVE` (1: colours by eq. 5-6; 0: by a and b, and the synthesis removes
//! eq. 5-6's multipliers and the divider's second use); `LANES`.
//!
//! Model: `model::vector::vector`. Emitted: `hdl-out/vector.v`.

use super::cull_sort::{COLOR, INV_W, XY, Z};
use super::divider::{DividerRtl, DIV_D, DIV_N, LATENCY_MAX};
use super::links::SortedSink;
use super::widths::{CHANNEL, C_ACC, DEPTH, DERIVED, DIM, FORMATS, PIXEL, SCREEN, Z_ACC};
use crate::emit::{emit_unit, Emitted};
use crate::mul::PipelinedMul;
use crate::parts::{defaults, DelayLine, Negative, SignExtend};
use crate::Params;
use blank::Blank;
use lane::Lane;
use rust_hdl::prelude::*;

#[path = "vector/lane.rs"]
mod lane;

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

/// A chunk's place through the pipeline: `{y, x}`.
const TAG: usize = 2 * SCREEN;

/// `y` = the low `OUT` bits of floor(x 2^lsh / 2^(rsh + by)), `x` an `IN`-bit two's
/// complement number: the model's `rescale` (floor) and its wrap into a register, as a bit
/// slice. `WIDE` >= `IN` and >= rsh + max(by) + `OUT`: every bit the slice takes lies
/// below it (bits shifted left past it are above the slice).
#[derive(LogicBlock, Blank)]
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
            lsh: Constant::new(lsh.to_bits()),
            rsh: Constant::new(rsh.to_bits()),
            msb: Constant::new((IN - 1).to_bits()),
            ext: Constant::new(if IN < WIDE { !Bits::<WIDE>::default() << (IN as u64) } else { Bits::default() }),
            ..Rescale::blank()
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
        LeadingOne {
            x: Default::default(),
            pos: Default::default(),
            index: (0..N).map(|i| Constant::new(i.to_bits())).collect(),
        }
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
#[derive(LogicBlock, Blank)]
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
        Normalise { top: Constant::new(TOP.to_bits()), ..Normalise::blank() }
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

/// `rejects` = edge function `e` rejects its sample: negative, or zero on an edge that does
/// not own its samples (top-left rule).
#[derive(LogicBlock, Default)]
pub struct Rejects {
    pub e: Signal<In, Bits<EFN>>,
    pub owns: Signal<In, Bit>,
    pub rejects: Signal<Out, Bit>,
    sign: Negative<EFN>,
}

impl Logic for Rejects {
    #[hdl_gen]
    fn update(&mut self) {
        self.sign.x.next = self.e.val();
        self.rejects.next = self.sign.neg.val() | ((self.e.val() == 0) & !self.owns.val());
    }
}

/// `y` = `x` placed at bit `at` of a wider word, zeros elsewhere.
#[derive(LogicBlock)]
pub struct Place<const W: usize, const OUT: usize> {
    pub x: Signal<In, Bits<W>>,
    pub y: Signal<Out, Bits<OUT>>,
    at: Constant<Bits<16>>,
}

impl<const W: usize, const OUT: usize> Place<W, OUT> {
    pub fn new(at: usize) -> Self {
        assert!(at + W <= OUT, "Place<{W}, {OUT}> at {at}");
        Place { x: Default::default(), y: Default::default(), at: Constant::new(at.to_bits()) }
    }
}

impl<const W: usize, const OUT: usize> Logic for Place<W, OUT> {
    #[hdl_gen]
    fn update(&mut self) {
        self.y.next = bit_cast::<OUT, W>(self.x.val()) << self.at.val();
    }
}

/// An edge's class from its (swapped, clockwise) deltas: its function rises to the right
/// (`left`: dy < 0, it bounds a row on the left), falls (`right`: dy > 0) or is constant
/// along a row (`flat`); whether it owns its samples (top edges run in +x, left edges in
/// -y); its function's step a pixel right (`g`: it falls by dy 2^s) and a row down (`h`:
/// it rises by dx 2^s).
#[derive(LogicBlock, Blank)]
pub struct EdgeClass {
    pub dx: Signal<In, Bits<D1>>,
    pub dy: Signal<In, Bits<D1>>,
    pub left: Signal<Out, Bit>,
    pub right: Signal<Out, Bit>,
    pub flat: Signal<Out, Bit>,
    pub owns: Signal<Out, Bit>,
    pub g: Signal<Out, Bits<EFN>>,
    pub h: Signal<Out, Bits<EFN>>,
    dx_neg: Negative<D1>,
    dy_neg: Negative<D1>,
    ex: SignExtend<D1, EFN>,
    ey: SignExtend<D1, EFN>,
    frac: Constant<Bits<8>>,
}

impl Default for EdgeClass {
    fn default() -> Self {
        EdgeClass { frac: Constant::new((FORMATS.xy.frac as usize).to_bits()), ..EdgeClass::blank() }
    }
}

impl Logic for EdgeClass {
    #[hdl_gen]
    fn update(&mut self) {
        self.dx_neg.x.next = self.dx.val();
        self.dy_neg.x.next = self.dy.val();
        self.left.next = self.dy_neg.neg.val();
        self.flat.next = self.dy.val() == 0;
        self.right.next = !self.dy_neg.neg.val() & (self.dy.val() != 0);
        self.owns.next = self.dy_neg.neg.val() | ((self.dy.val() == 0) & !self.dx_neg.neg.val() & (self.dx.val() != 0));
        self.ex.x.next = self.dx.val();
        self.ey.x.next = self.dy.val();
        self.g.next = self.ey.y.val() << self.frac.val();
        self.h.next = self.ex.y.val() << self.frac.val();
    }
}

/// The barycentric unit with `LANES` lanes (1, 2, 4 or 8; `ZW` = `LANES` x `DEPTH`, `CW` =
/// `LANES` x 3 x `CHANNEL`, the output's widths); see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct Vector<const LANES: usize, const ZW: usize, const CW: usize> {
    pub clock: Signal<In, Clock>,
    /// Screen size in pixels, 1 to 2^CLASS each; constant during a frame.
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// The sorted triangle in (`inp.crosses` is not read), taken when setup is free.
    pub inp: SortedSink,
    /// A chunk's pixels, held until `out_ready`: `out_mask` bit i for pixel (`out_x` + i,
    /// `out_y`) with depth `out_z` bits [i DEPTH, (i+1) DEPTH) and colour `{R, G, B}` (R on
    /// top) `out_rgb` bits [3i CHANNEL, 3(i+1) CHANNEL): the lanes as a memory word of
    /// `links::ChunkPort` holds them.
    pub out_valid: Signal<Out, Bit>,
    pub out_ready: Signal<In, Bit>,
    pub out_mask: Signal<Out, Bits<LANES>>,
    pub out_x: Signal<Out, Bits<SCREEN>>,
    pub out_y: Signal<Out, Bits<SCREEN>>,
    pub out_z: Signal<Out, Bits<ZW>>,
    pub out_rgb: Signal<Out, Bits<CW>>,
    /// No triangle in the unit.
    pub idle: Signal<Out, Bit>,

    lanes: Vec<Lane>,
    /// 1/area's divider, for the triangle in setup.
    #[given]
    div_a: DividerRtl,
    /// Setup's two multipliers: the area, then each edge function at the start chunk.
    mul_s: [PipelinedMul<D1, D1, EFN>; 2],

    // Control.
    /// A triangle is in setup (taken, not yet handed to the scout); the unit runs (no
    /// chunk waits on `out`).
    sbusy: DFF<Bit>,
    run: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    /// Setup's cycle (1 up to `at_walk`, where it waits for the handover; 0: none) and the
    /// cycles until the walker's last chunk has left.
    sc: DFF<Bits<8>>,
    dc: DFF<Bits<8>>,
    at_mant: Constant<Bits<8>>,
    at_walk: Constant<Bits<8>>,
    drain: Constant<Bits<8>>,
    /// The set the next triangle loads is free; the triangle in setup goes to the scout
    /// (or, with an empty box, away) this cycle.
    set_ok: Signal<Local, Bit>,
    hand: Signal<Local, Bit>,
    /// Per set of constants, the cycles they are still read (`model::vector::constants_read`
    /// from the walker's last chunk using them, less one).
    hold: [DFF<Bits<8>>; 2],
    held_m1: Constant<Bits<8>>,
    /// The scout's triangle's set, the walker's, and the sets of the chunks behind the
    /// walker: bit j that of the chunk at t+j+1. Taps: the stages that read a constant.
    sp: DFF<Bit>,
    wp: DFF<Bit>,
    ph: DFF<Bits<64>>,
    tap_exp: Constant<Bits<8>>,
    tap_z: Constant<Bits<8>>,
    tap_z0: Constant<Bits<8>>,
    tap_c: Constant<Bits<8>>,
    tap_c0: Constant<Bits<8>>,

    // Setup: the triangle's vertices (swapped for a negative area in cycle 4).
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
    /// x of the first vertex of least y.
    top_x: Signal<Local, Bits<XY>>,
    /// The vertices' extremes (sign bits flipped back) and the top vertex's x, registered in
    /// cycle 1.
    min_xr: DFF<Bits<XY>>,
    max_xr: DFF<Bits<XY>>,
    min_yr: DFF<Bits<XY>>,
    max_yr: DFF<Bits<XY>>,
    top_xr: DFF<Bits<XY>>,
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
    ext_top: SignExtend<XY, D1>,
    neg_top: Negative<XY>,
    px_half_m1: Constant<Bits<D1>>,
    px_half: Constant<Bits<D1>>,
    frac: Constant<Bits<8>>,
    /// The box (pixels, non-negative), whether its bottom or right lies left of or above
    /// the screen, and whether it is empty; the first row's start chunk (its first x).
    bx0: DFF<Bits<PIXEL>>,
    bx1: DFF<Bits<PIXEL>>,
    by0: DFF<Bits<PIXEL>>,
    by1: DFF<Bits<PIXEL>>,
    hi_x_c: Signal<Local, Bits<PIXEL>>,
    hi_y_c: Signal<Local, Bits<PIXEL>>,
    bneg: DFF<Bit>,
    empty: DFF<Bit>,
    top_c: Signal<Local, Bits<PIXEL>>,
    cs: DFF<Bits<PIXEL>>,
    /// Multiples of `LANES`: ones above the low log2(LANES) bits.
    chunk: Constant<Bits<SCREEN>>,
    chunk_p: Constant<Bits<PIXEL>>,
    lg: Constant<Bits<8>>,
    one_s: Constant<Bits<8>>,
    step: Constant<Bits<SCREEN>>,
    /// The start chunk's first pixel centre, in `xy` units.
    cx0: Signal<Local, Bits<D1>>,
    cy0: Signal<Local, Bits<D1>>,

    area: DFF<Bits<EFN>>,
    area_neg: Negative<EFN>,
    area_abs: DFF<Bits<AREA>>,
    lead_a: LeadingOne<AREA>,
    exp_a: DFF<Bits<8>>,
    norm_a: Normalise<AREA, { max(AREA, DIV_D) + 1 }>,
    recip_n: Constant<Bits<DIV_N>>,
    /// 1/area's mantissa: from its divider in cycle 7 + LA (the handover may come in it),
    /// from `mant` after.
    mant_c: Signal<Local, Bits<MANT>>,
    /// 1/area's divisor, registered in cycle 6.
    div_da: DFF<Bits<DIV_D>>,
    mant: DFF<Bits<MANT>>,

    /// Per edge (v1->v2, v2->v0, v0->v1): dx, dy, and its function at the start chunk.
    dx: [DFF<Bits<D1>>; 3],
    dy: [DFF<Bits<D1>>; 3],
    w0: [DFF<Bits<EFN>>; 3],
    /// Attribute differences v1 - v0, v2 - v0 (after the swap).
    d1z: DFF<Bits<Z1>>,
    d2z: DFF<Bits<Z1>>,
    d1c: [DFF<Bits<C1>>; 3],
    d2c: [DFF<Bits<C1>>; 3],

    // The scout: busy, its row and the last row, the box's first and last chunk and x
    // extent, each probe's chunk and the edge functions at its first pixel, its edges.
    sv: DFF<Bit>,
    sy: DFF<Bits<SCREEN>>,
    sy1: DFF<Bits<SCREEN>>,
    sc0: DFF<Bits<SCREEN>>,
    sc1: DFF<Bits<SCREEN>>,
    sx0: DFF<Bits<SCREEN>>,
    sx1: DFF<Bits<SCREEN>>,
    sl: DFF<Bits<SCREEN>>,
    sr: DFF<Bits<SCREEN>>,
    el: [DFF<Bits<EFN>>; 3],
    er: [DFF<Bits<EFN>>; 3],
    sdx: [DFF<Bits<D1>>; 3],
    sdy: [DFF<Bits<D1>>; 3],
    scls: [EdgeClass; 3],
    /// Each edge's step over a chunk, and over all but its last pixel.
    s_chunk: [Signal<Local, Bits<EFN>>; 3],
    s_less: [Signal<Local, Bits<EFN>>; 3],
    /// Per edge: at the left probe's last pixel, at the pixel left of it, at the left probe's
    /// first pixel (flat edges), at the right probe's first pixel and the next chunk's.
    rej_ll: [Rejects; 3],
    rej_lm: [Rejects; 3],
    rej_lf: [Rejects; 3],
    rej_rf: [Rejects; 3],
    rej_rn: [Rejects; 3],
    /// The left probe's chunk and all left of it hold no pixel; the chunk left of it holds
    /// none; the right probe's and all right of it; the next right; a flat edge rejects the
    /// row.
    out_l: Signal<Local, Bit>,
    out_lm: Signal<Local, Bit>,
    out_r: Signal<Local, Bit>,
    out_rn: Signal<Local, Bit>,
    dead: Signal<Local, Bit>,
    /// Probe moves: left probe right or left, right probe left or right.
    l_right: Signal<Local, Bit>,
    l_left: Signal<Local, Bit>,
    r_left: Signal<Local, Bit>,
    r_right: Signal<Local, Bit>,
    /// The scout's row is found (no probe moves), found empty, and its last.
    found: Signal<Local, Bit>,
    row_empty: Signal<Local, Bit>,
    row_last: Signal<Local, Bit>,

    // The walker: a chunk (its first x), the row's last chunk, the row; the box's x
    // extent, each edge function at the chunk's first pixel, its edges.
    tv: DFF<Bit>,
    tx: DFF<Bits<SCREEN>>,
    te: DFF<Bits<SCREEN>>,
    ty: DFF<Bits<SCREEN>>,
    wx0: DFF<Bits<SCREEN>>,
    wx1: DFF<Bits<SCREEN>>,
    w: [DFF<Bits<EFN>>; 3],
    /// Per edge: whether it owns its samples, its function's step over a chunk.
    wown: [DFF<Bit>; 3],
    wstep: [DFF<Bits<EFN>>; 3],
    walk_free: Signal<Local, Bit>,

    /// Two sets of a triangle's constants for the pixels (set s at index s, or 3s + k for
    /// vertex or channel k), and those of the chunk at each stage that reads one.
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
    c_iw: [Signal<Local, Bits<INV_W>>; 3],
    c_d1c: [Signal<Local, Bits<C1>>; 3],
    c_d2c: [Signal<Local, Bits<C1>>; 3],
    c_c0: [Signal<Local, Bits<COLOR>>; 3],
    /// The chunk's place `{y, x}` through the pipeline.
    tag: Signal<Local, Bits<TAG>>,
    #[given]
    tag_dl: DelayLine<TAG>,
    y_shift: Constant<Bits<8>>,
    o_x: DFF<Bits<SCREEN>>,
    o_y: DFF<Bits<SCREEN>>,
    /// The lanes' outputs gathered: after lane i, lanes 0 to i - 1 (`ZW`, `CW` bits).
    g_mask: Vec<Signal<Local, Bits<LANES>>>,
    g_z: Vec<Signal<Local, Bits<ZW>>>,
    g_rgb: Vec<Signal<Local, Bits<CW>>>,
    at_mask: Vec<Constant<Bits<LANES>>>,
    place_z: Vec<Place<DEPTH, ZW>>,
    place_rgb: Vec<Place<{ 3 * CHANNEL }, CW>>,
}

impl<const LANES: usize, const ZW: usize, const CW: usize> Vector<LANES, ZW, CW> {
    /// The unit with an `l`-stage divider, colours perspective-corrected or not.
    pub fn new(l: usize, perspective: bool) -> Result<Self, String> {
        assert!(
            matches!(LANES, 1 | 2 | 4 | 8) && ZW == LANES * DEPTH && CW == LANES * 3 * CHANNEL,
            "Vector<{LANES}, {ZW}, {CW}>"
        );
        if !(1..=LATENCY_MAX).contains(&l) {
            return Err(format!("vector: L = {l} divider stages is not supported: 1 to {LATENCY_MAX}"));
        }
        let (setup, pixel) = (model::vector::setup(l as u32) as usize, model::vector::pixel_latency(l as u32) as usize);
        let la = model::vector::area_divider_latency(l as u32) as usize;
        let px = 1usize << FORMATS.xy.frac;
        Ok(Vector {
            lanes: (0..LANES).map(|i| Lane::new(i, l, perspective)).collect(),
            mul_s: defaults(),
            at_mant: Constant::new((7 + la).to_bits()),
            at_walk: Constant::new((setup - 1).to_bits()),
            drain: Constant::new(pixel.to_bits()),
            hold: defaults(),
            held_m1: Constant::new((model::vector::constants_read(l as u32) as usize - 1).to_bits()),
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
            px_half_m1: Constant::new((px / 2 - 1).to_bits()),
            px_half: Constant::new((px / 2).to_bits()),
            frac: Constant::new((FORMATS.xy.frac as usize).to_bits()),
            chunk: Constant::new(!Bits::<SCREEN>::default() << (LANES.trailing_zeros() as u64)),
            chunk_p: Constant::new(!Bits::<PIXEL>::default() << (LANES.trailing_zeros() as u64)),
            lg: Constant::new((LANES.trailing_zeros() as usize).to_bits()),
            one_s: Constant::new(1usize.to_bits()),
            step: Constant::new(LANES.to_bits()),
            recip_n: Constant::new((1u128 << (TOP as u32 + FORMATS.ooa.frac)).to_bits()),
            dx: defaults(),
            dy: defaults(),
            w0: defaults(),
            d1c: defaults(),
            d2c: defaults(),
            el: defaults(),
            er: defaults(),
            sdx: defaults(),
            sdy: defaults(),
            scls: defaults(),
            s_chunk: defaults(),
            s_less: defaults(),
            rej_ll: defaults(),
            rej_lm: defaults(),
            rej_lf: defaults(),
            rej_rf: defaults(),
            rej_rn: defaults(),
            w: defaults(),
            wown: defaults(),
            wstep: defaults(),
            k_mant: defaults(),
            k_exp: defaults(),
            k_d1z: defaults(),
            k_d2z: defaults(),
            k_z0: defaults(),
            k_iw: defaults(),
            k_d1c: defaults(),
            k_d2c: defaults(),
            k_c0: defaults(),
            c_iw: defaults(),
            c_d1c: defaults(),
            c_d2c: defaults(),
            c_c0: defaults(),
            y_shift: Constant::new(SCREEN.to_bits()),
            g_mask: (0..=LANES).map(|_| Default::default()).collect(),
            g_z: (0..=LANES).map(|_| Default::default()).collect(),
            g_rgb: (0..=LANES).map(|_| Default::default()).collect(),
            at_mask: (0..LANES).map(|i| Constant::new((1usize << i).to_bits())).collect(),
            place_z: (0..LANES).map(|i| Place::new(i * DEPTH)).collect(),
            place_rgb: (0..LANES).map(|i| Place::new(3 * i * CHANNEL)).collect(),
            ..Vector::blank(VectorGiven { div_a: DividerRtl::new(la), tag_dl: DelayLine::new(pixel - 1) })
        })
    }
}

/// The default unit: the default divider, perspective-correct colours.
impl<const LANES: usize, const ZW: usize, const CW: usize> Default for Vector<LANES, ZW, CW> {
    fn default() -> Self {
        Vector::new(crate::L.default as usize, true).expect("the default L is supported")
    }
}

impl<const LANES: usize, const ZW: usize, const CW: usize> Logic for Vector<LANES, ZW, CW> {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- Clocks; every register holds unless written, and is written only while the
        // unit runs.
        dff_setup!(
            self, clock, sbusy, sc, dc, bx0, bx1, by0, by1, bneg, empty, cs, area, area_abs, exp_a, div_da, mant
        );
        dff_setup!(self, clock, sp, wp, ph, d1z, d2z, min_xr, max_xr, min_yr, max_yr, top_xr);
        dff_setup!(self, clock, sv, sy, sy1, sc0, sc1, sx0, sx1, sl, sr, tv, tx, te, ty, wx0, wx1, o_x, o_y);
        clock!(self, clock, div_a, tag_dl);
        for i in 0..LANES {
            self.lanes[i].clock.next = self.clock.val();
        }
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
            self.d1c[k].clock.next = self.clock.val();
            self.d1c[k].d.next = self.d1c[k].q.val();
            self.d2c[k].clock.next = self.clock.val();
            self.d2c[k].d.next = self.d2c[k].q.val();
            self.el[k].clock.next = self.clock.val();
            self.el[k].d.next = self.el[k].q.val();
            self.er[k].clock.next = self.clock.val();
            self.er[k].d.next = self.er[k].q.val();
            self.sdx[k].clock.next = self.clock.val();
            self.sdx[k].d.next = self.sdx[k].q.val();
            self.sdy[k].clock.next = self.clock.val();
            self.sdy[k].d.next = self.sdy[k].q.val();
            self.w[k].clock.next = self.clock.val();
            self.w[k].d.next = self.w[k].q.val();
            self.wown[k].clock.next = self.clock.val();
            self.wown[k].d.next = self.wown[k].q.val();
            self.wstep[k].clock.next = self.clock.val();
            self.wstep[k].d.next = self.wstep[k].q.val();
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

        // ---- Control: the unit runs unless a chunk waits on `out`. Setup takes a triangle
        // when it holds none and the unit runs, and hands it to the scout in its last cycle
        // (`at_walk`) or later: when the scout is free and the set of constants the triangle
        // loads (the other than the scout's last) is read no more; an empty box at once.
        // ---- The lanes' outputs gathered: the chunk on `out`; the unit runs unless it waits.
        self.g_mask[0].next = 0.into();
        self.g_z[0].next = 0.into();
        self.g_rgb[0].next = 0.into();
        for i in 0..LANES {
            self.g_mask[i + 1].next = self.g_mask[i].val();
            if self.lanes[i].o_valid.val() {
                self.g_mask[i + 1].next = self.g_mask[i].val() | self.at_mask[i].val();
            }
            self.place_z[i].x.next = self.lanes[i].o_z.val();
            self.place_rgb[i].x.next = self.lanes[i].o_rgb.val();
            self.g_z[i + 1].next = self.g_z[i].val() | self.place_z[i].y.val();
            self.g_rgb[i + 1].next = self.g_rgb[i].val() | self.place_rgb[i].y.val();
        }
        for i in LANES..(LANES + 1) {
            self.out_mask.next = self.g_mask[i].val();
            self.out_z.next = self.g_z[i].val();
            self.out_rgb.next = self.g_rgb[i].val();
        }
        self.out_valid.next = self.out_mask.val() != 0;
        self.run.next = !(self.out_valid.val() & !self.out_ready.val());
        for k in 0..2 {
            self.mul_s[k].en.next = self.run.val();
        }
        self.inp.ready.next = !self.sbusy.q.val() & self.run.val();
        self.take.next = self.inp.valid.val() & self.inp.ready.val();
        self.idle.next = !self.sbusy.q.val() & !self.sv.q.val() & !self.tv.q.val() & (self.dc.q.val() == 0);
        self.set_ok.next = self.hold[1].q.val() == 0;
        if self.sp.q.val() {
            self.set_ok.next = self.hold[0].q.val() == 0;
        }
        self.hand.next = self.sbusy.q.val()
            & (self.sc.q.val() == self.at_walk.val())
            & (self.empty.q.val() | (!self.sv.q.val() & self.set_ok.val()));
        self.div_a.hold.next = !self.run.val();
        self.div_a.out_ready.next = true;
        self.div_a.inp_valid.next = true;
        self.div_a.inp_n.next = self.recip_n.val();
        self.div_a.inp_d.next = self.div_da.q.val();
        self.mant_c.next = self.mant.q.val();
        if self.sc.q.val() == self.at_mant.val() {
            self.mant_c.next = self.div_a.out_q.val().get_bits::<MANT>(0);
        }
        self.tag_dl.en.next = self.run.val();

        // ---- Setup's geometry, combinationally from its registers.
        for k in 0..3 {
            self.ex[k].x.next = self.vx[k].q.val();
            self.ey[k].x.next = self.vy[k].q.val();
            self.ez[k].x.next = self.vz[k].q.val();
            self.ux[k].next = self.vx[k].q.val() ^ self.half_xy.val();
            self.uy[k].next = self.vy[k].q.val() ^ self.half_xy.val();
        }
        // The bounding box of the vertices, in unsigned order, and the top vertex's x; then
        // the box of pixel centres.
        self.min_x.next = self.ux[0].val();
        self.max_x.next = self.ux[0].val();
        self.min_y.next = self.uy[0].val();
        self.max_y.next = self.uy[0].val();
        self.top_x.next = self.vx[0].q.val();
        for k in 1..3 {
            if self.ux[k].val() < self.min_x.val() {
                self.min_x.next = self.ux[k].val();
            }
            if self.ux[k].val() > self.max_x.val() {
                self.max_x.next = self.ux[k].val();
            }
            if self.uy[k].val() < self.min_y.val() {
                self.min_y.next = self.uy[k].val();
                self.top_x.next = self.vx[k].q.val();
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
        // The top vertex's pixel, clamped to the box (cycle 3).
        self.ext_top.x.next = self.top_xr.q.val();
        self.neg_top.x.next = self.top_xr.q.val();
        self.top_c.next = bit_cast::<PIXEL, D1>(self.ext_top.y.val() >> self.frac.val());
        if self.top_c.val() > self.bx1.q.val() {
            self.top_c.next = self.bx1.q.val();
        }
        if self.neg_top.neg.val() | (self.top_c.val() < self.bx0.q.val()) {
            self.top_c.next = self.bx0.q.val();
        }
        self.cx0.next = (bit_cast::<D1, PIXEL>(self.cs.q.val()) << self.frac.val()) + self.px_half.val();
        self.cy0.next = (bit_cast::<D1, PIXEL>(self.by0.q.val()) << self.frac.val()) + self.px_half.val();
        self.area_neg.x.next = self.area.q.val();
        self.lead_a.x.next = self.area_abs.q.val();
        self.norm_a.x.next = self.area_abs.q.val();
        self.norm_a.exp.next = self.exp_a.q.val();

        // Setup's multipliers: the area in cycle 1, edge k's function at the start chunk's
        // first pixel centre in cycle 6 + k (from its start vertex v1, v2, v0).
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

        // ---- The scout: each probe's bound tests, its moves, the row found.
        self.out_l.next = false;
        self.out_lm.next = false;
        self.out_r.next = false;
        self.out_rn.next = false;
        self.dead.next = false;
        for k in 0..3 {
            self.scls[k].dx.next = self.sdx[k].q.val();
            self.scls[k].dy.next = self.sdy[k].q.val();
            self.s_chunk[k].next = self.scls[k].g.val() << self.lg.val();
            self.s_less[k].next = self.s_chunk[k].val() - self.scls[k].g.val();
            self.rej_ll[k].e.next = self.el[k].q.val() - self.s_less[k].val();
            self.rej_lm[k].e.next = self.el[k].q.val() + self.scls[k].g.val();
            self.rej_lf[k].e.next = self.el[k].q.val();
            self.rej_rf[k].e.next = self.er[k].q.val();
            self.rej_rn[k].e.next = self.er[k].q.val() - self.s_chunk[k].val();
            self.rej_ll[k].owns.next = self.scls[k].owns.val();
            self.rej_lm[k].owns.next = self.scls[k].owns.val();
            self.rej_lf[k].owns.next = self.scls[k].owns.val();
            self.rej_rf[k].owns.next = self.scls[k].owns.val();
            self.rej_rn[k].owns.next = self.scls[k].owns.val();
            if self.scls[k].left.val() & self.rej_ll[k].rejects.val() {
                self.out_l.next = true;
            }
            if self.scls[k].left.val() & self.rej_lm[k].rejects.val() {
                self.out_lm.next = true;
            }
            if self.scls[k].right.val() & self.rej_rf[k].rejects.val() {
                self.out_r.next = true;
            }
            if self.scls[k].right.val() & self.rej_rn[k].rejects.val() {
                self.out_rn.next = true;
            }
            if self.scls[k].flat.val() & self.rej_lf[k].rejects.val() {
                self.dead.next = true;
            }
        }
        self.l_right.next = !self.dead.val() & self.out_l.val() & (self.sl.q.val() != self.sc1.q.val());
        self.l_left.next =
            !self.dead.val() & !self.out_l.val() & !self.out_lm.val() & (self.sl.q.val() != self.sc0.q.val());
        self.r_left.next = !self.dead.val() & self.out_r.val() & (self.sr.q.val() != self.sc0.q.val());
        self.r_right.next =
            !self.dead.val() & !self.out_r.val() & !self.out_rn.val() & (self.sr.q.val() != self.sc1.q.val());
        self.found.next =
            self.sv.q.val() & !self.l_right.val() & !self.l_left.val() & !self.r_left.val() & !self.r_right.val();
        self.row_empty.next =
            self.dead.val() | self.out_l.val() | self.out_r.val() | (self.sl.q.val() > self.sr.q.val());
        self.row_last.next = self.sy.q.val() == self.sy1.q.val();
        // The walker is free in its row's last chunk; it takes a row found not empty.
        self.walk_free.next = !self.tv.q.val() | (self.tx.q.val() == self.te.q.val());

        // ---- Each stage's constants: of the set of the chunk there.
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

        // ---- The lanes: the walker's chunk, the constants; their outputs gathered.
        self.tag.next =
            (bit_cast::<TAG, SCREEN>(self.ty.q.val()) << self.y_shift.val()) | bit_cast::<TAG, SCREEN>(self.tx.q.val());
        self.tag_dl.d.next = self.tag.val();
        for i in 0..LANES {
            self.lanes[i].run.next = self.run.val();
            self.lanes[i].load.next = self.found.val() & !self.row_empty.val() & self.walk_free.val();
            self.lanes[i].valid.next = self.tv.q.val();
            self.lanes[i].x.next = self.tx.q.val();
            self.lanes[i].x0.next = self.wx0.q.val();
            self.lanes[i].x1.next = self.wx1.q.val();
            self.lanes[i].c_mant.next = self.c_mant.val();
            self.lanes[i].c_exp.next = self.c_exp.val();
            self.lanes[i].c_d1z.next = self.c_d1z.val();
            self.lanes[i].c_d2z.next = self.c_d2z.val();
            self.lanes[i].c_z0.next = self.c_z0.val();
            // Written out per edge and channel: rust-hdl substitutes a loop index in the
            // first [...] of a name only.
            self.lanes[i].g_0.next = self.scls[0].g.val();
            self.lanes[i].w_0.next = self.w[0].q.val();
            self.lanes[i].owns_0.next = self.wown[0].q.val();
            self.lanes[i].c_iw_0.next = self.c_iw[0].val();
            self.lanes[i].c_d1c_0.next = self.c_d1c[0].val();
            self.lanes[i].c_d2c_0.next = self.c_d2c[0].val();
            self.lanes[i].c_c0_0.next = self.c_c0[0].val();
            self.lanes[i].g_1.next = self.scls[1].g.val();
            self.lanes[i].w_1.next = self.w[1].q.val();
            self.lanes[i].owns_1.next = self.wown[1].q.val();
            self.lanes[i].c_iw_1.next = self.c_iw[1].val();
            self.lanes[i].c_d1c_1.next = self.c_d1c[1].val();
            self.lanes[i].c_d2c_1.next = self.c_d2c[1].val();
            self.lanes[i].c_c0_1.next = self.c_c0[1].val();
            self.lanes[i].g_2.next = self.scls[2].g.val();
            self.lanes[i].w_2.next = self.w[2].q.val();
            self.lanes[i].owns_2.next = self.wown[2].q.val();
            self.lanes[i].c_iw_2.next = self.c_iw[2].val();
            self.lanes[i].c_d1c_2.next = self.c_d1c[2].val();
            self.lanes[i].c_d2c_2.next = self.c_d2c[2].val();
            self.lanes[i].c_c0_2.next = self.c_c0[2].val();
        }
        self.out_x.next = self.o_x.q.val();
        self.out_y.next = self.o_y.q.val();

        // ---- Registers, while the unit runs.
        if self.run.val() {
            // Setup's counter, the drain's, the sets' holds.
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
            self.ph.d.next = self.ph.q.val() << self.one_s.val();
            if self.wp.q.val() {
                self.ph.d.next = (self.ph.q.val() << self.one_s.val()) | 1u64;
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
            // Cycle 1: the vertices' extremes, the top vertex's x; cycle 2: the box.
            if self.sc.q.val() == 1 {
                self.min_xr.d.next = self.min_x.val() ^ self.half_xy.val();
                self.max_xr.d.next = self.max_x.val() ^ self.half_xy.val();
                self.min_yr.d.next = self.min_y.val() ^ self.half_xy.val();
                self.max_yr.d.next = self.max_y.val() ^ self.half_xy.val();
                self.top_xr.d.next = self.top_x.val();
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
            // Cycle 3: empty? Twice the area; the start chunk.
            if self.sc.q.val() == 3 {
                self.empty.d.next =
                    self.bneg.q.val() | (self.bx0.q.val() > self.bx1.q.val()) | (self.by0.q.val() > self.by1.q.val());
                self.area.d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
                self.cs.d.next = self.top_c.val() & self.chunk_p.val();
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
                self.d1c[0].d.next =
                    bit_cast::<C1, COLOR>(self.vc[3].q.val()) - bit_cast::<C1, COLOR>(self.vc[0].q.val());
                self.d1c[1].d.next =
                    bit_cast::<C1, COLOR>(self.vc[4].q.val()) - bit_cast::<C1, COLOR>(self.vc[1].q.val());
                self.d1c[2].d.next =
                    bit_cast::<C1, COLOR>(self.vc[5].q.val()) - bit_cast::<C1, COLOR>(self.vc[2].q.val());
                self.d2c[0].d.next =
                    bit_cast::<C1, COLOR>(self.vc[6].q.val()) - bit_cast::<C1, COLOR>(self.vc[0].q.val());
                self.d2c[1].d.next =
                    bit_cast::<C1, COLOR>(self.vc[7].q.val()) - bit_cast::<C1, COLOR>(self.vc[1].q.val());
                self.d2c[2].d.next =
                    bit_cast::<C1, COLOR>(self.vc[8].q.val()) - bit_cast::<C1, COLOR>(self.vc[2].q.val());
                self.exp_a.d.next = self.lead_a.pos.val();
            }
            // Cycle 6: 1/area's divisor; cycles 8-10: the edge functions at the start chunk's
            // first pixel centre; cycle 7 + LA: 1/area's mantissa.
            if self.sc.q.val() == 6 {
                self.div_da.d.next = self.norm_a.d.val();
            }
            if self.sc.q.val() == 8 {
                self.w0[0].d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            if self.sc.q.val() == 9 {
                self.w0[1].d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            if self.sc.q.val() == 10 {
                self.w0[2].d.next = self.mul_s[0].p.val() - self.mul_s[1].p.val();
            }
            if self.sc.q.val() == self.at_mant.val() {
                self.mant.d.next = self.mant_c.val();
            }

            // The walker: a chunk a cycle to the row's last, then the next row the scout
            // found (below) or none. While it walks, its set of constants is held for the
            // chunks behind it, and the unit is not empty.
            if self.tv.q.val() {
                self.dc.d.next = self.drain.val();
                if self.wp.q.val() {
                    self.hold[1].d.next = self.held_m1.val();
                } else {
                    self.hold[0].d.next = self.held_m1.val();
                }
                if self.tx.q.val() == self.te.q.val() {
                    self.tv.d.next = false;
                } else {
                    self.tx.d.next = self.tx.q.val() + self.step.val();
                    for k in 0..3 {
                        self.w[k].d.next = self.w[k].q.val() - self.wstep[k].q.val();
                    }
                }
            }
            // The scout: probes move a chunk a cycle; a row found empty is left at once, a row
            // found not empty when the walker takes it; after the last row the scout is free.
            if self.sv.q.val() {
                if self.l_right.val() {
                    self.sl.d.next = self.sl.q.val() + self.step.val();
                    for k in 0..3 {
                        self.el[k].d.next = self.el[k].q.val() - self.s_chunk[k].val();
                    }
                }
                if self.l_left.val() {
                    self.sl.d.next = self.sl.q.val() - self.step.val();
                    for k in 0..3 {
                        self.el[k].d.next = self.el[k].q.val() + self.s_chunk[k].val();
                    }
                }
                if self.r_left.val() {
                    self.sr.d.next = self.sr.q.val() - self.step.val();
                    for k in 0..3 {
                        self.er[k].d.next = self.er[k].q.val() + self.s_chunk[k].val();
                    }
                }
                if self.r_right.val() {
                    self.sr.d.next = self.sr.q.val() + self.step.val();
                    for k in 0..3 {
                        self.er[k].d.next = self.er[k].q.val() - self.s_chunk[k].val();
                    }
                }
                if self.found.val() & (self.row_empty.val() | self.walk_free.val()) {
                    if self.row_last.val() {
                        self.sv.d.next = false;
                    } else {
                        self.sy.d.next = self.sy.q.val() + 1;
                        for k in 0..3 {
                            self.el[k].d.next = self.el[k].q.val() + self.scls[k].h.val();
                            self.er[k].d.next = self.er[k].q.val() + self.scls[k].h.val();
                        }
                    }
                }
                if self.found.val() & !self.row_empty.val() & self.walk_free.val() {
                    self.tv.d.next = true;
                    self.tx.d.next = self.sl.q.val();
                    self.te.d.next = self.sr.q.val();
                    self.ty.d.next = self.sy.q.val();
                    self.wx0.d.next = self.sx0.q.val();
                    self.wx1.d.next = self.sx1.q.val();
                    self.wp.d.next = self.sp.q.val();
                    for k in 0..3 {
                        self.w[k].d.next = self.el[k].q.val();
                        self.wown[k].d.next = self.scls[k].owns.val();
                        self.wstep[k].d.next = self.s_chunk[k].val();
                    }
                }
            }
            // The handover: setup is free from the next cycle; a non-empty box goes to the
            // scout, its first row's probes at the start chunk, its constants in the other set.
            if self.hand.val() {
                self.sbusy.d.next = false;
                self.sc.d.next = 0.into();
                if !self.empty.q.val() {
                    self.sv.d.next = true;
                    self.sp.d.next = !self.sp.q.val();
                    self.sy.d.next = bit_cast::<SCREEN, PIXEL>(self.by0.q.val());
                    self.sy1.d.next = bit_cast::<SCREEN, PIXEL>(self.by1.q.val());
                    self.sx0.d.next = bit_cast::<SCREEN, PIXEL>(self.bx0.q.val());
                    self.sx1.d.next = bit_cast::<SCREEN, PIXEL>(self.bx1.q.val());
                    self.sc0.d.next = bit_cast::<SCREEN, PIXEL>(self.bx0.q.val()) & self.chunk.val();
                    self.sc1.d.next = bit_cast::<SCREEN, PIXEL>(self.bx1.q.val()) & self.chunk.val();
                    self.sl.d.next = bit_cast::<SCREEN, PIXEL>(self.cs.q.val());
                    self.sr.d.next = bit_cast::<SCREEN, PIXEL>(self.cs.q.val());
                    for k in 0..3 {
                        self.el[k].d.next = self.w0[k].q.val();
                        self.er[k].d.next = self.w0[k].q.val();
                        self.sdx[k].d.next = self.dx[k].q.val();
                        self.sdy[k].d.next = self.dy[k].q.val();
                    }
                    if self.sp.q.val() {
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
            // The output's place: the chunk's first x and its row.
            self.o_x.d.next = bit_cast::<SCREEN, TAG>(self.tag_dl.q.val());
            self.o_y.d.next = bit_cast::<SCREEN, TAG>(self.tag_dl.q.val() >> self.y_shift.val());
        }
    }
}

crate::pins!(impl[const LANES: usize, const ZW: usize, const CW: usize] Vector<LANES, ZW, CW> {
    clock: clock,
    inputs: [width, height, out_ready],
    outputs: [idle, out_valid, out_mask, out_x, out_y, out_z, out_rgb],
    links: [inp],
});

/// `UNITS` entry: the barycentric unit with `LANES` lanes and an `L`-stage divider,
/// perspective-correct colours as `params["PERSPECTIVE"]` says.
pub fn emit_vector(params: &Params) -> Result<Emitted, String> {
    let perspective = match params["PERSPECTIVE"] {
        0 => false,
        1 => true,
        v => return Err(format!("vector: PERSPECTIVE = {v}: 0 or 1")),
    };
    let l = params["L"] as usize;
    Ok(match params["LANES"] {
        1 => emit_unit("vector", Vector::<1, DEPTH, { 3 * CHANNEL }>::new(l, perspective)?, params),
        2 => emit_unit("vector", Vector::<2, { 2 * DEPTH }, { 6 * CHANNEL }>::new(l, perspective)?, params),
        4 => emit_unit("vector", Vector::<4, { 4 * DEPTH }, { 12 * CHANNEL }>::new(l, perspective)?, params),
        8 => emit_unit("vector", Vector::<8, { 8 * DEPTH }, { 24 * CHANNEL }>::new(l, perspective)?, params),
        n => return Err(format!("vector: LANES = {n}: 1, 2, 4 or 8")),
    })
}
