//! The filter stage of 001's texture unit (`rtl::texture_filter`): rust-hdl and Verilator in
//! lockstep, every output compared every cycle, with random stalls (`en`); every pixel's
//! colour checked, at its cycle, against the model: `model::texture_filter::texel`
//! at `fx::TexFormats::DEFAULT`, then `model::texture_filter::environment` with Cf alpha
//! 255. Directed cases check the latency and values worked by hand.
//!
//! The model's texture state (`texture::TexelFormat`, `Weights`, `EnvMode`) is read from
//! the names of `rtl::texture_filter::FORMATS` and `ENVS` as a scene file gives them
//! (`scene::TextureSpec`), so the codes on the pins are the unit's, never re-declared here.

use fx::TexFormats;
use model::texture_filter::environment;
use model::texture_filter::{gaussian_table, texel, FilterIn};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_filter::{TextureFilter, ENVS, FORMATS, LATENCY, LF, SUB};
use scene::TextureSpec;
use std::collections::VecDeque;
use testbenches::{count, seed, verilated, Dual, Outputs, Value};

/// The pins of the two footprints' words.
const WORDS: [[&str; 4]; 2] = [
    ["inp_words0_0", "inp_words0_1", "inp_words0_2", "inp_words0_3"],
    ["inp_words1_0", "inp_words1_1", "inp_words1_2", "inp_words1_3"],
];

/// The largest fraction alpha, beta.
const MAX_SUB: u32 = (1 << SUB) - 1;

/// One pixel as the pins take it: the filter's inputs, the state codes (`FORMATS`, `ENVS`;
/// 5 to 7 are documented: Rgba8888, Replace) and the fragment colour R, G, B.
#[derive(Clone, Copy, Debug, Default)]
struct Pixel {
    x: FilterIn,
    format: u8,
    gaussian: bool,
    env: u8,
    cf: [u8; 3],
}

/// The model, with the texture state of every code.
struct Model {
    /// By `(format * 2 + gaussian) * 8 + env`.
    specs: Vec<TextureSpec>,
    gaussian: Vec<u32>,
}

impl Model {
    fn new() -> Self {
        let mut specs = Vec::new();
        for format in 0..8 {
            for gaussian in [false, true] {
                for env in 0..8 {
                    // Codes 5 to 7: Rgba8888 and Replace (`rtl::texture_filter`'s doc).
                    let format = FORMATS.get(format).copied().unwrap_or("rgba8888");
                    let env = ENVS.get(env).copied().unwrap_or("replace");
                    let weights = if gaussian { "gaussian" } else { "linear" };
                    let json =
                        format!(r#"{{"format": "{format}", "env": "{env}", "sampler": {{"weights": "{weights}"}}}}"#);
                    specs.push(scene::error::parse_json(&json).unwrap_or_else(|e| panic!("{json}: {e}")));
                }
            }
        }
        Model { specs, gaussian: gaussian_table(&TexFormats::DEFAULT) }
    }

    /// The pixel's colour, R 31..24 .. A 7..0.
    fn colour(&self, p: &Pixel) -> u32 {
        let s = &self.specs[(usize::from(p.format) * 2 + usize::from(p.gaussian)) * 8 + usize::from(p.env)];
        let cs = texel(&TexFormats::DEFAULT, s.format, s.sampler.weights, &self.gaussian, &p.x);
        u32::from_be_bytes(environment(s.env, [p.cf[0], p.cf[1], p.cf[2], 255], cs))
    }
}

/// The unit in both simulators, and the pixels in flight: `shadow[0]` is what the outputs
/// must show now (the pixel `LATENCY` enabled clocks back, or none).
struct Bench {
    dual: Dual<TextureFilter>,
    model: Model,
    shadow: VecDeque<Option<(Pixel, u32)>>,
}

impl Bench {
    fn new() -> Self {
        let vl = verilated("texture_filter");
        Bench {
            dual: Dual::new(TextureFilter::default(), vl.model().unwrap_or_else(|e| panic!("{e}"))),
            model: Model::new(),
            shadow: VecDeque::from(vec![None; LATENCY]),
        }
    }

    /// One cycle with `p` on the inputs: both simulators' outputs compared with each other
    /// and with the pixel due now.
    fn cycle(&mut self, p: &Pixel, valid: bool, en: bool) -> Result<Outputs, String> {
        let mut pins = vec![
            ("en", Value::new(1, en.into())),
            ("inp_valid", Value::new(1, valid.into())),
            ("inp_alpha0", Value::new(SUB, p.x.alpha[0].into())),
            ("inp_beta0", Value::new(SUB, p.x.beta[0].into())),
            ("inp_alpha1", Value::new(SUB, p.x.alpha[1].into())),
            ("inp_beta1", Value::new(SUB, p.x.beta[1].into())),
            ("inp_frac", Value::new(LF, p.x.frac.into())),
            ("inp_two_levels", Value::new(1, p.x.two_levels.into())),
            ("inp_format", Value::new(3, p.format.into())),
            ("inp_gaussian", Value::new(1, p.gaussian.into())),
            ("inp_env", Value::new(3, p.env.into())),
            ("inp_cf", Value::new(24, u32::from_be_bytes([0, p.cf[0], p.cf[1], p.cf[2]]).into())),
        ];
        for (l, names) in WORDS.iter().enumerate() {
            pins.extend(names.iter().zip(p.x.words[l]).map(|(n, w)| (*n, Value::new(32, w.into()))));
        }
        let out = self.dual.cycle(&pins).map_err(|m| format!("{m}\nthe pixel due: {:?}", self.shadow[0]))?;
        let due = self.shadow[0];
        let check = |pin: &str, want: Value| {
            self.dual.expect(&out, pin, &want).map_err(|m| format!("{m}\nthe pixel due: {due:?}"))
        };
        check("out_valid", Value::new(1, due.is_some().into()))?;
        if let Some((_, c)) = due {
            check("out_rgba", Value::new(32, c.into()))?;
        }
        if en {
            self.shadow.pop_front();
            self.shadow.push_back(valid.then(|| (*p, self.model.colour(p))));
        }
        Ok(out)
    }

    /// `p` alone through the unit, `en` high: its colour, out exactly `LATENCY` cycles after
    /// it went in.
    fn one(&mut self, p: &Pixel) -> u32 {
        let idle = Pixel::default();
        let mut got = None;
        for t in 0..=LATENCY + 1 {
            let out = self.cycle(if t == 0 { p } else { &idle }, t == 0, true).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(out.get("out_valid").bit(0), t == LATENCY, "cycle {t} of {p:?}");
            if t == LATENCY {
                got = Some(out.get("out_rgba").to_u128() as u32);
            }
        }
        got.expect("out at LATENCY")
    }
}

/// A pixel skewed toward the edges: fractions 0, 1/2 and the largest, equal words (a
/// nearest sample), words 0 and all ones, level weights 0 and the largest, codes 5 to 7
/// now and then, colours 0 and 255.
fn random_pixel(rng: &mut ChaCha8Rng) -> Pixel {
    let fraction = |rng: &mut ChaCha8Rng| match rng.gen_range(0..6) {
        0 => 0,
        1 => MAX_SUB,
        2 => 1 << (SUB - 1),
        _ => rng.gen_range(0..=MAX_SUB),
    };
    let code = |rng: &mut ChaCha8Rng| if rng.gen_ratio(1, 16) { rng.gen_range(5..8) } else { rng.gen_range(0..5) };
    let mut x = FilterIn::default();
    for l in 0..2 {
        let word = |rng: &mut ChaCha8Rng| match rng.gen_range(0..8) {
            0 => 0,
            1 => u32::MAX,
            _ => rng.gen(),
        };
        x.words[l] = match rng.gen_range(0..4) {
            0 => [word(rng); 4],
            _ => [word(rng), word(rng), word(rng), word(rng)],
        };
        x.alpha[l] = fraction(rng);
        x.beta[l] = fraction(rng);
    }
    x.frac = match rng.gen_range(0..4) {
        0 => 0,
        1 => (1 << LF) - 1,
        _ => rng.gen_range(0..1 << LF),
    };
    x.two_levels = rng.gen();
    let channel = |rng: &mut ChaCha8Rng| match rng.gen_range(0..6) {
        0 => 0,
        1 => 255,
        _ => rng.gen(),
    };
    Pixel { x, format: code(rng), gaussian: rng.gen(), env: code(rng), cf: [channel(rng), channel(rng), channel(rng)] }
}

/// Random pixels (20 x `EDGEPAINT_N`, at least 20,000), every format, weights and mode, one
/// or two levels, with `en` low a quarter of the cycles and no pixel an eighth.
#[test]
fn texture_filter_random_hdl_vs_verilator_lockstep_vs_model() {
    let (seed, n) = (seed(), (20 * count()).max(20_000));
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut bench = Bench::new();
    let (mut sent, mut out) = (0, 0);
    while sent < n || bench.shadow.iter().any(Option::is_some) {
        let p = random_pixel(&mut rng);
        let valid = sent < n && rng.gen_ratio(7, 8);
        let en = rng.gen_ratio(3, 4);
        let o = bench.cycle(&p, valid, en).unwrap_or_else(|e| panic!("{e}\nseed {seed}"));
        if en {
            sent += usize::from(valid);
            out += usize::from(o.get("out_valid").bit(0));
        }
    }
    assert_eq!(out, n, "every pixel out once");
}

/// A pixel in at cycle 3 comes out at 3 + LATENCY; each cycle of `en` low on the way delays
/// it by one, and the outputs hold through a stall.
#[test]
fn texture_filter_latency_in_enabled_clocks() {
    let mut bench = Bench::new();
    let p =
        Pixel { x: FilterIn { words: [[0x8040_20ff; 4]; 2], ..Default::default() }, format: 4, ..Default::default() };
    let idle = Pixel::default();
    let mut seen = vec![];
    for t in 0..12 {
        let out = bench.cycle(if t == 3 { &p } else { &idle }, t == 3, true).unwrap_or_else(|e| panic!("{e}"));
        if out.get("out_valid").bit(0) {
            seen.push((t, out.get("out_rgba").to_u128()));
        }
    }
    assert_eq!(seen, [(3 + LATENCY, 0x8040_20ff)], "REPLACE of the texel, LATENCY cycles later");

    let stalls = [5, 6, 10];
    let mut seen = vec![];
    for t in 0..16 {
        let en = !stalls.contains(&t);
        let out = bench.cycle(if t == 3 { &p } else { &idle }, t == 3, en).unwrap_or_else(|e| panic!("{e}"));
        if out.get("out_valid").bit(0) {
            seen.push(t);
        }
    }
    // In at 3; stalls at 5 and 6 delay it to 3 + LATENCY + 2 = 10, where it holds through
    // the stall and leaves with the enabled clock of cycle 11.
    assert_eq!(seen, [3 + LATENCY + 2, 3 + LATENCY + 3]);
}

/// A nearest sample (four equal words, zero fractions, one level) through REPLACE is the
/// texel decoded by bit replication, worked here by hand; bits above the format's are
/// ignored.
#[test]
fn texture_filter_nearest_sample_is_the_decoded_texel() {
    let cases: [(&str, u32, [u8; 4]); 11] = [
        // R 10000 -> 1000_0100, G 100000 -> 1000_0010, B 10000; no alpha.
        ("rgb565", 0x8410, [132, 130, 132, 255]),
        ("rgb565", 0xffff_f81f, [255, 0, 255, 255]),
        ("rgb565", 0x07e0, [0, 255, 0, 255]),
        // R, G, B 10000, A 1 -> 255, A 0 -> 0.
        ("rgba5551", 0x8421, [132, 132, 132, 255]),
        ("rgba5551", 0x8420, [132, 132, 132, 0]),
        ("rgba5551", 0x003e, [0, 0, 255, 0]),
        // c -> cc.
        ("rgba4444", 0x1234, [0x11, 0x22, 0x33, 0x44]),
        ("rgba4444", 0xabcd_000f, [0, 0, 0, 255]),
        ("rgb888", 0xab12_3456, [0x12, 0x34, 0x56, 255]),
        ("rgba8888", 0x1234_5678, [0x12, 0x34, 0x56, 0x78]),
        ("rgba8888", 0xff00_ff00, [255, 0, 255, 0]),
    ];
    let mut bench = Bench::new();
    for (name, word, want) in cases {
        let format = FORMATS.iter().position(|f| *f == name).expect("a format") as u8;
        for gaussian in [false, true] {
            let x = FilterIn { words: [[word; 4], [0x5a5a_a5a5; 4]], ..Default::default() };
            let p = Pixel { x, format, gaussian, env: 0, cf: [1, 2, 3] };
            assert_eq!(bench.one(&p), u32::from_be_bytes(want), "{name} {word:#010x} gaussian {gaussian}");
        }
    }
}

/// Values worked by hand (Rgba8888, REPLACE unless named):
/// - texels 0 and 255 along s at alpha = 1/2: 127.5, half up 128 (Gaussian too: its weight
///   at 1/2 is 1/2);
/// - texels [0, 1, 0, 0] at alpha = beta = 1/2: 0.25 -> 0, rounded once (rounding each row
///   first would give 0.5 -> 1);
/// - texels [1, 1, 1, 0] there: 0.75 -> 1;
/// - levels 0 and 255 at f = 32/64: 127.5 -> 128; at f = 1/64: 3.98 -> 4;
/// - MODULATE of 128 by 128: 64.25 -> 64; DECAL of Cf 255 with (0, As = 128): 127.0 -> 127
///   and alpha 255; ADD of 200 and 100: 255.
#[test]
fn texture_filter_worked_values() {
    let mut bench = Bench::new();
    let half = 1 << (SUB - 1);
    let rgba8888 = FORMATS.iter().position(|f| *f == "rgba8888").expect("rgba8888") as u8;
    let env = |name: &str| ENVS.iter().position(|e| *e == name).expect("a mode") as u8;
    let pixel = |words: [u32; 4], alpha: u32, beta: u32| Pixel {
        x: FilterIn { words: [words, [0; 4]], alpha: [alpha, 0], beta: [beta, 0], ..Default::default() },
        format: rgba8888,
        ..Default::default()
    };
    for gaussian in [false, true] {
        let p = Pixel { gaussian, ..pixel([0, u32::MAX, 0, u32::MAX], half, 77) };
        assert_eq!(bench.one(&p), 0x8080_8080, "0 and 255 at 1/2, gaussian {gaussian}");
    }
    assert_eq!(bench.one(&pixel([0, 0x0101_0101, 0, 0], half, half)), 0, "0.25: rounded once");
    assert_eq!(bench.one(&pixel([0x0101_0101, 0x0101_0101, 0x0101_0101, 0], half, half)), 0x0101_0101, "0.75");

    let levels = |frac: u32| Pixel {
        x: FilterIn { words: [[0; 4], [u32::MAX; 4]], frac, two_levels: true, ..Default::default() },
        format: rgba8888,
        ..Default::default()
    };
    assert_eq!(bench.one(&levels(1 << (LF - 1))), 0x8080_8080, "levels 0 and 255 at 1/2");
    assert_eq!(bench.one(&levels(1)), 0x0404_0404, "levels 0 and 255 at 1/64");
    assert_eq!(bench.one(&Pixel { x: FilterIn { two_levels: false, ..levels(1).x }, ..levels(1) }), 0, "one level");

    let modulate = Pixel { env: env("modulate"), cf: [128, 128, 0], ..pixel([0x80ff_80ff; 4], 0, 0) };
    assert_eq!(bench.one(&modulate), u32::from_be_bytes([64, 128, 0, 255]), "MODULATE");
    let decal = Pixel { env: env("decal"), cf: [255, 255, 255], ..pixel([0x0000_0080; 4], 0, 0) };
    assert_eq!(bench.one(&decal), u32::from_be_bytes([127, 127, 127, 255]), "DECAL");
    let add = Pixel { env: env("add"), cf: [200, 100, 0], ..pixel([0x6464_64ff; 4], 0, 0) };
    assert_eq!(bench.one(&add), u32::from_be_bytes([255, 200, 100, 255]), "ADD");
}
