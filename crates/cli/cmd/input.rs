//! Reading a render input (scene or trilist) into a triangle list.

use anyhow::{bail, Context, Result};
use scene::{Input, Trilist};
use std::path::Path;

/// A parsed `WxH` size.
#[derive(Clone, Copy, Debug)]
pub struct Size {
    pub width: u32,
    pub height: u32,
}

impl std::str::FromStr for Size {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("\"{s}\" is not WIDTHxHEIGHT, e.g. 320x240"))?;
        let n = |t: &str| t.trim().parse::<u32>().map_err(|_| format!("\"{t}\" in \"{s}\" is not a whole number"));
        let size = Size { width: n(w)?, height: n(h)? };
        scene::trilist::check_resolution(size.width, size.height).map_err(|e| e.to_string())?;
        Ok(size)
    }
}

/// What a scene asks of the renderer beyond its triangles.
pub struct Loaded {
    pub trilist: Trilist,
    pub background: [f64; 3],
    pub cull_back: bool,
}

/// Loads a scene (running the geometry stage) or a trilist. `size` overrides a
/// scene's resolution; a trilist's coordinates are fixed, so it cannot be resized.
pub fn load(path: &Path, size: Option<Size>) -> Result<Loaded> {
    match Input::load(path)? {
        Input::Scene(s) => {
            let s = match size {
                Some(z) => s.with_size(z.width, z.height).map_err(|e| e.in_file(path))?,
                None => *s,
            };
            let trilist = s.to_trilist().map_err(|e| e.in_file(path))?;
            Ok(Loaded { trilist, background: s.background, cull_back: s.cull_back })
        }
        Input::Trilist(t) => {
            if size.is_some() {
                bail!("{}: --size applies to scenes; a trilist's coordinates are already in pixels", path.display());
            }
            Ok(Loaded { trilist: t, background: [0.0; 3], cull_back: false })
        }
    }
}

/// Writes `bytes` produced by `what` to `path`, naming both on failure.
pub fn write(path: &Path, what: &str, bytes: &[u8]) -> Result<()> {
    std::fs::write(path, bytes).with_context(|| format!("writing {what} to {}", path.display()))
}
