//! What a copy of the scanline units is built at, and which builds the RTL supports.
//!
//! rust-hdl's widths are compile-time constants, so the scanline units (`cull_sort` to
//! `raster_top`) are compiled once per *build*: a size class `n` (screens up to 2^n x 2^n)
//! and the number formats of every quantity (`fx::Formats`). `crate::n10`, `n11` and `n12`
//! are the model's defaults for their class, `Formats::for_n(n)`; `crate::custom` is the
//! build given when edgepaint is compiled (`EDGEPAINT_CLASS`, `EDGEPAINT_FORMATS`, see
//! `build.rs`).
//!
//! The units compute what the models compute for any build [`check`] accepts: its
//! [`violation`] is asserted where each copy's widths are set (`widths.rs`), and `build.rs`
//! and `edgepaint` run [`check`] first, so that a format the RTL cannot take is refused
//! with a message, not a compile error. (`build.rs` loads this file too: it uses `fx` only.)

use fx::{Fmt, Formats, Overflow, Rounding};

/// The size classes a build may have (the models' `model::raster_top` classes): `CLASS_MIN`
/// is `fx::SMALLEST_CLASS` (screens up to 256 x 256), the smallest the tests of `rtl::custom`
/// prove (`testbenches/tests/raster_top.rs`, run at `EDGEPAINT_CLASS` = 9 and 8); the units
/// built into every edgepaint (`crate::CLASSES`) stay 10, 11 and 12, a smaller class is a
/// `custom` build (`edgepaint fit` of a workload of small screens).
pub const CLASS_MIN: u32 = fx::SMALLEST_CLASS;
pub const CLASS_MAX: u32 = 12;

/// Port and register widths of the scanline units at a build (`class`, formats): the one
/// table the RTL reads its widths from (each build's `widths` module is
/// `Widths::of(CLASS, &FORMATS)`) and the sweep's area model counts bits with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Widths {
    /// Screen coordinates of a pixel on screen (x, y < 2^class): unsigned.
    pub screen: usize,
    /// Screen width and height (1 to 2^class): unsigned.
    pub dim: usize,
    /// Memory address of a pixel: `{y, x}`, a row pitch of 2^class words.
    pub addr: usize,
    /// Pixel positions anywhere in the coordinate range (`Derived::pixel_bits`).
    pub pixel: usize,
    /// The exact edge walker's `r`, `rho` and `D` (`delta_bits + xy.frac`).
    pub edge_d: usize,
    /// The exact edge walker's step quotient (`delta_bits`).
    pub edge_q: usize,
    /// Vertex x and y, z, a colour channel, w_min / w, as they enter the rasterizer.
    pub xy: usize,
    pub z: usize,
    pub color: usize,
    pub inv_w: usize,
    /// z and colour accumulators and steps.
    pub z_acc: usize,
    pub dz: usize,
    pub c_acc: usize,
    pub dc: usize,
    /// A depth-buffer word: `z`'s fraction bits.
    pub depth: usize,
    /// The divider's dividend, divisor and signed quotient (`Derived::div_*_bits`).
    pub div_n: usize,
    pub div_d: usize,
    pub div_q: usize,
    /// `triangle_setup`'s multiplier operands ([`mul_a`], [`mul_b`]) and the products it
    /// keeps: the wide domain, the dividend or an A operand, the wider.
    pub mul_a: usize,
    pub mul_b: usize,
    pub mul_p: usize,
}

/// Outcode bits, one per clip plane.
pub const OUTCODE: usize = 6;
/// One colour channel of the colour buffer.
pub const CHANNEL: usize = 8;

impl Widths {
    /// The widths of the build (`class`, `f`).
    pub const fn of(class: u32, f: &Formats) -> Widths {
        let dv = f.derived();
        let (div_n, mul_a) = (dv.div_dividend_bits as usize, mul_a(f));
        let screen = class as usize;
        Widths {
            screen,
            dim: screen + 1,
            addr: 2 * screen,
            pixel: dv.pixel_bits as usize,
            edge_d: (dv.delta_bits + f.xy.frac) as usize,
            edge_q: dv.delta_bits as usize,
            xy: f.xy.bits() as usize,
            z: f.z.bits() as usize,
            color: f.color.bits() as usize,
            inv_w: f.inv_w.bits() as usize,
            z_acc: f.z_acc.bits() as usize,
            dz: f.dz.bits() as usize,
            c_acc: f.c_acc.bits() as usize,
            dc: f.dc.bits() as usize,
            depth: f.z.frac as usize,
            div_n,
            div_d: dv.div_divisor_bits as usize,
            div_q: dv.div_quotient_bits as usize,
            mul_a,
            mul_b: mul_b(f),
            mul_p: if div_n > mul_a { div_n } else { mul_a },
        }
    }

    /// Bits of a triangle's three vertices (`links::TriangleSource`).
    pub const fn triangle_link(&self) -> usize {
        3 * (2 * self.xy + self.z + 3 * self.color + self.inv_w)
    }

    /// Bits of a set-up triangle (`links::TriangleSetupSource`): three edges, each the
    /// exact walker and its attributes, and the per-pixel steps.
    pub const fn setup_link(&self) -> usize {
        let edge = 3 * self.pixel + 3 * self.edge_d + self.edge_q + self.z_acc + 3 * self.c_acc;
        2 + 3 * (edge + 2 * (self.dz + 3 * self.dc)) + self.dz + 3 * self.dc
    }

    /// Bits of a span command (`links::SpanCmdSource`).
    pub const fn span_cmd_link(&self) -> usize {
        self.screen + 2 * self.pixel + 2 * (self.z_acc + 3 * self.c_acc) + self.dz + 3 * self.dc
    }

    /// Bits of a pixel (`links::PixelSource`).
    pub const fn pixel_link(&self) -> usize {
        2 * self.screen + self.depth + 3 * CHANNEL
    }
}

/// `triangle_setup`'s multiplier operand A: the widest first factor, `ooa_d` (OneOverArea
/// x delta, the gradients' first factor).
pub const fn mul_a(f: &Formats) -> usize {
    f.ooa_d.bits() as usize
}

/// `triangle_setup`'s multiplier operand B: the widest second factor: a z difference
/// (`z.bits() + 1`), an edge delta or offset from v0 (`xy.bits() + 3`, with room to
/// sign-extend) or a step quotient (`delta_bits + 2`). Colour differences are narrower
/// (checked).
pub const fn mul_b(f: &Formats) -> usize {
    let (z, xy, q) = (f.z.bits() + 1, f.xy.bits() + 3, f.derived().delta_bits + 2);
    let m = if z > xy { z } else { xy };
    (if m > q { m } else { q }) as usize
}

/// The first requirement of the RTL that the build (`class`, `f`) breaks, beyond
/// `Formats::check`; `None` if it has none. A `const fn`, so that every copy of the units
/// asserts it of its own build when it compiles.
pub const fn violation(class: u32, f: &Formats) -> Option<&'static str> {
    let dv = f.derived();
    let (mul_a, mul_b) = (mul_a(f), mul_b(f));
    // Products are kept in the wide domain: the divider's dividend or an A operand.
    let dividend = dv.div_dividend_bits as usize;
    let product = if dividend > mul_a { dividend } else { mul_a };
    if class < CLASS_MIN || class > CLASS_MAX {
        return Some("the size class must be 8 to 12 (screens up to 256 to 4096 pixels wide and high)");
    }
    if f.xy.int < class + 1 {
        return Some("xy needs class + 1 integer bits: the screen's positions and its guard band");
    }
    let internal = [f.ooa, f.ooa_d, f.dz, f.z_acc, f.dc, f.c_acc, f.bary];
    let mut i = 0;
    while i < internal.len() {
        if !plain(internal[i]) {
            return Some("ooa, ooa_d, dz, z_acc, dc, c_acc and bary are registers of the RTL: truncate and wrap only");
        }
        i += 1;
    }
    if f.ooa_d.frac + f.z.frac < f.dz.frac || f.ooa_d.frac + f.color.frac < f.dc.frac {
        return Some("the gradients' slices of ooa_d x difference are floor shifts: ooa_d.frac + z.frac >= dz.frac and ooa_d.frac + color.frac >= dc.frac");
    }
    // setup keeps the gradients' numerators in ooa_d-wide registers (mod 2^ooa_d.bits())
    // and computes the accumulators' start values from their slices before narrowing them
    // to dz and dc: a start value (z_acc, c_acc after a floor shift by xy.frac) is right
    // modulo its accumulator only if the slice holds its bits. The defaults' rules give
    // this (the modular minimum); dz and dc narrower than it do not change it.
    if f.ooa_d.int < f.z.frac + f.z_acc.int + f.xy.frac || f.ooa_d.int < f.color.frac + f.c_acc.int + f.xy.frac {
        return Some("setup's gradient registers are ooa_d wide and the start values their slices: ooa_d.int >= z.frac + z_acc.int + xy.frac and color.frac + c_acc.int + xy.frac");
    }
    // The start values agree with the model's only from the modular minimum up. The model
    // computes a start value exactly, `at = v0 + floor((ddx off_x + ddy off_y) / 2^s)`, from
    // the gradients wrapped into dz and dc; setup computes it from the gradients' unwrapped
    // slices of the ooa_d registers, the sum (`plane`) in a lane dz bits wide, then shifts it
    // right by s. The two sums are equal modulo 2^dz.bits() for z and 2^dc.bits() for a
    // colour, so after the shift modulo 2^(dz.bits() - s) and 2^(dc.bits() - s): a start
    // value's z_acc or c_acc bits agree iff dz.int >= z_acc.int + s and dc.int >= c_acc.int
    // + s (equal fraction bits, below). Narrower, they differ where nothing wraps in the
    // model (class 8 with dz S2.40, dc S9.20: the cube's pixel (8, 3) in raster_top's
    // lockstep). Going below needs plane lanes of z_acc.bits() + s bits in setup and, for
    // dc, a model that takes the colour starts from the unwrapped gradients.
    if f.dz.int < f.z_acc.int + f.xy.frac || f.dc.int < f.c_acc.int + f.xy.frac {
        return Some("dz and dc need the modular minimum, z_acc.int + xy.frac and c_acc.int + xy.frac integer bits: setup computes the start values from the unwrapped gradients in dz-wide lanes, the model from the wrapped ones, and below it the two differ");
    }
    if f.dz.frac != f.z_acc.frac || f.dc.frac != f.c_acc.frac {
        return Some("gradients have the fraction bits of their accumulators");
    }
    if f.z_acc.frac < f.z.frac || f.c_acc.frac < f.color.frac {
        return Some("accumulators have at least the fraction bits of their vertex values");
    }
    if f.z_acc.frac == f.z.frac || f.c_acc.frac == 0 {
        return Some("span rounds z_acc and c_acc into the buffers by a shift of at least one bit (parts::RoundShift): z_acc.frac > z.frac and c_acc.frac >= 1");
    }
    if f.dz.bits() < f.dc.bits() || f.dz.bits() < f.z_acc.bits() || f.dc.bits() < f.c_acc.bits() {
        return Some("an attribute lane is z's gradient wide: dz at least as wide as dc and z_acc, dc as c_acc");
    }
    if f.dz.bits() as usize > product {
        return Some("dz must fit the products (the divider's dividend or ooa_d, the wider)");
    }
    if mul_b <= f.color.bits() as usize {
        return Some("colour differences must fit triangle_setup's multiplier operand B");
    }
    if mul_a + mul_b > 127 || product > 128 {
        return Some("triangle_setup's products must fit 128 bits (at most 127 bits of operands)");
    }
    if f.ooa_d.frac + f.xy.frac < f.ooa.frac {
        return Some("eq. (2)'s shift ooa_d.frac + xy.frac - ooa.frac must not be negative");
    }
    if f.z.bits() > 64 || f.xy.bits() > 64 || f.inv_w.bits() > 64 || f.color.int != 8 {
        return Some("vertex words are at most 64 bits, colours U8 (the colour buffer is RGB888)");
    }
    None
}

/// Truncating and wrapping: what a register of the RTL does.
const fn plain(f: Fmt) -> bool {
    matches!(f.rounding, Rounding::Truncate) && matches!(f.overflow, Overflow::Wrap)
}

/// Whether the scanline units can be built at size class `class` and formats `f`: the
/// formats work for a 2^class x 2^class screen (`Formats::check`) and the RTL takes them
/// ([`violation`]); the error says why not.
pub fn check(class: u32, f: &Formats) -> Result<(), String> {
    if let Some(why) = violation(class, f) {
        return Err(format!("the RTL cannot be built at size class {class} with these formats: {why}"));
    }
    let side = 1u32 << class;
    f.check(side, side).map_err(|e| format!("formats for size class {class} ({side}x{side}): {e}"))
}
