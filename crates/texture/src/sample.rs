//! Texture sampling: texel selection and filtering within a level (OpenGL 4.6 section 8.14.2)
//! and across the levels of a mipmap chain (section 8.14.3).

use serde::{Deserialize, Serialize};

use crate::image::{weighted_sum, Rgba, Texture};
use crate::lod::{level_choice, LevelChoice, MipMode};
use crate::mip::MipChain;
use crate::wrap::Wrap;

/// The filter within one level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Filter {
    /// GL_NEAREST: the texel (wrap(floor(u)), wrap(floor(v))).
    Nearest,
    /// GL_LINEAR: the 2x2 texels around (u - 1/2, v - 1/2), weighted bilinearly.
    #[default]
    Linear,
}

/// The curve giving a bilinear filter its weights from the fractions alpha and beta.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Weights {
    /// OpenGL's weights: alpha and beta themselves.
    #[default]
    Linear,
    /// Paper 001's weights approximating a Gaussian (its Fig. 6), in edgepaint's reading of the
    /// figure: the S-shaped curve 3a² - 2a³ through (0, 0), (1/2, 1/2) and (1, 1).
    Gaussian,
}

impl Weights {
    /// The weight of the second texel of a pair at fraction `a` in [0, 1] (the first gets
    /// 1 - weight).
    pub fn weight(self, a: f64) -> f64 {
        match self {
            Weights::Linear => a,
            Weights::Gaussian => a * a * (3.0 - 2.0 * a),
        }
    }
}

/// How a texture is sampled: the sampler state of OpenGL 4.6 section 8.14 plus 001's weights.
///
/// The default is bilinear within the nearest level (GL_LINEAR_MIPMAP_NEAREST minification,
/// GL_LINEAR magnification), linear weights, GL_REPEAT on both axes. In JSON every field may
/// be left out (it takes its default), e.g. `{"mip": "linear", "wrap_s": "mirrored_repeat"}`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Sampler {
    /// The filter within a level when minified.
    pub min: Filter,
    /// The filter when magnified (always on level 0).
    pub mag: Filter,
    /// Whether and how minification uses the mipmap levels.
    pub mip: MipMode,
    /// The wrap mode along s (texel columns).
    pub wrap_s: Wrap,
    /// The wrap mode along t (texel rows).
    pub wrap_t: Wrap,
    /// The bilinear weights' curve.
    pub weights: Weights,
}

/// One texel a sample reads: level, column, row and weight.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tap {
    /// The mipmap level.
    pub level: usize,
    /// The texel's column.
    pub i: u32,
    /// The texel's row (from the bottom).
    pub j: u32,
    /// Its weight in the sample; the weights of a footprint are >= 0 and sum to 1.
    pub weight: f64,
}

/// The texels a sample reads and their weights: what a tolerance checker compares against.
#[derive(Debug, Clone, PartialEq)]
pub struct Footprint {
    /// The levels chosen.
    pub choice: LevelChoice,
    /// The texels read: 1 (nearest) or 4 (linear) per level, coinciding texels repeated and
    /// zero weights kept.
    pub taps: Vec<Tap>,
}

impl Footprint {
    /// The sampled colour: the weighted sum of the taps' texels in `chain`, the chain the
    /// footprint was made for (panics if a tap lies outside it).
    pub fn colour(&self, chain: &MipChain) -> Rgba {
        weighted_sum(self.taps.iter().map(|tap| (chain.levels()[tap.level].texel(tap.i, tap.j), tap.weight)))
    }
}

/// The footprint of a sample at texture coordinates (s, t) and level of detail `lambda`: the
/// levels [`level_choice`] picks, each filtered with the magnification or minification filter
/// as [`sample_level`] does, and weighted (1 - frac, frac) when two levels are blended.
pub fn footprint(chain: &MipChain, sampler: &Sampler, s: f64, t: f64, lambda: f64) -> Footprint {
    let choice = level_choice(lambda, sampler.mip, chain.levels().len());
    let (filter, levels) = match choice {
        LevelChoice::Magnify => (sampler.mag, vec![(0, 1.0)]),
        LevelChoice::Level(d) => (sampler.min, vec![(d, 1.0)]),
        LevelChoice::Blend { d1, frac } => (sampler.min, vec![(d1, 1.0 - frac), (d1 + 1, frac)]),
    };
    let taps = levels
        .into_iter()
        .flat_map(|(level, weight)| {
            let texture = &chain.levels()[level];
            level_taps(texture, filter, sampler, s, t).into_iter().map(move |(i, j, w)| Tap {
                level,
                i,
                j,
                weight: weight * w,
            })
        })
        .collect();
    Footprint { choice, taps }
}

/// The sampled colour at (s, t) and level of detail `lambda`: [`footprint`]'s colour.
pub fn sample(chain: &MipChain, sampler: &Sampler, s: f64, t: f64, lambda: f64) -> Rgba {
    footprint(chain, sampler, s, t, lambda).colour(chain)
}

/// The colour at (s, t) of one level, of size w x h, by `filter` with `sampler`'s wrap
/// modes and weights (OpenGL 4.6 section 8.14.2), with u = s · w and v = t · h:
/// - [`Filter::Nearest`]: texel (wrap_s(floor(u)), wrap_t(floor(v))).
/// - [`Filter::Linear`]: i0 = wrap_s(floor(u - 1/2)), i1 = wrap_s(floor(u - 1/2) + 1),
///   alpha = frac(u - 1/2), and likewise j0, j1, beta along v; the colour is
///   (1 - a)(1 - b) T[i0, j0] + a(1 - b) T[i1, j0] + (1 - a) b T[i0, j1] + a b T[i1, j1]
///   with a = `weights`(alpha) and b = `weights`(beta).
///
/// A non-finite u or v (a NaN or infinite coordinate, or one so large the product
/// overflows) is taken as 0.
pub fn sample_level(level: &Texture, filter: Filter, sampler: &Sampler, s: f64, t: f64) -> Rgba {
    weighted_sum(level_taps(level, filter, sampler, s, t).into_iter().map(|(i, j, w)| (level.texel(i, j), w)))
}

/// The texels (i, j) and weights [`sample_level`] reads.
fn level_taps(level: &Texture, filter: Filter, sampler: &Sampler, s: f64, t: f64) -> Vec<(u32, u32, f64)> {
    let (wrap_s, wrap_t, weights) = (sampler.wrap_s, sampler.wrap_t, sampler.weights);
    let across = axis(s, level.width(), filter, wrap_s, weights);
    let up = axis(t, level.height(), filter, wrap_t, weights);
    up.iter().flat_map(|&(j, b)| across.iter().map(move |&(i, a)| (i, j, a * b))).collect()
}

/// The texel indices and weights along one axis of `size` texels at coordinate `coord`.
fn axis(coord: f64, size: u32, filter: Filter, wrap: Wrap, weights: Weights) -> Vec<(u32, f64)> {
    let u = coord * f64::from(size);
    let u = if u.is_finite() { u } else { 0.0 };
    match filter {
        Filter::Nearest => vec![(wrap.index(u.floor() as i64, size), 1.0)],
        Filter::Linear => {
            let i0 = (u - 0.5).floor();
            let a = weights.weight(u - 0.5 - i0);
            vec![(wrap.index(i0 as i64, size), 1.0 - a), (wrap.index((i0 + 1.0) as i64, size), a)]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_reads_the_pair_around_u_minus_one_half() {
        // u = 1.25: u - 1/2 = 0.75, texels 0 and 1 weighted 1/4 and 3/4.
        assert_eq!(axis(0.3125, 4, Filter::Linear, Wrap::Repeat, Weights::Linear), [(0, 0.25), (1, 0.75)]);
        // u = 0: texels -1 (wrapped) and 0, half each.
        assert_eq!(axis(0.0, 4, Filter::Linear, Wrap::Repeat, Weights::Linear), [(3, 0.5), (0, 0.5)]);
        assert_eq!(axis(0.0, 4, Filter::Linear, Wrap::ClampToEdge, Weights::Linear), [(0, 0.5), (0, 0.5)]);
        assert_eq!(axis(0.99, 4, Filter::Nearest, Wrap::Repeat, Weights::Linear), [(3, 1.0)]);
        for bad in [f64::NAN, f64::INFINITY, f64::MAX] {
            assert_eq!(axis(bad, 4, Filter::Linear, Wrap::Repeat, Weights::Linear), [(3, 0.5), (0, 0.5)]);
        }
    }
}
