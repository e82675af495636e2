//! The links between the scanline units of one build, each declared once (`crate::link!`),
//! at the build's widths (`super::widths`).

use super::widths::{CHANNEL, DEPTH, SCREEN};
use rust_hdl::prelude::*;

crate::link! {
    /// A pixel on screen (`model::span::Pixel`): `span` -> `pixel_out`, and the fragments
    /// out of a `raster_top` without `pixel_out`.
    PixelSource => PixelSink {
        x: Bits<SCREEN>,
        y: Bits<SCREEN>,
        /// Depth, the depth buffer's `DEPTH` bits.
        z: Bits<DEPTH>,
        /// R, G, B.
        rgb0: Bits<CHANNEL>,
        rgb1: Bits<CHANNEL>,
        rgb2: Bits<CHANNEL>,
    }
}
