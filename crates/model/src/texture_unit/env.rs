//! The texture environment (OpenGL 2.1's glTexEnv, section 3.13) in 8-bit fixed point: the
//! fragment's lit colour Cf (alpha 255) with the filtered texel Cs, the environment colour
//! Cc transparent black as GL's default. Each product of two 8-bit colours is rounded to
//! nearest: x · y / 255 exactly rounded ([`mul255`]).

use super::filter::Rgba8;
use texture::EnvMode;

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
    fn div255_rounds_exactly() {
        for p in 0..=255 * 255 {
            assert_eq!(u32::from(div255(p)), (2 * p + 255) / 510, "{p}");
        }
    }
}
