//! Judging a texturing implementation's colour the way the OpenGL and Vulkan conformance
//! tests judge texture filtering (`../shared/PRECISION.md`): against this crate's float
//! reference at the same level-of-detail rule, with a tolerance in 8-bit LSBs, and with
//! the neighbouring level or texel choices allowed where the pixel lies close to a
//! boundary between them.
//!
//! - A pixel whose lambda is more than [`LEVEL_MARGIN`] from a level boundary and whose
//!   texel coordinates are more than [`TEXEL_MARGIN`] texel from a texel boundary must be
//!   within [`tolerance_lsb`] of the reference in every channel.
//! - Any other pixel must be within that tolerance of the reference at one of the
//!   neighbouring choices: lambda moved by the margin either way, each coordinate near a
//!   boundary moved by the texel margin either way.
//!
//! Level boundaries are lambda = 0 (magnification against minification) and, with the
//! nearest mipmap, lambda = k + 1/2. Texel boundaries are where u (nearest) or u - 1/2
//! (linear) is an integer, u = s times the level's width (likewise t).

use crate::env::{environment, EnvMode};
use crate::lod::{level_choice, LevelChoice, MipMode};
use crate::mip::MipChain;
use crate::sample::{sample, Filter, Sampler};

/// How close to a level boundary a pixel's lambda may be and still choose either side:
/// 2^-6.
pub const LEVEL_MARGIN: f64 = 1.0 / 64.0;

/// How close to a texel boundary a texel coordinate may be and still choose either side:
/// 2^-7 texel.
pub const TEXEL_MARGIN: f64 = 1.0 / 128.0;

/// Where a pixel is sampled: texture coordinates and level of detail (by the design's rule).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Probe {
    /// Texture coordinate s.
    pub s: f64,
    /// Texture coordinate t.
    pub t: f64,
    /// Level of detail, log2 rho.
    pub lambda: f64,
}

/// The reference colour of a pixel, 0..255 per channel: the sample at `p` through the
/// texture environment `env` with the fragment's colour `cf` (0..255, alpha 1, the
/// environment colour transparent black).
pub fn reference(chain: &MipChain, sampler: &Sampler, env: EnvMode, cf: [f64; 3], p: Probe) -> [f64; 3] {
    let cs = sample(chain, sampler, p.s, p.t, p.lambda);
    let c = environment(env, [cf[0] / 255.0, cf[1] / 255.0, cf[2] / 255.0, 1.0], cs, [0.0; 4]);
    [c[0] * 255.0, c[1] * 255.0, c[2] * 255.0]
}

/// The tolerance in LSB at a level choice: 3 for a bilinear filter, 1 for nearest, plus 1
/// for each fixed-point blend multiply (between two levels; the MODULATE, DECAL and BLEND
/// environments).
pub fn tolerance_lsb(sampler: &Sampler, env: EnvMode, choice: LevelChoice) -> f64 {
    let filter = if choice == LevelChoice::Magnify { sampler.mag } else { sampler.min };
    let base = match filter {
        Filter::Linear => 3.0,
        Filter::Nearest => 1.0,
    };
    let levels = f64::from(matches!(choice, LevelChoice::Blend { .. }) as u8);
    let env = f64::from(matches!(env, EnvMode::Modulate | EnvMode::Decal | EnvMode::Blend) as u8);
    base + levels + env
}

/// Why a colour failed: the reference, the colour judged and the largest channel error
/// against the nearest allowed result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Miss {
    /// The allowed result nearest the colour judged.
    pub reference: [f64; 3],
    /// The colour judged.
    pub got: [u8; 3],
    /// Its largest channel error against `reference`.
    pub error_lsb: f64,
    /// The tolerance there.
    pub tolerance_lsb: f64,
}

/// Judges `got`, the colour an implementation gave a pixel probed at `p`: Ok, or the miss.
pub fn check(
    chain: &MipChain,
    sampler: &Sampler,
    env: EnvMode,
    cf: [f64; 3],
    p: Probe,
    got: [u8; 3],
) -> Result<(), Miss> {
    let levels = chain.levels().len();
    let near_level = |lambda: f64| {
        let mut boundaries = vec![0.0];
        if sampler.mip == MipMode::Nearest {
            boundaries.extend((0..levels.saturating_sub(1)).map(|k| k as f64 + 0.5));
        }
        boundaries.iter().any(|b| (lambda - b).abs() <= LEVEL_MARGIN)
    };
    let lambdas: Vec<f64> = if near_level(p.lambda) {
        vec![p.lambda, p.lambda - LEVEL_MARGIN, p.lambda + LEVEL_MARGIN]
    } else {
        vec![p.lambda]
    };
    let mut nearest = Miss { reference: [0.0; 3], got, error_lsb: f64::INFINITY, tolerance_lsb: 0.0 };
    for &lambda in &lambdas {
        let choice = level_choice(lambda, sampler.mip, levels);
        let (d, filter) = match choice {
            LevelChoice::Magnify => (0, sampler.mag),
            LevelChoice::Level(d) => (d, sampler.min),
            LevelChoice::Blend { d1, .. } => (d1, sampler.min),
        };
        let level = &chain.levels()[d];
        let offsets = |coord: f64, size: u32| {
            let u = coord * f64::from(size) - if filter == Filter::Linear { 0.5 } else { 0.0 };
            let step = TEXEL_MARGIN / f64::from(size);
            if (u - u.round()).abs() <= TEXEL_MARGIN {
                vec![0.0, -step, step]
            } else {
                vec![0.0]
            }
        };
        let tolerance = tolerance_lsb(sampler, env, choice);
        for ds in offsets(p.s, level.width()) {
            for dt in offsets(p.t, level.height()) {
                let want = reference(chain, sampler, env, cf, Probe { s: p.s + ds, t: p.t + dt, lambda });
                let error = want.iter().zip(got).map(|(w, g)| (w - f64::from(g)).abs()).fold(0.0, f64::max);
                if error <= tolerance {
                    return Ok(());
                }
                if error < nearest.error_lsb {
                    nearest = Miss { reference: want, got, error_lsb: error, tolerance_lsb: tolerance };
                }
            }
        }
    }
    Err(nearest)
}
