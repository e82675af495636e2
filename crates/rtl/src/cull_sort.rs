//! `cull_sort`: the cull & sort unit of paper 003 (Lee 2008, §II.1.다.(1), Fig. 4, Table 1:
//! "clipping 1 cycle").
//!
//! One triangle per beat: the three vertices in submission order on the link `inp`
//! (`links::TriangleSink`: `inp$v<i>_x` ... `inp$v<i>_iw`), screen size on `width`, `height`, face culling on `cull_back`. In
//! the one cycle it has, the unit computes
//! * a Cohen-Sutherland outcode per vertex (bits as `model::cull_sort::outcode`: x < 0,
//!   x > width, y < 0, y > height, z < 0, z > the largest depth value);
//! * the reject verdict, in the model's order: all three outside one plane (the AND of the
//!   outcodes), zero area, a back face (twice the signed area > 0, with `cull_back` high);
//! * the vertex order by (y, input index): three comparisons give each vertex its rank.
//!
//! ```text
//!   inp_v0..2 --+-- outcodes --- AND: outside? ----------------+
//!               |            `-- OR: crosses -------------------+--> register --> out_v0..2 (sorted),
//!               +-- 2 x Mul<17,17>: area2 -- zero? back face? --+                 out$crosses, out$valid
//!               `-- y0<=y1, y1<=y2, y0<=y2 -> ranks -> mux -----+                 verdict$*
//! ```
//!
//! A triangle taken in cycle t (`inp$valid & inp$ready`) is in the output register in
//! cycle t + 1 (latency `model::cull_sort::LATENCY` = 1, II 1). A passing triangle stays
//! there until `out$ready`; a rejected one leaves at once (it goes no further, so it never
//! waits for setup). `verdict$valid` is high in the cycle a triangle leaves, with its
//! verdict. No new vertices are made: a triangle that crosses the screen goes on whole
//! with `out$crosses` (the OR of the outcodes) and is clipped by the edge walk and span.
//!
//! Model: `model::cull_sort::cull_sort`. Emitted: `hdl-out/cull_sort.v`.

use crate::emit::{emit_unit, Emitted};
use crate::mul::Mul;
use crate::parts::SignExtend;
use crate::switch::{Parts, Switch};
use super::links::{SortedSource, TriangleSink, Verdict};
use super::widths::{DIM, FORMATS, WIDTHS};
use crate::Params;
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
#[derive(LogicBlock)]
pub struct CullSort {
    pub clock: Signal<In, Clock>,
    /// Screen size in pixels, 1 to 2^CLASS (the size class): the clip volume is [0, width] x [0, height].
    pub width: Signal<In, Bits<DIM>>,
    pub height: Signal<In, Bits<DIM>>,
    /// Drop back faces (clockwise on screen, y down).
    pub cull_back: Signal<In, Bit>,
    /// The triangle in; `inp.ready`: the output register is free (empty, holding a rejected triangle, or being taken).
    pub inp: TriangleSink,
    /// The sorted triangle out, with the planes it crosses.
    pub out: SortedSource,
    /// Each triangle leaving the unit (taken, or rejected) and why; `outside`: for
    /// `OUTSIDE` the planes all three vertices lie outside (`Reject::Outside`), else 0.
    pub verdict: Verdict,
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
    /// differences), and twice the signed area (submission order).
    wx: [SignExtend<XY, DELTA>; 3],
    wy: [SignExtend<XY, DELTA>; 3],
    area: Signal<Local, Bits<AREA>>,
    area_mul: [Mul<DELTA, DELTA, AREA>; 2],
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
    code: Signal<Local, Bits<2>>,
    take: Signal<Local, Bit>,
    leave: Signal<Local, Bit>,
    /// The output register: the sorted vertices, crosses, the verdict, and whether it
    /// holds a triangle.
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
            clock: Default::default(),
            width: Default::default(),
            height: Default::default(),
            cull_back: Default::default(),
            inp: Default::default(),
            out: Default::default(),
            verdict: Default::default(),
            vx: Default::default(),
            vy: Default::default(),
            vz: Default::default(),
            vc: Default::default(),
            viw: Default::default(),
            oc: Default::default(),
            left: Default::default(),
            right_of: Default::default(),
            top: Default::default(),
            below: Default::default(),
            near: Default::default(),
            far: Default::default(),
            right: Default::default(),
            bottom: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            area: Default::default(),
            area_mul: Default::default(),
            key: Default::default(),
            le01: Default::default(),
            le12: Default::default(),
            le02: Default::default(),
            gt01: Default::default(),
            gt12: Default::default(),
            gt02: Default::default(),
            rank: Default::default(),
            code: Default::default(),
            take: Default::default(),
            leave: Default::default(),
            sx: Default::default(),
            sy: Default::default(),
            sz: Default::default(),
            sc: Default::default(),
            siw: Default::default(),
            crosses: Default::default(),
            code_r: Default::default(),
            outside_r: Default::default(),
            full: Default::default(),
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
            cull: Default::default(),
        }
    }
}

impl Logic for CullSort {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, crosses, code_r, outside_r, full);
        for i in 0..3 {
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

        // Outcodes. x > width * 2^s only for x >= 0, where the unsigned order is the
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

        // Twice the signed area in submission order (`model::cull_sort::area2`), from edge
        // vectors one bit wider than the coordinates (their sign bit copied up).
        for i in 0..3 {
            self.wx[i].x.next = self.vx[i].val();
            self.wy[i].x.next = self.vy[i].val();
        }
        // (v1 - v0).x (v2 - v0).y - (v2 - v0).x (v1 - v0).y
        self.area_mul[0].a.next = self.wx[1].y.val() - self.wx[0].y.val();
        self.area_mul[0].b.next = self.wy[2].y.val() - self.wy[0].y.val();
        self.area_mul[1].a.next = self.wx[2].y.val() - self.wx[0].y.val();
        self.area_mul[1].b.next = self.wy[1].y.val() - self.wy[0].y.val();
        self.area.next = self.area_mul[0].p.val() - self.area_mul[1].p.val();

        // The verdict, in the model's order: outside one plane, zero area, back face.
        self.code.next = self.passed.val();
        if self.cull.on.val() {
            if self.cull_back.val() & !self.area.val().get_bit(self.area_msb.val().index()) {
                self.code.next = self.back_face.val();
            }
            if self.area.val() == 0 {
                self.code.next = self.zero_area.val();
            }
            if (self.oc[0].val() & self.oc[1].val() & self.oc[2].val()).any() {
                self.code.next = self.outside.val();
            }
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

        // The output register.
        self.leave.next = self.full.q.val() & ((self.code_r.q.val() != self.passed.val()) | self.out.ready.val());
        self.inp.ready.next = !self.full.q.val() | self.leave.val();
        self.take.next = self.inp.valid.val() & self.inp.ready.val();
        if self.leave.val() {
            self.full.d.next = false;
        }
        if self.take.val() {
            self.full.d.next = true;
            self.code_r.d.next = self.code.val();
            self.crosses.d.next = self.oc[0].val() | self.oc[1].val() | self.oc[2].val();
            self.outside_r.d.next = self.oc[0].val() & self.oc[1].val() & self.oc[2].val();
            for s in 0..3 {
                for i in 0..3 {
                    if self.rank[i].val().index() == s {
                        self.sx[s].d.next = self.vx[i].val();
                        self.sy[s].d.next = self.vy[i].val();
                        self.sz[s].d.next = self.vz[i].val();
                        self.siw[s].d.next = self.viw[i].val();
                        self.sc[3 * s].d.next = self.vc[3 * i].val();
                        self.sc[3 * s + 1].d.next = self.vc[3 * i + 1].val();
                        self.sc[3 * s + 2].d.next = self.vc[3 * i + 2].val();
                    }
                }
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
    inputs: [
        width, height, cull_back,
    ],
    outputs: [],
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
