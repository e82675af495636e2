//! Where the texture unit finds a texel: a mip chain laid out in texture memory as four
//! parity planes per level, so that the four texels of any 2x2 bilinear footprint lie in
//! four different banks of the texture cache (`model::texture_cache`, paper 001 section
//! II-5's texture cache) and are read in one clock.
//!
//! Level d of a 2^ws x 2^hs texture is W x H = 2^max(ws-d, 0) x 2^max(hs-d, 0) texels. It
//! takes 4 planes of P = max(W/2, 1) x max(H/2, 1) words: texel (i, j) is word
//! (j >> 1) · max(W/2, 1) + (i >> 1) of plane (j & 1) · 2 + (i & 1), its *bank*. The levels
//! follow each other from the texture's base address, level 0 first. A level at least 2x2
//! takes exactly W · H words; a 1-wide or 1-high level leaves its odd planes empty.
//!
//! One word is one texel in its [`TexelFormat`]'s encoding (`TexelFormat::encode`), in the
//! low bits.

use crate::texture_cache::{MemAsk, MemIn};
use crate::texture_unit::TexState;
use scene::Trilist;
use std::collections::VecDeque;
use texture::{LodRule, MipChain, TexelFormat};

/// Bits of a texture memory word address: 64 Mi words, room for the chain of a 4096 x 4096
/// texture (22.4 Mi words) and more.
pub const ADDR_BITS: u32 = 26;

/// Words of each plane of level `d` of a 2^`ws` x 2^`hs` texture.
pub fn plane_words(ws: u32, hs: u32, d: u32) -> u32 {
    1 << (ws.saturating_sub(d + 1) + hs.saturating_sub(d + 1))
}

/// Words before level `d`, from the texture's base address.
pub fn level_offset(ws: u32, hs: u32, d: u32) -> u32 {
    (0..d).map(|k| 4 * plane_words(ws, hs, k)).sum()
}

/// Words the chain of `levels` levels of a 2^`ws` x 2^`hs` texture takes.
pub fn chain_words(ws: u32, hs: u32, levels: u32) -> u32 {
    level_offset(ws, hs, levels)
}

/// The bank (parity plane) of texel (i, j).
pub fn bank(i: u32, j: u32) -> usize {
    ((j & 1) * 2 + (i & 1)) as usize
}

/// The word address of texel (i, j) of level `d`, of a texture at `base`.
pub fn address(base: u32, ws: u32, hs: u32, d: u32, i: u32, j: u32) -> u32 {
    let pitch_log2 = ws.saturating_sub(d + 1);
    base + level_offset(ws, hs, d) + bank(i, j) as u32 * plane_words(ws, hs, d) + ((j >> 1) << pitch_log2) + (i >> 1)
}

/// The words of `chain` (power-of-two sides) in `format`, laid out from address 0.
pub fn layout(chain: &MipChain, format: TexelFormat) -> Vec<u32> {
    let base = chain.base();
    let (ws, hs) = (base.width().trailing_zeros(), base.height().trailing_zeros());
    let mut words = vec![0; chain_words(ws, hs, chain.levels().len() as u32) as usize];
    for (d, level) in chain.levels().iter().enumerate() {
        for j in 0..level.height() {
            for i in 0..level.width() {
                words[address(0, ws, hs, d as u32, i, j) as usize] = format.encode(level.texel(i, j));
            }
        }
    }
    words
}

/// Every texture of a trilist in one texture memory, one after the other from word 0, and
/// the state each is drawn with (index: `scene::Tex::texture`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextureMemory {
    pub words: Vec<u32>,
    pub states: Vec<TexState>,
}

impl TextureMemory {
    /// `list`'s textures laid out, drawn at level-of-detail rule `lod`; an error names the
    /// texture and the unit's rule it breaks (`TexState::check`).
    pub fn load(list: &Trilist, lod: LodRule) -> Result<TextureMemory, String> {
        let mut m = TextureMemory { words: Vec::new(), states: Vec::new() };
        for (k, t) in list.textures.iter().enumerate() {
            let base = t.mips.base();
            let state = TexState {
                size_log2: [base.width().trailing_zeros(), base.height().trailing_zeros()],
                levels: t.mips.levels().len() as u32,
                base: m.words.len() as u32,
                format: t.format,
                sampler: t.sampler,
                env: t.env,
                lod,
            };
            state.check().map_err(|e| format!("texture {k} ({}): {e}", t.images[0].display()))?;
            m.words.extend(layout(&t.mips, t.format));
            m.states.push(state);
        }
        if m.words.len() as u64 > 1 << ADDR_BITS {
            return Err(format!("the textures take {} words: texture memory holds 2^{ADDR_BITS}", m.words.len()));
        }
        Ok(m)
    }
}

/// The texture memory behind `texture_unit`'s read port (`mem$valid`, `mem$addr`,
/// `mem$ack`, `mem$rvalid`, `mem$rdata`): each word asked and acknowledged comes back
/// `latency` cycles later, in order, at most one a cycle.
#[derive(Clone, Debug)]
pub struct ReadPort {
    pub words: Vec<u32>,
    pub latency: u64,
    queue: VecDeque<(u64, u32)>,
}

impl ReadPort {
    pub fn new(words: Vec<u32>, latency: u64) -> ReadPort {
        ReadPort { words, latency, queue: VecDeque::new() }
    }

    /// Cycle `now`'s answer; a word asked in it is taken when `ack`.
    pub fn answer(&mut self, now: u64, ack: bool) -> MemIn {
        let answer = self.queue.front().filter(|(due, _)| *due <= now).map(|&(_, w)| w);
        if answer.is_some() {
            self.queue.pop_front();
        }
        MemIn { ack, rvalid: answer.is_some(), rdata: answer.unwrap_or(0) }
    }

    /// After cycle `now` with answer `m`: the word `asked` (when valid).
    pub fn ask(&mut self, now: u64, m: &MemIn, asked: MemAsk) {
        if asked.valid && m.ack {
            let due = (now + self.latency).max(self.queue.back().map_or(0, |(d, _)| d + 1));
            let word = self.words.get(asked.addr as usize).copied().unwrap_or(0);
            self.queue.push_back((due, word));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_texel_of_a_chain_has_its_own_word_in_its_bank() {
        for (ws, hs) in [(0, 0), (3, 0), (0, 2), (2, 3), (4, 4)] {
            let levels = ws.max(hs) + 1;
            let mut seen = vec![false; chain_words(ws, hs, levels) as usize];
            for d in 0..levels {
                let (w, h) = (1 << ws.saturating_sub(d), 1 << hs.saturating_sub(d));
                for j in 0..h {
                    for i in 0..w {
                        let a = address(0, ws, hs, d, i, j);
                        let plane = (a - level_offset(ws, hs, d)) / plane_words(ws, hs, d);
                        assert_eq!(plane as usize, bank(i, j));
                        assert!(!std::mem::replace(&mut seen[a as usize], true), "{ws} {hs} level {d} ({i}, {j})");
                    }
                }
            }
            // Levels at least 2x2 are dense: only 1-wide or 1-high levels leave words unused.
            let dense: u32 = (0..levels).map(|d| 1 << (ws.saturating_sub(d) + hs.saturating_sub(d))).sum();
            assert!(seen.iter().filter(|s| **s).count() as u32 == dense);
        }
    }
}
