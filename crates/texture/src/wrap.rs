//! Wrap modes: which texel an integer texel index outside the image addresses.

use serde::{Deserialize, Serialize};

/// A texture wrap mode (TEXTURE_WRAP_S or TEXTURE_WRAP_T), applied to each integer texel
/// index a filter reads, as in OpenGL 4.6 section 8.14.2, Table 8.20.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Wrap {
    /// GL_REPEAT: i mod size (non-negative).
    #[default]
    Repeat,
    /// GL_MIRRORED_REPEAT: (size - 1) - mirror((i mod 2 size) - size), where mirror(a) is a
    /// for a >= 0 and -(1 + a) otherwise.
    MirroredRepeat,
    /// GL_CLAMP_TO_EDGE: clamp(i, 0, size - 1).
    ClampToEdge,
}

impl Wrap {
    /// The texel, in 0..size, that index `i` addresses along a side of `size` texels (a size of
    /// 0 counts as 1).
    pub fn index(self, i: i64, size: u32) -> u32 {
        let n = i64::from(size.max(1));
        let wrapped = match self {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::MirroredRepeat => (n - 1) - mirror(i.rem_euclid(2 * n) - n),
            Wrap::ClampToEdge => i.clamp(0, n - 1),
        };
        wrapped as u32
    }
}

/// OpenGL's mirror(a): a for a >= 0, -(1 + a) otherwise.
fn mirror(a: i64) -> i64 {
    if a >= 0 {
        a
    } else {
        -(1 + a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirror_reflects_negatives_about_minus_one_half() {
        let got: Vec<i64> = (-3..=2).map(mirror).collect();
        assert_eq!(got, [2, 1, 0, 0, 1, 2]);
    }
}
