//! The texture unit's area (paper 001 section II-5; `rtl::texture_*`) at formats and cache
//! geometries never synthesized, in ECP5 cells: LUT4s, flip-flops, MULT18X18D blocks,
//! DP16KD block RAMs and distributed (LUT) RAMs.
//!
//! **The cache** (`texture_cache`) is calibrated on Yosys `synth_ecp5` runs of the emitted
//! unit at every geometry built (`rtl::texture_cache::GEOMETRIES`; `area/texture.json`,
//! from `edgepaint report --no-pnr --flow ecp5 --unit texture_cache --param SETS=..
//! --param WAYS=.. --param LINE=..`). Its block RAMs are counted, not fitted
//! ([`block_rams`]): each bank keeps a data RAM and a tag RAM per way, and Yosys maps a RAM
//! of at least [`BRAM_MIN_BITS`] bits to DP16KDs in the configuration needing fewest, the
//! others to LUT RAM; that gives every calibration run's count. LUT4s, flip-flops and LUT
//! RAMs are non-negative least-squares combinations ([`crate::area::nnls`]) of the bit
//! counts of [`cache_features`], fitted to the runs not held out ([`CacheSample::held_out`]);
//! [`validation`] gives the error on the held-out ones. Yosys' mapping of the small
//! geometries scatters (8 sets, 2 ways, 4 words maps to 3,120 LUT4s, 16 sets to 1,492), so
//! the fit is a trend: a geometry that was synthesized is priced by its run
//! ([`cache_cost`] says `Measured`).
//!
//! **The other units** (`texture_coords`, `texture_address`, `texture_filter`) are emitted
//! at the default formats only (their widths are `fx::TexFormats::DEFAULT`'s, constants of
//! the RTL), measured there (`area/texture.json`'s `units`), and scaled elsewhere: LUT4s
//! and flip-flops in proportion to the sum of the widths each unit's datapath carries
//! ([`datapath_bits`]), multipliers and RAMs kept. A first-order estimate, `Modelled` at
//! any formats but the defaults.

use crate::row::Source;
use fx::TexFormats;
use model::texture_cache::Params as CacheParams;
use serde::{Deserialize, Serialize};

/// What a texture unit costs on ECP5 (Yosys `synth_ecp5`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TexCost {
    pub lut4: f64,
    pub ff: f64,
    /// MULT18X18D.
    pub dsp: f64,
    /// DP16KD (18 Kbit).
    pub bram: f64,
    /// Distributed RAMs (DPR16X4), as `edgepaint report` counts them.
    pub lut_ram: f64,
}

impl TexCost {
    fn add(self, o: TexCost) -> TexCost {
        TexCost {
            lut4: self.lut4 + o.lut4,
            ff: self.ff + o.ff,
            dsp: self.dsp + o.dsp,
            bram: self.bram + o.bram,
            lut_ram: self.lut_ram + o.lut_ram,
        }
    }
}

/// One Yosys run of `texture_cache` at a geometry.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CacheSample {
    pub sets: u32,
    pub ways: u32,
    pub line: u32,
    /// Left out of the fit, for [`validation`].
    #[serde(default)]
    pub held_out: bool,
    pub cost: TexCost,
}

impl CacheSample {
    fn params(&self) -> CacheParams {
        CacheParams { sets: self.sets, ways: self.ways, line: self.line }
    }
}

/// The calibration: the cache's runs and the other units' at the default formats.
#[derive(Clone, Debug, Deserialize)]
pub struct Calibration {
    pub cache: Vec<CacheSample>,
    pub texture_coords: TexCost,
    pub texture_address: TexCost,
    pub texture_filter: TexCost,
}

impl Calibration {
    /// The committed runs (`area/texture.json`).
    pub fn committed() -> &'static Calibration {
        static C: std::sync::OnceLock<Calibration> = std::sync::OnceLock::new();
        C.get_or_init(|| serde_json::from_str(include_str!("../area/texture.json")).expect("area/texture.json parses"))
    }
}

/// A RAM Yosys maps to block RAM when it holds at least this many bits (the calibration:
/// a 64-word data RAM, 2,048 bits, goes to a DP16KD; a 32-word one and a 64-set tag RAM of
/// 1,216 bits to LUT RAM; a 128-set tag RAM of 2,304 bits to a DP16KD).
pub const BRAM_MIN_BITS: u32 = 2048;

/// DP16KD's configurations, (depth, width).
const DP16KD: [(u32, u32); 6] = [(16384, 1), (8192, 2), (4096, 4), (2048, 9), (1024, 18), (512, 36)];

/// The RAMs of one bank of a geometry: (depth, width) of each way's data RAM (sets x line
/// words of 32 bits) and tag RAM (a tag and its valid bit per set).
fn rams(p: &CacheParams) -> [(u32, u32); 2] {
    [(p.sets * p.line, 32), (p.sets, p.tag_bits() + 1)]
}

/// The DP16KDs of a (depth, width) RAM: the configuration needing fewest.
fn dp16kd(depth: u32, width: u32) -> u32 {
    DP16KD.iter().map(|&(d, w)| depth.div_ceil(d) * width.div_ceil(w)).min().expect("configurations")
}

/// The block RAMs Yosys maps the cache at `p` to: four banks, each way's data and tag
/// RAMs of at least [`BRAM_MIN_BITS`] bits.
pub fn block_rams(p: &CacheParams) -> u32 {
    let per_way: u32 = rams(p).iter().filter(|(d, w)| d * w >= BRAM_MIN_BITS).map(|&(d, w)| dp16kd(d, w)).sum();
    model::texture_cache::LANES as u32 * p.ways * per_way
}

/// The bit counts the cache's LUT4s, flip-flops and LUT RAMs are fitted on, with their
/// names: fixed control (1); the ways' tag comparators and data multiplexers (ways x (tag
/// bits + 32), four banks); the bits of the RAMs left in LUT RAM; the fill's word counter
/// and the line's address bits (log2 line).
pub fn cache_features(p: &CacheParams) -> [(&'static str, f64); 4] {
    let lanes = model::texture_cache::LANES as f64;
    let lut_ram_bits: u32 =
        rams(p).iter().filter(|(d, w)| d * w < BRAM_MIN_BITS).map(|(d, w)| d * w).sum::<u32>() * p.ways;
    [
        ("1", 1.0),
        ("ways x (tag + 32) x 4", lanes * f64::from(p.ways * (p.tag_bits() + 32))),
        ("LUT RAM bits x 4", lanes * f64::from(lut_ram_bits)),
        ("log2 line", f64::from(p.line_bits())),
    ]
}

/// The fitted coefficients of [`cache_features`] for LUT4s, flip-flops and LUT RAMs.
#[derive(Clone, Debug, PartialEq)]
pub struct CacheModel {
    pub lut4: Vec<f64>,
    pub ff: Vec<f64>,
    pub lut_ram: Vec<f64>,
}

/// Fits [`CacheModel`] to the samples not held out; an error when there are none.
pub fn fit_cache(samples: &[CacheSample]) -> Result<CacheModel, String> {
    let kept: Vec<&CacheSample> = samples.iter().filter(|s| !s.held_out).collect();
    if kept.len() < cache_features(&kept.first().ok_or("no texture_cache sample to fit")?.params()).len() {
        return Err(format!("{} texture_cache samples: too few to fit", kept.len()));
    }
    let a: Vec<Vec<f64>> = kept.iter().map(|s| cache_features(&s.params()).map(|f| f.1).to_vec()).collect();
    let y = |f: fn(&TexCost) -> f64| kept.iter().map(|s| f(&s.cost)).collect::<Vec<f64>>();
    Ok(CacheModel {
        lut4: crate::area::nnls(&a, &y(|c| c.lut4)),
        ff: crate::area::nnls(&a, &y(|c| c.ff)),
        lut_ram: crate::area::nnls(&a, &y(|c| c.lut_ram)),
    })
}

impl CacheModel {
    /// The committed calibration fitted.
    pub fn calibrated() -> &'static CacheModel {
        static M: std::sync::OnceLock<CacheModel> = std::sync::OnceLock::new();
        M.get_or_init(|| fit_cache(&Calibration::committed().cache).expect("area/texture.json has cache samples"))
    }

    /// The model's cost of the cache at `p` (block RAMs counted).
    pub fn cost(&self, p: &CacheParams) -> TexCost {
        let f = cache_features(p);
        let dot = |c: &[f64]| f.iter().zip(c).map(|(f, c)| f.1 * c).sum::<f64>();
        TexCost {
            lut4: dot(&self.lut4),
            ff: dot(&self.ff),
            dsp: 0.0,
            bram: f64::from(block_rams(p)),
            lut_ram: dot(&self.lut_ram),
        }
    }
}

/// The cache at `p`: its Yosys run where the calibration synthesized it, else the model.
pub fn cache_cost(p: &CacheParams) -> (TexCost, Source) {
    let measured = Calibration::committed().cache.iter().find(|s| s.params() == *p);
    match measured {
        Some(s) => (s.cost, Source::Measured),
        None => (CacheModel::calibrated().cost(p), Source::Modelled),
    }
}

/// The bits each datapath unit carries at formats `f`, which its LUT4s and flip-flops are
/// scaled by: `texture_coords` the pixel's s·q, t·q and q, the triangle's six gradients
/// (carried past the divider's stages), the reciprocal and lambda (`lod_frac` bits);
/// `texture_address` s and t, the two sub-texel fractions and lambda; `texture_filter` the
/// weights of the bilinear filter's three lerps per channel and the level blend.
pub fn datapath_bits(f: &TexFormats) -> [f64; 3] {
    let st = f64::from(f.st.bits());
    let coords = 2.0 * st
        + f64::from(f.q.bits())
        + 4.0 * f64::from(f.dst.bits())
        + 2.0 * f64::from(f.dq.bits())
        + f64::from(f.recip)
        + f64::from(f.lod_frac);
    let address = 2.0 * st + 2.0 * f64::from(f.subtexel) + f64::from(f.lod_frac);
    let filter = 3.0 * f64::from(f.weight) + f64::from(f.lod_frac);
    [coords, address, filter]
}

/// `c` with its LUT4s and flip-flops scaled by `ratio`.
fn scaled(c: TexCost, ratio: f64) -> TexCost {
    TexCost { lut4: c.lut4 * ratio, ff: c.ff * ratio, ..c }
}

/// The texture unit at formats `f` with the cache at `p`: its four units summed, and
/// whether every figure is Yosys' (the default formats and a geometry synthesized).
pub fn unit_cost(f: &TexFormats, p: &CacheParams) -> (TexCost, Source) {
    let cal = Calibration::committed();
    let (bits, default) = (datapath_bits(f), datapath_bits(&TexFormats::DEFAULT));
    let datapath = [cal.texture_coords, cal.texture_address, cal.texture_filter]
        .into_iter()
        .zip(bits.iter().zip(default))
        .fold(TexCost::default(), |sum, (c, (b, d))| sum.add(scaled(c, b / d)));
    let (cache, source) = cache_cost(p);
    let measured = source == Source::Measured && *f == TexFormats::DEFAULT;
    (datapath.add(cache), if measured { Source::Measured } else { Source::Modelled })
}

/// The model's error on the held-out cache runs, as a Markdown table: per geometry, Yosys
/// against the model in each metric; then the mean absolute error.
pub fn validation(model: &CacheModel, samples: &[CacheSample]) -> String {
    let mut md = String::from(
        "| held-out geometry (sets, ways, words) | LUT4 Yosys / model | FF | LUT RAM | DP16KD |\n|---|---:|---:|---:|---:|\n",
    );
    let mut errors = [0.0f64; 3];
    let held: Vec<&CacheSample> = samples.iter().filter(|s| s.held_out).collect();
    for s in &held {
        let m = model.cost(&s.params());
        let cell = |y: f64, m: f64, k: usize, errors: &mut [f64; 3]| {
            let e = if y > 0.0 { m / y - 1.0 } else { 0.0 };
            errors[k] += e.abs();
            format!("{y:.0} / {m:.0} ({:+.0}%)", 100.0 * e)
        };
        md += &format!(
            "| {}, {}, {} | {} | {} | {} | {:.0} / {:.0} |\n",
            s.sets,
            s.ways,
            s.line,
            cell(s.cost.lut4, m.lut4, 0, &mut errors),
            cell(s.cost.ff, m.ff, 1, &mut errors),
            cell(s.cost.lut_ram, m.lut_ram, 2, &mut errors),
            s.cost.bram,
            m.bram
        );
    }
    let n = held.len().max(1) as f64;
    md += &format!(
        "| mean absolute error | {:.0}% | {:.0}% | {:.0}% | |\n",
        100.0 * errors[0] / n,
        100.0 * errors[1] / n,
        100.0 * errors[2] / n
    );
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_rams_are_counted_exactly_on_every_calibration_run() {
        for s in &Calibration::committed().cache {
            assert_eq!(f64::from(block_rams(&s.params())), s.cost.bram, "{s:?}");
        }
    }

    #[test]
    fn the_cache_model_grows_with_the_ways_and_prices_runs_as_measured() {
        let m = CacheModel::calibrated();
        let at = |sets, ways, line| m.cost(&CacheParams { sets, ways, line });
        assert!(at(64, 4, 4).lut4 > at(64, 2, 4).lut4 && at(64, 2, 4).lut4 > at(64, 1, 4).lut4);
        let default = CacheParams { sets: 64, ways: 2, line: 4 };
        assert_eq!(cache_cost(&default).1, Source::Measured);
        assert_eq!(cache_cost(&CacheParams { sets: 128, ways: 4, line: 2 }).1, Source::Modelled);
        let (unit, source) = unit_cost(&TexFormats::DEFAULT, &default);
        assert_eq!(source, Source::Measured);
        let narrow = TexFormats { recip: 12, lod_frac: 4, ..TexFormats::DEFAULT };
        let (cheaper, source) = unit_cost(&narrow, &default);
        assert!(cheaper.lut4 < unit.lut4 && source == Source::Modelled);
        assert!(validation(m, &Calibration::committed().cache).contains("mean absolute error"));
    }
}
