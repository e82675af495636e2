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

/// Every shipped scene (`scenes/*.json`), sorted by path.
pub fn all() -> std::io::Result<Vec<PathBuf>> {
    let mut paths = Vec::new();
    for entry in std::fs::read_dir(dir())? {
        let p = entry?.path();
        if p.extension().is_some_and(|e| e == "json") {
            paths.push(p);
        }
    }
    paths.sort();
    Ok(paths)
}
