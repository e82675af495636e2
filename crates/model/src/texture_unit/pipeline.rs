//! The texture unit of paper 001 (section II-5) as one pipeline, cycle for cycle as the RTL
//! top `rtl::texture_unit` runs it: `texture_coords` (21 stages, a global enable), then
//! `texture_address` (3 stages, a global enable; each access computed by `request` as it
//! enters and carried through them), the texture cache ([`crate::texture_cache`]'s cycle
//! model, inside), and `texture_filter` (5 stages, a global enable). Each colour is
//! computed from the words the cache gives, with the functions
//! [`super::TextureUnit::sample`] uses (`coords`, `request`, `texel`, `environment`), so it
//! is `sample`'s colour whenever the memory answers with the texture's words; when each
//! pixel appears, when input is taken, the memory requests and the cache's counters are
//! the RTL's.
//!
//! The cycle behaviour (`rtl::texture_unit`'s module documentation has the timing table):
//!
//! * `en_f = out_ready | !out_valid` moves the filter; the cache's `out_ready` is `en_f`.
//! * `en_a = !address_valid | (the cache takes the access)` moves texture_address.
//! * `en_c = !coords_valid | (en_a and the access entering texture_address is the pixel's
//!   last)` moves coords; `inp_ready = en_c & !st_load`.
//! * A pixel between two levels makes two accesses, the second (GL 4.6 section 8.14.3's
//!   level d1 + 1) into texture_address in the cycle after the first at the earliest
//!   (coords holds the pixel until then); both pass texture_address and the cache one
//!   after the other; its first level's words wait in a pair register and the filter takes
//!   the pixel with the second's.
//! * A one-level pixel taken in cycle t, with nothing stalling, is out in t + [`LATENCY`].
//!
//! [`cycles`] runs a stream of pixels through the unit behind a memory of fixed latency
//! with the output always ready: the cycles a scene's textured fragments take.

use super::{TexGrad, TexIn, TexState, TextureUnit};
use crate::texture_address::{request, Request};
use crate::texture_cache::{CacheIn, Counters, MemAsk, MemIn, Params, TextureCache, HIT_LATENCY, LANES};
use crate::texture_coords::Coords;
use crate::texture_filter::{environment, gaussian_table, texel, FilterIn, Rgba8};
use crate::texture_memory::ReadPort;
use fx::TexFormats;
use std::collections::VecDeque;
use texture::LodRule;

/// `texture_coords`' stages: the divider's 13 and 8 more (`rtl::texture_coords::LATENCY`).
pub const COORDS_STAGES: usize = 21;
/// `texture_address`' stages: the level, the footprint and offset, the wrap and words
/// (`rtl::texture_address::LATENCY`).
pub const ADDRESS_STAGES: usize = 3;
/// `texture_filter`'s stages.
pub const FILTER_STAGES: usize = 5;
/// Input to output of a one-level pixel when nothing stalls.
pub const LATENCY: u64 = COORDS_STAGES as u64 + ADDRESS_STAGES as u64 + HIT_LATENCY + FILTER_STAGES as u64;

/// One pixel offered: its inputs, its triangle's gradients, its lit colour and a tag the
/// unit carries to the output.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pixel {
    pub p: TexIn,
    pub g: TexGrad,
    pub cf: [u8; 3],
    pub tag: u32,
}

/// The unit's inputs in one cycle (the RTL's ports: `inp_*`, `st_load` and `st$*`, `inp_flush`,
/// `out_ready`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnitIn {
    pub inp_valid: bool,
    pub pixel: Pixel,
    /// The state registers take `state` (load only while idle).
    pub st_load: bool,
    pub state: TexState,
    pub flush: bool,
    pub out_ready: bool,
}

impl UnitIn {
    /// No pixel offered, no load, no flush, the output taken: a quiet cycle with `state` on
    /// the state ports.
    pub fn idle(state: TexState) -> UnitIn {
        UnitIn { inp_valid: false, pixel: Pixel::default(), st_load: false, state, flush: false, out_ready: true }
    }
}

/// The unit's outputs in one cycle, before the clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UnitOut {
    pub inp_ready: bool,
    pub out_valid: bool,
    /// The pixel's colour and tag (meaningful with `out_valid`).
    pub out_rgba: Rgba8,
    pub out_tag: u32,
    /// The cache's read port and counters.
    pub mem: MemAsk,
    pub counters: Counters,
    /// No pixel in flight.
    pub idle: bool,
}

/// A pixel in coords: its coordinates (computed at its taking, with the state then).
#[derive(Clone, Copy, Debug)]
struct InCoords {
    c: Coords,
}

/// The attributes of an access, as the RTL carries them on the cache's side payload.
fn attributes(r: &Request, second: bool) -> u64 {
    let banks: u64 = (0..4).map(|k| (r.banks[k] as u64) << (2 * k)).sum();
    (u64::from(r.beta) << 24)
        | (u64::from(r.alpha) << 16)
        | (banks << 8)
        | (u64::from(r.frac) << 2)
        | (u64::from(r.two_levels) << 1)
        | u64::from(second)
}

/// The texture unit's top, cycle for cycle: see the module documentation.
#[derive(Clone, Debug)]
pub struct Pipeline {
    f: TexFormats,
    unit: TextureUnit,
    gaussian: Vec<u32>,
    lod: LodRule,
    cache: TextureCache,
    state: TexState,
    coords: [Option<InCoords>; COORDS_STAGES],
    /// The access coords' pixel makes next is of its second level.
    second: bool,
    /// texture_address' stages: each access (computed as it enters, with the state then,
    /// which holds while pixels are in flight) and whether it is of a second level.
    address: [Option<(Request, bool)>; ADDRESS_STAGES],
    /// Each pixel's (cf, tag) from its taking: the RTL's RAMs, popped as the pixel enters
    /// the filter (cf) and leaves the output (tag).
    cf: VecDeque<[u8; 3]>,
    tags: VecDeque<u32>,
    /// A two-level pixel's first level: words in footprint order, alpha, beta.
    pair: ([u32; 4], u32, u32),
    /// The filter's stages: each pixel's colour (stage 0 first).
    filter: [Option<Rgba8>; FILTER_STAGES],
}

impl Pipeline {
    /// The unit at `formats` with a cache of geometry `cache` and the level-of-detail rule
    /// `lod` (the RTL's parameter `EXACT`), at power-up: the cache in Clear, the state 0.
    pub fn new(formats: TexFormats, cache: Params, lod: LodRule) -> Result<Pipeline, String> {
        let unit = TextureUnit::new(formats)?;
        cache.check()?;
        Ok(Pipeline {
            f: formats,
            gaussian: gaussian_table(&formats),
            unit,
            lod,
            cache: TextureCache::new(cache),
            state: TexState {
                size_log2: [0, 0],
                levels: 0,
                base: 0,
                format: texture::TexelFormat::ALL[0],
                sampler: texture::Sampler {
                    min: texture::Filter::Nearest,
                    mag: texture::Filter::Nearest,
                    mip: texture::MipMode::None,
                    wrap_s: texture::Wrap::Repeat,
                    wrap_t: texture::Wrap::Repeat,
                    weights: texture::Weights::Linear,
                },
                env: texture::EnvMode::Replace,
                lod,
            },
            coords: [None; COORDS_STAGES],
            second: false,
            address: [None; ADDRESS_STAGES],
            cf: VecDeque::new(),
            tags: VecDeque::new(),
            pair: ([0; 4], 0, 0),
            filter: [None; FILTER_STAGES],
        })
    }

    /// No pixel in flight (the output `idle` of this cycle): the state may be loaded.
    pub fn is_idle(&self) -> bool {
        self.tags.is_empty()
    }

    /// Whether the cache has left its power-up Clear (it takes accesses).
    pub fn cache_running(&self) -> bool {
        self.cache.state() == crate::texture_cache::State::Run
    }

    /// One clock: the outputs of this cycle for inputs `i` and the memory's `m`, then the
    /// edge. Panics if a state of another level-of-detail rule is loaded.
    pub fn step(&mut self, i: &UnitIn, m: MemIn) -> UnitOut {
        let f = self.f;
        let en_f = i.out_ready || self.filter[FILTER_STAGES - 1].is_none();
        let head = self.address[ADDRESS_STAGES - 1];
        let cin = match &head {
            Some((r, second)) => CacheIn {
                inp_valid: true,
                inp_en: (0..LANES).filter(|&b| r.fetch[b].is_some()).map(|b| 1u8 << b).sum(),
                inp_addr: r.fetch.map(|a| a.unwrap_or(0)),
                inp_side: attributes(r, *second),
                inp_flush: i.flush,
                out_ready: en_f,
            },
            None => CacheIn { inp_flush: i.flush, out_ready: en_f, ..CacheIn::default() },
        };
        let co = self.cache.step(&cin, m);
        // texture_address moves on when its last stage is empty or the cache takes its
        // access; coords when its last stage is empty or texture_address takes the last
        // access of its pixel.
        let en_a = head.is_none() || co.inp_ready;
        let entry = self.coords[COORDS_STAGES - 1].map(|h| request(&f, &self.state, &h.c, self.second));
        let two = entry.is_some_and(|r| r.two_levels);
        let en_c = entry.is_none() || (en_a && (!two || self.second));
        let inp_ready = en_c && !i.st_load;
        let accept = i.inp_valid && inp_ready;

        // The cache's result.
        let side = co.out_side;
        let (r_second, r_two) = (side & 1 == 1, side >> 1 & 1 == 1);
        let first = r_two && !r_second;
        let whole = co.out_valid && !first;
        let words: [u32; 4] = std::array::from_fn(|k| co.out_data[(side >> (8 + 2 * k) & 3) as usize]);
        let (alpha, beta, frac) = ((side >> 16 & 0xff) as u32, (side >> 24 & 0xff) as u32, (side >> 2 & 0x3f) as u32);

        let last = self.filter[FILTER_STAGES - 1];
        let out = UnitOut {
            inp_ready,
            out_valid: last.is_some(),
            out_rgba: last.unwrap_or_default(),
            out_tag: self.tags.front().copied().unwrap_or(0),
            mem: co.mem,
            counters: co.counters,
            idle: self.is_idle(),
        };

        // The edge.
        if last.is_some() && i.out_ready {
            self.tags.pop_front();
        }
        if en_f {
            let entering = whole.then(|| {
                let cf = self.cf.pop_front().expect("a pixel's colour in the RAM");
                let mut x = FilterIn { two_levels: r_two, frac, ..FilterIn::default() };
                x.words[0] = words;
                (x.alpha[0], x.beta[0]) = (alpha, beta);
                if r_two {
                    (x.words[0], x.alpha[0], x.beta[0]) = self.pair;
                    x.words[1] = words;
                    (x.alpha[1], x.beta[1]) = (alpha, beta);
                }
                let s = &self.state;
                let cs = texel(&f, s.format, s.sampler.weights, &self.gaussian, &x);
                environment(s.env, [cf[0], cf[1], cf[2], 255], cs)
            });
            self.filter.copy_within(0..FILTER_STAGES - 1, 1);
            self.filter[0] = entering;
            if co.out_valid && first {
                self.pair = (words, alpha, beta);
            }
        }
        if en_a {
            let entering = entry.map(|r| (r, self.second));
            if entry.is_some() {
                self.second = two && !self.second;
            }
            self.address.copy_within(0..ADDRESS_STAGES - 1, 1);
            self.address[0] = entering;
        }
        if en_c {
            let entering = accept.then(|| {
                self.cf.push_back(i.pixel.cf);
                self.tags.push_back(i.pixel.tag);
                InCoords { c: self.unit.coords(&self.state, &i.pixel.p, &i.pixel.g) }
            });
            self.coords.copy_within(0..COORDS_STAGES - 1, 1);
            self.coords[0] = entering;
        }
        if i.st_load {
            assert_eq!(i.state.lod, self.lod, "the unit's level-of-detail rule is a parameter");
            self.state = i.state;
        }
        out
    }
}

/// What [`cycles`] measured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Run {
    /// Cycles from the first pixel's offer (after the cache's power-up Clear) to the last
    /// pixel's output, inclusive.
    pub cycles: u64,
    pub pixels: u64,
    pub hits: u64,
    pub misses: u64,
    pub fills: u64,
}

impl Run {
    /// Textured pixels per clock.
    pub fn pixels_per_clock(&self) -> f64 {
        self.pixels as f64 / self.cycles.max(1) as f64
    }
}

/// The pixels of `draws` (each a state and its pixels, in order) through the unit at
/// `formats` with cache `cache`, behind a memory holding `memory` (a word past its end reads
/// 0) that takes a word a cycle and answers each `latency` (at least 1) cycles after, with
/// the output always ready. The unit is idle between draws (the state is loaded then, a
/// cycle each). Every colour and tag is checked against `TextureUnit::sample`'s and the
/// pixel's: `Err` if one differs (the model would be wrong), or for formats or a cache
/// geometry refused. Panics on a state of a rule other than `lod`.
pub fn cycles(
    formats: TexFormats,
    cache: Params,
    lod: LodRule,
    memory: &[u32],
    latency: u64,
    draws: &[(TexState, Vec<Pixel>)],
) -> Result<Run, String> {
    let mut u = Pipeline::new(formats, cache, lod)?;
    let mut port = ReadPort::new(memory.to_vec(), latency.max(1));
    let mut now = 0u64;
    let mut run = Run::default();
    let mut step = |u: &mut Pipeline, i: &UnitIn, now: &mut u64| {
        let m = port.answer(*now, true);
        let o = u.step(i, m);
        port.ask(*now, &m, o.mem);
        *now += 1;
        o
    };
    // The power-up Clear: the first pixel is offered once the cache takes requests.
    let mut start = None;
    let mut last = 0u64;
    let mut out = 0u64;
    for (state, pixels) in draws {
        let load = UnitIn { st_load: true, ..UnitIn::idle(*state) };
        step(&mut u, &load, &mut now);
        if start.is_none() {
            while !u.cache_running() {
                step(&mut u, &UnitIn::idle(*state), &mut now);
            }
            start = Some(now);
        }
        let want: Vec<Rgba8> = pixels.iter().map(|x| u.unit.sample(state, memory, &x.p, &x.g, x.cf).colour).collect();
        let (mut next, mut done) = (0, 0);
        while done < pixels.len() {
            let i = UnitIn {
                inp_valid: next < pixels.len(),
                pixel: pixels.get(next).copied().unwrap_or_default(),
                ..UnitIn::idle(*state)
            };
            let o = step(&mut u, &i, &mut now);
            if o.inp_ready && i.inp_valid {
                next += 1;
            }
            if o.out_valid {
                if o.out_rgba != want[done] || o.out_tag != pixels[done].tag {
                    return Err(format!("pixel {done} of a draw: {:?}, sample gives {:?}", o.out_rgba, want[done]));
                }
                done += 1;
                out += 1;
                last = now;
            }
        }
    }
    let state = u.state;
    let o = step(&mut u, &UnitIn::idle(state), &mut now);
    run.cycles = last - start.unwrap_or(0);
    run.pixels = out;
    (run.hits, run.misses, run.fills) = (o.counters.hits.into(), o.counters.misses.into(), o.counters.fills.into());
    Ok(run)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture_cache::hit_rate_of_trace;
    use crate::texture_unit::input::TexPlanes;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;
    use texture::{EnvMode, Filter, MipMode, Sampler, TexelFormat, Weights, Wrap};

    const F: TexFormats = TexFormats::DEFAULT;
    const CACHE: Params = Params { sets: 64, ways: 2, line: 4 };

    fn state(size_log2: [u32; 2], levels: u32, mip: MipMode, filter: Filter, lod: LodRule) -> TexState {
        TexState {
            size_log2,
            levels,
            base: 0,
            format: TexelFormat::Rgba8888,
            sampler: Sampler {
                min: filter,
                mag: filter,
                mip,
                wrap_s: Wrap::Repeat,
                wrap_t: Wrap::Repeat,
                weights: Weights::Linear,
            },
            env: EnvMode::Modulate,
            lod,
        }
    }

    /// A 1 x 1 texture, magnified (zero gradients), nearest: one lane an access. The first
    /// access misses: taken 24 cycles after the pixel (coords' 21, texture_address' 3), its
    /// word asked 2 cycles later, a line of 4 words asked in 4 cycles, the last answered L =
    /// 5 cycles after, then the cache's Wait and lookup (2) and output register (1): out of
    /// the cache in cycle 24 + 4 + 4 + 5 = 37, of the filter 5 later, 42; each later pixel,
    /// waiting in texture_address and coords, hits, one a clock. 100 pixels: 42 + 100
    /// cycles.
    #[test]
    fn texture_unit_pipeline_streams_a_pixel_a_clock_after_a_cold_miss() {
        let s = state([0, 0], 1, MipMode::None, Filter::Nearest, LodRule::Max);
        let memory = [0x11223344];
        let pixels: Vec<Pixel> = (0..100)
            .map(|k| Pixel {
                p: TexIn { sq: k, tq: 2 * k, q: 1 << F.q.frac },
                cf: [200, 100, 50],
                tag: k as u32,
                ..Pixel::default()
            })
            .collect();
        let run = cycles(F, CACHE, LodRule::Max, &memory, 5, &[(s, pixels)]).unwrap();
        // Out of the cache 4 + LINE + L cycles after it takes the access (the sum above).
        let miss = (COORDS_STAGES + ADDRESS_STAGES) as u64 + 4 + 4 + 5;
        let cycles = miss + FILTER_STAGES as u64 + 100;
        assert_eq!(run, Run { cycles, pixels: 100, hits: 99, misses: 1, fills: 1 });
    }

    /// A pixel taken alone comes out [`LATENCY`] = 31 cycles later (21 + 3 + 2 + 5) when its
    /// access hits, 32 when it reads two levels (its second access a cycle after the first).
    #[test]
    fn texture_unit_pipeline_latency_of_one_and_two_levels() {
        for (mip, latency) in [(MipMode::None, LATENCY), (MipMode::Linear, LATENCY + 1)] {
            let s = state([4, 4], 5, mip, Filter::Linear, LodRule::Max);
            let memory: Vec<u32> = (0..400).collect();
            let mut u = Pipeline::new(F, CACHE, LodRule::Max).unwrap();
            let quiet = UnitIn::idle(s);
            // lambda 1.5: d(s·q)/dx = 2^1.5 texels of level 0 (16 texels) a pixel.
            let step = F.dst.from_f64(2f64.powf(1.5) / 16.0).unwrap() as i64;
            let px = Pixel {
                p: TexIn { sq: 3 << (F.st.frac - 3), tq: 5 << (F.st.frac - 4), q: 1 << F.q.frac },
                g: TexGrad { dsq: [step, 0], dtq: [0, 0], dq: [0, 0] },
                cf: [255, 255, 255],
                tag: 7,
            };
            let mut mem_queue: VecDeque<(u64, u32)> = VecDeque::new();
            let mut taken = Vec::new();
            let mut outs = Vec::new();
            for now in 0..400u64 {
                let due = mem_queue.front().filter(|(t, _)| *t <= now).map(|&(_, w)| w);
                if due.is_some() {
                    mem_queue.pop_front();
                }
                // The same pixel at cycle 80 (a cold miss) and again at 200 (hits).
                let i = UnitIn { inp_valid: now == 80 || now == 200, pixel: px, st_load: now == 0, ..quiet };
                let o = u.step(&i, MemIn { ack: true, rvalid: due.is_some(), rdata: due.unwrap_or(0) });
                if o.mem.valid {
                    mem_queue.push_back((now + 3, memory.get(o.mem.addr as usize).copied().unwrap_or(0)));
                }
                if i.inp_valid && o.inp_ready {
                    taken.push(now);
                }
                if o.out_valid {
                    outs.push(now);
                }
            }
            assert_eq!(taken, [80, 200]);
            assert_eq!(outs.len(), 2, "{mip:?}: {outs:?}");
            assert_eq!(outs[1] - 200, latency, "{mip:?}");
        }
    }

    /// Random textures (random words), states and perspective triangles at memory latencies
    /// 1, 5 and 20: every colour is `sample`'s (`cycles` checks), the counters are the
    /// functional cache's on the accesses `sample` makes, and a pixel takes at least a clock
    /// an access.
    #[test]
    fn texture_unit_pipeline_random_draws_give_sample_colours_and_counts() {
        let mut rng = ChaCha8Rng::seed_from_u64(0x7e47);
        let memory: Vec<u32> = (0..1 << 14).map(|_| rng.gen()).collect();
        let unit = TextureUnit::new(F).unwrap();
        let filters = [Filter::Nearest, Filter::Linear];
        let mips = [MipMode::None, MipMode::Nearest, MipMode::Linear];
        for lod in [LodRule::Max, LodRule::Exact] {
            let mut draws = Vec::new();
            let mut fetches = Vec::new();
            for _ in 0..12 {
                let (ws, hs) = (rng.gen_range(0..=6), rng.gen_range(0..=6));
                let mut s = state(
                    [ws, hs],
                    rng.gen_range(1..=ws.max(hs) + 1),
                    mips[rng.gen_range(0..3)],
                    filters[rng.gen_range(0..2)],
                    lod,
                );
                s.base = rng.gen_range(0..8000);
                s.sampler.mag = filters[rng.gen_range(0..2)];
                s.format = TexelFormat::ALL[rng.gen_range(0..5)];
                let xy: [[f64; 2]; 3] = std::array::from_fn(|_| [rng.gen_range(0.0..16.0), rng.gen_range(0.0..16.0)]);
                let st: [[f64; 2]; 3] = std::array::from_fn(|_| [rng.gen_range(-4.0..4.0), rng.gen_range(-4.0..4.0)]);
                let Some(planes) = TexPlanes::new(xy, st, std::array::from_fn(|_| rng.gen_range(0.1..1.0))) else {
                    continue;
                };
                let g = planes.grad(&F);
                let pixels: Vec<Pixel> = (0..60)
                    .map(|k| Pixel {
                        p: planes.at(&F, (k % 8) as f64 + 4.5, (k / 8) as f64 + 4.5),
                        g,
                        cf: [rng.gen(), rng.gen(), rng.gen()],
                        tag: k,
                    })
                    .collect();
                for x in &pixels {
                    fetches.extend(unit.sample(&s, &memory, &x.p, &x.g, x.cf).fetches);
                }
                draws.push((s, pixels));
            }
            let n: u64 = draws.iter().map(|(_, p)| p.len() as u64).sum();
            let two = fetches.len() as u64 - n;
            println!("{lod:?}: {n} pixels, {two} of two levels");
            assert!(n >= 600 && two > 0, "{n} pixels, {two} of two levels");
            let want = hit_rate_of_trace(&CACHE, &fetches);
            for latency in [1, 5, 20] {
                let run = cycles(F, CACHE, lod, &memory, latency, &draws).unwrap();
                assert_eq!((run.pixels, run.hits, run.misses, run.fills), (n, want.hits, want.misses, want.fills));
                assert!(run.cycles >= fetches.len() as u64 + LATENCY, "{lod:?} {latency}: {run:?}");
            }
        }
    }

    /// Textured pixels per clock on every shipped textured scene: each textured fragment
    /// (the float triangle's planes, as `accuracy::texture` drives the unit) in raster
    /// order, triangle by triangle, through the unit at the default cache behind a memory
    /// of latency 10, the output always ready (`cargo test --release -p model --lib --
    /// --ignored pixels_per_clock --nocapture`).
    #[test]
    #[ignore = "minutes in a debug build; a measurement"]
    fn texture_unit_pipeline_pixels_per_clock_on_the_shipped_scenes() {
        use crate::texture_memory::TextureMemory;
        use reference::{prepare, raster, Interpolation, Options, Prepared};
        for path in scene::shipped::textured().unwrap() {
            let list = scene::Scene::load(&path).unwrap().to_trilist().unwrap();
            let memory = TextureMemory::load(&list, LodRule::Max).unwrap();
            let mut draws: Vec<(TexState, Vec<Pixel>)> = Vec::new();
            for tri in &list.triangles {
                let Some(tex) = tri[0].tex else { continue };
                let state = memory.states[tex.texture as usize];
                let Prepared::Draw(parts, interp) = prepare(tri, &Options::default()) else { continue };
                if draws.last().is_none_or(|(s, _)| *s != state) {
                    draws.push((state, Vec::new()));
                }
                let pixels = &mut draws.last_mut().unwrap().1;
                for part in &parts {
                    let inv_w = match interp {
                        Interpolation::Perspective => part.map(|v| v.inv_w),
                        _ => [1.0; 3],
                    };
                    let Some(planes) = TexPlanes::new(part.map(|v| [v.x, v.y]), part.map(|v| v.st), inv_w) else {
                        continue;
                    };
                    let g = planes.grad(&F);
                    raster::rasterize(part, list.width, list.height, interp, |frag| {
                        let cf = frag.rgb.map(|c| c.round().clamp(0.0, 255.0) as u8);
                        let p = planes.at(&F, f64::from(frag.x) + 0.5, f64::from(frag.y) + 0.5);
                        pixels.push(Pixel { p, g, cf, tag: frag.y << 16 | frag.x });
                    });
                }
            }
            let run = cycles(F, CACHE, LodRule::Max, &memory.words, 10, &draws).unwrap();
            let lookups = run.hits + run.misses;
            println!(
                "{}: {} pixels, {} cycles, {:.3} pixels a clock; {} lane lookups, hit rate {:.4}",
                path.file_name().unwrap().to_string_lossy(),
                run.pixels,
                run.cycles,
                run.pixels_per_clock(),
                lookups,
                run.hits as f64 / lookups.max(1) as f64
            );
            assert!(run.pixels > 5_000 && run.cycles > run.pixels);
        }
    }
}
