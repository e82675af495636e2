//! The texture unit of paper 001 (Woo, Jang and Lee 2004), section II-5, bit-exact: per
//! pixel, the perspective division of eq. (3), the level of detail of eq. (4) (or OpenGL's
//! exact rho), the texels of the 2x2 footprint across the mip chain, the bilinear filter
//! with linear or Gaussian-approximating weights (Fig. 6), the blend between levels, texel
//! decode and the texture environment. The RTL texture unit must give the same colour on
//! every pixel; the float reference (`texture`, `reference::textured`) measures it.
//!
//! Stages, one module each:
//! 1. [`coords`]: s = (s·q) / q, t likewise, and lambda, from the pixel's s·q, t·q and
//!    q = w_min / w ([`TexIn`]) and the triangle's gradients of them ([`TexGrad`]);
//! 2. [`address`]: the levels lambda selects, and each level's texels, wrapped;
//! 3. `texture_memory` and the texture cache: each texel's word, a 2x2 footprint in one
//!    clock from four banks ([`Fetch`]);
//! 4. [`filter`]: decode, bilinear filter, the blend between two levels;
//! 5. [`env`]: the texture environment with the fragment's lit colour.
//!
//! Every precision is a field of [`TexFormats`].

pub mod address;
pub mod coords;
pub mod env;
pub mod filter;
pub mod input;

use crate::texture_memory;
use address::{levels, taps, Levels, Taps};
use coords::{coords, log2_table, Coords};
use filter::{gaussian_table, texel, FilterIn, Rgba8};
use fx::TexFormats;
use texture::{EnvMode, LodRule, Sampler, TexelFormat};

/// The state a texture is drawn with: its size, chain, address and how it is sampled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
        let levels = levels(f, state, c.lambda);
        let (filter, first, second) = match levels {
            Levels::Magnify => (state.sampler.mag, 0, None),
            Levels::One(d) => (state.sampler.min, d, None),
            Levels::Two { d1, frac } => (state.sampler.min, d1, Some((d1 + 1, frac))),
        };
        let mut x = FilterIn { two_levels: second.is_some(), frac: second.map_or(0, |s| s.1), ..FilterIn::default() };
        let mut fetches = Vec::with_capacity(2);
        for (k, d) in std::iter::once(first).chain(second.map(|s| s.0)).enumerate() {
            let taps = taps(f, state, &c, d, filter);
            let (words, fetch) = read(state, memory, d, &taps);
            (x.words[k], x.alpha[k], x.beta[k]) = (words, taps.alpha, taps.beta);
            fetches.push(fetch);
        }
        let texel = texel(f, state.format, state.sampler.weights, &self.gaussian, &x);
        let colour = env::environment(state.env, [cf[0], cf[1], cf[2], 255], texel);
        Sample { coords: c, levels, texel, colour, fetches }
    }
}

/// The words of the four texels of `taps` in level `d` ([T(i0, j0), T(i1, j0), T(i0, j1),
/// T(i1, j1)]) and the cache access that reads them: one bank per distinct texel (two
/// texels of a footprint that coincide, at a clamped edge or in a 1-wide level, are one
/// read).
fn read(state: &TexState, memory: &[u32], d: u32, taps: &Taps) -> ([u32; 4], Fetch) {
    let [ws, hs] = state.size_log2;
    let mut fetch = [None; 4];
    let mut words = [0; 4];
    for (k, word) in words.iter_mut().enumerate() {
        let (i, j) = (taps.i[k & 1], taps.j[k >> 1]);
        let address = texture_memory::address(state.base, ws, hs, d, i, j);
        fetch[texture_memory::bank(i, j)] = Some(address);
        *word = memory.get(address as usize).copied().unwrap_or(0);
    }
    (words, fetch)
}
