//! The texture unit fitted to a workload (paper 001 section II-5; `model::texture_unit`):
//! which of it the workload needs ([`needs`]: the unit at all, its bilinear filter, its
//! mip chain), and the narrowest precision knobs (`subtexel`, `lod_frac`, `weight`,
//! `recip`: `fx::TexFormats`) with which every textured fragment of every scene stays
//! within the conformance tolerance and the target's PSNR ([`fit_formats`]), each scene
//! judged by `accuracy::texture::judge` at the design's level-of-detail rule (001's eq. 4).

use accuracy::texture::{judge, TextureSetup};
use fx::TexFormats;
use reference::{prepare, raster, Options, Prepared};
use scene::Trilist;
use sweep::texture::{Knob, Knobs};
use texture::{Filter, LodRule, MipMode};

/// A textured scene of the workload.
pub struct TexScene {
    pub name: String,
    pub list: Trilist,
}

/// What of the texture unit a workload needs, and the first scene needing each part.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TexNeeds {
    /// Some triangle is textured: the texture units are part of the design.
    pub unit: Option<String>,
    /// Some textured triangle's sampler filters bilinearly (`Filter::Linear`, minified or
    /// magnified).
    pub filter: Option<String>,
    /// Some textured fragment is minified (lambda > 0, GL 4.6 section 8.14.3) under a
    /// sampler with a mip mode: the chain's levels beyond the base are read.
    pub mip: Option<String>,
}

/// What `scenes` need. Minification is decided by the reference's level of detail at each
/// fragment (its screen-space derivatives of s and t, in texels of level 0, through 001's
/// scale factor, `texture::LodRule::Max`: `accuracy::texture`'s reference).
pub fn needs(scenes: &[TexScene]) -> TexNeeds {
    let mut n = TexNeeds::default();
    for sc in scenes {
        for tri in &sc.list.triangles {
            let Some(t) = tri[0].tex.and_then(|tex| sc.list.textures.get(tex.texture as usize)) else { continue };
            n.unit.get_or_insert_with(|| sc.name.clone());
            let s = t.sampler;
            if s.min == Filter::Linear || s.mag == Filter::Linear {
                n.filter.get_or_insert_with(|| sc.name.clone());
            }
            if s.mip == MipMode::None || n.mip.is_some() {
                continue;
            }
            let base = t.mips.base();
            let (w, h) = (f64::from(base.width()), f64::from(base.height()));
            let Prepared::Draw(parts, interp) = prepare(tri, &Options::default()) else { continue };
            let mut minified = false;
            for part in &parts {
                raster::rasterize(part, sc.list.width, sc.list.height, interp, |frag| {
                    let [[sx, tx], [sy, ty]] = frag.dst;
                    minified |= LodRule::Max.rho(sx * w, tx * h, sy * w, ty * h) > 1.0;
                });
            }
            if minified {
                n.mip = Some(sc.name.clone());
            }
        }
    }
    n
}

/// The texture unit's share of an accuracy target: no fragment out of the conformance
/// tolerance, and at least `psnr_db` on every scene when given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexTarget {
    pub psnr_db: Option<f64>,
}

/// One trial: the knobs, and the first scene's miss (`None`: every scene met the target).
#[derive(Clone, Debug, PartialEq)]
pub struct TexTrial {
    pub knobs: Knobs,
    pub miss: Option<String>,
}

/// The fit's outcome.
#[derive(Clone, Debug, PartialEq)]
pub struct TexFit {
    pub formats: TexFormats,
    /// Each knob one bit narrower than fitted (where it can be), every one missing the target.
    pub narrower: Vec<(Knob, TexTrial)>,
    /// Per scene at the fitted formats: (name, fragments, failures, PSNR; `None` exact).
    pub scenes: Vec<(String, u64, u64, Option<f64>)>,
    /// Designs judged.
    pub trials: usize,
}

/// Each knob's narrowest value tried: Vulkan's minimum of the sub-texel and level bits
/// would be 4, but the search goes below it, since a workload may need less.
fn floor(knob: Knob) -> u32 {
    match knob {
        Knob::Subtexel | Knob::LodFrac | Knob::Weight => 1,
        Knob::Recip => 4,
    }
}

/// The first miss of `target` by the unit at `knobs` over `scenes`, or `None`.
fn miss(scenes: &[TexScene], knobs: &Knobs, target: &TexTarget) -> Result<Option<String>, String> {
    let setup = TextureSetup { formats: knobs.formats(), lod: LodRule::Max, affine: false };
    for sc in scenes {
        let r = judge(&sc.list, &setup).map_err(|e| format!("{}: {e}", sc.name))?;
        if r.failures > 0 {
            return Ok(Some(format!("{}: {} fragments out of tolerance", sc.name, r.failures)));
        }
        if let Some(p) = target.psnr_db.filter(|&p| r.psnr_db < p) {
            return Ok(Some(format!("{}: PSNR {:.1} dB < {p}", sc.name, r.psnr_db)));
        }
    }
    Ok(None)
}

/// The narrowest knobs meeting `target` on every scene: from the defaults (an error when
/// they miss), each knob in turn bisected between its floor and its value with the others
/// fixed, in rounds until none moves; then each knob one bit narrower is judged, so that
/// the design is minimal knob by knob (the knobs are monotone on the shipped scenes,
/// `sweep --texture`'s sensitivity charts; a knob that is not is caught by that check).
pub fn fit_formats(scenes: &[TexScene], target: &TexTarget) -> Result<TexFit, String> {
    let mut trials = 0;
    let mut judge_at = |k: &Knobs| {
        trials += 1;
        miss(scenes, k, target)
    };
    if let Some(m) = judge_at(&Knobs::DEFAULT)? {
        return Err(format!("the texture unit's default formats miss the target: {m}"));
    }
    let mut knobs = Knobs::DEFAULT;
    loop {
        let before = knobs;
        for knob in Knob::ALL {
            // Invariant: `hi` passes; `lo - 1` is below the floor or fails.
            let (mut lo, mut hi) = (floor(knob), knobs.get(knob));
            while lo < hi {
                let mid = (lo + hi) / 2;
                if judge_at(&knobs.with(knob, mid))?.is_none() {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            knobs = knobs.with(knob, hi);
        }
        if knobs == before {
            break;
        }
    }
    let mut narrower = Vec::new();
    for knob in Knob::ALL.into_iter().filter(|&k| knobs.get(k) > floor(k)) {
        let k = knobs.with(knob, knobs.get(knob) - 1);
        let m = judge_at(&k)?;
        if m.is_none() {
            return Err(format!("{} = {} also meets the target: the search is not minimal", knob.name(), k.get(knob)));
        }
        narrower.push((knob, TexTrial { knobs: k, miss: m }));
    }
    let formats = knobs.formats();
    let setup = TextureSetup { formats, lod: LodRule::Max, affine: false };
    let scenes = scenes
        .iter()
        .map(|sc| {
            let r = judge(&sc.list, &setup).map_err(|e| format!("{}: {e}", sc.name))?;
            Ok((sc.name.clone(), r.pixels, r.failures, r.psnr_db.is_finite().then_some(r.psnr_db)))
        })
        .collect::<Result<_, String>>()?;
    Ok(TexFit { formats, narrower, scenes, trials })
}
