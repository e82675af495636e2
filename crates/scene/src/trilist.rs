//! trilist: the screen-space triangle list every rasterizer in edgepaint reads.
//!
//! ```json
//! {"width": W, "height": H,
//!  "triangles": [ [[x,y,z,r,g,b],[x,y,z,r,g,b],[x,y,z,r,g,b]], ... ]}
//! ```
//!
//! * `x`, `y`: pixels, origin at the top-left corner, y down. Pixel (i, j) covers
//!   [i, i+1) x [j, j+1) and is sampled at its centre (i + 0.5, j + 0.5).
//! * `z`: depth, 0 nearest, 1 farthest. Values outside [0, 1] are legal: the
//!   rasterizers clip them per pixel.
//! * `r`, `g`, `b`: colour in [0, 255].
//! * an optional 7th value, `w`: the vertex's clip-space w. With it colours are
//!   interpolated perspective-correctly; without it w = 1 (screen-linear).
//!   `w <= 0` is legal (a vertex behind the eye): see `reference` for how it is drawn.
//!
//! **Version 2** adds textures (version 1 files, without `"version"`, still read):
//!
//! ```json
//! {"version": 2, "width": W, "height": H,
//!  "textures": [{"image": "checker.png", "sampler": {"wrap_s": "clamp_to_edge"}, "env": "modulate",
//!                "format": "rgb565"}, {"levels": ["l0.png", "l1.png", "l2.png"]}],
//!  "triangles": [ [[x,y,z,r,g,b,w,s,t,texture], ...], ... ]}
//! ```
//!
//! * `textures`: the images (PNG, relative to the trilist's folder: `image`, its mip
//!   levels built from it, or `levels`, every level's own image down to 1x1), each with its
//!   sampler state, texture environment and texel format (`texture::Sampler`,
//!   `texture::EnvMode`, `texture::TexelFormat`: 001's five colour modes, the image and
//!   its mip levels stored in it; keys left out take the defaults: bilinear, nearest mip
//!   level, repeat, MODULATE, RGBA8888).
//! * a textured vertex has 10 values: w, then the texture coordinates `s`, `t`
//!   (OpenGL's: (0, 0) the image's bottom-left corner, 1 its width or height) and the
//!   index of its texture in `textures`; the three vertices of a triangle name the same
//!   texture, or none has one.
//!
//! * `blend`: framebuffer blending as state entries, each `{"first": n, "mode": m}`: the
//!   triangles from index `n` up to the next entry's `first` are blended onto the
//!   framebuffer by mode `m` (`texture::BlendMode`: `opaque`, `alpha`, `additive`,
//!   `multiply`, `premultiplied_alpha`, `alpha_additive`; paper 001's six blend modes,
//!   OpenGL 4.6 section 17.3.6). Entries run in increasing `first`, each below the number
//!   of triangles; the triangles before the first entry, and all of a file without
//!   `blend`, are opaque (no blending). Written as one entry where the mode changes.
//!
//! Reading validates everything and reports the file, the triangle, the vertex
//! and the value at fault; nothing here panics on bad input.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::error::{Error, Result};
use texture::BlendMode;

/// Largest width or height edgepaint accepts. The fixed-point formats derive
/// their integer bits from the resolution; 4096 keeps every default format
/// within the widths the RTL is built for.
pub const MAX_RESOLUTION: u32 = 4096;

/// One vertex as the rasterizer sees it (screen space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub r: f64,
    pub g: f64,
    pub b: f64,
    /// Clip-space w when the producer knew it (7th value); `None` means w = 1.
    pub w: Option<f64>,
    /// Texture coordinates and the texture they address (version 2), if textured.
    pub tex: Option<Tex>,
    /// How its triangle's fragments blend onto the framebuffer (version 2's `blend`);
    /// the three vertices of a triangle agree. [`BlendMode::Opaque`]: no blending.
    pub blend: BlendMode,
}

/// A vertex's texture coordinates (OpenGL's s and t: (0, 0) the image's bottom-left
/// corner, 1 its width or height) and the index of its texture in [`Trilist::textures`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tex {
    pub s: f64,
    pub t: f64,
    pub texture: u16,
}

/// A texture as the triangles address it: its image with the mip chain built from it (or
/// its levels' images) stored in its texel format, its sampler state and texture
/// environment.
#[derive(Clone, Debug)]
pub struct TextureRef {
    /// The PNG files, absolute: the base image alone, its chain built by the box filter;
    /// or every level's, base first.
    pub images: Vec<PathBuf>,
    pub sampler: texture::Sampler,
    pub env: texture::EnvMode,
    pub format: texture::TexelFormat,
    /// The image's mip chain (2 x 2 box filter) in `format`, built when it was loaded.
    pub mips: Arc<texture::MipChain>,
}

impl PartialEq for TextureRef {
    /// The same file with the same state (the mip chain follows from the file).
    fn eq(&self, o: &TextureRef) -> bool {
        (&self.images, &self.sampler, &self.env, &self.format) == (&o.images, &o.sampler, &o.env, &o.format)
    }
}

/// A texture as scene and trilist files give it: every key optional (a scene's OBJ
/// object may take its image from its material).
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TextureSpec {
    /// The PNG file, relative to the file that names it; its mip levels are built from it.
    pub image: Option<PathBuf>,
    /// Instead of `image`: every mip level's PNG file, base first, down to 1x1 (as OpenGL
    /// takes a texture's levels one by one).
    pub levels: Option<Vec<PathBuf>>,
    #[serde(default)]
    pub sampler: texture::Sampler,
    #[serde(default)]
    pub env: texture::EnvMode,
    #[serde(default)]
    pub format: texture::TexelFormat,
}

impl TextureRef {
    /// Loads `images` (one: the base, its mip chain built from it; several: every level,
    /// base first) with `spec`'s state; the error names the file.
    pub fn load(images: &[PathBuf], spec: &TextureSpec) -> Result<TextureRef> {
        let levels = images
            .iter()
            .map(|p| texture::Texture::load(p).map_err(|e| Error::invalid(e.to_string())))
            .collect::<Result<Vec<_>>>()?;
        let mips = match levels.len() {
            1 => texture::MipChain::new(levels.into_iter().next().expect("one level")),
            _ => texture::MipChain::from_levels(levels),
        };
        let mips = mips.map_err(|e| Error::invalid(e.to_string()))?.quantized(spec.format);
        // Held absolute: a trilist written elsewhere still finds them.
        let images = images.iter().map(|p| std::fs::canonicalize(p).unwrap_or_else(|_| p.clone())).collect();
        Ok(TextureRef { images, sampler: spec.sampler, env: spec.env, format: spec.format, mips: Arc::new(mips) })
    }
}

impl TextureSpec {
    /// Its files relative to `base_dir` (`image`, or `levels`); `None` when it names
    /// neither; an error when it names both.
    pub fn files(&self, base_dir: &Path) -> std::result::Result<Option<Vec<PathBuf>>, String> {
        match (&self.image, &self.levels) {
            (Some(_), Some(_)) => Err("give \"image\" or \"levels\", not both".into()),
            (Some(image), None) => Ok(Some(vec![base_dir.join(image)])),
            (None, Some(levels)) if levels.is_empty() => Err("\"levels\" is empty".into()),
            (None, Some(levels)) => Ok(Some(levels.iter().map(|l| base_dir.join(l)).collect())),
            (None, None) => Ok(None),
        }
    }
}

impl Vertex {
    /// A vertex without w (screen-linear interpolation).
    pub const fn new(x: f64, y: f64, z: f64, rgb: [f64; 3]) -> Self {
        Vertex { x, y, z, r: rgb[0], g: rgb[1], b: rgb[2], w: None, tex: None, blend: BlendMode::Opaque }
    }

    /// The colour as an array.
    pub fn rgb(&self) -> [f64; 3] {
        [self.r, self.g, self.b]
    }

    /// w, defaulting to 1 when the vertex carries none.
    pub fn w_or_one(&self) -> f64 {
        self.w.unwrap_or(1.0)
    }
}

/// Three vertices in submission order (winding matters for back-face culling).
pub type Triangle = [Vertex; 3];

/// A frame's worth of screen-space triangles.
#[derive(Clone, Debug, PartialEq)]
pub struct Trilist {
    pub width: u32,
    pub height: u32,
    pub triangles: Vec<Triangle>,
    /// The textures the vertices' [`Tex::texture`] index (version 2); empty in version 1.
    pub textures: Vec<TextureRef>,
}

/// Which vertex field a validation error refers to.
const FIELD_NAMES: [&str; 10] = ["x", "y", "z", "r", "g", "b", "w", "s", "t", "texture"];

impl Trilist {
    /// An empty list for a `width` x `height` screen (checked).
    pub fn new(width: u32, height: u32) -> Result<Self> {
        check_resolution(width, height)?;
        Ok(Trilist { width, height, triangles: Vec::new(), textures: Vec::new() })
    }

    /// Whether any triangle is textured.
    pub fn is_textured(&self) -> bool {
        self.triangles.iter().any(|t| t[0].tex.is_some())
    }

    /// Whether any triangle blends onto the framebuffer (a mode other than
    /// [`BlendMode::Opaque`]).
    pub fn is_blended(&self) -> bool {
        self.triangles.iter().any(|t| t[0].blend != BlendMode::Opaque)
    }

    /// The same triangles in their lit colours alone: no texture coordinates, no textures.
    pub fn without_textures(&self) -> Trilist {
        let triangles = self.triangles.iter().map(|t| t.map(|v| Vertex { tex: None, ..v })).collect();
        Trilist { width: self.width, height: self.height, triangles, textures: Vec::new() }
    }

    /// Reads and validates a trilist file; texture images are relative to its folder.
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let raw: serde_json::Value = crate::error::parse_json(&text).map_err(|e| e.in_file(path))?;
        Self::from_value(&raw, path.parent().unwrap_or(Path::new("."))).map_err(|e| e.in_file(path))
    }

    /// Parses and validates trilist JSON text (texture images relative to the working
    /// folder).
    pub fn from_json(text: &str) -> Result<Self> {
        let raw: serde_json::Value = crate::error::parse_json(text)?;
        Self::from_value(&raw, Path::new("."))
    }

    /// Validates an already parsed JSON value (also used to sniff input kinds); texture
    /// images are relative to `base_dir`.
    pub fn from_value(raw: &serde_json::Value, base_dir: &Path) -> Result<Self> {
        let obj = raw
            .as_object()
            .ok_or_else(|| Error::invalid("a trilist must be a JSON object with width, height and triangles"))?;
        let version = match obj.get("version") {
            None => 1,
            Some(v) if v.as_u64() == Some(2) => 2,
            Some(v) => {
                return Err(Error::invalid(format!("\"version\" = {v}: edgepaint reads trilist versions 1 and 2")))
            }
        };
        for key in obj.keys() {
            let known = matches!(key.as_str(), "width" | "height" | "triangles")
                || (version == 2 && matches!(key.as_str(), "version" | "textures" | "blend"));
            if !known {
                return Err(Error::invalid(format!(
                    "unknown key \"{key}\" (trilist v1 has width, height, triangles; v2 adds version, textures and blend)"
                )));
            }
        }
        let textures = match obj.get("textures") {
            None => Vec::new(),
            Some(t) => parse_textures(t, base_dir)?,
        };
        let dim = |name: &str| -> Result<u32> {
            let v = obj.get(name).ok_or_else(|| Error::invalid(format!("missing \"{name}\"")))?;
            let n = v
                .as_u64()
                .ok_or_else(|| Error::invalid(format!("\"{name}\" must be a whole number of pixels, got {v}")))?;
            u32::try_from(n).map_err(|_| Error::invalid(format!("\"{name}\" = {n} is out of range")))
        };
        let (width, height) = (dim("width")?, dim("height")?);
        check_resolution(width, height)?;
        let tris = obj
            .get("triangles")
            .ok_or_else(|| Error::invalid("missing \"triangles\""))?
            .as_array()
            .ok_or_else(|| Error::invalid("\"triangles\" must be an array of triangles"))?;
        let mut triangles = Vec::with_capacity(tris.len());
        for (t, tri) in tris.iter().enumerate() {
            let verts = tri
                .as_array()
                .ok_or_else(|| Error::invalid(format!("triangle {t}: must be an array of 3 vertices")))?;
            if verts.len() != 3 {
                return Err(Error::invalid(format!("triangle {t}: has {} vertices, a triangle needs 3", verts.len())));
            }
            let mut out = [Vertex::new(0.0, 0.0, 0.0, [0.0; 3]); 3];
            for (k, v) in verts.iter().enumerate() {
                out[k] = parse_vertex(v, version, textures.len())
                    .map_err(|msg| Error::invalid(format!("triangle {t} vertex {k}: {msg}")))?;
            }
            let units = out.map(|v| v.tex.map(|x| x.texture));
            if units[1] != units[0] || units[2] != units[0] {
                return Err(Error::invalid(format!(
                    "triangle {t}: its vertices name textures {units:?}: the three name the same texture, or none has one"
                )));
            }
            triangles.push(out);
        }
        if let Some(b) = obj.get("blend") {
            apply_blend(b, &mut triangles)?;
        }
        Ok(Trilist { width, height, triangles, textures })
    }

    /// Writes trilist JSON: version 1 without textures and blending, else version 2 (image
    /// paths as held; `blend` an entry wherever the mode changes). A vertex carries the 7th
    /// value exactly when it has w or a texture (w = 1 written for a textured vertex without
    /// w), and values 8 to 10 when textured.
    pub fn to_json(&self) -> String {
        #[derive(Serialize)]
        struct OutTexture<'a> {
            #[serde(skip_serializing_if = "Option::is_none")]
            image: Option<&'a PathBuf>,
            #[serde(skip_serializing_if = "Option::is_none")]
            levels: Option<&'a [PathBuf]>,
            sampler: texture::Sampler,
            env: texture::EnvMode,
            format: texture::TexelFormat,
        }
        #[derive(Serialize)]
        struct Out<'a> {
            #[serde(skip_serializing_if = "Option::is_none")]
            version: Option<u32>,
            width: u32,
            height: u32,
            #[serde(skip_serializing_if = "Vec::is_empty")]
            textures: Vec<OutTexture<'a>>,
            #[serde(skip_serializing_if = "Vec::is_empty")]
            blend: Vec<BlendEntry>,
            triangles: Vec<[Vec<f64>; 3]>,
        }
        let triangles = self
            .triangles
            .iter()
            .map(|t| {
                t.map(|v| {
                    let mut a = vec![v.x, v.y, v.z, v.r, v.g, v.b];
                    match v.tex {
                        Some(x) => a.extend([v.w_or_one(), x.s, x.t, x.texture as f64]),
                        None => a.extend(v.w),
                    }
                    a
                })
            })
            .collect();
        let textures: Vec<OutTexture> = self
            .textures
            .iter()
            .map(|t| {
                let (image, levels) = match &t.images[..] {
                    [one] => (Some(one), None),
                    all => (None, Some(all)),
                };
                OutTexture { image, levels, sampler: t.sampler, env: t.env, format: t.format }
            })
            .collect();
        let mut blend = Vec::new();
        let mut mode = BlendMode::Opaque;
        for (first, t) in self.triangles.iter().enumerate() {
            if t[0].blend != mode {
                mode = t[0].blend;
                blend.push(BlendEntry { first, mode });
            }
        }
        let version = (!textures.is_empty() || !blend.is_empty()).then_some(2);
        serde_json::to_string(&Out { version, width: self.width, height: self.height, textures, blend, triangles })
            .expect("finite floats always serialise")
    }

    /// Writes the list to `path` as trilist JSON.
    pub fn save(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_json()).map_err(|e| Error::io(path, e))
    }
}

/// Rejects zero and absurd resolutions.
pub fn check_resolution(width: u32, height: u32) -> Result<()> {
    for (name, v) in [("width", width), ("height", height)] {
        if v == 0 || v > MAX_RESOLUTION {
            return Err(Error::invalid(format!(
                "{name} {v} is out of range: edgepaint renders 1 to {MAX_RESOLUTION} pixels"
            )));
        }
    }
    Ok(())
}

/// A version 2 file's `textures`, each image loaded from `base_dir`.
fn parse_textures(raw: &serde_json::Value, base_dir: &Path) -> Result<Vec<TextureRef>> {
    let list = raw.as_array().ok_or_else(|| Error::invalid("\"textures\" must be an array"))?;
    if list.len() > u16::MAX as usize {
        return Err(Error::invalid(format!("{} textures: at most {}", list.len(), u16::MAX)));
    }
    list.iter()
        .enumerate()
        .map(|(i, t)| {
            let at = |e: &dyn fmt::Display| Error::invalid(format!("textures[{i}]: {e}"));
            let spec: TextureSpec = serde_json::from_value(t.clone()).map_err(|e| at(&e))?;
            let files = spec.files(base_dir).map_err(|e| at(&e))?.ok_or_else(|| at(&"missing \"image\""))?;
            TextureRef::load(&files, &spec).map_err(|e| at(&e))
        })
        .collect()
}

/// A state entry of a version 2 file's `blend`: triangles from `first` on blend by `mode`.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct BlendEntry {
    first: usize,
    mode: BlendMode,
}

/// Sets each triangle's blend mode from a version 2 file's `blend` entries; the error
/// names the entry and its key.
fn apply_blend(raw: &serde_json::Value, triangles: &mut [Triangle]) -> Result<()> {
    let list = raw.as_array().ok_or_else(|| {
        Error::invalid("\"blend\" must be an array of state entries {\"first\": triangle, \"mode\": name}")
    })?;
    let mut entries = Vec::with_capacity(list.len());
    for (i, e) in list.iter().enumerate() {
        let entry: BlendEntry = serde_path_to_error::deserialize(e).map_err(|err| {
            let at = err.path().to_string();
            let inner = err.into_inner();
            Error::invalid(if at == "." { format!("blend[{i}]: {inner}") } else { format!("blend[{i}].{at}: {inner}") })
        })?;
        if entry.first >= triangles.len() {
            return Err(Error::invalid(format!(
                "blend[{i}].first = {} is not a triangle of the file's {}",
                entry.first,
                triangles.len()
            )));
        }
        if let Some(prev) = entries.last().map(|p: &BlendEntry| p.first).filter(|&p| p >= entry.first) {
            return Err(Error::invalid(format!(
                "blend[{i}].first = {} does not follow blend[{}].first = {prev}: entries run in increasing order",
                entry.first,
                i - 1
            )));
        }
        entries.push(entry);
    }
    for (k, entry) in entries.iter().enumerate() {
        let end = entries.get(k + 1).map_or(triangles.len(), |n| n.first);
        for t in &mut triangles[entry.first..end] {
            t.iter_mut().for_each(|v| v.blend = entry.mode);
        }
    }
    Ok(())
}

/// One vertex of a version `version` file with `textures` textures.
fn parse_vertex(v: &serde_json::Value, version: u32, textures: usize) -> std::result::Result<Vertex, String> {
    let want = if version == 2 {
        "6 (x,y,z,r,g,b), 7 (with w) or 10 (with w, s, t and a texture)"
    } else {
        "6 (x,y,z,r,g,b) or 7 (with w)"
    };
    let a = v.as_array().ok_or_else(|| format!("must be an array of {want} values"))?;
    if !(a.len() == 6 || a.len() == 7 || (version == 2 && a.len() == 10)) {
        return Err(format!("has {} values, a vertex needs {want}", a.len()));
    }
    let mut f = [0.0f64; 10];
    for (i, x) in a.iter().enumerate() {
        f[i] = x.as_f64().ok_or_else(|| format!("{} must be a number, got {x}", FIELD_NAMES[i]))?;
        if !f[i].is_finite() {
            return Err(format!("{} is not finite ({})", FIELD_NAMES[i], f[i]));
        }
    }
    for (i, c) in f.iter().enumerate().take(6).skip(3) {
        if !(0.0..=255.0).contains(c) {
            return Err(format!("colour {} = {c} is outside [0, 255]", FIELD_NAMES[i]));
        }
    }
    let tex = if a.len() == 10 {
        let unit = f[9];
        if unit.fract() != 0.0 || unit < 0.0 || unit >= textures as f64 {
            return Err(format!(
                "texture {unit} is not one of the file's {textures} textures (0 to {})",
                textures as f64 - 1.0
            ));
        }
        Some(Tex { s: f[7], t: f[8], texture: unit as u16 })
    } else {
        None
    };
    let w = (a.len() >= 7).then_some(f[6]);
    Ok(Vertex { x: f[0], y: f[1], z: f[2], r: f[3], g: f[4], b: f[5], w, tex, blend: BlendMode::Opaque })
}

impl fmt::Display for Vertex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {}, z {}, rgb {} {} {}", self.x, self.y, self.z, self.r, self.g, self.b)?;
        if let Some(w) = self.w {
            write!(f, ", w {w}")?;
        }
        if let Some(x) = self.tex {
            write!(f, ", s {} t {} texture {}", x.s, x.t, x.texture)?;
        }
        if self.blend != BlendMode::Opaque {
            write!(f, ", blend {:?}", self.blend)?;
        }
        write!(f, ")")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trilist_round_trips_with_and_without_w() {
        let mut t = Trilist::new(64, 48).unwrap();
        t.triangles.push([
            Vertex::new(1.5, 2.25, 0.5, [1.0, 2.0, 3.0]),
            Vertex { w: Some(2.5), ..Vertex::new(10.0, 2.0, 0.25, [255.0, 0.0, 0.0]) },
            Vertex::new(3.0, 40.0, 1.0, [0.0, 0.0, 255.0]),
        ]);
        let back = Trilist::from_json(&t.to_json()).unwrap();
        assert_eq!(back, t);
    }

    /// Three untextured triangles: the first opaque, the other two blended `alpha` then
    /// `additive`.
    fn blended() -> Trilist {
        let mut t = Trilist::new(8, 8).unwrap();
        for (k, mode) in [BlendMode::Opaque, BlendMode::Alpha, BlendMode::Additive].into_iter().enumerate() {
            let v = |x: f64, y: f64| Vertex { blend: mode, ..Vertex::new(x, y, 0.1 * k as f64, [10.0, 20.0, 30.0]) };
            t.triangles.push([v(0.0, 0.0), v(8.0, 0.0), v(0.0, 8.0)]);
        }
        t
    }

    #[test]
    fn trilist_blend_state_round_trips_as_state_entries() {
        let t = blended();
        assert!(t.is_blended());
        let json = t.to_json();
        let raw: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert_eq!(raw["version"], 2);
        assert_eq!(raw["blend"], serde_json::json!([{"first": 1, "mode": "alpha"}, {"first": 2, "mode": "additive"}]));
        assert_eq!(Trilist::from_json(&json).unwrap(), t);
        // Without blending the list stays version 1, and a version 1 file reads unblended.
        let plain = Trilist { triangles: t.triangles[..1].to_vec(), ..t.clone() };
        assert!(!plain.is_blended());
        assert!(!plain.to_json().contains("version"));
        let v1 = r#"{"width":4,"height":4,"triangles":[[[0,0,0,9,9,9],[4,0,0,9,9,9],[0,4,0,9,9,9]]]}"#;
        let read = Trilist::from_json(v1).unwrap();
        assert!(!read.is_blended());
        assert_eq!(read.triangles[0].map(|v| v.blend), [BlendMode::Opaque; 3]);
        // An entry covers the triangles up to the next one; those before the first are opaque.
        let v2 = r#"{"version":2,"width":4,"height":4,"blend":[{"first":1,"mode":"premultiplied_alpha"}],
            "triangles":[[[0,0,0,9,9,9],[4,0,0,9,9,9],[0,4,0,9,9,9]],[[0,0,0,9,9,9],[4,0,0,9,9,9],[0,4,0,9,9,9]],
                         [[0,0,0,9,9,9],[4,0,0,9,9,9],[0,4,0,9,9,9]]]}"#;
        let modes: Vec<BlendMode> = Trilist::from_json(v2).unwrap().triangles.iter().map(|t| t[2].blend).collect();
        assert_eq!(modes, [BlendMode::Opaque, BlendMode::PremultipliedAlpha, BlendMode::PremultipliedAlpha]);
    }

    #[test]
    fn trilist_bad_blend_state_names_the_file_and_the_key() {
        let tri = "[[0,0,0,9,9,9],[4,0,0,9,9,9],[0,4,0,9,9,9]]";
        let file = |blend: &str, version: &str| {
            format!(r#"{{{version}"width":4,"height":4,"blend":{blend},"triangles":[{tri},{tri}]}}"#)
        };
        let v2 = r#""version":2,"#;
        let cases = [
            (file(r#"[{"first":0,"mode":"screen"}]"#, v2), "blend[0].mode: unknown variant `screen`, expected one of"),
            (file(r#"[{"first":0,"mode":"alpha"},{"first":-1,"mode":"alpha"}]"#, v2), "blend[1].first: invalid value"),
            (file(r#"[{"first":2,"mode":"alpha"}]"#, v2), "blend[0].first = 2 is not a triangle of the file's 2"),
            (
                file(r#"[{"first":1,"mode":"alpha"},{"first":1,"mode":"multiply"}]"#, v2),
                "blend[1].first = 1 does not follow blend[0].first = 1",
            ),
            (file(r#"[{"first":0}]"#, v2), "blend[0]: missing field `mode`"),
            (file(r#"[{"first":0,"mode":"alpha","op":"add"}]"#, v2), "blend[0].op: unknown field `op`"),
            (file(r#"{"first":0,"mode":"alpha"}"#, v2), "\"blend\" must be an array of state entries"),
            (file(r#"[{"first":0,"mode":"alpha"}]"#, ""), "unknown key \"blend\""),
        ];
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.json");
        for (json, want) in cases {
            std::fs::write(&path, &json).unwrap();
            let err = Trilist::load(&path).unwrap_err().to_string();
            let named = err.starts_with(&format!("{}: ", path.display()));
            assert!(named && err.contains(want), "{json}: got {err:?}, want the file and {want:?}");
        }
    }

    #[test]
    fn trilist_rejects_wrong_arity_and_bad_values() {
        let cases = [
            (r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0,0],[1,0,0,0,0,0]]]}"#, "triangle 0: has 2 vertices"),
            (
                r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]]]}"#,
                "vertex 0: has 5 values",
            ),
            (r#"{"width":0,"height":4,"triangles":[]}"#, "width 0 is out of range"),
            (r#"{"width":100000,"height":4,"triangles":[]}"#, "width 100000 is out of range"),
            (r#"{"width":4,"height":4,"triangles":[[[0,0,0,0,0,300],[1,0,0,0,0,0],[0,1,0,0,0,0]]]}"#, "colour b = 300"),
            (
                r#"{"width":4,"height":4,"triangles":[[[0,"a",0,0,0,0],[1,0,0,0,0,0],[0,1,0,0,0,0]]]}"#,
                "y must be a number",
            ),
            (r#"{"width":4,"height":4}"#, "missing \"triangles\""),
            (r#"{"width":4,"height":4,"triangles":[],"tris":1}"#, "unknown key \"tris\""),
        ];
        for (json, want) in cases {
            let err = Trilist::from_json(json).unwrap_err().to_string();
            assert!(err.contains(want), "{json}: got {err:?}, want {want:?}");
        }
    }
}
