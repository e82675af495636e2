//! The texture unit's stress families (issue 20, item 6): generated textured triangles
//! through the bit-exact unit (`model::texture_unit`, paper 001 section II-5) against the
//! float reference, judged as the GL and Vulkan conformance tests judge filtering
//! (`accuracy::texture::judge`, `texture::conformance`), at the default texture formats or
//! a formats file's `"texture"` object (`fx::TexFormats::from_formats_file`), with the
//! design's level-of-detail rule (001's eq. 4; GL 4.6 section 8.14.1 allows it).
//!
//! A cell passes when no textured fragment is out of tolerance. A cell whose inputs the
//! unit's formats cannot hold is not drawn but refused with the reason, rather than drawn
//! wrong ([`refusal`]): s·q or t·q beyond `st`'s range (the unit saturates them), a q =
//! w_min / w below `q`'s LSB (it would read as 0).

use accuracy::texture::{judge, TextureSetup};
use fx::TexFormats;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use scene::{Tex, TextureRef, Triangle, Trilist, Vertex};
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use texture::{EnvMode, Filter, LodRule, MipChain, MipMode, Sampler, TexelFormat, Texture, Weights, Wrap};

/// A family of textured stress cases.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TexFamily {
    /// A floor receding to the horizon: w from 1 at the near edge to r at the far one.
    TexGrazing,
    /// A triangle minified 2^k texels per pixel, past the top of a 4x4 texture's chain.
    TexMinify,
    /// A 4x4 texture magnified so that a texel spans 2^k pixels.
    TexMagnify,
    /// A vertex of w near 0: the other vertices' q = w_min / w of 2^-k.
    TexNearW0,
    /// s and t crossing integers (the texture's edges) under each wrap mode and filter.
    TexWrap,
    /// A 1x1 texture under every filter and mip mode, minified and magnified.
    Tex1x1,
    /// A 1024x1024 texture, from magnified 4 times to minified to its last level.
    Tex1024,
}

impl TexFamily {
    pub const ALL: [TexFamily; 7] = [
        TexFamily::TexGrazing,
        TexFamily::TexMinify,
        TexFamily::TexMagnify,
        TexFamily::TexNearW0,
        TexFamily::TexWrap,
        TexFamily::Tex1x1,
        TexFamily::Tex1024,
    ];

    /// The name the CLI and the files use.
    pub fn name(self) -> &'static str {
        match self {
            TexFamily::TexGrazing => "tex-grazing",
            TexFamily::TexMinify => "tex-minify",
            TexFamily::TexMagnify => "tex-magnify",
            TexFamily::TexNearW0 => "tex-near-w0",
            TexFamily::TexWrap => "tex-wrap",
            TexFamily::Tex1x1 => "tex-1x1",
            TexFamily::Tex1024 => "tex-1024",
        }
    }

    /// The family named `name`, if it is one.
    pub fn parse(name: &str) -> Option<TexFamily> {
        TexFamily::ALL.into_iter().find(|f| f.name() == name)
    }

    /// What it draws, for the report.
    pub fn what(self) -> &'static str {
        match self {
            TexFamily::TexGrazing => "a 64 x 64 px floor (two triangles) with w = 1 at the bottom and r at the top, a random 64 x 64 texture repeated 8 times along it, trilinear",
            TexFamily::TexMinify => "a 16 x 16 px triangle over 2^k texels per pixel of a random 4 x 4 texture (3 levels), s and t centred on 0, trilinear: lambda = k, up to 4 above the last level",
            TexFamily::TexMagnify => "a 64 x 64 px triangle on which a texel of a random 4 x 4 texture spans 2^k px, bilinear",
            TexFamily::TexNearW0 => "a 48 x 48 px triangle with w = 1 at one vertex and 2^k at the two others (q = 2^-k there), a random 16 x 16 texture, trilinear",
            TexFamily::TexWrap => "s and t from -2.5 to 2.5 over 60 px of a random 8 x 8 texture, pixel centres on texel edges, for each wrap mode x filter (nearest, bilinear, 001's Gaussian weights)",
            TexFamily::Tex1x1 => "a 1 x 1 texture under each mip mode and filter, magnified (8 px per texel) and minified (4 texels per px)",
            TexFamily::Tex1024 => "a random 1024 x 1024 texture (11 levels) on a 32 x 32 px triangle at 2^k texels per pixel, trilinear",
        }
    }

    /// The axis' name and its cells' labels, from easy to hard.
    pub fn axis(self) -> (&'static str, Vec<String>) {
        let pow = |r: std::ops::RangeInclusive<i32>| r.map(|k| format!("2^{k}")).collect();
        match self {
            TexFamily::TexGrazing => ("w ratio r", pow(0..=12)),
            TexFamily::TexMinify => ("texels per pixel", pow(0..=6)),
            TexFamily::TexMagnify => ("pixels per texel", pow(0..=12)),
            TexFamily::TexNearW0 => ("w ratio (q at the far vertices: its inverse)", pow(0..=22)),
            TexFamily::TexWrap => {
                let mut v = Vec::new();
                for w in ["repeat", "mirrored", "clamp"] {
                    for f in ["nearest", "linear", "gaussian"] {
                        v.push(format!("{w} {f}"));
                    }
                }
                ("wrap mode, filter", v)
            }
            TexFamily::Tex1x1 => {
                let mut v = Vec::new();
                for m in ["none", "nearest", "linear"] {
                    for f in ["nearest", "linear"] {
                        for z in ["magnified", "minified"] {
                            v.push(format!("mip {m}, {f}, {z}"));
                        }
                    }
                }
                ("state", v)
            }
            TexFamily::Tex1024 => ("texels per pixel", pow(-2..=10)),
        }
    }

    /// The cell at axis index `i`: its trilist.
    pub fn cell(self, i: usize) -> Trilist {
        let trilinear = Sampler { mip: MipMode::Linear, ..Sampler::default() };
        match self {
            TexFamily::TexGrazing => {
                let r = f64::from(1u32 << i);
                let tex = random(64, 64, 1, trilinear);
                // The far edge is 1/r as wide on screen (a floor seen at a grazing angle).
                let (half, c) = (32.0 / r, 32.0);
                let v = |x: f64, y: f64, w: f64, s: f64, t: f64| vertex(x, y, w, s, t);
                let quad = [
                    v(0.0, 64.0, 1.0, 0.0, 0.0),
                    v(64.0, 64.0, 1.0, 1.0, 0.0),
                    v(c + half, 0.0, r, 1.0, 8.0),
                    v(c - half, 0.0, r, 0.0, 8.0),
                ];
                list(64, 64, vec![[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]], tex)
            }
            TexFamily::TexMinify => {
                let c = 2.0 * f64::from(1u32 << i); // 16 px x 2^k texels / 4 texels, halved
                let tri =
                    [vertex(0.0, 16.0, 1.0, -c, -c), vertex(16.0, 16.0, 1.0, c, -c), vertex(0.0, 0.0, 1.0, -c, c)];
                list(16, 16, vec![tri], random(4, 4, 2, trilinear))
            }
            TexFamily::TexMagnify => {
                let span = 64.0 / f64::from(1u32 << i) / 4.0; // s across 64 px
                let (s0, t0) = (0.3, 0.6);
                let tri = [
                    vertex(0.0, 64.0, 1.0, s0, t0),
                    vertex(64.0, 64.0, 1.0, s0 + span, t0),
                    vertex(0.0, 0.0, 1.0, s0, t0 + span),
                ];
                list(64, 64, vec![tri], random(4, 4, 3, Sampler::default()))
            }
            TexFamily::TexNearW0 => {
                let r = f64::from(1u32 << i);
                let tri =
                    [vertex(0.0, 48.0, 1.0, 0.0, 0.0), vertex(48.0, 48.0, r, 3.0, 0.0), vertex(0.0, 0.0, r, 0.0, 3.0)];
                list(48, 48, vec![tri], random(16, 16, 4, trilinear))
            }
            TexFamily::TexWrap => {
                let wrap = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge][i / 3];
                let (filter, weights) = [
                    (Filter::Nearest, Weights::Linear),
                    (Filter::Linear, Weights::Linear),
                    (Filter::Linear, Weights::Gaussian),
                ][i % 3];
                let sampler =
                    Sampler { min: filter, mag: filter, mip: MipMode::None, wrap_s: wrap, wrap_t: wrap, weights };
                // 5 texture widths over 60 px: 12 px per texture, 1.5 px per texel, so that
                // pixel centres fall on texel edges and texel centres in turn.
                let tri = [
                    vertex(0.0, 60.0, 1.0, -2.5, -2.5),
                    vertex(60.0, 60.0, 1.0, 2.5, -2.5),
                    vertex(0.0, 0.0, 1.0, -2.5, 2.5),
                ];
                list(60, 60, vec![tri], random(8, 8, 5, sampler))
            }
            TexFamily::Tex1x1 => {
                let mip = [MipMode::None, MipMode::Nearest, MipMode::Linear][i / 4];
                let filter = [Filter::Nearest, Filter::Linear][i / 2 % 2];
                let sampler = Sampler { min: filter, mag: filter, mip, ..Sampler::default() };
                let span = if i.is_multiple_of(2) { 1.0 / 8.0 } else { 4.0 } * 32.0;
                let tri = [
                    vertex(0.0, 32.0, 1.0, 0.1, 0.2),
                    vertex(32.0, 32.0, 2.0, 0.1 + span, 0.2),
                    vertex(0.0, 0.0, 1.5, 0.1, 0.2 + span),
                ];
                list(32, 32, vec![tri], random(1, 1, 6, sampler))
            }
            TexFamily::Tex1024 => {
                let span = 32.0 * f64::from(i as i32 - 2).exp2() / 1024.0;
                let tri = [
                    vertex(0.0, 32.0, 1.0, 0.2, 0.3),
                    vertex(32.0, 32.0, 1.0, 0.2 + span, 0.3),
                    vertex(0.0, 0.0, 1.0, 0.2, 0.3 + span),
                ];
                list(32, 32, vec![tri], random(1024, 1024, 7, trilinear))
            }
        }
    }
}

/// A vertex at (x, y) with w and texture coordinates (s, t) of texture 0, a mid-grey lit
/// colour (REPLACE ignores it).
fn vertex(x: f64, y: f64, w: f64, s: f64, t: f64) -> Vertex {
    Vertex { w: Some(w), tex: Some(Tex { s, t, texture: 0 }), ..Vertex::new(x, y, 0.5, [128.0, 128.0, 128.0]) }
}

/// A `width` x `height` RGBA8 texture of random texels (seeded), its box-filtered chain,
/// sampled by `sampler`, REPLACE.
fn random(width: u32, height: u32, seed: u64, sampler: Sampler) -> TextureRef {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let rgba: Vec<u8> = (0..4 * width * height).map(|_| rng.gen()).collect();
    let base = Texture::from_rgba8(width, height, &rgba).expect("a valid generated texture");
    let mips = MipChain::new(base).expect("a power-of-two texture").quantized(TexelFormat::Rgba8888);
    TextureRef {
        images: vec![format!("generated {width}x{height} seed {seed}").into()],
        sampler,
        env: EnvMode::Replace,
        format: TexelFormat::Rgba8888,
        mips: Arc::new(mips),
    }
}

fn list(width: u32, height: u32, triangles: Vec<Triangle>, tex: TextureRef) -> Trilist {
    Trilist { width, height, triangles, textures: vec![tex] }
}

/// Why the unit at `f` cannot take `list`'s inputs, or `None`: a vertex's s·q or t·q
/// (q = w_min / w over its triangle) beyond `st`'s range, where the unit would saturate it;
/// a vertex's q below `q`'s LSB, where it would read as 0.
pub fn refusal(list: &Trilist, f: &TexFormats) -> Option<String> {
    let st_max = f.st.max_raw() as f64 / (f.st.frac as f64).exp2();
    let q_lsb = (-(f.q.frac as f64)).exp2();
    for tri in &list.triangles {
        let inv_w = tri.map(|v| 1.0 / v.w.unwrap_or(1.0));
        let max = inv_w.iter().copied().fold(0.0, f64::max);
        for (v, iw) in tri.iter().zip(inv_w) {
            let Some(tex) = v.tex else { continue };
            let q = iw / max;
            if q < q_lsb {
                return Some(format!(
                    "q = w_min / w = {q:.3e} at a vertex: below q's LSB (q = {}: 2^-{})",
                    f.q, f.q.frac
                ));
            }
            let (sq, tq) = (tex.s * q, tex.t * q);
            if sq.abs().max(tq.abs()) > st_max {
                return Some(format!(
                    "s·q, t·q = ({sq}, {tq}) at a vertex: beyond st = {}'s range ±{st_max:.0} (the unit saturates)",
                    f.st
                ));
            }
        }
    }
    None
}

/// One cell's record.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TexCell {
    pub family: TexFamily,
    /// The formats point's name (`default` or the formats file's stem).
    pub formats: String,
    pub label: String,
    pub fragments: u64,
    pub failures: u64,
    pub max_error_lsb: f64,
    /// `None`: exact (or not run).
    pub psnr_db: Option<f64>,
    /// The worst failure, as `accuracy::texture` describes it.
    pub worst: Option<String>,
    /// Why the cell was not drawn: the inputs the formats cannot hold ([`refusal`]), or the
    /// unit's own refusal.
    pub refused: Option<String>,
}

impl TexCell {
    /// Whether it passes (no fragment out of tolerance); `None` when refused.
    pub fn passes(&self) -> Option<bool> {
        self.refused.is_none().then_some(self.failures == 0)
    }
}

/// Runs cell `i` of `family` at formats `f` (named `formats`).
pub fn run_cell(family: TexFamily, i: usize, formats: &str, f: &TexFormats) -> TexCell {
    let list = family.cell(i);
    let mut cell = TexCell {
        family,
        formats: formats.into(),
        label: family.axis().1[i].clone(),
        fragments: 0,
        failures: 0,
        max_error_lsb: 0.0,
        psnr_db: None,
        worst: None,
        refused: refusal(&list, f),
    };
    if cell.refused.is_some() {
        return cell;
    }
    match judge(&list, &TextureSetup { formats: *f, lod: LodRule::Max, affine: false }) {
        Ok(r) => {
            cell.fragments = r.pixels;
            cell.failures = r.failures;
            cell.max_error_lsb = r.max_error_lsb;
            cell.psnr_db = r.psnr_db.is_finite().then_some(r.psnr_db);
            cell.worst = r.worst_failure.map(|m| {
                format!(
                    "({}, {}): {:?} against {:.1?}, {:.2} LSB over {}",
                    m.x, m.y, m.got, m.reference, m.error_lsb, m.tolerance_lsb
                )
            });
        }
        Err(e) => cell.refused = Some(e),
    }
    cell
}

/// Every cell of `families` at each (name, formats) point, in parallel on `jobs` threads
/// (0: one per core), `done` after each; in (family, point, axis) order.
pub fn run(
    families: &[TexFamily],
    points: &[(String, TexFormats)],
    jobs: usize,
    done: &(dyn Fn() + Sync),
) -> Result<Vec<TexCell>, String> {
    use rayon::prelude::*;
    let tasks: Vec<(TexFamily, usize, usize)> = families
        .iter()
        .flat_map(|&f| (0..points.len()).flat_map(move |p| (0..f.axis().1.len()).map(move |i| (f, p, i))))
        .collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(jobs).build().map_err(|e| e.to_string())?;
    Ok(pool.install(|| {
        tasks
            .par_iter()
            .map(|&(family, p, i)| {
                let c = run_cell(family, i, &points[p].0, &points[p].1);
                done();
                c
            })
            .collect()
    }))
}

/// The cells as Markdown: per family and formats point, its failures, worst error and
/// where it fails or is refused; then every cell.
pub fn report(cells: &[TexCell]) -> String {
    let mut md = String::from(
        "# The texture unit under stress\n\nEvery textured fragment through the bit-exact unit against the float \
         reference at 001's level-of-detail rule, judged as the conformance tests judge filtering \
         (`accuracy::texture`); a cell passes with no fragment out of tolerance. A cell whose inputs the formats \
         cannot hold is refused with the reason, not drawn.\n\n| family | formats | cells | fragments | out of \
         tolerance | worst error (LSB) | failing cells | refused cells |\n|---|---|---:|---:|---:|---:|---|---|\n",
    );
    let mut groups: Vec<(TexFamily, &str)> = cells.iter().map(|c| (c.family, c.formats.as_str())).collect();
    groups.dedup();
    for &(family, formats) in &groups {
        let mine: Vec<&TexCell> = cells.iter().filter(|c| c.family == family && c.formats == formats).collect();
        let names = |keep: fn(&TexCell) -> bool| {
            let v: Vec<&str> = mine.iter().filter(|c| keep(c)).map(|c| c.label.as_str()).collect();
            if v.is_empty() {
                "none".into()
            } else {
                v.join(", ")
            }
        };
        md += &format!(
            "| {} | {formats} | {} | {} | {} | {:.2} | {} | {} |\n",
            family.name(),
            mine.len(),
            mine.iter().map(|c| c.fragments).sum::<u64>(),
            mine.iter().map(|c| c.failures).sum::<u64>(),
            mine.iter().map(|c| c.max_error_lsb).fold(0.0, f64::max),
            names(|c| c.passes() == Some(false)),
            names(|c| c.passes().is_none()),
        );
    }
    for &(family, formats) in &groups {
        md += &format!(
            "\n## {} at {formats} formats\n\n{}. Axis: {}.\n\n| cell | fragments | out of tolerance | max error (LSB) | PSNR (dB) | worst failure or refusal |\n|---|---:|---:|---:|---:|---|\n",
            family.name(),
            family.what(),
            family.axis().0
        );
        for c in cells.iter().filter(|c| c.family == family && c.formats == formats) {
            md += &format!(
                "| {} | {} | {} | {:.2} | {} | {} |\n",
                c.label,
                c.fragments,
                c.failures,
                c.max_error_lsb,
                c.psnr_db.map_or("exact".into(), |p| format!("{p:.1}")),
                c.refused.as_deref().or(c.worst.as_deref()).unwrap_or("")
            );
        }
    }
    md
}
