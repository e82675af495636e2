//! Scene and mesh input, built-in models, the software geometry stage, and the
//! trilist v1 screen-space exchange format.

pub mod error;
pub mod input;
pub mod scene;
pub mod trilist;

pub use error::{Error, Result};
pub use input::Input;
pub use scene::Scene;
pub use trilist::{Triangle, Trilist, Vertex, MAX_RESOLUTION};
