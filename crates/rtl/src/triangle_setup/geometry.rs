//! `triangle_setup`'s geometry: what setup derives from a triangle's vertices with adders,
//! shifts and multiplexers only (model: `model::triangle_setup::triangle_setup`, its first
//! lines): the edge vectors, the walk direction and order (003), the scanline centres and
//! counts, the operands of the edge divisions, the offsets of the pixel centres each edge
//! tracks, and the attribute differences.
//!
//! Setup has several triangles in flight (see `Schedule`) and a copy of a triangle's
//! registers for each II cycles of its schedule. The geometry is computed once, from the
//! triangle setup takes ([`Geometry`], into copy 0's [`GeometryWord`] register), and moves
//! with the triangle from copy to copy as a register; each copy's [`GeometryView`] names its
//! fields. So the part of the schedule that reads a copy reads its geometry from registers,
//! and no path runs from a copy's counter through adders into them (issue 17: the scanline
//! centres and counts, computed per copy from its next vertices, were setup's critical path).

use super::super::cull_sort::{outcode_bit, COLOR, OUTCODE, XY, Z};
use super::super::divider::DIV_D;
use super::super::widths::{FORMATS, PIXEL};
use super::{ones_from, ATTR, G, NB, W};
use blank::Blank;
use rust_hdl::prelude::*;

const S: u32 = FORMATS.xy.frac;

/// A triangle's geometry as one word, which setup's copies hold and hand on: the edge
/// vectors e_maj (v0 -> v2), e_bot (v0 -> v1), e_top (v1 -> v2) (`kdx`, `kdy`); the walk
/// direction (`up`, 003: the triangle crosses the top boundary and not the bottom one); per
/// edge in walk order (e_maj, then the short edges as `TriangleSetupOut::short`) dx, dy,
/// the scanline centre, count (and whether it is over 0 and over 1: the edge's start and
/// step divisions used), the start division's offsets (t, x fraction, x integer) and
/// the tracked pixel centre's y offset from v0; the attribute differences from v0 along
/// e_maj and e_bot (z, R, G, B) and v0's attributes in a lane; v0's x in the narrow domain.
/// Fields `<name>_<index>` are [`GeometryView`]'s arrays.
#[derive(Clone, Copy, Debug, Default, PartialEq, LogicStruct)]
pub struct GeometryWord {
    pub kdx_0: Bits<W>,
    pub kdx_1: Bits<W>,
    pub kdx_2: Bits<W>,
    pub kdy_0: Bits<G>,
    pub kdy_1: Bits<G>,
    pub kdy_2: Bits<G>,
    pub up: Bit,
    pub edx_0: Bits<W>,
    pub edx_1: Bits<W>,
    pub edx_2: Bits<W>,
    pub edy_0: Bits<G>,
    pub edy_1: Bits<G>,
    pub edy_2: Bits<G>,
    pub cy_0: Bits<NB>,
    pub cy_1: Bits<NB>,
    pub cy_2: Bits<NB>,
    pub count_0: Bits<PIXEL>,
    pub count_1: Bits<PIXEL>,
    pub count_2: Bits<PIXEL>,
    pub used_0: Bit,
    pub used_1: Bit,
    pub used_2: Bit,
    pub step_0: Bit,
    pub step_1: Bit,
    pub step_2: Bit,
    pub toff_0: Bits<NB>,
    pub toff_1: Bits<NB>,
    pub toff_2: Bits<NB>,
    pub xf_0: Bits<NB>,
    pub xf_1: Bits<NB>,
    pub xf_2: Bits<NB>,
    pub xi_0: Bits<NB>,
    pub xi_1: Bits<NB>,
    pub xi_2: Bits<NB>,
    pub off_y_0: Bits<NB>,
    pub off_y_1: Bits<NB>,
    pub off_y_2: Bits<NB>,
    pub dmaj_0: Bits<NB>,
    pub dmaj_1: Bits<NB>,
    pub dmaj_2: Bits<NB>,
    pub dmaj_3: Bits<NB>,
    pub dbot_0: Bits<NB>,
    pub dbot_1: Bits<NB>,
    pub dbot_2: Bits<NB>,
    pub dbot_3: Bits<NB>,
    pub attr0_0: Bits<ATTR>,
    pub attr0_1: Bits<ATTR>,
    pub attr0_2: Bits<ATTR>,
    pub attr0_3: Bits<ATTR>,
    pub xn0: Bits<NB>,
}

/// A triangle's geometry, computed from its vertices (the triangle setup takes) with
/// adders, shifts and multiplexers: combinational, into copy 0's register.
#[derive(LogicBlock, Blank)]
pub struct Geometry {
    /// The triangle: x, y, z, colours (3 * vertex + channel), and its crossings.
    pub vx: [Signal<In, Bits<XY>>; 3],
    pub vy: [Signal<In, Bits<XY>>; 3],
    pub vz: [Signal<In, Bits<Z>>; 3],
    pub vc: [Signal<In, Bits<COLOR>>; 9],
    pub crosses: Signal<In, Bits<OUTCODE>>,
    pub word: Signal<Out, GeometryWord>,

    /// The word's fields (see [`GeometryWord`]).
    kdx: [Signal<Local, Bits<W>>; 3],
    kdy: [Signal<Local, Bits<G>>; 3],
    up: Signal<Local, Bit>,
    edx: [Signal<Local, Bits<W>>; 3],
    edy: [Signal<Local, Bits<G>>; 3],
    cy: [Signal<Local, Bits<NB>>; 3],
    count: [Signal<Local, Bits<PIXEL>>; 3],
    toff: [Signal<Local, Bits<NB>>; 3],
    xf: [Signal<Local, Bits<NB>>; 3],
    xi: [Signal<Local, Bits<NB>>; 3],
    off_y: [Signal<Local, Bits<NB>>; 3],
    dmaj: [Signal<Local, Bits<NB>>; 4],
    dbot: [Signal<Local, Bits<NB>>; 4],
    attr0: [Signal<Local, Bits<ATTR>>; 4],
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
    /// Per edge in walk order: the walk's base vertex, and its x - 1/2.
    bx: [Signal<Local, Bits<NB>>; 3],
    by: [Signal<Local, Bits<NB>>; 3],
    xb: [Signal<Local, Bits<NB>>; 3],

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
        self.up.next = self.crosses.val().get_bit(self.top_bit.val().index())
            & !self.crosses.val().get_bit(self.bottom_bit.val().index());
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
        for e in 0..3 {
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
        }
        // Attribute differences along e_maj and e_bot; v0's attributes.
        self.dmaj[0].next = self.zn[2].val() - self.zn[0].val();
        self.dbot[0].next = self.zn[1].val() - self.zn[0].val();
        self.attr0[0].next = bit_cast::<ATTR, NB>(self.zn[0].val());
        self.attr0[1].next = bit_cast::<ATTR, COLOR>(self.vc[0].val());
        self.attr0[2].next = bit_cast::<ATTR, COLOR>(self.vc[1].val());
        self.attr0[3].next = bit_cast::<ATTR, COLOR>(self.vc[2].val());
        for c in 0..3 {
            self.dmaj[c + 1].next = self.cn[6 + c].val() - self.cn[c].val();
            self.dbot[c + 1].next = self.cn[3 + c].val() - self.cn[c].val();
        }
        // ---- The word.
        self.word.next.kdx_0 = self.kdx[0].val();
        self.word.next.kdx_1 = self.kdx[1].val();
        self.word.next.kdx_2 = self.kdx[2].val();
        self.word.next.kdy_0 = self.kdy[0].val();
        self.word.next.kdy_1 = self.kdy[1].val();
        self.word.next.kdy_2 = self.kdy[2].val();
        self.word.next.up = self.up.val();
        self.word.next.edx_0 = self.edx[0].val();
        self.word.next.edx_1 = self.edx[1].val();
        self.word.next.edx_2 = self.edx[2].val();
        self.word.next.edy_0 = self.edy[0].val();
        self.word.next.edy_1 = self.edy[1].val();
        self.word.next.edy_2 = self.edy[2].val();
        self.word.next.cy_0 = self.cy[0].val();
        self.word.next.cy_1 = self.cy[1].val();
        self.word.next.cy_2 = self.cy[2].val();
        self.word.next.count_0 = self.count[0].val();
        self.word.next.count_1 = self.count[1].val();
        self.word.next.count_2 = self.count[2].val();
        self.word.next.used_0 = self.count[0].val() != 0;
        self.word.next.used_1 = self.count[1].val() != 0;
        self.word.next.used_2 = self.count[2].val() != 0;
        self.word.next.step_0 = self.count[0].val() > 1;
        self.word.next.step_1 = self.count[1].val() > 1;
        self.word.next.step_2 = self.count[2].val() > 1;
        self.word.next.toff_0 = self.toff[0].val();
        self.word.next.toff_1 = self.toff[1].val();
        self.word.next.toff_2 = self.toff[2].val();
        self.word.next.xf_0 = self.xf[0].val();
        self.word.next.xf_1 = self.xf[1].val();
        self.word.next.xf_2 = self.xf[2].val();
        self.word.next.xi_0 = self.xi[0].val();
        self.word.next.xi_1 = self.xi[1].val();
        self.word.next.xi_2 = self.xi[2].val();
        self.word.next.off_y_0 = self.off_y[0].val();
        self.word.next.off_y_1 = self.off_y[1].val();
        self.word.next.off_y_2 = self.off_y[2].val();
        self.word.next.dmaj_0 = self.dmaj[0].val();
        self.word.next.dmaj_1 = self.dmaj[1].val();
        self.word.next.dmaj_2 = self.dmaj[2].val();
        self.word.next.dmaj_3 = self.dmaj[3].val();
        self.word.next.dbot_0 = self.dbot[0].val();
        self.word.next.dbot_1 = self.dbot[1].val();
        self.word.next.dbot_2 = self.dbot[2].val();
        self.word.next.dbot_3 = self.dbot[3].val();
        self.word.next.attr0_0 = self.attr0[0].val();
        self.word.next.attr0_1 = self.attr0[1].val();
        self.word.next.attr0_2 = self.attr0[2].val();
        self.word.next.attr0_3 = self.attr0[3].val();
        self.word.next.xn0 = self.xn[0].val();
    }
}

/// A copy's geometry by name: [`GeometryWord`]'s fields as arrays, 2^s dy and dy as the
/// divisor (zero-extended when `G` is narrower), and the tracked pixel centre's x offset
/// from v0 (`off_x`), from the copy's start pixels and side.
#[derive(LogicBlock, Blank)]
pub struct GeometryView {
    pub word: Signal<In, GeometryWord>,
    /// e_maj is the left side (twice the area < 0).
    pub maj_left: Signal<In, Bit>,
    /// Each edge's start pixel, once its start division is back.
    pub start_x: [Signal<In, Bits<NB>>; 3],

    pub kdx: [Signal<Out, Bits<W>>; 3],
    pub kdy: [Signal<Out, Bits<G>>; 3],
    pub up: Signal<Out, Bit>,
    pub edx: [Signal<Out, Bits<W>>; 3],
    pub edy: [Signal<Out, Bits<G>>; 3],
    pub edy_d: [Signal<Out, Bits<DIV_D>>; 3],
    pub ed16: [Signal<Out, Bits<DIV_D>>; 3],
    pub cy: [Signal<Out, Bits<NB>>; 3],
    pub count: [Signal<Out, Bits<PIXEL>>; 3],
    /// The edge's start division is used (count > 0) and its step division (count > 1):
    /// computed with the count, so that the divisor's selection reads registers only.
    pub used: [Signal<Out, Bit>; 3],
    pub step: [Signal<Out, Bit>; 3],
    pub toff: [Signal<Out, Bits<NB>>; 3],
    pub xf: [Signal<Out, Bits<NB>>; 3],
    pub xi: [Signal<Out, Bits<NB>>; 3],
    pub off_x: [Signal<Out, Bits<NB>>; 3],
    pub off_y: [Signal<Out, Bits<NB>>; 3],
    pub dmaj: [Signal<Out, Bits<NB>>; 4],
    pub dbot: [Signal<Out, Bits<NB>>; 4],
    pub attr0: [Signal<Out, Bits<ATTR>>; 4],
    xn0: Signal<Local, Bits<NB>>,
    /// The pixel each edge's side tracks: x on the left side, x - 1 on the right.
    tracked: [Signal<Local, Bits<NB>>; 3],
    /// s, 2^(s-1).
    frac: Constant<Bits<8>>,
    half: Constant<Bits<NB>>,
}

impl Default for GeometryView {
    fn default() -> Self {
        GeometryView {
            frac: Constant::new((S as usize).to_bits()),
            half: Constant::new(((1usize << S) / 2).to_bits()),
            ..GeometryView::blank()
        }
    }
}

impl Logic for GeometryView {
    #[hdl_gen]
    fn update(&mut self) {
        self.kdx[0].next = self.word.val().kdx_0;
        self.kdx[1].next = self.word.val().kdx_1;
        self.kdx[2].next = self.word.val().kdx_2;
        self.kdy[0].next = self.word.val().kdy_0;
        self.kdy[1].next = self.word.val().kdy_1;
        self.kdy[2].next = self.word.val().kdy_2;
        self.up.next = self.word.val().up;
        self.edx[0].next = self.word.val().edx_0;
        self.edx[1].next = self.word.val().edx_1;
        self.edx[2].next = self.word.val().edx_2;
        self.edy[0].next = self.word.val().edy_0;
        self.edy[1].next = self.word.val().edy_1;
        self.edy[2].next = self.word.val().edy_2;
        self.cy[0].next = self.word.val().cy_0;
        self.cy[1].next = self.word.val().cy_1;
        self.cy[2].next = self.word.val().cy_2;
        self.count[0].next = self.word.val().count_0;
        self.count[1].next = self.word.val().count_1;
        self.count[2].next = self.word.val().count_2;
        self.used[0].next = self.word.val().used_0;
        self.used[1].next = self.word.val().used_1;
        self.used[2].next = self.word.val().used_2;
        self.step[0].next = self.word.val().step_0;
        self.step[1].next = self.word.val().step_1;
        self.step[2].next = self.word.val().step_2;
        self.toff[0].next = self.word.val().toff_0;
        self.toff[1].next = self.word.val().toff_1;
        self.toff[2].next = self.word.val().toff_2;
        self.xf[0].next = self.word.val().xf_0;
        self.xf[1].next = self.word.val().xf_1;
        self.xf[2].next = self.word.val().xf_2;
        self.xi[0].next = self.word.val().xi_0;
        self.xi[1].next = self.word.val().xi_1;
        self.xi[2].next = self.word.val().xi_2;
        self.off_y[0].next = self.word.val().off_y_0;
        self.off_y[1].next = self.word.val().off_y_1;
        self.off_y[2].next = self.word.val().off_y_2;
        self.dmaj[0].next = self.word.val().dmaj_0;
        self.dmaj[1].next = self.word.val().dmaj_1;
        self.dmaj[2].next = self.word.val().dmaj_2;
        self.dmaj[3].next = self.word.val().dmaj_3;
        self.dbot[0].next = self.word.val().dbot_0;
        self.dbot[1].next = self.word.val().dbot_1;
        self.dbot[2].next = self.word.val().dbot_2;
        self.dbot[3].next = self.word.val().dbot_3;
        self.attr0[0].next = self.word.val().attr0_0;
        self.attr0[1].next = self.word.val().attr0_1;
        self.attr0[2].next = self.word.val().attr0_2;
        self.attr0[3].next = self.word.val().attr0_3;
        self.xn0.next = self.word.val().xn0;
        // dy is positive; `bit_cast` (a loop's index cannot) widens it to the divisor.
        self.edy_d[0].next = bit_cast::<DIV_D, G>(self.edy[0].val());
        self.edy_d[1].next = bit_cast::<DIV_D, G>(self.edy[1].val());
        self.edy_d[2].next = bit_cast::<DIV_D, G>(self.edy[2].val());
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
            self.ed16[e].next = self.edy_d[e].val() << self.frac.val();
            self.off_x[e].next = (self.tracked[e].val() << self.frac.val()) + self.half.val() - self.xn0.val();
        }
    }
}
