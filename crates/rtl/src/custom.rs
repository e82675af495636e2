//! The scanline pipeline's units at the build given when edgepaint is compiled: size class
//! `EDGEPAINT_CLASS` (8 to 12, default 10) and the formats `EDGEPAINT_FORMATS` over its defaults
//! (default `crates/rtl/custom-formats.json`: a 24-bit depth buffer, 3 subpixel bits,
//! colours with 2 fraction bits). `build.rs` writes [`CLASS`], [`FORMATS`] and [`SOURCE`]
//! after checking them (`crate::config::check`); `edgepaint emit|render --formats FILE`
//! rebuilds edgepaint with them when the formats asked for are no build's.

include!(concat!(env!("OUT_DIR"), "/custom.rs"));
scanline_units!();
