//! The SE back end's engines (paper 000, Fig. 5): each a [`Bank`], one shading engine
//! (`rtl::se::SeWide`, P = 64 pixels, the widths `model::se::array::engine_params` gives
//! the default formats) on the span bus every engine shares, its four ports placed in the
//! array's memory words (`links::SeMemory`): engine i's port k is lane 4 i + k, the pixel
//! 64 i + 4 j + k of the row in group j. Old z is read zero extended from the depth
//! buffer's `DEPTH` bits; a new z is written as its low `DEPTH` bits (the engines write only
//! 0 <= z < old z <= z_max) and a colour word clamped to 0..255 ([`Clamp8`]), as
//! `model::se::array` does.

use super::widths::{CHANNEL, DEPTH, PIXEL, RGB, SE_CA, SE_ZA};
use crate::parts::Negative;
use crate::se::{SeWide, SPAN_X_BITS};
use blank::Blank;
use rust_hdl::prelude::*;

/// `SeWide`'s z and colour words and their A and B words.
const EZ: usize = 29;
const EC: usize = 21;
const EZA: usize = EZ + 16;
const ECA: usize = EC + 16;

/// Whether this build's SE back end is `SeWide`'s: the formats give its word widths and
/// its span ends.
pub const FITS: bool = SE_ZA == EZA && SE_CA == ECA && PIXEL == SPAN_X_BITS;

/// `y` = a `W`-bit two's complement colour word clamped to 0..255.
#[derive(LogicBlock)]
pub struct Clamp8<const W: usize> {
    pub x: Signal<In, Bits<W>>,
    pub y: Signal<Out, Bits<CHANNEL>>,
    sign: Negative<W>,
    max: Constant<Bits<W>>,
}

impl<const W: usize> Default for Clamp8<W> {
    fn default() -> Self {
        Clamp8 {
            x: Default::default(),
            y: Default::default(),
            sign: Default::default(),
            max: Constant::new(255.into()),
        }
    }
}

impl<const W: usize> Logic for Clamp8<W> {
    #[hdl_gen]
    fn update(&mut self) {
        self.sign.x.next = self.x.val();
        self.y.next = bit_cast::<CHANNEL, W>(self.x.val());
        if self.x.val() > self.max.val() {
            self.y.next = 255.into();
        }
        if self.sign.neg.val() {
            self.y.next = 0.into();
        }
    }
}

/// One engine port, lane `l` of the array's words (`ZW`, `CW` and `EL` bits of depths,
/// colours and enables): its old z out of the read word, its new z, colour and write
/// enable placed in the write word.
#[derive(LogicBlock, Blank)]
pub struct PortOut<const ZW: usize, const CW: usize, const EL: usize> {
    pub rd_z: Signal<In, Bits<ZW>>,
    pub oz: Signal<Out, Bits<EZ>>,
    pub nz: Signal<In, Bits<EZ>>,
    pub r: Signal<In, Bits<EC>>,
    pub g: Signal<In, Bits<EC>>,
    pub b: Signal<In, Bits<EC>>,
    pub we: Signal<In, Bit>,
    pub wr_z: Signal<Out, Bits<ZW>>,
    pub wr_rgb: Signal<Out, Bits<CW>>,
    pub wr_en: Signal<Out, Bits<EL>>,
    cr: Clamp8<EC>,
    cg: Clamp8<EC>,
    cb: Clamp8<EC>,
    /// The lane's first depth and colour bits, its enable bit, and G's and R's places.
    at_z: Constant<Bits<16>>,
    at_rgb: Constant<Bits<16>>,
    lane: Constant<Bits<EL>>,
    ch1: Constant<Bits<8>>,
    ch2: Constant<Bits<8>>,
    rgb: Signal<Local, Bits<RGB>>,
}

impl<const ZW: usize, const CW: usize, const EL: usize> PortOut<ZW, CW, EL> {
    fn new(l: usize) -> Self {
        assert!(l < EL && ZW == EL * DEPTH && CW == EL * RGB, "PortOut<{ZW}, {CW}, {EL}> lane {l}");
        PortOut {
            at_z: Constant::new((l * DEPTH).to_bits()),
            at_rgb: Constant::new((l * RGB).to_bits()),
            lane: Constant::new(Bits::<EL>::from(1u64) << (l as u64)),
            ch1: Constant::new(CHANNEL.to_bits()),
            ch2: Constant::new((2 * CHANNEL).to_bits()),
            ..PortOut::blank()
        }
    }
}

impl<const ZW: usize, const CW: usize, const EL: usize> Logic for PortOut<ZW, CW, EL> {
    #[hdl_gen]
    fn update(&mut self) {
        self.oz.next = bit_cast::<EZ, DEPTH>(bit_cast::<DEPTH, ZW>(self.rd_z.val() >> self.at_z.val()));
        self.cr.x.next = self.r.val();
        self.cg.x.next = self.g.val();
        self.cb.x.next = self.b.val();
        self.rgb.next = (bit_cast::<RGB, CHANNEL>(self.cr.y.val()) << self.ch2.val())
            | (bit_cast::<RGB, CHANNEL>(self.cg.y.val()) << self.ch1.val())
            | bit_cast::<RGB, CHANNEL>(self.cb.y.val());
        self.wr_z.next = bit_cast::<ZW, DEPTH>(bit_cast::<DEPTH, EZ>(self.nz.val())) << self.at_z.val();
        self.wr_rgb.next = bit_cast::<CW, RGB>(self.rgb.val()) << self.at_rgb.val();
        self.wr_en.next = 0.into();
        if self.we.val() {
            self.wr_en.next = self.lane.val();
        }
    }
}

/// One engine of the array and its four ports (`ZW`, `CW`, `EL`: the array's words): the
/// span bus in (`se_cmd`'s command), the engine's schedule out (`ready`, `oz_rd`,
/// `oz_addr`, `wr`, `wr_addr`: the same in every engine), its lanes of the read word in
/// and of the write word out (zero in the other lanes).
#[derive(LogicBlock, Blank)]
pub struct Bank<const ZW: usize, const CW: usize, const EL: usize> {
    pub clock: Signal<In, Clock>,
    pub valid: Signal<In, Bit>,
    pub xl: Signal<In, Bits<PIXEL>>,
    pub xr: Signal<In, Bits<PIXEL>>,
    pub za: Signal<In, Bits<SE_ZA>>,
    pub zb: Signal<In, Bits<SE_ZA>>,
    pub ra: Signal<In, Bits<SE_CA>>,
    pub rb: Signal<In, Bits<SE_CA>>,
    pub ga: Signal<In, Bits<SE_CA>>,
    pub gb: Signal<In, Bits<SE_CA>>,
    pub ba: Signal<In, Bits<SE_CA>>,
    pub bb: Signal<In, Bits<SE_CA>>,
    pub rd_z: Signal<In, Bits<ZW>>,
    pub ready: Signal<Out, Bit>,
    pub oz_rd: Signal<Out, Bit>,
    pub oz_addr: Signal<Out, Bits<4>>,
    pub wr: Signal<Out, Bit>,
    pub wr_addr: Signal<Out, Bits<4>>,
    pub wr_z: Signal<Out, Bits<ZW>>,
    pub wr_rgb: Signal<Out, Bits<CW>>,
    pub wr_en: Signal<Out, Bits<EL>>,
    #[given]
    se: SeWide,
    #[given]
    p0: PortOut<ZW, CW, EL>,
    #[given]
    p1: PortOut<ZW, CW, EL>,
    #[given]
    p2: PortOut<ZW, CW, EL>,
    #[given]
    p3: PortOut<ZW, CW, EL>,
}

impl<const ZW: usize, const CW: usize, const EL: usize> Bank<ZW, CW, EL> {
    /// Engine `i`: the region [64 i, 64 (i + 1)), lanes 4 i to 4 i + 3.
    pub fn new(i: usize) -> Self {
        let given = BankGiven {
            se: SeWide::new(i as u64),
            p0: PortOut::new(4 * i),
            p1: PortOut::new(4 * i + 1),
            p2: PortOut::new(4 * i + 2),
            p3: PortOut::new(4 * i + 3),
        };
        Bank { ..Bank::blank(given) }
    }
}

impl<const ZW: usize, const CW: usize, const EL: usize> Logic for Bank<ZW, CW, EL> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, se);
        self.se.valid.next = self.valid.val();
        self.se.xl.next = bit_cast::<SPAN_X_BITS, PIXEL>(self.xl.val());
        self.se.xr.next = bit_cast::<SPAN_X_BITS, PIXEL>(self.xr.val());
        self.se.za.next = bit_cast::<EZA, SE_ZA>(self.za.val());
        self.se.zb.next = bit_cast::<EZA, SE_ZA>(self.zb.val());
        self.se.ra.next = bit_cast::<ECA, SE_CA>(self.ra.val());
        self.se.rb.next = bit_cast::<ECA, SE_CA>(self.rb.val());
        self.se.ga.next = bit_cast::<ECA, SE_CA>(self.ga.val());
        self.se.gb.next = bit_cast::<ECA, SE_CA>(self.gb.val());
        self.se.ba.next = bit_cast::<ECA, SE_CA>(self.ba.val());
        self.se.bb.next = bit_cast::<ECA, SE_CA>(self.bb.val());
        self.p0.rd_z.next = self.rd_z.val();
        self.p1.rd_z.next = self.rd_z.val();
        self.p2.rd_z.next = self.rd_z.val();
        self.p3.rd_z.next = self.rd_z.val();
        self.se.oz0.next = self.p0.oz.val();
        self.se.oz1.next = self.p1.oz.val();
        self.se.oz2.next = self.p2.oz.val();
        self.se.oz3.next = self.p3.oz.val();
        self.p0.nz.next = self.se.nz0.val();
        self.p1.nz.next = self.se.nz1.val();
        self.p2.nz.next = self.se.nz2.val();
        self.p3.nz.next = self.se.nz3.val();
        self.p0.r.next = self.se.r0.val();
        self.p1.r.next = self.se.r1.val();
        self.p2.r.next = self.se.r2.val();
        self.p3.r.next = self.se.r3.val();
        self.p0.g.next = self.se.g0.val();
        self.p1.g.next = self.se.g1.val();
        self.p2.g.next = self.se.g2.val();
        self.p3.g.next = self.se.g3.val();
        self.p0.b.next = self.se.b0.val();
        self.p1.b.next = self.se.b1.val();
        self.p2.b.next = self.se.b2.val();
        self.p3.b.next = self.se.b3.val();
        self.p0.we.next = self.se.we0.val();
        self.p1.we.next = self.se.we1.val();
        self.p2.we.next = self.se.we2.val();
        self.p3.we.next = self.se.we3.val();
        self.ready.next = self.se.ready.val();
        self.oz_rd.next = self.se.oz_rd.val();
        self.oz_addr.next = self.se.oz_addr.val();
        self.wr.next = self.se.wr.val();
        self.wr_addr.next = self.se.wr_addr.val();
        self.wr_z.next = self.p0.wr_z.val() | self.p1.wr_z.val() | self.p2.wr_z.val() | self.p3.wr_z.val();
        self.wr_rgb.next = self.p0.wr_rgb.val() | self.p1.wr_rgb.val() | self.p2.wr_rgb.val() | self.p3.wr_rgb.val();
        self.wr_en.next = self.p0.wr_en.val() | self.p1.wr_en.val() | self.p2.wr_en.val() | self.p3.wr_en.val();
    }
}
