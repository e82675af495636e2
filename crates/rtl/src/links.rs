//! The links between the scanline units of one build, each declared once (`crate::link!`),
//! at the build's widths (`super::widths`).

use super::widths::{CHANNEL, C_ACC, DC, DEPTH, DZ, PIXEL, SCREEN, Z_ACC};
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

crate::link! {
    /// One scanline's span (`model::edge_walk::SpanCmd`): `edge_walk` -> the span FIFO ->
    /// `span`.
    SpanCmdSource => SpanCmdSink {
        /// The scanline.
        y: Bits<SCREEN>,
        /// First and last pixel inside (xl <= xr), `PIXEL` bits two's complement, possibly
        /// off screen: `span` clips x.
        xl: Bits<PIXEL>,
        xr: Bits<PIXEL>,
        /// Attributes at pixels xl and xr (`z_acc`, `c_acc`).
        left_z: Bits<Z_ACC>,
        left_c0: Bits<C_ACC>,
        left_c1: Bits<C_ACC>,
        left_c2: Bits<C_ACC>,
        right_z: Bits<Z_ACC>,
        right_c0: Bits<C_ACC>,
        right_c1: Bits<C_ACC>,
        right_c2: Bits<C_ACC>,
        /// Per-pixel steps (`dz`, `dc`).
        ddx_z: Bits<DZ>,
        ddx_c0: Bits<DC>,
        ddx_c1: Bits<DC>,
        ddx_c2: Bits<DC>,
    }
}
