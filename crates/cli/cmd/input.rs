//! Reading a render input (scene, trilist or vertex buffer) into a triangle list.

use anyhow::{anyhow, bail, Context, Result};
use fx::Build;
use model::vertex_buffer::{VertexBuffer, MAGIC};
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
    /// A vertex buffer's build (size class and formats): its words are at these formats,
    /// and its triangles (`trilist`) hold their values exactly.
    pub build: Option<Build>,
    /// A vertex buffer's bytes, as `render --engine rtl` hands them to `gpu_top`.
    pub bytes: Option<Vec<u8>>,
}

impl Loaded {
    /// An error naming `path` when its triangles are textured or blended, which `why` says
    /// the command cannot take (every engine of `render` draws them: the float reference,
    /// the scanline and vector models, and the textured `raster_top` in Verilator).
    pub fn untextured(&self, path: &Path, why: &str) -> Result<()> {
        let what = if self.trilist.is_textured() {
            "is textured"
        } else if self.trilist.is_blended() {
            "blends"
        } else {
            return Ok(());
        };
        bail!("{}: the scene {what}: {why}", path.display())
    }
}

/// Whether `path` starts as a vertex buffer does (`model::vertex_buffer::MAGIC`).
fn is_vertex_buffer(path: &Path) -> bool {
    use std::io::Read;
    let mut magic = [0; 4];
    std::fs::File::open(path).and_then(|mut f| f.read_exact(&mut magic)).is_ok() && magic == MAGIC
}

/// Reads the vertex buffer `path`; the error names the file, the offset and the rule.
pub fn vertex_buffer(path: &Path) -> Result<VertexBuffer> {
    Ok(vertex_buffer_bytes(path)?.0)
}

/// [`vertex_buffer`], with the file's bytes.
fn vertex_buffer_bytes(path: &Path) -> Result<(VertexBuffer, Vec<u8>)> {
    let bytes = std::fs::read(path).with_context(|| format!("{}: cannot read the vertex buffer", path.display()))?;
    let vb = VertexBuffer::decode(&bytes).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    Ok((vb, bytes))
}

/// Loads a scene (running the geometry stage), a trilist or a vertex buffer (told apart
/// by its first bytes). `size` overrides a scene's resolution; a trilist's or a vertex
/// buffer's coordinates are fixed, so they cannot be resized.
pub fn load(path: &Path, size: Option<Size>) -> Result<Loaded> {
    if is_vertex_buffer(path) {
        let (vb, bytes) = vertex_buffer_bytes(path)?;
        if size.is_some() {
            bail!("{}: --size applies to scenes; a vertex buffer's coordinates are already in pixels", path.display());
        }
        let background = vb.background.map(f64::from);
        let (trilist, cull_back, build) = (vb.to_trilist(), vb.cull_back, Some(vb.build));
        return Ok(Loaded { trilist, background, cull_back, build, bytes: Some(bytes) });
    }
    match Input::load(path)? {
        Input::Scene(s) => {
            let s = match size {
                Some(z) => s.with_size(z.width, z.height).map_err(|e| e.in_file(path))?,
                None => *s,
            };
            let trilist = s.to_trilist().map_err(|e| e.in_file(path))?;
            Ok(Loaded { trilist, background: s.background, cull_back: s.cull_back, build: None, bytes: None })
        }
        Input::Trilist(t) => {
            if size.is_some() {
                bail!("{}: --size applies to scenes; a trilist's coordinates are already in pixels", path.display());
            }
            Ok(Loaded { trilist: t, background: [0.0; 3], cull_back: false, build: None, bytes: None })
        }
    }
}

/// Writes `bytes` produced by `what` to `path`, naming both on failure.
pub fn write(path: &Path, what: &str, bytes: &[u8]) -> Result<()> {
    std::fs::write(path, bytes).with_context(|| format!("writing {what} to {}", path.display()))
}
