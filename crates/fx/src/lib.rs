//! Explicit fixed-point number formats shared by edgepaint's models and RTL.
//!
//! [`Fmt`] is one format (house notation `S11.4 [16]`), with its rounding and
//! overflow behaviour; [`Formats`] names the format of every quantity of the
//! pipelines, with defaults derived from the screen resolution.

pub mod fmt;
pub mod formats;
pub mod texture;

pub use fmt::{
    clog2, fits_s, shr_floor, shr_half_up, signed_bits, unsigned_bits, wrap_s, wrap_u, Fmt, Overflow, Rounding,
    MAX_BITS,
};
pub use formats::{
    resolution_bits, smallest_class, Build, Derived, Formats, Given, RTL_CLASS, SMALLEST_CLASS, SUBPIXEL_BITS,
};
pub use texture::TexFormats;
