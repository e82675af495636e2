//! `texture_cache` (paper 001's texture cache, four banks): rust-hdl and Verilator in
//! lockstep with `model::texture_cache`, every output compared every cycle, behind a
//! test-side memory of pseudo-random words (latency 1 to 8, refusing words at random,
//! answering in order); every word out is also checked against that memory directly.
//! Directed: one request a clock while hitting, a cold miss's cycles against the cycle
//! table, the counters against `hit_rate_of_trace`, a flush, round-robin replacement.

use model::texture_cache::{
    hit_rate_of_trace, CacheIn, CacheOut, MemIn, Params, TextureCache as Model, HIT_LATENCY, LANES,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::texture_cache::{TextureCacheOf, ADDR, GEOMETRIES};
use rust_hdl::prelude::Block;
use std::collections::VecDeque;
use testbenches::flow::Flow;
use testbenches::{count, seed, verilated_with, write_if_changed, Dual, Pins, Value, Verilated};

/// The memory's word at `addr`: a hash of the address and a salt, so that every word
/// differs from its neighbours' and from other runs'.
fn word(salt: u64, addr: u32) -> u32 {
    let mut z = (addr as u64 ^ salt.rotate_left(20)).wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    (z ^ (z >> 31)) as u32
}

/// One request: enabled lanes (bit b), each lane's address, the side payload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Req {
    en: u8,
    addr: [u32; LANES],
    side: u64,
}

impl Req {
    /// Every lane enabled.
    fn all(addr: [u32; LANES]) -> Self {
        Req { en: 0xf, addr, side: addr[0] as u64 * 7 }
    }

    /// Lane `b` only.
    fn lane(b: usize, addr: u32) -> Self {
        Req { en: 1 << b, addr: [addr; LANES], side: addr as u64 }
    }

    /// As `hit_rate_of_trace` takes it.
    fn lanes(&self) -> [Option<u32>; LANES] {
        std::array::from_fn(|b| (self.en >> b & 1 == 1).then_some(self.addr[b]))
    }
}

/// The test's memory: takes a word asked when `ack` (decided before the cycle, as a memory
/// would), answers it `latency` cycles later, plus up to `jitter` more, in order, at most
/// one word a cycle.
struct Memory {
    salt: u64,
    latency: u64,
    jitter: u64,
    ack_chance: f64,
    /// (cycle due, word)
    queue: VecDeque<(u64, u32)>,
    asked: u64,
}

/// Every output of the unit, by name.
const OUTPUTS: [&str; 12] = [
    "inp_ready",
    "out_valid",
    "out_data0",
    "out_data1",
    "out_data2",
    "out_data3",
    "out_side",
    "mem$valid",
    "mem$addr",
    "counters$hits",
    "counters$misses",
    "counters$fills",
];

/// The model's value of output `pin`.
fn model_pin(o: &CacheOut, pin: &str) -> Value {
    let bit = |b: bool| Value::new(1, b as u128);
    match pin {
        "inp_ready" => bit(o.inp_ready),
        "out_valid" => bit(o.out_valid),
        "out_data0" => Value::new(32, o.out_data[0] as u128),
        "out_data1" => Value::new(32, o.out_data[1] as u128),
        "out_data2" => Value::new(32, o.out_data[2] as u128),
        "out_data3" => Value::new(32, o.out_data[3] as u128),
        "out_side" => Value::new(64, o.out_side as u128),
        "mem$valid" => bit(o.mem.valid),
        "mem$addr" => Value::new(ADDR, o.mem.addr as u128),
        "counters$hits" => Value::new(32, o.counters.hits as u128),
        "counters$misses" => Value::new(32, o.counters.misses as u128),
        "counters$fills" => Value::new(32, o.counters.fills as u128),
        _ => unreachable!("{pin}"),
    }
}

/// The unit in both simulators beside the model and the memory, one cycle at a time.
struct Bench<U> {
    p: Params,
    dual: Dual<U>,
    model: Model,
    mem: Memory,
    rng: ChaCha8Rng,
    now: u64,
    /// The requests taken and not yet out, in order.
    inflight: VecDeque<Req>,
    /// Each request's cycles: taken, out.
    taken_at: VecDeque<u64>,
    log: Vec<(u64, u64)>,
    /// The outputs of the last cycle; the flushes asked.
    last: CacheOut,
    flushes: u64,
}

impl<U: Block + Pins + Default> Bench<U> {
    fn new(p: Params, rng_seed: u64) -> Self {
        let vl = verilated_with(
            "texture_cache",
            [("SETS", p.sets as u64), ("WAYS", p.ways as u64), ("LINE", p.line as u64)],
        );
        Self::beside(p, rng_seed, &vl)
    }

    /// The unit in rust-hdl beside `vl`, the Verilog of the same geometry.
    fn beside(p: Params, rng_seed: u64, vl: &Verilated) -> Self {
        let dual = Dual::new(U::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
        let mut rng = ChaCha8Rng::seed_from_u64(rng_seed);
        let mem = Memory { salt: rng.gen(), latency: 1, jitter: 0, ack_chance: 1.0, queue: VecDeque::new(), asked: 0 };
        Bench {
            p,
            dual,
            model: Model::new(p),
            mem,
            rng,
            now: 0,
            inflight: VecDeque::new(),
            taken_at: VecDeque::new(),
            log: Vec::new(),
            last: CacheOut::default(),
            flushes: 0,
        }
    }

    /// One clock: `i` and the memory's answer driven, every output compared between the
    /// simulators and with the model, the words out checked against the memory.
    fn cycle(&mut self, i: &CacheIn, req: &Req) -> Result<CacheOut, String> {
        let ack = self.mem.ack_chance >= 1.0 || self.rng.gen_bool(self.mem.ack_chance);
        let answer = self.mem.queue.front().filter(|(due, _)| *due <= self.now).map(|(_, w)| *w);
        if answer.is_some() {
            self.mem.queue.pop_front();
        }
        let m = MemIn { ack, rvalid: answer.is_some(), rdata: answer.unwrap_or(0) };
        let bit = |b: bool| Value::new(1, b as u128);
        let pins = [
            ("inp_valid", bit(i.inp_valid)),
            ("inp_en", Value::new(4, i.inp_en as u128)),
            ("inp_addr0", Value::new(ADDR, i.inp_addr[0] as u128)),
            ("inp_addr1", Value::new(ADDR, i.inp_addr[1] as u128)),
            ("inp_addr2", Value::new(ADDR, i.inp_addr[2] as u128)),
            ("inp_addr3", Value::new(ADDR, i.inp_addr[3] as u128)),
            ("inp_side", Value::new(64, i.inp_side as u128)),
            ("inp_flush", bit(i.inp_flush)),
            ("out_ready", bit(i.out_ready)),
            ("mem$ack", bit(m.ack)),
            ("mem$rvalid", bit(m.rvalid)),
            ("mem$rdata", Value::new(32, m.rdata as u128)),
        ];
        let got = self.dual.cycle(&pins).map_err(|e| e.to_string())?;
        let o = self.model.step(i, m);
        for pin in OUTPUTS {
            self.dual
                .expect(&got, pin, &model_pin(&o, pin))
                .map_err(|e| format!("{e} (model state {:?})", self.model.state()))?;
        }
        // The memory takes the word asked.
        if o.mem.valid && ack {
            let due = (self.now + self.mem.latency + self.rng.gen_range(0..=self.mem.jitter))
                .max(self.mem.queue.back().map_or(0, |(d, _)| d + 1));
            self.mem.queue.push_back((due, word(self.mem.salt, o.mem.addr)));
            self.mem.asked += 1;
        }
        // The independent oracle: each word out is the memory's word at its lane's address.
        if o.out_valid && i.out_ready {
            let r =
                self.inflight.pop_front().ok_or(format!("cycle {}: a result with no request in flight", self.now))?;
            for b in 0..LANES {
                let want = if r.en >> b & 1 == 1 { word(self.mem.salt, r.addr[b]) } else { 0 };
                if o.out_data[b] != want {
                    return Err(format!(
                        "cycle {}: lane {b} of {r:?}: {:#010x}, memory holds {want:#010x}",
                        self.now, o.out_data[b]
                    ));
                }
            }
            if o.out_side != r.side {
                return Err(format!("cycle {}: side {:#x} for {r:?}", self.now, o.out_side));
            }
            let t = self.taken_at.pop_front().expect("taken with its request");
            self.log.push((t, self.now));
        }
        if i.inp_valid && o.inp_ready {
            self.inflight.push_back(*req);
            self.taken_at.push_back(self.now);
        }
        self.flushes += i.inp_flush as u64;
        self.last = o;
        self.now += 1;
        Ok(o)
    }

    /// Idle cycles (nothing offered, the output taken) until `inp_ready`; returns how many
    /// cycles `inp_ready` was low.
    fn until_ready(&mut self) -> u64 {
        let idle = CacheIn { out_ready: true, ..Default::default() };
        for n in 0..10_000 {
            let o = self.cycle(&idle, &Req::all([0; LANES])).unwrap_or_else(|e| panic!("{e}"));
            if o.inp_ready {
                return n;
            }
        }
        panic!("inp_ready never rose")
    }

    /// `reqs` in order with `flow` (and flushes at `flush_chance` a cycle), until every
    /// result is out.
    fn run(&mut self, reqs: &[Req], flow: Flow, flush_chance: f64) -> Result<(), String> {
        let (mut next, mut offering, mut ready, start) = (0, false, true, self.log.len());
        let limit = self.now + 200 * reqs.len() as u64 + 20_000;
        while self.log.len() - start < reqs.len() {
            if self.now > limit {
                return Err(format!("{} of {} requests out by cycle {}", self.log.len() - start, reqs.len(), self.now));
            }
            if next < reqs.len() {
                offering = flow.offer(offering, &mut self.rng);
            }
            let r = reqs[next.min(reqs.len() - 1)];
            let flush = flush_chance > 0.0 && self.rng.gen_bool(flush_chance);
            let i = CacheIn {
                inp_valid: offering,
                inp_en: r.en,
                inp_addr: r.addr,
                inp_side: r.side,
                inp_flush: flush,
                out_ready: ready,
            };
            let o = self.cycle(&i, &r)?;
            if offering && o.inp_ready {
                (next, offering) = (next + 1, false);
            }
            ready = flow.next_ready(ready, &mut self.rng);
        }
        Ok(())
    }
}

/// The geometries of the lockstep tests: direct-mapped with one-word lines, 2-way with
/// 4-word lines, 4-way with 8-word lines.
const P411: Params = Params { sets: 4, ways: 1, line: 1 };
const P1624: Params = Params { sets: 16, ways: 2, line: 4 };
const P848: Params = Params { sets: 8, ways: 4, line: 8 };

/// Random requests in phases of 40: a texture's bilinear footprints walking over its four
/// parity planes (mostly hits), a small working set, addresses anywhere (mostly misses),
/// and lines that all map to one set (replacement); 1 in 5 with random lanes enabled.
fn random_requests(rng: &mut ChaCha8Rng, p: Params, n: usize) -> Vec<Req> {
    let mut out = Vec::with_capacity(n);
    let capacity = p.sets * p.ways * p.line;
    while out.len() < n {
        let kind = rng.gen_range(0..4);
        let base = rng.gen_range(0..1u32 << 19);
        let (pitch_log2, plane) = (rng.gen_range(1..6), 1u32 << rng.gen_range(8..12));
        let (mut i, mut j) = (rng.gen_range(0..32u32), rng.gen_range(0..32u32));
        let pool: Vec<u32> = (0..(capacity / 2).max(2)).map(|_| base + rng.gen_range(0..capacity)).collect();
        let set = rng.gen_range(0..p.sets);
        let conflicting: Vec<u32> = (0..p.ways + 1)
            .map(|_| (rng.gen_range(0..1u32 << ADDR) & !(p.sets * p.line - 1)) | (set * p.line))
            .collect();
        for _ in 0..40 {
            let mut addr = [0; LANES];
            match kind {
                0 => {
                    // Footprint (i, j)..(i + 1, j + 1): texel (x, y) in plane (y & 1) * 2 + (x & 1).
                    i = (i + rng.gen_range(0..3)).saturating_sub(1) % 64;
                    j = (j + rng.gen_range(0..3)).saturating_sub(1) % 64;
                    for (x, y) in [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)] {
                        let b = ((y & 1) * 2 + (x & 1)) as usize;
                        addr[b] = (base + b as u32 * plane + ((y >> 1) << pitch_log2) + (x >> 1)) & 0xf_ffff;
                    }
                }
                1 => addr = std::array::from_fn(|_| pool[rng.gen_range(0..pool.len())] & 0xf_ffff),
                2 => addr = std::array::from_fn(|_| rng.gen_range(0..1u32 << ADDR)),
                _ => {
                    addr = std::array::from_fn(|_| {
                        conflicting[rng.gen_range(0..conflicting.len())] + rng.gen_range(0..p.line)
                    })
                }
            }
            let en = if rng.gen_bool(0.8) { 0xf } else { rng.gen_range(0..16) };
            out.push(Req { en, addr, side: rng.gen() });
        }
    }
    out.truncate(n);
    out
}

/// Random requests through the unit at geometry `p` in both simulators beside the model, in
/// four phases: back to back with a memory of latency 1 that takes every word; with stalls
/// on both streams, a memory that refuses words and answers late and out of step, and
/// flushes; back to back at latency 8; and stalled behind a memory that takes a word in
/// three cycles of ten.
fn lockstep<U: Block + Pins + Default>(p: Params, salt: u64) {
    let seed = seed() ^ salt;
    let mut b = Bench::<U>::new(p, seed);
    let clear = b.until_ready();
    assert_eq!(clear, p.sets as u64, "{p:?}: inp_ready low after power-up");
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let n = count();
    let fail = |e: String| -> ! { panic!("seed {seed}, {p:?}: {e}") };
    // (flow, memory latency, extra delay up to, chance a word is taken, flushes a cycle)
    let phases = [
        (Flow::BACK_TO_BACK, 1, 0, 1.0, 0.0),
        (Flow::STALLING, rng.gen_range(1..=8), 3, 0.6, 0.001),
        (Flow::BACK_TO_BACK, 8, 0, 0.8, 0.0005),
        (Flow::STALLING, rng.gen_range(1..=8), 0, 0.3, 0.001),
    ];
    for (k, (flow, latency, jitter, ack, flush)) in phases.into_iter().enumerate() {
        (b.mem.latency, b.mem.jitter, b.mem.ack_chance) = (latency, jitter, ack);
        let reqs = random_requests(&mut rng, p, n / 4 + (k < n % 4) as usize);
        b.run(&reqs, flow, flush).unwrap_or_else(|e| fail(format!("phase {k}, memory latency {latency}: {e}")));
    }
    let o = b.last;
    assert!(
        o.counters.hits > 0 && o.counters.misses > 0,
        "{p:?}: hits {} misses {}: both must happen",
        o.counters.hits,
        o.counters.misses
    );
    assert!(b.flushes > 0, "{p:?}: no flush taken");
    eprintln!(
        "texture_cache {p:?}: {n} requests in {} cycles, hits {} misses {} fills {}, {} words asked, {} flushes",
        b.now, o.counters.hits, o.counters.misses, o.counters.fills, b.mem.asked, b.flushes
    );
}

#[test]
fn texture_cache_random_lockstep_4_sets_direct_mapped() {
    lockstep::<TextureCacheOf<4, 1, 1>>(P411, 0x411);
}

#[test]
fn texture_cache_random_lockstep_16_sets_2_ways_4_words() {
    lockstep::<TextureCacheOf<16, 2, 4>>(P1624, 0x1624);
}

#[test]
fn texture_cache_random_lockstep_8_sets_4_ways_8_words() {
    lockstep::<TextureCacheOf<8, 4, 8>>(P848, 0x848);
}

/// One request alone through `b` (the output always taken, the memory as set), its
/// (taken, out) cycles and the counters' changes (hits, misses).
fn one<U: Block + Pins + Default>(b: &mut Bench<U>, r: Req) -> ((u64, u64), (u32, u32)) {
    let before = (b.last.counters.hits, b.last.counters.misses);
    b.run(&[r], Flow::BACK_TO_BACK, 0.0).unwrap_or_else(|e| panic!("{:?}: {r:?}: {e}", b.p));
    // The counters show a lookup the cycle after it: one idle cycle more.
    b.cycle(&CacheIn { out_ready: true, ..Default::default() }, &r).unwrap_or_else(|e| panic!("{e}"));
    (*b.log.last().expect("the request's cycles"), (b.last.counters.hits - before.0, b.last.counters.misses - before.1))
}

/// After the power-up Clear (SETS cycles), 64 requests of four hitting lanes are taken
/// one a clock and come out one a clock, each HIT_LATENCY cycles after it was taken.
#[test]
fn texture_cache_hits_take_one_request_a_clock() {
    let p = P1624;
    let mut b = Bench::<TextureCacheOf<16, 2, 4>>::new(p, seed());
    assert_eq!(b.until_ready(), 16, "the power-up Clear takes SETS cycles");
    // Lines 0..15 of four planes: one per set of each bank, words 0..63 of each plane.
    let plane = |b: usize, a: u32| b as u32 * 0x1_0000 + a;
    let warm: Vec<Req> = (0..16).map(|k| Req::all(std::array::from_fn(|l| plane(l, 4 * k)))).collect();
    b.run(&warm, Flow::BACK_TO_BACK, 0.0).unwrap_or_else(|e| panic!("{e}"));
    let n = 64;
    let hot: Vec<Req> = (0..n).map(|k| Req::all(std::array::from_fn(|l| plane(l, (k * 13 + l as u32) % 64)))).collect();
    let (from, before) = (b.log.len(), b.last);
    b.run(&hot, Flow::BACK_TO_BACK, 0.0).unwrap_or_else(|e| panic!("{e}"));
    b.cycle(&CacheIn { out_ready: true, ..Default::default() }, &hot[0]).unwrap_or_else(|e| panic!("{e}"));
    let cycles = &b.log[from..];
    let first = cycles[0].0;
    for (k, &(taken, out)) in cycles.iter().enumerate() {
        assert_eq!((taken, out), (first + k as u64, first + k as u64 + HIT_LATENCY), "request {k} of {n}");
    }
    assert_eq!(cycles[n as usize - 1].1 - first + 1, n as u64 + HIT_LATENCY, "N requests take N + latency cycles");
    assert_eq!(
        (b.last.counters.hits - before.counters.hits, b.last.counters.misses - before.counters.misses),
        (4 * n, 0)
    );
}

/// A cold miss of m lanes costs `m · LINE + L + 2` cycles over a hit's HIT_LATENCY, for a
/// memory of latency L taking every word at once; the same request again hits.
fn cold_miss<U: Block + Pins + Default>(p: Params) {
    let mut b = Bench::<U>::new(p, seed());
    b.until_ready();
    let mut fresh = 0u32;
    for latency in [1, 4, 8] {
        for m in [1, 2, 4usize] {
            b.mem.latency = latency;
            fresh += 1;
            // A line never asked before in each lane (each bank: its own), at its word 3.
            let r = Req { en: (1 << m) - 1, addr: [fresh * 0x800 + (3 & (p.line - 1)); LANES], side: fresh as u64 };
            let ((taken, out), (hits, misses)) = one(&mut b, r);
            let want = HIT_LATENCY + p.miss_penalty(m as u32, latency as u32);
            assert_eq!(out - taken, want, "{p:?}, L = {latency}, {m} lanes missing: m·LINE + L + 2 over {HIT_LATENCY}");
            assert_eq!((hits, misses), (0, m as u32), "{p:?}: {r:?} cold");
            let ((taken, out), (hits, misses)) = one(&mut b, r);
            assert_eq!((out - taken, hits, misses), (HIT_LATENCY, m as u32, 0), "{p:?}: {r:?} again");
        }
    }
}

#[test]
fn texture_cache_cold_miss_costs_m_line_plus_l_plus_2() {
    cold_miss::<TextureCacheOf<4, 1, 1>>(P411);
    cold_miss::<TextureCacheOf<16, 2, 4>>(P1624);
    cold_miss::<TextureCacheOf<8, 4, 8>>(P848);
}

/// The counters after a random trace (stalls, a slow memory, no flush) are
/// `hit_rate_of_trace`'s, at each geometry.
fn counters_vs_functional<U: Block + Pins + Default>(p: Params, salt: u64) {
    let seed = seed() ^ salt;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let reqs = random_requests(&mut rng, p, count() / 4);
    let mut b = Bench::<U>::new(p, seed);
    b.until_ready();
    (b.mem.latency, b.mem.jitter, b.mem.ack_chance) = (5, 2, 0.7);
    b.run(&reqs, Flow::STALLING, 0.0).unwrap_or_else(|e| panic!("seed {seed}, {p:?}: {e}"));
    b.cycle(&CacheIn { out_ready: true, ..Default::default() }, &reqs[0]).unwrap_or_else(|e| panic!("{e}"));
    let trace: Vec<_> = reqs.iter().map(Req::lanes).collect();
    let s = hit_rate_of_trace(&p, &trace);
    let got = (b.last.counters.hits as u64, b.last.counters.misses as u64, b.last.counters.fills as u64);
    assert_eq!(got, (s.hits, s.misses, s.fills), "seed {seed}, {p:?}: counters (hits, misses, fills)");
    assert!(s.hits > 0 && s.misses > 0, "{s:?}");
}

#[test]
fn texture_cache_counters_equal_hit_rate_of_trace() {
    counters_vs_functional::<TextureCacheOf<4, 1, 1>>(P411, 1);
    counters_vs_functional::<TextureCacheOf<16, 2, 4>>(P1624, 2);
    counters_vs_functional::<TextureCacheOf<8, 4, 8>>(P848, 3);
}

/// A trace of 16 lines a bank (one per set) misses cold, then hits; a flush keeps
/// `inp_ready` low for its own cycle and SETS more, after which every lane misses again.
#[test]
fn texture_cache_after_a_flush_every_lane_misses_again() {
    let p = P1624;
    let mut b = Bench::<TextureCacheOf<16, 2, 4>>::new(p, seed());
    b.until_ready();
    let trace: Vec<Req> =
        (0..16).map(|k| Req::all(std::array::from_fn(|l| l as u32 * 0x4_0000 + 0x3000 + 4 * k + l as u32))).collect();
    let pass = |b: &mut Bench<TextureCacheOf<16, 2, 4>>| {
        let before = b.last;
        b.run(&trace, Flow::BACK_TO_BACK, 0.0).unwrap_or_else(|e| panic!("{e}"));
        b.cycle(&CacheIn { out_ready: true, ..Default::default() }, &trace[0]).unwrap_or_else(|e| panic!("{e}"));
        (b.last.counters.hits - before.counters.hits, b.last.counters.misses - before.counters.misses)
    };
    assert_eq!(pass(&mut b), (0, 64), "cold");
    assert_eq!(pass(&mut b), (64, 0), "warm");
    let o = b.cycle(&CacheIn { inp_flush: true, out_ready: true, ..Default::default() }, &trace[0]).unwrap();
    assert!(!o.inp_ready, "inp_ready low in the flush's cycle");
    assert_eq!(b.until_ready(), 16, "the flush's Clear takes SETS cycles");
    assert_eq!(pass(&mut b), (0, 64), "after the flush");
}

/// Lines A, B, C of one set: a direct-mapped cache loses A to B; a 2-way set keeps A and
/// B, and C evicts the line filled first (round robin), then A evicts B.
#[test]
fn texture_cache_two_ways_keep_conflicting_lines_round_robin() {
    // (lane, address, hit?)
    fn check<U: Block + Pins + Default>(p: Params, seq: &[(usize, u32, bool)]) {
        let mut b = Bench::<U>::new(p, seed());
        b.until_ready();
        for (k, &(lane, addr, hit)) in seq.iter().enumerate() {
            let (_, counted) = one(&mut b, Req::lane(lane, addr));
            assert_eq!(counted, (hit as u32, !hit as u32), "{p:?}: access {k}, lane {lane}, {addr:#x}: hit {hit}");
        }
        let trace: Vec<_> = seq.iter().map(|&(l, a, _)| Req::lane(l, a).lanes()).collect();
        let s = hit_rate_of_trace(&p, &trace);
        assert_eq!(
            (s.hits, s.misses),
            (b.last.counters.hits as u64, b.last.counters.misses as u64),
            "{p:?}: the functional model"
        );
    }
    // 16 sets of 4 words: set = address bits 2..5; A, B, C all in set 0 (tags 4, 8, 12).
    let (a, b, c) = (0x100, 0x200, 0x300);
    check::<TextureCacheOf<4, 1, 1>>(P411, &[(0, a, false), (0, b, false), (0, a, false), (0, b, false)]);
    check::<TextureCacheOf<16, 2, 4>>(
        P1624,
        &[
            (1, a, false),
            (1, b + 3, false),
            (1, a + 1, true),
            (1, b, true),
            (1, c, false), // evicts A (way 0)
            (1, b + 2, true),
            (1, a, false), // evicts B (way 1)
            (1, c + 1, true),
            (1, b, false),
            (2, a, false), // bank 2 has its own sets
        ],
    );
}

/// `edgepaint emit --unit texture_cache` refuses geometries the model does not take, each
/// with a message naming the parameter, and those the RTL is not built for, listing those
/// it is.
#[test]
fn texture_cache_emit_refuses_unsupported_geometries() {
    let unit = rtl::Unit::named("texture_cache").expect("texture_cache is in UNITS");
    for (k, v) in [("SETS", 2), ("SETS", 48), ("SETS", 512), ("WAYS", 3), ("WAYS", 8), ("LINE", 0), ("LINE", 32)] {
        let params = unit.params([(k.to_owned(), v)]).expect("its parameters");
        let e = unit.emit(&params).expect_err("an unsupported geometry");
        assert!(e.contains(&format!("{k} = {v}")), "{k} = {v}: {e}");
    }
    // A geometry the model takes but the RTL is not built for.
    let params =
        unit.params([("SETS".to_owned(), 32), ("WAYS".to_owned(), 4), ("LINE".to_owned(), 2)]).expect("its parameters");
    let e = unit.emit(&params).expect_err("not built");
    assert!(e.contains("SETS = 32, WAYS = 4, LINE = 2 is not built") && e.contains("64/2/4"), "{e}");
}

/// Every geometry built (`rtl::texture_cache::GEOMETRIES`: SETS 4 to 256, WAYS 1 to 4, LINE
/// 1 to 16 among them) emits, passes rust-hdl's checks and lints clean in Verilator with
/// `scripts/lint.sh`'s flags (no waiver names this unit).
#[test]
fn texture_cache_every_geometry_built_lints_clean() {
    testbenches::check_verilator("verilator").unwrap_or_else(|e| panic!("{e}"));
    let unit = rtl::Unit::named("texture_cache").expect("texture_cache is in UNITS");
    for &(s, w, l) in GEOMETRIES {
        let params = unit
            .params([("SETS".to_owned(), s as u64), ("WAYS".to_owned(), w as u64), ("LINE".to_owned(), l as u64)])
            .expect("its parameters");
        let e = unit.emit(&params).unwrap_or_else(|e| panic!("{e}"));
        let file = sim::verilog_file(&e).unwrap_or_else(|e| panic!("{e}"));
        let out = std::process::Command::new("verilator")
            .args(["--lint-only", "-Wall", "-Wno-WIDTH", "-Wno-DECLFILENAME", "--top-module", "texture_cache"])
            .arg(&file)
            .output()
            .expect("verilator runs");
        assert!(
            out.status.success() && !String::from_utf8_lossy(&out.stderr).contains("%Warning"),
            "SETS={s} WAYS={w} LINE={l}: {}\n{}",
            file.display(),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    for extreme in [(4, 1, 1), (256, 4, 16), (4, 4, 16), (256, 1, 1)] {
        assert!(GEOMETRIES.contains(&extreme), "{extreme:?} is built");
    }
}

/// The lockstep must catch a broken unit: the Verilog of (16, 2, 4) with every bank's
/// victim pointer stuck (`way` written back, not `way + 1`), beside the intact rust-hdl
/// unit. Lines A and B of one set then share way 0, and the third access (A again) hits in
/// one simulator and misses in the other: `inp_ready` differs in its S1 cycle.
#[test]
fn texture_cache_lockstep_catches_a_stuck_victim_pointer() {
    let unit = rtl::Unit::named("texture_cache").expect("texture_cache is in UNITS");
    let params =
        unit.params([("SETS".to_owned(), 16), ("WAYS".to_owned(), 2), ("LINE".to_owned(), 4)]).expect("its parameters");
    let good = unit.emit(&params).unwrap_or_else(|e| panic!("{e}")).verilog;
    let advance = "victim$write_data = (way + 32'h1) & way_mask;";
    assert_eq!(good.matches(advance).count(), 4, "one pointer update a bank");
    let bad = good.replace(advance, "victim$write_data = way & way_mask;");
    let dir = testbenches::target_dir().join("hdl").join("texture_cache-mutated");
    let file = write_if_changed(&dir, "texture_cache.v", &bad).expect("mutated Verilog");
    let u = TextureCacheOf::<16, 2, 4>::default();
    let vl = Verilated::new("texture_cache", &file, &rtl::emit::ports(&u)).unwrap_or_else(|e| panic!("{e}"));
    let mut b = Bench::<TextureCacheOf<16, 2, 4>>::beside(P1624, seed(), &vl);
    b.until_ready();
    let (a, bb) = (0x100, 0x200);
    let seq = [Req::lane(1, a), Req::lane(1, bb), Req::lane(1, a)];
    let e = b.run(&seq, Flow::BACK_TO_BACK, 0.0).expect_err("the mutation must be caught");
    // In S1 of the third access rust-hdl hits (and takes the next request), the mutant misses.
    assert!(e.contains("inp_ready differs: rust-hdl 1'h1; verilator 1'h0"), "caught between the simulators: {e}");
    assert_eq!(b.inflight.len(), 2, "caught with the third access in S1 (and B in the output register): {e}");
}
