//! The shading engine (SE) of paper 000 (Bang, Bae, Kyung, KAIST 1990: "A Graphics
//! Accelerator for Hidden Surface Removal and Color Shading"), Fig. 6: one engine over a
//! P-pixel region [XL_i, XR_i) = [P i, P (i + 1)) of a scanline.
//!
//! Blocks (Fig. 6), in this file unless named:
//! * control block: latches the span command (Xl, Xr; A, B of z, R, G, B), makes ML_i,
//!   MR_i for the EPT, and runs the schedule below;
//! * L and R multipliers ([`mul::SerialMul`], Fig. 7): f(XL_i), f(XR_i), rounded;
//! * interpolator ([`interp::Interp`], Figs. 8, 9): every pixel's round(f(x)), bit-serial;
//! * EPT (paper 002, [`crate::ept`], reused): the mask of pixels in [Xl, Xr];
//! * old-z block ([`turn::WordsToPlanes`]): loaded through the 4 read ports a port group a
//!   clock, read a bit plane (one bit of every pixel) a clock;
//! * z compare ([`zcmp::Zcmp`], Fig. 10) per pixel, and the WE storage (P flip-flops);
//! * new-z and RGB blocks ([`turn::PlanesToWords`]): written a bit plane a clock, read
//!   out through 4 interleaved ports (pixel 4j + k on port k, j = 0 .. P/4 - 1).
//!
//! The old-z, new-z and RGB blocks are small RAMs (W memories of P/4 x 4 bits each,
//! skewed so that a bit plane and a port group each meet every memory once; see
//! [`turn`]), where 000 and the first version here had P shift registers per block: LUT
//! RAM on an FPGA, a register file in an ASIC flow.
//!
//! Widths are type parameters: ZW and CW bits of z and colour words, ZA = ZW + F and
//! CA = CW + F bits of their A and B words (F fraction bits); 000: ZW = 24, CW = 16.
//! `Se64` .. `Se8` are the tops for P = 64 .. 8 (rust-hdl widths are compile-time).
//!
//! # Cycle schedule
//!
//! As `model::se` documents it (with its numbers for the default parameters); counters:
//! `h` (head: 0 idle, else clocks since the accept), `sc` (interpolator stream clock
//! s + 1, 0 idle), `dc` (output group j + 1, 0 idle).
//!
//! ```text
//! === CONTROL BLOCK =====  h = 0 (accept: valid & ready)   latch command, ML_i, MR_i, hit
//! === OLD-Z BLOCK =======  h = 1 .. P/4                     oz_rd: load 4 words per clock
//! === MULTIPLIERS =======  h = M_j ..                       A, B chain LSB first; first at M_j
//! === INTERPOLATOR ======  h = T_j - 1 starts stream j      sc = 1 at T_j = M_j + F
//!   sc = 1 (s = 0)              half; rounding carry loads bit F - 1
//!   sc > n + 1 (s > n)          sign extension
//!   sc = K + 2 .. K + n + 1     pixel bits into new-z (z: with Zcmp, first at K + 2) or R, G, B
//!   z:  sc = K + ZW + 2         WE := mask & hit & flag; stream ends
//!   B:  sc = K + CW + 1         last bit; stream ends; `dgo` set
//! === OUTPUT ============  dc = 1 .. P/4 (dc = 1 after dgo) wr: ports show pixels 4(dc-1)+k
//! ```
//!
//! `ready` = idle or h = HEAD (the multipliers' last clock), so spans run back to back
//! every HEAD clocks. Latency (accept to last write): `model::se::SeParams::latency`, 161
//! clocks for 000's widths (000: 170 per span); II = HEAD = 136.
//!
//! Model: `model::se::Se`, compared on every output every clock. Emitted:
//! `hdl-out/se.v` (P = 64, 000's widths, engine 0), `module se`.

pub mod interp;
pub mod mul;
pub mod turn;
pub mod zcmp;

use crate::emit::{ports, verilog, Emitted};
use crate::ept::{Ept16, Ept32, Ept64, Ept8};
use crate::parts::defaults;
use crate::sim::{Pins, Value};
use crate::Params;
use blank::Blank;
use interp::Interp;
use mul::{SerialMul, X_BITS};
use rust_hdl::prelude::*;
use turn::{PlanesToWords, WordsToPlanes};
use zcmp::Zcmp;

/// Bits of a span's ends Xl, Xr: a pixel column anywhere in the coordinate range.
pub const SPAN_X_BITS: usize = fx::Formats::for_n(fx::RTL_CLASS).derived().pixel_bits as usize;

/// Builds the constant `v` of any width.
fn k<const N: usize>(v: u64) -> Constant<Bits<N>> {
    Constant::new(v.into())
}

/// One SE top per region width: `$top` over `$p` pixels, K = `$k` levels, `$qb` bits of
/// port-group address (P/4 groups), `$dcb` bits of output counter (0 ..= P/4).
macro_rules! se_size {
    ($top:ident, $ept:ident, $p:tt, $k:tt, $qb:tt, $dcb:tt) => {
        #[doc = concat!("The shading engine of 000 (Fig. 6) over ", stringify!($p), " pixels: z words of ZW bits, \
            colour words of CW bits, A and B words of ZA = ZW + F and CA = CW + F bits. See the module doc.")]
        #[derive(LogicBlock, Blank)]
        pub struct $top<const ZW: usize, const CW: usize, const ZA: usize, const CA: usize> {
            pub clock: Signal<In, Clock>,
            /// A span command is offered; taken when `ready` is high too.
            pub valid: Signal<In, Bit>,
            /// Xl: first pixel of the span (inclusive), two's complement screen column.
            pub xl: Signal<In, Bits<SPAN_X_BITS>>,
            /// Xr: last pixel of the span (inclusive).
            pub xr: Signal<In, Bits<SPAN_X_BITS>>,
            /// A of z: slope in z-word LSBs per pixel, F fraction bits, two's complement.
            pub za: Signal<In, Bits<ZA>>,
            /// B of z: f(0) in z-word LSBs, F fraction bits.
            pub zb: Signal<In, Bits<ZA>>,
            /// A and B of R, G and B, likewise in colour-word LSBs.
            pub ra: Signal<In, Bits<CA>>,
            pub rb: Signal<In, Bits<CA>>,
            pub ga: Signal<In, Bits<CA>>,
            pub gb: Signal<In, Bits<CA>>,
            pub ba: Signal<In, Bits<CA>>,
            pub bb: Signal<In, Bits<CA>>,
            /// Old z of pixel XL_i + 4 oz_addr + k (k = 0..3) in the clock `oz_rd` asks.
            pub oz0: Signal<In, Bits<ZW>>,
            pub oz1: Signal<In, Bits<ZW>>,
            pub oz2: Signal<In, Bits<ZW>>,
            pub oz3: Signal<In, Bits<ZW>>,
            /// A command can be taken this clock.
            pub ready: Signal<Out, Bit>,
            /// Reading old z: port group `oz_addr` wanted on `oz0` .. `oz3` this clock.
            pub oz_rd: Signal<Out, Bit>,
            pub oz_addr: Signal<Out, Bits<$qb>>,
            /// Writing: pixels XL_i + 4 wr_addr + k on the ports below.
            pub wr: Signal<Out, Bit>,
            pub wr_addr: Signal<Out, Bits<$qb>>,
            /// New z of port k's pixel.
            pub nz0: Signal<Out, Bits<ZW>>,
            pub nz1: Signal<Out, Bits<ZW>>,
            pub nz2: Signal<Out, Bits<ZW>>,
            pub nz3: Signal<Out, Bits<ZW>>,
            /// R, G, B of port k's pixel.
            pub r0: Signal<Out, Bits<CW>>,
            pub r1: Signal<Out, Bits<CW>>,
            pub r2: Signal<Out, Bits<CW>>,
            pub r3: Signal<Out, Bits<CW>>,
            pub g0: Signal<Out, Bits<CW>>,
            pub g1: Signal<Out, Bits<CW>>,
            pub g2: Signal<Out, Bits<CW>>,
            pub g3: Signal<Out, Bits<CW>>,
            pub b0: Signal<Out, Bits<CW>>,
            pub b1: Signal<Out, Bits<CW>>,
            pub b2: Signal<Out, Bits<CW>>,
            pub b3: Signal<Out, Bits<CW>>,
            /// Write enable of port k's pixel (z and colour): mask AND z flag.
            pub we0: Signal<Out, Bit>,
            pub we1: Signal<Out, Bit>,
            pub we2: Signal<Out, Bit>,
            pub we3: Signal<Out, Bit>,

            // --- control block: counters, latched command ---
            /// Head counter: 0 idle, else clocks since the accept (1 ..= HEAD).
            h: DFF<Bits<9>>,
            /// Interpolator stream clock s + 1; 0 idle.
            sc: DFF<Bits<8>>,
            /// Attribute in the interpolator: 0 z, 1 R, 2 G, 3 B.
            att: DFF<Bits<2>>,
            /// Output group j + 1; 0 idle.
            dc: DFF<Bits<$dcb>>,
            /// B's last bit went into its block last clock: the output starts next clock
            /// (a bit plane takes a clock to be written, see `turn`).
            dgo: DFF<Bit>,
            /// ML_i, MR_i: the span's ends in the region, for the EPT; hit: it meets the region.
            ml: DFF<Bits<$k>>,
            mr: DFF<Bits<$k>>,
            hit: DFF<Bit>,
            /// The A and B shift chains: z, R, G, B one after another, LSB first out of `*_z`.
            ach_z: DFF<Bits<ZA>>,
            bch_z: DFF<Bits<ZA>>,
            ach_r: DFF<Bits<CA>>,
            bch_r: DFF<Bits<CA>>,
            ach_g: DFF<Bits<CA>>,
            bch_g: DFF<Bits<CA>>,
            ach_b: DFF<Bits<CA>>,
            bch_b: DFF<Bits<CA>>,

            // --- constants of the schedule (see the module doc) ---
            /// HEAD = ZA + 3 CA.
            k_head: Constant<Bits<9>>,
            /// M_1, M_2, M_3 (M_0 = 1): where each attribute's A, B start.
            k_m1: Constant<Bits<9>>,
            k_m2: Constant<Bits<9>>,
            k_m3: Constant<Bits<9>>,
            /// T_j - 1: the clock before each attribute's stream starts.
            k_t0: Constant<Bits<9>>,
            k_t1: Constant<Bits<9>>,
            k_t2: Constant<Bits<9>>,
            k_t3: Constant<Bits<9>>,
            /// P/4: the port groups.
            k_q: Constant<Bits<9>>,
            k_dq: Constant<Bits<$dcb>>,
            /// sc past the MSB of a z (ZW + 1) and colour (CW + 1) stream.
            k_zext: Constant<Bits<8>>,
            k_cext: Constant<Bits<8>>,
            /// sc of the first pixel bit (K + 2), of the last (K + ZW + 1, K + CW + 1) and
            /// of the WE latch (K + ZW + 2).
            k_win: Constant<Bits<8>>,
            k_zlast: Constant<Bits<8>>,
            k_clast: Constant<Bits<8>>,
            k_we: Constant<Bits<8>>,
            /// The region's first and last column, sign bit flipped (unsigned order).
            k_lo: Constant<Bits<SPAN_X_BITS>>,
            k_hi: Constant<Bits<SPAN_X_BITS>>,
            k_sign: Constant<Bits<SPAN_X_BITS>>,
            /// XL_i and XR_i for the multipliers.
            k_xl: Constant<Bits<X_BITS>>,
            k_xr: Constant<Bits<X_BITS>>,
            /// MSB of each A/B width, for shifting a bit in at the top.
            k_zamsb: Constant<Bits<ZA>>,
            k_camsb: Constant<Bits<CA>>,

            // --- blocks ---
            mul_l: SerialMul,
            mul_r: SerialMul,
            interp: Interp<$p, $k>,
            ept: $ept,
            zc: [Zcmp; $p],
            /// Old-z, new-z, R, G and B blocks: corner-turning memories.
            ozm: WordsToPlanes<ZW, $p>,
            nzm: PlanesToWords<ZW, $p>,
            rm: PlanesToWords<CW, $p>,
            gm: PlanesToWords<CW, $p>,
            bm: PlanesToWords<CW, $p>,
            /// WE storage: one flip-flop per pixel.
            wes: [DFF<Bit>; $p],

            // --- wires ---
            rdy: Signal<Local, Bit>,
            accept: Signal<Local, Bit>,
            xlb: Signal<Local, Bits<SPAN_X_BITS>>,
            xrb: Signal<Local, Bits<SPAN_X_BITS>>,
            ozload: Signal<Local, Bit>,
            mfirst: Signal<Local, Bit>,
            start: Signal<Local, Bit>,
            satt: Signal<Local, Bits<2>>,
            isz: Signal<Local, Bit>,
            half: Signal<Local, Bit>,
            ext: Signal<Local, Bit>,
            win: Signal<Local, Bit>,
            send: Signal<Local, Bit>,
            zwin: Signal<Local, Bit>,
            rwin: Signal<Local, Bit>,
            gwin: Signal<Local, Bit>,
            bwin: Signal<Local, Bit>,
            zfirst: Signal<Local, Bit>,
            /// Bit of the words in the interpolator's window: sc - K - 2.
            wbit: Signal<Local, Bits<8>>,
            welatch: Signal<Local, Bit>,
            dstart: Signal<Local, Bit>,
            dump: Signal<Local, Bit>,
            /// The port group on the output ports: dc - 1.
            og: Signal<Local, Bits<4>>,
            mask: Signal<Local, Bits<$p>>,
        }

        impl<const ZW: usize, const CW: usize, const ZA: usize, const CA: usize> $top<ZW, CW, ZA, CA> {
            /// Engine `index`: region [P index, P (index + 1)). Panics on widths or an
            /// index `model::se::SeParams::check` would reject.
            pub fn new(index: u64) -> Self {
                let (p, kk) = ($p as u64, $k as u64);
                let f = ZA - ZW;
                assert!(CA - CW == f && ZA > ZW, "ZA = ZW + F and CA = CW + F, one F");
                assert!(f as u64 >= kk + 2 && f as u64 >= p / 4, "F = {f} too small for P = {p}");
                assert!((index + 1) * p < 1 << X_BITS, "XR_i = {} does not fit {X_BITS} bits", (index + 1) * p);
                let (zw, cw, za, ca) = (ZW as u64, CW as u64, ZA as u64, CA as u64);
                let (m1, m2, m3) = (1 + za, 1 + za + ca, 1 + za + 2 * ca);
                let sign = 1u64 << (SPAN_X_BITS - 1);
                let xl = p * index;
                Self {
                    k_head: k(za + 3 * ca),
                    k_m1: k(m1),
                    k_m2: k(m2),
                    k_m3: k(m3),
                    k_t0: k(1 + f as u64 - 1),
                    k_t1: k(m1 + f as u64 - 1),
                    k_t2: k(m2 + f as u64 - 1),
                    k_t3: k(m3 + f as u64 - 1),
                    k_q: k(p / 4),
                    k_dq: k(p / 4),
                    k_zext: k(zw + 1),
                    k_cext: k(cw + 1),
                    k_win: k(kk + 2),
                    k_zlast: k(kk + zw + 1),
                    k_clast: k(kk + cw + 1),
                    k_we: k(kk + zw + 2),
                    k_lo: k(xl + sign),
                    k_hi: k(xl + p - 1 + sign),
                    k_sign: k(sign),
                    k_xl: k(xl),
                    k_xr: k(xl + p),
                    k_zamsb: k(1 << (za - 1)),
                    k_camsb: k(1 << (ca - 1)),
                    zc: defaults(),
                    wes: defaults(),
                    ..Self::blank()
                }
            }
        }

        impl<const ZW: usize, const CW: usize, const ZA: usize, const CA: usize> Logic for $top<ZW, CW, ZA, CA> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(
                    self, clock, h, sc, att, dc, dgo, ml, mr, hit, ach_z, bch_z, ach_r, bch_r, ach_g, bch_g, ach_b,
                    bch_b
                );
                clock!(self, clock, mul_l, mul_r, interp, ozm, nzm, rm, gm, bm);
                for x in 0..$p {
                    self.zc[x].clock.next = self.clock.val();
                    self.wes[x].clock.next = self.clock.val();
                    self.wes[x].d.next = self.wes[x].q.val();
                }

                // === CONTROL BLOCK: accept and latch (h = 0) ===
                self.rdy.next = (self.h.q.val() == 0) | (self.h.q.val() == self.k_head.val());
                self.accept.next = self.valid.val() & self.rdy.val();
                self.h.d.next = self.h.q.val() + 1;
                if self.rdy.val() {
                    self.h.d.next = 0.into();
                }
                if self.accept.val() {
                    self.h.d.next = 1.into();
                }
                // ML_i, MR_i by unsigned compares of sign-flipped columns; XL_i is a
                // multiple of P, so a column's offset in the region is its low K bits.
                self.xlb.next = self.xl.val() ^ self.k_sign.val();
                self.xrb.next = self.xr.val() ^ self.k_sign.val();
                // The A and B chains shift one bit a clock; the multipliers read bit 0.
                self.ach_z.d.next = self.ach_z.q.val() >> 1;
                self.bch_z.d.next = self.bch_z.q.val() >> 1;
                self.ach_r.d.next = self.ach_r.q.val() >> 1;
                self.bch_r.d.next = self.bch_r.q.val() >> 1;
                self.ach_g.d.next = self.ach_g.q.val() >> 1;
                self.bch_g.d.next = self.bch_g.q.val() >> 1;
                self.ach_b.d.next = self.ach_b.q.val() >> 1;
                self.bch_b.d.next = self.bch_b.q.val() >> 1;
                if self.ach_r.q.val().get_bit(0) {
                    self.ach_z.d.next = (self.ach_z.q.val() >> 1) | self.k_zamsb.val();
                }
                if self.bch_r.q.val().get_bit(0) {
                    self.bch_z.d.next = (self.bch_z.q.val() >> 1) | self.k_zamsb.val();
                }
                if self.ach_g.q.val().get_bit(0) {
                    self.ach_r.d.next = (self.ach_r.q.val() >> 1) | self.k_camsb.val();
                }
                if self.bch_g.q.val().get_bit(0) {
                    self.bch_r.d.next = (self.bch_r.q.val() >> 1) | self.k_camsb.val();
                }
                if self.ach_b.q.val().get_bit(0) {
                    self.ach_g.d.next = (self.ach_g.q.val() >> 1) | self.k_camsb.val();
                }
                if self.bch_b.q.val().get_bit(0) {
                    self.bch_g.d.next = (self.bch_g.q.val() >> 1) | self.k_camsb.val();
                }
                if self.accept.val() {
                    self.ml.d.next = 0.into();
                    if self.xlb.val() >= self.k_lo.val() {
                        self.ml.d.next = self.xl.val().get_bits::<$k>(0);
                    }
                    self.mr.d.next = bits::<$k>($p - 1);
                    if self.xrb.val() <= self.k_hi.val() {
                        self.mr.d.next = self.xr.val().get_bits::<$k>(0);
                    }
                    self.hit.d.next = (self.xlb.val() <= self.xrb.val())
                        & (self.xlb.val() <= self.k_hi.val())
                        & (self.xrb.val() >= self.k_lo.val());
                    self.ach_z.d.next = self.za.val();
                    self.bch_z.d.next = self.zb.val();
                    self.ach_r.d.next = self.ra.val();
                    self.bch_r.d.next = self.rb.val();
                    self.ach_g.d.next = self.ga.val();
                    self.bch_g.d.next = self.gb.val();
                    self.ach_b.d.next = self.ba.val();
                    self.bch_b.d.next = self.bb.val();
                }
                self.ready.next = self.rdy.val();

                // === OLD-Z BLOCK: load, h = 1 .. P/4 ===
                self.ozload.next = (self.h.q.val() != 0) & (self.h.q.val() <= self.k_q.val());
                self.oz_rd.next = self.ozload.val();
                self.oz_addr.next = self.h.q.val().get_bits::<$qb>(0) - 1;

                // === L/R MULTIPLIERS (Fig. 7) ===
                self.mfirst.next = (self.h.q.val() == 1)
                    | (self.h.q.val() == self.k_m1.val())
                    | (self.h.q.val() == self.k_m2.val())
                    | (self.h.q.val() == self.k_m3.val());
                self.mul_l.x.next = self.k_xl.val();
                self.mul_r.x.next = self.k_xr.val();
                self.mul_l.a.next = self.ach_z.q.val().get_bit(0);
                self.mul_r.a.next = self.ach_z.q.val().get_bit(0);
                self.mul_l.b.next = self.bch_z.q.val().get_bit(0);
                self.mul_r.b.next = self.bch_z.q.val().get_bit(0);
                self.mul_l.first.next = self.mfirst.val();
                self.mul_r.first.next = self.mfirst.val();

                // === INTERPOLATOR (Figs. 8, 9): stream counter ===
                self.start.next = false;
                self.satt.next = 0.into();
                if self.h.q.val() == self.k_t0.val() {
                    self.start.next = true;
                }
                if self.h.q.val() == self.k_t1.val() {
                    self.start.next = true;
                    self.satt.next = 1.into();
                }
                if self.h.q.val() == self.k_t2.val() {
                    self.start.next = true;
                    self.satt.next = 2.into();
                }
                if self.h.q.val() == self.k_t3.val() {
                    self.start.next = true;
                    self.satt.next = 3.into();
                }
                self.isz.next = self.att.q.val() == 0;
                self.half.next = self.sc.q.val() == 1;
                self.ext.next = self.sc.q.val() > self.k_cext.val();
                self.win.next = (self.sc.q.val() >= self.k_win.val()) & (self.sc.q.val() <= self.k_clast.val());
                self.send.next = self.sc.q.val() == self.k_clast.val();
                if self.isz.val() {
                    self.ext.next = self.sc.q.val() > self.k_zext.val();
                    self.win.next = (self.sc.q.val() >= self.k_win.val()) & (self.sc.q.val() <= self.k_zlast.val());
                    self.send.next = self.sc.q.val() == self.k_we.val();
                }
                self.sc.d.next = self.sc.q.val() + 1;
                if (self.sc.q.val() == 0) | self.send.val() {
                    self.sc.d.next = 0.into();
                }
                if self.start.val() {
                    self.sc.d.next = 1.into();
                    self.att.d.next = self.satt.val();
                }
                self.mul_l.rnd.next = self.half.val();
                self.mul_r.rnd.next = self.half.val();
                self.interp.e0.next = self.mul_l.e.val();
                self.interp.e1.next = self.mul_r.e.val();
                self.interp.half.next = self.half.val();
                self.interp.ext.next = self.ext.val();
                self.zwin.next = self.win.val() & self.isz.val();
                self.rwin.next = self.win.val() & (self.att.q.val() == 1);
                self.gwin.next = self.win.val() & (self.att.q.val() == 2);
                self.bwin.next = self.win.val() & (self.att.q.val() == 3);
                self.zfirst.next = self.sc.q.val() == self.k_win.val();
                self.welatch.next = self.isz.val() & (self.sc.q.val() == self.k_we.val());
                self.dstart.next = (self.att.q.val() == 3) & (self.sc.q.val() == self.k_clast.val());

                // === EPT MASKING, Z COMPARE (Fig. 10), NEW-Z AND RGB BLOCKS, WE STORAGE ===
                self.ept.xl.next = self.ml.q.val();
                self.ept.xr.next = self.mr.q.val();
                self.mask.next = 0.into();
                if self.hit.q.val() {
                    self.mask.next = self.ept.px.val();
                }
                // Bit plane wbit of the words: new z, R, G, B written, old z read.
                self.wbit.next = self.sc.q.val() - self.k_win.val();
                // The old-z block shows a plane from the next edge on: it is given the next's.
                self.ozm.plane.next = self.wbit.val() + 1;
                self.nzm.plane.next = self.wbit.val();
                self.rm.plane.next = self.wbit.val();
                self.gm.plane.next = self.wbit.val();
                self.bm.plane.next = self.wbit.val();
                self.nzm.px.next = self.interp.px.val();
                self.rm.px.next = self.interp.px.val();
                self.gm.px.next = self.interp.px.val();
                self.bm.px.next = self.interp.px.val();
                self.nzm.we.next = self.zwin.val();
                self.rm.we.next = self.rwin.val();
                self.gm.we.next = self.gwin.val();
                self.bm.we.next = self.bwin.val();
                for x in 0..$p {
                    self.zc[x].first.next = self.zfirst.val();
                    self.zc[x].nz.next = self.interp.px.val().get_bit(x);
                    self.zc[x].oz.next = self.ozm.px.val().get_bit(x);
                    if self.welatch.val() {
                        self.wes[x].d.next = self.mask.val().get_bit(x) & self.zc[x].closer.val();
                    }
                }

                // === OLD-Z BLOCK: load port group h - 1 ===
                self.ozm.we.next = self.ozload.val();
                self.ozm.group.next = self.h.q.val().get_bits::<4>(0) - 1;
                self.ozm.d0.next = self.oz0.val();
                self.ozm.d1.next = self.oz1.val();
                self.ozm.d2.next = self.oz2.val();
                self.ozm.d3.next = self.oz3.val();

                // === OUTPUT: 4 interleaved ports show port group dc - 1, zero when idle ===
                self.dump.next = self.dc.q.val() != 0;
                self.dc.d.next = self.dc.q.val() + 1;
                if (self.dc.q.val() == 0) | (self.dc.q.val() == self.k_dq.val()) {
                    self.dc.d.next = 0.into();
                }
                self.dgo.d.next = self.dstart.val();
                if self.dgo.q.val() {
                    self.dc.d.next = 1.into();
                }
                self.og.next = bit_cast::<4, $dcb>(self.dc.q.val()) - 1;
                self.nzm.group.next = self.og.val();
                self.rm.group.next = self.og.val();
                self.gm.group.next = self.og.val();
                self.bm.group.next = self.og.val();
                if self.dump.val() {
                    for x in 0..($p - 4) {
                        self.wes[x].d.next = self.wes[x + 4].q.val();
                    }
                    for x in ($p - 4)..$p {
                        self.wes[x].d.next = false;
                    }
                }
                self.wr.next = self.dump.val();
                self.wr_addr.next = self.dc.q.val().get_bits::<$qb>(0) - 1;
                self.nz0.next = 0.into();
                self.nz1.next = 0.into();
                self.nz2.next = 0.into();
                self.nz3.next = 0.into();
                self.r0.next = 0.into();
                self.r1.next = 0.into();
                self.r2.next = 0.into();
                self.r3.next = 0.into();
                self.g0.next = 0.into();
                self.g1.next = 0.into();
                self.g2.next = 0.into();
                self.g3.next = 0.into();
                self.b0.next = 0.into();
                self.b1.next = 0.into();
                self.b2.next = 0.into();
                self.b3.next = 0.into();
                self.we0.next = false;
                self.we1.next = false;
                self.we2.next = false;
                self.we3.next = false;
                if self.dump.val() {
                    self.nz0.next = self.nzm.w0.val();
                    self.nz1.next = self.nzm.w1.val();
                    self.nz2.next = self.nzm.w2.val();
                    self.nz3.next = self.nzm.w3.val();
                    self.r0.next = self.rm.w0.val();
                    self.r1.next = self.rm.w1.val();
                    self.r2.next = self.rm.w2.val();
                    self.r3.next = self.rm.w3.val();
                    self.g0.next = self.gm.w0.val();
                    self.g1.next = self.gm.w1.val();
                    self.g2.next = self.gm.w2.val();
                    self.g3.next = self.gm.w3.val();
                    self.b0.next = self.bm.w0.val();
                    self.b1.next = self.bm.w1.val();
                    self.b2.next = self.bm.w2.val();
                    self.b3.next = self.bm.w3.val();
                    self.we0.next = self.wes[0].q.val();
                    self.we1.next = self.wes[1].q.val();
                    self.we2.next = self.wes[2].q.val();
                    self.we3.next = self.wes[3].q.val();
                }
            }
        }

        impl<const ZW: usize, const CW: usize, const ZA: usize, const CA: usize> Pins for $top<ZW, CW, ZA, CA> {
            fn set(&mut self, pin: &str, v: &Value) {
                match pin {
                    "valid" => self.valid.next = v.bit(0),
                    "xl" => self.xl.next = v.to_bits(),
                    "xr" => self.xr.next = v.to_bits(),
                    "za" => self.za.next = v.to_bits(),
                    "zb" => self.zb.next = v.to_bits(),
                    "ra" => self.ra.next = v.to_bits(),
                    "rb" => self.rb.next = v.to_bits(),
                    "ga" => self.ga.next = v.to_bits(),
                    "gb" => self.gb.next = v.to_bits(),
                    "ba" => self.ba.next = v.to_bits(),
                    "bb" => self.bb.next = v.to_bits(),
                    "oz0" => self.oz0.next = v.to_bits(),
                    "oz1" => self.oz1.next = v.to_bits(),
                    "oz2" => self.oz2.next = v.to_bits(),
                    "oz3" => self.oz3.next = v.to_bits(),
                    _ => panic!("se has no input pin {pin}"),
                }
            }
            fn get(&self, pin: &str) -> Value {
                match pin {
                    "ready" => Value::from_bools(&[self.ready.val()]),
                    "oz_rd" => Value::from_bools(&[self.oz_rd.val()]),
                    "oz_addr" => Value::from_bits(self.oz_addr.val()),
                    "wr" => Value::from_bools(&[self.wr.val()]),
                    "wr_addr" => Value::from_bits(self.wr_addr.val()),
                    "nz0" => Value::from_bits(self.nz0.val()),
                    "nz1" => Value::from_bits(self.nz1.val()),
                    "nz2" => Value::from_bits(self.nz2.val()),
                    "nz3" => Value::from_bits(self.nz3.val()),
                    "r0" => Value::from_bits(self.r0.val()),
                    "r1" => Value::from_bits(self.r1.val()),
                    "r2" => Value::from_bits(self.r2.val()),
                    "r3" => Value::from_bits(self.r3.val()),
                    "g0" => Value::from_bits(self.g0.val()),
                    "g1" => Value::from_bits(self.g1.val()),
                    "g2" => Value::from_bits(self.g2.val()),
                    "g3" => Value::from_bits(self.g3.val()),
                    "b0" => Value::from_bits(self.b0.val()),
                    "b1" => Value::from_bits(self.b1.val()),
                    "b2" => Value::from_bits(self.b2.val()),
                    "b3" => Value::from_bits(self.b3.val()),
                    "we0" => Value::from_bools(&[self.we0.val()]),
                    "we1" => Value::from_bools(&[self.we1.val()]),
                    "we2" => Value::from_bools(&[self.we2.val()]),
                    "we3" => Value::from_bools(&[self.we3.val()]),
                    _ => panic!("se has no output pin {pin}"),
                }
            }
            fn clock(&mut self) -> Option<&mut Signal<In, Clock>> {
                Some(&mut self.clock)
            }
        }
    };
}

se_size!(Se64, Ept64, 64, 6, 4, 5);
se_size!(Se32, Ept32, 32, 5, 3, 4);
se_size!(Se16, Ept16, 16, 4, 2, 3);
se_size!(Se8, Ept8, 8, 3, 1, 2);

/// 000's engine: 64 pixels, 24-bit z, 16-bit colour, 16 fraction bits in A and B.
pub type SePaper = Se64<24, 16, 40, 32>;
/// The engine the span backend draws scenes with (`model::se::array::engine_params`):
/// z words of 29 bits, colour words of 21, so that no line overflows at the region's ends.
pub type SeWide = Se64<29, 21, 45, 37>;

/// Emits `u` (built, not yet connected) as unit `se`.
fn emit_unit<U: Block>(mut u: U, params: Params) -> Emitted {
    u.connect_all();
    Emitted { unit: "se", params, formats: None, ports: ports(&u), verilog: verilog("se", &u), dir: None }
}

/// `UNITS` entry: emits the SE for `params` P, ZW, CW, F, I (see `rtl::UNITS`).
pub fn emit_se(params: &Params) -> Result<Emitted, String> {
    let (p, zw, cw, f, i) = (params["P"], params["ZW"], params["CW"], params["F"], params["I"]);
    let supported = "supported: P = 8, 16, 32, 64 with (ZW, CW, F) = (24, 16, 16); P = 64 with (29, 21, 16)";
    if (i + 1) * p >= 1 << X_BITS {
        return Err(format!("se: I = {i}: XR_i = P (I + 1) must be below {}, the multipliers' X", 1 << X_BITS));
    }
    let params = params.clone();
    Ok(match (p, zw, cw, f) {
        (64, 24, 16, 16) => emit_unit(SePaper::new(i), params),
        (32, 24, 16, 16) => emit_unit(Se32::<24, 16, 40, 32>::new(i), params),
        (16, 24, 16, 16) => emit_unit(Se16::<24, 16, 40, 32>::new(i), params),
        (8, 24, 16, 16) => emit_unit(Se8::<24, 16, 40, 32>::new(i), params),
        (64, 29, 21, 16) => emit_unit(SeWide::new(i), params),
        _ => return Err(format!("se: P = {p}, ZW = {zw}, CW = {cw}, F = {f} is not built ({supported})")),
    })
}
