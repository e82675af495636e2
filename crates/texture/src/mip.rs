//! Mipmap chains: the levels of a texture, each half the size of the one before.

use crate::format::TexelFormat;
use crate::image::{weighted_sum, Error, Texture};

/// The levels of a mipmapped texture: level 0 is the base, each next level halves both sides
/// (down to 1) and the last is 1x1. Level k is max(1, floor(w / 2^k)) x max(1, floor(h / 2^k))
/// (OpenGL 4.6 section 8.14.3), and there are floor(log2(max(w, h))) + 1 levels.
#[derive(Debug, Clone, PartialEq)]
pub struct MipChain {
    levels: Vec<Texture>,
}

impl MipChain {
    /// The chain of `base`, each level the 2x2 box filter of the one before: a texel is the mean
    /// of the 4 texels it covers, or of 2 once one side is 1 (OpenGL 4.6 section 8.14.4 leaves the
    /// filter open; this is the box filter). Both sides of `base` must be powers of two.
    pub fn new(base: Texture) -> Result<MipChain, Error> {
        let (width, height) = (base.width(), base.height());
        if !(width.is_power_of_two() && height.is_power_of_two()) {
            return Err(Error::NotPowerOfTwo { name: base.name().to_string(), width, height });
        }
        let mut levels = vec![base];
        while let Some(last) = levels.last().filter(|l| l.width() > 1 || l.height() > 1) {
            levels.push(halve(last));
        }
        Ok(MipChain { levels })
    }

    /// The chain of the levels given, base first, as OpenGL takes each level of a texture
    /// from the application (`glTexImage2D` with its level): the base's sides powers of
    /// two, level k max(1, w / 2^k) x max(1, h / 2^k), down to 1x1. The errors name the
    /// level at fault.
    pub fn from_levels(levels: Vec<Texture>) -> Result<MipChain, Error> {
        let base = levels.first().ok_or_else(|| Error::LevelCount {
            name: "no level".into(),
            got: 0,
            want: 1,
            width: 0,
            height: 0,
        })?;
        let (width, height) = (base.width(), base.height());
        if !(width.is_power_of_two() && height.is_power_of_two()) {
            return Err(Error::NotPowerOfTwo { name: base.name().to_string(), width, height });
        }
        let want = width.max(height).ilog2() as usize + 1;
        if levels.len() != want {
            return Err(Error::LevelCount { name: base.name().to_string(), got: levels.len(), want, width, height });
        }
        for (k, level) in levels.iter().enumerate() {
            let (w, h) = ((width >> k).max(1), (height >> k).max(1));
            if (level.width(), level.height()) != (w, h) {
                return Err(Error::WrongLevelSize {
                    name: level.name().to_string(),
                    level: k,
                    width: level.width(),
                    height: level.height(),
                    base_width: width,
                    base_height: height,
                    want_width: w,
                    want_height: h,
                });
            }
        }
        Ok(MipChain { levels })
    }

    /// The levels, base first; never empty.
    pub fn levels(&self) -> &[Texture] {
        &self.levels
    }

    /// The base level, level 0.
    pub fn base(&self) -> &Texture {
        &self.levels[0]
    }

    /// The chain as stored in `format`: every level quantized (after filtering at full precision).
    pub fn quantized(&self, format: TexelFormat) -> MipChain {
        MipChain { levels: self.levels.iter().map(|l| l.quantized(format)).collect() }
    }
}

/// The next level of `level`: each side halved, down to 1, each texel the mean of those it covers.
fn halve(level: &Texture) -> Texture {
    let (width, height) = ((level.width() / 2).max(1), (level.height() / 2).max(1));
    let (fx, fy) = (level.width() / width, level.height() / height);
    let weight = 1.0 / f64::from(fx * fy);
    let mut texels = Vec::with_capacity(width as usize * height as usize);
    for j in 0..height {
        for i in 0..width {
            let covered = (fy * j..fy * (j + 1)).flat_map(|y| (fx * i..fx * (i + 1)).map(move |x| (x, y)));
            texels.push(weighted_sum(covered.map(|(x, y)| (level.texel(x, y), weight))));
        }
    }
    level.with_texels(width, height, texels)
}
