//! Texel formats: the five colour modes of paper 001 in which texels are stored.

use serde::{Deserialize, Serialize};

use crate::image::Rgba;

/// How a texel is stored: bits per channel, packed with red in the most significant bits and
/// alpha (when there is one) in the least, as OpenGL's packed types GL_UNSIGNED_SHORT_5_6_5,
/// GL_UNSIGNED_SHORT_5_5_5_1, GL_UNSIGNED_SHORT_4_4_4_4 and GL_UNSIGNED_INT_8_8_8_8;
/// RGB888 is 0xRRGGBB.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TexelFormat {
    /// 16 bits: red 5, green 6, blue 5, no alpha.
    Rgb565,
    /// 16 bits: red, green, blue 5 each, alpha 1.
    Rgba5551,
    /// 16 bits: 4 per channel.
    Rgba4444,
    /// 24 bits: 8 per colour channel, no alpha.
    Rgb888,
    /// 32 bits: 8 per channel (the default: an 8-bit PNG loses nothing).
    #[default]
    Rgba8888,
}

impl TexelFormat {
    /// Every format.
    pub const ALL: [TexelFormat; 5] =
        [TexelFormat::Rgb565, TexelFormat::Rgba5551, TexelFormat::Rgba4444, TexelFormat::Rgb888, TexelFormat::Rgba8888];

    /// Bits of red, green, blue and alpha (0: no alpha channel).
    pub fn bits(self) -> [u32; 4] {
        match self {
            TexelFormat::Rgb565 => [5, 6, 5, 0],
            TexelFormat::Rgba5551 => [5, 5, 5, 1],
            TexelFormat::Rgba4444 => [4; 4],
            TexelFormat::Rgb888 => [8, 8, 8, 0],
            TexelFormat::Rgba8888 => [8; 4],
        }
    }

    /// Bytes a texel takes in memory: 2, 2, 2, 3 or 4.
    pub fn bytes_per_texel(self) -> u32 {
        self.bits().iter().sum::<u32>().div_ceil(8)
    }

    /// The stored word of `rgba`: each channel c of b bits becomes round(c * (2^b - 1)), c first
    /// clamped to [0, 1] (NaN counts as 0). A format without alpha drops it.
    pub fn encode(self, rgba: Rgba) -> u32 {
        rgba.iter().zip(self.bits()).fold(0, |word, (&c, bits)| {
            let c = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
            (word << bits) | (c * f64::from(max_code(bits))).round() as u32
        })
    }

    /// The colour of a stored word: each channel's code v of b bits is v / (2^b - 1); a format
    /// without alpha decodes alpha as 1. Bits above the format's width are ignored.
    pub fn decode(self, word: u32) -> Rgba {
        let mut rgba = [1.0; 4];
        let mut rest = word;
        for (c, bits) in rgba.iter_mut().zip(self.bits()).rev().filter(|&(_, bits)| bits > 0) {
            *c = f64::from(rest & max_code(bits)) / f64::from(max_code(bits));
            rest >>= bits;
        }
        rgba
    }

    /// `rgba` as the format stores it: `decode(encode(rgba))`.
    pub fn quantize(self, rgba: Rgba) -> Rgba {
        self.decode(self.encode(rgba))
    }
}

/// The largest code of `bits` bits, 2^bits - 1.
fn max_code(bits: u32) -> u32 {
    (1 << bits) - 1
}
