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
//!
//! **Datapath.** `K` multipliers ([`Mul`], `MUL_A` x `MUL_B` bits) reused over 64
//! products, and the shared divider ([`crate::divider::Divider`]), into which setup
//! issues its seven divisions one per cycle in the model's order (`TriangleSetupOut::divisions`:
//! 1/area, then per edge the start and the step of the exact edge walker). Each product
//! is added into its destination register in the cycle it comes out; the model's wraps
//! (`ctx.put`) are the registers' widths, its floor shifts bit slices:
//!
//! | phase | products (A x B) | into | model |
//! |---|---|---|---|
//! | area | e_maj.dx * e_bot.dy, e_bot.dx * e_maj.dy | `area` (exact) | `area2` |
//! | normalise | - (leading one, shift) | 1/area issued | `recip_operands` |
//! | numerators | dy * (x fraction), dx * t per edge | `num` (exact) | `start_in` |
//! | eq. (2) | (OneOverArea << (15 - exp)) * (+-e.d), 4 | `p` (`ooa_d`; for exp > 15 the product >> (exp - 15), floor) | `ooa_times` |
//! | gradients | p * attribute deltas, 16 | `gx`, `gy` (mod 2^`ooa_d`); ddx, ddy are their slices | `grad` |
//! | starts, increments | ddx * off_x, ddy * off_y, ddx * q per edge and attribute, 36 | `plane`, `inc0` (mod 2^`dz`) | `at`, `inc0` |
//! | hand-over | - | `at = floor(plane / 2^s) + v0's`, `inc1 = inc0 + ddx` | `at`, `inc1` |
//!
//! The order of eq. (2) is the model's: `OOA * e.d` first (the four products every
//! attribute shares), then times the attribute difference, so no register overflows where
//! `OOA * (e_maj.dx * e_bot.dC - ...)` would (001's point). z and the colours run in
//! 40-bit lanes (`dz`); a colour keeps its low `dc`/`c_acc` bits, the only ones its
//! format holds (modular arithmetic, `fx::formats`).
//!
//! **Schedule** ([`Schedule`]; `model::cycles::setup_latency` is the same). Cycle 0 takes
//! the triangle; each phase puts its products `K` per cycle on the multipliers; the
//! numerators fill them from the normalise cycle on while the divider works. With 001's 7
//! multipliers and 5-stage divider:
//!
//! ```text
//!  cycle    0     1     2       3   4   5   6   7     8   9  10  11 ... 16   17       18
//!  input    take
//!  mults          area  numer.                  eq2   gradients  starts, increments
//!  divider issue        1/area  s0  q0  s1  q1  s2    q2
//!  divider result                               1/area s0 q0 s1  q1  s2 q2 (12, 13)
//!  output                                                                   hand-over valid
//! ```
//!
//! Latency 18 (001 Table 3: 34), II 18 when the edge walk takes each result at once:
//! setup takes the next triangle in the cycle it hands one over. `K` (1 to 7,
//! `model::cycles::SETUP_MULTIPLIERS_MAX`: with more, the last edge's products would wait
//! for its divisions) trades latency for area, 66 cycles with one multiplier; the
//! divider's `L` stages likewise.
//!
//! Model: `model::triangle_setup::triangle_setup`. Emitted: `hdl-out/triangle_setup.v`.

use super::cull_sort::{outcode_bit, COLOR, OUTCODE, XY, Z};
use super::divider::{DividerRtl, DIV_D, DIV_N, DIV_Q, DIV_QM};
use crate::emit::{ports, verilog, Emitted};
use crate::mul::Mul;
use crate::parts::defaults;
use super::links::{SortedSink, TriangleSetupSource};
use super::widths::{C_ACC, DC, DERIVED, DZ, EDGE_D, EDGE_Q, FORMATS, PIXEL, WIDTHS, Z_ACC};
use crate::Params;
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
/// The narrow signed domain of the B operands and the edge geometry.
const NB: usize = MUL_B;
/// Gradients and OneOverArea x delta (`ooa_d`).
const G: usize = MUL_A;
/// The quotient bits taken into the narrow domain: all of `q_n` unless the quotient is
/// narrower (a wide z makes the narrow domain wider than the divider's quotient).
const QL: usize = if DIV_Q < NB { DIV_Q } else { NB };
/// An attribute lane: z's gradient width; colours use its low bits.
const ATTR: usize = DZ;
/// OneOverArea's mantissa (`ooa`).
const MANT: usize = FORMATS.ooa.bits() as usize;
/// Products in setup's schedule.
pub const PRODUCTS: usize = 64;

const S: u32 = FORMATS.xy.frac;

// The shifts below are floor shifts (right), the lanes hold what they are given, and the
// products fit: `config::violation`, asserted of every build in `widths.rs`; these follow
// from it.
const _: () = assert!(DZ >= DC && DZ >= Z_ACC && DC >= C_ACC && ATTR <= MUL_P && G <= MUL_P);
const _: () = assert!(MUL_B > XY + 2 && MUL_B > COLOR && EDGE_Q + 2 <= MUL_B);

/// When each step of setup happens, in cycles after the cycle that takes the triangle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Schedule {
    pub multipliers: usize,
    pub divider_latency: usize,
    /// Per product: its cycle and its multiplier.
    pub slots: Vec<(usize, usize)>,
    /// The seven divisions' issue cycles, in the model's order.
    pub issue: [usize; 7],
    /// The hand-over cycle; the result is valid from the next one.
    pub handover: usize,
    pub latency: usize,
}

/// The products of each phase, in order: area, numerators, eq. (2), gradients, starts.
/// Product i of the kernel: area 0, 1; numerators 2 + 2e (dy * x fraction) and 3 + 2e
/// (dx * t) for edge e; eq. (2) 8 + d; gradients 12 + 4a + j for attribute a; starts and
/// increments 28 + 12e + 3a + j.
const PHASES: [usize; 5] = [2, 6, 4, 16, 36];

/// Most multipliers setup can use (`model::cycles::SETUP_MULTIPLIERS_MAX`): with more, the
/// last edge's products would wait for its divisions, which go one per cycle.
pub const MULTIPLIERS_MAX: usize = 7;

impl Schedule {
    /// The schedule for `k` multipliers and an `l`-stage divider.
    pub fn new(k: usize, l: usize) -> Result<Schedule, String> {
        if !(1..=MULTIPLIERS_MAX).contains(&k) {
            return Err(format!("triangle_setup: K = {k} multipliers is not supported: 1 to {MULTIPLIERS_MAX}"));
        }
        if !(1..=DIV_QM).contains(&l) {
            return Err(format!("triangle_setup: L = {l} divider stages is not supported: 1 to {DIV_QM}"));
        }
        let c = |n: usize| n.div_ceil(k);
        let mut slots = Vec::with_capacity(PRODUCTS);
        let mut place = |start: usize, n: usize| slots.extend((0..n).map(|i| (start + i / k, i % k)));
        // Area from cycle 1; normalise and issue 1/area in the next free cycle; the
        // numerators from then on.
        place(1, PHASES[0]);
        let norm = 1 + c(PHASES[0]);
        place(norm, PHASES[1]);
        // Each edge division as soon as it may go: the start once its numerator is summed.
        let mut issue = [norm; 7];
        for j in 1..7 {
            let ready = if j % 2 == 1 { norm + (j / 2 * 2 + 1) / k + 1 } else { 0 };
            issue[j] = (issue[j - 1] + 1).max(ready);
        }
        let eq2 = norm + l.max(c(PHASES[1]));
        place(eq2, PHASES[2]);
        let grad = eq2 + c(PHASES[2]);
        place(grad, PHASES[3]);
        let start = grad + c(PHASES[3]);
        place(start, PHASES[4]);
        let handover = start + c(PHASES[4]);
        let s = Schedule { multipliers: k, divider_latency: l, slots, issue, handover, latency: handover + 1 };
        // Edge e's 12 start products need both its quotients, registered.
        for e in 0..3 {
            let back = s.issue[2 + 2 * e] + l + 1;
            let first = s.slots[PRODUCTS - PHASES[4] + 12 * e].0;
            assert!(first >= back, "K = {k}, L = {l}: edge {e}'s products at {first}, its divisions back at {back}");
        }
        Ok(s)
    }

    /// The cycle a division's result is at the divider's output.
    pub fn result(&self, division: usize) -> usize {
        self.issue[division] + self.divider_latency
    }
}

/// The triangle setup unit; see the module documentation.
#[derive(LogicBlock)]
pub struct TriangleSetup {
    pub clock: Signal<In, Clock>,
    /// The sorted triangle in (`inp.v<k>_iw` is not read: the vector method's).
    pub inp: SortedSink,
    /// The set-up triangle, held until `out.ready`.
    pub out: TriangleSetupSource,

    // Sub-blocks.
    mul: Vec<Mul<MUL_A, MUL_B, MUL_P>>,
    div: DividerRtl,

    // Control: cycles since the triangle was taken (0: idle).
    t: DFF<Bits<8>>,
    take: Signal<Local, Bit>,
    /// Product i is due this cycle.
    act: [Signal<Local, Bit>; PRODUCTS],

    // The triangle, as taken: x, y, z, colours (3 * vertex + channel), crosses.
    vx: [DFF<Bits<XY>>; 3],
    vy: [DFF<Bits<XY>>; 3],
    vz: [DFF<Bits<Z>>; 3],
    vc: [DFF<Bits<COLOR>>; 9],
    crosses: DFF<Bits<OUTCODE>>,

    // Geometry, combinational from the triangle.
    /// x, y sign-extended to `W` and `G` bits (y only meets the multipliers' A side and
    /// divisors); z, colours as `NB`-bit numbers.
    xw: [Signal<Local, Bits<W>>; 3],
    yw: [Signal<Local, Bits<G>>; 3],
    zn: [Signal<Local, Bits<NB>>; 3],
    cn: [Signal<Local, Bits<NB>>; 9],
    /// x, y as `NB`-bit numbers.
    xn: [Signal<Local, Bits<NB>>; 3],
    yn: [Signal<Local, Bits<NB>>; 3],
    /// Edge vectors e_maj (v0 -> v2), e_bot (v0 -> v1), e_top (v1 -> v2): dx, dy.
    kdx: [Signal<Local, Bits<W>>; 3],
    kdy: [Signal<Local, Bits<G>>; 3],
    /// The first scanline centre at or below each vertex, `(y + 7) & !15 | 8` (subpixels).
    cv: [Signal<Local, Bits<NB>>; 3],
    /// Scanlines between those centres along e_maj, e_bot, e_top (vMin..vMax, vMin..vMid,
    /// vMid..vMax), 0 when negative, and the centres' differences.
    span: [Signal<Local, Bits<PIXEL>>; 3],
    diff: [Signal<Local, Bits<NB>>; 3],
    /// Walk up (003): the triangle crosses the top boundary and not the bottom one.
    up: Signal<Local, Bit>,
    /// e_maj is the left side (twice the area < 0).
    maj_left: Signal<Local, Bit>,
    /// Per edge in walk order (e_maj, then the short edges as `TriangleSetupOut::short`):
    /// dx, dy, 2^s dy, the walk's base vertex, scanline centre, count, the start
    /// division's offsets (t, x fraction, x integer) and the tracked side's offsets.
    edx: [Signal<Local, Bits<W>>; 3],
    edy: [Signal<Local, Bits<G>>; 3],
    /// dy as the divisor (zero-extended when `G` is narrower than the divisor).
    edy_d: [Signal<Local, Bits<DIV_D>>; 3],
    ed16: [Signal<Local, Bits<DIV_D>>; 3],
    bx: [Signal<Local, Bits<NB>>; 3],
    by: [Signal<Local, Bits<NB>>; 3],
    cy: [Signal<Local, Bits<NB>>; 3],
    count: [Signal<Local, Bits<PIXEL>>; 3],
    toff: [Signal<Local, Bits<NB>>; 3],
    xb: [Signal<Local, Bits<NB>>; 3],
    xi: [Signal<Local, Bits<NB>>; 3],
    xf: [Signal<Local, Bits<NB>>; 3],
    /// The pixel the side tracks: x on the left side, x - 1 on the right.
    tracked: [Signal<Local, Bits<NB>>; 3],
    off_x: [Signal<Local, Bits<NB>>; 3],
    off_y: [Signal<Local, Bits<NB>>; 3],
    /// Attribute differences from v0 along e_maj and e_bot (z, R, G, B).
    dmaj: [Signal<Local, Bits<NB>>; 4],
    dbot: [Signal<Local, Bits<NB>>; 4],
    /// v0's attributes in a lane.
    attr0: [Signal<Local, Bits<ATTR>>; 4],

    // Normalise.
    area: DFF<Bits<AREA>>,
    area_abs: Signal<Local, Bits<AREA>>,
    exp_c: Signal<Local, Bits<6>>,
    norm_d: Signal<Local, Bits<DIV_D>>,
    exp: DFF<Bits<6>>,

    // Divider results.
    mant: DFF<Bits<MANT>>,
    mant_now: Signal<Local, Bits<MANT>>,
    mant_a: Signal<Local, Bits<MUL_A>>,
    q_n: Signal<Local, Bits<NB>>,
    /// The quotient's sign bit and its extension into `q_n` (none when the quotient is
    /// as wide as `q_n`).
    q_msb: Constant<Bits<8>>,
    q_ext: Constant<Bits<NB>>,
    r_pos: Signal<Local, Bit>,
    x: [DFF<Bits<NB>>; 3],
    r: [DFF<Bits<EDGE_D>>; 3],
    q: [DFF<Bits<NB>>; 3],
    rho: [DFF<Bits<EDGE_D>>; 3],

    // Products, as they leave their multiplier (0 when not due).
    pa: [Signal<Local, Bits<AREA>>; 2],
    pn: [Signal<Local, Bits<MUL_P>>; 6],
    pe: [Signal<Local, Bits<G>>; 4],
    pg: [Signal<Local, Bits<G>>; 16],
    ps: [Signal<Local, Bits<ATTR>>; 36],
    /// eq. (2)'s B operands: +-e_maj.dx, e_bot.dx, e_maj.dy, e_bot.dy (sign of the area).
    delta: [Signal<Local, Bits<NB>>; 4],
    eq_b: [Signal<Local, Bits<NB>>; 4],
    /// eq. (2)'s products shifted right by exp - 15 (floor), for exp > 15; for exp <= 15
    /// the mantissa goes into the multipliers shifted left by 15 - exp instead.
    shr: [Signal<Local, Bits<G>>; 4],
    lsh: Signal<Local, Bits<6>>,
    rsh: Signal<Local, Bits<6>>,

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

    // The schedule and the numbers a kernel cannot name.
    lane: [Constant<Bits<8>>; PRODUCTS],
    cyc: [Constant<Bits<8>>; PRODUCTS],
    iss: [Constant<Bits<8>>; 7],
    res: [Constant<Bits<8>>; 7],
    handover: Constant<Bits<8>>,
    last: Constant<Bits<8>>,
    /// 2^56: 1/area's dividend (`recip_operands`); the exponent of 1/area's top bit (32).
    recip_n: Constant<Bits<DIV_N>>,
    recip_top: Constant<Bits<6>>,
    /// `ooa_d.frac + s - ooa.frac` (15): eq. (2)'s shift is this less exp.
    eq_shift: Constant<Bits<6>>,
    /// Per attribute: the gradient's slice (`ooa_d.frac + z.frac - dz.frac` and the
    /// colours'), and v0's shift into the accumulator (`z_acc.frac - z.frac`, ...).
    gsh: [Constant<Bits<8>>; 4],
    bsh: [Constant<Bits<8>>; 4],
    /// s; 2^(s-1) - 1, 2^(s-1), !(2^s - 1) and 2^s - 1 in the narrow domain.
    frac: Constant<Bits<8>>,
    half_m1: Constant<Bits<NB>>,
    half: Constant<Bits<NB>>,
    int_mask: Constant<Bits<NB>>,
    frac_mask: Constant<Bits<NB>>,
    /// Sign bits: x, y (`XY`), z, the area, the narrow domain, eq. (2)'s products.
    xy_msb: Constant<Bits<8>>,
    z_msb: Constant<Bits<8>>,
    area_msb: Constant<Bits<8>>,
    nb_msb: Constant<Bits<8>>,
    p_msb: Constant<Bits<8>>,
    /// Ones above a sign bit: x into `W` bits, y into `G` bits, z into `NB` bits, s bits below `NB`.
    xy_ext: Constant<Bits<W>>,
    y_ext: Constant<Bits<G>>,
    z_ext: Constant<Bits<NB>>,
    shr_ext: Constant<Bits<NB>>,
    ones: Constant<Bits<G>>,
    /// The outcode bits of the top and bottom planes.
    top_bit: Constant<Bits<8>>,
    bottom_bit: Constant<Bits<8>>,
    _k: usize,
}

/// An array of `N` constants from `f(i)`.
fn consts<const B: usize, const N: usize>(f: impl Fn(usize) -> usize) -> [Constant<Bits<B>>; N] {
    std::array::from_fn(|i| Constant::new(f(i).to_bits()))
}

/// Ones from bit `from` up to bit `to - 1`, as a `to`-bit constant or wider.
fn ones_from<const B: usize>(from: usize, to: usize) -> Constant<Bits<B>> {
    Constant::new((((1u128 << (to - from)) - 1) << from).to_bits())
}

impl TriangleSetup {
    /// Setup with `k` multipliers and an `l`-stage divider (see [`Schedule::new`]).
    pub fn new(k: usize, l: usize) -> Result<TriangleSetup, String> {
        let s = Schedule::new(k, l)?;
        let f = FORMATS;
        let (gz, gc) =
            ((f.ooa_d.frac + f.z.frac - f.dz.frac) as usize, (f.ooa_d.frac + f.color.frac - f.dc.frac) as usize);
        let (bz, bc) = ((f.z_acc.frac - f.z.frac) as usize, (f.c_acc.frac - f.color.frac) as usize);
        let px = 1usize << S;
        Ok(TriangleSetup {
            clock: Default::default(),
            inp: Default::default(),
            out: Default::default(),
            mul: (0..k).map(|_| Default::default()).collect(),
            div: DividerRtl::new(l),
            t: Default::default(),
            take: Default::default(),
            act: defaults(),
            vx: defaults(),
            vy: defaults(),
            vz: defaults(),
            vc: defaults(),
            crosses: Default::default(),
            xw: defaults(),
            yw: defaults(),
            zn: defaults(),
            cn: defaults(),
            xn: defaults(),
            yn: defaults(),
            kdx: defaults(),
            kdy: defaults(),
            cv: defaults(),
            span: defaults(),
            diff: defaults(),
            up: Default::default(),
            maj_left: Default::default(),
            edx: defaults(),
            edy: defaults(),
            edy_d: defaults(),
            ed16: defaults(),
            bx: defaults(),
            by: defaults(),
            cy: defaults(),
            count: defaults(),
            toff: defaults(),
            xb: defaults(),
            xi: defaults(),
            xf: defaults(),
            tracked: defaults(),
            off_x: defaults(),
            off_y: defaults(),
            dmaj: defaults(),
            dbot: defaults(),
            attr0: defaults(),
            area: Default::default(),
            area_abs: Default::default(),
            exp_c: Default::default(),
            norm_d: Default::default(),
            exp: Default::default(),
            mant: Default::default(),
            mant_now: Default::default(),
            mant_a: Default::default(),
            q_n: Default::default(),
            q_msb: Constant::new((QL - 1).to_bits()),
            q_ext: ones_from(QL, NB),
            r_pos: Default::default(),
            x: defaults(),
            r: defaults(),
            q: defaults(),
            rho: defaults(),
            pa: defaults(),
            pn: defaults(),
            pe: defaults(),
            pg: defaults(),
            ps: defaults(),
            delta: defaults(),
            eq_b: defaults(),
            shr: defaults(),
            lsh: Default::default(),
            rsh: Default::default(),
            area_base: Default::default(),
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
            lane: consts(|i| s.slots[i].1),
            cyc: consts(|i| s.slots[i].0),
            iss: consts(|j| s.issue[j]),
            res: consts(|j| s.result(j)),
            handover: Constant::new(s.handover.to_bits()),
            last: Constant::new(s.latency.to_bits()),
            recip_n: Constant::new((1u128 << (DERIVED.area_bits - 2 + f.ooa.frac)).to_bits()),
            recip_top: Constant::new(((DERIVED.area_bits - 2) as usize).to_bits()),
            eq_shift: Constant::new(((f.ooa_d.frac + S - f.ooa.frac) as usize).to_bits()),
            gsh: consts(|a| if a == 0 { gz } else { gc }),
            bsh: consts(|a| if a == 0 { bz } else { bc }),
            frac: Constant::new((S as usize).to_bits()),
            half_m1: Constant::new((px / 2 - 1).to_bits()),
            half: Constant::new((px / 2).to_bits()),
            int_mask: ones_from(S as usize, NB),
            frac_mask: Constant::new((px - 1).to_bits()),
            xy_msb: Constant::new((XY - 1).to_bits()),
            z_msb: Constant::new((Z - 1).to_bits()),
            area_msb: Constant::new((AREA - 1).to_bits()),
            nb_msb: Constant::new((NB - 1).to_bits()),
            p_msb: Constant::new((G - 1).to_bits()),
            xy_ext: ones_from(XY, W),
            y_ext: ones_from(XY, G),
            z_ext: ones_from(Z, NB),
            shr_ext: ones_from(NB - S as usize, NB),
            ones: ones_from(0, G),
            top_bit: Constant::new(outcode_bit::TOP.to_bits()),
            bottom_bit: Constant::new(outcode_bit::BOTTOM.to_bits()),
            _k: k,
        })
    }
}

impl Logic for TriangleSetup {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- Clocks; every register holds unless written.
        dff_setup!(self, clock, t, crosses, area, exp, mant);
        clock!(self, clock, div);
        for i in 0..3 {
            self.vx[i].clock.next = self.clock.val();
            self.vx[i].d.next = self.vx[i].q.val();
            self.vy[i].clock.next = self.clock.val();
            self.vy[i].d.next = self.vy[i].q.val();
            self.vz[i].clock.next = self.clock.val();
            self.vz[i].d.next = self.vz[i].q.val();
            self.x[i].clock.next = self.clock.val();
            self.x[i].d.next = self.x[i].q.val();
            self.r[i].clock.next = self.clock.val();
            self.r[i].d.next = self.r[i].q.val();
            self.q[i].clock.next = self.clock.val();
            self.q[i].d.next = self.q[i].q.val();
            self.rho[i].clock.next = self.clock.val();
            self.rho[i].d.next = self.rho[i].q.val();
            self.num[i].clock.next = self.clock.val();
        }
        for i in 0..9 {
            self.vc[i].clock.next = self.clock.val();
            self.vc[i].d.next = self.vc[i].q.val();
        }
        for a in 0..4 {
            self.p[a].clock.next = self.clock.val();
            self.p[a].d.next = self.p[a].q.val();
            self.gx[a].clock.next = self.clock.val();
            self.gy[a].clock.next = self.clock.val();
        }
        for i in 0..12 {
            self.plane[i].clock.next = self.clock.val();
            self.inc0[i].clock.next = self.clock.val();
            self.inc0[i].d.next = self.inc0[i].q.val();
            self.inc1[i].clock.next = self.clock.val();
            self.inc1[i].d.next = self.inc1[i].q.val();
        }

        // ---- Control: take a triangle when idle or handing one over.
        self.inp.ready.next = (self.t.q.val() == 0) | ((self.t.q.val() == self.last.val()) & self.out.ready.val());
        self.take.next = self.inp.valid.val() & self.inp.ready.val();
        self.out.valid.next = self.t.q.val() == self.last.val();
        if (self.t.q.val() != 0) & (self.t.q.val() != self.last.val()) {
            self.t.d.next = self.t.q.val() + 1;
        }
        if (self.t.q.val() == self.last.val()) & self.out.ready.val() {
            self.t.d.next = 0.into();
        }
        if self.take.val() {
            self.t.d.next = 1.into();
            self.vx[0].d.next = self.inp.v0_x.val();
            self.vy[0].d.next = self.inp.v0_y.val();
            self.vz[0].d.next = self.inp.v0_z.val();
            self.vc[0].d.next = self.inp.v0_c0.val();
            self.vc[1].d.next = self.inp.v0_c1.val();
            self.vc[2].d.next = self.inp.v0_c2.val();
            self.vx[1].d.next = self.inp.v1_x.val();
            self.vy[1].d.next = self.inp.v1_y.val();
            self.vz[1].d.next = self.inp.v1_z.val();
            self.vc[3].d.next = self.inp.v1_c0.val();
            self.vc[4].d.next = self.inp.v1_c1.val();
            self.vc[5].d.next = self.inp.v1_c2.val();
            self.vx[2].d.next = self.inp.v2_x.val();
            self.vy[2].d.next = self.inp.v2_y.val();
            self.vz[2].d.next = self.inp.v2_z.val();
            self.vc[6].d.next = self.inp.v2_c0.val();
            self.vc[7].d.next = self.inp.v2_c1.val();
            self.vc[8].d.next = self.inp.v2_c2.val();
            self.crosses.d.next = self.inp.crosses.val();
        }
        for i in 0..PRODUCTS {
            self.act[i].next = self.t.q.val() == self.cyc[i].val();
        }

        // ---- Geometry of the triangle taken (model: `triangle_setup`, its first lines).
        // x, y sign-extended into the wide domain, z into the narrow one (`bit_cast` cannot
        // take a loop's index).
        self.xw[0].next = bit_cast::<W, XY>(self.vx[0].q.val());
        if self.vx[0].q.val().get_bit(self.xy_msb.val().index()) {
            self.xw[0].next = bit_cast::<W, XY>(self.vx[0].q.val()) | self.xy_ext.val();
        }
        self.xw[1].next = bit_cast::<W, XY>(self.vx[1].q.val());
        if self.vx[1].q.val().get_bit(self.xy_msb.val().index()) {
            self.xw[1].next = bit_cast::<W, XY>(self.vx[1].q.val()) | self.xy_ext.val();
        }
        self.xw[2].next = bit_cast::<W, XY>(self.vx[2].q.val());
        if self.vx[2].q.val().get_bit(self.xy_msb.val().index()) {
            self.xw[2].next = bit_cast::<W, XY>(self.vx[2].q.val()) | self.xy_ext.val();
        }
        self.yw[0].next = bit_cast::<G, XY>(self.vy[0].q.val());
        if self.vy[0].q.val().get_bit(self.xy_msb.val().index()) {
            self.yw[0].next = bit_cast::<G, XY>(self.vy[0].q.val()) | self.y_ext.val();
        }
        self.yw[1].next = bit_cast::<G, XY>(self.vy[1].q.val());
        if self.vy[1].q.val().get_bit(self.xy_msb.val().index()) {
            self.yw[1].next = bit_cast::<G, XY>(self.vy[1].q.val()) | self.y_ext.val();
        }
        self.yw[2].next = bit_cast::<G, XY>(self.vy[2].q.val());
        if self.vy[2].q.val().get_bit(self.xy_msb.val().index()) {
            self.yw[2].next = bit_cast::<G, XY>(self.vy[2].q.val()) | self.y_ext.val();
        }
        self.zn[0].next = bit_cast::<NB, Z>(self.vz[0].q.val());
        if self.vz[0].q.val().get_bit(self.z_msb.val().index()) {
            self.zn[0].next = bit_cast::<NB, Z>(self.vz[0].q.val()) | self.z_ext.val();
        }
        self.zn[1].next = bit_cast::<NB, Z>(self.vz[1].q.val());
        if self.vz[1].q.val().get_bit(self.z_msb.val().index()) {
            self.zn[1].next = bit_cast::<NB, Z>(self.vz[1].q.val()) | self.z_ext.val();
        }
        self.zn[2].next = bit_cast::<NB, Z>(self.vz[2].q.val());
        if self.vz[2].q.val().get_bit(self.z_msb.val().index()) {
            self.zn[2].next = bit_cast::<NB, Z>(self.vz[2].q.val()) | self.z_ext.val();
        }
        self.cn[0].next = bit_cast::<NB, COLOR>(self.vc[0].q.val());
        self.cn[1].next = bit_cast::<NB, COLOR>(self.vc[1].q.val());
        self.cn[2].next = bit_cast::<NB, COLOR>(self.vc[2].q.val());
        self.cn[3].next = bit_cast::<NB, COLOR>(self.vc[3].q.val());
        self.cn[4].next = bit_cast::<NB, COLOR>(self.vc[4].q.val());
        self.cn[5].next = bit_cast::<NB, COLOR>(self.vc[5].q.val());
        self.cn[6].next = bit_cast::<NB, COLOR>(self.vc[6].q.val());
        self.cn[7].next = bit_cast::<NB, COLOR>(self.vc[7].q.val());
        self.cn[8].next = bit_cast::<NB, COLOR>(self.vc[8].q.val());
        for v in 0..3 {
            self.xn[v].next = self.xw[v].val().get_bits::<NB>(0);
            self.yn[v].next = self.yw[v].val().get_bits::<NB>(0);
            self.cv[v].next = ((self.yn[v].val() + self.half_m1.val()) & self.int_mask.val()) | self.half.val();
        }
        // e_maj, e_bot, e_top, and the scanlines between their ends' first centres
        // (`span` in the model).
        self.kdx[0].next = self.xw[2].val() - self.xw[0].val();
        self.kdy[0].next = self.yw[2].val() - self.yw[0].val();
        self.diff[0].next = self.cv[2].val() - self.cv[0].val();
        self.kdx[1].next = self.xw[1].val() - self.xw[0].val();
        self.kdy[1].next = self.yw[1].val() - self.yw[0].val();
        self.diff[1].next = self.cv[1].val() - self.cv[0].val();
        self.kdx[2].next = self.xw[2].val() - self.xw[1].val();
        self.kdy[2].next = self.yw[2].val() - self.yw[1].val();
        self.diff[2].next = self.cv[2].val() - self.cv[1].val();
        for k in 0..3 {
            self.span[k].next = self.diff[k].val().get_bits::<PIXEL>(self.frac.val().index());
            if self.diff[k].val().get_bit(self.nb_msb.val().index()) {
                self.span[k].next = 0.into();
            }
        }
        // The walk direction (003) and the edges in walk order. Walking down: e_maj,
        // e_bot, e_top, each from its upper vertex and first centre. Walking up: e_maj,
        // e_top, e_bot, each from its lower vertex and last centre.
        self.up.next = self.crosses.q.val().get_bit(self.top_bit.val().index())
            & !self.crosses.q.val().get_bit(self.bottom_bit.val().index());
        self.maj_left.next = self.area.q.val().get_bit(self.area_msb.val().index());
        for e in 0..3 {
            self.edx[e].next = self.kdx[e].val();
            self.edy[e].next = self.kdy[e].val();
            self.count[e].next = self.span[e].val();
        }
        self.bx[0].next = self.xn[0].val();
        self.by[0].next = self.yn[0].val();
        self.cy[0].next = self.cv[0].val();
        self.bx[1].next = self.xn[0].val();
        self.by[1].next = self.yn[0].val();
        self.cy[1].next = self.cv[0].val();
        self.bx[2].next = self.xn[1].val();
        self.by[2].next = self.yn[1].val();
        self.cy[2].next = self.cv[1].val();
        if self.up.val() {
            self.edx[1].next = self.kdx[2].val();
            self.edy[1].next = self.kdy[2].val();
            self.count[1].next = self.span[2].val();
            self.edx[2].next = self.kdx[1].val();
            self.edy[2].next = self.kdy[1].val();
            self.count[2].next = self.span[1].val();
            self.bx[0].next = self.xn[2].val();
            self.by[0].next = self.yn[2].val();
            self.cy[0].next = self.cv[2].val() - (self.frac_mask.val() + 1);
            self.bx[1].next = self.xn[2].val();
            self.by[1].next = self.yn[2].val();
            self.cy[1].next = self.cv[2].val() - (self.frac_mask.val() + 1);
            self.cy[2].next = self.cv[1].val() - (self.frac_mask.val() + 1);
        }
        // dy is positive; `bit_cast` (a loop's index cannot) widens it to the divisor.
        self.edy_d[0].next = bit_cast::<DIV_D, G>(self.edy[0].val());
        self.edy_d[1].next = bit_cast::<DIV_D, G>(self.edy[1].val());
        self.edy_d[2].next = bit_cast::<DIV_D, G>(self.edy[2].val());
        // e_maj is the left side when maj_left; the short edges are then on the right.
        self.tracked[0].next = self.x[0].q.val() - 1;
        if self.maj_left.val() {
            self.tracked[0].next = self.x[0].q.val();
        }
        for e in 1..3 {
            self.tracked[e].next = self.x[e].q.val();
            if self.maj_left.val() {
                self.tracked[e].next = self.x[e].q.val() - 1;
            }
        }
        for e in 0..3 {
            self.ed16[e].next = self.edy_d[e].val() << self.frac.val();
            // The start division's offsets: t from the base vertex to the centre, and the
            // base's x - 1/2 split into pixel and fraction (floor).
            self.toff[e].next = self.cy[e].val() - self.by[e].val();
            self.xb[e].next = self.bx[e].val() - self.half.val();
            self.xf[e].next = self.xb[e].val() & self.frac_mask.val();
            self.xi[e].next = self.xb[e].val() >> self.frac.val();
            if self.xb[e].val().get_bit(self.nb_msb.val().index()) {
                self.xi[e].next = (self.xb[e].val() >> self.frac.val()) | self.shr_ext.val();
            }
            // Offsets from v0 of the pixel centre this side tracks.
            self.off_y[e].next = self.cy[e].val() - self.yn[0].val();
            self.off_x[e].next = (self.tracked[e].val() << self.frac.val()) + self.half.val() - self.xn[0].val();
        }
        // Attribute differences along e_maj and e_bot; v0's attributes.
        self.dmaj[0].next = self.zn[2].val() - self.zn[0].val();
        self.dbot[0].next = self.zn[1].val() - self.zn[0].val();
        self.attr0[0].next = bit_cast::<ATTR, NB>(self.zn[0].val());
        self.attr0[1].next = bit_cast::<ATTR, COLOR>(self.vc[0].q.val());
        self.attr0[2].next = bit_cast::<ATTR, COLOR>(self.vc[1].q.val());
        self.attr0[3].next = bit_cast::<ATTR, COLOR>(self.vc[2].q.val());
        for c in 0..3 {
            self.dmaj[c + 1].next = self.cn[6 + c].val() - self.cn[c].val();
            self.dbot[c + 1].next = self.cn[3 + c].val() - self.cn[c].val();
        }

        // ---- Normalise twice the area for 1/area (`recip_operands`): |a| << (32 - exp).
        self.area_abs.next = self.area.q.val();
        if self.area.q.val().get_bit(self.area_msb.val().index()) {
            self.area_abs.next = bits::<AREA>(0) - self.area.q.val();
        }
        self.exp_c.next = 0.into();
        for i in 0..AREA {
            if self.area_abs.val().get_bit(i) {
                self.exp_c.next = i.to_bits();
            }
        }
        self.norm_d.next = self.area_abs.val() << (self.recip_top.val() - self.exp_c.val());
        if self.t.q.val() == self.iss[0].val() {
            self.exp.d.next = self.exp_c.val();
        }

        // ---- The divider: seven divisions issued, results taken.
        self.div.out_ready.next = true;
        self.div.inp_valid.next = false;
        self.div.inp_n.next = 0.into();
        self.div.inp_d.next = 1.into();
        if self.t.q.val() == self.iss[0].val() {
            self.div.inp_valid.next = true;
            self.div.inp_n.next = self.recip_n.val();
            self.div.inp_d.next = self.norm_d.val();
        }
        for e in 0..3 {
            // Unused divisions go in as 0/1 (`model::divider`).
            if self.t.q.val() == self.iss[1 + 2 * e].val() {
                self.div.inp_valid.next = true;
                if self.count[e].val() != 0 {
                    self.div.inp_n.next = self.num[e].q.val().get_bits::<DIV_N>(0);
                    self.div.inp_d.next = self.ed16[e].val();
                }
            }
            if self.t.q.val() == self.iss[2 + 2 * e].val() {
                self.div.inp_valid.next = true;
                if self.count[e].val() > 1 {
                    self.div.inp_n.next = self.edx[e].val().get_bits::<DIV_N>(0);
                    self.div.inp_d.next = self.edy_d[e].val();
                }
            }
        }
        // The step quotient (|q| <= |dx| fits both), sign-extended when narrower.
        self.q_n.next = bit_cast::<NB, QL>(self.div.out_q.val().get_bits::<QL>(0));
        if self.div.out_q.val().get_bit(self.q_msb.val().index()) {
            self.q_n.next = bit_cast::<NB, QL>(self.div.out_q.val().get_bits::<QL>(0)) | self.q_ext.val();
        }
        self.r_pos.next = self.div.out_r.val() != 0;
        self.mant_now.next = self.mant.q.val();
        if self.t.q.val() == self.res[0].val() {
            self.mant_now.next = self.div.out_q.val().get_bits::<MANT>(0);
            self.mant.d.next = self.div.out_q.val().get_bits::<MANT>(0);
        }
        // eq. (2)'s shift, 15 - exp, goes onto the mantissa when it is a left shift.
        self.lsh.next = self.eq_shift.val() - self.exp.q.val();
        self.rsh.next = self.exp.q.val() - self.eq_shift.val();
        self.mant_a.next = bit_cast::<MUL_A, MANT>(self.mant_now.val());
        if self.exp.q.val() <= self.eq_shift.val() {
            self.mant_a.next = bit_cast::<MUL_A, MANT>(self.mant_now.val()) << self.lsh.val();
        }
        for e in 0..3 {
            // The start: x = first pixel at or right of the edge, r = x*D - num in [0, D).
            if self.t.q.val() == self.res[1 + 2 * e].val() {
                self.x[e].d.next = self.xi[e].val() + self.q_n.val() + self.r_pos.val();
                self.r[e].d.next = 0.into();
                if self.r_pos.val() {
                    self.r[e].d.next =
                        self.ed16[e].val().get_bits::<EDGE_D>(0) - self.div.out_r.val().get_bits::<EDGE_D>(0);
                }
            }
            // The step: q + rho/D pixels per scanline.
            if self.t.q.val() == self.res[2 + 2 * e].val() {
                self.q[e].d.next = self.q_n.val();
                self.rho[e].d.next = self.div.out_r.val().get_bits::<EDGE_D>(0) << self.frac.val();
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
        // eq. (2)'s second factors: the edge deltas with the area's sign.
        for k in 0..2 {
            self.delta[k].next = self.kdx[k].val().get_bits::<NB>(0);
            self.delta[2 + k].next = self.kdy[k].val().get_bits::<NB>(0);
        }
        for d in 0..4 {
            self.eq_b[d].next = self.delta[d].val();
            if self.maj_left.val() {
                self.eq_b[d].next = bits::<NB>(0) - self.delta[d].val();
            }
        }
        // ddx, ddy of each attribute: floor(g / 2^gsh), as lanes.
        for a in 0..4 {
            self.ddx[a].next = self.gx[a].q.val() >> self.gsh[a].val();
            self.ddy[a].next = self.gy[a].q.val() >> self.gsh[a].val();
        }
        for m in 0..self._k {
            // Area: e_maj.dx * e_bot.dy - e_bot.dx * e_maj.dy.
            if (self.lane[0].val().index() == m) & self.act[0].val() {
                self.mul[m].a.next = self.kdx[0].val().get_bits::<MUL_A>(0);
                self.mul[m].b.next = self.kdy[1].val().get_bits::<MUL_B>(0);
                self.pa[0].next = self.mul[m].p.val().get_bits::<AREA>(0);
            }
            if (self.lane[1].val().index() == m) & self.act[1].val() {
                self.mul[m].a.next = self.kdx[1].val().get_bits::<MUL_A>(0);
                self.mul[m].b.next = self.kdy[0].val().get_bits::<MUL_B>(0);
                self.pa[1].next = self.mul[m].p.val().get_bits::<AREA>(0);
            }
            for e in 0..3 {
                // Start numerator: x fraction * dy + dx * t.
                if (self.lane[2 + 2 * e].val().index() == m) & self.act[2 + 2 * e].val() {
                    self.mul[m].a.next = self.edy[e].val();
                    self.mul[m].b.next = self.xf[e].val();
                    self.pn[2 * e].next = self.mul[m].p.val();
                }
                if (self.lane[3 + 2 * e].val().index() == m) & self.act[3 + 2 * e].val() {
                    self.mul[m].a.next = self.edx[e].val().get_bits::<MUL_A>(0);
                    self.mul[m].b.next = self.toff[e].val();
                    self.pn[2 * e + 1].next = self.mul[m].p.val();
                }
            }
            for d in 0..4 {
                // eq. (2): OneOverArea's mantissa times +-delta.
                if (self.lane[8 + d].val().index() == m) & self.act[8 + d].val() {
                    self.mul[m].a.next = self.mant_a.val();
                    self.mul[m].b.next = self.eq_b[d].val();
                    self.pe[d].next = self.mul[m].p.val().get_bits::<G>(0);
                }
            }
            for a in 0..4 {
                // dx = p_bot_dy * d_maj - p_maj_dy * d_bot; dy = p_maj_dx * d_bot - p_bot_dx * d_maj.
                if (self.lane[12 + 4 * a].val().index() == m) & self.act[12 + 4 * a].val() {
                    self.mul[m].a.next = self.p[3].q.val();
                    self.mul[m].b.next = self.dmaj[a].val();
                    self.pg[4 * a].next = self.mul[m].p.val().get_bits::<G>(0);
                }
                if (self.lane[13 + 4 * a].val().index() == m) & self.act[13 + 4 * a].val() {
                    self.mul[m].a.next = self.p[2].q.val();
                    self.mul[m].b.next = self.dbot[a].val();
                    self.pg[4 * a + 1].next = self.mul[m].p.val().get_bits::<G>(0);
                }
                if (self.lane[14 + 4 * a].val().index() == m) & self.act[14 + 4 * a].val() {
                    self.mul[m].a.next = self.p[0].q.val();
                    self.mul[m].b.next = self.dbot[a].val();
                    self.pg[4 * a + 2].next = self.mul[m].p.val().get_bits::<G>(0);
                }
                if (self.lane[15 + 4 * a].val().index() == m) & self.act[15 + 4 * a].val() {
                    self.mul[m].a.next = self.p[1].q.val();
                    self.mul[m].b.next = self.dmaj[a].val();
                    self.pg[4 * a + 3].next = self.mul[m].p.val().get_bits::<G>(0);
                }
            }
            for e in 0..3 {
                for a in 0..4 {
                    // at: ddx * off_x + ddy * off_y; inc0 = ddy + q * ddx.
                    if (self.lane[28 + 12 * e + 3 * a].val().index() == m) & self.act[28 + 12 * e + 3 * a].val() {
                        self.mul[m].a.next = self.ddx[a].val();
                        self.mul[m].b.next = self.off_x[e].val();
                        self.ps[12 * e + 3 * a].next = self.mul[m].p.val().get_bits::<ATTR>(0);
                    }
                    if (self.lane[29 + 12 * e + 3 * a].val().index() == m) & self.act[29 + 12 * e + 3 * a].val() {
                        self.mul[m].a.next = self.ddy[a].val();
                        self.mul[m].b.next = self.off_y[e].val();
                        self.ps[12 * e + 3 * a + 1].next = self.mul[m].p.val().get_bits::<ATTR>(0);
                    }
                    if (self.lane[30 + 12 * e + 3 * a].val().index() == m) & self.act[30 + 12 * e + 3 * a].val() {
                        self.mul[m].a.next = self.ddx[a].val();
                        self.mul[m].b.next = self.q[e].q.val();
                        self.ps[12 * e + 3 * a + 2].next = self.mul[m].p.val().get_bits::<ATTR>(0);
                    }
                }
            }
        }

        // ---- Accumulate each product into its register (the first one of a register
        // starts it afresh). Products not due are 0.
        self.area_base.next = self.area.q.val();
        if self.act[0].val() {
            self.area_base.next = 0.into();
        }
        self.area.d.next = self.area_base.val() + self.pa[0].val() - self.pa[1].val();
        for e in 0..3 {
            self.num_base[e].next = self.num[e].q.val();
            if self.act[2 + 2 * e].val() {
                self.num_base[e].next = 0.into();
            }
            self.num[e].d.next = self.num_base[e].val() + self.pn[2 * e].val() + self.pn[2 * e + 1].val();
        }
        // eq. (2): sign * delta * mant * 2^(15 - exp), floor, into `ooa_d`.
        for d in 0..4 {
            self.shr[d].next = self.pe[d].val() >> self.rsh.val();
            if self.pe[d].val().get_bit(self.p_msb.val().index()) {
                self.shr[d].next = (self.pe[d].val() >> self.rsh.val()) | !(self.ones.val() >> self.rsh.val());
            }
            if self.act[8 + d].val() {
                self.p[d].d.next = self.shr[d].val();
                if self.exp.q.val() <= self.eq_shift.val() {
                    self.p[d].d.next = self.pe[d].val();
                }
            }
        }
        for a in 0..4 {
            self.gx_base[a].next = self.gx[a].q.val();
            if self.act[12 + 4 * a].val() {
                self.gx_base[a].next = 0.into();
            }
            self.gx[a].d.next = self.gx_base[a].val() + self.pg[4 * a].val() - self.pg[4 * a + 1].val();
            self.gy_base[a].next = self.gy[a].q.val();
            if self.act[14 + 4 * a].val() {
                self.gy_base[a].next = 0.into();
            }
            self.gy[a].d.next = self.gy_base[a].val() + self.pg[4 * a + 2].val() - self.pg[4 * a + 3].val();
        }
        for e in 0..3 {
            for a in 0..4 {
                self.plane_base[4 * e + a].next = self.plane[4 * e + a].q.val();
                if self.act[28 + 12 * e + 3 * a].val() {
                    self.plane_base[4 * e + a].next = 0.into();
                }
                self.plane[4 * e + a].d.next = self.plane_base[4 * e + a].val()
                    + self.ps[12 * e + 3 * a].val()
                    + self.ps[12 * e + 3 * a + 1].val();
                if self.act[30 + 12 * e + 3 * a].val() {
                    self.inc0[4 * e + a].d.next =
                        self.ddy[a].val().get_bits::<ATTR>(0) + self.ps[12 * e + 3 * a + 2].val();
                }
                // Hand-over: at = v0's attribute + floor(plane / 2^s); inc1 = inc0 + ddx.
                if self.t.q.val() == self.handover.val() {
                    self.plane[4 * e + a].d.next =
                        (self.plane[4 * e + a].q.val() >> self.frac.val()) + (self.attr0[a].val() << self.bsh[a].val());
                    self.inc1[4 * e + a].d.next = self.inc0[4 * e + a].q.val() + self.ddx[a].val().get_bits::<ATTR>(0);
                }
            }
        }

        // ---- The result.
        self.out.walk.next = self.up.val();
        self.out.maj_left.next = self.maj_left.val();
        self.out.maj_j.next = self.cy[0].val().get_bits::<PIXEL>(self.frac.val().index());
        self.out.maj_count.next = self.count[0].val();
        self.out.maj_x.next = self.x[0].q.val().get_bits::<PIXEL>(0);
        self.out.maj_r.next = self.r[0].q.val();
        self.out.maj_q.next = self.q[0].q.val().get_bits::<EDGE_Q>(0);
        self.out.maj_rho.next = self.rho[0].q.val();
        self.out.maj_d.next = self.ed16[0].val().get_bits::<EDGE_D>(0);
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
        self.out.short0_j.next = self.cy[1].val().get_bits::<PIXEL>(self.frac.val().index());
        self.out.short0_count.next = self.count[1].val();
        self.out.short0_x.next = self.x[1].q.val().get_bits::<PIXEL>(0);
        self.out.short0_r.next = self.r[1].q.val();
        self.out.short0_q.next = self.q[1].q.val().get_bits::<EDGE_Q>(0);
        self.out.short0_rho.next = self.rho[1].q.val();
        self.out.short0_d.next = self.ed16[1].val().get_bits::<EDGE_D>(0);
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
        self.out.short1_j.next = self.cy[2].val().get_bits::<PIXEL>(self.frac.val().index());
        self.out.short1_count.next = self.count[2].val();
        self.out.short1_x.next = self.x[2].q.val().get_bits::<PIXEL>(0);
        self.out.short1_r.next = self.r[2].q.val();
        self.out.short1_q.next = self.q[2].q.val().get_bits::<EDGE_Q>(0);
        self.out.short1_rho.next = self.rho[2].q.val();
        self.out.short1_d.next = self.ed16[2].val().get_bits::<EDGE_D>(0);
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
        self.out.ddx_z.next = self.ddx[0].val().get_bits::<DZ>(0);
        self.out.ddx_c0.next = self.ddx[1].val().get_bits::<DC>(0);
        self.out.ddx_c1.next = self.ddx[2].val().get_bits::<DC>(0);
        self.out.ddx_c2.next = self.ddx[3].val().get_bits::<DC>(0);
    }
}

crate::pins!(TriangleSetup {
    clock: clock,
    inputs: [
    ],
    outputs: [
    ],
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
    })
}
