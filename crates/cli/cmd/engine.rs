//! The options shared by every command that runs a fixed-point pipeline:
//! which method, its lanes, and the number formats.

use super::input::Loaded;
use anyhow::{Context, Result};
use fx::{Formats, TexFormats};
use model::render::{Method, Texturing};
use model::texture_memory::TextureMemory;
use model::texture_unit::TextureUnit;
use scene::Trilist;
use std::path::Path;
use texture::LodRule;

/// Which rasterizer draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Engine {
    /// The f64 reference rasterizer.
    Float,
    /// The fixed-point scanline pipeline of 001 and 003 (setup, edge walk, span).
    Scanline,
    /// The fixed-point per-pixel barycentric method of 004.
    Vector,
    /// The scanline pipeline's spans drawn by an array of 000's shading engines.
    Se,
    /// The scanline pipeline's RTL (`raster_top`) simulated in Verilator: the scanline
    /// model's image bit for bit, with the hardware's cycle counts.
    Rtl,
}

/// Options for the fixed-point pipelines.
#[derive(clap::Args, Clone, Debug)]
pub struct FixedArgs {
    /// Number formats: "default" (derived from the resolution), "wide", or a JSON
    /// file mapping quantities to formats (e.g. {"xy": "S11.8 half-up"}); keys left out keep
    /// their defaults, or follow from the keys given (accumulators, gradients, products).
    #[arg(long, default_value = "default")]
    pub formats: String,
    /// Pixels the vector method evaluates per cycle: 4 by default; the RTL's vector unit
    /// (`--engine rtl --method vector`) evaluates 1.
    #[arg(long)]
    pub lanes: Option<u32>,
    /// The texture unit's level-of-detail rule: 001's eq. (4) (max, the design's) or GL's
    /// exact rho; the float reference uses the same.
    #[arg(long, value_enum, default_value = "max")]
    pub lod: Lod,
}

/// A level-of-detail rule (`texture::LodRule`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Lod {
    Max,
    Exact,
}

/// The vector model's lanes when `--lanes` is not given.
pub const DEFAULT_LANES: u32 = 4;

impl FixedArgs {
    /// The formats for a `width` x `height` screen, checked.
    pub fn formats(&self, width: u32, height: u32) -> Result<Formats> {
        let f = match self.formats.as_str() {
            "default" => Formats::for_resolution(width, height),
            "wide" => Formats::wide(width, height),
            path => return formats_file(Path::new(path), width, height),
        };
        f.check(width, height).map_err(|e| anyhow::anyhow!("formats \"{}\": {e}", self.formats))?;
        Ok(f)
    }

    /// The texture unit's formats: the formats file's `"texture"` object over the defaults
    /// (`fx::TexFormats`), or the defaults.
    pub fn texture_formats(&self) -> Result<TexFormats> {
        match self.formats.as_str() {
            "default" | "wide" => Ok(TexFormats::DEFAULT),
            path => TexFormats::from_formats_file(&formats_json(Path::new(path))?)
                .map_err(|e| anyhow::anyhow!("{path}: {e}")),
        }
    }

    /// The level-of-detail rule `--lod` names.
    pub fn lod_rule(&self) -> LodRule {
        match self.lod {
            Lod::Max => LodRule::Max,
            Lod::Exact => LodRule::Exact,
        }
    }

    /// How the fixed-point engines texture `list` (`None` when it is untextured): the unit at
    /// [`FixedArgs::texture_formats`], `--lod`, its textures in memory; `affine`: screen-linear
    /// coordinates. `path` names the input in errors.
    pub fn texturing(&self, list: &Trilist, affine: bool, path: &Path) -> Result<Option<Texturing>> {
        if !list.is_textured() {
            return Ok(None);
        }
        let unit = TextureUnit::new(self.texture_formats()?).map_err(|e| anyhow::anyhow!("texture formats: {e}"))?;
        let memory =
            TextureMemory::load(list, self.lod_rule()).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        Ok(Some(Texturing { unit, memory, affine }))
    }

    /// The formats `loaded` is drawn at: a vertex buffer's own (its words are at them; an
    /// error when `--formats` asks for others), else [`FixedArgs::formats`].
    pub fn formats_of(&self, loaded: &Loaded) -> Result<Formats> {
        let list = &loaded.trilist;
        match loaded.build {
            Some(_) if self.formats != "default" => anyhow::bail!(
                "--formats {}: a vertex buffer's words are at the formats its header gives, which draw it",
                self.formats
            ),
            Some(b) => Ok(b.formats),
            None => self.formats(list.width, list.height),
        }
    }

    /// The model's method for an engine (None for the float reference).
    pub fn method(&self, engine: Engine, perspective: bool) -> Result<Option<Method>> {
        if let Some(l) = self.lanes {
            anyhow::ensure!(
                model::vector::lanes_supported(l),
                "--lanes {l}: the vector walk's chunks are aligned to the lanes, so 1, 2, 4, ... up to 64"
            );
        }
        Ok(match engine {
            Engine::Float => None,
            Engine::Scanline | Engine::Rtl => Some(Method::Scanline),
            Engine::Vector => Some(Method::Vector { lanes: self.lanes.unwrap_or(DEFAULT_LANES), perspective }),
            Engine::Se => anyhow::bail!("--engine se has no model::render method: its spans are the scanline pipeline's, drawn by model::se::array"),
        })
    }
}

/// The formats file `path` (a JSON object of formats by quantity) over the defaults for a
/// `width` x `height` screen, checked.
pub fn formats_file(path: &Path, width: u32, height: u32) -> Result<Formats> {
    let json = formats_json(path)?;
    Formats::with_overrides(width, height, &json).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))
}

/// The JSON of the formats file `path`, not yet applied to a screen.
pub fn formats_json(path: &Path) -> Result<serde_json::Value> {
    let name = path.display();
    let text = std::fs::read_to_string(path).with_context(|| format!("{name}: cannot read the formats file"))?;
    serde_json::from_str(&text).with_context(|| format!("{name}: malformed JSON"))
}
