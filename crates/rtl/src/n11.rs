//! The scanline pipeline's units for size class 11: screens up to 2048 x 2048, number
//! formats `fx::Formats::for_n(11)`.

/// The size class of these units.
pub const CLASS: u32 = 11;
/// The formats of these units: the model's defaults for the class.
pub const FORMATS: fx::Formats = fx::Formats::for_n(CLASS);
scanline_units!();
