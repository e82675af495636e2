//! What the CLI reads: a scene file or a trilist, told apart by their keys.

use crate::error::{parse_json, Error, Result};
use crate::{Scene, Trilist};
use std::path::Path;

/// A render input: either kind of file.
pub enum Input {
    Scene(Box<Scene>),
    Trilist(Trilist),
}

impl Input {
    /// Reads `path` and decides what it is: a trilist has `triangles`, a scene has `objects`.
    pub fn load(path: &Path) -> Result<Input> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let raw: serde_json::Value = parse_json(&text).map_err(|e| e.in_file(path))?;
        let base = path.parent().unwrap_or(Path::new("."));
        let input = if raw.get("triangles").is_some() {
            Trilist::from_value(&raw, base).map(Input::Trilist)
        } else if raw.get("objects").is_some() {
            Scene::from_value(&raw, base).map(|s| Input::Scene(Box::new(s)))
        } else {
            Err(Error::invalid("neither a scene (no \"objects\") nor a trilist (no \"triangles\")"))
        };
        input.map_err(|e| e.in_file(path))
    }
}
