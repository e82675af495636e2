//! Texture mapping as OpenGL defines it, in f64: the float reference that edgepaint's
//! fixed-point texture hardware is measured against.
//!
//! - [`Texture`] ([`image`](mod@image)): RGBA texels in [0, 1], row 0 at t = 0, loaded from PNG.
//! - [`MipChain`] ([`mip`]): the levels a 2x2 box filter makes down to 1x1.
//! - [`TexelFormat`] ([`mod@format`]): the five colour modes texels are stored in.
//! - [`Wrap`] ([`wrap`]): REPEAT, MIRRORED_REPEAT and CLAMP_TO_EDGE, OpenGL 4.6 section 8.14.2.
//! - [`rho_exact`], [`rho_max`], [`lambda`], [`level_choice`] ([`lod`]): the level of detail
//!   (section 8.14.1) and the choice of mipmap levels (section 8.14.3, magnification 8.15).
//! - [`sample()`] ([`mod@sample`]): nearest and bilinear texel selection and filtering (section 8.14.2).
//! - [`environment`] ([`mod@env`]): the texture environment of OpenGL 2.1's glTexEnv.
//! - [`blend()`] ([`mod@blend`]): framebuffer blending (OpenGL 4.6 section 17.3.6).
//! - [`conformance`]: judging an implementation's texels as the GL and Vulkan conformance
//!   tests judge texture filtering.
//!
//! The texture unit it models is that of paper "001" (Woo, Jang and Lee 2004, *Embedded 3D
//! Graphics Rendering Processor*), section II-5: texture coordinates divided by w per pixel
//! (its eq. (3); done by whoever supplies s and t), the level
//! L = log2 max(ds/dx, dt/dx, ds/dy, dt/dy) (its eq. (4), here [`rho_max`] and
//! [`LodRule::Max`]), a bilinear filter whose weights approximate a Gaussian (its Fig. 6, here
//! [`Weights::Gaussian`]), six blend modes ([`BlendMode`]) and five colour modes
//! ([`TexelFormat`]).
//!
//! No function panics on any f64 input: non-finite inputs have documented results.

#![warn(missing_docs)]

pub mod blend;
pub mod conformance;
pub mod env;
pub mod format;
pub mod image;
pub mod lod;
pub mod mip;
pub mod sample;
pub mod wrap;

pub use self::image::{Error, Rgba, Texture, MAX_SIDE};
pub use blend::{blend, BlendFactor, BlendMode};
pub use env::{environment, EnvMode};
pub use format::TexelFormat;
pub use lod::{lambda, level_choice, rho_exact, rho_max, LevelChoice, LodRule, MipMode};
pub use mip::MipChain;
pub use sample::{footprint, sample, sample_level, Filter, Footprint, Sampler, Tap, Weights};
pub use wrap::Wrap;
