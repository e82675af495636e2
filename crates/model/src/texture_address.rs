//! From a pixel's coordinates and level of detail to the texels it reads: the levels
//! (OpenGL 4.6 sections 8.14.3 and 8.15), texel selection and wrap (section 8.14.2), in
//! fixed point.
//!
//! Level d is 2^max(ws-d, 0) texels wide; u = s · that width in `subtexel` fraction bits
//! (floor, an exact shift of s). Nearest: i = floor(u). Linear: u - 1/2 = i0 + alpha,
//! i1 = i0 + 1, alpha the `subtexel` fraction bits. Each index is wrapped on its own (the
//! footprint's texels are wrapped separately, as GL says); sides are powers of two, so
//! REPEAT is a mask, MIRRORED_REPEAT a mask and a reflection, CLAMP_TO_EDGE a clamp.

use crate::texture_coords::Coords;
use crate::texture_memory;
use crate::texture_unit::{Fetch, TexState};
use fx::TexFormats;
use texture::{Filter, MipMode, Wrap};

/// The levels a pixel reads (section 8.14.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Levels {
    /// lambda <= 0: the magnification filter on level 0.
    Magnify,
    /// The minification filter on one level.
    One(u32),
    /// The minification filter on levels d1 and d1 + 1, weighted by `frac` (`lod_frac` bits)
    /// for level d1 + 1.
    Two { d1: u32, frac: u32 },
}

/// The levels of a pixel at level of detail `lambda` (`lod_frac` bits) in `state`'s chain:
/// magnified when lambda <= 0; minified, level 0 without mipmaps, level
/// clamp(ceil(lambda + 1/2) - 1, 0, q) for the nearest, levels floor(lambda) and one more for
/// linear (level q alone when lambda >= q).
pub fn levels(f: &TexFormats, state: &TexState, lambda: i64) -> Levels {
    let q = i64::from(state.levels.max(1) - 1);
    let lf = f.lod_frac;
    if lambda <= 0 {
        return Levels::Magnify;
    }
    match state.sampler.mip {
        MipMode::None => Levels::One(0),
        MipMode::Nearest => Levels::One(((lambda + (1 << (lf - 1)) - 1) >> lf).clamp(0, q) as u32),
        MipMode::Linear if lambda >> lf >= q => Levels::One(q as u32),
        MipMode::Linear => Levels::Two { d1: (lambda >> lf) as u32, frac: (lambda & ((1 << lf) - 1)) as u32 },
    }
}

/// The texels a pixel reads of one level: columns `i`, rows `j` and the fractions alpha,
/// beta (`subtexel` bits) of the second of each. Nearest: one texel, i[0] = i[1], j[0] =
/// j[1], alpha = beta = 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Taps {
    pub i: [u32; 2],
    pub j: [u32; 2],
    pub alpha: u32,
    pub beta: u32,
}

/// The texels of level `d` that `filter` reads at `c`.
pub fn taps(f: &TexFormats, state: &TexState, c: &Coords, d: u32, filter: Filter) -> Taps {
    let [ws, hs] = state.size_log2;
    let (wl, hl) = (ws.saturating_sub(d), hs.saturating_sub(d));
    let (i, alpha) = axis(f, c.s, wl, filter, state.sampler.wrap_s);
    let (j, beta) = axis(f, c.t, hl, filter, state.sampler.wrap_t);
    Taps { i, j, alpha, beta }
}

/// The two indices (equal for nearest) and fraction along an axis of 2^`size_log2` texels.
fn axis(f: &TexFormats, s: i64, size_log2: u32, filter: Filter, wrap: Wrap) -> ([u32; 2], u32) {
    let sub = f.subtexel;
    let u = s >> (f.st.frac - sub - size_log2);
    match filter {
        Filter::Nearest => {
            let i = wrap_index(wrap, u >> sub, size_log2);
            ([i, i], 0)
        }
        Filter::Linear => {
            let u = u - (1 << (sub - 1));
            let i0 = u >> sub;
            let alpha = (u & ((1 << sub) - 1)) as u32;
            ([wrap_index(wrap, i0, size_log2), wrap_index(wrap, i0 + 1, size_log2)], alpha)
        }
    }
}

/// Texel index `i` wrapped into 0..2^`size_log2`.
pub fn wrap_index(wrap: Wrap, i: i64, size_log2: u32) -> u32 {
    let n = 1i64 << size_log2;
    match wrap {
        Wrap::Repeat => (i & (n - 1)) as u32,
        Wrap::MirroredRepeat => {
            let p = i & (2 * n - 1);
            (if p < n { p } else { 2 * n - 1 - p }) as u32
        }
        Wrap::ClampToEdge => i.clamp(0, n - 1) as u32,
    }
}

/// One access of the texture cache: the texels of one level of a pixel's footprint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Request {
    /// Each bank's word address, or none.
    pub fetch: Fetch,
    /// The bank of each footprint texel [T(i0, j0), T(i1, j0), T(i0, j1), T(i1, j1)]: two
    /// texels that coincide (at a clamped edge, in a 1-wide level, or a nearest sample's
    /// one texel four times) are one read of one bank.
    pub banks: [usize; 4],
    /// The level's fractions (`subtexel` bits; 0 for nearest).
    pub alpha: u32,
    pub beta: u32,
    /// Whether the pixel reads two levels, and the second's weight (`lod_frac` bits).
    pub two_levels: bool,
    pub frac: u32,
}

/// The cache access for the pixel at `c`: of its first level, or of its second (the finer
/// level's next) when `second` and it reads two: what the RTL unit `texture_address` gives,
/// `rtl::texture_address::LATENCY` (3) enabled clocks after the pixel goes in (its
/// `inp_two_levels`, whether the pixel reads two levels, at once).
pub fn request(f: &TexFormats, state: &TexState, c: &Coords, second: bool) -> Request {
    let (filter, d, two_levels, frac) = match levels(f, state, c.lambda) {
        Levels::Magnify => (state.sampler.mag, 0, false, 0),
        Levels::One(d) => (state.sampler.min, d, false, 0),
        Levels::Two { d1, frac } => (state.sampler.min, d1 + u32::from(second), true, frac),
    };
    let taps = taps(f, state, c, d, filter);
    let [ws, hs] = state.size_log2;
    let mut fetch = [None; 4];
    let banks = std::array::from_fn(|k| {
        let (i, j) = (taps.i[k & 1], taps.j[k >> 1]);
        let bank = texture_memory::bank(i, j);
        fetch[bank] = Some(texture_memory::address(state.base, ws, hs, d, i, j));
        bank
    });
    Request { fetch, banks, alpha: taps.alpha, beta: taps.beta, two_levels, frac }
}
