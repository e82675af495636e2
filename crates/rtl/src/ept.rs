//! The edge painting tree (EPT): paper 002 (Choi, Kim, Eo, Kyung, KAIST), "Design and
//! Simulation of Edge Painting Machine for Image Rasterization", section 3, Figs. 2–5.
//!
//! A scanline command (XL, XR) enters MSB first, one bit per tree level; each processing
//! element (PE, Fig. 3) steers the bounds to its children; every leaf PE drives 4 pixels.
//! Pixel i is painted iff XL <= i <= XR (both ends inclusive; XL > XR paints nothing).
//! Purely combinational: latency 0, one command per clock.
//!
//! ```text
//!              P = 16, B = 4 bits                     level  (LI, RI)    XL, XR bit
//!                   [PE]                                0    bit 3       bit 2
//!             /             \
//!          [PE]             [PE]                        1    routed      bit 1
//!         /    \           /    \
//!      [PE]    [PE]     [PE]    [PE]   leaves           2    routed      bit 0
//!      0..3    4..7     8..11   12..15  pixels
//! ```
//!
//! P pixels need log2(P) - 1 levels and P/4 leaves (section 3). rust-hdl widths are const
//! generics and a subtree of N pixels holds two subtrees of N/2, which stable Rust cannot
//! write generically, so `ept_size!` spells out one subtree type per N (`Tree4` … `Tree1024`)
//! and one top per P (`Ept8` … `Ept1024`). `Ept<P>` names the top for P.
//!
//! Model: `model::ept`. Emitted: `hdl-out/ept.v` (P = 64), `module ept`.

use crate::emit::{emit, Emitted};
use crate::sim::{Pins, Value};
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;

/// The processing element of paper 002, Fig. 3.
///
/// (LI, RI) are the bounds' bits its parent routed to it; XL, XR are this level's bits of
/// the command, after the control signals: LCS forces XL to 0 (the span began left of this
/// subtree) and RCS forces XR to 1 (the span goes on right of it). By (LI, RI):
///
/// | (LI, RI) | left child (LLC, RLC) | right child (LRC, RRC) | LRCSO |
/// |---|---|---|---|
/// | (0, 0) | (XL, XR): paint only left | (1, 0): inactive | 0 |
/// | (1, 1) | (1, 0): inactive | (XL, XR): paint only right | 0 |
/// | (0, 1) | (XL, 1) | (0, XR) | 1 |
/// | (1, 0) | (1, 0) | (1, 0): the whole subtree is inactive | 0 |
///
/// In case (0, 1) LRCSO drives the left child's RCS and the right child's LCS, so below
/// this PE the left child's XR bits read all ones and the right child's XL bits all zeros
/// (the left child paints to its end, the right child from its start). LCSO and RCSO pass
/// LCS and RCS on to the outer children.
///
/// Reading of the text: for (0, 1) the paper prints "LRC = XL, RRC = 1, LLC = 0,
/// RLC = XR", which would paint the left child from its start to XR; that contradicts its
/// own LRCSO sentence ("in the left child XR is set to 1, in the right child XL to 0") and
/// the Fig. 5 result. The table above is the reading that gives Fig. 5; the model test
/// `ept_paper_002_text_case01_literal_breaks_fig5` shows the literal text does not.
#[derive(LogicBlock, Default)]
pub struct Pe {
    /// LI: left-bound bit routed here by the parent PE (at the root: the MSB of XL).
    pub li: Signal<In, Bit>,
    /// RI: right-bound bit routed here by the parent PE (at the root: the MSB of XR).
    pub ri: Signal<In, Bit>,
    /// XL: this level's bit of XL, broadcast to every PE of the level.
    pub xl: Signal<In, Bit>,
    /// XR: this level's bit of XR, broadcast to every PE of the level.
    pub xr: Signal<In, Bit>,
    /// LCS: left control signal; high forces XL to 0.
    pub lcs: Signal<In, Bit>,
    /// RCS: right control signal; high forces XR to 1.
    pub rcs: Signal<In, Bit>,
    /// LLC: left signal of the left child.
    pub llc: Signal<Out, Bit>,
    /// RLC: right signal of the left child.
    pub rlc: Signal<Out, Bit>,
    /// LRC: left signal of the right child.
    pub lrc: Signal<Out, Bit>,
    /// RRC: right signal of the right child.
    pub rrc: Signal<Out, Bit>,
    /// LCSO: to the left child's LCS.
    pub lcso: Signal<Out, Bit>,
    /// LRCSO: to the left child's RCS and the right child's LCS; high in case (0, 1).
    pub lrcso: Signal<Out, Bit>,
    /// RCSO: to the right child's RCS.
    pub rcso: Signal<Out, Bit>,
    /// XL after LCS.
    xl_f: Signal<Local, Bit>,
    /// XR after RCS.
    xr_f: Signal<Local, Bit>,
}

impl Logic for Pe {
    #[hdl_gen]
    fn update(&mut self) {
        self.xl_f.next = self.xl.val() & !self.lcs.val();
        self.xr_f.next = self.xr.val() | self.rcs.val();
        self.lcso.next = self.lcs.val();
        self.rcso.next = self.rcs.val();
        // (1, 0), and the default of every other case: both children inactive.
        self.llc.next = true;
        self.rlc.next = false;
        self.lrc.next = true;
        self.rrc.next = false;
        self.lrcso.next = false;
        if !self.li.val() & !self.ri.val() {
            // (0, 0): the span lies in the left child.
            self.llc.next = self.xl_f.val();
            self.rlc.next = self.xr_f.val();
        }
        if self.li.val() & self.ri.val() {
            // (1, 1): the span lies in the right child.
            self.lrc.next = self.xl_f.val();
            self.rrc.next = self.xr_f.val();
        }
        if !self.li.val() & self.ri.val() {
            // (0, 1): left child from XL to its end, right child from its start to XR.
            self.llc.next = self.xl_f.val();
            self.rlc.next = true;
            self.lrc.next = false;
            self.rrc.next = self.xr_f.val();
            self.lrcso.next = true;
        }
    }
}

/// A leaf of the tree (paper 002, section 3: "each leaf processor has in effect 4 outputs,
/// one per pixel"): one PE over pixels 0..3 of its subtree, bit 0 of XL, XR.
///
/// The PE's child signals are one-bit bounds of the pixel pairs (0, 1) and (2, 3): a pair
/// (L, R) paints its left pixel iff L = 0 (XL <= it) and its right pixel iff R = 1
/// (XR >= it); the inactive (1, 0) paints neither. So px = (RRC, !LRC, RLC, !LLC), MSB first.
/// The leaf PE's LCSO, LRCSO and RCSO have no children to drive.
#[derive(LogicBlock, Default)]
pub struct Tree4 {
    /// LI for this leaf's PE, routed by its parent.
    pub li: Signal<In, Bit>,
    /// RI for this leaf's PE, routed by its parent.
    pub ri: Signal<In, Bit>,
    /// LCS from the parent.
    pub lcs: Signal<In, Bit>,
    /// RCS from the parent.
    pub rcs: Signal<In, Bit>,
    /// Bit 0 of XL.
    pub xl: Signal<In, Bits<1>>,
    /// Bit 0 of XR.
    pub xr: Signal<In, Bits<1>>,
    /// Paint mask of pixels 0..3 of this leaf (bit i = pixel i).
    pub px: Signal<Out, Bits<4>>,
    pe: Pe,
    /// Pixel 0 painted: !LLC.
    p0: Signal<Local, Bit>,
    /// Pixel 2 painted: !LRC.
    p2: Signal<Local, Bit>,
}

impl Logic for Tree4 {
    #[hdl_gen]
    fn update(&mut self) {
        self.pe.li.next = self.li.val();
        self.pe.ri.next = self.ri.val();
        self.pe.lcs.next = self.lcs.val();
        self.pe.rcs.next = self.rcs.val();
        self.pe.xl.next = self.xl.val().into();
        self.pe.xr.next = self.xr.val().into();
        self.p0.next = !self.pe.llc.val();
        self.p2.next = !self.pe.lrc.val();
        self.px.next = bits::<4>(0)
            .replace_bit(0, self.p0.val())
            .replace_bit(1, self.pe.rlc.val())
            .replace_bit(2, self.p2.val())
            .replace_bit(3, self.pe.rrc.val());
    }
}

/// One subtree type over `$n` pixels and one top over `$n` pixels, whose root it is.
///
/// `$tree` holds a PE and two `$child` subtrees of `$half` pixels; it takes the `$k` low
/// bits of XL and XR (its PE uses bit `$kc` = `$k - 1`, the children bits `$kc - 1 ..= 0`).
/// `$top` is the unit for P = `$n`, B = `$b` = `$k + 1` bits: the MSBs (bit `$k`) are the
/// root PE's (LI, RI). Literals, not expressions: rust-hdl copies index expressions into the
/// Verilog as written, and a const generic's name would be undefined there.
macro_rules! ept_size {
    ($top:ident, $tree:ident, $child:ident, $n:tt, $half:tt, $b:tt, $k:tt, $kc:tt) => {
        #[doc = concat!("A subtree of the EPT over ", stringify!($n), " pixels (paper 002, Fig. 4): \
            one PE (Fig. 3) over two ", stringify!($half), "-pixel subtrees.")]
        #[derive(LogicBlock, Blank)]
        pub struct $tree {
            /// LI for this subtree's PE, routed by its parent.
            pub li: Signal<In, Bit>,
            /// RI for this subtree's PE, routed by its parent.
            pub ri: Signal<In, Bit>,
            /// LCS from the parent.
            pub lcs: Signal<In, Bit>,
            /// RCS from the parent.
            pub rcs: Signal<In, Bit>,
            /// The low bits of XL, MSB for this subtree's PE, the rest for the children.
            pub xl: Signal<In, Bits<$k>>,
            /// The low bits of XR.
            pub xr: Signal<In, Bits<$k>>,
            /// Paint mask of this subtree's pixels (bit i = pixel i).
            pub px: Signal<Out, Bits<$n>>,
            pe: Pe,
            /// The left subtree, alone in a `Vec` so that it lives on the heap: inline, the
            /// tree for P = 1024 is 0.5 MB and overflows a 2 MB thread stack as it is built.
            left: Vec<$child>,
            /// The right subtree, likewise.
            right: Vec<$child>,
        }

        impl Default for $tree {
            fn default() -> Self {
                Self { left: vec![$child::default()], right: vec![$child::default()], ..Self::blank() }
            }
        }

        impl Logic for $tree {
            #[hdl_gen]
            fn update(&mut self) {
                self.pe.li.next = self.li.val();
                self.pe.ri.next = self.ri.val();
                self.pe.lcs.next = self.lcs.val();
                self.pe.rcs.next = self.rcs.val();
                self.pe.xl.next = self.xl.val().get_bit($kc);
                self.pe.xr.next = self.xr.val().get_bit($kc);
                self.left[0].li.next = self.pe.llc.val();
                self.left[0].ri.next = self.pe.rlc.val();
                self.left[0].lcs.next = self.pe.lcso.val();
                self.left[0].rcs.next = self.pe.lrcso.val();
                self.left[0].xl.next = self.xl.val().get_bits::<$kc>(0);
                self.left[0].xr.next = self.xr.val().get_bits::<$kc>(0);
                self.right[0].li.next = self.pe.lrc.val();
                self.right[0].ri.next = self.pe.rrc.val();
                self.right[0].lcs.next = self.pe.lrcso.val();
                self.right[0].rcs.next = self.pe.rcso.val();
                self.right[0].xl.next = self.xl.val().get_bits::<$kc>(0);
                self.right[0].xr.next = self.xr.val().get_bits::<$kc>(0);
                self.px.next = bit_cast::<$n, $half>(self.left[0].px.val())
                    | (bit_cast::<$n, $half>(self.right[0].px.val()) << $half);
            }
        }

        #[doc = concat!("The edge painting tree for P = ", stringify!($n), " pixels: paper 002, \
            Figs. 2 and 4. Pixel i is painted (`px` bit i) iff `xl` <= i <= `xr`. Combinational.")]
        #[derive(LogicBlock, Default)]
        pub struct $top {
            /// XL: left end of the span, inclusive; pixel index, unsigned.
            pub xl: Signal<In, Bits<$b>>,
            /// XR: right end of the span, inclusive; pixel index, unsigned.
            pub xr: Signal<In, Bits<$b>>,
            /// Paint mask: bit i high iff XL <= i <= XR.
            pub px: Signal<Out, Bits<$n>>,
            root: $tree,
        }

        impl Logic for $top {
            #[hdl_gen]
            fn update(&mut self) {
                // The root PE takes the MSBs as (LI, RI); nothing is forced above it.
                self.root.li.next = self.xl.val().get_bit($k);
                self.root.ri.next = self.xr.val().get_bit($k);
                self.root.lcs.next = false;
                self.root.rcs.next = false;
                self.root.xl.next = self.xl.val().get_bits::<$k>(0);
                self.root.xr.next = self.xr.val().get_bits::<$k>(0);
                self.px.next = self.root.px.val();
            }
        }

        impl Pins for $top {
            fn set(&mut self, pin: &str, value: &Value) {
                match pin {
                    "xl" => self.xl.next = value.to_bits(),
                    "xr" => self.xr.next = value.to_bits(),
                    _ => panic!("ept has no input pin {pin}"),
                }
            }
            fn get(&self, pin: &str) -> Value {
                match pin {
                    "px" => Value::from_bits(self.px.val()),
                    _ => panic!("ept has no output pin {pin}"),
                }
            }
        }

        impl EptSize for Pixels<$n> {
            type Unit = $top;
        }
    };
}

/// A pixel count, as a type: `Ept<P>` is `<Pixels<P> as EptSize>::Unit`.
pub struct Pixels<const P: usize>;

/// The EPT top for one supported pixel count.
pub trait EptSize {
    /// The unit: `Ept8` … `Ept1024`.
    type Unit: Block + Pins + Default;
}

/// The edge painting tree for P pixels (P a power of two, 8 to 1024).
pub type Ept<const P: usize> = <Pixels<P> as EptSize>::Unit;

ept_size!(Ept8, Tree8, Tree4, 8, 4, 3, 2, 1);
ept_size!(Ept16, Tree16, Tree8, 16, 8, 4, 3, 2);
ept_size!(Ept32, Tree32, Tree16, 32, 16, 5, 4, 3);
ept_size!(Ept64, Tree64, Tree32, 64, 32, 6, 5, 4);
ept_size!(Ept128, Tree128, Tree64, 128, 64, 7, 6, 5);
ept_size!(Ept256, Tree256, Tree128, 256, 128, 8, 7, 6);
ept_size!(Ept512, Tree512, Tree256, 512, 256, 9, 8, 7);
ept_size!(Ept1024, Tree1024, Tree512, 1024, 512, 10, 9, 8);

/// `UNITS` entry: emits the EPT for `params["P"]`, one of 8, 16, …, 1024.
pub fn emit_ept(params: &Params) -> Result<Emitted, String> {
    let p = params["P"];
    let params = params.clone();
    Ok(match p {
        8 => emit::<Ept<8>>("ept", params),
        16 => emit::<Ept<16>>("ept", params),
        32 => emit::<Ept<32>>("ept", params),
        64 => emit::<Ept<64>>("ept", params),
        128 => emit::<Ept<128>>("ept", params),
        256 => emit::<Ept<256>>("ept", params),
        512 => emit::<Ept<512>>("ept", params),
        1024 => emit::<Ept<1024>>("ept", params),
        _ => return Err(format!("ept: P = {p} is not supported: P must be a power of two from 8 to 1024")),
    })
}
