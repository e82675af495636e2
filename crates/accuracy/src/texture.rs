//! The texture unit's error: every textured fragment of a scene through the bit-exact
//! texture unit (`model::texture_unit`, paper 001 section II-5) against the float
//! reference at the same level-of-detail rule, judged as the GL and Vulkan conformance
//! tests judge texture filtering (`texture::conformance`).
//!
//! The unit is driven as the fixed-point engines drive it: the scene's triangles clipped by
//! their front end (`model::guard_band`, at the screen's default formats), each piece's
//! vertices in the hardware's words, and each fragment's s·q, t·q and q and its triangle's
//! gradients from `model::texture_setup`'s planes. The fragments are the float
//! reference's over the same triangle (its vertices snapped to the `xy` grid as the
//! rasterizer's are), and each one's lit colour is the reference's rounded to 8 bits, so
//! the numbers measure the texture path alone (setup's planes and the unit), not the
//! rasterizer's coverage, snapping or colour.

use fx::{Formats, TexFormats};
use model::guard_band;
use model::input::to_fixed;
use model::texture_cache::{hit_rate_of_trace, Params as CacheParams, Stats};
use model::texture_memory::TextureMemory;
use model::texture_setup::{tex_vertices, texture_setup};
use model::texture_unit::{Fetch, TextureUnit};
use reference::{prepare, raster, Options, Prepared};
use scene::Trilist;
use serde::Serialize;
use texture::conformance::{check, reference, tolerance_lsb, Probe};
use texture::lod::level_choice;
use texture::LodRule;

/// How the unit is driven.
#[derive(Clone, Copy, Debug)]
pub struct TextureSetup {
    pub formats: TexFormats,
    /// The unit's level-of-detail rule; the reference uses the same.
    pub lod: LodRule,
    /// Texture coordinates interpolated screen-linearly (q = 1 at every vertex: the
    /// rubber sheet) while the reference stays perspective-correct.
    pub affine: bool,
}

/// The pixel furthest out of tolerance.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TextureMiss {
    pub x: u32,
    pub y: u32,
    pub reference: [f64; 3],
    pub got: [u8; 3],
    pub error_lsb: f64,
    pub tolerance_lsb: f64,
}

/// The unit's error over a scene.
#[derive(Clone, Debug, Serialize)]
pub struct TextureReport {
    /// Textured fragments judged (hidden ones too: every fragment the rasterizer makes).
    pub pixels: u64,
    /// Fragments outside the conformance tolerance of every allowed result.
    pub failures: u64,
    /// Fragments at a level or texel boundary within the tolerance of a neighbouring level
    /// or texel choice only, not of the reference's own: allowed, but their whole difference
    /// from the reference (a texel or a level away) counts in the error and PSNR below.
    pub neighbour: u64,
    /// Against the reference at the fragment's own coordinates, 8-bit LSB.
    pub max_error_lsb: f64,
    pub mean_error_lsb: f64,
    pub psnr_db: f64,
    /// Cache accesses (a 2x2 footprint of one level each), in raster order triangle by
    /// triangle, the textures laid out one after the other from word 0.
    #[serde(skip)]
    pub trace: Vec<Fetch>,
    /// The texture cache's counts on `trace` at the default geometry ([`DEFAULT_CACHE`]).
    pub cache: CacheStats,
    pub worst_failure: Option<TextureMiss>,
}

/// The cache geometry the default design emits (`rtl::DEFAULT_DESIGN`'s `texture_cache`).
pub const DEFAULT_CACHE: CacheParams = CacheParams { sets: 64, ways: 2, line: 4 };

/// A cache geometry's counts on a trace.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CacheStats {
    pub sets: u32,
    pub ways: u32,
    pub line: u32,
    pub hits: u64,
    pub misses: u64,
    /// hits / (hits + misses), per lane lookup.
    pub hit_rate: f64,
}

/// The counts of the cache at `params` on `trace`.
pub fn cache_stats(params: &CacheParams, trace: &[Fetch]) -> CacheStats {
    let Stats { hits, misses, .. } = hit_rate_of_trace(params, trace);
    let CacheParams { sets, ways, line } = *params;
    let hit_rate = hits as f64 / (hits + misses).max(1) as f64;
    CacheStats { sets, ways, line, hits, misses, hit_rate }
}

/// Every textured fragment of `list` through the texture unit set up as `s`.
pub fn judge(list: &Trilist, s: &TextureSetup) -> Result<TextureReport, String> {
    let unit = TextureUnit::new(s.formats)?;
    let f = unit.formats;
    let memory = TextureMemory::load(list, s.lod)?;
    let mut r = TextureReport {
        pixels: 0,
        failures: 0,
        neighbour: 0,
        max_error_lsb: 0.0,
        mean_error_lsb: 0.0,
        psnr_db: f64::INFINITY,
        trace: Vec::new(),
        cache: cache_stats(&DEFAULT_CACHE, &[]),
        worst_failure: None,
    };
    let (mut sum, mut sum_sq) = (0.0, 0.0);
    let screen = Formats::for_resolution(list.width, list.height);
    for tri in &guard_band::pieces(list, &screen, true).triangles {
        let Some(tex) = tri[0].tex else { continue };
        let t = list.textures.get(tex.texture as usize).ok_or("a triangle names a texture the list lacks")?;
        let base = t.mips.base();
        let state = memory.states[tex.texture as usize];
        let v = to_fixed(tri, &screen).map_err(|e| format!("a clipped triangle: {e}"))?;
        // The reference takes the vertices where the rasterizer has them, snapped to `xy`:
        // the coordinates' error from the snapping (up to half a sub-pixel's worth of a
        // pixel's footprint) is the geometry's, not the texture path's.
        let snapped: scene::Triangle = std::array::from_fn(|k| scene::Vertex {
            x: screen.xy.to_f64(v[k].x),
            y: screen.xy.to_f64(v[k].y),
            ..tri[k]
        });
        let Prepared::Draw(parts, interp) = prepare(&snapped, &Options::default()) else { continue };
        let tv = tex_vertices(tri, &v, &f, s.affine).map_err(|e| e.to_string())?.expect("a textured triangle");
        let Some(planes) = texture_setup(&tv, &screen, &f) else { continue };
        let g = planes.grad();
        for part in &parts {
            raster::rasterize(part, list.width, list.height, interp, |frag| {
                let cf = frag.rgb.map(|c| c.round().clamp(0.0, 255.0) as u8);
                let p = planes.at(frag.x, frag.y);
                let sample = unit.sample(&state, &memory.words, &p, &g, cf);
                let [[sx, tx], [sy, ty]] = frag.dst;
                let (w, h) = (f64::from(base.width()), f64::from(base.height()));
                let lambda = s.lod.rho(sx * w, tx * h, sy * w, ty * h).log2();
                let probe = Probe { s: frag.st[0], t: frag.st[1], lambda };
                let cf = cf.map(f64::from);
                let got = [sample.colour[0], sample.colour[1], sample.colour[2]];
                let want = reference(&t.mips, &t.sampler, t.env, cf, probe);
                let mut worst = 0.0f64;
                for (w, g) in want.iter().zip(got) {
                    let e = (w - f64::from(g)).abs();
                    (sum, sum_sq) = (sum + e, sum_sq + e * e);
                    worst = worst.max(e);
                }
                r.max_error_lsb = r.max_error_lsb.max(worst);
                r.pixels += 1;
                r.trace.extend(&sample.fetches);
                let judged = check(&t.mips, &t.sampler, t.env, cf, probe, got);
                let own = level_choice(lambda, t.sampler.mip, t.mips.levels().len());
                if judged.is_ok() && worst > tolerance_lsb(&t.sampler, t.env, own) {
                    r.neighbour += 1;
                }
                if let Err(miss) = judged {
                    r.failures += 1;
                    if r.worst_failure.is_none_or(|w| miss.error_lsb > w.error_lsb) {
                        r.worst_failure = Some(TextureMiss {
                            x: frag.x,
                            y: frag.y,
                            reference: miss.reference,
                            got,
                            error_lsb: miss.error_lsb,
                            tolerance_lsb: miss.tolerance_lsb,
                        });
                    }
                }
            });
        }
    }
    r.cache = cache_stats(&DEFAULT_CACHE, &r.trace);
    let channels = 3.0 * r.pixels.max(1) as f64;
    r.mean_error_lsb = sum / channels;
    if sum_sq > 0.0 {
        r.psnr_db = 10.0 * (255.0f64 * 255.0 / (sum_sq / channels)).log10();
    }
    Ok(r)
}

impl TextureReport {
    /// The report as a Markdown table.
    pub fn table(&self) -> String {
        let worst = self.worst_failure.map_or("none".to_owned(), |m| {
            format!(
                "({}, {}): {:?} against {:.1?}, {:.2} LSB over a tolerance of {}",
                m.x, m.y, m.got, m.reference, m.error_lsb, m.tolerance_lsb
            )
        });
        format!(
            "| texture unit | value |\n|---|---|\n| textured fragments | {} |\n| out of conformance tolerance | {} |\n\
             | at a boundary, within tolerance of a neighbouring level or texel only | {} |\n\
             | colour max error (LSB) | {:.2} |\n| colour mean error (LSB) | {:.3} |\n| PSNR (dB) | {:.1} |\n\
             | cache accesses (2x2 footprints) | {} |\n| cache hit rate ({} sets, {} ways, {} words) | {:.4} |\n\
             | worst failure | {worst} |\n",
            self.pixels,
            self.failures,
            self.neighbour,
            self.max_error_lsb,
            self.mean_error_lsb,
            self.psnr_db,
            self.trace.len(),
            self.cache.sets,
            self.cache.ways,
            self.cache.line,
            self.cache.hit_rate
        )
    }
}
