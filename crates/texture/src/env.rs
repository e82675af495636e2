//! The texture environment: how the texture colour combines with the fragment's colour.
//!
//! OpenGL 4.6's core profile has no fixed-function texture environment; these are the
//! functions of OpenGL 2.1's glTexEnv (reference page, GL_TEXTURE_ENV_MODE, the table for an
//! RGBA texture; for an RGB texture As = 1 and the same formulas hold).

use serde::{Deserialize, Serialize};

use crate::image::Rgba;

/// A texture function (GL_TEXTURE_ENV_MODE). Cf is the fragment's (primary) colour, Cs the
/// texture's, Cc the environment colour (GL_TEXTURE_ENV_COLOR).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EnvMode {
    /// GL_REPLACE: C = Cs, A = As.
    Replace,
    /// GL_MODULATE: C = Cf Cs, A = Af As.
    #[default]
    Modulate,
    /// GL_DECAL: C = Cf (1 - As) + Cs As, A = Af.
    Decal,
    /// GL_BLEND: C = Cf (1 - Cs) + Cc Cs, A = Af As.
    Blend,
    /// GL_ADD: C = min(1, Cf + Cs), A = Af As.
    Add,
}

/// The textured colour of a fragment of colour `cf` with texture colour `cs` under `mode`;
/// `cc` is the environment colour (only [`EnvMode::Blend`] reads it, and not its alpha).
pub fn environment(mode: EnvMode, cf: Rgba, cs: Rgba, cc: Rgba) -> Rgba {
    let colour = |k: usize| match mode {
        EnvMode::Replace => cs[k],
        EnvMode::Modulate => cf[k] * cs[k],
        EnvMode::Decal => cf[k] * (1.0 - cs[3]) + cs[k] * cs[3],
        EnvMode::Blend => cf[k] * (1.0 - cs[k]) + cc[k] * cs[k],
        EnvMode::Add => (cf[k] + cs[k]).min(1.0),
    };
    let alpha = match mode {
        EnvMode::Replace => cs[3],
        EnvMode::Decal => cf[3],
        EnvMode::Modulate | EnvMode::Blend | EnvMode::Add => cf[3] * cs[3],
    };
    [colour(0), colour(1), colour(2), alpha]
}
