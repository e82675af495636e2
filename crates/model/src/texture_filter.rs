//! The texture unit's filter (paper 001 section II-5) in fixed point: texel decode, the
//! bilinear filter with plain linear weights or 001's Gaussian-approximating weights (its
//! Fig. 6), the linear blend between two levels, and the texture environment. Bit-exact
//! model of the RTL unit `texture_filter`: [`texel`] then [`environment`].
//!
//! - Decode: a c-bit channel widens to 8 bits by bit replication (c << (8 - c) | c >> (2c -
//!   8) ..., the usual hardware expansion, within 0.72 LSB of c · 255 / (2^c - 1): exact for 1,
//!   4 and 8 bits, 0.68 LSB at most for 5 and 0.72 for 6); a format
//!   without alpha reads alpha 255.
//! - Weights: a = alpha's top `weight` bits (linear), or the table
//!   round((3x² - 2x³) · 2^weight) at x = alpha / 2^subtexel (Gaussian); the first texel of a
//!   pair gets 2^weight - a.
//! - Bilinear: each pair along s weighted, then the two along t, rounded half up once:
//!   C = (Σ T · w_s · w_t + 2^(2·weight-1)) >> 2·weight.
//! - Levels: C = (C1 · (2^lod_frac - f) + C2 · f + 2^(lod_frac-1)) >> lod_frac.

//! - Environment (OpenGL 2.1's glTexEnv, section 3.13): the fragment's lit colour Cf
//!   (alpha 255) with the filtered texel Cs, the environment colour Cc transparent black as
//!   GL's default; each product of two 8-bit colours rounded to nearest ([`mul255`]).
use fx::TexFormats;
use texture::{EnvMode, TexelFormat, Weights};

/// A decoded texel or a filtered colour: R, G, B, A in 0..=255.
pub type Rgba8 = [u8; 4];

/// The channels of `word` in `format`, each widened to 8 bits.
pub fn decode(format: TexelFormat, word: u32) -> Rgba8 {
    let mut rgba = [255u8; 4];
    let mut rest = word;
    for (c, bits) in rgba.iter_mut().zip(format.bits()).rev().filter(|&(_, bits)| bits > 0) {
        let code = rest & ((1 << bits) - 1);
        rest >>= bits;
        let mut wide = 0u32;
        let mut filled = 0;
        while filled < 8 {
            wide = (wide << bits) | code;
            filled += bits;
        }
        *c = (wide >> (filled - 8)) as u8;
    }
    rgba
}

/// The Gaussian-approximating weight table: entry x = round((3a² - 2a³) · 2^weight) for
/// a = x / 2^subtexel, in 0..=2^weight. The RTL's ROM holds the same entries.
pub fn gaussian_table(f: &TexFormats) -> Vec<u32> {
    let n = 1u32 << f.subtexel;
    (0..n)
        .map(|x| {
            let a = f64::from(x) / f64::from(n);
            (a * a * (3.0 - 2.0 * a) * f64::from(1u32 << f.weight)).round() as u32
        })
        .collect()
}

/// The weight of the second texel of a pair at fraction `alpha` (`subtexel` bits).
pub fn weight(f: &TexFormats, weights: Weights, gaussian: &[u32], alpha: u32) -> u32 {
    match weights {
        Weights::Linear if f.subtexel >= f.weight => alpha >> (f.subtexel - f.weight),
        Weights::Linear => alpha << (f.weight - f.subtexel),
        Weights::Gaussian => gaussian[alpha as usize],
    }
}

/// One pixel's texels as the filter takes them: up to two levels' 2x2 footprints (texture
/// memory words `[T(i0, j0), T(i1, j0), T(i0, j1), T(i1, j1)]`; a nearest sample's one texel
/// four times with zero fractions), each level's fractions alpha and beta (`subtexel`
/// bits), and the second level's weight `frac` (`lod_frac` bits) when there are two.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FilterIn {
    pub words: [[u32; 4]; 2],
    pub alpha: [u32; 2],
    pub beta: [u32; 2],
    pub frac: u32,
    pub two_levels: bool,
}

/// The filtered texel Cs of `x`: each level's words decoded from `format` and mixed
/// bilinearly with `weights`, the two levels blended when there are two.
pub fn texel(f: &TexFormats, format: TexelFormat, weights: Weights, gaussian: &[u32], x: &FilterIn) -> Rgba8 {
    let level = |k: usize| {
        let (a, b) = (weight(f, weights, gaussian, x.alpha[k]), weight(f, weights, gaussian, x.beta[k]));
        bilinear(f, x.words[k].map(|w| decode(format, w)), a, b)
    };
    if x.two_levels {
        between_levels(f, level(0), level(1), x.frac)
    } else {
        level(0)
    }
}

/// The bilinear mix of texels `[T(i0, j0), T(i1, j0), T(i0, j1), T(i1, j1)]` with weights
/// `a` (along s) and `b` (along t) of the second of each pair.
pub fn bilinear(f: &TexFormats, texels: [Rgba8; 4], a: u32, b: u32) -> Rgba8 {
    let one = 1u64 << f.weight;
    let (a, b) = (u64::from(a), u64::from(b));
    let w = [(one - a) * (one - b), a * (one - b), (one - a) * b, a * b];
    let mut out = [0u8; 4];
    for (k, c) in out.iter_mut().enumerate() {
        let sum: u64 = texels.iter().zip(w).map(|(t, w)| u64::from(t[k]) * w).sum();
        *c = ((sum + (1 << (2 * f.weight - 1))) >> (2 * f.weight)) as u8;
    }
    out
}

/// The blend of two levels' colours, `frac` (`lod_frac` bits) the weight of the second.
pub fn between_levels(f: &TexFormats, c1: Rgba8, c2: Rgba8, frac: u32) -> Rgba8 {
    let one = 1u32 << f.lod_frac;
    let mut out = [0u8; 4];
    for (k, c) in out.iter_mut().enumerate() {
        let sum = u32::from(c1[k]) * (one - frac) + u32::from(c2[k]) * frac;
        *c = ((sum + (one >> 1)) >> f.lod_frac) as u8;
    }
    out
}

/// round(p / 255) for p in 0..=255 · 255 (the sum of two products whose weights add to 255
/// too): (p + 128 + ((p + 128) >> 8)) >> 8, exact in that range.
pub fn div255(p: u32) -> u8 {
    let p = p + 128;
    ((p + (p >> 8)) >> 8) as u8
}

/// round(x · y / 255).
pub fn mul255(x: u8, y: u8) -> u8 {
    div255(u32::from(x) * u32::from(y))
}

/// The texture environment `mode` of fragment colour `cf` and texel colour `cs`:
/// REPLACE Cs; MODULATE Cf · Cs; DECAL Cf (1 - As) + Cs As (alpha Af); BLEND Cf (1 - Cs)
/// (+ Cc Cs, 0), alpha Af · As; ADD min(Cf + Cs, 1), alpha Af · As.
pub fn environment(mode: EnvMode, cf: Rgba8, cs: Rgba8) -> Rgba8 {
    let colour = |k: usize| match mode {
        EnvMode::Replace => cs[k],
        EnvMode::Modulate => mul255(cf[k], cs[k]),
        EnvMode::Decal => div255(u32::from(cf[k]) * u32::from(255 - cs[3]) + u32::from(cs[k]) * u32::from(cs[3])),
        EnvMode::Blend => mul255(cf[k], 255 - cs[k]),
        EnvMode::Add => cf[k].saturating_add(cs[k]),
    };
    let alpha = match mode {
        EnvMode::Replace => cs[3],
        EnvMode::Decal => cf[3],
        EnvMode::Modulate | EnvMode::Blend | EnvMode::Add => mul255(cf[3], cs[3]),
    };
    [colour(0), colour(1), colour(2), alpha]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decode_replicates_bits_to_within_0_72_lsb() {
        for format in TexelFormat::ALL {
            let bits = format.bits();
            for c in [0u32, 1, 5, 9, 15, 31, 63, 255] {
                let word = bits.iter().fold(0u32, |w, &b| if b == 0 { w } else { (w << b) | (c & ((1 << b) - 1)) });
                let got = decode(format, word);
                for (k, &b) in bits.iter().enumerate() {
                    let want =
                        if b == 0 { 255.0 } else { f64::from(c & ((1 << b) - 1)) * 255.0 / f64::from((1 << b) - 1) };
                    assert!((f64::from(got[k]) - want).abs() <= 0.72, "{format:?} channel {k} code {c}: {}", got[k]);
                }
            }
        }
    }

    #[test]
    fn div255_rounds_exactly() {
        for p in 0..=255 * 255 {
            assert_eq!(u32::from(div255(p)), (2 * p + 255) / 510, "{p}");
        }
    }
}
