//! `triangle_setup`: the iterative fixed-point triangle setup of paper 001 (Woo 2004,
//! §II.2.나-라, eq. 2, Table 3), bit-exact to `model::triangle_setup`.
//!
//! It takes one sorted triangle from `cull_sort` (the link `inp`: `links::SortedSink`) and hands
//! the edge walk `model::triangle_setup::TriangleSetupOut` without `divisions` on the link
//! `out` (`links::TriangleSetupSource`: ports `out$<field>`, nested fields joined by `_`,
//! `out$walk` high for `Walk::Up`, `out$maj_x`, `out$short0_inc1_c2`, `out$ddx_z`, ...), each
//! field the low bits of the model's value at the widths of `crate::widths` (`j`, `count`,
//! `x`: `PIXEL`; `r`, `rho`, `d`: `EDGE_D`; `q`: `EDGE_Q`; `at`: `z_acc`/`c_acc`; `inc0`,
//! `inc1`, `ddx`: `dz`/`dc`), which `edge_walk` takes on its end of the link. `count`
//! reaches 2^(PIXEL-1) = 4096 (a triangle over the whole `xy` range): read it unsigned.
//! Beside `out`, `recip_mant` and `recip_exp` give the triangle's OneOverArea
//! (`TriangleSetupOut::recip`) for the texture path of a textured `raster_top`.
//!
//! **Datapath.** `K` multipliers ([`SplitMul`], `MUL_A` x `MUL_B` bits) reused over 64
//! products, and the shared divider ([`crate::divider::Divider`]), into which setup
//! issues its seven divisions (`TriangleSetupOut::divisions`: 1/area, then per edge the
//! start and the step of the exact edge walker), each in a cycle of its own. A multiplier
//! registers its operands, its partial products (one per DSP block) and their sum, and each
//! product is added into its destination register in the cycle it comes out (three after
//! its operands went in); the model's wraps
//! (`ctx.put`) are the registers' widths, its floor shifts bit slices:
//!
//! | phase | products (A x B) | into | model |
//! |---|---|---|---|
//! | area | e_maj.dx * e_bot.dy, e_bot.dx * e_maj.dy | `area` (exact) | `area2` |
//! | normalise | - (leading one, shift) | 1/area issued | `recip_operands` |
//! | numerators | dy * (x fraction), dx * t per edge | `num` (exact) | `start_in` |
//! | eq. (2) | (OneOverArea << (15 - exp)) * (+-e.d), 4 | `p` (`ooa_d`; for exp > 15 the product >> (exp - 15), floor) | `ooa_times` |
//! | gradients | p * attribute deltas, 16 | `gx`, `gy` (mod 2^`ooa_d`); ddx, ddy are their slices | `grad` |
//! | starts, increments | ddx * off_x, ddy * off_y, ddx * q per edge and attribute, 36 | `plane`, `inc0` and `inc1 = inc0 + ddx` (mod 2^`dz`) | `at`, `inc0`, `inc1` |
//! | hand-over | - | `at = floor(plane / 2^s) + v0's` | `at` |
//!
//! The order of eq. (2) is the model's: `OOA * e.d` first (the four products every
//! attribute shares), then times the attribute difference, so no register overflows where
//! `OOA * (e_maj.dx * e_bot.dC - ...)` would (001's point). z and the colours run in
//! 40-bit lanes (`dz`); a colour keeps its low `dc`/`c_acc` bits, the only ones its
//! format holds (modular arithmetic, `fx::formats`).
//!
//! **Schedule** ([`Schedule`], `model::triangle_setup::schedule`, which the cycle model
//! reads too). Cycle 0 takes the triangle. A modulo schedule: each multiplier and the
//! divider are reserved once per cycle modulo II, so setup takes a triangle every II cycles
//! (on the grid of the last one it took, or at once when it is empty) and up to
//! `Schedule::copies` are in flight (four here). With 001's 7 multipliers and 5-stage divider (the products' operand cycles; a
//! product is added three cycles later):
//!
//! ```text
//!  cycle       0    1     2  3  5    6    7  8  10   12   13   18 19 20  22 23 24 25 26 27  31        32
//!  input       take                             take (the next triangle)
//!  products         area, numerators (7 + 1)             eq2  gradients starts, increments (6 3 7 7 7 6)
//!  normalise                   norm
//!  div. issue       q0    q1 q2 s0   1/a  s1 s2
//!  div. result                                       1/a
//!  output                                                                                   hand-over valid
//! ```
//!
//! Latency 32 (001 Table 3: 34), II 10 = ceil(64 / 7); 52 with the default 25-stage
//! divider. The gradients wait a cycle past eq. (2)'s products, so that they and the
//! starts pack into fewer cycles and every shared register lives at most II cycles
//! (`Schedule::new` tries such placements and keeps the lowest latency). |area|, its leading one (found in two levels: nibbles, then the highest nibble)
//! and the normalising shift go into registers, the shift done on the way into the
//! divider's operand register ([`DIVIDER_OPERANDS`]), and 1/area, shifted for eq. (2), into a
//! register, so that no path runs from the vertices into the divider or from the divider into
//! a multiplier. The triangle's long-lived registers (its geometry, the area's sign and
//! exponent, each edge's x, r, q, rho) are copied every II cycles, `Schedule::copies` of
//! them: cycle c reads copy (c - 1) / II through that copy's [`GeometryView`] (`g0` to
//! `g5`). The geometry ([`Geometry`]: edge vectors, scanline centres and counts, the
//! divisions' offsets, attribute differences) is computed once, from the triangle offered,
//! into copy 0's [`GeometryWord`] register as the triangle is taken, and moves on with it
//! (so no path runs through its adders into a multiplier's or the divider's operands); a
//! cycle of the schedule is due when a bit of its copy's token is set (`tok`: one
//! register, no counter or decoder before it); a division's result goes into the copy of the cycle
//! after it. Every other register is written by the
//! next triangle only after this one has read it for the last time, which `Schedule::new`
//! checks. A deeper divider (for a faster clock) keeps II at 10 up to L = 28, past the
//! default L = 25 (latency 52, six copies; beyond six, II would be a sixth of the latency). While a result waits for the edge
//! walk, all of setup waits (`run` low: every register holds, the multipliers' and the
//! divider's too), the triangles behind it too. `K` (1 to 7) trades II and latency for
//! area: II 64 and latency 89 with one multiplier; the divider's `L` stages likewise.
//!
//! Model: `model::triangle_setup::triangle_setup`. Emitted: `hdl-out/triangle_setup.v`.

#[path = "triangle_setup/geometry.rs"]
mod geometry;

use super::cull_sort::{COLOR, XY};
use super::divider::{DividerRtl, DIV_D, DIV_N, DIV_Q, LATENCY_MAX};
use super::links::{SortedSink, TriangleSetupSource};
use super::widths::{C_ACC, DC, DERIVED, DZ, EDGE_D, EDGE_Q, FORMATS, PIXEL, WIDTHS, Z_ACC};
use crate::emit::{ports, verilog, Emitted};
use crate::mul::SplitMul;
use crate::parts::defaults;
use crate::Params;
use blank::Blank;
use geometry::{Geometry, GeometryView, GeometryWord};
pub use model::triangle_setup::schedule::{Schedule, COPIES_MAX, DIVIDER_OPERANDS, MULTIPLIERS_MAX, PRODUCTS};
use rust_hdl::prelude::*;

/// Multiplier operand A: the widest factor, `ooa_d` (`config::mul_a`).
pub const MUL_A: usize = WIDTHS.mul_a;
/// Multiplier operand B: the widest second factor (`config::mul_b`); at class 10's
/// defaults a z difference, an edge delta and a step quotient are all 19 bits.
pub const MUL_B: usize = WIDTHS.mul_b;
/// Product bits kept: the wide domain (`Widths::mul_p`), so that an edge start numerator
/// goes into the divider as it is (its low `DIV_N` bits).
pub const MUL_P: usize = WIDTHS.mul_p;
/// The wide domain: vertex x sign-extended to hold both the divider's dividend and an
/// A operand (the dividend is the wider at every size class's defaults).
const W: usize = MUL_P;
/// Twice the area, exact.
const AREA: usize = DERIVED.area_bits as usize;
/// Its nibbles, and its bits in whole nibbles.
const NIB: usize = AREA.div_ceil(4);
const AREA_P: usize = 4 * NIB;
/// The narrow signed domain of the B operands and the edge geometry.
const NB: usize = MUL_B;
/// Gradients and OneOverArea x delta (`ooa_d`).
const G: usize = MUL_A;
/// The quotient bits taken into the narrow domain: all of `q_n` unless the quotient is
/// narrower (a wide z makes the narrow domain wider than the divider's quotient).
const QL: usize = if DIV_Q < NB { DIV_Q } else { NB };
/// An attribute lane: z's gradient width; colours use its low bits.
const ATTR: usize = DZ;
/// A copy's token bits: its part of the schedule is II cycles at most, and II is 64 at
/// most (one multiplier).
const TOKENS: usize = 64;
/// OneOverArea's mantissa (`ooa`).
pub const MANT: usize = FORMATS.ooa.bits() as usize;

const S: u32 = FORMATS.xy.frac;

// The shifts below are floor shifts (right), the lanes hold what they are given, and the
// products fit: `config::violation`, asserted of every build in `widths.rs`; these follow
// from it.
const _: () = assert!(DZ >= DC && DZ >= Z_ACC && DC >= C_ACC && ATTR <= MUL_P && G <= MUL_P);
const _: () = assert!(MUL_B > XY + 2 && MUL_B > COLOR && EDGE_Q + 2 <= MUL_B);

/// The triangle setup unit; see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct TriangleSetup {
    pub clock: Signal<In, Clock>,
    /// The sorted triangle in (`inp.v<k>_iw` is not read: the vector method's).
    pub inp: SortedSink,
    /// The set-up triangle, held until `out.ready`.
    pub out: TriangleSetupSource,
    /// With `out`: OneOverArea (`TriangleSetupOut::recip`), the reciprocal of |twice the
    /// area| as the divider returned it, its mantissa and the exponent of |twice the area|'s
    /// top bit: the texture path's (`rtl::raster_top_textured`), which sets up its own
    /// planes with it, so that one divider serves both.
    pub recip_mant: Signal<Out, Bits<MANT>>,
    pub recip_exp: Signal<Out, Bits<6>>,
    /// No triangle in setup (none taken and not yet handed over), from a register.
    pub idle: Signal<Out, Bit>,
    /// The edge walk is free next cycle (its `free_next`): `out.ready` then unless
    /// `out_hold`, which `stall_r` reads a cycle ahead.
    pub out_free_next: Signal<In, Bit>,
    /// The edge walk is held this cycle (its `hold`, so `out.ready` is low whatever
    /// `out_free_next` said): low in every build but the textured `raster_top`, where it is
    /// the one path from the edge walk's handshake into `run`.
    pub out_hold: Signal<In, Bit>,

    // Sub-blocks.
    mul: Vec<SplitMul<MUL_A, MUL_B, MUL_P>>,
    #[given]
    div: DividerRtl,

    take: Signal<Local, Bit>,
    /// Setup advances: no result waits for the edge walk. Every register of setup is
    /// written only while it is high (its enable), and nothing else waits for it.
    run: Signal<Local, Bit>,
    /// A result waits for the edge walk, as the walk's registers say a cycle ahead (the
    /// result valid next cycle and the walk not free then), so that `run`, which reaches
    /// every register of setup, is a register and not the walk's handshake (unless
    /// `out_hold`). Stop 57 measured that handshake into `run` and on into `cull_sort`'s
    /// enables at 14.8 ns, the walk, `run` and `cull_sort` at three corners of the die.
    stall_r: DFF<Bit>,
    valid_n: Signal<Local, Bit>,
    /// The normalise, division j's issue and result, the hand-over are due this cycle and
    /// setup runs.
    at_norm: Signal<Local, Bit>,
    at_iss: [Signal<Local, Bit>; 7],
    at_res: [Signal<Local, Bit>; 7],
    at_handover: Signal<Local, Bit>,
    /// Per copy, a triangle enters it at the end of this cycle if setup runs: copy 0's
    /// taken, copy v's handed on from copy v - 1 (at the end of its part).
    enter: [Signal<Local, Bit>; COPIES_MAX],
    /// The schedule as tokens, one per triangle in setup: per copy, one bit per cycle of
    /// its part (bit j: cycle `v II + 1 + j`), set while the copy's triangle is at that
    /// cycle. While setup runs every token moves up a bit, a triangle taken or handed on
    /// enters its copy at bit 0 and the one at the end of a part leaves it; while setup
    /// stands still every bit holds. So whatever is due in a cycle (product i's operands
    /// into its multiplier, `act`, and its addition into its destination, `add`; the
    /// normalise, division j's issue and result, the hand-over into the edge walk, the
    /// result valid, a copy's hand-over into the next) is one register, with no counter,
    /// comparison or decoder before it. (Stop 57 decoded counters a cycle ahead into
    /// registers: 150 decoders, and a counter's comparison on the path into the next
    /// copy's hand-over.)
    tok: [DFF<Bits<TOKENS>>; COPIES_MAX],
    tok_n: [Signal<Local, Bits<TOKENS>>; COPIES_MAX],
    act: [Signal<Local, Bit>; PRODUCTS],
    add: [Signal<Local, Bit>; PRODUCTS],
    valid: Signal<Local, Bit>,
    busy_r: DFF<Bit>,
    /// Setup holds a triangle and is off the II grid next cycle (`busy_r` and `off_grid_r`
    /// a cycle ahead), so that `inp.ready` is `run` and one register.
    gate_r: DFF<Bit>,
    /// Cycles of running since the last triangle was taken, modulo II, and whether that is
    /// not 0 next cycle: setup takes a triangle on the II grid of the last one (the
    /// schedule's lanes are reserved modulo II), or when it is empty.
    phase: DFF<Bits<8>>,
    off_grid_r: DFF<Bit>,
    /// `busy_r` and `off_grid_r`'s next values.
    busy_n: Signal<Local, Bit>,
    off_grid_n: Signal<Local, Bit>,

    // The triangle's registers, one copy per II cycles of its schedule (copy v at index
    // v, or 3v + edge): its geometry, computed from the triangle taken, the sign of the
    // area (from copy 1; copy 0's is the area register's), its exponent, and each edge's
    // start x, r and step q, rho (from its divisions).
    geometry: Geometry,
    geo: [DFF<GeometryWord>; COPIES_MAX],
    sign: [DFF<Bit>; COPIES_MAX],
    exp: [DFF<Bits<6>>; COPIES_MAX],
    /// OneOverArea's mantissa as the divider returned it, from the copy after its return.
    mant: [DFF<Bits<MANT>>; COPIES_MAX],
    x: [DFF<Bits<NB>>; 3 * COPIES_MAX],
    r: [DFF<Bits<EDGE_D>>; 3 * COPIES_MAX],
    q: [DFF<Bits<NB>>; 3 * COPIES_MAX],
    rho: [DFF<Bits<EDGE_D>>; 3 * COPIES_MAX],
    /// e_maj is the left side (twice the area < 0), per copy.
    maj_left: [Signal<Local, Bit>; COPIES_MAX],
    /// The geometry of each copy, by name: rust-hdl writes `g[v].count[e]`, a path with
    /// two indices, wrongly. Copies past `Schedule::copies` are never loaded, and
    /// synthesis removes them.
    g0: GeometryView,
    g1: GeometryView,
    g2: GeometryView,
    g3: GeometryView,
    g4: GeometryView,
    g5: GeometryView,

    // Normalise: |area|, its leading one's position (`exp`) and the shift that normalises
    // it into registers; shifted as it goes into the divider.
    area: DFF<Bits<AREA>>,
    area_abs: Signal<Local, Bits<AREA>>,
    /// |area| in whole nibbles; per nibble, whether it has a one and the position of its
    /// leading one, and the shift that puts it at `recip_top`: the leading one found in
    /// two levels (nibbles, then the highest nibble with a one).
    abs_p: Signal<Local, Bits<AREA_P>>,
    nib_any: [Signal<Local, Bit>; NIB],
    nib_pos: [Signal<Local, Bits<6>>; NIB],
    nib_sh: [Signal<Local, Bits<6>>; NIB],
    exp_c: Signal<Local, Bits<6>>,
    nsh_c: Signal<Local, Bits<6>>,
    norm: DFF<Bits<DIV_D>>,
    nsh: DFF<Bits<6>>,
    norm_d: Signal<Local, Bits<DIV_D>>,

    /// The divider's operands, registered ([`DIVIDER_OPERANDS`]).
    div_v: DFF<Bit>,
    div_n: DFF<Bits<DIV_N>>,
    div_d: DFF<Bits<DIV_D>>,

    // Divider results.
    /// 1/area's mantissa, shifted left by 15 - exp when exp <= 15, and for eq. (2)'s
    /// products the right shift exp - 15 and whether exp <= 15, registered from 1/area's
    /// return (the area's exponent from the copy of that cycle).
    mant_s: DFF<Bits<MUL_A>>,
    rsh: DFF<Bits<6>>,
    left: DFF<Bit>,
    exp_r: Signal<Local, Bits<6>>,
    q_n: Signal<Local, Bits<NB>>,
    /// The quotient's sign bit and its extension into `q_n` (none when the quotient is
    /// as wide as `q_n`).
    q_msb: Constant<Bits<8>>,
    q_ext: Constant<Bits<NB>>,
    r_pos: Signal<Local, Bit>,
    /// The start results' operands from the geometry of their cycle: x - 1/2's pixel, 2^s dy.
    xi: [Signal<Local, Bits<NB>>; 3],
    ed: [Signal<Local, Bits<EDGE_D>>; 3],

    // Products, as they leave their multiplier (0 when not to be added this cycle).
    pa: [Signal<Local, Bits<AREA>>; 2],
    pn: [Signal<Local, Bits<MUL_P>>; 6],
    pe: [Signal<Local, Bits<G>>; 4],
    pg: [Signal<Local, Bits<G>>; 16],
    ps: [Signal<Local, Bits<ATTR>>; 36],
    /// eq. (2)'s B operands: +-e_maj.dx, e_bot.dx, e_maj.dy, e_bot.dy (sign of the area),
    /// per copy (4v + d).
    delta: [Signal<Local, Bits<NB>>; 4 * COPIES_MAX],
    eq_b: [Signal<Local, Bits<NB>>; 4 * COPIES_MAX],
    /// The B operands from the geometry of their product's cycle: eq. (2)'s, the
    /// gradients' (the attribute differences), the starts' (x and y offsets, per edge and
    /// attribute).
    op_e: [Signal<Local, Bits<NB>>; 4],
    op_g: [Signal<Local, Bits<NB>>; 16],
    op_s: [Signal<Local, Bits<NB>>; 24],
    /// The increments' B operand, q, from the copy of their cycle (4e + a).
    op_q: [Signal<Local, Bits<NB>>; 12],
    /// v0's attributes, from the copy the hand-over reads.
    attr0: [Signal<Local, Bits<ATTR>>; 4],
    /// eq. (2)'s products shifted right by exp - 15 (floor), for exp > 15; for exp <= 15
    /// the mantissa goes into the multipliers shifted left by 15 - exp instead.
    shr: [Signal<Local, Bits<G>>; 4],
    lsh: Signal<Local, Bits<6>>,

    // Accumulators, and what each adds its products to: itself, or 0 for the first.
    area_base: Signal<Local, Bits<AREA>>,
    num_base: [Signal<Local, Bits<MUL_P>>; 3],
    gx_base: [Signal<Local, Bits<G>>; 4],
    gy_base: [Signal<Local, Bits<G>>; 4],
    plane_base: [Signal<Local, Bits<ATTR>>; 12],
    num: [DFF<Bits<MUL_P>>; 3],
    p: [DFF<Bits<G>>; 4],
    gx: [DFF<Bits<G>>; 4],
    gy: [DFF<Bits<G>>; 4],
    /// ddx, ddy of each attribute as a lane (the gradients' slices).
    ddx: [Signal<Local, Bits<G>>; 4],
    ddy: [Signal<Local, Bits<G>>; 4],
    plane: [DFF<Bits<ATTR>>; 12],
    inc0: [DFF<Bits<ATTR>>; 12],
    inc1: [DFF<Bits<ATTR>>; 12],
    /// ddx, registered with each increment for the result; the walk direction, the side
    /// of e_maj and each edge's first scanline, count and 2^s dy, registered at the hand-over.
    ddx_o: [DFF<Bits<ATTR>>; 4],
    o_walk: DFF<Bit>,
    o_maj_left: DFF<Bit>,
    o_j: [DFF<Bits<PIXEL>>; 3],
    o_count: [DFF<Bits<PIXEL>>; 3],
    o_d: [DFF<Bits<EDGE_D>>; 3],

    // The schedule and the numbers a kernel cannot name.
    lane: [Constant<Bits<8>>; PRODUCTS],
    /// The copy product i's operands, division j's result, the hand-over read
    /// (`Schedule::view`); the copy division j's result is written into (that of the cycle
    /// after, as copies move on at the end of a cycle).
    view: [Constant<Bits<8>>; PRODUCTS],
    view_add: [Constant<Bits<8>>; PRODUCTS],
    view_res: [Constant<Bits<8>>; 7],
    view_res_w: [Constant<Bits<8>>; 7],
    view_handover: Constant<Bits<8>>,
    /// The schedule's cycles as the bits of their copies' tokens: product i's operands and
    /// addition, the normalise, division j's issue and result, the hand-over, the result
    /// (the last copy's), and the end of each copy's part but the last (its hand-over into
    /// the next; 0 for copies not used, which `tok_mask` keeps empty).
    act_bit: [Constant<Bits<8>>; PRODUCTS],
    add_bit: [Constant<Bits<8>>; PRODUCTS],
    norm_bit: Constant<Bits<8>>,
    iss_bit: [Constant<Bits<8>>; 7],
    res_bit: [Constant<Bits<8>>; 7],
    handover_bit: Constant<Bits<8>>,
    last_bit: Constant<Bits<8>>,
    end_bit: [Constant<Bits<8>>; COPIES_MAX - 1],
    /// Per copy, the bits of its part.
    tok_mask: [Constant<Bits<TOKENS>>; COPIES_MAX],
    /// II - 1.
    ii_m1: Constant<Bits<8>>,
    /// 2^56: 1/area's dividend (`recip_operands`); the exponent of 1/area's top bit (32).
    recip_n: Constant<Bits<DIV_N>>,
    recip_top: Constant<Bits<6>>,
    /// i, for the leading one's position.
    bit_index: [Constant<Bits<6>>; AREA_P],
    /// `ooa_d.frac + s - ooa.frac` (15): eq. (2)'s shift is this less exp.
    eq_shift: Constant<Bits<6>>,
    /// Per attribute: the gradient's slice (`ooa_d.frac + z.frac - dz.frac` and the
    /// colours'), and v0's shift into the accumulator (`z_acc.frac - z.frac`, ...).
    gsh: [Constant<Bits<8>>; 4],
    bsh: [Constant<Bits<8>>; 4],
    /// s; the sign bits of the area and of eq. (2)'s products; ones in `G` bits.
    frac: Constant<Bits<8>>,
    area_msb: Constant<Bits<8>>,
    p_msb: Constant<Bits<8>>,
    ones: Constant<Bits<G>>,
    _k: usize,
    _copies: usize,
}

/// An array of `N` constants from `f(i)`.
fn consts<const B: usize, const N: usize>(f: impl Fn(usize) -> usize) -> [Constant<Bits<B>>; N] {
    std::array::from_fn(|i| Constant::new(f(i).to_bits()))
}

/// Ones from bit `from` up to bit `to - 1`, as a `to`-bit constant or wider.
pub(crate) fn ones_from<const B: usize>(from: usize, to: usize) -> Constant<Bits<B>> {
    Constant::new((((1u128 << (to - from)) - 1) << from).to_bits())
}

impl TriangleSetup {
    /// Setup with `k` multipliers and an `l`-stage divider (see [`Schedule::new`]).
    pub fn new(k: usize, l: usize) -> Result<TriangleSetup, String> {
        if !(1..=LATENCY_MAX).contains(&l) {
            return Err(format!("triangle_setup: L = {l} divider stages is not supported: 1 to {LATENCY_MAX}"));
        }
        let s = Schedule::new(k, l)?;
        // A copy's part fits its token bits, and the phase II - 1 its 8 bits.
        assert!(s.interval <= TOKENS, "triangle_setup: K = {k}, L = {l}: II {} over {TOKENS}", s.interval);
        // The normalise and the issues read copy 0's token.
        assert!(
            s.view(s.normalise) == 0 && s.issue.iter().all(|&c| s.view(c) == 0),
            "triangle_setup: K = {k}, L = {l}: the normalise and the issues lie in copy 0's part"
        );
        // Cycle c (1 to the latency) as a bit of its copy's token.
        let bit = |c: usize| c - 1 - s.view(c) * s.interval;
        let part = |v: usize| if v < s.copies { ((v + 1) * s.interval).min(s.latency) - v * s.interval } else { 0 };
        let f = FORMATS;
        let (gz, gc) =
            ((f.ooa_d.frac + f.z.frac - f.dz.frac) as usize, (f.ooa_d.frac + f.color.frac - f.dc.frac) as usize);
        let (bz, bc) = ((f.z_acc.frac - f.z.frac) as usize, (f.c_acc.frac - f.color.frac) as usize);
        Ok(TriangleSetup {
            mul: (0..k).map(|_| Default::default()).collect(),
            at_iss: defaults(),
            at_res: defaults(),
            tok: defaults(),
            tok_n: defaults(),
            act: defaults(),
            add: defaults(),
            sign: defaults(),
            exp: defaults(),
            mant: defaults(),
            x: defaults(),
            r: defaults(),
            q: defaults(),
            rho: defaults(),
            maj_left: defaults(),
            nib_any: defaults(),
            nib_pos: defaults(),
            nib_sh: defaults(),
            bit_index: consts(|i| i),
            q_msb: Constant::new((QL - 1).to_bits()),
            q_ext: ones_from(QL, NB),
            xi: defaults(),
            ed: defaults(),
            pa: defaults(),
            pn: defaults(),
            pe: defaults(),
            pg: defaults(),
            ps: defaults(),
            delta: defaults(),
            eq_b: defaults(),
            op_e: defaults(),
            op_g: defaults(),
            op_s: defaults(),
            op_q: defaults(),
            attr0: defaults(),
            shr: defaults(),
            num_base: defaults(),
            gx_base: defaults(),
            gy_base: defaults(),
            plane_base: defaults(),
            num: defaults(),
            p: defaults(),
            gx: defaults(),
            gy: defaults(),
            ddx: defaults(),
            ddy: defaults(),
            plane: defaults(),
            inc0: defaults(),
            inc1: defaults(),
            ddx_o: defaults(),
            o_j: defaults(),
            o_count: defaults(),
            o_d: defaults(),
            lane: consts(|i| s.slots[i].1),
            view: consts(|i| s.view(s.slots[i].0)),
            view_add: consts(|i| s.view(s.add(i))),
            view_res: consts(|j| s.view(s.result(j))),
            view_res_w: consts(|j| s.view(s.result(j) + 1)),
            view_handover: Constant::new(s.view(s.handover).to_bits()),
            act_bit: consts(|i| bit(s.slots[i].0)),
            add_bit: consts(|i| bit(s.add(i))),
            norm_bit: Constant::new(bit(s.normalise).to_bits()),
            iss_bit: consts(|j| bit(s.issue[j])),
            res_bit: consts(|j| bit(s.result(j))),
            handover_bit: Constant::new(bit(s.handover).to_bits()),
            last_bit: Constant::new(bit(s.latency).to_bits()),
            end_bit: consts(|v| part(v).max(1) - 1),
            tok_mask: std::array::from_fn(|v| ones_from(0, part(v))),
            ii_m1: Constant::new((s.interval - 1).to_bits()),
            recip_n: Constant::new((1u128 << (DERIVED.area_bits - 2 + f.ooa.frac)).to_bits()),
            recip_top: Constant::new(((DERIVED.area_bits - 2) as usize).to_bits()),
            eq_shift: Constant::new(((f.ooa_d.frac + S - f.ooa.frac) as usize).to_bits()),
            gsh: consts(|a| if a == 0 { gz } else { gc }),
            bsh: consts(|a| if a == 0 { bz } else { bc }),
            frac: Constant::new((S as usize).to_bits()),
            area_msb: Constant::new((AREA - 1).to_bits()),
            p_msb: Constant::new((G - 1).to_bits()),
            ones: ones_from(0, G),
            _k: k,
            _copies: s.copies,
            ..TriangleSetup::blank(TriangleSetupGiven { div: DividerRtl::new(l) })
        })
    }
}

impl Logic for TriangleSetup {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- Clocks; every register holds unless written.
        dff_setup!(
            self, clock, area, norm, nsh, div_v, div_n, div_d, mant_s, rsh, left, busy_r, gate_r, phase, off_grid_r,
            stall_r
        );
        dff_setup!(self, clock, o_walk, o_maj_left);
        for e in 0..3 {
            self.o_j[e].clock.next = self.clock.val();
            self.o_j[e].d.next = self.o_j[e].q.val();
            self.o_count[e].clock.next = self.clock.val();
            self.o_count[e].d.next = self.o_count[e].q.val();
            self.o_d[e].clock.next = self.clock.val();
            self.o_d[e].d.next = self.o_d[e].q.val();
        }
        clock!(self, clock, div);
        for v in 0..COPIES_MAX {
            self.tok[v].clock.next = self.clock.val();
            self.geo[v].clock.next = self.clock.val();
            self.geo[v].d.next = self.geo[v].q.val();
            self.sign[v].clock.next = self.clock.val();
            self.sign[v].d.next = self.sign[v].q.val();
            self.exp[v].clock.next = self.clock.val();
            self.exp[v].d.next = self.exp[v].q.val();
            self.mant[v].clock.next = self.clock.val();
            self.mant[v].d.next = self.mant[v].q.val();
            for i in 0..3 {
                self.x[3 * v + i].clock.next = self.clock.val();
                self.x[3 * v + i].d.next = self.x[3 * v + i].q.val();
                self.r[3 * v + i].clock.next = self.clock.val();
                self.r[3 * v + i].d.next = self.r[3 * v + i].q.val();
                self.q[3 * v + i].clock.next = self.clock.val();
                self.q[3 * v + i].d.next = self.q[3 * v + i].q.val();
                self.rho[3 * v + i].clock.next = self.clock.val();
                self.rho[3 * v + i].d.next = self.rho[3 * v + i].q.val();
            }
        }
        for i in 0..3 {
            self.num[i].clock.next = self.clock.val();
            self.num[i].d.next = self.num[i].q.val();
        }
        for a in 0..4 {
            self.p[a].clock.next = self.clock.val();
            self.p[a].d.next = self.p[a].q.val();
            self.gx[a].clock.next = self.clock.val();
            self.gx[a].d.next = self.gx[a].q.val();
            self.gy[a].clock.next = self.clock.val();
            self.gy[a].d.next = self.gy[a].q.val();
            self.ddx_o[a].clock.next = self.clock.val();
            self.ddx_o[a].d.next = self.ddx_o[a].q.val();
        }
        for m in 0..self._k {
            self.mul[m].clock.next = self.clock.val();
        }
        for i in 0..12 {
            self.plane[i].clock.next = self.clock.val();
            self.plane[i].d.next = self.plane[i].q.val();
            self.inc0[i].clock.next = self.clock.val();
            self.inc0[i].d.next = self.inc0[i].q.val();
            self.inc1[i].clock.next = self.clock.val();
            self.inc1[i].d.next = self.inc1[i].q.val();
        }
        // The area's sign: copy 0's from the area register, the others' as copied.
        self.maj_left[0].next = self.area.q.val().get_bit(self.area_msb.val().index());
        for v in 1..COPIES_MAX {
            self.maj_left[v].next = self.sign[v].q.val();
        }

        // ---- Control. Everything waits while a result is not taken. Otherwise each copy's
        // triangle moves on, into the next copy at the end of its part; setup takes a triangle
        // into copy 0 on the II grid of the last one taken (the copy there reaches cycle II),
        // or when setup is empty.
        for v in (self._copies - 1)..self._copies {
            self.valid.next = self.tok[v].q.val().get_bit(self.last_bit.val().index());
        }
        self.run.next = !self.stall_r.q.val() & !(self.valid.val() & self.out_hold.val() & !self.out.ready.val());
        self.out.valid.next = self.valid.val();
        self.inp.ready.next = self.run.val() & !self.gate_r.q.val();
        self.take.next = self.inp.valid.val() & self.inp.ready.val();
        if self.run.val() {
            self.phase.d.next = self.phase.q.val() + 1;
            if self.phase.q.val() == self.ii_m1.val() {
                self.phase.d.next = 0.into();
            }
            if self.take.val() {
                self.phase.d.next = 1.into();
            }
            for v in 0..(self._copies - 1) {
                if self.enter[v + 1].val() {
                    self.geo[v + 1].d.next = self.geo[v].q.val();
                    self.sign[v + 1].d.next = self.maj_left[v].val();
                    self.exp[v + 1].d.next = self.exp[v].q.val();
                    self.mant[v + 1].d.next = self.mant[v].q.val();
                    for i in 0..3 {
                        self.x[3 * v + 3 + i].d.next = self.x[3 * v + i].q.val();
                        self.r[3 * v + 3 + i].d.next = self.r[3 * v + i].q.val();
                        self.q[3 * v + 3 + i].d.next = self.q[3 * v + i].q.val();
                        self.rho[3 * v + 3 + i].d.next = self.rho[3 * v + i].q.val();
                    }
                }
            }
        }
        if self.take.val() {
            self.geo[0].d.next = self.geometry.word.val();
        }
        // The tokens move on while setup runs (`tok`).
        self.enter[0].next = self.take.val();
        for v in 1..COPIES_MAX {
            self.enter[v].next = self.tok[v - 1].q.val().get_bit(self.end_bit[v - 1].val().index());
        }
        for v in 0..COPIES_MAX {
            self.tok_n[v].next = self.tok[v].q.val();
            if self.run.val() {
                self.tok_n[v].next = (self.tok[v].q.val() << 1) & self.tok_mask[v].val();
                if self.enter[v].val() {
                    self.tok_n[v].next = ((self.tok[v].q.val() << 1) | 1) & self.tok_mask[v].val();
                }
            }
            self.tok[v].d.next = self.tok_n[v].val();
        }
        for v in (self._copies - 1)..self._copies {
            self.valid_n.next = self.tok_n[v].val().get_bit(self.last_bit.val().index());
        }
        self.stall_r.d.next = self.valid_n.val() & !self.out_free_next.val();
        // What is due this cycle: a bit of its copy's token.
        for i in 0..PRODUCTS {
            self.act[i].next = false;
            self.add[i].next = false;
            for v in 0..self._copies {
                if self.view[i].val().index() == v {
                    self.act[i].next = self.tok[v].q.val().get_bit(self.act_bit[i].val().index());
                }
                if self.view_add[i].val().index() == v {
                    self.add[i].next = self.tok[v].q.val().get_bit(self.add_bit[i].val().index());
                }
            }
        }
        self.at_norm.next = self.tok[0].q.val().get_bit(self.norm_bit.val().index()) & self.run.val();
        for j in 0..7 {
            self.at_iss[j].next = self.tok[0].q.val().get_bit(self.iss_bit[j].val().index()) & self.run.val();
            self.at_res[j].next = false;
            for v in 0..self._copies {
                if self.view_res[j].val().index() == v {
                    self.at_res[j].next = self.tok[v].q.val().get_bit(self.res_bit[j].val().index()) & self.run.val();
                }
            }
        }
        self.at_handover.next = false;
        for v in 0..self._copies {
            if self.view_handover.val().index() == v {
                self.at_handover.next = self.tok[v].q.val().get_bit(self.handover_bit.val().index()) & self.run.val();
            }
        }
        // A triangle is in setup next cycle (a token), and setup is off the II grid next
        // cycle: a cycle ahead, so that `inp.ready` is `run` and one register.
        self.busy_n.next = false;
        for v in 0..COPIES_MAX {
            if self.tok_n[v].val().any() {
                self.busy_n.next = true;
            }
        }
        self.off_grid_n.next = self.off_grid_r.q.val();
        if self.run.val() {
            // The phase is 0 next cycle only at the end of an II not ended by a take.
            self.off_grid_n.next = self.take.val() | (self.phase.q.val() != self.ii_m1.val());
        }
        self.busy_r.d.next = self.busy_n.val();
        self.off_grid_r.d.next = self.off_grid_n.val();
        self.gate_r.d.next = self.busy_n.val() & self.off_grid_n.val();
        self.idle.next = !self.busy_r.q.val();

        // ---- Geometry: computed from the triangle offered (into copy 0's register when
        // taken), and each copy's by name.
        self.geometry.vx[0].next = self.inp.v0_x.val();
        self.geometry.vy[0].next = self.inp.v0_y.val();
        self.geometry.vz[0].next = self.inp.v0_z.val();
        self.geometry.vc[0].next = self.inp.v0_c0.val();
        self.geometry.vc[1].next = self.inp.v0_c1.val();
        self.geometry.vc[2].next = self.inp.v0_c2.val();
        self.geometry.vx[1].next = self.inp.v1_x.val();
        self.geometry.vy[1].next = self.inp.v1_y.val();
        self.geometry.vz[1].next = self.inp.v1_z.val();
        self.geometry.vc[3].next = self.inp.v1_c0.val();
        self.geometry.vc[4].next = self.inp.v1_c1.val();
        self.geometry.vc[5].next = self.inp.v1_c2.val();
        self.geometry.vx[2].next = self.inp.v2_x.val();
        self.geometry.vy[2].next = self.inp.v2_y.val();
        self.geometry.vz[2].next = self.inp.v2_z.val();
        self.geometry.vc[6].next = self.inp.v2_c0.val();
        self.geometry.vc[7].next = self.inp.v2_c1.val();
        self.geometry.vc[8].next = self.inp.v2_c2.val();
        self.geometry.crosses.next = self.inp.crosses.val();
        self.g0.word.next = self.geo[0].q.val();
        self.g0.maj_left.next = self.maj_left[0].val();
        for i in 0..3 {
            self.g0.start_x[i].next = self.x[i].q.val();
        }
        self.g1.word.next = self.geo[1].q.val();
        self.g1.maj_left.next = self.maj_left[1].val();
        for i in 0..3 {
            self.g1.start_x[i].next = self.x[3 + i].q.val();
        }
        self.g2.word.next = self.geo[2].q.val();
        self.g2.maj_left.next = self.maj_left[2].val();
        for i in 0..3 {
            self.g2.start_x[i].next = self.x[6 + i].q.val();
        }
        self.g3.word.next = self.geo[3].q.val();
        self.g3.maj_left.next = self.maj_left[3].val();
        for i in 0..3 {
            self.g3.start_x[i].next = self.x[9 + i].q.val();
        }
        self.g4.word.next = self.geo[4].q.val();
        self.g4.maj_left.next = self.maj_left[4].val();
        for i in 0..3 {
            self.g4.start_x[i].next = self.x[12 + i].q.val();
        }
        self.g5.word.next = self.geo[5].q.val();
        self.g5.maj_left.next = self.maj_left[5].val();
        for i in 0..3 {
            self.g5.start_x[i].next = self.x[15 + i].q.val();
        }

        // ---- Normalise twice the area for 1/area (`recip_operands`): |a| << (32 - exp).
        // |a|, exp and the shift into registers; the shift is done as 1/area is issued.
        self.area_abs.next = self.area.q.val();
        if self.area.q.val().get_bit(self.area_msb.val().index()) {
            self.area_abs.next = bits::<AREA>(0) - self.area.q.val();
        }
        self.abs_p.next = bit_cast::<AREA_P, AREA>(self.area_abs.val());
        for g in 0..NIB {
            self.nib_any[g].next = false;
            self.nib_pos[g].next = 0.into();
            for j in 0..4 {
                if self.abs_p.val().get_bit(4 * g + j) {
                    self.nib_any[g].next = true;
                    self.nib_pos[g].next = self.bit_index[4 * g + j].val();
                }
            }
            self.nib_sh[g].next = self.recip_top.val() - self.nib_pos[g].val();
        }
        self.exp_c.next = 0.into();
        self.nsh_c.next = self.recip_top.val();
        for g in 0..NIB {
            if self.nib_any[g].val() {
                self.exp_c.next = self.nib_pos[g].val();
                self.nsh_c.next = self.nib_sh[g].val();
            }
        }
        if self.at_norm.val() {
            self.norm.d.next = self.area_abs.val();
            self.nsh.d.next = self.nsh_c.val();
            self.exp[0].d.next = self.exp_c.val();
        }
        self.norm_d.next = self.norm.q.val() << self.nsh.q.val();

        // ---- The divider: seven divisions issued in the first II cycles (copy 0,
        // `Schedule::build`) into its operand register (held, as the divider is, while
        // setup waits), results taken in any.
        self.div.out_ready.next = true;
        self.div.hold.next = !self.run.val();
        self.div.inp_valid.next = self.div_v.q.val();
        self.div.inp_n.next = self.div_n.q.val();
        self.div.inp_d.next = self.div_d.q.val();
        self.div_v.d.next = self.div_v.q.val();
        self.div_n.d.next = self.div_n.q.val();
        self.div_d.d.next = self.div_d.q.val();
        if self.run.val() {
            self.div_v.d.next = false;
            self.div_n.d.next = 0.into();
            self.div_d.d.next = 1.into();
        }
        if self.at_iss[0].val() {
            self.div_v.d.next = true;
            self.div_n.d.next = self.recip_n.val();
            self.div_d.d.next = self.norm_d.val();
        }
        for e in 0..3 {
            // Unused divisions go in as 0/1 (`model::divider`).
            if self.at_iss[1 + 2 * e].val() {
                self.div_v.d.next = true;
                if self.g0.used[e].val() {
                    self.div_n.d.next = self.num[e].q.val().get_bits::<DIV_N>(0);
                    self.div_d.d.next = self.g0.ed16[e].val();
                }
            }
            if self.at_iss[2 + 2 * e].val() {
                self.div_v.d.next = true;
                if self.g0.step[e].val() {
                    self.div_n.d.next = self.g0.edx[e].val().get_bits::<DIV_N>(0);
                    self.div_d.d.next = self.g0.edy_d[e].val();
                }
            }
        }
        // The step quotient (|q| <= |dx| fits both), sign-extended when narrower.
        self.q_n.next = bit_cast::<NB, QL>(self.div.out_q.val().get_bits::<QL>(0));
        if self.div.out_q.val().get_bit(self.q_msb.val().index()) {
            self.q_n.next = bit_cast::<NB, QL>(self.div.out_q.val().get_bits::<QL>(0)) | self.q_ext.val();
        }
        self.r_pos.next = self.div.out_r.val() != 0;
        // 1/area as it comes back, with eq. (2)'s shift, 15 - exp, on it when that is a
        // left shift, and the area's exponent, into registers for eq. (2).
        self.exp_r.next = self.exp[0].q.val();
        for v in 1..self._copies {
            if self.view_res[0].val().index() == v {
                self.exp_r.next = self.exp[v].q.val();
            }
        }
        self.lsh.next = self.eq_shift.val() - self.exp_r.val();
        if self.at_res[0].val() {
            self.rsh.d.next = self.exp_r.val() - self.eq_shift.val();
            self.left.d.next = self.exp_r.val() <= self.eq_shift.val();
            self.mant_s.d.next = bit_cast::<MUL_A, MANT>(self.div.out_q.val().get_bits::<MANT>(0));
            if self.exp_r.val() <= self.eq_shift.val() {
                self.mant_s.d.next =
                    bit_cast::<MUL_A, MANT>(self.div.out_q.val().get_bits::<MANT>(0)) << self.lsh.val();
            }
        }
        for e in 0..3 {
            // The start: x = first pixel at or right of the edge, r = x*D - num in [0, D).
            self.xi[e].next = self.g0.xi[e].val();
            self.ed[e].next = self.g0.ed16[e].val().get_bits::<EDGE_D>(0);
            if self.view_res[1 + 2 * e].val().index() == 1 {
                self.xi[e].next = self.g1.xi[e].val();
                self.ed[e].next = self.g1.ed16[e].val().get_bits::<EDGE_D>(0);
            }
            if self.view_res[1 + 2 * e].val().index() == 2 {
                self.xi[e].next = self.g2.xi[e].val();
                self.ed[e].next = self.g2.ed16[e].val().get_bits::<EDGE_D>(0);
            }
            if self.view_res[1 + 2 * e].val().index() == 3 {
                self.xi[e].next = self.g3.xi[e].val();
                self.ed[e].next = self.g3.ed16[e].val().get_bits::<EDGE_D>(0);
            }
            if self.view_res[1 + 2 * e].val().index() == 4 {
                self.xi[e].next = self.g4.xi[e].val();
                self.ed[e].next = self.g4.ed16[e].val().get_bits::<EDGE_D>(0);
            }
            if self.view_res[1 + 2 * e].val().index() == 5 {
                self.xi[e].next = self.g5.xi[e].val();
                self.ed[e].next = self.g5.ed16[e].val().get_bits::<EDGE_D>(0);
            }
            // Into the copy the triangle is in next cycle.
            for v in 0..self._copies {
                if self.at_res[1 + 2 * e].val() & (self.view_res_w[1 + 2 * e].val().index() == v) {
                    self.x[3 * v + e].d.next = self.xi[e].val() + self.q_n.val() + self.r_pos.val();
                    self.r[3 * v + e].d.next = 0.into();
                    if self.r_pos.val() {
                        self.r[3 * v + e].d.next = self.ed[e].val() - self.div.out_r.val().get_bits::<EDGE_D>(0);
                    }
                }
                // The step: q + rho/D pixels per scanline.
                if self.at_res[2 + 2 * e].val() & (self.view_res_w[2 + 2 * e].val().index() == v) {
                    self.q[3 * v + e].d.next = self.q_n.val();
                    self.rho[3 * v + e].d.next = self.div.out_r.val().get_bits::<EDGE_D>(0) << self.frac.val();
                }
            }
        }
        // OneOverArea as it returned, for the texture path, into the copy of the cycle after.
        for v in 0..self._copies {
            if self.at_res[0].val() & (self.view_res_w[0].val().index() == v) {
                self.mant[v].d.next = self.div.out_q.val().get_bits::<MANT>(0);
            }
        }

        // ---- The multipliers: each product on its multiplier in its cycle.
        for m in 0..self._k {
            self.mul[m].a.next = 0.into();
            self.mul[m].b.next = 0.into();
        }
        for i in 0..2 {
            self.pa[i].next = 0.into();
        }
        for i in 0..6 {
            self.pn[i].next = 0.into();
        }
        for i in 0..4 {
            self.pe[i].next = 0.into();
        }
        for i in 0..16 {
            self.pg[i].next = 0.into();
        }
        for i in 0..36 {
            self.ps[i].next = 0.into();
        }
        // eq. (2)'s second factors: the edge deltas with the area's sign, of each copy.
        for k in 0..2 {
            self.delta[k].next = self.g0.kdx[k].val().get_bits::<NB>(0);
            self.delta[2 + k].next = self.g0.kdy[k].val().get_bits::<NB>(0);
            self.delta[4 + k].next = self.g1.kdx[k].val().get_bits::<NB>(0);
            self.delta[6 + k].next = self.g1.kdy[k].val().get_bits::<NB>(0);
            self.delta[8 + k].next = self.g2.kdx[k].val().get_bits::<NB>(0);
            self.delta[10 + k].next = self.g2.kdy[k].val().get_bits::<NB>(0);
            self.delta[12 + k].next = self.g3.kdx[k].val().get_bits::<NB>(0);
            self.delta[14 + k].next = self.g3.kdy[k].val().get_bits::<NB>(0);
            self.delta[16 + k].next = self.g4.kdx[k].val().get_bits::<NB>(0);
            self.delta[18 + k].next = self.g4.kdy[k].val().get_bits::<NB>(0);
            self.delta[20 + k].next = self.g5.kdx[k].val().get_bits::<NB>(0);
            self.delta[22 + k].next = self.g5.kdy[k].val().get_bits::<NB>(0);
        }
        for v in 0..COPIES_MAX {
            for d in 0..4 {
                self.eq_b[4 * v + d].next = self.delta[4 * v + d].val();
                if self.maj_left[v].val() {
                    self.eq_b[4 * v + d].next = bits::<NB>(0) - self.delta[4 * v + d].val();
                }
            }
        }
        // The B operands of eq. (2), the gradients and the starts from the copy of their
        // cycle (`Schedule::view`; constants, so no multiplexers are built).
        for d in 0..4 {
            self.op_e[d].next = self.eq_b[d].val();
        }
        for a in 0..4 {
            self.op_g[4 * a].next = self.g0.dmaj[a].val();
            self.op_g[4 * a + 1].next = self.g0.dbot[a].val();
            self.op_g[4 * a + 2].next = self.g0.dbot[a].val();
            self.op_g[4 * a + 3].next = self.g0.dmaj[a].val();
        }
        for e in 0..3 {
            for a in 0..4 {
                self.op_s[8 * e + 2 * a].next = self.g0.off_x[e].val();
                self.op_s[8 * e + 2 * a + 1].next = self.g0.off_y[e].val();
            }
        }
        for d in 0..4 {
            if self.view[8 + d].val().index() == 1 {
                self.op_e[d].next = self.eq_b[4 + d].val();
            }
        }
        for a in 0..4 {
            if self.view[12 + 4 * a].val().index() == 1 {
                self.op_g[4 * a].next = self.g1.dmaj[a].val();
            }
            if self.view[13 + 4 * a].val().index() == 1 {
                self.op_g[4 * a + 1].next = self.g1.dbot[a].val();
            }
            if self.view[14 + 4 * a].val().index() == 1 {
                self.op_g[4 * a + 2].next = self.g1.dbot[a].val();
            }
            if self.view[15 + 4 * a].val().index() == 1 {
                self.op_g[4 * a + 3].next = self.g1.dmaj[a].val();
            }
        }
        for e in 0..3 {
            for a in 0..4 {
                if self.view[28 + 12 * e + 3 * a].val().index() == 1 {
                    self.op_s[8 * e + 2 * a].next = self.g1.off_x[e].val();
                }
                if self.view[29 + 12 * e + 3 * a].val().index() == 1 {
                    self.op_s[8 * e + 2 * a + 1].next = self.g1.off_y[e].val();
                }
            }
        }
        for d in 0..4 {
            if self.view[8 + d].val().index() == 2 {
                self.op_e[d].next = self.eq_b[8 + d].val();
            }
        }
        for a in 0..4 {
            if self.view[12 + 4 * a].val().index() == 2 {
                self.op_g[4 * a].next = self.g2.dmaj[a].val();
            }
            if self.view[13 + 4 * a].val().index() == 2 {
                self.op_g[4 * a + 1].next = self.g2.dbot[a].val();
            }
            if self.view[14 + 4 * a].val().index() == 2 {
                self.op_g[4 * a + 2].next = self.g2.dbot[a].val();
            }
            if self.view[15 + 4 * a].val().index() == 2 {
                self.op_g[4 * a + 3].next = self.g2.dmaj[a].val();
            }
        }
        for e in 0..3 {
            for a in 0..4 {
                if self.view[28 + 12 * e + 3 * a].val().index() == 2 {
                    self.op_s[8 * e + 2 * a].next = self.g2.off_x[e].val();
                }
                if self.view[29 + 12 * e + 3 * a].val().index() == 2 {
                    self.op_s[8 * e + 2 * a + 1].next = self.g2.off_y[e].val();
                }
            }
        }
        for d in 0..4 {
            if self.view[8 + d].val().index() == 3 {
                self.op_e[d].next = self.eq_b[12 + d].val();
            }
        }
        for a in 0..4 {
            if self.view[12 + 4 * a].val().index() == 3 {
                self.op_g[4 * a].next = self.g3.dmaj[a].val();
            }
            if self.view[13 + 4 * a].val().index() == 3 {
                self.op_g[4 * a + 1].next = self.g3.dbot[a].val();
            }
            if self.view[14 + 4 * a].val().index() == 3 {
                self.op_g[4 * a + 2].next = self.g3.dbot[a].val();
            }
            if self.view[15 + 4 * a].val().index() == 3 {
                self.op_g[4 * a + 3].next = self.g3.dmaj[a].val();
            }
        }
        for e in 0..3 {
            for a in 0..4 {
                if self.view[28 + 12 * e + 3 * a].val().index() == 3 {
                    self.op_s[8 * e + 2 * a].next = self.g3.off_x[e].val();
                }
                if self.view[29 + 12 * e + 3 * a].val().index() == 3 {
                    self.op_s[8 * e + 2 * a + 1].next = self.g3.off_y[e].val();
                }
            }
        }
        for d in 0..4 {
            if self.view[8 + d].val().index() == 4 {
                self.op_e[d].next = self.eq_b[16 + d].val();
            }
        }
        for a in 0..4 {
            if self.view[12 + 4 * a].val().index() == 4 {
                self.op_g[4 * a].next = self.g4.dmaj[a].val();
            }
            if self.view[13 + 4 * a].val().index() == 4 {
                self.op_g[4 * a + 1].next = self.g4.dbot[a].val();
            }
            if self.view[14 + 4 * a].val().index() == 4 {
                self.op_g[4 * a + 2].next = self.g4.dbot[a].val();
            }
            if self.view[15 + 4 * a].val().index() == 4 {
                self.op_g[4 * a + 3].next = self.g4.dmaj[a].val();
            }
        }
        for e in 0..3 {
            for a in 0..4 {
                if self.view[28 + 12 * e + 3 * a].val().index() == 4 {
                    self.op_s[8 * e + 2 * a].next = self.g4.off_x[e].val();
                }
                if self.view[29 + 12 * e + 3 * a].val().index() == 4 {
                    self.op_s[8 * e + 2 * a + 1].next = self.g4.off_y[e].val();
                }
            }
        }
        for d in 0..4 {
            if self.view[8 + d].val().index() == 5 {
                self.op_e[d].next = self.eq_b[20 + d].val();
            }
        }
        for a in 0..4 {
            if self.view[12 + 4 * a].val().index() == 5 {
                self.op_g[4 * a].next = self.g5.dmaj[a].val();
            }
            if self.view[13 + 4 * a].val().index() == 5 {
                self.op_g[4 * a + 1].next = self.g5.dbot[a].val();
            }
            if self.view[14 + 4 * a].val().index() == 5 {
                self.op_g[4 * a + 2].next = self.g5.dbot[a].val();
            }
            if self.view[15 + 4 * a].val().index() == 5 {
                self.op_g[4 * a + 3].next = self.g5.dmaj[a].val();
            }
        }
        for e in 0..3 {
            for a in 0..4 {
                if self.view[28 + 12 * e + 3 * a].val().index() == 5 {
                    self.op_s[8 * e + 2 * a].next = self.g5.off_x[e].val();
                }
                if self.view[29 + 12 * e + 3 * a].val().index() == 5 {
                    self.op_s[8 * e + 2 * a + 1].next = self.g5.off_y[e].val();
                }
            }
        }
        // ddx, ddy of each attribute: floor(g / 2^gsh), as lanes.
        for a in 0..4 {
            self.ddx[a].next = self.gx[a].q.val() >> self.gsh[a].val();
            self.ddy[a].next = self.gy[a].q.val() >> self.gsh[a].val();
        }
        // v0's attributes at the hand-over, from its copy.
        for a in 0..4 {
            self.attr0[a].next = self.g0.attr0[a].val();
            if self.view_handover.val().index() == 1 {
                self.attr0[a].next = self.g1.attr0[a].val();
            }
            if self.view_handover.val().index() == 2 {
                self.attr0[a].next = self.g2.attr0[a].val();
            }
            if self.view_handover.val().index() == 3 {
                self.attr0[a].next = self.g3.attr0[a].val();
            }
            if self.view_handover.val().index() == 4 {
                self.attr0[a].next = self.g4.attr0[a].val();
            }
            if self.view_handover.val().index() == 5 {
                self.attr0[a].next = self.g5.attr0[a].val();
            }
        }
        // The increments' q, from the copy of their cycle.
        for e in 0..3 {
            for a in 0..4 {
                self.op_q[4 * e + a].next = self.q[e].q.val();
                for v in 1..self._copies {
                    if self.view[30 + 12 * e + 3 * a].val().index() == v {
                        self.op_q[4 * e + a].next = self.q[3 * v + e].q.val();
                    }
                }
            }
        }
        // Each product's operands into its multiplier in its cycle (`act`), its product
        // out M cycles later (`add`); the multipliers' registers move while setup runs.
        for m in 0..self._k {
            self.mul[m].en.next = self.run.val();
            // Area: e_maj.dx * e_bot.dy - e_bot.dx * e_maj.dy.
            if (self.lane[0].val().index() == m) & self.act[0].val() {
                self.mul[m].a.next = self.g0.kdx[0].val().get_bits::<MUL_A>(0);
                self.mul[m].b.next = self.g0.kdy[1].val().get_bits::<MUL_B>(0);
            }
            if (self.lane[1].val().index() == m) & self.act[1].val() {
                self.mul[m].a.next = self.g0.kdx[1].val().get_bits::<MUL_A>(0);
                self.mul[m].b.next = self.g0.kdy[0].val().get_bits::<MUL_B>(0);
            }
            for i in 0..2 {
                if (self.lane[i].val().index() == m) & self.add[i].val() {
                    self.pa[i].next = self.mul[m].p.val().get_bits::<AREA>(0);
                }
            }
            for e in 0..3 {
                // Start numerator: x fraction * dy + dx * t.
                if (self.lane[2 + 2 * e].val().index() == m) & self.act[2 + 2 * e].val() {
                    self.mul[m].a.next = self.g0.edy[e].val();
                    self.mul[m].b.next = self.g0.xf[e].val();
                }
                if (self.lane[3 + 2 * e].val().index() == m) & self.act[3 + 2 * e].val() {
                    self.mul[m].a.next = self.g0.edx[e].val().get_bits::<MUL_A>(0);
                    self.mul[m].b.next = self.g0.toff[e].val();
                }
            }
            for i in 0..6 {
                if (self.lane[2 + i].val().index() == m) & self.add[2 + i].val() {
                    self.pn[i].next = self.mul[m].p.val();
                }
            }
            for d in 0..4 {
                // eq. (2): OneOverArea's mantissa times +-delta.
                if (self.lane[8 + d].val().index() == m) & self.act[8 + d].val() {
                    self.mul[m].a.next = self.mant_s.q.val();
                    self.mul[m].b.next = self.op_e[d].val();
                }
                if (self.lane[8 + d].val().index() == m) & self.add[8 + d].val() {
                    self.pe[d].next = self.mul[m].p.val().get_bits::<G>(0);
                }
            }
            for a in 0..4 {
                // dx = p_bot_dy * d_maj - p_maj_dy * d_bot; dy = p_maj_dx * d_bot - p_bot_dx * d_maj.
                if (self.lane[12 + 4 * a].val().index() == m) & self.act[12 + 4 * a].val() {
                    self.mul[m].a.next = self.p[3].q.val();
                    self.mul[m].b.next = self.op_g[4 * a].val();
                }
                if (self.lane[13 + 4 * a].val().index() == m) & self.act[13 + 4 * a].val() {
                    self.mul[m].a.next = self.p[2].q.val();
                    self.mul[m].b.next = self.op_g[4 * a + 1].val();
                }
                if (self.lane[14 + 4 * a].val().index() == m) & self.act[14 + 4 * a].val() {
                    self.mul[m].a.next = self.p[0].q.val();
                    self.mul[m].b.next = self.op_g[4 * a + 2].val();
                }
                if (self.lane[15 + 4 * a].val().index() == m) & self.act[15 + 4 * a].val() {
                    self.mul[m].a.next = self.p[1].q.val();
                    self.mul[m].b.next = self.op_g[4 * a + 3].val();
                }
            }
            for i in 0..16 {
                if (self.lane[12 + i].val().index() == m) & self.add[12 + i].val() {
                    self.pg[i].next = self.mul[m].p.val().get_bits::<G>(0);
                }
            }
            for e in 0..3 {
                for a in 0..4 {
                    // at: ddx * off_x + ddy * off_y; inc0 = ddy + q * ddx.
                    if (self.lane[28 + 12 * e + 3 * a].val().index() == m) & self.act[28 + 12 * e + 3 * a].val() {
                        self.mul[m].a.next = self.ddx[a].val();
                        self.mul[m].b.next = self.op_s[8 * e + 2 * a].val();
                    }
                    if (self.lane[29 + 12 * e + 3 * a].val().index() == m) & self.act[29 + 12 * e + 3 * a].val() {
                        self.mul[m].a.next = self.ddy[a].val();
                        self.mul[m].b.next = self.op_s[8 * e + 2 * a + 1].val();
                    }
                    if (self.lane[30 + 12 * e + 3 * a].val().index() == m) & self.act[30 + 12 * e + 3 * a].val() {
                        self.mul[m].a.next = self.ddx[a].val();
                        self.mul[m].b.next = self.op_q[4 * e + a].val();
                    }
                }
            }
            for i in 0..36 {
                if (self.lane[28 + i].val().index() == m) & self.add[28 + i].val() {
                    self.ps[i].next = self.mul[m].p.val().get_bits::<ATTR>(0);
                }
            }
        }

        // ---- Add each product into its register while setup runs (the first one of a
        // register starts it afresh). Products not due are 0.
        self.area_base.next = self.area.q.val();
        if self.add[0].val() {
            self.area_base.next = 0.into();
        }
        for e in 0..3 {
            self.num_base[e].next = self.num[e].q.val();
            if self.add[2 + 2 * e].val() {
                self.num_base[e].next = 0.into();
            }
        }
        // eq. (2): sign * delta * mant * 2^(15 - exp), floor, into `ooa_d`.
        for d in 0..4 {
            self.shr[d].next = self.pe[d].val() >> self.rsh.q.val();
            if self.pe[d].val().get_bit(self.p_msb.val().index()) {
                self.shr[d].next = (self.pe[d].val() >> self.rsh.q.val()) | !(self.ones.val() >> self.rsh.q.val());
            }
        }
        for a in 0..4 {
            self.gx_base[a].next = self.gx[a].q.val();
            if self.add[12 + 4 * a].val() {
                self.gx_base[a].next = 0.into();
            }
            self.gy_base[a].next = self.gy[a].q.val();
            if self.add[14 + 4 * a].val() {
                self.gy_base[a].next = 0.into();
            }
        }
        for e in 0..3 {
            for a in 0..4 {
                self.plane_base[4 * e + a].next = self.plane[4 * e + a].q.val();
                if self.add[28 + 12 * e + 3 * a].val() {
                    self.plane_base[4 * e + a].next = 0.into();
                }
            }
        }
        if self.run.val() {
            self.area.d.next = self.area_base.val() + self.pa[0].val() - self.pa[1].val();
            for e in 0..3 {
                self.num[e].d.next = self.num_base[e].val() + self.pn[2 * e].val() + self.pn[2 * e + 1].val();
            }
            for d in 0..4 {
                if self.add[8 + d].val() {
                    self.p[d].d.next = self.shr[d].val();
                    if self.left.q.val() {
                        self.p[d].d.next = self.pe[d].val();
                    }
                }
            }
            for a in 0..4 {
                self.gx[a].d.next = self.gx_base[a].val() + self.pg[4 * a].val() - self.pg[4 * a + 1].val();
                self.gy[a].d.next = self.gy_base[a].val() + self.pg[4 * a + 2].val() - self.pg[4 * a + 3].val();
            }
            for e in 0..3 {
                for a in 0..4 {
                    self.plane[4 * e + a].d.next = self.plane_base[4 * e + a].val()
                        + self.ps[12 * e + 3 * a].val()
                        + self.ps[12 * e + 3 * a + 1].val();
                    // inc0 = ddy + q * ddx, inc1 = inc0 + ddx; ddx for the result.
                    if self.add[30 + 12 * e + 3 * a].val() {
                        self.inc0[4 * e + a].d.next =
                            self.ddy[a].val().get_bits::<ATTR>(0) + self.ps[12 * e + 3 * a + 2].val();
                        self.inc1[4 * e + a].d.next = self.ddy[a].val().get_bits::<ATTR>(0)
                            + self.ps[12 * e + 3 * a + 2].val()
                            + self.ddx[a].val().get_bits::<ATTR>(0);
                        self.ddx_o[a].d.next = self.ddx[a].val().get_bits::<ATTR>(0);
                    }
                }
            }
        }
        // Hand-over: at = v0's attribute + floor(plane / 2^s).
        for e in 0..3 {
            for a in 0..4 {
                if self.at_handover.val() {
                    self.plane[4 * e + a].d.next =
                        (self.plane[4 * e + a].q.val() >> self.frac.val()) + (self.attr0[a].val() << self.bsh[a].val());
                }
            }
        }

        // ---- The result: the geometry's part registered at the hand-over from its copy, so
        // that the edge walk starts from registers.
        if self.at_handover.val() & (self.view_handover.val().index() == 0) {
            self.o_walk.d.next = self.g0.up.val();
            self.o_maj_left.d.next = self.maj_left[0].val();
            for e in 0..3 {
                self.o_j[e].d.next = self.g0.cy[e].val().get_bits::<PIXEL>(self.frac.val().index());
                self.o_count[e].d.next = self.g0.count[e].val();
                self.o_d[e].d.next = self.g0.ed16[e].val().get_bits::<EDGE_D>(0);
            }
        }
        if self.at_handover.val() & (self.view_handover.val().index() == 1) {
            self.o_walk.d.next = self.g1.up.val();
            self.o_maj_left.d.next = self.maj_left[1].val();
            for e in 0..3 {
                self.o_j[e].d.next = self.g1.cy[e].val().get_bits::<PIXEL>(self.frac.val().index());
                self.o_count[e].d.next = self.g1.count[e].val();
                self.o_d[e].d.next = self.g1.ed16[e].val().get_bits::<EDGE_D>(0);
            }
        }
        if self.at_handover.val() & (self.view_handover.val().index() == 2) {
            self.o_walk.d.next = self.g2.up.val();
            self.o_maj_left.d.next = self.maj_left[2].val();
            for e in 0..3 {
                self.o_j[e].d.next = self.g2.cy[e].val().get_bits::<PIXEL>(self.frac.val().index());
                self.o_count[e].d.next = self.g2.count[e].val();
                self.o_d[e].d.next = self.g2.ed16[e].val().get_bits::<EDGE_D>(0);
            }
        }
        if self.at_handover.val() & (self.view_handover.val().index() == 3) {
            self.o_walk.d.next = self.g3.up.val();
            self.o_maj_left.d.next = self.maj_left[3].val();
            for e in 0..3 {
                self.o_j[e].d.next = self.g3.cy[e].val().get_bits::<PIXEL>(self.frac.val().index());
                self.o_count[e].d.next = self.g3.count[e].val();
                self.o_d[e].d.next = self.g3.ed16[e].val().get_bits::<EDGE_D>(0);
            }
        }
        if self.at_handover.val() & (self.view_handover.val().index() == 4) {
            self.o_walk.d.next = self.g4.up.val();
            self.o_maj_left.d.next = self.maj_left[4].val();
            for e in 0..3 {
                self.o_j[e].d.next = self.g4.cy[e].val().get_bits::<PIXEL>(self.frac.val().index());
                self.o_count[e].d.next = self.g4.count[e].val();
                self.o_d[e].d.next = self.g4.ed16[e].val().get_bits::<EDGE_D>(0);
            }
        }
        if self.at_handover.val() & (self.view_handover.val().index() == 5) {
            self.o_walk.d.next = self.g5.up.val();
            self.o_maj_left.d.next = self.maj_left[5].val();
            for e in 0..3 {
                self.o_j[e].d.next = self.g5.cy[e].val().get_bits::<PIXEL>(self.frac.val().index());
                self.o_count[e].d.next = self.g5.count[e].val();
                self.o_d[e].d.next = self.g5.ed16[e].val().get_bits::<EDGE_D>(0);
            }
        }
        self.out.walk.next = self.o_walk.q.val();
        self.out.maj_left.next = self.o_maj_left.q.val();
        self.out.maj_j.next = self.o_j[0].q.val();
        self.out.maj_count.next = self.o_count[0].q.val();
        self.out.maj_d.next = self.o_d[0].q.val();
        self.out.short0_j.next = self.o_j[1].q.val();
        self.out.short0_count.next = self.o_count[1].q.val();
        self.out.short0_d.next = self.o_d[1].q.val();
        self.out.short1_j.next = self.o_j[2].q.val();
        self.out.short1_count.next = self.o_count[2].q.val();
        self.out.short1_d.next = self.o_d[2].q.val();
        // Each edge's start and step, and OneOverArea, from the last copy.
        for v in (self._copies - 1)..self._copies {
            self.recip_mant.next = self.mant[v].q.val();
            self.recip_exp.next = self.exp[v].q.val();
            self.out.maj_x.next = self.x[3 * v].q.val().get_bits::<PIXEL>(0);
            self.out.maj_r.next = self.r[3 * v].q.val();
            self.out.maj_q.next = self.q[3 * v].q.val().get_bits::<EDGE_Q>(0);
            self.out.maj_rho.next = self.rho[3 * v].q.val();
            self.out.short0_x.next = self.x[3 * v + 1].q.val().get_bits::<PIXEL>(0);
            self.out.short0_r.next = self.r[3 * v + 1].q.val();
            self.out.short0_q.next = self.q[3 * v + 1].q.val().get_bits::<EDGE_Q>(0);
            self.out.short0_rho.next = self.rho[3 * v + 1].q.val();
            self.out.short1_x.next = self.x[3 * v + 2].q.val().get_bits::<PIXEL>(0);
            self.out.short1_r.next = self.r[3 * v + 2].q.val();
            self.out.short1_q.next = self.q[3 * v + 2].q.val().get_bits::<EDGE_Q>(0);
            self.out.short1_rho.next = self.rho[3 * v + 2].q.val();
        }
        self.out.maj_at_z.next = self.plane[0].q.val().get_bits::<Z_ACC>(0);
        self.out.maj_at_c0.next = self.plane[1].q.val().get_bits::<C_ACC>(0);
        self.out.maj_at_c1.next = self.plane[2].q.val().get_bits::<C_ACC>(0);
        self.out.maj_at_c2.next = self.plane[3].q.val().get_bits::<C_ACC>(0);
        self.out.maj_inc0_z.next = self.inc0[0].q.val().get_bits::<DZ>(0);
        self.out.maj_inc0_c0.next = self.inc0[1].q.val().get_bits::<DC>(0);
        self.out.maj_inc0_c1.next = self.inc0[2].q.val().get_bits::<DC>(0);
        self.out.maj_inc0_c2.next = self.inc0[3].q.val().get_bits::<DC>(0);
        self.out.maj_inc1_z.next = self.inc1[0].q.val().get_bits::<DZ>(0);
        self.out.maj_inc1_c0.next = self.inc1[1].q.val().get_bits::<DC>(0);
        self.out.maj_inc1_c1.next = self.inc1[2].q.val().get_bits::<DC>(0);
        self.out.maj_inc1_c2.next = self.inc1[3].q.val().get_bits::<DC>(0);
        self.out.short0_at_z.next = self.plane[4].q.val().get_bits::<Z_ACC>(0);
        self.out.short0_at_c0.next = self.plane[5].q.val().get_bits::<C_ACC>(0);
        self.out.short0_at_c1.next = self.plane[6].q.val().get_bits::<C_ACC>(0);
        self.out.short0_at_c2.next = self.plane[7].q.val().get_bits::<C_ACC>(0);
        self.out.short0_inc0_z.next = self.inc0[4].q.val().get_bits::<DZ>(0);
        self.out.short0_inc0_c0.next = self.inc0[5].q.val().get_bits::<DC>(0);
        self.out.short0_inc0_c1.next = self.inc0[6].q.val().get_bits::<DC>(0);
        self.out.short0_inc0_c2.next = self.inc0[7].q.val().get_bits::<DC>(0);
        self.out.short0_inc1_z.next = self.inc1[4].q.val().get_bits::<DZ>(0);
        self.out.short0_inc1_c0.next = self.inc1[5].q.val().get_bits::<DC>(0);
        self.out.short0_inc1_c1.next = self.inc1[6].q.val().get_bits::<DC>(0);
        self.out.short0_inc1_c2.next = self.inc1[7].q.val().get_bits::<DC>(0);
        self.out.short1_at_z.next = self.plane[8].q.val().get_bits::<Z_ACC>(0);
        self.out.short1_at_c0.next = self.plane[9].q.val().get_bits::<C_ACC>(0);
        self.out.short1_at_c1.next = self.plane[10].q.val().get_bits::<C_ACC>(0);
        self.out.short1_at_c2.next = self.plane[11].q.val().get_bits::<C_ACC>(0);
        self.out.short1_inc0_z.next = self.inc0[8].q.val().get_bits::<DZ>(0);
        self.out.short1_inc0_c0.next = self.inc0[9].q.val().get_bits::<DC>(0);
        self.out.short1_inc0_c1.next = self.inc0[10].q.val().get_bits::<DC>(0);
        self.out.short1_inc0_c2.next = self.inc0[11].q.val().get_bits::<DC>(0);
        self.out.short1_inc1_z.next = self.inc1[8].q.val().get_bits::<DZ>(0);
        self.out.short1_inc1_c0.next = self.inc1[9].q.val().get_bits::<DC>(0);
        self.out.short1_inc1_c1.next = self.inc1[10].q.val().get_bits::<DC>(0);
        self.out.short1_inc1_c2.next = self.inc1[11].q.val().get_bits::<DC>(0);
        self.out.ddx_z.next = self.ddx_o[0].q.val().get_bits::<DZ>(0);
        self.out.ddx_c0.next = self.ddx_o[1].q.val().get_bits::<DC>(0);
        self.out.ddx_c1.next = self.ddx_o[2].q.val().get_bits::<DC>(0);
        self.out.ddx_c2.next = self.ddx_o[3].q.val().get_bits::<DC>(0);
    }
}

crate::pins!(TriangleSetup {
    clock: clock,
    inputs: [out_free_next, out_hold],
    outputs: [recip_mant, recip_exp, idle],
    links: [inp, out],
});

/// `UNITS` entry: setup with `params["K"]` multipliers and a `params["L"]`-stage divider.
pub fn emit_triangle_setup(params: &Params) -> Result<Emitted, String> {
    let mut u = TriangleSetup::new(params["K"] as usize, params["L"] as usize)?;
    u.connect_all();
    Ok(Emitted {
        unit: "triangle_setup",
        params: params.clone(),
        formats: None,
        ports: ports(&u),
        verilog: verilog("triangle_setup", &u),
        dir: None,
    })
}
