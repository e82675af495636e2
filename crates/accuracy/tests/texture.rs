//! The texture unit (`model::texture_unit`, paper 001 section II-5) judged as the GL and
//! Vulkan conformance tests judge texture filtering (`accuracy::texture`,
//! `texture::conformance`): on every shipped textured scene at both level-of-detail rules,
//! on random textures, states and triangles, on the grazing checkerboard with and without
//! perspective correction, and at formats below Vulkan's minimums (which must fail).

use accuracy::texture::{judge, TextureReport, TextureSetup};
use fx::TexFormats;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use scene::{Scene, Triangle, Trilist};
use std::path::Path;
use texture::{EnvMode, Filter, LodRule, MipChain, MipMode, Sampler, TexelFormat, Texture, Weights, Wrap};

fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

fn setup(formats: TexFormats, lod: LodRule, affine: bool) -> TextureSetup {
    TextureSetup { formats, lod, affine }
}

/// (pixels, failures, PSNR) of a report, as the tests read it.
struct Judged(u64, u64, f64);

impl From<TextureReport> for Judged {
    fn from(r: TextureReport) -> Judged {
        if let Some(w) = r.worst_failure {
            eprintln!("worst failure: {w:?}");
        }
        Judged(r.pixels, r.failures, r.psnr_db)
    }
}

fn shipped(name: &str) -> Trilist {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/textured");
    Scene::load(&dir.join(name)).unwrap().to_trilist().unwrap()
}

#[test]
fn every_shipped_textured_scene_passes_the_conformance_check_at_both_lod_rules() {
    let paths = scene::shipped::textured().unwrap();
    assert!(paths.len() >= 4, "{paths:?}");
    for path in paths {
        let list = Scene::load(&path).unwrap().to_trilist().unwrap();
        for rule in [LodRule::Max, LodRule::Exact] {
            let r = judge(&list, &setup(TexFormats::default(), rule, false)).unwrap();
            let (neighbour, Judged(pixels, failures, psnr)) = (r.neighbour, r.into());
            println!(
                "{} {rule:?}: {pixels} pixels, {failures} failures, {neighbour} at a boundary took a neighbouring \
                 choice, {psnr:.1} dB",
                path.display()
            );
            assert!(pixels > 5_000, "{}: {pixels} textured pixels", path.display());
            assert_eq!(failures, 0, "{} {rule:?}", path.display());
            // The design's rule (001's eq. 4) is at 40 dB. At GL's exact rule, one level per
            // colour (the mip-level scene) makes each pixel near a level boundary that chose
            // the other level count in full (46 of its 15,428 at stop 53): at most 1 in 100 may.
            let few = neighbour * 100 <= pixels;
            assert!(psnr >= 40.0 || (rule == LodRule::Exact && few), "{} {rule:?}: {psnr:.1} dB", path.display());
        }
    }
}

#[test]
fn the_grazing_checkerboard_shows_the_rubber_sheet_only_when_affine() {
    let list = shipped("checker.json");
    let Judged(pixels, failures, _) = judge(&list, &setup(TexFormats::default(), LodRule::Max, false)).unwrap().into();
    assert_eq!(failures, 0);
    let Judged(_, affine_failures, psnr) =
        judge(&list, &setup(TexFormats::default(), LodRule::Max, true)).unwrap().into();
    println!("checker: affine {affine_failures} of {pixels} pixels out of tolerance, {psnr:.1} dB");
    assert!(affine_failures * 5 > pixels, "affine: only {affine_failures} of {pixels} pixels out of tolerance");
}

/// A random 2^ws x 2^hs RGBA texture.
fn random_chain(rng: &mut ChaCha8Rng, ws: u32, hs: u32, format: TexelFormat) -> MipChain {
    let n = (1usize << ws) * (1usize << hs);
    let rgba: Vec<u8> = (0..4 * n).map(|_| rng.gen()).collect();
    MipChain::new(Texture::from_rgba8(1 << ws, 1 << hs, &rgba).unwrap()).unwrap().quantized(format)
}

#[test]
fn random_states_textures_and_triangles_pass_the_conformance_check() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let filters = [Filter::Nearest, Filter::Linear];
    let mips = [MipMode::None, MipMode::Nearest, MipMode::Linear];
    let wraps = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
    let envs = [EnvMode::Replace, EnvMode::Modulate, EnvMode::Decal, EnvMode::Blend, EnvMode::Add];
    let (mut pixels, mut failures) = (0, 0);
    for case in 0..120 {
        let format = TexelFormat::ALL[case % 5];
        let (ws, hs) = (rng.gen_range(0..=6), rng.gen_range(0..=6));
        let sampler = Sampler {
            min: filters[rng.gen_range(0..2)],
            mag: filters[rng.gen_range(0..2)],
            mip: mips[rng.gen_range(0..3)],
            wrap_s: wraps[rng.gen_range(0..3)],
            wrap_t: wraps[rng.gen_range(0..3)],
            weights: if rng.gen() { Weights::Linear } else { Weights::Gaussian },
        };
        let mips = std::sync::Arc::new(random_chain(&mut rng, ws, hs, format));
        let env = envs[rng.gen_range(0..5)];
        let tex = scene::TextureRef { images: vec!["random".into()], sampler, env, format, mips };
        // A screen-space triangle in perspective: w from 1 to 8, s and t over a few repeats.
        let v = |rng: &mut ChaCha8Rng| scene::Vertex {
            w: Some(rng.gen_range(1.0..8.0)),
            tex: Some(scene::Tex { s: rng.gen_range(-3.0..3.0), t: rng.gen_range(-3.0..3.0), texture: 0 }),
            ..scene::Vertex::new(
                rng.gen_range(-8.0..72.0),
                rng.gen_range(-8.0..72.0),
                0.5,
                [rng.gen_range(0.0..255.0), 200.0, 90.0],
            )
        };
        let tri: Triangle = [v(&mut rng), v(&mut rng), v(&mut rng)];
        let list = Trilist { width: 64, height: 64, triangles: vec![tri], textures: vec![tex] };
        let rule = if case % 2 == 0 { LodRule::Max } else { LodRule::Exact };
        let Judged(p, fails, _) = judge(&list, &setup(TexFormats::default(), rule, false)).unwrap().into();
        pixels += p;
        failures += fails;
        assert_eq!(fails, 0, "case {case}: {ws}x{hs} {format:?} {sampler:?} {env:?} {rule:?}");
    }
    println!("{pixels} pixels, {failures} failures");
    assert!(pixels > 20_000);
}

#[test]
fn formats_below_vulkans_minimums_fail_the_check_where_the_defaults_pass() {
    // The defaults: Vulkan 1.0's minimums (4 sub-texel and 4 level bits) and Roadmap 2022's
    // (8 and 6) met.
    let d = TexFormats::default();
    assert!(d.subtexel >= 8 && d.lod_frac >= 6);
    let list = shipped("crate.json");
    for (what, coarse) in [
        ("2 sub-texel bits", TexFormats { subtexel: 2, weight: 2, ..d }),
        ("2 level bits", TexFormats { lod_frac: 2, ..d }),
        ("8 reciprocal bits", TexFormats { recip: 8, ..d }),
    ] {
        let Judged(pixels, failures, psnr) = judge(&list, &setup(coarse, LodRule::Max, false)).unwrap().into();
        println!("crate at {what}: {failures} of {pixels} pixels out of tolerance, {psnr:.1} dB");
        assert!(failures > 0, "{what}: no failures");
    }
}

#[test]
fn the_cache_hit_rate_on_each_shipped_textured_scene_grows_with_the_cache() {
    use accuracy::texture::cache_stats;
    use model::texture_cache::Params;
    let geometries = [
        Params { sets: 16, ways: 1, line: 4 },
        Params { sets: 64, ways: 2, line: 4 },
        Params { sets: 256, ways: 4, line: 16 },
    ];
    for path in scene::shipped::textured().unwrap() {
        let list = Scene::load(&path).unwrap().to_trilist().unwrap();
        let r = judge(&list, &setup(TexFormats::default(), LodRule::Max, false)).unwrap();
        let rates: Vec<f64> = geometries.iter().map(|g| cache_stats(g, &r.trace).hit_rate).collect();
        println!("{}: {} accesses, hit rates {rates:.4?}", path.display(), r.trace.len());
        // Every access reads at least one word, and neighbouring pixels share texels: the
        // smallest cache already hits most lookups, and the largest at least as often.
        assert_eq!(r.cache.hit_rate, rates[1]);
        assert!(rates[0] > 0.5 && rates[2] >= rates[0], "{rates:?}");
    }
}
