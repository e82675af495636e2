//! The texture unit of paper 001 (Woo, Jang and Lee 2004), section II-5, bit-exact: per
//! pixel, the perspective division of eq. (3), the level of detail of eq. (4) (or OpenGL's
//! exact rho), the texels of the 2x2 footprint across the mip chain, the bilinear filter
//! with linear or Gaussian-approximating weights (Fig. 6), the blend between levels, texel
//! decode and the texture environment. The RTL texture unit must give the same colour on
//! every pixel; the float reference (`texture`, `reference::textured`) measures it.
//!
//! Stages, one unit each (the RTL's of the same names):
//! 1. `texture_coords`: s = (s·q) / q, t likewise, and lambda, from the pixel's s·q, t·q
//!    and q = w_min / w ([`TexIn`]) and the triangle's gradients of them ([`TexGrad`]);
//! 2. `texture_address`: the levels lambda selects, and each level's texels, wrapped, as
//!    one cache access (`texture_address::request`) per level;
//! 3. `texture_memory` and `texture_cache`: each texel's word, a 2x2 footprint in one
//!    clock from four banks ([`Fetch`]);
//! 4. `texture_filter`: decode, bilinear filter, the blend between two levels, and the
//!    texture environment with the fragment's lit colour.
//!
//! Every precision is a field of [`TexFormats`].

pub mod input;
pub mod pipeline;

use crate::texture_address::{levels, request, Levels};
use crate::texture_coords::{coords, log2_table, Coords};
use crate::texture_filter::{environment, gaussian_table, texel, FilterIn, Rgba8};
use fx::TexFormats;
use texture::{EnvMode, LodRule, Sampler, TexelFormat};

/// The state a texture is drawn with: its size, chain, address and how it is sampled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TexState {
    /// log2 of the base level's width and height (at most `fx::texture::MAX_SIZE_LOG2`).
    pub size_log2: [u32; 2],
    /// Levels in the chain (1 to max(size_log2) + 1).
    pub levels: u32,
    /// The word address of level 0 in texture memory (`texture_memory`'s layout).
    pub base: u32,
    pub format: TexelFormat,
    pub sampler: Sampler,
    pub env: EnvMode,
    /// Which scale factor the level of detail is taken from.
    pub lod: LodRule,
}

impl TexState {
    /// Whether the unit can draw with this state; the error names the rule broken.
    pub fn check(&self) -> Result<(), String> {
        let [ws, hs] = self.size_log2;
        if ws.max(hs) > fx::texture::MAX_SIZE_LOG2 {
            return Err(format!("a texture of 2^{ws} x 2^{hs} texels: at most 2^{}", fx::texture::MAX_SIZE_LOG2));
        }
        if !(1..=ws.max(hs) + 1).contains(&self.levels) {
            return Err(format!("{} levels for a 2^{ws} x 2^{hs} texture: 1 to {}", self.levels, ws.max(hs) + 1));
        }
        Ok(())
    }
}

/// One pixel's texture inputs, raw: s·q and t·q in `st`, q = w_min / w in `q`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct TexIn {
    pub sq: i64,
    pub tq: i64,
    pub q: i64,
}

/// A triangle's gradients of s·q, t·q (`dst`) and q (`dq`), raw: `[d/dx, d/dy]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct TexGrad {
    pub dsq: [i64; 2],
    pub dtq: [i64; 2],
    pub dq: [i64; 2],
}

/// One access of the texture cache: each bank's word address, or none.
pub type Fetch = [Option<u32>; 4];

/// What the unit did for one pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sample {
    pub coords: Coords,
    pub levels: Levels,
    /// The filtered texel colour Cs.
    pub texel: Rgba8,
    /// Cs through the texture environment with the fragment's colour.
    pub colour: Rgba8,
    /// The cache accesses, one per level read, in order.
    pub fetches: Vec<Fetch>,
}

/// The texture unit at a set of formats, with its tables.
#[derive(Clone, Debug)]
pub struct TextureUnit {
    pub formats: TexFormats,
    log2: Vec<i64>,
    gaussian: Vec<u32>,
}

impl TextureUnit {
    /// The unit at `formats` (checked).
    pub fn new(formats: TexFormats) -> Result<TextureUnit, String> {
        formats.check()?;
        Ok(TextureUnit { formats, log2: log2_table(&formats), gaussian: gaussian_table(&formats) })
    }

    /// Stage 1 alone: the coordinates and level of detail of pixel `p`.
    pub fn coords(&self, state: &TexState, p: &TexIn, g: &TexGrad) -> Coords {
        coords(&self.formats, state, &self.log2, p, g)
    }

    /// Pixel `p` of a triangle with gradients `g` and lit colour `cf`, textured by `state`
    /// from texture memory `memory` (words from address 0; a word past its end reads 0).
    pub fn sample(&self, state: &TexState, memory: &[u32], p: &TexIn, g: &TexGrad, cf: [u8; 3]) -> Sample {
        let f = &self.formats;
        let c = self.coords(state, p, g);
        let first = request(f, state, &c, false);
        let mut x = FilterIn { two_levels: first.two_levels, frac: first.frac, ..FilterIn::default() };
        let mut fetches = Vec::with_capacity(2);
        for k in 0..1 + usize::from(first.two_levels) {
            let r = if k == 0 { first } else { request(f, state, &c, true) };
            let word = |bank: usize| r.fetch[bank].and_then(|a| memory.get(a as usize)).copied().unwrap_or(0);
            (x.words[k], x.alpha[k], x.beta[k]) = (r.banks.map(word), r.alpha, r.beta);
            fetches.push(r.fetch);
        }
        let texel = texel(f, state.format, state.sampler.weights, &self.gaussian, &x);
        let colour = environment(state.env, [cf[0], cf[1], cf[2], 255], texel);
        Sample { coords: c, levels: levels(f, state, c.lambda), texel, colour, fetches }
    }
}
