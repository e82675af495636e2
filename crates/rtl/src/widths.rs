//! Port and register widths of the scanline pipeline's RTL, read off the build it is
//! compiled at (`crate::config`): its size class [`CLASS`] (screens up to 2^CLASS x
//! 2^CLASS) and its number formats [`FORMATS`] (`crate::n10`, ..., `crate::custom`), so that
//! a change of format reaches every port.
//!
//! Configurable quantities take their format's width; exact quantities (positions, edge
//! walker remainders) take the widths `Formats::derived` gives them.

pub use super::{CLASS, FORMATS};
use crate::config::Widths;
use fx::Derived;

// Every build of the units is one the RTL supports.
const _: () = if let Some(why) = crate::config::violation(CLASS, &FORMATS) {
    panic!("{}", why)
};
/// Widths of the exact quantities under [`FORMATS`].
pub const DERIVED: Derived = FORMATS.derived();
/// This build's widths (`crate::config::Widths`).
pub const WIDTHS: Widths = Widths::of(CLASS, &FORMATS);

/// Screen coordinates of a pixel on screen (x, y < 2^CLASS): unsigned.
pub const SCREEN: usize = WIDTHS.screen;
/// Screen width and height (1 to 2^CLASS): unsigned.
pub const DIM: usize = WIDTHS.dim;
/// Memory address of a pixel: `{y, x}`, a row pitch of 2^CLASS words.
pub const ADDR: usize = WIDTHS.addr;
/// Pixel positions anywhere in the coordinate range (scanline `j`, edge `x`, span ends,
/// scanline counts): `pixel_bits`, two's complement.
pub const PIXEL: usize = WIDTHS.pixel;
/// The exact edge walker's `r`, `rho` and `D = 2^s * dy` (all in [0, D)): the divider's
/// edge divisor width, `delta_bits + s`.
pub const EDGE_D: usize = WIDTHS.edge_d;
/// The exact edge walker's step quotient `q = floor(dx / dy)`, |q| <= |dx|: `delta_bits`.
pub const EDGE_Q: usize = WIDTHS.edge_q;
/// z accumulators (`z_acc`) and z steps (`dz`).
pub const Z_ACC: usize = WIDTHS.z_acc;
pub const DZ: usize = WIDTHS.dz;
/// Colour accumulators (`c_acc`) and colour steps (`dc`).
pub const C_ACC: usize = WIDTHS.c_acc;
pub const DC: usize = WIDTHS.dc;
// Steps are at least as wide as their accumulators: only their low bits reach them.
const _: () = assert!(DZ >= Z_ACC && DC >= C_ACC);
/// A depth-buffer word: `z`'s fraction bits.
pub const DEPTH: usize = WIDTHS.depth;
/// One colour channel of the colour buffer.
pub use crate::config::CHANNEL;
/// A colour-buffer word: R, G, B, R in the top byte.
pub const RGB: usize = 3 * CHANNEL;

/// The SE back end's engines at this build (`model::se::array::engine_params`): z and
/// colour words of `SE_ZW` and `SE_CW` bits, `SE_F` fraction bits in A and B, whose words
/// are `SE_ZA` and `SE_CA` bits.
pub const SE: model::se::SeParams = model::se::array::engine_params(&FORMATS);
pub const SE_ZW: usize = SE.zw as usize;
pub const SE_CW: usize = SE.cw as usize;
pub const SE_F: usize = SE.frac as usize;
pub const SE_ZA: usize = SE_ZW + SE_F;
pub const SE_CA: usize = SE_CW + SE_F;
