//! `triangle_setup`'s geometry: what setup derives from a triangle's vertices with adders,
//! shifts and multiplexers only (model: `model::triangle_setup::triangle_setup`, its first
//! lines): the edge vectors, the walk direction and order (003), the scanline centres and
//! counts, the operands of the edge divisions, the offsets of the pixel centres each edge
//! tracks, and the attribute differences.
//!
//! Setup has several triangles in flight (see `Schedule`) and a copy of a triangle's
//! registers for each II cycles of its schedule, so it has one of these per copy: the part
//! of the schedule that reads a copy reads its geometry, from registers (issue 17: the
//! scanline centres and counts into the division issue were setup's critical path).

use super::super::cull_sort::{outcode_bit, COLOR, OUTCODE, XY, Z};
use super::super::divider::DIV_D;
use super::super::widths::{FORMATS, PIXEL};
use super::{ones_from, ATTR, G, NB, W};
use blank::Blank;
use rust_hdl::prelude::*;

const S: u32 = FORMATS.xy.frac;

/// A triangle's geometry, registered: its inputs are the copy's next vertices (the values
/// its registers are loaded with), so its outputs, registers loaded every cycle, are the
/// geometry of the vertices the copy holds, one cycle of adders away from every register
/// that reads them. `off_x`, from the copy's start pixels and side, is combinational.
#[derive(LogicBlock, Blank)]
pub struct Geometry {
    pub clock: Signal<In, Clock>,
    /// The triangle: x, y, z, colours (3 * vertex + channel), and its crossings.
    pub vx: [Signal<In, Bits<XY>>; 3],
    pub vy: [Signal<In, Bits<XY>>; 3],
    pub vz: [Signal<In, Bits<Z>>; 3],
    pub vc: [Signal<In, Bits<COLOR>>; 9],
    pub crosses: Signal<In, Bits<OUTCODE>>,
    /// e_maj is the left side (twice the area < 0).
    pub maj_left: Signal<In, Bit>,
    /// Each edge's start pixel, once its start division is back.
    pub start_x: [Signal<In, Bits<NB>>; 3],

    /// Edge vectors e_maj (v0 -> v2), e_bot (v0 -> v1), e_top (v1 -> v2): dx, dy.
    pub kdx: [Signal<Out, Bits<W>>; 3],
    pub kdy: [Signal<Out, Bits<G>>; 3],
    /// Walk up (003): the triangle crosses the top boundary and not the bottom one.
    pub up: Signal<Out, Bit>,
    /// Per edge in walk order (e_maj, then the short edges as `TriangleSetupOut::short`):
    /// dx, dy, dy as the divisor (zero-extended when `G` is narrower), 2^s dy, the
    /// scanline centre, count, the start division's offsets (t, x fraction, x integer) and
    /// the tracked pixel centre's offsets from v0.
    pub edx: [Signal<Out, Bits<W>>; 3],
    pub edy: [Signal<Out, Bits<G>>; 3],
    pub edy_d: [Signal<Out, Bits<DIV_D>>; 3],
    pub ed16: [Signal<Out, Bits<DIV_D>>; 3],
    pub cy: [Signal<Out, Bits<NB>>; 3],
    pub count: [Signal<Out, Bits<PIXEL>>; 3],
    pub toff: [Signal<Out, Bits<NB>>; 3],
    pub xf: [Signal<Out, Bits<NB>>; 3],
    pub xi: [Signal<Out, Bits<NB>>; 3],
    pub off_x: [Signal<Out, Bits<NB>>; 3],
    pub off_y: [Signal<Out, Bits<NB>>; 3],
    /// Attribute differences from v0 along e_maj and e_bot (z, R, G, B); v0's attributes
    /// in a lane.
    pub dmaj: [Signal<Out, Bits<NB>>; 4],
    pub dbot: [Signal<Out, Bits<NB>>; 4],
    pub attr0: [Signal<Out, Bits<ATTR>>; 4],

    /// The geometry as computed (from the copy's next vertices), and its registers: each
    /// output above but `off_x` is its register, so that no path runs from a copy's vertices
    /// through the adders above into the multipliers' operands or the divider's.
    c_kdx: [Signal<Local, Bits<W>>; 3],
    c_kdy: [Signal<Local, Bits<G>>; 3],
    c_up: Signal<Local, Bit>,
    c_edx: [Signal<Local, Bits<W>>; 3],
    c_edy: [Signal<Local, Bits<G>>; 3],
    c_edy_d: [Signal<Local, Bits<DIV_D>>; 3],
    c_ed16: [Signal<Local, Bits<DIV_D>>; 3],
    c_cy: [Signal<Local, Bits<NB>>; 3],
    c_count: [Signal<Local, Bits<PIXEL>>; 3],
    c_toff: [Signal<Local, Bits<NB>>; 3],
    c_xf: [Signal<Local, Bits<NB>>; 3],
    c_xi: [Signal<Local, Bits<NB>>; 3],
    c_off_y: [Signal<Local, Bits<NB>>; 3],
    c_dmaj: [Signal<Local, Bits<NB>>; 4],
    c_dbot: [Signal<Local, Bits<NB>>; 4],
    c_attr0: [Signal<Local, Bits<ATTR>>; 4],
    kdx_r: [DFF<Bits<W>>; 3],
    kdy_r: [DFF<Bits<G>>; 3],
    up_r: DFF<Bit>,
    edx_r: [DFF<Bits<W>>; 3],
    edy_r: [DFF<Bits<G>>; 3],
    edy_d_r: [DFF<Bits<DIV_D>>; 3],
    ed16_r: [DFF<Bits<DIV_D>>; 3],
    cy_r: [DFF<Bits<NB>>; 3],
    count_r: [DFF<Bits<PIXEL>>; 3],
    toff_r: [DFF<Bits<NB>>; 3],
    xf_r: [DFF<Bits<NB>>; 3],
    xi_r: [DFF<Bits<NB>>; 3],
    off_y_r: [DFF<Bits<NB>>; 3],
    dmaj_r: [DFF<Bits<NB>>; 4],
    dbot_r: [DFF<Bits<NB>>; 4],
    attr0_r: [DFF<Bits<ATTR>>; 4],
    /// v0's x in the narrow domain, registered for `off_x`.
    xn0_r: DFF<Bits<NB>>,
    /// x, y sign-extended to `W` and `G` bits (y only meets the multipliers' A side and
    /// divisors); z, colours as `NB`-bit numbers.
    xw: [Signal<Local, Bits<W>>; 3],
    yw: [Signal<Local, Bits<G>>; 3],
    zn: [Signal<Local, Bits<NB>>; 3],
    cn: [Signal<Local, Bits<NB>>; 9],
    /// x, y as `NB`-bit numbers.
    xn: [Signal<Local, Bits<NB>>; 3],
    yn: [Signal<Local, Bits<NB>>; 3],
    /// The first scanline centre at or below each vertex, `(y + 7) & !15 | 8` (subpixels).
    cv: [Signal<Local, Bits<NB>>; 3],
    /// Scanlines between those centres along e_maj, e_bot, e_top (vMin..vMax, vMin..vMid,
    /// vMid..vMax), 0 when negative, and the centres' differences.
    span: [Signal<Local, Bits<PIXEL>>; 3],
    diff: [Signal<Local, Bits<NB>>; 3],
    /// Per edge in walk order: the walk's base vertex, its x - 1/2, and the pixel the side
    /// tracks (x on the left side, x - 1 on the right).
    bx: [Signal<Local, Bits<NB>>; 3],
    by: [Signal<Local, Bits<NB>>; 3],
    xb: [Signal<Local, Bits<NB>>; 3],
    tracked: [Signal<Local, Bits<NB>>; 3],

    /// s; 2^(s-1) - 1, 2^(s-1), !(2^s - 1) and 2^s - 1 in the narrow domain.
    frac: Constant<Bits<8>>,
    half_m1: Constant<Bits<NB>>,
    half: Constant<Bits<NB>>,
    int_mask: Constant<Bits<NB>>,
    frac_mask: Constant<Bits<NB>>,
    /// Sign bits: x, y (`XY`), z, the narrow domain.
    xy_msb: Constant<Bits<8>>,
    z_msb: Constant<Bits<8>>,
    nb_msb: Constant<Bits<8>>,
    /// Ones above a sign bit: x into `W` bits, y into `G` bits, z into `NB` bits, s bits below `NB`.
    xy_ext: Constant<Bits<W>>,
    y_ext: Constant<Bits<G>>,
    z_ext: Constant<Bits<NB>>,
    shr_ext: Constant<Bits<NB>>,
    /// The outcode bits of the top and bottom planes.
    top_bit: Constant<Bits<8>>,
    bottom_bit: Constant<Bits<8>>,
}

impl Default for Geometry {
    fn default() -> Self {
        let px = 1usize << S;
        Geometry {
            frac: Constant::new((S as usize).to_bits()),
            half_m1: Constant::new((px / 2 - 1).to_bits()),
            half: Constant::new((px / 2).to_bits()),
            int_mask: ones_from(S as usize, NB),
            frac_mask: Constant::new((px - 1).to_bits()),
            xy_msb: Constant::new((XY - 1).to_bits()),
            z_msb: Constant::new((Z - 1).to_bits()),
            nb_msb: Constant::new((NB - 1).to_bits()),
            xy_ext: ones_from(XY, W),
            y_ext: ones_from(XY, G),
            z_ext: ones_from(Z, NB),
            shr_ext: ones_from(NB - S as usize, NB),
            top_bit: Constant::new(outcode_bit::TOP.to_bits()),
            bottom_bit: Constant::new(outcode_bit::BOTTOM.to_bits()),
            ..Geometry::blank()
        }
    }
}

impl Logic for Geometry {
    #[hdl_gen]
    fn update(&mut self) {
        // x, y sign-extended into the wide domain, z into the narrow one (`bit_cast` cannot
        // take a loop's index).
        self.xw[0].next = bit_cast::<W, XY>(self.vx[0].val());
        if self.vx[0].val().get_bit(self.xy_msb.val().index()) {
            self.xw[0].next = bit_cast::<W, XY>(self.vx[0].val()) | self.xy_ext.val();
        }
        self.xw[1].next = bit_cast::<W, XY>(self.vx[1].val());
        if self.vx[1].val().get_bit(self.xy_msb.val().index()) {
            self.xw[1].next = bit_cast::<W, XY>(self.vx[1].val()) | self.xy_ext.val();
        }
        self.xw[2].next = bit_cast::<W, XY>(self.vx[2].val());
        if self.vx[2].val().get_bit(self.xy_msb.val().index()) {
            self.xw[2].next = bit_cast::<W, XY>(self.vx[2].val()) | self.xy_ext.val();
        }
        self.yw[0].next = bit_cast::<G, XY>(self.vy[0].val());
        if self.vy[0].val().get_bit(self.xy_msb.val().index()) {
            self.yw[0].next = bit_cast::<G, XY>(self.vy[0].val()) | self.y_ext.val();
        }
        self.yw[1].next = bit_cast::<G, XY>(self.vy[1].val());
        if self.vy[1].val().get_bit(self.xy_msb.val().index()) {
            self.yw[1].next = bit_cast::<G, XY>(self.vy[1].val()) | self.y_ext.val();
        }
        self.yw[2].next = bit_cast::<G, XY>(self.vy[2].val());
        if self.vy[2].val().get_bit(self.xy_msb.val().index()) {
            self.yw[2].next = bit_cast::<G, XY>(self.vy[2].val()) | self.y_ext.val();
        }
        self.zn[0].next = bit_cast::<NB, Z>(self.vz[0].val());
        if self.vz[0].val().get_bit(self.z_msb.val().index()) {
            self.zn[0].next = bit_cast::<NB, Z>(self.vz[0].val()) | self.z_ext.val();
        }
        self.zn[1].next = bit_cast::<NB, Z>(self.vz[1].val());
        if self.vz[1].val().get_bit(self.z_msb.val().index()) {
            self.zn[1].next = bit_cast::<NB, Z>(self.vz[1].val()) | self.z_ext.val();
        }
        self.zn[2].next = bit_cast::<NB, Z>(self.vz[2].val());
        if self.vz[2].val().get_bit(self.z_msb.val().index()) {
            self.zn[2].next = bit_cast::<NB, Z>(self.vz[2].val()) | self.z_ext.val();
        }
        self.cn[0].next = bit_cast::<NB, COLOR>(self.vc[0].val());
        self.cn[1].next = bit_cast::<NB, COLOR>(self.vc[1].val());
        self.cn[2].next = bit_cast::<NB, COLOR>(self.vc[2].val());
        self.cn[3].next = bit_cast::<NB, COLOR>(self.vc[3].val());
        self.cn[4].next = bit_cast::<NB, COLOR>(self.vc[4].val());
        self.cn[5].next = bit_cast::<NB, COLOR>(self.vc[5].val());
        self.cn[6].next = bit_cast::<NB, COLOR>(self.vc[6].val());
        self.cn[7].next = bit_cast::<NB, COLOR>(self.vc[7].val());
        self.cn[8].next = bit_cast::<NB, COLOR>(self.vc[8].val());
        for v in 0..3 {
            self.xn[v].next = self.xw[v].val().get_bits::<NB>(0);
            self.yn[v].next = self.yw[v].val().get_bits::<NB>(0);
            self.cv[v].next = ((self.yn[v].val() + self.half_m1.val()) & self.int_mask.val()) | self.half.val();
        }
        // e_maj, e_bot, e_top, and the scanlines between their ends' first centres
        // (`span` in the model).
        self.c_kdx[0].next = self.xw[2].val() - self.xw[0].val();
        self.c_kdy[0].next = self.yw[2].val() - self.yw[0].val();
        self.diff[0].next = self.cv[2].val() - self.cv[0].val();
        self.c_kdx[1].next = self.xw[1].val() - self.xw[0].val();
        self.c_kdy[1].next = self.yw[1].val() - self.yw[0].val();
        self.diff[1].next = self.cv[1].val() - self.cv[0].val();
        self.c_kdx[2].next = self.xw[2].val() - self.xw[1].val();
        self.c_kdy[2].next = self.yw[2].val() - self.yw[1].val();
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
        self.c_up.next = self.crosses.val().get_bit(self.top_bit.val().index())
            & !self.crosses.val().get_bit(self.bottom_bit.val().index());
        for e in 0..3 {
            self.c_edx[e].next = self.c_kdx[e].val();
            self.c_edy[e].next = self.c_kdy[e].val();
            self.c_count[e].next = self.span[e].val();
        }
        self.bx[0].next = self.xn[0].val();
        self.by[0].next = self.yn[0].val();
        self.c_cy[0].next = self.cv[0].val();
        self.bx[1].next = self.xn[0].val();
        self.by[1].next = self.yn[0].val();
        self.c_cy[1].next = self.cv[0].val();
        self.bx[2].next = self.xn[1].val();
        self.by[2].next = self.yn[1].val();
        self.c_cy[2].next = self.cv[1].val();
        if self.c_up.val() {
            self.c_edx[1].next = self.c_kdx[2].val();
            self.c_edy[1].next = self.c_kdy[2].val();
            self.c_count[1].next = self.span[2].val();
            self.c_edx[2].next = self.c_kdx[1].val();
            self.c_edy[2].next = self.c_kdy[1].val();
            self.c_count[2].next = self.span[1].val();
            self.bx[0].next = self.xn[2].val();
            self.by[0].next = self.yn[2].val();
            self.c_cy[0].next = self.cv[2].val() - (self.frac_mask.val() + 1);
            self.bx[1].next = self.xn[2].val();
            self.by[1].next = self.yn[2].val();
            self.c_cy[1].next = self.cv[2].val() - (self.frac_mask.val() + 1);
            self.c_cy[2].next = self.cv[1].val() - (self.frac_mask.val() + 1);
        }
        // dy is positive; `bit_cast` (a loop's index cannot) widens it to the divisor.
        self.c_edy_d[0].next = bit_cast::<DIV_D, G>(self.c_edy[0].val());
        self.c_edy_d[1].next = bit_cast::<DIV_D, G>(self.c_edy[1].val());
        self.c_edy_d[2].next = bit_cast::<DIV_D, G>(self.c_edy[2].val());
        // e_maj is the left side when maj_left; the short edges are then on the right.
        self.tracked[0].next = self.start_x[0].val() - 1;
        if self.maj_left.val() {
            self.tracked[0].next = self.start_x[0].val();
        }
        for e in 1..3 {
            self.tracked[e].next = self.start_x[e].val();
            if self.maj_left.val() {
                self.tracked[e].next = self.start_x[e].val() - 1;
            }
        }
        for e in 0..3 {
            self.c_ed16[e].next = self.c_edy_d[e].val() << self.frac.val();
            // The start division's offsets: t from the base vertex to the centre, and the
            // base's x - 1/2 split into pixel and fraction (floor).
            self.c_toff[e].next = self.c_cy[e].val() - self.by[e].val();
            self.xb[e].next = self.bx[e].val() - self.half.val();
            self.c_xf[e].next = self.xb[e].val() & self.frac_mask.val();
            self.c_xi[e].next = self.xb[e].val() >> self.frac.val();
            if self.xb[e].val().get_bit(self.nb_msb.val().index()) {
                self.c_xi[e].next = (self.xb[e].val() >> self.frac.val()) | self.shr_ext.val();
            }
            // Offsets from v0 of the pixel centre this side tracks.
            self.c_off_y[e].next = self.c_cy[e].val() - self.yn[0].val();
            self.off_x[e].next = (self.tracked[e].val() << self.frac.val()) + self.half.val() - self.xn0_r.q.val();
        }
        // Attribute differences along e_maj and e_bot; v0's attributes.
        self.c_dmaj[0].next = self.zn[2].val() - self.zn[0].val();
        self.c_dbot[0].next = self.zn[1].val() - self.zn[0].val();
        self.c_attr0[0].next = bit_cast::<ATTR, NB>(self.zn[0].val());
        self.c_attr0[1].next = bit_cast::<ATTR, COLOR>(self.vc[0].val());
        self.c_attr0[2].next = bit_cast::<ATTR, COLOR>(self.vc[1].val());
        self.c_attr0[3].next = bit_cast::<ATTR, COLOR>(self.vc[2].val());
        for c in 0..3 {
            self.c_dmaj[c + 1].next = self.cn[6 + c].val() - self.cn[c].val();
            self.c_dbot[c + 1].next = self.cn[3 + c].val() - self.cn[c].val();
        }
        // ---- The registers: loaded every cycle from the next vertices, so each holds the
        // geometry of the copy's vertices as they are.
        self.xn0_r.clock.next = self.clock.val();
        self.xn0_r.d.next = self.xn[0].val();
        for i in 0..3 {
            self.kdx_r[i].clock.next = self.clock.val();
            self.kdx_r[i].d.next = self.c_kdx[i].val();
            self.kdx[i].next = self.kdx_r[i].q.val();
        }
        for i in 0..3 {
            self.kdy_r[i].clock.next = self.clock.val();
            self.kdy_r[i].d.next = self.c_kdy[i].val();
            self.kdy[i].next = self.kdy_r[i].q.val();
        }
        self.up_r.clock.next = self.clock.val();
        self.up_r.d.next = self.c_up.val();
        self.up.next = self.up_r.q.val();
        for i in 0..3 {
            self.edx_r[i].clock.next = self.clock.val();
            self.edx_r[i].d.next = self.c_edx[i].val();
            self.edx[i].next = self.edx_r[i].q.val();
        }
        for i in 0..3 {
            self.edy_r[i].clock.next = self.clock.val();
            self.edy_r[i].d.next = self.c_edy[i].val();
            self.edy[i].next = self.edy_r[i].q.val();
        }
        for i in 0..3 {
            self.edy_d_r[i].clock.next = self.clock.val();
            self.edy_d_r[i].d.next = self.c_edy_d[i].val();
            self.edy_d[i].next = self.edy_d_r[i].q.val();
        }
        for i in 0..3 {
            self.ed16_r[i].clock.next = self.clock.val();
            self.ed16_r[i].d.next = self.c_ed16[i].val();
            self.ed16[i].next = self.ed16_r[i].q.val();
        }
        for i in 0..3 {
            self.cy_r[i].clock.next = self.clock.val();
            self.cy_r[i].d.next = self.c_cy[i].val();
            self.cy[i].next = self.cy_r[i].q.val();
        }
        for i in 0..3 {
            self.count_r[i].clock.next = self.clock.val();
            self.count_r[i].d.next = self.c_count[i].val();
            self.count[i].next = self.count_r[i].q.val();
        }
        for i in 0..3 {
            self.toff_r[i].clock.next = self.clock.val();
            self.toff_r[i].d.next = self.c_toff[i].val();
            self.toff[i].next = self.toff_r[i].q.val();
        }
        for i in 0..3 {
            self.xf_r[i].clock.next = self.clock.val();
            self.xf_r[i].d.next = self.c_xf[i].val();
            self.xf[i].next = self.xf_r[i].q.val();
        }
        for i in 0..3 {
            self.xi_r[i].clock.next = self.clock.val();
            self.xi_r[i].d.next = self.c_xi[i].val();
            self.xi[i].next = self.xi_r[i].q.val();
        }
        for i in 0..3 {
            self.off_y_r[i].clock.next = self.clock.val();
            self.off_y_r[i].d.next = self.c_off_y[i].val();
            self.off_y[i].next = self.off_y_r[i].q.val();
        }
        for i in 0..4 {
            self.dmaj_r[i].clock.next = self.clock.val();
            self.dmaj_r[i].d.next = self.c_dmaj[i].val();
            self.dmaj[i].next = self.dmaj_r[i].q.val();
        }
        for i in 0..4 {
            self.dbot_r[i].clock.next = self.clock.val();
            self.dbot_r[i].d.next = self.c_dbot[i].val();
            self.dbot[i].next = self.dbot_r[i].q.val();
        }
        for i in 0..4 {
            self.attr0_r[i].clock.next = self.clock.val();
            self.attr0_r[i].d.next = self.c_attr0[i].val();
            self.attr0[i].next = self.attr0_r[i].q.val();
        }
    }
}
