//! `edge_walk`: the edge walk of paper 001 (Woo 2004, §II.2.라) with the Y clipping of
//! paper 003 (Lee 2008, §II.1.다.(2), Fig. 5), one scanline per cycle.
//!
//! It takes one set-up triangle (`model::triangle_setup::TriangleSetupOut` without
//! `divisions`, on the link `inp`: `links::TriangleSetupSink`) and walks it with two
//! exact edge steppers ([`Stepper`]): `maj` on the long edge and `cur` on the short edge
//! being walked, while the other short edge waits in the `pend_*` registers until the walk
//! reaches its first scanline. Each scanline with pixels on screen leaves as a span
//! command (`model::edge_walk::SpanCmd`, on the link `out`); an empty scanline, or one
//! above the screen, still takes its cycle with `out$valid` low.
//!
//! ```text
//!   walk Down (from vMin)            walk Up (from vMax: crosses row 0 only)
//!        vMin                         -------- row 0 --------   <- stops after row 0
//!        /|     k = 0                     /|    k = count - 1
//!  e_bot/ |e_maj                    e_bot/ |
//!      /  |     ...                     /  |e_maj   ...
//!  vMid\  |                         vMid\  |
//!  e_top\ |                         e_top\ |
//!        \|     <- stops at vMax          \|    k = 0
//!        vMax      or after the last row   vMax
//! ```
//!
//! Y clipping (003): setup chose the walk direction (`inp.walk`); the walk stops after
//! the last row of the screen walking down and after row 0 walking up, so no cycle is
//! spent beyond the boundary it walks towards.
//!
//! **Pipeline** (for the clock: every decision is a register, no adder feeds another in
//! one cycle). Two stages, the walker and the span command register (`o_*`, which drives
//! `out`):
//!
//! ```text
//!   inp --[accept: EdgeStart x3, counters]--> steppers maj, cur; pend_* (short[1])
//!   walker (scanline k) --[emit: sides, x - 1, Y clip]--> o_* (scanline k) --> out
//!              \--[step]--> walker (scanline k + 1)
//! ```
//!
//! * Each stepper keeps, instead of 001's remainder r, the decision variable `t`: walking
//!   down t = r - rho, walking up t = D - 1 - r - rho; x moves q + 1 exactly when t < 0
//!   (down: r < rho; up: r + rho >= D) and either way t += D - rho on such a step and
//!   t -= rho on the others ([`EdgeStart`] at the hand-over, [`Stepper`]). So the step's
//!   choice is t's sign bit, a register, and not a compare behind an add. A step up
//!   subtracts as an add of the inverse (x + !q + !one, at + !inc + 1), so x and each
//!   attribute have one adder for both directions.
//! * The walker runs one scanline ahead of `out`: in the cycle it writes scanline k into
//!   `o_*` it steps to k + 1. Whether its scanline is the last (the long edge ends, or the
//!   Y clip's boundary) and whether its next step moves `cur` to the second short edge are
//!   registers too (`last_r`, `sw_r`), set a step ahead from down-counters (`rem`, `crow`,
//!   `crem`) loaded at the hand-over. `cur` takes the second short edge at the hand-over
//!   when the first crosses no scanline.
//! * At the hand-over `inp` goes through one adder (`EdgeStart`: t in carry-save form, D -
//!   rho, -rho; the rows to the Y clip's boundary) and the steppers' load multiplexers into
//!   registers: inside `raster_top` the path begins wherever setup's outputs do.
//! * `o_*` takes the next scanline whenever the one it holds leaves (taken, or no pixels):
//!   the walk holds while a command waits for `out$ready`, exactly as a walk with no
//!   register would.
//!
//! Timing (`model::edge_walk::{LATENCY, II}` = 2, 1, as before the pipelining): a
//! triangle is taken in cycle t (IDLE); in cycle t + 1 the walker writes scanline 0 into
//! `o_*` (or, when the Y clip leaves no scanline, goes idle again); scanline k is presented
//! in cycle t + 2 + k and held while `out$ready` is low; the next triangle is taken the
//! cycle after the last scanline is presented and taken. Model:
//! `model::edge_walk::edge_walk`. Emitted: `hdl-out/edge_walk.v`.

use super::links::{SpanCmdSource, TriangleSetupSink};
use super::widths::{C_ACC, DC, DIM, DZ, EDGE_D, EDGE_Q, PIXEL, SCREEN, Z_ACC};
use crate::emit::{emit_unit, Emitted};
use crate::parts::{Negative, SignedLess};
use crate::switch::{Parts, Switch};
use crate::Params;
use rust_hdl::prelude::*;

/// One attribute (z, R, G or B) of an edge stepper: its value at the pixel the stepper
/// tracks, and its change per scanline when x moves q (`inc0`) or q + 1 (`inc1`) pixels.
/// `W` is the accumulator's width (`z_acc` or `c_acc`); the increments keep only their
/// low `W` bits, the only ones that reach a `W`-bit accumulator (modular arithmetic,
/// `fx::formats`).
#[derive(LogicBlock, Default)]
pub struct EdgeAttr<const W: usize> {
    pub clock: Signal<In, Clock>,
    /// Load `ld_*` (takes priority over `step`).
    pub load: Signal<In, Bit>,
    /// Step one scanline in the walk direction.
    pub step: Signal<In, Bit>,
    /// Walk direction: high walks up (subtracts the increment).
    pub up: Signal<In, Bit>,
    /// x moves q + 1 pixels on this step (add `inc1`), else q (add `inc0`).
    pub one: Signal<In, Bit>,
    pub ld_at: Signal<In, Bits<W>>,
    pub ld_inc0: Signal<In, Bits<W>>,
    pub ld_inc1: Signal<In, Bits<W>>,
    /// The attribute at the tracked pixel.
    pub at: Signal<Out, Bits<W>>,
    at_r: DFF<Bits<W>>,
    inc0_r: DFF<Bits<W>>,
    inc1_r: DFF<Bits<W>>,
    inc: Signal<Local, Bits<W>>,
    /// `inc`, inverted walking up.
    inc_dir: Signal<Local, Bits<W>>,
}

impl<const W: usize> Logic for EdgeAttr<W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, at_r, inc0_r, inc1_r);
        self.inc.next = self.inc0_r.q.val();
        if self.one.val() {
            self.inc.next = self.inc1_r.q.val();
        }
        // Up subtracts: at + !inc + 1, so that one adder does both directions.
        self.inc_dir.next = self.inc.val();
        if self.up.val() {
            self.inc_dir.next = !self.inc.val();
        }
        if self.step.val() {
            self.at_r.d.next = self.at_r.q.val() + self.inc_dir.val() + self.up.val();
        }
        if self.load.val() {
            self.at_r.d.next = self.ld_at.val();
            self.inc0_r.d.next = self.ld_inc0.val();
            self.inc1_r.d.next = self.ld_inc1.val();
        }
        self.at.next = self.at_r.q.val();
    }
}

/// Width of a stepper's decision variable `t` and its two steps: r, rho in [0, D) with
/// D < 2^EDGE_D, so t is in (-D, D) and D - rho in (0, D].
pub const EDGE_T: usize = EDGE_D + 1;

/// An edge's walk state at the hand-over, from setup's remainder form (`r`, `rho`, `D`;
/// combinational): the stepper's decision variable `t` (down: r - rho; up: D - 1 - r - rho)
/// and its steps, `a` = D - rho after a step of q + 1 pixels, `b` = -rho after one of q.
#[derive(LogicBlock, Default)]
pub struct EdgeStart {
    /// The walk goes up.
    pub up: Signal<In, Bit>,
    pub r: Signal<In, Bits<EDGE_D>>,
    pub rho: Signal<In, Bits<EDGE_D>>,
    pub d: Signal<In, Bits<EDGE_D>>,
    pub t: Signal<Out, Bits<EDGE_T>>,
    pub a: Signal<Out, Bits<EDGE_T>>,
    pub b: Signal<Out, Bits<EDGE_T>>,
    r_w: Signal<Local, Bits<EDGE_T>>,
    rho_w: Signal<Local, Bits<EDGE_T>>,
    d_w: Signal<Local, Bits<EDGE_T>>,
    /// The walk up's t = D + !r + !rho + 1 in carry-save form (one adder, not two):
    /// `sum` + (`carry` << 1 | 1).
    nr: Signal<Local, Bits<EDGE_T>>,
    nrho: Signal<Local, Bits<EDGE_T>>,
    sum: Signal<Local, Bits<EDGE_T>>,
    carry: Signal<Local, Bits<EDGE_T>>,
}

impl Logic for EdgeStart {
    #[hdl_gen]
    fn update(&mut self) {
        self.r_w.next = bit_cast::<EDGE_T, EDGE_D>(self.r.val());
        self.rho_w.next = bit_cast::<EDGE_T, EDGE_D>(self.rho.val());
        self.d_w.next = bit_cast::<EDGE_T, EDGE_D>(self.d.val());
        self.a.next = self.d_w.val() - self.rho_w.val();
        self.b.next = !self.rho_w.val() + 1;
        // Up: D - 1 - r - rho = D + !r + !rho + 1, a full adder per bit and one carry chain.
        self.nr.next = !self.r_w.val();
        self.nrho.next = !self.rho_w.val();
        self.sum.next = self.d_w.val() ^ self.nr.val() ^ self.nrho.val();
        self.carry.next =
            (self.d_w.val() & self.nr.val()) | (self.d_w.val() & self.nrho.val()) | (self.nr.val() & self.nrho.val());
        self.t.next = self.r_w.val() - self.rho_w.val();
        if self.up.val() {
            self.t.next = self.sum.val() + ((self.carry.val() << 1) | 1);
        }
    }
}

/// One exact edge stepper (001's edge walk, exact in the manner of Bresenham): on each
/// scanline, `x` is the first pixel whose centre is at or right of the edge. 001 keeps r
/// in [0, D), how far the edge lies left of that centre in units of 1/D pixel: a step down
/// moves x by q + 1 when `r < rho` (r += D - rho) and by q otherwise (r -= rho); a step up
/// is its exact inverse (q + 1 when r + rho >= D). The stepper keeps `t` instead
/// ([`EdgeStart`]: r - rho walking down, D - 1 - r - rho walking up), so that in both
/// directions the step is q + 1 exactly when t < 0, t += D - rho (`a`) then and t -= rho
/// (`b`) otherwise: t's sign bit, a register, chooses the step. Model: `Stepper` in
/// `model::edge_walk`.
///
/// `q` keeps only its low `PIXEL` bits: x always lands in the `PIXEL`-bit range, so the
/// sum modulo 2^PIXEL is exact.
#[derive(LogicBlock, Default)]
pub struct Stepper {
    pub clock: Signal<In, Clock>,
    /// Load the edge from `ld_*` (takes priority over `step`).
    pub load: Signal<In, Bit>,
    /// Step one scanline in the walk direction.
    pub step: Signal<In, Bit>,
    /// Walk direction: high walks up.
    pub up: Signal<In, Bit>,
    pub ld_x: Signal<In, Bits<PIXEL>>,
    pub ld_q: Signal<In, Bits<PIXEL>>,
    /// `t`, `a`, `b` of [`EdgeStart`].
    pub ld_t: Signal<In, Bits<EDGE_T>>,
    pub ld_a: Signal<In, Bits<EDGE_T>>,
    pub ld_b: Signal<In, Bits<EDGE_T>>,
    pub ld_at_z: Signal<In, Bits<Z_ACC>>,
    pub ld_at_c0: Signal<In, Bits<C_ACC>>,
    pub ld_at_c1: Signal<In, Bits<C_ACC>>,
    pub ld_at_c2: Signal<In, Bits<C_ACC>>,
    pub ld_inc0_z: Signal<In, Bits<Z_ACC>>,
    pub ld_inc0_c0: Signal<In, Bits<C_ACC>>,
    pub ld_inc0_c1: Signal<In, Bits<C_ACC>>,
    pub ld_inc0_c2: Signal<In, Bits<C_ACC>>,
    pub ld_inc1_z: Signal<In, Bits<Z_ACC>>,
    pub ld_inc1_c0: Signal<In, Bits<C_ACC>>,
    pub ld_inc1_c1: Signal<In, Bits<C_ACC>>,
    pub ld_inc1_c2: Signal<In, Bits<C_ACC>>,
    /// The tracked pixel on this scanline.
    pub x: Signal<Out, Bits<PIXEL>>,
    /// The attributes there.
    pub at_z: Signal<Out, Bits<Z_ACC>>,
    pub at_c0: Signal<Out, Bits<C_ACC>>,
    pub at_c1: Signal<Out, Bits<C_ACC>>,
    pub at_c2: Signal<Out, Bits<C_ACC>>,
    x_r: DFF<Bits<PIXEL>>,
    q_r: DFF<Bits<PIXEL>>,
    t_r: DFF<Bits<EDGE_T>>,
    a_r: DFF<Bits<EDGE_T>>,
    b_r: DFF<Bits<EDGE_T>>,
    z: EdgeAttr<Z_ACC>,
    c0: EdgeAttr<C_ACC>,
    c1: EdgeAttr<C_ACC>,
    c2: EdgeAttr<C_ACC>,
    /// t < 0: the next step moves x by q + 1 pixels.
    t_sign: Negative<EDGE_T>,
    one: Signal<Local, Bit>,
    /// a or b.
    t_inc: Signal<Local, Bits<EDGE_T>>,
    /// q and `one`, both inverted walking up.
    q_dir: Signal<Local, Bits<PIXEL>>,
    one_dir: Signal<Local, Bit>,
}

impl Logic for Stepper {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, x_r, q_r, t_r, a_r, b_r);
        clock!(self, clock, z, c0, c1, c2);
        self.t_sign.x.next = self.t_r.q.val();
        self.one.next = self.t_sign.neg.val();
        self.t_inc.next = self.b_r.q.val();
        if self.one.val() {
            self.t_inc.next = self.a_r.q.val();
        }
        // x += q + one walking down; walking up x -= q + one, as x + !q + !one (one adder).
        self.q_dir.next = self.q_r.q.val();
        self.one_dir.next = self.one.val();
        if self.up.val() {
            self.q_dir.next = !self.q_r.q.val();
            self.one_dir.next = !self.one.val();
        }
        if self.step.val() {
            self.t_r.d.next = self.t_r.q.val() + self.t_inc.val();
            self.x_r.d.next = self.x_r.q.val() + self.q_dir.val() + self.one_dir.val();
        }
        if self.load.val() {
            self.x_r.d.next = self.ld_x.val();
            self.q_r.d.next = self.ld_q.val();
            self.t_r.d.next = self.ld_t.val();
            self.a_r.d.next = self.ld_a.val();
            self.b_r.d.next = self.ld_b.val();
        }
        self.z.load.next = self.load.val();
        self.z.step.next = self.step.val();
        self.z.up.next = self.up.val();
        self.z.one.next = self.one.val();
        self.z.ld_at.next = self.ld_at_z.val();
        self.z.ld_inc0.next = self.ld_inc0_z.val();
        self.z.ld_inc1.next = self.ld_inc1_z.val();
        self.c0.load.next = self.load.val();
        self.c0.step.next = self.step.val();
        self.c0.up.next = self.up.val();
        self.c0.one.next = self.one.val();
        self.c0.ld_at.next = self.ld_at_c0.val();
        self.c0.ld_inc0.next = self.ld_inc0_c0.val();
        self.c0.ld_inc1.next = self.ld_inc1_c0.val();
        self.c1.load.next = self.load.val();
        self.c1.step.next = self.step.val();
        self.c1.up.next = self.up.val();
        self.c1.one.next = self.one.val();
        self.c1.ld_at.next = self.ld_at_c1.val();
        self.c1.ld_inc0.next = self.ld_inc0_c1.val();
        self.c1.ld_inc1.next = self.ld_inc1_c1.val();
        self.c2.load.next = self.load.val();
        self.c2.step.next = self.step.val();
        self.c2.up.next = self.up.val();
        self.c2.one.next = self.one.val();
        self.c2.ld_at.next = self.ld_at_c2.val();
        self.c2.ld_inc0.next = self.ld_inc0_c2.val();
        self.c2.ld_inc1.next = self.ld_inc1_c2.val();
        self.x.next = self.x_r.q.val();
        self.at_z.next = self.z.at.val();
        self.at_c0.next = self.c0.at.val();
        self.at_c1.next = self.c1.at.val();
        self.at_c2.next = self.c2.at.val();
    }
}

/// The edge walk unit: see the module documentation. The link `inp` carries
/// `model::triangle_setup::TriangleSetupOut` (`links::TriangleSetupSink`), the link `out`
/// `model::edge_walk::SpanCmd` (`links::SpanCmdSource`, `y` on screen).
///
/// `inp$short0_j`, `inp$short1_j` and `inp$short1_count` are part of the one-to-one link
/// with `triangle_setup` but follow from the others (the short edges start where the long
/// edge does, and at scanline `short0.count`), so the walk does not read them.
#[derive(LogicBlock, Default)]
pub struct EdgeWalk {
    pub clock: Signal<In, Clock>,
    /// Screen height in pixels, 1 to 2^SCREEN: the walk down stops after row `height - 1`.
    /// Read only when a triangle is taken.
    pub height: Signal<In, Bits<DIM>>,
    /// The set-up triangle; `inp.ready` high in IDLE while `hold` is low: a triangle is
    /// taken when `inp.valid` is high too.
    pub inp: TriangleSetupSink,
    /// A span command (a scanline with pixels, on screen).
    pub out: SpanCmdSource,
    /// Take no triangle (the textured `raster_top`'s gate: one triangle behind setup at a
    /// time).
    pub hold: Signal<In, Bit>,
    /// IDLE: no triangle taken, no span command held.
    pub idle: Signal<Out, Bit>,
    /// IDLE next cycle (`busy`'s next value): `inp.ready` then, unless `hold` is high. Setup
    /// registers its stall from it a cycle ahead (`triangle_setup`'s `out_free_next`).
    pub free_next: Signal<Out, Bit>,
    /// Y clipping present (`CLIP_Y`, `crate::switch`); without it the walk is always down
    /// and the screen's rows are not checked: no triangle may cross the top or bottom.
    clip_y: Switch,
    /// The long edge and the short edge being walked.
    maj: Stepper,
    cur: Stepper,
    /// The walk state of the three edges at the hand-over.
    start_maj: EdgeStart,
    start_s0: EdgeStart,
    start_s1: EdgeStart,
    /// IDLE = !busy; the walker has a scanline to write into `o_*` while `walking`; busy and
    /// not walking: the last scanline (or none) is still in `o_*`.
    busy: DFF<Bit>,
    walking: DFF<Bit>,
    /// Walk direction and side of the long edge, for the triangle being walked.
    up: DFF<Bit>,
    maj_left: DFF<Bit>,
    /// The walker's scanline `j` (the k-th of the walk), and down-counters: `rem` =
    /// count - 1 - k scanlines of the long edge after it, `crow` rows to the Y clip's
    /// boundary (walking down, height - 1 - j; up, j), `crem` = short0.count - 1 - k.
    j: DFF<Bits<PIXEL>>,
    rem: DFF<Bits<PIXEL>>,
    crow: DFF<Bits<PIXEL>>,
    crem: DFF<Bits<PIXEL>>,
    /// The walker's scanline is the last (rem = 0, or crow = 0 with the Y clip).
    last_r: DFF<Bit>,
    /// The walker's next step moves `cur` to the second short edge (crem = 0).
    sw_r: DFF<Bit>,
    ddx_z: DFF<Bits<DZ>>,
    ddx_c0: DFF<Bits<DC>>,
    ddx_c1: DFF<Bits<DC>>,
    ddx_c2: DFF<Bits<DC>>,
    /// The second short edge, waiting (as `Stepper` loads it).
    pend_x: DFF<Bits<PIXEL>>,
    pend_q: DFF<Bits<PIXEL>>,
    pend_t: DFF<Bits<EDGE_T>>,
    pend_a: DFF<Bits<EDGE_T>>,
    pend_b: DFF<Bits<EDGE_T>>,
    pend_at_z: DFF<Bits<Z_ACC>>,
    pend_at_c0: DFF<Bits<C_ACC>>,
    pend_at_c1: DFF<Bits<C_ACC>>,
    pend_at_c2: DFF<Bits<C_ACC>>,
    pend_inc0_z: DFF<Bits<Z_ACC>>,
    pend_inc0_c0: DFF<Bits<C_ACC>>,
    pend_inc0_c1: DFF<Bits<C_ACC>>,
    pend_inc0_c2: DFF<Bits<C_ACC>>,
    pend_inc1_z: DFF<Bits<Z_ACC>>,
    pend_inc1_c0: DFF<Bits<C_ACC>>,
    pend_inc1_c1: DFF<Bits<C_ACC>>,
    pend_inc1_c2: DFF<Bits<C_ACC>>,
    /// The span command presented on `out`: `o_valid` high when it has pixels on screen.
    o_valid: DFF<Bit>,
    o_y: DFF<Bits<SCREEN>>,
    o_xl: DFF<Bits<PIXEL>>,
    o_xr: DFF<Bits<PIXEL>>,
    o_left_z: DFF<Bits<Z_ACC>>,
    o_left_c0: DFF<Bits<C_ACC>>,
    o_left_c1: DFF<Bits<C_ACC>>,
    o_left_c2: DFF<Bits<C_ACC>>,
    o_right_z: DFF<Bits<Z_ACC>>,
    o_right_c0: DFF<Bits<C_ACC>>,
    o_right_c1: DFF<Bits<C_ACC>>,
    o_right_c2: DFF<Bits<C_ACC>>,
    /// The walker's j < 0; its left side's x < its right side's (the scanline has pixels).
    j_sign: Negative<PIXEL>,
    sides: SignedLess<PIXEL>,
    /// At the hand-over: `inp.maj_j` < 0.
    in_j_sign: Negative<PIXEL>,
    accept: Signal<Local, Bit>,
    /// At the hand-over: the triangle's walk direction; no scanline left after the Y clip;
    /// `crow` and `last_r` for scanline 0; the first short edge crosses no scanline.
    in_up: Signal<Local, Bit>,
    in_no_rows: Signal<Local, Bit>,
    in_crow: Signal<Local, Bits<PIXEL>>,
    in_last: Signal<Local, Bit>,
    in_short0_none: Signal<Local, Bit>,
    height_j: Signal<Local, Bits<PIXEL>>,
    /// `o_*` is free for the next scanline (empty, holding no pixels, or taken now).
    free: Signal<Local, Bit>,
    /// The walker writes its scanline into `o_*`; and steps to the next.
    emit: Signal<Local, Bit>,
    step: Signal<Local, Bit>,
    /// The walker's scanline has pixels on screen.
    valid: Signal<Local, Bit>,
    j_next: Signal<Local, Bits<PIXEL>>,
}

impl Logic for EdgeWalk {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            busy,
            walking,
            up,
            maj_left,
            j,
            rem,
            crow,
            crem,
            last_r,
            sw_r,
            ddx_z,
            ddx_c0,
            ddx_c1,
            ddx_c2,
            pend_x,
            pend_q,
            pend_t,
            pend_a,
            pend_b,
            pend_at_z,
            pend_at_c0,
            pend_at_c1,
            pend_at_c2,
            pend_inc0_z,
            pend_inc0_c0,
            pend_inc0_c1,
            pend_inc0_c2,
            pend_inc1_z,
            pend_inc1_c0,
            pend_inc1_c1,
            pend_inc1_c2,
            o_valid,
            o_y,
            o_xl,
            o_xr,
            o_left_z,
            o_left_c0,
            o_left_c1,
            o_left_c2,
            o_right_z,
            o_right_c0,
            o_right_c1,
            o_right_c2
        );
        clock!(self, clock, maj, cur);

        // IDLE: take a triangle. What its walk needs first, from the link: the direction,
        // whether the Y clip leaves any scanline (none when the long edge crosses no
        // scanline centre or the walk starts beyond the boundary it walks towards), the rows
        // to the boundary and whether scanline 0 is the last.
        self.idle.next = !self.busy.q.val();
        self.inp.ready.next = !self.busy.q.val() & !self.hold.val();
        self.accept.next = self.inp.valid.val() & !self.busy.q.val() & !self.hold.val();
        self.in_up.next = self.inp.walk.val() & self.clip_y.on.val();
        self.height_j.next = bit_cast::<PIXEL, DIM>(self.height.val());
        self.in_j_sign.x.next = self.inp.maj_j.val();
        self.in_no_rows.next = self.inp.maj_count.val() == 0;
        if self.clip_y.on.val() {
            if self.in_up.val() {
                if self.in_j_sign.neg.val() {
                    self.in_no_rows.next = true;
                }
            } else if !self.in_j_sign.neg.val() & (self.inp.maj_j.val() >= self.height_j.val()) {
                self.in_no_rows.next = true;
            }
        }
        // Down: height - 1 - j = height + !j.
        self.in_crow.next = self.height_j.val() + !self.inp.maj_j.val();
        if self.in_up.val() {
            self.in_crow.next = self.inp.maj_j.val();
        }
        self.in_last.next = self.inp.maj_count.val() == 1;
        if self.clip_y.on.val() & (self.in_crow.val() == 0) {
            self.in_last.next = true;
        }
        self.in_short0_none.next = self.inp.short0_count.val() == 0;
        self.start_maj.up.next = self.in_up.val();
        self.start_maj.r.next = self.inp.maj_r.val();
        self.start_maj.rho.next = self.inp.maj_rho.val();
        self.start_maj.d.next = self.inp.maj_d.val();
        self.start_s0.up.next = self.in_up.val();
        self.start_s0.r.next = self.inp.short0_r.val();
        self.start_s0.rho.next = self.inp.short0_rho.val();
        self.start_s0.d.next = self.inp.short0_d.val();
        self.start_s1.up.next = self.in_up.val();
        self.start_s1.r.next = self.inp.short1_r.val();
        self.start_s1.rho.next = self.inp.short1_rho.val();
        self.start_s1.d.next = self.inp.short1_d.val();

        // The walker's scanline as a span command: left side from x, right side up to
        // x - 1; pixels when left x < right x, and on screen when j >= 0.
        self.j_sign.x.next = self.j.q.val();
        self.j_next.next = self.j.q.val() + 1;
        if self.up.q.val() {
            self.j_next.next = self.j.q.val() - 1;
        }
        self.sides.a.next = self.cur.x.val();
        self.sides.b.next = self.maj.x.val();
        if self.maj_left.q.val() {
            self.sides.a.next = self.maj.x.val();
            self.sides.b.next = self.cur.x.val();
        }
        self.valid.next = self.sides.lt.val();
        if self.clip_y.on.val() & self.j_sign.neg.val() {
            self.valid.next = false;
        }

        // The command register: the walker writes the next scanline whenever the one
        // presented leaves (taken, or without pixels), and steps on unless it wrote the last.
        self.free.next = !self.o_valid.q.val() | self.out.ready.val();
        self.emit.next = self.walking.q.val() & self.free.val();
        self.step.next = self.emit.val() & !self.last_r.q.val();
        if self.free.val() {
            self.o_valid.d.next = false;
        }
        if self.emit.val() {
            self.o_valid.d.next = self.valid.val();
            self.o_y.d.next = bit_cast::<SCREEN, PIXEL>(self.j.q.val());
            if self.maj_left.q.val() {
                self.o_xl.d.next = self.maj.x.val();
                self.o_xr.d.next = self.cur.x.val() - 1;
                self.o_left_z.d.next = self.maj.at_z.val();
                self.o_left_c0.d.next = self.maj.at_c0.val();
                self.o_left_c1.d.next = self.maj.at_c1.val();
                self.o_left_c2.d.next = self.maj.at_c2.val();
                self.o_right_z.d.next = self.cur.at_z.val();
                self.o_right_c0.d.next = self.cur.at_c0.val();
                self.o_right_c1.d.next = self.cur.at_c1.val();
                self.o_right_c2.d.next = self.cur.at_c2.val();
            } else {
                self.o_xl.d.next = self.cur.x.val();
                self.o_xr.d.next = self.maj.x.val() - 1;
                self.o_left_z.d.next = self.cur.at_z.val();
                self.o_left_c0.d.next = self.cur.at_c0.val();
                self.o_left_c1.d.next = self.cur.at_c1.val();
                self.o_left_c2.d.next = self.cur.at_c2.val();
                self.o_right_z.d.next = self.maj.at_z.val();
                self.o_right_c0.d.next = self.maj.at_c0.val();
                self.o_right_c1.d.next = self.maj.at_c1.val();
                self.o_right_c2.d.next = self.maj.at_c2.val();
            }
        }
        self.out.valid.next = self.o_valid.q.val();
        self.out.y.next = self.o_y.q.val();
        self.out.xl.next = self.o_xl.q.val();
        self.out.xr.next = self.o_xr.q.val();
        self.out.left_z.next = self.o_left_z.q.val();
        self.out.left_c0.next = self.o_left_c0.q.val();
        self.out.left_c1.next = self.o_left_c1.q.val();
        self.out.left_c2.next = self.o_left_c2.q.val();
        self.out.right_z.next = self.o_right_z.q.val();
        self.out.right_c0.next = self.o_right_c0.q.val();
        self.out.right_c1.next = self.o_right_c1.q.val();
        self.out.right_c2.next = self.o_right_c2.q.val();
        self.out.ddx_z.next = self.ddx_z.q.val();
        self.out.ddx_c0.next = self.ddx_c0.q.val();
        self.out.ddx_c1.next = self.ddx_c1.q.val();
        self.out.ddx_c2.next = self.ddx_c2.q.val();

        // The steppers: both load at the hand-over, `cur` with the first short edge (the
        // second when the first crosses no scanline); `cur` loads the second short edge on
        // the step to its first scanline (k + 1 == short0.count).
        self.maj.up.next = self.up.q.val();
        self.maj.load.next = self.accept.val();
        self.maj.step.next = self.step.val();
        self.cur.up.next = self.up.q.val();
        self.cur.load.next = self.accept.val() | (self.step.val() & self.sw_r.q.val());
        self.cur.step.next = self.step.val();
        self.maj.ld_x.next = self.inp.maj_x.val();
        self.maj.ld_q.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.maj_q.val());
        self.maj.ld_t.next = self.start_maj.t.val();
        self.maj.ld_a.next = self.start_maj.a.val();
        self.maj.ld_b.next = self.start_maj.b.val();
        self.maj.ld_at_z.next = self.inp.maj_at_z.val();
        self.maj.ld_at_c0.next = self.inp.maj_at_c0.val();
        self.maj.ld_at_c1.next = self.inp.maj_at_c1.val();
        self.maj.ld_at_c2.next = self.inp.maj_at_c2.val();
        self.maj.ld_inc0_z.next = bit_cast::<Z_ACC, DZ>(self.inp.maj_inc0_z.val());
        self.maj.ld_inc0_c0.next = bit_cast::<C_ACC, DC>(self.inp.maj_inc0_c0.val());
        self.maj.ld_inc0_c1.next = bit_cast::<C_ACC, DC>(self.inp.maj_inc0_c1.val());
        self.maj.ld_inc0_c2.next = bit_cast::<C_ACC, DC>(self.inp.maj_inc0_c2.val());
        self.maj.ld_inc1_z.next = bit_cast::<Z_ACC, DZ>(self.inp.maj_inc1_z.val());
        self.maj.ld_inc1_c0.next = bit_cast::<C_ACC, DC>(self.inp.maj_inc1_c0.val());
        self.maj.ld_inc1_c1.next = bit_cast::<C_ACC, DC>(self.inp.maj_inc1_c1.val());
        self.maj.ld_inc1_c2.next = bit_cast::<C_ACC, DC>(self.inp.maj_inc1_c2.val());
        if self.busy.q.val() {
            self.cur.ld_x.next = self.pend_x.q.val();
            self.cur.ld_q.next = self.pend_q.q.val();
            self.cur.ld_t.next = self.pend_t.q.val();
            self.cur.ld_a.next = self.pend_a.q.val();
            self.cur.ld_b.next = self.pend_b.q.val();
            self.cur.ld_at_z.next = self.pend_at_z.q.val();
            self.cur.ld_at_c0.next = self.pend_at_c0.q.val();
            self.cur.ld_at_c1.next = self.pend_at_c1.q.val();
            self.cur.ld_at_c2.next = self.pend_at_c2.q.val();
            self.cur.ld_inc0_z.next = self.pend_inc0_z.q.val();
            self.cur.ld_inc0_c0.next = self.pend_inc0_c0.q.val();
            self.cur.ld_inc0_c1.next = self.pend_inc0_c1.q.val();
            self.cur.ld_inc0_c2.next = self.pend_inc0_c2.q.val();
            self.cur.ld_inc1_z.next = self.pend_inc1_z.q.val();
            self.cur.ld_inc1_c0.next = self.pend_inc1_c0.q.val();
            self.cur.ld_inc1_c1.next = self.pend_inc1_c1.q.val();
            self.cur.ld_inc1_c2.next = self.pend_inc1_c2.q.val();
        } else if self.in_short0_none.val() {
            self.cur.ld_x.next = self.inp.short1_x.val();
            self.cur.ld_q.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.short1_q.val());
            self.cur.ld_t.next = self.start_s1.t.val();
            self.cur.ld_a.next = self.start_s1.a.val();
            self.cur.ld_b.next = self.start_s1.b.val();
            self.cur.ld_at_z.next = self.inp.short1_at_z.val();
            self.cur.ld_at_c0.next = self.inp.short1_at_c0.val();
            self.cur.ld_at_c1.next = self.inp.short1_at_c1.val();
            self.cur.ld_at_c2.next = self.inp.short1_at_c2.val();
            self.cur.ld_inc0_z.next = bit_cast::<Z_ACC, DZ>(self.inp.short1_inc0_z.val());
            self.cur.ld_inc0_c0.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc0_c0.val());
            self.cur.ld_inc0_c1.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc0_c1.val());
            self.cur.ld_inc0_c2.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc0_c2.val());
            self.cur.ld_inc1_z.next = bit_cast::<Z_ACC, DZ>(self.inp.short1_inc1_z.val());
            self.cur.ld_inc1_c0.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc1_c0.val());
            self.cur.ld_inc1_c1.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc1_c1.val());
            self.cur.ld_inc1_c2.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc1_c2.val());
        } else {
            self.cur.ld_x.next = self.inp.short0_x.val();
            self.cur.ld_q.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.short0_q.val());
            self.cur.ld_t.next = self.start_s0.t.val();
            self.cur.ld_a.next = self.start_s0.a.val();
            self.cur.ld_b.next = self.start_s0.b.val();
            self.cur.ld_at_z.next = self.inp.short0_at_z.val();
            self.cur.ld_at_c0.next = self.inp.short0_at_c0.val();
            self.cur.ld_at_c1.next = self.inp.short0_at_c1.val();
            self.cur.ld_at_c2.next = self.inp.short0_at_c2.val();
            self.cur.ld_inc0_z.next = bit_cast::<Z_ACC, DZ>(self.inp.short0_inc0_z.val());
            self.cur.ld_inc0_c0.next = bit_cast::<C_ACC, DC>(self.inp.short0_inc0_c0.val());
            self.cur.ld_inc0_c1.next = bit_cast::<C_ACC, DC>(self.inp.short0_inc0_c1.val());
            self.cur.ld_inc0_c2.next = bit_cast::<C_ACC, DC>(self.inp.short0_inc0_c2.val());
            self.cur.ld_inc1_z.next = bit_cast::<Z_ACC, DZ>(self.inp.short0_inc1_z.val());
            self.cur.ld_inc1_c0.next = bit_cast::<C_ACC, DC>(self.inp.short0_inc1_c0.val());
            self.cur.ld_inc1_c1.next = bit_cast::<C_ACC, DC>(self.inp.short0_inc1_c1.val());
            self.cur.ld_inc1_c2.next = bit_cast::<C_ACC, DC>(self.inp.short0_inc1_c2.val());
        }

        // The walker.
        if self.step.val() {
            self.j.d.next = self.j_next.val();
            self.rem.d.next = self.rem.q.val() - 1;
            self.crow.d.next = self.crow.q.val() - 1;
            self.crem.d.next = self.crem.q.val() - 1;
            self.last_r.d.next = self.rem.q.val() == 1;
            if self.clip_y.on.val() & (self.crow.q.val() == 1) {
                self.last_r.d.next = true;
            }
            self.sw_r.d.next = self.crem.q.val() == 1;
        }
        if self.emit.val() & self.last_r.q.val() {
            self.walking.d.next = false;
        }
        if self.busy.q.val() & !self.walking.q.val() & self.free.val() {
            self.busy.d.next = false;
        }
        if self.accept.val() {
            self.busy.d.next = true;
            self.walking.d.next = !self.in_no_rows.val();
            self.up.d.next = self.in_up.val();
            self.maj_left.d.next = self.inp.maj_left.val();
            self.j.d.next = self.inp.maj_j.val();
            self.rem.d.next = self.inp.maj_count.val() - 1;
            self.crow.d.next = self.in_crow.val();
            self.crem.d.next = self.inp.short0_count.val() - 1;
            self.last_r.d.next = self.in_last.val();
            self.sw_r.d.next = self.inp.short0_count.val() == 1;
            self.ddx_z.d.next = self.inp.ddx_z.val();
            self.ddx_c0.d.next = self.inp.ddx_c0.val();
            self.ddx_c1.d.next = self.inp.ddx_c1.val();
            self.ddx_c2.d.next = self.inp.ddx_c2.val();
            self.pend_x.d.next = self.inp.short1_x.val();
            self.pend_q.d.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.short1_q.val());
            self.pend_t.d.next = self.start_s1.t.val();
            self.pend_a.d.next = self.start_s1.a.val();
            self.pend_b.d.next = self.start_s1.b.val();
            self.pend_at_z.d.next = self.inp.short1_at_z.val();
            self.pend_at_c0.d.next = self.inp.short1_at_c0.val();
            self.pend_at_c1.d.next = self.inp.short1_at_c1.val();
            self.pend_at_c2.d.next = self.inp.short1_at_c2.val();
            self.pend_inc0_z.d.next = bit_cast::<Z_ACC, DZ>(self.inp.short1_inc0_z.val());
            self.pend_inc0_c0.d.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc0_c0.val());
            self.pend_inc0_c1.d.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc0_c1.val());
            self.pend_inc0_c2.d.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc0_c2.val());
            self.pend_inc1_z.d.next = bit_cast::<Z_ACC, DZ>(self.inp.short1_inc1_z.val());
            self.pend_inc1_c0.d.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc1_c0.val());
            self.pend_inc1_c1.d.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc1_c1.val());
            self.pend_inc1_c2.d.next = bit_cast::<C_ACC, DC>(self.inp.short1_inc1_c2.val());
        }
        // IDLE next cycle: idle and taking nothing, or busy with the last scanline leaving.
        self.free_next.next = !self.busy.q.val() | (!self.walking.q.val() & self.free.val());
        if self.accept.val() {
            self.free_next.next = false;
        }
    }
}

crate::pins!(EdgeWalk { clock: clock, inputs: [height, hold,], outputs: [idle, free_next,], links: [inp, out] });

impl EdgeWalk {
    /// The edge walk with Y clipping present or not (`parts.clip_y`).
    pub fn new(parts: &Parts) -> EdgeWalk {
        EdgeWalk { clip_y: Switch::new(parts.clip_y), ..Default::default() }
    }
}

/// `UNITS` entry: the edge walk, with Y clipping as `params["CLIP_Y"]` says (widths from
/// `crate::widths`).
pub fn emit_edge_walk(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("edge_walk", EdgeWalk::new(&Parts::of(params)?), params))
}
