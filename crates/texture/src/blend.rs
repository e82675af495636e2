//! Framebuffer blending: how a fragment's colour combines with the colour already stored.
//!
//! Paper 001 names six blend modes without listing them; [`BlendMode`] is the six Direct3D /
//! OpenGL blend setups edgepaint chooses, each an OpenGL blend function pair under the
//! blend equation FUNC_ADD (OpenGL 4.6 section 17.3.6): result = src · S + dst · D.

use serde::{Deserialize, Serialize};

use crate::image::Rgba;

/// A blend mode: source and destination factors of OpenGL's glBlendFunc.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BlendMode {
    /// No blending, src (GL_ONE, GL_ZERO).
    #[default]
    Opaque,
    /// Transparency, src As + dst (1 - As) (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA).
    Alpha,
    /// src + dst (GL_ONE, GL_ONE).
    Additive,
    /// src dst (GL_DST_COLOR, GL_ZERO).
    Multiply,
    /// src + dst (1 - As), for colours premultiplied by alpha (GL_ONE, GL_ONE_MINUS_SRC_ALPHA).
    PremultipliedAlpha,
    /// src As + dst (GL_SRC_ALPHA, GL_ONE).
    AlphaAdditive,
}

/// An OpenGL blend factor (OpenGL 4.6 section 17.3.6.2), the ones [`BlendMode`] uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlendFactor {
    /// GL_ZERO: 0.
    Zero,
    /// GL_ONE: 1.
    One,
    /// GL_SRC_ALPHA: As.
    SrcAlpha,
    /// GL_ONE_MINUS_SRC_ALPHA: 1 - As.
    OneMinusSrcAlpha,
    /// GL_DST_COLOR: the destination's channel itself (Rd, Gd, Bd, Ad).
    DstColor,
}

impl BlendFactor {
    /// The factor's value for channel `k` (0..4: R, G, B, A).
    pub fn value(self, src: Rgba, dst: Rgba, k: usize) -> f64 {
        match self {
            BlendFactor::Zero => 0.0,
            BlendFactor::One => 1.0,
            BlendFactor::SrcAlpha => src[3],
            BlendFactor::OneMinusSrcAlpha => 1.0 - src[3],
            BlendFactor::DstColor => dst[k],
        }
    }
}

impl BlendMode {
    /// The source and destination factors (glBlendFunc's sfactor, dfactor).
    pub fn factors(self) -> (BlendFactor, BlendFactor) {
        use BlendFactor::*;
        match self {
            BlendMode::Opaque => (One, Zero),
            BlendMode::Alpha => (SrcAlpha, OneMinusSrcAlpha),
            BlendMode::Additive => (One, One),
            BlendMode::Multiply => (DstColor, Zero),
            BlendMode::PremultipliedAlpha => (One, OneMinusSrcAlpha),
            BlendMode::AlphaAdditive => (SrcAlpha, One),
        }
    }
}

/// The colour stored when fragment colour `src` is blended onto framebuffer colour `dst`: per
/// channel (alpha included, as glBlendFunc does) src · S + dst · D, clamped to [0, 1].
pub fn blend(mode: BlendMode, src: Rgba, dst: Rgba) -> Rgba {
    let (s, d) = mode.factors();
    std::array::from_fn(|k| (src[k] * s.value(src, dst, k) + dst[k] * d.value(src, dst, k)).clamp(0.0, 1.0))
}
