//! The scanline pipeline's units for size class 10: screens up to 1024 x 1024, number
//! formats `fx::Formats::for_n(10)`.

/// The size class of these units.
pub const CLASS: u32 = 10;
/// The formats of these units: the model's defaults for the class.
pub const FORMATS: fx::Formats = fx::Formats::for_n(CLASS);
scanline_units!();
