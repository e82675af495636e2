//! The number formats of the texture unit (paper 001, section II-5): what it is given per
//! pixel and per triangle, and the precisions of its level of detail, texel addresses and
//! filter. Model: `model::texture_unit`.
//!
//! | field | default | quantity |
//! |---|---|---|
//! | `st` | S8.20 saturate | s·q and t·q per pixel (q below), and s, t after the divide (001 eq. 3) |
//! | `q` | U1.20 | q = w_min / w per pixel, in (0, 1] |
//! | `dst` | S8.24 | d(s·q)/dx, d(s·q)/dy, d(t·q)/dx, d(t·q)/dy per triangle |
//! | `dq` | S1.28 | dq/dx, dq/dy per triangle |
//! | `recip` | 24 | fraction bits of the reciprocal mantissa 1/m, m in [1/2, 1) the normalised q |
//! | `subtexel` | 8 | fraction bits of texel coordinates (Vulkan's `subTexelPrecisionBits`) |
//! | `lod_frac` | 6 | fraction bits of the level of detail (Vulkan's `mipmapPrecisionBits`) |
//! | `weight` | 8 | fraction bits of the bilinear filter's weights |
//!
//! The defaults meet Vulkan 1.0's minimums (4 sub-texel and 4 level bits) and Vulkan
//! Roadmap 2022's (8 and 6), see `../shared/PRECISION.md`. In a formats file they are the
//! object under the key `"texture"`, e.g. `{"xy": "S11.4", "texture": {"subtexel": 4}}`.

use crate::fmt::Fmt;
use serde::{Deserialize, Serialize};

/// The largest texture side the texture unit addresses, log2: 4096 texels, as the scene
/// loader allows (`texture::MAX_SIDE`).
pub const MAX_SIZE_LOG2: u32 = 12;

/// The texture unit's formats and precisions (see the module doc). JSON: an object with
/// these keys, every one optional.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TexFormats {
    pub st: Fmt,
    pub q: Fmt,
    pub dst: Fmt,
    pub dq: Fmt,
    pub recip: u32,
    pub subtexel: u32,
    pub lod_frac: u32,
    pub weight: u32,
}

impl Default for TexFormats {
    fn default() -> TexFormats {
        TexFormats::DEFAULT
    }
}

impl TexFormats {
    /// The texture unit's formats of a formats file: its object `"texture"` over the
    /// defaults (all of them when it has none), checked.
    pub fn from_formats_file(json: &serde_json::Value) -> Result<TexFormats, String> {
        let f = match json.get("texture") {
            None => TexFormats::DEFAULT,
            Some(t) => serde_json::from_value(t.clone()).map_err(|e| format!("texture: {e}"))?,
        };
        f.check().map_err(|e| format!("texture: {e}"))?;
        Ok(f)
    }

    /// The defaults, as a constant: the RTL's widths are read off it at compile time.
    pub const DEFAULT: TexFormats = TexFormats {
        st: Fmt::s(8, 20).saturating(),
        q: Fmt::u(1, 20),
        dst: Fmt::s(8, 24),
        dq: Fmt::s(1, 28),
        recip: 24,
        subtexel: 8,
        lod_frac: 6,
        weight: 8,
    };

    /// Whether these formats can work; the error names the field and the rule.
    pub fn check(&self) -> Result<(), String> {
        let need = |ok: bool, what: String| if ok { Ok(()) } else { Err(what) };
        need(
            self.st.signed && self.st.frac >= self.subtexel + MAX_SIZE_LOG2 && self.st.bits() <= 40,
            format!(
                "st = {}: must be signed, at most 40 bits, with at least subtexel + {MAX_SIZE_LOG2} = {} fraction bits \
                 (texel coordinates of a {}-texel level)",
                self.st,
                self.subtexel + MAX_SIZE_LOG2,
                1 << MAX_SIZE_LOG2
            ),
        )?;
        need(
            !self.q.signed && self.q.int == 1 && (2..=32).contains(&self.q.frac),
            format!("q = {}: q = w_min / w is in (0, 1]: U1.<2 to 32>", self.q),
        )?;
        need(self.dst.signed && self.dst.bits() <= 48, format!("dst = {}: must be signed, at most 48 bits", self.dst))?;
        need(self.dq.signed && self.dq.bits() <= 40, format!("dq = {}: must be signed, at most 40 bits", self.dq))?;
        need((4..=32).contains(&self.recip), format!("recip = {}: 4 to 32 fraction bits", self.recip))?;
        need((1..=12).contains(&self.subtexel), format!("subtexel = {}: 1 to 12 bits", self.subtexel))?;
        need((1..=10).contains(&self.lod_frac), format!("lod_frac = {}: 1 to 10 bits", self.lod_frac))?;
        need((1..=12).contains(&self.weight), format!("weight = {}: 1 to 12 bits", self.weight))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_pass_and_impossible_formats_are_named() {
        TexFormats::default().check().unwrap();
        let narrow_st = TexFormats { st: Fmt::s(8, 12), ..TexFormats::default() };
        assert!(narrow_st.check().unwrap_err().starts_with("st = S8.12"));
        let signed_q = TexFormats { q: Fmt::s(1, 20), ..TexFormats::default() };
        assert!(signed_q.check().unwrap_err().starts_with("q = S1.20"));
        let json: TexFormats = serde_json::from_str(r#"{"subtexel": 4, "lod_frac": 4}"#).unwrap();
        assert_eq!((json.subtexel, json.lod_frac, json.weight), (4, 4, 8));
        assert!(serde_json::from_str::<TexFormats>(r#"{"texels": 4}"#).is_err());
        let file: serde_json::Value = serde_json::from_str(r#"{"xy": "S11.4", "texture": {"weight": 6}}"#).unwrap();
        assert_eq!(TexFormats::from_formats_file(&file).unwrap().weight, 6);
        assert_eq!(crate::Formats::with_overrides(320, 240, &file).unwrap().xy.frac, 4);
        let bad: serde_json::Value = serde_json::from_str(r#"{"texture": {"subtexel": 0}}"#).unwrap();
        assert!(TexFormats::from_formats_file(&bad).unwrap_err().starts_with("texture: subtexel = 0"));
    }
}
