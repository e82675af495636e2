//! The texture unit's top (paper 001 section II-5: coordinates, addresses, cache, filter in
//! one pipeline): rust-hdl and Verilator in lockstep with the cycle model
//! `model::texture_unit::pipeline`, every output compared every cycle (the colour and tag
//! when `out_valid`), behind a test-side memory holding random textures in
//! `model::texture_memory`'s layout (latency 1, 5 or 20 cycles, refusing words at random),
//! with random output backpressure and flushes; every colour out is also checked against
//! `model::texture_unit::TextureUnit::sample` and every tag against the pixel's, in order.
//! Random states (every format, filter, mip mode, wrap, environment, both weight curves;
//! both level-of-detail rules, one per build) and pixels of random perspective triangles
//! (`model::texture_unit::input::TexPlanes`), at the default cache and at a 4-set
//! direct-mapped cache of 1-word lines, where nearly every access misses.

use fx::TexFormats;
use model::texture_cache::{hit_rate_of_trace, Counters, MemAsk, MemIn, Params};
use model::texture_memory::ReadPort;
use model::texture_memory::{chain_words, layout};
use model::texture_unit::input::TexPlanes;
use model::texture_unit::pipeline::{Pipeline, Pixel, UnitIn, UnitOut};
use model::texture_unit::{Fetch, TexState, TextureUnit};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_cache::ADDR;
use rtl::texture_unit::{TextureUnit411, TextureUnit6424};
use rust_hdl::prelude::Block;
use sim::textured::{state_pins, ENVS, MIPS, WRAPS};
use testbenches::texture::coord_pins;
use testbenches::{count, seed, verilated_with, Dual, Pins, Value};
use texture::{Filter, LodRule, MipChain, MipMode, Sampler, TexelFormat, Texture, Weights};

const F: TexFormats = TexFormats::DEFAULT;
/// Words of the test's texture memory.
pub(crate) const MEMORY: usize = 1 << 15;

fn bit(b: bool) -> Value {
    Value::new(1, b.into())
}

/// The unit's input pins for `i` and the memory's `m`.
fn pins(i: &UnitIn, m: &MemIn) -> Vec<(&'static str, Value)> {
    let cf = i.pixel.cf;
    let mut pins = vec![("inp_valid", bit(i.inp_valid))];
    pins.extend(coord_pins(&i.pixel.p, &i.pixel.g));
    pins.extend([
        ("inp_cf", Value::new(24, (cf[0] as u128) << 16 | (cf[1] as u128) << 8 | cf[2] as u128)),
        ("inp_tag", Value::new(32, i.pixel.tag.into())),
        ("st_load", bit(i.st_load)),
        ("inp_flush", bit(i.flush)),
        ("out_ready", bit(i.out_ready)),
    ]);
    pins.extend(state_pins(&i.state));
    pins.extend(mem_pins(m));
    pins
}

/// The memory's answer on the `mem_*` pins.
pub(crate) fn mem_pins(m: &MemIn) -> [(&'static str, Value); 3] {
    [("mem$ack", bit(m.ack)), ("mem$rvalid", bit(m.rvalid)), ("mem$rdata", Value::new(32, m.rdata.into()))]
}

/// The model's outputs compared every cycle (`out_rgba` and `out_tag` with `out_valid`).
fn every_cycle(o: &UnitOut) -> Vec<(&'static str, Value)> {
    let mut want = vec![("inp_ready", bit(o.inp_ready)), ("out_valid", bit(o.out_valid)), ("idle", bit(o.idle))];
    want.extend(request_pins(o.mem, o.counters));
    want
}

/// The memory request (`mem$*`) and the cache's counters (`counters$*`) on the pins of
/// `texture_cache`, of `texture_unit` and of `texture_path`, which hold it.
pub(crate) fn request_pins(mem: MemAsk, c: Counters) -> [(&'static str, Value); 5] {
    [
        ("mem$valid", bit(mem.valid)),
        ("mem$addr", Value::new(ADDR, mem.addr.into())),
        ("counters$hits", Value::new(32, c.hits.into())),
        ("counters$misses", Value::new(32, c.misses.into())),
        ("counters$fills", Value::new(32, c.fills.into())),
    ]
}

/// One draw: a state, its pixels and each pixel's colour by `TextureUnit::sample`, and the
/// cache accesses `sample` says the pixels make.
struct Draw {
    state: TexState,
    pixels: Vec<Pixel>,
    colours: Vec<[u8; 4]>,
    fetches: Vec<Fetch>,
}

/// A random texture in a random format at a random place of `memory` (laid out by
/// `texture_memory::layout`), and a random state to draw it with.
pub(crate) fn random_state(rng: &mut ChaCha8Rng, memory: &mut [u32], lod: LodRule) -> TexState {
    let format = TexelFormat::ALL[rng.gen_range(0..5)];
    let (ws, hs) = (rng.gen_range(0..=6), rng.gen_range(1..=6));
    let n = (1usize << ws) * (1usize << hs);
    let rgba: Vec<u8> = (0..4 * n).map(|_| rng.gen()).collect();
    let chain = MipChain::new(Texture::from_rgba8(1 << ws, 1 << hs, &rgba).unwrap()).unwrap().quantized(format);
    let all = chain.levels().len() as u32;
    // The whole chain half the time: minified pixels then read two levels or the last.
    let levels = if rng.gen() { all } else { rng.gen_range(1..=all) };
    let words = layout(&chain, format);
    let used = chain_words(ws, hs, levels) as usize;
    let base = rng.gen_range(0..=MEMORY - used);
    memory[base..base + used].copy_from_slice(&words[..used]);
    let filter = |rng: &mut ChaCha8Rng| if rng.gen() { Filter::Linear } else { Filter::Nearest };
    let sampler = Sampler {
        min: filter(rng),
        mag: filter(rng),
        // Linear between levels half the time: the pixels that make two accesses.
        mip: if rng.gen() { MipMode::Linear } else { MIPS[rng.gen_range(0..2)] },
        wrap_s: WRAPS[rng.gen_range(0..3)],
        wrap_t: WRAPS[rng.gen_range(0..3)],
        weights: if rng.gen() { Weights::Linear } else { Weights::Gaussian },
    };
    let state = TexState {
        size_log2: [ws, hs],
        levels,
        base: base as u32,
        format,
        sampler,
        env: ENVS[rng.gen_range(0..5)],
        lod,
    };
    state.check().unwrap();
    state
}

/// The pixels of a random perspective triangle (w from 1 to 8, s and t over a few
/// repeats, on a 24 x 24 screen), in raster order, at most `max`.
fn random_triangle(rng: &mut ChaCha8Rng, max: usize) -> Vec<Pixel> {
    loop {
        let xy: [[f64; 2]; 3] = std::array::from_fn(|_| [rng.gen_range(-4.0..28.0), rng.gen_range(-4.0..28.0)]);
        let reach = [0.5, 3.0, 12.0][rng.gen_range(0..3)];
        let st: [[f64; 2]; 3] = std::array::from_fn(|_| [rng.gen_range(-reach..reach), rng.gen_range(-reach..reach)]);
        let inv_w: [f64; 3] = std::array::from_fn(|_| 1.0 / rng.gen_range(1.0..8.0));
        let Some(planes) = TexPlanes::new(xy, st, inv_w) else { continue };
        let g = planes.grad(&F);
        let edge =
            |a: [f64; 2], b: [f64; 2], p: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        let area = edge(xy[0], xy[1], xy[2]);
        let mut pixels = Vec::new();
        for y in 0..24 {
            for x in 0..24 {
                let p = [x as f64 + 0.5, y as f64 + 0.5];
                let inside = (0..3).all(|k| edge(xy[k], xy[(k + 1) % 3], p) * area >= 0.0);
                if inside && pixels.len() < max {
                    let cf = [rng.gen(), rng.gen(), rng.gen()];
                    pixels.push(Pixel { p: planes.at(&F, p[0], p[1]), g, cf, tag: rng.gen() });
                }
            }
        }
        if !pixels.is_empty() {
            return pixels;
        }
    }
}

/// Random draws over `memory` (each texture written into it as its draw is made), `pixels`
/// pixels in all, their colours by `sample` from the memory with every texture written.
fn random_draws(rng: &mut ChaCha8Rng, memory: &mut [u32], lod: LodRule, pixels: usize) -> Vec<Draw> {
    let unit = TextureUnit::new(F).unwrap();
    let mut draws = Vec::new();
    let mut n = 0;
    while n < pixels {
        let state = random_state(rng, memory, lod);
        let mut d = Draw { state, pixels: Vec::new(), colours: Vec::new(), fetches: Vec::new() };
        for _ in 0..rng.gen_range(1..=2) {
            d.pixels.extend(random_triangle(rng, 24));
        }
        n += d.pixels.len();
        draws.push(d);
    }
    // The colours once every texture is in memory (a texture may overwrite part of an
    // earlier one: the memory the unit reads is the final one).
    for d in &mut draws {
        for x in &d.pixels {
            let s = unit.sample(&d.state, memory, &x.p, &x.g, x.cf);
            d.colours.push(s.colour);
            d.fetches.extend(s.fetches);
        }
    }
    draws
}

/// The test's memory: takes the word asked when `ack` (decided before the cycle), answers
/// it `latency` cycles later, in order, a word a cycle at most.
pub(crate) struct Memory {
    pub(crate) mem: ReadPort,
    pub(crate) ack_chance: f64,
}

impl Memory {
    /// `words` answered `latency` cycles after they are asked, a request taken with
    /// probability `ack_chance`.
    pub(crate) fn new(words: Vec<u32>, latency: u64, ack_chance: f64) -> Memory {
        Memory { mem: ReadPort::new(words, latency), ack_chance }
    }

    /// Cycle `now`'s answer, and whether a word asked is taken.
    pub(crate) fn answer(&mut self, now: u64, rng: &mut ChaCha8Rng) -> MemIn {
        let ack = self.ack_chance >= 1.0 || rng.gen_bool(self.ack_chance);
        self.mem.answer(now, ack)
    }

    /// After cycle `now` with answer `m`: the word `asked` (when valid).
    pub(crate) fn ask(&mut self, now: u64, m: &MemIn, asked: MemAsk) {
        self.mem.ask(now, m, asked)
    }
}

/// The unit in both simulators beside the model and the memory.
struct Bench<U> {
    dual: Dual<U>,
    model: Pipeline,
    mem: Memory,
    rng: ChaCha8Rng,
    now: u64,
    /// The chance `out_ready` is high in a cycle, and a flush is asked.
    ready_chance: f64,
    flush_chance: f64,
}

impl<U: Block + Pins> Bench<U> {
    /// One clock: `i` and the memory's answer driven, every output compared between the
    /// simulators and with the model.
    fn cycle(&mut self, i: &UnitIn) -> UnitOut {
        let m = self.mem.answer(self.now, &mut self.rng);
        let got = self.dual.cycle(&pins(i, &m)).unwrap_or_else(|e| panic!("{e}"));
        let o = self.model.step(i, m);
        let mut want = every_cycle(&o);
        if o.out_valid {
            let [r, g, b, a] = o.out_rgba.map(u128::from);
            want.push(("out_rgba", Value::new(32, r << 24 | g << 16 | b << 8 | a)));
            want.push(("out_tag", Value::new(32, o.out_tag.into())));
        }
        for (pin, v) in want {
            self.dual.expect(&got, pin, &v).unwrap_or_else(|e| panic!("{e} (seed {})", seed()));
        }
        self.mem.ask(self.now, &m, o.mem);
        self.now += 1;
        o
    }

    /// Every draw: the state loaded while idle, the pixels offered with random gaps, the
    /// output taken with random backpressure; each colour against `sample`'s, each tag the
    /// pixel's, in order. Returns the cache accesses the draws made by `sample`.
    fn run(&mut self, draws: &[Draw]) -> Vec<Fetch> {
        let mut fetches = Vec::new();
        for d in draws {
            let mut o = self.cycle(&UnitIn::idle(d.state));
            while !o.idle {
                o = self.cycle(&UnitIn::idle(d.state));
            }
            self.cycle(&UnitIn { st_load: true, ..UnitIn::idle(d.state) });
            let (mut next, mut done) = (0, 0);
            let limit = self.now + 200 * (d.pixels.len() as u64 + 10);
            while done < d.pixels.len() {
                assert!(self.now < limit, "{done} of {} pixels out (seed {})", d.pixels.len(), seed());
                let valid = next < d.pixels.len() && self.rng.gen_range(0..6) != 0;
                let i = UnitIn {
                    inp_valid: valid,
                    pixel: if valid { d.pixels[next] } else { Pixel::default() },
                    flush: self.rng.gen_bool(self.flush_chance),
                    out_ready: self.rng.gen_bool(self.ready_chance),
                    ..UnitIn::idle(d.state)
                };
                let o = self.cycle(&i);
                if valid && o.inp_ready {
                    next += 1;
                }
                if o.out_valid && i.out_ready {
                    assert_eq!(o.out_rgba, d.colours[done], "pixel {done} of {:?} (seed {})", d.state, seed());
                    assert_eq!(o.out_tag, d.pixels[done].tag, "pixel {done}: its tag (seed {})", seed());
                    done += 1;
                }
            }
            fetches.extend(&d.fetches);
        }
        fetches
    }
}

/// Random draws through unit `U` (cache `p`, level-of-detail rule `lod`) at each memory
/// latency, in lockstep; without flushes the counters are the functional cache's on the
/// accesses `sample` makes.
fn lockstep<U: Block + Pins>(unit: impl Fn() -> U, p: Params, lod: LodRule, salt: u64) {
    let exact = u64::from(lod == LodRule::Exact);
    let vl = verilated_with(
        "texture_unit",
        [("SETS", p.sets.into()), ("WAYS", p.ways.into()), ("LINE", p.line.into()), ("EXACT", exact)],
    );
    for (k, latency) in [1u64, 5, 20].into_iter().enumerate() {
        let mut rng = ChaCha8Rng::seed_from_u64(seed() ^ salt ^ latency);
        let mut words: Vec<u32> = (0..MEMORY).map(|_| rng.gen()).collect();
        let draws = random_draws(&mut rng, &mut words, lod, count() / 2 + 1);
        let flush_chance = if k == 1 { 0.01 } else { 0.0 };
        let mut b = Bench {
            dual: Dual::new(unit(), vl.model().unwrap_or_else(|e| panic!("{e}"))),
            model: Pipeline::new(F, p, lod).unwrap(),
            mem: Memory::new(words, latency, if k == 2 { 0.7 } else { 1.0 }),
            rng,
            now: 0,
            ready_chance: [1.0, 0.7, 0.4][k],
            flush_chance,
        };
        let fetches = b.run(&draws);
        let two = draws.iter().flat_map(|d| d.fetches.len().checked_sub(d.pixels.len())).sum::<usize>();
        let o = b.cycle(&UnitIn::idle(draws[0].state));
        println!(
            "texture_unit {p:?} {lod:?} latency {latency}: {} pixels ({two} of two levels), {} cycles, {} hits, {} \
             misses",
            draws.iter().map(|d| d.pixels.len()).sum::<usize>(),
            b.now,
            o.counters.hits,
            o.counters.misses
        );
        assert!(two > 0, "no pixel between two levels");
        if flush_chance == 0.0 {
            let s = hit_rate_of_trace(&p, &fetches);
            assert_eq!(
                (o.counters.hits.into(), o.counters.misses.into(), o.counters.fills.into()),
                (s.hits, s.misses, s.fills)
            );
        }
    }
}

#[test]
fn texture_unit_random_draws_default_cache_in_lockstep() {
    lockstep(|| TextureUnit6424::new(false), Params { sets: 64, ways: 2, line: 4 }, LodRule::Max, 0x6424);
}

#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn texture_unit_random_draws_missing_cache_exact_rule_in_lockstep() {
    lockstep(|| TextureUnit411::new(true), Params { sets: 4, ways: 1, line: 1 }, LodRule::Exact, 0x411);
}
