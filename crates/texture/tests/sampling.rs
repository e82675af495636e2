//! Sampling: wrap modes, level of detail and level choice, nearest and bilinear filtering.

use proptest::prelude::*;
use texture::{
    footprint, lambda, level_choice, rho_exact, rho_max, sample, sample_level, Filter, LevelChoice, LodRule, MipChain,
    MipMode, Rgba, Sampler, Tap, Texture, Weights, Wrap,
};

/// A texture whose texels are red `reds[j * width + i] / 255` with green and blue 0, alpha 1.
fn reds(width: u32, height: u32, reds: &[u8]) -> Texture {
    let bytes: Vec<u8> = reds.iter().flat_map(|&r| [r, 0, 0, 255]).collect();
    Texture::from_rgba8(width, height, &bytes).unwrap()
}

fn assert_red(colour: Rgba, red: f64) {
    assert!((colour[0] - red / 255.0).abs() < 1e-12, "{colour:?}, want red {red}/255");
}

#[test]
fn wrap_modes_on_a_side_of_4() {
    let indices = -5..=8;
    let table = [
        (Wrap::Repeat, [3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0]),
        (Wrap::MirroredRepeat, [3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0]),
        (Wrap::ClampToEdge, [0, 0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3, 3]),
    ];
    for (wrap, want) in table {
        let got: Vec<u32> = indices.clone().map(|i| wrap.index(i, 4)).collect();
        assert_eq!(got, want, "{wrap:?}");
    }
    for wrap in [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge] {
        assert!(wrap.index(i64::MAX, 4) < 4 && wrap.index(i64::MIN, 4) < 4 && wrap.index(7, 0) == 0);
    }
}

/// 2x2: a = 0 at (0, 0), b = 100 at (1, 0), c = 200 at (0, 1), d = 40 at (1, 1).
fn two_by_two() -> Texture {
    reds(2, 2, &[0, 100, 200, 40])
}

fn at(filter: Filter, wrap: Wrap, s: f64, t: f64) -> Rgba {
    let sampler = Sampler { wrap_s: wrap, wrap_t: wrap, weights: Weights::Linear, ..Sampler::default() };
    sample_level(&two_by_two(), filter, &sampler, s, t)
}

#[test]
fn texel_centres_give_the_texel() {
    for filter in [Filter::Nearest, Filter::Linear] {
        assert_red(at(filter, Wrap::Repeat, 0.25, 0.25), 0.0);
        assert_red(at(filter, Wrap::Repeat, 0.75, 0.25), 100.0);
        assert_red(at(filter, Wrap::Repeat, 0.25, 0.75), 200.0);
        assert_red(at(filter, Wrap::Repeat, 0.75, 0.75), 40.0);
    }
}

#[test]
fn bilinear_midway_between_columns_is_the_mean() {
    assert_red(at(Filter::Linear, Wrap::Repeat, 0.5, 0.25), 50.0);
    assert_red(at(Filter::Linear, Wrap::Repeat, 0.5, 0.75), 120.0);
    // The centre of all four: (0 + 100 + 200 + 40) / 4.
    assert_red(at(Filter::Linear, Wrap::Repeat, 0.5, 0.5), 85.0);
    // Nearest takes floor(u) = 1 there.
    assert_red(at(Filter::Nearest, Wrap::Repeat, 0.5, 0.25), 100.0);
    // A quarter of the way: alpha = 0.25.
    assert_red(at(Filter::Linear, Wrap::Repeat, 0.375, 0.25), 25.0);
}

#[test]
fn border_repeat_mixes_the_last_column_clamp_does_not() {
    // s = 0: u - 1/2 = -1/2, i0 = wrap(-1), i1 = 0, alpha = 1/2.
    assert_red(at(Filter::Linear, Wrap::Repeat, 0.0, 0.25), 50.0);
    assert_red(at(Filter::Linear, Wrap::ClampToEdge, 0.0, 0.25), 0.0);
    assert_red(at(Filter::Linear, Wrap::MirroredRepeat, 0.0, 0.25), 0.0);
    // Nearest wraps whole texels: s = -0.25 is u = -0.5, floor -1.
    assert_red(at(Filter::Nearest, Wrap::Repeat, -0.25, 0.25), 100.0);
    assert_red(at(Filter::Nearest, Wrap::ClampToEdge, -0.25, 0.25), 0.0);
    assert_red(at(Filter::Nearest, Wrap::MirroredRepeat, -0.25, 0.25), 0.0);
    // Repeat: s = 1.25 is s = 0.25; mirrored: s = 1.25 is u = 2.5, texel 2 mirrors to 1.
    assert_red(at(Filter::Nearest, Wrap::Repeat, 1.25, 0.25), 0.0);
    assert_red(at(Filter::Nearest, Wrap::MirroredRepeat, 1.25, 0.25), 100.0);
}

#[test]
fn gaussian_weights_follow_3a2_minus_2a3() {
    assert_eq!(Weights::Gaussian.weight(0.0), 0.0);
    assert_eq!(Weights::Gaussian.weight(0.5), 0.5);
    assert_eq!(Weights::Gaussian.weight(1.0), 1.0);
    // alpha = 0.25: 3/16 - 2/64 = 0.15625 of b = 100.
    let t = two_by_two();
    let gaussian =
        Sampler { wrap_s: Wrap::Repeat, wrap_t: Wrap::Repeat, weights: Weights::Gaussian, ..Sampler::default() };
    let colour = sample_level(&t, Filter::Linear, &gaussian, 0.375, 0.25);
    assert_red(colour, 15.625);
}

#[test]
fn rho_exact_and_max() {
    assert_eq!(rho_exact(3.0, 4.0, 0.0, 0.0), 5.0);
    assert_eq!(rho_max(3.0, 4.0, 0.0, 0.0), 4.0);
    assert_eq!(rho_exact(0.0, 0.0, -6.0, 8.0), 10.0);
    assert_eq!(LodRule::Exact.rho(3.0, 4.0, 0.0, 0.0), 5.0);
    assert_eq!(LodRule::Max.rho(3.0, -4.0, 0.0, 1.0), 4.0);
    assert_eq!(lambda(8.0), 3.0);
    assert_eq!(lambda(0.0), f64::NEG_INFINITY);
}

proptest! {
    #[test]
    fn rho_max_and_exact_lie_within_gl_bounds(ux in -1e3..1e3f64, vx in -1e3..1e3f64, uy in -1e3..1e3f64, vy in -1e3..1e3f64) {
        let (exact, max) = (rho_exact(ux, vx, uy, vy), rho_max(ux, vx, uy, vy));
        let tolerance = 1e-9 * (1.0 + exact);
        prop_assert!(max <= exact + tolerance);
        prop_assert!(exact <= 2f64.sqrt() * (ux.abs() + vx.abs()).max(uy.abs() + vy.abs()) + tolerance);
        // OpenGL 4.6 section 8.14.1: max(mu, mv) <= f <= mu + mv.
        let (mu, mv) = (ux.abs().max(uy.abs()), vx.abs().max(vy.abs()));
        prop_assert!(mu.max(mv) <= max && max <= mu + mv);
        prop_assert!(exact <= mu + mv + tolerance);
    }
}

#[test]
fn magnified_at_lambda_0_and_below() {
    for mip in [MipMode::None, MipMode::Nearest, MipMode::Linear] {
        for lambda in [0.0, -1.0, f64::NEG_INFINITY, f64::NAN] {
            assert_eq!(level_choice(lambda, mip, 4), LevelChoice::Magnify, "{mip:?} {lambda}");
        }
        assert_ne!(level_choice(1e-9, mip, 4), LevelChoice::Magnify);
    }
}

#[test]
fn nearest_level_rounds_lambda_and_clamps_to_the_last() {
    let level = |lambda| level_choice(lambda, MipMode::Nearest, 4);
    assert_eq!(level(0.49), LevelChoice::Level(0));
    assert_eq!(level(0.5), LevelChoice::Level(0));
    assert_eq!(level(0.51), LevelChoice::Level(1));
    assert_eq!(level(1.49), LevelChoice::Level(1));
    assert_eq!(level(1.51), LevelChoice::Level(2));
    assert_eq!(level(3.6), LevelChoice::Level(3));
    assert_eq!(level(40.0), LevelChoice::Level(3));
    assert_eq!(level(f64::INFINITY), LevelChoice::Level(3));
    assert_eq!(level_choice(7.0, MipMode::None, 4), LevelChoice::Level(0));
}

#[test]
fn linear_levels_blend_by_the_fraction_of_lambda() {
    let choice = |lambda| level_choice(lambda, MipMode::Linear, 4);
    assert_eq!(choice(1.25), LevelChoice::Blend { d1: 1, frac: 0.25 });
    assert_eq!(choice(0.5), LevelChoice::Blend { d1: 0, frac: 0.5 });
    assert_eq!(choice(2.75), LevelChoice::Blend { d1: 2, frac: 0.75 });
    assert_eq!(choice(3.0), LevelChoice::Level(3));
    assert_eq!(choice(f64::INFINITY), LevelChoice::Level(3));
    assert_eq!(level_choice(0.5, MipMode::Linear, 1), LevelChoice::Level(0));
}

/// The 4x4 chain of red 10 (4 j + i): level 1 is 25, 45 / 105, 125 and level 2 is 75.
fn chain_4x4() -> MipChain {
    MipChain::new(reds(4, 4, &(0..16).map(|k| 10 * k).collect::<Vec<u8>>())).unwrap()
}

#[test]
fn footprint_blends_two_levels() {
    let chain = chain_4x4();
    let sampler = Sampler { min: Filter::Nearest, mip: MipMode::Linear, ..Sampler::default() };
    let fp = footprint(&chain, &sampler, 0.1, 0.1, 1.25);
    assert_eq!(fp.choice, LevelChoice::Blend { d1: 1, frac: 0.25 });
    assert_eq!(fp.taps, [Tap { level: 1, i: 0, j: 0, weight: 0.75 }, Tap { level: 2, i: 0, j: 0, weight: 0.25 }]);
    // 0.75 * 25 + 0.25 * 75.
    assert_red(sample(&chain, &sampler, 0.1, 0.1, 1.25), 37.5);
}

#[test]
fn magnification_uses_the_mag_filter_minification_the_min_filter() {
    let chain = MipChain::new(two_by_two()).unwrap();
    let sampler = Sampler { min: Filter::Nearest, mag: Filter::Linear, ..Sampler::default() };
    // lambda 0 (magnified): bilinear midway between a and b.
    assert_red(sample(&chain, &sampler, 0.5, 0.25, 0.0), 50.0);
    // lambda 0.3 (minified, nearest level 0): nearest, column floor(1) = 1.
    assert_red(sample(&chain, &sampler, 0.5, 0.25, 0.3), 100.0);
    // lambda 0.7: level 1, the 1x1 mean (0 + 100 + 200 + 40) / 4.
    assert_red(sample(&chain, &sampler, 0.5, 0.25, 0.7), 85.0);
    let linear_taps = footprint(&chain, &Sampler::default(), 0.5, 0.25, -2.0).taps;
    assert_eq!(linear_taps.len(), 4);
    assert_eq!(linear_taps.iter().map(|t| t.weight).sum::<f64>(), 1.0);
}

#[test]
fn default_sampler_is_bilinear_nearest_level_repeat() {
    let d = Sampler::default();
    assert_eq!((d.min, d.mag, d.mip), (Filter::Linear, Filter::Linear, MipMode::Nearest));
    assert_eq!((d.wrap_s, d.wrap_t, d.weights), (Wrap::Repeat, Wrap::Repeat, Weights::Linear));
    assert_eq!(LodRule::default(), LodRule::Exact);
}

#[test]
fn sampler_reads_snake_case_json() {
    let s: Sampler = serde_json::from_str(r#"{"min": "nearest", "mip": "linear", "wrap_s": "mirrored_repeat", "wrap_t": "clamp_to_edge", "weights": "gaussian"}"#).unwrap();
    assert_eq!(
        s,
        Sampler {
            min: Filter::Nearest,
            mip: MipMode::Linear,
            wrap_s: Wrap::MirroredRepeat,
            wrap_t: Wrap::ClampToEdge,
            weights: Weights::Gaussian,
            ..Sampler::default()
        }
    );
    assert_eq!(serde_json::from_str::<Sampler>("{}").unwrap(), Sampler::default());
    assert!(serde_json::from_str::<Sampler>(r#"{"wrap": "repeat"}"#).is_err());
    assert_eq!(serde_json::to_string(&MipMode::None).unwrap(), r#""none""#);
    assert_eq!(serde_json::to_string(&LodRule::Max).unwrap(), r#""max""#);
}

fn sampler() -> impl Strategy<Value = Sampler> {
    let filter = || prop::sample::select(vec![Filter::Nearest, Filter::Linear]);
    let wrap = || prop::sample::select(vec![Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge]);
    (
        filter(),
        filter(),
        prop::sample::select(vec![MipMode::None, MipMode::Nearest, MipMode::Linear]),
        wrap(),
        wrap(),
        prop::sample::select(vec![Weights::Linear, Weights::Gaussian]),
    )
        .prop_map(|(min, mag, mip, wrap_s, wrap_t, weights)| Sampler { min, mag, mip, wrap_s, wrap_t, weights })
}

/// A texture of 1 to 8 texels a side (powers of two) with random bytes.
fn texture() -> impl Strategy<Value = Texture> {
    (0..4u32, 0..4u32).prop_flat_map(|(lw, lh)| {
        let (w, h) = (1 << lw, 1 << lh);
        prop::collection::vec(any::<u8>(), 4 * w as usize * h as usize)
            .prop_map(move |bytes| Texture::from_rgba8(w, h, &bytes).unwrap())
    })
}

/// Whether every channel of `colour` lies within that channel's range over `texture`.
fn within(colour: Rgba, texture: &Texture) -> bool {
    (0..4).all(|k| {
        let channel = texture.texels().iter().map(|t| t[k]);
        let (lo, hi) = channel.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| (lo.min(c), hi.max(c)));
        lo - 1e-12 <= colour[k] && colour[k] <= hi + 1e-12
    })
}

fn check_sample(base: Texture, sampler: Sampler, s: f64, t: f64, lambda: f64) -> Result<(), TestCaseError> {
    let chain = MipChain::new(base).unwrap();
    let fp = footprint(&chain, &sampler, s, t, lambda);
    prop_assert!(fp.taps.iter().all(|tap| tap.weight >= 0.0));
    prop_assert!((fp.taps.iter().map(|tap| tap.weight).sum::<f64>() - 1.0).abs() < 1e-12);
    // Every level's texels are means of the base's, so the base's range bounds every level.
    prop_assert!(within(sample(&chain, &sampler, s, t, lambda), chain.base()));
    for level in chain.levels() {
        let colour = sample_level(level, sampler.min, &sampler, s, t);
        prop_assert!(within(colour, level), "{colour:?} outside level {}x{}", level.width(), level.height());
    }
    Ok(())
}

proptest! {
    #[test]
    fn samples_stay_within_the_texels(base in texture(), sampler in sampler(), s in -4.0..4.0f64, t in -4.0..4.0f64, lambda in -2.0..6.0f64) {
        check_sample(base, sampler, s, t, lambda)?;
    }

    #[test]
    fn any_f64_is_sampled_without_panic(base in texture(), sampler in sampler(), s in any::<f64>(), t in any::<f64>(), lambda in any::<f64>()) {
        check_sample(base, sampler, s, t, lambda)?;
    }
}

#[test]
fn non_finite_coordinates_count_as_0() {
    let chain = MipChain::new(two_by_two()).unwrap();
    let sampler = Sampler::default();
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e308] {
        assert_eq!(sample(&chain, &sampler, bad, 0.25, -1.0), sample(&chain, &sampler, 0.0, 0.25, -1.0), "{bad}");
    }
}
