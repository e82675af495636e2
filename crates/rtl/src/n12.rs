//! The scanline pipeline's units for size class 12: screens up to 4096 x 4096, number
//! formats `fx::Formats::for_n(12)`.

/// The size class of these units.
pub const CLASS: u32 = 12;
/// The formats of these units: the model's defaults for the class.
pub const FORMATS: fx::Formats = fx::Formats::for_n(CLASS);
scanline_units!();
