//! Scene and mesh input, built-in models, the software geometry stage, and the
//! trilist screen-space exchange format (v1, and v2 with textures).
//!
//! A [`Scene`] (read from a JSON scene file, see [`scene`]) becomes a
//! [`Trilist`] through [`Scene::to_trilist`], the [`geometry`] stage that paper
//! 001 runs in software: transform, light, project, clip to the guard band.

pub mod builtin;
pub mod error;
pub mod geometry;
pub mod input;
mod math;
pub mod measure;
pub mod mesh;
pub mod scene;
pub mod shipped;
pub mod stress;
pub mod trilist;

pub use error::{Error, Result};
pub use geometry::{guard_band, GuardBand, GUARD_Z_MAX, GUARD_Z_MIN};
pub use input::Input;
pub use mesh::{Mesh, MeshVertex};
pub use scene::Scene;
pub use trilist::{Tex, TextureRef, TextureSpec, Triangle, Trilist, Vertex, MAX_RESOLUTION};
