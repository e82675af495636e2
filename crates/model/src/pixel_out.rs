//! `pixel_out`: the depth test (LESS) and the writes to the depth and colour
//! buffers, behind `span`. The depth buffer is cleared to z_max (the far plane).
//!
//! In hardware it reads the old depth through a synchronous memory port (data
//! the cycle after the address) and writes depth and colour when the new depth
//! is less: latency 2, one pixel per cycle. Mirrors `rtl::pixel_out`; with its `BLEND` = 1
//! it also reads the colour and writes the blend, as [`Framebuffer::pixel_out_blended`], at
//! the same latency.

use crate::blend::blend;
use crate::span::Pixel;
use texture::BlendMode;

/// Cycles from a pixel in to its write (read, compare-and-write).
pub const LATENCY: u32 = 2;
/// Cycles per pixel.
pub const II: u32 = 1;

/// The depth and colour buffers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Framebuffer {
    pub width: u32,
    pub height: u32,
    /// Depth per pixel (`z.frac` bits), row-major from the top-left.
    pub depth: Vec<u32>,
    pub rgb: Vec<[u8; 3]>,
    /// Whether a pixel was ever written.
    pub written: Vec<bool>,
    /// Which triangle (index in the list) wrote it last; `u32::MAX` if none.
    /// Analysis only: the hardware has no such buffer.
    pub writer: Vec<u32>,
}

impl Framebuffer {
    /// Buffers cleared to `background` and depth `z_max`.
    pub fn new(width: u32, height: u32, z_max: u32, background: [u8; 3]) -> Self {
        let n = (width * height) as usize;
        Framebuffer {
            width,
            height,
            depth: vec![z_max; n],
            rgb: vec![background; n],
            written: vec![false; n],
            writer: vec![u32::MAX; n],
        }
    }

    /// Depth test LESS, then write a pixel of triangle `tri`. Returns whether it was written.
    pub fn pixel_out(&mut self, p: &Pixel, tri: u32) -> bool {
        self.pixel_out_blended(p, 255, BlendMode::Opaque, tri)
    }

    /// Depth test LESS, then blend the fragment (colour `p.rgb`, alpha `alpha`) onto the
    /// colour buffer by `mode` (`blend`, 001's six modes; the buffer has no alpha, so the
    /// destination's is 255) and write it, depth as without blending (GL 4.6 §17.3.6).
    pub fn pixel_out_blended(&mut self, p: &Pixel, alpha: u8, mode: BlendMode, tri: u32) -> bool {
        let i = (p.y * self.width + p.x) as usize;
        if p.z < self.depth[i] {
            let [r, g, b] = self.rgb[i];
            let c = blend(mode, [p.rgb[0], p.rgb[1], p.rgb[2], alpha], [r, g, b, 255]);
            self.depth[i] = p.z;
            self.rgb[i] = [c[0], c[1], c[2]];
            self.written[i] = true;
            self.writer[i] = tri;
            true
        } else {
            false
        }
    }
}
