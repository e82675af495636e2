//! Texture images: RGBA texels in [0, 1], addressed as OpenGL addresses them.

use std::path::Path;

use ::image::codecs::png::PngDecoder;
use ::image::{imageops, DynamicImage, ImageDecoder, ImageError};

use crate::format::TexelFormat;

/// One RGBA colour or texel, each channel in [0, 1].
pub type Rgba = [f64; 4];

/// The largest width or height, in texels, of a texture.
pub const MAX_SIDE: u32 = 4096;

/// Why a texture could not be made or mip-mapped. Every message begins with the texture's
/// name: its file, or `RGBA8 data` for [`Texture::from_rgba8`].
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The file could not be read.
    #[error("{name}: cannot read the texture file: {source}")]
    Unreadable {
        /// The texture's name.
        name: String,
        /// Why not.
        source: std::io::Error,
    },
    /// The file is not a PNG image, or its PNG data does not decode.
    #[error("{name}: not a PNG image or not decodable: {source}")]
    Undecodable {
        /// The texture's name.
        name: String,
        /// Why not.
        source: ImageError,
    },
    /// The texture has no texel.
    #[error("{name}: the texture has zero size ({width}x{height})")]
    ZeroSize {
        /// The texture's name.
        name: String,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
    },
    /// A side is longer than [`MAX_SIDE`].
    #[error("{name}: the texture is {width}x{height}, larger than {MAX_SIDE} texels on a side")]
    TooLarge {
        /// The texture's name.
        name: String,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
    },
    /// The RGBA8 data given to [`Texture::from_rgba8`] is not 4 bytes per texel.
    #[error("{name}: {len} bytes are not the {width}x{height}x4 bytes of an RGBA8 texture")]
    WrongLength {
        /// The texture's name.
        name: String,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
        /// The number of bytes given.
        len: usize,
    },
    /// [`MipChain::new`](crate::MipChain::new) needs power-of-two sides.
    #[error(
        "{name}: textures are mip-mapped by halving: width and height must be powers of two (got {width}x{height})"
    )]
    NotPowerOfTwo {
        /// The texture's name.
        name: String,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
    },
    /// A level given to [`MipChain::from_levels`](crate::MipChain::from_levels) is not the
    /// size its place in the chain asks for.
    #[error("{name}: mip level {level} is {width}x{height}; level {level} of a {base_width}x{base_height} texture is {want_width}x{want_height}")]
    WrongLevelSize {
        /// The level's name.
        name: String,
        /// Its place in the chain.
        level: usize,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
        /// The base level's width.
        base_width: u32,
        /// The base level's height.
        base_height: u32,
        /// The width level `level` must have.
        want_width: u32,
        /// The height level `level` must have.
        want_height: u32,
    },
    /// [`MipChain::from_levels`](crate::MipChain::from_levels) was given more or fewer levels
    /// than the base's chain has.
    #[error("{name}: {got} mip levels given; a {width}x{height} texture has {want} (down to 1x1)")]
    LevelCount {
        /// The base level's name.
        name: String,
        /// Levels given.
        got: usize,
        /// Levels the base's chain has.
        want: usize,
        /// The base level's width.
        width: u32,
        /// The base level's height.
        height: u32,
    },
}

/// A texture image: `width` x `height` RGBA texels in [0, 1].
///
/// Texel (i, j) is column i from the left and row j from the bottom: row 0 is the one at
/// t near 0, as OpenGL addresses a texture image (OpenGL 4.6 section 8.14.2).
#[derive(Debug, Clone, PartialEq)]
pub struct Texture {
    name: String,
    width: u32,
    height: u32,
    texels: Vec<Rgba>,
}

impl Texture {
    /// Reads a PNG file (any colour type, converted to RGBA8: RGB gets alpha 1). The PNG's
    /// first row is the top of the image, so it becomes row `height - 1`.
    pub fn load(path: impl AsRef<Path>) -> Result<Texture, Error> {
        let path = path.as_ref();
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|source| Error::Unreadable { name: name.clone(), source })?;
        let undecodable = |source| Error::Undecodable { name: name.clone(), source };
        let decoder = PngDecoder::new(bytes.as_slice()).map_err(undecodable)?;
        let (width, height) = decoder.dimensions();
        check_size(&name, width, height)?;
        let top_first = DynamicImage::from_decoder(decoder).map_err(undecodable)?.into_rgba8();
        Texture::rgba8(name, width, height, imageops::flip_vertical(&top_first).as_raw())
    }

    /// A texture from RGBA8 bytes, 4 a texel, rows from the bottom (row 0 first, as
    /// glTexImage2D takes them); channel value v becomes v / 255.
    pub fn from_rgba8(width: u32, height: u32, rgba: &[u8]) -> Result<Texture, Error> {
        Texture::rgba8("RGBA8 data".to_string(), width, height, rgba)
    }

    fn rgba8(name: String, width: u32, height: u32, rgba: &[u8]) -> Result<Texture, Error> {
        check_size(&name, width, height)?;
        if rgba.len() != 4 * width as usize * height as usize {
            return Err(Error::WrongLength { name, width, height, len: rgba.len() });
        }
        let texels = rgba.chunks_exact(4).map(|c| std::array::from_fn(|k| f64::from(c[k]) / 255.0)).collect();
        Ok(Texture { name, width, height, texels })
    }

    /// A texture of the same name with other texels (`texels.len() == width * height`).
    pub(crate) fn with_texels(&self, width: u32, height: u32, texels: Vec<Rgba>) -> Texture {
        Texture { name: self.name.clone(), width, height, texels }
    }

    /// The file the texture came from, or `RGBA8 data`.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Width in texels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Texel (i, j): column i, row j from the bottom. Panics if `i >= width` or `j >= height`.
    pub fn texel(&self, i: u32, j: u32) -> Rgba {
        assert!(i < self.width && j < self.height, "texel ({i}, {j}) outside {}x{}", self.width, self.height);
        self.texels[j as usize * self.width as usize + i as usize]
    }

    /// All texels, row by row from the bottom.
    pub fn texels(&self) -> &[Rgba] {
        &self.texels
    }

    /// The texture as stored in `format`: each texel decoded from its encoding.
    pub fn quantized(&self, format: TexelFormat) -> Texture {
        self.with_texels(self.width, self.height, self.texels.iter().map(|&c| format.quantize(c)).collect())
    }
}

fn check_size(name: &str, width: u32, height: u32) -> Result<(), Error> {
    if width == 0 || height == 0 {
        Err(Error::ZeroSize { name: name.to_string(), width, height })
    } else if width > MAX_SIDE || height > MAX_SIDE {
        Err(Error::TooLarge { name: name.to_string(), width, height })
    } else {
        Ok(())
    }
}

/// The sum of the colours, each times its weight.
pub(crate) fn weighted_sum(terms: impl IntoIterator<Item = (Rgba, f64)>) -> Rgba {
    let mut sum = [0.0; 4];
    for (colour, weight) in terms {
        for (s, c) in sum.iter_mut().zip(colour) {
            *s += weight * c;
        }
    }
    sum
}
