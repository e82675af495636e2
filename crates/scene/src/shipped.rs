//! The scenes shipped in the repository's `scenes/` folder, as tests, examples and
//! benchmarks find them.

use std::path::PathBuf;

/// The repository's `scenes/` folder.
pub fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenes")
}

/// Shipped scene `name`: `scenes/<name>.json`.
pub fn path(name: &str) -> PathBuf {
    dir().join(format!("{name}.json"))
}

/// The dense scene, `scenes/dense/dense.json`: 003's torus at detail 15 (76,500
/// triangles) at 640 x 480. It lives in a folder of its own so that [`all`], which the
/// tests run through every model and simulator, stays fast.
pub fn dense() -> PathBuf {
    dir().join("dense/dense.json")
}

/// Every shipped scene (`scenes/*.json`, not the folders under it), sorted by path.
pub fn all() -> std::io::Result<Vec<PathBuf>> {
    scenes_in(dir())
}

/// The shipped textured scenes, `scenes/textured/*.json` (with their OBJ, MTL and PNG
/// files, from `scripts/gen-textures.py`): the float reference and the scanline and vector
/// models draw them, and `rtl::texture_path` their textured fragments (`raster_top` has no
/// texture path yet).
pub fn textured() -> std::io::Result<Vec<PathBuf>> {
    scenes_in(dir().join("textured"))
}

/// The scene files (`*.json`) in `folder`, sorted by path.
fn scenes_in(folder: PathBuf) -> std::io::Result<Vec<PathBuf>> {
    let mut paths = Vec::new();
    for entry in std::fs::read_dir(folder)? {
        let p = entry?.path();
        if p.extension().is_some_and(|e| e == "json") {
            paths.push(p);
        }
    }
    paths.sort();
    Ok(paths)
}
