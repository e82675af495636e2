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
//! Timing (`model::edge_walk::{LATENCY, II}` = 2, 1): a triangle is taken in cycle t
//! (state IDLE); in cycle t + 1 (SETUP) the first short edge is chosen and the walk is
//! skipped when the Y clip leaves no scanline; scanline k is presented in cycle t + 2 + k
//! (WALK) and held while `out$ready` is low; the next triangle is taken the cycle after the
//! last scanline. Model: `model::edge_walk::edge_walk`. Emitted: `hdl-out/edge_walk.v`.

use crate::emit::{emit_unit, Emitted};
use crate::parts::{Negative, SignedLess};
use crate::switch::{Parts, Switch};
use super::links::{SpanCmdSource, TriangleSetupSink};
use super::widths::{C_ACC, DC, DIM, DZ, EDGE_D, EDGE_Q, PIXEL, SCREEN, Z_ACC};
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
}

impl<const W: usize> Logic for EdgeAttr<W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, at_r, inc0_r, inc1_r);
        self.inc.next = self.inc0_r.q.val();
        if self.one.val() {
            self.inc.next = self.inc1_r.q.val();
        }
        if self.step.val() {
            if self.up.val() {
                self.at_r.d.next = self.at_r.q.val() - self.inc.val();
            } else {
                self.at_r.d.next = self.at_r.q.val() + self.inc.val();
            }
        }
        if self.load.val() {
            self.at_r.d.next = self.ld_at.val();
            self.inc0_r.d.next = self.ld_inc0.val();
            self.inc1_r.d.next = self.ld_inc1.val();
        }
        self.at.next = self.at_r.q.val();
    }
}

/// One exact edge stepper (001's edge walk, exact in the manner of Bresenham): on each
/// scanline, `x` is the first pixel whose centre is at or right of the edge and `r` in
/// [0, D) how far the edge lies left of that centre, in units of 1/D pixel. A step down
/// moves x by q + 1 when `r < rho` (r += D - rho) and by q otherwise (r -= rho); a step up
/// is its exact inverse. Model: `Stepper` in `model::edge_walk`.
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
    pub ld_r: Signal<In, Bits<EDGE_D>>,
    pub ld_q: Signal<In, Bits<PIXEL>>,
    pub ld_rho: Signal<In, Bits<EDGE_D>>,
    pub ld_d: Signal<In, Bits<EDGE_D>>,
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
    r_r: DFF<Bits<EDGE_D>>,
    q_r: DFF<Bits<PIXEL>>,
    rho_r: DFF<Bits<EDGE_D>>,
    d_r: DFF<Bits<EDGE_D>>,
    z: EdgeAttr<Z_ACC>,
    c0: EdgeAttr<C_ACC>,
    c1: EdgeAttr<C_ACC>,
    c2: EdgeAttr<C_ACC>,
    /// This step moves x by q + 1 pixels.
    one: Signal<Local, Bit>,
    /// r + rho and r - rho (both exact in `EDGE_D` bits where they are used).
    r_plus: Signal<Local, Bits<EDGE_D>>,
    r_minus: Signal<Local, Bits<EDGE_D>>,
    /// q or q + 1.
    x_step: Signal<Local, Bits<PIXEL>>,
}

impl Logic for Stepper {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, x_r, r_r, q_r, rho_r, d_r);
        clock!(self, clock, z, c0, c1, c2);
        self.r_plus.next = self.r_r.q.val() + self.rho_r.q.val();
        self.r_minus.next = self.r_r.q.val() - self.rho_r.q.val();
        // Down: q + 1 when r < rho. Up (the inverse): q + 1 unless r + rho < D.
        self.one.next = self.r_r.q.val() < self.rho_r.q.val();
        if self.up.val() {
            self.one.next = self.r_plus.val() >= self.d_r.q.val();
        }
        self.x_step.next = self.q_r.q.val() + self.one.val();
        if self.step.val() {
            if self.up.val() {
                self.x_r.d.next = self.x_r.q.val() - self.x_step.val();
                self.r_r.d.next = self.r_plus.val();
                if self.one.val() {
                    self.r_r.d.next = self.r_plus.val() - self.d_r.q.val();
                }
            } else {
                self.x_r.d.next = self.x_r.q.val() + self.x_step.val();
                self.r_r.d.next = self.r_minus.val();
                if self.one.val() {
                    self.r_r.d.next = self.r_minus.val() + self.d_r.q.val();
                }
            }
        }
        if self.load.val() {
            self.x_r.d.next = self.ld_x.val();
            self.r_r.d.next = self.ld_r.val();
            self.q_r.d.next = self.ld_q.val();
            self.rho_r.d.next = self.ld_rho.val();
            self.d_r.d.next = self.ld_d.val();
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
    pub height: Signal<In, Bits<DIM>>,
    /// The set-up triangle; `inp.ready` high in IDLE: a triangle is taken when `inp.valid` is high too.
    pub inp: TriangleSetupSink,
    /// A span command (a scanline with pixels, on screen).
    pub out: SpanCmdSource,
    /// Y clipping present (`CLIP_Y`, `crate::switch`); without it the walk is always down
    /// and the screen's rows are not checked: no triangle may cross the top or bottom.
    clip_y: Switch,
    /// The long edge and the short edge being walked.
    maj: Stepper,
    cur: Stepper,
    /// State: IDLE = !busy, SETUP = busy & !walking, WALK = busy & walking.
    busy: DFF<Bit>,
    walking: DFF<Bit>,
    /// Walk direction and side of the long edge, for the triangle being walked.
    up: DFF<Bit>,
    maj_left: DFF<Bit>,
    /// Scanline `j` and its index `k` in the walk; `total` scanlines before the Y clip;
    /// the walk moves to the second short edge at `k == c0`.
    j: DFF<Bits<PIXEL>>,
    k: DFF<Bits<PIXEL>>,
    total: DFF<Bits<PIXEL>>,
    c0: DFF<Bits<PIXEL>>,
    ddx_z: DFF<Bits<DZ>>,
    ddx_c0: DFF<Bits<DC>>,
    ddx_c1: DFF<Bits<DC>>,
    ddx_c2: DFF<Bits<DC>>,
    /// The second short edge, waiting (q and the increments cut as `Stepper` keeps them).
    pend_x: DFF<Bits<PIXEL>>,
    pend_r: DFF<Bits<EDGE_D>>,
    pend_q: DFF<Bits<PIXEL>>,
    pend_rho: DFF<Bits<EDGE_D>>,
    pend_d: DFF<Bits<EDGE_D>>,
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
    /// j < 0; the left side's x < the right side's (the scanline has pixels).
    j_sign: Negative<PIXEL>,
    sides: SignedLess<PIXEL>,
    accept: Signal<Local, Bit>,
    /// In SETUP: no scanline is left after the Y clip.
    no_rows: Signal<Local, Bit>,
    /// In WALK: the scanline presented is the last; the walk advances past it.
    last: Signal<Local, Bit>,
    advance: Signal<Local, Bit>,
    /// The current short edge gives way to the pending one.
    switch: Signal<Local, Bit>,
    valid: Signal<Local, Bit>,
    j_next: Signal<Local, Bits<PIXEL>>,
    k_next: Signal<Local, Bits<PIXEL>>,
    height_j: Signal<Local, Bits<PIXEL>>,
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
            k,
            total,
            c0,
            ddx_z,
            ddx_c0,
            ddx_c1,
            ddx_c2,
            pend_x,
            pend_r,
            pend_q,
            pend_rho,
            pend_d,
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
            pend_inc1_c2
        );
        clock!(self, clock, maj, cur);

        // IDLE: take a triangle.
        self.inp.ready.next = !self.busy.q.val();
        self.accept.next = self.inp.valid.val() & !self.busy.q.val();

        // Where the walk is: scanline j (k-th of the walk), the next one, and whether the
        // one presented is the last (its edge ends, or the Y clip: the walk reaches the
        // bottom row walking down or row 0 walking up).
        self.j_sign.x.next = self.j.q.val();
        self.height_j.next = bit_cast::<PIXEL, DIM>(self.height.val());
        self.k_next.next = self.k.q.val() + 1;
        self.j_next.next = self.j.q.val() + 1;
        if self.up.q.val() {
            self.j_next.next = self.j.q.val() - 1;
        }
        self.last.next = self.k_next.val() == self.total.q.val();
        if self.clip_y.on.val() {
            if self.up.q.val() {
                if self.j.q.val() == 0 {
                    self.last.next = true;
                }
            } else if self.j_next.val() == self.height_j.val() {
                self.last.next = true;
            }
        }
        // SETUP: nothing to walk when the edge crosses no scanline centre or the walk
        // starts beyond the boundary it walks towards.
        self.no_rows.next = self.total.q.val() == 0;
        if self.clip_y.on.val() {
            if self.up.q.val() {
                if self.j_sign.neg.val() {
                    self.no_rows.next = true;
                }
            } else if !self.j_sign.neg.val() & (self.j.q.val() >= self.height_j.val()) {
                self.no_rows.next = true;
            }
        }

        // The span command: left side from x, right side up to x - 1; pixels when
        // left x < right x, and on screen when j >= 0.
        self.out.y.next = bit_cast::<SCREEN, PIXEL>(self.j.q.val());
        self.out.ddx_z.next = self.ddx_z.q.val();
        self.out.ddx_c0.next = self.ddx_c0.q.val();
        self.out.ddx_c1.next = self.ddx_c1.q.val();
        self.out.ddx_c2.next = self.ddx_c2.q.val();
        if self.maj_left.q.val() {
            self.sides.a.next = self.maj.x.val();
            self.sides.b.next = self.cur.x.val();
            self.out.xl.next = self.maj.x.val();
            self.out.xr.next = self.cur.x.val() - 1;
            self.out.left_z.next = self.maj.at_z.val();
            self.out.left_c0.next = self.maj.at_c0.val();
            self.out.left_c1.next = self.maj.at_c1.val();
            self.out.left_c2.next = self.maj.at_c2.val();
            self.out.right_z.next = self.cur.at_z.val();
            self.out.right_c0.next = self.cur.at_c0.val();
            self.out.right_c1.next = self.cur.at_c1.val();
            self.out.right_c2.next = self.cur.at_c2.val();
        } else {
            self.sides.a.next = self.cur.x.val();
            self.sides.b.next = self.maj.x.val();
            self.out.xl.next = self.cur.x.val();
            self.out.xr.next = self.maj.x.val() - 1;
            self.out.left_z.next = self.cur.at_z.val();
            self.out.left_c0.next = self.cur.at_c0.val();
            self.out.left_c1.next = self.cur.at_c1.val();
            self.out.left_c2.next = self.cur.at_c2.val();
            self.out.right_z.next = self.maj.at_z.val();
            self.out.right_c0.next = self.maj.at_c0.val();
            self.out.right_c1.next = self.maj.at_c1.val();
            self.out.right_c2.next = self.maj.at_c2.val();
        }
        self.valid.next = self.busy.q.val() & self.walking.q.val() & self.sides.lt.val();
        if self.clip_y.on.val() & self.j_sign.neg.val() {
            self.valid.next = false;
        }
        self.out.valid.next = self.valid.val();
        // WALK: move on unless the command presented waits for `out.ready`.
        self.advance.next = self.busy.q.val() & self.walking.q.val() & (!self.valid.val() | self.out.ready.val());

        // The steppers: both load at the triangle's hand-over; `cur` loads the second
        // short edge when the walk reaches it (at k == c0, which in SETUP means c0 == 0).
        self.switch.next = false;
        if self.busy.q.val() & !self.walking.q.val() & (self.c0.q.val() == 0) {
            self.switch.next = true;
        }
        if self.advance.val() & !self.last.val() & (self.k_next.val() == self.c0.q.val()) {
            self.switch.next = true;
        }
        self.maj.up.next = self.up.q.val();
        self.maj.load.next = self.accept.val();
        self.maj.step.next = self.advance.val() & !self.last.val();
        self.cur.up.next = self.up.q.val();
        self.cur.load.next = self.accept.val() | self.switch.val();
        self.cur.step.next = self.advance.val() & !self.last.val();
        self.maj.ld_x.next = self.inp.maj_x.val();
        self.maj.ld_r.next = self.inp.maj_r.val();
        self.maj.ld_q.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.maj_q.val());
        self.maj.ld_rho.next = self.inp.maj_rho.val();
        self.maj.ld_d.next = self.inp.maj_d.val();
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
        if self.switch.val() {
            self.cur.ld_x.next = self.pend_x.q.val();
            self.cur.ld_r.next = self.pend_r.q.val();
            self.cur.ld_q.next = self.pend_q.q.val();
            self.cur.ld_rho.next = self.pend_rho.q.val();
            self.cur.ld_d.next = self.pend_d.q.val();
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
        } else {
            self.cur.ld_x.next = self.inp.short0_x.val();
            self.cur.ld_r.next = self.inp.short0_r.val();
            self.cur.ld_q.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.short0_q.val());
            self.cur.ld_rho.next = self.inp.short0_rho.val();
            self.cur.ld_d.next = self.inp.short0_d.val();
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

        // State and the triangle's registers.
        if self.accept.val() {
            self.busy.d.next = true;
            self.walking.d.next = false;
            self.up.d.next = self.inp.walk.val() & self.clip_y.on.val();
            self.maj_left.d.next = self.inp.maj_left.val();
            self.j.d.next = self.inp.maj_j.val();
            self.k.d.next = 0.into();
            self.total.d.next = self.inp.maj_count.val();
            self.c0.d.next = self.inp.short0_count.val();
            self.ddx_z.d.next = self.inp.ddx_z.val();
            self.ddx_c0.d.next = self.inp.ddx_c0.val();
            self.ddx_c1.d.next = self.inp.ddx_c1.val();
            self.ddx_c2.d.next = self.inp.ddx_c2.val();
            self.pend_x.d.next = self.inp.short1_x.val();
            self.pend_r.d.next = self.inp.short1_r.val();
            self.pend_q.d.next = bit_cast::<PIXEL, EDGE_Q>(self.inp.short1_q.val());
            self.pend_rho.d.next = self.inp.short1_rho.val();
            self.pend_d.d.next = self.inp.short1_d.val();
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
        if self.busy.q.val() & !self.walking.q.val() {
            self.walking.d.next = !self.no_rows.val();
            self.busy.d.next = !self.no_rows.val();
        }
        if self.advance.val() {
            if self.last.val() {
                self.busy.d.next = false;
                self.walking.d.next = false;
            } else {
                self.j.d.next = self.j_next.val();
                self.k.d.next = self.k_next.val();
            }
        }
    }
}

crate::pins!(EdgeWalk {
    clock: clock,
    inputs: [
        height,
    ],
    outputs: [
    ],
    links: [inp, out],
});

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
