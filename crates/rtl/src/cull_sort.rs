//! `cull_sort`: the cull & sort unit of paper 003 (Lee 2008, §II.1.다.(1), Fig. 4, Table 1:
//! "clipping 1 cycle"), here in three pipeline stages for the clock.
//!
//! One triangle per beat: the three vertices in submission order on the link `inp`
//! (`links::TriangleSink`: `inp$v<i>_x` ... `inp$v<i>_iw`), screen size on `width`, `height`, face culling on `cull_back`. It
//! computes
//! * a Cohen-Sutherland outcode per vertex (bits as `model::cull_sort::outcode`: x < 0,
//!   x > width, y < 0, y > height, z < 0, z > the largest depth value);
//! * the reject verdict, in the model's order: all three outside one plane (the AND of the
//!   outcodes), zero area, a back face (twice the signed area > 0, with `cull_back` high);
//! * the vertex order by (y, input index): three comparisons give each vertex its rank.
//!
//! ```text
//!   stage 1 (taken)                      stage 2                  stage 3 (output register)
//!   inp_v0..2 -+- outcodes: AND, OR -->  -----------------------> verdict: outside? zero
//!              +- edge vectors ------->  2 x Mul<17,17>: the -->  area? back face? --> verdict$*,
//!              |                         products of area2        out$valid, out$crosses
//!              `- y0<=y1, y1<=y2, y0<=y2 -> ranks -> mux: sorted vertices ---------> out_v0..2
//! ```
//!
//! 003 does it all in one cycle; at 100 MHz on ECP5 the multipliers alone take most of a
//! cycle (their MULT18X18D about 4 ns unregistered), so the edge vectors, the products and
//! the verdict each have a cycle: a triangle taken in cycle t (`inp$valid & inp$ready`) is
//! in the output register in cycle t + 3 (latency `model::cull_sort::LATENCY` = 3, II 1).
//! Each stage moves its triangle on when the next stage is empty or moving on itself (a
//! bubble does not stay in the pipeline), so three triangles may be in the unit while the
//! one in the output register waits. A passing triangle stays there until `out$ready`; a
//! rejected one leaves at once (it goes no further, so it never waits for setup).
//! `verdict$valid` is high in the cycle a triangle leaves, with its verdict. No new
//! vertices are made: a triangle that crosses the screen goes on whole with `out$crosses`
//! (the OR of the outcodes) and is clipped by the edge walk and span.
//!
//! Model: `model::cull_sort::cull_sort`; its timing `model::cycles::scanline_frame`.
//! Emitted: `hdl-out/cull_sort.v`.

use super::links::{SortedSource, TriangleSink, Verdict};
use super::widths::{DIM, FORMATS, WIDTHS};
use crate::emit::{emit_unit, Emitted};
use crate::mul::Mul;
use crate::parts::SignExtend;
use crate::switch::{Parts, Switch};
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;

/// Vertex x, y (`xy`), z (`z`), R, G, B (`color`) and w_min / w (`inv_w`), as they enter
/// the rasterizer: the widths of the triangle stream from `cull_sort` to `triangle_setup`.
pub const XY: usize = WIDTHS.xy;
pub const Z: usize = WIDTHS.z;
pub const COLOR: usize = WIDTHS.color;
pub const INV_W: usize = WIDTHS.inv_w;
/// Outcode bits, one per clip plane.
pub use crate::config::OUTCODE;

/// Each clip plane's bit in an outcode (`model::cull_sort::outcode` has their masks).
pub mod outcode_bit {
    /// x < 0
    pub const LEFT: usize = 0;
    /// x > width
    pub const RIGHT: usize = 1;
    /// y < 0 (the top row)
    pub const TOP: usize = 2;
    /// y > height
    pub const BOTTOM: usize = 3;
    /// z < 0
    pub const NEAR: usize = 4;
    /// z > the largest depth value
    pub const FAR: usize = 5;
}
/// Edge vectors (differences of two vertices) and twice the area, exact.
const DELTA: usize = XY + 1;
const AREA: usize = 2 * DELTA;

/// `verdict$code`: why a triangle went no further (`model::cull_sort::Reject`), or 0.
pub mod verdict {
    pub const PASSED: u64 = 0;
    pub const OUTSIDE: u64 = 1;
    pub const BACK_FACE: u64 = 2;
    pub const ZERO_AREA: u64 = 3;
}

/// The cull & sort unit; see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct CullSort {
    pub clock: Signal<In, Clock>,
    /// Screen size in pixels, 1 to 2^CLASS (the size class): the clip volume is [0, width] x [0, height].
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// Drop back faces (clockwise on screen, y down); read with the triangle it comes with.
    pub cull_back: Signal<In, Bit>,
    /// The triangle in; `inp.ready`: stage 1 is free (empty, or its triangle moving on).
    pub inp: TriangleSink,
    /// The sorted triangle out, with the planes it crosses.
    pub out: SortedSource,
    /// Each triangle leaving the unit (taken, or rejected) and why; `outside`: for
    /// `OUTSIDE` the planes all three vertices lie outside (`Reject::Outside`), else 0.
    pub verdict: Verdict,
    /// No triangle in stages 1 and 2 and none waiting in the output register (a rejected
    /// one may be leaving): for `raster_top`'s frame-done.
    pub idle: Signal<Out, Bit>,
    /// The inputs as arrays, by vertex (colours: 3 * vertex + channel).
    vx: [Signal<Local, Bits<XY>>; 3],
    vy: [Signal<Local, Bits<XY>>; 3],
    vz: [Signal<Local, Bits<Z>>; 3],
    vc: [Signal<Local, Bits<COLOR>>; 9],
    viw: [Signal<Local, Bits<INV_W>>; 3],
    /// Outcode of each vertex, and its six planes as bits.
    oc: [Signal<Local, Bits<OUTCODE>>; 3],
    left: [Signal<Local, Bit>; 3],
    right_of: [Signal<Local, Bit>; 3],
    top: [Signal<Local, Bit>; 3],
    below: [Signal<Local, Bit>; 3],
    near: [Signal<Local, Bit>; 3],
    far: [Signal<Local, Bit>; 3],
    /// The right and bottom planes in subpixels (width and height * 2^s).
    right: Signal<Local, Bits<XY>>,
    bottom: Signal<Local, Bits<XY>>,
    /// The vertices' x and y sign-extended to `DELTA` bits (edge vectors from v0 are their
    /// differences).
    wx: [SignExtend<XY, DELTA>; 3],
    wy: [SignExtend<XY, DELTA>; 3],
    /// y_i with its sign bit flipped: the signed order as an unsigned one.
    key: [Signal<Local, Bits<XY>>; 3],
    /// y0 <= y1, y1 <= y2, y0 <= y2, and their negations.
    le01: Signal<Local, Bit>,
    le12: Signal<Local, Bit>,
    le02: Signal<Local, Bit>,
    gt01: Signal<Local, Bit>,
    gt12: Signal<Local, Bit>,
    gt02: Signal<Local, Bit>,
    /// Each vertex's place in the sorted order (0: vMin).
    rank: [Signal<Local, Bits<2>>; 3],
    /// Stage 1: the sorted vertices, the edge vectors (v1 - v0).x, (v2 - v0).y,
    /// (v2 - v0).x, (v1 - v0).y in submission order, the AND and OR of the outcodes,
    /// `cull_back`, and whether it holds a triangle.
    s1x: [DFF<Bits<XY>>; 3],
    s1y: [DFF<Bits<XY>>; 3],
    s1z: [DFF<Bits<Z>>; 3],
    s1c: [DFF<Bits<COLOR>>; 9],
    s1iw: [DFF<Bits<INV_W>>; 3],
    e1x: DFF<Bits<DELTA>>,
    e2y: DFF<Bits<DELTA>>,
    e2x: DFF<Bits<DELTA>>,
    e1y: DFF<Bits<DELTA>>,
    outside1: DFF<Bits<OUTCODE>>,
    crosses1: DFF<Bits<OUTCODE>>,
    back1: DFF<Bit>,
    full1: DFF<Bit>,
    /// Stage 2: as stage 1, with the two products of twice the area in place of the edge
    /// vectors.
    s2x: [DFF<Bits<XY>>; 3],
    s2y: [DFF<Bits<XY>>; 3],
    s2z: [DFF<Bits<Z>>; 3],
    s2c: [DFF<Bits<COLOR>>; 9],
    s2iw: [DFF<Bits<INV_W>>; 3],
    area_mul: [Mul<DELTA, DELTA, AREA>; 2],
    prod0: DFF<Bits<AREA>>,
    prod1: DFF<Bits<AREA>>,
    outside2: DFF<Bits<OUTCODE>>,
    crosses2: DFF<Bits<OUTCODE>>,
    back2: DFF<Bit>,
    full2: DFF<Bit>,
    /// Twice the signed area (submission order), from stage 2's products, and the verdict.
    area: Signal<Local, Bits<AREA>>,
    code: Signal<Local, Bits<2>>,
    /// The handshakes: a triangle taken into stage 1, moving from 1 to 2 and from 2 to the
    /// output register, leaving the output register.
    take: Signal<Local, Bit>,
    move1: Signal<Local, Bit>,
    move2: Signal<Local, Bit>,
    leave: Signal<Local, Bit>,
    /// The output register, stage 2, stage 1: empty or freed whatever setup's ready (a
    /// rejected triangle leaving, or the stages after it empty or freed).
    out_free: Signal<Local, Bit>,
    s2_free: Signal<Local, Bit>,
    s1_free: Signal<Local, Bit>,
    /// Stage 3, the output register: the sorted vertices, crosses, the verdict, and
    /// whether it holds a triangle.
    sx: [DFF<Bits<XY>>; 3],
    sy: [DFF<Bits<XY>>; 3],
    sz: [DFF<Bits<Z>>; 3],
    sc: [DFF<Bits<COLOR>>; 9],
    siw: [DFF<Bits<INV_W>>; 3],
    crosses: DFF<Bits<OUTCODE>>,
    code_r: DFF<Bits<2>>,
    outside_r: DFF<Bits<OUTCODE>>,
    full: DFF<Bit>,
    /// The largest depth value, `2^z.frac - 1` (`model::cull_sort::z_max`).
    z_max: Constant<Bits<Z>>,
    /// 2^(XY-1): flips a sign bit.
    half: Constant<Bits<XY>>,
    /// Bit indices and shifts (a kernel cannot name a Rust constant): the sign bits of
    /// `xy`, `z` and the area, `xy.frac`.
    xy_msb: Constant<Bits<8>>,
    z_msb: Constant<Bits<8>>,
    area_msb: Constant<Bits<8>>,
    frac: Constant<Bits<8>>,
    /// The [`verdict`] codes.
    passed: Constant<Bits<2>>,
    outside: Constant<Bits<2>>,
    back_face: Constant<Bits<2>>,
    zero_area: Constant<Bits<2>>,
    /// Rejecting and culling present (`CULL`, `crate::switch`); without it every triangle
    /// passes and the area is not computed: no triangle of the frame may be rejected or
    /// culled.
    cull: Switch,
}

impl Default for CullSort {
    fn default() -> Self {
        Self {
            z_max: Constant::new(((1u64 << FORMATS.z.frac) - 1).to_bits()),
            half: Constant::new((1u64 << (XY - 1)).to_bits()),
            xy_msb: Constant::new((XY - 1).to_bits()),
            z_msb: Constant::new((Z - 1).to_bits()),
            area_msb: Constant::new((AREA - 1).to_bits()),
            frac: Constant::new((FORMATS.xy.frac as usize).to_bits()),
            passed: Constant::new(verdict::PASSED.to_bits()),
            outside: Constant::new(verdict::OUTSIDE.to_bits()),
            back_face: Constant::new(verdict::BACK_FACE.to_bits()),
            zero_area: Constant::new(verdict::ZERO_AREA.to_bits()),
            ..Self::blank()
        }
    }
}

impl Logic for CullSort {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, e1x, e2y, e2x, e1y, outside1, crosses1, back1, full1, prod0, prod1, outside2, crosses2, back2,
            full2, crosses, code_r, outside_r, full
        );
        for i in 0..3 {
            self.s1x[i].clock.next = self.clock.val();
            self.s1x[i].d.next = self.s1x[i].q.val();
            self.s1y[i].clock.next = self.clock.val();
            self.s1y[i].d.next = self.s1y[i].q.val();
            self.s1z[i].clock.next = self.clock.val();
            self.s1z[i].d.next = self.s1z[i].q.val();
            self.s1iw[i].clock.next = self.clock.val();
            self.s1iw[i].d.next = self.s1iw[i].q.val();
            self.s2x[i].clock.next = self.clock.val();
            self.s2x[i].d.next = self.s2x[i].q.val();
            self.s2y[i].clock.next = self.clock.val();
            self.s2y[i].d.next = self.s2y[i].q.val();
            self.s2z[i].clock.next = self.clock.val();
            self.s2z[i].d.next = self.s2z[i].q.val();
            self.s2iw[i].clock.next = self.clock.val();
            self.s2iw[i].d.next = self.s2iw[i].q.val();
            self.sx[i].clock.next = self.clock.val();
            self.sx[i].d.next = self.sx[i].q.val();
            self.sy[i].clock.next = self.clock.val();
            self.sy[i].d.next = self.sy[i].q.val();
            self.sz[i].clock.next = self.clock.val();
            self.sz[i].d.next = self.sz[i].q.val();
            self.siw[i].clock.next = self.clock.val();
            self.siw[i].d.next = self.siw[i].q.val();
        }
        for i in 0..9 {
            self.s1c[i].clock.next = self.clock.val();
            self.s1c[i].d.next = self.s1c[i].q.val();
            self.s2c[i].clock.next = self.clock.val();
            self.s2c[i].d.next = self.s2c[i].q.val();
            self.sc[i].clock.next = self.clock.val();
            self.sc[i].d.next = self.sc[i].q.val();
        }
        self.vx[0].next = self.inp.v0_x.val();
        self.vy[0].next = self.inp.v0_y.val();
        self.vz[0].next = self.inp.v0_z.val();
        self.vc[0].next = self.inp.v0_c0.val();
        self.vc[1].next = self.inp.v0_c1.val();
        self.vc[2].next = self.inp.v0_c2.val();
        self.viw[0].next = self.inp.v0_iw.val();
        self.vx[1].next = self.inp.v1_x.val();
        self.vy[1].next = self.inp.v1_y.val();
        self.vz[1].next = self.inp.v1_z.val();
        self.vc[3].next = self.inp.v1_c0.val();
        self.vc[4].next = self.inp.v1_c1.val();
        self.vc[5].next = self.inp.v1_c2.val();
        self.viw[1].next = self.inp.v1_iw.val();
        self.vx[2].next = self.inp.v2_x.val();
        self.vy[2].next = self.inp.v2_y.val();
        self.vz[2].next = self.inp.v2_z.val();
        self.vc[6].next = self.inp.v2_c0.val();
        self.vc[7].next = self.inp.v2_c1.val();
        self.vc[8].next = self.inp.v2_c2.val();
        self.viw[2].next = self.inp.v2_iw.val();

        // The handshakes, from the output register back: a rejected triangle leaves at
        // once, a passing one when taken; each stage moves on when the next is empty or
        // moving on itself. Written as what frees each stage whatever setup's ready (from
        // the registers) or setup's ready, so that the ready, which comes from setup and
        // the edge walk, is one gate from every enable (raster_top's critical path at
        // stop 57 ran through the three stages' handshakes in series).
        self.out_free.next = !self.full.q.val() | (self.code_r.q.val() != self.passed.val());
        self.s2_free.next = !self.full2.q.val() | self.out_free.val();
        self.s1_free.next = !self.full1.q.val() | self.s2_free.val();
        self.leave.next = self.full.q.val() & ((self.code_r.q.val() != self.passed.val()) | self.out.ready.val());
        self.move2.next = self.full2.q.val() & (self.out_free.val() | self.out.ready.val());
        self.move1.next = self.full1.q.val() & (self.s2_free.val() | self.out.ready.val());
        self.inp.ready.next = self.s1_free.val() | self.out.ready.val();
        self.take.next = self.inp.valid.val() & (self.s1_free.val() | self.out.ready.val());
        if self.leave.val() {
            self.full.d.next = false;
        }
        if self.move2.val() {
            self.full2.d.next = false;
            self.full.d.next = true;
        }
        if self.move1.val() {
            self.full1.d.next = false;
            self.full2.d.next = true;
        }
        if self.take.val() {
            self.full1.d.next = true;
        }
        self.idle.next = !self.full1.q.val()
            & !self.full2.q.val()
            & !(self.full.q.val() & (self.code_r.q.val() == self.passed.val()));

        // Stage 1 (the cycle a triangle is taken): outcodes, edge vectors, the sort.
        // Outcodes: x > width * 2^s only for x >= 0, where the unsigned order is the
        // signed one; likewise y and z.
        self.right.next = bit_cast::<XY, DIM>(self.width.val()) << self.frac.val();
        self.bottom.next = bit_cast::<XY, DIM>(self.height.val()) << self.frac.val();
        for i in 0..3 {
            self.left[i].next = self.vx[i].val().get_bit(self.xy_msb.val().index());
            self.right_of[i].next = !self.left[i].val() & (self.vx[i].val() > self.right.val());
            self.top[i].next = self.vy[i].val().get_bit(self.xy_msb.val().index());
            self.below[i].next = !self.top[i].val() & (self.vy[i].val() > self.bottom.val());
            self.near[i].next = self.vz[i].val().get_bit(self.z_msb.val().index());
            self.far[i].next = !self.near[i].val() & (self.vz[i].val() > self.z_max.val());
            // Bits as `outcode_bit`.
            self.oc[i].next = bits::<OUTCODE>(0)
                .replace_bit(0, self.left[i].val())
                .replace_bit(1, self.right_of[i].val())
                .replace_bit(2, self.top[i].val())
                .replace_bit(3, self.below[i].val())
                .replace_bit(4, self.near[i].val())
                .replace_bit(5, self.far[i].val());
        }
        // Edge vectors one bit wider than the coordinates (their sign bit copied up), in
        // submission order (`model::cull_sort::area2`).
        for i in 0..3 {
            self.wx[i].x.next = self.vx[i].val();
            self.wy[i].x.next = self.vy[i].val();
        }
        // Sort by (y, input index): vertex i goes before j (i < j) iff y_i <= y_j; a
        // vertex's rank is the number of vertices before it.
        for i in 0..3 {
            self.key[i].next = self.vy[i].val() ^ self.half.val();
        }
        self.le01.next = self.key[0].val() <= self.key[1].val();
        self.le12.next = self.key[1].val() <= self.key[2].val();
        self.le02.next = self.key[0].val() <= self.key[2].val();
        self.gt01.next = !self.le01.val();
        self.gt12.next = !self.le12.val();
        self.gt02.next = !self.le02.val();
        self.rank[0].next = bits::<2>(0) + self.gt01.val() + self.gt02.val();
        self.rank[1].next = bits::<2>(0) + self.le01.val() + self.gt12.val();
        self.rank[2].next = bits::<2>(0) + self.le02.val() + self.le12.val();
        if self.take.val() {
            self.e1x.d.next = self.wx[1].y.val() - self.wx[0].y.val();
            self.e2y.d.next = self.wy[2].y.val() - self.wy[0].y.val();
            self.e2x.d.next = self.wx[2].y.val() - self.wx[0].y.val();
            self.e1y.d.next = self.wy[1].y.val() - self.wy[0].y.val();
            self.outside1.d.next = self.oc[0].val() & self.oc[1].val() & self.oc[2].val();
            self.crosses1.d.next = self.oc[0].val() | self.oc[1].val() | self.oc[2].val();
            self.back1.d.next = self.cull_back.val();
            for s in 0..3 {
                for i in 0..3 {
                    if self.rank[i].val().index() == s {
                        self.s1x[s].d.next = self.vx[i].val();
                        self.s1y[s].d.next = self.vy[i].val();
                        self.s1z[s].d.next = self.vz[i].val();
                        self.s1iw[s].d.next = self.viw[i].val();
                        self.s1c[3 * s].d.next = self.vc[3 * i].val();
                        self.s1c[3 * s + 1].d.next = self.vc[3 * i + 1].val();
                        self.s1c[3 * s + 2].d.next = self.vc[3 * i + 2].val();
                    }
                }
            }
        }

        // Stage 2: the two products of twice the area,
        // (v1 - v0).x (v2 - v0).y - (v2 - v0).x (v1 - v0).y, each into a register.
        self.area_mul[0].a.next = self.e1x.q.val();
        self.area_mul[0].b.next = self.e2y.q.val();
        self.area_mul[1].a.next = self.e2x.q.val();
        self.area_mul[1].b.next = self.e1y.q.val();
        if self.move1.val() {
            self.prod0.d.next = self.area_mul[0].p.val();
            self.prod1.d.next = self.area_mul[1].p.val();
            self.outside2.d.next = self.outside1.q.val();
            self.crosses2.d.next = self.crosses1.q.val();
            self.back2.d.next = self.back1.q.val();
            for i in 0..3 {
                self.s2x[i].d.next = self.s1x[i].q.val();
                self.s2y[i].d.next = self.s1y[i].q.val();
                self.s2z[i].d.next = self.s1z[i].q.val();
                self.s2iw[i].d.next = self.s1iw[i].q.val();
            }
            for i in 0..9 {
                self.s2c[i].d.next = self.s1c[i].q.val();
            }
        }

        // Stage 3: twice the area and the verdict, in the model's order: outside one
        // plane, zero area, back face (twice the area > 0).
        self.area.next = self.prod0.q.val() - self.prod1.q.val();
        self.code.next = self.passed.val();
        if self.cull.on.val() {
            if self.back2.q.val() & !self.area.val().get_bit(self.area_msb.val().index()) {
                self.code.next = self.back_face.val();
            }
            if self.prod0.q.val() == self.prod1.q.val() {
                self.code.next = self.zero_area.val();
            }
            if self.outside2.q.val().any() {
                self.code.next = self.outside.val();
            }
        }
        if self.move2.val() {
            self.code_r.d.next = self.code.val();
            self.crosses.d.next = self.crosses2.q.val();
            self.outside_r.d.next = self.outside2.q.val();
            for i in 0..3 {
                self.sx[i].d.next = self.s2x[i].q.val();
                self.sy[i].d.next = self.s2y[i].q.val();
                self.sz[i].d.next = self.s2z[i].q.val();
                self.siw[i].d.next = self.s2iw[i].q.val();
            }
            for i in 0..9 {
                self.sc[i].d.next = self.s2c[i].q.val();
            }
        }
        self.out.valid.next = self.full.q.val() & (self.code_r.q.val() == self.passed.val());
        self.verdict.valid.next = self.leave.val();
        self.verdict.code.next = self.code_r.q.val();
        self.verdict.outside.next = self.outside_r.q.val();
        self.out.crosses.next = self.crosses.q.val();
        self.out.v0_x.next = self.sx[0].q.val();
        self.out.v0_y.next = self.sy[0].q.val();
        self.out.v0_z.next = self.sz[0].q.val();
        self.out.v0_c0.next = self.sc[0].q.val();
        self.out.v0_c1.next = self.sc[1].q.val();
        self.out.v0_c2.next = self.sc[2].q.val();
        self.out.v0_iw.next = self.siw[0].q.val();
        self.out.v1_x.next = self.sx[1].q.val();
        self.out.v1_y.next = self.sy[1].q.val();
        self.out.v1_z.next = self.sz[1].q.val();
        self.out.v1_c0.next = self.sc[3].q.val();
        self.out.v1_c1.next = self.sc[4].q.val();
        self.out.v1_c2.next = self.sc[5].q.val();
        self.out.v1_iw.next = self.siw[1].q.val();
        self.out.v2_x.next = self.sx[2].q.val();
        self.out.v2_y.next = self.sy[2].q.val();
        self.out.v2_z.next = self.sz[2].q.val();
        self.out.v2_c0.next = self.sc[6].q.val();
        self.out.v2_c1.next = self.sc[7].q.val();
        self.out.v2_c2.next = self.sc[8].q.val();
        self.out.v2_iw.next = self.siw[2].q.val();
    }
}

crate::pins!(CullSort {
    clock: clock,
    inputs: [width, height, cull_back,],
    outputs: [idle],
    links: [out, inp, verdict],
});

impl CullSort {
    /// The cull & sort unit with rejecting and culling present or not (`parts.cull`).
    pub fn new(parts: &Parts) -> CullSort {
        CullSort { cull: Switch::new(parts.cull), ..Default::default() }
    }
}

/// `UNITS` entry: the cull & sort unit, with rejecting and culling as `params["CULL"]`
/// says (the screen size is an input).
pub fn emit_cull_sort(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("cull_sort", CullSort::new(&Parts::of(params)?), params))
}
