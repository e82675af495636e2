//! Framebuffer blending (paper 001 section II-5's six blend modes) in 8-bit fixed point:
//! bit-exact model of the RTL unit `blend`.
//!
//! Each mode is an OpenGL blend function pair under the blend equation FUNC_ADD (OpenGL 4.6
//! section 17.3.6, `texture::BlendMode`): per channel, alpha included, C = Cs · S + Cd · D
//! with Cs the fragment's (source) channel, Cd the framebuffer's (destination) and As the
//! source alpha, all in 0..=255 standing for 0..1:
//!
//! | mode | S, D | C |
//! |---|---|---|
//! | opaque | ONE, ZERO | Cs |
//! | alpha | SRC_ALPHA, ONE_MINUS_SRC_ALPHA | round((Cs · As + Cd · (255 - As)) / 255) |
//! | additive | ONE, ONE | min(Cs + Cd, 255) |
//! | multiply | DST_COLOR, ZERO | round(Cs · Cd / 255) |
//! | premultiplied alpha | ONE, ONE_MINUS_SRC_ALPHA | min(Cs + round(Cd · (255 - As) / 255), 255) |
//! | alpha additive | SRC_ALPHA, ONE | min(round(Cs · As / 255) + Cd, 255) |
//!
//! Every product is rounded to nearest once ([`div255`], [`mul255`], exact; alpha's two
//! products are summed before it), and a sum past 255 saturates, as GL clamps to [0, 1]:
//! each channel is the float blend's result times 255 rounded to nearest (a quotient by 255
//! is never a tie), so the model is exactly `texture::blend` rounded to 8 bits.

use crate::texture_filter::{div255, mul255, Rgba8};
use texture::BlendMode;

/// The six modes in `texture::BlendMode`'s declaration order: a mode's index is its code at
/// the RTL unit's `mode` port.
pub const MODES: [BlendMode; 6] = [
    BlendMode::Opaque,
    BlendMode::Alpha,
    BlendMode::Additive,
    BlendMode::Multiply,
    BlendMode::PremultipliedAlpha,
    BlendMode::AlphaAdditive,
];

/// A worked example, by hand: source (200, 30, 160) at alpha 128 onto (60, 120, 200, 255)...
pub const WORKED_SRC_DST: (Rgba8, Rgba8) = ([200, 30, 160, 128], [60, 120, 200, 255]);

/// ... gives, in each mode (the unit's and the model's tests check both against it):
pub const WORKED: [(BlendMode, Rgba8); 6] = [
    (BlendMode::Opaque, [200, 30, 160, 128]),
    // (200·128 + 60·127) / 255 = 130.27; (30·128 + 120·127) / 255 = 74.82;
    // (160·128 + 200·127) / 255 = 179.92; (128·128 + 255·127) / 255 = 191.25.
    (BlendMode::Alpha, [130, 75, 180, 191]),
    (BlendMode::Additive, [255, 150, 255, 255]),
    // 200·60 / 255 = 47.06; 30·120 / 255 = 14.12; 160·200 / 255 = 125.49; 128.
    (BlendMode::Multiply, [47, 14, 125, 128]),
    // 200 + 60·127/255 = 200 + 29.88; 30 + 59.76; 160 + 99.61; 128 + 127.
    (BlendMode::PremultipliedAlpha, [230, 90, 255, 255]),
    // 200·128/255 = 100.39 + 60; 30·128/255 = 15.06 + 120; 80.31 + 200; 64.25 + 255.
    (BlendMode::AlphaAdditive, [160, 135, 255, 255]),
];

/// Fragment colour `src` blended onto framebuffer colour `dst` by `mode`, per channel
/// (alpha with its own channel, as glBlendFunc blends it); the table of the module's docs.
pub fn blend(mode: BlendMode, src: Rgba8, dst: Rgba8) -> Rgba8 {
    let a = src[3];
    std::array::from_fn(|k| {
        let (s, d) = (src[k], dst[k]);
        match mode {
            BlendMode::Opaque => s,
            BlendMode::Alpha => div255(u32::from(s) * u32::from(a) + u32::from(d) * u32::from(255 - a)),
            BlendMode::Additive => s.saturating_add(d),
            BlendMode::Multiply => mul255(s, d),
            BlendMode::PremultipliedAlpha => s.saturating_add(mul255(d, 255 - a)),
            BlendMode::AlphaAdditive => mul255(s, a).saturating_add(d),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The float blend of 8-bit colours, times 255, unrounded.
    fn float(mode: BlendMode, src: Rgba8, dst: Rgba8) -> [f64; 4] {
        let unit = |c: Rgba8| c.map(|v| f64::from(v) / 255.0);
        texture::blend(mode, unit(src), unit(dst)).map(|v| v * 255.0)
    }

    #[test]
    fn blend_is_the_float_blend_rounded_for_every_colour_alpha_and_mode() {
        // A colour channel depends on (Cs, Cd, As) alone: every one of the 2^24 triples,
        // in channel 0 (the other channels hold the same values: R, G, B are alike).
        for mode in MODES {
            for a in 0..=255u8 {
                for s in 0..=255u8 {
                    for d in 0..=255u8 {
                        let (src, dst) = ([s, s, s, a], [d, d, d, 0]);
                        let got = blend(mode, src, dst)[0];
                        let want = float(mode, src, dst)[0];
                        assert!(
                            (f64::from(got) - want).abs() < 0.5,
                            "{mode:?} Cs {s} Cd {d} As {a}: {got}, float {want}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn blend_alpha_channel_is_the_float_blend_rounded_for_every_pair() {
        // The alpha channel's source is As itself: every (As, Ad).
        for mode in MODES {
            for a in 0..=255u8 {
                for d in 0..=255u8 {
                    let (src, dst) = ([0, 0, 0, a], [0, 0, 0, d]);
                    let got = blend(mode, src, dst)[3];
                    let want = float(mode, src, dst)[3];
                    assert!((f64::from(got) - want).abs() < 0.5, "{mode:?} As {a} Ad {d}: {got}, float {want}");
                }
            }
        }
    }

    #[test]
    fn blend_hand_computed_values() {
        let (src, dst) = WORKED_SRC_DST;
        for (mode, want) in WORKED {
            assert_eq!(blend(mode, src, dst), want, "{mode:?}");
        }
    }

    #[test]
    fn blend_random_colours_within_half_an_lsb_of_the_float_blend() {
        let mut rng = ChaCha8Rng::seed_from_u64(crate::test_seed());
        for _ in 0..crate::test_count() {
            let (src, dst): (Rgba8, Rgba8) = (rng.gen(), rng.gen());
            for mode in MODES {
                let (got, want) = (blend(mode, src, dst), float(mode, src, dst));
                for k in 0..4 {
                    assert!(
                        (f64::from(got[k]) - want[k]).abs() < 0.5,
                        "{mode:?} {src:?} onto {dst:?}: channel {k} {}, float {}",
                        got[k],
                        want[k]
                    );
                }
            }
        }
    }
}
