//! Level of detail: the scale factor rho, lambda = log2 rho, and the mipmap levels lambda selects.

use serde::{Deserialize, Serialize};

/// The scale factor of OpenGL 4.6 section 8.14.1: the longer of the two screen-space derivative
/// vectors of (u, v), max(sqrt(dudx² + dvdx²), sqrt(dudy² + dvdy²)). u = s · width and
/// v = t · height are in texels of level 0.
pub fn rho_exact(dudx: f64, dvdx: f64, dudy: f64, dvdy: f64) -> f64 {
    dudx.hypot(dvdx).max(dudy.hypot(dvdy))
}

/// Paper 001's eq. (4) scale factor, max(|dudx|, |dvdx|, |dudy|, |dvdy|). It is conformant:
/// section 8.14.1 allows any f with max(|dudx|, |dudy|, |dvdx|, |dvdy|) <= f <= the sum of the
/// per-axis maxima, and this is the lower bound.
pub fn rho_max(dudx: f64, dvdx: f64, dudy: f64, dvdy: f64) -> f64 {
    dudx.abs().max(dvdx.abs()).max(dudy.abs()).max(dvdy.abs())
}

/// Which scale factor a texture unit computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LodRule {
    /// [`rho_exact`], OpenGL's reference.
    #[default]
    Exact,
    /// [`rho_max`], paper 001's eq. (4).
    Max,
}

impl LodRule {
    /// The scale factor of the derivatives (texels per pixel) under this rule.
    pub fn rho(self, dudx: f64, dvdx: f64, dudy: f64, dvdy: f64) -> f64 {
        match self {
            LodRule::Exact => rho_exact(dudx, dvdx, dudy, dvdy),
            LodRule::Max => rho_max(dudx, dvdx, dudy, dvdy),
        }
    }
}

/// The level of detail lambda = log2(rho) (section 8.14.1, without bias or clamps). rho = 0
/// gives -inf (magnification); a negative or NaN rho gives NaN, which [`level_choice`] takes as 0.
pub fn lambda(rho: f64) -> f64 {
    rho.log2()
}

/// Whether and how a minified texture uses its mipmaps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MipMode {
    /// No mipmapping (GL_NEAREST or GL_LINEAR minification): level 0 only.
    None,
    /// The nearest level (GL_*_MIPMAP_NEAREST).
    #[default]
    Nearest,
    /// The two nearest levels, blended linearly (GL_*_MIPMAP_LINEAR).
    Linear,
}

/// The level or levels a sample filters, and with which filter (section 8.14.3 and 8.15).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LevelChoice {
    /// lambda <= 0: magnified, the magnification filter on level 0.
    Magnify,
    /// Minified, the minification filter on this one level.
    Level(usize),
    /// Minified, the minification filter on levels `d1` and `d1 + 1`, giving
    /// (1 - `frac`) tau1 + `frac` tau2 with `frac` = frac(lambda).
    Blend {
        /// The finer level, floor(lambda).
        d1: usize,
        /// The weight of level `d1 + 1`.
        frac: f64,
    },
}

/// The levels a sample at level of detail `lambda` uses, in a chain of `levels` levels
/// (q = `levels` - 1 is the last; 0 levels count as 1; level_base is 0). OpenGL 4.6 section 8.14:
/// magnified when lambda <= 0, else minified. Minified, by section 8.14.3:
/// - [`MipMode::None`]: level 0.
/// - [`MipMode::Nearest`]: d = ceil(lambda + 1/2) - 1, clamped to [0, q].
/// - [`MipMode::Linear`]: level q alone when lambda >= q, else d1 = floor(lambda) and
///   d2 = d1 + 1 blended by frac(lambda).
///
/// A NaN lambda is taken as 0 (magnified); +inf selects level q, -inf magnifies.
pub fn level_choice(lambda: f64, mip: MipMode, levels: usize) -> LevelChoice {
    let q = levels.saturating_sub(1);
    if lambda.is_nan() || lambda <= 0.0 {
        return LevelChoice::Magnify;
    }
    match mip {
        MipMode::None => LevelChoice::Level(0),
        MipMode::Nearest => LevelChoice::Level(((lambda + 0.5).ceil() - 1.0).clamp(0.0, q as f64) as usize),
        MipMode::Linear if lambda >= q as f64 => LevelChoice::Level(q),
        MipMode::Linear => LevelChoice::Blend { d1: lambda.floor() as usize, frac: lambda - lambda.floor() },
    }
}
