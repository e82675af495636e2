//! Scene files (placeholder; the scene work replaces this module).
use crate::{Result, Trilist};
use std::path::Path;

/// A scene: resolution, background, camera, lights and objects.
pub struct Scene {
    pub width: u32,
    pub height: u32,
    /// Background colour in [0, 255].
    pub background: [f64; 3],
    /// Whether the scene asks for back faces to be culled.
    pub cull_back: bool,
}

impl Scene {
    /// Reads and validates a scene file; OBJ paths are relative to its folder.
    pub fn load(_path: &Path) -> Result<Scene> {
        todo!()
    }
    /// Parses a scene from JSON text; OBJ paths are relative to `base_dir`.
    pub fn from_value(_raw: &serde_json::Value, _base_dir: &Path) -> Result<Scene> {
        todo!()
    }
    /// Runs the geometry stage: the screen-space triangles, with w.
    pub fn to_trilist(&self) -> Result<Trilist> {
        todo!()
    }
}
